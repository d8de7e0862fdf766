"""Find students and their notebooks in a folder of submissions.

Two layouts are understood:

- one folder per student: ``PATH/<student_id>/01_frames_and_rotations.ipynb``;
- nbgrader's: ``PATH/submitted/<student_id>/<assignment>/01_....ipynb`` (PATH may
  also be the ``submitted`` folder itself, or an nbgrader course root).

A notebook is matched to a lesson by its content (:func:`match_lessons`):
the ``grade_id`` of its answer cells, or the ``def`` of the lesson's
exercises, whatever the file is called (``dan_exp_log_final.ipynb``). When
several notebooks match one lesson, the one holding the most of the
student's own work is graded and the choice is explained; notebooks that
match no lesson are listed. A notebook that cannot be read at all is matched
by its file name (or its ``NN_`` prefix), so its reason reaches the student.

Whatever a folder holds, looking at it costs a bounded time and memory and
never blocks: symbolic links are never followed, only regular files are
opened (:func:`~autograder.lessons.notebook_files.read_regular_file`), walks
are iterative and bounded (:func:`scan_folder`), and a notebook that cannot
be read or parsed costs that notebook only. Everything skipped is listed with
why (:class:`Skipped`): hidden entries, links, stray files at the top of the
submissions folder, folders deeper than the search depth.
"""

from __future__ import annotations

import ast
import hashlib
import os
import re
import stat
from datetime import datetime, timezone
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Callable

import nbformat
from dateutil import parser as date_parser

from autograder.lessons import cells
from autograder.lessons.catalog import Catalog
from autograder.lessons.notebook_files import (
    MAX_NOTEBOOK_BYTES,
    UnreadableNotebook,
    file_kind,
    read_master,
    read_regular_file,
    read_submission,
)

MAX_DEPTH = 2  # folders searched below a student's folder
MAX_ENTRIES = 10_000  # entries looked at in one student's folder, all levels together
MAX_NOTEBOOKS = 50  # notebooks read per student (a course has 9)
MAX_SKIPPED_LISTED = 50  # skipped entries listed one by one per student; the rest are counted


@dataclass(frozen=True)
class Skipped:
    """Something the grader saw and did not use: ``path`` (as found, relative) and ``why``."""

    path: str
    why: str

    def line(self) -> str:
        return f"{self.path}: {self.why}"


@dataclass
class Found:
    """What a folder holds for the grader: the files it asked for, and what it skipped with why."""

    files: list = field(default_factory=list)  # Paths
    skipped: list = field(default_factory=list)  # Skipped


def _top_level_why(entry):
    """Why an entry of the submissions folder is not a student, or ``None`` when it is one."""
    if entry.name.startswith("."):
        return "hidden (its name starts with a dot): not graded"
    try:
        mode = entry.stat(follow_symlinks=False).st_mode
    except OSError as error:
        return f"cannot be read ({error.strerror}): not graded"
    if stat.S_ISDIR(mode):
        return None
    if stat.S_ISLNK(mode):
        return "a symbolic link: links are never followed, not graded"
    return f"{file_kind(mode)}, not a student folder (each student's notebooks go in a folder of their own)"


def scan_submissions(path: str | Path) -> Found:
    """The students under ``path`` and what was skipped there (see the module docstring).

    Returns
    -------
    Found
        ``files``: sorted ``[(student_id, folder)]``; ``skipped``: hidden entries, links, stray files.
    """
    path = Path(path)
    if (path / "submitted").is_dir() and not (path / "submitted").is_symlink():
        path = path / "submitted"
    found = Found()
    with os.scandir(path) as entries:
        for entry in sorted(entries, key=lambda e: e.name):
            why = _top_level_why(entry)
            if why is None:
                found.files.append((entry.name, Path(entry.path)))
            else:
                found.skipped.append(Skipped(entry.name, why))
    return found


def student_folders(path: str | Path) -> list[Path]:
    """Sorted ``[(student_id, folder)]`` under ``path`` (see the module docstring)."""
    return scan_submissions(path).files


def is_notebook_name(name: str) -> bool:
    return name.endswith(".ipynb") and not name.startswith(".")


def _listing(directory, budget, wanted, max_files):
    """The entries of one folder, sorted by name: the first ``budget`` of any kind, and beyond them
    at most ``max_files`` more that ``wanted`` accepts or that are folders (so a flood of files cannot
    hide the notebooks); and how many were passed over."""
    entries, extra, passed_over = [], 0, 0
    with os.scandir(directory) as scan:
        for entry in scan:
            if len(entries) < budget:
                entries.append(entry)
            elif extra < max_files and (wanted(entry.name) or _is_folder(entry)):
                entries.append(entry)
                extra += 1
            else:
                passed_over += 1
    return sorted(entries, key=lambda e: e.name), passed_over


def _is_folder(entry):
    try:
        return entry.is_dir(follow_symlinks=False)
    except OSError:
        return False


def scan_folder(
    folder: Path, wanted: Callable[[str], bool] = is_notebook_name, max_files: int = MAX_NOTEBOOKS
) -> Found:
    """The files of a student's ``folder`` that ``wanted(name)`` accepts, and everything skipped, with why.

    The walk is iterative and bounded: :data:`MAX_DEPTH` folders down, :data:`MAX_ENTRIES` entries and
    ``max_files`` wanted files in all. Links are never followed (a link named like a wanted file is
    returned, so that reading it can say why it is refused); hidden folders and hidden notebooks, links
    to folders, folders too deep, folders that cannot be read and what is over a bound are listed in
    ``skipped``. Files are in the order of a top-down walk with sorted names.

    Examples
    --------
    >>> found = scan_folder(Path("class/dan"))                               # doctest: +SKIP
    >>> [p.name for p in found.files], [s.line() for s in found.skipped]
    (['dan_exp_log_final.ipynb'], ['.ipynb_checkpoints/: a hidden folder, not searched'])
    """
    folder = Path(folder)
    found, budget = Found(), MAX_ENTRIES
    stack = [(folder, 0)]
    while stack:
        directory, depth = stack.pop()
        relative = directory.relative_to(folder).as_posix() + "/" if directory != folder else ""
        try:
            entries, passed_over = _listing(directory, max(budget, 0), wanted, max_files)
        except OSError as error:
            found.skipped.append(Skipped(relative or "./", f"cannot be read ({error.strerror}), not searched"))
            continue
        budget -= len(entries)
        if passed_over:
            found.skipped.append(
                Skipped(
                    relative or "./",
                    f"more than {MAX_ENTRIES:,} entries in the submission: "
                    f"past them only notebooks and folders were looked at, "
                    f"{passed_over:,} other entries were not",
                )
            )
        subfolders = []
        for entry in entries:
            name = f"{relative}{entry.name}"
            try:
                is_link, is_dir = entry.is_symlink(), entry.is_dir(follow_symlinks=False)
            except OSError as error:
                found.skipped.append(Skipped(name, f"cannot be read ({error.strerror})"))
                continue
            if entry.name.startswith("."):
                if is_dir or entry.name.endswith(".ipynb"):
                    what = "a hidden folder, not searched" if is_dir else "a hidden notebook, not graded"
                    found.skipped.append(Skipped(name + ("/" if is_dir else ""), what))
            elif is_dir:
                if depth < MAX_DEPTH:
                    subfolders.append(Path(entry.path))
                else:
                    found.skipped.append(
                        Skipped(name + "/", f"deeper than {MAX_DEPTH} folders below the student's folder, not searched")
                    )
            elif wanted(entry.name):
                if len(found.files) < max_files:
                    found.files.append(Path(entry.path))
                else:
                    found.skipped.append(Skipped(name, f"not read: at most {max_files} notebooks are read per student"))
            elif is_link:
                found.skipped.append(Skipped(name, "a symbolic link, not followed"))
        stack.extend((sub, depth + 1) for sub in reversed(subfolders))
    if len(found.skipped) > MAX_SKIPPED_LISTED:
        more = len(found.skipped) - MAX_SKIPPED_LISTED
        found.skipped[MAX_SKIPPED_LISTED:] = [Skipped("…", f"and {more:,} more entries skipped as above")]
    return found


def files_in(folder: Path, wanted: Callable[[str], bool]) -> list[Path]:
    """Paths of the files (and links) whose name ``wanted(name)`` accepts (see :func:`scan_folder`)."""
    return scan_folder(folder, wanted).files


def notebooks_in(folder: Path) -> list[Path]:
    """Regular ``.ipynb`` files and links to them up to two levels down, as paths."""
    return scan_folder(folder).files


@dataclass
class LessonFiles:
    """Which file of a submission is graded for each lesson, and what was left over."""

    chosen: dict = field(default_factory=dict)  # lesson number -> Path
    notes: dict = field(default_factory=dict)  # lesson number -> why this file among several
    unmatched: list = field(default_factory=list)  # Paths of notebooks that belong to no graded lesson
    unreadable: dict = field(default_factory=dict)  # Path -> why it could not be read (unmatched or chosen)
    skipped: list = field(default_factory=list)  # Skipped: what the walk of the folder did not use


def _fingerprint(source):
    """A short digest of a cell's source, whitespace normalised: what "is this the stub?" compares."""
    text = re.sub(r"\s+", " ", source or "").strip()
    return hashlib.sha256(text.encode("utf-8", "surrogatepass")).digest()


@lru_cache(maxsize=None)
def _stubs(released, filename):
    """``{exercise: fingerprint of its answer cell}`` in the released notebook (untouched work)."""
    try:
        nb = read_master(Path(released) / filename)
    except OSError:
        return {}
    return {cells.grade_id(c): _fingerprint(cells.source_text(c)) for c in nb.cells if cells.is_answer_cell(c)}


_DEFINED = {}  # sha256 of a cell's exact source -> the functions it defines (cells repeat across students)
MAX_REMEMBERED = 4096


def _defined_functions(source):
    """Names of the functions ``source`` defines at top level (``()`` if it cannot be parsed), parsed once per
    distinct text: the released cells every student kept, and answers handed in alike, are not parsed again.
    Only a digest of the text is kept, so a large cell is not held in memory.

    >>> _defined_functions("def f(x):\\n    return x\\n\\ndef g():\\n    pass\\n")
    ('f', 'g')
    """
    if "def" not in source:
        return ()
    key = hashlib.sha256(source.encode("utf-8", "surrogatepass")).digest()
    if key not in _DEFINED:
        tree = cells.parse_source(source)
        if len(_DEFINED) >= MAX_REMEMBERED:
            _DEFINED.clear()
        _DEFINED[key] = tuple(node.name for node in tree.body if isinstance(node, ast.FunctionDef)) if tree else ()
    return _DEFINED[key]


def _code_cells(nb):
    """``[(grade_id, fingerprint of the source, names of the functions it defines)]`` for a notebook's code
    cells, check cells excepted; each distinct cell text is parsed once (and only if it can define a
    function). Only fingerprints are kept, so a student's megabytes of source are not held while others
    are read."""
    found = []
    for cell in nb.cells:
        if cell.get("cell_type") != "code" or cells.is_check_cell(cell):
            continue
        source = cells.source_text(cell)
        found.append((cells.grade_id(cell), _fingerprint(source), _defined_functions(source)))
    return found


def _answers(code_cells, names):
    """``{exercise: fingerprint}`` for the exercises of ``names`` these cells hold (by grade_id, else by def)."""
    found = {}
    for grade_id, fingerprint, defined in code_cells:
        if grade_id in names:
            found[grade_id] = fingerprint
            continue
        for name in defined:
            if name in names:
                found.setdefault(name, fingerprint)
    return found


def _name_matches(path, lesson):
    return path.name == lesson.filename or path.name.startswith(lesson.number + "_")


def match_lessons(
    folder: Path,
    catalog: Catalog,
    released: Path,
    notebooks: list[Path] | None = None,
    read: Callable[[Path], nbformat.NotebookNode] | None = None,
) -> LessonFiles:
    """Match the notebooks of one student's ``folder`` to ``catalog``'s graded lessons, by content.

    ``released``: the folder of the released notebooks (``course.released``), whose answer cells tell
    untouched stubs from work.

    ``read(path)``: how a notebook is read (default :func:`read_submission` inside ``folder``); a caller
    that reads the chosen notebooks again passes a memoising one, so each file is parsed once.

    Returns
    -------
    LessonFiles
        ``chosen[number]`` is the file to grade for a lesson (absent: the lesson is missing).

    Examples
    --------
    >>> files = match_lessons(Path("class/dan"), course.catalog, course.released)  # doctest: +SKIP
    >>> files.chosen["03"].name, files.unmatched
    ('dan_exp_log_final.ipynb', [])
    """
    folder = Path(folder)
    skipped = []
    if notebooks is None:
        scan = scan_folder(folder)
        notebooks, skipped = scan.files, scan.skipped
    lessons = catalog.graded_lessons
    read = read or (lambda path: read_submission(path, root=folder))
    readable, unreadable = {}, {}
    for path in notebooks:
        try:
            readable[path] = _code_cells(read(path))
        except UnreadableNotebook as error:
            unreadable[path] = str(error)
        except Exception as error:  # anything else costs this notebook only
            unreadable[path] = f"the grader could not read it ({type(error).__name__}: {error})"
    files = LessonFiles(skipped=skipped, unreadable=unreadable)
    claimed = set()
    for lesson in lessons:
        names = {e.name for e in lesson.exercises}
        stubs = _stubs(released, lesson.filename)
        candidates = []
        for path, code_cells in readable.items():
            answers = _answers(code_cells, names)
            if answers:
                work = sum(1 for name, fingerprint in answers.items() if fingerprint != stubs.get(name))
                candidates.append((work, len(answers), path.name == lesson.filename, path))
        if not candidates:  # only a damaged file under the lesson's name: grade it, so its reason is shown
            damaged = [p for p in unreadable if _name_matches(p, lesson)]
            if damaged:
                files.chosen[lesson.number] = damaged[0]
                claimed.add(damaged[0])
            continue
        candidates.sort(key=lambda c: (c[0], c[1], c[2], str(c[3])), reverse=True)
        best = candidates[0]
        files.chosen[lesson.number] = best[3]
        claimed.update(c[3] for c in candidates)
        if len(candidates) > 1:
            others = ", ".join(f"{c[3].relative_to(folder)} ({_work(c[0])})" for c in candidates[1:])
            files.notes[lesson.number] = (
                f"several notebooks hold lesson {lesson.number}: graded "
                f"{best[3].relative_to(folder)} ({_work(best[0])}); not graded: {others}"
            )
    ungraded = {lesson.filename for lesson in catalog.lessons if not lesson.exercises}
    files.unmatched = [p for p in notebooks if p not in claimed and p.name not in ungraded]
    return files


def _work(count):
    return "no answer written" if count == 0 else f"{count} answer{'s' if count > 1 else ''} written"


NBGRADER_TIMESTAMP = "timestamp.txt"


def handed_in_at(notebook: Path, folder: Path) -> datetime | None:
    """When ``notebook`` (under the student's ``folder``) was handed in, from one trusted source, or ``None``.

    - nbgrader's ``timestamp.txt`` at the top level of the submission, ``folder/<assignment>/timestamp.txt``
      (where ``nbgrader collect`` writes it), for a notebook anywhere under ``<assignment>/``;
    - else the notebook file's modification time as collected (an LMS download, a copied class).

    A ``timestamp.txt`` anywhere else (beside a notebook in a deeper folder, or in the student's folder itself,
    which in the one-folder-per-student layout holds only what the student handed in) is the student's file
    and never read. A damaged or linked ``timestamp.txt`` falls back on the file's time.

    Examples
    --------
    >>> handed_in_at(Path("submitted/ana/lesson03/03_exp_and_log.ipynb"), Path("submitted/ana"))  # doctest: +SKIP
    datetime.datetime(2026, 12, 1, 22, 10, 3, tzinfo=datetime.timezone.utc)
    """
    return nbgrader_timestamp(notebook, folder) or collected_time(notebook)


def nbgrader_timestamp(notebook: Path, folder: Path) -> datetime | None:
    """The time in ``folder/<assignment>/timestamp.txt`` for a notebook under ``<assignment>/`` (see
    :func:`handed_in_at`), or ``None`` when there is none, it is not a regular file, or it cannot be read."""
    notebook, folder = Path(notebook), Path(folder)
    try:
        parts = notebook.relative_to(folder).parts
    except ValueError:
        return None
    if len(parts) < 2:
        return None
    stamp = folder / parts[0] / NBGRADER_TIMESTAMP
    try:
        if stat.S_ISREG(os.lstat(stamp).st_mode):
            text = read_regular_file(stamp, 200)[0].decode("utf-8", "replace").strip()[:100]
            moment = date_parser.parse(text)
            return moment if moment.tzinfo else moment.replace(tzinfo=timezone.utc)
    except (OSError, ValueError, OverflowError, UnreadableNotebook):
        pass  # absent or damaged: the caller falls back on the file's own time
    return None


def collected_time(notebook: Path) -> datetime | None:
    """The modification time of ``notebook`` as collected (aware, UTC), or ``None`` when it cannot be read."""
    try:
        return datetime.fromtimestamp(os.lstat(notebook).st_mtime, tz=timezone.utc)
    except (OSError, ValueError, OverflowError):
        return None


def submission_hash(folder: str | Path) -> str:
    """SHA-256 over the names, bytes and hand-in times (:func:`handed_in_at`) of every notebook of a student
    (links by their target text), so a corrected hand-in time re-grades the student like changed bytes.

    Only regular files are read, at most :data:`MAX_NOTEBOOK_BYTES` + 1 bytes each (a larger one is
    refused whole, so what lies beyond cannot change its grade); a FIFO, socket or device is hashed by
    its kind. It never blocks and never raises for what the folder holds.
    """
    digest = hashlib.sha256()
    folder = Path(folder)
    for path in notebooks_in(folder):
        digest.update(str(path.relative_to(folder)).encode("utf-8", "surrogatepass") + b"\0")
        try:
            mode = os.lstat(path).st_mode
            if stat.S_ISLNK(mode):
                digest.update(b"link:" + os.fsencode(os.readlink(path)))
            elif stat.S_ISREG(mode):
                digest.update(read_regular_file(path, MAX_NOTEBOOK_BYTES + 1)[0])
            else:
                digest.update(f"kind:{file_kind(mode)}".encode())
        except OSError as error:
            digest.update(f"unreadable:{error.errno}".encode())
        moment = handed_in_at(path, folder)
        digest.update(b"\0" + (moment.isoformat() if moment else "no time").encode())
        digest.update(b"\0")
    return digest.hexdigest()
