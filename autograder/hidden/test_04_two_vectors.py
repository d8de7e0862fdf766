"""Hidden checks for lesson 04, section 16: quat_from_two_vectors.

Oracle: the data are built by turning a known direction a through a known angle θ about an axis n
perpendicular to it (scipy's Rotation), and the answer is applied with scipy. A correct answer is a unit
quaternion whose rotation takes the direction of a to that of b and turns through θ (the shortest turn is
the only one that does both). Core idea (3 of 6 points): the half angle and the axis along a × b, accurate for
every angle from 1e-12 to π − 1e-3 and for inputs of any length. Near opposite directions the axis itself is
ill-conditioned (a × b is tiny), so there the action is held to 1e-15 / (π − θ) instead. Every test calls
quat_from_two_vectors only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect, expect_array, expect_same_with_lists, fmt

ANGLES = (1.0, 2.0, 0.3, 1e-12, 1e-9, 1e-6, 1e-3, 0.05, 3.0, np.pi - 1e-3, np.pi - 1e-6)  # generic turns first


def _matrix(q):
    return Rotation.from_quat(np.asarray(q, dtype=float), scalar_first=True).as_matrix()


def _angle(q):
    q = np.asarray(q, dtype=float)
    return 2.0 * np.arctan2(np.linalg.norm(q[1:]), abs(q[0]))


def _pair(theta, seed):
    rng = np.random.default_rng(seed)
    a = rng.normal(size=3) * 10.0 ** rng.uniform(-2, 2)
    n = np.cross(a, rng.normal(size=3))
    n /= np.linalg.norm(n)
    b = Rotation.from_rotvec(theta * n).as_matrix() @ a * 10.0 ** rng.uniform(-2, 2)
    return a, b


def _truth(a, b, theta):
    """The shortest turn from a to b, which _pair built to be ``theta``."""
    a_hat, b_hat = a / np.linalg.norm(a), b / np.linalg.norm(b)
    u = np.cross(a_hat, b_hat) / np.linalg.norm(np.cross(a_hat, b_hat))
    return np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])


def _slip_values(a, b):
    a_hat, b_hat = a / np.linalg.norm(a), b / np.linalg.norm(b)
    axis = np.cross(a_hat, b_hat)
    s = np.linalg.norm(axis)
    theta = np.arctan2(s, a_hat @ b_hat)
    u = axis / s
    raw = np.concatenate([[1.0 + a @ b], np.cross(a, b)])
    return [
        (
            np.concatenate([[np.cos(theta)], np.sin(theta) * u]),
            "R(q) turns a twice as far as b: a quaternion holds half the angle of its turn, [cos(φ/2), "
            "sin(φ/2) u] turns by φ (section 7)",
        ),
        (
            np.concatenate([[np.cos(theta / 2)], -np.sin(theta / 2) * u]),
            "the axis points the wrong way: the turn takes a away from b",
        ),
        (raw / np.linalg.norm(raw), "only the directions count: normalise a and b first"),
        (
            np.concatenate(
                [
                    [np.cos(np.arccos(np.clip(a_hat @ b_hat, -1, 1)) / 2)],
                    np.sin(np.arccos(np.clip(a_hat @ b_hat, -1, 1)) / 2) * u,
                ]
            ),
            hints.ARCCOS_LOSES_SMALL_ANGLES_HINT,
        ),
    ]


def _hint(got, a, b, truth):
    for candidate, hint in _slip_values(a, b):
        if np.max(np.abs(candidate - truth)) > 1e-13 and explains(got, candidate, truth, floor=1e-17):
            return hint
    return (
        "the rotation of q must take the direction of a onto that of b, and no rotation that does may turn less: "
        "try pairs whose answer you can see (x onto y is a quarter turn about +z), and check how q holds the "
        "angle, the sense of the turn and the accuracy at tiny angles"
    )


@exercise("quat_from_two_vectors", weight=3)
def test_two_vectors_every_angle(student):
    """takes a to b by the shortest turn, for turns from 1e-12 to π − 1e-6 rad and |a|, |b| from 0.01 to 100:
    unit norm to 1e-14, angle to 1e-14, action to 1e-14 (1e-15 / (π − θ) near π)"""
    for k, theta in enumerate(ANGLES):
        a, b = _pair(theta, 4100 + k)
        got = expect_array(student.quat_from_two_vectors(a, b), (4,), "quat_from_two_vectors(a, b)")
        a_hat, b_hat = a / np.linalg.norm(a), b / np.linalg.norm(b)
        truth = _truth(a, b, theta)
        hint = _hint(got, a, b, truth)
        expect(abs(np.linalg.norm(got) - 1.0) <= 1e-14, f"|q| = {np.linalg.norm(got):.15f} for θ = {theta:.3g}", hint)
        tol = 1e-14 if theta <= 3.0 else 1e-15 / (np.pi - theta)
        miss = np.linalg.norm(_matrix(got) @ a_hat - b_hat)
        expect(
            miss <= tol,
            f"for θ = {theta:.3g} rad the rotation misses the direction of b by {miss:.2g} "
            f"(tolerance {tol:.2g}): got {fmt(got, 6)}",
            hint,
        )
        if theta <= 3.0:
            error = abs(_angle(got) - theta)
            expect(
                error <= 1e-14,
                f"for θ = {theta:.3g} rad the rotation turns by {_angle(got):.15g} rad "
                f"(off by {error:.2g}): not the shortest turn",
                hint,
            )


@exercise("quat_from_two_vectors", weight=1)
def test_two_vectors_opposite_and_parallel(student):
    """opposite directions give a unit half turn sending a to -a (to 1e-14); parallel ones the identity"""
    for a in ([1.0, 0.0, 0.0], [0.0, 0.0, -2.0], [1.0, 2.0, 3.0], [-0.3, 0.7, 0.1]):
        a = np.asarray(a)
        got = student.quat_from_two_vectors(a, -3.0 * a)
        expect(
            np.shape(got) != (4,) or np.all(np.isfinite(np.asarray(got, dtype=float))),
            f"for opposite directions ({fmt(a)} and its negative) got NaN",
            "for opposite directions whatever gives your axis elsewhere is zero or rounding noise here: take a half "
            "turn about any axis perpendicular to a, found another way",
        )
        got = expect_array(got, (4,), "quat_from_two_vectors(a, -3a)")
        a_hat = a / np.linalg.norm(a)
        half_turn_wrong_axis = abs(np.linalg.norm(got) - 1.0) <= 1e-14 and abs(got[0]) <= 1e-14
        expect(
            abs(np.linalg.norm(got) - 1.0) <= 1e-14 and np.linalg.norm(_matrix(got) @ a_hat + a_hat) <= 1e-14,
            f"for opposite directions got {fmt(got, 6)}: not a unit half turn sending a to -a",
            "for opposite directions whatever gives your axis elsewhere is zero or rounding noise here: take a half "
            "turn about any axis perpendicular to a, found another way"
            if half_turn_wrong_axis
            else hints.OPPOSITE_DIRECTIONS_ANSWER_HALF_HINT,
        )
        same = expect_array(student.quat_from_two_vectors(a, 0.25 * a), (4,), "quat_from_two_vectors(a, a/4)")
        expect(
            np.max(np.abs(same - [1.0, 0.0, 0.0, 0.0])) <= 1e-15,
            f"parallel directions gave {fmt(same, 6)}, not the identity",
            "parallel directions need no turn",
        )


@exercise("quat_from_two_vectors", weight=1)
def test_two_vectors_only_directions_count(student):
    """scaling a and b by 1e-12 … 1e8 leaves the answer unchanged, to 1e-14, at 1.2 rad and at 1e-6 rad (where an
    unnormalised a × b falls below any small-angle threshold)"""
    for theta, seed in ((1.2, 4120), (1e-6, 4121)):
        a, b = _pair(theta, seed)
        base = expect_array(student.quat_from_two_vectors(a, b), (4,), "quat_from_two_vectors(a, b)")
        truth = _truth(a, b, theta)
        # An answer that moves with the scale is blamed on normalisation only if it is right unscaled: an
        # inaccurate formula (arccos) also moves, because its rounding noise changes with the inputs' digits.
        hint = (
            "only the directions count: normalise a and b first"
            if np.max(np.abs(base - truth)) <= 1e-14
            else _hint(base, a, b, truth)
        )
        for scale_a, scale_b in ((1e-8, 1.0), (1.0, 1e8), (1e5, 1e-5), (3.0, 0.5), (1.0, 1e-12), (1e-12, 1.0)):
            got = expect_array(
                student.quat_from_two_vectors(scale_a * a, scale_b * b), (4,), "quat_from_two_vectors(c1 a, c2 b)"
            )
            expect(
                np.max(np.abs(got - base)) <= 1e-14,
                f"at θ = {theta:g} rad, scaling a by {scale_a:g} and b by "
                f"{scale_b:g} changed the answer by {np.max(np.abs(got - base)):.2g}",
                hint,
            )


@exercise("quat_from_two_vectors", weight=1)
def test_two_vectors_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    expect_same_with_lists(student.quat_from_two_vectors, _pair(0.8, 4130), (4,), "quat_from_two_vectors(a, b)")
