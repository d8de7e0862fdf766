"""Hidden checks for lesson 09, section 4: compound_pose_covariance.

Oracles: the first-order covariance of the definition T1 Exp(ξ1) T2 Exp(ξ2) = T1 T2 Exp(ξ), exact: ξ1 carried
across T2 by conjugation (column j of its matrix is the twist of T2⁻¹ e_j^ T2, computed as written), which
tests/test_hidden_oracles_lesson09.py holds against central differences of the definition; the Jacobians by
central differences (scipy's expm and logm-free Log via scipy's Rotation) to name slips; and a Monte-Carlo
propagation of the definition with a tolerance from the sample size. S to 1e-11 relative: the docstring's
first-order covariance is exact, and one linearised by the lesson's central differences (good to about 1e-10)
does not pass (a high-order stencil with a tuned step can pass: values alone cannot tell an accurate numerical
Jacobian from an exact one).
Core idea (3 of 6 points): carrying the first twist across T2, for rotations of T2 at every decade from 1e-12 to
π and translations up to 10 m.
Every test calls compound_pose_covariance only.
"""

import functools

import numpy as np
from coursekit import hints
from scipy.linalg import expm
from scipy.spatial.transform import Rotation

from .helpers import exercise, expect, expect_array, expect_close

ANGLES = (1e-12, 1e-9, 1e-6, 1e-4, 1e-2, 0.3, 1.0, 2.0, 3.0, np.pi - 1e-6)


def _skew(v):
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _exp_se3(xi):
    M = np.zeros((4, 4))
    M[:3, :3], M[:3, 3] = _skew(xi[3:]), xi[:3]
    return expm(M)


def _log_se3(T):
    phi = Rotation.from_matrix(T[:3, :3]).as_rotvec()
    block = np.zeros((6, 6))
    block[:3, :3], block[:3, 3:] = _skew(phi), np.eye(3)
    V = expm(block)[:3, 3:]
    return np.concatenate([np.linalg.solve(V, T[:3, 3]), phi])


def _V_batch(phi):
    """V(φ) for rotation vectors as rows, shape (N, 3) → (N, 3, 3) (Taylor terms below 1e-2 rad)."""
    theta = np.linalg.norm(phi, axis=1)[:, None, None]
    small = theta < 1e-2
    safe = np.where(small, 1.0, theta)
    t2 = theta**2
    b = np.where(small, 0.5 - t2 / 24 + t2**2 / 720, (1 - np.cos(safe)) / safe**2)
    c = np.where(small, 1.0 / 6 - t2 / 120 + t2**2 / 5040, (safe - np.sin(safe)) / safe**3)
    K = np.zeros((len(phi), 3, 3))
    K[:, 0, 1], K[:, 0, 2], K[:, 1, 2] = -phi[:, 2], phi[:, 1], -phi[:, 0]
    K = K - K.transpose(0, 2, 1)
    return np.eye(3) + b * K + c * (K @ K)


def _exp_se3_batch(xi):
    """Exp of twists [ρ, φ] as rows, shape (N, 6) → poses (N, 4, 4), in closed form."""
    T = np.zeros((len(xi), 4, 4))
    T[:, :3, :3] = Rotation.from_rotvec(xi[:, 3:]).as_matrix()
    T[:, :3, 3] = (_V_batch(xi[:, 3:]) @ xi[:, :3, None])[:, :, 0]
    T[:, 3, 3] = 1.0
    return T


def _log_se3_batch(T):
    """Log of poses, shape (N, 4, 4) → twists [ρ, φ] as rows (N, 6)."""
    phi = Rotation.from_matrix(T[:, :3, :3]).as_rotvec()
    rho = np.linalg.solve(_V_batch(phi), T[:, :3, 3:])[:, :, 0]
    return np.concatenate([rho, phi], axis=1)


@functools.lru_cache(maxsize=None)
def _monte_carlo_case():
    """The Monte-Carlo test's poses, covariances and sampled covariance (computed once per process: it is the
    same for every student)."""
    rng = np.random.default_rng(9820)
    T1 = _pose(1.2, [0.3, -0.5, 0.8], [1.0, -2.0, 0.5])
    T2 = _pose(2.1, [-0.6, 0.2, 0.4], [3.0, 1.0, -1.0])
    S1, S2 = _covariance(rng, 1e-6), _covariance(rng, 1e-6)
    draws1 = rng.multivariate_normal(np.zeros(6), S1, size=40_000)
    draws2 = rng.multivariate_normal(np.zeros(6), S2, size=40_000)
    inverse = np.linalg.inv(T1 @ T2)
    errors = _log_se3_batch(inverse @ T1 @ _exp_se3_batch(draws1) @ T2 @ _exp_se3_batch(draws2))
    for case in (T1, T2, S1, S2):
        case.setflags(write=False)
    return T1, T2, S1, S2, np.cov(errors.T)


def _pose(angle, axis, t):
    T = np.eye(4)
    T[:3, :3] = Rotation.from_rotvec(angle * np.asarray(axis) / np.linalg.norm(axis)).as_matrix()
    T[:3, 3] = t
    return T


def _covariance(rng, size):
    A = rng.normal(size=(6, 6))
    return size * (A @ A.T + 0.3 * np.eye(6))


def _pair(value):
    expect(isinstance(value, (tuple, list)) and len(value) == 2, hints.COMPOUND_PAIR_REASON)
    return expect_array(value[0], (4, 4), "T"), expect_array(value[1], (6, 6), "S")


def _linearised(T1, S1, T2, S2, h=1e-6):
    inverse = np.linalg.inv(T1 @ T2)

    def error(x):
        return _log_se3(inverse @ T1 @ _exp_se3(x[:6]) @ T2 @ _exp_se3(x[6:]))

    J = np.column_stack([(error(h * e) - error(-h * e)) / (2.0 * h) for e in np.eye(12)])
    return J[:, :6] @ S1 @ J[:, :6].T + J[:, 6:] @ S2 @ J[:, 6:].T, J


def _hat(xi):
    M = np.zeros((4, 4))
    M[:3, :3] = _skew(xi[3:])
    M[:3, 3] = xi[:3]
    return M


def exact_covariance(T1, S1, T2, S2):
    """The first-order covariance of ξ, exact: ξ ≈ C ξ1 + ξ2 with C ξ1 the twist of T2⁻¹ ξ1^ T2 (linear in ξ1)."""
    inverse = np.linalg.inv(T2)
    C = np.column_stack(
        [np.concatenate([M[:3, 3], [M[2, 1], M[0, 2], M[1, 0]]]) for M in (inverse @ _hat(e) @ T2 for e in np.eye(6))]
    )
    return C @ S1 @ C.T + S2


EXACT = 1e-11  # relative; Jacobians by central differences leave about 1.5e-10
FINITE_DIFFERENCES_HINT = hints.COMPOUND_FINITE_DIFFERENCES_HINT


def _adjoint_of(T):
    """Ad_T from its definition: column j is the twist of T e_j^ T⁻¹ (central differences of Exp)."""
    inverse = np.linalg.inv(T)
    return np.column_stack([_log_se3(T @ _exp_se3(1e-7 * e) @ inverse) / 1e-7 for e in np.eye(6)])


def _parts_hint(student, T1, S1, T2, S2):
    """Which part of S is wrong, told from the student's own S with S2 = 0 (the part from S1) and with S1 = 0."""
    zero = np.zeros((6, 6))
    scale = np.max(np.abs(S1)) + np.max(np.abs(S2))
    try:
        _, from_s1 = _pair(student.compound_pose_covariance(T1, S1, T2, zero))
        _, from_s2 = _pair(student.compound_pose_covariance(T1, zero, T2, S2))
    except Exception:  # noqa: BLE001 - the test itself reports the failure
        return ""
    s1_right = np.max(np.abs(from_s1 - exact_covariance(T1, S1, T2, zero))) <= 1e-9 * scale
    s2_right = np.max(np.abs(from_s2 - S2)) <= 1e-9 * scale
    if s1_right and s2_right:
        return hints.COMPOUND_NOT_A_SUM_HINT
    if s2_right:
        return hints.COMPOUND_S1_PART_HINT
    return hints.COMPOUND_S2_PART_HINT if s1_right else hints.COMPOUND_BOTH_PARTS_HINT


def _hint(student, S, T1, S1, T2, S2):
    _, J = _linearised(T1, S1, T2, S2)
    A = J[:, :6]
    R2 = np.kron(np.eye(2), T2[:3, :3].T)
    B = np.linalg.inv(A)
    slips = [
        (S1 + S2, hints.COMPOUND_IGNORES_T2_HINT),
        (B @ S1 @ B.T + S2, hints.COMPOUND_INVERTED_T2_HINT),
        (R2 @ S1 @ R2.T + S2, hints.COMPOUND_SHIFT_IGNORED_HINT),
        (A @ S1 + S2, "a covariance takes the linear map on both sides"),
        (
            _adjoint_of(np.linalg.inv(T1)) @ S1 @ _adjoint_of(np.linalg.inv(T1)).T + S2,
            hints.COMPOUND_DEPENDS_ON_T1_HINT,
        ),
    ]
    scale = np.max(np.abs(S1)) + np.max(np.abs(S2))
    matching = [hint for value, hint in slips if np.max(np.abs(S - value)) <= 1e-6 * scale]
    # two slips that agree at this input (T2 barely turning) cannot be told apart here: name neither
    return matching[0] if len(matching) == 1 else _parts_hint(student, T1, S1, T2, S2)


def compound_cases(seed=9800):
    """(angle, T1, S1, T2, S2) for T2 turning by each of ANGLES and shifted up to 10 m."""
    rng = np.random.default_rng(seed)
    for angle in ANGLES:
        T1 = _pose(rng.uniform(0, 3), rng.normal(size=3), rng.normal(size=3))
        T2 = _pose(angle, rng.normal(size=3), rng.uniform(0.1, 10.0) * rng.normal(size=3) / np.sqrt(3))
        yield angle, T1, _covariance(rng, 1e-3), T2, _covariance(rng, 1e-3)


@exercise("compound_pose_covariance", weight=3)
def test_compound_every_angle(student):
    """S equals the first-order covariance to 1e-11 (relative), for T2 turning 1e-12 to π rad and shifted up to 10 m"""
    for angle, T1, S1, T2, S2 in compound_cases():
        _, S = _pair(student.compound_pose_covariance(T1, S1, T2, S2))
        expected = exact_covariance(T1, S1, T2, S2)
        scale = np.max(np.abs(expected))
        near = np.max(np.abs(S - expected)) <= 1e-7 * scale
        expect_close(
            S / scale,
            expected / scale,
            EXACT,
            f"S / |S| for T2 turning {angle:.3g} rad",
            lambda: FINITE_DIFFERENCES_HINT if near else _hint(student, S, T1, S1, T2, S2),
        )


@exercise("compound_pose_covariance", weight=1)
def test_compound_pose(student):
    """T equals T1 T2 to 1e-12 (relative to the translations)"""
    rng = np.random.default_rng(9810)
    for angle in ANGLES[::3]:
        T1 = _pose(1.0, rng.normal(size=3), 3 * rng.normal(size=3))
        T2 = _pose(angle, rng.normal(size=3), 3 * rng.normal(size=3))
        T, _ = _pair(student.compound_pose_covariance(T1, 1e-3 * np.eye(6), T2, 1e-3 * np.eye(6)))
        hint = "T2 T1 is the other chain" if np.allclose(T, T2 @ T1, atol=1e-9) else ""
        expect_close(T, T1 @ T2, 1e-12, f"T for T2 turning {angle:.3g} rad", hint, scale=10.0)


@exercise("compound_pose_covariance", weight=1)
def test_compound_exact_when_nothing_is_carried(student):
    """with T2 = I: S equals S1 + S2 to 1e-9 (relative), for covariances whose digits need float64"""
    rng = np.random.default_rng(9815)
    for size in (1e-8, 1e-3, 1.0):
        T1 = _pose(rng.uniform(0, 3), rng.normal(size=3), 3 * rng.normal(size=3))
        S1, S2 = _covariance(rng, size), _covariance(rng, size)
        _, S = _pair(student.compound_pose_covariance(T1, S1, np.eye(4), S2))
        scale = np.max(np.abs(S1 + S2))
        near = np.max(np.abs(S - (S1 + S2))) <= 1e-5 * scale  # near: digits lost; far: the other tests say why
        expect_close(
            S / scale,
            (S1 + S2) / scale,
            1e-9,
            f"S with T2 = I (covariances of size {size:g})",
            hints.COMPOUND_PRECISION_HINT if near else "",
        )


@exercise("compound_pose_covariance", weight=1)
def test_compound_against_monte_carlo(student):
    """S agrees with the covariance of 40 000 sampled chains (twists drawn, composed exactly) within 4 %"""
    T1, T2, S1, S2, sampled = _monte_carlo_case()
    _, S = _pair(student.compound_pose_covariance(T1.copy(), S1.copy(), T2.copy(), S2.copy()))
    scale = np.max(np.abs(sampled))
    # sample covariance entries scatter by about sqrt(2 / 40 000) = 0.7 % of the scale: 4 % is over five of those
    expect_close(
        S / scale, sampled / scale, 0.04, "S / |S| against Monte Carlo", lambda: _hint(student, S, T1, S1, T2, S2)
    )


@exercise("compound_pose_covariance", weight=1)
def test_compound_lists_and_inputs(student):
    """accepts plain lists, leaves its inputs unchanged, and returns a symmetric S"""
    rng = np.random.default_rng(9830)
    args = (
        _pose(0.7, [1, 2, 3], [1, 0, 2]),
        _covariance(rng, 1e-3),
        _pose(1.9, [0, 1, -1], [0, 3, 1]),
        _covariance(rng, 1e-3),
    )
    copies = [a.copy() for a in args]
    T, S = _pair(student.compound_pose_covariance(*copies))
    expect(
        all(np.array_equal(a, b) for a, b in zip(args, copies)),
        "compound_pose_covariance changed its inputs",
        "work on copies",
    )
    T_lists, S_lists = _pair(student.compound_pose_covariance(*[a.tolist() for a in args]))
    scale = np.max(np.abs(S))
    expect_close(T_lists, T, 1e-14, "T with lists", "convert every argument with np.asarray(x, dtype=float)")
    expect_close(
        S_lists / scale, S / scale, 1e-14, "S with lists", "convert every argument with np.asarray(x, dtype=float)"
    )
    expect_close(
        S / scale, S.T / scale, 1e-12, "S against its transpose", "a covariance takes the linear map on both sides"
    )
