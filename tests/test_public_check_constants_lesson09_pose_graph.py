"""The numbers stored in lesson 09's public checks of pose_graph_edge, recomputed from their definitions."""

import numpy as np
import pytest

from coursekit.checks import lesson09_pose_graph as checks
from coursekit.lie import AdSE3, JrSE3, LogSE3

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def test_the_edge_slips():
    T_i, T_j, T_ij = checks.EDGE_T_I, checks.EDGE_T_J, checks.EDGE_T_IJ
    between = np.linalg.inv(T_i) @ T_j
    r = LogSE3(np.linalg.inv(T_ij) @ between)
    assert np.allclose(r, checks.EDGE_RESIDUAL, rtol=0, atol=1e-12)
    Jr = JrSE3(r)
    assert np.allclose(checks.EDGE_I_NO_JR, -AdSE3(np.linalg.inv(between)), rtol=0, atol=1e-12)
    assert np.allclose(checks.EDGE_I_ADJOINT_INVERTED, -np.linalg.solve(Jr, AdSE3(between)), rtol=0, atol=1e-12)
    assert np.allclose(
        checks.EDGE_I_MEASUREMENT_ADJOINT, -np.linalg.solve(Jr, AdSE3(np.linalg.inv(T_ij))), rtol=0, atol=1e-12
    )
    assert np.allclose(checks.EDGE_J_NOT_INVERTED, Jr, rtol=0, atol=1e-12)
