"""Run the course in stock nbgrader: build a course folder from solutions/.

The masters are nbgrader source notebooks, so a course is just a folder::

    ROOT/nbgrader_config.py
    ROOT/source/lesson01/01_frames_and_rotations.ipynb
    ROOT/source/lesson01/coursekit/...          (the support package the notebook imports)

``nbgrader generate_assignment lesson01`` then writes the release, and
``nbgrader autograde lesson01`` grades ``ROOT/submitted/<student>/lesson01/``
with the visible check cells as the autograder tests. The benchmark and the
project's tests use this module; an instructor can use it to start a course.

Examples
--------
>>> root = build_course("/tmp/rotations-nbgrader")          # doctest: +SKIP
>>> run_nbgrader(root, "generate_assignment", "lesson01")     # doctest: +SKIP
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat

from autograder.lessons import cells
from autograder.lessons.catalog import Lesson, load_catalog
from autograder.lessons.course import SUPPORT_PACKAGE

CONFIG = """c = get_config()
c.CourseDirectory.root = {root!r}
c.CourseDirectory.course_id = "rotations"
c.ClearSolutions.code_stub = {{"python": {stub!r}}}
c.ExecutePreprocessor.timeout = 120
"""


def assignment_name(lesson: Lesson) -> str:
    """nbgrader's assignment name for a lesson: ``lesson01``."""
    return f"lesson{lesson.number}"


def build_course(root: str | Path, solutions_dir: Path, lessons: list[str] | None = None) -> Path:
    """Write an nbgrader course with one assignment per lesson of the masters in ``solutions_dir``; return
    its root."""
    from autograder.authoring.release import CODE_STUB

    root = Path(root).resolve()
    root.mkdir(parents=True, exist_ok=True)
    (root / "nbgrader_config.py").write_text(CONFIG.format(root=str(root), stub=CODE_STUB), encoding="utf-8")
    for lesson in load_catalog(solutions_dir).graded_lessons:
        if lessons and lesson.number not in lessons:
            continue
        source = root / "source" / assignment_name(lesson)
        source.mkdir(parents=True, exist_ok=True)
        _write_student_master(Path(solutions_dir) / lesson.filename, source / lesson.filename)
        shutil.copytree(
            Path(solutions_dir) / SUPPORT_PACKAGE,
            source / SUPPORT_PACKAGE,
            ignore=shutil.ignore_patterns("__pycache__"),
            dirs_exist_ok=True,
        )
    return root


def _write_student_master(master, target):
    """``master`` as nbgrader's source: the lab's edition, without the cells only the book shows
    (tagged ``reader-only``, :mod:`autograder.lessons.cells`) and the exercises' giveaways, as ``release``
    leaves them out."""
    nb = nbformat.read(str(master), as_version=4)
    nb.cells = [cell for cell in nb.cells if not cells.is_reader_only(cell)]
    for cell in nb.cells:
        cells.drop_giveaways(cell)
    nbformat.write(nb, str(target))
    shutil.copystat(master, target)


def submit(root: str | Path, student_id: str, lesson: Lesson, notebook: str | Path) -> Path:
    """Place a student's notebook where ``nbgrader autograde`` looks for it."""
    folder = Path(root) / "submitted" / student_id / assignment_name(lesson)
    folder.mkdir(parents=True, exist_ok=True)
    shutil.copy2(notebook, folder / lesson.filename)
    return folder


def with_environment_tools(env: dict[str, str] | None = None) -> dict[str, str]:
    """``env`` (default: ours) with this Python's ``bin/`` first on PATH.

    nbgrader runs the ``alembic`` command of its own environment to create a
    gradebook; without an activated virtual environment it would not be found.
    """
    env = dict(os.environ if env is None else env)
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env.get("PATH", "")
    return env


def run_nbgrader(
    root: str | Path, *args: str, check: bool = True, env: dict[str, str] | None = None
) -> subprocess.CompletedProcess:
    """Run ``nbgrader ARGS`` in the course root with this Python; return the CompletedProcess."""
    command = [sys.executable, "-m", "nbgrader", *args]
    env = with_environment_tools(env)
    result = subprocess.run(command, cwd=root, capture_output=True, text=True, env=env)
    if check and result.returncode != 0:
        raise RuntimeError(f"nbgrader {' '.join(args)} failed:\n{result.stdout[-3000:]}\n{result.stderr[-3000:]}")
    return result
