"""Hidden checks for lesson 08, section 6: weighted_rotation_mean.

Oracles: the first-order optimality of the weighted geodesic mean (Σ w_i Log(Mᵀ R_i) = 0, computed with scipy),
repetition (integer weights are copies, compared with the balance of the repeated list), invariance under a
common scale of the weights, bi-invariance, and two rotations (the weighted point on their arc). Core idea
(3 of 7 points): the weighted balance for clouds of spread 0.1 to 0.8 rad and weights spread over three
decades, to 1e-9 rad. Every test calls weighted_rotation_mean only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect, expect_array, expect_close, random_rotations, rotation_problem

SLOW = 20


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(np.asarray(R, dtype=float)).as_rotvec()


def _cloud(count, seed, spread):
    rng = np.random.default_rng(seed)
    centre = random_rotations(1, seed + 7)[0]
    return np.array([centre @ _exp(spread * rng.normal(size=3)) for _ in range(count)])


def _balance(M, Rs, w):
    return float(np.linalg.norm(sum(wi * _log(M.T @ R) for wi, R in zip(w, Rs)))) / float(np.sum(w))


def _geodesic(Rs, w, start=0, steps=200):
    M = Rs[start]
    for _ in range(steps):
        delta = sum(wi * _log(M.T @ R) for wi, R in zip(w, Rs)) / np.sum(w)
        M = M @ _exp(delta)
        if np.linalg.norm(delta) < 1e-15:
            break
    return M


def _hint(M, Rs, w):
    truth = _geodesic(Rs, w)
    U, _, Vt = np.linalg.svd(sum(wi * R for wi, R in zip(w, Rs)))
    slips = [
        (_geodesic(Rs, np.ones(len(Rs))), "the weights were ignored: each Log(Mᵀ R_i) must count w_i times"),
        (
            U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt,
            "that is the weighted chordal mean; the geodesic mean balances Σ w_i Log(Mᵀ R_i) = 0",
        ),
        (_geodesic(Rs, w, steps=1), "that is a single step from Rs[0]: repeat until the step is tiny"),
        (_geodesic(Rs, np.asarray(w) ** 2), "the weights were squared: a weight of 2 must count like two copies"),
    ]
    for candidate, hint in slips:
        if np.max(np.abs(candidate - truth)) > 1e-9 and explains(M, candidate, truth, floor=1e-12):
            return hint
    return "the weighted residuals must balance, Σ w_i Log(Mᵀ R_i) = 0: iterate until your step is tiny (|δ| < 1e-12)"


def _mean(student, Rs, w, what):
    M = expect_array(student.with_timeout(SLOW).weighted_rotation_mean(Rs, w), (3, 3), what)
    problem = rotation_problem(M, 1e-8)
    expect(problem is None, f"{what} is not a rotation: {problem}", lambda: _hint(M, Rs, w))
    return M


@exercise("weighted_rotation_mean", weight=3)
def test_weighted_balance(student):
    """Σ w_i Log(Mᵀ R_i) / Σ w_i ≈ 0 (to 1e-9) for clouds of spread 0.1 to 0.8 rad and weights from 1e-3 to 1"""
    for k, (count, spread) in enumerate(((6, 0.1), (15, 0.4), (30, 0.8), (9, 0.5))):
        Rs = _cloud(count, 8300 + k, spread)
        w = 10.0 ** np.random.default_rng(8310 + k).uniform(-3, 0, size=count)
        M = _mean(student, Rs, w, f"weighted_rotation_mean of {count} rotations")
        imbalance = _balance(M, Rs, w)
        expect(
            imbalance <= 1e-9,
            f"|Σ w_i Log(Mᵀ R_i)| / Σ w_i = {imbalance:.2g} for {count} rotations of spread "
            f"{spread} rad (should be 0 at the weighted mean)",
            lambda: _hint(M, Rs, w),
        )


@exercise("weighted_rotation_mean", weight=1)
def test_weights_are_counts(student):
    """integer weights act like repeated rotations, and scaling every weight by 1e-6 or 1e6 changes nothing (1e-9)"""
    Rs = _cloud(5, 8320, 0.5)
    counts = np.array([1.0, 3.0, 2.0, 1.0, 4.0])
    M = _mean(student, Rs, counts, "weighted_rotation_mean(Rs, counts)")
    repeated = np.repeat(Rs, counts.astype(int), axis=0)
    imbalance = _balance(M, repeated, np.ones(len(repeated)))
    expect(
        imbalance <= 1e-9,
        f"with integer weights the mean does not balance the repeated list ({imbalance:.2g})",
        lambda: _hint(M, Rs, counts),
    )
    for scale in (1e-6, 1e6):
        scaled = _mean(student, Rs, scale * counts, f"weighted_rotation_mean(Rs, {scale:g} × counts)")
        expect_close(
            scaled,
            M,
            1e-9,
            f"the mean with every weight multiplied by {scale:g}",
            hints.WEIGHT_RATIOS_HINT,
        )


@exercise("weighted_rotation_mean", weight=1)
def test_weighted_two_rotations(student):
    """two rotations with weights a and b: the point a fraction b / (a + b) along their arc, to 1e-9"""
    A = random_rotations(1, 8330)[0]
    step = np.array([0.4, -1.0, 0.7])
    for a, b in ((1.0, 1.0), (1.0, 3.0), (5.0, 1.0)):
        M = _mean(
            student, np.array([A, A @ _exp(step)]), [a, b], f"weighted_rotation_mean of two, weights {a:g}, {b:g}"
        )
        expect_close(
            M,
            A @ _exp(b / (a + b) * step),
            1e-9,
            f"the weighted mean of two rotations (weights {a:g}, {b:g})",
            lambda: _hint(M, np.array([A, A @ _exp(step)]), [a, b]),
        )


@exercise("weighted_rotation_mean", weight=1)
def test_weighted_bi_invariant(student):
    """the weighted mean of A R_i B is A M B (for 2 pairs A, B), to 1e-8"""
    Rs = _cloud(12, 8340, 0.4)
    w = np.random.default_rng(8341).uniform(0.2, 3.0, size=12)
    M = _mean(student, Rs, w, "weighted_rotation_mean(Rs, w)")
    for A, B in zip(random_rotations(2, 8342), random_rotations(2, 8343)):
        moved = np.array([A @ R @ B for R in Rs])
        got = _mean(student, moved, w, "weighted_rotation_mean of A R_i B")
        expect_close(
            got, A @ M @ B, 1e-8, "weighted_rotation_mean(A R_i B) against A M B", lambda: _hint(got, moved, w)
        )


@exercise("weighted_rotation_mean", weight=1)
def test_weighted_accepts_lists(student):
    """accepts a list of 3×3 arrays and a list of weights"""
    Rs = _cloud(6, 8350, 0.3)
    w = [1.0, 2.0, 0.5, 1.5, 3.0, 1.0]
    from_arrays = _mean(student, Rs, np.array(w), "weighted_rotation_mean(array, array)")
    from_lists = expect_array(
        student.with_timeout(SLOW).weighted_rotation_mean([R.tolist() for R in Rs], w),
        (3, 3),
        "weighted_rotation_mean(list, list)",
    )
    expect_close(
        from_lists,
        from_arrays,
        1e-12,
        "weighted_rotation_mean of lists against arrays",
        hints.CONVERT_INPUTS_NP_ASARRAY_HINT,
    )
