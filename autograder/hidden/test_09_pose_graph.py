"""Hidden checks for lesson 09, section 7: pose_graph_edge.

r = Log(T_ij⁻¹ T_i⁻¹ T_j) (twists [ρ, φ]) and the Jacobians of r with respect to right perturbations of T_i and T_j.
Oracles: coursekit.lie's LogSE3 for r; for the Jacobians, the exact ones built from coursekit.lie's matrix
exponentials (JrSE3 and AdSE3, no closed form written out), which tests/test_hidden_oracles_lesson09.py holds
against central differences of the definition. Any exact derivation passes; the docstring promises exact Jacobians,
and the lesson's central differences (good to about 1e-10 here) do not pass (values alone cannot tell an accurate
numerical Jacobian from an exact one: a high-order stencil with a tuned step (8th order, h = 0.02) reaches about
1e-13 and passes). Residual angles |φ| at every decade from 1e-12 to 3 rad (short of π, where Log jumps),
translations from 1 mm to 10 m; r to 1e-9 (1 + |ρ|), the Jacobians to 1e-11 (1 + the largest translation).
Core idea (4 of 6 points): both Jacobians hold at large residuals, where Log's Jacobian J_r(r)⁻¹ is not I.
Every test calls pose_graph_edge only.
"""

import numpy as np
from coursekit import hints
from coursekit.lie import AdSE3, ExpSE3, JrSE3, LogSE3

from .helpers import Wrong, exercise, expect_array, expect_close, expect_same_with_lists

ANGLES = (1.7, 2.5, 1e-12, 1e-9, 1e-6, 1e-3, 1e-2, 0.1, 1.0, 3.0)
SHIFTS = (2.0, 5.0, 1e-3, 0.5, 1.0, 10.0, 0.01, 3.0, 0.2, 1.5)


def _unit(rng):
    v = rng.normal(size=3)
    return v / np.linalg.norm(v)


def _edges(seed):
    rng = np.random.default_rng(seed)
    for angle, shift in zip(ANGLES, SHIFTS):
        T_i = ExpSE3(np.concatenate([3.0 * rng.normal(size=3), rng.uniform(0.2, 2.5) * _unit(rng)]))
        T_ij = ExpSE3(np.concatenate([shift * _unit(rng), rng.uniform(0.1, 2.0) * _unit(rng)]))
        residual = np.concatenate([shift * _unit(rng), angle * _unit(rng)])
        yield T_i, T_i @ T_ij @ ExpSE3(residual), T_ij, residual


def _triple(value):
    if not isinstance(value, (tuple, list)) or len(value) != 3:
        raise Wrong(
            f"pose_graph_edge returned {type(value).__name__}, not a triple (r, J_i, J_j)",
            "return all three: r, J_i, J_j",
        )
    return (
        expect_array(value[0], (6,), "pose_graph_edge's r"),
        expect_array(value[1], (6, 6), "J_i"),
        expect_array(value[2], (6, 6), "J_j"),
    )


def _residual(T_i, T_j, T_ij):
    return LogSE3(np.linalg.inv(T_ij) @ np.linalg.inv(T_i) @ T_j)


def exact_jacobians(T_i, T_j, T_ij):
    """(J_i, J_j) of the edge, exact: Log's Jacobian J_r(r)⁻¹, and δ_i carried across T_i⁻¹ T_j by the adjoint."""
    between = np.linalg.inv(T_i) @ T_j
    Jr_inv = np.linalg.inv(JrSE3(_residual(T_i, T_j, T_ij)))
    return -Jr_inv @ AdSE3(np.linalg.inv(between)), Jr_inv


EXACT = 1e-11  # relative to 1 + the largest translation; central differences stay above 3e-11 on every edge
FINITE_DIFFERENCES_HINT = hints.EDGE_FINITE_DIFFERENCES_HINT


def _scale(T_i, T_j, T_ij):
    return 1.0 + max(np.linalg.norm(T[:3, 3]) for T in (T_i, T_j, T_ij))


def _slip(got, candidates, truth, tol):
    for candidate, hint in candidates:
        if np.max(np.abs(candidate - truth)) > 10 * tol and np.max(np.abs(got - candidate)) <= tol:
            return hint
    return ""


NO_JR = hints.EDGE_SMALL_RESIDUAL_HINT
NOT_INVERTED = hints.EDGE_NOT_INVERTED_HINT


@exercise("pose_graph_edge", weight=1)
def test_edge_residual(student):
    """r = Log(T_ij⁻¹ T_i⁻¹ T_j) to 1e-9 (1 + |ρ|) for residuals from 1e-12 to 3 rad"""
    for T_i, T_j, T_ij, residual in _edges(9400):
        r, _, _ = _triple(student.pose_graph_edge(T_i, T_j, T_ij))
        hint = "that is the residual of the reversed edge, -r" if np.max(np.abs(r + residual)) < 1e-8 else ""
        expect_close(
            r,
            residual,
            1e-9,
            f"r for a residual of {np.linalg.norm(residual[3:]):.3g} rad",
            hint,
            scale=1.0 + np.linalg.norm(residual[:3]),
        )


@exercise("pose_graph_edge", weight=2)
def test_edge_jacobian_j(student):
    """J_j is the exact Jacobian to 1e-11 (1 + the largest translation), for residuals from 1e-12 to 3 rad"""
    for T_i, T_j, T_ij, residual in _edges(9410):
        _, _, J_j = _triple(student.pose_graph_edge(T_i, T_j, T_ij))
        truth = exact_jacobians(T_i, T_j, T_ij)[1]
        scale = _scale(T_i, T_j, T_ij)
        hint = _slip(J_j, [(np.eye(6), NO_JR), (JrSE3(residual), NOT_INVERTED)], truth, 1e-6 * scale)
        if not hint and np.max(np.abs(J_j - truth)) <= 1e-6 * scale:
            hint = FINITE_DIFFERENCES_HINT
        expect_close(
            J_j, truth, EXACT, f"J_j at a residual of {np.linalg.norm(residual[3:]):.3g} rad", hint, scale=scale
        )


@exercise("pose_graph_edge", weight=2)
def test_edge_jacobian_i(student):
    """J_i is the exact Jacobian to 1e-11 (1 + the largest translation), for residuals from 1e-12 to 3 rad"""
    for T_i, T_j, T_ij, residual in _edges(9420):
        _, J_i, _ = _triple(student.pose_graph_edge(T_i, T_j, T_ij))
        truth = exact_jacobians(T_i, T_j, T_ij)[0]
        scale = _scale(T_i, T_j, T_ij)
        between = np.linalg.inv(T_i) @ T_j
        Jr, Jr_inv = JrSE3(residual), np.linalg.inv(JrSE3(residual))
        candidates = [
            (-AdSE3(np.linalg.inv(between)), NO_JR),
            (-Jr_inv @ AdSE3(between), "the adjoint is of the wrong pose, or inverted"),
            (
                -Jr_inv @ AdSE3(np.linalg.inv(T_ij)),
                "J_i is right at r = 0 but not at this residual, while J_j is right at both",
            ),
            (-truth, hints.EDGE_SIGN_HINT),
            (-Jr @ AdSE3(np.linalg.inv(between)), NOT_INVERTED),
        ]
        hint = _slip(J_i, candidates, truth, 1e-6 * scale)
        if not hint and np.max(np.abs(J_i - truth)) <= 1e-6 * scale:
            hint = FINITE_DIFFERENCES_HINT
        expect_close(
            J_i, truth, EXACT, f"J_i at a residual of {np.linalg.norm(residual[3:]):.3g} rad", hint, scale=scale
        )


@exercise("pose_graph_edge", weight=1)
def test_edge_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    T_i, T_j, T_ij, _ = next(_edges(9430))

    def flat(*args):
        r, J_i, J_j = student.pose_graph_edge(*args)
        return np.vstack([np.reshape(r, (1, 6)), J_i, J_j])

    expect_same_with_lists(flat, (T_i, T_j, T_ij), (13, 6), "pose_graph_edge(T_i, T_j, T_ij)")
