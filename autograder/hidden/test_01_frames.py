"""Hidden checks for lesson 01: frames, points and rotation matrices.

Independent oracles: scipy's ``Rotation.from_euler`` for the elementary
rotations, plain matrix algebra for the rest, and the reference solutions.
Every test calls the student's functions of its own exercise only.

Core ideas (they carry at least half of each exercise's points): the sign of
the sines (the right-hand rule); orthonormal *and* det = +1, compared with an
absolute tolerance (diag(1, 1, 1 + 1e-6) must be rejected, which np.allclose's
rtol would hide); the determinant fix of the SVD projection.
Edge cases: integer angles, multiples of π and 2π, 1e-9, large angles; lists
as inputs (compared with the same function's answer for arrays).
Precision: rot2d and the elementary rotations agree with np.cos/np.sin to
1e-12 at a generic angle and at every decade of angle from 1 down to 1e-8
(both signs), where a small-angle series or float32 storage would hide.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.checks import tolerance
from coursekit.checks.lesson01 import (
    EXACT_ROTATION_HINT,
    NOT_A_MATRIX_HINT,
    QUARTER_TURN_X,
    QUARTER_TURN_Z,
    SQUARE_BATCH_HINT,
)
from coursekit.diagnose import FLOAT32_HINT, SERIES_HINT, close, float32_rounding

from autograder.sandbox.session import StudentError

from .helpers import (
    ALLCLOSE_HINT,
    Wrong,
    exercise,
    expect,
    expect_array,
    expect_bool,
    expect_close,
    expect_same_with_lists,
    fmt,
    random_angles,
    random_rotations,
    rotation_problem,
)

TOL = 1e-9
SPECIAL_ANGLES = [0.0, np.pi / 2, -np.pi / 2, np.pi, 2 * np.pi, 1e-9, 10 * np.pi + 0.3, -7.0]


def _or_float32(hint, got, expected):
    """FLOAT32_HINT when ``got`` is off from ``expected`` by float32 rounding only, else ``hint``."""
    return FLOAT32_HINT if float32_rounding(got, expected) else hint


def _first_match(got, candidates, otherwise=""):
    """The hint of the first (candidate value, hint) that ``got`` equals (to 1e-6), else ``otherwise``.

    Each candidate is what one typical mistake returns for the same input, so a
    hint is given only when its diagnosis holds.
    """
    got = np.asarray(got, dtype=float)
    for candidate, hint in candidates:
        if close(got, candidate, 1e-6):
            return hint
    return otherwise


DEGREES_HINT = "looks like the angle was taken in degrees: the course works in radians (np.cos takes radians)"
SAME_SIGN_HINT = hints.BOTH_SINES_HAVE_SAME_HINT


# ---------------------------------------------------------------- rot2d
def _rot2d(theta):
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s], [s, c]])


def _rot2d_hint(got, theta):
    c, s = np.cos(theta), np.sin(theta)
    return _first_match(
        got,
        [
            (_rot2d(theta).T, "looks like the transpose (a clockwise turn): the minus sign belongs on the upper sine"),
            (_rot2d(np.deg2rad(theta)), DEGREES_HINT),
            (np.array([[s, -c], [c, s]]), hints.SINE_COSINE_SWAPPED_COS_HINT),
            (np.array([[c, s], [s, c]]), SAME_SIGN_HINT),
            (np.array([[c, -s], [-s, c]]), SAME_SIGN_HINT),
        ],
        "compare entry by entry with [[cos θ, -sin θ], [sin θ, cos θ]]",
    )


@exercise("rot2d", weight=3)
def test_rot2d_values(student):
    """matches cos/sin of the angle for random and special angles"""
    for theta in list(random_angles(12, seed=101)) + SPECIAL_ANGLES:
        got = expect_array(student.rot2d(theta), (2, 2), f"rot2d({theta:.4g})")
        expect_close(got, _rot2d(theta), TOL, f"rot2d({theta:.4g})", lambda: _rot2d_hint(got, theta))


@exercise("rot2d", weight=1)
def test_rot2d_composes_angles(student):
    """rot2d(a) @ rot2d(b) equals rot2d(a + b)"""
    for a, b in zip(random_angles(5, seed=102), random_angles(5, seed=103)):
        got = expect_array(student.rot2d(a + b), (2, 2), "rot2d(a + b)")
        product = expect_array(student.rot2d(a), (2, 2), "rot2d(a)") @ expect_array(
            student.rot2d(b), (2, 2), "rot2d(b)"
        )
        expect_close(got, product, TOL, f"rot2d({a + b:.3f}) vs rot2d({a:.3f}) @ rot2d({b:.3f})")


@exercise("rot2d", weight=1)
def test_rot2d_accepts_integers(student):
    """accepts an integer angle (rot2d(0) is the identity)"""
    expect_close(expect_array(student.rot2d(0), (2, 2), "rot2d(0)"), np.eye(2), TOL, "rot2d(0)")


# Every decade of angle, both signs, after a generic one (a float32 answer fails there first).
DECADE_ANGLES = [0.9] + [sign * 10.0**-k for k in range(9) for sign in (1.0, -1.0)]
PRECISION = 1e-12


def _check_every_decade(function, name, expected_of, shape):
    """``function(angle)`` equals ``expected_of(angle)`` to PRECISION at every angle of DECADE_ANGLES."""
    for angle in DECADE_ANGLES:
        got = expect_array(function(angle), shape, f"{name}({angle:.0e})")
        expected = expected_of(angle)
        hint = ""
        if abs(angle) >= 0.1 and float32_rounding(got, expected):
            hint = FLOAT32_HINT
        elif abs(angle) < 0.1:
            hint = SERIES_HINT
        expect_close(got, expected, PRECISION, f"{name}({angle:.0e})", hint)


@exercise("rot2d", weight=1)
def test_rot2d_every_decade(student):
    """agrees with cos and sin to 1e-12 at every decade of angle, 1e-8 … 1"""
    _check_every_decade(student.rot2d, "rot2d", _rot2d, (2, 2))


# ---------------------------------------------------------------- rot_x, rot_y, rot_z
ELEMENTARY = [("rot_x", "x", 0), ("rot_y", "y", 1), ("rot_z", "z", 2)]


def _elementary(axis_name, angle):
    return Rotation.from_euler(axis_name, angle).as_matrix()


def _elementary_hint(got, axis_name, angle):
    """Name the typical slip behind a wrong rot_x/rot_y/rot_z(angle), only when its value matches ``got``."""
    axis = "xyz".index(axis_name)
    expected = _elementary(axis_name, angle)
    i, j = [k for k in range(3) if k != axis]
    s = expected[j, i] if axis != 1 else expected[i, j]  # +sin a, wherever it sits
    both_plus, both_minus = expected.copy(), expected.copy()
    both_plus[i, j] = both_plus[j, i] = s
    both_minus[i, j] = both_minus[j, i] = -s
    corner_zero = expected.copy()
    corner_zero[axis, axis] = 0.0
    candidates = [
        (
            expected.T,
            "looks like the transpose (the inverse rotation): the minus sign is on the wrong sine"
            + (" (for rot_y it sits in the bottom-left)" if axis_name == "y" else ""),
        ),
        (_elementary(axis_name, np.deg2rad(angle)), DEGREES_HINT),
        (both_plus, SAME_SIGN_HINT),
        (both_minus, SAME_SIGN_HINT),
        (corner_zero, f"the diagonal entry of the {axis_name} axis is 0: it must be 1 (the axis does not move)"),
    ]
    for other in "xyz".replace(axis_name, ""):
        candidates.append(
            (
                _elementary(other, angle),
                f"this is a rotation about {other}, not {axis_name}: the "
                f"cos/sin block of rot_{axis_name} sits in the rows and columns of the other two axes",
            )
        )
    return _first_match(
        got,
        candidates,
        f"compare entry by entry with the rotation about {axis_name} by the angle "
        f"(scipy: Rotation.from_euler('{axis_name}', a).as_matrix())",
    )


def _check_elementary(student, name, axis_name, seed):
    function = getattr(student, name)
    for angle in list(random_angles(15, seed=seed)) + SPECIAL_ANGLES:
        got = expect_array(function(angle), (3, 3), f"{name}({angle:.4g})")
        expect_close(
            got,
            _elementary(axis_name, angle),
            TOL,
            f"{name}({angle:.4g})",
            lambda: _elementary_hint(got, axis_name, angle),
        )


def _check_axis_fixed(student, name, axis):
    function = getattr(student, name)
    e = np.eye(3)[axis]
    for angle in random_angles(6, seed=200 + axis):
        R = expect_array(function(angle), (3, 3), f"{name}({angle:.3f})")
        expect_close(
            R @ e,
            e,
            TOL,
            f"{name}({angle:.3f}) applied to its own axis",
            "the rotation axis must not move: its row and column are the unit vector",
        )
        problem = rotation_problem(R)
        expect(problem is None, f"{name}({angle:.3f}): {problem}")


def _check_additive(student, name):
    function = getattr(student, name)
    for a, b in zip(random_angles(5, seed=301), random_angles(5, seed=302)):
        product = expect_array(function(a), (3, 3), name) @ expect_array(function(b), (3, 3), name)
        expect_close(
            expect_array(function(a + b), (3, 3), name),
            product,
            TOL,
            f"{name}(a + b) vs {name}(a) @ {name}(b) for a={a:.3f}, b={b:.3f}",
        )


@exercise("rot_x", weight=3)
def test_rot_x_matches_scipy(student):
    """agrees with scipy's rotation about x for random and special angles"""
    _check_elementary(student, "rot_x", "x", seed=111)


@exercise("rot_x", weight=1)
def test_rot_x_is_a_rotation_about_x(student):
    """is orthogonal with det +1 and leaves the x axis fixed"""
    _check_axis_fixed(student, "rot_x", 0)


@exercise("rot_x", weight=1)
def test_rot_x_adds_angles(student):
    """rot_x(a) @ rot_x(b) equals rot_x(a + b)"""
    _check_additive(student, "rot_x")


@exercise("rot_x", weight=1)
def test_rot_x_every_decade(student):
    """agrees with cos and sin to 1e-12 at every decade of angle, 1e-8 … 1"""
    _check_every_decade(student.rot_x, "rot_x", lambda angle: _elementary("x", angle), (3, 3))


@exercise("rot_y", weight=3)
def test_rot_y_matches_scipy(student):
    """agrees with scipy's rotation about y for random and special angles"""
    _check_elementary(student, "rot_y", "y", seed=112)


@exercise("rot_y", weight=1)
def test_rot_y_is_a_rotation_about_y(student):
    """is orthogonal with det +1 and leaves the y axis fixed"""
    _check_axis_fixed(student, "rot_y", 1)


@exercise("rot_y", weight=1)
def test_rot_y_adds_angles(student):
    """rot_y(a) @ rot_y(b) equals rot_y(a + b)"""
    _check_additive(student, "rot_y")


@exercise("rot_y", weight=1)
def test_rot_y_every_decade(student):
    """agrees with cos and sin to 1e-12 at every decade of angle, 1e-8 … 1"""
    _check_every_decade(student.rot_y, "rot_y", lambda angle: _elementary("y", angle), (3, 3))


@exercise("rot_z", weight=3)
def test_rot_z_matches_scipy(student):
    """agrees with scipy's rotation about z for random and special angles"""
    _check_elementary(student, "rot_z", "z", seed=113)


@exercise("rot_z", weight=1)
def test_rot_z_is_a_rotation_about_z(student):
    """is orthogonal with det +1 and leaves the z axis fixed"""
    _check_axis_fixed(student, "rot_z", 2)


@exercise("rot_z", weight=1)
def test_rot_z_adds_angles(student):
    """rot_z(a) @ rot_z(b) equals rot_z(a + b)"""
    _check_additive(student, "rot_z")


@exercise("rot_z", weight=1)
def test_rot_z_every_decade(student):
    """agrees with cos and sin to 1e-12 at every decade of angle, 1e-8 … 1"""
    _check_every_decade(student.rot_z, "rot_z", lambda angle: _elementary("z", angle), (3, 3))


# ---------------------------------------------------------------- is_rotation_matrix
SHAPE_HINT = hints.CHECK_M_S_SHAPE_HINT


def _shape_or_none(M):
    """``np.shape(M)``, or None for what has no shape (a ragged list, None)."""
    try:
        return np.shape(M) if M is not None else None
    except ValueError:
        return None


def _is_rotation_verdict(student, M, what="is_rotation_matrix", **kwargs):
    """The student's verdict for M; a crash on a matrix that is not 3×3 is named as a missing shape check."""
    try:
        value = student.is_rotation_matrix(M, **kwargs)
    except StudentError as error:
        if error.kind == "exception" and _shape_or_none(M) != (3, 3):
            shape = _shape_or_none(M)
            described = f"a {'×'.join(map(str, shape))} input" if shape else f"the input {M!r}"
            raise Wrong(f"{what} crashed on {described}: {error}", SHAPE_HINT if shape else NOT_A_MATRIX_HINT) from None
        raise
    return expect_bool(value, what)


def _accepted_hint(M, tol=TOL):
    """Why a wrong is_rotation_matrix could accept the non-rotation M: the rule it would have to use."""
    M = np.asarray(M, dtype=float)
    gram = M.T @ M
    if np.allclose(gram, np.eye(3), atol=tol) and np.linalg.det(M) > 0:
        return ALLCLOSE_HINT
    if abs(np.linalg.det(M) - 1.0) <= tol:
        return "det = 1 is not enough (a shear has det 1): also check max |MᵀM - I| <= tol"
    return f"check that MᵀM equals I within tol (here max |MᵀM - I| = {np.max(np.abs(gram - np.eye(3))):.2g})"


@exercise("is_rotation_matrix", weight=2)
def test_is_rotation_matrix_accepts_rotations(student):
    """accepts the identity, exact quarter turns, 20 random rotations and a 2D rotation"""
    exact = [np.eye(3), QUARTER_TURN_Z, QUARTER_TURN_X]  # first: rejecting these is not about rounding
    candidates = exact + list(random_rotations(20, seed=121)) + [_rot2d(0.4)]
    rounding = "compare with a tolerance: rounding makes RᵀR differ from I by ~1e-16"
    for index, R in enumerate(candidates):
        verdict = _is_rotation_verdict(student, R)
        exactly = np.array_equal(R.T @ R, np.eye(len(R)))
        expect(verdict, f"rejected a valid rotation (#{index}): {fmt(R)}", EXACT_ROTATION_HINT if exactly else rounding)


@exercise("is_rotation_matrix", weight=2)
def test_is_rotation_matrix_rejects_reflections(student):
    """rejects reflections (orthogonal with det = -1)"""
    mirror = np.diag([1.0, 1.0, -1.0])
    for index, R in enumerate(random_rotations(10, seed=122)):
        verdict = _is_rotation_verdict(student, R @ mirror)
        expect(
            not verdict,
            f"accepted a reflection (#{index}, det = -1)",
            "orthogonality is not enough: also require det(M) > 0",
        )


@exercise("is_rotation_matrix", weight=2)
def test_is_rotation_matrix_rejects_non_orthogonal(student):
    """rejects scaled, sheared and noisy matrices"""
    R = random_rotations(1, seed=123)[0]
    noise = np.random.default_rng(124).normal(size=(3, 3))
    cases = {
        "2·R": 2.0 * R,
        "a shear": np.array([[1.0, 0.3, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
        "R + 1e-6 noise": R + 1e-6 * noise,
        "the zero matrix": np.zeros((3, 3)),
        "R with its columns scaled by (1, 1, 1.001)": R @ np.diag([1.0, 1.0, 1.001]),
        "diag(1, 1, 1 + 1e-6)": np.diag([1.0, 1.0, 1.0 + 1e-6]),
        "R with its last column stretched by 1e-6": R @ np.diag([1.0, 1.0, 1.0 + 1e-6]),
    }
    for name, M in cases.items():
        verdict = _is_rotation_verdict(student, M)
        expect(
            not verdict,
            f"accepted {name} (max |MᵀM - I| = {np.max(np.abs(M.T @ M - np.eye(3))):.2g}, tol = {TOL:g})",
            lambda: _accepted_hint(M),
        )


@exercise("is_rotation_matrix", weight=1)
def test_is_rotation_matrix_respects_tol(student):
    """uses the tol argument: tiny noise passes, noise above tol fails"""
    R = random_rotations(1, seed=125)[0]
    noise = np.random.default_rng(126).normal(size=(3, 3))
    M = R + 1e-6 * noise
    gap = np.max(np.abs(M.T @ M - np.eye(3)))
    ignores_tol = "the verdict does not follow the tol argument: compare with tol, not a fixed number"
    expect(
        _is_rotation_verdict(student, R + 1e-13 * noise),
        "rejected a rotation with 1e-13 rounding noise at the default tol=1e-9",
        "compare with a tolerance: rounding makes MᵀM differ from I by ~1e-16",
    )
    if not _is_rotation_verdict(student, M, tol=1e-4):
        still = not _is_rotation_verdict(student, M, tol=0.1)
        raise Wrong(f"rejected R + 1e-6 noise (max |MᵀM - I| = {gap:.2g}) with tol=1e-4", ignores_tol if still else "")
    if _is_rotation_verdict(student, M, tol=1e-8):
        still = _is_rotation_verdict(student, M, tol=1e-15)
        raise Wrong(
            f"accepted R + 1e-6 noise (max |MᵀM - I| = {gap:.2g}) with tol=1e-8",
            ignores_tol if still else _accepted_hint(M, 1e-8),
        )


@exercise("is_rotation_matrix", weight=1)
def test_is_rotation_matrix_tol_boundary(student):
    """tol is the largest accepted entry of |MᵀM - I|: M = diag(1 + 2^-k, 1 + 2^-k, 1), its gap exact in
    binary, at tol 0.1 % below, equal to and 0.1 % above the gap, k = 8 … 26"""
    for k in tolerance.GAP_EXPONENTS:
        s = 1.0 + 2.0**-k
        M = np.diag([s, s, 1.0])
        name = f"is_rotation_matrix(diag(1 + 2^-{k}, 1 + 2^-{k}, 1), tol)"
        problem = tolerance.boundary_problem(
            lambda tol: _is_rotation_verdict(student, M, name, tol=tol), s * s - 1.0, "max |MᵀM - I|", name
        )
        if problem:
            raise Wrong(*problem)


@exercise("is_rotation_matrix", weight=1)
def test_is_rotation_matrix_bad_input(student):
    """returns False, without crashing, for anything else: wrong shapes, NaN, a ragged list,
    text, None and a dict ("Anything else gives False")"""
    cases = {
        "a 3×4 matrix": np.eye(4)[:3],
        "a vector": np.ones(3),
        "a matrix with NaN": np.full((3, 3), np.nan),
        "a nested list 3×2": [[1.0, 0.0]] * 3,
        "a ragged nested list": [[1.0, 0.0, 0.0], [0.0, 1.0], [0.0, 0.0, 1.0]],
        "the text 'identity'": "identity",
        "None": None,
        "a dict": {"R": np.eye(3)},
    }
    for name, M in cases.items():
        verdict = _is_rotation_verdict(student, M, f"is_rotation_matrix({name})")
        expect(not verdict, f"accepted {name}", "check the shape and that the entries are finite first")


# ---------------------------------------------------------------- rotate_point
@exercise("rotate_point", weight=3)
def test_rotate_point_single(student):
    """p_w = R_wb p_b for 20 random rotations and points"""
    points = np.random.default_rng(131).normal(size=(20, 3))
    for R, p in zip(random_rotations(20, seed=132), points):
        got = expect_array(student.rotate_point(R, p), (3,), "rotate_point(R, p) for one point")
        hint = _first_match(got, [(R.T @ p, "looks like you used R.T (the inverse): p_w = R_wb @ p_b")])
        expect_close(got, R @ p, TOL, "rotate_point(R, p)", lambda: _or_float32(hint, got, R @ p))


@exercise("rotate_point", weight=2)
def test_rotate_point_batch(student):
    """rotates N points given as rows, shape (N, 3), for N = 7 and for N = 3 (a square batch)"""
    R = random_rotations(1, seed=133)[0]
    for count in (7, 3):
        _rotate_rows(student, R, np.random.default_rng(134 + count).normal(size=(count, 3)))


def _rotate_rows(student, R, P):
    count = len(P)
    try:
        value = student.rotate_point(R, P)
    except StudentError as error:
        if error.kind != "exception":
            raise
        if "broadcast" in error.message:
            hint = hints.NUMPY_COULD_BROADCAST_R_HINT
        elif "matmul" in error.message:
            hint = hints.ONE_POINT_NOT_ROWS_HINT
        else:
            hint = "the points are the rows of P: P @ R.T rotates each of them"
        raise Wrong(f"rotate_point(R, P) for {count} points: {error}", hint) from None
    got = expect_array(value, (count, 3), f"rotate_point(R, P) for {count} points")
    hint = _first_match(
        got,
        [(P @ R, "looks like P @ R, which rotates each row by R.T (the inverse): for rows use P @ R.T")]
        + ([(R @ P, SQUARE_BATCH_HINT)] if count == 3 else []),
    )
    expect_close(got, (R @ P.T).T, TOL, f"rotate_point(R, P) for {count} points", hint)


@exercise("rotate_point", weight=1)
def test_rotate_point_accepts_lists(student):
    """accepts plain Python lists"""
    expect_same_with_lists(
        student.rotate_point, (random_rotations(1, seed=135)[0], [1.0, 2.0, 3.0]), (3,), "rotate_point(R, p)"
    )


# ---------------------------------------------------------------- compose
def _compose_hint(got, A, B):
    return _first_match(
        got,
        [
            (B @ A, "the order is reversed: R_ac = R_ab @ R_bc"),
            (A * B, hints.ELEMENTWISE_PRODUCT_HINT),
            (A.T @ B, hints.FIRST_FACTOR_TRANSPOSED_HINT),
        ],
        "R_ac = R_ab @ R_bc, the matrix product in this order",
    )


@exercise("compose", weight=3)
def test_compose_random(student):
    """R_ac = R_ab R_bc for 20 random pairs"""
    As, Bs = random_rotations(20, seed=141), random_rotations(20, seed=142)
    for A, B in zip(As, Bs):
        got = expect_array(student.compose(A, B), (3, 3), "compose(R_ab, R_bc)")
        expect_close(got, A @ B, TOL, "compose(R_ab, R_bc)", lambda: _or_float32(_compose_hint(got, A, B), got, A @ B))


@exercise("compose", weight=1)
def test_compose_identity(student):
    """composing with the identity changes nothing"""
    R = random_rotations(1, seed=143)[0]
    for A, B, what in ((R, np.eye(3), "compose(R, I)"), (np.eye(3), R, "compose(I, R)")):
        got = expect_array(student.compose(A, B), (3, 3), what)
        expect_close(got, R, TOL, what, lambda: _or_float32(_compose_hint(got, A, B), got, R))


@exercise("compose", weight=1)
def test_compose_accepts_lists(student):
    """accepts plain Python lists"""
    A, B = random_rotations(2, seed=144)
    expect_same_with_lists(student.compose, (A, B), (3, 3), "compose(R_ab, R_bc)")


# ---------------------------------------------------------------- invert_rotation
def _inverse_hint(got, R):
    return _first_match(
        got,
        [
            (R, "returned R itself: the inverse is the transpose"),
            (-R, hints.NEGATED_NOT_TRANSPOSED_HINT),
            (R[::-1], hints.REVERSED_ORDER_ROWS_R_HINT),
        ],
        "the inverse of a rotation is its transpose: R_ba = R_ab.T",
    )


@exercise("invert_rotation", weight=3)
def test_invert_rotation_random(student):
    """R_ba = R_abᵀ for 20 random rotations"""
    for R in random_rotations(20, seed=151):
        got = expect_array(student.invert_rotation(R), (3, 3), "invert_rotation(R)")
        expect_close(got, R.T, TOL, "invert_rotation(R)", lambda: _or_float32(_inverse_hint(got, R), got, R.T))


@exercise("invert_rotation", weight=1)
def test_invert_rotation_undoes(student):
    """R @ invert_rotation(R) is the identity"""
    R = random_rotations(1, seed=152)[0]
    got = expect_array(student.invert_rotation(R), (3, 3), "invert_rotation(R)")
    expect_close(R @ got, np.eye(3), TOL, "R @ invert_rotation(R)", lambda: _inverse_hint(got, R))


@exercise("invert_rotation", weight=1)
def test_invert_rotation_leaves_input_alone(student):
    """returns a new matrix and works on lists"""
    expect_same_with_lists(student.invert_rotation, (random_rotations(1, seed=153)[0],), (3, 3), "invert_rotation(R)")


# ---------------------------------------------------------------- nearest_rotation
def _nearest(M):
    U, _, Vt = np.linalg.svd(M)
    return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt


def _nearest_hint(got, M, otherwise="R = U Vᵀ from the SVD M = U Σ Vᵀ (with the determinant fix)"):
    M = np.asarray(M, dtype=float)
    U, _, Vt = np.linalg.svd(M)
    Q, upper = np.linalg.qr(M)
    Q = Q @ np.diag(np.sign(np.diag(upper)))
    candidates = [
        (_nearest(M).T, "looks like V Uᵀ, the transpose of the answer: R = U Vᵀ"),
        (M / np.linalg.norm(M, axis=0), hints.DIVIDING_EACH_COLUMN_LENGTH_HINT),
        (Q * np.sign(np.linalg.det(Q)), hints.QR_NOT_NEAREST_HINT),
    ]
    if np.linalg.det(U @ Vt) < 0:
        candidates.insert(
            0,
            (
                U @ Vt,
                "U Vᵀ is a reflection here (det -1): when det(U Vᵀ) < 0, flip the last column "
                "of U (use diag(1, 1, det(U Vᵀ)))",
            ),
        )
        flip = np.diag([1.0, 1.0, -1.0])
        for wrong_side in (flip @ U @ Vt, U @ Vt @ flip):  # det +1, but not the nearest rotation
            candidates.append((wrong_side, hints.SIGN_FIX_GOES_BETWEEN_HINT))
    return _first_match(got, candidates, otherwise)


@exercise("nearest_rotation", weight=1)
def test_nearest_rotation_keeps_rotations(student):
    """leaves exact rotations unchanged"""
    for R in random_rotations(10, seed=161):
        got = expect_array(student.nearest_rotation(R), (3, 3), "nearest_rotation(R)")
        expect_close(got, R, 1e-9, "nearest_rotation of a rotation", lambda: _or_float32(_nearest_hint(got, R), got, R))


@exercise("nearest_rotation", weight=2)
def test_nearest_rotation_noisy(student):
    """projects 20 noisy rotations onto the closest rotation (Frobenius norm)"""
    rng = np.random.default_rng(162)
    for R in random_rotations(20, seed=163):
        M = R + 0.05 * rng.normal(size=(3, 3))
        got = expect_array(student.nearest_rotation(M), (3, 3), "nearest_rotation(M)")
        problem = rotation_problem(got)
        expect(problem is None, f"nearest_rotation(M) is not a rotation: {problem}", lambda: _nearest_hint(got, M, ""))
        expect_close(got, _nearest(M), 1e-8, "nearest_rotation(M)", lambda: _nearest_hint(got, M))


@exercise("nearest_rotation", weight=4)
def test_nearest_rotation_never_reflects(student):
    """returns a rotation (det +1) even for mirror-like inputs"""
    rng = np.random.default_rng(164)
    mirror = np.diag([1.0, 1.0, -1.0])
    for R in random_rotations(10, seed=165):
        M = R @ mirror @ np.diag(rng.uniform(0.5, 2.0, 3)) + 0.1 * rng.normal(size=(3, 3))  # det(U Vᵀ) = -1
        got = expect_array(student.nearest_rotation(M), (3, 3), "nearest_rotation(M)")
        det = np.linalg.det(got)
        expect(
            det > 0,
            f"returned a matrix with det = {det:.3f} for a mirror-like M",
            lambda: _nearest_hint(got, M, "the result must be a rotation, det = +1"),
        )
        expect_close(got, _nearest(M), 1e-8, "nearest_rotation(M) for a mirror-like M", lambda: _nearest_hint(got, M))


@exercise("nearest_rotation", weight=1)
def test_nearest_rotation_scaled(student):
    """removes a uniform scale: nearest_rotation(3 R) = R"""
    R = random_rotations(1, seed=166)[0]
    got = expect_array(student.nearest_rotation(3.0 * R), (3, 3), "nearest_rotation(3 R)")
    expect_close(got, R, 1e-9, "nearest_rotation(3 R)", lambda: _nearest_hint(got, 3.0 * R))
