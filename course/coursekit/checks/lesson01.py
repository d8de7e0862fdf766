"""Public checks for lesson 01: frames, points and rotation matrices.

The checks use a few rotations written out by hand (quarter turns, whose
entries are 0 and ±1) and properties that any correct answer has.
"""

import numpy as np

from ..checking import Mismatch, public_check
from ..diagnose import ALLCLOSE_HINT, close
from .common import fmt, require_rotation, require_same_with_lists, require_shape

# A quarter turn about z, written out: x goes to y, y goes to -x.
QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
# A quarter turn about x: y goes to z.
QUARTER_TURN_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
E = np.eye(3)


# ---------------------------------------------------------------- rot2d
@public_check("rot2d", "returns a 2×2 rotation matrix")
def _(rot2d):
    require_rotation(require_shape(rot2d(0.7), (2, 2)))


@public_check("rot2d", "a positive angle turns x counter-clockwise (quarter turn: x → y)")
def _(rot2d):
    R = require_shape(rot2d(np.pi / 2), (2, 2))
    image = R @ [1.0, 0.0]
    if close(image, [0.0, 1.0], 1e-9):
        return
    if close(image, [0.0, -1.0], 1e-9):
        raise Mismatch(f"rot2d(pi/2) sends x to {fmt(image)}",
                       "looks like the transpose (a clockwise turn): check the sign of the sines")
    if close(image, [np.cos(np.deg2rad(np.pi / 2)), np.sin(np.deg2rad(np.pi / 2))], 1e-9):
        raise Mismatch(f"rot2d(pi/2) barely moves x: {fmt(image)}",
                       "looks like degrees: angles in this course are radians")
    raise Mismatch(f"rot2d(pi/2) sends x to {fmt(image)}, expected [0, 1]")


# ---------------------------------------------------------------- rot_x, rot_y, rot_z
def _elementary_checks(name, axis, quarter_from, quarter_to):
    @public_check(name, "returns a 3×3 rotation matrix")
    def _(fn):
        require_rotation(require_shape(fn(0.9), (3, 3)))

    @public_check(name, f"leaves its own axis ({'xyz'[axis]}) where it is")
    def _(fn):
        R = require_shape(fn(0.9), (3, 3))
        if not close(R @ E[axis], E[axis], 1e-9):
            raise Mismatch(f"{name}(0.9) moves the {'xyz'[axis]} axis to {fmt(R @ E[axis])}",
                           f"row and column {axis} of {name} should be the unit vector e_{'xyz'[axis]}")

    src, dst = "xyz"[quarter_from], "xyz"[quarter_to]

    @public_check(name, f"a quarter turn sends {src} to {dst} (right-hand rule)")
    def _(fn):
        R = require_shape(fn(np.pi / 2), (3, 3))
        image = R @ E[quarter_from]
        if close(image, E[quarter_to], 1e-9):
            return
        if close(image, -E[quarter_to], 1e-9):
            raise Mismatch(f"{name}(pi/2) sends {src} to {fmt(image)}",
                           "looks like the transpose: the minus sign is on the wrong sine"
                           + (" (for rot_y it sits in the bottom-left)" if name == "rot_y" else ""))
        degrees = np.deg2rad(np.pi / 2)
        if close(image, np.cos(degrees) * E[quarter_from] + np.sin(degrees) * E[quarter_to], 1e-9):
            raise Mismatch(f"{name}(pi/2) barely moves {src}: {fmt(image)}",
                           "looks like degrees: angles in this course are radians")
        raise Mismatch(f"{name}(pi/2) sends {src} to {fmt(image)}, expected e_{dst}")


_elementary_checks("rot_x", 0, 1, 2)
_elementary_checks("rot_y", 1, 2, 0)
_elementary_checks("rot_z", 2, 0, 1)


# ---------------------------------------------------------------- is_rotation_matrix
@public_check("is_rotation_matrix", "accepts rotations (identity, a quarter turn)")
def _(is_rotation_matrix):
    for M in (np.eye(3), QUARTER_TURN_Z):
        verdict = is_rotation_matrix(M)
        if not isinstance(verdict, (bool, np.bool_)):
            raise Mismatch(f"returned {verdict!r}; return a bool (True or False)", "wrap the test in bool(...)")
        if not verdict:
            raise Mismatch(f"rejected the rotation\n{M}")


@public_check("is_rotation_matrix", "rejects a mirror (det = -1) and a scaled matrix")
def _(is_rotation_matrix):
    if is_rotation_matrix(np.diag([1.0, 1.0, -1.0])):
        raise Mismatch("accepted diag(1, 1, -1), a mirror",
                       "orthogonal is not enough: a rotation also needs det = +1")
    if is_rotation_matrix(2.0 * np.eye(3)):
        raise Mismatch("accepted 2·I", "check RᵀR = I, not only that the columns are orthogonal")
    if is_rotation_matrix(QUARTER_TURN_Z @ np.diag([1.0, 1.0, 1.0 + 1e-6])):
        raise Mismatch("accepted a quarter turn with its last column stretched by 1e-6 (tol is 1e-9)",
                       ALLCLOSE_HINT)
    if is_rotation_matrix(np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])):
        raise Mismatch("accepted a shear (det = 1, but the columns are not orthogonal)",
                       "det = +1 is not enough: also check MᵀM = I")
    if not is_rotation_matrix(QUARTER_TURN_Z + 1e-6, tol=1e-4) or is_rotation_matrix(QUARTER_TURN_X + 1e-6):
        raise Mismatch("ignores tol: R + 1e-6 must pass with tol=1e-4 and fail with the default tol=1e-9",
                       "compare with the tol argument, not a fixed number")


@public_check("is_rotation_matrix", "rejects a matrix of the wrong shape without crashing")
def _(is_rotation_matrix):
    if is_rotation_matrix(np.eye(4)[:3]):
        raise Mismatch("accepted a 3×4 matrix", "check the shape first")


# ---------------------------------------------------------------- rotate_point
@public_check("rotate_point", "expresses a point of frame b in frame w (one point, shape (3,))")
def _(rotate_point):
    p_w = require_shape(rotate_point(QUARTER_TURN_Z, [1.0, 0.0, 0.0]), (3,))
    if close(p_w, [0.0, -1.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(p_w)} for x_b with R_wb a quarter turn about z",
                       "looks like you used the transpose of R_wb: p_w = R_wb @ p_b")
    if not close(p_w, [0.0, 1.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(p_w)}, expected [0, 1, 0]")


@public_check("rotate_point", "handles N points at once (shape (N, 3))")
def _(rotate_point):
    points = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0], [1.0, 1.0, 1.0]])
    got = require_shape(rotate_point(QUARTER_TURN_Z, points), (4, 3))
    one_by_one = np.array([QUARTER_TURN_Z @ p for p in points])
    if not close(got, one_by_one, 1e-9):
        raise Mismatch("rows do not match rotating each point on its own",
                       "for rows, use P @ R.T (each row p becomes (R p)ᵀ = pᵀ Rᵀ)")


@public_check("rotate_point", "accepts plain lists")
def _(rotate_point):
    require_same_with_lists(rotate_point, (QUARTER_TURN_X, [0.5, -1.0, 2.0]), (3,), "rotate_point")


# ---------------------------------------------------------------- compose
@public_check("compose", "R_ac = compose(R_ab, R_bc) maps points of c to a in one step")
def _(compose):
    R_ab, R_bc = QUARTER_TURN_Z, QUARTER_TURN_X
    R_ac = require_shape(compose(R_ab, R_bc), (3, 3))
    p_c = np.array([0.3, -1.2, 2.0])
    if close(R_ac @ p_c, R_ab @ (R_bc @ p_c), 1e-9):
        return
    if close(R_ac, R_bc @ R_ab, 1e-9):
        raise Mismatch("the two rotations are multiplied in the wrong order",
                       "subscripts must chain: R_ac = R_ab R_bc (b meets b)")
    raise Mismatch("compose(R_ab, R_bc) @ p_c differs from R_ab @ (R_bc @ p_c)")


@public_check("compose", "accepts plain lists")
def _(compose):
    require_same_with_lists(compose, (QUARTER_TURN_Z, QUARTER_TURN_X), (3, 3), "compose")


# ---------------------------------------------------------------- invert_rotation
@public_check("invert_rotation", "R_ab composed with its inverse is the identity")
def _(invert_rotation):
    R_ba = require_shape(invert_rotation(QUARTER_TURN_Z), (3, 3))
    if close(R_ba, QUARTER_TURN_Z, 1e-9):
        raise Mismatch("returned the same rotation", "the inverse of a rotation is its transpose")
    if not close(QUARTER_TURN_Z @ R_ba, E, 1e-9):
        raise Mismatch("R_ab @ invert_rotation(R_ab) is not the identity")


@public_check("invert_rotation", "accepts plain lists")
def _(invert_rotation):
    require_same_with_lists(invert_rotation, (QUARTER_TURN_X @ QUARTER_TURN_Z,), (3, 3), "invert_rotation")


# ---------------------------------------------------------------- nearest_rotation
@public_check("nearest_rotation", "leaves an exact rotation unchanged")
def _(nearest_rotation):
    got = require_shape(nearest_rotation(QUARTER_TURN_Z), (3, 3))
    if not close(got, QUARTER_TURN_Z, 1e-9):
        raise Mismatch("changed a matrix that was already a rotation")


@public_check("nearest_rotation", "turns a slightly wrong matrix into a rotation close to it")
def _(nearest_rotation):
    noisy = QUARTER_TURN_Z + 0.01 * np.array([[0.3, -0.2, 0.5], [0.1, 0.4, -0.3], [-0.2, 0.2, 0.1]])
    got = require_shape(nearest_rotation(noisy), (3, 3))
    require_rotation(got)
    if np.max(np.abs(got - noisy)) > 0.02:
        raise Mismatch("the result is a rotation, but far from the input")
    asymmetry = np.max(np.abs(got.T @ noisy - noisy.T @ got))
    if asymmetry > 1e-9:
        raise Mismatch(f"the result is a rotation near the input, but not the nearest: Rᵀ M is not symmetric "
                       f"(off by {asymmetry:.2g})", "the nearest rotation comes from the SVD M = U Σ Vᵀ: R = U Vᵀ")


@public_check("nearest_rotation", "never returns a mirror, even for a mirror-like input")
def _(nearest_rotation):
    got = require_shape(nearest_rotation(np.diag([1.0, 1.0, -0.9])), (3, 3))
    if np.linalg.det(got) < 0:
        raise Mismatch(f"det of the result is {np.linalg.det(got):.3f}",
                       "U Vᵀ can be a reflection: flip the sign of the last column of U when det(U Vᵀ) < 0")
    require_rotation(got)
