"""Hidden checks for lesson 04: quaternions (Hamilton product, scalar first [w, x, y, z]).

Independent oracle: scipy's ``Rotation`` in both layouts (``scalar_first=True``
and its default scalar-last ``[x, y, z, w]``) and ``Slerp``; exact values come
from the reference solutions (``ref``) or from the definitions written here.
Quaternions of rotations are compared up to sign (q and -q are one rotation)
wherever the exercise's meaning allows it; the conjugate, the inverse, the
conversions, the product of non-unit quaternions and the canonical sign of
``matrix_to_quat`` are compared exactly. Random quaternions come from both
hemispheres (w > 0 and w < 0). Every test calls the student's function of its
own exercise only. Tolerance 1e-9 unless stated; matrix_to_quat, 1e-12 in every component
(its docstring's promise, at every angle).

Core ideas (at least half of each exercise's points): Hamilton's sign of the
cross product; the half angle; the canonical sign w >= 0 with Shepperd's
branches (test rotations take every branch, so a missing flip shows); slerp's
constant angular speed along the shorter arc (nlerp agrees only at t = 0.5).
An argument changed in place (an in-place quat_conjugate) costs the exercise a quarter of its points:
the sandbox watches every call (``coursekit.watching``), and the public checks say the same.
Over the whole domain (properties drawn by Hypothesis, derandomized, see ``properties.py``): quat_slerp
is within 2e-15 of q0 turned t of the way along the shorter arc, for turns from 1e-12 to π rad between
q0 and q1 (every decade), either sign of q1 and t in [0, 1] with both endpoints; lists are accepted.
"""

import numpy as np
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation, Slerp

from coursekit import hints
from coursekit.diagnose import close, quaternion_hint, same_rotation_quat

from .properties import angles, expect_within, for_all, quaternions, unit_vectors
from .helpers import (
    LISTS_HINT,
    Wrong,
    exercise,
    expect,
    expect_array,
    expect_close,
    expect_same_with_lists,
    fmt,
    rotation_hint,
    rotation_problem,
    shape_problem,
)

TOL = 1e-9
SLERP_TOL = 2e-15  # quat_slerp for turns Ω from 1e-12 to π between q0 and q1: each component within 2e-15
ONE = np.array([1.0, 0.0, 0.0, 0.0])
UNITS = {
    "1": ONE,
    "i": np.array([0.0, 1.0, 0.0, 0.0]),
    "j": np.array([0.0, 0.0, 1.0, 0.0]),
    "k": np.array([0.0, 0.0, 0.0, 1.0]),
}
# Hamilton's table: (a, b) -> (sign, unit) of a ⊗ b
TABLE = {
    ("i", "j"): (1, "k"),
    ("j", "k"): (1, "i"),
    ("k", "i"): (1, "j"),
    ("j", "i"): (-1, "k"),
    ("k", "j"): (-1, "i"),
    ("i", "k"): (-1, "j"),
    ("i", "i"): (-1, "1"),
    ("j", "j"): (-1, "1"),
    ("k", "k"): (-1, "1"),
}


def unit_quats(count, seed):
    """``count`` random unit quaternions [w, x, y, z]; every other one has w < 0."""
    q = Rotation.random(count, random_state=seed).as_quat(scalar_first=True, canonical=True)
    q[1::2] *= -1.0
    return q


def general_quats(count, seed):
    """``count`` random quaternions of lengths between 0.1 and 10, both hemispheres."""
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(count, 4))
    return q / np.linalg.norm(q, axis=1)[:, None] * 10.0 ** rng.uniform(-1.0, 1.0, count)[:, None]


def scipy_rotation(q):
    return Rotation.from_quat(np.asarray(q, dtype=float), scalar_first=True)


def conj(q):
    return np.asarray(q, dtype=float) * [1.0, -1.0, -1.0, -1.0]


def expect_same_rotation(got, expected, tol, what, hint=""):
    """``got`` must equal ``expected`` or ``-expected`` (one rotation) within ``tol``."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if not same_rotation_quat(got, expected, tol):
        error = min(np.max(np.abs(got - expected)), np.max(np.abs(got + expected)))
        raise Wrong(
            f"{what} is off by {error:.2g} even up to sign (tolerance {tol:g}): "
            f"got {fmt(got)}, expected ±{fmt(expected)}",
            hint or quaternion_hint(got, expected) or "",
        )


def rotation_of_pi(axis):
    """The exact half-turn matrix 2 u uᵀ - I about ``axis`` (normalised)."""
    u = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    return 2.0 * np.outer(u, u) - np.eye(3)


# ---------------------------------------------------------------- quat_multiply
PRODUCT_HINTS = {
    "swapped": "this is q ⊗ p: the sign of the cross product p_v × q_v is flipped (the JPL product, ij = -k), "
    "or the factors are swapped",
    "no_cross": "the cross product is missing: the vector part is p_w q_v + q_w p_v + p_v × q_v",
    "dot_plus": "the scalar part is p_w q_w - p_v · q_v (minus the dot product)",
    "elementwise": hints.MULTIPLIED_ENTRY_ENTRY_EVERY_HINT,
    "normalised": hints.PRODUCT_DIVIDED_NORM_P_HINT,
}
PRODUCT_GENERIC = "compare each of the 16 terms with p ⊗ q = [p_w q_w - p_v · q_v, p_w q_v + q_w p_v + p_v × q_v]"


def product_hint(got, p, q, ref, tol, up_to_sign=False):
    """The hint for the one typical wrong product that ``got`` equals, else an honest general one."""
    p, q = np.asarray(p, dtype=float), np.asarray(q, dtype=float)
    exact = np.asarray(ref.quat_multiply(p, q), dtype=float)
    candidates = {
        "swapped": np.asarray(ref.quat_multiply(q, p), dtype=float),
        "no_cross": exact - np.concatenate([[0.0], np.cross(p[1:], q[1:])]),
        "dot_plus": exact + np.concatenate([[2.0 * (p[1:] @ q[1:])], np.zeros(3)]),
        "elementwise": p * q,
        "normalised": exact / np.linalg.norm(exact),
    }
    same = same_rotation_quat if up_to_sign else close
    matches = [key for key, value in candidates.items() if not close(value, exact, tol) and same(got, value, tol)]
    return PRODUCT_HINTS[matches[0]] if len(matches) == 1 else PRODUCT_GENERIC


@exercise("quat_multiply", weight=3)
def test_quat_multiply_matches_scipy(student, ref):
    """composes like scipy's rotations for 20 random unit pairs (both hemispheres)"""
    for p, q in zip(unit_quats(20, seed=401), unit_quats(20, seed=402)[::-1]):
        got = expect_array(student.quat_multiply(p, q), (4,), "quat_multiply(p, q)")
        expected = (scipy_rotation(p) * scipy_rotation(q)).as_quat(scalar_first=True)
        if not same_rotation_quat(got, expected, TOL):
            expect_same_rotation(
                got,
                expected,
                TOL,
                "quat_multiply(p, q) as a rotation",
                product_hint(got, p, q, ref, 1e-6, up_to_sign=True),
            )


@exercise("quat_multiply", weight=2)
def test_quat_multiply_exact_general(student, ref):
    """exact Hamilton product of 20 random quaternions that are not unit"""
    for p, q in zip(general_quats(20, seed=403), general_quats(20, seed=404)):
        got = expect_array(student.quat_multiply(p, q), (4,), "quat_multiply(p, q)")
        expected = ref.quat_multiply(p, q)
        scale = np.linalg.norm(p) * np.linalg.norm(q)
        if not close(got, expected, TOL * scale):
            expect_close(
                got,
                expected,
                TOL * scale,
                f"quat_multiply(p, q) with |p| |q| = {scale:.3g}",
                product_hint(got, p, q, ref, 1e-9 * scale),
            )


@exercise("quat_multiply", weight=1)
def test_quat_multiply_unit_table(student, ref):
    """reproduces Hamilton's table: i² = j² = k² = -1, ij = k = -ji, jk = i, ki = j"""
    for (a, b), (sign, c) in TABLE.items():
        got = expect_array(student.quat_multiply(UNITS[a], UNITS[b]), (4,), f"quat_multiply({a}, {b})")
        if not close(got, sign * UNITS[c], TOL):
            expect_close(got, sign * UNITS[c], TOL, f"{a} ⊗ {b}", product_hint(got, UNITS[a], UNITS[b], ref, 1e-9))


@exercise("quat_multiply", weight=1)
def test_quat_multiply_identity_and_lists(student, ref):
    """[1, 0, 0, 0] is a two-sided identity; plain lists are accepted"""
    for q in general_quats(5, seed=405):
        for what, p_, q_ in (("1 ⊗ q", ONE, q), ("q ⊗ 1", q, ONE)):
            got = expect_array(student.quat_multiply(p_, q_), (4,), "quat_multiply")
            tol = TOL * np.linalg.norm(q)
            if not close(got, q, tol):
                expect_close(got, q, tol, what, product_hint(got, p_, q_, ref, tol))
    expect_same_with_lists(student.quat_multiply, tuple(general_quats(2, seed=406)), (4,), "quat_multiply(p, q)")


# ---------------------------------------------------------------- quat_left, quat_right
def product_matrix_hint(M, q, name, ref, tol):
    """The hint for the one typical wrong product matrix that ``M`` equals, else ""."""
    q = np.asarray(q, dtype=float)
    own, other = (ref.quat_left, ref.quat_right) if name == "quat_left" else (ref.quat_right, ref.quat_left)
    letter, mine, theirs, sign = ("p", "L", "R", "plus") if name == "quat_left" else ("q", "R", "L", "minus")
    exact = np.asarray(own(q), dtype=float)
    no_minus = exact.copy()
    no_minus[0, 1:] = q[1:]
    candidates = [
        (other(q), f"this is [{letter}]_{theirs}: in [{letter}]_{mine} the [v]× block has a {sign} sign"),
        (
            exact.T,
            f"looks like the transpose of [{letter}]_{mine}: row i holds the coefficients of component i of p ⊗ q",
        ),
        (no_minus, hints.FIRST_ROW_W_X_HINT),
        (own(np.roll(q, 1)), f"{letter} was read as scalar last [x, y, z, w]: this course stores [w, x, y, z]"),
    ]
    matches = [hint for value, hint in candidates if not close(value, exact, tol) and close(M, value, tol)]
    return matches[0] if len(matches) == 1 else ""


def _check_product_matrix(student, ref, name, seed):
    function = getattr(student, name)
    for p, q in zip(general_quats(15, seed=seed), general_quats(15, seed=seed + 1)):
        if name == "quat_left":
            M = expect_array(function(p), (4, 4), "quat_left(p)")
            got, expected, what = M @ q, ref.quat_multiply(p, q), "quat_left(p) @ q vs p ⊗ q"
            factor = p
        else:
            M = expect_array(function(q), (4, 4), "quat_right(q)")
            got, expected, what = M @ p, ref.quat_multiply(p, q), "quat_right(q) @ p vs p ⊗ q"
            factor = q
        scale = np.linalg.norm(p) * np.linalg.norm(q)
        if not close(got, expected, TOL * scale):
            expect_close(
                got,
                expected,
                TOL * scale,
                what,
                product_matrix_hint(M, factor, name, ref, 1e-9 * np.linalg.norm(factor)),
            )


def _check_orthogonal(student, name, seed):
    function = getattr(student, name)
    for q in unit_quats(6, seed=seed):
        M = expect_array(function(q), (4, 4), f"{name}(q)")
        expect_close(
            M.T @ M,
            np.eye(4),
            TOL,
            f"{name}(q)ᵀ {name}(q) for a unit q",
            "the four columns must be orthonormal: compare each sign with the matrix in §4",
        )
    for q in general_quats(4, seed=seed + 1):
        M = expect_array(function(q), (4, 4), f"{name}(q)")
        expect_close(M.T @ M, (q @ q) * np.eye(4), TOL * (q @ q), f"{name}(q)ᵀ {name}(q) for |q|² = {q @ q:.3g}")


def _check_scipy(student, ref, name, seed):
    function = getattr(student, name)
    for a, b in zip(unit_quats(8, seed=seed), unit_quats(8, seed=seed + 1)):
        factor = a if name == "quat_left" else b
        M = expect_array(function(factor), (4, 4), f"{name}({'a' if name == 'quat_left' else 'b'})")
        got = M @ (b if name == "quat_left" else a)
        expected = (scipy_rotation(a) * scipy_rotation(b)).as_quat(scalar_first=True)
        if not same_rotation_quat(got, expected, TOL):
            expect_same_rotation(
                got,
                expected,
                TOL,
                f"the composition a ⊗ b through {name}",
                product_matrix_hint(M, factor, name, ref, 1e-9),
            )


@exercise("quat_left", weight=3)
def test_quat_left_is_left_product(student, ref):
    """quat_left(p) @ q equals p ⊗ q for 15 random quaternions (not unit)"""
    _check_product_matrix(student, ref, "quat_left", seed=411)


@exercise("quat_left", weight=1)
def test_quat_left_orthogonal(student):
    """is orthogonal for unit q, and [q]_Lᵀ [q]_L = |q|² I in general"""
    _check_orthogonal(student, "quat_left", seed=413)


@exercise("quat_left", weight=1)
def test_quat_left_matches_scipy(student, ref):
    """[a]_L b composes like scipy's rotations (up to sign)"""
    _check_scipy(student, ref, "quat_left", seed=415)


@exercise("quat_right", weight=3)
def test_quat_right_is_right_product(student, ref):
    """quat_right(q) @ p equals p ⊗ q for 15 random quaternions (not unit)"""
    _check_product_matrix(student, ref, "quat_right", seed=421)


@exercise("quat_right", weight=1)
def test_quat_right_orthogonal(student):
    """is orthogonal for unit q, and [q]_Rᵀ [q]_R = |q|² I in general"""
    _check_orthogonal(student, "quat_right", seed=423)


@exercise("quat_right", weight=1)
def test_quat_right_matches_scipy(student, ref):
    """[b]_R a composes like scipy's rotations (up to sign)"""
    _check_scipy(student, ref, "quat_right", seed=425)


# ---------------------------------------------------------------- quat_conjugate
@exercise("quat_conjugate", weight=3)
def test_quat_conjugate_values(student):
    """[w, x, y, z]* = [w, -x, -y, -z] for 20 random quaternions"""
    for q in general_quats(20, seed=431):
        got = expect_array(student.quat_conjugate(q), (4,), "quat_conjugate(q)")
        tol = TOL * np.linalg.norm(q)
        hint = (
            "negated the scalar instead of the vector part"
            if close(got, -conj(q), tol)
            else hints.RETURNED_Q_UNCHANGED_NEGATE_HINT
            if close(got, q, tol)
            else hints.RETURNED_Q_KEEP_SCALAR_HINT
            if close(got, -q, tol)
            else ""
        )
        expect_close(got, conj(q), tol, "quat_conjugate(q)", hint)


@exercise("quat_conjugate", weight=1)
def test_quat_conjugate_is_inverse_rotation(student):
    """the conjugate of a unit quaternion is the inverse rotation (scipy)"""
    for q in unit_quats(8, seed=432):
        got = expect_array(student.quat_conjugate(q), (4,), "quat_conjugate(q)")
        expected = scipy_rotation(q).inv().as_quat(scalar_first=True)
        hint = (
            "this is the rotation of q itself (q and -q are one rotation), not its inverse: q* = [w, -x, -y, -z]"
            if same_rotation_quat(got, q, TOL)
            else ""
        )
        expect_same_rotation(got, expected, TOL, "quat_conjugate(q) as a rotation", hint)


@exercise("quat_conjugate", weight=1)
def test_quat_conjugate_lists(student):
    """accepts a plain list"""
    expect_same_with_lists(student.quat_conjugate, ([1.0, 2.0, 3.0, 4.0],), (4,), "quat_conjugate(q)")


# ---------------------------------------------------------------- quat_inverse
def inverse_hint(got, q):
    """The hint for the one typical wrong inverse that ``got`` equals (relative tolerance 1e-9), else ""."""
    q = np.asarray(q, dtype=float)
    n2 = q @ q
    exact = conj(q) / n2
    candidates = [
        (conj(q), "returned the conjugate: divide it by |q|²"),
        (conj(q) / np.sqrt(n2), "divided by |q|, not by |q|²"),
        (-q / n2, hints.RETURNED_Q_Q_ONLY_HINT),
    ]
    if np.all(q != 0.0):
        candidates.append((1.0 / q, hints.TOOK_Q_ENTRY_ENTRY_HINT))
    matches = [
        hint
        for value, hint in candidates
        if not close(value, exact, 1e-9 * np.max(np.abs(exact))) and close(got, value, 1e-9 * np.max(np.abs(value)))
    ]
    return matches[0] if len(matches) == 1 else ""


@exercise("quat_inverse", weight=3)
def test_quat_inverse_non_unit(student):
    """q⁻¹ = q* / |q|² for 20 random quaternions of lengths 0.1 to 10"""
    for q in general_quats(20, seed=441):
        got = expect_array(student.quat_inverse(q), (4,), "quat_inverse(q)")
        n2 = q @ q
        if not close(got, conj(q) / n2, TOL / n2):
            expect_close(
                got, conj(q) / n2, TOL / n2, f"quat_inverse(q) for |q| = {np.sqrt(n2):.3g}", inverse_hint(got, q)
            )


@exercise("quat_inverse", weight=2)
def test_quat_inverse_undoes_product(student, ref):
    """q ⊗ q⁻¹ = q⁻¹ ⊗ q = 1 for lengths at every decade from 1e-12 to 1e12 (every non-zero q has an inverse)"""
    rng = np.random.default_rng(442)
    for scale in [0.5, 3.0] + [10.0**k for k in range(12, -13, -1)]:  # the long ones first
        q = rng.normal(size=4)
        q = scale * q / np.linalg.norm(q)
        got = expect_array(student.quat_inverse(q), (4,), "quat_inverse(q)")
        for what, product in (("q ⊗ q⁻¹", ref.quat_multiply(q, got)), ("q⁻¹ ⊗ q", ref.quat_multiply(got, q))):
            if not close(product, ONE, 1e-9):
                hint = inverse_hint(got, q) or (hints.NO_GUARD_FOR_SHORT_Q_HINT if scale < 1e-3 else "")
                expect_close(product, ONE, 1e-9, f"{what} for |q| = {scale:g}", hint)


@exercise("quat_inverse", weight=1)
def test_quat_inverse_unit(student):
    """for unit quaternions the inverse is the conjugate; lists and integers work too"""
    for q in unit_quats(6, seed=443):
        got = expect_array(student.quat_inverse(q), (4,), "quat_inverse(q)")
        if not close(got, conj(q), TOL):
            expect_close(got, conj(q), TOL, "quat_inverse(q) for a unit q", inverse_hint(got, q))
    expect_same_with_lists(
        student.quat_inverse, ([1.0, 2.0, -2.0, 4.0],), (4,), "quat_inverse([1, 2, -2, 4])", lists=([1, 2, -2, 4],)
    )


# ---------------------------------------------------------------- quat_from_axis_angle
def _axis_angle_cases(seed):
    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(20, 3))
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    angles = list(rng.uniform(-2 * np.pi, 2 * np.pi, 14)) + [0.0, np.pi, -np.pi, 2 * np.pi, 1e-9, np.pi / 2]
    return zip(axes, angles)


def axis_angle_hint(got, axis, theta, up_to_sign=False, tol=1e-9):
    """The hint for the one typical wrong quaternion of (axis, θ) that ``got`` equals, else ""."""
    axis = np.asarray(axis, dtype=float)
    u = axis / np.linalg.norm(axis)

    def quat(c, s, direction):
        return np.concatenate([[c], s * direction])

    exact = quat(np.cos(theta / 2), np.sin(theta / 2), u)
    half_degrees = np.deg2rad(theta) / 2
    candidates = [
        (
            quat(np.cos(theta), np.sin(theta), u),
            "this is the rotation by 2θ: the quaternion uses the half angle, [cos(θ/2), u sin(θ/2)]",
        ),
        (quat(np.cos(half_degrees), np.sin(half_degrees), u), "looks like degrees: the course works in radians"),
        (quat(np.sin(theta / 2), np.cos(theta / 2), u), hints.SIN_COS_SWAPPED_SCALAR_HINT),
        (quat(np.cos(theta / 2), np.sin(theta / 2), axis), hints.DIVIDE_U_NORM_FIRST_HINT),
    ]
    same = same_rotation_quat if up_to_sign else close
    matches = [hint for value, hint in candidates if not same(value, exact, tol) and same(got, value, tol)]
    if len(matches) == 1:
        return matches[0]
    if not up_to_sign and close(got, -exact, tol):
        return "the sign was changed: keep [cos(θ/2), u sin(θ/2)] as it is (w may be negative)"
    return ""


@exercise("quat_from_axis_angle", weight=3)
def test_quat_from_axis_angle_matches_scipy(student):
    """the same rotation as scipy's rotation vector θu, for 20 random and special cases"""
    for u, theta in _axis_angle_cases(451):
        got = expect_array(student.quat_from_axis_angle(u, theta), (4,), f"quat_from_axis_angle(u, {theta:.4g})")
        expected = Rotation.from_rotvec(theta * u).as_quat(scalar_first=True)
        if not same_rotation_quat(got, expected, TOL):
            expect_same_rotation(
                got,
                expected,
                TOL,
                f"quat_from_axis_angle(u, {theta:.4g})",
                axis_angle_hint(got, u, theta, up_to_sign=True, tol=1e-6),
            )


@exercise("quat_from_axis_angle", weight=1)
def test_quat_from_axis_angle_exact_formula(student):
    """returns exactly [cos(θ/2), u sin(θ/2)], without changing the sign, for θ up to 4π"""
    rng = np.random.default_rng(452)
    for theta in (0.5, 2.0, 3.5, 5.0, 7.0, 9.5, 12.0):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        got = expect_array(student.quat_from_axis_angle(u, theta), (4,), f"quat_from_axis_angle(u, {theta})")
        expected = np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])
        if not close(got, expected, TOL):
            expect_close(got, expected, TOL, f"quat_from_axis_angle(u, {theta})", axis_angle_hint(got, u, theta))


@exercise("quat_from_axis_angle", weight=1)
def test_quat_from_axis_angle_normalises_axis(student):
    """normalises an axis that is not unit length"""
    for axis, theta in (([0.0, 0.0, 5.0], 1.0), ([1.0, 2.0, 2.0], -2.5), ([0.01, 0.0, 0.0], 0.3)):
        got = expect_array(student.quat_from_axis_angle(axis, theta), (4,), f"quat_from_axis_angle({axis}, {theta})")
        u = np.asarray(axis) / np.linalg.norm(axis)
        expected = np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])
        if not close(got, expected, TOL):
            expect_close(
                got,
                expected,
                TOL,
                f"quat_from_axis_angle({axis}, {theta})",
                axis_angle_hint(got, axis, theta)
                or "expected [cos(θ/2), u sin(θ/2)] with the unit axis u = axis / |axis|",
            )


# ---------------------------------------------------------------- quat_rotate
def rotate_hint(got, q, v, ref, tol):
    """The hint for the one typical wrong rotated vector that ``got`` equals, else ""."""
    q, v = np.asarray(q, dtype=float), np.asarray(v, dtype=float)
    exact = scipy_rotation(q).apply(v)
    no_conjugate = ref.quat_multiply(ref.quat_multiply(q, np.concatenate([[0.0], v])), q)[1:]
    candidates = [
        (
            scipy_rotation(q).inv().apply(v),
            "rotated the opposite way: the sandwich is q ⊗ [0, v] ⊗ q*, with the conjugate on the right",
        ),
        (Rotation.from_quat(q).apply(v), hints.SCALAR_LAST_HINT),
        (no_conjugate, hints.CONJUGATE_MISSING_Q_V_HINT),
        (v + 2.0 * q[0] * np.cross(q[1:], v), hints.SECOND_ORDER_TERM_MISSING_HINT),
    ]
    matches = [hint for value, hint in candidates if not close(value, exact, tol) and close(got, value, tol)]
    return matches[0] if len(matches) == 1 else ""


@exercise("quat_rotate", weight=3)
def test_quat_rotate_matches_scipy(student, ref):
    """rotates 20 random vectors like scipy, for unit q in both hemispheres"""
    vectors = np.random.default_rng(461).normal(size=(20, 3)) * 3.0
    for q, v in zip(unit_quats(20, seed=462), vectors):
        got = expect_array(student.quat_rotate(q, v), (3,), "quat_rotate(q, v)")
        tol = TOL * 3.0 * np.linalg.norm(v)
        if not close(got, scipy_rotation(q).apply(v), tol):
            expect_close(
                got,
                scipy_rotation(q).apply(v),
                tol,
                "quat_rotate(q, v)",
                rotate_hint(got, q, v, ref, 1e-6 * np.linalg.norm(v)),
            )


@exercise("quat_rotate", weight=1)
def test_quat_rotate_sign_of_q(student):
    """q and -q rotate a vector the same way"""
    v = np.array([0.4, -2.0, 1.1])
    for q in unit_quats(6, seed=463):
        a = expect_array(student.quat_rotate(q, v), (3,), "quat_rotate(q, v)")
        b = expect_array(student.quat_rotate(-q, v), (3,), "quat_rotate(-q, v)")
        expect_close(a, b, TOL * 3.0, "quat_rotate(q, v) vs quat_rotate(-q, v)")


@exercise("quat_rotate", weight=1)
def test_quat_rotate_axis_and_lists(student, ref):
    """leaves the rotation axis where it is and accepts plain lists"""
    rng = np.random.default_rng(464)
    for _ in range(4):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        theta = rng.uniform(-3.0, 3.0)
        q = np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])
        got = expect_array(student.quat_rotate(q.tolist(), (2.0 * u).tolist()), (3,), "quat_rotate(q, axis)")
        if not close(got, 2.0 * u, TOL * 2.0):
            with_arrays = expect_array(student.quat_rotate(q, 2.0 * u), (3,), "quat_rotate(q, axis)")
            hint = (
                LISTS_HINT if close(with_arrays, 2.0 * u, TOL * 2.0) else rotate_hint(got, q, 2.0 * u, ref, 1e-6 * 2.0)
            )
            expect_close(got, 2.0 * u, TOL * 2.0, "quat_rotate(q, 2u) along the axis u", hint)


# ---------------------------------------------------------------- quat_to_matrix
def matrix_hint(got, q, tol=1e-6):
    """The hint for the one typical wrong matrix of ``q`` that ``got`` equals, else a shared guess or ""."""
    q = np.asarray(q, dtype=float)
    exact = scipy_rotation(q).as_matrix()
    w, v = q[0], q[1:]
    K = np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])
    candidates = [
        (exact.T, "looks like the transpose (the inverse rotation): check the sign of every term linear in w"),
        (Rotation.from_quat(q).as_matrix(), hints.SCALAR_LAST_HINT),
        (
            np.eye(3) + w * K + K @ K,
            "not a rotation: its columns are shorter than 1, where a rotation keeps lengths; rotate e_x with the "
            "sandwich on paper and compare with your first column, term by term",
        ),
    ]
    matches = [hint for value, hint in candidates if not close(value, exact, tol) and close(got, value, tol)]
    if len(matches) == 1:
        return matches[0]
    return "" if matches else rotation_hint(got, exact) or ""


@exercise("quat_to_matrix", weight=3)
def test_quat_to_matrix_matches_scipy(student):
    """equals scipy's matrix (scalar_first=True) for 20 random unit q, both hemispheres"""
    for q in unit_quats(20, seed=471):
        got = expect_array(student.quat_to_matrix(q), (3, 3), "quat_to_matrix(q)")
        expected = scipy_rotation(q).as_matrix()
        if not close(got, expected, TOL):
            expect_close(got, expected, TOL, "quat_to_matrix(q)", matrix_hint(got, q))


@exercise("quat_to_matrix", weight=1)
def test_quat_to_matrix_scalar_last_oracle(student):
    """agrees with scipy's default scalar-last reading of the reordered quaternion"""
    for xyzw in Rotation.random(8, random_state=472).as_quat():
        wxyz = np.concatenate([xyzw[3:], xyzw[:3]])
        got = expect_array(student.quat_to_matrix(wxyz), (3, 3), "quat_to_matrix(q)")
        if not close(got, Rotation.from_quat(xyzw).as_matrix(), TOL):
            expect_close(
                got, Rotation.from_quat(xyzw).as_matrix(), TOL, "quat_to_matrix([w, x, y, z])", matrix_hint(got, wxyz)
            )


@exercise("quat_to_matrix", weight=1)
def test_quat_to_matrix_edge_cases(student):
    """identity, half turns (w = 0) and R(q) == R(-q)"""
    got = expect_array(student.quat_to_matrix(ONE), (3, 3), "quat_to_matrix(1)")
    expect_close(got, np.eye(3), TOL, "quat_to_matrix([1, 0, 0, 0])", matrix_hint(got, ONE))
    rng = np.random.default_rng(473)
    for _ in range(4):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        got = expect_array(student.quat_to_matrix(np.concatenate([[0.0], u])), (3, 3), "quat_to_matrix")
        expect_close(
            got,
            rotation_of_pi(u),
            TOL,
            "quat_to_matrix([0, u]), a half turn",
            matrix_hint(got, np.concatenate([[0.0], u])),
        )
    for q in unit_quats(4, seed=474):
        a = expect_array(student.quat_to_matrix(q), (3, 3), "quat_to_matrix(q)")
        b = expect_array(student.quat_to_matrix(-q), (3, 3), "quat_to_matrix(-q)")
        problem = rotation_problem(a)
        expect(problem is None, f"quat_to_matrix(q) is not a rotation: {problem}")
        expect_close(a, b, TOL, "quat_to_matrix(q) vs quat_to_matrix(-q)")


# ---------------------------------------------------------------- matrix_to_quat
M2Q_TOL = 1e-12  # matrix_to_quat promises every component within 1e-12 of the exact quaternion, at every angle
SHEPPERD = "divide only by a component that cannot be small"
NAN_NEAR_PI_HINT = "NaN or inf near θ = π, where w = cos(θ/2) → 0: dividing by 4w fails there; " + SHEPPERD


def naive_hint(got, expected):
    """Near θ = π, the trace formula's signature: the right direction in R⁴ but the wrong length, else ""."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    length = np.linalg.norm(got)
    if (
        abs(expected[0]) > 0.1
        or abs(length - 1.0) <= M2Q_TOL / 2
        or not same_rotation_quat(got / length, expected, 1e-6)
    ):
        return ""
    return (
        f"|q| = 1 {'+' if length > 1 else '-'} {abs(length - 1.0):.2g}: near θ = π the trace formula "
        f"w = ½√(1 + tr R) loses accuracy, and dividing by 4w carries the error into x, y, z; " + SHEPPERD
    )


def m2q_array(value, what, near_pi):
    """``value`` as a (4,) array; NaN or inf near θ = π is the division by w = 0."""
    if shape_problem(value, (4,)) == "returned NaN or inf values":
        raise Wrong(f"{what} returned NaN or inf values", NAN_NEAR_PI_HINT if near_pi else "")
    return expect_array(value, (4,), what)


def m2q_hint(got, expected):
    """Layout, conjugate or sign (``quaternion_hint``), else the trace formula's signature, else ""."""
    return quaternion_hint(got, expected) or naive_hint(got, expected) or ""


@exercise("matrix_to_quat", weight=2)
def test_matrix_to_quat_random(student):
    """the quaternion of 20 random rotations (compared up to sign)"""
    for R in Rotation.random(20, random_state=481).as_matrix():
        got = expect_array(student.matrix_to_quat(R), (4,), "matrix_to_quat(R)")
        expected = Rotation.from_matrix(R).as_quat(scalar_first=True)
        expect_same_rotation(got, expected, M2Q_TOL, "matrix_to_quat(R)", m2q_hint(got, expected))


@exercise("matrix_to_quat", weight=1)
def test_matrix_to_quat_near_pi(student):
    """stays accurate for rotations by π - δ, δ from 1e-4 down to 1e-12"""
    rng = np.random.default_rng(482)
    for delta in (1e-4, 1e-6, 1e-8, 1e-10, 1e-12):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        theta = np.pi - delta
        q_true = np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])
        R = scipy_rotation(q_true).as_matrix()
        got = m2q_array(student.matrix_to_quat(R), f"matrix_to_quat(R) at θ = π - {delta:g}", near_pi=True)
        expect_same_rotation(got, q_true, M2Q_TOL, f"matrix_to_quat(R) at θ = π - {delta:g}", m2q_hint(got, q_true))


@exercise("matrix_to_quat", weight=1)
def test_matrix_to_quat_exactly_pi(student):
    """exact half turns (w = 0) about coordinate and generic axes"""
    rng = np.random.default_rng(483)
    axes = [np.eye(3)[k] for k in range(3)] + [rng.normal(size=3) for _ in range(4)]
    for axis in axes:
        u = axis / np.linalg.norm(axis)
        got = m2q_array(
            student.matrix_to_quat(rotation_of_pi(u)), f"matrix_to_quat at θ = π about {fmt(u)}", near_pi=True
        )
        expected = np.concatenate([[0.0], u])
        expect_same_rotation(got, expected, M2Q_TOL, f"matrix_to_quat at θ = π about {fmt(u)}", m2q_hint(got, expected))


@exercise("matrix_to_quat", weight=5)
def test_matrix_to_quat_canonical_sign(student):
    """returns the canonical sign w >= 0 (angles up to 2π, near π too)"""
    rng = np.random.default_rng(484)
    for theta in (0.3, 2.0, 3.0, np.pi - 1e-6, 4.0, 5.5, 6.2):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        q = np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])
        canonical = q if q[0] >= 0 else -q
        got = m2q_array(
            student.matrix_to_quat(scipy_rotation(q).as_matrix()), "matrix_to_quat(R)", near_pi=abs(theta - np.pi) < 0.1
        )
        hint = (
            "q and -q are the same rotation; the canonical choice has w >= 0: negate q when w < 0"
            if close(got, -canonical, 1e-9)
            else m2q_hint(got, canonical)
        )
        expect_close(got, canonical, M2Q_TOL, f"matrix_to_quat(R) for a turn by {theta:.4g} rad", hint)


def _one_component_small(seed):
    """Unit quaternions (w >= 0) with one component 0, 1e-8 or 1e-4 and the other three generic, for each of the
    four components: where a branch chosen by the wrong pivot divides by a vanishing one."""
    rng = np.random.default_rng(seed)
    found = []
    for k in range(4):
        for small in (0.0, 1e-8, 1e-4):
            for _ in range(4):
                q = rng.uniform(0.3, 1.0, 4) * rng.choice([-1.0, 1.0], 4)
                q[k] = small
                q /= np.linalg.norm(q)
                found.append(q if q[0] >= 0 else -q)
    return found


@exercise("matrix_to_quat", weight=1)
def test_matrix_to_quat_one_component_small(student):
    """accurate, with w >= 0, when one of w, x, y, z is 0, 1e-8 or 1e-4 and the others are generic (every branch
    next to its boundary: a method must never divide by a small component)"""
    for q in _one_component_small(486):
        R = scipy_rotation(q).as_matrix()
        got = m2q_array(student.matrix_to_quat(R), f"matrix_to_quat(R) for q = {fmt(q)}", near_pi=False)
        hint = m2q_hint(got, q) or (
            "a component you divide by was small here: divide only by a component that cannot be small"
        )
        if q[0] == 0.0:  # w = 0: q and -q both have w >= 0, either is the answer
            expect_same_rotation(got, q, M2Q_TOL, f"matrix_to_quat(R) for q = {fmt(q)}", hint)
        else:  # the docstring's w >= 0 holds at w = 1e-8 too
            expect_close(got, q, M2Q_TOL, f"matrix_to_quat(R) for q = {fmt(q)}", hint)


@exercise("matrix_to_quat", weight=1)
def test_matrix_to_quat_identity_and_norm(student):
    """identity → [1, 0, 0, 0]; the result has unit length"""
    got = expect_array(student.matrix_to_quat(np.eye(3)), (4,), "matrix_to_quat(I)")
    expect_close(got, ONE, M2Q_TOL, "matrix_to_quat(I)", quaternion_hint(got, ONE) or "")
    for R in Rotation.random(5, random_state=485).as_matrix():
        got = expect_array(student.matrix_to_quat(R.tolist()), (4,), "matrix_to_quat(R as a list)")
        expect(
            abs(np.linalg.norm(got) - 1.0) <= M2Q_TOL,
            f"|matrix_to_quat(R)| = {np.linalg.norm(got):.12f}",
            "scale the result to unit length",
        )


# ---------------------------------------------------------------- wxyz_to_xyzw, xyzw_to_wxyz
def layout_hint(got, q, to_end):
    """The hint for the one typical wrong reordering of ``q`` (one quaternion or a stack) that ``got`` equals."""
    q = np.asarray(q, dtype=float)
    shift, where, index = (
        (-1, "end", "q[..., 1:] and q[..., :1]") if to_end else (1, "front", "q[..., 3:] and q[..., :3]")
    )
    exact = np.roll(q, shift, axis=-1)
    candidates = [
        (q[..., ::-1], hints.ARRAY_REVERSED_ONLY_SCALAR_HINT),
        (q, f"returned q unchanged: the scalar must move to the {where}"),
        (np.roll(q, -shift, axis=-1), f"rolled the wrong way: the scalar must move to the {where}"),
        (
            np.roll(q.ravel(), shift).reshape(q.shape),
            f"the whole stack was rolled as one flat array: roll along the last axis (axis=-1) or index {index}",
        ),
    ]
    matches = [hint for value, hint in candidates if not close(value, exact, 0.0) and close(got, value, 0.0)]
    return matches[0] if len(matches) == 1 else ""


@exercise("wxyz_to_xyzw", weight=3)
def test_wxyz_to_xyzw_values(student):
    """moves the scalar to the end; scipy's default from_quat then gives the same rotation"""
    for q in unit_quats(10, seed=491):
        got = expect_array(student.wxyz_to_xyzw(q), (4,), "wxyz_to_xyzw(q)")
        expect_close(got, np.concatenate([q[1:], q[:1]]), 0.0, "wxyz_to_xyzw(q)", layout_hint(got, q, to_end=True))
        expect_close(
            Rotation.from_quat(got).as_matrix(),
            scipy_rotation(q).as_matrix(),
            TOL,
            "scipy's Rotation.from_quat(wxyz_to_xyzw(q))",
        )


@exercise("wxyz_to_xyzw", weight=1)
def test_wxyz_to_xyzw_stack(student):
    """converts a stack of shape (N, 4) row by row, and accepts lists"""
    stack = general_quats(5, seed=492)
    got = expect_array(student.wxyz_to_xyzw(stack), (5, 4), "wxyz_to_xyzw(stack of 5)")
    expect_close(
        got,
        np.concatenate([stack[:, 1:], stack[:, :1]], axis=1),
        0.0,
        "wxyz_to_xyzw(stack)",
        layout_hint(got, stack, to_end=True),
    )
    got = expect_array(student.wxyz_to_xyzw([1.0, 2.0, 3.0, 4.0]), (4,), "wxyz_to_xyzw(list)")
    expect_close(got, [2.0, 3.0, 4.0, 1.0], 0.0, "wxyz_to_xyzw([1, 2, 3, 4])")


@exercise("xyzw_to_wxyz", weight=3)
def test_xyzw_to_wxyz_values(student):
    """moves the scalar to the front; scipy's scalar-last output becomes scalar_first=True's"""
    quats = Rotation.random(10, random_state=493).as_quat(canonical=True)  # scipy's layout: [x, y, z, w]
    quats[1::2] *= -1.0  # both hemispheres
    for xyzw in quats:
        got = expect_array(student.xyzw_to_wxyz(xyzw), (4,), "xyzw_to_wxyz(q)")
        expect_close(
            got, np.concatenate([xyzw[3:], xyzw[:3]]), 0.0, "xyzw_to_wxyz(q)", layout_hint(got, xyzw, to_end=False)
        )
        expect_close(
            scipy_rotation(got).as_matrix(),
            Rotation.from_quat(xyzw).as_matrix(),
            TOL,
            "Rotation.from_quat(xyzw_to_wxyz(q), scalar_first=True)",
        )


@exercise("xyzw_to_wxyz", weight=1)
def test_xyzw_to_wxyz_stack(student):
    """converts a stack of shape (N, 4) row by row, and accepts lists"""
    stack = general_quats(5, seed=494)
    got = expect_array(student.xyzw_to_wxyz(stack), (5, 4), "xyzw_to_wxyz(stack of 5)")
    expect_close(
        got,
        np.concatenate([stack[:, 3:], stack[:, :3]], axis=1),
        0.0,
        "xyzw_to_wxyz(stack)",
        layout_hint(got, stack, to_end=False),
    )
    got = expect_array(student.xyzw_to_wxyz([2.0, 3.0, 4.0, 1.0]), (4,), "xyzw_to_wxyz(list)")
    expect_close(got, [1.0, 2.0, 3.0, 4.0], 0.0, "xyzw_to_wxyz([2, 3, 4, 1])")


# ---------------------------------------------------------------- quat_slerp
def scipy_slerp(q0, q1, t):
    """scipy's Slerp between the rotations of q0 and q1 (always the shorter way)."""
    pair = Rotation.from_quat(np.array([q0, q1]), scalar_first=True)
    return Slerp([0.0, 1.0], pair)([t]).as_quat(scalar_first=True)[0]


def long_arc(q0, q1, t):
    omega = np.arccos(np.clip(q0 @ q1, -1.0, 1.0))
    return (np.sin((1 - t) * omega) * q0 + np.sin(t * omega) * q1) / np.sin(omega)


NLERP_HINT = hints.CONSTANT_SPEED_NORMALISED_LINEAR_HINT


def nlerp(q0, q1, t):
    q1 = -q1 if q0 @ q1 < 0 else q1
    q = (1 - t) * q0 + t * q1
    return q / np.linalg.norm(q)


def angle_between(a, b):
    return 2.0 * np.arccos(min(abs(float(np.dot(a, b))), 1.0))


LONG_ARC_HINT = "took the longer arc: q1 and -q1 are one rotation; when q0 · q1 < 0, interpolate towards -q1"
TINY_OMEGA_HINT = (
    "NaN or inf for (nearly) equal inputs: sin Ω = 0 there; when sin Ω is tiny, fall back to "
    "(normalised) linear interpolation"
)


def slerp_hint(got, q0, q1, t):
    """The hint for the typical wrong slerp that ``got`` equals, else what property failed, else ""."""
    q0, q1 = np.asarray(q0, dtype=float), np.asarray(q1, dtype=float)
    near = q1 if q0 @ q1 >= 0 else -q1
    length = np.linalg.norm(got)
    if q0 @ q1 < 0 and abs(q0 @ q1) < 1.0 - 1e-12 and same_rotation_quat(got, long_arc(q0, q1, t), 1e-6):
        return LONG_ARC_HINT
    if abs(length - 1.0) > 1e-12 and (
        close(got, (1 - t) * q0 + t * near, 1e-9) or close(got, (1 - t) * q0 + t * q1, 1e-9)
    ):
        return (
            f"plain linear interpolation (1 - t) q0 + t q1 leaves the unit sphere (|result| = {length:.4f}): "
            "use the weights sin((1 - t)Ω)/sin Ω and sin(tΩ)/sin Ω"
        )
    if abs(length - 1.0) > 1e-6:
        return f"|result| = {length:.4f}: slerp stays on the unit sphere"
    # nlerp is slerp to within about Ω³ / 50: below Ω ≈ 1e-2 every answer near either is "nlerp" to 1e-9
    apart = 2.0 * np.arcsin(min(1.0, np.linalg.norm(near - q0) / 2.0))
    if t != 0.5 and apart > 1e-2 and same_rotation_quat(got, nlerp(q0, q1, t), 1e-9):
        return NLERP_HINT
    return ""


def slerp_array(value, what, q0, q1):
    """``value`` as a (4,) array; NaN or inf for (nearly) equal or opposite inputs is the division by sin Ω."""
    if shape_problem(value, (4,)) == "returned NaN or inf values":
        raise Wrong(f"{what} returned NaN or inf values", TINY_OMEGA_HINT if abs(np.dot(q0, q1)) > 1.0 - 1e-6 else "")
    return expect_array(value, (4,), what)


@exercise("quat_slerp", weight=3)
def test_quat_slerp_matches_scipy(student):
    """agrees with scipy's Slerp for 12 random pairs at t = 0.1 … 0.9 (half of them need the sign flip)"""
    for k, (q0, q1) in enumerate(zip(unit_quats(12, seed=501), unit_quats(12, seed=502))):
        if (q0 @ q1 < 0) != (k % 2 == 1):
            q1 = -q1  # odd pairs have q0 · q1 < 0, even pairs q0 · q1 > 0
        for t in (0.1, 0.25, 0.5, 0.75, 0.9):
            got = expect_array(student.quat_slerp(q0, q1, t), (4,), f"quat_slerp(q0, q1, {t})")
            if not same_rotation_quat(got, scipy_slerp(q0, q1, t), TOL):
                expect_same_rotation(
                    got, scipy_slerp(q0, q1, t), TOL, f"quat_slerp(q0, q1, {t})", slerp_hint(got, q0, q1, t)
                )


@exercise("quat_slerp", weight=2)
def test_quat_slerp_endpoints(student):
    """t = 0 gives q0 and t = 1 gives q1 (up to sign)"""
    for q0, q1 in zip(unit_quats(6, seed=503), unit_quats(6, seed=504)):
        expect_same_rotation(
            expect_array(student.quat_slerp(q0, q1, 0.0), (4,), "quat_slerp(q0, q1, 0)"),
            q0,
            TOL,
            "quat_slerp(q0, q1, 0)",
        )
        expect_same_rotation(
            expect_array(student.quat_slerp(q0, q1, 1.0), (4,), "quat_slerp(q0, q1, 1)"),
            q1,
            TOL,
            "quat_slerp(q0, q1, 1)",
        )


@exercise("quat_slerp", weight=2)
def test_quat_slerp_shorter_arc(student):
    """turns at constant speed along the shorter arc, also for rotations almost π apart"""
    rng = np.random.default_rng(505)
    cases = []
    for angle in (2.5, 3.0, np.pi - 0.02):  # rotation angle from q0 to q1
        q0 = unit_quats(1, seed=int(rng.integers(1000)))[0]
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        step = np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * u])
        w, v = q0[0], q0[1:]
        q1 = np.concatenate([[w * step[0] - v @ step[1:]], w * step[1:] + step[0] * v + np.cross(v, step[1:])])
        cases.append((q0, -q1 if q0 @ q1 > 0 else q1, angle))  # q1 handed over with q0 · q1 < 0
    for q0, q1, angle in cases:
        for t in (0.25, 0.5, 0.8):
            got = expect_array(student.quat_slerp(q0, q1, t), (4,), f"quat_slerp(q0, q1, {t})")
            expect(
                abs(np.linalg.norm(got) - 1.0) <= 1e-9,
                f"|quat_slerp(q0, q1, {t})| = {np.linalg.norm(got):.6f}, off the unit sphere by "
                f"{abs(np.linalg.norm(got) - 1.0):.2g}",
                slerp_hint(got, q0, q1, t) or hints.SLERP_STAYS_UNIT_SPHERE_HINT,
            )
            turned = angle_between(q0, got)
            hint = slerp_hint(got, q0, q1, t) or (hints.CONSTANT_SPEED_TURN_Q0_HINT)
            expect(
                abs(turned - t * angle) <= 1e-8,
                f"at t = {t} the result is {turned:.6f} rad from q0, off by {abs(turned - t * angle):.2g} from "
                f"t × {angle:.4f} = {t * angle:.6f}",
                hint,
            )


def _turned(q, angle, axis):
    """q ⊗ [cos(angle/2), sin(angle/2) axis]: q turned by ``angle`` about the body axis ``axis``."""
    step = np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * axis])
    w, v = q[0], q[1:]
    return np.concatenate([[w * step[0] - v @ step[1:]], w * step[1:] + step[0] * v + np.cross(v, step[1:])])


@exercise("quat_slerp", weight=2)
def test_quat_slerp_every_decade(student):
    """exact to 2e-15 for turns from q0 to q1 of 1e-12 to π rad (every decade), either sign of q1, t in [0, 1]
    (the endpoints too)"""

    def check(case):
        q0, angle, axis, sign, t = case
        q1 = sign * _turned(q0, angle, axis)
        got = expect_array(student.quat_slerp(q0, q1, t), (4,), "quat_slerp(q0, q1, t)")
        expected = _turned(q0, t * angle, axis)  # t of the way along the shorter arc
        expected = expected if got @ expected >= 0 else -expected
        expect_within(
            got,
            expected,
            SLERP_TOL,
            "quat_slerp(q0, q1, t)",
            f"Ω = {angle:.2g} between q0 and q1, t = {t:.3g}",
            lambda: slerp_hint(got, q0, q1, t),
        )

    q0 = unit_quats(1, seed=508)[0]
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    # turns just below each decade, and turns whose half-angle Ω = acos|q0 · q1| is just below one (1.94 · 10⁻ᵏ):
    # a fallback threshold at a decade of either is tried where its error peaks
    explicit = (
        [(q0, 0.97 * 10.0**-k, axis, sign, t) for k in range(1, 12) for sign, t in ((1.0, 0.3), (-1.0, 0.0))]
        + [(q0, 2.0, axis, 1.0, 1.0)]
        + [(q0, 1.94 * 10.0**-k, axis, 1.0, 0.3) for k in range(1, 12)]
    )
    cases = st.tuples(
        quaternions(),
        angles(sign=False, near_pi=False, zero=False),
        unit_vectors(),
        st.sampled_from([1.0, -1.0]),
        st.one_of(st.sampled_from([0.0, 1.0]), st.floats(0.0, 1.0)),
    )
    for_all(cases, check, explicit=explicit)


@exercise("quat_slerp", weight=1)
def test_quat_slerp_nearly_identical(student):
    """nearly identical (and nearly opposite) quaternions: no division by zero (tolerance 1e-8); lists too"""
    q0 = unit_quats(1, seed=506)[0]
    rng = np.random.default_rng(507)
    for tiny in (0.0, 1e-12, 1e-8, 1e-5):
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        step = np.concatenate([[np.cos(tiny)], np.sin(tiny) * u])
        w, v = q0[0], q0[1:]
        q1 = np.concatenate([[w * step[0] - v @ step[1:]], w * step[1:] + step[0] * v + np.cross(v, step[1:])])
        for other, name in ((q1, "nearly identical"), (-q1, "nearly opposite")):
            for t in (0.3, 0.5):
                got = slerp_array(
                    student.quat_slerp(q0, other, t), f"quat_slerp for {name} inputs ({tiny:g} apart)", q0, other
                )
                if not same_rotation_quat(got, scipy_slerp(q0, other, t), 1e-8):
                    expect_same_rotation(
                        got,
                        scipy_slerp(q0, other, t),
                        1e-8,
                        f"quat_slerp(q0, q1, {t}) for {name} inputs ({tiny:g} apart)",
                        slerp_hint(got, q0, other, t),
                    )
            if tiny == 0.0:
                expect_same_with_lists(
                    student.quat_slerp, (q0, other), (4,), f"quat_slerp(q0, q1, 0.3) for {name} inputs", t=0.3
                )
