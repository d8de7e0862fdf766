"""Public checks for lesson 05: Euler angles and their singularities.

The checks build attitudes from elementary rotations (``coursekit.lie.Exp``
about one coordinate axis at a time, the definition of z-y-x angles) and from
scipy, and test properties: a single angle turns about its own axis, angles
rebuild the matrix they came from, roll is zero at gimbal lock, and the rate
matrix matches a finite difference of a moving attitude.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from ..checking import Mismatch, public_check
from ..diagnose import as_float_array, close, rotation_problem, shape_problem
from ..lie import Exp, unskew
from .common import fmt, require_shape

E = np.eye(3)
HALF_PI = np.pi / 2
REBUILD_TOL = 1e-11
NAN_HINT = ("np.arcsin of a number a hair beyond ±1 (rounding) is nan: get pitch from "
            "atan2(-R[2, 0], hypot(R[0, 0], R[1, 0])), or clip the argument to [-1, 1]")


def _zyx(yaw, pitch, roll):
    """Rz(yaw) Ry(pitch) Rx(roll), each an elementary rotation (the definition)."""
    return Exp([0.0, 0.0, yaw]) @ Exp([0.0, pitch, 0.0]) @ Exp([roll, 0.0, 0.0])


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
    yaw, pitch, roll = angles
    if _rebuild_error((roll, pitch, yaw), R) < 1e-6:
        return "the angles come back as (roll, pitch, yaw): return (yaw, pitch, roll)"
    if close(Rotation.from_euler("zyx", angles).as_matrix(), R, 1e-6):
        return "these are scipy's lowercase 'zyx' (extrinsic) angles; the course's z-y-x is intrinsic, 'ZYX'"
    if _rebuild_error(np.deg2rad(angles), R) < 1e-6:
        return "looks like degrees: return radians"
    return None


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
        if name != "pitch" and close(R, _zyx(*args[::-1]), 1e-9):
            raise Mismatch(f"a quarter turn of {name} turns about the wrong axis",
                           "yaw and roll are swapped: yaw turns about z, roll about x")
        if close(image, -E[target], 1e-9):
            raise Mismatch(f"{name} = π/2 sends {words.split()[0]} to {fmt(image)}, expected {words.split()[-1]}",
                           "looks like the transpose: check the signs of the sines")
        if close(image, E[source], 0.05):
            raise Mismatch(f"{name} = π/2 barely moves anything", "looks like degrees: angles are in radians")
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
    if close(R, Rx @ Ry @ Rz, 1e-9):
        raise Mismatch("the three turns are multiplied in the x-y-z order, Rx(roll) Ry(pitch) Rz(yaw)",
                       "that is the extrinsic reading (scipy's lowercase 'zyx'); the course uses "
                       "R = Rz(yaw) @ Ry(pitch) @ Rx(roll)")
    raise Mismatch("euler_zyx_to_matrix(yaw, pitch, roll) differs from the product of its three single-angle turns")


# ---------------------------------------------------------------- matrix_to_euler_zyx
@public_check("matrix_to_euler_zyx", "returns (yaw, pitch, roll) that rebuild the matrix (5 random attitudes)")
def _(matrix_to_euler_zyx):
    for R in _random_attitudes(seed=505):
        angles = _require_angles(matrix_to_euler_zyx(R))
        error = _rebuild_error(angles, R)
        if error > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(angles)} rebuild R only to {error:.2g}", _angles_hint(angles, R))


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
            raise Mismatch(f"the angles {fmt(got)} do not rebuild R", _angles_hint(got, R))


@public_check("matrix_to_euler_zyx", "at gimbal lock (pitch = ±π/2): no NaN, roll = 0, the same matrix")
def _(matrix_to_euler_zyx):
    for sign in (1.0, -1.0):
        R = _zyx(0.7, sign * HALF_PI, -0.4)
        rounded = R.copy()
        rounded[2, 0] = -sign * (1.0 + 2.0 ** -52)     # rounding can push |R[2, 0]| a hair above 1
        for matrix in (R, rounded):
            got = _require_angles(matrix_to_euler_zyx(matrix))
            if abs(got[2]) > 1e-12:
                raise Mismatch(f"at pitch = {'+' if sign > 0 else '-'}π/2 the roll is {got[2]:.4f}",
                               "at the lock only yaw ∓ roll is defined: the course sets roll = 0 "
                               "and yaw = atan2(-R[0, 1], R[1, 1])")
            if _rebuild_error(got, matrix) > REBUILD_TOL:
                raise Mismatch(f"at pitch = {'+' if sign > 0 else '-'}π/2 the angles {fmt(got)} do not rebuild R",
                               _angles_hint(got, matrix))


@public_check("matrix_to_euler_zyx", "stays exact just next to the lock (pitch = ±(π/2 - 1e-9))")
def _(matrix_to_euler_zyx):
    for sign in (1.0, -1.0):
        R = Rotation.from_euler("ZYX", [2.2, sign * (HALF_PI - 1e-9), -0.9]).as_matrix()
        got = _require_angles(matrix_to_euler_zyx(R))
        error = _rebuild_error(got, R)
        if error > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(got)} rebuild R only to {error:.2g}",
                           "take pitch from atan2(-R[2, 0], hypot(R[0, 0], R[1, 0])), call it locked only when "
                           "cos(pitch) < 1e-12, and get roll from the large entries once yaw is known")


# ---------------------------------------------------------------- euler_zyx_to_quat
def _same_quat(got, expected, tol=1e-9):
    return close(got, expected, tol) or close(got, -np.asarray(expected), tol)


@public_check("euler_zyx_to_quat", "returns a unit quaternion [w, x, y, z]")
def _(euler_zyx_to_quat):
    q = require_shape(euler_zyx_to_quat(0.3, -0.4, 1.1), (4,))
    if abs(np.linalg.norm(q) - 1.0) > 1e-9:
        raise Mismatch(f"|q| = {np.linalg.norm(q):.6f}", "a rotation quaternion has unit length: check the half angles")


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
            raise Mismatch(f"{name} = {a} gives {fmt(q)}", "use half angles: cos(angle / 2), sin(angle / 2)")
        if _same_quat(q, np.roll(expected, -1)):
            raise Mismatch(f"{name} = {a} gives {fmt(q)}", "scalar first: the course's quaternions are [w, x, y, z]")
        raise Mismatch(f"{name} = {a} gives {fmt(q)}, expected ±{fmt(expected)}")


@public_check("euler_zyx_to_quat", "the same rotation as Rz(yaw) Ry(pitch) Rx(roll)")
def _(euler_zyx_to_quat):
    for yaw, pitch, roll in [(0.9, -0.5, 1.3), (-2.4, 1.1, 0.2)]:
        q = require_shape(euler_zyx_to_quat(yaw, pitch, roll), (4,))
        if abs(np.linalg.norm(q) - 1.0) > 1e-9:
            raise Mismatch(f"|q| = {np.linalg.norm(q):.6f}")
        R = _quat_to_matrix(q)
        if close(R, _zyx(yaw, pitch, roll), 1e-9):
            continue
        if close(R, Exp([roll, 0.0, 0.0]) @ Exp([0.0, pitch, 0.0]) @ Exp([0.0, 0.0, yaw]), 1e-9):
            raise Mismatch("the factors are multiplied as q_x ⊗ q_y ⊗ q_z",
                           "the course's order is q = q_z(yaw) ⊗ q_y(pitch) ⊗ q_x(roll), like the matrices")
        raise Mismatch(f"euler_zyx_to_quat({yaw}, {pitch}, {roll}) is a different rotation")


# ---------------------------------------------------------------- quat_to_euler_zyx
def _quat_hint(angles, q):
    hint = _angles_hint(angles, _quat_to_matrix(q))
    if hint:
        return hint
    if _rebuild_error(angles, Rotation.from_quat(q).as_matrix()) < 1e-6:
        return "q was read as scalar-last [x, y, z, w]: the course's quaternions are [w, x, y, z]"
    return None


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


@public_check("quat_to_euler_zyx", "at gimbal lock (pitch = ±π/2): no NaN, roll = 0, the same rotation")
def _(quat_to_euler_zyx):
    for sign in (1.0, -1.0):
        q = Rotation.from_euler("ZYX", [-1.9, sign * HALF_PI, 0.6]).as_quat(scalar_first=True)
        R = _quat_to_matrix(q)
        got = _require_angles(quat_to_euler_zyx(q))
        if abs(got[2]) > 1e-12:
            raise Mismatch(f"at pitch = {'+' if sign > 0 else '-'}π/2 the roll is {got[2]:.4f}",
                           "at the lock only yaw ∓ roll is defined: set roll = 0 and give the whole turn to yaw")
        if _rebuild_error(got, R) > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(got)} do not rebuild the rotation", _quat_hint(got, q))


@public_check("quat_to_euler_zyx", "stays exact just next to the lock (pitch = ±(π/2 - 1e-9))")
def _(quat_to_euler_zyx):
    for sign in (1.0, -1.0):
        q = Rotation.from_euler("ZYX", [0.5, sign * (HALF_PI - 1e-9), 2.6]).as_quat(scalar_first=True)
        got = _require_angles(quat_to_euler_zyx(q))
        error = _rebuild_error(got, _quat_to_matrix(q))
        if error > REBUILD_TOL:
            raise Mismatch(f"the angles {fmt(got)} rebuild the rotation only to {error:.2g}",
                           "asin(2(wy - xz)) loses digits near ±1: use the half-angle sums w ± y, x + z, z - x")


# ---------------------------------------------------------------- euler_rates_matrix
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
    R = _zyx(*angles)
    dR = (_zyx(*(angles + h * rates)) - _zyx(*(angles - h * rates))) / (2 * h)
    body = unskew(R.T @ dR)
    E_got = require_shape(euler_rates_matrix(angles[1], angles[2]), (3, 3))
    if close(E_got @ rates, body, 1e-7):
        return
    world = unskew(dR @ R.T)
    if close(E_got @ rates, world, 1e-7):
        raise Mismatch("E @ rates gives the angular velocity in the world frame",
                       "the course's E gives body rates: [ω_b]× = Rᵀ dR/dt")
    raise Mismatch(f"E @ rates = {fmt(E_got @ rates)}, but the body rates are {fmt(body)}",
                   "ω_b = roll_rate e_x + pitch_rate Rx(roll)ᵀ e_y + yaw_rate Rx(roll)ᵀ Ry(pitch)ᵀ e_z")


@public_check("euler_rates_matrix", "|det E| = cos(pitch): it vanishes at pitch = ±π/2")
def _(euler_rates_matrix):
    for pitch in (0.3, -1.0, HALF_PI, -HALF_PI):
        E_got = require_shape(euler_rates_matrix(pitch, 0.6), (3, 3))
        det = abs(np.linalg.det(E_got))
        if abs(det - np.cos(pitch)) > 1e-9:
            raise Mismatch(f"|det E| = {det:.4f} at pitch = {pitch:.4f}, expected cos(pitch) = {np.cos(pitch):.4f}")
