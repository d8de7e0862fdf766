"""Hidden checks for lesson 06: perturbations and Jacobians.

Independent oracles: scipy's ``Rotation`` for Exp and Log, analytic Jacobians
written out in this file, finite differences taken here, first-order
(manif-style) expansions f(X ⊞ d) ≈ f(X) + J d whose remainder must be of
order |d|², and the reference solutions.

numerical_jacobian: any forward or central scheme at least as accurate as the
lecture's rule earns full marks. The rule (``coursekit.diagnose.
jacobian_error_allowed``, shared with the public checks): max |J - J_exact| <=
2 · max |J_lecture - J_exact| + 1e-8 · (1 + max |J_exact|), where J_lecture
uses forward steps δ_j = max(|1e-4 x_j|, 1e-6). On manifolds: 5e-6 (1 + |p|).
Tiny angles: Jr and Jr⁻¹ at 1e-9 … 1e-3 rad must be off by at most
1e-6 θ + 1e-15, so a missing [w]× or [w]×² series term shows. Callable arguments travel as
``Probe``s. Every test calls the student's function of its own exercise only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from autograder.sandbox.child import probes

from coursekit.diagnose import JACOBIAN_STEP_HINT, jacobian_error_allowed

from .helpers import (Probe, Wrong, exercise, expect, expect_array, expect_close, expect_same_with_lists, fmt,
                      random_rotations, rotation_problem, shape_problem)

TOL = 1e-10


# ---------------------------------------------------------------- oracles written out here
def _skew(v):
    """[v]×, built column by column: its column j is v × e_j."""
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(np.asarray(R, dtype=float)).as_rotvec()


def _qmul(p, q):
    return probes.quat_multiply(p, q)


def _exp_q(d):
    d = np.asarray(d, dtype=float)
    angle = np.linalg.norm(d)
    if angle < 1e-12:
        return np.concatenate([[1.0], d / 2.0])
    return np.concatenate([[np.cos(angle / 2.0)], np.sin(angle / 2.0) * d / angle])


def _quat_matrix(q):
    return Rotation.from_quat(np.asarray(q, dtype=float), scalar_first=True).as_matrix()


def _unit(seed, count):
    v = np.random.default_rng(seed).normal(size=(count, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _rotvecs(count, seed, low, high):
    """``count`` rotation vectors with random axes and angles uniform in [low, high]."""
    angles = np.random.default_rng(seed + 1).uniform(low, high, count)
    return _unit(seed, count) * angles[:, None]


def _same_quat(a, b, tol):
    return np.max(np.abs(a - b)) <= tol or np.max(np.abs(a + b)) <= tol


# ---------------------------------------------------------------- boxplus_right
def _boxplus_hint(got, R, d, right):
    other = _exp(d) @ R if right else R @ _exp(d)
    if np.allclose(got, other, atol=1e-8):
        return ("that is the left perturbation Exp(δ) R; boxplus_right is R @ Exp(δ)" if right else
                "that is the right perturbation R Exp(δ); boxplus_left is Exp(δ) @ R")
    first_order = R @ (np.eye(3) + _skew(d)) if right else (np.eye(3) + _skew(d)) @ R
    if np.allclose(got, first_order, atol=1e-8):
        return "I + [δ]× is only the first-order approximation and not a rotation: use Exp(δ)"
    if np.allclose(got, R @ _exp(-np.asarray(d)) if right else _exp(-np.asarray(d)) @ R, atol=1e-8):
        return "turned by -δ: check the sign (Exp(δ), not Exp(δ)ᵀ)"
    return ""


def _boxplus_cases(seed):
    Rs = random_rotations(14, seed=seed)
    ds = list(_rotvecs(10, seed + 10, 0.0, 3.0)) + [np.zeros(3), 1e-9 * _unit(seed + 20, 1)[0],
                                                      np.pi * _unit(seed + 21, 1)[0], 5.0 * _unit(seed + 22, 1)[0]]
    return list(zip(Rs, ds))


@exercise("boxplus_right", weight=3)
def test_boxplus_right_matches_definition(student):
    """equals R @ Exp(δ) for random rotations, δ = 0, tiny δ, |δ| = π and |δ| > π"""
    for R, d in _boxplus_cases(601):
        got = expect_array(student.boxplus_right(R, d), (3, 3), f"boxplus_right(R, {fmt(d)})")
        expect_close(got, R @ _exp(d), TOL, f"boxplus_right(R, {fmt(d)})", _boxplus_hint(got, R, d, right=True))


@exercise("boxplus_right", weight=1)
def test_boxplus_right_stays_rotation(student):
    """always returns a rotation matrix, even for large δ"""
    for R, d in zip(random_rotations(8, seed=602), _rotvecs(8, 603, 0.5, 6.0)):
        got = expect_array(student.boxplus_right(R, d), (3, 3), "boxplus_right(R, δ)")
        problem = rotation_problem(got, tol=1e-9)
        expect(problem is None, f"boxplus_right(R, {fmt(d)}) is not a rotation: {problem}",
               "R (I + [δ]×) is not a rotation: use R @ Exp(δ)")


@exercise("boxplus_right", weight=1)
def test_boxplus_right_turns_about_body_axes(student):
    """turns about the body's own axes (R ⊞ a e_k keeps R e_k) and accepts lists"""
    R = random_rotations(1, seed=604)[0]
    for k in range(3):
        d = 0.7 * np.eye(3)[k]
        got = expect_array(student.boxplus_right(R.tolist(), d.tolist()), (3, 3), "boxplus_right with lists")
        expect_close(got[:, k], R[:, k], TOL, f"body axis {k} after turning about it",
                     "the right perturbation turns about the body's axes: R @ Exp(δ)")


# ---------------------------------------------------------------- boxplus_left
@exercise("boxplus_left", weight=3)
def test_boxplus_left_matches_definition(student):
    """equals Exp(δ) @ R for random rotations, δ = 0, tiny δ, |δ| = π and |δ| > π"""
    for R, d in _boxplus_cases(611):
        got = expect_array(student.boxplus_left(R, d), (3, 3), f"boxplus_left(R, {fmt(d)})")
        expect_close(got, _exp(d) @ R, TOL, f"boxplus_left(R, {fmt(d)})", _boxplus_hint(got, R, d, right=False))


@exercise("boxplus_left", weight=1)
def test_boxplus_left_stays_rotation(student):
    """always returns a rotation matrix, even for large δ"""
    for R, d in zip(random_rotations(8, seed=612), _rotvecs(8, 613, 0.5, 6.0)):
        got = expect_array(student.boxplus_left(R, d), (3, 3), "boxplus_left(R, δ)")
        problem = rotation_problem(got, tol=1e-9)
        expect(problem is None, f"boxplus_left(R, {fmt(d)}) is not a rotation: {problem}",
               "use Exp(δ) @ R, which is always a rotation")


@exercise("boxplus_left", weight=1)
def test_boxplus_left_turns_about_world_axes(student):
    """turns about the world axes (rows: e_kᵀ (Exp(a e_k) R) = e_kᵀ R) and accepts lists"""
    R = random_rotations(1, seed=614)[0]
    for k in range(3):
        d = 0.7 * np.eye(3)[k]
        got = expect_array(student.boxplus_left(R.tolist(), d.tolist()), (3, 3), "boxplus_left with lists")
        expect_close(got[k, :], R[k, :], TOL, f"row {k} after turning about world axis {k}",
                     "the left perturbation turns about the world's axes: Exp(δ) @ R")


# ---------------------------------------------------------------- boxminus
def _boxminus_hint(got, R_a, R_b):
    expected = _log(R_b.T @ R_a)
    if np.allclose(got, -expected, atol=1e-8):
        return "got the step back: arguments swapped? boxminus(R_a, R_b) = Log(R_bᵀ R_a)"
    if np.allclose(_exp(got), R_a @ R_b.T, atol=1e-8):
        return "that is the left difference Log(R_a R_bᵀ); the right one is Log(R_bᵀ R_a)"
    return ""


@exercise("boxminus", weight=3)
def test_boxminus_matches_log(student):
    """equals Log(R_bᵀ R_a) for 15 random pairs (relative angle below π)"""
    R_bs = random_rotations(15, seed=621)
    steps = _rotvecs(15, 622, 0.0, np.pi - 0.05)
    for R_b, step in zip(R_bs, steps):
        R_a = R_b @ _exp(step)
        got = expect_array(student.boxminus(R_a, R_b), (3,), "boxminus(R_a, R_b)")
        expect_close(got, step, 1e-9, "boxminus(R_a, R_b)", _boxminus_hint(got, R_a, R_b))


@exercise("boxminus", weight=2)
def test_boxminus_round_trip(student):
    """R_b Exp(R_a ⊟ R_b) = R_a with |R_a ⊟ R_b| ≤ π, also at and near a half turn"""
    R_bs = random_rotations(9, seed=623)
    axes = _unit(624, 9)
    angles = [0.3, 1.0, 2.0, 3.0, np.pi - 1e-7, np.pi, np.pi, 2 * np.pi - 0.5, 0.0]
    for R_b, axis, angle in zip(R_bs, axes, angles):
        R_a = R_b @ _exp(angle * axis)
        got = expect_array(student.boxminus(R_a, R_b), (3,), "boxminus(R_a, R_b)")
        expect_close(R_b @ _exp(got), R_a, 1e-8, f"R_b @ Exp(boxminus(R_a, R_b)) for a relative angle of {angle:.4f}",
                     _boxminus_hint(got, R_a, R_b))
        expect(np.linalg.norm(got) <= np.pi + 1e-9, f"|boxminus| = {np.linalg.norm(got):.4f} exceeds π",
               "Log returns the shortest rotation vector, angle in [0, π]")


@exercise("boxminus", weight=1)
def test_boxminus_inverts_boxplus(student):
    """(R ⊞ δ) ⊟ R = δ for |δ| < π, tiny δ and δ = 0"""
    R = random_rotations(1, seed=625)[0]
    deltas = list(_rotvecs(5, 626, 0.1, 3.0)) + [1e-9 * _unit(627, 1)[0], np.zeros(3)]
    for d in deltas:
        got = expect_array(student.boxminus(R @ _exp(d), R), (3,), "boxminus(R ⊞ δ, R)")
        expect_close(got, d, 1e-9, f"boxminus(R Exp(δ), R) for δ = {fmt(d)}", _boxminus_hint(got, R @ _exp(d), R))


# ---------------------------------------------------------------- quat_boxplus
def _random_quats(count, seed):
    return Rotation.random(count, random_state=seed).as_quat(scalar_first=True)


def _quat_hint(got, q, d):
    length = np.linalg.norm(got)
    if abs(length - 1.0) > 1e-9:
        return f"|result| = {length:.6f}: q ⊗ [1, δ/2] is not a unit quaternion; use the exact Exp_q(δ) or normalise"
    if _same_quat(got, _qmul(q, _exp_q(2.0 * np.asarray(d))), 1e-8):
        return "turned twice as far: a quaternion holds the half angle, cos(|δ|/2) and sin(|δ|/2)"
    if _same_quat(got, _qmul(_exp_q(d), q), 1e-8):
        return "that is Exp_q(δ) ⊗ q, the left perturbation; multiply on the right: q ⊗ Exp_q(δ)"
    if _same_quat(got[[3, 0, 1, 2]], _qmul(q, _exp_q(d)), 1e-8):
        return "scalar last? The course stores quaternions scalar first, [w, x, y, z]"
    return ""


@exercise("quat_boxplus", weight=3)
def test_quat_boxplus_matches_definition(student):
    """equals q ⊗ Exp_q(δ) (up to sign) for random unit quaternions and δ up to 3 rad"""
    for q, d in zip(_random_quats(15, 631), _rotvecs(15, 632, 0.05, 3.0)):
        got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ)")
        expected = _qmul(q, _exp_q(d))
        if not _same_quat(got, expected, TOL):
            expect_close(got, expected if np.dot(got, expected) >= 0 else -expected, TOL,
                         f"quat_boxplus(q, {fmt(d)})", _quat_hint(got, q, d))


@exercise("quat_boxplus", weight=1)
def test_quat_boxplus_unit_norm(student):
    """returns a unit quaternion, also for large δ"""
    for q, d in zip(_random_quats(8, 633), _rotvecs(8, 634, 1.0, 6.0)):
        got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ)")
        norm = np.linalg.norm(got)
        expect(abs(norm - 1.0) <= 1e-12, f"|quat_boxplus(q, {fmt(d)})| = {norm:.9f}",
               "q ⊗ [1, δ/2] has norm √(1 + |δ|²/4): use the exact Exp_q(δ) or normalise")


@exercise("quat_boxplus", weight=1)
def test_quat_boxplus_agrees_with_matrices(student):
    """R(q ⊞ δ) = R(q) Exp(δ): the same right perturbation as for matrices"""
    for q, d in zip(_random_quats(8, 635), _rotvecs(8, 636, 0.1, 3.0)):
        got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ)")
        expect(abs(np.linalg.norm(got) - 1.0) <= 1e-9, f"|quat_boxplus(q, δ)| = {np.linalg.norm(got):.6f}",
               "return a unit quaternion")
        expect_close(_quat_matrix(got), _quat_matrix(q) @ _exp(d), 1e-9, "R(quat_boxplus(q, δ))",
                     _quat_hint(got, q, d))


@exercise("quat_boxplus", weight=1)
def test_quat_boxplus_tiny_and_zero(student):
    """δ = 0 returns q and a tiny δ (1e-9 rad) is exact, with no NaN"""
    q = _random_quats(1, 637)[0]
    got = expect_array(student.quat_boxplus(q, np.zeros(3)), (4,), "quat_boxplus(q, 0)")
    expect(_same_quat(got, q, 1e-14), f"quat_boxplus(q, 0) = {fmt(got)}, expected q = {fmt(q)}",
           "δ/|δ| is 0/0 at δ = 0: use [1, δ/2] below a tiny angle")
    d = 1e-9 * _unit(638, 1)[0]
    got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ) for |δ| = 1e-9")
    expected = _qmul(q, _exp_q(d))
    expect(_same_quat(got, expected, 1e-15), f"quat_boxplus(q, δ) for |δ| = 1e-9 is off: got {fmt(got, 12)}",
           "below a tiny angle, Exp_q(δ) = [1, δ/2] to machine precision")


# ---------------------------------------------------------------- numerical_jacobian
SMOOTH_POINTS = [np.array([0.7, -1.3, 2.1]), np.array([2.0, -1.5, 0.0]), np.array([1.5, 2.5, -3.0]),
                 np.array([-0.4, 0.9, 0.3])]


def _matrix_entries_hint(value):
    if np.shape(value) in ((3, 9), (3, 4)):
        return ("one column per stored number: with a boxplus, differentiate with respect to the 3-vector δ "
                "in boxplus(x, δ), not the entries of x")
    return ""


@exercise("numerical_jacobian", weight=2)
def test_numerical_jacobian_vector_function(student):
    """approximates the analytic Jacobian of a smooth R³ → R² function (shape 2×3)"""
    for x in SMOOTH_POINTS:
        value = student.numerical_jacobian(Probe("smooth_vector_function"), x)
        expect(np.shape(value) != (3, 2), "returned shape 3×2 for f: R³ → R²: the Jacobian is transposed",
               "row i is output f_i, column j is input x_j: shape (len(f(x)), n)")
        got = expect_array(value, (2, 3), f"numerical_jacobian(f, {fmt(x)})")
        expected = probes.smooth_vector_function_jacobian(x)
        expect_close(got, expected, 2e-3 * (1.0 + np.max(np.abs(expected))), f"numerical_jacobian(f, {fmt(x)})")


def _expect_accurate_jacobian(got, x, what, ref):
    """The course's rule: at most twice the error of the lecture's forward steps (+ 1e-8 for rounding).
    The reference solution is the lecture's rule, so it measures the lecture's error here."""
    exact = probes.smooth_vector_function_jacobian(x)
    lecture_error = np.max(np.abs(np.asarray(ref.numerical_jacobian(probes.smooth_vector_function, x)) - exact))
    allowed = jacobian_error_allowed(lecture_error, exact)
    error = float(np.max(np.abs(got - exact)))
    expect(error <= allowed, f"{what} is off by {error:.2g} from the analytic Jacobian; the lecture's forward "
           f"steps are off by {(allowed - 1e-8 * (1 + np.max(np.abs(exact)))) / 2:.2g} (allowed: {allowed:.2g})",
           JACOBIAN_STEP_HINT)


@exercise("numerical_jacobian", weight=2)
def test_numerical_jacobian_step_rule(student, ref):
    """at least as accurate as forward differences with the lecture's steps δ_j = max(|1e-4 x_j|, 1e-6)"""
    for x in SMOOTH_POINTS:
        got = expect_array(student.numerical_jacobian(Probe("smooth_vector_function"), x), (2, 3),
                           f"numerical_jacobian(f, {fmt(x)})")
        _expect_accurate_jacobian(got, x, f"numerical_jacobian(f, {fmt(x)})", ref)


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_at_zero(student, ref):
    """works at x = 0 (no 0/0: the lecture's step has the floor 1e-6), as accurately as the lecture's rule"""
    x = np.zeros(3)
    got = expect_array(student.numerical_jacobian(Probe("smooth_vector_function"), x), (2, 3),
                       "numerical_jacobian(f, 0)")
    _expect_accurate_jacobian(got, x, "numerical_jacobian(f, 0)", ref)


def _rotation_cases(seed, count=6):
    Rs = random_rotations(count, seed=seed)
    ps = np.random.default_rng(seed + 1).normal(size=(count, 3)) * 1.5
    return list(zip(Rs, ps))


def _manifold_tol(p):
    return 5e-6 * (1.0 + np.linalg.norm(p))


@exercise("numerical_jacobian", weight=2)
def test_numerical_jacobian_rotation_right(student):
    """with a right boxplus, the Jacobian of R ↦ R p is -R [p]× (3 columns, one per δ_j)"""
    for R, p in _rotation_cases(641):
        value = student.numerical_jacobian(Probe("rotate_point_by", p), R, Probe("so3_plus_right"))
        expect(not _matrix_entries_hint(value), f"returned shape {np.shape(value)} for a rotation",
               _matrix_entries_hint(value))
        got = expect_array(value, (3, 3), "numerical_jacobian(R ↦ R p, R, so3_plus_right)")
        hint = "looks like the left-perturbation Jacobian: use the boxplus you are given" \
            if np.allclose(got, -_skew(R @ p), atol=1e-4) else "column j: (f(boxplus(x, h e_j)) - f(x)) / h"
        expect_close(got, -R @ _skew(p), _manifold_tol(p), "numerical_jacobian(R ↦ R p, R, right ⊞)", hint)


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_rotation_left(student):
    """with a left boxplus, the Jacobian of R ↦ R p is -[R p]×"""
    for R, p in _rotation_cases(643, count=4):
        value = student.numerical_jacobian(Probe("rotate_point_by", p), R, Probe("so3_plus_left"))
        expect(not _matrix_entries_hint(value), f"returned shape {np.shape(value)} for a rotation",
               _matrix_entries_hint(value))
        got = expect_array(value, (3, 3), "numerical_jacobian(R ↦ R p, R, so3_plus_left)")
        expect_close(got, -_skew(R @ p), _manifold_tol(p), "numerical_jacobian(R ↦ R p, R, left ⊞)",
                     "perturb through the boxplus you are given: boxplus(x, h e_j)")


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_unrotate(student):
    """with a right boxplus, the Jacobian of R ↦ Rᵀ p is [Rᵀ p]×"""
    for R, p in _rotation_cases(645, count=4):
        value = student.numerical_jacobian(Probe("unrotate_point_by", p), R, Probe("so3_plus_right"))
        expect(not _matrix_entries_hint(value), f"returned shape {np.shape(value)} for a rotation",
               _matrix_entries_hint(value))
        got = expect_array(value, (3, 3), "numerical_jacobian(R ↦ Rᵀ p, R, so3_plus_right)")
        expect_close(got, _skew(R.T @ p), _manifold_tol(p), "numerical_jacobian(R ↦ Rᵀ p, R, right ⊞)",
                     "column j: (f(boxplus(x, h e_j)) - f(x)) / h, forward differences with h = 1e-6")


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_quaternion(student):
    """with a quaternion x (4 numbers) and its boxplus, the Jacobian still has 3 columns: -R(q) [p]×"""
    quats = _random_quats(4, 647)
    ps = np.random.default_rng(648).normal(size=(4, 3))
    for q, p in zip(quats, ps):
        value = student.numerical_jacobian(Probe("quat_rotate_point_by", p), q, Probe("quat_plus_right"))
        expect(not _matrix_entries_hint(value), f"returned shape {np.shape(value)} for a quaternion",
               _matrix_entries_hint(value))
        got = expect_array(value, (3, 3), "numerical_jacobian(q ↦ R(q) p, q, quat_plus_right)")
        expect_close(got, -_quat_matrix(q) @ _skew(p), _manifold_tol(p), "numerical_jacobian(q ↦ R(q) p, q, ⊞)",
                     "column j: (f(boxplus(x, h e_j)) - f(x)) / h, forward differences with h = 1e-6")


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_shapes(student):
    """returns shape (len(f(x)), n): 5×5 for the identity on R⁵, 3×3 for a rotation"""
    x = np.array([3.0, -0.2, 0.0, 1e-3, 40.0])
    got = expect_array(student.numerical_jacobian(Probe("identity_function"), x), (5, 5),
                       "numerical_jacobian(identity, x in R⁵)")
    expect_close(got, np.eye(5), 1e-6, "numerical_jacobian of the identity map")
    R = random_rotations(1, seed=649)[0]
    value = student.numerical_jacobian(Probe("rotate_point_by", [1.0, 2.0, 3.0]), R, Probe("so3_plus_right"))
    expect(np.shape(value) == (3, 3), f"returned shape {np.shape(value)} for f: SO(3) → R³, expected (3, 3)",
           _matrix_entries_hint(value))


# ---------------------------------------------------------------- jacobian_rotate_point
def _rotate_point_hint(got, R, p):
    if np.allclose(got, -_skew(R @ p), atol=1e-8):
        return "that is -[R p]×, the Jacobian of the left perturbation; the right one is -R [p]×"
    if np.allclose(got, R @ _skew(p), atol=1e-8):
        return "the sign is flipped: [δ]× p = -[p]× δ, so the Jacobian is -R [p]×"
    if np.allclose(got, -_skew(p) @ R, atol=1e-8):
        return "the factors are in the wrong order: -R [p]×, not -[p]× R"
    if np.allclose(got, -_skew(p), atol=1e-8):
        return "R is missing: the Jacobian is -R [p]×"
    if np.allclose(got, (-R @ _skew(p)).T, atol=1e-8):
        return "that is the transpose of -R [p]×: row i is output i, column j is δ_j"
    return ""


@exercise("jacobian_rotate_point", weight=3)
def test_jacobian_rotate_point_formula(student):
    """equals d(R Exp(δ) p)/dδ = -R [p]× for 20 random rotations and points"""
    for R, p in _rotation_cases(651, count=20):
        got = expect_array(student.jacobian_rotate_point(R, p), (3, 3), "jacobian_rotate_point(R, p)")
        expect_close(got, -R @ _skew(p), TOL, "jacobian_rotate_point(R, p)", _rotate_point_hint(got, R, p))


@exercise("jacobian_rotate_point", weight=2)
def test_jacobian_rotate_point_linearises(student):
    """R Exp(δ) p ≈ R p + J δ with a remainder of order |δ|² (|δ| = 1e-3 and 1e-4)"""
    directions = _unit(653, 6)
    for (R, p), direction in zip(_rotation_cases(652), directions):
        J = expect_array(student.jacobian_rotate_point(R, p), (3, 3), "jacobian_rotate_point(R, p)")
        for scale in (1e-3, 1e-4):
            step = scale * direction
            remainder = np.linalg.norm(R @ _exp(step) @ p - R @ p - J @ step)
            expect(remainder <= np.linalg.norm(p) * scale**2 + 1e-13,
                   f"R Exp(δ) p - R p - J δ = {remainder:.2g} for |δ| = {scale:g}: not of order |δ|²",
                   _rotate_point_hint(J, R, p))


@exercise("jacobian_rotate_point", weight=1)
def test_jacobian_rotate_point_matches_finite_differences(student):
    """agrees with central differences of δ ↦ R Exp(δ) p taken by the grader"""
    for R, p in _rotation_cases(654, count=4):
        got = expect_array(student.jacobian_rotate_point(R, p), (3, 3), "jacobian_rotate_point(R, p)")
        h = 1e-6
        numeric = np.column_stack([(R @ _exp(h * e) @ p - R @ _exp(-h * e) @ p) / (2 * h) for e in np.eye(3)])
        expect_close(got, numeric, 1e-8 * (1.0 + np.linalg.norm(p)), "jacobian_rotate_point vs finite differences",
                     _rotate_point_hint(got, R, p))


@exercise("jacobian_rotate_point", weight=1)
def test_jacobian_rotate_point_edge_cases(student):
    """is zero for p = 0 and accepts lists"""
    R = random_rotations(1, seed=655)[0]
    got = expect_array(student.jacobian_rotate_point(R, np.zeros(3)), (3, 3), "jacobian_rotate_point(R, 0)")
    expect_close(got, np.zeros((3, 3)), TOL, "jacobian_rotate_point(R, 0)", "the origin does not move when R turns")
    expect_same_with_lists(student.jacobian_rotate_point, (R, [1.0, -2.0, 0.5]), (3, 3), "jacobian_rotate_point(R, p)")


# ---------------------------------------------------------------- right_jacobian_so3
def _jr_series(w):
    W = _skew(w)
    return np.eye(3) - W / 2.0 + W @ W / 6.0


def _expect_identity_at_zero(value, what, hint):
    problem = shape_problem(value, (3, 3))
    if problem:
        raise Wrong(f"{what} {problem}", hint)
    expect_close(value, np.eye(3), 1e-15, what, hint)


def _expect_tiny_angle(got, w, expected, what, hint, sign):
    """Compare at a tiny angle; on failure, report the coefficient of the [w]× term."""
    angle = np.linalg.norm(w)
    error = float(np.max(np.abs(got - expected)))
    if error <= 1e-6 * angle + 1e-15:
        return
    anti = 0.5 * (got - got.T)
    coefficient = np.dot([anti[2, 1], anti[0, 2], anti[1, 0]], w) / angle**2 + 0.0
    raise Wrong(f"{what}: the coefficient of [w]× came out as {coefficient:.9g}, expected {sign * 0.5:g} "
                f"(max error {error:.2g}, tolerance {1e-6 * angle + 1e-15:.2g})", hint)


def _jacobian_side_hint(got, w, dw):
    """Name the left Jacobian when J works as Exp(J dw) Exp(w) instead of Exp(w) Exp(J dw)."""
    left = np.linalg.norm(_log((_exp(got @ dw) @ _exp(w)).T @ _exp(w + dw)))
    if left <= 2.0 * np.dot(dw, dw) + 1e-13:
        return "this J works on the left, Exp(J dw) Exp(w): it is the left Jacobian Jl = Jr(-w); flip the sign of the [w]× term"
    return ""


@exercise("right_jacobian_so3", weight=2)
def test_right_jacobian_matches_reference(student, ref):
    """matches Jr(w) for 20 random w with angles from 1e-3 to π"""
    for w in _rotvecs(20, 661, 1e-3, np.pi):
        got = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        hint = ("that is Jr(w)ᵀ = Jl(w), the left Jacobian: the [w]× term has the wrong sign"
                if np.allclose(got, ref.right_jacobian_so3(w).T, atol=1e-8) else "")
        expect_close(got, ref.right_jacobian_so3(w), 1e-9, f"right_jacobian_so3 at angle {np.linalg.norm(w):.4f}", hint)


@exercise("right_jacobian_so3", weight=2)
def test_right_jacobian_linearises(student):
    """Exp(w + dw) ≈ Exp(w) Exp(Jr(w) dw) with an error of order |dw|² (angles up to π)"""
    ws = list(_rotvecs(10, 662, 0.3, np.pi)) + [(np.pi - 1e-6) * _unit(663, 1)[0], np.pi * _unit(664, 1)[0]]
    directions = _unit(665, len(ws))
    for w, direction in zip(ws, directions):
        J = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        dw = 1e-4 * direction
        leftover = np.linalg.norm(_log((_exp(w) @ _exp(J @ dw)).T @ _exp(w + dw)))
        expect(leftover <= np.dot(dw, dw) + 1e-13,
               f"at angle {np.linalg.norm(w):.4f}, Exp(w) Exp(J dw) misses Exp(w + dw) by {leftover:.2g} rad "
               f"for |dw| = 1e-4 (expected below 1e-8)", _jacobian_side_hint(J, w, dw))


@exercise("right_jacobian_so3", weight=1)
def test_right_jacobian_matches_finite_differences(student):
    """agrees with central differences of dw ↦ Log(Exp(w)ᵀ Exp(w + dw)) taken by the grader"""
    for w in _rotvecs(4, 666, 0.2, 3.0):
        got = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        h = 1e-6
        R_inv = _exp(w).T
        numeric = np.column_stack([(_log(R_inv @ _exp(w + h * e)) - _log(R_inv @ _exp(w - h * e))) / (2 * h)
                                   for e in np.eye(3)])
        expect_close(got, numeric, 1e-8, f"right_jacobian_so3 vs finite differences at angle {np.linalg.norm(w):.3f}")


@exercise("right_jacobian_so3", weight=2)
def test_right_jacobian_tiny_angles(student):
    """w = 0 gives I (no NaN); at 1e-12, 1e-9, 1e-8, 1e-7 rad the [w]× term is accurate to 6 digits"""
    _expect_identity_at_zero(student.right_jacobian_so3(np.zeros(3)), "right_jacobian_so3(0)",
                             "the closed form is 0/0 at θ = 0: use the Taylor series below a small angle")
    axes = _unit(667, 4)
    for angle, axis in zip([1e-12, 1e-9, 1e-8, 1e-7], axes):
        w = angle * axis
        got = expect_array(student.right_jacobian_so3(w), (3, 3), f"right_jacobian_so3 at angle {angle:g}")
        _expect_tiny_angle(got, w, _jr_series(w), f"right_jacobian_so3 at angle {angle:g}",
                           "(1 - cos θ)/θ² loses its digits at tiny angles: use the Taylor series "
                           "1/2 - θ²/24 + … below a threshold (and mind the sign: Jr = I - a [w]× + …)", sign=-1.0)


@exercise("right_jacobian_so3", weight=1)
def test_right_jacobian_near_pi(student, ref):
    """stays finite and accurate at and near a half turn (θ = π, π - 1e-6, π - 1e-9)"""
    for offset, axis in zip([0.0, 1e-6, 1e-9], _unit(668, 3)):
        w = (np.pi - offset) * axis
        got = expect_array(student.right_jacobian_so3(w), (3, 3), f"right_jacobian_so3 at angle π - {offset:g}")
        expect_close(got, ref.right_jacobian_so3(w), 1e-9, f"right_jacobian_so3 at angle π - {offset:g}")


@exercise("right_jacobian_so3", weight=1)
def test_right_jacobian_identities(student):
    """Jr(w) w = w, Jr(-w) = Jr(w)ᵀ and Jl(w) = Jr(-w) = Exp(w) Jr(w)"""
    for w in _rotvecs(5, 669, 0.2, 3.0):
        J = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        J_minus = expect_array(student.right_jacobian_so3(-w), (3, 3), "right_jacobian_so3(-w)")
        expect_close(J @ w, w, 1e-10, "Jr(w) @ w", "Jr leaves w itself unchanged: [w]× w = 0")
        expect_close(J_minus, J.T, 1e-10, "Jr(-w) against Jr(w)ᵀ")
        expect_close(J_minus, _exp(w) @ J, 1e-10, "Jr(-w) against Exp(w) Jr(w)",
                     "Jl(w) = Exp(w) Jr(w) holds for the right Jacobian only: check the sign of the [w]× term")


# ---------------------------------------------------------------- right_jacobian_inv_so3
def _inverse_hint(got, w, ref):
    Jr = ref.right_jacobian_so3(w)
    if np.allclose(got, Jr.T, atol=1e-8):
        return "that is Jr(w)ᵀ: Jr is not orthogonal, its transpose is not its inverse"
    if np.allclose(got, Jr, atol=1e-8):
        return "that is Jr(w) itself, not its inverse"
    if np.allclose(got, np.linalg.inv(Jr.T), atol=1e-8):
        return "that is the inverse of the left Jacobian: the [w]×/2 term has the wrong sign"
    return ""


@exercise("right_jacobian_inv_so3", weight=2)
def test_right_jacobian_inv_inverts(student, ref):
    """Jr⁻¹(w) Jr(w) = I for 20 random w with angles from 1e-3 to π"""
    for w in _rotvecs(20, 671, 1e-3, np.pi):
        got = expect_array(student.right_jacobian_inv_so3(w), (3, 3), "right_jacobian_inv_so3(w)")
        expect_close(got @ ref.right_jacobian_so3(w), np.eye(3), 1e-9,
                     f"right_jacobian_inv_so3(w) @ Jr(w) at angle {np.linalg.norm(w):.4f}", _inverse_hint(got, w, ref))


@exercise("right_jacobian_inv_so3", weight=2)
def test_right_jacobian_inv_linearises_log(student, ref):
    """Log(Exp(w) Exp(v)) ≈ w + Jr⁻¹(w) v with an error of order |v|²"""
    ws = _rotvecs(10, 672, 0.3, np.pi - 0.1)
    for w, direction in zip(ws, _unit(673, len(ws))):
        J = expect_array(student.right_jacobian_inv_so3(w), (3, 3), "right_jacobian_inv_so3(w)")
        v = 1e-4 * direction
        error = np.linalg.norm(_log(_exp(w) @ _exp(v)) - w - J @ v)
        expect(error <= np.dot(v, v) + 1e-13,
               f"at angle {np.linalg.norm(w):.4f}, Log(Exp(w) Exp(v)) - w - J v = {error:.2g} for |v| = 1e-4 "
               f"(expected below 1e-8)", _inverse_hint(J, w, ref))


@exercise("right_jacobian_inv_so3", weight=2)
def test_right_jacobian_inv_tiny_angles(student):
    """w = 0 gives I (no NaN); at 1e-12, 1e-9 and 1e-7 rad it equals I + [w]×/2 + [w]×²/12"""
    _expect_identity_at_zero(student.right_jacobian_inv_so3(np.zeros(3)), "right_jacobian_inv_so3(0)",
                             "the closed form is 0/0 at θ = 0: use the series 1/12 + θ²/720 of the [w]×² "
                             "coefficient below a small angle")
    for angle, axis in zip([1e-12, 1e-9, 1e-7], _unit(674, 3)):
        w = angle * axis
        W = _skew(w)
        got = expect_array(student.right_jacobian_inv_so3(w), (3, 3), f"right_jacobian_inv_so3 at angle {angle:g}")
        _expect_tiny_angle(got, w, np.eye(3) + W / 2.0 + W @ W / 12.0, f"right_jacobian_inv_so3 at angle {angle:g}",
                           "Jr⁻¹ = I + [w]×/2 + c [w]×²: use the series c = 1/12 + θ²/720 below a threshold", sign=1.0)


@exercise("right_jacobian_inv_so3", weight=1)
def test_right_jacobian_inv_near_pi(student, ref):
    """stays finite and accurate at and near a half turn (θ = π, π - 1e-7, π - 1e-4)"""
    for offset, axis in zip([0.0, 1e-7, 1e-4], _unit(675, 3)):
        w = (np.pi - offset) * axis
        got = expect_array(student.right_jacobian_inv_so3(w), (3, 3), f"right_jacobian_inv_so3 at angle π - {offset:g}")
        expect_close(got, ref.right_jacobian_inv_so3(w), 1e-8, f"right_jacobian_inv_so3 at angle π - {offset:g}",
                     _inverse_hint(got, w, ref))
