"""The students' hand-out: ``python -m autograder handout --out course.zip``.

The zip holds one folder (``rotations-course/`` for this repository's course: the course's
``handout`` name, see :class:`~autograder.lessons.course.Course`), with

- the released notebooks of ``course/`` and the ``coursekit`` package beside them;
- ``requirements.txt``: what a student installs: the notebooks' and coursekit's direct
  requirements, each with its tested range (:mod:`autograder.authoring.student_install`), not
  the instructor's exact lock, so the Python a student already has works (3.10 and newer);
  none of the instructor's tools (nbgrader, nbval, pytest, the sandbox);
- ``check_python.py``: one line on whether this Python is new enough, run before pip;
- ``README.md``: which Pythons work, how to install, where to start, what to hand in.

Nothing in it is a solution, a hidden test or the grader; a test reads every
file of the zip to make sure it never names them.

Examples
--------
>>> build_handout("course.zip", course)              # doctest: +SKIP
PosixPath('course.zip')
"""

from __future__ import annotations

import os
import stat
import time
import zipfile
from pathlib import Path

from autograder.authoring.student_install import (
    PYTHONS,
    check_python_text,
    floor_table,
    python_floor_text,
    requirements_text,
)
from autograder.lessons.course import SUPPORT_PACKAGE, Course

README = """# {title} — your copy of the course

{about}

## Which Python

Python {pythons} work, on Linux, macOS (Intel and Apple
silicon) and Windows: every lesson is run on Python {floor} with the oldest
versions below, and the install list is checked to resolve from ready-made
wheels for each of these Pythons on each of these systems. Check yours with `python3 --version` (on Windows,
`py --version`).

{table}
## Install and start

In a terminal, in this folder. Linux and macOS:

```bash
python3 check_python.py && python3 -m venv .venv && .venv/bin/pip install -r requirements.txt
.venv/bin/jupyter lab {start}
```

Windows, in Command Prompt (`cmd`):

```bat
py check_python.py && py -m venv .venv && .venv\\Scripts\\pip install -r requirements.txt
.venv\\Scripts\\jupyter lab {start}
```

`check_python.py` prints one line before anything is installed: that your
Python is fine, or which Python you have and that the course needs {floor}
or newer. It also writes your Python's version into the lessons, where
JupyterLab looks for it: without it, every lesson would open marked as
modified. On Debian or Ubuntu, if `venv` says that `ensurepip` is not
available, install it first with `sudo apt install python3-venv`.

**An older Python?** Install a newer one beside it and use that one in the
install line: from [python.org](https://www.python.org/downloads/) on macOS
and Windows (then `python3.12` in place of `python3` on macOS, `py -3.12` in
place of `py` on Windows), or with your package manager on Linux. Your
older Python stays as it is.

Start with `{start}`: it explains how the lessons, the exercises
and the check cells work. Keep the `coursekit` folder next to the notebooks:
the check cells and figures use it.

## Working and handing in

- Write each exercise in its answer cell, then run the check cell under it:
  every public check prints ✓ or ✗ with a hint.
- Each lesson ends with a **Ready to hand in?** cell that runs all of the
  lesson's checks at once and lists what is still to do.
- Hand in each lesson's notebook file (`{example}`, ...)
  the way your course asks. Only your answer cells are graded; more thorough
  hidden checks run when your work is graded, so a clean check cell is
  encouraging, not a guarantee.
"""


def student_requirements() -> str:
    """The students' ``requirements.txt`` text: the direct requirements, each with its tested range."""
    return requirements_text()


def readme(course: Course) -> str:
    """The hand-out's ``README.md``: which Pythons and versions work, how to install, how to hand in."""
    pythons = ", ".join(PYTHONS[:-1]) + " and " + PYTHONS[-1]
    lessons = course.catalog.lessons
    return README.format(
        pythons=pythons,
        floor=python_floor_text(),
        table=floor_table(),
        title=course.title,
        about=course.about,
        start=lessons[0].filename,
        example=course.catalog.graded_lessons[0].filename,
    )


def handout_files(course: Course) -> dict[str, bytes]:
    """``{path inside the zip: bytes}`` for ``course``'s hand-out (its released notebooks and coursekit)."""
    files, folder, released = {}, course.handout, course.released
    for path in sorted(released.glob("*.ipynb")):
        files[f"{folder}/{path.name}"] = path.read_bytes()
    for path in sorted((released / SUPPORT_PACKAGE).rglob("*")):  # its modules and its data files
        if path.is_file() and "__pycache__" not in path.parts and path.suffix != ".pyc":
            files[f"{folder}/{path.relative_to(released).as_posix()}"] = path.read_bytes()
    files[f"{folder}/requirements.txt"] = student_requirements().encode()
    files[f"{folder}/check_python.py"] = check_python_text().encode()
    files[f"{folder}/README.md"] = readme(course).encode()
    return files


def packed_at() -> tuple[int, int, int, int, int, int]:
    """The date every file of the zip carries: now, or ``SOURCE_DATE_EPOCH`` for reproducible bytes.

    A real date, because unzipping gives each file this time: a fixed date in the past would make an
    untouched notebook look handed in long ago, and one in the future would look newer than a
    student's saved work.
    """
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    moment = time.gmtime(int(epoch)) if epoch else time.localtime()
    return tuple(max(moment[:6], (1980, 1, 1, 0, 0, 0)))  # the zip format starts in 1980


def build_handout(out: str | Path, course: Course) -> Path:
    """Write ``course``'s hand-out zip to ``out``; return its path."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    date = packed_at()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in handout_files(course).items():
            info = zipfile.ZipInfo(name, date_time=date)
            info.external_attr = (stat.S_IFREG | 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            archive.writestr(info, data)
    return out
