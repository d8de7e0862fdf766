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
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit.diagnose import close

from .helpers import (ALLCLOSE_HINT, exercise, expect, expect_array, expect_bool, expect_close, expect_same_with_lists, fmt,
                      random_angles, random_rotations, rotation_hint, rotation_problem)

TOL = 1e-9
SPECIAL_ANGLES = [0.0, np.pi / 2, -np.pi / 2, np.pi, 2 * np.pi, 1e-9, 10 * np.pi + 0.3, -7.0]


# ---------------------------------------------------------------- rot2d
def _rot2d(theta):
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s], [s, c]])


@exercise("rot2d", weight=3)
def test_rot2d_values(student):
    """matches cos/sin of the angle for random and special angles"""
    for theta in list(random_angles(12, seed=101)) + SPECIAL_ANGLES:
        got = expect_array(student.rot2d(theta), (2, 2), f"rot2d({theta:.4g})")
        expected = _rot2d(theta)
        expect_close(got, expected, TOL, f"rot2d({theta:.4g})",
                     rotation_hint(got, expected, degrees_version=_rot2d(np.deg2rad(theta))))


@exercise("rot2d", weight=1)
def test_rot2d_composes_angles(student):
    """rot2d(a) @ rot2d(b) equals rot2d(a + b)"""
    for a, b in zip(random_angles(5, seed=102), random_angles(5, seed=103)):
        got = expect_array(student.rot2d(a + b), (2, 2), "rot2d(a + b)")
        product = expect_array(student.rot2d(a), (2, 2), "rot2d(a)") @ expect_array(student.rot2d(b), (2, 2), "rot2d(b)")
        expect_close(got, product, TOL, f"rot2d({a + b:.3f}) vs rot2d({a:.3f}) @ rot2d({b:.3f})")


@exercise("rot2d", weight=1)
def test_rot2d_accepts_integers(student):
    """accepts an integer angle (rot2d(0) is the identity)"""
    expect_close(expect_array(student.rot2d(0), (2, 2), "rot2d(0)"), np.eye(2), TOL, "rot2d(0)")


# ---------------------------------------------------------------- rot_x, rot_y, rot_z
ELEMENTARY = [("rot_x", "x", 0), ("rot_y", "y", 1), ("rot_z", "z", 2)]


def _elementary(axis_name, angle):
    return Rotation.from_euler(axis_name, angle).as_matrix()


def _check_elementary(student, name, axis_name, seed):
    function = getattr(student, name)
    for angle in list(random_angles(15, seed=seed)) + SPECIAL_ANGLES:
        got = expect_array(function(angle), (3, 3), f"{name}({angle:.4g})")
        expected = _elementary(axis_name, angle)
        expect_close(got, expected, TOL, f"{name}({angle:.4g})",
                     rotation_hint(got, expected, degrees_version=_elementary(axis_name, np.deg2rad(angle))))


def _check_axis_fixed(student, name, axis):
    function = getattr(student, name)
    e = np.eye(3)[axis]
    for angle in random_angles(6, seed=200 + axis):
        R = expect_array(function(angle), (3, 3), f"{name}({angle:.3f})")
        expect_close(R @ e, e, TOL, f"{name}({angle:.3f}) applied to its own axis",
                     "the rotation axis must not move: its row and column are the unit vector")
        problem = rotation_problem(R)
        expect(problem is None, f"{name}({angle:.3f}): {problem}")


def _check_additive(student, name):
    function = getattr(student, name)
    for a, b in zip(random_angles(5, seed=301), random_angles(5, seed=302)):
        product = expect_array(function(a), (3, 3), name) @ expect_array(function(b), (3, 3), name)
        expect_close(expect_array(function(a + b), (3, 3), name), product, TOL,
                     f"{name}(a + b) vs {name}(a) @ {name}(b) for a={a:.3f}, b={b:.3f}")


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


# ---------------------------------------------------------------- is_rotation_matrix
@exercise("is_rotation_matrix", weight=2)
def test_is_rotation_matrix_accepts_rotations(student):
    """accepts 20 random rotations, the identity and a 2D rotation"""
    candidates = list(random_rotations(20, seed=121)) + [np.eye(3), _rot2d(0.4)]
    for index, R in enumerate(candidates):
        verdict = expect_bool(student.is_rotation_matrix(R), "is_rotation_matrix")
        expect(verdict, f"rejected a valid rotation (#{index}): {fmt(R)}",
               "compare with a tolerance: rounding makes RᵀR differ from I by ~1e-16")


@exercise("is_rotation_matrix", weight=2)
def test_is_rotation_matrix_rejects_reflections(student):
    """rejects reflections (orthogonal with det = -1)"""
    mirror = np.diag([1.0, 1.0, -1.0])
    for index, R in enumerate(random_rotations(10, seed=122)):
        verdict = expect_bool(student.is_rotation_matrix(R @ mirror), "is_rotation_matrix")
        expect(not verdict, f"accepted a reflection (#{index}, det = -1)",
               "orthogonality is not enough: also require det(M) > 0")


@exercise("is_rotation_matrix", weight=2)
def test_is_rotation_matrix_rejects_non_orthogonal(student):
    """rejects scaled, sheared and noisy matrices"""
    R = random_rotations(1, seed=123)[0]
    noise = np.random.default_rng(124).normal(size=(3, 3))
    cases = {"2·R": 2.0 * R, "a shear": np.array([[1.0, 0.3, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
             "R + 1e-6 noise": R + 1e-6 * noise, "the zero matrix": np.zeros((3, 3)),
             "R with its columns scaled by (1, 1, 1.001)": R @ np.diag([1.0, 1.0, 1.001]),
             "diag(1, 1, 1 + 1e-6)": np.diag([1.0, 1.0, 1.0 + 1e-6]),
             "R with its last column stretched by 1e-6": R @ np.diag([1.0, 1.0, 1.0 + 1e-6])}
    for name, M in cases.items():
        verdict = expect_bool(student.is_rotation_matrix(M), "is_rotation_matrix")
        expect(not verdict, f"accepted {name} (max |MᵀM - I| = {np.max(np.abs(M.T @ M - np.eye(3))):.2g})",
               ALLCLOSE_HINT if "1e-6" in name else "check that MᵀM equals I within tol")


@exercise("is_rotation_matrix", weight=1)
def test_is_rotation_matrix_respects_tol(student):
    """uses the tol argument: tiny noise passes, noise above tol fails"""
    R = random_rotations(1, seed=125)[0]
    noise = np.random.default_rng(126).normal(size=(3, 3))
    expect(expect_bool(student.is_rotation_matrix(R + 1e-13 * noise), "is_rotation_matrix"),
           "rejected a rotation with 1e-13 rounding noise at the default tol=1e-9")
    expect(expect_bool(student.is_rotation_matrix(R + 1e-6 * noise, tol=1e-4), "is_rotation_matrix"),
           "rejected R + 1e-6 noise with tol=1e-4", "use the tol argument instead of a fixed number")
    expect(not expect_bool(student.is_rotation_matrix(R + 1e-6 * noise, tol=1e-8), "is_rotation_matrix"),
           "accepted R + 1e-6 noise with tol=1e-8", "use the tol argument instead of a fixed number")


@exercise("is_rotation_matrix", weight=1)
def test_is_rotation_matrix_bad_input(student):
    """returns False, without crashing, for wrong shapes and NaN"""
    cases = {"a 3×4 matrix": np.eye(4)[:3], "a vector": np.ones(3),
             "a matrix with NaN": np.full((3, 3), np.nan), "a nested list 3×2": [[1.0, 0.0]] * 3}
    for name, M in cases.items():
        verdict = expect_bool(student.is_rotation_matrix(M), f"is_rotation_matrix({name})")
        expect(not verdict, f"accepted {name}", "check the shape and that the entries are finite first")


# ---------------------------------------------------------------- rotate_point
@exercise("rotate_point", weight=3)
def test_rotate_point_single(student):
    """p_w = R_wb p_b for 20 random rotations and points"""
    points = np.random.default_rng(131).normal(size=(20, 3))
    for R, p in zip(random_rotations(20, seed=132), points):
        got = expect_array(student.rotate_point(R, p), (3,), "rotate_point(R, p) for one point")
        hint = "looks like you used R.T (the inverse): p_w = R_wb @ p_b" if close(got, R.T @ p, 1e-6) else ""
        expect_close(got, R @ p, TOL, "rotate_point(R, p)", hint)


@exercise("rotate_point", weight=2)
def test_rotate_point_batch(student):
    """rotates N points given as rows, shape (N, 3)"""
    R = random_rotations(1, seed=133)[0]
    P = np.random.default_rng(134).normal(size=(7, 3))
    got = expect_array(student.rotate_point(R, P), (7, 3), "rotate_point(R, P) for 7 points")
    hint = "for rows use P @ R.T" if close(got, P @ R, 1e-6) else ""
    expect_close(got, (R @ P.T).T, TOL, "rotate_point(R, P) for 7 points", hint)


@exercise("rotate_point", weight=1)
def test_rotate_point_accepts_lists(student):
    """accepts plain Python lists"""
    expect_same_with_lists(student.rotate_point, (random_rotations(1, seed=135)[0], [1.0, 2.0, 3.0]), (3,),
                           "rotate_point(R, p)")


# ---------------------------------------------------------------- compose
@exercise("compose", weight=3)
def test_compose_random(student):
    """R_ac = R_ab R_bc for 20 random pairs"""
    As, Bs = random_rotations(20, seed=141), random_rotations(20, seed=142)
    for A, B in zip(As, Bs):
        got = expect_array(student.compose(A, B), (3, 3), "compose(R_ab, R_bc)")
        hint = "the order is reversed: R_ac = R_ab @ R_bc" if close(got, B @ A, 1e-6) else ""
        expect_close(got, A @ B, TOL, "compose(R_ab, R_bc)", hint)


@exercise("compose", weight=1)
def test_compose_identity(student):
    """composing with the identity changes nothing"""
    R = random_rotations(1, seed=143)[0]
    expect_close(expect_array(student.compose(R, np.eye(3)), (3, 3), "compose(R, I)"), R, TOL, "compose(R, I)")
    expect_close(expect_array(student.compose(np.eye(3), R), (3, 3), "compose(I, R)"), R, TOL, "compose(I, R)")


@exercise("compose", weight=1)
def test_compose_accepts_lists(student):
    """accepts plain Python lists"""
    A, B = random_rotations(2, seed=144)
    expect_same_with_lists(student.compose, (A, B), (3, 3), "compose(R_ab, R_bc)")


# ---------------------------------------------------------------- invert_rotation
@exercise("invert_rotation", weight=3)
def test_invert_rotation_random(student):
    """R_ba = R_abᵀ for 20 random rotations"""
    for R in random_rotations(20, seed=151):
        got = expect_array(student.invert_rotation(R), (3, 3), "invert_rotation(R)")
        hint = "returned R itself: the inverse is the transpose" if close(got, R, 1e-6) else ""
        expect_close(got, R.T, TOL, "invert_rotation(R)", hint)


@exercise("invert_rotation", weight=1)
def test_invert_rotation_undoes(student):
    """R @ invert_rotation(R) is the identity"""
    R = random_rotations(1, seed=152)[0]
    got = expect_array(student.invert_rotation(R), (3, 3), "invert_rotation(R)")
    expect_close(R @ got, np.eye(3), TOL, "R @ invert_rotation(R)")


@exercise("invert_rotation", weight=1)
def test_invert_rotation_leaves_input_alone(student):
    """returns a new matrix and works on lists"""
    expect_same_with_lists(student.invert_rotation, (random_rotations(1, seed=153)[0],), (3, 3),
                           "invert_rotation(R)")


# ---------------------------------------------------------------- nearest_rotation
def _nearest(M):
    U, _, Vt = np.linalg.svd(M)
    return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt


@exercise("nearest_rotation", weight=1)
def test_nearest_rotation_keeps_rotations(student):
    """leaves exact rotations unchanged"""
    for R in random_rotations(10, seed=161):
        expect_close(expect_array(student.nearest_rotation(R), (3, 3), "nearest_rotation(R)"), R, 1e-9,
                     "nearest_rotation of a rotation")


@exercise("nearest_rotation", weight=2)
def test_nearest_rotation_noisy(student):
    """projects 20 noisy rotations onto the closest rotation (Frobenius norm)"""
    rng = np.random.default_rng(162)
    for R in random_rotations(20, seed=163):
        M = R + 0.05 * rng.normal(size=(3, 3))
        got = expect_array(student.nearest_rotation(M), (3, 3), "nearest_rotation(M)")
        problem = rotation_problem(got)
        expect(problem is None, f"nearest_rotation(M) is not a rotation: {problem}")
        expect_close(got, _nearest(M), 1e-8, "nearest_rotation(M)", "R = U Vᵀ from the SVD M = U Σ Vᵀ")


@exercise("nearest_rotation", weight=4)
def test_nearest_rotation_never_reflects(student):
    """returns a rotation (det +1) even for mirror-like inputs"""
    rng = np.random.default_rng(164)
    mirror = np.diag([1.0, 1.0, -1.0])
    for R in random_rotations(10, seed=165):
        M = R @ mirror @ np.diag(rng.uniform(0.5, 2.0, 3))
        got = expect_array(student.nearest_rotation(M), (3, 3), "nearest_rotation(M)")
        det = np.linalg.det(got)
        expect(det > 0, f"returned a reflection (det = {det:.3f}) for a mirror-like M",
               "when det(U Vᵀ) < 0, flip the last column of U (use diag(1, 1, det(U Vᵀ)))")
        expect_close(got, _nearest(M), 1e-8, "nearest_rotation(M) for a mirror-like M")


@exercise("nearest_rotation", weight=1)
def test_nearest_rotation_scaled(student):
    """removes a uniform scale: nearest_rotation(3 R) = R"""
    R = random_rotations(1, seed=166)[0]
    expect_close(expect_array(student.nearest_rotation(3.0 * R), (3, 3), "nearest_rotation(3 R)"), R, 1e-9,
                 "nearest_rotation(3 R)")
