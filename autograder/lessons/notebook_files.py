"""Read notebooks defensively and write them in one canonical form.

Submissions come from students: a file may be a symlink, a FIFO, a socket or
a device named like a notebook, huge, not UTF-8, not JSON, JSON nested
thousands of levels deep or made of millions of tiny lists, or JSON that is
not a notebook. :func:`read_submission` turns each of those into
:class:`UnreadableNotebook` with one sentence a student can act on; it opens
only regular files (:func:`read_regular_file`: never following a link, never
blocking), reads at most :data:`MAX_NOTEBOOK_BYTES`, and bounds what parsing
may build (:data:`MAX_CONTAINERS`, :data:`MAX_ITEMS`, :data:`MAX_NESTING`, :data:`MAX_CELLS`), so
one notebook costs the grader a bounded time and memory.
"""

from __future__ import annotations

import errno
import json
import os
import stat
from pathlib import Path

import nbformat

MAX_NOTEBOOK_BYTES = 20 * 1024 * 1024
MAX_CONTAINERS = 200_000  # JSON lists and objects (a lesson notebook has under 1,300, brackets in text included)
MAX_ITEMS = 1_000_000  # commas: JSON values and keys (a lesson notebook has under 10,000, commas in text included)
MAX_NESTING = 64  # levels of JSON (a lesson notebook has 7)
MAX_CELLS = 5_000  # a lesson notebook has under 100


class NotARegularFile(OSError):
    """A path that is a link, a FIFO, a socket, a device or a folder where a file was expected."""


def file_kind(mode: int) -> str:
    """What a file of ``mode`` (``st_mode``) is, in words: ``"a FIFO"``, ``"a symbolic link"``, ...

    Examples
    --------
    >>> file_kind(stat.S_IFIFO)
    'a FIFO (named pipe)'
    """
    kinds = (
        (stat.S_ISLNK, "a symbolic link"),
        (stat.S_ISDIR, "a folder"),
        (stat.S_ISFIFO, "a FIFO (named pipe)"),
        (stat.S_ISSOCK, "a socket"),
        (stat.S_ISCHR, "a character device"),
        (stat.S_ISBLK, "a block device"),
        (stat.S_ISREG, "a regular file"),
    )
    return next((words for test, words in kinds if test(mode)), "not a regular file")


def read_regular_file(path: str | os.PathLike, max_bytes: int) -> tuple[bytes, int]:
    """The first ``max_bytes`` bytes of a regular file, and its size; nothing else is ever opened.

    The file is opened with ``O_NOFOLLOW | O_NONBLOCK`` and checked with ``fstat`` on the open
    descriptor, so a symbolic link is refused, a FIFO, socket or device never blocks and is never read,
    and a file swapped after a check is caught.

    Returns
    -------
    (bytes, int)
        At most ``max_bytes`` bytes, and the file's size in bytes.

    Raises
    ------
    NotARegularFile
        ``path`` is a link, a FIFO, a socket, a device or a folder (``str(error)`` says which).
    OSError
        It cannot be opened or read.
    """
    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC | getattr(os, "O_NOCTTY", 0)
    info = os.lstat(path)
    if not stat.S_ISREG(info.st_mode):
        raise NotARegularFile(f"{Path(path).name} is {file_kind(info.st_mode)}, not a regular file")
    try:
        descriptor = os.open(path, flags)
    except OSError as error:
        if error.errno == errno.ELOOP:  # it became a link after the check
            raise NotARegularFile(f"{Path(path).name} is a symbolic link, not a regular file") from None
        raise
    try:
        info = os.fstat(descriptor)
        if not stat.S_ISREG(info.st_mode):
            raise NotARegularFile(f"{Path(path).name} is {file_kind(info.st_mode)}, not a regular file")
        chunks, left = [], max_bytes
        while left > 0:
            chunk = os.read(descriptor, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
        return b"".join(chunks), info.st_size
    finally:
        os.close(descriptor)


class UnreadableNotebook(Exception):
    """A submitted notebook that cannot be graded; ``str(error)`` says why."""


def read_submission(
    path: str | os.PathLike, root: str | os.PathLike | None = None, max_bytes: int = MAX_NOTEBOOK_BYTES
) -> nbformat.NotebookNode:
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
    if root is not None:
        real_root = Path(root).resolve()
        if real_root not in path.resolve().parents:
            raise UnreadableNotebook(f"{path.name} lies outside the submission folder")
    try:
        raw, size = read_regular_file(path, max_bytes + 1)
    except NotARegularFile as error:
        raise UnreadableNotebook(f"{error}; submit the notebook file itself") from None
    except OSError as error:
        raise UnreadableNotebook(f"cannot read {path.name}: {error.strerror or error}") from None
    if size > max_bytes or len(raw) > max_bytes:
        raise UnreadableNotebook(
            f"{path.name} is {max(size, len(raw)) / 2**20:.0f} MB, over the {max_bytes / 2**20:.0f} MB limit "
            "(clear large outputs with Edit → Clear Outputs of All Cells, save, resubmit)"
        )
    return parse_notebook(raw, path.name)


def _nesting(data):
    """How many levels of lists and objects ``data`` holds (iteratively: any depth costs no stack)."""
    deepest, stack = 0, [(data, 1)]
    while stack:
        value, level = stack.pop()
        if isinstance(value, dict):
            value = value.values()
        elif not isinstance(value, list):
            continue
        deepest = max(deepest, level)
        if deepest > MAX_NESTING:
            break
        stack.extend((item, level + 1) for item in value if isinstance(item, (dict, list)))
    return deepest


def _damaged(name, what):
    return UnreadableNotebook(
        f"{name} {what}; the file was damaged or not written by Jupyter "
        "(clear outputs, save it from Jupyter and resubmit)"
    )


def parse_notebook(raw: bytes, name: str = "notebook") -> nbformat.NotebookNode:
    """Parse notebook bytes (see :func:`read_submission` for the errors)."""
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as error:
        raise UnreadableNotebook(
            f"{name} is not UTF-8 text (bad byte at position {error.start}); was it saved by Jupyter?"
        ) from None
    containers, items = raw.count(b"[") + raw.count(b"{"), raw.count(b",")
    if containers > MAX_CONTAINERS:  # counted on the bytes: what parsing would build is bounded before it starts
        raise _damaged(
            name,
            f"holds {containers:,} JSON lists and objects (a notebook needs a few hundred, "
            f"at most {MAX_CONTAINERS:,} are read)",
        )
    if items > MAX_ITEMS:
        raise _damaged(
            name, f"holds {items:,} JSON values (a notebook needs a few thousand, at most {MAX_ITEMS:,} are read)"
        )
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise UnreadableNotebook(
            f"{name} is not valid JSON (line {error.lineno}, column {error.colno}: {error.msg}); "
            "the file was damaged, perhaps by editing it as text"
        ) from None
    except (RecursionError, MemoryError):
        raise _damaged(name, f"nests its JSON deeper than the {MAX_NESTING} levels read") from None
    if _nesting(data) > MAX_NESTING:
        raise _damaged(name, f"nests its JSON deeper than the {MAX_NESTING} levels read (a notebook needs about 7)")
    if not isinstance(data, dict) or not isinstance(data.get("cells"), list):
        raise UnreadableNotebook(f"{name} is JSON but not a Jupyter notebook (no list of cells)")
    if data.get("nbformat") != 4:
        raise UnreadableNotebook(
            f"{name} has notebook format {data.get('nbformat')!r}; save it with a current Jupyter (format 4)"
        )
    if not isinstance(data.get("metadata", {}), dict):
        data["metadata"] = {}
    if len(data["cells"]) > MAX_CELLS:
        raise _damaged(name, f"has {len(data['cells']):,} cells (at most {MAX_CELLS:,} are read)")
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


def read_master(path: str | os.PathLike) -> nbformat.NotebookNode:
    """Read a notebook we wrote ourselves (masters, released notebooks)."""
    return nbformat.read(str(path), as_version=4)


def canonical_text(nb: nbformat.NotebookNode) -> str:
    """The exact text we commit for a notebook: sorted keys, one-space indent, final newline."""
    text = nbformat.writes(nb)
    return text if text.endswith("\n") else text + "\n"


def write_if_changed(path: str | os.PathLike, text: str) -> bool:
    """Write ``text`` to ``path`` unless it already holds it; return True if written."""
    path = Path(path)
    if path.exists() and path.read_text(encoding="utf-8") == text:
        return False
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)
    return True
