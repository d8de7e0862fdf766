"""Record the reference outputs of the masters' demonstration cells.

``python -m autograder record`` runs every master top to bottom (matplotlib's
Agg backend, as in grading) and stores the text printed by cells tagged
``nbval-check-output``. The nbval stage compares students' notebooks with
these outputs, and ``pytest --nbval-lax solutions/`` checks they are current.
"""

from __future__ import annotations

from pathlib import Path

from autograder.authoring.execute import errors, execute_notebook
from autograder.authoring.release import normalize_master
from autograder.lessons.notebook_files import canonical_text, read_master, write_if_changed


class RecordingFailed(RuntimeError):
    """A master raised an error while its outputs were being recorded."""


def record_outputs(solutions_dir: str | Path, only: list[str] | None = None) -> list[str]:
    """Execute each master (or those whose name starts with one of ``only``); return changed files."""
    changed = []
    for path in sorted(Path(solutions_dir).glob("[0-9][0-9]_*.ipynb")):
        if only and not any(path.name.startswith(prefix) for prefix in only):
            continue
        nb = execute_notebook(read_master(path), cwd=path.parent, allow_errors=True, inline_figures=False)
        found = errors(nb)
        if found:
            index, ename, evalue = found[0]
            raise RecordingFailed(f"{path.name}: cell {index + 1} raised {ename}: {evalue}")
        if write_if_changed(path, canonical_text(normalize_master(nb))):
            changed.append(str(path))
    return changed
