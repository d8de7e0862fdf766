"""Hidden checks for lesson 09: estimation on Lie groups.

Independent oracles: scipy's ``Rotation`` and ``expm``, the closed forms
derived in this file, Monte-Carlo-free first-order covariances, and, for the
two solvers, the reference's single Gauss-Newton step, scipy's closed-form pose
alignment and the first-order optimality of the Huber cost (its gradient,
written out here).

Core ideas carry at least half of each exercise's points, so the classic
mistake earns at most half: body rates on the right, R ← R Exp(ω dt), for
varying rates (3 of 7); J Σ Jᵀ with the right-perturbation Jacobian (3 of 5);
Rᵀ Σ R, not R Σ Rᵀ (3 of 5); iterating Gauss-Newton on SE(3) to convergence
(3 of 6); a stationary point of the Huber cost, not of the squared one (3 of
7). Angles cover every decade from 1e-12 to π; tolerances are stated in each
docstring. Every test calls the
student's function of its own exercise only.
"""

import numpy as np
from coursekit import hints
from coursekit.diagnose import explains
from scipy.linalg import expm
from scipy.spatial.transform import Rotation

from .helpers import (
    exercise,
    expect,
    expect_array,
    expect_close,
    expect_same_with_lists,
    fmt,
    random_rotations,
    rotation_problem,
)

SLOW = 20  # seconds per call for the iterative exercises
ANGLES = (1e-12, 1e-9, 1e-6, 1e-4, 1e-2, 0.3, 1.0, 2.0, 3.0, np.pi - 1e-6, np.pi - 1e-9)


# ---------------------------------------------------------------- oracles written out here
def _skew(v):
    """[v]×, built column by column: its column j is v × e_j."""
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(np.asarray(R, dtype=float)).as_rotvec()


def _twist_matrix(xi):
    M = np.zeros((4, 4))
    M[:3, :3], M[:3, 3] = _skew(xi[3:]), xi[:3]
    return M


def _exp_se3(xi):
    T = expm(_twist_matrix(np.asarray(xi, dtype=float)))
    T[3] = [0.0, 0.0, 0.0, 1.0]
    return T


def _pose(R, t):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, t
    return T


def _random_poses(count, seed, scale=1.0):
    rng = np.random.default_rng(seed)
    return [_pose(R, scale * rng.normal(size=3)) for R in random_rotations(count, seed + 1)]


def _unit(seed, count):
    v = np.random.default_rng(seed).normal(size=(count, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _rotations_at_every_angle(seed):
    """One rotation per angle of ANGLES, about seeded random axes."""
    return [_exp(angle * axis) for angle, axis in zip(ANGLES, _unit(seed, len(ANGLES)))]


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _first_explained(got, candidates, truth, floor=1e-12):
    """The hint of the first slip whose value accounts for ``got``; slips within 100 floors of the truth are
    indistinguishable from it on this input and are skipped."""
    for candidate, hint in candidates:
        candidate = np.asarray(candidate, dtype=float)
        if candidate.shape == np.shape(truth) and np.max(np.abs(candidate - truth)) < 100 * floor:
            continue
        if explains(got, candidate, truth, floor=floor):
            return hint
    return ""


# ---------------------------------------------------------------- integrate_gyro
def _integrate(R0, omegas, dt, side="right"):
    R = np.array(R0, dtype=float)
    for omega in np.asarray(omegas, dtype=float).reshape(-1, 3):
        R = R @ _exp(omega * dt) if side == "right" else _exp(omega * dt) @ R
    return R


def _gyro_hint(got, R0, omegas, dt):
    truth = _integrate(R0, omegas, dt)
    omegas = np.asarray(omegas, dtype=float).reshape(-1, 3)
    first_order = np.array(R0, dtype=float)
    for omega in omegas:
        first_order = first_order @ (np.eye(3) + _skew(omega * dt))
    return (
        _first_explained(
            got,
            [
                (_integrate(R0, omegas, dt, side="left"), hints.TURNED_ABOUT_WORLD_S_HINT),
                (_integrate(R0, omegas, 1.0), "each sample turns by ω dt: multiply the rates by dt"),
                (
                    np.array(R0, dtype=float) @ _exp(omegas.sum(axis=0) * dt),
                    "one Exp of the summed rates is right only about a fixed axis: one update per sample",
                ),
                (first_order, "R (I + [ω dt]×) is only first order and drifts off SO(3): update with Exp"),
                (
                    _integrate(R0, omegas[::-1], dt),
                    "the samples were applied in reverse order: the first row comes first",
                ),
                (np.array(R0, dtype=float), hints.RETURNED_R0_UNCHANGED_APPLY_HINT),
            ],
            truth,
        )
        or "R ← R Exp(ω_b dt), once per row, in order"
    )


@exercise("integrate_gyro", weight=3)
def test_gyro_varying_rates(student):
    """200 samples of varying body rates from a random R0 equal R0 Π Exp(ω_k dt), to 1e-11 per sample"""
    rng = np.random.default_rng(9500)
    for R0, scale in zip(random_rotations(3, 9501), (0.5, 2.0, 8.0)):
        omegas = scale * rng.normal(size=(200, 3))
        got = expect_array(
            student.with_timeout(SLOW).integrate_gyro(R0, omegas, 0.01), (3, 3), "integrate_gyro(R0, ω, dt)"
        )
        expect_close(
            got,
            _integrate(R0, omegas, 0.01),
            200 * 1e-11,
            f"integrate_gyro for 200 samples of about {scale:g} rad/s",
            lambda: _gyro_hint(got, R0, omegas, 0.01),
        )


@exercise("integrate_gyro", weight=1)
def test_gyro_constant_rate_every_decade(student):
    """a constant body rate gives R0 Exp(N ω dt) for |ω dt| from 1e-12 to 3 rad per sample, to 1e-14 + 1e-10 Nθ"""
    steps = sorted(ANGLES, key=lambda a: (a < 0.1, -a))  # generic turns first
    for R0, step, axis in zip(random_rotations(len(steps), 9510), steps, _unit(9511, len(steps))):
        omegas = np.tile(step * axis / 0.01, (10, 1))
        got = expect_array(student.integrate_gyro(R0, omegas, 0.01), (3, 3), "integrate_gyro(R0, ω, dt)")
        expected = R0 @ _exp(10 * step * axis)
        expect_close(
            got,
            expected,
            1e-14 + 1e-10 * 10 * step,
            f"10 samples turning {step:.3g} rad each",
            lambda: _gyro_hint(got, R0, omegas, 0.01),
        )


@exercise("integrate_gyro", weight=1)
def test_gyro_edge_cases(student):
    """no samples returns R0 (an ndarray, also for R0 given as a list); one sample is R0 Exp(ω dt); 2000 samples
    stay a rotation to 1e-9"""
    R0 = random_rotations(1, 9520)[0]
    got = expect_array(student.integrate_gyro(R0, np.zeros((0, 3)), 0.01), (3, 3), "integrate_gyro with no samples")
    expect_close(got, R0, 1e-15, "integrate_gyro with no samples", "with no samples the attitude stays R0")
    from_list = student.integrate_gyro(R0.tolist(), np.zeros((0, 3)), 0.01)
    expect(
        isinstance(from_list, np.ndarray),
        f"integrate_gyro with R0 as a list and no samples returned a {type(from_list).__name__}, not an ndarray",
        "start from a float array, R = np.array(R0, dtype=float): "
        "the docstring promises an ndarray even when there is nothing to integrate",
    )
    omega = np.array([[0.3, -2.0, 1.1]])
    got = expect_array(student.integrate_gyro(R0, omega, 0.05), (3, 3), "integrate_gyro with one sample")
    expect_close(
        got,
        R0 @ _exp(0.05 * omega[0]),
        1e-14,
        "integrate_gyro with one sample",
        lambda: _gyro_hint(got, R0, omega, 0.05),
    )
    omegas = np.tile([3.0, -4.0, 0.0], (2000, 1))
    got = expect_array(
        student.with_timeout(SLOW).integrate_gyro(np.eye(3), omegas, 0.01), (3, 3), "integrate_gyro after 2000 samples"
    )
    problem = rotation_problem(got, 1e-9)
    expect(
        problem is None,
        f"after 2000 samples the result is not a rotation: {problem}",
        lambda: _gyro_hint(got, np.eye(3), omegas, 0.01),
    )


@exercise("integrate_gyro", weight=1)
def test_gyro_left_invariant(student):
    """integrating from M R0 gives M times the result from R0 (the world frame does not matter), to 1e-12"""
    rng = np.random.default_rng(9530)
    omegas = rng.normal(size=(20, 3))
    R0, M = random_rotations(2, 9531)
    base = expect_array(student.integrate_gyro(R0, omegas, 0.1), (3, 3), "integrate_gyro(R0, ω, dt)")
    moved = expect_array(student.integrate_gyro(M @ R0, omegas, 0.1), (3, 3), "integrate_gyro(M R0, ω, dt)")
    expect_close(
        moved,
        M @ base,
        1e-12,
        "integrate_gyro(M R0) against M integrate_gyro(R0)",
        lambda: _gyro_hint(moved, M @ R0, omegas, 0.1),
    )


@exercise("integrate_gyro", weight=1)
def test_gyro_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    omegas = np.random.default_rng(9540).normal(size=(5, 3))
    expect_same_with_lists(
        lambda R0, w: student.integrate_gyro(R0, w, 0.1),
        (random_rotations(1, 9541)[0], omegas),
        (3, 3),
        "integrate_gyro(R0, ω, dt)",
    )


# ---------------------------------------------------------------- rotated_point_covariance
def _random_covariance(rng, size=1.0):
    A = rng.normal(size=(3, 3))
    return size * (A @ A.T + 0.1 * np.eye(3))


def _point_covariance_hint(got, R, Sigma, p):
    J = -R @ _skew(p)
    truth = J @ Sigma @ J.T
    size = np.max(np.abs(truth)) or 1.0  # compare relative to the covariance's size
    got, truth, Sigma = got / size, truth / size, Sigma / size
    return (
        _first_explained(
            got,
            [
                (
                    _skew(p) @ Sigma @ _skew(p).T,
                    "[p]× Σ [p]×ᵀ is the covariance in the body frame: the world point is R p, so R belongs in J "
                    "(the Jacobian of R p that you derived in lesson 06)",
                ),
                (
                    _skew(R @ p) @ Sigma @ _skew(R @ p).T,
                    "[R p]× Σ [R p]×ᵀ treats ε as a world-frame (left) perturbation; here R Exp(ε): J is lesson 06's "
                    "Jacobian of the right perturbation",
                ),
                (R @ Sigma @ R.T, "that is the covariance of the turn, not of the point: use the point's Jacobian"),
                (J @ Sigma, "a covariance takes the Jacobian on both sides: J Σ Jᵀ"),
                (J.T @ Sigma @ J, "Jᵀ Σ J has the Jacobian on the wrong sides: J Σ Jᵀ"),
            ],
            truth,
        )
        or "to first order y ≈ R p + J ε, with J the Jacobian of R Exp(ε) p at ε = 0 (lesson 06), so Σ_y = J Σ Jᵀ"
    )


@exercise("rotated_point_covariance", weight=3)
def test_point_covariance_exact(student):
    """equals J Σ Jᵀ (J of R p, lesson 06) to 1e-12 |p|² |Σ| for 8 cases, |p| from 1e-6 to 1e3 m, |Σ| from 1e-10 to 1"""
    rng = np.random.default_rng(9600)
    for R, p_size, sigma_size in zip(
        random_rotations(8, 9601),
        (1e-6, 1e-3, 0.1, 1.0, 1.0, 10.0, 1e2, 1e3),
        (1e-4, 1.0, 1e-2, 1e-10, 1.0, 1e-6, 1e-3, 1e-8),
    ):
        p = p_size * rng.normal(size=3) / np.sqrt(3.0)
        Sigma = _random_covariance(rng, sigma_size)
        J = -R @ _skew(p)
        expected = J @ Sigma @ J.T
        got = expect_array(student.rotated_point_covariance(R, Sigma, p), (3, 3), "rotated_point_covariance(R, Σ, p)")
        scale = np.max(np.abs(expected)) or 1.0
        expect_close(
            got / scale,
            expected / scale,
            1e-12,
            f"rotated_point_covariance for |p| ≈ {p_size:g} m (relative to its largest entry)",
            lambda: _point_covariance_hint(got, R, Sigma, p),
        )


@exercise("rotated_point_covariance", weight=1)
def test_point_covariance_shape_of_the_spread(student):
    """symmetric, positive semi-definite, and no spread along R p (to 1e-12 of its size)"""
    rng = np.random.default_rng(9610)
    for R in random_rotations(4, 9611):
        p, Sigma = rng.normal(size=3), _random_covariance(rng, 0.01)
        got = expect_array(student.rotated_point_covariance(R, Sigma, p), (3, 3), "rotated_point_covariance(R, Σ, p)")
        size = np.max(np.abs(got)) or 1.0
        hint = _point_covariance_hint(got, R, Sigma, p)
        expect_close(got, got.T, 1e-14 * size, "rotated_point_covariance against its transpose", hint)
        expect(
            np.min(np.linalg.eigvalsh(0.5 * (got + got.T))) >= -1e-12 * size,
            "the covariance has a negative eigenvalue",
            hint,
        )
        along = got @ (R @ p) / np.linalg.norm(R @ p)
        expect(
            np.max(np.abs(along)) <= 1e-12 * size,
            f"the covariance spreads along R p ({np.max(np.abs(along)):.2g})",
            hint,
        )


@exercise("rotated_point_covariance", weight=1)
def test_point_covariance_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    rng = np.random.default_rng(9620)
    expect_same_with_lists(
        student.rotated_point_covariance,
        (random_rotations(1, 9621)[0], _random_covariance(rng, 0.01), rng.normal(size=3)),
        (3, 3),
        "rotated_point_covariance(R, Σ, p)",
    )


# ---------------------------------------------------------------- covariance_left_to_right
def _left_to_right_hint(got, R, Sigma):
    size = np.max(np.abs(Sigma)) or 1.0  # compare relative to the covariance's size
    got, Sigma = got / size, Sigma / size
    return (
        _first_explained(
            got,
            [
                (
                    R @ Sigma @ R.T,
                    "that converts right to left: on a body turned a third of a turn about (1, 1, 1), a heading "
                    "uncertainty about the world's vertical must end up on the body's y axis",
                ),
                (Sigma, "the covariance must change frame: world axes (left) are not body axes (right) unless R = I"),
                (R.T @ Sigma, hints.COVARIANCE_TAKES_LINEAR_MAP_HINT),
                (Sigma @ R, hints.COVARIANCE_TAKES_LINEAR_MAP_HINT),
            ],
            R.T @ Sigma @ R,
        )
        or hints.LEFT_TO_RIGHT_WITH_ADJOINT_HINT
    )


@exercise("covariance_left_to_right", weight=3)
def test_left_to_right_exact(student):
    """equals the body-frame covariance to 1e-12 |Σ| for rotations at every angle from 1e-12 to π and |Σ| from 1e-10 to 10"""
    rng = np.random.default_rng(9700)
    sizes = (1.0, 0.01, 1e-10, 1e-6, 1e-3, 1e-2, 0.1, 1.0, 10.0, 1e-4, 1e-2, 1.0, 0.3)
    for R, size in zip(list(random_rotations(2, 9702)) + _rotations_at_every_angle(9701), sizes):  # generic first
        Sigma = _random_covariance(rng, size)
        got = expect_array(student.covariance_left_to_right(R, Sigma), (3, 3), "covariance_left_to_right(R, Σ)")
        expected = R.T @ Sigma @ R
        expect_close(
            got / size,
            expected / size,
            1e-12,
            f"covariance_left_to_right for a turn of {np.linalg.norm(_log(R)):.3g} rad (relative to |Σ|)",
            lambda: _left_to_right_hint(got, R, Sigma),
        )


@exercise("covariance_left_to_right", weight=1)
def test_left_to_right_keeps_the_uncertainty(student):
    """keeps the eigenvalues (only the axes change) and matches the sampled conversion of 20 000 draws to 5 %"""
    rng = np.random.default_rng(9710)
    R, Sigma = random_rotations(1, 9711)[0], _random_covariance(rng, 1e-3)
    got = expect_array(student.covariance_left_to_right(R, Sigma), (3, 3), "covariance_left_to_right(R, Σ)")
    expect_close(
        np.linalg.eigvalsh(0.5 * (got + got.T)),
        np.linalg.eigvalsh(Sigma),
        1e-14,
        "the eigenvalues of the converted covariance",
        lambda: _left_to_right_hint(got, R, Sigma),
    )
    eps_left = rng.multivariate_normal(np.zeros(3), Sigma, size=20_000)
    eps_right = Rotation.from_matrix(R.T @ Rotation.from_rotvec(eps_left).as_matrix() @ R).as_rotvec()
    sampled = np.cov(eps_right.T)
    gap = np.max(np.abs(got - sampled)) / np.max(np.abs(sampled))
    expect(
        gap <= 0.05,
        f"differs from the covariance of 20 000 converted samples by {100 * gap:.0f} %",
        lambda: _left_to_right_hint(got, R, Sigma),
    )


@exercise("covariance_left_to_right", weight=1)
def test_left_to_right_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    rng = np.random.default_rng(9720)
    expect_same_with_lists(
        student.covariance_left_to_right,
        (random_rotations(1, 9721)[0], _random_covariance(rng, 0.01)),
        (3, 3),
        "covariance_left_to_right(R, Σ)",
    )


# ---------------------------------------------------------------- align_pose_gauss_newton
def _pose_data(count, seed, noise=0.0, T=None):
    rng = np.random.default_rng(seed)
    T = _random_poses(1, seed + 500, 2.0)[0] if T is None else T
    P = rng.normal(size=(count, 3))
    Q = P @ T[:3, :3].T + T[:3, 3] + noise * rng.normal(size=(count, 3))
    return P, Q, T


def _closed_form_pose(P, Q):
    """Centre both sets, align the centred sets with scipy, t = q̄ - R p̄ (independent of the reference)."""
    p_mean, q_mean = P.mean(axis=0), Q.mean(axis=0)
    R = Rotation.align_vectors(Q - q_mean, P - p_mean)[0].as_matrix()
    return _pose(R, q_mean - R @ p_mean)


def _gauss_newton_pose(P, Q, T0, iters, update="right", sign=-1.0, jacobian="right"):
    T = np.array(T0, dtype=float)
    for _ in range(iters):
        R, t = T[:3, :3], T[:3, 3]
        H, g = np.zeros((6, 6)), np.zeros(6)
        for p, q in zip(P, Q):
            J = np.hstack([R, -R @ _skew(p)]) if jacobian == "right" else np.hstack([np.eye(3), -_skew(R @ p + t)])
            H += J.T @ J
            g += J.T @ (R @ p + t - q)
        xi = np.linalg.solve(H, sign * g)
        if update == "right":
            T = T @ _exp_se3(xi)
        elif update == "left":
            T = _exp_se3(xi) @ T
        else:  # rotation and translation updated separately
            T = _pose(R @ _exp(xi[3:]), t + xi[:3])
    return T


def _pose_gn_hint(got, P, Q, T0, iters, expected):
    if np.max(np.abs(got - T0)) == 0.0:
        return hints.RETURNED_T0_UNCHANGED_DO_HINT
    slips = [
        (
            dict(update="left"),
            "the update Exp(xi) T goes with the left Jacobian [I, -[T p]×]; with "
            "lesson 07's jacobian_transform_point (a right Jacobian) update on the right, T ← T Exp(xi)",
        ),
        (dict(sign=1.0), "steps uphill: xi solves H xi = -g (mind the minus sign)"),
        (
            dict(update="separate"),
            "R ← R Exp(phi), t ← t + rho is another manifold: with the Jacobian "
            "the right Jacobian of lesson 07 update the pose with T ← T ExpSE3(xi)",
        ),
    ]
    for options, hint in slips:
        try:
            candidate = _gauss_newton_pose(P, Q, T0, iters, **options)
        except np.linalg.LinAlgError:
            continue
        if explains(got, candidate, expected, floor=1e-12):
            return hint
    if iters > 1 and explains(got, _gauss_newton_pose(P, Q, T0, 1), expected, floor=1e-12):
        return f"that is one Gauss-Newton step, whatever iters says: repeat the update iters times (here {iters})"
    if rotation_problem(got[:3, :3], 1e-8) or not np.allclose(got[3], [0.0, 0.0, 0.0, 1.0]):
        return "the result drifted off SE(3): update with T ← T ExpSE3(xi), which stays a pose"
    return "J_i from lesson 07's jacobian_transform_point, H = Σ J_iᵀ J_i, g = Σ J_iᵀ r_i, xi = solve(H, -g), T ← T ExpSE3(xi)"


@exercise("align_pose_gauss_newton", weight=1)
def test_pose_gn_one_step(student, ref):
    """one iteration is exactly one Gauss-Newton step on SE(3) (right perturbation, T ← T Exp(ξ)), to 1e-8"""
    solver = student.with_timeout(SLOW)
    for k in range(3):
        P, Q, T = _pose_data(20, seed=9800 + k, noise=0.05)
        T0 = T @ _exp_se3(0.4 * np.random.default_rng(9810 + k).normal(size=6))
        expected = ref.align_pose_gauss_newton(P, Q, T0, iters=1)
        got = expect_array(
            solver.align_pose_gauss_newton(P, Q, T0, iters=1), (4, 4), "align_pose_gauss_newton(..., iters=1)"
        )
        expect_close(
            got,
            expected,
            1e-8,
            "one Gauss-Newton step from T0",
            lambda: _pose_gn_hint(got, P, Q, T0, 1, expected),
            scale=np.linalg.norm(T[:3, 3]),
        )


@exercise("align_pose_gauss_newton", weight=3)
def test_pose_gn_converges_from_far(student):
    """reaches the closed-form pose (scipy) from 2 rad and 2 m away with the default 10 iterations, to 1e-8"""
    solver = student.with_timeout(SLOW)
    for k in range(3):
        P, Q, _ = _pose_data(25, seed=9820 + k, noise=0.05)
        expected = _closed_form_pose(P, Q)
        rng = np.random.default_rng(9830 + k)
        axis = rng.normal(size=3)
        shift = rng.normal(size=3)
        T0 = expected @ _exp_se3(
            np.concatenate([2.0 * shift / np.linalg.norm(shift), 2.0 * axis / np.linalg.norm(axis)])
        )
        got = expect_array(solver.align_pose_gauss_newton(P, Q, T0), (4, 4), "align_pose_gauss_newton(P, Q, T0)")
        expect_close(
            got,
            expected,
            1e-8,
            "align_pose_gauss_newton from 2 rad and 2 m away (10 iterations)",
            lambda: _pose_gn_hint(got, P, Q, T0, 10, expected),
            scale=np.linalg.norm(expected[:3, 3]),
        )


@exercise("align_pose_gauss_newton", weight=1)
def test_pose_gn_exact_data(student):
    """recovers the pose to 1e-10 from noise-free pairs, including a tiny turn (1e-9 rad) and a far shift (100 m)"""
    solver = student.with_timeout(SLOW)
    cases = [_pose(_exp(1e-9 * _unit(9840, 1)[0]), [100.0, -50.0, 20.0]), _random_poses(1, 9841, 3.0)[0]]
    for k, T in enumerate(cases):
        P, Q, _ = _pose_data(8, seed=9842 + k, T=T)
        T0 = T @ _exp_se3([0.3, -0.2, 0.4, 0.5, -0.4, 0.3])
        got = expect_array(
            solver.align_pose_gauss_newton(P, Q, T0, iters=10), (4, 4), "align_pose_gauss_newton on exact data"
        )
        expect_close(
            got,
            T,
            1e-10,
            "align_pose_gauss_newton on exact data",
            lambda: _pose_gn_hint(got, P, Q, T0, 10, T),
            scale=np.linalg.norm(T[:3, 3]),
        )


@exercise("align_pose_gauss_newton", weight=1)
def test_pose_gn_stays_on_se3_and_accepts_lists(student):
    """returns an exact pose after 30 iterations, and the same answer for plain lists"""
    solver = student.with_timeout(SLOW)
    P, Q, T = _pose_data(12, seed=9850, noise=0.1)
    T0 = T @ _exp_se3([1.0, 0.8, -0.7, 0.9, -0.6, 0.5])
    got = expect_array(solver.align_pose_gauss_newton(P, Q, T0, iters=30), (4, 4), "align_pose_gauss_newton(..., 30)")
    problem = rotation_problem(got[:3, :3], 1e-9)
    expect(
        problem is None and np.array_equal(got[3], [0.0, 0.0, 0.0, 1.0]),
        f"after 30 iterations the result is not a pose: {problem or 'bottom row ' + fmt(got[3])}",
        lambda: _pose_gn_hint(got, P, Q, T0, 30, _closed_form_pose(P, Q)),
    )
    expect_same_with_lists(
        lambda a, b, c: solver.align_pose_gauss_newton(a, b, c, iters=3),
        (P, Q, T0),
        (4, 4),
        "align_pose_gauss_newton(P, Q, T0)",
    )


# ---------------------------------------------------------------- align_pose_robust
K = 0.05


def _huber_gradient(T, P, Q, k):
    """Gradient of Σ ρ_k(|T p_i - q_i|) with respect to a right perturbation ξ of T (a 6-vector)."""
    R, t = T[:3, :3], T[:3, 3]
    g = np.zeros(6)
    for p, q in zip(P, Q):
        r = R @ p + t - q
        size = np.linalg.norm(r)
        weight = 1.0 if size <= k else k / size
        g += weight * np.hstack([R, -R @ _skew(p)]).T @ r
    return g


def _huber_cost(T, P, Q, k):
    r = np.linalg.norm(P @ T[:3, :3].T + T[:3, 3] - Q, axis=1)
    return float(np.sum(np.where(r <= k, 0.5 * r**2, k * r - 0.5 * k * k)))


def _outlier_data(count, seed, share, noise=0.005):
    rng = np.random.default_rng(seed)
    P, Q, T = _pose_data(count, seed, noise=noise)
    wrong = rng.permutation(count)[: int(round(share * count))]
    Q[wrong] += rng.normal(size=(len(wrong), 3))
    T0 = T @ _exp_se3(0.25 * rng.normal(size=6))
    return P, Q, T, T0


def _squared_weights_stationary(T, P, Q, k):
    """Is T a stationary point of the cost whose weights are (k/|r|)² beyond k (a log tail, not Huber's)?"""
    R, t = T[:3, :3], T[:3, 3]
    g = np.zeros(6)
    for p, q in zip(P, Q):
        r = R @ p + t - q
        size = np.linalg.norm(r)
        g += (1.0 if size <= k else (k / size) ** 2) * np.hstack([R, -R @ _skew(p)]).T @ r
    return bool(np.max(np.abs(g)) < 1e-8 * len(P))


def _robust_hint(got, P, Q, T0, k):
    if np.max(np.abs(got - np.asarray(T0, dtype=float))) == 0.0:
        return hints.RETURNED_T0_UNCHANGED_ITERATE_HINT
    if rotation_problem(got[:3, :3], 1e-8):
        return "the result is not a pose: update with T ← T ExpSE3(xi)"
    if np.max(np.abs(_huber_gradient(got, P, Q, np.inf))) < 1e-8:
        return hints.MINIMISES_SQUARED_COST_LEAST_HINT
    if _squared_weights_stationary(got, P, Q, k):
        return hints.ROBUST_SLOWER_TAIL_HINT
    if _huber_cost(got, P, Q, k) < _huber_cost(np.asarray(T0, dtype=float), P, Q, k):
        return "the cost went down but the gradient is not zero yet: iterate until your steps are tiny"
    return hints.ROBUST_GRADIENT_NOT_ZERO_HINT


@exercise("align_pose_robust", weight=3)
def test_robust_stationary(student):
    """the gradient of the Huber cost vanishes at the answer (to 1e-10 per point) for 0 to 40 % wrong pairs"""
    solver = student.with_timeout(SLOW)
    for k, share in enumerate((0.0, 0.1, 0.25, 0.4)):
        P, Q, _, T0 = _outlier_data(30, 9900 + k, share)
        got = expect_array(solver.align_pose_robust(P, Q, T0, K), (4, 4), "align_pose_robust(P, Q, T0, k)")
        problem = rotation_problem(got[:3, :3], 1e-8)
        expect(
            problem is None,
            f"align_pose_robust did not return a pose: {problem}",
            lambda: _robust_hint(got, P, Q, T0, K),
        )
        gradient = _huber_gradient(got, P, Q, K)
        expect(
            np.max(np.abs(gradient)) <= 1e-10 * len(P),
            f"with {100 * share:.0f} % wrong pairs the Huber gradient is {fmt(gradient, 3)}, not zero",
            lambda: _robust_hint(got, P, Q, T0, K),
        )


@exercise("align_pose_robust", weight=1)
def test_robust_is_a_minimum(student):
    """no small turn or shift (1e-4 in each of 12 directions) lowers the Huber cost at the answer"""
    solver = student.with_timeout(SLOW)
    P, Q, _, T0 = _outlier_data(25, 9910, 0.2)
    got = expect_array(solver.align_pose_robust(P, Q, T0, K), (4, 4), "align_pose_robust(P, Q, T0, k)")
    best = _huber_cost(got, P, Q, K)
    for direction in np.vstack([np.eye(6), -np.eye(6)]):
        moved = _huber_cost(got @ _exp_se3(1e-4 * direction), P, Q, K)
        expect(
            moved >= best - 1e-12,
            f"a step of 1e-4 along {fmt(direction)} lowers the cost from {best:.9g} to {moved:.9g}",
            lambda: _robust_hint(got, P, Q, T0, K),
        )


@exercise("align_pose_robust", weight=1)
def test_robust_resists_outliers(student):
    """with 25 % of pairs moved by about 1 m, the position stays within 2 cm and the turn within 0.01 rad"""
    solver = student.with_timeout(SLOW)
    for seed in (9920, 9921):
        P, Q, T, T0 = _outlier_data(40, seed, 0.25)
        got = expect_array(solver.align_pose_robust(P, Q, T0, K), (4, 4), "align_pose_robust(P, Q, T0, k)")
        position = np.linalg.norm(got[:3, 3] - T[:3, 3])
        turn = np.linalg.norm(_log(T[:3, :3].T @ got[:3, :3])) if rotation_problem(got[:3, :3], 1e-6) is None else 9.9
        expect(
            position <= 0.02 and turn <= 0.01,
            f"off by {100 * position:.1f} cm and {turn:.3g} rad",
            lambda: _robust_hint(got, P, Q, T0, K),
        )


@exercise("align_pose_robust", weight=1)
def test_robust_exact_data(student):
    """recovers the pose to 1e-9 from clean pairs (where the Huber cost is the squared cost)"""
    solver = student.with_timeout(SLOW)
    P, Q, T = _pose_data(10, seed=9930)
    T0 = T @ _exp_se3([0.2, -0.3, 0.1, 0.3, 0.2, -0.25])
    got = expect_array(solver.align_pose_robust(P, Q, T0, K), (4, 4), "align_pose_robust on clean pairs")
    expect_close(
        got,
        T,
        1e-9,
        "align_pose_robust on clean pairs",
        lambda: _robust_hint(got, P, Q, T0, K),
        scale=np.linalg.norm(T[:3, 3]),
    )


@exercise("align_pose_robust", weight=1)
def test_robust_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    P, Q, _, T0 = _outlier_data(12, 9940, 0.2)
    expect_same_with_lists(
        lambda a, b, c: student.with_timeout(SLOW).align_pose_robust(a, b, c, K),
        (P, Q, T0),
        (4, 4),
        "align_pose_robust(P, Q, T0, k)",
    )
