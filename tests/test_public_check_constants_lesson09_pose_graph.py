"""The numbers stored in lesson 09's public checks of pose_graph_edge, recomputed from their definitions: the
answer's Jacobians both by central differences of the residual (as the checks once computed them) and in closed
form, J_j = J_r(r)⁻¹ and J_i = -J_r(r)⁻¹ Ad((T_i⁻¹ T_j)⁻¹), with coursekit.lie's JrSE3 and AdSE3."""

import numpy as np
import pytest

from coursekit.checks import lesson09_pose_graph as checks
from coursekit.lie import AdSE3, ExpSE3, JrSE3, LogSE3

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _residual(T_i, T_j, T_ij):
    return LogSE3(np.linalg.inv(T_ij) @ np.linalg.inv(T_i) @ T_j)


def _numeric(T_i, T_j, T_ij):
    """J_i and J_j by central differences of r(δ_i, δ_j) = Log(T_ij⁻¹ (T_i Exp(δ_i))⁻¹ T_j Exp(δ_j))."""
    J_i = _central(lambda d: _residual(T_i @ ExpSE3(d), T_j, T_ij), 6)
    J_j = _central(lambda d: _residual(T_i, T_j @ ExpSE3(d), T_ij), 6)
    return J_i, J_j


def _exact(T_i, T_j, T_ij):
    """r = Log(T_ij⁻¹ T_i⁻¹ T_j Exp(-Ad((T_i⁻¹ T_j)⁻¹) δ_i) Exp(δ_j)), through Log's Jacobian J_r(r)⁻¹."""
    between = np.linalg.inv(T_i) @ T_j
    inverse = np.linalg.inv(JrSE3(_residual(T_i, T_j, T_ij)))
    return -inverse @ AdSE3(np.linalg.inv(between)), inverse


def test_the_jacobians_at_the_large_edge():
    edge = checks.EDGE_T_I, checks.EDGE_T_J, checks.EDGE_T_IJ
    for stored, exact, numeric in zip((checks.EDGE_J_I, checks.EDGE_J_J), _exact(*edge), _numeric(*edge)):
        assert np.allclose(stored, exact, rtol=0, atol=1e-13)
        assert np.allclose(stored, numeric, rtol=0, atol=5e-9)  # central differences are good to 1e-9 here


def test_the_jacobians_at_the_consistent_edge():
    T_i, T_ij = checks.CONSISTENT_T_I, checks.CONSISTENT_T_IJ
    edge = T_i, T_i @ T_ij, T_ij
    assert np.allclose(_residual(*edge), 0.0, rtol=0, atol=1e-14)
    exact_i, exact_j = _exact(*edge)
    numeric_i, numeric_j = _numeric(*edge)
    assert np.allclose(checks.CONSISTENT_J_I, exact_i, rtol=0, atol=1e-13)
    assert np.allclose(checks.CONSISTENT_J_I, -AdSE3(np.linalg.inv(T_ij)), rtol=0, atol=1e-13)
    assert np.allclose(checks.CONSISTENT_J_I, numeric_i, rtol=0, atol=5e-9)
    assert np.allclose(np.eye(6), exact_j, rtol=0, atol=1e-13)  # the check's J_j at r = 0
    assert np.allclose(np.eye(6), numeric_j, rtol=0, atol=5e-9)


def test_the_edge_slips():
    T_i, T_j, T_ij = checks.EDGE_T_I, checks.EDGE_T_J, checks.EDGE_T_IJ
    between = np.linalg.inv(T_i) @ T_j
    r = LogSE3(np.linalg.inv(T_ij) @ between)
    assert np.allclose(r, checks.EDGE_RESIDUAL, rtol=0, atol=1e-12)
    Jr = JrSE3(r)
    assert np.allclose(checks.EDGE_I_SMALL_RESIDUAL, -AdSE3(np.linalg.inv(between)), rtol=0, atol=1e-12)
    assert np.allclose(checks.EDGE_I_ADJOINT_INVERTED, -np.linalg.solve(Jr, AdSE3(between)), rtol=0, atol=1e-12)
    assert np.allclose(
        checks.EDGE_I_MEASUREMENT_ADJOINT, -np.linalg.solve(Jr, AdSE3(np.linalg.inv(T_ij))), rtol=0, atol=1e-12
    )
    assert np.allclose(checks.EDGE_J_NOT_INVERTED, Jr, rtol=0, atol=1e-12)
    assert np.allclose(checks.EDGE_I_NOT_INVERTED, Jr @ checks.EDGE_I_SMALL_RESIDUAL, rtol=0, atol=1e-12)
