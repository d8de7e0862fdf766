"""Hidden checks for lesson 03: the Lie algebra so(3), exp and log.

Independent oracles: scipy's ``Rotation`` (``from_rotvec``, ``as_rotvec``,
``as_matrix``), ``scipy.linalg.expm``, ``np.cross`` and explicit sums.
Tolerances: 1e-12 absolute for unit-size values; at tiny angles the log
must be off by at most 1e-15 + 1e-10 θ, so a dropped series term (θ²/6)
shows at θ = 1e-3. Lists are compared with the same function's answer for
arrays, so "convert with np.asarray" fires only when lists are the difference.
The axis is real: a complex eigenvector (np.linalg.eig's dtype) is refused, hidden and public.
Promises checked over the whole domain (properties drawn by Hypothesis, derandomized, see
``properties.py``): exp_so3 is within 1e-14 of scipy entrywise at every angle from 1e-12 to π, each
decade and just below each power of ten (where a small-angle branch whose series is too short shows);
axis_angle names u = [1, 0, 0] at θ = 0 and takes integer lists; every answer is real (no complex dtype).
Edge cases: θ = 0, tiny angles (1e-12, 1e-8), π/2, angles within 1e-6 and
1e-9 of π, exactly π about generic axes and about (1, 1, 1)/√3 (the half
turn that Modern Robotics' ``MatrixLog3`` maps to zero), |w| > π, and
"identities" whose trace rounding pushes above 3. Rotation vectors are
compared by meaning: at exactly π, w and -w are the same rotation; the axis
of an eigenvector may have either sign. Every test calls the student's
functions of its own exercise only.
"""

import numpy as np
from scipy.linalg import expm
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.checks.lesson03 import COLUMN_HINT, REAL_AXIS_HINT, vee_hint
from coursekit.diagnose import explains

from .properties import angle_text, decade_vectors, expect_within, for_all, given_forms, rotation_vectors
from .helpers import (
    Wrong,
    exercise,
    expect,
    expect_array,
    expect_close,
    expect_same_with_lists,
    fmt,
    random_rotations,
    rotation_problem,
    shape_problem,
)

TOL = 1e-12
EXP_TOL = 1e-14  # exp_so3's promise at every angle: each entry within 1e-14 (scipy's own error is ~3e-16)
DIAGONAL = np.ones(3) / np.sqrt(3.0)


def _skew(w):
    x, y, z = np.asarray(w, dtype=float)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _unit_axes(count, seed):
    axes = np.random.default_rng(seed).normal(size=(count, 3))
    return axes / np.linalg.norm(axes, axis=1, keepdims=True)


def _special_axes():
    """Axes where a naive near-π branch tends to fail: equal components, zeros, negative largest entries."""
    axes = [
        DIAGONAL,
        -DIAGONAL,
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
        [1.0, -1.0, 0.0],
        [0.6, 0.0, -0.8],
        [-0.48, 0.6, -0.64],
        [1.0, 1.0, -1.0],
        [-2.0, 1.0, 2.0],
    ]
    return [np.asarray(a, dtype=float) / np.linalg.norm(a) for a in axes]


def _half_turn_matrices(axis):
    """Two floating-point versions of the turn by exactly π about ``axis``."""
    return [("2uuᵀ - I", 2.0 * np.outer(axis, axis) - np.eye(3)), ("scipy", _exp(np.pi * axis))]


def _nearly_identities():
    """R @ Rᵀ for random R: identities up to rounding, some with (tr R - 1)/2 slightly above 1."""
    found = []
    for R in random_rotations(40, seed=399):
        P = R @ R.T
        if (np.trace(P) - 1.0) / 2.0 > 1.0:
            found.append(P)
    return found[:5]


# ---------------------------------------------------------------- hat


def _hat_hint(W, w):
    """Name the slip behind a wrong hat(w) = ``W``, by comparing with what each slip returns."""
    x, y, z = np.asarray(w, dtype=float)
    truth = _skew(w)
    if explains(W, truth.T, truth):
        return "the signs are swapped (the transpose, -[w]×): the top row is [0, -w3, w2], so [w]× v = w × v"
    if explains(W, np.array([[0.0, z, y], [z, 0.0, x], [y, x, 0.0]]), truth):
        return hints.MINUS_SIGNS_MISSING_SYMMETRIC_HINT
    if explains(W, np.diag([x, y, z]), truth):
        return hints.W_SITS_DIAGONAL_W_HINT
    for order in ((2, 1, 0), (1, 0, 2), (0, 2, 1), (1, 2, 0), (2, 0, 1)):
        if explains(W, _skew(np.asarray(w, dtype=float)[list(order)]), truth):
            return (
                "the components of w are permuted: check which component of w sits in each "
                "off-diagonal entry of W, against the page"
            )
    if np.max(np.abs(W + W.T)) > 0.0:
        return "not skew-symmetric: [w]× has zeros on the diagonal and W[j, i] = -W[i, j]"
    return hints.COMPARE_ENTRY_ENTRY_W3_HINT


@exercise("hat", weight=3)
def test_hat_is_cross_product(student):
    """hat(w) @ v equals np.cross(w, v) for 20 random vectors"""
    rng = np.random.default_rng(301)
    for w, v in zip(rng.normal(size=(20, 3)), rng.normal(size=(20, 3))):
        W = expect_array(student.hat(w), (3, 3), "hat(w)")
        got, want = W @ v, np.cross(w, v)
        if not np.max(np.abs(got - want)) <= TOL:
            expect_close(got, want, TOL, "hat(w) @ v", lambda: _hat_hint(W, w))


@exercise("hat", weight=2)
def test_hat_layout(student):
    """has the layout [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]] and is skew-symmetric"""
    W = expect_array(student.hat([1.0, 2.0, 3.0]), (3, 3), "hat([1, 2, 3])")
    expected = np.array([[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]])
    if not np.array_equal(W, expected):
        expect_close(W, expected, 0.0, "hat([1, 2, 3])", lambda: _hat_hint(W, [1.0, 2.0, 3.0]))
    W = expect_array(student.hat([-0.5, 4.0, 1e-9]), (3, 3), "hat(w)")
    expect_close(W, -W.T, 0.0, "hat(w) + hat(w)ᵀ", lambda: _hat_hint(W, [-0.5, 4.0, 1e-9]))


@exercise("hat", weight=1)
def test_hat_accepts_lists_and_zero(student):
    """accepts lists and integers; hat(0) is the zero matrix"""
    expect_close(
        expect_array(student.hat([0, 0, 0]), (3, 3), "hat([0, 0, 0])"), np.zeros((3, 3)), 0.0, "hat([0, 0, 0])"
    )
    expect_same_with_lists(student.hat, ([1.0, 0.0, 0.0],), (3, 3), "hat([1, 0, 0])", lists=([1, 0, 0],))


# ---------------------------------------------------------------- vee


@exercise("vee", weight=3)
def test_vee_inverts_hat(student):
    """vee([w]×) = w for 20 random vectors"""
    for w in np.random.default_rng(302).normal(size=(20, 3)):
        got = expect_array(student.vee(_skew(w)), (3,), "vee(W)")
        if not np.max(np.abs(got - w)) <= TOL:
            expect_close(got, w, TOL, "vee([w]×)", lambda: vee_hint(got, _skew(w), w))


@exercise("vee", weight=1)
def test_vee_is_linear(student):
    """vee(a A + b B) = a vee(A) + b vee(B)"""
    rng = np.random.default_rng(303)
    x, y = rng.normal(size=(2, 3))
    W = 2.5 * _skew(x) - 0.75 * _skew(y)
    combined = expect_array(student.vee(W), (3,), "vee(2.5 A - 0.75 B)")
    if not np.max(np.abs(combined - (2.5 * x - 0.75 * y))) <= TOL:
        expect_close(
            combined, 2.5 * x - 0.75 * y, TOL, "vee(2.5 [x]× - 0.75 [y]×)", vee_hint(combined, W, 2.5 * x - 0.75 * y)
        )


@exercise("vee", weight=1)
def test_vee_accepts_lists(student):
    """accepts a nested list"""
    expect_same_with_lists(student.vee, (_skew([1.0, -2.0, 3.0]),), (3,), "vee(W)")


# ---------------------------------------------------------------- bracket
def _bracket_hint(got, A, B):
    truth = A @ B - B @ A
    if explains(got, A @ B + B @ A, truth):
        return hints.AB_BA_BRACKET_DIFFERENCE_HINT
    if explains(got, B @ A - A @ B, truth):
        return "the order is reversed: [A, B] = AB - BA"
    if explains(got, A * B - B * A, truth):
        return hints.GOT_ZERO_MULTIPLIES_ENTRY_HINT
    if explains(got, A @ B, truth):
        return hints.ONLY_AB_BRACKET_SUBTRACTS_HINT
    if explains(got, B @ A, truth):
        return "that is only BA: the bracket is AB - BA"
    return "[A, B] = A @ B - B @ A, with matrix products"


@exercise("bracket", weight=3)
def test_bracket_random_matrices(student):
    """[A, B] = AB - BA for random 3×3 and 4×4 matrices"""
    rng = np.random.default_rng(304)
    for n in (3, 3, 3, 4, 2):
        A, B = rng.normal(size=(2, n, n))
        got = expect_array(student.bracket(A, B), (n, n), f"bracket(A, B) for {n}×{n} matrices")
        if not np.max(np.abs(got - (A @ B - B @ A))) <= 1e-12:
            expect_close(got, A @ B - B @ A, 1e-12, f"bracket(A, B) ({n}×{n})", lambda: _bracket_hint(got, A, B))


@exercise("bracket", weight=2)
def test_bracket_is_cross_product(student):
    """[a^, b^] = (a × b)^ for random vectors"""
    rng = np.random.default_rng(305)
    for a, b in zip(rng.normal(size=(10, 3)), rng.normal(size=(10, 3))):
        A, B = _skew(a), _skew(b)
        got = expect_array(student.bracket(A, B), (3, 3), "bracket(a^, b^)")
        if not np.max(np.abs(got - _skew(np.cross(a, b)))) <= 1e-12:
            expect_close(
                got, _skew(np.cross(a, b)), 1e-12, "bracket(a^, b^) vs (a × b)^", lambda: _bracket_hint(got, A, B)
            )


@exercise("bracket", weight=1)
def test_bracket_alternating(student):
    """[A, A] = 0 and [A, B] = -[B, A]"""
    rng = np.random.default_rng(306)
    A, B = rng.normal(size=(2, 3, 3))
    same = expect_array(student.bracket(A, A), (3, 3), "bracket(A, A)")
    if not np.max(np.abs(same)) <= 1e-12:
        hint = (
            "that is AA + AA: "
            if explains(same, 2 * A @ A, np.zeros((3, 3)))
            else "that is AA: "
            if explains(same, A @ A, np.zeros((3, 3)))
            else ""
        )
        expect_close(
            same, np.zeros((3, 3)), 1e-12, "bracket(A, A)", hint + "the bracket of a matrix with itself is AA - AA = 0"
        )
    ab = expect_array(student.bracket(A, B), (3, 3), "bracket(A, B)")
    ba = expect_array(student.bracket(B, A), (3, 3), "bracket(B, A)")
    expect_close(ab, -ba, 1e-12, "bracket(A, B) + bracket(B, A)")


# ---------------------------------------------------------------- exp_series
def _series_hint(student_value, W, n):
    """Recognise the usual slips by computing what each returns (neighbouring partial sums, W ** k, no 1/k!)."""

    def partial(first, last, factorial=True):
        term, total = np.eye(W.shape[0]), np.zeros_like(W)
        for k in range(last + 1):
            if k >= first:
                total = total + term
            term = term @ W / (k + 1 if factorial else 1)
        return total

    truth = partial(0, n - 1)
    if explains(student_value, partial(1, n), truth) or explains(student_value, partial(1, n - 1), truth):
        return hints.IDENTITY_TERM_MISSING_SUM_HINT
    if explains(student_value, partial(0, n), truth):
        return hints.ONE_TERM_TOO_MANY_HINT
    if n >= 2 and explains(student_value, partial(0, n - 2), truth):
        return hints.ONE_TERM_TOO_FEW_HINT
    entrywise = sum(W**k / np.prod(np.arange(1, k + 1)) for k in range(n))
    if explains(student_value, entrywise, truth):
        return hints.ENTRYWISE_POWER_HINT
    if explains(student_value, partial(0, n - 1, factorial=False), truth):
        return hints.FACTORIAL_MISSING_HINT
    return hints.SUM_TERMS_W_K_HINT


@exercise("exp_series", weight=3)
def test_exp_series_partial_sums(student):
    """sums exactly the terms k = 0 … n_terms-1 (n_terms = 1 gives I)"""
    rng = np.random.default_rng(307)
    for W in [rng.normal(size=(3, 3)), _skew(rng.normal(size=3)), rng.normal(size=(2, 2))]:
        n = W.shape[0]
        expected, term = np.zeros((n, n)), np.eye(n)
        for n_terms in range(1, 7):
            expected = expected + term
            term = term @ W / n_terms
            got = expect_array(student.exp_series(W, n_terms), (n, n), f"exp_series(W, {n_terms})")
            expect_close(got, expected, 1e-12, f"exp_series(W, {n_terms})", lambda: _series_hint(got, W, n_terms))


@exercise("exp_series", weight=2)
def test_exp_series_converges(student):
    """many terms reach the exponential: rotations up to π, and general matrices (scipy's expm)"""
    for w in list(np.random.default_rng(308).normal(size=(5, 3))) + [np.pi * DIAGONAL]:
        got = expect_array(student.exp_series(_skew(w), 40), (3, 3), "exp_series([w]×, 40)")
        expect_close(got, _exp(w), 1e-12, "exp_series([w]×, 40) vs Exp(w)", lambda: _series_hint(got, _skew(w), 40))
    M = np.random.default_rng(309).normal(size=(4, 4))
    got = expect_array(student.exp_series(M, 60), (4, 4), "exp_series(M, 60) for a 4×4 matrix")
    expect_close(got, expm(M), 1e-10, "exp_series(M, 60) vs scipy.linalg.expm(M)", lambda: _series_hint(got, M, 60))


@exercise("exp_series", weight=1)
def test_exp_series_accepts_lists(student):
    """accepts a nested list"""
    W = _skew([0.1, 0.2, -0.3])
    expect_same_with_lists(lambda W: student.exp_series(W, 3), (W,), (3, 3), "exp_series(W, 3)")


# ---------------------------------------------------------------- exp_so3
def _exp_hint(got, expected, w):
    """Name the slip behind a wrong exp_so3(w) = ``got`` by computing what each slip returns."""
    w = np.asarray(w, dtype=float)
    angle = float(np.linalg.norm(w))
    if 0.0 < angle and np.array_equal(got, np.eye(3)):
        return (
            "returned exactly I for a tiny angle: R - I ≈ [w]× is the whole rotation; "
            "below a small angle use the Taylor series of each coefficient (on the page), with its θ² term"
        )
    if explains(got, expected.T, expected):
        return "looks like the inverse rotation: check the sign of the sin θ term against the page"
    if angle > 0.0:
        K = _skew(w / angle)
        W = _skew(w)
        if explains(got, np.eye(3) + (1 - np.cos(angle)) * K + np.sin(angle) * K @ K, expected):
            return hints.COEFFICIENTS_SWAPPED_R_I_HINT
        if explains(got, np.eye(3) + np.sin(angle) * W + (1 - np.cos(angle)) * W @ W, expected):
            return hints.RODRIGUES_FORMULA_NEEDS_UNIT_HINT
    problem = rotation_problem(got, 1e-9)
    if problem:
        return f"the result is not a rotation ({problem}): compare each term with Rodrigues' formula on the page"
    return hints.RODRIGUES_FORMULA_HINT


@exercise("exp_so3", weight=3)
def test_exp_so3_matches_scipy(student):
    """agrees with scipy for 30 random rotation vectors, |w| up to 3π"""
    rng = np.random.default_rng(310)
    axes = _unit_axes(30, seed=311)
    for axis, angle in zip(axes, rng.uniform(0.0, 3 * np.pi, 30)):
        w = angle * axis
        got = expect_array(student.exp_so3(w), (3, 3), "exp_so3(w)")
        expected = _exp(w)
        expect_close(got, expected, TOL, f"exp_so3(w) for |w| = {angle:.3f}", lambda: _exp_hint(got, expected, w))


@exercise("exp_so3", weight=3)
def test_exp_so3_special_angles(student):
    """exact at θ = 0, 1e-12, 1e-8, 1e-5, π/2, π (also about (1, 1, 1)/√3), 2π and 10 rad"""
    axes = _special_axes() + list(_unit_axes(3, seed=312))
    for angle in (0.0, 1e-12, 1e-8, 1e-5, np.pi / 2, np.pi, 2 * np.pi, 10.0):
        for axis in axes:
            w = angle * axis
            got = expect_array(student.exp_so3(w), (3, 3), f"exp_so3(w) at θ = {angle:.3g}")
            expected = _exp(w)
            what = f"exp_so3(w) at θ = {angle:.3g} about {fmt(axis, 3)}"
            if 0.0 < angle < 1e-4:
                error = float(np.max(np.abs(got - expected)))
                expect(
                    error <= 1e-15,
                    f"{what} is off by {error:.2g} (tolerance 1e-15): (R - I)/θ = "
                    f"{fmt((got - np.eye(3)) / angle)}, expected {fmt((expected - np.eye(3)) / angle)}",
                    lambda: _exp_hint(got, expected, w),
                )
            else:
                expect_close(got, expected, TOL, what, lambda: _exp_hint(got, expected, w))


@exercise("exp_so3", weight=2)
def test_exp_so3_every_decade(student):
    """exact to 1e-14 at every angle from 1e-12 to π (each decade, just below each power of ten), lists too"""

    def check(case):
        w, given = case
        got = expect_array(student.exp_so3(given), (3, 3), "exp_so3(w)")
        expected = _exp(w)
        expect_within(
            got, expected, EXP_TOL, "exp_so3(w)", angle_text(np.linalg.norm(w)), lambda: _exp_hint(got, expected, w)
        )

    for_all(given_forms(rotation_vectors()), check, explicit=decade_vectors())


@exercise("exp_so3", weight=1)
def test_exp_so3_group_properties(student):
    """is a rotation fixing its axis, and exp_so3(-w) is the inverse of exp_so3(w)"""
    for w in np.random.default_rng(313).normal(scale=1.5, size=(10, 3)):
        R = expect_array(student.exp_so3(w), (3, 3), "exp_so3(w)")
        problem = rotation_problem(R, 1e-12)
        expect(problem is None, f"exp_so3(w) is not a rotation: {problem}", lambda: _exp_hint(R, _exp(w), w))
        expect_close(R @ w, w, TOL, "exp_so3(w) @ w (the axis must not move)")
        R_back = expect_array(student.exp_so3(-w), (3, 3), "exp_so3(-w)")
        expect_close(R_back @ R, np.eye(3), TOL, "exp_so3(-w) @ exp_so3(w)")


@exercise("exp_so3", weight=1)
def test_exp_so3_accepts_lists(student):
    """accepts lists and integer entries"""
    expect_same_with_lists(student.exp_so3, ([0.0, 0.0, 1.0],), (3, 3), "exp_so3([0, 0, 1])", lists=([0, 0, 1],))


# ---------------------------------------------------------------- log_so3
def _log_parts(R):
    """a = vee(R - Rᵀ)/2 = sin θ u, c = (tr R - 1)/2 = cos θ, and θ from atan2 and from (clipped) arccos."""
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    c = 0.5 * (np.trace(R) - 1.0)
    return a, c, float(np.arctan2(np.linalg.norm(a), c)), float(np.arccos(np.clip(c, -1.0, 1.0)))


def _symmetric_part(R):
    """B = (R + Rᵀ)/2 - cos θ I = (1 - cos θ) u uᵀ."""
    R = np.asarray(R, dtype=float)
    return 0.5 * (R + R.T) - 0.5 * (np.trace(R) - 1.0) * np.eye(3)


def _weak_column(R):
    """Some column of B is (nearly) zero: a branch that always takes it divides by ~0 there."""
    diagonal = np.diag(_symmetric_part(R))
    return float(np.min(diagonal)) <= 1e-8 * float(np.max(diagonal))


def _column_logs(R, theta, a):
    """θ u with u read from each non-zero column of B, signed by a: what a near-π branch that always reads one
    fixed column returns (``explains`` never matches the columns that give the right answer). The public checks
    store these values at their own rotations (``LOG_SLIPS``), recomputed by the course's tests."""
    B = _symmetric_part(R)
    logs = []
    for j in range(3):
        norm = np.sqrt(B[:, j] @ B[:, j])
        if norm > 0.0:
            u = B[:, j] / norm
            logs.append(theta * u * (1.0 if u @ a >= 0.0 else -1.0))
    return logs


def _log_hint(got, R, expected):
    """Name the slip behind a wrong log_so3(R) = ``got`` (``expected`` the right vector), or say what to look at.

    Each diagnosis computes what the slip returns for this R and compares: the opposite axis, twice the
    vector, vee(R - Rᵀ)/2 without θ/sin θ, θ from arccos, θ/(2 sin θ)·vee(R - Rᵀ) without a branch at π.
    """
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    a, c, theta, theta_acos = _log_parts(R)
    angle = float(np.linalg.norm(expected))
    if not np.all(np.isfinite(got)):
        if abs(c) > 1.0:
            return (
                f"NaN: (tr R - 1)/2 = 1 {'+' if c > 0 else '-'} {abs(c) - 1.0:.1e} is just outside [-1, 1] "
                "by rounding, and arccos of it is NaN: clip it first (or use atan2)"
            )
        if angle < 1e-3:
            return hints.NAN_AT_ZERO_ANGLE_HINT
        if angle > 3.0 and _weak_column(R):
            return COLUMN_HINT
        if angle > 3.0:
            return hints.NAN_NEAR_PI_HINT
        return "NaN or inf: look for a division by zero or an arccos outside [-1, 1]"
    if angle == 0.0:
        return "the identity's log is the zero vector" if np.max(np.abs(got)) > 0.0 else ""
    unit = expected / angle
    if explains(got, -expected, expected):
        return hints.LOG_AXIS_SIGN_NEAR_PI_HINT if angle > 3.0 else hints.OPPOSITE_ROTATION_CHECK_SIGN_HINT
    if explains(got, 2.0 * expected, expected):
        return hints.TWICE_ROTATION_VECTOR_VEE_HINT
    if angle < 0.5 and explains(got, a, expected):
        return (
            f"returned vee(R - Rᵀ)/2 = sin θ u, off by about {angle**3 / 6:.1e} at θ = {angle:.3g}: below your "
            "small-angle threshold the log has lost its relative accuracy (the check asks for 1e-10 of θ)"
        )
    if explains(got, theta_acos * unit, expected):
        if theta_acos == 0.0:
            return hints.RETURNED_ZERO_TINY_ROTATION_HINT
        return (
            f"θ from arccos is off by {abs(theta_acos - angle):.1e}: arccos loses accuracy where its argument "
            "is near ±1; the angle must come from numbers that keep it"
        )
    no_branch = [t / np.sin(t) * a for t in (theta, theta_acos) if np.sin(t) != 0.0]
    if any(explains(got, candidate, expected) for candidate in no_branch) or (
        angle > 3.0 and np.linalg.norm(got) <= 1e-3 * angle
    ):
        return (
            f"θ/(2 sin θ)·vee(R - Rᵀ) divides two tiny numbers near π (here sin θ = {abs(np.sin(angle)):.1e}): the log "
            "needs its own branch near π that does not divide by sin θ (section 5: which part of R still holds "
            "the axis there?)"
        )
    if angle > 3.0 and any(explains(got, candidate, expected) for candidate in _column_logs(R, theta, a)):
        return COLUMN_HINT
    if angle > 3.0:
        return hints.LOG_OFF_NEAR_TAKE_HINT
    return hints.LOG_FORMULA_HINT


def _log(student, R, what):
    value = student.log_so3(R)
    got = np.asarray(value, dtype=float) if shape_problem(value, (3,)) == "returned NaN or inf values" else None
    if got is not None:
        raise Wrong(f"{what} returned {fmt(got)}", _log_hint(got, R, Rotation.from_matrix(R).as_rotvec()))
    return expect_array(value, (3,), what)


@exercise("log_so3", weight=3)
def test_log_so3_random(student):
    """agrees with scipy for 40 random rotations; exp(log(R)) = R"""
    for R in random_rotations(40, seed=314):
        got = _log(student, R, "log_so3(R)")
        expected = Rotation.from_matrix(R).as_rotvec()
        expect_close(
            got,
            expected,
            1e-10,
            f"log_so3(R) (angle {np.linalg.norm(expected):.3f})",
            lambda: _log_hint(got, R, expected),
        )
        expect_close(_exp(got), R, 1e-10, "Exp(log_so3(R)) vs R")


@exercise("log_so3", weight=2)
def test_log_so3_small_angles(student):
    """θ = 0, 1e-12, 1e-8, 1e-5, 1e-3: off by at most 1e-15 + 1e-10 θ (a dropped series term shows), never NaN"""
    got = _log(student, np.eye(3), "log_so3(I)")
    expect_close(got, np.zeros(3), 1e-15, "log_so3(I)", lambda: _log_hint(got, np.eye(3), np.zeros(3)))
    for index, P in enumerate(_nearly_identities()):
        got = _log(student, P, "log_so3(R Rᵀ)")
        expect(
            np.linalg.norm(got) <= 1e-12,
            f"log_so3 of an identity up to rounding (trace = 3 + {np.trace(P) - 3:.1e}) returned {fmt(got)}",
            "an identity up to rounding must give (almost) zero: (tr R - 1)/2 is just above 1 here; "
            "clip it to [-1, 1] before arccos, or use atan2",
        )
    for angle in (1e-12, 1e-8, 1e-5, 1e-3):
        for axis in _special_axes()[:4] + list(_unit_axes(4, seed=315)):
            w = angle * axis
            R = _exp(w)
            got = _log(student, R, f"log_so3(R) at θ = {angle:g}")
            expect_close(
                got,
                w,
                1e-15 + 1e-10 * angle,
                f"log_so3(R) at θ = {angle:g} about {fmt(axis, 3)}",
                lambda: _log_hint(got, R, w),
            )


@exercise("log_so3", weight=3)
def test_log_so3_near_pi(student):
    """θ = π - 1e-6 and π - 1e-9 about generic axes: the right vector (sign included) to 1e-8"""
    for gap in (1e-3, 1e-6, 1e-9):
        for axis in _special_axes() + list(_unit_axes(6, seed=316)):
            w = (np.pi - gap) * axis
            R = _exp(w)
            got = _log(student, R, f"log_so3(R) at θ = π - {gap:g}")
            expect_close(
                got, w, 1e-8, f"log_so3(R) at θ = π - {gap:g} about {fmt(axis, 3)}", lambda: _log_hint(got, R, w)
            )


@exercise("log_so3", weight=3)
def test_log_so3_exactly_pi(student):
    """θ = π exactly, about (1, 1, 1)/√3 and other axes: ±πu to 1e-10 (not zero, not NaN)"""
    for axis in _special_axes() + list(_unit_axes(4, seed=317)):
        w = np.pi * axis
        for how, R in _half_turn_matrices(axis):
            got = _log(student, R, f"log_so3 of a half turn ({how})")
            best = w if np.linalg.norm(got - w) <= np.linalg.norm(got + w) else -w
            expect_close(
                got,
                best,
                1e-10,
                f"log_so3 of the half turn about {fmt(axis, 3)} ({how}), either sign accepted",
                lambda: _log_hint(got, R, best),
            )


@exercise("log_so3", weight=2)
def test_log_so3_round_trips(student):
    """log(Exp(w)) = w for |w| < π; for π < |w| < 2π the angle folds to 2π - |w| about -u"""
    rng = np.random.default_rng(318)
    axes = _unit_axes(12, seed=319)
    for axis, angle in zip(axes[:6], rng.uniform(0.01, np.pi - 0.01, 6)):
        w = angle * axis
        R = _exp(w)
        got = _log(student, R, "log_so3(Exp(w))")
        expect_close(got, w, 1e-10, f"log_so3(Exp(w)) for |w| = {angle:.3f}", lambda: _log_hint(got, R, w))
    for axis, angle in zip(axes[6:], rng.uniform(np.pi + 0.01, 2 * np.pi - 0.01, 6)):
        w = angle * axis
        expected = -(2 * np.pi - angle) * axis
        R = _exp(w)
        got = _log(student, R, "log_so3(Exp(w))")
        hint = _log_hint(got, R, expected)
        if explains(got, w, expected):
            hint = "the log returns the angle in [0, π]: here 2π - |w| about -u"
        expect_close(got, expected, 1e-10, f"log_so3(Exp(w)) for |w| = {angle:.3f} > π", hint)


@exercise("log_so3", weight=1)
def test_log_so3_accepts_lists(student):
    """accepts a nested list"""
    expect_same_with_lists(student.log_so3, (_exp([0.2, -0.4, 0.1]),), (3,), "log_so3(R)")


# ---------------------------------------------------------------- axis_angle
def _theta_hint(theta, R, true_angle):
    """Name the slip behind a wrong angle θ from axis_angle(R): degrees, or θ from arccos."""
    _, c, _, theta_acos = _log_parts(R)
    if explains(theta, np.degrees(true_angle), true_angle):
        return hints.DEGREES_VALUE_RADIANS_COURSE_HINT
    if explains(theta, theta_acos, true_angle):
        if theta_acos == 0.0:
            return "arccos loses tiny angles (here it rounds θ to 0): the angle must come from numbers that keep it"
        return (
            f"θ from arccos is off by {abs(theta_acos - true_angle):.1e}: arccos is inaccurate next to ±1; "
            "the angle must come from numbers that keep it"
        )
    return hints.ANGLE_FORMULA_HINT


def _axis_hint(u, R, axis):
    """Name the slip behind a wrong axis u from axis_angle(R) (``axis`` the right unit axis, sign included)."""
    a, _, _, _ = _log_parts(R)
    if np.linalg.norm(a) <= 1e-9 and (np.linalg.norm(a) == 0.0 or abs(abs(u @ a) / np.linalg.norm(a) - 1.0) <= 1e-6):
        return hints.AXIS_AT_HALF_TURN_HINT
    if explains(u, -axis, axis):
        return hints.U_POINTS_WRONG_WAY_HINT
    return "u is off: check it against R u = u, its length 1 and the sense of the turn, near π as well as far from it"


def _axis_angle(student, R, what):
    value = student.axis_angle(R)
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Wrong(f"{what} returned {type(value).__name__}, expected a pair (u, theta)", "return u, theta")
    true_angle = float(np.linalg.norm(Rotation.from_matrix(R).as_rotvec()))
    _, c, _, _ = _log_parts(R)
    if shape_problem(value[1], ()) == "returned NaN or inf values":
        raise Wrong(
            f"{what}: θ is {value[1]} (the true angle is {true_angle:.3g})",
            f"(tr R - 1)/2 = 1 + {c - 1.0:.1e} is just above 1 by rounding, so arccos gives NaN: "
            "clip (tr R - 1)/2 to [-1, 1] before arccos (or use atan2)"
            if abs(c) > 1.0
            else "θ must be a number",
        )
    theta = float(expect_array(value[1], (), f"{what}: theta"))
    if shape_problem(value[0], (3,)) == "returned NaN or inf values":
        raise Wrong(
            f"{what}: u is {fmt(np.asarray(value[0], dtype=float))} at θ = {theta:.3g}",
            hints.AXIS_AT_ZERO_ANGLE_HINT
            if true_angle <= 1e-12
            else "look for a division by a vanishing sin θ or norm",
        )
    u = expect_array(value[0], (3,), f"{what}: u")
    expect(
        abs(np.linalg.norm(u) - 1.0) <= 1e-12,
        f"{what}: |u| = {np.linalg.norm(u):.6g}, not 1",
        "u must be a unit vector: normalise it (at θ = 0 return [1, 0, 0])",
    )
    expect(
        -1e-15 <= theta <= np.pi + 1e-12,
        f"{what}: θ = {theta:.6g} is outside [0, π]",
        lambda: _theta_hint(theta, R, true_angle),
    )
    return u, theta


@exercise("axis_angle", weight=3)
def test_axis_angle_random(student):
    """unit u and θ in [0, π] that rebuild 30 random rotations; they agree with scipy"""
    for R in random_rotations(30, seed=320):
        u, theta = _axis_angle(student, R, "axis_angle(R)")
        expected = Rotation.from_matrix(R).as_rotvec()
        angle = np.linalg.norm(expected)
        expect_close(theta, angle, 1e-10, "θ", lambda: _theta_hint(theta, R, angle))
        expect_close(
            theta * u, expected, 1e-10, "θ u vs scipy's rotation vector", lambda: _axis_hint(u, R, expected / angle)
        )


@exercise("axis_angle", weight=1)
def test_axis_angle_identity(student):
    """θ = 0 for the identity and for identities up to rounding (trace just above 3), with the axis the
    docstring names for θ = 0, u = [1, 0, 0]; the identity as a list of integers too"""
    for index, P in enumerate([np.eye(3)] + _nearly_identities()):
        u, theta = _axis_angle(student, P, f"axis_angle(identity #{index})")
        expect(theta <= 1e-12, f"axis_angle of an identity (#{index}) gave θ = {theta:.3g}")
    u, theta = _axis_angle(student, np.eye(3).astype(int).tolist(), "axis_angle([[1, 0, 0], [0, 1, 0], [0, 0, 1]])")
    expect(
        np.array_equal(u, [1.0, 0.0, 0.0]) and theta == 0.0,
        f"axis_angle of the identity gave u = {fmt(u)}, θ = {theta:.3g}; the docstring names u = [1, 0, 0]",
        "at θ = 0 every axis is valid: return the one the docstring names, [1, 0, 0], and θ = 0",
    )


@exercise("axis_angle", weight=1)
def test_axis_angle_small(student):
    """tiny angles (1e-8, 1e-5): θ to relative 1e-6 and the right axis"""
    for angle in (1e-8, 1e-5):
        for axis in _unit_axes(5, seed=321):
            R = _exp(angle * axis)
            u, theta = _axis_angle(student, R, f"axis_angle at θ = {angle:g}")
            expect_close(theta / angle, 1.0, 1e-6, f"θ / θ_true at θ = {angle:g}", lambda: _theta_hint(theta, R, angle))
            expect_close(u, axis, 1e-6, f"u at θ = {angle:g}", lambda: _axis_hint(u, R, axis))


@exercise("axis_angle", weight=2)
def test_axis_angle_near_and_at_pi(student):
    """π - 1e-9: the right axis with its sign; exactly π: ±u, also about (1, 1, 1)/√3"""
    for axis in _special_axes():
        R = _exp((np.pi - 1e-9) * axis)
        u, theta = _axis_angle(student, R, "axis_angle at θ = π - 1e-9")
        expect_close(
            theta * u,
            (np.pi - 1e-9) * axis,
            1e-8,
            f"θ u at θ = π - 1e-9 about {fmt(axis, 3)}",
            lambda: (
                _theta_hint(theta, R, np.pi - 1e-9) if abs(theta - (np.pi - 1e-9)) > 1e-9 else _axis_hint(u, R, axis)
            ),
        )
        for how, R in _half_turn_matrices(axis):
            u, theta = _axis_angle(student, R, f"axis_angle of a half turn ({how})")
            expect(
                abs(theta - np.pi) <= 1e-10,
                f"θ of the half turn about {fmt(axis, 3)} ({how}) is "
                f"{theta:.12f}, off by {abs(theta - np.pi):.2g} from π (tolerance 1e-10)",
                lambda: _theta_hint(theta, R, np.pi),
            )
            error = min(np.max(np.abs(u - axis)), np.max(np.abs(u + axis)))
            expect(
                error <= 1e-10,
                f"u of the half turn about {fmt(axis, 3)} ({how}) is {fmt(u)}, off by "
                f"{error:.2g} from ± the axis (tolerance 1e-10)",
                lambda: _axis_hint(u, R, axis if u @ axis >= 0 else -axis),
            )


# ---------------------------------------------------------------- axis_from_eigen
def _eigen_hint(u, R):
    """Name the slip behind a wrong axis_from_eigen(R) = ``u`` by computing what each slip returns (up to sign)."""
    values, vectors = np.linalg.eig(R)
    k = int(np.argmin(np.abs(values - 1.0)))

    def unit(v):
        v = np.real(np.asarray(v))
        return v / np.linalg.norm(v)

    def same_line(v):
        return min(np.max(np.abs(u - v)), np.max(np.abs(u + v))) <= 1e-6

    axis = unit(vectors[:, k])
    candidates = [
        (unit(vectors[k]), hints.ROW_EIGENVECTOR_MATRIX_EIGENVECTORS_HINT),
        (
            unit(vectors[:, 0]),
            f"that is the first eigenvector, whose eigenvalue is {values[0]:.3g}, not 1: take k = argmin |λ - 1|",
        ),
        (np.linalg.svd(R)[2][-1], hints.SVD_NULL_SPACE_R_HINT),
        (
            np.linalg.eigh(R)[1][:, int(np.argmin(np.abs(np.linalg.eigh(R)[0] - 1.0)))],
            hints.NP_LINALG_EIGH_ASSUMES_HINT,
        ),
    ]
    for candidate, hint in candidates:
        if same_line(candidate) and not same_line(axis):
            return hint
    return (
        "u must be the eigenvector of the eigenvalue 1: the column vectors[:, k] of np.linalg.eig's second "
        "result, with k = argmin |λ - 1|"
    )


def _eigen_axis(student, R, what):
    value = student.axis_from_eigen(R)
    array = np.asarray(value)
    expect(not np.iscomplexobj(array), f"{what} returned a complex vector (dtype {array.dtype})", REAL_AXIS_HINT)
    u = expect_array(value, (3,), what)
    expect(
        abs(np.linalg.norm(u) - 1.0) <= 1e-9,
        f"{what}: |u| = {np.linalg.norm(u):.6g}, not 1",
        "normalise the eigenvector",
    )
    return u


@exercise("axis_from_eigen", weight=3)
def test_axis_from_eigen_random(student):
    """R u = u with u = ± the rotation axis, for 20 random rotations (θ from 0.2 to π)"""
    rng = np.random.default_rng(322)
    for axis, angle in zip(_unit_axes(20, seed=323), rng.uniform(0.2, np.pi, 20)):
        R = _exp(angle * axis)
        u = _eigen_axis(student, R, "axis_from_eigen(R)")
        moved = float(np.max(np.abs(R @ u - u)))
        expect(
            moved <= 1e-9,
            f"R u ≠ u for u = {fmt(u)} (θ = {angle:.3f}): |R u - u| is up to {moved:.2g}",
            lambda: _eigen_hint(u, R),
        )
        expect(
            abs(abs(u @ axis) - 1.0) <= 1e-9, f"u = {fmt(u)} is not ± the axis {fmt(axis)}", lambda: _eigen_hint(u, R)
        )


@exercise("axis_from_eigen", weight=1)
def test_axis_from_eigen_half_turns(student):
    """half turns, also about (1, 1, 1)/√3: the eigenvalue 1 among a double -1"""
    for axis in _special_axes()[:6]:
        R = 2.0 * np.outer(axis, axis) - np.eye(3)
        u = _eigen_axis(student, R, "axis_from_eigen(half turn)")
        expect(
            abs(abs(u @ axis) - 1.0) <= 1e-9,
            f"half turn about {fmt(axis, 3)}: got {fmt(u)}, |R u - u| = {np.max(np.abs(R @ u - u)):.2g}",
            lambda: _eigen_hint(u, R),
        )


@exercise("axis_from_eigen", weight=1)
def test_axis_from_eigen_identity(student):
    """the identity: any unit vector (every vector is fixed)"""
    u = _eigen_axis(student, np.eye(3), "axis_from_eigen(I)")
    expect(np.all(np.isfinite(u)), "axis_from_eigen(I) returned NaN")
