"""The exact Jacobians that lesson 09's hidden pose_graph_edge checks compare with, held against their
definition: central differences of r(δ_i, δ_j) = Log(T_ij⁻¹ (T_i Exp(δ_i))⁻¹ T_j Exp(δ_j)), on every edge the
checks draw. And the bar they set (EXACT) is one that central differences do not reach, on any of those edges."""

import numpy as np
import pytest

from autograder.hidden import test_09_pose_graph as edge
from coursekit.lie import ExpSE3

pytestmark = pytest.mark.blas_sensitive


def _central(f, n=6, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _numeric(T_i, T_j, T_ij):
    J_i = _central(lambda d: edge._residual(T_i @ ExpSE3(d), T_j, T_ij))
    J_j = _central(lambda d: edge._residual(T_i, T_j @ ExpSE3(d), T_ij))
    return J_i, J_j


@pytest.mark.parametrize("seed", [9410, 9420])
def test_the_exact_jacobians_are_the_derivatives_of_the_residual(seed):
    for T_i, T_j, T_ij, _ in edge._edges(seed):
        scale = edge._scale(T_i, T_j, T_ij)
        for exact, numeric in zip(edge.exact_jacobians(T_i, T_j, T_ij), _numeric(T_i, T_j, T_ij)):
            assert np.max(np.abs(exact - numeric)) < 1e-8 * scale


@pytest.mark.parametrize("seed", [9410, 9420])
def test_central_differences_miss_the_bar_on_every_edge(seed):
    for T_i, T_j, T_ij, _ in edge._edges(seed):
        scale = edge._scale(T_i, T_j, T_ij)
        for exact, numeric in zip(edge.exact_jacobians(T_i, T_j, T_ij), _numeric(T_i, T_j, T_ij)):
            assert np.max(np.abs(exact - numeric)) > edge.EXACT * scale


def _update_cases():
    from autograder.hidden import test_09_update as update

    for seed in (9200, 9210):
        yield from update._update_cases(seed)


def test_the_measurement_jacobian_is_the_derivative_of_the_prediction():
    from autograder.hidden import test_09_update as update

    for R, _, _, g_w, _ in _update_cases():
        numeric = _central(lambda e: (R @ update._exp(e)).T @ g_w, 3)
        assert np.max(np.abs(update.measurement_jacobian(R, g_w) - numeric)) < 1e-8 * np.linalg.norm(g_w)


@pytest.mark.parametrize("seed, part", [(9200, 0), (9210, 1)])  # the seeds of the step's test and of P_new's
def test_an_update_with_a_numerical_jacobian_misses_the_bar(seed, part):
    from autograder.hidden import test_09_update as update

    misses = 0
    for R, P, y, g_w, Rn in update._update_cases(seed):
        truth = update._map(R, P, y, g_w, Rn)[part]
        H = _central(lambda e: (R @ update._exp(e)).T @ g_w, 3)
        information = np.linalg.inv(P) + H.T @ np.linalg.solve(Rn, H)
        numeric = (np.linalg.solve(information, H.T @ np.linalg.solve(Rn, y - R.T @ g_w)), np.linalg.inv(information))
        misses += np.max(np.abs(numeric[part] - truth)) > update.EXACT * max(1e-6, np.max(np.abs(truth)))
    assert misses >= 2


def test_the_exact_compound_covariance_is_the_linearised_one():
    from autograder.hidden import test_09_compound as compound

    for _, T1, S1, T2, S2 in compound.compound_cases():
        exact = compound.exact_covariance(T1, S1, T2, S2)
        numeric, _ = compound._linearised(T1, S1, T2, S2)
        assert np.max(np.abs(exact - numeric)) < 1e-8 * np.max(np.abs(exact))


def test_a_compound_covariance_by_central_differences_misses_the_bar():
    from autograder.hidden import test_09_compound as compound

    misses = 0
    for _, T1, S1, T2, S2 in compound.compound_cases():
        exact = compound.exact_covariance(T1, S1, T2, S2)
        numeric, _ = compound._linearised(T1, S1, T2, S2)
        misses += np.max(np.abs(exact - numeric)) > compound.EXACT * np.max(np.abs(exact))
    assert misses >= 2


def test_the_exact_predicted_covariance_is_the_linearised_one():
    from autograder.hidden import test_09_filter as filters

    for R, P, omega, dt, Q in filters._predict_cases(9100):
        exact = filters.exact_predict_covariance(R, P, omega, dt, Q)
        F, G = filters._predict_jacobians(R, omega, dt)
        assert np.max(np.abs(exact - (F @ P @ F.T + G @ Q @ G.T))) < 1e-8 * np.max(np.abs(exact))


def test_a_prediction_by_central_differences_misses_the_bar():
    from autograder.hidden import test_09_filter as filters

    misses = 0
    for R, P, omega, dt, Q in filters._predict_cases(9100):
        exact = filters.exact_predict_covariance(R, P, omega, dt, Q)
        F, G = filters._predict_jacobians(R, omega, dt)
        misses += np.max(np.abs(exact - (F @ P @ F.T + G @ Q @ G.T))) > filters.EXACT * np.max(np.abs(exact))
    assert misses >= 2
