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
Symbolic links are never followed.
"""

import ast
import hashlib
import os
import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from autograder.lessons import cells
from autograder.lessons.notebook_files import UnreadableNotebook, read_master, read_submission
from autograder.lessons.paths import COURSE

MAX_DEPTH = 2


def student_folders(path):
    """Sorted ``[(student_id, folder)]`` under ``path`` (see the module docstring)."""
    path = Path(path)
    if (path / "submitted").is_dir() and not (path / "submitted").is_symlink():
        path = path / "submitted"
    found = []
    for entry in sorted(path.iterdir()):
        if entry.is_dir() and not entry.is_symlink() and not entry.name.startswith("."):
            found.append((entry.name, entry))
    return found


def is_notebook_name(name):
    return name.endswith(".ipynb") and not name.startswith(".")


def files_in(folder, wanted):
    """Paths of the files (and links) whose name ``wanted(name)`` accepts, up to two levels down,
    in sorted order, skipping hidden folders and never following a link."""
    folder = Path(folder)
    for root, dirs, files in os.walk(folder, followlinks=False):
        depth = len(Path(root).relative_to(folder).parts)
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and depth < MAX_DEPTH)
        yield from (Path(root) / name for name in sorted(files) if wanted(name))


def notebooks_in(folder):
    """Regular ``.ipynb`` files and links to them up to two levels down, as paths."""
    return list(files_in(folder, is_notebook_name))


@dataclass
class LessonFiles:
    """Which file of a submission is graded for each lesson, and what was left over."""

    chosen: dict = field(default_factory=dict)  # lesson number -> Path
    notes: dict = field(default_factory=dict)  # lesson number -> why this file among several
    unmatched: list = field(default_factory=list)  # Paths of notebooks that belong to no graded lesson


def _normalised(source):
    return re.sub(r"\s+", " ", source or "").strip()


@lru_cache(maxsize=None)
def _stubs(filename):
    """``{exercise: answer-cell source}`` of the released notebook (what untouched work looks like)."""
    try:
        nb = read_master(COURSE / filename)
    except OSError:
        return {}
    return {cells.grade_id(c): _normalised(cells.source_text(c)) for c in nb.cells if cells.is_answer_cell(c)}


def _code_cells(nb):
    """``[(grade_id, source, names of the functions it defines)]`` for a notebook's code cells, check
    cells excepted; each cell is parsed once (and only if it can define a function)."""
    found = []
    for cell in nb.cells:
        if cell.get("cell_type") != "code" or cells.is_check_cell(cell):
            continue
        source = cells.source_text(cell)
        defined = ()
        if "def" in source:
            try:
                defined = tuple(node.name for node in ast.parse(source).body if isinstance(node, ast.FunctionDef))
            except (SyntaxError, ValueError):
                pass
        found.append((cells.grade_id(cell), source, defined))
    return found


def _answers(code_cells, names):
    """``{exercise: source}`` for the exercises of ``names`` these cells hold (by grade_id, else by def)."""
    found = {}
    for grade_id, source, defined in code_cells:
        if grade_id in names:
            found[grade_id] = source
            continue
        for name in defined:
            if name in names:
                found.setdefault(name, source)
    return found


def _name_matches(path, lesson):
    return path.name == lesson.filename or path.name.startswith(lesson.number + "_")


def match_lessons(folder, catalog, notebooks=None):
    """Match the notebooks of one student's ``folder`` to ``catalog``'s graded lessons, by content.

    Returns
    -------
    LessonFiles
        ``chosen[number]`` is the file to grade for a lesson (absent: the lesson is missing).

    Examples
    --------
    >>> files = match_lessons(Path("class/dan"), load_catalog())           # doctest: +SKIP
    >>> files.chosen["03"].name, files.unmatched
    ('dan_exp_log_final.ipynb', [])
    """
    folder = Path(folder)
    notebooks = notebooks_in(folder) if notebooks is None else notebooks
    lessons = catalog.graded_lessons
    readable, unreadable = {}, []
    for path in notebooks:
        try:
            readable[path] = _code_cells(read_submission(path, root=folder))
        except UnreadableNotebook:
            unreadable.append(path)
    files = LessonFiles()
    claimed = set()
    for lesson in lessons:
        names = {e.name for e in lesson.exercises}
        stubs = _stubs(lesson.filename)
        candidates = []
        for path, code_cells in readable.items():
            answers = _answers(code_cells, names)
            if answers:
                work = sum(1 for name, source in answers.items() if _normalised(source) != stubs.get(name))
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
            files.notes[lesson.number] = (f"several notebooks hold lesson {lesson.number}: graded "
                                          f"{best[3].relative_to(folder)} ({_work(best[0])}); not graded: {others}")
    ungraded = {lesson.filename for lesson in catalog.lessons if not lesson.exercises}
    files.unmatched = [p for p in notebooks if p not in claimed and p.name not in ungraded]
    return files


def _work(count):
    return "no answer written" if count == 0 else f"{count} answer{'s' if count > 1 else ''} written"


def submission_hash(folder):
    """SHA-256 over the names and bytes of every notebook of a student (links by their target text)."""
    digest = hashlib.sha256()
    folder = Path(folder)
    for path in notebooks_in(folder):
        digest.update(str(path.relative_to(folder)).encode("utf-8") + b"\0")
        if path.is_symlink():
            digest.update(b"link:" + os.readlink(path).encode("utf-8", "replace"))
        else:
            try:
                with open(path, "rb") as handle:
                    for block in iter(lambda: handle.read(1 << 20), b""):
                        digest.update(block)
            except OSError as error:
                digest.update(f"unreadable:{error.errno}".encode())
        digest.update(b"\0")
    return digest.hexdigest()
