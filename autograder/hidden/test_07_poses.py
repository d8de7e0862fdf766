"""Hidden checks for lesson 07: poses and rigid-body transformations.

Independent oracles: plain block algebra for poses, scipy's general matrix
exponential ``scipy.linalg.expm`` of the 4×4 twist matrix for the exponential
map, and group laws (composition, inverse, round trips). Every test calls the
student's function of its own exercise only; inputs are built here.

Tolerances scale with the inputs: at tiny rotation parts (|phi| from 1e-12
to 9e-3) exp_se3 and log_se3 must be off by at most 1e-12 |rho| (1e-11 for
the log), with |rho| up to 50, so a V or c(θ) guarded only at θ = 0 (whose
W coefficient is 0 instead of 1/2 once cos θ rounds to 1) or computed with
the cancelling closed form is caught. Over the whole domain (properties drawn by Hypothesis, derandomized, see ``properties.py``):
exp_se3 and log_se3 are within 5e-14 max(1, |rho|) of scipy's expm (and of the twist itself) at every
angle of phi from 1e-12 to π (3 for the log), each decade and just below each power of ten, |rho| up to 50.
Lists are compared with the same
function's answer for arrays.
"""

import numpy as np
from hypothesis import strategies as st
from scipy.linalg import expm
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.checks.lesson01 import SQUARE_BATCH_HINT
from coursekit.diagnose import as_float_array, close

from .properties import GENERIC_AXIS, as_given, decade_edges, expect_within, for_all, points, rotation_vectors
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
)

TOL = 1e-9
SE3_TOL = 5e-14  # exp_se3 and log_se3 at every angle of phi from 1e-12 to π: within 5e-14 max(1, |rho|)
MIRROR_HINT = "xi = [rho, phi]: the translation part comes first, the rotation part last"


# ---------------------------------------------------------------- building blocks of the tests
def _pose(R, t):
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = t
    return T


def _random_poses(count, seed, scale=2.0):
    rng = np.random.default_rng(seed)
    return [_pose(R, scale * rng.normal(size=3)) for R in random_rotations(count, seed + 1000)]


def _inverse(T):
    R, t = T[:3, :3], T[:3, 3]
    return _pose(R.T, -R.T @ t)


def _twist_matrix(xi):
    rho, phi = xi[:3], xi[3:]
    M = np.zeros((4, 4))
    M[:3, :3] = [[0.0, -phi[2], phi[1]], [phi[2], 0.0, -phi[0]], [-phi[1], phi[0], 0.0]]
    M[:3, 3] = rho
    return M


def _exp(xi):
    return expm(_twist_matrix(np.asarray(xi, dtype=float)))


def _v_matrix(phi):
    """V(phi) from expm: the top-right block of exp of [[W, e_j], [0, 0]] is V e_j."""
    V = np.empty((3, 3))
    for j in range(3):
        V[:, j] = _exp(np.concatenate([np.eye(3)[j], phi]))[:3, 3]
    return V


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def _twist(rho, angle, axis):
    return np.concatenate([np.asarray(rho, dtype=float), angle * _unit(axis)])


def _random_twists(count, seed, max_angle):
    rng = np.random.default_rng(seed)
    return [_twist(rng.normal(size=3), rng.uniform(0.0, max_angle), rng.normal(size=3)) for _ in range(count)]


SERIES_HINT_V = hints.V_SERIES_TINY_ANGLE_HINT
SERIES_NAN_HINT_V = (
    "NaN or inf at a tiny angle: the closed forms of V's coefficients divide 0 by 0 at θ = 0; "
    "below θ = 1e-2 use their Taylor series, each with its θ² term"
)
SERIES_HINT_C = hints.SMALL_ANGLE_SERIES_HINT


def _expect_finite(value, what, hint):
    """Fail with ``hint`` when a numeric answer holds NaN or inf."""
    numbers = as_float_array(value)
    if numbers is not None:
        expect(bool(np.all(np.isfinite(numbers))), f"{what} returned NaN or inf values", hint)


def _close(a, b, tol=1e-9):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.max(np.abs(a - b), initial=0.0) <= tol)


def _first_match(got, truth, candidates, general):
    """The hint of the first candidate (a mistake's value computed from the inputs) that ``got`` equals."""
    for candidate, hint in candidates:
        if not _close(candidate, truth, 1e-6) and _close(got, candidate):
            return hint
    return general


def _expect_pose(T, what):
    expect_close(
        T[3],
        [0.0, 0.0, 0.0, 1.0],
        1e-12,
        f"{what}: the bottom row",
        "a pose's bottom row is [0, 0, 0, 1]: the translation belongs in the last column",
    )
    problem = rotation_problem(T[:3, :3], 1e-8)
    expect(problem is None, f"{what}: the rotation block is not a rotation ({problem})")


# ---------------------------------------------------------------- make_pose
@exercise("make_pose", weight=3)
def test_make_pose_blocks(student):
    """puts R top-left, t in the last column and [0, 0, 0, 1] below, for 10 random poses"""
    rng = np.random.default_rng(701)
    for R in random_rotations(10, seed=702):
        t = rng.normal(size=3)
        got = expect_array(student.make_pose(R, t), (4, 4), "make_pose(R, t)")
        bottom_row = np.eye(4)
        bottom_row[:3, :3], bottom_row[3, :3] = R, t
        no_one = _pose(R, t)
        no_one[3, 3] = 0.0
        hint = _first_match(
            got,
            _pose(R, t),
            [
                (_pose(R, t).T, "t belongs in the last column, not the bottom row (this is the transpose of T)"),
                (bottom_row, "t belongs in the last column, not the bottom row"),
                (_pose(R.T, t), "the top-left block holds Rᵀ: copy R itself, not its transpose"),
                (no_one, "T[3, 3] is 0: a pose's bottom row is [0, 0, 0, 1] (start from np.eye(4), not np.zeros)"),
            ],
            "T = [[R, t], [0, 0, 0, 1]]: R in T[:3, :3], t in T[:3, 3], and T[3] = [0, 0, 0, 1]",
        )
        expect_close(got, _pose(R, t), 1e-12, "make_pose(R, t)", hint)


@exercise("make_pose", weight=1)
def test_make_pose_accepts_lists(student):
    """accepts plain lists (and integers)"""
    expect_same_with_lists(
        student.make_pose,
        (np.eye(3), [1.0, 2.0, 3.0]),
        (4, 4),
        "make_pose(I, [1, 2, 3])",
        lists=(np.eye(3, dtype=int).tolist(), [1, 2, 3]),
    )


# ---------------------------------------------------------------- pose_inverse
def _inverse_hint(got, T):
    R, t = T[:3, :3], T[:3, 3]
    return _first_match(
        got,
        _inverse(T),
        [
            (
                T.T,
                "that is the plain transpose of T: a pose is not orthogonal, and Tᵀ puts t in the bottom row "
                "without undoing the shift",
            ),
            (_pose(R.T, -t), hints.INVERSE_TRANSLATION_FRAME_HINT),
            (_pose(R.T, t), hints.KEPT_T_UNCHANGED_INVERSE_HINT),
            (_pose(R, -R @ t), hints.ROTATION_BLOCK_INVERSE_RT_HINT),
        ],
        hints.INVERSE_R_T_RT_HINT,
    )


@exercise("pose_inverse", weight=3)
def test_pose_inverse_formula(student):
    """returns the inverse matrix of T for 20 random poses"""
    for T in _random_poses(20, seed=711):
        got = expect_array(student.pose_inverse(T), (4, 4), "pose_inverse(T)")
        expect_close(got, _inverse(T), TOL, "pose_inverse(T)", lambda: _inverse_hint(got, T))


@exercise("pose_inverse", weight=2)
def test_pose_inverse_undoes(student):
    """T @ pose_inverse(T) and pose_inverse(T) @ T are the identity; the inverse of the inverse is T"""
    for T in _random_poses(10, seed=712, scale=5.0):
        inverse = expect_array(student.pose_inverse(T), (4, 4), "pose_inverse(T)")
        expect_close(T @ inverse, np.eye(4), TOL, "T @ pose_inverse(T)", lambda: _inverse_hint(inverse, T))
        expect_close(inverse @ T, np.eye(4), TOL, "pose_inverse(T) @ T")
        again = expect_array(student.pose_inverse(inverse), (4, 4), "pose_inverse(pose_inverse(T))")
        expect_close(again, T, TOL, "pose_inverse(pose_inverse(T))")


@exercise("pose_inverse", weight=1)
def test_pose_inverse_of_a_chain(student):
    """the inverse of T_ab T_bc is T_bc⁻¹ T_ab⁻¹ (frame chain walked backwards); lists work too"""
    poses = _random_poses(6, seed=713)
    for T_ab, T_bc in zip(poses[::2], poses[1::2]):
        whole = expect_array(student.pose_inverse(T_ab @ T_bc), (4, 4), "pose_inverse(T_ab @ T_bc)")
        parts = expect_array(student.pose_inverse(T_bc), (4, 4), "pose_inverse(T_bc)") @ expect_array(
            student.pose_inverse(T_ab), (4, 4), "pose_inverse(T_ab)"
        )
        expect_close(
            whole,
            parts,
            TOL,
            "pose_inverse(T_ab T_bc) vs pose_inverse(T_bc) pose_inverse(T_ab)",
            lambda: _inverse_hint(whole, T_ab @ T_bc),
        )
    expect_same_with_lists(student.pose_inverse, (poses[0],), (4, 4), "pose_inverse(T)")


# ---------------------------------------------------------------- pose_compose
def _compose_hint(got, T_ab, T_bc):
    added = T_ab @ T_bc
    added[:3, 3] = T_ab[:3, 3] + T_bc[:3, 3]
    return _first_match(
        got,
        T_ab @ T_bc,
        [
            (T_bc @ T_ab, "the order is reversed: T_ac = T_ab @ T_bc"),
            (T_ab * T_bc, "* multiplies entry by entry: compose poses with the matrix product @"),
            (added, "t_ab + t_bc: t_bc must be turned by R_ab first, t_ac = R_ab t_bc + t_ab"),
            (T_ab.T @ T_bc, hints.TRANSPOSES_T_AB_T_HINT),
        ],
        "T_ac = T_ab @ T_bc: R_ac = R_ab R_bc, t_ac = R_ab t_bc + t_ab",
    )


@exercise("pose_compose", weight=3)
def test_pose_compose_random(student):
    """T_ac = T_ab T_bc for 20 random pairs"""
    poses = _random_poses(40, seed=721)
    for T_ab, T_bc in zip(poses[::2], poses[1::2]):
        got = expect_array(student.pose_compose(T_ab, T_bc), (4, 4), "pose_compose(T_ab, T_bc)")
        expect_close(got, T_ab @ T_bc, TOL, "pose_compose(T_ab, T_bc)", lambda: _compose_hint(got, T_ab, T_bc))


@exercise("pose_compose", weight=2)
def test_pose_compose_frame_chain(student):
    """world → robot → camera: a camera point reaches the world the same way in one step or two"""
    T_wr, T_rc = _random_poses(2, seed=722, scale=3.0)
    T_wc = expect_array(student.pose_compose(T_wr, T_rc), (4, 4), "pose_compose(T_wr, T_rc)")
    points_c = np.random.default_rng(723).normal(size=(6, 3)) * 4.0
    for p_c in points_c:
        p_w_two_steps = T_wr[:3, :3] @ (T_rc[:3, :3] @ p_c + T_rc[:3, 3]) + T_wr[:3, 3]
        expect_close(
            T_wc[:3, :3] @ p_c + T_wc[:3, 3],
            p_w_two_steps,
            TOL,
            "a camera point mapped with pose_compose(T_wr, T_rc)",
            lambda: _compose_hint(T_wc, T_wr, T_rc),
        )


@exercise("pose_compose", weight=1)
def test_pose_compose_laws(student):
    """is associative, has the identity as neutral element and stays a pose"""
    A, B, C = _random_poses(3, seed=724)
    AB = expect_array(student.pose_compose(A, B), (4, 4), "pose_compose(A, B)")
    BC = expect_array(student.pose_compose(B, C), (4, 4), "pose_compose(B, C)")
    left = expect_array(student.pose_compose(AB, C), (4, 4), "pose_compose(AB, C)")
    right = expect_array(student.pose_compose(A, BC), (4, 4), "pose_compose(A, BC)")
    expect_close(left, right, TOL, "(A B) C vs A (B C)", lambda: _compose_hint(AB, A, B))
    _expect_pose(AB, "pose_compose(A, B)")
    expect_close(
        expect_array(student.pose_compose(A, np.eye(4)), (4, 4), "pose_compose(A, I)"), A, TOL, "pose_compose(A, I)"
    )


# ---------------------------------------------------------------- to_homogeneous
ROW_HINT = (
    "a row of ones was added below the points: append a column, the new coordinate belongs to every point (axis=-1)"
)


def _homogeneous_hint(got, P):
    ones = np.ones(P.shape[:-1] + (1,))
    return _first_match(
        got,
        np.concatenate([P, ones], axis=-1),
        [
            (np.concatenate([P, 0.0 * ones], axis=-1), "points get a 1; a trailing 0 marks a direction"),
            (np.concatenate([ones, P], axis=-1), "the 1 goes last: [x, y, z] becomes [x, y, z, 1]"),
        ],
        "each point [x, y, z] becomes [x, y, z, 1]",
    )


@exercise("to_homogeneous", weight=2)
def test_to_homogeneous_rows(student):
    """(N, 3) → (N, 4): each row gets a trailing 1"""
    P = np.random.default_rng(731).normal(size=(7, 3))
    got = student.to_homogeneous(P)
    expect(
        np.shape(got) != (8, 3),
        "to_homogeneous(P) for 7 points returned shape 8×3: a row was added below them",
        ROW_HINT,
    )
    got = expect_array(got, (7, 4), "to_homogeneous(P) for 7 points")
    expect_close(got, np.column_stack([P, np.ones(7)]), 0.0, "to_homogeneous(P)", lambda: _homogeneous_hint(got, P))


@exercise("to_homogeneous", weight=2)
def test_to_homogeneous_single(student):
    """(3,) → (4,) for a single point, and lists work"""
    got = student.to_homogeneous([1.5, -2.0, 0.25])
    expect(
        np.shape(got) != (1, 4),
        "to_homogeneous of one point returned shape 1×4, expected 4",
        "one point of shape (3,) became a batch of shape (1, 4) (np.atleast_2d / np.column_stack): "
        "append along the last axis, np.concatenate([P, ones], axis=-1), so (3,) gives (4,)",
    )
    got = expect_array(got, (4,), "to_homogeneous of one point")
    expect_close(
        got,
        [1.5, -2.0, 0.25, 1.0],
        0.0,
        "to_homogeneous([1.5, -2, 0.25])",
        lambda: _homogeneous_hint(got, np.array([1.5, -2.0, 0.25])),
    )


@exercise("to_homogeneous", weight=1)
def test_to_homogeneous_one_row(student):
    """keeps a batch of one point as a batch: (1, 3) → (1, 4)"""
    got = student.to_homogeneous(np.array([[3.0, 2.0, 1.0]]))
    expect(np.shape(got) != (2, 3), "to_homogeneous of shape (1, 3) returned shape 2×3: a row was added", ROW_HINT)
    got = expect_array(got, (1, 4), "to_homogeneous of shape (1, 3)")
    expect_close(
        got,
        [[3.0, 2.0, 1.0, 1.0]],
        0.0,
        "to_homogeneous([[3, 2, 1]])",
        lambda: _homogeneous_hint(got, np.array([[3.0, 2.0, 1.0]])),
    )


# ---------------------------------------------------------------- from_homogeneous
def _dehomogeneous_hint(got, P_h):
    return _first_match(
        got,
        P_h[..., :3] / P_h[..., 3:],
        [
            (P_h[..., :3], "divide by the last coordinate before dropping it"),
            (P_h[..., 1:] / P_h[..., :1], hints.DIVIDED_FIRST_COORDINATE_X_HINT),
            (P_h[..., :3] * P_h[..., 3:], hints.MULTIPLIED_LAST_COORDINATE_DIVIDE_HINT),
        ],
        "[x, y, z, w] is the point [x/w, y/w, z/w]: divide each row by its own last coordinate",
    )


SINGLE_ONLY_HINT = (
    "P_h[:3] / P_h[3] indexes rows, so it works for one point only: index the last axis, P_h[..., :3] / P_h[..., 3:]"
)


def _expect_rows(got, P_h, shape, what):
    if P_h.ndim == 2 and np.shape(got) == (3, 4) and len(P_h) > 3 and _close(got, P_h[:3] / P_h[3]):
        raise Wrong(f"{what} returned shape 3×4, expected {shape[0]}×3", SINGLE_ONLY_HINT)
    return expect_array(got, shape, what)


@exercise("from_homogeneous", weight=3)
def test_from_homogeneous_divides(student):
    """(N, 4) → (N, 3), dividing each row by its last coordinate (scales 0.5, 2.5, -3, ...)"""
    rng = np.random.default_rng(741)
    P = rng.normal(size=(6, 3))
    w = np.array([0.5, 2.5, -3.0, 1.0, 1e-3, 7.0])
    P_h = np.column_stack([P * w[:, None], w])
    got = _expect_rows(student.from_homogeneous(P_h), P_h, (6, 3), "from_homogeneous(P_h)")
    expect_close(got, P, 1e-12, "from_homogeneous(P_h)", lambda: _dehomogeneous_hint(got, P_h))


@exercise("from_homogeneous", weight=1)
def test_from_homogeneous_single(student):
    """(4,) → (3,) for a single point"""
    got = expect_array(student.from_homogeneous([2.0, -4.0, 1.0, 2.0]), (3,), "from_homogeneous of one point")
    expect_close(
        got,
        [1.0, -2.0, 0.5],
        1e-12,
        "from_homogeneous([2, -4, 1, 2])",
        lambda: _dehomogeneous_hint(got, np.array([2.0, -4.0, 1.0, 2.0])),
    )


@exercise("from_homogeneous", weight=1)
def test_from_homogeneous_undoes_a_pose(student):
    """recovers the points after a pose acts on [p, 1] and the vector is rescaled"""
    T = _random_poses(1, seed=742)[0]
    P = np.random.default_rng(743).normal(size=(5, 3))
    P_h = np.column_stack([P, np.ones(5)]) @ T.T * 3.0
    got = _expect_rows(student.from_homogeneous(P_h), P_h, (5, 3), "from_homogeneous(3 T [p, 1])")
    expect_close(
        got, P @ T[:3, :3].T + T[:3, 3], 1e-12, "from_homogeneous(3 T [p, 1])", lambda: _dehomogeneous_hint(got, P_h)
    )


# ---------------------------------------------------------------- transform_points
def _transform_hint(got, T, P):
    """The mistake whose points ``got`` are (each candidate computed from T and P), or a general hint."""
    R, t = T[:3, :3], T[:3, 3]
    moved = np.concatenate([P, np.ones(P.shape[:-1] + (1,))], axis=-1) @ T
    with np.errstate(divide="ignore", invalid="ignore"):
        divided = moved[..., :3] / moved[..., 3:]
    return _first_match(
        got,
        P @ R.T + t,
        [
            (P @ R + t, "for rows use P @ R.T (or P_h @ T.T): P @ R is the inverse rotation"),
            (moved[..., :3], hints.HOMOGENEOUS_ROWS_TRANSPOSE_HINT),
            (divided, hints.HOMOGENEOUS_ROWS_TRANSPOSE_HINT),
            (P @ R.T, "the translation is missing: add T[:3, 3]"),
            ((P + t) @ R.T, "rotate first, then shift: R p + t, not R (p + t)"),
        ],
        hints.TRANSFORM_ROWS_FORMULA_HINT,
    )


@exercise("transform_points", weight=3)
def test_transform_points_rows(student):
    """p_a = R_ab p_b + t_ab for N points as rows, shape (N, 3), N = 9 and N = 3 (a square batch)"""
    rng = np.random.default_rng(751)
    for count, T in zip([9, 3] * 4, _random_poses(8, seed=752)):
        P = rng.normal(size=(count, 3)) * 3.0
        got = expect_array(student.transform_points(T, P), (count, 3), f"transform_points(T, P) for {count} points")
        as_columns = count == 3 and close(got, T[:3, :3] @ P + T[:3, 3:], 1e-6)  # the points taken as columns
        hint = SQUARE_BATCH_HINT if as_columns else _transform_hint(got, T, P)
        expect_close(got, P @ T[:3, :3].T + T[:3, 3], TOL, "transform_points(T, P)", hint)


@exercise("transform_points", weight=1)
def test_transform_points_single(student):
    """accepts one point of shape (3,) and returns shape (3,)"""
    for T in _random_poses(4, seed=753):
        p = np.array([0.4, -1.1, 2.3])
        got = expect_array(student.transform_points(T, p), (3,), "transform_points(T, p) for one point")
        expect_close(got, T[:3, :3] @ p + T[:3, 3], TOL, "transform_points(T, p)", lambda: _transform_hint(got, T, p))


@exercise("transform_points", weight=1)
def test_transform_points_chain(student):
    """transforming by T_ab T_bc equals transforming by T_bc, then by T_ab; inverse poses undo it"""
    T_ab, T_bc = _random_poses(2, seed=754)
    P = np.random.default_rng(755).normal(size=(5, 3))
    in_b = expect_array(student.transform_points(T_bc, P), (5, 3), "transform_points(T_bc, P)")
    in_a = expect_array(student.transform_points(T_ab, in_b), (5, 3), "transform_points(T_ab, ...)")
    direct = expect_array(student.transform_points(T_ab @ T_bc, P), (5, 3), "transform_points(T_ab T_bc, P)")
    expect_close(
        direct, in_a, TOL, "one step vs two steps along the chain", lambda: _transform_hint(direct, T_ab @ T_bc, P)
    )
    back = expect_array(
        student.transform_points(_inverse(T_ab @ T_bc), direct), (5, 3), "transform_points(T_ac⁻¹, ...)"
    )
    expect_close(
        back,
        P,
        TOL,
        "transforming back with the inverse pose",
        lambda: _transform_hint(back, _inverse(T_ab @ T_bc), direct),
    )


@exercise("transform_points", weight=1)
def test_transform_points_lists(student):
    """accepts plain lists"""
    T = _random_poses(1, seed=755)[0]
    expect_same_with_lists(
        student.transform_points, (T, [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]), (2, 3), "transform_points(T, P)"
    )


# ---------------------------------------------------------------- exp_se3
FORGETS_V_HINT = hints.EXP_SE3_TRANSLATION_IS_RHO_HINT


def _is_rho(got, xi):
    """The translation of ``got`` is rho itself, and rho is visibly not the right translation V rho."""
    xi = np.asarray(xi, dtype=float)
    gap = np.max(np.abs(_exp(xi)[:3, 3] - xi[:3]))
    return gap > 0.0 and np.max(np.abs(got[:3, 3] - xi[:3])) <= 1e-3 * gap


def _one_term_series_hint(got, xi):
    """The hint for V's one-term series I + W/2 + W²/6 used where its θ² terms matter (|phi| up to 0.1), or ""."""
    phi, rho = xi[3:], xi[:3]
    theta = float(np.linalg.norm(phi))
    if not 0.0 < theta < 0.1:
        return ""
    W = np.array([[0.0, -phi[2], phi[1]], [phi[2], 0.0, -phi[0]], [-phi[1], phi[0], 0.0]])
    short = (np.eye(3) + W / 2.0 + W @ W / 6.0) @ rho
    exact = _exp(xi)[:3, 3]
    gap = float(np.max(np.abs(short - exact)))
    if gap > 0.0 and float(np.max(np.abs(np.asarray(got)[:3, 3] - short))) <= 1e-2 * gap:
        return (
            f"that is V's one-term series I + W/2 + W²/6 at |phi| = {theta:.2g}, whose error grows like θ³ |rho|: "
            "below your threshold keep the θ² term of each coefficient's series"
        )
    return ""


def _exp_hint(got, xi, tiny=False):
    xi = np.asarray(xi, dtype=float)
    if not np.all(np.isfinite(got)):
        return SERIES_HINT_V
    if np.allclose(got, _exp(np.concatenate([xi[3:], xi[:3]])), atol=1e-8, rtol=0.0):
        return MIRROR_HINT
    if _is_rho(got, xi) and not tiny:
        return FORGETS_V_HINT
    short = _one_term_series_hint(got, xi)
    if short:
        return short
    if np.allclose(got[:3, :3], _exp(xi)[:3, :3], atol=1e-8, rtol=0.0):
        return (
            SERIES_HINT_V
            if tiny
            else "the rotation block is right; check V (its two coefficients and the sign of the W term)"
        )
    return "compare your pose with expm of the 4×4 twist matrix ξ^ = [[skew(phi), rho], [0, 0]], xi = [rho, phi]"


@exercise("exp_se3", weight=3)
def test_exp_se3_matches_expm(student):
    """agrees with scipy.linalg.expm of the 4×4 twist matrix for 30 random twists (angles up to 3 rad)"""
    for xi in _random_twists(30, seed=761, max_angle=3.0):
        got = expect_array(student.exp_se3(xi), (4, 4), f"exp_se3({fmt(xi, 3)})")
        expect_close(got, _exp(xi), TOL, f"exp_se3({fmt(xi, 3)})", lambda: _exp_hint(got, xi))


@exercise("exp_se3", weight=2)
def test_exp_se3_tiny_angles(student):
    """is exact at tiny rotation parts (|phi| = 0 … 9e-3) with |rho| up to 50: error ≤ 1e-12 |rho|"""
    rng = np.random.default_rng(762)
    failures = []
    for angle in (0.0, 1e-12, 1e-9, 1e-6, 1e-4, 9e-3):
        for length in (1.0, 50.0):
            xi = _twist(length * _unit(rng.normal(size=3)), angle, rng.normal(size=3))
            what = f"exp_se3 at |phi| = {angle:g}, |rho| = {length:g}"
            got = student.exp_se3(xi)
            _expect_finite(got, what, SERIES_NAN_HINT_V)
            got = expect_array(got, (4, 4), what)
            if np.max(np.abs(got - _exp(xi))) > 1e-12 * length:
                failures.append((what, got, xi, length))
    if failures:
        # At |phi| = 1e-9 a V whose coefficients round to 0 gives V = I exactly, like a missing V: the
        # diagnosis looks at every failing angle, and blames V itself only when each one returned rho.
        if all(_is_rho(got, xi) for _, got, xi, _ in failures):
            hint = FORGETS_V_HINT
        else:
            hint = next(
                (_exp_hint(got, xi, tiny=True) for _, got, xi, _ in failures if not _is_rho(got, xi)), SERIES_HINT_V
            )
        what, got, xi, length = failures[0]
        expect_close(got, _exp(xi), 1e-12, what, hint, scale=length)


def _twists_every_decade(max_angle=np.pi):
    """``(xi, form)``: rho anywhere in a ball of radius 50, phi at every decade of angle up to ``max_angle``."""
    twists = st.tuples(points(50.0), rotation_vectors(high=max_angle, near_pi=max_angle >= np.pi)).map(np.concatenate)
    return twists.flatmap(lambda xi: st.tuples(st.just(xi), as_given(xi)))


def _decade_twists():
    rho = np.array([30.0, -20.0, 35.0])
    return [(np.concatenate([rho, t * GENERIC_AXIS]),) * 2 for t in decade_edges()]


@exercise("exp_se3", weight=2)
def test_exp_se3_every_decade(student):
    """exact to 5e-14 max(1, |rho|) at every angle of phi from 1e-12 to π (each decade, just below each
    power of ten), |rho| up to 50, lists too"""

    def check(case):
        xi, given = case
        got = expect_array(student.exp_se3(given), (4, 4), "exp_se3(xi)")
        scale = max(1.0, float(np.linalg.norm(xi[:3])))
        expect_within(
            got,
            _exp(xi),
            SE3_TOL * scale,
            "exp_se3(xi)",
            f"|phi| = {np.linalg.norm(xi[3:]):.2g}, |rho| = {scale:.2g}",
            lambda: _exp_hint(got, xi, tiny=not _is_rho(got, xi) and np.linalg.norm(xi[3:]) < 1e-2),
        )

    for_all(_twists_every_decade(), check, explicit=_decade_twists())


@exercise("exp_se3", weight=1)
def test_exp_se3_large_angles(student):
    """handles rotation parts near and beyond π (π - 1e-6, π, 4 rad, 7 rad)"""
    rng = np.random.default_rng(763)
    for angle in (np.pi - 1e-6, np.pi, 4.0, 7.0):
        xi = _twist(rng.normal(size=3), angle, rng.normal(size=3))
        got = expect_array(student.exp_se3(xi), (4, 4), f"exp_se3 at |phi| = {angle:.6g}")
        expect_close(got, _exp(xi), TOL, f"exp_se3 at |phi| = {angle:.6g}", lambda: _exp_hint(got, xi))


@exercise("exp_se3", weight=1)
def test_exp_se3_group_laws(student):
    """returns a pose; exp(a xi) exp(b xi) = exp((a + b) xi); a pure translation moves by rho"""
    xi = _twist([0.3, -1.0, 0.7], 1.1, [1.0, -2.0, 0.5])
    T = student.exp_se3(xi)
    _expect_finite(T, "exp_se3(xi)", SERIES_NAN_HINT_V)
    T = expect_array(T, (4, 4), "exp_se3(xi)")
    _expect_pose(T, "exp_se3(xi)")
    a = expect_array(student.exp_se3(0.3 * xi), (4, 4), "exp_se3(0.3 xi)")
    b = expect_array(student.exp_se3(0.7 * xi), (4, 4), "exp_se3(0.7 xi)")
    expect_close(a @ b, T, TOL, "exp_se3(0.3 xi) @ exp_se3(0.7 xi) vs exp_se3(xi)", lambda: _exp_hint(T, xi))
    shift = student.exp_se3([1.0, -2.0, 3.0, 0.0, 0.0, 0.0])
    _expect_finite(shift, "exp_se3 of a pure translation (phi = 0)", SERIES_NAN_HINT_V)
    shift = expect_array(shift, (4, 4), "exp_se3 of a pure translation")
    expect_close(
        shift,
        _pose(np.eye(3), [1.0, -2.0, 3.0]),
        TOL,
        "exp_se3([1, -2, 3, 0, 0, 0])",
        lambda: _exp_hint(shift, [1.0, -2.0, 3.0, 0.0, 0.0, 0.0]),
    )


# ---------------------------------------------------------------- log_se3
def _log_hint(got, T, xi, tiny=False):
    """The mistake whose twist ``got`` is (each candidate computed from T), or a general hint."""
    xi = np.asarray(xi, dtype=float)
    if np.allclose(np.concatenate([got[3:], got[:3]]), xi, atol=1e-6, rtol=0.0):
        return MIRROR_HINT
    gap = np.max(np.abs(T[:3, 3] - xi[:3]))
    if gap > 0.0 and np.max(np.abs(got[:3] - T[:3, 3])) <= 1e-3 * gap:
        return "rho is V(phi)⁻¹ t, not t itself"
    phi = xi[3:]
    W = _twist_matrix(np.concatenate([np.zeros(3), phi]))[:3, :3]
    constant_c = (np.eye(3) - 0.5 * W + W @ W / 12.0) @ T[:3, 3]
    if not _close(constant_c, xi[:3], 1e-8) and _close(got[:3], constant_c, 1e-8):
        return hints.SERIES_VALUE_AT_ZERO_ONLY_HINT
    if np.allclose(got[3:], xi[3:], atol=1e-6, rtol=0.0):
        return SERIES_HINT_C if tiny else "phi is right; check V⁻¹ (the -W/2 term and the coefficient c(θ) of W²)"
    return "xi = [V(phi)⁻¹ t, phi] with phi = Log(R)"


@exercise("log_se3", weight=3)
def test_log_se3_round_trip(student):
    """log_se3(expm(xi^)) = xi for 30 random twists with angles up to π - 0.01"""
    for xi in _random_twists(30, seed=771, max_angle=np.pi - 0.01):
        T = _exp(xi)
        got = expect_array(student.log_se3(T), (6,), "log_se3(T)")
        expect_close(got, xi, TOL, f"log_se3 of the pose reached by xi = {fmt(xi, 3)}", lambda: _log_hint(got, T, xi))


@exercise("log_se3", weight=2)
def test_log_se3_tiny_angles(student):
    """is exact at tiny rotation parts (|phi| = 0 … 9e-3) with |rho| up to 50: error ≤ 1e-11 |rho|"""
    rng = np.random.default_rng(772)
    for angle in (0.0, 1e-12, 1e-9, 1e-6, 1e-4, 9e-3):
        for length in (1.0, 50.0):
            xi = _twist(length * _unit(rng.normal(size=3)), angle, rng.normal(size=3))
            what = f"log_se3 at |phi| = {angle:g}, |rho| = {length:g}"
            T = _exp(xi)
            got = student.log_se3(T)
            _expect_finite(got, what, SERIES_HINT_C)
            got = expect_array(got, (6,), what)
            expect_close(got, xi, 1e-11, what, lambda: _log_hint(got, T, xi, tiny=True) or SERIES_HINT_C, scale=length)


@exercise("log_se3", weight=2)
def test_log_se3_every_decade(student):
    """exact to 5e-14 max(1, |rho|) at every angle of phi from 1e-12 to 3 (each decade, just below each power
    of ten), |rho| up to 50"""

    def check(case):
        xi, _ = case
        T = _exp(xi)
        got = expect_array(student.log_se3(T), (6,), "log_se3(T)")
        scale = max(1.0, float(np.linalg.norm(xi[:3])))
        expect_within(
            got,
            xi,
            SE3_TOL * scale,
            "log_se3(T)",
            f"|phi| = {np.linalg.norm(xi[3:]):.2g}, |rho| = {scale:.2g}",
            lambda: _log_hint(got, T, xi, tiny=True),
        )

    for_all(_twists_every_decade(max_angle=3.0), check, explicit=_decade_twists())


@exercise("log_se3", weight=2)
def test_log_se3_near_pi(student):
    """near and at π (π - 1e-6, π - 1e-9, exactly π): exp of the result is T, angle at most π"""
    rng = np.random.default_rng(773)
    for angle in (np.pi - 1e-6, np.pi - 1e-9):
        xi = _twist(rng.normal(size=3), angle, rng.normal(size=3))
        got = expect_array(student.log_se3(_exp(xi)), (6,), f"log_se3 at |phi| = {angle:.12g}")
        expect_close(got, xi, 1e-6, f"log_se3 at |phi| = {angle:.12g}", lambda: _log_hint(got, _exp(xi), xi))
    for axis in ([1.0, 1.0, 1.0], [0.3, -0.8, 0.5], [0.0, 0.0, 1.0]):
        u = _unit(axis)
        R = 2.0 * np.outer(u, u) - np.eye(3)  # exactly π about u
        T = _pose(R, rng.normal(size=3))
        got = expect_array(student.log_se3(T), (6,), f"log_se3 at exactly π about {fmt(u, 3)}")
        expect(
            np.linalg.norm(got[3:]) <= np.pi + 1e-9,
            f"the rotation part has angle {np.linalg.norm(got[3:]):.6f} > π",
            "Log returns angles in [0, π]",
        )
        expect_close(
            _exp(got),
            T,
            1e-8,
            f"expm of the twist of log_se3(T) at exactly π about {fmt(u, 3)}",
            "at θ = π, c(π) = 1/π² and both axis signs work; phi must still be π times the axis",
        )


@exercise("log_se3", weight=1)
def test_log_se3_large_rotation(student):
    """a twist with a 5 rad rotation part comes back as an equivalent twist with angle ≤ π; lists work too"""
    xi = _twist([1.0, 0.5, -2.0], 5.0, [0.2, 0.9, -0.4])
    T = _exp(xi)
    got = expect_array(student.log_se3(T), (6,), "log_se3(T) for a 5 rad turn")
    expect(
        np.linalg.norm(got[3:]) <= np.pi + 1e-9,
        f"the rotation part has angle {np.linalg.norm(got[3:]):.4f} > π",
        "Log returns angles in [0, π]",
    )
    phi = Rotation.from_matrix(T[:3, :3]).as_rotvec()  # the same rotation with angle ≤ π
    expect_close(
        _exp(got),
        T,
        TOL,
        "expm of the twist of log_se3(T) for a 5 rad turn",
        lambda: _log_hint(got, T, np.concatenate([np.linalg.solve(_v_matrix(phi), T[:3, 3]), phi])),
    )
    expect_same_with_lists(student.log_se3, (T,), (6,), "log_se3(T)")
