"""The numbers stored in the public checks of lesson 07, recomputed from each slip's definition.

The public checks are shipped to students, so they carry the exponential map and the usual slips at their
fixed inputs as literals instead of the formulas. This test recomputes every literal (from the definitions
and, for poses, also from scipy's expm of the 4×4 twist matrix) and requires agreement to about 1e-12.
"""

import numpy as np
import pytest
from scipy.linalg import expm

from coursekit.checks import lesson07 as checks
from coursekit.lie import Exp, Log, skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run

TQ, TX = checks.T_QUARTER, checks.T_QUARTER_X


def same(stored, computed, rel=1e-12):
    stored, computed = np.asarray(stored, dtype=float), np.asarray(computed, dtype=float)
    assert stored.shape == computed.shape
    assert np.max(np.abs(stored - computed)) <= rel * max(1.0, np.max(np.abs(computed))), (stored, computed)


def pose(R, t):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, t
    return T


def twist_matrix(xi):
    T = np.zeros((4, 4))
    T[:3, :3], T[:3, 3] = skew(xi[3:]), xi[:3]
    return T


def V(phi):
    theta, W = np.linalg.norm(phi), skew(phi)
    if theta < 1e-2:
        b, c = 0.5 - theta**2 / 24 + theta**4 / 720, 1 / 6 - theta**2 / 120 + theta**4 / 5040
    else:
        b, c = (1 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
    return np.eye(3) + b * W + c * W @ W


def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    return pose(Exp(xi[3:]), V(xi[3:]) @ xi[:3])


def mirrored(xi):
    return np.concatenate([xi[3:], xi[:3]])


def test_hand_written_poses():
    same(TQ, pose(checks.QUARTER_TURN_Z, checks.SHIFT))
    same(TX, pose(Exp([np.pi / 2, 0.0, 0.0]), [0.0, -1.0, 0.5]))


def test_exp_of_the_quarter_twist_and_its_mirror():
    xi = np.array([1.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])
    same(pose(checks.QUARTER_TURN_Z, [2 / np.pi, 2 / np.pi, 0.0]), exp_se3(xi))
    same(pose(checks.QUARTER_TURN_Z, [2 / np.pi, 2 / np.pi, 0.0]), expm(twist_matrix(xi)))
    same(checks.EXP_MIRRORED_QUARTER, exp_se3(mirrored(xi)))
    same(checks.EXP_MIRRORED_QUARTER, expm(twist_matrix(mirrored(xi))))


@pytest.mark.parametrize("angle", [1e-9, 1e-6])
def test_exp_of_the_tiny_twists_and_their_mirrors(angle):
    xi = np.concatenate(checks._tiny_twist(angle))
    same(checks.EXP_TINY[angle], exp_se3(xi), 1e-15)
    same(checks.EXP_TINY[angle], expm(twist_matrix(xi)))
    same(checks.EXP_TINY_MIRRORED[angle], exp_se3(mirrored(xi)))
    same(checks.EXP_TINY_MIRRORED[angle], expm(twist_matrix(mirrored(xi))))


@pytest.mark.parametrize("theta", checks.DECADE_ANGLES)
def test_the_translations_at_every_decade(theta):
    """exp_se3's translation at [RHO_DECADES, θ u]: V's series (θ < 1e-2) or closed form, and expm of the twist."""
    phi = theta * checks.DECADE_AXIS
    xi = np.concatenate([checks.RHO_DECADES, phi])
    same(checks.TRANSLATION_AT_DECADES[theta], V(phi) @ checks.RHO_DECADES, 1e-14)
    same(checks.TRANSLATION_AT_DECADES[theta], expm(twist_matrix(xi))[:3, 3], 1e-13)
    assert set(checks.TRANSLATION_AT_DECADES) == set(checks.DECADE_ANGLES)


@pytest.mark.parametrize("name", ["T_QUARTER", "T_QUARTER_X"])
def test_logs_of_the_hand_written_poses(name):
    T = getattr(checks, name)
    xi = checks.LOG_T_QUARTER if name == "T_QUARTER" else checks.LOG_T_QUARTER_X
    phi = Log(T[:3, :3])
    same(xi, np.concatenate([np.linalg.solve(V(phi), T[:3, 3]), phi]))
    same(expm(twist_matrix(xi)), T)
    W = skew(phi)
    same(checks.RHO_C_CONSTANT[name], (np.eye(3) - 0.5 * W + W @ W / 12.0) @ T[:3, 3])
    assert np.max(np.abs(checks.RHO_C_CONSTANT[name] - xi[:3])) > 1e-3  # the slip is not the answer


def test_make_pose_transposed_block():
    same(checks.MAKE_POSE_R_TRANSPOSED, pose(checks.QUARTER_TURN_Z.T, checks.SHIFT))
    bottom_row = np.eye(4)
    bottom_row[:3, :3], bottom_row[3, :3] = checks.QUARTER_TURN_Z, checks.SHIFT
    same(checks.MAKE_POSE_T_IN_BOTTOM_ROW, bottom_row)


def test_pose_compose_slips():
    A, B = TQ, TX
    added = A @ B
    added[:3, 3] = A[:3, 3] + B[:3, 3]
    for (value, *_), computed in zip(checks.COMPOSE_SLIPS, [B @ A, A * B, added, A.T @ B]):
        same(value, computed)


@pytest.mark.parametrize("T", [TQ, TX])
def test_pose_inverse_slips_are_told_by_their_blocks(T):
    """Each slip, written by its formula, gets its own reason; the true inverse gets none (no inverse is stored)."""
    R, t = T[:3, :3], T[:3, 3]
    told = {
        "-t": checks._inverse_mistake(pose(R.T, -t), T),
        "t": checks._inverse_mistake(pose(R.T, t), T),
        "R kept": checks._inverse_mistake(pose(R, -R @ t), T),
        "transpose": checks._inverse_mistake(T.T, T),
    }
    assert all(told.values()) and len({reason for reason, _ in told.values()}) == len(told), told
    assert checks._inverse_mistake(np.linalg.inv(T), T) is None
    assert not any(name.startswith("INVERSE_SLIPS") for name in vars(checks))


def test_transform_points_slips():
    P = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 2.0, -1.0]])
    R, t = TQ[:3, :3], TQ[:3, 3]
    moved = np.concatenate([P, np.ones((3, 1))], axis=-1) @ TQ
    computed = [P @ R.T, P @ R + t, moved[:, :3], moved[:, :3] / moved[:, 3:], (P + t) @ R.T]
    for (value, *_), c in zip(checks.TRANSFORM_SLIPS, computed):
        same(value, c)
    assert len(checks.TRANSFORM_SLIPS) == len(computed)
    same(checks.COLUMNS_SLIP[0], R @ P + t[:, None])


def test_homogeneous_slips():
    for P_h, slips in (
        (np.array([2.0, 4.0, 6.0, 2.0]), checks.DEHOMOGENEOUS_SLIPS_ONE),
        (
            np.array([[2.0, 4.0, 6.0, 2.0], [1.0, -1.0, 0.5, 0.5], [3.0, 0.0, 0.0, 1.0]]),
            checks.DEHOMOGENEOUS_SLIPS_ROWS,
        ),
    ):
        computed = [P_h[..., :3], P_h[..., 1:] / P_h[..., :1], P_h[..., :3] * P_h[..., 3:]]
        for (value, _), c in zip(slips, computed):
            same(value, c)
