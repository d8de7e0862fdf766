"""Public checks for lesson 09: estimation on Lie groups.

The checks use quarter turns written out by hand, definitional identities,
finite differences, and, to name a slip, the values of the usual slips at the
checks' fixed inputs stored as numbers (``tests/test_public_check_constants_lesson09.py``
recomputes every one of them from its definition).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import Exp, ExpSE3
from .common import (
    central_differences,
    first_match,
    fmt,
    off_by,
    require_pose,
    require_same_with_lists,
    require_shape,
    require_unchanged_inputs,
)

# Quarter turns, written out: about z (x goes to y), about x (y goes to z), and their product (a third of
# a turn about (1, 1, 1), which permutes the axes x → y → z → x).
QUARTER_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
QUARTER_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
QUARTER_Y = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])
PERMUTATION = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])  # QUARTER_Z @ QUARTER_X
SHIFT = np.array([1.0, 2.0, 3.0])
T_QUARTER = np.array([[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]])


# ---------------------------------------------------------------- integrate_gyro
QUARTER_BODY_Z = np.array([[0.0, -1.0, 0.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0]])  # QUARTER_X @ QUARTER_Z
QUARTER_WORLD_Z = PERMUTATION  # QUARTER_Z @ QUARTER_X
GYRO_NO_DT = np.array([[-1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, -1.0, 0.0]])  # QUARTER_X Exp(25π z)
GYRO_X_THEN_Y = PERMUTATION  # QUARTER_X @ QUARTER_Y
GYRO_Y_THEN_X = np.array([[0.0, 1.0, 0.0], [0.0, 0.0, -1.0], [-1.0, 0.0, 0.0]])  # QUARTER_Y @ QUARTER_X
GYRO_SUMMED = np.array(
    [
        [0.197150066460593, 0.802849933539407, 0.5626400585724],  # Exp([π/2, π/2, 0])
        [0.802849933539407, 0.197150066460593, -0.5626400585724],
        [-0.5626400585724, 0.5626400585724, -0.605699867078814],
    ]
)
WORLD_SIDE_HINT = hints.TURNED_ABOUT_WORLD_S_HINT
NO_DT_HINT = "each sample turns by ω dt (rad/s times s): multiply the rates by dt"
SUMMED_HINT = (
    "one Exp of the summed rates is right only when every sample turns about the same axis: apply one "
    "update per sample, in order"
)
DRIFT_HINT = "R (I + [ω dt]×) is only first order and drifts off SO(3): update with Exp, R ← R Exp(ω_b dt)"


@public_check(
    "integrate_gyro",
    "π/2 rad/s about body z for 1 s (50 samples) turns a body lying on its side a quarter turn about its own z",
)
def _(integrate_gyro):
    rates = np.tile([0.0, 0.0, np.pi / 2], (50, 1))
    got = require_shape(integrate_gyro(QUARTER_X, rates, 0.02), (3, 3), "integrate_gyro(R0, ω, dt)")
    if not close(got, QUARTER_BODY_Z, 1e-9):
        hint = first_match(
            got,
            [
                (QUARTER_WORLD_Z, WORLD_SIDE_HINT),
                (GYRO_NO_DT, NO_DT_HINT),
                (QUARTER_X, hints.RETURNED_R0_UNCHANGED_APPLY_HINT),
            ],
        )
        raise Mismatch(
            f"got {fmt(got)}, expected R0 times a quarter turn about z ({off_by(got, QUARTER_BODY_Z)})", hint
        )


@public_check("integrate_gyro", "a quarter turn about x, then one about y (dt = 1 s) is R0 Exp(π/2 x) Exp(π/2 y)")
def _(integrate_gyro):
    rates = np.array([[np.pi / 2, 0.0, 0.0], [0.0, np.pi / 2, 0.0]])
    got = require_shape(integrate_gyro(np.eye(3), rates, 1.0), (3, 3), "integrate_gyro(I, ω, 1)")
    if not close(got, GYRO_X_THEN_Y, 1e-9):
        hint = first_match(
            got,
            [
                (GYRO_Y_THEN_X, WORLD_SIDE_HINT + " (or the samples were taken in reverse order)"),
                (GYRO_SUMMED, SUMMED_HINT),
            ],
        )
        raise Mismatch(f"got {fmt(got)}, expected {fmt(GYRO_X_THEN_Y)} ({off_by(got, GYRO_X_THEN_Y)})", hint)


@public_check("integrate_gyro", "stays a rotation after 1000 samples of 0.05 rad each")
def _(integrate_gyro):
    rates = np.tile([3.0, -4.0, 0.0], (1000, 1))  # 5 rad/s for 10 ms per sample
    got = require_shape(integrate_gyro(np.eye(3), rates, 0.01), (3, 3), "integrate_gyro after 1000 samples")
    error = np.max(np.abs(got.T @ got - np.eye(3)))
    if error > 1e-9:
        raise Mismatch(f"after 1000 samples max |RᵀR − I| = {error:.2g}", DRIFT_HINT)


GYRO_ARRAY_HINT = (
    "start from a float array, R = np.array(R0, dtype=float): then no samples still returns an "
    "ndarray, and R0 itself is never handed back"
)


@public_check(
    "integrate_gyro",
    "no samples returns R0, as an array even when R0 is a list; accepts lists; leaves its inputs unchanged",
)
def _(integrate_gyro):
    got = require_shape(integrate_gyro(QUARTER_X, np.zeros((0, 3)), 0.01), (3, 3), "integrate_gyro with no samples")
    if not close(got, QUARTER_X, 1e-15):
        raise Mismatch(
            "with no samples the attitude must stay R0", "loop over the rows of omegas_b (there may be none)"
        )
    from_list = integrate_gyro(QUARTER_X.tolist(), np.zeros((0, 3)), 0.01)
    if not isinstance(from_list, np.ndarray):
        raise Mismatch(
            f"with R0 as a list and no samples it returned a {type(from_list).__name__}, not an ndarray",
            GYRO_ARRAY_HINT,
        )
    rates = np.array([[0.1, -0.2, 0.3], [0.3, 0.1, -0.1], [0.0, 0.4, 0.2]])
    require_same_with_lists(
        lambda R0, omegas: integrate_gyro(R0, omegas, 0.1), (QUARTER_X, rates), (3, 3), "integrate_gyro(R0, ω, dt)"
    )
    require_unchanged_inputs(lambda R0, omegas: integrate_gyro(R0, omegas, 0.1), (QUARTER_X, rates), "integrate_gyro")


# ---------------------------------------------------------------- rotated_point_covariance
SIGMA = np.array([[0.04, 0.01, 0.0], [0.01, 0.09, 0.02], [0.0, 0.02, 0.01]])
COV_P = np.array([1.0, 2.0, -1.0])
COV_POINT = np.array([[0.21, 0.11, 0.05], [0.11, 0.21, -0.05], [0.05, -0.05, 0.05]])
COV_POINT_NO_R = np.array([[0.21, -0.05, 0.11], [-0.05, 0.05, 0.05], [0.11, 0.05, 0.21]])
COV_POINT_LEFT = np.array([[0.29, -0.07, 0.18], [-0.07, 0.17, -0.12], [0.18, -0.12, 0.15]])
COV_POINT_TURNED_SIGMA = np.array([[0.01, 0.0, 0.02], [0.0, 0.04, 0.01], [0.02, 0.01, 0.09]])
COV_POINT_ONE_SIDED = np.array([[0.07, -0.07, -0.02], [-0.01, -0.13, -0.04], [0.04, 0.03, 0.01]])
COV_POINT_TRANSPOSED = np.array([[0.17, -0.12, -0.07], [-0.12, 0.15, 0.18], [-0.07, 0.18, 0.29]])
COV_NO_R_HINT = (
    "that is the covariance in the body frame: the world point is R p, so the attitude R belongs in J (the "
    "Jacobian of R p that you derived in lesson 06)"
)
COV_LEFT_HINT = (
    "[R p]× Σ [R p]×ᵀ treats ε as a world-frame (left) perturbation; here R Exp(ε): J is lesson 06's Jacobian of "
    "the right perturbation, Σ_y = J Σ Jᵀ"
)
COV_TURNED_HINT = (
    "that is the covariance of the turn, not of the point: a small turn moves the point sideways only, so its "
    "covariance has no spread along R p; propagate with the point's Jacobian"
)
COV_ONE_SIDED_HINT = "a covariance takes the Jacobian on both sides: Σ_y = J Σ Jᵀ (J Σ alone is not even symmetric)"
COV_TRANSPOSED_HINT = "Jᵀ Σ J has the Jacobian on the wrong sides: Σ_y = J Σ Jᵀ for y ≈ y0 + J ε"
COV_POINT_SLIPS = [
    (COV_POINT_NO_R, COV_NO_R_HINT),
    (COV_POINT_LEFT, COV_LEFT_HINT),
    (COV_POINT_TURNED_SIGMA, COV_TURNED_HINT),
    (COV_POINT_ONE_SIDED, COV_ONE_SIDED_HINT),
    (COV_POINT_TRANSPOSED, COV_TRANSPOSED_HINT),
]


@public_check("rotated_point_covariance", "equals the first-order covariance at a third of a turn about (1, 1, 1)")
def _(rotated_point_covariance):
    got = require_shape(
        rotated_point_covariance(PERMUTATION, SIGMA, COV_P), (3, 3), "rotated_point_covariance(R, Σ, p)"
    )
    if not close(got, COV_POINT, 1e-12):
        raise Mismatch(
            f"got {fmt(got)}, expected {fmt(COV_POINT)} ({off_by(got, COV_POINT)})",
            first_match(got, COV_POINT_SLIPS, 1e-12)
            or "to first order y ≈ R p + J ε with lesson 06's J; the covariance of J ε is J Σ Jᵀ",
        )


@public_check("rotated_point_covariance", "is symmetric, doubles with Σ, and has no spread along R p")
def _(rotated_point_covariance):
    R, p = Exp([0.4, -0.7, 1.2]), np.array([0.5, 1.5, -2.0])
    got = require_shape(rotated_point_covariance(R, SIGMA, p), (3, 3), "rotated_point_covariance(R, Σ, p)")
    if not close(got, got.T, 1e-15):
        raise Mismatch(f"the covariance is not symmetric ({off_by(got, got.T)})", COV_ONE_SIDED_HINT)
    doubled = require_shape(rotated_point_covariance(R, 2.0 * SIGMA, p), (3, 3), "rotated_point_covariance(R, 2Σ, p)")
    if not close(doubled, 2.0 * got, 1e-14):
        raise Mismatch("doubling Σ does not double the covariance", "Σ_y = J Σ Jᵀ is linear in Σ: no square roots")
    along = got @ (R @ p) / np.linalg.norm(R @ p)
    if np.max(np.abs(along)) > 1e-12:
        raise Mismatch(
            f"the covariance spreads along R p ({np.max(np.abs(along)):.2g} m²/m)",
            "a small turn moves the world point sideways, never along R p, so Σ_y (R p) = 0: "
            "propagate with the point's Jacobian, whose rows are all perpendicular to R p",
        )


@public_check("rotated_point_covariance", "accepts plain lists and leaves its inputs unchanged")
def _(rotated_point_covariance):
    require_same_with_lists(
        rotated_point_covariance, (PERMUTATION, SIGMA, COV_P), (3, 3), "rotated_point_covariance(R, Σ, p)"
    )
    require_unchanged_inputs(rotated_point_covariance, (PERMUTATION, SIGMA, COV_P), "rotated_point_covariance")


# ---------------------------------------------------------------- covariance_left_to_right
SIGMA_LEFT = np.array([[0.09, 0.02, -0.01], [0.02, 0.04, 0.005], [-0.01, 0.005, 0.01]])
COV_RIGHT = np.array([[0.04, 0.005, 0.02], [0.005, 0.01, -0.01], [0.02, -0.01, 0.09]])
COV_RIGHT_WRONG_WAY = np.array([[0.01, -0.01, 0.005], [-0.01, 0.09, 0.02], [0.005, 0.02, 0.04]])
COV_RIGHT_ONE_SIDED = np.array([[0.02, 0.04, 0.005], [-0.01, 0.005, 0.01], [0.09, 0.02, -0.01]])
COV_RIGHT_OTHER_SIDE = np.array([[0.02, -0.01, 0.09], [0.04, 0.005, 0.02], [0.005, 0.01, -0.01]])
WRONG_WAY_HINT = (
    "that converts right to left: test it on a body turned a third of a turn about (1, 1, 1), x to y, y to z and "
    "z to x; a heading uncertainty about the world's vertical must end up on the body's y axis, the one that points up"
)
UNCHANGED_HINT = (
    "the covariance must change frame: a world-axis uncertainty (left) is a different body-axis "
    "uncertainty (right) unless R = I"
)
ONE_SIDED_LEFT_HINT = hints.COVARIANCE_TAKES_LINEAR_MAP_HINT
COV_RIGHT_SLIPS = [
    (COV_RIGHT_WRONG_WAY, WRONG_WAY_HINT),
    (SIGMA_LEFT, UNCHANGED_HINT),
    (COV_RIGHT_ONE_SIDED, ONE_SIDED_LEFT_HINT),
    (COV_RIGHT_OTHER_SIDE, ONE_SIDED_LEFT_HINT),
]


@public_check("covariance_left_to_right", "converts a covariance at a third of a turn about (1, 1, 1)")
def _(covariance_left_to_right):
    got = require_shape(covariance_left_to_right(PERMUTATION, SIGMA_LEFT), (3, 3), "covariance_left_to_right(R, Σ)")
    if not close(got, COV_RIGHT, 1e-12):
        raise Mismatch(
            f"Σ_R disagrees with the covariance of ε_R ({off_by(got, COV_RIGHT)})",
            first_match(got, COV_RIGHT_SLIPS, 1e-12)
            or hints.LEFT_TO_RIGHT_WITH_ADJOINT_HINT,
        )


@public_check("covariance_left_to_right", "keeps the eigenvalues (the same uncertainty, in other axes); accepts lists")
def _(covariance_left_to_right):
    R = Exp([1.1, -0.4, 0.7])
    got = require_shape(covariance_left_to_right(R, SIGMA_LEFT), (3, 3), "covariance_left_to_right(R, Σ)")
    if not close(got, got.T, 1e-15):
        raise Mismatch("the result is not symmetric", ONE_SIDED_LEFT_HINT)
    if not close(np.linalg.eigvalsh(got), np.linalg.eigvalsh(SIGMA_LEFT), 1e-12):
        raise Mismatch(
            "the eigenvalues changed: the size of the uncertainty is not the same",
            "the same uncertainty seen in other axes keeps its size: nothing may stretch or shrink Σ_L",
        )
    require_same_with_lists(covariance_left_to_right, (R, SIGMA_LEFT), (3, 3), "covariance_left_to_right(R, Σ)")
    require_unchanged_inputs(covariance_left_to_right, (R, SIGMA_LEFT), "covariance_left_to_right")


# ---------------------------------------------------------------- align_pose_gauss_newton
BOARD = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 0.5]])
BOARD_SEEN = BOARD @ QUARTER_Z.T + SHIFT  # the board moved by T_QUARTER


def _pose_cost(T, P, Q):
    return float(np.sum((P @ T[:3, :3].T + T[:3, 3] - Q) ** 2))


def _gn_pose_hint(align_pose_gauss_newton, got, T0, iters):
    """The slip behind a wrong answer, told from how the student's own function behaves."""
    if np.max(np.abs(got - T0)) == 0.0:
        return hints.RETURNED_T0_UNCHANGED_DO_HINT
    if not close(got[:3, :3].T @ got[:3, :3], np.eye(3), 1e-6) or not close(got[3], [0.0, 0.0, 0.0, 1.0], 1e-12):
        return "the result is not a pose: update with T ← T @ ExpSE3(xi), which stays in SE(3)"
    if _pose_cost(got, BOARD, BOARD_SEEN) > _pose_cost(np.asarray(T0, dtype=float), BOARD, BOARD_SEEN):
        try:  # from T0 = I a left and a right update coincide: downhill there means the sign is right
            from_identity = np.asarray(align_pose_gauss_newton(BOARD, BOARD_SEEN, np.eye(4), iters=1), dtype=float)
        except Exception:  # noqa: BLE001 - its own check reports the crash
            from_identity = None
        if (
            from_identity is not None
            and from_identity.shape == (4, 4)
            and _pose_cost(from_identity, BOARD, BOARD_SEEN) < _pose_cost(np.eye(4), BOARD, BOARD_SEEN)
        ):
            return (
                "a step from T0 = I lowers the cost but a step from a turned pose raises it: the right Jacobian of "
                "lesson 07 (jacobian_transform_point) goes with the update on the same side, T ← T Exp(xi)"
            )
        return "steps uphill (the cost went up): xi solves H xi = -g (mind the minus sign)"
    if iters > 1:
        try:
            once = np.asarray(align_pose_gauss_newton(BOARD, BOARD_SEEN, T0, iters=1), dtype=float)
        except Exception:  # noqa: BLE001 - its own check reports the crash
            once = None
        if once is not None and once.shape == got.shape and np.max(np.abs(once - got)) <= 1e-12:
            return f"that is one Gauss-Newton step, whatever iters says: repeat the update iters times (here {iters})"
    return (
        "check that the Jacobian and the update are on the same side: lesson 07's jacobian_transform_point goes "
        "with T ← T Exp(xi)"
    )


@public_check("align_pose_gauss_newton", "recovers a quarter turn and a shift from exact pairs, starting at T0 = I")
def _(align_pose_gauss_newton):
    got = require_shape(
        align_pose_gauss_newton(BOARD, BOARD_SEEN, np.eye(4), iters=10),
        (4, 4),
        "align_pose_gauss_newton(P, Q, I, iters=10)",
    )
    if not close(got, T_QUARTER, 1e-9):
        raise Mismatch(
            f"after 10 iterations the pose is off by {np.max(np.abs(got - T_QUARTER)):.2g}",
            _gn_pose_hint(align_pose_gauss_newton, got, np.eye(4), 10),
        )


@public_check("align_pose_gauss_newton", "one iteration moves the pose, lowers the cost a lot, and stays a pose")
def _(align_pose_gauss_newton):
    T0 = T_QUARTER @ ExpSE3([0.2, -0.1, 0.3, 0.3, -0.2, 0.4])
    got = require_shape(
        align_pose_gauss_newton(BOARD, BOARD_SEEN, T0, iters=1), (4, 4), "align_pose_gauss_newton(..., iters=1)"
    )
    if close(got, T0, 1e-12):
        raise Mismatch(
            "one iteration returned T0 unchanged",
            "the update T ← T Exp(ξ) never reaches what you return: start from a copy of T0, "
            "update that estimate once per iteration (iters of them) and return it",
        )
    hint = _gn_pose_hint(align_pose_gauss_newton, got, T0, 1)
    if not close(got[:3, :3].T @ got[:3, :3], np.eye(3), 1e-9) or not close(got[3], [0.0, 0.0, 0.0, 1.0], 1e-12):
        raise Mismatch("after one iteration the result is not a pose", hint)
    before, after = _pose_cost(T0, BOARD, BOARD_SEEN), _pose_cost(got, BOARD, BOARD_SEEN)
    if not after < 0.1 * before:
        raise Mismatch(f"one step only took the cost from {before:.3g} to {after:.3g}", hint)


@public_check("align_pose_gauss_newton", "accepts plain lists and leaves its inputs unchanged")
def _(align_pose_gauss_newton):
    require_same_with_lists(
        lambda P, Q, T0: align_pose_gauss_newton(P, Q, T0, iters=3),
        (BOARD, BOARD_SEEN, np.eye(4)),
        (4, 4),
        "align_pose_gauss_newton(P, Q, T0)",
    )
    require_unchanged_inputs(
        lambda P, Q, T0: align_pose_gauss_newton(P, Q, T0, iters=3),
        (BOARD, BOARD_SEEN, np.eye(4)),
        "align_pose_gauss_newton",
    )


# ---------------------------------------------------------------- align_pose_robust
HUBER_K = 0.05


def _huber_cost(T, P, Q, k):
    r = np.linalg.norm(P @ T[:3, :3].T + T[:3, 3] - Q, axis=1)
    return float(np.sum(np.where(r <= k, 0.5 * r**2, k * r - 0.5 * k * k)))


def _log_tail_cost(T, P, Q, k):
    """A cost that grows like log r beyond k (not Huber's linear tail): ½ r² up to k, then ½ k² + k² log(r / k)."""
    r = np.linalg.norm(P @ T[:3, :3].T + T[:3, 3] - Q, axis=1)
    return float(np.sum(np.where(r <= k, 0.5 * r**2, 0.5 * k * k + k * k * np.log(np.maximum(r, k) / k))))


def _numeric_gradient(cost, T):
    """Central differences of cost(T Exp(xi)) with respect to xi at 0 (a 6-vector)."""
    return central_differences(lambda xi: np.array([cost(T @ ExpSE3(xi))]), 6)[0]


def _outlier_data():
    rng = np.random.default_rng(2024)
    P = rng.uniform(-1.0, 1.0, size=(12, 3))
    T_true = T_QUARTER @ ExpSE3([0.1, -0.2, 0.1, 0.3, 0.2, -0.1])
    Q = P @ T_true[:3, :3].T + T_true[:3, 3] + 0.005 * rng.normal(size=P.shape)
    Q[[2, 5, 9]] += np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]])  # three wrong pairs, 1 m off
    T0 = T_true @ ExpSE3([0.2, 0.1, -0.2, -0.2, 0.25, 0.1])
    return P, Q, T_true, T0


def _robust_hint(got, P, Q, T0, k):
    if np.max(np.abs(got - np.asarray(T0, dtype=float))) == 0.0:
        return hints.RETURNED_T0_UNCHANGED_ITERATE_HINT
    squared = _numeric_gradient(lambda T: _pose_cost(T, P, Q), got)
    if np.max(np.abs(squared)) < 1e-6:
        return hints.MINIMISES_SQUARED_COST_LEAST_HINT
    log_tail = _numeric_gradient(lambda T: _log_tail_cost(T, P, Q, k), got)
    if np.max(np.abs(log_tail)) < 1e-6:
        return hints.ROBUST_SLOWER_TAIL_HINT
    if _huber_cost(got, P, Q, k) < _huber_cost(np.asarray(T0, dtype=float), P, Q, k):
        return (
            "the cost went down but the gradient is not zero yet: iterate until your steps are tiny "
            "(|xi| below about 1e-12)"
        )
    return hints.ROBUST_GRADIENT_NOT_ZERO_HINT


@public_check("align_pose_robust", "returns a pose where the Huber cost's gradient vanishes (3 of 12 pairs 1 m off)")
def _(align_pose_robust):
    P, Q, _, T0 = _outlier_data()
    got = require_shape(align_pose_robust(P, Q, T0, HUBER_K), (4, 4), "align_pose_robust(P, Q, T0, k)")
    require_pose(got, "align_pose_robust(P, Q, T0, k)")
    gradient = _numeric_gradient(lambda T: _huber_cost(T, P, Q, HUBER_K), got)
    # the hidden checks' bar, 1e-10 per pair; these central differences are good to about 1e-11 here
    if np.max(np.abs(gradient)) > 1e-10 * len(P):
        raise Mismatch(
            f"the gradient of the Huber cost is {fmt(gradient, 4)} there, not zero (allowed {1e-10 * len(P):.1e})",
            _robust_hint(got, P, Q, T0, HUBER_K),
        )


@public_check("align_pose_robust", "holds within 2 cm of the truth where least squares is dragged more than 10 cm away")
def _(align_pose_robust):
    P, Q, T_true, T0 = _outlier_data()
    got = require_shape(align_pose_robust(P, Q, T0, HUBER_K), (4, 4), "align_pose_robust(P, Q, T0, k)")
    error = np.linalg.norm(got[:3, 3] - T_true[:3, 3])
    if error > 0.02:
        raise Mismatch(f"the position is {100 * error:.1f} cm from the truth", _robust_hint(got, P, Q, T0, HUBER_K))


@public_check("align_pose_robust", "recovers a pose exactly from clean pairs; accepts lists")
def _(align_pose_robust):
    T0 = T_QUARTER @ ExpSE3([0.3, -0.2, 0.1, 0.2, -0.3, 0.25])
    got = require_shape(align_pose_robust(BOARD, BOARD_SEEN, T0, HUBER_K), (4, 4), "align_pose_robust on clean pairs")
    if not close(got, T_QUARTER, 1e-9):
        raise Mismatch(
            f"on clean pairs the pose is off by {np.max(np.abs(got - T_QUARTER)):.2g}",
            _robust_hint(got, BOARD, BOARD_SEEN, T0, HUBER_K),
        )
    require_same_with_lists(
        lambda P, Q, T: align_pose_robust(P, Q, T, HUBER_K),
        (BOARD, BOARD_SEEN, T0),
        (4, 4),
        "align_pose_robust(P, Q, T0, k)",
    )
    require_unchanged_inputs(lambda P, Q, T: align_pose_robust(P, Q, T, HUBER_K), (BOARD, BOARD_SEEN, T0), "align_pose_robust")
