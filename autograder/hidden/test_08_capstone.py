"""Hidden checks for lesson 08: estimating a rotation.

Independent oracles: scipy's ``Rotation.align_vectors`` (the closed-form
Kabsch/Wahba solution, with the reflection handled) for the alignment
exercises, the reference's single Gauss-Newton step, and the defining
properties of the geodesic mean (first-order optimality Σ Log(Mᵀ R_i) = 0,
bi-invariance, the midpoint of two rotations). Every test calls the student's
function of its own exercise only.

Core ideas carry at least half of each exercise's points, so the classic
mistake earns at most half: the determinant fix in align_svd (mirrored data,
4 of 7), iterating Gauss-Newton to convergence (from 2.5 rad away, 3 of 6;
one step alone earns 2 of 6), the geodesic, not chordal, mean (Σ Log(Mᵀ R_i)
= 0, 4 of 7; the chordal mean and a single step are bi-invariant and exact
for two rotations, so they earn 3 of 7).
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import (
    LISTS_HINT,
    exercise,
    expect,
    expect_array,
    expect_close,
    expect_same_with_lists,
    random_rotations,
    rotation_problem,
)

TOL = 1e-9
SLOW = 20  # seconds per call for the iterative exercises


# ---------------------------------------------------------------- data
def _points(count, seed, scale=1.0):
    return np.random.default_rng(seed).normal(size=(count, 3)) * scale


def _data(count, seed, noise=0.0, R=None):
    """(P, Q, R_true) with rows q_i = R p_i + noise."""
    rng = np.random.default_rng(seed)
    R = random_rotations(1, seed + 500)[0] if R is None else R
    P = rng.normal(size=(count, 3))
    Q = P @ R.T + noise * rng.normal(size=(count, 3))
    return P, Q, R


def _closed_form(P, Q):
    """scipy's solution of min Σ |q_i - R p_i|² over rotations (independent of the reference)."""
    rotation, _ = Rotation.align_vectors(Q, P)
    return rotation.as_matrix()


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(R).as_rotvec()


def _angle(A, B):
    return float(np.linalg.norm(_log(A.T @ B)))


def _expect_rotation(R, what, tol=1e-8, hint=""):
    problem = rotation_problem(R, tol)
    expect(problem is None, f"{what} is not a rotation: {problem}", hint)


# ---------------------------------------------------------------- diagnosis
def _explains(got, candidate, truth):
    return explains(got, candidate, truth, floor=1e-12)


def _hat(v):
    x, y, z = v
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


# ---------------------------------------------------------------- align_svd
def _svd_hint(got, P, Q, expected):
    """Name the slip behind a wrong align_svd(P, Q) = ``got`` by computing what each slip returns."""
    P, Q = np.asarray(P, dtype=float), np.asarray(Q, dtype=float)
    U, _, Vt = np.linalg.svd(Q.T @ P)
    if np.linalg.det(U @ Vt) < 0 and _explains(got, U @ Vt, expected):
        return (
            "that is U Vᵀ without the determinant fix: a reflection (det = -1); "
            "use U diag(1, 1, d) Vᵀ with d = det(U Vᵀ)"
        )
    if _explains(got, expected.T, expected):
        return hints.INVERSE_ROTATION_TRANSPOSE_USE_HINT
    if _explains(got, np.linalg.lstsq(P, Q, rcond=None)[0].T, expected):
        return hints.UNCONSTRAINED_LEAST_SQUARES_MATRIX_HINT
    if _explains(got, np.eye(3), expected):
        return hints.RETURNED_IDENTITY_IF_Q_HINT
    det = np.linalg.det(got)
    if det < 0:
        return f"det = {det:.3f}: a reflection, not a rotation"
    if rotation_problem(got, 1e-8):
        return "the result must be a rotation (orthonormal, det +1): build it from the SVD of M = Qᵀ P"
    return hints.ALIGNMENT_SVD_FORMULA_HINT


@exercise("align_svd", weight=1)
def test_align_svd_exact(student):
    """recovers the rotation exactly from noise-free pairs (3 to 20 points, 10 rotations)"""
    for k, count in enumerate((3, 4, 5, 8, 12, 20, 3, 6, 10, 20)):
        P, Q, R = _data(count, seed=800 + k)
        got = expect_array(student.align_svd(P, Q), (3, 3), f"align_svd for {count} exact pairs")
        expect_close(got, R, TOL, f"align_svd for {count} exact pairs", lambda: _svd_hint(got, P, Q, R))


@exercise("align_svd", weight=1)
def test_align_svd_noisy(student):
    """matches the closed-form least-squares rotation (scipy) for noisy data"""
    for k, (count, noise) in enumerate(((10, 0.05), (30, 0.2), (6, 0.5), (50, 1.0))):
        P, Q, _ = _data(count, seed=820 + k, noise=noise)
        expected = _closed_form(P, Q)
        got = expect_array(student.align_svd(P, Q), (3, 3), f"align_svd for {count} noisy pairs")
        expect_close(
            got,
            expected,
            1e-8,
            f"align_svd for {count} pairs with noise {noise}",
            lambda: _svd_hint(got, P, Q, expected),
        )


@exercise("align_svd", weight=4)
def test_align_svd_no_reflection(student):
    """returns the best rotation, not a reflection, when the naive U Vᵀ has det = -1"""
    mirror = np.diag([1.0, 1.0, -1.0])
    for k in range(4):
        P, _, R = _data(15, seed=840 + k)
        Q = P @ (R @ mirror).T + 0.01 * np.random.default_rng(850 + k).normal(size=P.shape)
        # (for this data the naive U Vᵀ of Qᵀ P has det = -1: the case this test is about)
        got = expect_array(student.align_svd(P, Q), (3, 3), "align_svd for mirrored data")
        expected = _closed_form(P, Q)
        det = np.linalg.det(got)
        expect(
            det > 0,
            f"returned a reflection (det = {det:.3f}) for mirrored data",
            lambda: _svd_hint(got, P, Q, expected),
        )
        expect_close(got, expected, 1e-8, "align_svd for mirrored data", lambda: _svd_hint(got, P, Q, expected))


@exercise("align_svd", weight=1)
def test_align_svd_is_a_rotation_and_accepts_lists(student):
    """returns a rotation for nearly coplanar data, and accepts plain lists"""
    P, Q, _ = _data(12, seed=860, noise=0.05)
    P[:, 2] *= 1e-3
    got = expect_array(student.align_svd(P, Q), (3, 3), "align_svd for nearly coplanar data")
    expected = _closed_form(P, Q)
    _expect_rotation(got, "align_svd for nearly coplanar data", hint=_svd_hint(got, P, Q, expected))
    expect_close(got, expected, 1e-7, "align_svd for nearly coplanar data", lambda: _svd_hint(got, P, Q, expected))
    P, Q, R = _data(5, seed=861)
    expect_same_with_lists(student.align_svd, (P, Q), (3, 3), "align_svd(P, Q)")


# ---------------------------------------------------------------- align_gauss_newton
def _gauss_newton(P, Q, R0, iters, jacobian="right", update="exp", sign=-1.0):
    """Gauss-Newton as the lecture writes it, or with one known slip (to recognise it in an answer)."""
    R = np.array(R0, dtype=float)
    for _ in range(iters):
        H, g = np.zeros((3, 3)), np.zeros(3)
        for p, q in zip(P, Q):
            J = -R @ _hat(p) if jacobian == "right" else -_hat(R @ p)
            H += J.T @ J
            g += J.T @ (R @ p - q)
        delta = np.linalg.solve(H, sign * g)
        R = R @ _exp(delta) if update == "exp" else R + R @ _hat(delta)
    return R


def _gn_hint(got, P, Q, R0, iters, expected):
    """Name the slip behind a wrong align_gauss_newton(P, Q, R0, iters) = ``got``."""
    P, Q = np.asarray(P, dtype=float), np.asarray(Q, dtype=float)
    if np.max(np.abs(got - R0)) == 0.0:
        return hints.RETURNED_R0_UNCHANGED_DO_HINT
    slips = [
        (
            dict(jacobian="left"),
            "the left Jacobian -[R p_i]× with the right update R Exp(δ) mixes two conventions: "
            "R ← R Exp(δ) needs the Jacobian of the right perturbation (lesson 06); -[R p_i]× would need Exp(δ) R",
        ),
        (dict(sign=1.0), "steps uphill: δ solves H δ = -g (mind the minus sign)"),
        (dict(update="add"), hints.UPDATED_ADDING_R_R_HINT),
    ]
    for options, hint in slips:
        try:
            candidate = _gauss_newton(P, Q, R0, iters, **options)
        except np.linalg.LinAlgError:
            continue
        if _explains(got, candidate, expected):
            return hint
    if iters > 1 and _explains(got, _gauss_newton(P, Q, R0, 1), expected):
        return f"that is one Gauss-Newton step, whatever iters says: repeat the update iters times (here {iters})"
    if rotation_problem(got, 1e-8):
        return "the result drifted off SO(3): update with R ← R Exp(δ), which stays a rotation"
    return "J_i of the right perturbation (lesson 06), H = Σ J_iᵀ J_i, g = Σ J_iᵀ r_i, δ = solve(H, -g), R ← R Exp(δ)"


@exercise("align_gauss_newton", weight=1)
def test_align_gauss_newton_one_step(student, ref):
    """one iteration is exactly one Gauss-Newton step (right perturbation, R ← R Exp(δ))"""
    solver = student.with_timeout(SLOW)
    for k in range(3):
        P, Q, R = _data(20, seed=900 + k, noise=0.1)
        R0 = R @ _exp(0.5 * np.random.default_rng(910 + k).normal(size=3))
        expected = ref.align_gauss_newton(P, Q, R0, iters=1)
        got = expect_array(solver.align_gauss_newton(P, Q, R0, iters=1), (3, 3), "align_gauss_newton(..., iters=1)")
        expect_close(got, expected, 1e-8, "one Gauss-Newton step from R0", lambda: _gn_hint(got, P, Q, R0, 1, expected))


@exercise("align_gauss_newton", weight=3)
def test_align_gauss_newton_converges_from_far(student):
    """converges to the closed-form answer from 2.5 rad away with the default 10 iterations (noisy data)"""
    solver = student.with_timeout(SLOW)
    for k in range(3):
        P, Q, _ = _data(25, seed=920 + k, noise=0.05)
        expected = _closed_form(P, Q)
        axis = np.random.default_rng(930 + k).normal(size=3)
        R0 = expected @ _exp(2.5 * axis / np.linalg.norm(axis))
        got = expect_array(solver.align_gauss_newton(P, Q, R0), (3, 3), "align_gauss_newton(P, Q, R0)")
        expect_close(
            got,
            expected,
            1e-8,
            f"align_gauss_newton from {2.5:.1f} rad away (10 iterations)",
            lambda: _gn_hint(got, P, Q, R0, 10, expected),
        )


@exercise("align_gauss_newton", weight=1)
def test_align_gauss_newton_exact_data(student):
    """recovers the rotation to 1e-10 from noise-free data, starting 1 rad away"""
    solver = student.with_timeout(SLOW)
    P, Q, R = _data(8, seed=940)
    R0 = R @ _exp([0.6, -0.5, 0.6])
    got = expect_array(solver.align_gauss_newton(P, Q, R0, iters=10), (3, 3), "align_gauss_newton on exact data")
    expect_close(got, R, 1e-10, "align_gauss_newton on exact data", lambda: _gn_hint(got, P, Q, R0, 10, R))
    from_lists = expect_array(
        solver.align_gauss_newton(P.tolist(), Q.tolist(), R0.tolist(), iters=10),
        (3, 3),
        "align_gauss_newton with P, Q and R0 as plain lists",
    )
    expect_close(from_lists, got, 1e-12, "align_gauss_newton with lists vs with arrays", LISTS_HINT)


@exercise("align_gauss_newton", weight=1)
def test_align_gauss_newton_stays_on_so3(student):
    """returns an exact rotation after 30 iterations from a start 1.5 rad away"""
    solver = student.with_timeout(SLOW)
    P, Q, R = _data(12, seed=950, noise=0.1)
    R0 = R @ _exp([1.0, 0.8, -0.7])
    got = expect_array(solver.align_gauss_newton(P, Q, R0, iters=30), (3, 3), "align_gauss_newton(..., iters=30)")
    _expect_rotation(
        got, "align_gauss_newton after 30 iterations", tol=1e-9, hint=_gn_hint(got, P, Q, R0, 30, _closed_form(P, Q))
    )


# ---------------------------------------------------------------- rotation_mean
def _cloud(count, seed, spread, centre=None):
    rng = np.random.default_rng(seed)
    centre = random_rotations(1, seed + 7)[0] if centre is None else centre
    return np.array([centre @ _exp(spread * rng.normal(size=3)) for _ in range(count)])


def _chordal(Rs):
    U, _, Vt = np.linalg.svd(np.mean(Rs, axis=0))
    return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt


def _geodesic_mean(Rs):
    M = _chordal(Rs)
    for _ in range(100):
        delta = np.mean([_log(M.T @ R) for R in Rs], axis=0)
        M = M @ _exp(delta)
        if np.linalg.norm(delta) < 1e-14:
            break
    return M


def _mean_hint(M, Rs):
    """Name the slip behind a wrong rotation_mean(Rs) = ``M`` by computing what each slip returns."""
    Rs = np.asarray(Rs, dtype=float)
    if np.all(Rs == Rs[0]):
        return hints.COPIES_NOT_KEPT_HINT
    truth = _geodesic_mean(Rs)
    if _explains(M, _chordal(Rs), truth):
        return (
            "that is the chordal mean (the projected arithmetic mean): its residuals Log(Mᵀ R_i) do not balance; "
            "the geodesic mean needs an iteration"
        )
    one_step = Rs[0] @ _exp(np.mean([_log(Rs[0].T @ R) for R in Rs], axis=0))
    if _explains(M, one_step, truth):
        return "that is a single step from Rs[0]: repeat until the step is tiny (|δ| < 1e-12)"
    if _explains(M, _exp(np.mean([_log(R) for R in Rs], axis=0)), truth):
        return hints.AVERAGING_LOG_R_I_HINT
    if _explains(M, Rs[0], truth):
        return hints.RETURNED_FIRST_ROTATION_RS_HINT
    return "the residuals Log(Mᵀ R_i) must balance, Σ Log(Mᵀ R_i) = 0: iterate until your step is tiny (|δ| < 1e-12)"


def _imbalance(M, Rs):
    return float(np.linalg.norm(sum(_log(M.T @ R) for R in Rs))) / len(Rs)


@exercise("rotation_mean", weight=4)
def test_rotation_mean_first_order_optimality(student):
    """Σ Log(Mᵀ R_i) ≈ 0 at the returned mean, for clouds of spread 0.1 to 0.6 rad"""
    solver = student.with_timeout(SLOW)
    for k, (count, spread) in enumerate(((10, 0.1), (25, 0.4), (40, 0.6), (7, 0.5))):
        Rs = _cloud(count, seed=1000 + k, spread=spread)
        M = expect_array(solver.rotation_mean(Rs), (3, 3), f"rotation_mean of {count} rotations")
        _expect_rotation(M, f"rotation_mean of {count} rotations")
        imbalance = _imbalance(M, Rs)
        expect(
            imbalance <= 1e-8,
            f"|Σ Log(Mᵀ R_i)| / N = {imbalance:.2g} for {count} rotations of spread {spread} rad "
            "(should be 0 at the geodesic mean)",
            lambda: _mean_hint(M, Rs),
        )


@exercise("rotation_mean", weight=1)
def test_rotation_mean_bi_invariant(student):
    """the mean of A R_i B is A M B (for 3 random pairs A, B)"""
    solver = student.with_timeout(SLOW)
    Rs = _cloud(20, seed=1010, spread=0.5)
    M = expect_array(solver.rotation_mean(Rs), (3, 3), "rotation_mean(Rs)")
    for A, B in zip(random_rotations(3, seed=1011), random_rotations(3, seed=1012)):
        moved = np.array([A @ R @ B for R in Rs])
        got = expect_array(solver.rotation_mean(moved), (3, 3), "rotation_mean of A R_i B")
        expect_close(
            got, A @ M @ B, 1e-8, "rotation_mean(A R_i B) vs A rotation_mean(R_i) B", lambda: _mean_hint(got, moved)
        )


@exercise("rotation_mean", weight=1)
def test_rotation_mean_simple_cases(student):
    """copies of one rotation average to it; two rotations average to the midpoint of their arc"""
    solver = student.with_timeout(SLOW)
    R = random_rotations(1, seed=1020)[0]
    got = expect_array(solver.rotation_mean(np.array([R, R, R, R])), (3, 3), "rotation_mean of 4 copies of R")
    expect_close(got, R, TOL, "rotation_mean of 4 copies of R", lambda: _mean_hint(got, np.array([R, R, R, R])))
    A = random_rotations(1, seed=1021)[0]
    step = np.array([0.3, -1.1, 0.9])
    pair = np.array([A, A @ _exp(step)])
    got = expect_array(solver.rotation_mean(pair), (3, 3), "rotation_mean of two rotations")
    expect_close(
        got, A @ _exp(step / 2.0), 1e-8, "rotation_mean of two rotations (the midpoint)", lambda: _mean_hint(got, pair)
    )
    expect(_angle(got, A) > 0.1, "the mean of two different rotations is one of them")


@exercise("rotation_mean", weight=1)
def test_rotation_mean_accepts_a_list(student):
    """accepts a list of 3×3 arrays, and nested plain lists, as well as one (N, 3, 3) array"""
    solver = student.with_timeout(SLOW)
    Rs = _cloud(6, seed=1030, spread=0.3)
    from_array = expect_array(solver.rotation_mean(Rs), (3, 3), "rotation_mean(array of rotations)")
    for what, given in (("list of rotations", [R for R in Rs]), ("nested lists", Rs.tolist())):
        from_list = expect_array(solver.rotation_mean(given), (3, 3), f"rotation_mean({what})")
        expect_close(
            from_list,
            from_array,
            1e-12,
            f"rotation_mean of a {what} vs of the same rotations as an array",
            "convert the input with np.asarray(Rs, dtype=float)",
        )
