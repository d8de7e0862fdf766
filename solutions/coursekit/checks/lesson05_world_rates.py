"""Public checks for lesson 05, section 9: Euler-angle rates in world axes.

The angular velocity in world axes is computed here by central differences of scipy's z-y-x Euler angles
(ω_w from Ṙ Rᵀ), one rate at a time. The usual slips are recognised by what the finite differences give
instead (at yaw 0, at pitch 0, at -yaw, or in reverse order), never by their formulas
(``tests/test_public_check_constants_lesson05_world_rates.py`` gives each slip to them).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from .common import fmt, off_by, require_shape

YAW, PITCH = np.pi / 3, np.pi / 6
TRANSPOSED_HINT = ("the pitch column disagrees with a finite difference of a pitch rate alone at yaw π/3: it is "
                   "what that difference gives at the opposite yaw, -π/3")
ROLL_UNPITCHED_HINT = ("the yaw and pitch columns agree with finite differences, the roll column does not: it is what "
                       "a finite difference of a roll rate alone gives at pitch 0, not at pitch π/6")
IGNORES_YAW_HINT = ("your E_w is what the finite differences give at yaw 0, whatever the yaw: at yaw π/3 they give "
                    "another matrix")
REVERSED_HINT = hints.COLUMNS_GO_ORDER_RATES_HINT


def _slip_hint(got, roll):
    """Name the slip by what the finite differences say instead: the columns in reverse order, the matrix at
    yaw 0, a horizontal roll axis (the one of pitch 0), or a pitch axis turned by -yaw."""
    numeric = _world_rates_by_differences(YAW, PITCH, roll)
    if close(got[:, ::-1], numeric, 1e-8):
        return REVERSED_HINT
    if close(got, _world_rates_by_differences(0.0, PITCH, roll), 1e-8):
        return IGNORES_YAW_HINT
    if close(got[:, :2], numeric[:, :2], 1e-8) and close(got[:, 2], _world_rates_by_differences(YAW, 0.0, roll)[:, 2], 1e-8):
        return ROLL_UNPITCHED_HINT
    if close(got[:, 1], _world_rates_by_differences(-YAW, PITCH, roll)[:, 1], 1e-8):
        return TRANSPOSED_HINT
    return None


def _world_rates_by_differences(yaw, pitch, roll, h=1e-6):
    """The 3×3 matrix of ω_w per unit yaw, pitch and roll rate, by central differences (scipy's z-y-x angles)."""
    from scipy.spatial.transform import Rotation

    def matrix(angles):
        return Rotation.from_euler("ZYX", angles).as_matrix()

    angles = np.array([yaw, pitch, roll])
    R = matrix(angles)
    columns = []
    for e in np.eye(3):
        W = (matrix(angles + h * e) - matrix(angles - h * e)) / (2 * h) @ R.T
        columns.append(0.5 * np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]))
    return np.column_stack(columns)


@public_check("euler_rates_matrix_world", "E_w @ rates is the world angular velocity (finite differences at "
                                          "yaw π/3, pitch π/6, for two different rolls)")
def _(euler_rates_matrix_world):
    got = require_shape(euler_rates_matrix_world(YAW, PITCH), (3, 3), "euler_rates_matrix_world(π/3, π/6)")
    for roll in (0.0, 1.2):
        numeric = _world_rates_by_differences(YAW, PITCH, roll)
        if not close(got, numeric, 1e-8):
            hint = _slip_hint(got, roll)
            raise Mismatch(f"E_w @ rates misses the world angular velocity at roll {roll:g} "
                           f"({off_by(got, numeric)})", hint or "ω_w is defined by Ṙ Rᵀ = [ω_w]×: differentiate "
                           "Rz Ry Rx and multiply by Rᵀ on the right")


@public_check("euler_rates_matrix_world", "level and facing x: yaw about z, pitch about y, roll about x; det = -cos θ")
def _(euler_rates_matrix_world):
    level = require_shape(euler_rates_matrix_world(0.0, 0.0), (3, 3), "euler_rates_matrix_world(0, 0)")
    expected = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])
    if not close(level, expected, 1e-15):
        raise Mismatch(f"E_w(0, 0) = {fmt(level)}, expected {fmt(expected)}",
                       REVERSED_HINT if close(level, expected[:, ::-1], 1e-15) else
                       "level, every Euler axis is a world axis: yaw about z, pitch about y, roll about x")
    for pitch in (0.3, -1.1, np.pi / 2):
        det = np.linalg.det(require_shape(euler_rates_matrix_world(0.8, pitch), (3, 3), "euler_rates_matrix_world"))
        if abs(det + np.cos(pitch)) > 1e-12:
            raise Mismatch(f"det E_w = {det:.6f} at pitch {pitch:.3g}, expected -cos(pitch) = {-np.cos(pitch):.6f}",
                           "E_w must lose rank exactly at the lock, as the body-rate matrix does: compare "
                           "the yaw and roll columns at pitch ±π/2")


@public_check("euler_rates_matrix_world", "accepts integers and NumPy scalars alike")
def _(euler_rates_matrix_world):
    floats = require_shape(euler_rates_matrix_world(1.0, 0.0), (3, 3), "euler_rates_matrix_world(1.0, 0.0)")
    ints = require_shape(euler_rates_matrix_world(1, 0), (3, 3), "euler_rates_matrix_world(1, 0)")
    scalars = require_shape(euler_rates_matrix_world(np.float64(1.0), np.float32(0.0)), (3, 3),
                            "euler_rates_matrix_world(np.float64(1), np.float32(0))")
    if not (close(floats, ints, 1e-15) and close(floats, scalars, 1e-7)):
        raise Mismatch("the answer changes with the type of the angles", "work with np.cos and np.sin of the angles")
