"""Read notebooks defensively and write them in one canonical form.

Submissions come from students: a file may be a symlink, huge, not UTF-8,
not JSON, or JSON that is not a notebook. :func:`read_submission` turns each
of those into :class:`UnreadableNotebook` with one sentence a student can act
on, and never follows a link out of the submission.
"""

import json
import os
import stat
from pathlib import Path

import nbformat

MAX_NOTEBOOK_BYTES = 20 * 1024 * 1024


class UnreadableNotebook(Exception):
    """A submitted notebook that cannot be graded; ``str(error)`` says why."""


def read_submission(path, root=None, max_bytes=MAX_NOTEBOOK_BYTES):
    """Read a student's notebook, or raise :class:`UnreadableNotebook`.

    Parameters
    ----------
    path : path-like
        The notebook file.
    root : path-like, optional
        The student's submission folder; ``path`` must resolve inside it.
    max_bytes : int
        Larger files are refused.

    Returns
    -------
    nbformat.NotebookNode
        A version-4 notebook whose cells all have ``cell_type`` and ``source``.
    """
    path = Path(path)
    try:
        info = os.lstat(path)
    except OSError as error:
        raise UnreadableNotebook(f"cannot open {path.name}: {error.strerror}") from None
    if stat.S_ISLNK(info.st_mode):
        raise UnreadableNotebook(f"{path.name} is a symbolic link; submit the notebook file itself")
    if not stat.S_ISREG(info.st_mode):
        raise UnreadableNotebook(f"{path.name} is not a regular file")
    if root is not None:
        real_root = Path(root).resolve()
        if real_root not in path.resolve().parents:
            raise UnreadableNotebook(f"{path.name} lies outside the submission folder")
    if info.st_size > max_bytes:
        raise UnreadableNotebook(
            f"{path.name} is {info.st_size / 2**20:.0f} MB, over the {max_bytes / 2**20:.0f} MB limit "
            "(clear large outputs with Edit → Clear Outputs of All Cells, save, resubmit)")
    try:
        with open(path, "rb") as handle:
            raw = handle.read(max_bytes + 1)
    except OSError as error:
        raise UnreadableNotebook(f"cannot read {path.name}: {error.strerror}") from None
    return parse_notebook(raw, path.name)


def parse_notebook(raw, name="notebook"):
    """Parse notebook bytes (see :func:`read_submission` for the errors)."""
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as error:
        raise UnreadableNotebook(
            f"{name} is not UTF-8 text (bad byte at position {error.start}); "
            "was it saved by Jupyter?") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise UnreadableNotebook(
            f"{name} is not valid JSON (line {error.lineno}, column {error.colno}: {error.msg}); "
            "the file was damaged, perhaps by editing it as text") from None
    if not isinstance(data, dict) or not isinstance(data.get("cells"), list):
        raise UnreadableNotebook(f"{name} is JSON but not a Jupyter notebook (no list of cells)")
    if data.get("nbformat") != 4:
        raise UnreadableNotebook(
            f"{name} has notebook format {data.get('nbformat')!r}; save it with a current Jupyter (format 4)")
    for index, cell in enumerate(data["cells"]):
        if not isinstance(cell, dict) or cell.get("cell_type") not in ("code", "markdown", "raw"):
            raise UnreadableNotebook(f"{name}: cell {index + 1} is damaged (no valid cell_type)")
        source = cell.get("source", "")
        if isinstance(source, list):
            if not all(isinstance(line, str) for line in source):
                raise UnreadableNotebook(f"{name}: cell {index + 1} has a damaged source")
            cell["source"] = "".join(source)
        elif not isinstance(source, str):
            raise UnreadableNotebook(f"{name}: cell {index + 1} has a damaged source")
        if not isinstance(cell.get("metadata", {}), dict):
            cell["metadata"] = {}
    return nbformat.from_dict(data)


def read_master(path):
    """Read a notebook we wrote ourselves (masters, released notebooks)."""
    return nbformat.read(str(path), as_version=4)


def canonical_text(nb):
    """The exact text we commit for a notebook: sorted keys, one-space indent, final newline."""
    text = nbformat.writes(nb)
    return text if text.endswith("\n") else text + "\n"


def write_if_changed(path, text):
    """Write ``text`` to ``path`` unless it already holds it; return True if written."""
    path = Path(path)
    if path.exists() and path.read_text(encoding="utf-8") == text:
        return False
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)
    return True
