"""Public checks for lesson 05: Euler angles and their singularities.

The checks build attitudes with scipy (intrinsic 'ZYX' angles, a trusted
oracle) and test properties: a single angle turns about its own axis, angles
rebuild the matrix they came from, roll is zero at gimbal lock, and the rate
matrix matches a finite difference of a moving attitude. The candidate
mistakes behind a hint are stored as their values at the checks' fixed inputs
(tests/test_public_check_constants_lesson05.py recomputes each of them).
"""

import numpy as np
from scipy.spatial.transform import Rotation

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import as_float_array, close, rotation_problem, shape_problem
from ..lie import Log
from .common import fmt, off_by, require_shape

E = np.eye(3)
HALF_PI = np.pi / 2
REBUILD_TOL = 1e-11
NAN_HINT = ("np.arcsin of a number a hair beyond ±1 (rounding) is nan: the pitch must come out finite for every "
            "rotation matrix, rounded entries included")


def _zyx(yaw, pitch, roll):
    """Rz(yaw) Ry(pitch) Rx(roll), from scipy's intrinsic 'ZYX' angles (the oracle)."""
    return Rotation.from_euler("ZYX", [yaw, pitch, roll]).as_matrix()


def _quat_to_matrix(q):
    return Rotation.from_quat(np.asarray(q, dtype=float), scalar_first=True).as_matrix()


def _require_angles(value, what="returned"):
    array = as_float_array(value)
    if array is not None and array.shape == (3,) and not np.all(np.isfinite(array)):
        raise Mismatch(f"{what} {fmt(array)}: NaN", NAN_HINT)
    problem = shape_problem(value, (3,))
    if problem:
        raise Mismatch(f"{problem}; return the three angles (yaw, pitch, roll)")
    return array


def _rebuild_error(angles, R):
    return float(np.max(np.abs(_zyx(*angles) - np.asarray(R, dtype=float))))


def _angles_hint(angles, R):
    """The mistake whose angles these are (each candidate rebuilt and compared with R), or None."""
    yaw, pitch, roll = angles
    if _rebuild_error((roll, pitch, yaw), R) < 1e-6:
        return "the angles come back as (roll, pitch, yaw): return (yaw, pitch, roll)"
    if close(Rotation.from_euler("zyx", angles).as_matrix(), R, 1e-6):
        return "these are scipy's lowercase 'zyx' (extrinsic) angles; the course's z-y-x is intrinsic, 'ZYX'"
    if _rebuild_error(np.deg2rad(angles), R) < 1e-6:
        return "looks like degrees: return radians"
    return None


ANGLES_GENERAL_HINT = (hints.ANGLES_MUST_SATISFY_R_HINT)
NO_LOCK_BRANCH_HINT = (hints.NO_SEPARATE_GIMBAL_LOCK_HINT)
LOCK_CONVENTION_HINT = (hints.LOCK_ONLY_YAW_ROLL_HINT)


def _wrapped(difference):
    return (np.asarray(difference, dtype=float) + np.pi) % (2 * np.pi) - np.pi


# ---- Fixed matrices at and next to gimbal lock, stored bit for bit: there the entries that vanish at the lock
# are rounding noise, and that noise decides what a mistaken extraction returns. Each mistake's angles at these
# matrices are stored with them (recomputed by tests/test_public_check_constants_lesson05.py).
# Rz(0.7) Ry(±π/2) Rx(-0.4), each factor built by coursekit.lie.Exp
LOCK_MATRIX = {
    1.0: np.array([[1.6982908130558103e-16, -0.8912073600614352, 0.45359612142557737],
                   [1.4304506184841049e-16, 0.4535961214255774, 0.8912073600614353],
                   [-1.0, -8.64682419684849e-17, 2.0451662452522725e-16]]),
    -1.0: np.array([[1.6982908130558103e-16, -0.29552020666133955, -0.955336489125606],
                    [1.4304506184841049e-16, 0.955336489125606, -0.2955202066613396],
                    [1.0, -8.64682419684849e-17, 2.0451662452522725e-16]]),
}
# scipy's 'ZYX' [2.2, ±(π/2 - 1e-9), -0.9]
NEAR_LOCK_MATRIX = {
    1.0: np.array([[-5.885011888071869e-10, -0.04158066243329024, -0.9991351502732793],
                   [8.084965856525184e-10, -0.9991351502732793, 0.04158066243329024],
                   [-0.9999999999999998, -7.833270872226183e-10, 6.21610044633427e-10]]),
    -1.0: np.array([[-5.885011922224237e-10, -0.963558185417193, -0.26749882862458735],
                    [8.084966029997531e-10, 0.2674988286245873, -0.963558185417193],
                    [1.0, -7.833269588530811e-10, 6.216100967293414e-10]]),
}
# mistake "no lock branch" (the general atan2 formulas used everywhere) at LOCK_MATRIX (the same with R[2, 0]
# rounded past ∓1) and at NEAR_LOCK_MATRIX
NO_BRANCH_AT_LOCK = {1.0: np.array([0.7, 1.5707963267948963, -0.39999999999999997]),
                     -1.0: np.array([0.7, -1.5707963267948963, -0.39999999999999997])}
NO_BRANCH_NEAR_LOCK = {1.0: np.array([2.1999999508405343, 1.5707963257948965, -0.90000005057789]),
                       -1.0: np.array([2.1999999433928763, -1.5707963257948965, -0.8999999299739921])}
# mistake "pitch = arcsin(-R[2, 0])" at NEAR_LOCK_MATRIX
ASIN_PITCH_NEAR_LOCK = {1.0: 1.5707963057214724, -1.0: -1.5707963267948966}


def _rounded_past_one(R, sign):
    """R with R[2, 0] a hair beyond ∓1, as rounding can leave it."""
    rounded = R.copy()
    rounded[2, 0] = -sign * (1.0 + 2.0 ** -52)
    return rounded


def _extraction_hint(angles, R, pitch, no_branch, asin=None, near=False):
    """At or next to the lock: which extraction gave these angles of R (built with this pitch).

    ``no_branch`` and ``asin`` are the angles without a lock branch and the arcsin pitch at R (stored values).
    """
    hint = _angles_hint(angles, R)
    if hint:
        return hint
    if asin is not None and abs(asin - pitch) > 1e-13 and abs(angles[1] - asin) <= 1e-15 + 1e-3 * abs(asin - pitch):
        return (hints.PITCH_ARCSIN_R_LOSES_HINT)
    if np.max(np.abs(_wrapped(angles - no_branch))) <= 1e-12:
        if not near:
            return NO_LOCK_BRANCH_HINT
        difference = np.abs(_zyx(*angles) - np.asarray(R, dtype=float))
        i, j = np.unravel_index(int(np.argmax(difference)), difference.shape)
        return ("next to the lock R[0, 0], R[1, 0], R[2, 1], R[2, 2] shrink like cos(pitch): angles read from them "
                f"rebuild those, but not the large entries (R[{i}, {j}] is off by {difference[i, j]:.1e}); every "
                "entry of R must come back")
    if near and angles[2] == 0.0:
        return "treated a matrix 1e-9 rad from the lock as locked: call it gimbal lock only when cos(pitch) < 1e-12"
    return ("at and next to the lock the angles must rebuild R to 1e-11: check the pitch's digits, the lock test "
            "against the docstring's threshold, and the large entries of R as well as the small ones")


def _random_attitudes(seed, count=5):
    return Rotation.random(count, random_state=seed).as_matrix()


# ---------------------------------------------------------------- euler_zyx_to_matrix
@public_check("euler_zyx_to_matrix", "returns a 3×3 rotation matrix")
def _(euler_zyx_to_matrix):
    R = require_shape(euler_zyx_to_matrix(0.3, -0.4, 1.1), (3, 3))
    problem = rotation_problem(R)
    if problem:
        raise Mismatch(problem)


@public_check("euler_zyx_to_matrix", "one angle at a time: yaw turns about z, pitch about y, roll about x")
def _(euler_zyx_to_matrix):
    cases = [("yaw", (HALF_PI, 0.0, 0.0), 0, 1, "x to y"), ("pitch", (0.0, HALF_PI, 0.0), 2, 0, "z to x"),
             ("roll", (0.0, 0.0, HALF_PI), 1, 2, "y to z")]
    for name, args, source, target, words in cases:
        R = require_shape(euler_zyx_to_matrix(*args), (3, 3))
        image = R @ E[source]
        if close(image, E[target], 1e-9):
            continue
        seen = f"{name} = π/2 sends {words.split()[0]} to {fmt(image)}, expected {words.split()[-1]}"
        if name != "pitch" and close(R, _zyx(*args[::-1]), 1e-9):
            raise Mismatch(f"a quarter turn of {name} turns about the wrong axis",
                           hints.YAW_ROLL_SWAPPED_YAW_HINT)
        if close(R, _zyx(*np.deg2rad(args)), 1e-9):
            raise Mismatch(f"{name} = π/2 barely moves anything (a turn of π/2 degrees)",
                           "looks like degrees: angles are in radians")
        if close(R, _zyx(*args).T, 1e-9):
            if name == "pitch":
                raise Mismatch(seen, hints.PITCH_TURNS_WRONG_WAY_HINT)
            raise Mismatch(seen, f"{name} turns the wrong way: looks like the transpose, check the signs of the sines")
        raise Mismatch(f"{name} = π/2 should send {words}; it sends {words.split()[0]} to {fmt(image)}")


@public_check("euler_zyx_to_matrix", "yaw first, then pitch, then roll about the moving axes: Rz(yaw) Ry(pitch) Rx(roll)")
def _(euler_zyx_to_matrix):
    yaw, pitch, roll = 0.9, -0.5, 1.3
    R = require_shape(euler_zyx_to_matrix(yaw, pitch, roll), (3, 3))
    Rz = require_shape(euler_zyx_to_matrix(yaw, 0.0, 0.0), (3, 3))
    Ry = require_shape(euler_zyx_to_matrix(0.0, pitch, 0.0), (3, 3))
    Rx = require_shape(euler_zyx_to_matrix(0.0, 0.0, roll), (3, 3))
    if close(R, Rz @ Ry @ Rx, 1e-9):
        return
    truth = _zyx(yaw, pitch, roll)
    if close(R, Rx @ Ry @ Rz, 1e-9) and close(R, _zyx(0.0, 0.0, roll) @ _zyx(0.0, pitch, 0.0) @ _zyx(yaw, 0.0, 0.0),
                                              1e-9):
        raise Mismatch("the three turns are multiplied in the x-y-z order, Rx(roll) Ry(pitch) Rz(yaw)",
                       "the x-y-z order is the extrinsic reading (scipy's lowercase 'zyx'); the course uses "
                       "R = Rz(yaw) @ Ry(pitch) @ Rx(roll)")
    if close(R, truth.T, 1e-9):
        raise Mismatch(f"euler_zyx_to_matrix(yaw, pitch, roll) is the transpose of Rz Ry Rx ({off_by(R, truth)})",
                       "looks like the transpose (the inverse rotation): check the signs of the sines")
    raise Mismatch(f"euler_zyx_to_matrix(yaw, pitch, roll) differs from the product of its three single-angle turns "
                   f"({off_by(R, Rz @ Ry @ Rx)})", "return Rz(yaw) @ Ry(pitch) @ Rx(roll)")


# ---------------------------------------------------------------- matrix_to_euler_zyx
@public_check("matrix_to_euler_zyx", "returns (yaw, pitch, roll) that rebuild the matrix (5 random attitudes)")
def _(matrix_to_euler_zyx):
    for R in _random_attitudes(seed=505):
        angles = _require_angles(matrix_to_euler_zyx(R))
        error = _rebuild_error(angles, R)
        if error > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(angles)} rebuild R only to {error:.2g}",
                           _angles_hint(angles, R) or ANGLES_GENERAL_HINT)


@public_check("matrix_to_euler_zyx", "yaw and roll lie in (-π, π], pitch in [-π/2, π/2]")
def _(matrix_to_euler_zyx):
    # Built from out-of-range angles: the same matrix also has in-range angles (yaw ± π, π - pitch, roll ± π).
    for yaw, pitch, roll in [(0.4 + np.pi, np.pi - 0.3, -0.6 + np.pi), (7.0, 2.9, -4.0)]:
        R = _zyx(yaw, pitch, roll)
        got = _require_angles(matrix_to_euler_zyx(R))
        if abs(got[1]) > HALF_PI + 1e-12:
            raise Mismatch(f"pitch = {got[1]:.4f} is outside [-π/2, π/2]", "choose the solution with cos(pitch) >= 0")
        if max(abs(got[0]), abs(got[2])) > np.pi + 1e-12:
            raise Mismatch(f"yaw = {got[0]:.4f}, roll = {got[2]:.4f}: outside (-π, π]")
        if _rebuild_error(got, R) > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(got)} rebuild R only to {_rebuild_error(got, R):.2g}",
                           _angles_hint(got, R) or ANGLES_GENERAL_HINT)


HALF_OPEN_HINT = ("np.arctan2 returns -π for (-0.0, negative): the course's range is (-π, π], so map an angle "
                  "of -π to π at the end")


@public_check("matrix_to_euler_zyx", "a half turn about z is yaw = π, never -π (also when its sine is -0.0)")
def _(matrix_to_euler_zyx):
    half_z = np.array([[-1.0, 0.0, 0.0], [-0.0, -1.0, 0.0], [0.0, 0.0, 1.0]])     # arctan2(-0.0, -1) = -π
    got = _require_angles(matrix_to_euler_zyx(half_z))
    if got[0] != np.pi:
        raise Mismatch(f"yaw = {got[0]:.17g}, expected π (the range is (-π, π])", HALF_OPEN_HINT)


@public_check("matrix_to_euler_zyx", "at gimbal lock (pitch = ±π/2): no NaN, roll = 0, the same matrix")
def _(matrix_to_euler_zyx):
    for sign in (1.0, -1.0):
        R = LOCK_MATRIX[sign]                           # Rz(0.7) Ry(±π/2) Rx(-0.4)
        no_branch = NO_BRANCH_AT_LOCK[sign]
        for matrix in (R, _rounded_past_one(R, sign)):  # rounding can push |R[2, 0]| a hair above 1
            got = _require_angles(matrix_to_euler_zyx(matrix.copy()))
            error = _rebuild_error(got, matrix)
            if abs(got[2]) > 1e-12:
                if np.max(np.abs(_wrapped(got - no_branch))) <= 1e-12:
                    hint = NO_LOCK_BRANCH_HINT
                elif error <= REBUILD_TOL:
                    hint = LOCK_CONVENTION_HINT
                else:
                    hint = _extraction_hint(got, matrix, sign * HALF_PI, no_branch)
                raise Mismatch(f"at pitch = {'+' if sign > 0 else '-'}π/2 the roll is {got[2]:.4f}", hint)
            if error > REBUILD_TOL:
                raise Mismatch(f"at pitch = {'+' if sign > 0 else '-'}π/2 the angles {fmt(got)} rebuild R only "
                               f"to {error:.2g}", _extraction_hint(got, matrix, sign * HALF_PI, no_branch))


@public_check("matrix_to_euler_zyx", "stays exact just next to the lock (pitch = ±(π/2 - 1e-9))")
def _(matrix_to_euler_zyx):
    for sign in (1.0, -1.0):
        R = NEAR_LOCK_MATRIX[sign]                      # scipy's 'ZYX' [2.2, ±(π/2 - 1e-9), -0.9]
        got = _require_angles(matrix_to_euler_zyx(R.copy()))
        error = _rebuild_error(got, R)
        if error > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(got)} rebuild R only to {error:.2g}",
                           _extraction_hint(got, R, sign * (HALF_PI - 1e-9), NO_BRANCH_NEAR_LOCK[sign],
                                            ASIN_PITCH_NEAR_LOCK[sign], near=True))


# ---------------------------------------------------------------- euler_zyx_to_quat
def _same_quat(got, expected, tol=1e-9):
    return close(got, expected, tol) or close(got, -np.asarray(expected), tol)


# mistake "every mixed product of the half-angle formula added (the minus signs lost)" at the checks' angles
ALL_PLUS_QUAT = {
    (0.3, -0.4, 1.1): np.array([0.8106307378338158, 0.4812056554334095, -0.09091621275834293,
                                0.022184271872579528]),
    (0.9, -0.5, 1.3): np.array([0.6294213612575311, 0.44232920676446297, 0.07770496842533611, 0.2006844453230425]),
    (-2.4, 1.1, 0.2): np.array([0.2587402246826965, -0.4538907052376294, 0.10912730781794047, -0.7717081288877795]),
}


def _norm_hint(q, angles):
    all_plus = ALL_PLUS_QUAT.get(tuple(angles))
    if all_plus is not None and _same_quat(q, all_plus):
        return (hints.MIXED_PRODUCTS_LOST_THEIR_HINT)
    return "a rotation quaternion has unit length: q = q_z(yaw) ⊗ q_y(pitch) ⊗ q_x(roll) is a product of unit quaternions"


@public_check("euler_zyx_to_quat", "returns a unit quaternion [w, x, y, z]")
def _(euler_zyx_to_quat):
    q = require_shape(euler_zyx_to_quat(0.3, -0.4, 1.1), (4,))
    if abs(np.linalg.norm(q) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(q):.6f} (off by {abs(np.linalg.norm(q) - 1.0):.2g})",
                       _norm_hint(q, (0.3, -0.4, 1.1)))


@public_check("euler_zyx_to_quat", "a single angle a gives [cos(a/2), sin(a/2) × its axis]")
def _(euler_zyx_to_quat):
    a = 0.8
    for k, (name, axis) in enumerate([("yaw", 3), ("pitch", 2), ("roll", 1)]):
        args = [0.0, 0.0, 0.0]
        args[k] = a
        q = require_shape(euler_zyx_to_quat(*args), (4,))
        expected = np.zeros(4)
        expected[0], expected[axis] = np.cos(a / 2), np.sin(a / 2)
        if _same_quat(q, expected):
            continue
        full = np.zeros(4)
        full[0], full[axis] = np.cos(a), np.sin(a)
        if _same_quat(q, full):
            raise Mismatch(f"{name} = {a} gives {fmt(q)}",
                           "full angles: a quaternion uses half angles, cos(angle / 2), sin(angle / 2)")
        if _same_quat(q, np.roll(expected, -1)):
            raise Mismatch(f"{name} = {a} gives {fmt(q)}",
                           "looks scalar-last [x, y, z, w]: the course's quaternions are [w, x, y, z]")
        raise Mismatch(f"{name} = {a} gives {fmt(q)}, expected ±{fmt(expected)}",
                       "a single angle a about an axis u is the quaternion [cos(a/2), sin(a/2) u]")


@public_check("euler_zyx_to_quat", "the same rotation as Rz(yaw) Ry(pitch) Rx(roll)")
def _(euler_zyx_to_quat):
    for yaw, pitch, roll in [(0.9, -0.5, 1.3), (-2.4, 1.1, 0.2)]:
        q = require_shape(euler_zyx_to_quat(yaw, pitch, roll), (4,))
        if abs(np.linalg.norm(q) - 1.0) > 1e-9:
            raise Mismatch(f"|q| = {np.linalg.norm(q):.6f} (off by {abs(np.linalg.norm(q) - 1.0):.2g})",
                           _norm_hint(q, (yaw, pitch, roll)))
        R = _quat_to_matrix(q)
        if close(R, _zyx(yaw, pitch, roll), 1e-9):
            continue
        if close(R, Rotation.from_euler("zyx", [yaw, pitch, roll]).as_matrix(), 1e-9):     # Rx Ry Rz, extrinsic
            raise Mismatch("the factors are multiplied as q_x ⊗ q_y ⊗ q_z",
                           "q_x ⊗ q_y ⊗ q_z is the extrinsic reading; the course's order is "
                           "q = q_z(yaw) ⊗ q_y(pitch) ⊗ q_x(roll), like the matrices")
        if _same_quat(q, np.roll(Rotation.from_matrix(_zyx(yaw, pitch, roll)).as_quat(scalar_first=True), -1)):
            raise Mismatch(f"euler_zyx_to_quat({yaw}, {pitch}, {roll}) is a different rotation",
                           "looks scalar-last [x, y, z, w]: the course's quaternions are [w, x, y, z]")
        raise Mismatch(f"euler_zyx_to_quat({yaw}, {pitch}, {roll}) is a different rotation "
                       f"(its matrix is {off_by(R, _zyx(yaw, pitch, roll))})",
                       "q = q_z(yaw) ⊗ q_y(pitch) ⊗ q_x(roll)")


# ---------------------------------------------------------------- quat_to_euler_zyx
QUAT_NO_LOCK_HINT = (hints.NO_GIMBAL_LOCK_BRANCH_HINT)
QUAT_ASIN_HINT = ("the lecture's formulas lose digits next to the lock: asin(2(wy - xz)) near ±1, and the atan2 "
                  "arguments for yaw and roll shrink like cos(pitch); use the half-angle sums w ± y, x + z, z - x")


# Fixed quaternions [w, x, y, z] at and next to the lock, stored bit for bit (as the matrices above):
# scipy's 'ZYX' [-1.9, ±π/2, 0.6] and [0.5, ±(π/2 - 1e-9), 2.6]
QUAT_AT_LOCK = {
    1.0: np.array([0.22296658070945657, 0.6710334595880695, 0.2229665807094565, -0.6710334595880696]),
    -1.0: np.array([0.5629162523467828, -0.4279314113778668, -0.5629162523467828, -0.42793141137786694]),
}
QUAT_NEAR_LOCK = {
    1.0: np.array([0.35183586209368856, 0.6133608453297148, 0.35183586207898443, -0.6133608446227607]),
    -1.0: np.array([0.014704163929091157, 0.7069538796851869, -0.014704163577255208, 0.7069538790718259]),
}
# mistake "the lecture's atan2/asin formulas (asin clipped), no lock branch" at those q, for q divided by each of
# NORMS_OF_A_UNIT_QUATERNION. At the lock the formulas' atan2 arguments are rounding noise, so the angles jump with
# the last bit of |q|, and |q| comes from BLAS (np.linalg.norm), whose kernel differs from CPU to CPU: every |q|
# within two units in the last place of 1 is stored (1.0 is q as given, unnormalised).
NORMS_OF_A_UNIT_QUATERNION = (1.0 - 2.0 ** -52, 1.0 - 2.0 ** -53, 1.0, 1.0 + 2.0 ** -52, 1.0 + 2.0 ** -51)
LECTURE_AT_LOCK = {
    1.0: (np.array([-2.498091544796509, 1.5707963267948966, 1.5707963267948966]),
          np.array([-2.498091544796509, 1.5707963267948966, 1.5707963267948966]),
          np.array([-1.5707963267948966, 1.5707963118937354, 0.24497866312686414]),
          np.array([-0.3217505543966422, 1.5707962969925742, 0.16514867741462683]),
          np.array([-0.16514867741462683, 1.5707962796732875, 0.04542327942157701])),
    -1.0: (np.array([-2.677945044588987, -1.5707963267948966, 2.356194490192345]),
           np.array([-2.677945044588987, -1.5707963267948966, 1.5707963267948966]),
           np.array([-1.5707963267948966, -1.5707963267948966, 0.7853981633974483]),
           np.array([-0.4636476090008061, -1.570796290294655, 0.3217505543966422]),
           np.array([-0.27829965900511133, -1.570796284648048, 0.19739555984988075])),
}
LECTURE_NEAR_LOCK = {
    1.0: (np.array([0.5000002134601855, 1.5707963267948966, 2.600000203057621]),
          np.array([0.5000002134601855, 1.5707963267948966, 2.600000203057621]),
          np.array([0.5000000050637824, 1.5707963267948966, 2.6000000410265174]),
          np.array([0.49999989409868145, 1.5707962969925742, 2.599999859664793]),
          np.array([0.4999996811912195, 1.570796284648048, 2.5999996307360234])),
    -1.0: (np.array([0.5000001054281796, -1.5707963267948966, 2.6000000202160125]),
           np.array([0.5000001084729054, -1.5707963267948966, 2.6000000202160125]),
           np.array([0.49999994574742324, -1.5707963057214724, 2.5999999087246577]),
           np.array([0.4999997891114848, -1.5707962934748871, 2.5999996768230287]),
           np.array([0.49999951993252933, -1.5707962796732875, 2.5999993334296536])),
}


def _quat_hint(angles, q, lecture_angles=(), at_lock=False):
    """The mistake behind these angles of q, or a general hint.

    ``lecture_angles``: the lecture formulas' angles at q (stored values, given at and next to the lock only: elsewhere
    they are the right angles, and a (roll, pitch, yaw) return is caught by ``_angles_hint``).
    """
    hint = _angles_hint(angles, _quat_to_matrix(q))
    if hint:
        return hint
    if _rebuild_error(angles, Rotation.from_quat(q).as_matrix()) < 1e-6:
        return "q was read as scalar-last [x, y, z, w]: the course's quaternions are [w, x, y, z]"
    for lecture in lecture_angles:
        if np.max(np.abs(_wrapped(np.asarray(angles)[::-1] - lecture))) <= 1e-9:
            return "the angles come back as (roll, pitch, yaw): return (yaw, pitch, roll)"
        if np.max(np.abs(_wrapped(angles - lecture))) <= 1e-9:
            return QUAT_NO_LOCK_HINT if at_lock else QUAT_ASIN_HINT
    if not at_lock and angles[2] == 0.0:
        return (hints.TREATED_ROTATION_NEXT_LOCK_HINT)
    return ("pitch = 2 atan2(hypot(w + y, z - x), hypot(w - y, x + z)) - π/2, then yaw ± roll from 2 atan2 "
            "of the same half-angle sums")


@public_check("quat_to_euler_zyx", "returns (yaw, pitch, roll) that rebuild the rotation, for q and for -q")
def _(quat_to_euler_zyx):
    for R in _random_attitudes(seed=506, count=4):
        q = Rotation.from_matrix(R).as_quat(scalar_first=True)
        for sign in (1.0, -1.0):
            angles = _require_angles(quat_to_euler_zyx(sign * q))
            error = _rebuild_error(angles, R)
            if error > REBUILD_TOL:
                raise Mismatch(f"the angles {fmt(angles)} of {'-' if sign < 0 else ''}q rebuild the rotation "
                               f"only to {error:.2g}", _quat_hint(angles, sign * q))
            if max(abs(angles[0]), abs(angles[2])) > np.pi + 1e-12 or abs(angles[1]) > HALF_PI + 1e-12:
                raise Mismatch(f"the angles {fmt(angles)} are out of range",
                               "yaw and roll in (-π, π], pitch in [-π/2, π/2]: wrap at the end")


@public_check("quat_to_euler_zyx", "the half turn -[0, 0, 0, 1] is yaw = π, never -π; 2q gives the angles of q")
def _(quat_to_euler_zyx):
    got = _require_angles(quat_to_euler_zyx([0.0, 0.0, 0.0, -1.0]))
    if got[0] != np.pi:
        raise Mismatch(f"quat_to_euler_zyx([0, 0, 0, -1]) gave yaw = {got[0]:.17g}, expected π (the range is "
                       "(-π, π])", HALF_OPEN_HINT)
    q = np.array([0.5, 0.5, 0.5, -0.5])
    unit, double = _require_angles(quat_to_euler_zyx(q)), _require_angles(quat_to_euler_zyx(2.0 * q))
    if np.max(np.abs(_zyx(*unit) - _zyx(*double))) > REBUILD_TOL:
        raise Mismatch(f"q = {fmt(q)} gives {fmt(unit)} but 2q gives {fmt(double)}",
                       hints.NON_UNIT_Q_STANDS_HINT)


@public_check("quat_to_euler_zyx", "at gimbal lock (pitch = ±π/2): no NaN, roll = 0, the same rotation")
def _(quat_to_euler_zyx):
    for sign in (1.0, -1.0):
        q = QUAT_AT_LOCK[sign]                          # scipy's 'ZYX' [-1.9, ±π/2, 0.6]
        R = _quat_to_matrix(q)
        got = _require_angles(quat_to_euler_zyx(q.copy()))
        error = _rebuild_error(got, R)
        if abs(got[2]) > 1e-12:
            hint = (hints.LOCK_ONLY_YAW_ROLL_DEFINED_HINT) if error <= REBUILD_TOL else \
                _quat_hint(got, q, LECTURE_AT_LOCK[sign], at_lock=True)
            raise Mismatch(f"at pitch = {'+' if sign > 0 else '-'}π/2 the roll is {got[2]:.4f}", hint)
        if error > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(got)} rebuild the rotation only to {error:.2g}",
                           _quat_hint(got, q, LECTURE_AT_LOCK[sign], at_lock=True))


@public_check("quat_to_euler_zyx", "stays exact just next to the lock (pitch = ±(π/2 - 1e-9))")
def _(quat_to_euler_zyx):
    for sign in (1.0, -1.0):
        q = QUAT_NEAR_LOCK[sign]                        # scipy's 'ZYX' [0.5, ±(π/2 - 1e-9), 2.6]
        got = _require_angles(quat_to_euler_zyx(q.copy()))
        error = _rebuild_error(got, _quat_to_matrix(q))
        if error > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(got)} rebuild the rotation only to {error:.2g}",
                           _quat_hint(got, q, LECTURE_NEAR_LOCK[sign]))


# ---------------------------------------------------------------- euler_rates_matrix
def _body_rates_by_differences(pitch, roll, yaw=0.4, h=1e-6):
    """The 3×3 matrix of ω_b per unit yaw, pitch and roll rate, by central differences of the z-y-x rotation."""
    angles = np.array([yaw, pitch, roll])
    return np.column_stack([Log(_zyx(*(angles - h * e)).T @ _zyx(*(angles + h * e))) / (2 * h) for e in np.eye(3)])


def _rates_slip_hint(E_got, pitch, roll):
    """Name the slip by what the finite differences say instead: the columns in reverse order, the matrix of
    the opposite roll (each roll sign flipped), or the transpose."""
    numeric = _body_rates_by_differences(pitch, roll)
    for candidate, expected, hint in [(E_got[:, ::-1], numeric, hints.COLUMNS_ORDER_ROLL_PITCH_HINT),
                                      (E_got, _body_rates_by_differences(pitch, -roll), hints.ROLL_SIGNS_FLIPPED_EXPRESS_HINT),
                                      (E_got.T, numeric, "looks like the transpose of E"),
                                      (E_got, np.eye(3), "E = I treats the Euler-angle rates as body rates; they are "
                                       "not: each rate spins about its own axis, seen in the body frame")]:
        if close(candidate, expected, 1e-7):
            return hint
    return None


@public_check("euler_rates_matrix", "at zero angles the three rates spin about z, y and x")
def _(euler_rates_matrix):
    got = require_shape(euler_rates_matrix(0.0, 0.0), (3, 3))
    expected = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])
    if close(got, expected, 1e-12):
        return
    if close(got, np.eye(3), 1e-12):
        raise Mismatch("E(0, 0) is the identity",
                       "the columns belong to [yaw_rate, pitch_rate, roll_rate]: a yaw rate spins about z")
    raise Mismatch(f"E(0, 0) = {fmt(got)}, expected the columns e_z, e_y, e_x")


@public_check("euler_rates_matrix", "E @ rates matches the body rates of a moving attitude (finite differences)")
def _(euler_rates_matrix):
    angles, rates, h = np.array([0.4, 0.7, -1.1]), np.array([0.3, -0.8, 0.5]), 1e-6
    ahead, behind = _zyx(*(angles + h * rates)), _zyx(*(angles - h * rates))
    body = Log(behind.T @ ahead) / (2 * h)    # the turn about the body's own axes over 2h, per second
    world = Log(ahead @ behind.T) / (2 * h)   # the same turn about the world's axes
    E_got = require_shape(euler_rates_matrix(angles[1], angles[2]), (3, 3))
    if close(E_got @ rates, body, 1e-7):
        return
    if close(E_got @ rates, world, 1e-7):
        raise Mismatch("E @ rates gives the angular velocity in the world frame",
                       "the course's E gives body rates: the turn about the body's own axes, as in lesson 03")
    seen = f"E @ rates = {fmt(E_got @ rates)}, but the body rates are {fmt(body)} ({off_by(E_got @ rates, body)})"
    hint = _rates_slip_hint(E_got, angles[1], angles[2])
    if hint:
        raise Mismatch(seen, hint)
    raise Mismatch(seen, "each rate alone spins the body about one axis: try one rate at a time (each gives one "
                         "column of E) and compare it with the finite difference of a pure yaw, pitch or roll")


@public_check("euler_rates_matrix", "|det E| = cos(pitch): it vanishes at pitch = ±π/2")
def _(euler_rates_matrix):
    for pitch in (0.3, -1.0, HALF_PI, -HALF_PI):
        E_got = require_shape(euler_rates_matrix(pitch, 0.6), (3, 3))
        det = abs(np.linalg.det(E_got))
        if abs(det - np.cos(pitch)) > 1e-9:
            raise Mismatch(f"|det E| = {det:.4f} at pitch = {pitch:.4f}, expected cos(pitch) = {np.cos(pitch):.4f}")
