"""Public checks for lesson 08: estimating a rotation.

The checks use a quarter turn about z written out by hand, small point sets
whose best rotation is known exactly (no noise), a mirrored point set, and the
defining property of the geodesic mean (the residual rotation vectors sum to
zero, computed with scipy through ``coursekit.lie.Log``).
"""

import numpy as np
from scipy.spatial.transform import Rotation

from ..checking import Mismatch, public_check
from ..diagnose import close, shape_problem
from ..lie import Exp, Log
from .common import require_rotation, require_shape

QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
# Four points that are not coplanar, and their images under the quarter turn (rows: q_i = R p_i).
POINTS = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 1.5], [1.0, -1.0, 0.5]])
TURNED = POINTS @ QUARTER_TURN_Z.T


def _rotation_of(value, what):
    return require_rotation(require_shape(value, (3, 3), what), what)


def _cost(R, P, Q):
    return float(np.sum((Q - P @ R.T) ** 2))


# ---------------------------------------------------------------- align_svd
@public_check("align_svd", "recovers a quarter turn about z from four exact point pairs")
def _(align_svd):
    got = align_svd(POINTS, TURNED)
    if shape_problem(got, (3, 3)) is None and close(got, QUARTER_TURN_Z.T, 1e-9):
        raise Mismatch("got the inverse rotation (the transpose)",
                       "use M = Qᵀ P = Σ q_i p_iᵀ; Pᵀ Q gives Rᵀ")
    R = _rotation_of(got, "align_svd(P, Q)")
    if not close(R, QUARTER_TURN_Z, 1e-9):
        raise Mismatch(f"got {np.round(R, 3).tolist()}, expected the quarter turn about z")


@public_check("align_svd", "returns a rotation (det = +1), never a reflection, for mirrored data")
def _(align_svd):
    mirrored = TURNED * np.array([1.0, 1.0, -1.0])
    got = align_svd(POINTS, mirrored)
    problem = shape_problem(got, (3, 3))
    if problem:
        raise Mismatch(f"align_svd(P, Q) {problem}")
    det = np.linalg.det(np.asarray(got, dtype=float))
    if det < 0:
        raise Mismatch(f"det = {det:.3f}: a reflection",
                       "U Vᵀ can be a reflection: use U diag(1, 1, det(U Vᵀ)) Vᵀ")
    _rotation_of(got, "align_svd(P, Q)")


# ---------------------------------------------------------------- align_gauss_newton
@public_check("align_gauss_newton", "finds a quarter turn about z from R0 = I with exact data")
def _(align_gauss_newton):
    R = _rotation_of(align_gauss_newton(POINTS, TURNED, np.eye(3), iters=10),
                                "align_gauss_newton(P, Q, I, iters=10)")
    if close(R, QUARTER_TURN_Z.T, 1e-6):
        raise Mismatch("converged to the inverse rotation", "the residual is r_i = R p_i - q_i")
    if not close(R, QUARTER_TURN_Z, 1e-8):
        raise Mismatch(f"got {np.round(R, 3).tolist()} after 10 iterations, expected the quarter turn",
                       "J_i = -R [p_i]×, solve H δ = -g, then R ← R Exp(δ): the same side for both")


@public_check("align_gauss_newton", "one iteration lowers the cost and stays a rotation")
def _(align_gauss_newton):
    R0 = QUARTER_TURN_Z @ Exp([0.3, -0.2, 0.4])
    R1 = _rotation_of(align_gauss_newton(POINTS, TURNED, R0, iters=1),
                                 "align_gauss_newton(..., iters=1)")
    before, after = _cost(R0, POINTS, TURNED), _cost(R1, POINTS, TURNED)
    if close(R1, R0, 1e-12):
        raise Mismatch("one iteration did not move R0", "use the iters argument: do exactly iters updates")
    if not after < 0.1 * before:
        raise Mismatch(f"one step only took the cost from {before:.3g} to {after:.3g}",
                       "a right step needs J_i = -R [p_i]× with the update R @ Exp(δ), and δ = -H⁻¹ g")


# ---------------------------------------------------------------- rotation_mean
@public_check("rotation_mean", "the mean of one rotation repeated is that rotation")
def _(rotation_mean):
    R = Exp([0.4, -1.1, 0.7])
    got = _rotation_of(rotation_mean([R, R, R]), "rotation_mean([R, R, R])")
    if not close(got, R, 1e-9):
        raise Mismatch("the mean of three copies of R is not R")


@public_check("rotation_mean", "the mean of two rotations is the midpoint of the arc between them")
def _(rotation_mean):
    A = Exp([0.2, 0.1, -0.3])
    B = A @ Exp([0.0, 1.2, 0.0])
    got = _rotation_of(rotation_mean(np.array([A, B])), "rotation_mean([A, B])")
    midpoint = A @ Exp([0.0, 0.6, 0.0])
    if not close(got, midpoint, 1e-8):
        raise Mismatch(f"it is {np.rad2deg(np.linalg.norm(Log(midpoint.T @ got))):.3f}° away from the midpoint",
                       "iterate M ← M Exp(mean of Log(Mᵀ R_i)) until the step is tiny")


@public_check("rotation_mean", "the residuals balance at the mean: Σ Log(Mᵀ R_i) ≈ 0")
def _(rotation_mean):
    rng = np.random.default_rng(0)
    centre = Exp([0.5, -0.2, 0.9])
    Rs = np.array([centre @ Exp(0.5 * rng.normal(size=3)) for _ in range(12)])
    M = _rotation_of(rotation_mean(Rs), "rotation_mean(Rs)")
    imbalance = np.linalg.norm(sum(Log(M.T @ R) for R in Rs)) / len(Rs)
    if imbalance > 1e-7:
        chordal = Rotation.from_matrix(Rs).mean().as_matrix()  # scipy's mean is the chordal one
        hint = ("that is the chordal mean (the projected arithmetic mean); the geodesic mean needs the iteration"
                if close(M, chordal, 1e-9) else
                "keep iterating until |δ| < 1e-12 (at most 100 iterations), and step from M: M ← M Exp(δ)")
        raise Mismatch(f"|Σ Log(Mᵀ R_i)| / N = {imbalance:.2g}", hint)
