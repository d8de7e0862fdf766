"""The students' hand-out: ``python -m autograder handout --out course.zip``.

The zip holds one folder, ``rotations-course/``, with

- the released notebooks of ``course/`` and the ``coursekit`` package beside them;
- ``requirements.txt``: what a student installs, pinned exactly as in
  ``environment.txt`` but only what the notebooks need (JupyterLab, numpy,
  scipy, matplotlib, ipywidgets and their dependencies): none of the
  instructor's tools (nbgrader and its menus, nbval, pytest, the sandbox);
- ``README.md``: how to install, where to start, what to hand in.

Nothing in it is a solution, a hidden test or the grader; a test reads every
file of the zip to make sure it never names them.

Examples
--------
>>> build_handout("course.zip")                      # doctest: +SKIP
PosixPath('course.zip')
"""

import os
import re
import stat
import subprocess
import time
import zipfile
from importlib import metadata
from pathlib import Path

from packaging.requirements import Requirement

from autograder.lessons.paths import COURSE, PROJECT_ROOT, SUPPORT_PACKAGE

FOLDER = "rotations-course"
# What the notebooks import or run in; everything they pull in is added from the pins.
STUDENT_ROOTS = ("jupyterlab", "ipykernel", "ipywidgets", "ipympl", "numpy", "scipy", "matplotlib")

README = """# Rotations, hands on — your copy of the course

A Jupyter course on 3D rotations: frames and rotation matrices, the Lie
algebra and Rodrigues' formula, quaternions, Euler angles and gimbal lock,
perturbations and Jacobians, poses, and a capstone.

## Start

With Python {python} or newer:

```bash
python3 -m venv .venv
.venv/bin/pip install -r requirements.txt
.venv/bin/jupyter lab 00_start_here.ipynb
```

(On Windows: `py -m venv .venv`, then `.venv\\Scripts\\pip install -r requirements.txt`
and `.venv\\Scripts\\jupyter lab 00_start_here.ipynb`.)

Start with `00_start_here.ipynb`: it explains how the lessons, the exercises
and the check cells work. Keep the `coursekit` folder next to the notebooks:
the check cells and figures use it.

## Working and handing in

- Write each exercise in its answer cell, then run the check cell under it:
  every public check prints ✓ or ✗ with a hint.
- Each lesson ends with a **Ready to hand in?** cell that runs all of the
  lesson's checks at once and lists what is still to do.
- Hand in each lesson's notebook file (`01_frames_and_rotations.ipynb`, ...)
  the way your course asks. Only your answer cells are graded; more thorough
  hidden checks run when your work is graded, so a clean check cell is
  encouraging, not a guarantee.
"""


def _closure(roots, pins):
    """The pinned distributions that ``roots`` need, following installed metadata (and requested extras)."""
    needed, seen, todo = set(), set(), [(name, frozenset()) for name in roots]
    while todo:
        name, extras = todo.pop()
        key = _canonical(name)
        if (key, extras) in seen or key not in pins:
            continue
        seen.add((key, extras))
        needed.add(key)
        for line in metadata.requires(pins[key][0]) or []:
            requirement = Requirement(line)
            wanted = requirement.marker is None or any(
                requirement.marker.evaluate({"extra": extra}) for extra in ("", *extras))
            if wanted:
                todo.append((requirement.name, frozenset(requirement.extras)))
    return needed


def _canonical(name):
    return re.sub(r"[-_.]+", "-", name).lower()


def _pins():
    pins = {}
    for line in (PROJECT_ROOT / "environment.txt").read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        if "==" in line:
            name, version = line.split("==", 1)
            pins[_canonical(name)] = (name, version)
    return pins


def student_requirements():
    """The students' ``requirements.txt`` text: the pins the notebooks need, nothing else."""
    pins = _pins()
    names = sorted(_closure(STUDENT_ROOTS, pins), key=lambda key: pins[key][0].lower())
    lines = ["# What the course notebooks need, pinned (generated from the course's environment.txt)."]
    return "\n".join(lines + [f"{pins[key][0]}=={pins[key][1]}" for key in names]) + "\n"


def handout_files():
    """``{path inside the zip: bytes}`` for the hand-out."""
    from autograder import MINIMUM_PYTHON

    files = {}
    for path in sorted(COURSE.glob("*.ipynb")):
        files[f"{FOLDER}/{path.name}"] = path.read_bytes()
    for path in sorted((COURSE / SUPPORT_PACKAGE).rglob("*.py")):
        if "__pycache__" not in path.parts:
            files[f"{FOLDER}/{path.relative_to(COURSE).as_posix()}"] = path.read_bytes()
    files[f"{FOLDER}/requirements.txt"] = student_requirements().encode()
    files[f"{FOLDER}/README.md"] = README.format(python=MINIMUM_PYTHON).encode()
    return files


def release_date():
    """When the course was released, as seconds since the epoch: the files' date inside the zip.

    ``SOURCE_DATE_EPOCH`` when set (reproducible builds' convention), else the
    date of the last commit that changed ``course/``, else now. The same commit
    gives the same bytes, and a student's file manager shows a real date, not
    a made-up one.
    """
    if os.environ.get("SOURCE_DATE_EPOCH", "").strip().isdigit():
        return int(os.environ["SOURCE_DATE_EPOCH"])
    try:
        found = subprocess.run(["git", "log", "-1", "--format=%ct", "--", str(COURSE)], cwd=PROJECT_ROOT,
                               capture_output=True, text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        found = ""
    return int(found) if found.isdigit() else int(time.time())


def build_handout(out):
    """Write the hand-out zip to ``out``; return its path."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    stamp = time.gmtime(max(release_date(), 315532800))[:6]  # zip dates start in 1980
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in handout_files().items():
            info = zipfile.ZipInfo(name, date_time=stamp)  # reproducible bytes for a given release
            info.external_attr = (stat.S_IFREG | 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            archive.writestr(info, data)
    return out
