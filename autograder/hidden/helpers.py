"""What hidden tests are written with: marks, failures with hints, comparisons.

Every hidden test names the exercise it grades and, through its docstring's
first line, what it checks — that line is what the student reads. When a
check fails it raises :class:`Wrong` with one line on what was seen and,
where a mistake is recognisable, a hint::

    @exercise("rot_z", weight=2)
    def test_rot_z_matches_scipy(student):
        \"\"\"agrees with scipy for 20 random angles\"\"\"
        for angle in angles(seed=1):
            got = expect_array(student.rot_z(angle), (3, 3), "rot_z")
            expect_close(got, Rotation.from_euler("z", angle).as_matrix(), 1e-9,
                         f"rot_z({angle:.3f})", hint=rotation_hint(got, ...))

A test may call student functions of its own exercise only; inputs and
expected values come from the reference (``ref``), scipy, or the test itself,
so one wrong exercise never costs points elsewhere.
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from autograder.sandbox.child.wire import Probe  # noqa: F401  (callable arguments, by name)
from autograder.sandbox.session import StudentError
from coursekit.diagnose import (ALLCLOSE_HINT, LISTS_HINT, rotation_hint, rotation_problem,  # noqa: F401  (for the tests)
                                shape_problem)


class Wrong(AssertionError):
    """A failed hidden check: ``reason`` is what was seen, ``hint`` a likely cause."""

    def __init__(self, reason, hint=""):
        super().__init__(reason)
        self.reason = reason
        self.hint = hint or ""


def exercise(name, weight=1.0):
    """Mark a test as grading exercise ``name`` with relative ``weight``."""
    return pytest.mark.exercise(name=name, weight=float(weight))


def fmt(value, digits=4):
    """Short text for a value in a failure message; tiny numbers keep their significant digits.

    Examples
    --------
    >>> fmt([1.0, 2.5e-9, -0.0])
    '[1, 2.5e-09, 0]'
    """
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return repr(value)[:120]
    text = np.array2string(array + 0.0, separator=", ", threshold=20, max_line_width=1000,
                           formatter={"float_kind": lambda x: f"{x:.{digits}g}"})
    return " ".join(text.split())


def expect(condition, reason, hint=""):
    """Raise :class:`Wrong` unless ``condition``."""
    if not condition:
        raise Wrong(reason, hint)


def expect_array(value, shape, what):
    """``value`` as a float array of ``shape``, or :class:`Wrong` saying why not."""
    problem = shape_problem(value, shape)
    if problem:
        raise Wrong(f"{what} {problem}")
    return np.asarray(value, dtype=float)


def expect_close(got, expected, tol, what, hint="", scale=1.0):
    """Raise :class:`Wrong` unless ``got`` matches ``expected`` entrywise within ``tol · max(1, scale)``.

    ``scale`` is the size of the inputs (e.g. |ρ| of a pose), so the tolerance
    is relative to them; the message gives the size of the error.
    """
    got = np.asarray(got, dtype=float)
    expected = np.asarray(expected, dtype=float)
    if got.shape != expected.shape:
        raise Wrong(f"{what}: shape {got.shape}, expected {expected.shape}", hint)
    tol = tol * max(1.0, float(scale))
    error = float(np.max(np.abs(got - expected))) if got.size else 0.0
    if not error <= tol:
        raise Wrong(f"{what} is off by {error:.2g} (tolerance {tol:.2g}): got {fmt(got, 6)}, "
                    f"expected {fmt(expected, 6)}", hint)


def expect_same_with_lists(function, args, shape, what, lists=None, **kwargs):
    """``function`` gives the same answer for plain lists as for arrays (whether or not it is right).

    The hint blames lists only when lists are the difference: a wrong answer
    that is wrong either way loses its points in the checks of its values.
    ``lists`` replaces the default plain-list form of ``args`` (e.g. integers).
    """
    arrays = [np.array(a, dtype=float) for a in args]
    with_arrays = expect_array(function(*arrays, **kwargs), shape, f"{what} with arrays")
    try:
        with_lists = function(*(lists if lists is not None else [a.tolist() for a in arrays]), **kwargs)
    except StudentError as error:
        if error.kind != "exception":
            raise
        raise Wrong(f"{what} with lists: {error}", LISTS_HINT) from None
    with_lists = expect_array(with_lists, shape, f"{what} with lists")
    expect_close(with_lists, with_arrays, 1e-12, f"{what} with lists, compared with arrays", LISTS_HINT)


def expect_bool(value, what):
    """``value`` as a Python bool, or :class:`Wrong` if it is not a boolean."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise Wrong(f"{what} returned {value!r} ({type(value).__name__}), not True or False",
                "return a bool: wrap numpy's result in bool(...)")


def random_rotations(count, seed):
    """``count`` uniformly random rotation matrices, shape (count, 3, 3), seeded."""
    return Rotation.random(count, random_state=seed).as_matrix()


def random_angles(count, seed, low=-2 * np.pi, high=2 * np.pi):
    """``count`` seeded random angles in [low, high)."""
    return np.random.default_rng(seed).uniform(low, high, count)
