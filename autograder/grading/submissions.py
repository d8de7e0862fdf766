"""Find students and their notebooks in a folder of submissions.

Two layouts are understood:

- one folder per student: ``PATH/<student_id>/01_frames_and_rotations.ipynb``;
- nbgrader's: ``PATH/submitted/<student_id>/<assignment>/01_....ipynb`` (PATH may
  also be the ``submitted`` folder itself, or an nbgrader course root).

The class is read one way, from what the instructor controls (:func:`detect_layout`): the layout
declared (``grade --layout``), else nbgrader's only when its course root says so (a regular
``nbgrader_config.py`` or ``gradebook.db`` beside ``submitted/``). No student's folder name or content
changes how another student is found or dated. Each student's folder is read once, into one frozen
:class:`StudentFolder` (its notebooks' bytes, what was skipped, the hand-in times, their digest) that
grading, the late policy and the saved result all use.

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
    NotARegularFile,
    UnreadableNotebook,
    file_kind,
    parse_notebook,
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
    layout: ClassLayout | None = None  # scan_submissions: how the class was read


FOLDERS, NBGRADER = "folders", "nbgrader"
LAYOUTS = (FOLDERS, NBGRADER)
NBGRADER_MARKERS = ("nbgrader_config.py", "gradebook.db")  # regular files of nbgrader's course root


@dataclass(frozen=True)
class ClassLayout:
    """How a class is read: ``kind`` (:data:`FOLDERS` or :data:`NBGRADER`), the folder whose folders are the
    students (``root``), and why this layout was chosen (``why``, one sentence for the run's first lines)."""

    kind: str
    root: Path
    why: str

    def line(self) -> str:
        """``layout: nbgrader (nbgrader_config.py beside submitted/): the students are the folders of …``"""
        return f"layout: {self.kind} ({self.why}); the students are the folders of {self.root}"


def _marker(folder):
    """The first of :data:`NBGRADER_MARKERS` that is a regular file (not a link, not a folder) in ``folder``."""
    for name in NBGRADER_MARKERS:
        try:
            if stat.S_ISREG(os.lstat(Path(folder) / name).st_mode):
                return name
        except OSError:
            continue
    return None


def _real_folder(path):
    try:
        return stat.S_ISDIR(os.lstat(path).st_mode)
    except OSError:
        return False


def detect_layout(path: str | Path, declared: str | None = None) -> ClassLayout:
    """The layout of the class under ``path``: the one the instructor ``declared`` (``grade --layout``), else
    read from markers no student can make.

    A student controls the name and the contents of their own folder only, so neither decides the layout:
    nbgrader's layout is recognised by its course root, a regular ``nbgrader_config.py`` or ``gradebook.db``
    beside ``submitted/`` (``path`` is that root, or its ``submitted`` folder). Anything else is one folder
    per student, where a folder named ``submitted`` is a student like any other.

    Examples
    --------
    >>> detect_layout(Path("nbgrader-course")).line()                                    # doctest: +SKIP
    'layout: nbgrader (nbgrader_config.py beside submitted/); the students are the folders of nbgrader-course/submitted'
    >>> detect_layout(Path("class"), declared="folders").kind                             # doctest: +SKIP
    'folders'
    """
    path = Path(path)
    submitted = path / "submitted"
    if declared is not None and declared not in LAYOUTS:
        raise ValueError(f"unknown layout {declared!r} (known: {', '.join(LAYOUTS)})")
    if declared == FOLDERS:
        return ClassLayout(FOLDERS, path, "declared with --layout folders")
    if declared == NBGRADER:
        inside = _real_folder(submitted) and path.name != "submitted"
        return ClassLayout(NBGRADER, submitted if inside else path, "declared with --layout nbgrader")
    marker = _marker(path)
    if marker and _real_folder(submitted):
        return ClassLayout(NBGRADER, submitted, f"nbgrader's course root: {marker} beside submitted/")
    marker = _marker(path.parent) if path.name == "submitted" else None
    if marker:
        return ClassLayout(NBGRADER, path, f"the submitted/ folder of nbgrader's course root ({marker} beside it)")
    why = "no nbgrader course root (nbgrader_config.py or gradebook.db beside submitted/)"
    if _real_folder(submitted):
        why += "; submitted/ is graded as a student: give --layout nbgrader if it is nbgrader's"
    return ClassLayout(FOLDERS, path, why)


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


def scan_submissions(path: str | Path | ClassLayout, layout: str | ClassLayout | None = None) -> Found:
    """The students under ``path`` and what was skipped there (see the module docstring).

    ``layout``: the layout the instructor declared (``"folders"``, ``"nbgrader"``), a :class:`ClassLayout`
    already decided, or None to detect it from markers no student can make (:func:`detect_layout`). ``path``
    may be a :class:`ClassLayout` itself, so a later stage reads the class exactly as grading did.

    Returns
    -------
    Found
        ``files``: sorted ``[(student_id, folder)]``; ``skipped``: hidden entries, links, stray files;
        ``layout``: the :class:`ClassLayout` it was read with.
    """
    if isinstance(path, ClassLayout):  # a class already read (the batch hands its layout to later stages)
        path, layout = path.root, path
    chosen = layout if isinstance(layout, ClassLayout) else detect_layout(path, layout)
    found = Found(layout=chosen)
    with os.scandir(chosen.root) as entries:
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
    student: StudentFolder | None = None,
) -> LessonFiles:
    """Match the notebooks of one student's ``folder`` to ``catalog``'s graded lessons, by content.

    ``released``: the folder of the released notebooks (``course.released``), whose answer cells tell
    untouched stubs from work.

    ``read(path)``: how a notebook is read (default :func:`read_submission` inside ``folder``); a caller
    that reads the chosen notebooks again passes a memoising one, so each file is parsed once.

    ``student``: the folder as read once (:func:`read_student_folder`): its notebooks and bytes are used, the
    folder is not walked again.

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
    if student is not None:
        notebooks, skipped, read = student.notebook_paths, list(student.skipped), read or student.read
    elif notebooks is None:
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
EARLIEST = datetime(1970, 1, 1, tzinfo=timezone.utc)  # hand-in times are read in [EARLIEST, LATEST)
LATEST = datetime(2200, 1, 1, tzinfo=timezone.utc)
MAX_TIMESTAMP_BYTES = 200  # nbgrader writes one line of about 30 bytes
HELD_BYTES = 256 * 1024 * 1024  # notebook bytes a StudentFolder holds; past it, a notebook is read again and checked


@dataclass(frozen=True)
class HandIn:
    """When a notebook was handed in: ``moment`` (aware, UTC, within 1970..2200) and where it came from
    (``source``: ``"timestamp.txt"`` or ``"file time"``), or ``moment`` None and why (``problem``)."""

    moment: datetime | None = None
    source: str = ""
    problem: str = ""


def bounded_time(moment: datetime, what: str) -> HandIn:
    """``moment`` as a :class:`HandIn` in UTC when it lies in 1970..2200 (naive: UTC), else refused with why.

    >>> bounded_time(datetime(9999, 12, 31), "timestamp.txt").problem
    'timestamp.txt says 9999-12-31 00:00:00, outside 1970..2200: lateness unknown'
    """
    try:
        aware = (
            moment
            if moment.tzinfo is not None and moment.utcoffset() is not None
            else moment.replace(tzinfo=timezone.utc)
        )
        if EARLIEST <= aware < LATEST:
            return HandIn(aware.astimezone(timezone.utc), what)
    except (ValueError, OverflowError, TypeError, ArithmeticError):
        pass
    return HandIn(None, what, f"{what} says {str(moment)[:60]}, outside 1970..2200: lateness unknown")


def parse_hand_in_time(text: str, what: str = NBGRADER_TIMESTAMP) -> HandIn:
    """A time written as text (nbgrader's ``2026-12-01 10:00:00.000000 UTC``), bounded, or refused with why.

    >>> parse_hand_in_time("2026-12-01 10:00:00.000000 UTC").moment.isoformat()
    '2026-12-01T10:00:00+00:00'
    >>> parse_hand_in_time("soon").problem[:40]
    "timestamp.txt holds no date ('soon'): la"
    """
    text = text.strip()[:100]
    try:
        moment = date_parser.parse(text)
    except (ValueError, OverflowError, TypeError, ArithmeticError, LookupError):
        return HandIn(None, what, f"{what} holds no date ({text[:40]!r}): lateness unknown")
    return bounded_time(moment, what)


def _timestamp_of(folder):
    """nbgrader's hand-in time in ``folder/timestamp.txt``: a :class:`HandIn`, or None when there is none."""
    stamp = Path(folder) / NBGRADER_TIMESTAMP
    try:
        os.lstat(stamp)
    except OSError:
        return None
    try:
        raw, size = read_regular_file(stamp, MAX_TIMESTAMP_BYTES + 1)
    except OSError as error:
        return HandIn(None, NBGRADER_TIMESTAMP, f"{NBGRADER_TIMESTAMP} cannot be read ({error}): lateness unknown")
    if size > MAX_TIMESTAMP_BYTES or len(raw) > MAX_TIMESTAMP_BYTES:
        return HandIn(
            None, NBGRADER_TIMESTAMP, f"{NBGRADER_TIMESTAMP} is {size:,} bytes, not one line: lateness unknown"
        )
    return parse_hand_in_time(raw.decode("utf-8", "replace"))


def _file_time(info):
    """The modification time of ``info`` (an ``lstat`` result) as collected, bounded."""
    seconds = info.st_mtime
    if not EARLIEST.timestamp() <= seconds < LATEST.timestamp():
        return HandIn(None, "file time", f"its file time ({seconds:.6g} s after 1970) is outside 1970..2200")
    return HandIn(datetime.fromtimestamp(seconds, tz=timezone.utc), "file time")


@dataclass(frozen=True)
class NotebookFile:
    """One notebook of a :class:`StudentFolder`, read once: its bytes (``data``, None when it cannot be used or
    is not held), or why it cannot be used (``problem``); nbgrader's ``recorded`` time and the file's ``collected``
    time (:class:`HandIn`)."""

    path: Path
    relative: str
    data: bytes | None
    problem: str
    sha256: bytes
    recorded: HandIn | None
    collected: HandIn


@dataclass(frozen=True)
class StudentFolder:
    """Everything the grader uses of one student's folder, read in one walk (:func:`read_student_folder`):
    the notebooks' bytes, what the walk skipped, the hand-in times and the digest of it all. Grading, the
    late policy and the saved result all use this one value, so what was graded is what was hashed and dated.

    Examples
    --------
    >>> student = read_student_folder(Path("class/dan"), FOLDERS, "dan")             # doctest: +SKIP
    >>> [n.relative for n in student.notebooks], student.digest[:8]
    (['dan_exp_log_final.ipynb'], '3f0c9a1e')
    """

    student_id: str
    path: Path
    layout: str
    notebooks: tuple[NotebookFile, ...]
    skipped: tuple[Skipped, ...]
    digest: str

    def file(self, path: str | Path) -> NotebookFile | None:
        """The :class:`NotebookFile` at ``path`` (as the walk named it: below ``self.path``, absolute or relative
        to the working folder alike; or relative to the folder), or None."""
        path = Path(path)
        relative = path.as_posix()
        for base, candidate in ((self.path, path), (Path(os.path.abspath(self.path)), Path(os.path.abspath(path)))):
            try:
                relative = candidate.relative_to(base).as_posix()
                break
            except ValueError:
                continue
        return next((n for n in self.notebooks if n.relative == relative), None)

    def read(self, path: str | Path) -> nbformat.NotebookNode:
        """The notebook at ``path`` parsed from the bytes read by the walk; :class:`UnreadableNotebook` otherwise."""
        notebook = self.file(path)
        if notebook is None:
            raise UnreadableNotebook(f"{Path(path).name} was not found by the walk of the folder")
        if notebook.problem:
            raise UnreadableNotebook(notebook.problem)
        data = notebook.data
        if data is None:  # over HELD_BYTES: read again, and only if it did not change
            try:
                data = read_regular_file(notebook.path, MAX_NOTEBOOK_BYTES + 1)[0]
            except OSError as error:
                raise UnreadableNotebook(f"cannot read {notebook.path.name}: {error.strerror or error}") from None
            if hashlib.sha256(data).digest() != notebook.sha256:
                raise UnreadableNotebook(f"{notebook.path.name} changed while it was being graded; grade again")
        return parse_notebook(data, notebook.path.name)

    def hand_in(self, path: str | Path, file_times: bool = True) -> HandIn:
        """When the notebook at ``path`` was handed in (:func:`handed_in_at`); ``file_times``: whether a file's
        modification time may say it (``grade --ignore-mtimes`` says no)."""
        notebook = self.file(path)
        if notebook is None:
            return HandIn()
        if notebook.recorded is not None:
            return notebook.recorded
        return notebook.collected if file_times else HandIn()

    @property
    def notebook_paths(self) -> list[Path]:
        return [n.path for n in self.notebooks]


def _read_notebook(path, folder, real_root, held):
    """``(data or None, problem, the bytes hashed)`` for one notebook, with :func:`read_submission`'s reasons."""
    name = path.name
    try:
        info = os.lstat(path)
    except OSError as error:
        return None, f"cannot open {name}: {error.strerror}", f"unreadable:{error.errno}".encode(), None
    if stat.S_ISLNK(info.st_mode):
        try:
            target = b"link:" + os.fsencode(os.readlink(path))
        except OSError as error:
            target = f"unreadable:{error.errno}".encode()
        return None, f"{name} is a symbolic link; submit the notebook file itself", target, info
    if not stat.S_ISREG(info.st_mode):
        kind = file_kind(info.st_mode)
        return (
            None,
            f"{name} is {kind}, not a regular file; submit the notebook file itself",
            f"kind:{kind}".encode(),
            info,
        )
    try:
        raw, size = read_regular_file(path, MAX_NOTEBOOK_BYTES + 1)
    except NotARegularFile as error:
        return None, f"{error}; submit the notebook file itself", f"unreadable:{error.errno}".encode(), info
    except OSError as error:
        return None, f"cannot read {name}: {error.strerror or error}", f"unreadable:{error.errno}".encode(), info
    if real_root not in path.resolve().parents:
        return None, f"{name} lies outside the submission folder", raw, info
    if size > MAX_NOTEBOOK_BYTES or len(raw) > MAX_NOTEBOOK_BYTES:
        return (
            None,
            f"{name} is {max(size, len(raw)) / 2**20:.0f} MB, over the {MAX_NOTEBOOK_BYTES / 2**20:.0f} MB limit "
            "(clear large outputs with Edit → Clear Outputs of All Cells, save, resubmit)",
            raw,
            info,
        )
    return (raw if held + len(raw) <= HELD_BYTES else None), "", raw, info


def read_student_folder(folder: str | Path, layout: str = FOLDERS, student_id: str = "") -> StudentFolder:
    """Walk ``folder`` once (:func:`scan_folder`, its bounds unchanged) and read each notebook once: a frozen
    :class:`StudentFolder`. Never raises for what the folder holds.

    The hand-in times come from the ``layout`` the instructor's side decided (:func:`detect_layout`): in
    nbgrader's, ``<assignment>/timestamp.txt`` (as ``nbgrader collect`` writes it) for a notebook under
    ``<assignment>/``; in every layout, else, the file's own time as collected. Any time is bounded to
    1970..2200 or refused with why (:class:`HandIn`).
    """
    folder = Path(folder)
    scan = scan_folder(folder)
    try:
        real_root = folder.resolve()
    except (OSError, RuntimeError):
        real_root = folder
    digest, notebooks, held, stamps = hashlib.sha256(), [], 0, {}
    for path in scan.files:
        relative = path.relative_to(folder)
        data, problem, hashed, info = _read_notebook(path, folder, real_root, held)
        held += len(data or b"")
        recorded = None
        if layout == NBGRADER and len(relative.parts) >= 2:
            assignment = relative.parts[0]
            if assignment not in stamps:
                stamps[assignment] = _timestamp_of(folder / assignment)
            recorded = stamps[assignment]
        collected = _file_time(info) if info is not None else HandIn(None, "file time", "its file time cannot be read")
        moment = (recorded if recorded is not None else collected).moment
        digest.update(str(relative).encode("utf-8", "surrogatepass") + b"\0")
        digest.update(hashed)
        digest.update(b"\0" + (moment.isoformat() if moment else "no time").encode())
        digest.update(b"\0")
        notebooks.append(
            NotebookFile(path, relative.as_posix(), data, problem, hashlib.sha256(hashed).digest(), recorded, collected)
        )
    return StudentFolder(
        student_id or folder.name, folder, layout, tuple(notebooks), tuple(scan.skipped), digest.hexdigest()
    )


def handed_in_at(notebook: Path, folder: Path, layout: str = FOLDERS) -> datetime | None:
    """When ``notebook`` (under the student's ``folder``) was handed in, from one trusted source, or ``None``.

    - in nbgrader's layout only, ``folder/<assignment>/timestamp.txt`` (where ``nbgrader collect`` writes it),
      for a notebook anywhere under ``<assignment>/``;
    - else the notebook file's modification time as collected (an LMS download, a copied class).

    In the one-folder-per-student layout every ``timestamp.txt`` is the student's own file and never read.
    A time outside 1970..2200 or that cannot be read gives ``None`` (:meth:`StudentFolder.hand_in` says why).

    Examples
    --------
    >>> handed_in_at(Path("submitted/ana/lesson03/03_exp_and_log.ipynb"), Path("submitted/ana"), NBGRADER)  # doctest: +SKIP
    datetime.datetime(2026, 12, 1, 22, 10, 3, tzinfo=datetime.timezone.utc)
    """
    return read_student_folder(folder, layout).hand_in(notebook).moment


def nbgrader_timestamp(notebook: Path, folder: Path) -> datetime | None:
    """The time in ``folder/<assignment>/timestamp.txt`` for a notebook under ``<assignment>/`` (nbgrader's
    layout), or ``None`` when there is none or it is refused."""
    notebook, folder = Path(notebook), Path(folder)
    try:
        parts = notebook.relative_to(folder).parts
    except ValueError:
        return None
    if len(parts) < 2:
        return None
    stamp = _timestamp_of(folder / parts[0])
    return stamp.moment if stamp is not None else None


def collected_time(notebook: Path) -> datetime | None:
    """The modification time of ``notebook`` as collected (aware, UTC, within 1970..2200), or ``None``."""
    try:
        return _file_time(os.lstat(notebook)).moment
    except OSError:
        return None


def submission_hash(folder: str | Path, layout: str = FOLDERS) -> str:
    """SHA-256 over the names, bytes and hand-in times of every notebook of a student (links by their target
    text): the ``digest`` of :func:`read_student_folder`, so a corrected hand-in time re-grades the student
    like changed bytes.

    Only regular files are read, at most :data:`MAX_NOTEBOOK_BYTES` + 1 bytes each (a larger one is
    refused whole, so what lies beyond cannot change its grade); a FIFO, socket or device is hashed by
    its kind. It never blocks and never raises for what the folder holds.
    """
    return read_student_folder(folder, layout).digest
