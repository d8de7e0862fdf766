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
Promises checked over the whole domain (properties drawn by Hypothesis, derandomized, see
``properties.py``), at every angle from 1e-12 to π, each decade and just below each power of ten:
Jr and Jr⁻¹ within 1e-13 entrywise of a branch-free series (and its inverse); q ⊞ δ within 2e-15 of
q ⊗ Exp_q(δ) (up to sign) for q from both hemispheres; lists of floats and integers as inputs.
Tiny angles: Jr and Jr⁻¹ at 1e-9 … 1e-3 rad must be off by at most
1e-6 θ + 1e-15, so a missing [w]× or [w]×² series term shows. Callable arguments travel as
``Probe``s. Every test calls the student's function of its own exercise only.
"""

import numpy as np
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from autograder.sandbox.child import probes

from coursekit import hints
from coursekit.checks.lesson06 import INTEGER_X_HINT, JACOBIAN_TYPE_HINT, floor_hint, jacobian_type_problem
from coursekit.diagnose import JACOBIAN_STEP_HINT, jacobian_error_allowed

from .properties import (
    angle_text,
    as_given,
    decade_vectors,
    expect_within,
    for_all,
    given_forms,
    quaternions,
    rotation_vectors,
)
from .helpers import (
    Probe,
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

TOL = 1e-10
# Jr and Jr⁻¹ at every angle from 1e-12 to π: each entry within 1e-13 (the reference's error is 9e-16 and
# 1.3e-15; a one-term series kept up to 1e-4 is off by θ³/24 = 4e-14 there, and passes; up to 1e-3 it fails)
JR_TOL = 1e-13
JR_INV_TOL = 1e-13
QUAT_BOXPLUS_TOL = 2e-15  # q ⊞ d for |d| from 1e-12 to π: each component within 2e-15 (up to the sign of q)


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


def _is(got, candidate, truth, tol=1e-8):
    """True when ``got`` is the candidate mistake's value: within ``tol`` of it, and much closer to it than the
    candidate is to the truth (so a hint never fires where the mistake and the right answer agree)."""
    got, candidate, truth = (np.asarray(a, dtype=float) for a in (got, candidate, truth))
    if got.shape != candidate.shape or candidate.shape != truth.shape or not np.all(np.isfinite(got)):
        return False
    gap = float(np.max(np.abs(candidate - truth)))
    return gap > 0.0 and float(np.max(np.abs(got - candidate))) <= min(tol, 1e-2 * gap + 1e-15)


def _diagnose(got, truth, candidates, fallback=""):
    """The hint of the first candidate (value, hint) that ``got`` equals, else ``fallback``."""
    for value, hint in candidates:
        if _is(got, value, truth):
            return hint
    return fallback


def _array(value, shape, what, nan_hint=""):
    """Like ``expect_array``, with a hint for NaN or inf (``nan_hint``, may be a callable) or a transposed shape."""
    problem = shape_problem(value, shape)
    if problem:
        hint = ""
        if problem == "returned NaN or inf values":
            hint = nan_hint(np.asarray(value, dtype=float)) if callable(nan_hint) else nan_hint
        elif len(shape) == 2 and shape[0] != shape[1] and np.shape(value) == tuple(reversed(shape)):
            hint = hints.ROW_I_OUTPUT_F_HINT
        raise Wrong(f"{what} {problem}", hint)
    return np.asarray(value, dtype=float)


# ---------------------------------------------------------------- boxplus_right
def _boxplus_hint(got, R, d, right, fallback=""):
    """Name the mistake when ``got`` is one of the typical wrong versions of R ⊞ δ (right or left)."""
    R, d = np.asarray(R, dtype=float), np.asarray(d, dtype=float)
    if right:
        truth = R @ _exp(d)
        candidates = [
            (_exp(d) @ R, "that is the left perturbation Exp(δ) R; boxplus_right is R @ Exp(δ)"),
            (
                R @ (np.eye(3) + _skew(d)),
                "that is R (I + [δ]×), only the first-order approximation and not a rotation: use R @ Exp(δ)",
            ),
            (R @ _exp(-d), hints.TURNED_CHECK_SIGN_R_HINT),
            (R.T @ _exp(d), "that is Rᵀ Exp(δ): R got transposed; boxplus_right is R @ Exp(δ)"),
        ]
    else:
        truth = _exp(d) @ R
        candidates = [
            (R @ _exp(d), "that is the right perturbation R Exp(δ); boxplus_left is Exp(δ) @ R"),
            (
                (np.eye(3) + _skew(d)) @ R,
                "that is (I + [δ]×) R, only the first-order approximation and not a rotation: use Exp(δ) @ R",
            ),
            (_exp(-d) @ R, hints.TURNED_CHECK_SIGN_EXP_HINT),
            (_exp(d) @ R.T, "that is Exp(δ) Rᵀ: R got transposed; boxplus_left is Exp(δ) @ R"),
            (
                R @ _exp(R @ d),
                "that is R Exp(R δ): with R first the left perturbation is R Exp(Rᵀ δ) "
                "(Rᵀ, not R: R Exp(v) Rᵀ = Exp(R v)); or simply Exp(δ) @ R",
            ),
        ]
    candidates.append((R + _skew(d), hints.R_ROTATIONS_DO_ADD_HINT))
    return _diagnose(got, truth, candidates, fallback)


def _boxplus_cases(seed):
    Rs = random_rotations(14, seed=seed)
    ds = list(_rotvecs(10, seed + 10, 0.0, 3.0)) + [
        np.zeros(3),
        1e-9 * _unit(seed + 20, 1)[0],
        np.pi * _unit(seed + 21, 1)[0],
        5.0 * _unit(seed + 22, 1)[0],
    ]
    return list(zip(Rs, ds))


@exercise("boxplus_right", weight=3)
def test_boxplus_right_matches_definition(student):
    """equals R @ Exp(δ) for random rotations, δ = 0, tiny δ, |δ| = π and |δ| > π"""
    for R, d in _boxplus_cases(601):
        got = expect_array(student.boxplus_right(R, d), (3, 3), f"boxplus_right(R, {fmt(d)})")
        expect_close(got, R @ _exp(d), TOL, f"boxplus_right(R, {fmt(d)})", lambda: _boxplus_hint(got, R, d, right=True))


@exercise("boxplus_right", weight=1)
def test_boxplus_right_stays_rotation(student):
    """always returns a rotation matrix, even for large δ"""
    for R, d in zip(random_rotations(8, seed=602), _rotvecs(8, 603, 0.5, 6.0)):
        got = expect_array(student.boxplus_right(R, d), (3, 3), "boxplus_right(R, δ)")
        problem = rotation_problem(got, tol=1e-9)
        expect(
            problem is None,
            f"boxplus_right(R, {fmt(d)}) is not a rotation: {problem}",
            lambda: _boxplus_hint(got, R, d, True, hints.RIGHT_UPDATE_IS_A_ROTATION_HINT),
        )


@exercise("boxplus_right", weight=1)
def test_boxplus_right_turns_about_body_axes(student):
    """turns about the body's own axes (R ⊞ a e_k keeps R e_k) and accepts lists"""
    R = random_rotations(1, seed=604)[0]
    for k in range(3):
        d = 0.7 * np.eye(3)[k]
        got = expect_array(student.boxplus_right(R.tolist(), d.tolist()), (3, 3), "boxplus_right with lists")
        expect_close(
            got[:, k],
            R[:, k],
            TOL,
            f"body axis {k} after turning about it",
            lambda: _boxplus_hint(got, R, d, True, "the right perturbation turns about the body's axes: R @ Exp(δ)"),
        )


# ---------------------------------------------------------------- boxplus_left
@exercise("boxplus_left", weight=3)
def test_boxplus_left_matches_definition(student):
    """equals Exp(δ) @ R for random rotations, δ = 0, tiny δ, |δ| = π and |δ| > π"""
    for R, d in _boxplus_cases(611):
        got = expect_array(student.boxplus_left(R, d), (3, 3), f"boxplus_left(R, {fmt(d)})")
        expect_close(got, _exp(d) @ R, TOL, f"boxplus_left(R, {fmt(d)})", lambda: _boxplus_hint(got, R, d, right=False))


@exercise("boxplus_left", weight=1)
def test_boxplus_left_stays_rotation(student):
    """always returns a rotation matrix, even for large δ"""
    for R, d in zip(random_rotations(8, seed=612), _rotvecs(8, 613, 0.5, 6.0)):
        got = expect_array(student.boxplus_left(R, d), (3, 3), "boxplus_left(R, δ)")
        problem = rotation_problem(got, tol=1e-9)
        expect(
            problem is None,
            f"boxplus_left(R, {fmt(d)}) is not a rotation: {problem}",
            lambda: _boxplus_hint(got, R, d, False, hints.LEFT_UPDATE_IS_A_ROTATION_HINT),
        )


@exercise("boxplus_left", weight=1)
def test_boxplus_left_turns_about_world_axes(student):
    """turns about the world axes (rows: e_kᵀ (Exp(a e_k) R) = e_kᵀ R) and accepts lists"""
    R = random_rotations(1, seed=614)[0]
    for k in range(3):
        d = 0.7 * np.eye(3)[k]
        got = expect_array(student.boxplus_left(R.tolist(), d.tolist()), (3, 3), "boxplus_left with lists")
        expect_close(
            got[k, :],
            R[k, :],
            TOL,
            f"row {k} after turning about world axis {k}",
            lambda: _boxplus_hint(got, R, d, False, "the left perturbation turns about the world's axes: Exp(δ) @ R"),
        )


# ---------------------------------------------------------------- boxminus
def _boxminus_hint(got, R_a, R_b):
    """Name the mistake when ``got`` is one of the typical wrong versions of R_a ⊟ R_b."""
    truth = _log(R_b.T @ R_a)
    D = R_b.T @ R_a
    hint = _diagnose(
        got,
        truth,
        [
            (-truth, "got the step back: arguments swapped? boxminus(R_a, R_b) is the step from R_b to R_a"),
            (_log(R_a) - _log(R_b), hints.LOGS_DO_NOT_SUBTRACT_HINT),
            (0.5 * np.array([D[2, 1] - D[1, 2], D[0, 2] - D[2, 0], D[1, 0] - D[0, 1]]), hints.AXIS_TIMES_SIN_VEE_HINT),
        ],
    )
    if not hint and np.all(np.isfinite(got)) and _is(_exp(got), R_a @ R_b.T, D):
        hint = hints.LEFT_DIFFERENCE_STEP_RIGHT_HINT
    return hint


@exercise("boxminus", weight=3)
def test_boxminus_matches_log(student):
    """equals Log(R_bᵀ R_a) for 15 random pairs (relative angle below π)"""
    R_bs = random_rotations(15, seed=621)
    steps = _rotvecs(15, 622, 0.0, np.pi - 0.05)
    for R_b, step in zip(R_bs, steps):
        R_a = R_b @ _exp(step)
        got = expect_array(student.boxminus(R_a, R_b), (3,), "boxminus(R_a, R_b)")
        expect_close(got, step, 1e-9, "boxminus(R_a, R_b)", lambda: _boxminus_hint(got, R_a, R_b))


@exercise("boxminus", weight=2)
def test_boxminus_round_trip(student):
    """R_b Exp(R_a ⊟ R_b) = R_a with |R_a ⊟ R_b| ≤ π, also at and near a half turn"""
    R_bs = random_rotations(9, seed=623)
    axes = _unit(624, 9)
    angles = [0.3, 1.0, 2.0, 3.0, np.pi - 1e-7, np.pi, np.pi, 2 * np.pi - 0.5, 0.0]
    for R_b, axis, angle in zip(R_bs, axes, angles):
        R_a = R_b @ _exp(angle * axis)
        got = expect_array(student.boxminus(R_a, R_b), (3,), "boxminus(R_a, R_b)")
        expect_close(
            R_b @ _exp(got),
            R_a,
            1e-8,
            f"R_b @ Exp(boxminus(R_a, R_b)) for a relative angle of {angle:.4f}",
            lambda: _boxminus_hint(got, R_a, R_b),
        )
        expect(
            np.linalg.norm(got) <= np.pi + 1e-9,
            f"|boxminus| = {np.linalg.norm(got):.4f} exceeds π",
            "Log returns the shortest rotation vector, angle in [0, π]",
        )


@exercise("boxminus", weight=1)
def test_boxminus_inverts_boxplus(student):
    """(R ⊞ δ) ⊟ R = δ for |δ| < π, tiny δ and δ = 0; lists work too"""
    R = random_rotations(1, seed=625)[0]
    deltas = list(_rotvecs(5, 626, 0.1, 3.0)) + [1e-9 * _unit(627, 1)[0], np.zeros(3)]
    for d in deltas:
        got = expect_array(student.boxminus(R @ _exp(d), R), (3,), "boxminus(R ⊞ δ, R)")
        expect_close(
            got, d, 1e-9, f"boxminus(R Exp(δ), R) for δ = {fmt(d)}", lambda: _boxminus_hint(got, R @ _exp(d), R)
        )
    expect_same_with_lists(student.boxminus, (R @ _exp(deltas[0]), R), (3,), "boxminus(R_a, R_b)")


# ---------------------------------------------------------------- quat_boxplus
def _random_quats(count, seed):
    return Rotation.random(count, random_state=seed).as_quat(scalar_first=True)


def _is_quat(got, candidate, truth):
    """``_is`` for quaternions, where q and -q are the same rotation."""
    candidate = candidate if np.dot(candidate, truth) >= 0 else -candidate
    return _is(got, candidate, truth) or _is(-np.asarray(got, dtype=float), candidate, truth)


def _quat_hint(got, q, d, fallback=""):
    """Name the mistake when ``got`` is one of the typical wrong versions of q ⊞ δ."""
    d = np.asarray(d, dtype=float)
    truth = _qmul(q, _exp_q(d))
    first_order = _qmul(q, np.concatenate([[1.0], d / 2.0]))
    angle = np.linalg.norm(d)
    if 0.0 < angle < 1e-2 and _is_quat(got, first_order / np.linalg.norm(first_order), truth):
        return (
            f"that is q ⊗ [1, δ/2], normalised, at |δ| = {angle:.2g}: off by about |δ|³/24 there; keep that "
            "shortcut for |δ| below about 1e-8, where it is exact to rounding, and use Exp_q(δ) above"
        )
    candidates = [
        (first_order, hints.Q_WITHOUT_NORMALISING_NORM_HINT),
        (
            first_order / np.linalg.norm(first_order),
            "that is q ⊗ [1, δ/2] rescaled to unit length: a unit "
            "quaternion, but it turns by 2·atan(|δ|/2) instead of |δ|; use the exact Exp_q(δ) = "
            "[cos(|δ|/2), sin(|δ|/2) δ/|δ|]",
        ),
        (_qmul(q, _exp_q(2.0 * d)), hints.TURNED_TWICE_FAR_QUATERNION_HINT),
        (_qmul(_exp_q(d), q), hints.LEFT_QUAT_PERTURBATION_HINT),
    ]
    for value, hint in candidates:
        if _is_quat(got, value, truth):
            return hint
    if _is_quat(got, truth[[1, 2, 3, 0]], truth):
        return "scalar last? The course stores quaternions scalar first, [w, x, y, z]"
    length = np.linalg.norm(got)
    if abs(length - 1.0) > 1e-9:
        return f"|result| = {length:.6f}: not a unit quaternion; q ⊗ Exp_q(δ) always has norm 1"
    return fallback


@exercise("quat_boxplus", weight=3)
def test_quat_boxplus_matches_definition(student):
    """equals q ⊗ Exp_q(δ) (up to sign) for random unit quaternions and δ up to 3 rad"""
    for q, d in zip(_random_quats(15, 631), _rotvecs(15, 632, 0.05, 3.0)):
        got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ)")
        expected = _qmul(q, _exp_q(d))
        if not _same_quat(got, expected, TOL):
            expect_close(
                got,
                expected if np.dot(got, expected) >= 0 else -expected,
                TOL,
                f"quat_boxplus(q, {fmt(d)})",
                lambda: _quat_hint(got, q, d),
            )


@exercise("quat_boxplus", weight=1)
def test_quat_boxplus_unit_norm(student):
    """returns a unit quaternion, also for large δ"""
    for q, d in zip(_random_quats(8, 633), _rotvecs(8, 634, 1.0, 6.0)):
        got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ)")
        norm = np.linalg.norm(got)
        expect(
            abs(norm - 1.0) <= 1e-12,
            f"|quat_boxplus(q, {fmt(d)})| = {norm:.9f} (off by {abs(norm - 1):.2g})",
            lambda: _quat_hint(got, q, d),
        )


@exercise("quat_boxplus", weight=1)
def test_quat_boxplus_agrees_with_matrices(student):
    """R(q ⊞ δ) = R(q) Exp(δ): the same right perturbation as for matrices"""
    for q, d in zip(_random_quats(8, 635), _rotvecs(8, 636, 0.1, 3.0)):
        got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ)")
        expect(
            abs(np.linalg.norm(got) - 1.0) <= 1e-9,
            f"|quat_boxplus(q, δ)| = {np.linalg.norm(got):.6f}",
            lambda: _quat_hint(got, q, d, "return a unit quaternion"),
        )
        expect_close(
            _quat_matrix(got), _quat_matrix(q) @ _exp(d), 1e-9, "R(quat_boxplus(q, δ))", lambda: _quat_hint(got, q, d)
        )


@exercise("quat_boxplus", weight=1)
def test_quat_boxplus_tiny_and_zero(student):
    """δ = 0 returns q and a tiny δ (1e-9 rad) is exact, with no NaN"""
    q = _random_quats(1, 637)[0]
    got = _array(student.quat_boxplus(q, np.zeros(3)), (4,), "quat_boxplus(q, 0)", hints.USE_BELOW_TINY_ANGLE_HINT)
    expect(
        _same_quat(got, q, 1e-14),
        f"quat_boxplus(q, 0) = {fmt(got)}, expected q = {fmt(q)}",
        "a zero step must return q itself (or -q)",
    )
    d = 1e-9 * _unit(638, 1)[0]
    got = expect_array(student.quat_boxplus(q, d), (4,), "quat_boxplus(q, δ) for |δ| = 1e-9")
    expected = _qmul(q, _exp_q(d))
    error = min(np.max(np.abs(got - expected)), np.max(np.abs(got + expected)))
    expect(
        _same_quat(got, expected, 1e-15),
        f"quat_boxplus(q, δ) for |δ| = 1e-9 is off by {error:.2g} (tolerance 1e-15)",
        lambda: _quat_hint(got, q, d, "below a tiny angle, Exp_q(δ) = [1, δ/2] to machine precision"),
    )


@exercise("quat_boxplus", weight=2)
def test_quat_boxplus_every_decade(student):
    """exact to 2e-15 for |δ| from 1e-12 to π (each decade, just below each power of ten), q from both
    hemispheres, lists too"""

    def check(case):
        (q, d), given = case
        got = expect_array(student.quat_boxplus(q, given), (4,), "quat_boxplus(q, δ)")
        expected = _qmul(q, _exp_q(d))
        expected = expected if np.dot(got, expected) >= 0 else -expected
        expect_within(
            got,
            expected,
            QUAT_BOXPLUS_TOL,
            "quat_boxplus(q, δ)",
            f"|δ| = {np.linalg.norm(d):.2g}",
            lambda: _quat_hint(got, q, d),
        )

    q = _random_quats(1, 639)[0]
    cases = st.tuples(quaternions(), rotation_vectors()).flatmap(
        lambda pair: st.tuples(st.just(pair), as_given(pair[1]))
    )
    for_all(cases, check, explicit=[((q, d), d) for d, _ in decade_vectors()])


# ---------------------------------------------------------------- numerical_jacobian
SMOOTH_POINTS = [
    np.array([0.7, -1.3, 2.1]),
    np.array([2.0, -1.5, 0.0]),
    np.array([1.5, 2.5, -3.0]),
    np.array([-0.4, 0.9, 0.3]),
]


def _forward_differences(f, x, h, boxplus=None):
    """The grader's own forward differences with one fixed step ``h`` (a candidate for a wrong step size)."""
    if boxplus is None:
        x = np.asarray(x, dtype=float)
        f0 = np.asarray(f(x), dtype=float)
        columns = []
        for j in range(x.size):
            moved = x.copy()
            moved[j] += h
            columns.append((np.asarray(f(moved), dtype=float) - f0) / h)
        return np.column_stack(columns)
    f0 = np.asarray(f(x), dtype=float)
    return np.column_stack([(np.asarray(f(boxplus(x, h * e)), dtype=float) - f0) / h for e in np.eye(3)])


def _step_hint(got, exact, f, x, boxplus=None, fallback=JACOBIAN_STEP_HINT):
    """Name a fixed step that is far too large or far too small when ``got`` is exactly the forward
    differences with that step; the transpose; else ``fallback``."""
    got, exact = np.asarray(got, dtype=float), np.asarray(exact, dtype=float)
    if got.shape != exact.shape or not np.all(np.isfinite(got)):
        return fallback
    error = float(np.max(np.abs(got - exact)))
    if got.shape[0] == got.shape[1] and float(np.max(np.abs(got.T - exact))) <= 1e-3 * error:
        return hints.ROW_I_OUTPUT_F_I_HINT
    for k in list(range(1, 5)) + list(range(10, 16)):
        h = 10.0**-k
        if float(np.max(np.abs(got - _forward_differences(f, x, h, boxplus)))) <= 1e-3 * error:
            if h >= 1e-4:
                return (
                    f"that is forward differences with a fixed step h = {h:g}, a step far too large: the slope is "
                    "biased by about h/2 · f'' (the right side of the V-curve); use δ_j = max(|1e-4 x_j|, 1e-6), "
                    "a step near √ε ≈ 1e-8, or central differences"
                )
            return (
                f"that is forward differences with a fixed step h = {h:g}, a step far too small: rounding noise "
                "of about ε·|f|/h swamps the slope (the left side of the V-curve); use δ_j = max(|1e-4 x_j|, "
                "1e-6) or a step near √ε ≈ 1e-8"
            )
    return fallback


def _matrix_entries_hint(value):
    if np.shape(value) in ((3, 9), (3, 4)):
        return (
            "one column per stored number: with a boxplus, differentiate with respect to the 3-vector δ "
            "in boxplus(x, δ), not the entries of x"
        )
    return ""


@exercise("numerical_jacobian", weight=2)
def test_numerical_jacobian_vector_function(student):
    """approximates the analytic Jacobian of a smooth R³ → R² function (shape 2×3)"""
    for x in SMOOTH_POINTS:
        value = student.numerical_jacobian(Probe("smooth_vector_function"), x)
        expect(np.shape(value) != (3, 2), hints.RETURNED_SHAPE_F_R3_HINT, hints.ROW_I_OUTPUT_F_HINT)
        got = _array(value, (2, 3), f"numerical_jacobian(f, {fmt(x)})", floor_hint(x))
        expected = probes.smooth_vector_function_jacobian(x)
        expect_close(
            got,
            expected,
            2e-3 * (1.0 + np.max(np.abs(expected))),
            f"numerical_jacobian(f, {fmt(x)})",
            lambda: _step_hint(got, expected, probes.smooth_vector_function, x),
        )


def _expect_accurate_jacobian(got, x, what, ref):
    """The course's rule: at most twice the error of the lecture's forward steps (+ 1e-8 for rounding).
    The reference solution is the lecture's rule, so it measures the lecture's error here."""
    exact = probes.smooth_vector_function_jacobian(x)
    lecture_error = np.max(np.abs(np.asarray(ref.numerical_jacobian(probes.smooth_vector_function, x)) - exact))
    allowed = jacobian_error_allowed(lecture_error, exact)
    error = float(np.max(np.abs(got - exact)))
    expect(
        error <= allowed,
        f"{what} is off by {error:.2g} from the analytic Jacobian; the lecture's forward "
        f"steps are off by {(allowed - 1e-8 * (1 + np.max(np.abs(exact)))) / 2:.2g} (allowed: {allowed:.2g})",
        lambda: _step_hint(got, exact, probes.smooth_vector_function, x),
    )


@exercise("numerical_jacobian", weight=2)
def test_numerical_jacobian_step_rule(student, ref):
    """at least as accurate as forward differences with the lecture's steps δ_j = max(|1e-4 x_j|, 1e-6)"""
    for x in SMOOTH_POINTS:
        got = _array(
            student.numerical_jacobian(Probe("smooth_vector_function"), x),
            (2, 3),
            f"numerical_jacobian(f, {fmt(x)})",
            floor_hint(x),
        )
        _expect_accurate_jacobian(got, x, f"numerical_jacobian(f, {fmt(x)})", ref)


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_at_zero(student, ref):
    """works at x = 0 (no 0/0: the lecture's step has the floor 1e-6), as accurately as the lecture's rule"""
    x = np.zeros(3)
    got = _array(
        student.numerical_jacobian(Probe("smooth_vector_function"), x),
        (2, 3),
        "numerical_jacobian(f, 0)",
        floor_hint(x),
    )
    _expect_accurate_jacobian(got, x, "numerical_jacobian(f, 0)", ref)


def _rotation_cases(seed, count=6):
    Rs = random_rotations(count, seed=seed)
    ps = np.random.default_rng(seed + 1).normal(size=(count, 3)) * 1.5
    return list(zip(Rs, ps))


def _manifold_tol(p):
    return 5e-6 * (1.0 + np.linalg.norm(p))


_MANIFOLD_HINT = "column j: (f(boxplus(x, h e_j)) - f(x)) / h, forward differences with a small h (e.g. 1e-6)"


@exercise("numerical_jacobian", weight=2)
def test_numerical_jacobian_rotation_right(student):
    """with a right boxplus, the Jacobian of R ↦ R p is the exact one (3 columns, one per δ_j)"""
    for R, p in _rotation_cases(641):
        value = student.numerical_jacobian(Probe("rotate_point_by", p), R, Probe("so3_plus_right"))
        expect(
            not _matrix_entries_hint(value),
            f"returned shape {np.shape(value)} for a rotation",
            lambda: _matrix_entries_hint(value),
        )
        got = expect_array(value, (3, 3), "numerical_jacobian(R ↦ R p, R, so3_plus_right)")
        exact = -R @ _skew(p)
        hint = (
            "looks like the left-perturbation Jacobian: use the boxplus you are given"
            if np.max(np.abs(got + _skew(R @ p))) <= _manifold_tol(p)
            else _step_hint(
                got, exact, lambda X: probes.rotate_point_by(p, X), R, probes.so3_plus_right, _MANIFOLD_HINT
            )
        )
        expect_close(got, exact, _manifold_tol(p), "numerical_jacobian(R ↦ R p, R, right ⊞)", hint)


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_rotation_left(student):
    """with a left boxplus, the Jacobian of R ↦ R p is -[R p]×"""
    for R, p in _rotation_cases(643, count=4):
        value = student.numerical_jacobian(Probe("rotate_point_by", p), R, Probe("so3_plus_left"))
        expect(
            not _matrix_entries_hint(value),
            f"returned shape {np.shape(value)} for a rotation",
            lambda: _matrix_entries_hint(value),
        )
        got = expect_array(value, (3, 3), "numerical_jacobian(R ↦ R p, R, so3_plus_left)")
        exact = -_skew(R @ p)
        hint = (
            "looks like the right-perturbation Jacobian: perturb through the boxplus you are given"
            if np.max(np.abs(got + R @ _skew(p))) <= _manifold_tol(p)
            else _step_hint(got, exact, lambda X: probes.rotate_point_by(p, X), R, probes.so3_plus_left, _MANIFOLD_HINT)
        )
        expect_close(got, exact, _manifold_tol(p), "numerical_jacobian(R ↦ R p, R, left ⊞)", hint)


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_unrotate(student):
    """with a right boxplus, the Jacobian of R ↦ Rᵀ p matches the exact one"""
    for R, p in _rotation_cases(645, count=4):
        value = student.numerical_jacobian(Probe("unrotate_point_by", p), R, Probe("so3_plus_right"))
        expect(
            not _matrix_entries_hint(value),
            f"returned shape {np.shape(value)} for a rotation",
            lambda: _matrix_entries_hint(value),
        )
        got = expect_array(value, (3, 3), "numerical_jacobian(R ↦ Rᵀ p, R, so3_plus_right)")
        exact = _skew(R.T @ p)
        expect_close(
            got,
            exact,
            _manifold_tol(p),
            "numerical_jacobian(R ↦ Rᵀ p, R, right ⊞)",
            lambda: _step_hint(
                got, exact, lambda X: probes.unrotate_point_by(p, X), R, probes.so3_plus_right, _MANIFOLD_HINT
            ),
        )


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_quaternion(student):
    """with a quaternion x (4 numbers) and its boxplus, the Jacobian still has 3 columns, the exact ones"""
    quats = _random_quats(4, 647)
    ps = np.random.default_rng(648).normal(size=(4, 3))
    for q, p in zip(quats, ps):
        value = student.numerical_jacobian(Probe("quat_rotate_point_by", p), q, Probe("quat_plus_right"))
        expect(
            not _matrix_entries_hint(value),
            f"returned shape {np.shape(value)} for a quaternion",
            lambda: _matrix_entries_hint(value),
        )
        got = expect_array(value, (3, 3), "numerical_jacobian(q ↦ R(q) p, q, quat_plus_right)")
        exact = -_quat_matrix(q) @ _skew(p)
        expect_close(
            got,
            exact,
            _manifold_tol(p),
            "numerical_jacobian(q ↦ R(q) p, q, ⊞)",
            lambda: _step_hint(
                got, exact, lambda X: probes.quat_rotate_point_by(p, X), q, probes.quat_plus_right, _MANIFOLD_HINT
            ),
        )


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_shapes(student):
    """returns shape (len(f(x)), n): 5×5 for the identity on R⁵, 3×3 for a rotation; x may be a list, an
    integer array or a tuple of integers (the steps must not be rounded away)"""
    x = np.array([3.0, -0.2, 0.0, 1e-3, 40.0])
    got = _array(
        student.numerical_jacobian(Probe("identity_function"), x),
        (5, 5),
        "numerical_jacobian(identity, x in R⁵)",
        floor_hint(x),
    )
    expect_close(
        got,
        np.eye(5),
        1e-6,
        "numerical_jacobian of the identity map",
        lambda: _step_hint(got, np.eye(5), probes.identity_function, x),
    )
    R = random_rotations(1, seed=649)[0]
    value = student.numerical_jacobian(Probe("rotate_point_by", [1.0, 2.0, 3.0]), R, Probe("so3_plus_right"))
    expect(
        np.shape(value) == (3, 3),
        f"returned shape {np.shape(value)} for f: SO(3) → R³, expected (3, 3)",
        lambda: _matrix_entries_hint(value),
    )


@exercise("numerical_jacobian", weight=1)
def test_numerical_jacobian_returns_float64_arrays(student):
    """returns a float64 numpy array on both paths, with and without boxplus (the docstring's ndarray)"""
    R = random_rotations(1, seed=650)[0]
    for value, how in (
        (student.numerical_jacobian(Probe("identity_function"), np.array([3.0, -0.2, 1.0])), "without boxplus"),
        (
            student.numerical_jacobian(Probe("rotate_point_by", [1.0, 2.0, 3.0]), R, Probe("so3_plus_right")),
            "with boxplus",
        ),
    ):
        problem = jacobian_type_problem(value)
        expect(problem is None, f"numerical_jacobian {how}: {problem}", JACOBIAN_TYPE_HINT)
    for x, form in (([3, 0, -2], "list"), (np.array([3, 0, -2]), "integer array"), ((3, 0, -2), "tuple")):
        got = _array(
            student.numerical_jacobian(Probe("identity_function"), x),
            (3, 3),
            f"numerical_jacobian(identity, [3, 0, -2] as an {form})",
            floor_hint(np.array([3.0, 0.0, -2.0])),
        )
        expect_close(
            got, np.eye(3), 1e-6, f"numerical_jacobian of the identity at [3, 0, -2] as an {form}", INTEGER_X_HINT
        )


# ---------------------------------------------------------------- jacobian_rotate_point
def _rotate_point_hint(got, R, p):
    """Name the mistake when ``got`` is one of the typical wrong versions of the Jacobian -R [p]×."""
    return _diagnose(
        got,
        -R @ _skew(p),
        [
            (-_skew(R @ p), hints.LEFT_JACOBIAN_OF_ROTATED_POINT_HINT),
            (R @ _skew(p), hints.ROTATED_POINT_SIGN_FLIPPED_HINT),
            (-_skew(p) @ R, hints.FACTORS_WRONG_ORDER_R_HINT),
            (-_skew(p), hints.ROTATED_POINT_R_MISSING_HINT),
            ((-R @ _skew(p)).T, hints.TRANSPOSE_R_P_ROW_HINT),
        ],
    )


@exercise("jacobian_rotate_point", weight=3)
def test_jacobian_rotate_point_formula(student):
    """equals d(R Exp(δ) p)/dδ at δ = 0 for 20 random rotations and points"""
    for R, p in _rotation_cases(651, count=20):
        got = expect_array(student.jacobian_rotate_point(R, p), (3, 3), "jacobian_rotate_point(R, p)")
        expect_close(got, -R @ _skew(p), TOL, "jacobian_rotate_point(R, p)", lambda: _rotate_point_hint(got, R, p))


@exercise("jacobian_rotate_point", weight=2)
def test_jacobian_rotate_point_linearises(student):
    """R Exp(δ) p ≈ R p + J δ with a remainder of order |δ|² (|δ| = 1e-3 and 1e-4)"""
    directions = _unit(659, 6)  # not 653: the points are drawn with that seed, and δ ∥ p would hide J
    for (R, p), direction in zip(_rotation_cases(652), directions):
        J = expect_array(student.jacobian_rotate_point(R, p), (3, 3), "jacobian_rotate_point(R, p)")
        for scale in (1e-3, 1e-4):
            step = scale * direction
            remainder = np.linalg.norm(R @ _exp(step) @ p - R @ p - J @ step)
            expect(
                remainder <= np.linalg.norm(p) * scale**2 + 1e-13,
                f"R Exp(δ) p - R p - J δ = {remainder:.2g} for |δ| = {scale:g}: not of order |δ|² "
                f"(allowed {np.linalg.norm(p) * scale**2 + 1e-13:.2g})",
                lambda: _rotate_point_hint(J, R, p),
            )


@exercise("jacobian_rotate_point", weight=1)
def test_jacobian_rotate_point_matches_finite_differences(student):
    """agrees with central differences of δ ↦ R Exp(δ) p taken by the grader"""
    for R, p in _rotation_cases(654, count=4):
        got = expect_array(student.jacobian_rotate_point(R, p), (3, 3), "jacobian_rotate_point(R, p)")
        h = 1e-6
        numeric = np.column_stack([(R @ _exp(h * e) @ p - R @ _exp(-h * e) @ p) / (2 * h) for e in np.eye(3)])
        expect_close(
            got,
            numeric,
            1e-8 * (1.0 + np.linalg.norm(p)),
            "jacobian_rotate_point vs finite differences",
            lambda: _rotate_point_hint(got, R, p),
        )


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


def _jr_coefficients(theta, swapped=False):
    """a = (1 - cos θ)/θ², b = (θ - sin θ)/θ³, with their series below 1e-4 rad."""
    if theta < 1e-4:
        a, b = 0.5 - theta**2 / 24.0, 1.0 / 6.0 - theta**2 / 120.0
    else:
        a, b = 2.0 * np.sin(theta / 2.0) ** 2 / theta**2, (theta - np.sin(theta)) / theta**3
    return (b, a) if swapped else (a, b)


def _jr(w, swapped=False):
    """Jr(w) = I - a [w]× + b [w]×², written out here (``swapped``: the two coefficients exchanged)."""
    w = np.asarray(w, dtype=float)
    a, b = _jr_coefficients(np.linalg.norm(w), swapped)
    W = _skew(w)
    return np.eye(3) - a * W + b * W @ W


def _jr_exact(w, terms=40):
    """Jr(w) = Σ (-[w]×)^k / (k + 1)!, summed far past convergence: an oracle with no branch at all."""
    W = _skew(w)
    total, term, factorial = np.zeros((3, 3)), np.eye(3), 1.0
    for k in range(terms):
        total = total + term / factorial
        term = -term @ W
        factorial *= k + 2
    return total


def _jr_naive(w):
    """The closed form with no small-angle branch, as a student writes it: 1 - cos θ loses its digits."""
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = _skew(w)
    with np.errstate(all="ignore"):  # 0/0 at θ = 0: the candidate is NaN there, and matches nothing
        return np.eye(3) - (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W


JR_FORMULA = hints.RIGHT_JACOBIAN_FORMULA_HINT


def _jr_candidates(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    candidates = [
        (_jr(-w), "that is Jr(w)ᵀ = Jr(-w) = Jl(w), the left Jacobian: the [w]× term has the wrong sign"),
        (_jr(w, swapped=True), hints.COEFFICIENTS_SWAPPED_COS_MULTIPLIES_HINT),
        (
            np.eye(3),
            f"returned I at θ = {theta:.2g}: the first-order term -[w]×/2 is missing; below a small angle use "
            "the Taylor series of a and b in Jr = I - a [w]× + b [w]×², not I",
        ),
        (_jr_naive(w), hints.CLOSED_FORM_LOSES_DIGITS_HINT),
        (
            _jr_series(w),
            f"that is a one-term series of each coefficient at θ = {theta:.2g}, whose error grows like θ³: "
            "below your threshold keep the θ² term of each coefficient's series",
        ),
    ]
    return candidates


def _jr_hint(got, w, fallback=JR_FORMULA):
    return _diagnose(got, _jr(w), _jr_candidates(w), fallback)


def _expect_identity_at_zero(value, what, nan_hint):
    problem = shape_problem(value, (3, 3))
    if problem:
        raise Wrong(f"{what} {problem}", nan_hint if problem == "returned NaN or inf values" else "")
    expect_close(value, np.eye(3), 1e-15, what, "at w = 0 there is nothing to correct: the result is the identity")


def _expect_tiny_angles(results, expected, candidates, what, fallback, sign):
    """Compare at tiny angles (``results``: (w, got) pairs); on failure, report the coefficient of the [w]× term
    and name the candidate mistake that ``got`` equals at every failing angle."""
    failing = [
        (w, got, truth)
        for (w, got), truth in zip(results, expected)
        if not float(np.max(np.abs(got - truth))) <= 1e-6 * np.linalg.norm(w) + 1e-15
    ]
    if not failing:
        return
    w, got, truth = failing[0]
    angle = np.linalg.norm(w)
    error = float(np.max(np.abs(got - truth)))
    anti = 0.5 * (got - got.T)
    coefficient = np.dot([anti[2, 1], anti[0, 2], anti[1, 0]], w) / angle**2 + 0.0
    hint = fallback
    for index, (_, text) in enumerate(candidates(w)):
        if all(_is(g, candidates(v)[index][0], t) for v, g, t in failing):
            hint = text
            break
    raise Wrong(
        f"{what} at angle {angle:g}: the coefficient of [w]× came out as {coefficient:.9g}, expected "
        f"{sign * 0.5:g} (off by {error:.2g}, tolerance {1e-6 * angle + 1e-15:.2g})",
        hint,
    )


def _jacobian_side_hint(got, w, dw):
    """Name the left Jacobian when J works as Exp(J dw) Exp(w) instead of Exp(w) Exp(J dw)."""
    left = np.linalg.norm(_log((_exp(got @ dw) @ _exp(w)).T @ _exp(w + dw)))
    if left <= 2.0 * np.dot(dw, dw) + 1e-13:
        return hints.LEFT_JACOBIAN_WORKS_ON_LEFT_HINT
    return ""


@exercise("right_jacobian_so3", weight=2)
def test_right_jacobian_matches_reference(student, ref):
    """matches Jr(w) for 20 random w with angles from 1e-3 to π"""
    for w in _rotvecs(20, 661, 1e-3, np.pi):
        got = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        expect_close(
            got,
            ref.right_jacobian_so3(w),
            1e-9,
            f"right_jacobian_so3 at angle {np.linalg.norm(w):.4f}",
            lambda: _jr_hint(got, w),
        )


@exercise("right_jacobian_so3", weight=2)
def test_right_jacobian_linearises(student):
    """Exp(w + dw) ≈ Exp(w) Exp(Jr(w) dw) with an error of order |dw|² (angles up to π)"""
    ws = list(_rotvecs(10, 662, 0.3, np.pi)) + [(np.pi - 1e-6) * _unit(663, 1)[0], np.pi * _unit(664, 1)[0]]
    directions = _unit(665, len(ws))
    for w, direction in zip(ws, directions):
        J = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        dw = 1e-4 * direction
        leftover = np.linalg.norm(_log((_exp(w) @ _exp(J @ dw)).T @ _exp(w + dw)))
        expect(
            leftover <= np.dot(dw, dw) + 1e-13,
            f"at angle {np.linalg.norm(w):.4f}, Exp(w) Exp(J dw) misses Exp(w + dw) by {leftover:.2g} rad "
            f"for |dw| = 1e-4 (expected below 1e-8)",
            lambda: _jr_hint(J, w, _jacobian_side_hint(J, w, dw) or JR_FORMULA),
        )


@exercise("right_jacobian_so3", weight=1)
def test_right_jacobian_matches_finite_differences(student):
    """agrees with central differences of dw ↦ Log(Exp(w)ᵀ Exp(w + dw)) taken by the grader"""
    for w in _rotvecs(4, 666, 0.2, 3.0):
        got = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        h = 1e-6
        R_inv = _exp(w).T
        numeric = np.column_stack(
            [(_log(R_inv @ _exp(w + h * e)) - _log(R_inv @ _exp(w - h * e))) / (2 * h) for e in np.eye(3)]
        )
        expect_close(
            got,
            numeric,
            1e-8,
            f"right_jacobian_so3 vs finite differences at angle {np.linalg.norm(w):.3f}",
            lambda: _jr_hint(got, w),
        )


@exercise("right_jacobian_so3", weight=2)
def test_right_jacobian_tiny_angles(student):
    """w = 0 gives I (no NaN); at 1e-12, 1e-9, 1e-8, 1e-7 rad the [w]× term is accurate to 6 digits"""
    _expect_identity_at_zero(
        student.right_jacobian_so3(np.zeros(3)), "right_jacobian_so3(0)", hints.CLOSED_FORM_USE_TAYLOR_HINT
    )
    ws = [angle * axis for angle, axis in zip([1e-12, 1e-9, 1e-8, 1e-7], _unit(667, 4))]
    results = [
        (w, expect_array(student.right_jacobian_so3(w), (3, 3), f"right_jacobian_so3 at angle {np.linalg.norm(w):g}"))
        for w in ws
    ]
    _expect_tiny_angles(
        results,
        [_jr_series(w) for w in ws],
        _jr_candidates,
        "right_jacobian_so3",
        "Jr = I - a [w]× + b [w]×²: below a small angle use the Taylor series of a and b (from your series), each "
        "with its θ² term",
        sign=-1.0,
    )


@exercise("right_jacobian_so3", weight=2)
def test_right_jacobian_every_decade(student):
    """exact to 1e-13 at every angle from 1e-12 to π (each decade, just below each power of ten), lists too"""

    def check(case):
        w, given = case
        got = expect_array(student.right_jacobian_so3(given), (3, 3), "right_jacobian_so3(w)")
        expect_within(
            got, _jr_exact(w), JR_TOL, "right_jacobian_so3(w)", angle_text(np.linalg.norm(w)), lambda: _jr_hint(got, w)
        )

    for_all(given_forms(rotation_vectors()), check, explicit=decade_vectors())


@exercise("right_jacobian_so3", weight=1)
def test_right_jacobian_near_pi(student, ref):
    """stays finite and accurate at and near a half turn (θ = π, π - 1e-6, π - 1e-9)"""
    for offset, axis in zip([0.0, 1e-6, 1e-9], _unit(668, 3)):
        w = (np.pi - offset) * axis
        got = expect_array(student.right_jacobian_so3(w), (3, 3), f"right_jacobian_so3 at angle π - {offset:g}")
        expect_close(
            got,
            ref.right_jacobian_so3(w),
            1e-9,
            f"right_jacobian_so3 at angle π - {offset:g}",
            lambda: _jr_hint(got, w),
        )


@exercise("right_jacobian_so3", weight=1)
def test_right_jacobian_identities(student):
    """Jr(w) w = w, Jr(-w) = Jr(w)ᵀ and Jl(w) = Jr(-w) = Exp(w) Jr(w)"""
    for w in _rotvecs(5, 669, 0.2, 3.0):
        J = expect_array(student.right_jacobian_so3(w), (3, 3), "right_jacobian_so3(w)")
        J_minus = expect_array(student.right_jacobian_so3(-w), (3, 3), "right_jacobian_so3(-w)")
        expect_close(J @ w, w, 1e-10, "Jr(w) @ w", lambda: _jr_hint(J, w, "Jr leaves w itself unchanged: [w]× w = 0"))
        expect_close(J_minus, J.T, 1e-10, "Jr(-w) against Jr(w)ᵀ", lambda: _jr_hint(J, w))
        expect_close(
            J_minus,
            _exp(w) @ J,
            1e-10,
            "Jr(-w) against Exp(w) Jr(w)",
            lambda: _jr_hint(J, w, "Jl(w) = Exp(w) Jr(w) holds for the right Jacobian only: " + JR_FORMULA),
        )


# ---------------------------------------------------------------- right_jacobian_inv_so3
JR_INV_FORMULA = hints.RIGHT_JACOBIAN_INVERSE_FORMULA_HINT


def _inverse_candidates(w):
    Jr = _jr(w)
    W = _skew(w)
    return [
        (Jr.T, hints.JACOBIAN_TRANSPOSE_NOT_INVERSE_HINT),
        (Jr, "that is Jr(w) itself, not its inverse"),
        (np.linalg.inv(Jr.T), "that is the inverse of the left Jacobian: the [w]×/2 term has the wrong sign"),
        (np.eye(3) + 0.5 * W, hints.FIRST_ORDER_PART_ONLY_HINT),
        (
            np.eye(3) + 0.5 * W + W @ W / 12.0,
            f"that is the one-term series I + [w]×/2 + [w]×²/12 at "
            f"θ = {np.linalg.norm(w):.2g}, off by about θ⁴/720 there: below your threshold keep the θ² term of "
            "c's series (on the page)",
        ),
    ]


def _inverse_hint(got, w, ref=None, fallback=JR_INV_FORMULA):
    return _diagnose(got, np.linalg.inv(_jr(w)), _inverse_candidates(w), fallback)


@exercise("right_jacobian_inv_so3", weight=2)
def test_right_jacobian_inv_inverts(student, ref):
    """Jr⁻¹(w) Jr(w) = I for 20 random w with angles from 1e-3 to π"""
    for w in _rotvecs(20, 671, 1e-3, np.pi):
        got = expect_array(student.right_jacobian_inv_so3(w), (3, 3), "right_jacobian_inv_so3(w)")
        expect_close(
            got @ ref.right_jacobian_so3(w),
            np.eye(3),
            1e-9,
            f"right_jacobian_inv_so3(w) @ Jr(w) at angle {np.linalg.norm(w):.4f}",
            lambda: _inverse_hint(got, w, ref),
        )


@exercise("right_jacobian_inv_so3", weight=2)
def test_right_jacobian_inv_linearises_log(student, ref):
    """Log(Exp(w) Exp(v)) ≈ w + Jr⁻¹(w) v with an error of order |v|²"""
    ws = _rotvecs(10, 672, 0.3, np.pi - 0.1)
    for w, direction in zip(ws, _unit(673, len(ws))):
        J = expect_array(student.right_jacobian_inv_so3(w), (3, 3), "right_jacobian_inv_so3(w)")
        v = 1e-4 * direction
        error = np.linalg.norm(_log(_exp(w) @ _exp(v)) - w - J @ v)
        expect(
            error <= np.dot(v, v) + 1e-13,
            f"at angle {np.linalg.norm(w):.4f}, Log(Exp(w) Exp(v)) - w - J v = {error:.2g} for |v| = 1e-4 "
            f"(expected below 1e-8)",
            lambda: _inverse_hint(J, w, ref),
        )


@exercise("right_jacobian_inv_so3", weight=2)
def test_right_jacobian_inv_tiny_angles(student):
    """w = 0 gives I (no NaN); at 1e-12, 1e-9 and 1e-7 rad it equals I + [w]×/2 + [w]×²/12"""
    _expect_identity_at_zero(
        student.right_jacobian_inv_so3(np.zeros(3)),
        "right_jacobian_inv_so3(0)",
        "the closed form is 0/0 at θ = 0: use the series of the [w]×² coefficient (on the page) below a small angle",
    )
    ws = [angle * axis for angle, axis in zip([1e-12, 1e-9, 1e-7], _unit(674, 3))]
    results = [
        (
            w,
            expect_array(
                student.right_jacobian_inv_so3(w), (3, 3), f"right_jacobian_inv_so3 at angle {np.linalg.norm(w):g}"
            ),
        )
        for w in ws
    ]
    expected = [np.eye(3) + _skew(w) / 2.0 + _skew(w) @ _skew(w) / 12.0 for w in ws]
    _expect_tiny_angles(
        results,
        expected,
        _inverse_candidates,
        "right_jacobian_inv_so3",
        "Jr⁻¹ = I + [w]×/2 + c [w]×²: below a small angle use the series of c (on the page), with its θ² term",
        sign=1.0,
    )


@exercise("right_jacobian_inv_so3", weight=2)
def test_right_jacobian_inv_every_decade(student):
    """exact to 1e-13 at every angle from 1e-12 to π (each decade, just below each power of ten), lists too"""

    def check(case):
        w, given = case
        got = expect_array(student.right_jacobian_inv_so3(given), (3, 3), "right_jacobian_inv_so3(w)")
        expect_within(
            got,
            np.linalg.inv(_jr_exact(w)),
            JR_INV_TOL,
            "right_jacobian_inv_so3(w)",
            angle_text(np.linalg.norm(w)),
            lambda: _inverse_hint(got, w),
        )

    for_all(given_forms(rotation_vectors()), check, explicit=decade_vectors())


@exercise("right_jacobian_inv_so3", weight=1)
def test_right_jacobian_inv_near_pi(student, ref):
    """stays finite and accurate at and near a half turn (θ = π, π - 1e-7, π - 1e-4)"""
    for offset, axis in zip([0.0, 1e-7, 1e-4], _unit(675, 3)):
        w = (np.pi - offset) * axis
        got = expect_array(student.right_jacobian_inv_so3(w), (3, 3), f"right_jacobian_inv_so3 at angle π - {offset:g}")
        expect_close(
            got,
            ref.right_jacobian_inv_so3(w),
            1e-8,
            f"right_jacobian_inv_so3 at angle π - {offset:g}",
            lambda: _inverse_hint(got, w, ref),
        )
