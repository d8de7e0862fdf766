"""Public checks for lesson 08, section 6: the weighted geodesic mean.

The checks use three rotations Exp(a_i) with fixed rotation vectors and weights (1, 2, 5), the defining balance
Σ w_i Log(Mᵀ R_i) = 0 (computed with scipy through ``coursekit.lie``), repetition (a weight of 2 is a sample
listed twice, watched on the student's own function) and the values the usual slips return for these data,
stored as numbers: three slips' means, and for a mean stopped after one step only the size of its imbalance
(``tests/test_public_check_constants_lesson08_weighted_mean.py`` recomputes them).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close, rotation_problem
from ..lie import Exp, Log
from .common import require_same_with_lists, require_shape

VECTORS = np.array([[0.3, -0.2, 0.5], [0.1, 0.4, 0.2], [-0.2, 0.1, 0.9]])
WEIGHTS = np.array([1.0, 2.0, 5.0])
UNWEIGHTED = np.array([[0.853621460389426, -0.507903511227956, 0.1156046090990188],
                       [0.5148403607236772, 0.8563973286349627, -0.0390258693281027],
                       [-0.079182102349822, 0.0928312382186804, 0.9925283652764032]])
WEIGHTED_CHORDAL = np.array([[0.7657326959842663, -0.634179606188924, 0.1070965237284974],
                             [0.6256514831788987, 0.7730767035278152, 0.104463544160684],
                             [-0.1490424768202373, -0.0129860523881931, 0.9887455196088935]])
# |Σ w_i Log(Mᵀ R_i)| / Σ w_i at the M that a single step from Rs[0] reaches (a size, not a rotation).
ONE_STEP_IMBALANCE = 0.0048893410814279704
SQUARED_WEIGHTS = np.array([[0.6927569252339351, -0.7182799743745537, 0.0645114017280181],
                            [0.7004734513463551, 0.6914544398558987, 0.1767136145363181],
                            [-0.171536545666947, -0.0772310560335385, 0.9821459043770412]])
IGNORES_HINT = "the weights were ignored: that is the plain geodesic mean; each Log(Mᵀ R_i) must count w_i times"
CHORDAL_HINT = ("that is the weighted chordal mean (the nearest rotation to Σ w_i R_i); the geodesic mean balances "
                "Σ w_i Log(Mᵀ R_i) = 0")
ONE_STEP_HINT = ("that is a single step from Rs[0]: the weighted residuals shrank from those at Rs[0] but do not "
                 "balance yet, and the mean balances them to about 1e-12")
SQUARED_HINT = "the weights were squared: a weight of 2 must count like the rotation listed twice, not four times"
SLIPS = [(UNWEIGHTED, IGNORES_HINT), (WEIGHTED_CHORDAL, CHORDAL_HINT), (SQUARED_WEIGHTS, SQUARED_HINT)]


def _rotations():
    return np.array([Exp(v) for v in VECTORS])


def _mean_of(function, Rs, weights, what):
    M = require_shape(function(Rs, weights), (3, 3), what)
    problem = rotation_problem(M)
    if problem:
        raise Mismatch(f"{what} is not a rotation: {problem}", "update with M ← M Exp(δ), which stays a rotation")
    return M


@public_check("weighted_rotation_mean", "the weighted residuals balance: Σ w_i Log(Mᵀ R_i) ≈ 0 for weights 1, 2, 5")
def _(weighted_rotation_mean):
    Rs = _rotations()
    M = _mean_of(weighted_rotation_mean, Rs, WEIGHTS, "weighted_rotation_mean(Rs, w)")
    imbalance = np.linalg.norm(sum(w * Log(M.T @ R) for w, R in zip(WEIGHTS, Rs))) / WEIGHTS.sum()
    if imbalance > 1e-9:
        one_step = abs(imbalance - ONE_STEP_IMBALANCE) < 1e-9
        raise Mismatch(f"|Σ w_i Log(Mᵀ R_i)| / Σ w_i = {imbalance:.2g}",
                       next((hint for value, hint in SLIPS if close(M, value, 1e-9)), None) or
                       (ONE_STEP_HINT if one_step else None) or
                       "at the weighted mean the weighted rotation vectors Log(Mᵀ R_i) balance out")


@public_check("weighted_rotation_mean", "a weight of 2 counts like the rotation listed twice; scaling all weights "
                                        "changes nothing")
def _(weighted_rotation_mean):
    Rs = _rotations()
    weighted = _mean_of(weighted_rotation_mean, Rs, [1.0, 2.0, 1.0], "weighted_rotation_mean(Rs, [1, 2, 1])")
    repeated = _mean_of(weighted_rotation_mean, np.array([Rs[0], Rs[1], Rs[1], Rs[2]]), [1.0, 1.0, 1.0, 1.0],
                        "weighted_rotation_mean of the list with R_2 twice")
    if not close(weighted, repeated, 1e-9):
        raise Mismatch(f"weight 2 and listing twice differ by {np.max(np.abs(weighted - repeated)):.2g}",
                       next((hint for value, hint in SLIPS if close(weighted, value, 1e-9)), None) or
                       "a weight of 2 must act exactly like a second copy of the rotation")
    scaled = _mean_of(weighted_rotation_mean, Rs, [1e-3, 2e-3, 1e-3], "weighted_rotation_mean(Rs, w / 1000)")
    if not close(scaled, weighted, 1e-9):
        raise Mismatch(f"dividing every weight by 1000 moved the mean by {np.max(np.abs(scaled - weighted)):.2g}",
                       hints.WEIGHT_RATIOS_HINT)


@public_check("weighted_rotation_mean", "accepts a list of rotations and a list of weights")
def _(weighted_rotation_mean):
    Rs = _rotations()
    require_same_with_lists(weighted_rotation_mean, (Rs, WEIGHTS), (3, 3), "weighted_rotation_mean(Rs, w)")


@public_check("weighted_rotation_mean", "generic weights 0.3, 1.7, 2.9: the weighted residuals balance to 1e-11 "
                                        "(float64 kept)")
def _(weighted_rotation_mean):
    Rs = _rotations()
    weights = np.array([0.3, 1.7, 2.9])
    M = _mean_of(weighted_rotation_mean, Rs, weights, "weighted_rotation_mean(Rs, [0.3, 1.7, 2.9])")
    imbalance = np.linalg.norm(sum(w * Log(M.T @ R) for w, R in zip(weights, Rs))) / weights.sum()
    if imbalance > 1e-11:
        raise Mismatch(f"|Σ w_i Log(Mᵀ R_i)| / Σ w_i = {imbalance:.2g} (tolerance 1e-11)",
                       "iterate until the step |δ| is below about 1e-12, with the weights in float64: the residuals "
                       "Log(Mᵀ R_i) are in M's body frame, so the step goes on the right, M ← M Exp(δ)")
