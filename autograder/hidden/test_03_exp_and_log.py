"""Hidden checks for lesson 03: the Lie algebra so(3), exp and log.

Independent oracles: scipy's ``Rotation`` (``from_rotvec``, ``as_rotvec``,
``as_matrix``), ``scipy.linalg.expm``, ``np.cross`` and explicit sums.
Tolerances: 1e-12 absolute for unit-size values; at tiny angles the log
must be off by at most 1e-15 + 1e-10 θ, so a dropped series term (θ²/6)
shows at θ = 1e-3. Lists are compared with the same function's answer for
arrays, so "convert with np.asarray" fires only when lists are the difference.
A complex eigenvector with zero imaginary part is accepted (hidden and public).
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

from .helpers import (Wrong, exercise, expect, expect_array, expect_close, expect_same_with_lists, fmt,
                      random_rotations, rotation_hint, rotation_problem, shape_problem)
from coursekit.diagnose import rotation_vector_hint

TOL = 1e-12
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
    axes = [DIAGONAL, -DIAGONAL, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0],
            [1.0, -1.0, 0.0], [0.6, 0.0, -0.8], [-0.48, 0.6, -0.64], [1.0, 1.0, -1.0], [-2.0, 1.0, 2.0]]
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
@exercise("hat", weight=3)
def test_hat_is_cross_product(student):
    """hat(w) @ v equals np.cross(w, v) for 20 random vectors"""
    rng = np.random.default_rng(301)
    for w, v in zip(rng.normal(size=(20, 3)), rng.normal(size=(20, 3))):
        W = expect_array(student.hat(w), (3, 3), "hat(w)")
        got, want = W @ v, np.cross(w, v)
        hint = "the signs are swapped (the transpose): [w]× v must equal w × v" if np.allclose(got, -want) else ""
        expect_close(got, want, TOL, "hat(w) @ v", hint)


@exercise("hat", weight=2)
def test_hat_layout(student):
    """has the layout [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]] and is skew-symmetric"""
    W = expect_array(student.hat([1.0, 2.0, 3.0]), (3, 3), "hat([1, 2, 3])")
    expected = np.array([[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]])
    expect_close(W, expected, 0.0, "hat([1, 2, 3])",
                 "looks like the transpose" if np.allclose(W, expected.T) else "")
    W = expect_array(student.hat([-0.5, 4.0, 1e-9]), (3, 3), "hat(w)")
    expect_close(W, -W.T, 0.0, "hat(w) + hat(w)ᵀ", "a skew-symmetric matrix has Wᵀ = -W, zeros on the diagonal")


@exercise("hat", weight=1)
def test_hat_accepts_lists_and_zero(student):
    """accepts lists and integers; hat(0) is the zero matrix"""
    expect_close(expect_array(student.hat([0, 0, 0]), (3, 3), "hat([0, 0, 0])"), np.zeros((3, 3)), 0.0,
                 "hat([0, 0, 0])")
    expect_same_with_lists(student.hat, ([1.0, 0.0, 0.0],), (3, 3), "hat([1, 0, 0])", lists=([1, 0, 0],))


# ---------------------------------------------------------------- vee
@exercise("vee", weight=3)
def test_vee_inverts_hat(student):
    """vee([w]×) = w for 20 random vectors"""
    for w in np.random.default_rng(302).normal(size=(20, 3)):
        got = expect_array(student.vee(_skew(w)), (3,), "vee(W)")
        hint = ("the negative of w: read w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0]"
                if np.allclose(got, -w) else "")
        expect_close(got, w, TOL, "vee([w]×)", hint)


@exercise("vee", weight=1)
def test_vee_is_linear(student):
    """vee(a A + b B) = a vee(A) + b vee(B)"""
    rng = np.random.default_rng(303)
    x, y = rng.normal(size=(2, 3))
    combined = expect_array(student.vee(2.5 * _skew(x) - 0.75 * _skew(y)), (3,), "vee(2.5 A - 0.75 B)")
    expect_close(combined, 2.5 * x - 0.75 * y, TOL, "vee(2.5 [x]× - 0.75 [y]×)")


@exercise("vee", weight=1)
def test_vee_accepts_lists(student):
    """accepts a nested list"""
    expect_same_with_lists(student.vee, (_skew([1.0, -2.0, 3.0]),), (3,), "vee(W)")


# ---------------------------------------------------------------- bracket
def _bracket_hint(got, A, B):
    if np.allclose(got, A @ B + B @ A):
        return "that is AB + BA: the bracket is the difference AB - BA"
    if np.allclose(got, B @ A - A @ B):
        return "the order is reversed: [A, B] = AB - BA"
    if np.allclose(got, 0.0):
        return "got zero: * multiplies entry by entry, use @"
    return ""


@exercise("bracket", weight=3)
def test_bracket_random_matrices(student):
    """[A, B] = AB - BA for random 3×3 and 4×4 matrices"""
    rng = np.random.default_rng(304)
    for n in (3, 3, 3, 4, 2):
        A, B = rng.normal(size=(2, n, n))
        got = expect_array(student.bracket(A, B), (n, n), f"bracket(A, B) for {n}×{n} matrices")
        expect_close(got, A @ B - B @ A, 1e-12, f"bracket(A, B) ({n}×{n})", _bracket_hint(got, A, B))


@exercise("bracket", weight=2)
def test_bracket_is_cross_product(student):
    """[a^, b^] = (a × b)^ for random vectors"""
    rng = np.random.default_rng(305)
    for a, b in zip(rng.normal(size=(10, 3)), rng.normal(size=(10, 3))):
        A, B = _skew(a), _skew(b)
        got = expect_array(student.bracket(A, B), (3, 3), "bracket(a^, b^)")
        expect_close(got, _skew(np.cross(a, b)), 1e-12, "bracket(a^, b^) vs (a × b)^", _bracket_hint(got, A, B))


@exercise("bracket", weight=1)
def test_bracket_alternating(student):
    """[A, A] = 0 and [A, B] = -[B, A]"""
    rng = np.random.default_rng(306)
    A, B = rng.normal(size=(2, 3, 3))
    expect_close(expect_array(student.bracket(A, A), (3, 3), "bracket(A, A)"), np.zeros((3, 3)), 1e-12,
                 "bracket(A, A)", "the bracket of a matrix with itself is AA - AA = 0")
    ab = expect_array(student.bracket(A, B), (3, 3), "bracket(A, B)")
    ba = expect_array(student.bracket(B, A), (3, 3), "bracket(B, A)")
    expect_close(ab, -ba, 1e-12, "bracket(A, B) + bracket(B, A)")


# ---------------------------------------------------------------- exp_series
def _series_hint(student_value, W, n):
    """Recognise the usual slips by comparing with neighbouring partial sums."""
    def partial(first, last):
        term, total = np.eye(W.shape[0]), np.zeros_like(W)
        for k in range(last + 1):
            if k >= first:
                total = total + term
            term = term @ W / (k + 1)
        return total
    if np.allclose(student_value, partial(1, n - 1)):
        return "the identity term is missing: the sum starts at k = 0 (W⁰ = I)"
    if np.allclose(student_value, partial(0, n)):
        return "one term too many: n_terms terms means k = 0 … n_terms - 1"
    if n >= 2 and np.allclose(student_value, partial(0, n - 2)):
        return "one term too few: n_terms terms means k = 0 … n_terms - 1"
    entrywise = sum(W ** k / np.prod(np.arange(1, k + 1)) for k in range(n))
    if np.allclose(student_value, entrywise):
        return "W ** k is an entry-wise power: use the matrix product (term = term @ W / k)"
    return ""


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
            expect_close(got, expected, 1e-12, f"exp_series(W, {n_terms})", _series_hint(got, W, n_terms))


@exercise("exp_series", weight=2)
def test_exp_series_converges(student):
    """many terms reach the exponential: rotations up to π, and general matrices (scipy's expm)"""
    for w in list(np.random.default_rng(308).normal(size=(5, 3))) + [np.pi * DIAGONAL]:
        got = expect_array(student.exp_series(_skew(w), 40), (3, 3), "exp_series([w]×, 40)")
        expect_close(got, _exp(w), 1e-12, "exp_series([w]×, 40) vs Exp(w)", _series_hint(got, _skew(w), 40))
    M = np.random.default_rng(309).normal(size=(4, 4))
    got = expect_array(student.exp_series(M, 60), (4, 4), "exp_series(M, 60) for a 4×4 matrix")
    expect_close(got, expm(M), 1e-10, "exp_series(M, 60) vs scipy.linalg.expm(M)", _series_hint(got, M, 60))


@exercise("exp_series", weight=1)
def test_exp_series_accepts_lists(student):
    """accepts a nested list"""
    W = _skew([0.1, 0.2, -0.3])
    expect_same_with_lists(lambda W: student.exp_series(W, 3), (W,), (3, 3), "exp_series(W, 3)")


# ---------------------------------------------------------------- exp_so3
def _exp_hint(got, expected, w):
    angle = np.linalg.norm(w)
    if 0.0 < angle < 1e-4:
        if np.array_equal(got, np.eye(3)):
            return ("returned exactly I for a tiny angle: R - I ≈ [w]× is the whole rotation; "
                    "use the Taylor coefficients sin θ/θ ≈ 1 - θ²/6, (1 - cos θ)/θ² ≈ 1/2 - θ²/24")
        if np.allclose((got - np.eye(3)) / angle, -(expected - np.eye(3)) / angle, atol=1e-6):
            return "looks like the inverse rotation: check the sign of the sin θ term (R = I + sin θ K + ...)"
        return ""
    hint = rotation_hint(got, expected)
    if hint and "transpose" in hint:
        return "looks like the inverse rotation: check the sign of the sin θ term (R = I + sin θ K + ...)"
    return hint or ""


@exercise("exp_so3", weight=3)
def test_exp_so3_matches_scipy(student):
    """agrees with scipy for 30 random rotation vectors, |w| up to 3π"""
    rng = np.random.default_rng(310)
    axes = _unit_axes(30, seed=311)
    for axis, angle in zip(axes, rng.uniform(0.0, 3 * np.pi, 30)):
        w = angle * axis
        got = expect_array(student.exp_so3(w), (3, 3), "exp_so3(w)")
        expected = _exp(w)
        expect_close(got, expected, TOL, f"exp_so3(w) for |w| = {angle:.3f}", _exp_hint(got, expected, w))


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
                expect(error <= 1e-15, f"{what} is off by {error:.2g} (tolerance 1e-15): (R - I)/θ = "
                       f"{fmt((got - np.eye(3)) / angle)}, expected {fmt((expected - np.eye(3)) / angle)}",
                       _exp_hint(got, expected, w))
            else:
                expect_close(got, expected, TOL, what, _exp_hint(got, expected, w))


@exercise("exp_so3", weight=1)
def test_exp_so3_group_properties(student):
    """is a rotation fixing its axis, and exp_so3(-w) is the inverse of exp_so3(w)"""
    for w in np.random.default_rng(313).normal(scale=1.5, size=(10, 3)):
        R = expect_array(student.exp_so3(w), (3, 3), "exp_so3(w)")
        problem = rotation_problem(R, 1e-12)
        expect(problem is None, f"exp_so3(w) is not a rotation: {problem}")
        expect_close(R @ w, w, TOL, "exp_so3(w) @ w (the axis must not move)")
        R_back = expect_array(student.exp_so3(-w), (3, 3), "exp_so3(-w)")
        expect_close(R_back @ R, np.eye(3), TOL, "exp_so3(-w) @ exp_so3(w)")


@exercise("exp_so3", weight=1)
def test_exp_so3_accepts_lists(student):
    """accepts lists and integer entries"""
    expect_same_with_lists(student.exp_so3, ([0.0, 0.0, 1.0],), (3, 3), "exp_so3([0, 0, 1])", lists=([0, 0, 1],))


# ---------------------------------------------------------------- log_so3
def _log(student, R, what):
    value = student.log_so3(R)
    got = np.asarray(value, dtype=float) if shape_problem(value, (3,)) == "returned NaN or inf values" else None
    if got is not None:
        raise Wrong(f"{what} returned {fmt(got)}", rotation_vector_hint(got, Rotation.from_matrix(R).as_rotvec()))
    return expect_array(value, (3,), what)


@exercise("log_so3", weight=3)
def test_log_so3_random(student):
    """agrees with scipy for 40 random rotations; exp(log(R)) = R"""
    for R in random_rotations(40, seed=314):
        got = _log(student, R, "log_so3(R)")
        expected = Rotation.from_matrix(R).as_rotvec()
        expect_close(got, expected, 1e-10, f"log_so3(R) (angle {np.linalg.norm(expected):.3f})",
                     rotation_vector_hint(got, expected))
        expect_close(_exp(got), R, 1e-10, "Exp(log_so3(R)) vs R")


@exercise("log_so3", weight=2)
def test_log_so3_small_angles(student):
    """θ = 0, 1e-12, 1e-8, 1e-5, 1e-3: off by at most 1e-15 + 1e-10 θ (a dropped θ²/6 term shows), never NaN"""
    got = _log(student, np.eye(3), "log_so3(I)")
    expect_close(got, np.zeros(3), 1e-15, "log_so3(I)", rotation_vector_hint(got, np.zeros(3)))
    for index, P in enumerate(_nearly_identities()):
        got = _log(student, P, "log_so3(R Rᵀ)")
        expect(np.linalg.norm(got) <= 1e-12,
               f"log_so3 of an identity up to rounding (trace = 3 + {np.trace(P) - 3:.1e}) returned {fmt(got)}",
               "clip (tr R - 1)/2 to [-1, 1] before arccos, or use atan2")
    for angle in (1e-12, 1e-8, 1e-5, 1e-3):
        for axis in _special_axes()[:4] + list(_unit_axes(4, seed=315)):
            w = angle * axis
            got = _log(student, _exp(w), f"log_so3(R) at θ = {angle:g}")
            expect_close(got, w, 1e-15 + 1e-10 * angle, f"log_so3(R) at θ = {angle:g} about {fmt(axis, 3)}",
                         rotation_vector_hint(got, w))


@exercise("log_so3", weight=3)
def test_log_so3_near_pi(student):
    """θ = π - 1e-6 and π - 1e-9 about generic axes: the right vector (sign included) to 1e-8"""
    for gap in (1e-3, 1e-6, 1e-9):
        for axis in _special_axes() + list(_unit_axes(6, seed=316)):
            w = (np.pi - gap) * axis
            got = _log(student, _exp(w), f"log_so3(R) at θ = π - {gap:g}")
            expect_close(got, w, 1e-8, f"log_so3(R) at θ = π - {gap:g} about {fmt(axis, 3)}",
                         rotation_vector_hint(got, w)
                         or "near π, take the axis from the symmetric part (R + Rᵀ)/2 and its sign from R - Rᵀ")


@exercise("log_so3", weight=3)
def test_log_so3_exactly_pi(student):
    """θ = π exactly, about (1, 1, 1)/√3 and other axes: ±πu to 1e-10 (not zero, not NaN)"""
    for axis in _special_axes() + list(_unit_axes(4, seed=317)):
        w = np.pi * axis
        for how, R in _half_turn_matrices(axis):
            got = _log(student, R, f"log_so3 of a half turn ({how})")
            best = w if np.linalg.norm(got - w) <= np.linalg.norm(got + w) else -w
            expect_close(got, best, 1e-10, f"log_so3 of the half turn about {fmt(axis, 3)} ({how}), "
                         "either sign accepted", rotation_vector_hint(got, w)
                         or "at θ = π take the axis from (R + I)/2: the column with the largest diagonal entry")


@exercise("log_so3", weight=2)
def test_log_so3_round_trips(student):
    """log(Exp(w)) = w for |w| < π; for π < |w| < 2π the angle folds to 2π - |w| about -u"""
    rng = np.random.default_rng(318)
    axes = _unit_axes(12, seed=319)
    for axis, angle in zip(axes[:6], rng.uniform(0.01, np.pi - 0.01, 6)):
        w = angle * axis
        got = _log(student, _exp(w), "log_so3(Exp(w))")
        expect_close(got, w, 1e-10, f"log_so3(Exp(w)) for |w| = {angle:.3f}", rotation_vector_hint(got, w))
    for axis, angle in zip(axes[6:], rng.uniform(np.pi + 0.01, 2 * np.pi - 0.01, 6)):
        w = angle * axis
        expected = -(2 * np.pi - angle) * axis
        got = _log(student, _exp(w), "log_so3(Exp(w))")
        expect_close(got, expected, 1e-10, f"log_so3(Exp(w)) for |w| = {angle:.3f} > π",
                     "the log returns the angle in [0, π]: here 2π - |w| about -u")


@exercise("log_so3", weight=1)
def test_log_so3_accepts_lists(student):
    """accepts a nested list"""
    expect_same_with_lists(student.log_so3, (_exp([0.2, -0.4, 0.1]),), (3,), "log_so3(R)")


# ---------------------------------------------------------------- axis_angle
def _axis_angle(student, R, what):
    value = student.axis_angle(R)
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Wrong(f"{what} returned {type(value).__name__}, expected a pair (u, theta)", "return u, theta")
    u = expect_array(value[0], (3,), f"{what}: u")
    theta = float(expect_array(value[1], (), f"{what}: theta"))
    expect(abs(np.linalg.norm(u) - 1.0) <= 1e-12, f"{what}: |u| = {np.linalg.norm(u):.6g}, not 1",
           "at θ = 0 return the unit axis [1, 0, 0]; otherwise normalise")
    expect(-1e-15 <= theta <= np.pi + 1e-12, f"{what}: θ = {theta:.6g} is outside [0, π]",
           "θ = 57.3 × the right value means degrees" if theta > np.pi else "")
    return u, theta


@exercise("axis_angle", weight=3)
def test_axis_angle_random(student):
    """unit u and θ in [0, π] that rebuild 30 random rotations; they agree with scipy"""
    for R in random_rotations(30, seed=320):
        u, theta = _axis_angle(student, R, "axis_angle(R)")
        expected = Rotation.from_matrix(R).as_rotvec()
        expect_close(theta, np.linalg.norm(expected), 1e-10, "θ", "θ = arctan2(sin θ, cos θ), in radians"
                     if not np.isclose(theta, np.rad2deg(np.linalg.norm(expected))) else "θ looks like degrees")
        expect_close(theta * u, expected, 1e-10, "θ u vs scipy's rotation vector", rotation_vector_hint(theta * u, expected))


@exercise("axis_angle", weight=1)
def test_axis_angle_identity(student):
    """θ = 0 for the identity and for identities up to rounding (trace just above 3), with a unit axis"""
    for index, P in enumerate([np.eye(3)] + _nearly_identities()):
        u, theta = _axis_angle(student, P, f"axis_angle(identity #{index})")
        expect(theta <= 1e-12, f"axis_angle of an identity (#{index}) gave θ = {theta:.3g}")


@exercise("axis_angle", weight=1)
def test_axis_angle_small(student):
    """tiny angles (1e-8, 1e-5): θ to relative 1e-6 and the right axis"""
    for angle in (1e-8, 1e-5):
        for axis in _unit_axes(5, seed=321):
            u, theta = _axis_angle(student, _exp(angle * axis), f"axis_angle at θ = {angle:g}")
            hint = ("θ looks like degrees: the course works in radians" if np.isclose(theta, np.rad2deg(angle))
                    else "arccos loses tiny angles: use atan2(|R - Rᵀ|/2, (tr R - 1)/2)")
            expect_close(theta / angle, 1.0, 1e-6, f"θ / θ_true at θ = {angle:g}", hint)
            expect_close(u, axis, 1e-6, f"u at θ = {angle:g}", "u = vee(R - Rᵀ)/(2 sin θ) points along +axis")


@exercise("axis_angle", weight=2)
def test_axis_angle_near_and_at_pi(student):
    """π - 1e-9: the right axis with its sign; exactly π: ±u, also about (1, 1, 1)/√3"""
    for axis in _special_axes():
        u, theta = _axis_angle(student, _exp((np.pi - 1e-9) * axis), "axis_angle at θ = π - 1e-9")
        expect_close(theta * u, (np.pi - 1e-9) * axis, 1e-8, f"θ u at θ = π - 1e-9 about {fmt(axis, 3)}",
                     rotation_vector_hint(theta * u, (np.pi - 1e-9) * axis))
        for how, R in _half_turn_matrices(axis):
            u, theta = _axis_angle(student, R, f"axis_angle of a half turn ({how})")
            expect(abs(theta - np.pi) <= 1e-10, f"θ of the half turn about {fmt(axis, 3)} ({how}) is "
                   f"{theta:.12f}, off by {abs(theta - np.pi):.2g} from π (tolerance 1e-10)",
                   "arccos is inaccurate next to ±1: use θ = atan2(sin θ, cos θ)")
            expect(min(np.max(np.abs(u - axis)), np.max(np.abs(u + axis))) <= 1e-10,
                   f"u of the half turn about {fmt(axis, 3)} ({how}) is {fmt(u)}, expected ± the axis",
                   "at θ = π take the axis from (R + I)/2: the column with the largest diagonal entry")


# ---------------------------------------------------------------- axis_from_eigen
def _eigen_axis(student, R, what):
    value = student.axis_from_eigen(R)
    array = np.asarray(value)
    if np.iscomplexobj(array):
        expect(np.max(np.abs(array.imag)) <= 1e-12, f"{what} returned a complex vector with imaginary part "
               f"{fmt(np.abs(array.imag))}", "take np.real(...) of the eigenvector for the eigenvalue 1")
        value = array.real
    u = expect_array(value, (3,), what)
    expect(abs(np.linalg.norm(u) - 1.0) <= 1e-9, f"{what}: |u| = {np.linalg.norm(u):.6g}, not 1",
           "normalise the eigenvector")
    return u


@exercise("axis_from_eigen", weight=3)
def test_axis_from_eigen_random(student):
    """R u = u with u = ± the rotation axis, for 20 random rotations (θ from 0.2 to π)"""
    rng = np.random.default_rng(322)
    for axis, angle in zip(_unit_axes(20, seed=323), rng.uniform(0.2, np.pi, 20)):
        R = _exp(angle * axis)
        u = _eigen_axis(student, R, "axis_from_eigen(R)")
        hint = "eigenvectors are the columns of np.linalg.eig's second result: vectors[:, k]"
        expect(np.max(np.abs(R @ u - u)) <= 1e-9, f"R u ≠ u for u = {fmt(u)} (θ = {angle:.3f})",
               hint + ", with k the index of the eigenvalue closest to 1")
        expect(abs(abs(u @ axis) - 1.0) <= 1e-9, f"u = {fmt(u)} is not ± the axis {fmt(axis)}", hint)


@exercise("axis_from_eigen", weight=1)
def test_axis_from_eigen_half_turns(student):
    """half turns, also about (1, 1, 1)/√3: the eigenvalue 1 among a double -1"""
    for axis in _special_axes()[:6]:
        u = _eigen_axis(student, 2.0 * np.outer(axis, axis) - np.eye(3), "axis_from_eigen(half turn)")
        expect(abs(abs(u @ axis) - 1.0) <= 1e-9, f"half turn about {fmt(axis, 3)}: got {fmt(u)}",
               "pick the eigenvalue closest to 1, not the first one")


@exercise("axis_from_eigen", weight=1)
def test_axis_from_eigen_identity(student):
    """the identity: any unit vector (every vector is fixed)"""
    u = _eigen_axis(student, np.eye(3), "axis_from_eigen(I)")
    expect(np.all(np.isfinite(u)), "axis_from_eigen(I) returned NaN")
