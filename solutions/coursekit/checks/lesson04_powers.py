"""Public checks for lesson 04, section 14: the power q^t of a unit quaternion.

The checks use the defining properties of the power (q¹ = q, q⁰ = 1, q^½ ⊗ q^½ = q with its sign, the identity
to any power, q² = q ⊗ q at a tiny angle), never its formula; the values three usual slips return at the checks'
fixed inputs are stored as numbers (``tests/test_public_check_constants_lesson04_powers.py`` recomputes them).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import quat_product
from .common import fmt, off_by, require_shape

# 2 rad about (0, 0.6, 0.8): α = 1, written with the course's half angle.
Q_TWO_RAD = np.array([np.cos(1.0), 0.0, 0.6 * np.sin(1.0), 0.8 * np.sin(1.0)])
# Two typical slips' answers, stored: their q¹, and the length of their q^½'s vector part.
Q_ONE_FULL_ANGLE = np.array([-0.4161468365471424, 0.0, 0.545578456095409, 0.7274379414605454])
HALF_WITHOUT_UNIT_AXIS = 0.4034226801113349
# What q ** ½ gives, each entry raised to the power ½ (every entry of Q_TWO_RAD is >= 0, so no NaN).
HALF_ELEMENTWISE = np.array([0.7350525871447157, 0.0, 0.7105509066103131, 0.8204735144087939])
ELEMENTWISE_HINT = "q ** t raises each entry to the power t; the power of a quaternion is Exp_q(t Log_q q)"
NAN_HINT = "look for an arccos or arcsin of a number beyond ±1, or a division by zero"
NOT_UNIT_HINT = "the power of a unit quaternion is a unit quaternion, for every t: q^½ must have length 1"


def _power(quat_power, q, t, what):
    return require_shape(quat_power(q, t), (4,), what)


def _unchanged_input(quat_power):
    q = Q_TWO_RAD.copy()
    quat_power(q, 0.5)
    if not np.array_equal(q, Q_TWO_RAD):
        raise Mismatch("quat_power changed its input array",
                       "work on a copy (np.array(q, dtype=float)), never on the caller's array")


@public_check("quat_power", "q¹ = q and q⁰ = [1, 0, 0, 0] (2 rad about (0, 0.6, 0.8))")
def _(quat_power):
    with np.errstate(invalid="ignore", divide="ignore"):
        one = quat_power(Q_TWO_RAD, 1.0)
    if np.shape(one) == (4,) and np.all(np.isfinite(np.asarray(one, dtype=float))) \
            and close(one, Q_ONE_FULL_ANGLE, 1e-9):
        raise Mismatch("q¹ turns by 4 rad, twice the rotation of q", hints.POWER_HALF_ANGLE_HINT)
    one = _power(quat_power, Q_TWO_RAD, 1.0, "quat_power(q, 1)")
    if not close(one, Q_TWO_RAD, 1e-12):
        hint = hints.POWER_UNIT_AXIS_HINT if close(one[1:], np.sin(1.0) * Q_TWO_RAD[1:], 1e-9) else None
        raise Mismatch(f"q¹ = {fmt(one, 4)}, expected q = {fmt(Q_TWO_RAD, 4)} ({off_by(one, Q_TWO_RAD)})", hint)
    zero = _power(quat_power, Q_TWO_RAD, 0.0, "quat_power(q, 0)")
    if not close(zero, [1.0, 0.0, 0.0, 0.0], 1e-12):
        raise Mismatch(f"q⁰ = {fmt(zero, 4)}, expected the identity [1, 0, 0, 0]")


@public_check("quat_power", "q^½ ⊗ q^½ = q and (−q)^½ ⊗ (−q)^½ = −q, sign included")
def _(quat_power):
    with np.errstate(invalid="ignore"):
        half = np.asarray(quat_power(Q_TWO_RAD, 0.5), dtype=float)
    if half.shape == (4,) and not np.all(np.isfinite(half)):
        raise Mismatch("q^½ has NaN entries", NAN_HINT)
    half = _power(quat_power, Q_TWO_RAD, 0.5, "quat_power(q, 0.5)")
    if abs(np.linalg.norm(half) - 1.0) > 1e-9:
        if abs(np.linalg.norm(half[1:]) - HALF_WITHOUT_UNIT_AXIS) < 1e-9:
            hint = hints.POWER_UNIT_AXIS_HINT
        else:
            hint = ELEMENTWISE_HINT if close(half, HALF_ELEMENTWISE, 1e-12) else NOT_UNIT_HINT
        raise Mismatch(f"q^½ has length {np.linalg.norm(half):.6f}, not 1", hint)
    if not close(quat_product(half, half), Q_TWO_RAD, 1e-9):
        raise Mismatch(f"q^½ ⊗ q^½ misses q ({off_by(quat_product(half, half), Q_TWO_RAD)})",
                       hints.POWER_DEFINITION_HINT)
    other = _power(quat_power, -Q_TWO_RAD, 0.5, "quat_power(-q, 0.5)")
    squared = quat_product(other, other)
    if close(squared, Q_TWO_RAD, 1e-9):
        raise Mismatch("(−q)^½ ⊗ (−q)^½ = +q: the sign of -q was thrown away", hints.POWER_SIGN_FLIP_HINT)
    if not close(squared, -Q_TWO_RAD, 1e-9):
        raise Mismatch(f"(−q)^½ ⊗ (−q)^½ misses −q ({off_by(squared, -Q_TWO_RAD)})", hints.POWER_SIGN_FLIP_HINT)


@public_check("quat_power", "the identity to any power is the identity; q² = q ⊗ q at a tiny angle (α = 1e-10)")
def _(quat_power):
    with np.errstate(invalid="ignore", divide="ignore"):
        identity = np.asarray(quat_power([1.0, 0.0, 0.0, 0.0], 0.7), dtype=float)
    if identity.shape == (4,) and not np.all(np.isfinite(identity)):
        raise Mismatch("the identity to the power 0.7 gave NaN", hints.POWER_IDENTITY_HINT)
    identity = _power(quat_power, [1.0, 0.0, 0.0, 0.0], 0.7, "quat_power([1, 0, 0, 0], 0.7)")
    if not close(identity, [1.0, 0.0, 0.0, 0.0], 1e-15):
        raise Mismatch(f"the identity to the power 0.7 is {fmt(identity)}, not the identity", hints.POWER_IDENTITY_HINT)
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    tiny = np.concatenate([[np.cos(1e-10)], np.sin(1e-10) * axis])
    squared = _power(quat_power, tiny, 2.0, "quat_power(q_tiny, 2)")
    expected = quat_product(tiny, tiny)
    error = np.max(np.abs(squared[1:] - expected[1:]))
    if error > 1e-6 * 2e-10:
        hint = hints.POWER_ARCCOS_HINT if np.all(squared[1:] == 0.0) else None
        raise Mismatch(f"the vector part of q² is off by {error:.2g} (it has length 2e-10)", hint)


@public_check("quat_power", "accepts plain lists and leaves its input unchanged")
def _(quat_power):
    for t in (0.5, 2.0):
        arrays = _power(quat_power, Q_TWO_RAD.copy(), t, "quat_power(q, t)")
        lists = _power(quat_power, Q_TWO_RAD.tolist(), t, "quat_power(list, t)")
        if not close(arrays, lists, 1e-12):
            raise Mismatch("quat_power with a list differs from an array", hints.CONVERT_INPUTS_NP_ASARRAY_HINT)
    _unchanged_input(quat_power)
