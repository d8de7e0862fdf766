"""Public checks for lesson 01: frames, points and rotation matrices.

The checks use a few rotations written out by hand (quarter turns, whose
entries are 0 and ±1) and properties that any correct answer has.
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, _where_in_student_code, public_check
from ..diagnose import ALLCLOSE_HINT, FLOAT32_HINT, SERIES_HINT, close, float32_rounding, rotation_problem
from ..lie import Exp
from .common import fmt, off_by, require_rotation, require_same_with_lists, require_shape
from .tolerance import GAP_EXPONENTS, boundary_problem

# A quarter turn about z, written out: x goes to y, y goes to -x.
QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
# A quarter turn about x: y goes to z.
QUARTER_TURN_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
E = np.eye(3)
# Generic rotations (no zero entries), for naming a mistake from its value.
GENERIC_A, GENERIC_B = Exp([0.3, -0.8, 0.5]), Exp([-0.6, 0.2, 0.9])
# A generic angle, then every decade where a shortcut's error could hide, both signs, from 1 down to 1e-8:
# a float32 answer fails at the first, a small-angle series only further down.
DECADE_ANGLES = [0.9] + [sign * 10.0 ** -k for k in range(9) for sign in (1.0, -1.0)]
PRECISION = 1e-12  # cos and sin in float64 are accurate to about 1e-16; a float32 array or a series is not


def _precision_mismatch(what, got, expected, angle):
    """A Mismatch for ``got`` (the answer for ``angle``) off from ``expected`` by more than PRECISION, naming
    float32 rounding or a small-angle series when the error looks like one."""
    error = float(np.max(np.abs(got - expected)))
    hint = None
    if abs(angle) >= 0.1 and float32_rounding(got, expected):
        hint = FLOAT32_HINT
    elif abs(angle) < 0.1:
        hint = SERIES_HINT
    return Mismatch(f"{what} is off by {error:.2g} at angle {angle:.0e} (allowed: {PRECISION:.0e})", hint)


def _require_double_precision(what, got, expected):
    """Mismatch unless ``got`` equals ``expected`` to PRECISION (float64 matrix arithmetic stays far below it)."""
    if not close(got, expected, PRECISION):
        raise Mismatch(f"{what} is {off_by(got, expected)} for generic entries (allowed: {PRECISION:.0e})",
                       FLOAT32_HINT if float32_rounding(got, expected) else None)


SAME_SIGN_HINT = (hints.BOTH_SINES_HAVE_SAME_HINT)


def _first_match(got, candidates, otherwise=None):
    """The hint of the first (value a typical mistake returns, hint) that ``got`` equals, else ``otherwise``."""
    for candidate, hint in candidates:
        if close(got, candidate, 1e-9):
            return hint
    return otherwise


def _crash(error, hint, given=""):
    """A Mismatch for an exception raised by the student's code (given ``given``, when named), naming its
    likely cause."""
    on = f" on {given}" if given else ""
    return Mismatch(f"raised {type(error).__name__}{on}: {error}{_where_in_student_code(error)}", hint)


def _same_sign_sines(R, i, j, angle):
    """True when the sine entries (i, j) and (j, i) of R are ±sin(angle) with the same sign."""
    s = np.sin(angle)
    return abs(R[i, j] - R[j, i]) <= 1e-9 and abs(abs(R[i, j]) - abs(s)) <= 1e-9 and abs(s) > 1e-3


# ---------------------------------------------------------------- rot2d
@public_check("rot2d", "returns a 2×2 rotation matrix")
def _(rot2d):
    R = require_shape(rot2d(0.7), (2, 2))
    if _same_sign_sines(R, 0, 1, 0.7) and rotation_problem(R):
        raise Mismatch(f"rot2d(0.7) is not a rotation: {rotation_problem(R)}", SAME_SIGN_HINT)
    require_rotation(R)


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
    c, s = np.cos(0.7), np.sin(0.7)
    hint = _first_match(require_shape(rot2d(0.7), (2, 2)), [
        (np.array([[s, -c], [c, s]]), hints.SINE_COSINE_SWAPPED_COS_HINT)])
    raise Mismatch(f"rot2d(pi/2) sends x to {fmt(image)}, expected [0, 1]", hint)


@public_check("rot2d", "agrees with cos and sin to 1e-12 at every decade of angle, 1e-8 … 1")
def _(rot2d):
    for angle in DECADE_ANGLES:
        got = require_shape(rot2d(angle), (2, 2), f"rot2d({angle:.0e})")
        c, s = np.cos(angle), np.sin(angle)
        if not close(got, [[c, -s], [s, c]], PRECISION):
            raise _precision_mismatch(f"rot2d({angle:.0e})", got, np.array([[c, -s], [s, c]]), angle)


# ---------------------------------------------------------------- rot_x, rot_y, rot_z
def _elementary_checks(name, axis, quarter_from, quarter_to):
    i, j = [k for k in range(3) if k != axis]

    @public_check(name, "returns a 3×3 rotation matrix")
    def _(fn):
        R = require_shape(fn(0.9), (3, 3))
        if _same_sign_sines(R, i, j, 0.9):
            raise Mismatch(f"{name}(0.9): the two sine entries are equal, {R[i, j]:.3f}, so RᵀR ≠ I "
                           f"({off_by(R.T @ R, E)})", SAME_SIGN_HINT)
        require_rotation(R)

    @public_check(name, f"leaves its own axis ({'xyz'[axis]}) where it is")
    def _(fn):
        R = require_shape(fn(0.9), (3, 3))
        if not close(R @ E[axis], E[axis], 1e-9):
            hint = f"row and column {axis} of {name} should be the unit vector e_{'xyz'[axis]}"
            if close(R[axis], 0.0 * E[axis], 1e-9) and close(R[:, axis], 0.0 * E[axis], 1e-9):
                hint = f"the diagonal entry of the {'xyz'[axis]} axis is 0: it must be 1 (the axis does not move)"
            for other in {i, j}:
                if close(R @ E[other], E[other], 1e-9):
                    hint = (f"this is a rotation about {'xyz'[other]}, not {'xyz'[axis]}: the cos/sin block of "
                            f"{name} sits in the rows and columns of the other two axes")
            raise Mismatch(f"{name}(0.9) moves the {'xyz'[axis]} axis to {fmt(R @ E[axis])}", hint)

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

    @public_check(name, "agrees with cos and sin to 1e-12 at every decade of angle, 1e-8 … 1")
    def _(fn):
        for angle in DECADE_ANGLES:
            got = require_shape(fn(angle), (3, 3), f"{name}({angle:.0e})")
            expected = np.eye(3)
            c, s = np.cos(angle), np.sin(angle)
            expected[i, i] = expected[j, j] = c
            expected[j, i], expected[i, j] = (s, -s) if axis != 1 else (-s, s)
            if not close(got, expected, PRECISION):
                raise _precision_mismatch(f"{name}({angle:.0e})", got, expected, angle)


_elementary_checks("rot_x", 0, 1, 2)
_elementary_checks("rot_y", 1, 2, 0)
_elementary_checks("rot_z", 2, 0, 1)


# ---------------------------------------------------------------- is_rotation_matrix
EXACT_ROTATION_HINT = ("an exact rotation (MᵀM is exactly I) was rejected: print the product your test compares "
                       "with I (a quarter turn times itself is a half turn, not I)")


@public_check("is_rotation_matrix", "accepts rotations (identity, a quarter turn)")
def _(is_rotation_matrix):
    for M in (np.eye(3), QUARTER_TURN_Z):
        verdict = is_rotation_matrix(M)
        if not isinstance(verdict, (bool, np.bool_)):
            raise Mismatch(f"returned {verdict!r}; return a bool (True or False)", "wrap the test in bool(...)")
        if not verdict:
            raise Mismatch(f"rejected the rotation\n{M}", EXACT_ROTATION_HINT)


@public_check("is_rotation_matrix", "rejects a mirror (det = -1) and a scaled matrix")
def _(is_rotation_matrix):
    if is_rotation_matrix(np.diag([1.0, 1.0, -1.0])):
        raise Mismatch("accepted diag(1, 1, -1), a mirror",
                       "orthogonal is not enough: a rotation also needs det = +1")
    if is_rotation_matrix(2.0 * np.eye(3)):
        raise Mismatch("accepted 2·I", "check RᵀR = I, not only that the columns are orthogonal")
    stretched = QUARTER_TURN_Z @ np.diag([1.0, 1.0, 1.0 + 1e-6])
    if is_rotation_matrix(stretched):
        gram = stretched.T @ stretched
        raise Mismatch(f"accepted a quarter turn with its last column stretched by 1e-6: max |MᵀM - I| = "
                       f"{np.max(np.abs(gram - E)):.2g}, tol is 1e-9",
                       ALLCLOSE_HINT if np.allclose(gram, E, atol=1e-9) else "compare max |MᵀM - I| with tol")
    if is_rotation_matrix(np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])):
        raise Mismatch("accepted a shear (det = 1, but the columns are not orthogonal)",
                       "a shear has det 1 too: also check max |MᵀM - I| <= tol")
    ignores = "the verdict does not follow tol: compare with the tol argument, not a fixed number"
    if not is_rotation_matrix(QUARTER_TURN_Z + 1e-6, tol=1e-4):
        if not is_rotation_matrix(QUARTER_TURN_Z):
            raise Mismatch("rejected R + 1e-6 with tol=1e-4, and R itself", EXACT_ROTATION_HINT)
        raise Mismatch("rejected R + 1e-6 (max |MᵀM - I| ≈ 2e-6) with tol=1e-4",
                       ignores if not is_rotation_matrix(QUARTER_TURN_Z + 1e-6, tol=0.1) else None)
    if is_rotation_matrix(QUARTER_TURN_X + 1e-6):
        raise Mismatch("accepted R + 1e-6 (max |MᵀM - I| ≈ 2e-6) with the default tol=1e-9",
                       ignores if is_rotation_matrix(QUARTER_TURN_X + 1e-6, tol=1e-15) else None)


NOT_A_MATRIX_HINT = ("for input that is not a matrix at all (a ragged list, None, a dict) np.asarray raises ValueError "
                     "or TypeError: \"anything else gives False\", so catch those and return False")


@public_check("is_rotation_matrix", "gives False without crashing for anything else: a 3×4, a ragged list, None, a dict")
def _(is_rotation_matrix):
    cases = {"a 3×4 matrix": np.eye(4)[:3], "a ragged nested list": [[1.0, 0.0, 0.0], [0.0, 1.0], [0.0, 0.0, 1.0]],
             "None": None, "a dict": {"R": np.eye(3)}}
    for name, M in cases.items():
        try:
            verdict = is_rotation_matrix(M)
        except Exception as error:
            raise _crash(error, NOT_A_MATRIX_HINT if name in ("a ragged nested list", "None", "a dict")
                         else hints.CHECK_M_S_SHAPE_HINT, name) from None
        if verdict:
            raise Mismatch(f"accepted {name}", "check the shape first: a rotation matrix is square")



@public_check("is_rotation_matrix", "tol is the largest accepted max |MᵀM - I|: just below, at and just above it")
def _(is_rotation_matrix):
    for k in GAP_EXPONENTS:
        s = 1.0 + 2.0**-k  # diag(s, s, 1): max |MᵀM - I| = s² - 1, exact in binary
        name = f"is_rotation_matrix(diag(1 + 2^-{k}, 1 + 2^-{k}, 1), tol)"
        M = np.diag([s, s, 1.0])
        problem = boundary_problem(lambda tol: is_rotation_matrix(M, tol=tol), s * s - 1.0, "max |MᵀM - I|", name)
        if problem:
            raise Mismatch(*problem)

# ---------------------------------------------------------------- rotate_point
@public_check("rotate_point", "expresses a point of frame b in frame w (one point, shape (3,))")
def _(rotate_point):
    p_w = require_shape(rotate_point(QUARTER_TURN_Z, [1.0, 0.0, 0.0]), (3,))
    if close(p_w, [0.0, -1.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(p_w)} for x_b with R_wb a quarter turn about z",
                       "looks like you used the transpose of R_wb: p_w = R_wb @ p_b")
    if not close(p_w, [0.0, 1.0, 0.0], 1e-9):
        raise Mismatch(f"got {fmt(p_w)}, expected [0, 1, 0]")


ROWS_HINT = hints.ONE_POINT_NOT_ROWS_HINT


@public_check("rotate_point", "handles N points at once (shape (N, 3))")
def _(rotate_point):
    points = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0], [1.0, 1.0, 1.0]])
    try:
        value = rotate_point(QUARTER_TURN_Z, points)
    except Exception as error:
        if "broadcast" in str(error):
            raise _crash(error, hints.NUMPY_COULD_BROADCAST_R_HINT) from None
        raise _crash(error, ROWS_HINT) from None
    got = require_shape(value, (4, 3))
    one_by_one = np.array([QUARTER_TURN_Z @ p for p in points])
    if not close(got, one_by_one, 1e-9):
        raise Mismatch(f"rows do not match rotating each point on its own ({off_by(got, one_by_one)})",
                       "for rows, use P @ R.T (each row p becomes (R p)ᵀ = pᵀ Rᵀ)")


def _batch_of_four(rotate_point):
    """What ``rotate_point`` does with 4 points as rows (a shape that cannot be misread): "rows" when it
    rotates each row, "raises" when it cannot take a batch, else "wrong"."""
    points = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0], [1.0, 1.0, 1.0]])
    try:
        got = np.asarray(rotate_point(QUARTER_TURN_Z, points), dtype=float)
    except Exception:
        return "raises"
    return "rows" if got.shape == (4, 3) and close(got, points @ QUARTER_TURN_Z.T, 1e-9) else "wrong"


SQUARE_BATCH_HINT = ("a batch of 3 points, shape (3, 3), was read as 3 columns: tell one point from a batch by "
                     "p.ndim (1 or 2), never by shape[0] == 3; P @ R.T handles both")


@public_check("rotate_point", "reads a batch of exactly 3 points (shape (3, 3)) as rows too")
def _(rotate_point):
    points = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1.0, 1.0, 3.0]])
    got = require_shape(rotate_point(QUARTER_TURN_Z, points), (3, 3))
    one_by_one = np.array([QUARTER_TURN_Z @ p for p in points])
    if not close(got, one_by_one, 1e-9):
        four = _batch_of_four(rotate_point)  # the check above has the hint when no batch works
        if four == "raises":
            hint = ROWS_HINT
        elif four == "rows" and close(got, QUARTER_TURN_Z @ points, 1e-9):
            hint = SQUARE_BATCH_HINT
        else:
            hint = "for rows, use P @ R.T (each row p becomes (R p)ᵀ = pᵀ Rᵀ)"
        raise Mismatch(f"the 3 rows do not match rotating each point on its own ({off_by(got, one_by_one)})", hint)


@public_check("rotate_point", "agrees with R_wb @ p_b to 1e-12 for a generic rotation and point")
def _(rotate_point):
    p_b = np.array([0.3, -1.7, 2.9])
    got = require_shape(rotate_point(GENERIC_A, p_b.copy()), (3,))
    _require_double_precision("rotate_point(R_wb, p_b)", got, GENERIC_A @ p_b)


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
    A, B = GENERIC_A, GENERIC_B
    hint = _first_match(require_shape(compose(A, B), (3, 3)), [
        (A * B, hints.ELEMENTWISE_PRODUCT_HINT),
        (A.T @ B, hints.FIRST_FACTOR_TRANSPOSED_HINT)])
    raise Mismatch(f"compose(R_ab, R_bc) @ p_c differs from R_ab @ (R_bc @ p_c) "
                   f"({off_by(R_ac @ p_c, R_ab @ (R_bc @ p_c))})", hint)


@public_check("compose", "agrees with R_ab @ R_bc to 1e-12 for generic rotations")
def _(compose):
    got = require_shape(compose(GENERIC_A.copy(), GENERIC_B.copy()), (3, 3))
    _require_double_precision("compose(R_ab, R_bc)", got, GENERIC_A @ GENERIC_B)


@public_check("compose", "accepts plain lists")
def _(compose):
    require_same_with_lists(compose, (QUARTER_TURN_Z, QUARTER_TURN_X), (3, 3), "compose")


# ---------------------------------------------------------------- invert_rotation
@public_check("invert_rotation", "R_ab composed with its inverse is the identity")
def _(invert_rotation):
    R_ba = require_shape(invert_rotation(QUARTER_TURN_Z), (3, 3))
    if not close(QUARTER_TURN_Z @ R_ba, E, 1e-9):
        R = GENERIC_A
        hint = _first_match(require_shape(invert_rotation(R), (3, 3)), [
            (R, "returned R itself: the inverse of a rotation is its transpose"),
            (-R, hints.NEGATED_NOT_TRANSPOSED_HINT),
            (R[::-1], hints.REVERSED_ORDER_ROWS_R_HINT)], "the inverse of a rotation is its transpose")
        raise Mismatch(f"R_ab @ invert_rotation(R_ab) is not the identity ({off_by(QUARTER_TURN_Z @ R_ba, E)})",
                       hint)


@public_check("invert_rotation", "agrees with the transpose to 1e-12 for a generic rotation")
def _(invert_rotation):
    got = require_shape(invert_rotation(GENERIC_A.copy()), (3, 3))
    _require_double_precision("invert_rotation(R_ab)", got, GENERIC_A.T)


@public_check("invert_rotation", "accepts plain lists")
def _(invert_rotation):
    require_same_with_lists(invert_rotation, (QUARTER_TURN_X @ QUARTER_TURN_Z,), (3, 3), "invert_rotation")


# ---------------------------------------------------------------- nearest_rotation
@public_check("nearest_rotation", "leaves an exact rotation unchanged")
def _(nearest_rotation):
    got = require_shape(nearest_rotation(QUARTER_TURN_Z), (3, 3))
    if not close(got, QUARTER_TURN_Z, 1e-9):
        raise Mismatch(f"changed a matrix that was already a rotation ({off_by(got, QUARTER_TURN_Z)})",
                       _first_match(got, [(QUARTER_TURN_Z.T, "returned the transpose, V Uᵀ: R = U Vᵀ")]))


@public_check("nearest_rotation", "leaves a generic rotation unchanged to 1e-12")
def _(nearest_rotation):
    got = require_shape(nearest_rotation(GENERIC_B.copy()), (3, 3))
    _require_double_precision("nearest_rotation(R)", got, GENERIC_B)


@public_check("nearest_rotation", "turns a slightly wrong matrix into a rotation close to it")
def _(nearest_rotation):
    noisy = QUARTER_TURN_Z + 0.01 * np.array([[0.3, -0.2, 0.5], [0.1, 0.4, -0.3], [-0.2, 0.2, 0.1]])
    got = require_shape(nearest_rotation(noisy), (3, 3))
    Q, upper = np.linalg.qr(noisy)
    Q = Q @ np.diag(np.sign(np.diag(upper)))
    hint = _first_match(got, [
        (noisy / np.linalg.norm(noisy, axis=0), hints.DIVIDING_EACH_COLUMN_LENGTH_HINT),
        (Q * np.sign(np.linalg.det(Q)), hints.QR_NOT_NEAREST_HINT)])
    if hint:
        problem = rotation_problem(got)
        raise Mismatch(f"not the nearest rotation: {problem}" if problem else
                       f"the result is a rotation near the input, but not the nearest: RᵀM is not symmetric "
                       f"(off by {np.max(np.abs(got.T @ noisy - noisy.T @ got)):.2g})", hint)
    require_rotation(got)
    if np.max(np.abs(got - noisy)) > 0.02:
        raise Mismatch("the result is a rotation, but far from the input")
    asymmetry = np.max(np.abs(got.T @ noisy - noisy.T @ got))
    if asymmetry > 1e-9:
        raise Mismatch(f"the result is a rotation near the input, but not the nearest: Rᵀ M is not symmetric "
                       f"(off by {asymmetry:.2g})", "the nearest rotation comes from the SVD M = U Σ Vᵀ: R = U Vᵀ")


@public_check("nearest_rotation", "never returns a mirror, even for a mirror-like input")
def _(nearest_rotation):
    M = np.diag([1.0, 1.0, -0.9]) + 0.2 * np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]])
    got = require_shape(nearest_rotation(M), (3, 3))
    if np.linalg.det(got) < 0:
        U, _, Vt = np.linalg.svd(M)
        raise Mismatch(f"det of the result is {np.linalg.det(got):.3f}", _first_match(got, [
            (U @ Vt, "U Vᵀ can be a reflection: flip the sign of the last column of U when det(U Vᵀ) < 0"),
            (M / np.linalg.norm(M, axis=0), "dividing each column by its length keeps the mirror (det -1): "
                                            "project with the SVD, and flip the last column of U when det(U Vᵀ) < 0")],
            "the result must be a rotation, det = +1"))
    require_rotation(got)
    asymmetry = np.max(np.abs(got.T @ M - M.T @ got))
    if asymmetry > 1e-9:
        U, _, Vt = np.linalg.svd(M)
        flip = np.diag([1.0, 1.0, -1.0])
        fix = (hints.SIGN_FIX_GOES_BETWEEN_HINT)
        raise Mismatch(f"the result is a rotation, but not the nearest one: Rᵀ M is not symmetric (off by "
                       f"{asymmetry:.2g})", _first_match(got, [(flip @ U @ Vt, fix), (U @ Vt @ flip, fix)],
                                                       "the nearest rotation comes from the SVD M = U Σ Vᵀ: "
                                                       "R = U diag(1, 1, det(U Vᵀ)) Vᵀ"))
