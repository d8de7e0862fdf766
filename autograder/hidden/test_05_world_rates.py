"""Hidden checks for lesson 05, section 9: euler_rates_matrix_world.

Oracles: central differences of scipy's z-y-x Euler angles (ω_w from Ṙ Rᵀ, one rate at a time) and the
columns written out here (the yaw, pitch and roll axes in world coordinates: e_z, Rz(ψ) e_y, Rz(ψ) Ry(θ) e_x).
Core idea (3 of 5 points): each Euler axis is turned by the rotations to its left in Rz Ry Rx, for yaw and
pitch over the whole range, next to the lock and at angles from 1e-12 up, to 1e-12. Every test calls
euler_rates_matrix_world only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect, expect_array, expect_close

STATES = [
    (0.7, -0.4),
    (2.9, 1.2),
    (-3.0, -1.5),
    (1e-12, 1e-12),
    (1e-6, -1e-9),
    (0.3, np.pi / 2 - 1e-9),
    (-2.2, -np.pi / 2 + 1e-12),
    (np.pi, 0.5),
    (-1.1, np.pi / 2),
    (1e-3, 0.9),
]


def _rz(a):
    return Rotation.from_rotvec([0.0, 0.0, a]).as_matrix()


def _ry(a):
    return Rotation.from_rotvec([0.0, a, 0.0]).as_matrix()


def _world_rates(yaw, pitch):
    ex, ey, ez = np.eye(3)
    return np.column_stack([ez, _rz(yaw) @ ey, _rz(yaw) @ _ry(pitch) @ ex])


def _by_differences(yaw, pitch, roll, h=1e-6):
    def matrix(angles):
        return Rotation.from_euler("ZYX", angles).as_matrix()

    angles = np.array([yaw, pitch, roll])
    columns = []
    for e in np.eye(3):
        W = (matrix(angles + h * e) - matrix(angles - h * e)) / (2 * h) @ matrix(angles).T
        columns.append(0.5 * np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]))
    return np.column_stack(columns)


def _hint(got, yaw, pitch):
    ex, ey, ez = np.eye(3)
    truth = _world_rates(yaw, pitch)
    slips = [
        (
            np.column_stack([ez, _rz(yaw).T @ ey, _ry(pitch).T @ _rz(yaw).T @ ex]),
            "the pitch column disagrees with a finite difference of a pitch rate alone: it is what that difference "
            "gives at the opposite yaw",
        ),
        (
            np.column_stack([ez, _rz(yaw) @ ey, _rz(yaw) @ ex]),
            "the roll column disagrees with a finite difference of a roll rate alone: it is what that difference "
            "gives at pitch 0",
        ),
        (_world_rates(0.0, pitch), "your E_w is what the finite differences give at yaw 0, whatever the yaw"),
        (truth[:, ::-1], hints.COLUMNS_GO_ORDER_RATES_HINT),
    ]
    for candidate, hint in slips:
        if np.max(np.abs(candidate - truth)) > 1e-9 and explains(got, candidate, truth, floor=1e-13):
            return hint
    return (
        "E_w @ rates must be the world angular velocity: each rate alone spins about its own axis, written in "
        "world axes; compare one column at a time with a finite difference of a pure yaw, pitch or roll rate"
    )


@exercise("euler_rates_matrix_world", weight=3)
def test_world_rates_everywhere(student):
    """E_w @ rates is the world angular velocity, to 1e-12 for 10 states: generic, tiny angles, next to and at the lock"""
    for yaw, pitch in STATES:
        got = expect_array(
            student.euler_rates_matrix_world(yaw, pitch), (3, 3), f"euler_rates_matrix_world({yaw:.3g}, {pitch:.3g})"
        )
        expect_close(
            got,
            _world_rates(yaw, pitch),
            1e-12,
            f"E_w at yaw {yaw:.3g}, pitch {pitch:.3g}",
            lambda: _hint(got, yaw, pitch),
        )


@exercise("euler_rates_matrix_world", weight=1)
def test_world_rates_by_finite_differences(student):
    """E_w @ rates matches the world angular velocity of a moving attitude (central differences) to 1e-8, any roll"""
    for (yaw, pitch), roll in zip([(0.7, -0.4), (-2.5, 1.0), (1.9, 0.2)], (0.0, 2.2, -1.4)):
        got = expect_array(student.euler_rates_matrix_world(yaw, pitch), (3, 3), "euler_rates_matrix_world")
        expect_close(
            got,
            _by_differences(yaw, pitch, roll),
            1e-8,
            f"E_w against finite differences at yaw {yaw:g}, pitch {pitch:g}, roll {roll:g}",
            lambda: _hint(got, yaw, pitch),
        )


@exercise("euler_rates_matrix_world", weight=1)
def test_world_rates_singularity(student):
    """det E_w = -cos(pitch) (to 1e-12) for 7 pitches, and at the lock the yaw and roll columns are parallel"""
    for pitch in (-1.5, -0.7, 0.0, 0.4, 1.2, np.pi / 2 - 1e-6, np.pi / 2):
        got = expect_array(student.euler_rates_matrix_world(0.6, pitch), (3, 3), "euler_rates_matrix_world")
        expect(
            abs(np.linalg.det(got) + np.cos(pitch)) <= 1e-12,
            f"det E_w = {np.linalg.det(got):.9f} at pitch {pitch:.6g}, expected {-np.cos(pitch):.9f}",
            lambda: _hint(got, 0.6, pitch),
        )
    lock = expect_array(student.euler_rates_matrix_world(0.6, np.pi / 2), (3, 3), "euler_rates_matrix_world at lock")
    expect(
        np.linalg.norm(np.cross(lock[:, 0], lock[:, 2])) <= 1e-12,
        "at the lock the yaw and roll axes should be the same vertical line",
        lambda: _hint(lock, 0.6, np.pi / 2),
    )
