"""What a student installs: the direct requirements of the notebooks and ``coursekit``, as tested ranges.

The instructor's ``environment.txt`` is an exact lock for grading and CI; students get this list
instead, so the Python they already have (3.10 on Ubuntu 22.04, Debian 12's 3.11.2, ...) works.
Each package has a **floor** (the oldest version the lessons are run with, in CI, by
``tests/student_floor.py``), a **ceiling** (the next major version, not yet seen) and, where the
floor is newer than an Ubuntu 22.04-era release, the reason. The instructor's lock sits inside every
range (``tests/test_handout.py``).

One source for the hand-out's ``requirements.txt``, the floors' constraints file, the Python check
script and the README's table. Standard library only: ``tests/student_floor.py`` loads this file
with whatever Python it finds, before the project's own environment exists.

Examples
--------
>>> [line for line in requirements_text().splitlines() if not line.startswith("#")][0]
'numpy>=1.23.5,<3'
>>> print(floors_text().splitlines()[1])
numpy==1.23.5
"""

from __future__ import annotations

# The oldest Python the lessons are run with, and the newest the install list is resolved for.
PYTHON_FLOOR = (3, 10)
PYTHONS = ("3.10", "3.11", "3.12", "3.13", "3.14")

# (name, floor, ceiling, why the floor is not an Ubuntu 22.04-era release); the order of the README.
PACKAGES = (
    ("numpy", "1.23.5", "3", "the oldest numpy that scipy 1.14 accepts (Ubuntu 22.04 ships 1.21)"),
    ("scipy", "1.14.0", "2", "the lessons use `Rotation`'s `scalar_first=True`, new in scipy 1.14"),
    ("matplotlib", "3.6.0", "4", "the figures use `Figure.get_layout_engine`, new in matplotlib 3.6"),
    ("ipython", "8.10.0", "10", ""),
    ("ipykernel", "6.20.2", "8", ""),
    ("ipywidgets", "8.1.0", "9", ""),
    ("ipympl", "0.9.4", "1", "the first ipympl built for JupyterLab 4"),
    ("jupyterlab", "4.0.0", "5", ""),
)

HEADER = (
    "# What the course's notebooks need: the direct requirements, each with the range it is tested in.\n"
    "# Install with `pip install -r requirements.txt` (see README.md); pip picks the newest versions\n"
    "# that suit your Python.\n"
)


def requirements_text() -> str:
    """The hand-out's ``requirements.txt``: one ``name>=floor,<ceiling`` line per package."""
    return HEADER + "".join(f"{name}>={floor},<{ceiling}\n" for name, floor, ceiling, _ in PACKAGES)


def floors_text() -> str:
    """A pip constraints file that holds every package at its floor (``pip install -r ... -c floors``)."""
    return "# Every direct requirement at its floor: the oldest versions the lessons are run with.\n" + "".join(
        f"{name}=={floor}\n" for name, floor, _, _ in PACKAGES
    )


def python_floor_text() -> str:
    return ".".join(str(part) for part in PYTHON_FLOOR)


CHECK_PYTHON = '''"""Is this Python new enough for the course? Run it with the Python you will use: python3 check_python.py

It also writes this Python's description into the lessons' metadata: JupyterLab writes the running kernel's
into a notebook when the kernel starts, and shows the notebook as modified unless the same words are there.
"""
import glob
import io
import json
import os
import sys

if sys.version_info < {floor!r}:
    sys.stderr.write("This course needs Python {floor_text} or newer, and this is Python %s (%s). "
                     "Install a newer Python (see README.md), then run the install line again with it.\\n"
                     % (sys.version.split()[0], sys.executable))
    sys.exit(1)

# ipykernel's language_info, word for word as it reports it for this Python
LANGUAGE_INFO = {{"codemirror_mode": {{"name": "ipython", "version": sys.version_info[0]}}, "file_extension": ".py",
                 "mimetype": "text/x-python", "name": "python", "nbconvert_exporter": "python",
                 "pygments_lexer": "ipython3", "version": sys.version.split()[0]}}
for path in sorted(glob.glob(os.path.join(os.path.dirname(os.path.abspath(__file__)), "*.ipynb"))):
    try:
        with io.open(path, encoding="utf-8") as handle:
            notebook = json.load(handle)
        if notebook["metadata"].get("language_info") != LANGUAGE_INFO:
            notebook["metadata"]["language_info"] = LANGUAGE_INFO
            text = json.dumps(notebook, indent=1, sort_keys=True, ensure_ascii=False) + "\\n"
            with io.open(path + ".tmp", "w", encoding="utf-8", newline="\\n") as handle:
                handle.write(text)
            os.replace(path + ".tmp", path)  # whole or not at all
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        pass  # a notebook that cannot be read is left exactly as it is
print("Python %s: good for this course." % sys.version.split()[0])
'''


def check_python_text() -> str:
    """``check_python.py``: one line, and exit status 1, on a Python older than the floor.

    Written so that any Python, 2.7 included, can run it (no f-strings), so the message and not a
    syntax error is what an old Python prints.
    """
    return CHECK_PYTHON.format(floor=PYTHON_FLOOR, floor_text=python_floor_text())


def floor_table() -> str:
    """The README's table of packages, their tested range and why each floor is what it is (markdown)."""
    rows = ["| package | tested from | up to (not incl.) | why this floor |", "| --- | --- | --- | --- |"]
    for name, floor, ceiling, why in PACKAGES:
        rows.append(f"| {name} | {floor} | {ceiling} | {why or 'the oldest release tested; older ones may work'} |")
    return "\n".join(rows) + "\n"
