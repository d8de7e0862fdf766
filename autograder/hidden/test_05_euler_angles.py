"""Hidden checks for lesson 05: Euler angles and their singularities.

Independent oracles: scipy's ``Rotation`` with the intrinsic ``"ZYX"``
sequence (yaw, pitch, roll), products of elementary rotations written out
here, and finite differences of R(t) for the rate matrix. Angles are compared
through their matrices wherever they are not unique (at and next to gimbal
lock) and modulo 2π elsewhere. Every test calls the student's function of its
own exercise only.

Tolerances: 1e-12 for matrices and quaternions built from angles, 1e-9 for
angles away from the lock, 1e-11 for matrices rebuilt from angles extracted
at or next to the lock ("the same matrix to ~1e-12"), 1e-7 against central
differences with step 1e-6. Yaw and roll lie in (-π, π] exactly: -π is never returned (checked with
half turns whose sines are -0.0, where np.arctan2 gives -π); quat_to_euler_zyx normalises first (q
scaled by 1e-8 … 1e8 gives the angles of q, also next to the lock).
"""

import warnings

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.checks.lesson05 import HALF_OPEN_HINT
from coursekit.diagnose import as_float_array

from .helpers import Wrong, exercise, expect, expect_array, expect_close, fmt, random_rotations, rotation_problem

HALF_PI = np.pi / 2
TOL = 1e-12
ANGLE_TOL = 1e-9
REBUILD_TOL = 1e-11
# Distances from the lock: pitch = ±(π/2 - ε). Rounding makes ε = 0 a lock with cos(pitch) ≈ 6e-17.
NEAR_LOCK = [1e-15, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5]


# ---------------------------------------------------------------- oracles
def scipy_matrix(yaw, pitch, roll):
    """Rz(yaw) Ry(pitch) Rx(roll), computed by scipy through a quaternion (rounding in every entry)."""
    return Rotation.from_euler("ZYX", [yaw, pitch, roll]).as_matrix()


def _rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def _ry(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def product_matrix(yaw, pitch, roll):
    """The same matrix as a product of elementary rotations (different rounding)."""
    return _rz(yaw) @ _ry(pitch) @ _rx(roll)


def scipy_quat(yaw, pitch, roll):
    return Rotation.from_euler("ZYX", [yaw, pitch, roll]).as_quat(scalar_first=True)


def scipy_angles(R):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Rotation.from_matrix(R).as_euler("ZYX")


def random_euler(count, seed):
    """(yaw, pitch, roll) rows with yaw, roll in (-π, π) and pitch in (-π/2, π/2)."""
    rng = np.random.default_rng(seed)
    return np.column_stack(
        [rng.uniform(-np.pi, np.pi, count), rng.uniform(-1.5, 1.5, count), rng.uniform(-np.pi, np.pi, count)]
    )


def wrapped(difference):
    """An angle difference brought into [-π, π): 0 means the same angle."""
    return (np.asarray(difference, dtype=float) + np.pi) % (2 * np.pi) - np.pi


def near_lock_cases(seed, count_per_eps=1):
    """(yaw, pitch, roll, ε) with pitch = ±(π/2 - ε) for every ε of NEAR_LOCK, both signs."""
    rng = np.random.default_rng(seed)
    cases = []
    for eps in NEAR_LOCK:
        for sign in (1.0, -1.0):
            for _ in range(count_per_eps):
                yaw, roll = rng.uniform(-np.pi, np.pi, 2)
                cases.append((yaw, sign * (HALF_PI - eps), roll, eps))
    return cases


def lock_matrices(seed):
    """Matrices exactly at pitch = ±π/2: products, scipy's, and one with |R[2, 0]| a hair above 1."""
    rng = np.random.default_rng(seed)
    found = []
    for sign in (1.0, -1.0):
        R = product_matrix(0.4, sign * HALF_PI, -1.1)
        R[2, 0] = np.nextafter(R[2, 0], 2.0 * R[2, 0])  # |R[2, 0]| = 1 + 2.2e-16, as rounding produces
        found.append((f"pitch = {'+' if sign > 0 else '-'}π/2 with |R[2, 0]| = 1 + 2e-16 (rounding)", R))
        for make in (product_matrix, scipy_matrix):
            yaw, roll = rng.uniform(-np.pi, np.pi, 2)
            found.append(
                (
                    f"pitch = {'+' if sign > 0 else '-'}π/2, yaw = {yaw:.3f}, roll = {roll:.3f}",
                    make(yaw, sign * HALF_PI, roll),
                )
            )
    return found


# ---------------------------------------------------------------- hints
NAN_HINT = (
    "np.arcsin of a value a hair beyond ±1 (rounding) is nan: the pitch must come out finite for every rotation "
    "matrix, rounded entries included"
)


PITCH_SIGN_HINT = hints.PITCH_TURNS_WRONG_WAY_HINT
MATRIX_GENERAL_HINT = (
    "R should be Rz(yaw) @ Ry(pitch) @ Rx(roll); compare each elementary rotation with "
    "a quarter turn (yaw = π/2 sends x to y, pitch = π/2 sends z to x, roll = π/2 sends y to z)"
)


def _matrix_hint(got, yaw, pitch, roll):
    """The mistake whose matrix ``got`` is (computed from the same angles), or a general hint."""
    candidates = [
        (
            _rx(roll) @ _ry(pitch) @ _rz(yaw),
            "looks like Rx(roll) @ Ry(pitch) @ Rz(yaw): the x-y-z order (scipy's extrinsic 'zyx'); "
            "the course uses R = Rz(yaw) @ Ry(pitch) @ Rx(roll)",
        ),
        (product_matrix(roll, pitch, yaw), hints.YAW_ROLL_SWAPPED_YAW_HINT),
        (product_matrix(yaw, -pitch, roll), PITCH_SIGN_HINT),
        (product_matrix(yaw, pitch, roll).T, "looks like the transpose (the inverse rotation)"),
        (product_matrix(*np.deg2rad([yaw, pitch, roll])), "looks like degrees: angles are in radians"),
    ]
    truth = product_matrix(yaw, pitch, roll)
    for candidate, hint in candidates:
        if np.max(np.abs(candidate - truth)) > 1e-6 and np.max(np.abs(got - candidate)) <= 1e-9:
            return hint
    return MATRIX_GENERAL_HINT


def _rebuilds(angles, R, tol):
    return float(np.max(np.abs(scipy_matrix(*angles) - R))) <= tol


def _angles_hint(got, R):
    """Name the mistake when angles ``got`` do not rebuild ``R`` (each candidate checked), else ""."""
    if not np.all(np.isfinite(got)):
        return NAN_HINT
    yaw, pitch, roll = got
    # 1e-6: these mistakes are off by O(1); the loose tolerance still recognises them next to the lock,
    # where the extraction itself loses digits.
    if _rebuilds((roll, pitch, yaw), R, 1e-6):
        return "returned (roll, pitch, yaw): the order is (yaw, pitch, roll)"
    if np.max(np.abs(Rotation.from_euler("zyx", got).as_matrix() - R)) <= 1e-6:
        return (
            "these are angles of the extrinsic sequence (scipy's lowercase 'zyx', R = Rx(c) Ry(b) Rz(a)); "
            "the course uses intrinsic z-y-x, scipy's 'ZYX'"
        )
    if _rebuilds(np.deg2rad(got), R, 1e-6):
        return "looks like degrees: return radians"
    return ""


ANGLES_GENERAL_HINT = hints.ANGLES_MUST_SATISFY_R_HINT

NO_LOCK_BRANCH_HINT = hints.NO_SEPARATE_GIMBAL_LOCK_HINT
ASIN_HINT = hints.PITCH_ARCSIN_R_LOSES_HINT


def _naive_angles(R):
    """What the textbook formulas give without a lock branch: atan2 of the entries that vanish at the lock."""
    return np.array(
        [np.arctan2(R[1, 0], R[0, 0]), np.arctan2(-R[2, 0], np.hypot(R[0, 0], R[1, 0])), np.arctan2(R[2, 1], R[2, 2])]
    )


def _asin_pitch(R):
    with np.errstate(invalid="ignore"):
        return float(np.arcsin(-R[2, 0]))


def _extraction_hint(got, R, eps=None):
    """At or next to the lock: which extraction gave ``got`` (each candidate computed from R)."""
    hint = _angles_hint(got, R)
    if hint:
        return hint
    good_pitch = float(np.arctan2(-R[2, 0], np.hypot(R[0, 0], R[1, 0])))
    asin = _asin_pitch(R)
    if (
        np.isfinite(asin)
        and abs(asin - good_pitch) > 1e-13
        and abs(got[1] - asin) <= 1e-15 + 1e-3 * abs(asin - good_pitch)
    ):
        return ASIN_HINT
    naive = _naive_angles(R)
    if np.max(np.abs(wrapped(got - naive))) <= 1e-12:
        if eps is None:
            return NO_LOCK_BRANCH_HINT
        return (
            "next to the lock R[0, 0], R[1, 0], R[2, 1], R[2, 2] shrink like cos(pitch) and lose their digits: "
            "atan2 of them gives yaw and roll only to ~1e-16/cos(pitch), and the angles rebuild the large entries "
            "of R badly; the angles must rebuild every entry of R, the large ones included"
        )
    if eps is not None and abs(got[2]) == 0.0:
        return (
            f"treated a matrix {eps:g} rad from the lock as locked: only call it gimbal lock when "
            "cos(pitch) is below about 1e-12"
        )
    return (
        "at and next to the lock the angles must rebuild R: check the pitch's digits there, a lock branch at the "
        "docstring's threshold (roll = 0), and whether your angles rebuild the large entries of R as well as the "
        "small ones"
    )


def _expect_angles(value, what):
    """The three returned angles as a float array; NaN gets its own message and hint."""
    array = as_float_array(value)
    if array is not None and array.shape == (3,) and not np.all(np.isfinite(array)):
        raise Wrong(f"{what} returned NaN or inf: {fmt(array)}", NAN_HINT)
    return expect_array(value, (3,), what)


def _expect_in_range(got, what):
    yaw, pitch, roll = got
    slack = 1e-12
    expect(
        -np.pi - slack <= yaw <= np.pi + slack and -np.pi - slack <= roll <= np.pi + slack,
        f"{what}: yaw = {yaw:.4f}, roll = {roll:.4f} outside (-π, π]",
        "np.arctan2 already returns angles in [-π, π]: do not add offsets",
    )
    expect(
        -HALF_PI - slack <= pitch <= HALF_PI + slack,
        f"{what}: pitch = {pitch:.4f} outside [-π/2, π/2]",
        "choose the solution with cos(pitch) >= 0",
    )


# ---------------------------------------------------------------- euler_zyx_to_matrix
@exercise("euler_zyx_to_matrix", weight=3)
def test_euler_zyx_to_matrix_matches_scipy(student):
    """agrees with scipy's intrinsic 'ZYX' for 30 random (yaw, pitch, roll) and any angle values"""
    cases = list(random_euler(30, seed=501)) + [(5.0, 2.5, -7.0), (-4.0, -3.0, 9.0)]
    for yaw, pitch, roll in cases:
        what = f"euler_zyx_to_matrix({yaw:.3f}, {pitch:.3f}, {roll:.3f})"
        got = expect_array(student.euler_zyx_to_matrix(yaw, pitch, roll), (3, 3), what)
        expect_close(got, scipy_matrix(yaw, pitch, roll), TOL, what, lambda: _matrix_hint(got, yaw, pitch, roll))


@exercise("euler_zyx_to_matrix", weight=1)
def test_euler_zyx_to_matrix_single_axes(student):
    """one angle at a time: yaw turns about z, pitch about y, roll about x"""
    for k, axis in enumerate("zyx"):
        for angle in (0.7, -2.0):
            args = [0.0, 0.0, 0.0]
            args[k] = angle
            what = f"euler_zyx_to_matrix{tuple(args)}"
            got = expect_array(student.euler_zyx_to_matrix(*args), (3, 3), what)
            expected = Rotation.from_euler(axis, angle).as_matrix()
            expect_close(got, expected, TOL, what, lambda: _matrix_hint(got, *args))


@exercise("euler_zyx_to_matrix", weight=1)
def test_euler_zyx_to_matrix_at_lock(student):
    """is a rotation and exact at pitch = ±π/2, and accepts integers"""
    for yaw, pitch, roll in [(0.3, HALF_PI, -1.2), (-2.5, -HALF_PI, 0.8), (0, 0, 0), (1, -1, 2)]:
        what = f"euler_zyx_to_matrix({yaw:.3f}, {pitch:.3f}, {roll:.3f})"
        got = expect_array(student.euler_zyx_to_matrix(yaw, pitch, roll), (3, 3), what)
        problem = rotation_problem(got, 1e-9)
        expect(problem is None, f"{what}: {problem}")
        expect_close(got, scipy_matrix(yaw, pitch, roll), TOL, what, lambda: _matrix_hint(got, yaw, pitch, roll))


# ---------------------------------------------------------------- matrix_to_euler_zyx
@exercise("matrix_to_euler_zyx", weight=3)
def test_matrix_to_euler_zyx_random(student):
    """30 random rotations: (yaw, pitch, roll) agree with scipy's 'ZYX' and rebuild R"""
    for index, R in enumerate(random_rotations(30, seed=511)):
        what = f"matrix_to_euler_zyx(R) for random rotation #{index}"
        got = _expect_angles(student.matrix_to_euler_zyx(R), what)
        rebuilt = scipy_matrix(*got)
        error = float(np.max(np.abs(rebuilt - R)))
        expect(
            error <= REBUILD_TOL,
            f"{what} = {fmt(got)} rebuilds R only to {error:.2g}",
            lambda: _angles_hint(got, R) or ANGLES_GENERAL_HINT,
        )
        _expect_in_range(got, what)
        difference = np.max(np.abs(wrapped(got - scipy_angles(R))))
        expect(
            difference <= ANGLE_TOL,
            f"{what} = {fmt(got)} differs from scipy's {fmt(scipy_angles(R))}",
            "keep pitch in [-π/2, π/2] (cos(pitch) >= 0)",
        )


@exercise("matrix_to_euler_zyx", weight=1)
def test_matrix_to_euler_zyx_other_solution(student):
    """returns the in-range angles for matrices built from out-of-range ones, and accepts lists"""
    for yaw, pitch, roll in [(0.5 + np.pi, np.pi - 0.3, -0.8 + np.pi), (-3.0, 2.0, 3.0), (7.0, -0.2, -6.5)]:
        R = scipy_matrix(yaw, pitch, roll)
        what = f"matrix_to_euler_zyx(R) for R built from ({yaw:.3f}, {pitch:.3f}, {roll:.3f})"
        got = _expect_angles(student.matrix_to_euler_zyx(R.tolist()), what)
        expect_close(
            scipy_matrix(*got),
            R,
            REBUILD_TOL,
            f"the matrix rebuilt from {what}",
            lambda: _angles_hint(got, R) or ANGLES_GENERAL_HINT,
        )
        _expect_in_range(got, what)


@exercise("matrix_to_euler_zyx", weight=1)
def test_matrix_to_euler_zyx_half_open_range(student):
    """yaw and roll lie in (-π, π]: half turns about z and x whose sines are -0.0 give π, never -π (at the
    gimbal lock too)"""
    half_z = np.array([[-1.0, 0.0, 0.0], [-0.0, -1.0, 0.0], [0.0, 0.0, 1.0]])  # arctan2(-0.0, -1) = -π
    half_x = np.array([[1.0, 0.0, -0.0], [0.0, -1.0, 0.0], [0.0, -0.0, -1.0]])  # roll from (-0.0, -1)
    lock = np.array([[0.0, 0.0, -1.0], [0.0, -1.0, 0.0], [-1.0, 0.0, 0.0]])  # yaw π at pitch = π/2
    for name, R, index in (
        ("a half turn about z", half_z, 0),
        ("a half turn about x", half_x, 2),
        ("yaw π at the lock", lock, 0),
    ):
        got = _expect_angles(student.matrix_to_euler_zyx(R), f"matrix_to_euler_zyx({name})")
        expect(
            got[index] == np.pi,
            f"matrix_to_euler_zyx({name}) gave {'yaw' if index == 0 else 'roll'} = "
            f"{got[index]:.17g}, expected π (the range is (-π, π])",
            HALF_OPEN_HINT,
        )


@exercise("matrix_to_euler_zyx", weight=2)
def test_matrix_to_euler_zyx_at_lock(student):
    """at pitch = ±π/2 (gimbal lock): no NaN, roll = 0, pitch = ±π/2, and the same matrix"""
    for label, R in lock_matrices(seed=512):
        what = f"matrix_to_euler_zyx(R) at {label}"
        got = _expect_angles(student.matrix_to_euler_zyx(R), what)
        yaw, pitch, roll = got
        expected_pitch = -np.sign(R[2, 0]) * HALF_PI
        expect(
            abs(abs(pitch) - HALF_PI) <= 1e-12 and np.sign(pitch) == -np.sign(R[2, 0]),
            f"{what}: pitch = {pitch:.17g} is off by {abs(pitch - expected_pitch):.2g} from "
            f"{'-' if R[2, 0] > 0 else ''}π/2",
            lambda: _extraction_hint(got, R),
        )
        rebuilt_error = float(np.max(np.abs(scipy_matrix(*got) - R)))
        if np.max(np.abs(wrapped(got - _naive_angles(R)))) <= 1e-12:
            roll_hint = NO_LOCK_BRANCH_HINT
        elif rebuilt_error <= REBUILD_TOL:
            roll_hint = hints.LOCK_ONLY_YAW_ROLL_HINT
        else:
            roll_hint = _extraction_hint(got, R)
        expect(
            abs(roll) <= 1e-12,
            f"{what}: roll = {roll:.4f}, expected 0 (the course's convention at the lock)",
            roll_hint,
        )
        expect_close(
            scipy_matrix(*got),
            R,
            REBUILD_TOL,
            f"the matrix rebuilt from {what} = {fmt(got)}",
            lambda: _extraction_hint(got, R),
        )


@exercise("matrix_to_euler_zyx", weight=2)
def test_matrix_to_euler_zyx_near_lock(student):
    """stays exact next to the lock: pitch within 1e-15 … 1e-5 of ±π/2 rebuilds R to 1e-11"""
    cases = [(make, *case) for case in near_lock_cases(seed=513) for make in (scipy_matrix, product_matrix)]
    for make, yaw, pitch, roll, eps in cases:
        R = make(yaw, pitch, roll)
        what = f"matrix_to_euler_zyx(R) for pitch = {'+' if pitch > 0 else '-'}(π/2 - {eps:g})"
        got = _expect_angles(student.matrix_to_euler_zyx(R), what)
        error = float(np.max(np.abs(scipy_matrix(*got) - R)))
        expect(
            error <= REBUILD_TOL,
            f"{what}: the angles {fmt(got)} rebuild R only to {error:.2g}",
            lambda: _extraction_hint(got, R, eps),
        )


# ---------------------------------------------------------------- euler_zyx_to_quat
def _all_plus_quat(yaw, pitch, roll):
    """The z-y-x formula with every mixed product added (the minus signs lost)."""
    cy, sy, cp, sp, cr, sr = (f(a / 2) for a in (yaw, pitch, roll) for f in (np.cos, np.sin))
    return np.array(
        [
            cy * cp * cr + sy * sp * sr,
            cy * cp * sr + sy * sp * cr,
            cy * sp * cr + sy * cp * sr,
            sy * cp * cr + cy * sp * sr,
        ]
    )


def _quat_hint(got, yaw, pitch, roll):
    """The mistake whose quaternion ``got`` is (each candidate computed from the angles), or a general hint."""
    expected = scipy_quat(yaw, pitch, roll)
    candidates = [
        (np.roll(expected, -1), "looks scalar-last [x, y, z, w]: the course puts the scalar first, [w, x, y, z]"),
        (
            Rotation.from_euler("zyx", [yaw, pitch, roll]).as_quat(scalar_first=True),
            "looks like q_x ⊗ q_y ⊗ q_z (scipy's extrinsic 'zyx'): the course uses q = q_z(yaw) ⊗ q_y(pitch) ⊗ q_x(roll)",
        ),
        (scipy_quat(2 * yaw, 2 * pitch, 2 * roll), "full angles: a quaternion uses half angles, cos(yaw / 2)"),
        (scipy_quat(roll, pitch, yaw), "yaw and roll are swapped"),
        (_all_plus_quat(yaw, pitch, roll), hints.MIXED_PRODUCTS_LOST_THEIR_HINT),
    ]
    for candidate, hint in candidates:
        if min(np.max(np.abs(candidate - expected)), np.max(np.abs(candidate + expected))) <= 1e-6:
            continue  # here the candidate is the right answer: no diagnosis
        if np.max(np.abs(got - candidate)) <= 1e-9 or np.max(np.abs(got + candidate)) <= 1e-9:
            return hint
    norm = np.linalg.norm(got)
    if abs(norm - 1.0) > 1e-6:
        return (
            f"|q| = {norm:.4f}: a rotation quaternion has unit length; q = q_z(yaw) ⊗ q_y(pitch) ⊗ q_x(roll) "
            "is a product of unit quaternions"
        )
    return "q = q_z(yaw) ⊗ q_y(pitch) ⊗ q_x(roll) with q_z(a) = [cos(a/2), 0, 0, sin(a/2)] and so on"


def _expect_same_quat(got, expected, what, hint):
    error = min(np.max(np.abs(got - expected)), np.max(np.abs(got + expected)))
    if not error <= TOL:
        raise Wrong(f"{what} is {fmt(got)}, expected ±{fmt(expected)} (off by {error:.2g})", hint)


@exercise("euler_zyx_to_quat", weight=3)
def test_euler_zyx_to_quat_matches_scipy(student):
    """equals ± scipy's 'ZYX' quaternion, scalar first, for 30 random angle triples"""
    for yaw, pitch, roll in list(random_euler(30, seed=521)) + [(3.0, -1.4, -3.1)]:
        what = f"euler_zyx_to_quat({yaw:.3f}, {pitch:.3f}, {roll:.3f})"
        got = expect_array(student.euler_zyx_to_quat(yaw, pitch, roll), (4,), what)
        _expect_same_quat(got, scipy_quat(yaw, pitch, roll), what, _quat_hint(got, yaw, pitch, roll))


@exercise("euler_zyx_to_quat", weight=1)
def test_euler_zyx_to_quat_single_axes(student):
    """one angle at a time gives [cos(a/2), sin(a/2) × axis], also at pitch = ±π/2"""
    for k, axis in enumerate("zyx"):
        for angle in (0.9, -HALF_PI, HALF_PI):
            args = [0.0, 0.0, 0.0]
            args[k] = angle
            what = f"euler_zyx_to_quat{tuple(round(a, 4) for a in args)}"
            got = expect_array(student.euler_zyx_to_quat(*args), (4,), what)
            expected = Rotation.from_euler(axis, angle).as_quat(scalar_first=True)
            _expect_same_quat(got, expected, what, _quat_hint(got, *args))


@exercise("euler_zyx_to_quat", weight=1)
def test_euler_zyx_to_quat_unit_and_lock(student):
    """returns unit quaternions, exact at gimbal lock and for integer angles"""
    for yaw, pitch, roll in [(0.6, HALF_PI, -0.2), (-1.7, -HALF_PI, 2.9), (1, 0, -1), (0, 0, 0)]:
        what = f"euler_zyx_to_quat({yaw:.3f}, {pitch:.3f}, {roll:.3f})"
        got = expect_array(student.euler_zyx_to_quat(yaw, pitch, roll), (4,), what)
        expect(
            abs(np.linalg.norm(got) - 1.0) <= TOL,
            f"{what} has |q| = {np.linalg.norm(got):.6f} (off by {abs(np.linalg.norm(got) - 1.0):.2g})",
            lambda: _quat_hint(got, yaw, pitch, roll),
        )
        _expect_same_quat(got, scipy_quat(yaw, pitch, roll), what, _quat_hint(got, yaw, pitch, roll))


# ---------------------------------------------------------------- quat_to_euler_zyx
QUAT_ASIN_HINT = (
    "the lecture's formulas lose digits next to the lock: asin(2(wy - xz)) near ±1, and the atan2 "
    "arguments for yaw and roll shrink like cos(pitch); use the half-angle sums (w ± y, x + z, z - x) "
    "and atan2"
)
QUAT_NO_LOCK_HINT = hints.NO_GIMBAL_LOCK_BRANCH_HINT


def _lecture_angles(q, normalise=True):
    """(yaw, pitch, roll) of the lecture's formulas with a clipped asin, from q (normalised first or not)."""
    q = np.asarray(q, dtype=float)
    w, x, y, z = q / np.linalg.norm(q) if normalise else q
    return np.array(
        [
            np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)),
            np.arcsin(np.clip(2 * (w * y - z * x), -1.0, 1.0)),
            np.arctan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y)),
        ]
    )


def _quat_angles_hint(got, q, at_lock=False):
    """The mistake behind angles ``got`` of ``q`` (each candidate computed from q), or a general hint."""
    R = Rotation.from_quat(q, scalar_first=True).as_matrix()
    hint = _angles_hint(got, R)
    if hint:
        return hint
    if np.max(np.abs(scipy_matrix(*got) - Rotation.from_quat(q).as_matrix())) <= 1e-6:
        return "read q as scalar-last [x, y, z, w]: the course's quaternions are [w, x, y, z]"
    for lecture in (_lecture_angles(q), _lecture_angles(q, normalise=False)):
        # The lecture's atan2/asin formulas, recomputed here: near and at the lock they are what goes wrong.
        if np.max(np.abs(wrapped(got[::-1] - lecture))) <= 1e-9:
            return "returned (roll, pitch, yaw): the order is (yaw, pitch, roll)"
        if np.max(np.abs(wrapped(got - lecture))) <= 1e-9:
            return QUAT_NO_LOCK_HINT if at_lock else QUAT_ASIN_HINT
    if not at_lock and got[2] == 0.0:
        return hints.TREATED_ROTATION_NEXT_LOCK_HINT
    return (
        "the angles must rebuild the rotation of q: pitch from the half-angle sums, "
        "2 atan2(hypot(w + y, z - x), hypot(w - y, x + z)) - π/2, then yaw ± roll from 2 atan2 of the same sums"
    )


@exercise("quat_to_euler_zyx", weight=3)
def test_quat_to_euler_zyx_random(student):
    """30 random unit quaternions (either sign): angles agree with scipy's 'ZYX' and rebuild q"""
    rng = np.random.default_rng(531)
    for index, R in enumerate(random_rotations(30, seed=532)):
        q = Rotation.from_matrix(R).as_quat(scalar_first=True) * rng.choice([-1.0, 1.0])
        what = f"quat_to_euler_zyx(q) for random q #{index} = {fmt(q)}"
        got = _expect_angles(student.quat_to_euler_zyx(q), what)
        error = float(np.max(np.abs(scipy_matrix(*got) - R)))
        expect(
            error <= REBUILD_TOL,
            f"{what}: the angles {fmt(got)} rebuild the rotation only to {error:.2g}",
            lambda: _quat_angles_hint(got, q),
        )
        _expect_in_range(got, what)
        difference = np.max(np.abs(wrapped(got - scipy_angles(R))))
        expect(difference <= ANGLE_TOL, f"{what} = {fmt(got)} differs from scipy's {fmt(scipy_angles(R))}")


@exercise("quat_to_euler_zyx", weight=1)
def test_quat_to_euler_zyx_sign(student):
    """q and -q give the same angles"""
    for yaw, pitch, roll in random_euler(8, seed=533):
        q = scipy_quat(yaw, pitch, roll)
        plus = _expect_angles(student.quat_to_euler_zyx(q), "quat_to_euler_zyx(q)")
        minus = _expect_angles(student.quat_to_euler_zyx(-q), "quat_to_euler_zyx(-q)")
        expect(
            np.max(np.abs(wrapped(plus - minus))) <= ANGLE_TOL,
            f"q = {fmt(q)} gives {fmt(plus)} but -q gives {fmt(minus)}",
            "q and -q are the same rotation: bring yaw and roll into (-π, π] at the end",
        )


@exercise("quat_to_euler_zyx", weight=1)
def test_quat_to_euler_zyx_normalises_and_half_open(student):
    """normalises first: q scaled by 1e-8, 2 and 1e8 (also next to the lock) gives the angles of q; and the
    half turn -[0, 0, 0, 1] gives yaw = π, never -π"""
    for yaw, pitch, roll in [(0.3, 0.4, -0.5), (0.3, HALF_PI - 1e-6, 0.5), (-2.0, -HALF_PI + 1e-7, 1.0)]:
        q = scipy_quat(yaw, pitch, roll)
        unit = _expect_angles(student.quat_to_euler_zyx(q), f"quat_to_euler_zyx(q) for {fmt([yaw, pitch, roll])}")
        for scale in (1e-8, 2.0, 1e8):
            got = _expect_angles(student.quat_to_euler_zyx(scale * q), f"quat_to_euler_zyx({scale:g} q)")
            error = float(np.max(np.abs(scipy_matrix(*got) - scipy_matrix(*unit))))
            expect(
                error <= REBUILD_TOL,
                f"quat_to_euler_zyx({scale:g} q) gives {fmt(got)}, but q gives "
                f"{fmt(unit)} (the rotations differ by {error:.2g}) for pitch = {pitch:.9g}",
                hints.NON_UNIT_Q_STANDS_HINT,
            )
    got = _expect_angles(student.quat_to_euler_zyx([0.0, 0.0, 0.0, -1.0]), "quat_to_euler_zyx([0, 0, 0, -1])")
    expect(got[0] == np.pi, f"quat_to_euler_zyx([0, 0, 0, -1]) gave yaw = {got[0]:.17g}, expected π", HALF_OPEN_HINT)


@exercise("quat_to_euler_zyx", weight=2)
def test_quat_to_euler_zyx_at_lock(student):
    """at pitch = ±π/2 (gimbal lock): no NaN, roll = 0, the same rotation, yaw in (-π, π]"""
    rng = np.random.default_rng(534)
    for sign in (1.0, -1.0):
        for _ in range(4):
            yaw, roll = rng.uniform(-np.pi, np.pi, 2)
            q = scipy_quat(yaw, sign * HALF_PI, roll) * rng.choice([-1.0, 1.0])
            R = scipy_matrix(yaw, sign * HALF_PI, roll)
            what = f"quat_to_euler_zyx(q) at pitch = {'+' if sign > 0 else '-'}π/2 (q = {fmt(q, 6)})"
            got = _expect_angles(student.quat_to_euler_zyx(q), what)
            rebuilt_error = float(np.max(np.abs(scipy_matrix(*got) - R)))
            expect(
                abs(got[2]) <= 1e-12,
                f"{what}: roll = {got[2]:.4f}, expected 0 (the course's convention)",
                lambda: (
                    hints.LOCK_ONLY_YAW_ROLL_DEFINED_HINT
                    if rebuilt_error <= REBUILD_TOL
                    else _quat_angles_hint(got, q, at_lock=True)
                ),
            )
            expect_close(
                scipy_matrix(*got),
                R,
                REBUILD_TOL,
                f"the rotation rebuilt from {what} = {fmt(got)}",
                lambda: _quat_angles_hint(got, q, at_lock=True),
            )
            expect(
                -np.pi < got[0] <= np.pi,
                f"{what}: yaw = {got[0]:.4f} is outside (-π, π]",
                "at the lock yaw is twice an atan2, which can leave (-π, π]: wrap it back into the range",
            )


@exercise("quat_to_euler_zyx", weight=1)
def test_quat_to_euler_zyx_near_lock(student):
    """stays exact next to the lock: pitch within 1e-15 … 1e-5 of ±π/2 rebuilds the rotation to 1e-11"""
    for yaw, pitch, roll, eps in near_lock_cases(seed=535):
        q = scipy_quat(yaw, pitch, roll)
        R = scipy_matrix(yaw, pitch, roll)
        what = f"quat_to_euler_zyx(q) for pitch = {'+' if pitch > 0 else '-'}(π/2 - {eps:g})"
        got = _expect_angles(student.quat_to_euler_zyx(q), what)
        error = float(np.max(np.abs(scipy_matrix(*got) - R)))
        expect(
            error <= REBUILD_TOL,
            f"{what}: the angles {fmt(got)} rebuild the rotation only to {error:.2g}",
            lambda: _quat_angles_hint(got, q),
        )


# ---------------------------------------------------------------- euler_rates_matrix
def _body_rates(angles, rates, h=1e-6):
    """ω_b with [ω_b]× = R(t)ᵀ dR/dt at t = 0, for angles(t) = angles + t rates (central differences)."""
    R0 = scipy_matrix(*angles)
    derivative = (scipy_matrix(*(angles + h * rates)) - scipy_matrix(*(angles - h * rates))) / (2 * h)
    S = R0.T @ derivative
    return 0.5 * np.array([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]])


def _rates_hint(E, pitch, roll):
    cp, sp, cr, sr = np.cos(pitch), np.sin(pitch), np.cos(roll), np.sin(roll)
    right = np.array([[-sp, 0.0, 1.0], [cp * sr, cr, 0.0], [cp * cr, -sr, 0.0]])
    candidates = [
        (right[:, ::-1], hints.COLUMNS_ORDER_ROLL_PITCH_HINT),
        (np.array([[-sp, 0.0, 1.0], [-cp * sr, cr, 0.0], [cp * cr, sr, 0.0]]), hints.ROLL_SIGNS_FLIPPED_EXPRESS_HINT),
        (right.T, "looks like the transpose of E"),
        (
            np.eye(3),
            "E = I treats the Euler-angle rates as body rates; they are not: yaw spins about the world z, "
            "pitch about the once-turned y, roll about the body x, each seen in the body frame",
        ),
    ]
    matching = [
        hint
        for candidate, hint in candidates
        if np.max(np.abs(candidate - right)) > 1e-6 and np.max(np.abs(E - candidate)) <= 1e-6
    ]
    if len(matching) == 1:
        return matching[0]
    # None, or several mistakes that coincide at these angles (at zero angles reversed columns are I).
    return (
        f"E({pitch:.3g}, {roll:.3g}) should be {fmt(right, 3)}: each column is what one rate alone does, the "
        "body rate of a pure yaw, pitch or roll rate; compare one at a time with finite differences"
    )


@exercise("euler_rates_matrix", weight=3)
def test_euler_rates_matrix_finite_differences(student):
    """E @ [yaw_rate, pitch_rate, roll_rate] equals the body rates of R(t)ᵀ dR/dt (finite differences)"""
    rng = np.random.default_rng(541)
    cases = list(random_euler(12, seed=542)) + [(0.4, HALF_PI, -0.7), (-1.0, -HALF_PI, 2.0), (0.0, 0.0, 0.0)]
    for yaw, pitch, roll in cases:
        rates = rng.normal(size=3)
        what = f"euler_rates_matrix({pitch:.3f}, {roll:.3f})"
        E = expect_array(student.euler_rates_matrix(pitch, roll), (3, 3), what)
        expected = _body_rates(np.array([yaw, pitch, roll]), rates)
        expect_close(
            E @ rates, expected, 1e-7, f"{what} @ {fmt(rates, 3)} (body rates)", lambda: _rates_hint(E, pitch, roll)
        )


@exercise("euler_rates_matrix", weight=1)
def test_euler_rates_matrix_determinant(student):
    """det E = -cos(pitch): it vanishes at pitch = ±π/2, where yaw and roll rates cancel"""
    for pitch, roll in [(0.0, 0.0), (0.5, -1.0), (-1.2, 2.5), (HALF_PI, 0.3), (-HALF_PI, -2.0)]:
        what = f"euler_rates_matrix({pitch:.3f}, {roll:.3f})"
        E = expect_array(student.euler_rates_matrix(pitch, roll), (3, 3), what)
        det = np.linalg.det(E)
        expect(
            abs(det + np.cos(pitch)) <= 1e-9,
            f"det {what} = {det:.4f}, expected -cos(pitch) = {-np.cos(pitch):.4f} (off by {abs(det + np.cos(pitch)):.2g})",
            lambda: _rates_hint(E, pitch, roll),
        )
    for pitch, null in [(HALF_PI, [1.0, 0.0, 1.0]), (-HALF_PI, [1.0, 0.0, -1.0])]:
        E = expect_array(student.euler_rates_matrix(pitch, 0.8), (3, 3), "euler_rates_matrix")
        expect_close(
            E @ null,
            np.zeros(3),
            1e-12,
            f"euler_rates_matrix({pitch:.4f}, 0.8) @ {null}",
            lambda: _rates_hint(E, pitch, 0.8),
        )
