"""Hidden checks for lesson 03, section 8: body_angular_velocity.

Oracle: the motion R(t) = R Exp(t ω_b) has Ṙ = R [ω_b]× (and, the same motion seen from the world,
Ṙ = [R ω_b]× R); the test builds Ṙ from a chosen body rate and asks for it back. Core idea (3 of 5 points):
the rate in body axes, not the world rate Ṙ Rᵀ, for attitudes at every angle from 1e-12 to π and spins
from 1e-12 to 1e3 rad/s, to 1e-12 of the spin's size. Every test calls body_angular_velocity only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect, expect_array, expect_same_with_lists, fmt, random_rotations

ANGLES = (1.0, 2.5, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 3.0, np.pi - 1e-9)  # generic turns first
SPINS = (1.0, 30.0, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 1e3, 5.0)


def _skew(v):
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _vee(W):
    return 0.5 * np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]])


def _hint(got, R, R_dot, omega_b):
    slips = [
        (_vee(R_dot @ R.T), hints.BODY_RATE_IS_WORLD_RATE_HINT),
        (-omega_b, "the opposite spin: ω_b came out negated"),
        (_vee(R_dot), "Ṙ alone is not skew-symmetric: it still holds the attitude R"),
        (R.T @ omega_b, hints.RATE_TURNED_INTO_BODY_HINT),
    ]
    size = np.linalg.norm(omega_b)
    for candidate, hint in slips:
        if np.max(np.abs(candidate - omega_b)) > 1e-6 * size and explains(
            got / size, candidate / size, omega_b / size, floor=1e-12
        ):
            return hint
    return (
        "ω_b is off: combine section 8's two facts with the identity for [R v]×, and test your formula on "
        "R(t) = R0 Exp(t ω_b), whose body rate you know"
    )


@exercise("body_angular_velocity", weight=3)
def test_body_rate_every_angle_and_spin(student):
    """returns ω_b (ω_w = R ω_b) for R at every angle from 1e-12 to π, |ω_b| from 1e-12 to 1e3, to 1e-12 |ω_b|"""
    axes = np.random.default_rng(3100).normal(size=(len(ANGLES), 3))
    spins = np.random.default_rng(3101).normal(size=(len(SPINS), 3))
    for angle, axis, size, spin in zip(ANGLES, axes, SPINS, spins):
        R = Rotation.from_rotvec(angle * axis / np.linalg.norm(axis)).as_matrix()
        omega_b = size * spin / np.linalg.norm(spin)
        R_dot = R @ _skew(omega_b)
        got = expect_array(student.body_angular_velocity(R, R_dot), (3,), "body_angular_velocity(R, Ṙ)")
        error = np.max(np.abs(got - omega_b))
        expect(
            error <= 1e-12 * size,
            f"for a turn of {angle:.3g} rad spinning at {size:g} rad/s the body rate is "
            f"off by {error:.2g} (tolerance {1e-12 * size:.2g}): got {fmt(got, 6)}, expected {fmt(omega_b, 6)}",
            lambda: _hint(got, R, R_dot, omega_b),
        )


@exercise("body_angular_velocity", weight=1)
def test_body_rate_of_a_world_spin(student):
    """a spin at the world rate ω_w (Ṙ = [ω_w]× R) has the body rate Rᵀ ω_w, to 1e-12 (5 attitudes)"""
    for R, omega_w in zip(random_rotations(5, 3110), np.random.default_rng(3111).normal(size=(5, 3))):
        R_dot = _skew(omega_w) @ R
        got = expect_array(student.body_angular_velocity(R, R_dot), (3,), "body_angular_velocity(R, Ṙ)")
        expected = R.T @ omega_w
        expect(
            np.max(np.abs(got - expected)) <= 1e-12 * (1.0 + np.linalg.norm(omega_w)),
            f"for a world spin {fmt(omega_w)} rad/s got {fmt(got)}, expected Rᵀ ω_w = {fmt(expected)}",
            lambda: _hint(got, R, R_dot, expected),
        )


@exercise("body_angular_velocity", weight=1)
def test_body_rate_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    R = random_rotations(1, 3120)[0]
    expect_same_with_lists(
        student.body_angular_velocity, (R, R @ _skew([0.3, -1.2, 0.5])), (3,), "body_angular_velocity(R, Ṙ)"
    )
