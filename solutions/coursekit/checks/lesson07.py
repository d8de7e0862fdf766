"""Public checks for lesson 07: poses and rigid-body transformations.

The checks use poses written out by hand (a quarter turn about z and a shift
by (1, 2, 3)), definitional facts (a pose times its inverse is the identity,
a pure translation has V = I) and scipy's general matrix exponential ``expm``
as an independent oracle for the exponential map of SE(3).
"""

import numpy as np
from scipy.linalg import expm

from ..checking import Mismatch, public_check
from ..diagnose import close
from .common import fmt, off_by, require_pose, require_same_with_lists, require_shape

# A quarter turn about z (x goes to y) followed by a shift of (1, 2, 3) m, written out.
QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
SHIFT = np.array([1.0, 2.0, 3.0])
T_QUARTER = np.array([[0.0, -1.0, 0.0, 1.0],
                      [1.0, 0.0, 0.0, 2.0],
                      [0.0, 0.0, 1.0, 3.0],
                      [0.0, 0.0, 0.0, 1.0]])
# A quarter turn about x (y goes to z) with a shift of (0, -1, 0.5) m.
T_QUARTER_X = np.array([[1.0, 0.0, 0.0, 0.0],
                        [0.0, 0.0, -1.0, -1.0],
                        [0.0, 1.0, 0.0, 0.5],
                        [0.0, 0.0, 0.0, 1.0]])


def _twist_matrix(xi):
    rho, phi = np.asarray(xi[:3], dtype=float), np.asarray(xi[3:], dtype=float)
    return np.array([[0.0, -phi[2], phi[1], rho[0]],
                     [phi[2], 0.0, -phi[0], rho[1]],
                     [-phi[1], phi[0], 0.0, rho[2]],
                     [0.0, 0.0, 0.0, 0.0]])


# ---------------------------------------------------------------- make_pose
@public_check("make_pose", "puts R top-left, t in the last column and [0, 0, 0, 1] below")
def _(make_pose):
    T = require_shape(make_pose(QUARTER_TURN_Z, SHIFT), (4, 4))
    if close(T, T_QUARTER.T, 1e-12):
        raise Mismatch("got the transpose of the pose matrix",
                       "t goes in the last column (T[:3, 3]), not in the bottom row")
    if not close(T[:3, 3], SHIFT, 1e-12):
        raise Mismatch(f"the last column holds {fmt(T[:3, 3])}, expected t = [1, 2, 3]")
    if not close(T[:3, :3], QUARTER_TURN_Z, 1e-12):
        raise Mismatch("the top-left 3×3 block is not R", "copy R itself, not its transpose")
    if not close(T[3], [0.0, 0.0, 0.0, 1.0], 1e-12):
        raise Mismatch(f"the bottom row is {fmt(T[3])}, expected [0, 0, 0, 1]")


@public_check("make_pose", "accepts plain lists")
def _(make_pose):
    require_same_with_lists(make_pose, (QUARTER_TURN_Z, SHIFT), (4, 4), "make_pose")


# ---------------------------------------------------------------- to_homogeneous / from_homogeneous
@public_check("to_homogeneous", "appends a 1 to one point: shape (3,) → (4,)")
def _(to_homogeneous):
    got = require_shape(to_homogeneous([1.0, 2.0, 3.0]), (4,))
    if close(got, [1.0, 2.0, 3.0, 0.0], 1e-12):
        raise Mismatch("appended a 0", "a 0 marks a direction; points get a 1")
    if not close(got, [1.0, 2.0, 3.0, 1.0], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [1, 2, 3, 1]")


@public_check("to_homogeneous", "appends a 1 to every row: shape (N, 3) → (N, 4)")
def _(to_homogeneous):
    P = np.array([[1.0, 2.0, 3.0], [-4.0, 0.5, 0.0]])
    got = to_homogeneous(P)
    if np.shape(got) == (3, 3):
        raise Mismatch("returned shape 3×3: a row of ones was added below the points",
                       "append a column: the new coordinate belongs to every point (axis=-1)")
    got = require_shape(got, (2, 4))
    if not close(got, np.column_stack([P, np.ones(2)]), 1e-12):
        raise Mismatch(f"got {fmt(got)}", "each row should be the point followed by a 1")


@public_check("from_homogeneous", "divides by the last coordinate: [2, 4, 6, 2] → [1, 2, 3]")
def _(from_homogeneous):
    got = require_shape(from_homogeneous([2.0, 4.0, 6.0, 2.0]), (3,))
    if close(got, [2.0, 4.0, 6.0], 1e-12):
        raise Mismatch("got [2, 4, 6]: the last coordinate was dropped without dividing",
                       "[x, y, z, w] is the point [x/w, y/w, z/w]")
    if not close(got, [1.0, 2.0, 3.0], 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected [1, 2, 3]")


@public_check("from_homogeneous", "works on rows: shape (N, 4) → (N, 3)")
def _(from_homogeneous):
    P_h = np.array([[2.0, 4.0, 6.0, 2.0], [1.0, -1.0, 0.5, 0.5], [3.0, 0.0, 0.0, 1.0]])
    got = require_shape(from_homogeneous(P_h), (3, 3))
    expected = np.array([[1.0, 2.0, 3.0], [2.0, -2.0, 1.0], [3.0, 0.0, 0.0]])
    if not close(got, expected, 1e-12):
        raise Mismatch(f"got {fmt(got)}, expected {fmt(expected)}",
                       "divide each row by its own last coordinate (P_h[..., -1:] keeps the shape)")


# ---------------------------------------------------------------- transform_points
@public_check("transform_points", "turns and shifts N points (shape (N, 3)): p_a = R p_b + t")
def _(transform_points):
    P = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 2.0, -1.0]])
    got = require_shape(transform_points(T_QUARTER, P), (3, 3))
    expected = np.array([[1.0, 3.0, 3.0], [1.0, 2.0, 3.0], [-1.0, 2.0, 2.0]])
    if close(got, expected, 1e-12):
        return
    if close(got, P @ QUARTER_TURN_Z.T, 1e-12):
        raise Mismatch("the points were turned but not shifted", "add the translation t = T[:3, 3]")
    if close(got, P @ QUARTER_TURN_Z + SHIFT, 1e-12):
        raise Mismatch("the points were turned the wrong way",
                       "for rows use P @ R.T (or P_h @ T.T), not P @ R")
    if close(got, (P + SHIFT) @ QUARTER_TURN_Z.T, 1e-12):
        raise Mismatch("the points were shifted, then turned", "rotate first, then shift: R p + t")
    raise Mismatch(f"got {fmt(got)}, expected {fmt(expected)}")


@public_check("transform_points", "accepts a single point of shape (3,)")
def _(transform_points):
    got = require_shape(transform_points(T_QUARTER, [1.0, 0.0, 0.0]), (3,))
    if not close(got, [1.0, 3.0, 3.0], 1e-12):
        raise Mismatch(f"got {fmt(got)} for the point [1, 0, 0], expected [1, 3, 3]")


# ---------------------------------------------------------------- pose_compose
@public_check("transform_points", "accepts plain lists")
def _(transform_points):
    require_same_with_lists(transform_points, (T_QUARTER_X, [[0.5, -1.0, 2.0], [1.0, 0.0, 0.0]]), (2, 3),
                            "transform_points")


@public_check("pose_compose", "T_ac = T_ab T_bc: one step equals two steps for a point of c")
def _(pose_compose):
    T_ac = require_shape(pose_compose(T_QUARTER, T_QUARTER_X), (4, 4))
    p_c = np.array([0.3, -1.2, 2.0, 1.0])
    if close(T_ac @ p_c, T_QUARTER @ (T_QUARTER_X @ p_c), 1e-12):
        return
    if close(T_ac, T_QUARTER_X @ T_QUARTER, 1e-12):
        raise Mismatch("the two poses are multiplied in the wrong order",
                       "inner letters must match: T_ac = T_ab @ T_bc")
    raise Mismatch("pose_compose(T_ab, T_bc) @ p differs from T_ab @ (T_bc @ p)")


# ---------------------------------------------------------------- pose_inverse
@public_check("pose_inverse", "a pose times its inverse is the identity")
def _(pose_inverse):
    got = require_shape(pose_inverse(T_QUARTER), (4, 4))
    if close(got, T_QUARTER.T, 1e-12):
        raise Mismatch("returned the transpose of T",
                       "a pose is not orthogonal: transpose the rotation block and use -Rᵀ t")
    require_pose(got)
    if close(got[:3, 3], -SHIFT, 1e-12):
        raise Mismatch(f"the translation of the inverse is -t = {fmt(-SHIFT)}",
                       "turn it too: the inverse translation is -Rᵀ t")
    if not close(T_QUARTER @ got, np.eye(4), 1e-12):
        raise Mismatch("T @ pose_inverse(T) is not the identity")


@public_check("pose_inverse", "takes a point back: T_ba (T_ab p) = p")
def _(pose_inverse):
    got = require_shape(pose_inverse(T_QUARTER_X), (4, 4))
    p = np.array([0.7, 0.1, -2.0, 1.0])
    if not close(got @ (T_QUARTER_X @ p), p, 1e-12):
        raise Mismatch(f"got {fmt((got @ (T_QUARTER_X @ p))[:3])} back instead of {fmt(p[:3])}")


# ---------------------------------------------------------------- exp_se3
@public_check("exp_se3", "a twist with phi = 0 is a pure translation by rho")
def _(exp_se3):
    T = exp_se3([1.0, 2.0, 3.0, 0.0, 0.0, 0.0])
    if np.shape(T) == (4, 4) and not np.all(np.isfinite(np.asarray(T, dtype=float))):
        raise Mismatch("returned NaN or inf at phi = 0", "below θ = 1e-2 use the series for V: no 0/0")
    T = require_shape(T, (4, 4))
    if close(T[:3, :3], expm(_twist_matrix([0.0, 0.0, 0.0, 1.0, 2.0, 3.0]))[:3, :3], 1e-9):
        raise Mismatch("rho was used as the rotation vector",
                       "xi = [rho, phi]: translation part first (xi[:3]), rotation part last (xi[3:])")
    expected = np.eye(4)
    expected[:3, 3] = [1.0, 2.0, 3.0]
    if not close(T, expected, 1e-12):
        raise Mismatch(f"got translation {fmt(T[:3, 3])} and a non-identity rotation block")


@public_check("exp_se3", "xi = [0, 0, 0, 0, 0, π/2] is a quarter turn about z")
def _(exp_se3):
    T = require_shape(exp_se3([0.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2]), (4, 4))
    expected = np.eye(4)
    expected[:3, :3] = QUARTER_TURN_Z
    if not close(T, expected, 1e-12):
        raise Mismatch(f"got {fmt(T)}", "the rotation block is Exp(phi) with phi = xi[3:]")


@public_check("exp_se3", "agrees with scipy's matrix exponential (expm) of the 4×4 twist matrix")
def _(exp_se3):
    xi = np.array([1.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])
    T = require_shape(exp_se3(xi), (4, 4))
    expected = expm(_twist_matrix(xi))
    if close(T, expected, 1e-9):
        return
    if close(T[:3, 3], xi[:3], 1e-9):
        raise Mismatch(f"the translation equals rho = {fmt(xi[:3])}, expected {fmt(expected[:3, 3])}",
                       "the translation of exp(xi) is V(phi) @ rho, not rho")
    raise Mismatch(f"got translation {fmt(T[:3, 3])}, expected {fmt(expected[:3, 3])}")


def _tiny_twist(angle):
    """rho of length 50 and a rotation part of length ``angle``."""
    return np.array([30.0, -40.0, 0.0]), angle * np.array([2.0, -1.0, 2.0]) / 3.0


@public_check("exp_se3", "tiny rotation parts keep their accuracy: |phi| = 1e-9 and 1e-6 with |rho| = 50")
def _(exp_se3):
    for angle in (1e-9, 1e-6):
        rho, phi = _tiny_twist(angle)
        xi = np.concatenate([rho, phi])
        T = require_shape(exp_se3(xi), (4, 4), f"exp_se3 at |phi| = {angle:g}")
        expected = expm(_twist_matrix(xi))
        if not close(T, expected, 1e-12 * 50.0):
            raise Mismatch(f"at |phi| = {angle:g}, |rho| = 50 the pose is {off_by(T, expected)} (allowed 5e-11)",
                           "below θ = 1e-2 use the series of V's coefficients (1/2 - θ²/24, 1/6 - θ²/120): "
                           "once cos θ rounds to 1, (1 - cos θ)/θ² is 0, not 1/2")


# ---------------------------------------------------------------- log_se3
@public_check("log_se3", "log_se3(I) = 0 (no NaN at zero angle)")
def _(log_se3):
    xi = log_se3(np.eye(4))
    if np.shape(xi) == (6,) and not np.all(np.isfinite(np.asarray(xi, dtype=float))):
        raise Mismatch("returned NaN or inf for the identity",
                       "below θ = 1e-2 use the series for c(θ): 1/12 + θ²/720 + θ⁴/30240")
    xi = require_shape(xi, (6,))
    if not close(xi, np.zeros(6), 1e-12):
        raise Mismatch(f"got {fmt(xi)}")


@public_check("log_se3", "a pure translation gives xi = [t, 0, 0, 0]")
def _(log_se3):
    T = np.eye(4)
    T[:3, 3] = SHIFT
    xi = require_shape(log_se3(T), (6,))
    if close(xi, [0.0, 0.0, 0.0, 1.0, 2.0, 3.0], 1e-12):
        raise Mismatch("got [0, 0, 0, 1, 2, 3]", "xi = [rho, phi]: translation part first")
    if not close(xi, [1.0, 2.0, 3.0, 0.0, 0.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(xi)}, expected [1, 2, 3, 0, 0, 0]")


@public_check("log_se3", "tiny rotation parts keep their accuracy: |phi| = 1e-9 and 1e-6 with |rho| = 50")
def _(log_se3):
    for angle in (1e-9, 1e-6):
        rho, phi = _tiny_twist(angle)
        xi = np.concatenate([rho, phi])
        got = require_shape(log_se3(expm(_twist_matrix(xi))), (6,), f"log_se3 at |phi| = {angle:g}")
        if not close(got, xi, 1e-11 * 50.0):
            raise Mismatch(f"at |phi| = {angle:g}, |rho| = 50 the twist is {off_by(got, xi)} (allowed 5e-10)",
                           "below θ = 1e-2 use the series c = 1/12 + θ²/720 + θ⁴/30240: "
                           "the closed form cancels catastrophically there")


@public_check("log_se3", "round trip: expm of the twist matrix of log_se3(T) gives T back")
def _(log_se3):
    for T in (T_QUARTER, T_QUARTER_X):
        xi = require_shape(log_se3(T), (6,))
        if close(xi[:3], T[:3, 3], 1e-9):
            raise Mismatch(f"rho equals t = {fmt(T[:3, 3])} although T rotates",
                           "rho = V(phi)⁻¹ t: the translation must be undone through V")
        if close(expm(_twist_matrix(np.concatenate([xi[3:], xi[:3]]))), T, 1e-9):
            raise Mismatch("rho and phi are swapped", "xi = [rho, phi]: translation part first")
        if not close(expm(_twist_matrix(xi)), T, 1e-9):
            raise Mismatch(f"expm(twist(log_se3(T))) differs from T for T = {fmt(T)}")
