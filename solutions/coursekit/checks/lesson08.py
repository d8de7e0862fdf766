"""Public checks for lesson 08: estimating a rotation.

The checks use a quarter turn about z written out by hand, small point sets
whose best rotation is known exactly (no noise), a mirrored point set, and the
defining property of the geodesic mean (the residual rotation vectors sum to
zero, computed with scipy through ``coursekit.lie.Log``).
"""

import numpy as np
from scipy.spatial.transform import Rotation

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import FLOAT32_HINT, close, explains, rotation_problem, single_precision_error
from ..lie import Exp, Log
from .common import require_rotation, require_same_with_lists, require_shape

QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
# Four points that are not coplanar, and their images under the quarter turn (rows: q_i = R p_i).
POINTS = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 1.5], [1.0, -1.0, 0.5]])
TURNED = POINTS @ QUARTER_TURN_Z.T


def _rotation_of(value, what, hint=None):
    R = require_shape(value, (3, 3), what)
    if hint is not None and rotation_problem(R):
        raise Mismatch(f"{what} is not a rotation: {rotation_problem(R)}", hint)
    return require_rotation(R, what)


def _cost(R, P, Q):
    return float(np.sum((Q - P @ R.T) ** 2))


def _explains(got, candidate, truth):
    return explains(got, candidate, truth, floor=1e-12)


# ---------------------------------------------------------------- align_svd
def _svd_hint(got, P, Q, expected):
    """The slip behind a wrong alignment, from properties and wrong formulas only (never the answer's)."""
    if np.linalg.det(got) < 0 and close(got.T @ got, np.eye(3), 1e-6):
        return ("a reflection (det = -1): that is U Vᵀ without the determinant fix; "
                "use U diag(1, 1, d) Vᵀ with d = det(U Vᵀ)")
    if _explains(got, expected.T, expected):
        return hints.INVERSE_ROTATION_TRANSPOSE_USE_HINT
    if _explains(got, np.linalg.lstsq(P, Q, rcond=None)[0].T, expected):
        return (hints.UNCONSTRAINED_LEAST_SQUARES_MATRIX_HINT)
    if _explains(got, np.eye(3), expected):
        return hints.RETURNED_IDENTITY_IF_Q_HINT
    return hints.ALIGNMENT_SVD_FORMULA_HINT


@public_check("align_svd", "recovers a quarter turn about z from four exact point pairs")
def _(align_svd):
    got = require_shape(align_svd(POINTS, TURNED), (3, 3), "align_svd(P, Q)")
    if not close(got, QUARTER_TURN_Z, 1e-9):
        raise Mismatch(f"got {np.round(got, 3).tolist()}, expected the quarter turn about z "
                       f"(off by {np.max(np.abs(got - QUARTER_TURN_Z)):.2g})",
                       _svd_hint(got, POINTS, TURNED, QUARTER_TURN_Z))
    _rotation_of(got, "align_svd(P, Q)")


@public_check("align_svd", "returns a rotation (det = +1), never a reflection, for mirrored data: the best one")
def _(align_svd):
    # mirrored, and moved a little off any rigid image so that no matrix fits exactly
    mirrored = TURNED * np.array([1.0, 1.0, -1.0]) + 0.01 * np.array(
        [[1.0, -2.0, 0.0], [0.0, 1.0, 2.0], [-1.0, 0.0, 1.0], [2.0, 1.0, -1.0]])
    got = require_shape(align_svd(POINTS, mirrored), (3, 3), "align_svd(P, Q)")
    best = Rotation.align_vectors(mirrored, POINTS)[0].as_matrix()
    det = np.linalg.det(got)
    if det < 0:
        raise Mismatch(f"det = {det:.3f}: a reflection", _svd_hint(got, POINTS, mirrored, best))
    _rotation_of(got, "align_svd(P, Q)", _svd_hint(got, POINTS, mirrored, best))
    if not close(got, best, 1e-9):
        U, _, Vt = np.linalg.svd(mirrored.T @ POINTS)
        flipped_rows = np.diag([1.0, 1.0, np.linalg.det(U @ Vt)]) @ U @ Vt
        hint = ("the sign d belongs to the last column of U (the direction of the smallest singular value): "
                "U @ diag(1, 1, d) @ Vᵀ, with the diagonal on the right of U, not on its left"
                if _explains(got, flipped_rows, best) else _svd_hint(got, POINTS, mirrored, best))
        raise Mismatch(f"a rotation, but not the best one: its cost is {_cost(got, POINTS, mirrored):.6g}, the best "
                       f"{_cost(best, POINTS, mirrored):.6g}", hint)


# A generic turn and five generic points, none of their numbers exact in float32 (exact data: q_i = R p_i).
R_GENERIC = Exp([0.9, -0.4, 1.3])
P_GENERIC = np.array([[0.3, -1.1, 2.7], [1.9, 0.6, -0.4], [-2.2, 1.3, 0.1], [0.7, 0.7, -3.1], [1.1, -2.3, 0.9]])
Q_GENERIC = P_GENERIC @ R_GENERIC.T


def _require_generic_turn(got, what):
    error = np.max(np.abs(got - R_GENERIC))
    if error > 1e-12:
        raise Mismatch(f"{what} is off by {error:.1e} from the turn that maps P onto Q exactly (tolerance 1e-12)",
                       FLOAT32_HINT if single_precision_error(got, R_GENERIC) else None)


@public_check("align_svd", "exact data from a generic turn: recovers it to 1e-12 (float64 kept); plain lists "
              "accepted")
def _(align_svd):
    got = require_shape(align_svd(P_GENERIC, Q_GENERIC), (3, 3), "align_svd(P, Q)")
    _require_generic_turn(got, "align_svd(P, Q)")
    require_same_with_lists(align_svd, (P_GENERIC, Q_GENERIC), (3, 3), "align_svd(P, Q)")


# ---------------------------------------------------------------- align_gauss_newton
def _gn_hint(align_gauss_newton, got, R0, iters):
    """The slip behind a wrong Gauss-Newton answer, told from how the student's own function behaves."""
    if np.max(np.abs(got - R0)) == 0.0:
        return hints.RETURNED_R0_UNCHANGED_DO_HINT
    if not close(got.T @ got, np.eye(3), 1e-6):
        return hints.UPDATED_ADDING_R_R_HINT
    if _cost(got, POINTS, TURNED) > _cost(R0, POINTS, TURNED):
        return "steps uphill (the cost went up): δ solves H δ = -g (mind the minus sign)"
    if iters > 1:
        try:
            once = np.asarray(align_gauss_newton(POINTS, TURNED, R0, iters=1), dtype=float)
        except Exception:  # noqa: BLE001 - its own check reports the crash
            once = None
        if once is not None and once.shape == got.shape and np.max(np.abs(once - got)) <= 1e-12:
            return (f"that is one Gauss-Newton step, whatever iters says: repeat the update iters times "
                    f"(here {iters})")
    return ("check that the Jacobian and the update are on the same side: the left Jacobian -[R p_i]× with the "
            "update R ← R Exp(δ) mixes two conventions; that update needs lesson 06's right-perturbation Jacobian")


@public_check("align_gauss_newton", "finds a quarter turn about z from R0 = I with exact data")
def _(align_gauss_newton):
    got = require_shape(align_gauss_newton(POINTS, TURNED, np.eye(3), iters=10), (3, 3),
                        "align_gauss_newton(P, Q, I, iters=10)")
    hint = _gn_hint(align_gauss_newton, got, np.eye(3), 10)
    R = _rotation_of(got, "align_gauss_newton(P, Q, I, iters=10)", hint)
    if not close(R, QUARTER_TURN_Z, 1e-8):
        raise Mismatch(f"got {np.round(R, 3).tolist()} after 10 iterations, expected the quarter turn "
                       f"(off by {np.max(np.abs(R - QUARTER_TURN_Z)):.2g})", hint)


@public_check("align_gauss_newton", "one iteration lowers the cost and stays a rotation")
def _(align_gauss_newton):
    R0 = QUARTER_TURN_Z @ Exp([0.3, -0.2, 0.4])
    got = require_shape(align_gauss_newton(POINTS, TURNED, R0, iters=1), (3, 3), "align_gauss_newton(..., iters=1)")
    hint = _gn_hint(align_gauss_newton, got, R0, 1)
    R1 = _rotation_of(got, "align_gauss_newton(..., iters=1)", hint)
    before, after = _cost(R0, POINTS, TURNED), _cost(R1, POINTS, TURNED)
    if close(R1, R0, 1e-12):
        raise Mismatch("one iteration returned R0 unchanged",
                       "the update R ← R Exp(δ) never reaches what you return: start from a copy of R0, "
                       "update that estimate once per iteration (iters of them) and return it")
    if not after < 0.1 * before:
        raise Mismatch(f"one step only took the cost from {before:.3g} to {after:.3g}", hint)


@public_check("align_gauss_newton", "exact data from a generic turn: 10 iterations from R0 = I recover it to 1e-12 "
              "(float64 kept); plain lists accepted")
def _(align_gauss_newton):
    got = require_shape(align_gauss_newton(P_GENERIC, Q_GENERIC, np.eye(3), iters=10), (3, 3),
                        "align_gauss_newton(P, Q, I, iters=10)")
    _require_generic_turn(got, "align_gauss_newton(P, Q, I, iters=10)")
    require_same_with_lists(lambda P, Q, R0: align_gauss_newton(P, Q, R0, iters=10),
                            (P_GENERIC, Q_GENERIC, np.eye(3)), (3, 3), "align_gauss_newton(P, Q, R0, iters=10)")


@public_check("align_gauss_newton", "iters counts the steps: iters=1 twice in a row equals iters=2")
def _(align_gauss_newton):
    noisy = Q_GENERIC + 0.05 * np.array([[1.0, -2.0, 0.0], [0.0, 1.0, 2.0], [-1.0, 0.0, 1.0], [2.0, 1.0, -1.0],
                                         [0.5, -0.5, 1.5]])
    R0 = Exp([0.3, 1.2, -0.8])
    once = require_shape(align_gauss_newton(P_GENERIC, noisy, R0, iters=1), (3, 3), "align_gauss_newton(..., iters=1)")
    twice = require_shape(align_gauss_newton(P_GENERIC, noisy, once, iters=1), (3, 3),
                          "align_gauss_newton(..., iters=1) from that result")
    both = require_shape(align_gauss_newton(P_GENERIC, noisy, R0, iters=2), (3, 3), "align_gauss_newton(..., iters=2)")
    if not close(twice, both, 1e-12):
        raise Mismatch(f"two calls with iters=1 and one with iters=2 differ by {np.max(np.abs(twice - both)):.2g}",
                       "do exactly iters updates R ← R Exp(δ), starting from R0: for _ in range(iters)")


# ---------------------------------------------------------------- rotation_mean
def _mean_hint(M, Rs, truth=None):
    """The slip behind a wrong mean M (known to be wrong): compared with each slip's value, relative to the
    truth when it is known, else to 1e-9."""
    Rs = np.asarray(Rs, dtype=float)

    def matches(candidate):
        return close(M, candidate, 1e-9) if truth is None else _explains(M, candidate, truth)

    if matches(Rotation.from_matrix(Rs).mean().as_matrix()):   # scipy's mean is the chordal one
        return "that is the chordal mean (the projected arithmetic mean); the geodesic mean needs the iteration"
    if matches(Exp(np.mean([Log(R) for R in Rs], axis=0))):
        return hints.AVERAGING_LOG_R_I_HINT
    if matches(Rs[0]):
        return hints.RETURNED_FIRST_ROTATION_RS_HINT
    return ("the residuals Log(Mᵀ R_i) do not balance yet; if you stop after a single step from Rs[0], "
            "repeat your step M ← M Exp(δ) until |δ| < 1e-12 (at most 100 iterations)")


def _keeps_copies(rotation_mean):
    """Does the answer give R for copies of R? Stopping early never breaks this; a step that overshoots does."""
    R = Exp([0.4, -1.1, 0.7])
    try:
        return close(np.asarray(rotation_mean([R, R, R]), dtype=float), R, 1e-9)
    except Exception:
        return False


def _unbalanced_hint(rotation_mean, M, Rs, truth=None):
    return _mean_hint(M, Rs, truth) if _keeps_copies(rotation_mean) else hints.COPIES_NOT_KEPT_HINT


@public_check("rotation_mean", "the mean of one rotation repeated is that rotation")
def _(rotation_mean):
    R = Exp([0.4, -1.1, 0.7])
    got = _rotation_of(rotation_mean([R, R, R]), "rotation_mean([R, R, R])")
    if not close(got, R, 1e-9):
        raise Mismatch(f"the mean of three copies of R is not R (off by {np.max(np.abs(got - R)):.2g})",
                       hints.COPIES_NOT_KEPT_HINT)


@public_check("rotation_mean", "the mean of two rotations is the midpoint of the arc between them")
def _(rotation_mean):
    A = Exp([0.2, 0.1, -0.3])
    B = A @ Exp([0.0, 1.2, 0.0])
    got = _rotation_of(rotation_mean(np.array([A, B])), "rotation_mean([A, B])")
    midpoint = A @ Exp([0.0, 0.6, 0.0])
    if not close(got, midpoint, 1e-8):
        raise Mismatch(f"it is {np.rad2deg(np.linalg.norm(Log(midpoint.T @ got))):.3g}° away from the midpoint",
                       _unbalanced_hint(rotation_mean, got, [A, B], midpoint))


@public_check("rotation_mean", "the residuals balance at the mean: |Σ Log(Mᵀ R_i)| / N below 1e-9; a plain list "
              "of rotations accepted")
def _(rotation_mean):
    rng = np.random.default_rng(0)
    centre = Exp([0.5, -0.2, 0.9])
    Rs = np.array([centre @ Exp(0.5 * rng.normal(size=3)) for _ in range(12)])
    M = _rotation_of(rotation_mean(Rs), "rotation_mean(Rs)")
    imbalance = np.linalg.norm(sum(Log(M.T @ R) for R in Rs)) / len(Rs)
    # 1e-9 sits between a stop at |δ| < 1e-7 (3.9e-10 here; the hidden suite accepts it) and one at 1e-6 (1.2e-8;
    # the hidden suite's clouds show 1.5e-8 against its 1e-8)
    if imbalance > 1e-9:
        raise Mismatch(f"|Σ Log(Mᵀ R_i)| / N = {imbalance:.2g} (tolerance 1e-9)", _unbalanced_hint(rotation_mean, M, Rs))
    require_same_with_lists(rotation_mean, (Rs,), (3, 3), "rotation_mean(Rs)")
