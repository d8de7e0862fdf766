"""The numbers stored in lesson 05's public checks of euler_rates_matrix_world, recomputed from their definitions."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson05_world_rates as checks

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def rz(a):
    return Rotation.from_rotvec([0.0, 0.0, a]).as_matrix()


def ry(a):
    return Rotation.from_rotvec([0.0, a, 0.0]).as_matrix()


def world_rates(yaw, pitch):
    ex, ey, ez = np.eye(3)
    return np.column_stack([ez, rz(yaw) @ ey, rz(yaw) @ ry(pitch) @ ex])


def test_the_answer_matches_finite_differences():
    assert np.allclose(
        world_rates(checks.YAW, checks.PITCH),
        checks._world_rates_by_differences(checks.YAW, checks.PITCH, 0.4),
        atol=1e-8,
    )


def test_each_slip_gets_its_hint():
    """Each slip, written out here by its formula, is told apart by what the finite differences give instead."""
    ex, ey, ez = np.eye(3)
    y, p = checks.YAW, checks.PITCH
    slips = {
        checks.TRANSPOSED_HINT: np.column_stack([ez, rz(y).T @ ey, ry(p).T @ rz(y).T @ ex]),
        checks.ROLL_UNPITCHED_HINT: np.column_stack([ez, rz(y) @ ey, rz(y) @ ex]),
        checks.IGNORES_YAW_HINT: world_rates(0.0, p),
        checks.REVERSED_HINT: world_rates(y, p)[:, ::-1],
    }
    for roll in (0.0, 1.2):
        for hint, slip in slips.items():
            assert checks._slip_hint(slip, roll) == hint
        assert checks._slip_hint(world_rates(y, p), roll) is None
