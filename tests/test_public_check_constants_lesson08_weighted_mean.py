"""The numbers stored in lesson 08's public checks of weighted_rotation_mean, recomputed from their definitions."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson08_weighted_mean as checks

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def exp(v):
    return Rotation.from_rotvec(v).as_matrix()


def log(R):
    return Rotation.from_matrix(R).as_rotvec()


def geodesic_mean(Rs, w, start=0, steps=200):
    M = Rs[start]
    for _ in range(steps):
        delta = sum(wi * log(M.T @ R) for wi, R in zip(w, Rs)) / np.sum(w)
        M = M @ exp(delta)
    return M


def test_the_slips():
    Rs, w = [exp(v) for v in checks.VECTORS], checks.WEIGHTS
    assert np.allclose(checks.UNWEIGHTED, geodesic_mean(Rs, np.ones(3)), atol=1e-14)
    U, _, Vt = np.linalg.svd(sum(wi * R for wi, R in zip(w, Rs)))
    assert np.allclose(
        checks.WEIGHTED_CHORDAL, U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt, atol=1e-14
    )
    one_step = geodesic_mean(Rs, w, steps=1)
    imbalance = np.linalg.norm(sum(wi * log(one_step.T @ R) for wi, R in zip(w, Rs))) / np.sum(w)
    assert abs(checks.ONE_STEP_IMBALANCE - imbalance) < 1e-15
    assert not hasattr(checks, "ONE_STEP")  # the step's result itself is not stored: it is the answer's first step
    assert np.allclose(checks.SQUARED_WEIGHTS, geodesic_mean(Rs, w**2), atol=1e-14)
    M = geodesic_mean(Rs, w)
    assert np.linalg.norm(sum(wi * log(M.T @ R) for wi, R in zip(w, Rs))) < 1e-13  # the answer balances
