"""Generate the students' ``course/`` from the masters in ``solutions/``.

``python -m autograder release`` does three things:

1. normalises each master in place (no execution counts, no outputs except the
   recorded ones of ``nbval-check-output`` cells, no editor metadata), so that
   diffs of the masters show only what an author changed;
2. writes ``course/NN_*.ipynb`` without the book's ``reader-only`` cells, nor the ``giveaways`` of an answer
   cell's ``exercise`` metadata (its kind and minutes stay), with nbgrader's own preprocessors: solution
   regions replaced by a stub that raises ``NotImplementedError``, outputs
   cleared, check cells locked, checksums computed as ``nbgrader
   generate_assignment`` would;
3. copies the support package ``coursekit`` next to the notebooks.

``--check`` writes nothing and exits with status 1 if any of these files
differs from what release would write.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from nbformat import NotebookNode

from autograder.lessons import cells
from autograder.lessons.notebook_files import canonical_text, read_master, write_if_changed
from autograder.lessons.course import SUPPORT_PACKAGE

CODE_STUB = (
    "# Your code here: replace the next line with your solution.\n"
    'raise NotImplementedError("this exercise is not written yet")'
)
KEPT_CELL_METADATA = ("deletable", "editable", "exercise", "nbgrader", "tags")
KEPT_OUTPUT_MIME = ("text/plain",)


def _clean_output(output):
    if output.get("output_type") == "stream":
        return NotebookNode(output_type="stream", name=output["name"], text=output["text"])
    if output.get("output_type") in ("execute_result", "display_data"):
        data = {k: v for k, v in output.get("data", {}).items() if k in KEPT_OUTPUT_MIME}
        if not data:
            return None
        if output["output_type"] == "display_data":
            return NotebookNode(output_type="display_data", data=data, metadata={})
        return NotebookNode(output_type="execute_result", data=data, metadata={}, execution_count=1)
    return None


def normalize_master(nb: NotebookNode) -> NotebookNode:
    """Strip execution noise from a master, keeping recorded demonstration outputs.

    Only cells tagged ``nbval-check-output`` keep outputs (printed text and
    plain-text displays, execution count 1, as nbval needs a count to compare);
    every other cell is cleared.
    Cell ids are made unique and stable: answer and check cells use their
    ``grade_id``, others keep theirs or get ``cell-NNN``.
    """
    nb = NotebookNode(nb)
    nb.nbformat, nb.nbformat_minor = 4, 5
    kernelspec = nb.metadata.get("kernelspec", {})
    nb.metadata = NotebookNode(kernelspec=kernelspec, language_info={"name": "python"})
    seen = set()
    for index, cell in enumerate(nb.cells):
        cell.metadata = NotebookNode({k: v for k, v in cell.metadata.items() if k in KEPT_CELL_METADATA})
        cell.source = cells.source_text(cell)
        wanted = cells.grade_id(cell) if cell.cell_type == "code" and cells.grade_id(cell) else cell.get("id")
        if not wanted or wanted in seen:
            wanted = f"cell-{index:03d}"
        cell.id = wanted
        seen.add(wanted)
        if not cell.get("attachments"):
            cell.pop("attachments", None)
        if cell.cell_type != "code":
            continue
        outputs = []
        if cells.checks_output(cell):
            outputs = [o for o in (_clean_output(out) for out in cell.get("outputs", [])) if o]
        cell.outputs = outputs
        cell.execution_count = 1 if outputs else None
    return nb


def student_version(master: NotebookNode) -> NotebookNode:
    """The notebook students get for one master (see the module docstring)."""
    from nbgrader.preprocessors import (
        ClearHiddenTests,
        ClearMarkScheme,
        ClearOutput,
        ClearSolutions,
        ComputeChecksums,
        LockCells,
    )

    nb = normalize_master(master)
    nb.cells = [cell for cell in nb.cells if not cells.is_reader_only(cell)]
    for cell in nb.cells:
        cells.drop_giveaways(cell)
    resources = {}
    for preprocessor in (
        ClearSolutions(code_stub={"python": CODE_STUB}),
        ClearHiddenTests(),
        ClearMarkScheme(),
        ClearOutput(),
        LockCells(lock_solution_cells=False),
        ComputeChecksums(),
    ):
        nb, resources = preprocessor.preprocess(nb, resources)
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.execution_count = None
    return nb


def _support_files(solutions_dir):
    root = Path(solutions_dir) / SUPPORT_PACKAGE
    for path in sorted(root.rglob("*")):
        if path.is_file() and "__pycache__" not in path.parts and path.suffix != ".pyc":
            yield path.relative_to(solutions_dir)


def planned_files(solutions_dir: str | Path) -> dict[tuple[str, str], str]:
    """Map each generated file (relative path under course/ or solutions/) to its text."""
    solutions_dir = Path(solutions_dir)
    plan = {}
    for master_path in sorted(solutions_dir.glob("[0-9][0-9]_*.ipynb")):
        master = read_master(master_path)
        plan[("solutions", master_path.name)] = canonical_text(normalize_master(master))
        plan[("course", master_path.name)] = canonical_text(student_version(master))
    for relative in _support_files(solutions_dir):
        plan[("course", str(relative))] = (solutions_dir / relative).read_text(encoding="utf-8")
    return plan


def _target_dirs(solutions_dir, course_dir):
    return {"solutions": Path(solutions_dir), "course": Path(course_dir)}


def stale_files(solutions_dir: str | Path, course_dir: str | Path) -> list[tuple[str, str]]:
    """What release would change: a sorted list of (path, reason)."""
    dirs = _target_dirs(solutions_dir, course_dir)
    plan = planned_files(solutions_dir)
    problems = []
    for (where, relative), text in plan.items():
        path = dirs[where] / relative
        if not path.exists():
            problems.append((str(path), "missing"))
        elif path.read_text(encoding="utf-8") != text:
            problems.append((str(path), "differs from what release writes"))
    expected = {dirs["course"] / rel for (where, rel) in plan if where == "course"}
    for path in sorted(Path(course_dir).rglob("*")):
        if (
            path.is_file()
            and "__pycache__" not in path.parts
            and ".ipynb_checkpoints" not in path.parts
            and path not in expected
        ):
            problems.append((str(path), "not generated by release (remove it or add its master)"))
    return sorted(problems)


def release(solutions_dir: str | Path, course_dir: str | Path) -> list[str]:
    """Write ``course_dir`` (``course/``) from the masters in ``solutions_dir`` (and normalise the masters);
    return the list of files written."""
    dirs = _target_dirs(solutions_dir, course_dir)
    written = []
    for (where, relative), text in planned_files(solutions_dir).items():
        if write_if_changed(dirs[where] / relative, text):
            written.append(str(dirs[where] / relative))
    for path, reason in stale_files(solutions_dir, course_dir):
        if reason.startswith("not generated"):
            Path(path).unlink()
            written.append(f"{path} (removed)")
    for cache in Path(course_dir).rglob("__pycache__"):
        shutil.rmtree(cache, ignore_errors=True)
    return written
