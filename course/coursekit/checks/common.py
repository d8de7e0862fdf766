"""Helpers shared by the lessons' public checks: turn a bad value into a :class:`Mismatch`.

Examples
--------
>>> R = require_rotation(require_shape(np.eye(3), (3, 3), "rot_z(0)"), "rot_z(0)")
>>> fmt([0.12345, -0.0])
'[0.123, 0.   ]'
"""

import numpy as np

from ..checking import Mismatch
from ..diagnose import pose_problem, rotation_problem, shape_problem

__all__ = ["require_shape", "require_rotation", "require_pose", "fmt"]


def _prefixed(what, problem):
    return f"{what} {problem}" if what else problem


def require_shape(value, shape, what=""):
    """``value`` as a float array of ``shape``, or :class:`Mismatch` saying why not."""
    problem = shape_problem(value, shape)
    if problem:
        raise Mismatch(_prefixed(what, problem))
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
