"""The stored literals of lesson 05's public checks match the definitions they stand for.

``coursekit/checks/lesson05.py`` is shipped to students, so it must not compute an exercise's answer (or the
answer one step away) to recognise a mistake. It stores the mistaken formulas' values at the checks' fixed inputs
instead; this test recomputes each literal from its definition, so a literal can never silently go stale.
The fixed matrices and quaternions at the lock are stored bit for bit (their rounding noise decides what a
formula without a lock branch returns), so they are compared with their definition to 1e-12 and every mistake's
value is recomputed from the stored input itself.
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson05 as checks
from coursekit.lie import Exp

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run

HALF_PI = np.pi / 2
SIGNS = (1.0, -1.0)


def assert_same(stored, computed, rtol=1e-12):
    stored, computed = np.asarray(stored, dtype=float), np.asarray(computed, dtype=float)
    assert stored.shape == computed.shape
    scale = max(1.0, float(np.max(np.abs(computed))))
    assert np.max(np.abs(stored - computed)) <= rtol * scale, f"stored {stored!r}, recomputed {computed!r}"


def rz_ry_rx(yaw, pitch, roll):
    """The definition: yaw about z, then pitch about the new y, then roll about the new x."""
    return Exp([0.0, 0.0, yaw]) @ Exp([0.0, pitch, 0.0]) @ Exp([roll, 0.0, 0.0])


def without_lock_branch(R):
    """Mistake: the general atan2 formulas of matrix_to_euler_zyx used at (and next to) the lock too."""
    return np.array(
        [np.arctan2(R[1, 0], R[0, 0]), np.arctan2(-R[2, 0], np.hypot(R[0, 0], R[1, 0])), np.arctan2(R[2, 1], R[2, 2])]
    )


def lecture_angles(q, normalise):
    """Mistake: the lecture's atan2/asin formulas for quat_to_euler_zyx (asin clipped), no lock branch."""
    q = np.asarray(q, dtype=float)
    w, x, y, z = q / np.linalg.norm(q) if normalise else q
    return np.array(
        [
            np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)),
            np.arcsin(np.clip(2 * (w * y - z * x), -1.0, 1.0)),
            np.arctan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y)),
        ]
    )


def all_plus_quat(yaw, pitch, roll):
    """Mistake: the z-y-x half-angle quaternion with every mixed product added (the minus signs lost)."""
    cy, sy, cp, sp, cr, sr = (f(a / 2) for a in (yaw, pitch, roll) for f in (np.cos, np.sin))
    return np.array(
        [
            cy * cp * cr + sy * sp * sr,
            cy * cp * sr + sy * sp * cr,
            cy * sp * cr + sy * cp * sr,
            sy * cp * cr + cy * sp * sr,
        ]
    )


def rates_matrix(pitch, roll):
    """The right E: columns e_z, e_y, e_x seen in the body, Rx(roll)ᵀ Ry(pitch)ᵀ e_z, Rx(roll)ᵀ e_y, e_x."""
    Rx, Ry = Exp([roll, 0.0, 0.0]), Exp([0.0, pitch, 0.0])
    return np.column_stack([Rx.T @ Ry.T @ [0.0, 0.0, 1.0], Rx.T @ [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])


@pytest.mark.parametrize("sign", SIGNS)
def test_lock_matrix_is_rz_ry_rx_at_the_lock(sign):
    assert_same(checks.LOCK_MATRIX[sign], rz_ry_rx(0.7, sign * HALF_PI, -0.4))


@pytest.mark.parametrize("sign", SIGNS)
def test_near_lock_matrix_is_scipys_zyx(sign):
    expected = Rotation.from_euler("ZYX", [2.2, sign * (HALF_PI - 1e-9), -0.9]).as_matrix()
    assert_same(checks.NEAR_LOCK_MATRIX[sign], expected)
    assert_same(checks.NEAR_LOCK_MATRIX[sign], rz_ry_rx(2.2, sign * (HALF_PI - 1e-9), -0.9))


@pytest.mark.parametrize("sign", SIGNS)
def test_no_lock_branch_angles_at_the_lock(sign):
    R = checks.LOCK_MATRIX[sign]
    assert_same(checks.NO_BRANCH_AT_LOCK[sign], without_lock_branch(R))
    # the check uses the same stored angles for R with R[2, 0] rounded a hair past ∓1
    rounded = checks._rounded_past_one(R, sign)
    assert abs(rounded[2, 0]) > 1.0 and np.array_equal(np.delete(rounded.ravel(), 6), np.delete(R.ravel(), 6))
    assert_same(checks.NO_BRANCH_AT_LOCK[sign], without_lock_branch(rounded))


@pytest.mark.parametrize("sign", SIGNS)
def test_slips_next_to_the_lock(sign):
    R = checks.NEAR_LOCK_MATRIX[sign]
    assert_same(checks.NO_BRANCH_NEAR_LOCK[sign], without_lock_branch(R))
    assert_same(checks.ASIN_PITCH_NEAR_LOCK[sign], np.arcsin(-R[2, 0]))


@pytest.mark.parametrize("sign", SIGNS)
def test_lock_quaternions_are_scipys_zyx(sign):
    at_lock = Rotation.from_euler("ZYX", [-1.9, sign * HALF_PI, 0.6]).as_quat(scalar_first=True)
    near = Rotation.from_euler("ZYX", [0.5, sign * (HALF_PI - 1e-9), 2.6]).as_quat(scalar_first=True)
    assert_same(checks.QUAT_AT_LOCK[sign], at_lock)
    assert_same(checks.QUAT_NEAR_LOCK[sign], near)


@pytest.mark.parametrize("sign", SIGNS)
def test_lecture_angles_at_and_next_to_the_lock(sign):
    for stored, q in (
        (checks.LECTURE_AT_LOCK[sign], checks.QUAT_AT_LOCK[sign]),
        (checks.LECTURE_NEAR_LOCK[sign], checks.QUAT_NEAR_LOCK[sign]),
    ):
        assert len(stored) == len(checks.NORMS_OF_A_UNIT_QUATERNION)
        for angles, norm in zip(stored, checks.NORMS_OF_A_UNIT_QUATERNION):
            assert_same(angles, lecture_angles(q / norm, normalise=False))


@pytest.mark.parametrize("sign", SIGNS)
def test_this_machines_lecture_angles_are_among_the_stored(sign):
    """Whatever kernel computes |q| here, the slip a student makes on this machine is recognised by the hint."""
    for stored, q in (
        (checks.LECTURE_AT_LOCK[sign], checks.QUAT_AT_LOCK[sign]),
        (checks.LECTURE_NEAR_LOCK[sign], checks.QUAT_NEAR_LOCK[sign]),
    ):
        assert np.linalg.norm(q) in checks.NORMS_OF_A_UNIT_QUATERNION
        here = lecture_angles(q, normalise=True)
        assert min(np.max(np.abs(here - angles)) for angles in stored) <= 1e-12, f"{here!r} is not stored"


def test_all_plus_quaternions_at_the_checks_angles():
    assert sorted(checks.ALL_PLUS_QUAT) == sorted([(0.3, -0.4, 1.1), (0.9, -0.5, 1.3), (-2.4, 1.1, 0.2)])
    for angles, stored in checks.ALL_PLUS_QUAT.items():
        assert_same(stored, all_plus_quat(*angles))


def test_rates_matrix_mistakes_each_get_their_hint_at_the_finite_difference_attitude():
    """Each slip, written out here by its formula, is told apart by what the finite differences give instead."""
    pitch, roll = 0.7, -1.1
    E = rates_matrix(pitch, roll)
    assert np.allclose(checks._body_rates_by_differences(pitch, roll), E, atol=1e-9)
    Rx, Ry = Exp([roll, 0.0, 0.0]), Exp([0.0, pitch, 0.0])  # Rx(roll) where Rx(roll)ᵀ belongs
    flipped = np.column_stack([Rx @ Ry.T @ [0.0, 0.0, 1.0], Rx @ [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])
    found = [checks._rates_slip_hint(slip, pitch, roll) for slip in (E[:, ::-1], flipped, E.T, np.eye(3))]
    assert None not in found and len(set(found)) == 4, found
    assert checks._rates_slip_hint(E, pitch, roll) is None


def test_the_oracle_is_rz_ry_rx():
    """The check's rebuild (scipy's intrinsic 'ZYX') agrees with the product of elementary rotations."""
    for angles in [(0.9, -0.5, 1.3), (-2.4, 1.1, 0.2), (0.4 + np.pi, np.pi - 0.3, -0.6 + np.pi), (7.0, 2.9, -4.0)]:
        assert_same(checks._zyx(*angles), rz_ry_rx(*angles))
