"""Public checks for lesson 04: quaternions.

The checks use quaternions whose products can be written down by hand
(the units 1, i, j, k, quarter and half turns about a coordinate axis) and
properties every correct answer has: unit norms, orthogonality, fixed axes,
a round trip through one function. Quaternions are stored scalar first,
``[w, x, y, z]``.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import (
    FLOAT32_HINT,
    close,
    float32_rounding,
    quaternion_hint,
    rotation_problem,
    same_rotation_quat,
    shape_problem,
)
from .common import fmt, off_by, require_same_with_lists, require_shape

ONE = np.array([1.0, 0.0, 0.0, 0.0])
I_ = np.array([0.0, 1.0, 0.0, 0.0])
J_ = np.array([0.0, 0.0, 1.0, 0.0])
K_ = np.array([0.0, 0.0, 0.0, 1.0])
HALF = np.sqrt(0.5)
QUARTER_Z = np.array([HALF, 0.0, 0.0, HALF])          # a quarter turn about z
QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
# A unit quaternion with no special structure, and a non-unit one.
GENERIC = np.array([0.5, -0.1, 0.7, 0.5]) / np.linalg.norm([0.5, -0.1, 0.7, 0.5])
LONG = np.array([1.0, 2.0, -1.0, 0.5])


def _conjugate(q):
    return np.asarray(q, dtype=float) * [1.0, -1.0, -1.0, -1.0]


# ---------------------------------------------------------------- quat_multiply
JPL_HINT = ("the sign of the cross product is flipped (that is the JPL product, ij = -k): "
            "the vector part is p_w q_v + q_w p_v + p_v × q_v")
NO_CROSS_HINT = ("your product is commutative (p ⊗ q = q ⊗ p for every pair tried): the cross product is missing "
                 "from the vector part p_w q_v + q_w p_v + p_v × q_v")
DOT_PLUS_HINT = "the scalar part is p_w q_w - p_v · q_v (minus the dot product): i ⊗ i = -1"
ELEMENTWISE_HINT = hints.MULTIPLIED_ENTRY_ENTRY_EVERY_HINT
NORMALISED_HINT = (hints.PRODUCT_DIVIDED_NORM_P_HINT)
PRODUCT_GENERIC = "check each of the 16 terms of the product against the formula"


def _product_diagnosis(quat_multiply):
    """The hint for the typical wrong product that ``quat_multiply`` computes (judged on a few products)."""
    pq = require_shape(quat_multiply(LONG, GENERIC), (4,))
    if close(pq, LONG * GENERIC, 1e-12):
        return ELEMENTWISE_HINT
    if close(require_shape(quat_multiply(I_, I_), (4,)), ONE, 1e-12):
        return DOT_PLUS_HINT
    qp = require_shape(quat_multiply(GENERIC, LONG), (4,))
    if close(require_shape(quat_multiply(I_, J_), (4,)), -K_, 1e-12):
        return JPL_HINT
    if close(pq, qp, 1e-12):
        return NO_CROSS_HINT
    if abs(np.linalg.norm(pq) - 1.0) < 1e-12 and abs(np.linalg.norm(LONG) - 1.0) > 0.1:
        return NORMALISED_HINT
    return PRODUCT_GENERIC


@public_check("quat_multiply", "follows Hamilton's rules: i ⊗ j = k, j ⊗ i = -k, i ⊗ i = -1")
def _(quat_multiply):
    got = require_shape(quat_multiply(I_, J_), (4,))
    if close(got, -K_, 1e-12):
        raise Mismatch("i ⊗ j gave -k", JPL_HINT)
    if not close(got, K_, 1e-12):
        raise Mismatch(f"i ⊗ j gave {fmt(got)}, expected k = [0, 0, 0, 1]", _product_diagnosis(quat_multiply))
    got = require_shape(quat_multiply(J_, I_), (4,))
    if not close(got, -K_, 1e-12):
        raise Mismatch(f"j ⊗ i gave {fmt(got)}, expected -k = [0, 0, 0, -1]", "the product is not commutative")
    got = require_shape(quat_multiply(I_, I_), (4,))
    if not close(got, -ONE, 1e-12):
        raise Mismatch(f"i ⊗ i gave {fmt(got)}, expected -1 = [-1, 0, 0, 0]", _product_diagnosis(quat_multiply))


@public_check("quat_multiply", "[1, 0, 0, 0] is the identity on both sides, for any quaternion")
def _(quat_multiply):
    for name, got in (("1 ⊗ q", quat_multiply(ONE, LONG)), ("q ⊗ 1", quat_multiply(LONG, ONE))):
        got = require_shape(got, (4,))
        if not close(got, LONG, 1e-12):
            raise Mismatch(f"{name} gave {fmt(got)} for q = {fmt(LONG)}, {off_by(got, LONG)}",
                           _product_diagnosis(quat_multiply))


@public_check("quat_multiply", "the norm is multiplicative: |p ⊗ q| = |p| |q|")
def _(quat_multiply):
    got = require_shape(quat_multiply(LONG, GENERIC), (4,))
    error = abs(np.linalg.norm(got) - np.linalg.norm(LONG))
    if error > 1e-12:
        raise Mismatch(f"|p ⊗ q| = {np.linalg.norm(got):.6f}, expected {np.linalg.norm(LONG):.6f} "
                       f"(off by {error:.2g})",
                       _product_diagnosis(quat_multiply))


@public_check("quat_multiply", "undoes itself to 1e-12: (p ⊗ q) ⊗ q* = |q|² p for generic p and q, also as lists")
def _(quat_multiply):
    p, q = LONG * [0.7, 1.3, 0.9, -1.1], GENERIC * 1.5   # neither is a unit quaternion, no entry is 0 or 1
    pq = require_shape(quat_multiply(p.copy(), q.copy()), (4,), "quat_multiply(p, q)")
    back = require_shape(quat_multiply(pq, _conjugate(q)), (4,), "quat_multiply(p ⊗ q, q*)")
    if not close(back, (q @ q) * p, 1e-12):
        raise Mismatch(f"(p ⊗ q) ⊗ q* is {off_by(back, (q @ q) * p)} from |q|² p",
                       FLOAT32_HINT if float32_rounding(back, (q @ q) * p) else _product_diagnosis(quat_multiply))
    require_same_with_lists(quat_multiply, (p, q), (4,), "quat_multiply(p, q)")


# ---------------------------------------------------------------- quat_left, quat_right
def _layout_diagnosis(M, q, mine):
    """A hint when the first row and column of ``M`` show a transpose or a scalar-last reading of ``q``."""
    if close(M[:, 0], _conjugate(q), 1e-12) and close(M[0, :], q, 1e-12):
        return f"looks like the transpose of [q]_{mine}: its first column must be q and its first row [w, -x, -y, -z]"
    if close(M[:, 0], np.roll(q, 1), 1e-12):
        return hints.SCALAR_LAST_HINT
    return None


def _matrix_checks(name, side):
    mine, theirs = ("L", "R") if side == "left" else ("R", "L")

    @public_check(name, "returns a 4×4 matrix whose first column is q (q ⊗ 1 = 1 ⊗ q = q)")
    def _(fn):
        M = require_shape(fn(LONG), (4, 4))
        if not close(M @ ONE, LONG, 1e-12):
            raise Mismatch(f"{name}(q) @ [1, 0, 0, 0] = {fmt(M @ ONE)}, expected q = {fmt(LONG)}, "
                           f"{off_by(M @ ONE, LONG)}", _layout_diagnosis(M, LONG, mine))

    if side == "left":
        factor, other, description = I_, J_, "[i]_L @ j = i ⊗ j = k"
    else:
        factor, other, description = J_, I_, "[j]_R @ i = i ⊗ j = k"

    @public_check(name, description)
    def _(fn):
        M = require_shape(fn(factor), (4, 4))
        got = M @ other
        if close(got, K_, 1e-12):
            return
        hint = _layout_diagnosis(M, factor, mine)
        if hint is None and close(got, -K_, 1e-12) and close(M[:, 0], factor, 1e-12):
            hint = (f"the [v]× block has the wrong sign: this is [q]_{theirs}; "
                    "+[v]× belongs in [q]_L, -[v]× in [q]_R")
        raise Mismatch("got -k instead of k" if close(got, -K_, 1e-12) else
                       f"got {fmt(got)}, expected k = [0, 0, 0, 1]", hint)

    @public_check(name, "is orthogonal for a unit quaternion (MᵀM = I)")
    def _(fn):
        M = require_shape(fn(GENERIC), (4, 4))
        error = np.max(np.abs(M.T @ M - np.eye(4)))
        if error > 1e-12:
            hint = (hints.FIRST_ROW_W_X_HINT
                    if close(M[0, :], GENERIC, 1e-12) and close(M[:, 0], GENERIC, 1e-12) else
                    "compare your entries with the matrix in §4, one sign at a time")
            raise Mismatch(f"max |MᵀM - I| = {error:.2g}", hint)


_matrix_checks("quat_left", "left")
_matrix_checks("quat_right", "right")


# ---------------------------------------------------------------- quat_conjugate
@public_check("quat_conjugate", "flips the vector part: [1, 2, 3, 4]* = [1, -2, -3, -4]")
def _(quat_conjugate):
    q = np.array([1.0, 2.0, 3.0, 4.0])
    got = require_shape(quat_conjugate(q.copy()), (4,))        # a copy: an in-place answer is accepted
    if close(got, [-1.0, 2.0, 3.0, 4.0], 1e-12):
        raise Mismatch("negated the scalar part instead of the vector part",
                       "q* = [w, -x, -y, -z]; the result is -q*, the same rotation but not the conjugate")
    if close(got, q, 1e-12):
        raise Mismatch("got [1, 2, 3, 4], the input itself", hints.RETURNED_Q_UNCHANGED_NEGATE_HINT)
    if close(got, -q, 1e-12):
        raise Mismatch("got [-1, -2, -3, -4]", hints.RETURNED_Q_KEEP_SCALAR_HINT)
    if not close(got, [1.0, -2.0, -3.0, -4.0], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [1, -2, -3, -4], {off_by(got, [1.0, -2.0, -3.0, -4.0])}")


@public_check("quat_conjugate", "keeps every digit of a generic quaternion (float64)")
def _(quat_conjugate):
    got = require_shape(quat_conjugate(GENERIC.copy()), (4,))
    if not close(got, _conjugate(GENERIC), 1e-15):
        raise Mismatch(f"the conjugate of {fmt(GENERIC, 6)} is {off_by(got, _conjugate(GENERIC))}",
                       FLOAT32_HINT if float32_rounding(got, _conjugate(GENERIC)) else None)


@public_check("quat_conjugate", "accepts a plain list")
def _(quat_conjugate):
    require_same_with_lists(quat_conjugate, (GENERIC,), (4,), "quat_conjugate")


# ---------------------------------------------------------------- quat_inverse
def _inverse_diagnosis(got, q):
    """A hint when ``got`` is -q / |q|² or 1/q entry by entry."""
    q = np.asarray(q, dtype=float)
    if close(got, -q / (q @ q), 1e-12):
        return hints.RETURNED_Q_Q_ONLY_HINT
    if close(got, 1.0 / q, 1e-12):
        return hints.TOOK_Q_ENTRY_ENTRY_HINT
    return None


@public_check("quat_inverse", "for a unit quaternion the inverse is the conjugate")
def _(quat_inverse):
    got = require_shape(quat_inverse(GENERIC), (4,))
    if not close(got, _conjugate(GENERIC), 1e-12):
        raise Mismatch(f"got {fmt(got)} for q = {fmt(GENERIC)}, expected its conjugate, "
                       f"{off_by(got, _conjugate(GENERIC))}", _inverse_diagnosis(got, GENERIC))


@public_check("quat_inverse", "works at every length: [1, 1, 1, 1] scaled by 1e-8 and by 1e8")
def _(quat_inverse):
    for scale in (1e-8, 1e8):
        q = scale * np.ones(4)
        expected = np.array([1.0, -1.0, -1.0, -1.0]) / (4.0 * scale)
        got = require_shape(quat_inverse(q), (4,))
        if not close(got, expected, 1e-12 / scale):
            hint = hints.NO_GUARD_FOR_SHORT_Q_HINT if scale < 1 and close(quat_inverse(np.ones(4)), expected * scale, 1e-12) else None
            raise Mismatch(f"got {fmt(got)} for q = {scale:g}·[1, 1, 1, 1], {off_by(got, expected)}", hint)


@public_check("quat_inverse", "works for quaternions that are not unit: [1, 1, 1, 1]⁻¹ = [1, -1, -1, -1] / 4")
def _(quat_inverse):
    q = np.array([1.0, 1.0, 1.0, 1.0])
    got = require_shape(quat_inverse(q.tolist()), (4,))
    if close(got, [1.0, -1.0, -1.0, -1.0], 1e-12):
        raise Mismatch("got [1, -1, -1, -1], 4 times too long",
                       "returned the conjugate: divide it by |q|², with |q|² = w² + x² + y² + z²")
    if close(got, [0.5, -0.5, -0.5, -0.5], 1e-12):
        raise Mismatch("got [0.5, -0.5, -0.5, -0.5]", "divided by |q| = 2, not by |q|² = 4: q⁻¹ = q* / |q|²")
    if not close(got, [0.25, -0.25, -0.25, -0.25], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [0.25, -0.25, -0.25, -0.25], "
                       f"{off_by(got, [0.25, -0.25, -0.25, -0.25])}", _inverse_diagnosis(got, q))


# ---------------------------------------------------------------- quat_from_axis_angle
HALF_ANGLE_HINT = "the quaternion uses the half angle: [cos(θ/2), u sin(θ/2)]"
DEGREES_HINT = "looks like degrees: angles in this course are radians"
SWAPPED_HINT = hints.SIN_COS_SWAPPED_SCALAR_HINT


def _axis_angle_diagnosis(got, axis, theta):
    """The hint for the typical wrong quaternion of (axis, θ) that ``got`` equals, else None."""
    axis = np.asarray(axis, dtype=float)
    u = axis / np.linalg.norm(axis)
    half_degrees = np.deg2rad(theta) / 2
    for c, s, direction, hint in ((np.cos(theta), np.sin(theta), u, HALF_ANGLE_HINT),
                                  (np.cos(half_degrees), np.sin(half_degrees), u, DEGREES_HINT),
                                  (np.sin(theta / 2), np.cos(theta / 2), u, SWAPPED_HINT),
                                  (np.cos(theta / 2), np.sin(theta / 2), axis,
                                   hints.DIVIDE_U_NORM_FIRST_HINT)):
        if close(got, np.concatenate([[c], s * direction]), 1e-9):
            return hint
    return None


@public_check("quat_from_axis_angle", "a quarter turn about z is [cos 45°, 0, 0, sin 45°]")
def _(quat_from_axis_angle):
    got = require_shape(quat_from_axis_angle([0.0, 0.0, 1.0], np.pi / 2), (4,))
    if close(got, [0.0, 0.0, 0.0, 1.0], 1e-9):
        raise Mismatch("got [0, 0, 0, 1], the quaternion of a half turn", HALF_ANGLE_HINT)
    if close(got, [0.0, 0.0, HALF, HALF], 1e-9):
        raise Mismatch(f"got {fmt(got)}", "scalar last? this course stores [w, x, y, z]")
    if not close(got, QUARTER_Z, 1e-9):
        raise Mismatch(f"got {fmt(got)}, expected [0.7071, 0, 0, 0.7071], {off_by(got, QUARTER_Z)}",
                       _axis_angle_diagnosis(got, [0.0, 0.0, 1.0], np.pi / 2))


@public_check("quat_from_axis_angle", "normalises the axis and returns a unit quaternion")
def _(quat_from_axis_angle):
    got = require_shape(quat_from_axis_angle(np.array([0.0, 3.0, 4.0]), 1.2), (4,))   # an array: is it left alone?
    hint = _axis_angle_diagnosis(got, [0.0, 3.0, 4.0], 1.2)
    if abs(np.linalg.norm(got) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.4f} for the axis [0, 3, 4]",
                       hint or "a unit axis u and the half angle give |q|² = cos² + sin² = 1")
    expected = np.array([np.cos(0.6), 0.0, 0.6 * np.sin(0.6), 0.8 * np.sin(0.6)])
    if not close(got, expected, 1e-9):
        raise Mismatch(f"got {fmt(got)}, expected {fmt(expected)}, {off_by(got, expected)}", hint)


@public_check("quat_from_axis_angle", "θ = 0 gives the identity [1, 0, 0, 0]")
def _(quat_from_axis_angle):
    got = require_shape(quat_from_axis_angle([1.0, 0.0, 0.0], 0.0), (4,))
    if not close(got, ONE, 1e-12):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, ONE)}", _axis_angle_diagnosis(got, [1.0, 0.0, 0.0], 0.0))


# ---------------------------------------------------------------- quat_rotate
@public_check("quat_rotate", "a quarter turn about z sends x to y, and leaves z where it is")
def _(quat_rotate):
    got = require_shape(quat_rotate(QUARTER_Z, [1.0, 0.0, 0.0]), (3,))
    axis = require_shape(quat_rotate(QUARTER_Z, [0.0, 0.0, 2.0]), (3,))
    if close(got, [0.0, -1.0, 0.0], 1e-9):
        raise Mismatch("x went to -y: the rotation runs backwards",
                       "rotated the opposite way: use q ⊗ [0, v] ⊗ q*, with the conjugate on the right")
    if not close(got, [0.0, 1.0, 0.0], 1e-9):
        # What the typical mistakes give for this q = [cos 45°, 0, 0, sin 45°], worked out by hand:
        if close(got, [1.0, 0.0, 0.0], 1e-9) and close(axis, [0.0, -2.0, 0.0], 1e-9):
            hint = "q was read as scalar last [x, y, z, w] (a quarter turn about x): this course stores [w, x, y, z]"
        elif close(got, [1.0, 0.0, 0.0], 1e-9) and close(axis, [0.0, 0.0, 0.0], 1e-9):
            hint = hints.CONJUGATE_MISSING_Q_V_HINT
        elif close(got, [1.0, 1.0, 0.0], 1e-9):
            hint = hints.SECOND_ORDER_TERM_MISSING_HINT
        else:
            hint = None
        raise Mismatch(f"x went to {fmt(got)}, expected [0, 1, 0], {off_by(got, [0.0, 1.0, 0.0])}", hint)
    if not close(axis, [0.0, 0.0, 2.0], 1e-9):
        raise Mismatch(f"the axis z went to {fmt(axis)}", "vectors along the axis must not move")


@public_check("quat_rotate", "keeps lengths and gives the same result for q and -q")
def _(quat_rotate):
    v = np.array([0.3, -1.2, 2.0])
    got = require_shape(quat_rotate(GENERIC, v), (3,))
    if abs(np.linalg.norm(got) - np.linalg.norm(v)) > 1e-9:
        raise Mismatch(f"|v| = {np.linalg.norm(v):.4f} became {np.linalg.norm(got):.4f}",
                       "a rotation keeps lengths: check the sandwich q ⊗ [0, v] ⊗ q* term by term")
    other = require_shape(quat_rotate(-GENERIC, v), (3,))
    if not close(got, other, 1e-9):
        raise Mismatch("q and -q rotate the vector differently", "the sandwich uses q twice, so the signs cancel")


# ---------------------------------------------------------------- quat_to_matrix
@public_check("quat_to_matrix", "returns a rotation matrix, the same for q and -q")
def _(quat_to_matrix):
    R = require_shape(quat_to_matrix(GENERIC), (3, 3))
    problem = rotation_problem(R)
    if problem:
        raise Mismatch(problem)
    if not close(R, require_shape(quat_to_matrix(-GENERIC), (3, 3)), 1e-12):
        raise Mismatch("R(q) differs from R(-q)", "every entry of R(q) is a sum of products of two components of q")


@public_check("quat_to_matrix", "the quarter turn about z: x → y (and the identity for [1, 0, 0, 0])")
def _(quat_to_matrix):
    R = require_shape(quat_to_matrix(QUARTER_Z), (3, 3))
    if close(R, QUARTER_TURN_Z.T, 1e-9):
        raise Mismatch("got the transpose (the inverse rotation)",
                       "looks like the transpose: the quarter turn about z sent x to -y; check the sign of "
                       "every term linear in w")
    if close(R, np.array([[1.0, 0, 0], [0, 0, -1.0], [0, 1.0, 0]]), 1e-9):
        raise Mismatch("got a quarter turn about x", "scalar last? this course stores q = [w, x, y, z]")
    # What the quarter turn gives when a factor of the formula is lost (a typical slip's answer, stored).
    if close(R, [[0.5, -0.5, 0.0], [0.5, 0.5, 0.0], [0.0, 0.0, 1.0]], 1e-9):
        raise Mismatch(f"got\n{fmt(R)}", "e_x went to (0.5, 0.5, 0), of length 0.71, not to e_y: a rotation keeps "
                       "lengths; rotate e_x with the sandwich on paper and compare with your first column, term by "
                       "term")
    if not close(R, QUARTER_TURN_Z, 1e-9):
        raise Mismatch(f"got\n{fmt(R)}\n{off_by(R, QUARTER_TURN_Z)}")
    R = require_shape(quat_to_matrix(ONE), (3, 3))
    if not close(R, np.eye(3), 1e-12):
        raise Mismatch("R([1, 0, 0, 0]) is not the identity")


# ---------------------------------------------------------------- matrix_to_quat
@public_check("matrix_to_quat", "identity → [1, 0, 0, 0] and the quarter turn about z → [0.7071, 0, 0, 0.7071]")
def _(matrix_to_quat):
    got = require_shape(matrix_to_quat(np.eye(3)), (4,))
    if not close(got, ONE, 1e-12):
        raise Mismatch(f"the identity gave {fmt(got)}",
                       "-[1, 0, 0, 0] is the same rotation, but the canonical sign has w >= 0"
                       if close(got, -ONE, 1e-12) else None)
    got = require_shape(matrix_to_quat(QUARTER_TURN_Z), (4,))
    if not close(got, QUARTER_Z, 1e-12):
        raise Mismatch(f"the quarter turn about z gave {fmt(got)}", quaternion_hint(got, QUARTER_Z))


@public_check("matrix_to_quat", "a half turn about x (θ = π) gives ±[0, 1, 0, 0], with no division by zero")
def _(matrix_to_quat):
    got = matrix_to_quat(np.diag([1.0, -1.0, -1.0]))
    problem = shape_problem(got, (4,))
    if problem == "returned NaN or inf values":
        raise Mismatch(problem, "at θ = π, w = 0 and dividing by 4w fails")
    got = require_shape(got, (4,))
    if not same_rotation_quat(got, I_, 1e-12):
        hint = quaternion_hint(got, I_)
        if hint is None and np.max(np.abs(got[1:])) < 1e-6:
            hint = "the vector part vanished at θ = π, where R - Rᵀ = 0"
        raise Mismatch(f"got {fmt(got)}, expected ±[0, 1, 0, 0]", hint)


@public_check("matrix_to_quat", "returns a unit quaternion with w >= 0 (a turn by 5 rad about y)")
def _(matrix_to_quat):
    c, s = np.cos(5.0), np.sin(5.0)
    R = np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    got = require_shape(matrix_to_quat(R), (4,))
    if abs(np.linalg.norm(got) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.6f}", "scale the result to unit length")
    expected = np.array([np.cos(2.5), 0.0, np.sin(2.5), 0.0])   # w < 0: the canonical answer is -expected
    if close(got, expected, 1e-9):
        raise Mismatch(f"got w = {got[0]:.4f} < 0", "negate the whole quaternion when w < 0 (canonical sign)")
    if not close(got, -expected, 1e-9):
        raise Mismatch(f"got {fmt(got)}, expected {fmt(-expected)}, {off_by(got, -expected)}",
                       quaternion_hint(got, -expected))


@public_check("matrix_to_quat", "the canonical sign holds for a turn by 3 rad about (-0.8, 0.6, 0)")
def _(matrix_to_quat):
    u = np.array([-0.8, 0.6, 0.0])
    K = np.array([[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]])
    R = np.eye(3) + np.sin(3.0) * K + (1 - np.cos(3.0)) * K @ K
    got = require_shape(matrix_to_quat(R), (4,))
    expected = np.concatenate([[np.cos(1.5)], np.sin(1.5) * u])      # w = cos 1.5 > 0
    if close(got, -expected, 1e-9):
        raise Mismatch(f"got w = {got[0]:.4f} < 0",
                       "negate the whole quaternion when w < 0 (canonical sign), whichever way your code computed it")
    if not close(got, expected, 1e-9):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)}", quaternion_hint(got, expected))


def _rotation_of(q):
    """The rotation matrix of the unit quaternion q = [w, x, y, z] (scipy's, which stores [x, y, z, w])."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_quat(np.roll(q, -1)).as_matrix()


# Eight unit quaternions (w >= 0) spread over the sphere, four of them with a component 0 or nearly (w is 1e-6,
# not 0, so that the canonical sign w >= 0 names one of ±q).
SPREAD_QUATERNIONS = [q / np.linalg.norm(q) for q in np.array([
    [0.9, 0.3, -0.4, 0.2], [0.3, -0.9, 0.4, 0.2], [0.2, 0.4, 0.9, -0.3], [0.4, -0.2, 0.3, 0.9],
    [1e-6, 0.6, -0.5, 0.7], [0.5, 0.0, 0.6, -0.7], [0.6, -0.5, 0.0, 0.7], [0.5, 0.7, -0.6, 0.0]])]


@public_check("matrix_to_quat", "exact to 1e-12 for eight rotations spread over the sphere, four with a zero component")
def _(matrix_to_quat):
    for q in SPREAD_QUATERNIONS:
        R = _rotation_of(q)
        got = require_shape(matrix_to_quat(R.copy()), (4,), f"matrix_to_quat of the rotation of q = {fmt(q)}")
        if not close(got, q, 1e-12):
            hint = quaternion_hint(got, q)
            if hint is None and same_rotation_quat(got, q, 1e-12):
                hint = "negate the whole quaternion when w < 0 (canonical sign), whichever way your code computed it"
            if hint is None and float32_rounding(got, q):
                hint = FLOAT32_HINT
            raise Mismatch(f"the rotation of q = {fmt(q)} gave {fmt(got)} ({off_by(got, q)})",
                           hint or (f"this rotation turns by nearly π (w = {q[0]:.0e}): a component you divide by was "
                                    "small here" if q[0] < 1e-3 else
                                    "one of the components is wrong although the angle is far from π: compare the "
                                    "rotation of your quaternion with the input, entry by entry"))


# ---------------------------------------------------------------- wxyz_to_xyzw, xyzw_to_wxyz
def _layout_hint(got, q, to_end):
    """The hint for the typical wrong reordering of ``q`` (one quaternion or a stack) that ``got`` equals."""
    q = np.asarray(q, dtype=float)
    shift, where, index = ((-1, "end", "q[..., 1:] and q[..., :1]") if to_end else
                           (1, "front", "q[..., 3:] and q[..., :3]"))
    for value, hint in (
            (q[..., ::-1], hints.ARRAY_REVERSED_ONLY_SCALAR_HINT),
            (q, f"returned q unchanged: the scalar must move to the {where}"),
            (np.roll(q, -shift, axis=-1), f"rolled the wrong way: the scalar must move to the {where}"),
            (np.roll(q.ravel(), shift).reshape(q.shape),
             f"the whole stack was rolled as one flat array: roll along the last axis (axis=-1) or index {index}")):
        if close(got, value, 0.0):
            return hint
    return None


def _layout_checks(name, to_end):
    wxyz = np.array([[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0]])
    xyzw = np.roll(wxyz, -1, axis=-1)
    given, wanted = (wxyz, xyzw) if to_end else (xyzw, wxyz)
    description = ("[w, x, y, z] = [1, 2, 3, 4] becomes [x, y, z, w] = [2, 3, 4, 1]" if to_end else
                   "[x, y, z, w] = [2, 3, 4, 1] becomes [w, x, y, z] = [1, 2, 3, 4]")

    @public_check(name, description)
    def _(fn):
        got = require_shape(fn(given[0].tolist()), (4,))
        if not close(got, wanted[0], 0.0):
            raise Mismatch(f"got {fmt(got)}, expected {fmt(wanted[0])}", _layout_hint(got, given[0], to_end))

    @public_check(name, "keeps every digit of a generic quaternion (float64)")
    def _(fn):
        source = GENERIC if to_end else np.roll(GENERIC, -1)
        target = np.roll(source, -1) if to_end else np.roll(source, 1)
        got = require_shape(fn(source.copy()), (4,))
        if not close(got, target, 0.0):
            raise Mismatch(f"got {fmt(got, 6)}, expected {fmt(target, 6)} ({off_by(got, target)})",
                           FLOAT32_HINT if float32_rounding(got, target) else _layout_hint(got, source, to_end))

    @public_check(name, "converts a stack of quaternions, shape (N, 4), row by row")
    def _(fn):
        got = require_shape(fn(given.copy()), (2, 4))
        if not close(got, wanted, 0.0):
            raise Mismatch(f"got {fmt(got)}, expected {fmt(wanted)}", _layout_hint(got, given, to_end))


_layout_checks("wxyz_to_xyzw", to_end=True)
_layout_checks("xyzw_to_wxyz", to_end=False)


# ---------------------------------------------------------------- quat_slerp
@public_check("quat_slerp", "starts at q0 (t = 0) and ends at q1 (t = 1)")
def _(quat_slerp):
    got = require_shape(quat_slerp(ONE, GENERIC, 0.0), (4,))
    if not same_rotation_quat(got, ONE, 1e-9):
        raise Mismatch(f"t = 0 gave {fmt(got)}, expected q0 = [1, 0, 0, 0]")
    got = require_shape(quat_slerp(ONE, GENERIC, 1.0), (4,))
    if not same_rotation_quat(got, GENERIC, 1e-9):
        raise Mismatch(f"t = 1 gave {fmt(got)}, expected q1 = {fmt(GENERIC)}")


def _lerp_hint(got, q0, q1, t):
    """A hint when ``got`` is the plain linear blend (1 - t) q0 + t q1 (with or without the sign flip)."""
    for target in (q1, -q1):
        if close(got, (1 - t) * q0 + t * target, 1e-9):
            return ("plain linear interpolation (1 - t) q0 + t q1 leaves the unit sphere: "
                    "use the weights sin((1 - t)Ω)/sin Ω and sin(tΩ)/sin Ω")
    return hints.SLERP_STAYS_UNIT_SPHERE_HINT


@public_check("quat_slerp", "halfway from the identity to a quarter turn about z is an eighth turn")
def _(quat_slerp):
    got = require_shape(quat_slerp(ONE, QUARTER_Z, 0.5), (4,))
    eighth = np.array([np.cos(np.pi / 8), 0.0, 0.0, np.sin(np.pi / 8)])
    if abs(np.linalg.norm(got) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.4f}", _lerp_hint(got, ONE, QUARTER_Z, 0.5))
    if not same_rotation_quat(got, eighth, 1e-9):
        raise Mismatch(f"got {fmt(got)}, expected {fmt(eighth)}, "
                       f"off by {min(np.max(np.abs(got - eighth)), np.max(np.abs(got + eighth))):.2g} even up to sign")


@public_check("quat_slerp", "takes the shorter arc when q1 is given with the opposite sign")
def _(quat_slerp):
    eighth = np.array([np.cos(np.pi / 8), 0.0, 0.0, np.sin(np.pi / 8)])
    # The longer way from 1 to -q1 turns by -3π/2 about z; its midpoint is a turn by -3π/4.
    long_way = np.array([np.cos(3 * np.pi / 8), 0.0, 0.0, -np.sin(3 * np.pi / 8)])
    got = require_shape(quat_slerp(ONE, -QUARTER_Z, 0.5), (4,))
    if not same_rotation_quat(got, eighth, 1e-9):
        if abs(np.linalg.norm(got) - 1.0) > 1e-9:
            hint = _lerp_hint(got, ONE, -QUARTER_Z, 0.5)
        elif same_rotation_quat(got, long_way, 1e-9):
            hint = "took the longer arc: q1 and -q1 are one rotation; if q0 · q1 < 0, use -q1 (the shorter arc)"
        else:
            hint = None
        raise Mismatch(f"with q1 = -(quarter turn) the midpoint is {fmt(got)}, not an eighth turn", hint)


@public_check("quat_slerp", "turns at constant speed: at t = 0.25 of a 2.5 rad turn it has turned 0.625 rad")
def _(quat_slerp):
    u = np.array([2.0, -1.0, 2.0]) / 3.0
    q1 = np.concatenate([[np.cos(1.25)], np.sin(1.25) * u])
    got = require_shape(quat_slerp(ONE, q1, 0.25), (4,))
    if abs(np.linalg.norm(got) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.4f}", _lerp_hint(got, ONE, q1, 0.25))
    turned = 2.0 * np.arccos(min(abs(got[0]), 1.0))
    if abs(turned - 0.625) > 1e-9:
        blend = 0.75 * ONE + 0.25 * q1
        if same_rotation_quat(got, blend / np.linalg.norm(blend), 1e-9):
            hint = (hints.CONSTANT_SPEED_NORMALISED_LINEAR_HINT)
        else:
            hint = (hints.CONSTANT_SPEED_TURN_Q0_HINT)
        raise Mismatch(f"at t = 0.25 it has turned {turned:.6f} rad, off by {abs(turned - 0.625):.2g}", hint)


# Half-angles Ω between q0 = 1 and q1 = [cos Ω, 0, 0, sin Ω]: every decade, and one below any sensible fallback.
# The expected value is the rotation by the fraction t of the turn from q0 to q1, about z, from scipy.
SLERP_OMEGAS = [1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-13]


@public_check("quat_slerp", "exact to 2e-15 at t = 0.3 for every decade of Ω = acos(q0 · q1), 1 … 1e-8 and 1e-13, "
                            "with q1 given with either sign")
def _(quat_slerp):
    t = 0.3
    for omega in SLERP_OMEGAS:
        expected = Rotation.from_rotvec([0.0, 0.0, 2.0 * t * omega]).as_quat(scalar_first=True)
        for sign in (1.0, -1.0):
            q1 = sign * np.array([np.cos(omega), 0.0, 0.0, np.sin(omega)])
            got = require_shape(quat_slerp(ONE.copy(), q1, t), (4,), f"quat_slerp(1, q1, 0.3) at Ω = {omega:g}")
            if not close(got, expected, 2e-15):
                hint = None
                if float32_rounding(got, expected):
                    hint = FLOAT32_HINT
                elif omega < 0.5:
                    hint = ("off at small Ω only: a linear fallback (nlerp) differs from slerp by about Ω³ t (1 - t), "
                            "so use it only where that is below rounding (Ω under about 1e-5), and blend both ends "
                            "there too")
                raise Mismatch(f"at Ω = {omega:g} with q1 given {'as is' if sign > 0 else 'negated'}: got "
                               f"{fmt(got, 6)}, expected {fmt(expected, 6)} ({off_by(got, expected)})", hint)


@public_check("quat_slerp", "nearly identical and equal inputs do not divide by zero (nor take arccos of 1 + 2e-16)")
def _(quat_slerp):
    tiny = np.array([np.cos(1e-10), np.sin(1e-10), 0.0, 0.0])
    got = require_shape(quat_slerp(ONE, tiny, 0.5), (4,),
                        nan_hint=lambda _: "sin Ω = 0 for equal inputs; when sin Ω is tiny, fall back to "
                                           "(normalised) linear interpolation")
    if not same_rotation_quat(got, ONE, 1e-9):
        raise Mismatch(f"got {fmt(got)}, off by {min(np.max(np.abs(got - ONE)), np.max(np.abs(got + ONE))):.2g} "
                       "even up to sign", "between nearly identical inputs the result is (nearly) q0")
    # a unit quaternion whose q · q rounds to 1 + 2.2e-16: arccos(q0 · q1) is NaN unless q0 · q1 is clipped to 1
    q = np.array([-0.8466057152828365, -0.07966788016829934, -0.45366940523260274, -0.2666380739426069])
    got = require_shape(quat_slerp(q, q, 0.5), (4,),
                        nan_hint=lambda _: "q0 · q1 can round to just above 1 for equal inputs: clip it with "
                                           "min(d, 1.0) before np.arccos")
    if not same_rotation_quat(got, q, 1e-12):
        raise Mismatch(f"quat_slerp(q, q, 0.5) = {fmt(got)}, expected q itself", None)
