"""Helpers shared by the lessons' public checks: turn a bad value into a :class:`Mismatch`.

Examples
--------
>>> R = require_rotation(require_shape(np.eye(3), (3, 3), "rot_z(0)"), "rot_z(0)")
>>> fmt([0.12345, -0.0])
'[0.123, 0.   ]'
"""

import numpy as np

from ..checking import Mismatch
from ..diagnose import LISTS_HINT, close, pose_problem, rotation_problem, shape_problem

__all__ = [
    "require_shape",
    "require_rotation",
    "require_pose",
    "require_same_with_lists",
    "require_unchanged_inputs",
    "fmt",
    "off_by",
    "first_match",
    "central_differences",
]


def _prefixed(what, problem):
    return f"{what} {problem}" if what else problem


def require_shape(value, shape, what="", nan_hint=None):
    """``value`` as a float array of ``shape``, or :class:`Mismatch` saying why not.

    ``nan_hint(array)`` names the likely cause when the right shape holds NaN or inf.
    """
    problem = shape_problem(value, shape)
    if problem:
        hint = nan_hint(np.asarray(value, dtype=float)) if nan_hint and problem == "returned NaN or inf values" \
            else None
        raise Mismatch(_prefixed(what, problem), hint)
    return np.asarray(value, dtype=float)


def require_rotation(R, what=""):
    """``R`` unchanged if it is a rotation matrix, else :class:`Mismatch` saying why not."""
    problem = rotation_problem(R)
    if problem:
        raise Mismatch(_prefixed(f"{what} is not a rotation:" if what else "", problem))
    return R


def require_pose(T, what=""):
    """``T`` unchanged if it is a 4×4 pose, else :class:`Mismatch` saying why not."""
    problem = pose_problem(T)
    if problem:
        raise Mismatch(_prefixed(f"{what} is not a pose:" if what else "", problem))
    return T


def fmt(value, digits=3):
    """A short, stable text for a number or array in a check's message."""
    return np.array2string(np.round(np.asarray(value, dtype=float), digits) + 0.0, separator=", ")


def off_by(got, expected):
    """The largest entrywise difference, as text: ``"off by 3.2e-07"``."""
    error = np.max(np.abs(np.asarray(got, dtype=float) - np.asarray(expected, dtype=float)))
    return f"off by {error:.2g}"


def require_same_with_lists(function, args, shape, what):
    """``function`` answers the same for plain lists as for arrays, else :class:`Mismatch`.

    Compares the function with itself, so it blames lists only when lists are
    the difference (a wrong answer is wrong either way, and other checks say so).
    """
    arrays = [np.array(a, dtype=float) for a in args]          # copies: an answer may change its input
    with_arrays = require_shape(function(*[a.copy() for a in arrays]), shape, f"{what} with arrays")
    try:
        with_lists = function(*[a.tolist() for a in arrays])
    except Exception as error:
        raise Mismatch(f"{what} with lists raised {type(error).__name__}: {error}",
                       LISTS_HINT) from None
    with_lists = require_shape(with_lists, shape, f"{what} with lists")
    if np.max(np.abs(with_lists - with_arrays), initial=0.0) > 1e-12:
        raise Mismatch(f"{what} with lists differs from {what} with arrays ({off_by(with_lists, with_arrays)})",
                       LISTS_HINT)


def first_match(got, candidates, tol=1e-6):
    """The hint of the first candidate (a slip's value at the check's inputs) that ``got`` equals, else None."""
    for candidate, hint in candidates:
        if np.shape(got) == np.shape(candidate) and close(got, candidate, tol):
            return hint
    return None


def central_differences(f, n, h=1e-6):
    """Central differences of the vector function f(d) of a small n-vector d, at d = 0: shape (len(f), n)."""
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def require_unchanged_inputs(function, args, what):
    """Call ``function`` on copies of ``args`` and raise :class:`Mismatch` if it changed them."""
    copies = [np.array(a, dtype=float) for a in args]
    function(*copies)
    for before, after in zip(args, copies):
        if not np.array_equal(np.asarray(before, dtype=float), after):
            raise Mismatch(
                f"{what} changed its input array",
                "work on a copy (np.array(x, dtype=float)), never on the caller's array",
            )
