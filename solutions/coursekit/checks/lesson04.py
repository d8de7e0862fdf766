"""Public checks for lesson 04: quaternions.

The checks use quaternions whose products can be written down by hand
(the units 1, i, j, k, quarter and half turns about a coordinate axis) and
properties every correct answer has: unit norms, orthogonality, fixed axes,
a round trip through one function. Quaternions are stored scalar first,
``[w, x, y, z]``.
"""

import numpy as np

from ..checking import Mismatch, public_check
from ..diagnose import (
    close,
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
@public_check("quat_multiply", "follows Hamilton's rules: i ⊗ j = k, j ⊗ i = -k, i ⊗ i = -1")
def _(quat_multiply):
    got = require_shape(quat_multiply(I_, J_), (4,))
    if close(got, -K_, 1e-12):
        raise Mismatch("i ⊗ j gave -k",
                       "the sign of the cross product is flipped (that is the JPL product): "
                       "the vector part is p_w q_v + q_w p_v + p_v × q_v")
    if not close(got, K_, 1e-12):
        raise Mismatch(f"i ⊗ j gave {fmt(got)}, expected k = [0, 0, 0, 1]")
    got = require_shape(quat_multiply(J_, I_), (4,))
    if not close(got, -K_, 1e-12):
        raise Mismatch(f"j ⊗ i gave {fmt(got)}, expected -k = [0, 0, 0, -1]", "the product is not commutative")
    got = require_shape(quat_multiply(I_, I_), (4,))
    if not close(got, -ONE, 1e-12):
        raise Mismatch(f"i ⊗ i gave {fmt(got)}, expected -1 = [-1, 0, 0, 0]",
                       "the scalar part is p_w q_w - p_v · q_v (minus the dot product)")


@public_check("quat_multiply", "[1, 0, 0, 0] is the identity on both sides, for any quaternion")
def _(quat_multiply):
    for name, got in (("1 ⊗ q", quat_multiply(ONE, LONG)), ("q ⊗ 1", quat_multiply(LONG, ONE))):
        got = require_shape(got, (4,))
        if not close(got, LONG, 1e-12):
            raise Mismatch(f"{name} gave {fmt(got)} for q = {fmt(LONG)}")


@public_check("quat_multiply", "the norm is multiplicative: |p ⊗ q| = |p| |q|")
def _(quat_multiply):
    got = require_shape(quat_multiply(LONG, GENERIC), (4,))
    if abs(np.linalg.norm(got) - np.linalg.norm(LONG)) > 1e-12:
        raise Mismatch(f"|p ⊗ q| = {np.linalg.norm(got):.6f}, expected {np.linalg.norm(LONG):.6f}",
                       "check each of the 16 terms of the product against the formula")


# ---------------------------------------------------------------- quat_left, quat_right
def _matrix_checks(name, side):
    @public_check(name, "returns a 4×4 matrix whose first column is q (q ⊗ 1 = 1 ⊗ q = q)")
    def _(fn):
        M = require_shape(fn(LONG), (4, 4))
        if not close(M @ ONE, LONG, 1e-12):
            raise Mismatch(f"{name}(q) @ [1, 0, 0, 0] = {fmt(M @ ONE)}, expected q = {fmt(LONG)}")

    if side == "left":
        factor, other, description = I_, J_, "[i]_L @ j = i ⊗ j = k"
    else:
        factor, other, description = J_, I_, "[j]_R @ i = i ⊗ j = k"

    @public_check(name, description)
    def _(fn):
        got = require_shape(fn(factor), (4, 4)) @ other
        if close(got, -K_, 1e-12):
            raise Mismatch("got -k instead of k",
                           "the [v]× block has the wrong sign: +[v]× in [q]_L, -[v]× in [q]_R")
        if not close(got, K_, 1e-12):
            raise Mismatch(f"got {fmt(got)}, expected k = [0, 0, 0, 1]")

    @public_check(name, "is orthogonal for a unit quaternion (MᵀM = I)")
    def _(fn):
        M = require_shape(fn(GENERIC), (4, 4))
        error = np.max(np.abs(M.T @ M - np.eye(4)))
        if error > 1e-12:
            raise Mismatch(f"max |MᵀM - I| = {error:.2g}", "compare your entries with the matrix in §4, one sign at a time")


_matrix_checks("quat_left", "left")
_matrix_checks("quat_right", "right")


# ---------------------------------------------------------------- quat_conjugate
@public_check("quat_conjugate", "flips the vector part: [1, 2, 3, 4]* = [1, -2, -3, -4]")
def _(quat_conjugate):
    q = np.array([1.0, 2.0, 3.0, 4.0])
    got = require_shape(quat_conjugate(q), (4,))
    if close(got, [-1.0, 2.0, 3.0, 4.0], 1e-12):
        raise Mismatch("negated the scalar part instead of the vector part",
                       "q* = [w, -x, -y, -z]; the result is -q*, the same rotation but not the conjugate")
    if not close(got, [1.0, -2.0, -3.0, -4.0], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [1, -2, -3, -4]")


@public_check("quat_conjugate", "accepts a plain list")
def _(quat_conjugate):
    require_same_with_lists(quat_conjugate, (GENERIC,), (4,), "quat_conjugate")


# ---------------------------------------------------------------- quat_inverse
@public_check("quat_inverse", "for a unit quaternion the inverse is the conjugate")
def _(quat_inverse):
    got = require_shape(quat_inverse(GENERIC), (4,))
    if not close(got, _conjugate(GENERIC), 1e-12):
        raise Mismatch(f"got {fmt(got)} for q = {fmt(GENERIC)}, expected its conjugate")


@public_check("quat_inverse", "works for quaternions that are not unit: [1, 1, 1, 1]⁻¹ = [1, -1, -1, -1] / 4")
def _(quat_inverse):
    got = require_shape(quat_inverse([1.0, 1.0, 1.0, 1.0]), (4,))
    if close(got, [1.0, -1.0, -1.0, -1.0], 1e-12):
        raise Mismatch("returned the conjugate without dividing", "q⁻¹ = q* / |q|², with |q|² = w² + x² + y² + z²")
    if close(got, [0.5, -0.5, -0.5, -0.5], 1e-12):
        raise Mismatch("divided by |q| = 2 instead of |q|² = 4", "q⁻¹ = q* / |q|²: the norm squared")
    if not close(got, [0.25, -0.25, -0.25, -0.25], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [0.25, -0.25, -0.25, -0.25]")


# ---------------------------------------------------------------- quat_from_axis_angle
@public_check("quat_from_axis_angle", "a quarter turn about z is [cos 45°, 0, 0, sin 45°]")
def _(quat_from_axis_angle):
    got = require_shape(quat_from_axis_angle([0.0, 0.0, 1.0], np.pi / 2), (4,))
    if close(got, [0.0, 0.0, 0.0, 1.0], 1e-9):
        raise Mismatch("got [0, 0, 0, 1], the quaternion of a half turn",
                       "the quaternion uses half the angle: [cos(θ/2), u sin(θ/2)]")
    if close(got, [0.0, 0.0, HALF, HALF], 1e-9):
        raise Mismatch(f"got {fmt(got)}", "scalar last? this course stores [w, x, y, z]")
    half_degrees = np.deg2rad(np.pi / 2) / 2       # what np.cos(θ/2) gives when θ = π/2 is read as degrees
    if close(got, [np.cos(half_degrees), 0.0, 0.0, np.sin(half_degrees)], 1e-9):
        raise Mismatch(f"got {fmt(got)}, barely a turn", "looks like degrees: angles in this course are radians")
    if not close(got, QUARTER_Z, 1e-9):
        raise Mismatch(f"got {fmt(got)}, expected [0.7071, 0, 0, 0.7071]")


@public_check("quat_from_axis_angle", "normalises the axis and returns a unit quaternion")
def _(quat_from_axis_angle):
    got = require_shape(quat_from_axis_angle([0.0, 3.0, 4.0], 1.2), (4,))
    if abs(np.linalg.norm(got) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.4f} for the axis [0, 3, 4]", "divide u by its norm first")
    expected = np.array([np.cos(0.6), 0.0, 0.6 * np.sin(0.6), 0.8 * np.sin(0.6)])
    if not close(got, expected, 1e-9):
        raise Mismatch(f"got {fmt(got)}, expected {fmt(expected)}")


@public_check("quat_from_axis_angle", "θ = 0 gives the identity [1, 0, 0, 0]")
def _(quat_from_axis_angle):
    got = require_shape(quat_from_axis_angle([1.0, 0.0, 0.0], 0.0), (4,))
    if not close(got, ONE, 1e-12):
        raise Mismatch(f"got {fmt(got)}")


# ---------------------------------------------------------------- quat_rotate
@public_check("quat_rotate", "a quarter turn about z sends x to y, and leaves z where it is")
def _(quat_rotate):
    got = require_shape(quat_rotate(QUARTER_Z, [1.0, 0.0, 0.0]), (3,))
    if close(got, [0.0, -1.0, 0.0], 1e-9):
        raise Mismatch("x went to -y: the rotation runs backwards",
                       "use q ⊗ [0, v] ⊗ q*, with the conjugate on the right")
    if not close(got, [0.0, 1.0, 0.0], 1e-9):
        raise Mismatch(f"x went to {fmt(got)}, expected [0, 1, 0]")
    got = require_shape(quat_rotate(QUARTER_Z, [0.0, 0.0, 2.0]), (3,))
    if not close(got, [0.0, 0.0, 2.0], 1e-9):
        raise Mismatch(f"the axis z went to {fmt(got)}", "vectors along the axis must not move")


@public_check("quat_rotate", "keeps lengths and gives the same result for q and -q")
def _(quat_rotate):
    v = np.array([0.3, -1.2, 2.0])
    got = require_shape(quat_rotate(GENERIC, v), (3,))
    if abs(np.linalg.norm(got) - np.linalg.norm(v)) > 1e-9:
        raise Mismatch(f"|v| = {np.linalg.norm(v):.4f} became {np.linalg.norm(got):.4f}",
                       "use the conjugate of q (and a unit q) on the right of the sandwich")
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
        raise Mismatch("R(q) differs from R(-q)", "every entry of R(q) is a product of two components of q")


@public_check("quat_to_matrix", "the quarter turn about z: x → y (and the identity for [1, 0, 0, 0])")
def _(quat_to_matrix):
    R = require_shape(quat_to_matrix(QUARTER_Z), (3, 3))
    if close(R, QUARTER_TURN_Z.T, 1e-9):
        raise Mismatch("got the transpose (the inverse rotation)",
                       "check the sign of the 2w[v]× part: R[1, 0] = 2(xy + wz)")
    if close(R, np.array([[1.0, 0, 0], [0, 0, -1.0], [0, 1.0, 0]]), 1e-9):
        raise Mismatch("got a quarter turn about x", "scalar last? this course stores q = [w, x, y, z]")
    if not close(R, QUARTER_TURN_Z, 1e-9):
        raise Mismatch(f"got\n{fmt(R)}")
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
    if problem:
        raise Mismatch(problem, "at θ = π, w = 0: start from the largest of w², x², y², z² (Shepperd)")
    if not same_rotation_quat(got, I_, 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected ±[0, 1, 0, 0]",
                       "at θ = π, w = 0: start from the largest of w², x², y², z² (Shepperd)")


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
        raise Mismatch(f"got {fmt(got)}, expected {fmt(-expected)}", quaternion_hint(got, -expected))


@public_check("matrix_to_quat", "the canonical sign holds in every branch (a turn by 3 rad about (-0.8, 0.6, 0))")
def _(matrix_to_quat):
    u = np.array([-0.8, 0.6, 0.0])
    K = np.array([[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]])
    R = np.eye(3) + np.sin(3.0) * K + (1 - np.cos(3.0)) * K @ K      # R[0, 0] is the largest diagonal entry
    got = require_shape(matrix_to_quat(R), (4,))
    expected = np.concatenate([[np.cos(1.5)], np.sin(1.5) * u])      # w = cos 1.5 > 0
    if close(got, -expected, 1e-9):
        raise Mismatch(f"got w = {got[0]:.4f} < 0 from the x branch",
                       "negate the whole quaternion when w < 0 (canonical sign), in every branch")
    if not close(got, expected, 1e-9):
        raise Mismatch(f"got {fmt(got)}, {off_by(got, expected)}", quaternion_hint(got, expected))


# ---------------------------------------------------------------- wxyz_to_xyzw, xyzw_to_wxyz
@public_check("wxyz_to_xyzw", "[w, x, y, z] = [1, 2, 3, 4] becomes [x, y, z, w] = [2, 3, 4, 1]")
def _(wxyz_to_xyzw):
    got = require_shape(wxyz_to_xyzw([1.0, 2.0, 3.0, 4.0]), (4,))
    if close(got, [4.0, 3.0, 2.0, 1.0], 0.0):
        raise Mismatch("got [4, 3, 2, 1]: the array was reversed", "move only the scalar: the vector keeps x, y, z order")
    if not close(got, [2.0, 3.0, 4.0, 1.0], 0.0):
        raise Mismatch(f"got {fmt(got)}, expected [2, 3, 4, 1]")


@public_check("wxyz_to_xyzw", "converts a stack of quaternions, shape (N, 4), row by row")
def _(wxyz_to_xyzw):
    stack = np.array([[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0]])
    got = require_shape(wxyz_to_xyzw(stack), (2, 4))
    if not close(got, [[2.0, 3.0, 4.0, 1.0], [6.0, 7.0, 8.0, 5.0]], 0.0):
        raise Mismatch(f"got {fmt(got)}", "index the last axis: q[..., 1:] and q[..., :1]")


@public_check("xyzw_to_wxyz", "[x, y, z, w] = [2, 3, 4, 1] becomes [w, x, y, z] = [1, 2, 3, 4]")
def _(xyzw_to_wxyz):
    got = require_shape(xyzw_to_wxyz([2.0, 3.0, 4.0, 1.0]), (4,))
    if close(got, [1.0, 4.0, 3.0, 2.0], 0.0):
        raise Mismatch("got [1, 4, 3, 2]: the array was reversed", "move only the scalar: the vector keeps x, y, z order")
    if close(got, [3.0, 4.0, 1.0, 2.0], 0.0):
        raise Mismatch("got [3, 4, 1, 2]", "the scalar is the last entry: move it to the front")
    if not close(got, [1.0, 2.0, 3.0, 4.0], 0.0):
        raise Mismatch(f"got {fmt(got)}, expected [1, 2, 3, 4]")


@public_check("xyzw_to_wxyz", "converts a stack of quaternions, shape (N, 4), row by row")
def _(xyzw_to_wxyz):
    stack = np.array([[2.0, 3.0, 4.0, 1.0], [6.0, 7.0, 8.0, 5.0]])
    got = require_shape(xyzw_to_wxyz(stack), (2, 4))
    if not close(got, [[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0]], 0.0):
        raise Mismatch(f"got {fmt(got)}", "index the last axis: q[..., 3:] and q[..., :3]")


# ---------------------------------------------------------------- quat_slerp
@public_check("quat_slerp", "starts at q0 (t = 0) and ends at q1 (t = 1)")
def _(quat_slerp):
    got = require_shape(quat_slerp(ONE, GENERIC, 0.0), (4,))
    if not same_rotation_quat(got, ONE, 1e-9):
        raise Mismatch(f"t = 0 gave {fmt(got)}, expected q0 = [1, 0, 0, 0]")
    got = require_shape(quat_slerp(ONE, GENERIC, 1.0), (4,))
    if not same_rotation_quat(got, GENERIC, 1e-9):
        raise Mismatch(f"t = 1 gave {fmt(got)}, expected q1 = {fmt(GENERIC)}")


@public_check("quat_slerp", "halfway from the identity to a quarter turn about z is an eighth turn")
def _(quat_slerp):
    got = require_shape(quat_slerp(ONE, QUARTER_Z, 0.5), (4,))
    eighth = np.array([np.cos(np.pi / 8), 0.0, 0.0, np.sin(np.pi / 8)])
    if abs(np.linalg.norm(got) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.4f}", "slerp stays on the unit sphere; plain averaging does not")
    if not same_rotation_quat(got, eighth, 1e-9):
        raise Mismatch(f"got {fmt(got)}, expected {fmt(eighth)}")


@public_check("quat_slerp", "takes the shorter arc when q1 is given with the opposite sign")
def _(quat_slerp):
    eighth = np.array([np.cos(np.pi / 8), 0.0, 0.0, np.sin(np.pi / 8)])
    got = require_shape(quat_slerp(ONE, -QUARTER_Z, 0.5), (4,))
    if not same_rotation_quat(got, eighth, 1e-9):
        raise Mismatch(f"with q1 = -(quarter turn) the midpoint is {fmt(got)}, not an eighth turn",
                       "q1 and -q1 are one rotation: if q0 · q1 < 0, use -q1 (the shorter arc)")


@public_check("quat_slerp", "turns at constant speed: at t = 0.25 of a 2.5 rad turn it has turned 0.625 rad")
def _(quat_slerp):
    u = np.array([2.0, -1.0, 2.0]) / 3.0
    q1 = np.concatenate([[np.cos(1.25)], np.sin(1.25) * u])
    got = require_shape(quat_slerp(ONE, q1, 0.25), (4,))
    if abs(np.linalg.norm(got) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(got):.4f}", "slerp stays on the unit sphere; plain averaging does not")
    turned = 2.0 * np.arccos(min(abs(got[0]), 1.0))
    if abs(turned - 0.625) > 1e-9:
        raise Mismatch(f"at t = 0.25 it has turned {turned:.6f} rad, off by {abs(turned - 0.625):.2g}",
                       "not at constant speed: a normalised linear blend (nlerp) runs fast in the middle; use the "
                       "weights sin((1 - t)Ω)/sin Ω and sin(tΩ)/sin Ω")


@public_check("quat_slerp", "nearly identical inputs do not divide by zero")
def _(quat_slerp):
    tiny = np.array([np.cos(1e-10), np.sin(1e-10), 0.0, 0.0])
    got = require_shape(quat_slerp(ONE, tiny, 0.5), (4,))
    if not same_rotation_quat(got, ONE, 1e-9):
        raise Mismatch(f"got {fmt(got)}", "when sin Ω is tiny, fall back to (normalised) linear interpolation")
