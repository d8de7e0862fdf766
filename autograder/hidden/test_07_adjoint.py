"""Hidden checks for lesson 07, section 10: adjoint_se3, jacobian_transform_point and right_jacobian_se3.

Independent oracles: scipy's ``Rotation`` and ``expm`` (for T Exp(ξ) T⁻¹ and T Exp(ξ) p), finite differences
of each definition taken here, and, for the Jacobian of Exp, J_r(ξ) = ∫₀¹ exp(-s ad_ξ) ds read off scipy's
matrix exponential of the 12×12 block matrix [[-ad_ξ, I], [0, 0]].

Core ideas carry at least half of each exercise's points, so the classic mistake earns at most half: the
coupling block [t]× R of the adjoint (the defining identity T Exp(ξ) T⁻¹ = Exp(Ad ξ), 3 of 6); both blocks of
the point Jacobian carry R (3 of 5); the coupling block of J_r(ξ), exact at every decade of angle from 1e-12 to
π - 1e-9 (3 of 6). Tolerances: the adjoint to 1e-12 (1 + |t|) |ξ|; the point Jacobian to 1e-12 |p|; J_r to
1e-11 (1 + |ρ|), which every exact route meets (series, closed form, quadrature) and finite differences do
not. Every test calls the student's function of its own exercise only.
"""

import numpy as np
from scipy.linalg import expm, logm
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect_array, expect_close, expect_same_with_lists, fmt, random_rotations

ANGLES = (1.0, 2.5, 3.0, np.pi - 1e-9, 1e-12, 1e-9, 1e-6, 1e-4, 1e-3, 1e-2 - 1e-9, 1e-2, 0.1, 0.3)


# ---------------------------------------------------------------- oracles written out here
def _skew(v):
    """[v]×, built column by column: its column j is v × e_j."""
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _twist_matrix(xi):
    M = np.zeros((4, 4))
    M[:3, :3], M[:3, 3] = _skew(xi[3:]), xi[:3]
    return M


def _exp_se3(xi):
    T = expm(_twist_matrix(np.asarray(xi, dtype=float)))
    T[3] = [0.0, 0.0, 0.0, 1.0]
    return T


def _log_se3_near_identity(T):
    M = np.real(logm(T))
    return np.array([M[0, 3], M[1, 3], M[2, 3], M[2, 1], M[0, 2], M[1, 0]])


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


# ---------------------------------------------------------------- adjoint_se3
def _adjoint(R, t, layout="right"):
    Ad = np.zeros((6, 6))
    Ad[:3, :3], Ad[3:, 3:] = R, R
    coupling = {
        "right": _skew(t) @ R,
        "none": np.zeros((3, 3)),
        "no_R": _skew(t),
        "sign": -_skew(t) @ R,
        "R_first": R @ _skew(t),
    }
    if layout == "rotation_first":
        Ad[3:, :3] = _skew(t) @ R
    else:
        Ad[:3, 3:] = coupling[layout]
    return Ad


def _adjoint_hint(got, T):
    R, t = T[:3, :3], T[:3, 3]
    truth = _adjoint(R, t)
    return (
        _first_explained(
            got,
            [
                (_adjoint(R, t, "rotation_first"), hints.ADJOINT_SPIN_FROM_SHIFT_HINT),
                (_adjoint(R, t, "none"), hints.ADJOINT_SPIN_WITHOUT_SHIFT_HINT),
                (_adjoint(R, t, "no_R"), hints.ADJOINT_COUPLING_WITHOUT_R_HINT),
                (_adjoint(R, t, "sign"), hints.ADJOINT_SPIN_SHIFT_SIGN_HINT),
                (_adjoint(R, t, "R_first"), hints.ADJOINT_COUPLING_IDENTITY_HINT),
                (
                    _adjoint(R.T, t),
                    "your Ad_T turns twists the opposite way from T ξ^ T⁻¹: compare the spin part of Ad_T [0, phi] "
                    "with that of (T ξ^ T⁻¹)∨ at a pure turn",
                ),
            ],
            truth,
        )
        or hints.ADJOINT_DEFINITION_HINT
    )


@exercise("adjoint_se3", weight=3)
def test_adjoint_defining_identity(student):
    """T Exp(ξ) T⁻¹ = Exp(Ad_T ξ) for 8 poses (|t| from 1e-3 to 30 m) and twists of size 1e-6 to 2:
    Ad_T ξ to 1e-12 (1 + |t|) |ξ|, the poses to 1e-9 (1 + |t|)"""
    rng = np.random.default_rng(9000)
    for T, scale in zip(_random_poses(8, 9001), (1e-3, 0.1, 1.0, 1.0, 3.0, 10.0, 30.0, 0.5)):
        T[:3, 3] *= scale / np.linalg.norm(T[:3, 3])
        Ad = expect_array(student.adjoint_se3(T), (6, 6), "adjoint_se3(T)")
        for size in (1e-6, 0.1, 2.0):
            xi = size * rng.normal(size=6) / np.sqrt(6.0)
            expect_close(
                Ad @ xi,
                _adjoint(T[:3, :3], T[:3, 3]) @ xi,
                1e-12 * size,
                f"Ad_T ξ for |t| = {scale:g} m and |ξ| ≈ {size:g}",
                lambda: _adjoint_hint(Ad, T),
                scale=1.0 + scale,
            )
            conjugated = T @ _exp_se3(xi) @ np.linalg.inv(T)
            expect_close(
                _exp_se3(Ad @ xi),
                conjugated,
                1e-9,
                f"Exp(Ad_T ξ) against T Exp(ξ) T⁻¹ for |t| = {scale:g} m and |ξ| ≈ {size:g}",
                lambda: _adjoint_hint(Ad, T),
                scale=1.0 + scale,
            )


@exercise("adjoint_se3", weight=1)
def test_adjoint_group_laws(student):
    """Ad(T1 T2) = Ad(T1) Ad(T2) and Ad(T⁻¹) = Ad(T)⁻¹ for 4 pairs of poses, to 1e-10 (1 + |t|²)"""
    firsts, seconds = _random_poses(4, 9010, 2.0), _random_poses(4, 9020, 2.0)
    for T1, T2 in zip(firsts, seconds):
        A1 = expect_array(student.adjoint_se3(T1), (6, 6), "adjoint_se3(T1)")
        A2 = expect_array(student.adjoint_se3(T2), (6, 6), "adjoint_se3(T2)")
        A12 = expect_array(student.adjoint_se3(T1 @ T2), (6, 6), "adjoint_se3(T1 T2)")
        size = 1.0 + np.linalg.norm(T1[:3, 3]) ** 2 + np.linalg.norm(T2[:3, 3]) ** 2
        expect_close(
            A12, A1 @ A2, 1e-10, "Ad(T1 T2) against Ad(T1) Ad(T2)", lambda: _adjoint_hint(A12, T1 @ T2), scale=size
        )
        inverse = expect_array(student.adjoint_se3(np.linalg.inv(T1)), (6, 6), "adjoint_se3(T⁻¹)")
        expect_close(inverse @ A1, np.eye(6), 1e-10, "Ad(T⁻¹) Ad(T)", lambda: _adjoint_hint(A1, T1), scale=size)


@exercise("adjoint_se3", weight=1)
def test_adjoint_pure_motions(student):
    """exact (to 1e-14) for pure rotations and pure translations, and Ad(I) = I"""
    for R in random_rotations(3, 9030):
        got = expect_array(student.adjoint_se3(_pose(R, np.zeros(3))), (6, 6), "adjoint_se3 of a pure rotation")
        expect_close(
            got,
            _adjoint(R, np.zeros(3)),
            1e-14,
            "adjoint_se3 of a pure rotation",
            "at a pure turn (t = 0), Ad_T ξ must be the twist of T ξ^ T⁻¹: compare a pure shift [rho, 0] and a "
            "pure spin [0, phi] on their own",
        )
    for t in ([1.0, 0.0, 0.0], [0.0, -2.0, 3.0]):
        T = _pose(np.eye(3), t)
        got = expect_array(student.adjoint_se3(T), (6, 6), "adjoint_se3 of a pure translation")
        expect_close(
            got,
            _adjoint(np.eye(3), np.asarray(t)),
            1e-14,
            f"adjoint_se3 of a shift by {fmt(t)}",
            lambda: _adjoint_hint(got, T),
        )
    expect_close(
        expect_array(student.adjoint_se3(np.eye(4)), (6, 6), "adjoint_se3(I)"), np.eye(6), 0.0, "adjoint_se3(I)"
    )


@exercise("adjoint_se3", weight=1)
def test_adjoint_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    expect_same_with_lists(student.adjoint_se3, (_random_poses(1, 9040, 2.0)[0],), (6, 6), "adjoint_se3(T)")


# ---------------------------------------------------------------- jacobian_transform_point
def _point_jacobian(T, p, kind="right"):
    R, t = T[:3, :3], T[:3, 3]
    p = np.asarray(p, dtype=float)
    return {
        "right": np.hstack([R, -R @ _skew(p)]),
        "rotation_first": np.hstack([-R @ _skew(p), R]),
        "translation_I": np.hstack([np.eye(3), -R @ _skew(p)]),
        "left": np.hstack([np.eye(3), -_skew(R @ p + t)]),
        "sign": np.hstack([R, R @ _skew(p)]),
        "world_rotation": np.hstack([R, -_skew(R @ p)]),
    }[kind]


def _point_hint(J, T, p):
    return (
        _first_explained(
            J,
            [
                (_point_jacobian(T, p, "rotation_first"), "xi = [rho, phi]: the first three columns are for rho"),
                (
                    _point_jacobian(T, p, "translation_I"),
                    "the rho block is off: for a small shift, T Exp([rho, 0]) p - T p must equal J [rho, 0] to first order",
                ),
                (_point_jacobian(T, p, "left"), "[I, -[T p]×] is the Jacobian of the left perturbation Exp(xi) T"),
                (_point_jacobian(T, p, "sign"), hints.SIGN_ROTATION_BLOCK_PHI_HINT),
                (
                    _point_jacobian(T, p, "world_rotation"),
                    "-[R p]× is the rotation block of a left perturbation; for T Exp(xi) the turn is about body axes",
                ),
            ],
            _point_jacobian(T, p),
        )
        or "expand T (I + ξ^) [p; 1] to first order and collect what multiplies rho and what multiplies phi"
    )


@exercise("jacobian_transform_point", weight=3)
def test_point_jacobian_exact(student):
    """equals the exact Jacobian to 1e-12 |p| for 8 poses and points with |p| from 1e-6 to 1e3 m"""
    rng = np.random.default_rng(9300)
    for T, size in zip(_random_poses(8, 9301, 5.0), (1e-6, 1e-3, 0.1, 1.0, 2.0, 10.0, 100.0, 1e3)):
        p = size * rng.normal(size=3) / np.sqrt(3.0)
        J = expect_array(student.jacobian_transform_point(T, p), (3, 6), "jacobian_transform_point(T, p)")
        expect_close(
            J,
            _point_jacobian(T, p),
            1e-12,
            f"jacobian_transform_point for |p| ≈ {size:g} m",
            lambda: _point_hint(J, T, p),
            scale=size,
        )


@exercise("jacobian_transform_point", weight=1)
def test_point_jacobian_finite_differences(student):
    """matches central differences of T Exp(ξ) p (scipy's expm) to 1e-8 (1 + |p|)"""
    rng = np.random.default_rng(9310)
    for T in _random_poses(4, 9311, 2.0):
        p = 2.0 * rng.normal(size=3)
        J = expect_array(student.jacobian_transform_point(T, p), (3, 6), "jacobian_transform_point(T, p)")
        numeric = _central(lambda xi: (T @ _exp_se3(xi) @ np.append(p, 1.0))[:3], 6)
        expect_close(
            J,
            numeric,
            1e-8,
            "jacobian_transform_point against finite differences",
            lambda: _point_hint(J, T, p),
            scale=1.0 + np.linalg.norm(p),
        )


@exercise("jacobian_transform_point", weight=1)
def test_point_jacobian_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    T = _random_poses(1, 9320, 2.0)[0]
    expect_same_with_lists(
        student.jacobian_transform_point, (T, [0.3, -1.2, 2.0]), (3, 6), "jacobian_transform_point(T, p)"
    )


# ---------------------------------------------------------------- right_jacobian_se3
def _ad(xi):
    xi = np.asarray(xi, dtype=float)
    A = np.zeros((6, 6))
    A[:3, :3] = A[3:, 3:] = _skew(xi[3:])
    A[:3, 3:] = _skew(xi[:3])
    return A


def _jr_se3(xi):
    """∫₀¹ exp(-s ad_ξ) ds, the top-right block of expm([[-ad_ξ, I], [0, 0]])."""
    block = np.zeros((12, 12))
    block[:6, :6] = -_ad(xi)
    block[:6, 6:] = np.eye(6)
    return expm(block)[:6, 6:]


def _truncated(xi, terms):
    A, S = -_ad(xi), np.eye(6)
    for k in range(terms, 0, -1):
        S = np.eye(6) + A @ S / (k + 1)
    return S


def _jr_hint(got, xi):
    truth = _jr_se3(xi)
    no_coupling = truth.copy()
    no_coupling[:3, 3:] = 0.0
    flipped = truth.copy()
    flipped[:3, 3:] *= -1.0
    candidates = [
        (no_coupling, hints.JR_SE3_NO_COUPLING_HINT),
        (flipped, hints.JR_SE3_COUPLING_SIGN_HINT),
        (_jr_se3(-np.asarray(xi, dtype=float)), "that is the left Jacobian: Exp(ξ + dξ) ≈ Exp(J dξ) Exp(ξ)"),
        (np.linalg.inv(truth), "that is J⁻¹, the Jacobian of Log; return the Jacobian of Exp"),
    ]
    candidates += [
        (_truncated(xi, terms), "a series cut off after a few terms: near π it needs many more")
        for terms in range(1, 12)
    ]
    hint = _first_explained(got, candidates, truth)
    if hint:
        return hint
    error = np.max(np.abs(np.asarray(got, dtype=float) - truth)) / (1.0 + np.linalg.norm(xi[:3]))
    if error < 1e-5:
        return hints.JR_SE3_DIFFERENCES_HINT.format(error=f"{error:.2g} relative")
    return (
        "J_r(ξ) = ∫₀¹ Ad_Exp(-s ξ) ds: compare your J with central differences of Log(Exp(ξ)⁻¹ Exp(ξ + dξ)), "
        "part by part"
    )


def _twists(seed, angles, rho_sizes):
    rng = np.random.default_rng(seed)
    axes = _unit(seed + 1, len(angles))
    for angle, axis, size in zip(angles, axes, rho_sizes):
        rho = rng.normal(size=3)
        rho *= size / np.linalg.norm(rho)
        yield np.concatenate([rho, angle * axis])


@exercise("right_jacobian_se3", weight=3)
def test_jr_se3_every_angle(student):
    """equals ∫₀¹ Ad_Exp(-s ξ) ds to 1e-11 (1 + |ρ|) at every decade of angle from 1e-12 to π - 1e-9, |ρ| ≈ 2 m"""
    for xi in _twists(9500, ANGLES, [2.0] * len(ANGLES)):
        J = expect_array(student.right_jacobian_se3(xi), (6, 6), "right_jacobian_se3(xi)")
        expect_close(
            J,
            _jr_se3(xi),
            1e-11,
            f"right_jacobian_se3 at θ = {np.linalg.norm(xi[3:]):.3g}, |ρ| = 2",
            lambda: _jr_hint(J, xi),
            scale=1.0 + np.linalg.norm(xi[:3]),
        )


@exercise("right_jacobian_se3", weight=1)
def test_jr_se3_large_and_small_translations(student):
    """to 1e-11 (1 + |ρ|) for |ρ| from 0 to 1e3 m, θ = 0 included"""
    angles = (0.7, 3.0, 1e-8, 0.0, 0.0, 2.0, 1e-3)
    sizes = (1e3, 1e3, 1e3, 1e3, 0.0, 0.0, 1e-3)
    for xi in _twists(9510, angles, sizes):
        xi = np.nan_to_num(xi)
        J = expect_array(student.right_jacobian_se3(xi), (6, 6), "right_jacobian_se3(xi)")
        expect_close(
            J,
            _jr_se3(xi),
            1e-11,
            f"right_jacobian_se3 at θ = {np.linalg.norm(xi[3:]):.3g}, |ρ| = {np.linalg.norm(xi[:3]):.3g}",
            lambda: _jr_hint(J, xi),
            scale=1.0 + np.linalg.norm(xi[:3]),
        )


@exercise("right_jacobian_se3", weight=1)
def test_jr_se3_defining_property(student):
    """Log(Exp(ξ)⁻¹ Exp(ξ + dξ)) ≈ J dξ, by central differences (scipy's expm and logm), to 1e-7 (1 + |ρ|)"""
    for xi in _twists(9520, (0.4, 1.7, 2.9, 1e-5), (1.0, 3.0, 0.5, 2.0)):
        J = expect_array(student.right_jacobian_se3(xi), (6, 6), "right_jacobian_se3(xi)")
        base_inverse = np.linalg.inv(_exp_se3(xi))
        numeric = _central(lambda d: _log_se3_near_identity(base_inverse @ _exp_se3(xi + d)), 6)
        expect_close(
            J,
            numeric,
            1e-7,
            f"right_jacobian_se3 against finite differences at ξ = {fmt(xi)}",
            lambda: _jr_hint(J, xi),
            scale=1.0 + np.linalg.norm(xi[:3]),
        )


@exercise("right_jacobian_se3", weight=1)
def test_jr_se3_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    expect_same_with_lists(
        student.right_jacobian_se3, ([0.8, -1.5, 1.1, 0.6, -0.3, 0.7],), (6, 6), "right_jacobian_se3(xi)"
    )
