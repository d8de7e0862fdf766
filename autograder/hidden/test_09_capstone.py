"""Hidden checks for lesson 09, section 7: the capstone hand_eye_rotation (design).

Judged by the result only, never by the method: on datasets the grader draws here with its own seeds (6 to 40
pairs, noise σ = 0.01 to 0.05 rad per axis on A_i, up to 40 % outliers drawn uniformly on SO(3), turns of B_i
between 0.3 and 2.5 rad, near-degenerate sets whose axes lie within about 0.1 to 0.15 rad of one direction, and
exact sets whose axes all lie in one plane),
the angle of X from the truth must stay below 4 σ_X, where σ_X = σ √trace(H⁻¹), H = Σ (2 I - B_i - B_iᵀ) over the
good pairs, is the first-order spread of the best estimate (1e-9 rad for exact data): the noise is A_i = X B_i Xᵀ
Exp(n_i), and with X = X̂ Exp(δ) a pair's residual moves by X̂ (B_iᵀ - I) δ, whose information is (B_i - I)(B_i - I)ᵀ
= 2 I - B_i - B_iᵀ per σ². Why 4 σ_X: the first-order error of the best estimate is Gaussian with total spread σ_X, so
it leaves 4 σ_X with a probability below 1e-4 per dataset even when all of it lies along one axis (the reference
stays within 1 σ_X on these sets), while an X fitted to the two pairs that most others agree with does not stay
within it (4.6 and 4.9 σ_X on two sets; a bar of 5 σ_X let it pass). Core idea (3 of 6 points):
surviving outliers at the noise's accuracy. Every test calls hand_eye_rotation only.
"""

import numpy as np
from coursekit import hints
from scipy.spatial.transform import Rotation

from .helpers import Wrong, exercise, expect, expect_array, rotation_problem

PLANE_SEEDS = (9712, 9713, 9714, 9715, 9716, 9717)  # exact pairs whose axes share one plane (X is still determined)
SLOW = 20  # seconds per call: a search over pairs of pairs is allowed


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(R).as_rotvec()


def _dataset(seed, pairs, sigma, outliers, cone=None, plane=False):
    rng = np.random.default_rng(seed)
    X = Rotation.random(random_state=rng).as_matrix()
    main_axis = rng.normal(size=3)
    main_axis /= np.linalg.norm(main_axis)
    As, Bs = [], []
    for _ in range(pairs):
        axis = rng.normal(size=3) if cone is None else main_axis + cone * rng.normal(size=3) / np.sqrt(3)
        if plane:  # every turn's axis in the plane normal to main_axis
            axis = axis - (axis @ main_axis) * main_axis
        B = _exp(rng.uniform(0.3, 2.5) * axis / np.linalg.norm(axis))
        Bs.append(B)
        As.append(X @ B @ X.T @ _exp(sigma * rng.normal(size=3)))
    wrong = rng.choice(pairs, outliers, replace=False)
    for i in wrong:
        As[i] = Rotation.random(random_state=rng).as_matrix()
    good = sorted(set(range(pairs)) - set(wrong))
    H = sum(2 * np.eye(3) - Bs[i] - Bs[i].T for i in good)
    bound = 4.0 * sigma * np.sqrt(np.trace(np.linalg.inv(H))) if sigma > 0 else 1e-9
    return np.array(As), np.array(Bs), X, bound, good


def _nearest(M):
    U, _, Vt = np.linalg.svd(M)
    return U @ np.diag([1.0, 1.0, np.linalg.det(U @ Vt)]) @ Vt


def _judge(student, seed, pairs, sigma, outliers, cone=None, plane=False):
    As, Bs, X_true, bound, good = _dataset(seed, pairs, sigma, outliers, cone, plane)
    X = expect_array(student.with_timeout(SLOW).hand_eye_rotation(As, Bs), (3, 3), "hand_eye_rotation(As, Bs)")
    problem = rotation_problem(X)
    expect(
        not problem,
        f"hand_eye_rotation returned a matrix that is not a rotation: {problem}",
        hints.HAND_EYE_NOT_A_ROTATION_HINT,
    )
    error = float(np.linalg.norm(_log(X.T @ X_true)))
    what = (
        f"{pairs} pairs, σ = {sigma:g} rad, {outliers} outliers"
        + ("" if cone is None else f", axes within {cone:g} rad")
        + (", every axis in one plane" if plane else "")
    )
    if not error <= bound:
        transposed = float(np.linalg.norm(_log(X @ X_true)))
        if transposed < 0.05:
            hint = "that is Xᵀ: in A X = X B, X carries B's frame into A's"
        else:  # the same student on the pairs in reverse order, then on the good pairs alone, tells what went wrong
            hint = "with noise, every good pair adds precision: use all the good ones"
            X_reversed = np.asarray(student.with_timeout(SLOW).hand_eye_rotation(As[::-1], Bs[::-1]), dtype=float)
            order_matters = (
                X_reversed.shape != (3, 3) or float(np.linalg.norm(_log(_nearest(X_reversed).T @ X))) > bound
            )
            if outliers and not order_matters:  # the answer follows every pair, whatever their order
                X_good = np.asarray(student.with_timeout(SLOW).hand_eye_rotation(As[good], Bs[good]), dtype=float)
                if X_good.shape == (3, 3) and float(np.linalg.norm(_log(_nearest(X_good).T @ X_true))) <= bound:
                    hint = "the wrong pairs pulled X away: some pairs fit no single X, and your answer follows them"
        raise Wrong(f"X is {error:.3g} rad from the truth ({what}); the bound is {bound:.3g} rad", hint)


@exercise("hand_eye_rotation", weight=3)
def test_hand_eye_with_outliers(student):
    """within 4 σ_X of the truth on 6 grader-drawn datasets: 12 to 40 pairs, σ = 0.01 to 0.05 rad, 20 to 40 % outliers"""
    for seed, pairs, sigma, outliers in [
        (9700, 20, 0.01, 4),
        (9701, 40, 0.02, 16),
        (9702, 12, 0.05, 3),
        (9703, 30, 0.03, 9),
        (9704, 12, 0.02, 4),
        (9705, 12, 0.02, 4),
    ]:
        _judge(student, seed, pairs, sigma, outliers)


@exercise("hand_eye_rotation", weight=1)
def test_hand_eye_without_outliers(student):
    """exact to 1e-9 rad on 6 exact pairs and on exact pairs whose axes share one plane, and within 4 σ_X on 8
    noisy pairs without outliers"""
    _judge(student, 9710, 6, 0.0, 0)
    for seed in PLANE_SEEDS:
        _judge(student, seed, 8, 0.0, 0, plane=True)
    _judge(student, 9711, 8, 0.02, 0)


@exercise("hand_eye_rotation", weight=1)
def test_hand_eye_near_degenerate(student):
    """within 4 σ_X when every turn's axis lies within about 0.1 to 0.15 rad of one direction (with outliers)"""
    for seed, pairs, cone, outliers in [(9720, 20, 0.15, 4), (9721, 14, 0.1, 3)]:
        _judge(student, seed, pairs, 0.01, outliers, cone)


@exercise("hand_eye_rotation", weight=1)
def test_hand_eye_lists_and_inputs(student):
    """accepts plain lists, leaves its inputs unchanged, and answers within 4 σ_X (16 pairs, 4 outliers)"""
    As, Bs, X_true, bound, _ = _dataset(9730, 16, 0.01, 4)
    copies = [As.copy(), Bs.copy()]
    X = expect_array(student.with_timeout(SLOW).hand_eye_rotation(*copies), (3, 3), "hand_eye_rotation")
    expect(
        np.array_equal(copies[0], As) and np.array_equal(copies[1], Bs),
        "hand_eye_rotation changed its inputs",
        "work on copies",
    )
    X_lists = expect_array(
        student.with_timeout(SLOW).hand_eye_rotation(As.tolist(), Bs.tolist()), (3, 3), "hand_eye_rotation with lists"
    )
    expect(
        float(np.linalg.norm(_log(X.T @ X_true))) <= bound,
        "X is beyond 4 σ_X of the truth",
        "the accuracy checks of this exercise say more",
    )
    expect(
        np.allclose(X_lists, X, atol=1e-12),
        hints.HAND_EYE_LISTS_REASON,
        "convert the arguments with np.asarray(x, dtype=float)",
    )
