"""Write a small, complete course to start a new one from: ``python -m autograder new-course DIR``.

The course, "Turning the plane", has a start page and two lessons on rotations
in 2-D (four exercises) and everything the grader needs to release, grade and
publish it (docs/AUTHORING.md, "Write your own course")::

    DIR/layout.toml                      [course] title = "Turning the plane"
    DIR/solutions/00_start_here.ipynb    the start page (the book's front page)
    DIR/solutions/01_rotation_matrices.ipynb, 02_reading_angles.ipynb   the masters
    DIR/solutions/coursekit/             the support package (see below)
    DIR/hidden/test_01_rotation_matrices.py, test_02_reading_angles.py  the hidden suite

Three sources, each written once in this repository:

- the **masters** are built here, from Python, with the constructors of
  :mod:`autograder.lessons.cells`, and saved with :func:`~autograder.authoring.masters.save_master`;
  their demonstration outputs are then recorded (:func:`~autograder.authoring.record.record_outputs`);
- the course's **own text files** (its layout file, ``coursekit/__init__``, ``contracts``,
  ``diagnose``, ``hints``, the public checks, the hidden tests) are copied from
  ``course_template/`` beside this module, where the Python ones end in ``.tmpl``
  so that they are not read as modules of the grader;
- the **generic modules** of ``coursekit`` (:data:`GENERIC_MODULES`: the check
  cells, the hand-in cell, watching calls, printing values, one-line stubs) are
  copied from the support package given, this repository's ``solutions/coursekit``,
  byte for byte.

Examples
--------
>>> from pathlib import Path
>>> course = write_course(Path("/tmp/plane"), Path("solutions/coursekit"))     # doctest: +SKIP
>>> sorted(path.name for path in course.iterdir())                             # doctest: +SKIP
['hidden', 'layout.toml', 'solutions']
"""

from __future__ import annotations

import shutil
from collections.abc import Callable
from pathlib import Path

import nbformat

from autograder.authoring.masters import new_lesson, save_master
from autograder.authoring.record import record_outputs
from autograder.lessons import cells
from autograder.lessons.course import LAYOUT_FILE, SUPPORT_PACKAGE

TEMPLATE = Path(__file__).resolve().parent / "course_template"
TEMPLATE_SUFFIX = ".tmpl"  # stripped on copy: course_template/hidden/test_01_*.py.tmpl -> DIR/hidden/test_01_*.py
TEMPLATE_LAYOUT = "layout.toml"  # written as DIR/<LAYOUT_FILE>
# The modules of coursekit that any course uses unchanged. They import nothing course-specific but
# .contracts (every course writes its own) and each other.
GENERIC_MODULES = (
    "checking.py",
    "watching.py",
    "handin.py",
    "display.py",
    "stubs.py",
    "exercise_contracts.py",  # without the course's exercise_contracts.json it checks nothing
    "checks/__init__.py",
)
SETUP = "import numpy as np\nfrom coursekit import check, show"


def write_course(dest: Path, support_from: Path, *, record: bool = True) -> Path:
    """Write the small course "Turning the plane" into the folder ``dest``; return ``dest``.

    Parameters
    ----------
    dest : Path
        The course folder to create: missing, or an empty folder.
    support_from : Path
        A course's support package (this repository's ``solutions/coursekit``), where the
        :data:`GENERIC_MODULES` are copied from.
    record : bool, optional
        Run each master once in a kernel and store its demonstration outputs (a few seconds),
        as ``python -m autograder record`` does. Without it, the demonstration cells have no
        outputs yet, and the notebook stage of grading would find them changed.

    Returns
    -------
    Path
        ``dest``, with ``layout.toml``, ``solutions/`` (the masters and ``coursekit/``) and ``hidden/``.

    Raises
    ------
    ValueError
        If ``dest`` holds files already or is a file, or ``support_from`` lacks a generic module.

    Examples
    --------
    >>> course = write_course(Path("/tmp/plane"), Path("solutions/coursekit"))    # doctest: +SKIP
    >>> from autograder.lessons.catalog import load_catalog                       # doctest: +SKIP
    >>> [(e.name, e.points) for e in load_catalog(course / "solutions").exercises]  # doctest: +SKIP
    [('rot2', 2.0), ('rotate2', 2.0), ('angle_of', 2.0), ('angle_difference', 2.0)]
    """
    dest, support_from = Path(dest), Path(support_from)
    if dest.exists() and not dest.is_dir():
        raise ValueError(f"{dest} is a file: a new course is written into an empty or missing folder")
    if dest.exists() and any(dest.iterdir()):
        raise ValueError(f"{dest} is not empty: a new course is written into an empty or missing folder")
    missing = [name for name in GENERIC_MODULES if not (support_from / name).is_file()]
    if missing:
        raise ValueError(f"{support_from} is not a course's support package: it has no {', '.join(missing)}")
    for path in sorted(TEMPLATE.rglob("*")):
        if not path.is_file() or "__pycache__" in path.parts:
            continue
        relative = path.relative_to(TEMPLATE).as_posix().removesuffix(TEMPLATE_SUFFIX)
        target = dest / (LAYOUT_FILE if relative == TEMPLATE_LAYOUT else relative)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, target)
    support = dest / "solutions" / SUPPORT_PACKAGE
    for name in GENERIC_MODULES:
        (support / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(support_from / name, support / name)
    demonstrating = []
    for filename, build in MASTERS.items():
        lesson = build()
        save_master(new_lesson(lesson), dest / "solutions" / filename)
        if any(cells.checks_output(cell) for cell in lesson):
            demonstrating.append(filename[:2])
    if record and demonstrating:
        record_outputs(dest / "solutions", only=demonstrating)
    return dest


# ---------------------------------------------------------------- the masters
HOW_EXERCISES_WORK = """
**How the exercises work.** Each exercise is a function with its documentation written and a body
that raises `NotImplementedError`. Replace that line with your code and run the cell, then run the
**check cell** below it: it prints ✓ or ✗, with a hint, for each public check. The public checks are
quick; more thorough hidden checks run when your notebook is graded, so a clean check is a good sign
rather than a guarantee. A graded function uses only its arguments and `numpy` (imported as `np` in
the first code cell): never variables defined elsewhere in the notebook.
"""

READY_TO_HAND_IN = """
## Ready to hand in?

Run the cell below whenever you like: it runs the public checks of every exercise of this lesson at
once and lists what is still to do. When every line shows ✓, save the notebook and hand in this
file; the hidden checks run when it is graded.
"""


def _start_here() -> list[nbformat.NotebookNode]:
    return [
        cells.markdown("""
# Start here — Turning the plane

Welcome. This short course is about one idea that robots, games and drawing programs use all the
time: turning things about a point. In the plane a turn is described by a single angle, and yet the
way we write it down, apply it and read it back holds a few traps. Two lessons walk through them.
"""),
        _tagged(
            cells.markdown("""
You will not only read: in each lesson you write the functions yourself, and a check cell under
each one tells you at once whether you are on track.
"""),
            cells.STUDENT_ONLY_TAG,
        ),
        cells.markdown("""
## The lessons

| # | lesson | you will learn to | time |
| --- | --- | --- | --- |
| 01 | [Rotation matrices in the plane](01_rotation_matrices.ipynb) | build the matrix of a turn, turn points | 30 minutes |
| 02 | [Reading an angle back](02_reading_angles.ipynb) | read a turn's angle; find the short way between two angles | 30 minutes |

You need a little numpy (arrays, `@` for the matrix product) and the sine and cosine of school
trigonometry; nothing else is assumed.
"""),
        _tagged(
            cells.markdown("""
## Reading this book

This is the reader's edition of the course: every exercise is shown with its reference answer, and
every printed result was produced by running those answers.
"""),
            cells.READER_ONLY_TAG,
        ),
        _tagged(
            cells.markdown("""
## How a lesson works

Run the cells from top to bottom (Shift+Enter runs one and moves on). An **exercise** is a function
whose body says `raise NotImplementedError(...)`: replace that line with your code and run the cell.
The locked **check cell** below it, such as `check("rot2", rot2)`, tries your function on a few
cases and prints ✓ or ✗ with a hint. These public checks are quick sanity tests; the hidden checks
that grade your work are more thorough. The last cell of each lesson, **Ready to hand in?**, runs all
of the lesson's checks at once.
"""),
            cells.STUDENT_ONLY_TAG,
        ),
        cells.markdown("""
## Conventions

| topic | convention |
| --- | --- |
| angles | radians; positive turns counter-clockwise (from x towards y) |
| points | numpy float arrays of shape `(2,)`; lists work too |
| matrices | numpy arrays of shape `(2, 2)`; nested lists work too |

**Next:** [Lesson 01 — Rotation matrices in the plane](01_rotation_matrices.ipynb)
"""),
    ]


ROT2 = '''
def rot2(theta):
    """The matrix that turns the plane counter-clockwise by ``theta``.

    Parameters
    ----------
    theta : float
        The angle in radians; a positive angle turns x towards y.

    Returns
    -------
    ndarray, shape (2, 2)
        ``[[cos θ, -sin θ], [sin θ, cos θ]]``: its columns are where x and y land.

    Examples
    --------
    >>> np.round(rot2(np.pi / 2), 12)   # a quarter turn: x lands on y, y on -x
    array([[ 0., -1.],
           [ 1.,  0.]])
    """
    ### BEGIN SOLUTION
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s], [s, c]])
    ### END SOLUTION
'''

ROTATE2 = '''
def rotate2(theta, p):
    """The point ``p`` turned counter-clockwise by ``theta`` about the origin.

    Parameters
    ----------
    theta : float
        The angle in radians.
    p : array_like, shape (2,)
        The point's coordinates (a list works too); it is left unchanged.

    Returns
    -------
    ndarray, shape (2,)
        The turned point, ``rot2(theta) @ p``.

    Examples
    --------
    >>> np.round(rotate2(np.pi / 2, [1.0, 0.0]), 12)
    array([0., 1.])
    """
    ### BEGIN SOLUTION
    x, y = np.asarray(p, dtype=float)
    c, s = np.cos(theta), np.sin(theta)
    return np.array([c * x - s * y, s * x + c * y])
    ### END SOLUTION
'''


def _lesson_01() -> list[nbformat.NotebookNode]:
    return [
        cells.markdown("""
# Lesson 01 — Rotation matrices in the plane

Turning a picture, steering a robot, spinning a game character: each time, every point moves on a
circle about a centre by the same angle. This lesson writes that turn as a matrix, so that turning a
point becomes one matrix product.

**By the end of this lesson you will be able to**

- write the matrix of a turn by any angle, and say why its columns are what they are;
- turn points with it, and check a turn with a case you can do in your head.

*Time:* about 30 minutes. *You need:* numpy arrays and the sine and cosine.
"""),
        _tagged(cells.markdown(HOW_EXERCISES_WORK), cells.STUDENT_ONLY_TAG),
        cells.markdown("""
### Conventions used in this lesson

| topic | convention |
| --- | --- |
| angles | radians (`np.deg2rad(90)` converts); positive turns counter-clockwise |
| points | numpy float arrays of shape `(2,)`; lists work too |
"""),
        cells.setup(SETUP),
        cells.markdown(r"""
## 1. Where the axes go

A turn about the origin is a linear map: it sends sums to sums and doubles to doubles. So it is
known as soon as we know where it sends the two unit vectors $\mathbf x = (1, 0)$ and
$\mathbf y = (0, 1)$. Turning by $\theta$ counter-clockwise, $\mathbf x$ lands on the unit circle at
angle $\theta$, and $\mathbf y$, which starts a quarter turn ahead of $\mathbf x$, stays a quarter
turn ahead:

$$\mathbf x \mapsto \begin{bmatrix} \cos\theta \\ \sin\theta \end{bmatrix}, \qquad
\mathbf y \mapsto \begin{bmatrix} -\sin\theta \\ \cos\theta \end{bmatrix}.$$

Stack the two images as columns and you have the matrix of the turn:

$$\mathbf R(\theta) = \begin{bmatrix} \cos\theta & -\sin\theta \\ \sin\theta & \cos\theta \end{bmatrix}.$$

The minus sign sits on the upper-right sine. Put it on the lower-left one instead and you get
$\mathbf R(-\theta)$, a turn the other way: a slip that no error message will ever point out, so
test with a quarter turn, $\theta = \pi/2$, which must send $\mathbf x$ to $\mathbf y$.
"""),
        cells.markdown("""
### Exercise 1: `rot2` (2 points)

Write `rot2(theta)`, the 2 × 2 matrix that turns the plane counter-clockwise by `theta` radians.
"""),
        cells.answer("rot2", ROT2),
        cells.check("rot2", 2),
        cells.markdown(r"""
## 2. Turning a point

Any point is a combination of the axes, $\mathbf p = p_x \mathbf x + p_y \mathbf y$, so the turned
point is the same combination of the turned axes: $\mathbf R(\theta)\,\mathbf p$. Written out,

$$\mathbf R(\theta)\,\mathbf p = \begin{bmatrix} p_x\cos\theta - p_y\sin\theta \\
p_x\sin\theta + p_y\cos\theta \end{bmatrix}.$$

A turn changes where a point is, never how far it is from the origin: its length stays the same.
"""),
        cells.markdown("""
### Exercise 2: `rotate2` (2 points)

Write `rotate2(theta, p)`, the point `p` turned counter-clockwise by `theta` about the origin. Use
`np.cos` and `np.sin` in the function itself (each graded function stands on its own), accept a list
for `p` as well as an array, and leave `p` unchanged.
"""),
        cells.answer("rotate2", ROTATE2),
        cells.check("rotate2", 2),
        cells.markdown("""
## 3. Turns add up

Turning by a quarter turn twice is a half turn, and four quarter turns bring every point home. The
matrices agree: the product of two turns is the turn by the sum of the angles. The cell below shows
both with the functions above.
"""),
        cells.code(
            """
p = np.array([2.0, 1.0])
show("rotate2(pi/2, p)", rotate2(np.pi / 2, p))
show("rotate2(pi, p)", rotate2(np.pi, p))
show("rot2(0.3) @ rot2(0.4) - rot2(0.7)", rot2(0.3) @ rot2(0.4) - rot2(0.7))
""",
            check_output=True,
        ),
        _tagged(cells.markdown(READY_TO_HAND_IN), cells.STUDENT_ONLY_TAG),
        cells.hand_in("01"),
        cells.markdown("""
## Pitfalls

- **The sign on the wrong sine.** `[[cos, sin], [-sin, cos]]` is a perfectly good rotation matrix:
  of the opposite angle. Nothing crashes; points simply turn clockwise. A quarter turn catches it.
- **Degrees.** `np.cos(90)` is the cosine of 90 radians. Convert with `np.deg2rad` at the edge of
  your program and keep radians inside.

## Summary

The matrix of a turn holds the images of the axes as its columns; turning a point is one product
with it, and turns compose by adding their angles.

**Next:** [Lesson 02 — Reading an angle back](02_reading_angles.ipynb)
"""),
    ]


ANGLE_OF = '''
def angle_of(R):
    """The angle of the turn ``R``, between -π and π.

    Parameters
    ----------
    R : array_like, shape (2, 2)
        The matrix of a turn, ``[[cos θ, -sin θ], [sin θ, cos θ]]``; nested lists work too.

    Returns
    -------
    float
        The angle θ in radians, in [-π, π].

    Examples
    --------
    >>> round(angle_of([[0.0, -1.0], [1.0, 0.0]]), 12)   # a quarter turn
    1.570796326795
    """
    ### BEGIN SOLUTION
    R = np.asarray(R, dtype=float)
    return float(np.arctan2(R[1, 0], R[0, 0]))
    ### END SOLUTION
'''

ANGLE_DIFFERENCE = '''
def angle_difference(a, b):
    """The signed shortest turn from the angle ``a`` to the angle ``b``, between -π and π.

    Parameters
    ----------
    a, b : float
        Two angles in radians, of any size (7.0 points the same way as 7.0 - 2π).

    Returns
    -------
    float
        The angle d in [-π, π] with b = a + d up to whole turns: positive when the short way
        from a to b is counter-clockwise.

    Examples
    --------
    >>> round(angle_difference(3.0, -3.0), 6)   # across ±π: a small step, not -6
    0.283185
    """
    ### BEGIN SOLUTION
    d = b - a
    return float(np.arctan2(np.sin(d), np.cos(d)))
    ### END SOLUTION
'''


def _lesson_02() -> list[nbformat.NotebookNode]:
    return [
        cells.markdown("""
# Lesson 02 — Reading an angle back

A sensor, a file or another program hands you a turn as a matrix; you want its angle, to print it,
compare it or steer by it. Reading it back looks easy, and there are two ways to get it subtly
wrong: lose the direction of the turn, or go the long way round.

**By the end of this lesson you will be able to**

- read the angle of a turn from its matrix in all four quadrants, to full precision;
- find the short turn from one angle to another, however many whole turns apart they are.

*Time:* about 30 minutes. *You need:* Lesson 01.
"""),
        _tagged(cells.markdown(HOW_EXERCISES_WORK), cells.STUDENT_ONLY_TAG),
        cells.markdown("""
### Conventions used in this lesson

| topic | convention |
| --- | --- |
| angles | radians, counter-clockwise positive; an angle read back lies in [−π, π] |
| matrices | `[[cos θ, −sin θ], [sin θ, cos θ]]`, numpy arrays of shape `(2, 2)`; nested lists work too |
"""),
        cells.setup(SETUP),
        cells.markdown(r"""
## 1. One entry is not enough

The first column of $\mathbf R(\theta)$ is $(\cos\theta, \sin\theta)$: the point where $\mathbf x$
landed. Either entry alone leaves the angle ambiguous. $\arccos(\cos\theta)$ cannot tell $\theta$
from $-\theta$, since both have the same cosine; $\arcsin(\sin\theta)$ cannot tell $\theta$ from
$\pi - \theta$. And for a tiny turn, $\cos\theta = 1 - \theta^2/2$ rounds to a number so close to 1
that $\arccos$ gives back only a few correct digits, or none.

The function `np.arctan2(y, x)` reads both coordinates of a point and returns its angle in
$[-\pi, \pi]$, in the right quadrant and to full precision. Note the order: $y$ first.
"""),
        cells.markdown("""
### Exercise 1: `angle_of` (2 points)

Write `angle_of(R)`, the angle of the turn `R` in radians, between −π and π. For a half turn either
π or −π is right.
"""),
        cells.answer("angle_of", ANGLE_OF),
        cells.check("angle_of", 2),
        cells.markdown(r"""
## 2. The short way round

Angles repeat every whole turn: $0.5$ and $0.5 + 2\pi$ point the same way. So the difference
$b - a$ of two angles is right only up to whole turns. A compass needle going from $3.0$ rad to
$-3.0$ rad has not swept $-6$ rad; it moved $2\pi - 6 \approx 0.28$ rad counter-clockwise, across the
line where $\pi$ meets $-\pi$. To get the short turn, bring the difference $d = b - a$ into
$[-\pi, \pi]$. One way: $d$ is the angle of the turn $\mathbf R(d)$, and you have just written a
function that reads such an angle in exactly that range.
"""),
        cells.markdown("""
### Exercise 2: `angle_difference` (2 points)

Write `angle_difference(a, b)`, the signed shortest turn from `a` to `b`, between −π and π:
positive when the short way from `a` to `b` is counter-clockwise. Use `numpy` in the function itself
rather than calling `angle_of` (each graded function stands on its own).
"""),
        cells.answer("angle_difference", ANGLE_DIFFERENCE),
        cells.check("angle_difference", 2),
        cells.markdown("""
## 3. Reading angles back

The cell below writes out a few turns (one beyond a whole turn, at 7 rad) and reads their angles
back, then crosses the ±π line.
"""),
        cells.code(
            """
def turn(theta):
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s], [s, c]])


for theta in (0.5, 2.5, -2.5, 7.0):
    show(f"angle_of(turn({theta}))", angle_of(turn(theta)))
show("angle_difference(3.0, -3.0)", angle_difference(3.0, -3.0))
""",
            check_output=True,
        ),
        _tagged(cells.markdown(READY_TO_HAND_IN), cells.STUDENT_ONLY_TAG),
        cells.hand_in("02"),
        cells.markdown("""
## Pitfalls

- **`np.arctan2(x, y)`.** The arguments are (y, x), the opposite of how a point is written. Swapped,
  the angle is measured from the y axis the wrong way round.
- **`np.arccos` of one entry.** It drops the sign of the turn, and for tiny turns most of its digits.
- **Forgetting to wrap.** `b - a` is a difference of numbers, not yet a turn: it can be many turns
  long and take the long way round.

## Summary

The angle of a turn is the angle of where the x axis landed: `arctan2` of the first column, sine
first. The difference of two angles is a turn too, and reading it back the same way gives the short
way round.

**Back to the start:** [Start here](00_start_here.ipynb)
"""),
    ]


def _tagged(cell: nbformat.NotebookNode, tag: str) -> nbformat.NotebookNode:
    cell.metadata["tags"] = [*cell.metadata.get("tags", []), tag]
    return cell


MASTERS: dict[str, Callable[[], list[nbformat.NotebookNode]]] = {
    "00_start_here.ipynb": _start_here,
    "01_rotation_matrices.ipynb": _lesson_01,
    "02_reading_angles.ipynb": _lesson_02,
}
