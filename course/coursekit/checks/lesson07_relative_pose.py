"""Public checks for lesson 07, section 8: the relative pose of two frames known in the world.

The checks use poses written out by hand (quarter turns and shifts), the defining property T_wa T_ab = T_wb,
and the values the usual slips return for them, stored as numbers
(``tests/test_public_check_constants_lesson07_relative_pose.py`` recomputes them).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from .common import fmt, off_by, require_same_with_lists, require_shape
from .lesson07 import T_GENERIC, T_GENERIC_2, require_exact

T_WA = np.array([[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
T_WB = np.array([[0.0, 0.0, 1.0, 3.0], [1.0, 0.0, 0.0, -1.0], [0.0, 1.0, 0.0, 2.0], [0.0, 0.0, 0.0, 1.0]])
T_AB = np.array([[1.0, 0.0, 0.0, -3.0], [0.0, 0.0, -1.0, -2.0], [0.0, 1.0, 0.0, 2.0], [0.0, 0.0, 0.0, 1.0]])
COLLEAGUE_RESULT = np.array([[0.0, 0.0, 1.0, 3.0], [0.0, 1.0, 0.0, -3.0], [-1.0, 0.0, 0.0, 3.0],
                             [0.0, 0.0, 0.0, 1.0]])
TRANSPOSED = np.array([[1.0, 0.0, 0.0, -1.0], [0.0, 0.0, -1.0, -3.0], [0.0, 1.0, 0.0, 2.0], [2.0, 0.0, 1.0, 2.0]])
REVERSED = np.array([[1.0, 0.0, 0.0, 3.0], [0.0, 0.0, 1.0, -2.0], [0.0, -1.0, 0.0, -2.0], [0.0, 0.0, 0.0, 1.0]])
UNROTATED = np.array([[1.0, 0.0, 0.0, 2.0], [0.0, 0.0, -1.0, -3.0], [0.0, 1.0, 0.0, 2.0], [0.0, 0.0, 0.0, 1.0]])
COLLEAGUE_HINT = hints.RELATIVE_POSE_COLLEAGUE_HINT
TRANSPOSED_HINT = hints.INVERSE_POSE_TRANSPOSE_T1_HINT
REVERSED_HINT = hints.RELATIVE_POSE_REVERSED_HINT
UNROTATED_HINT = hints.SHIFT_IN_WORLD_AXES_HINT
SLIPS = [(COLLEAGUE_RESULT, COLLEAGUE_HINT), (TRANSPOSED, TRANSPOSED_HINT), (REVERSED, REVERSED_HINT),
         (UNROTATED, UNROTATED_HINT)]


@public_check("relative_pose", "T_wa T_ab = T_wb for two poses that turn and shift")
def _(relative_pose):
    got = require_shape(relative_pose(T_WA, T_WB), (4, 4), "relative_pose(T_wa, T_wb)")
    if not close(got, T_AB, 1e-12):
        raise Mismatch(f"T_wa @ T_ab misses T_wb ({off_by(T_WA @ got, T_WB)})",
                       next((hint for value, hint in SLIPS if close(got, value, 1e-12)), None) or
                       hints.RELATIVE_POSE_CHAIN_HINT)


@public_check("relative_pose", "a frame seen from itself is the identity; b seen from the world is T_wb")
def _(relative_pose):
    same = require_shape(relative_pose(T_WB, T_WB), (4, 4), "relative_pose(T_wb, T_wb)")
    if not close(same, np.eye(4), 1e-12):
        raise Mismatch(f"relative_pose(T, T) = {fmt(same)}, not the identity",
                       TRANSPOSED_HINT if not close(same[3], [0.0, 0.0, 0.0, 1.0], 1e-12) else None)
    from_world = require_shape(relative_pose(np.eye(4), T_WB), (4, 4), "relative_pose(I, T_wb)")
    if not close(from_world, T_WB, 1e-12):
        raise Mismatch(f"seen from the world itself, b should be T_wb ({off_by(from_world, T_WB)})")


@public_check("relative_pose", "accepts plain lists")
def _(relative_pose):
    require_same_with_lists(relative_pose, (T_WA, T_WB), (4, 4), "relative_pose(T_wa, T_wb)")


@public_check("relative_pose", "two generic poses: T_wa T_ab = T_wb to 1e-12 (float64 kept)")
def _(relative_pose):
    got = require_shape(relative_pose(T_GENERIC, T_GENERIC_2), (4, 4), "relative_pose(T_wa, T_wb)")
    require_exact(T_GENERIC @ got, T_GENERIC_2, "T_wa @ relative_pose(T_wa, T_wb)",
                  hint="T_wa T_ab must equal T_wb to rounding: build T_ab from the two poses in float64")
