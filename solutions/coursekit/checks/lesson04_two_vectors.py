"""Public checks for lesson 04, section 16: the shortest rotation between two directions.

The checks use pairs of directions whose answer is known by heart (x onto y, an eighth of a turn in the x-y
plane), exactly opposite and parallel vectors, and a pair 1e-10 rad apart; the values the usual slips return
for the first two pairs are stored as numbers (``tests/test_public_check_constants_lesson04_two_vectors.py``
recomputes them). Rotations are applied with scipy, never with an answer of this exercise.
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from .common import fmt, off_by, require_same_with_lists, require_shape

HALF = np.sqrt(0.5)
X_ONTO_Y = np.array([HALF, 0.0, 0.0, HALF])                    # a quarter turn about z
X_ONTO_Y_FULL_ANGLE = np.array([0.0, 0.0, 0.0, 1.0])           # [cos θ, sin θ u]: a half turn
X_ONTO_Y_REVERSED = np.array([HALF, 0.0, 0.0, -HALF])
EIGHTH = np.array([0.9238795325112867, 0.0, 0.0, 0.3826834323650898])       # 45° about z
EIGHTH_UNNORMALISED = np.array([0.7592566023652966, 0.0, 0.0, 0.6507913734559685])   # a and b used unnormalised
# the answer for the pair 1e-6 rad apart of the scaling check, to the last digit
MICRO = np.array([0.999999999999877, -4.91862567841899e-07, -3.2549728759549535e-08, 5.424954791639181e-08])

FULL_ANGLE_HINT = ("R(q) turns a twice as far as b (x went past y, to -x): a quaternion holds half the angle of its "
                   "turn, [cos(φ/2), sin(φ/2) u] turns by φ (section 7)")
REVERSED_HINT = ("the axis points the wrong way: the turn takes a away from b (x went to -y); a positive turn "
                 "about an axis follows the right-hand rule")
UNNORMALISED_HINT = "only the directions count: normalise a and b first (a · b is |a| |b| cos θ)"
ARCCOS_HINT = hints.ARCCOS_LOSES_SMALL_ANGLES_HINT
OPPOSITE_HINT = ("for opposite directions whatever gives your axis elsewhere is zero here, or only rounding noise "
                 "pointing anywhere: take a half turn about any axis perpendicular to a, found another way")


def _rotate(q, v):
    from scipy.spatial.transform import Rotation

    return Rotation.from_quat(np.asarray(q, dtype=float), scalar_first=True).as_matrix() @ v


def _first_match(got, candidates):
    for value, hint in candidates:
        if close(got, value, 1e-9):
            return hint
    return None


@public_check("quat_from_two_vectors", "x onto y is a quarter turn about z; 2x onto 3x + 3y an eighth of a turn")
def _(quat_from_two_vectors):
    got = require_shape(quat_from_two_vectors([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]), (4,), "quat_from_two_vectors(x, y)")
    if not close(got, X_ONTO_Y, 1e-12):
        raise Mismatch(f"got {fmt(got, 4)}, expected {fmt(X_ONTO_Y, 4)} ({off_by(got, X_ONTO_Y)})",
                       _first_match(got, [(X_ONTO_Y_FULL_ANGLE, FULL_ANGLE_HINT), (X_ONTO_Y_REVERSED, REVERSED_HINT)]))
    got = require_shape(quat_from_two_vectors([2.0, 0.0, 0.0], [3.0, 3.0, 0.0]), (4,),
                        "quat_from_two_vectors(2x, 3x + 3y)")
    if not close(got, EIGHTH, 1e-12):
        raise Mismatch(f"got {fmt(got, 4)}, expected {fmt(EIGHTH, 4)} ({off_by(got, EIGHTH)})",
                       _first_match(got, [(EIGHTH_UNNORMALISED, UNNORMALISED_HINT)]) or
                       ("NaN: arccos of a · b above 1? " + UNNORMALISED_HINT if not np.all(np.isfinite(got)) else None))


@public_check("quat_from_two_vectors", "opposite directions give a half turn that sends a to -a; parallel ones the "
                                       "identity")
def _(quat_from_two_vectors):
    for a, factor in (([1.0, 2.0, 3.0], -2.0), ([-0.3, 0.7, 0.1], -3.0)):
        a = np.array(a)
        with np.errstate(invalid="ignore", divide="ignore"):
            got = np.asarray(quat_from_two_vectors(a, factor * a), dtype=float)
        if got.shape == (4,) and not np.all(np.isfinite(got)):
            raise Mismatch(f"opposite directions ({fmt(a)} and {factor:g} times it) gave NaN", OPPOSITE_HINT)
        got = require_shape(got, (4,), "quat_from_two_vectors(a, -c a)")
        a_hat = a / np.linalg.norm(a)
        turned = _rotate(got / np.linalg.norm(got), a_hat) if np.linalg.norm(got) > 0 else a_hat
        if abs(np.linalg.norm(got) - 1.0) > 1e-12 or not close(turned, -a_hat, 1e-12) or abs(got[0]) > 1e-12:
            noisy_axis = abs(np.linalg.norm(got) - 1.0) <= 1e-12 and abs(got[0]) <= 1e-12  # a half turn, wrong axis
            raise Mismatch(f"for {fmt(a)} and {factor:g} times it got {fmt(got, 4)}: it must be a unit half turn "
                           "([0, u] with u perpendicular to a) sending a to -a",
                           OPPOSITE_HINT if noisy_axis else hints.OPPOSITE_DIRECTIONS_ANSWER_HALF_HINT)
    same = require_shape(quat_from_two_vectors(a, 0.5 * a), (4,), "quat_from_two_vectors(a, a/2)")
    if not close(same, [1.0, 0.0, 0.0, 0.0], 1e-12):
        raise Mismatch(f"parallel directions gave {fmt(same, 4)}, not the identity [1, 0, 0, 0]",
                       "parallel directions need no turn: the identity [1, 0, 0, 0]")


@public_check("quat_from_two_vectors", "keeps its accuracy at a tiny angle: 1e-10 rad, to 1e-6 of the angle")
def _(quat_from_two_vectors):
    b = np.array([np.cos(1e-10), np.sin(1e-10), 0.0])
    got = require_shape(quat_from_two_vectors([1.0, 0.0, 0.0], b), (4,), "quat_from_two_vectors(x, b)")
    error = abs(got[3] - 5e-11) + np.max(np.abs(got[1:3]))
    if error > 5e-17:
        hint = ARCCOS_HINT if np.all(got[1:] == 0.0) else None
        raise Mismatch(f"the vector part is off by {error:.2g} (it should be [0, 0, 5e-11])", hint)


@public_check("quat_from_two_vectors", "only the directions count, also at 1e-6 rad: b scaled by 1e-12 or a by 1e-12 "
                                       "gives the same answer to 1e-14")
def _(quat_from_two_vectors):
    a, b = np.array([0.3, -1.2, 2.0]), np.array([0.3, -1.2 + 2e-6, 2.0 + 1.2e-6])   # about 1e-6 rad apart
    base = require_shape(quat_from_two_vectors(a, b), (4,), "quat_from_two_vectors(a, b)")
    # when the unscaled answer misses MICRO, the answer is inaccurate at small angles (the check above says why),
    # and its noise, not the scaling, moves it
    accurate = close(base, MICRO, 1e-13) or close(base, -MICRO, 1e-13)
    for scale_a, scale_b in ((1.0, 1e-12), (1e-12, 1.0), (1e4, 1.0)):
        got = require_shape(quat_from_two_vectors(scale_a * a, scale_b * b), (4,),
                            f"quat_from_two_vectors({scale_a:g} a, {scale_b:g} b)")
        if not close(got, base, 1e-14):
            raise Mismatch(f"scaling a by {scale_a:g} and b by {scale_b:g} changed the answer ({off_by(got, base)})",
                           UNNORMALISED_HINT if accurate else None)


@public_check("quat_from_two_vectors", "accepts plain lists and returns a unit quaternion")
def _(quat_from_two_vectors):
    a, b = np.array([0.3, -1.2, 2.0]), np.array([-0.5, 0.4, 1.5])
    got = require_shape(quat_from_two_vectors(a, b), (4,), "quat_from_two_vectors(a, b)")
    if abs(np.linalg.norm(got) - 1.0) > 1e-12:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.6f}, not 1",
                       "q = [cos(θ/2), sin(θ/2) u] is a unit quaternion only when its axis u is a unit vector")
    turned, target = _rotate(got, a / np.linalg.norm(a)), b / np.linalg.norm(b)
    if not close(turned, target, 1e-12):
        miss = np.linalg.norm(turned - target)
        raise Mismatch(f"R(q) a/|a| misses b/|b| by {miss:.2g} (the distance between the two unit vectors)",
                       "R(q) must take the direction of a onto that of b: try it on pairs whose answer you can see, "
                       "x onto y (a quarter turn about +z), y onto x, x onto z, and see where each lands")
    require_same_with_lists(quat_from_two_vectors, (a, b), (4,), "quat_from_two_vectors(a, b)")
