"""Public checks for lesson 09, section 6: the attitude filter's update with a measured direction.

The error state is the right perturbation, R_true = R Exp(ε). The update is compared, at the checks' fixed inputs,
with numbers stored here: the minimiser of its linearised MAP cost and the inverse of half its Hessian there, and the steps the
usual slips take there (all recomputed by ``tests/test_public_check_constants_lesson09_update.py``, from the
definition by central differences of (R Exp(ε))ᵀ g_w and in closed form). Nothing here computes an update for
other inputs; the remaining checks test properties (no innovation, no correction) and the accepted argument types.
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import Exp, Log
from .common import off_by, require_same_with_lists, require_shape

QUARTER_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
P0 = np.array([[4.0, 1.0, 0.0], [1.0, 3.0, -1.0], [0.0, -1.0, 2.0]]) * 1e-3
GRAVITY_W = np.array([0.0, 0.0, 9.80665])
Y_ACCEL = np.array([0.5, 9.6, -0.8])
R_NOISE = np.array([[4.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 1.0]]) * 1e-2

# The answer of filter_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE): its step Log(Rᵀ R_new) and its P_new, the
# minimiser of the linearised MAP cost and the inverse of half its Hessian.
UPDATE_STEP = np.array([0.07951038259168972, -0.006147640176339278, 0.05205047164852342])
UPDATE_P_NEW = np.array(
    [
        [0.00010134753278603005, 2.5336883196507505e-05, 0.0],
        [2.5336883196507512e-05, 0.0023333111753493334, -0.00015395390910041487],
        [0.0, -0.0001539539091004149, 0.00030790781820082985],
    ]
)

# A generic attitude, where every entry of R and of the measurement Jacobian carries rounding, and the answer there:
# filter_update(Exp(UPDATE_GENERIC_ROTATION), P0, UPDATE_GENERIC_Y, GRAVITY_W, R_NOISE) turns by UPDATE_GENERIC_STEP.
UPDATE_GENERIC_ROTATION = np.array([0.4, -1.1, 2.0])
UPDATE_GENERIC_Y = np.array([1.2, -2.9, 9.1])
UPDATE_GENERIC_STEP = np.array([0.3570486100400298, 0.3632161898041903, -0.008786095858571083])
UPDATE_GENERIC_P_NEW = np.array(
    [
        [0.0011686654270208936, -0.000995710067617639, 0.0009428145712758859],
        [-0.0009957100676176393, 0.0010643805823109568, -0.0008575440226116048],
        [0.0009428145712758859, -0.0008575440226116048, 0.001170670911789379],
    ]
)

# The step Log(Rᵀ R_new) that the usual slips take in filter_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE).
UPDATE_SIGN_STEP = np.array([-0.07951038259168974, 0.006147640176339267, -0.0520504716485234])
UPDATE_NO_R_STEP = np.array([-0.022168626738025207, -0.04519060476755945, 0.0144176174847466])
UPDATE_LEFT_STEP = np.array([0.07884941040238526, -0.05202786526636899, 0.02608735195162375])
SIGN_HINT = hints.UPDATE_SIGN_HINT
NO_R_HINT = "the measurement Jacobian must depend on the attitude R: the body sees g_w through Rᵀ"
LEFT_JACOBIAN_HINT = (
    "that measurement Jacobian belongs to a left (world-frame) error; this filter's error is on the right, R Exp(ε)"
)
LEFT_UPDATE_HINT = hints.UPDATE_WRONG_SIDE_HINT
UPDATE_SLIPS = [(UPDATE_SIGN_STEP, SIGN_HINT), (UPDATE_NO_R_STEP, NO_R_HINT), (UPDATE_LEFT_STEP, LEFT_JACOBIAN_HINT)]
EXACT = 1e-11  # relative, as the hidden checks hold it: H derived (to rounding), not taken by differences
P_UNCHANGED_HINT = "a measurement adds information: the covariance must shrink along the directions it sees"


def _as_tuples(args):
    """The plain lists among ``args`` as nested tuples (array_like, as the docstring allows); arrays kept."""

    def tuples(a):
        return tuple(tuples(x) for x in a) if isinstance(a, list) else a

    return [tuples(a) for a in args]


def _pair(value, what):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Mismatch(
            f"{what} returned {type(value).__name__}, not a pair (R_new, P_new)", "return both: R_new, P_new"
        )
    return (require_shape(value[0], (3, 3), f"{what}'s R_new"), require_shape(value[1], (3, 3), f"{what}'s P_new"))


# ---------------------------------------------------------------- filter_update
@public_check("filter_update", "the correction minimises the linearised MAP cost, applied on the right")
def _(filter_update):
    R_new, _ = _pair(filter_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE), "filter_update")
    step = UPDATE_STEP
    got = Log(QUARTER_X.T @ R_new)
    if not close(got, step, EXACT * np.max(np.abs(step))):  # relative: the stored digits are BLAS's, good to 1e-15
        hint = next((h for value, h in UPDATE_SLIPS if close(got, value, 1e-8)), None)
        if hint is None and close(Log(R_new @ QUARTER_X.T), step, 1e-8):
            hint = LEFT_UPDATE_HINT
        if hint is None and close(got, step, 1e-7 * np.max(np.abs(step))):
            hint = hints.UPDATE_FINITE_DIFFERENCES_HINT
        raise Mismatch(
            f"the correction Log(Rᵀ R_new) is not the minimiser of the MAP cost ({off_by(got, step)})",
            hint or "linearise the predicted measurement in ε, then minimise the two weighted squares",
        )


@public_check("filter_update", "P_new is the inverse of half the Hessian of the linearised MAP cost")
def _(filter_update):
    _, P_new = _pair(filter_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE), "filter_update")
    expected = UPDATE_P_NEW
    if not close(P_new, expected, EXACT * np.max(np.abs(expected))):
        raise Mismatch(
            f"P_new disagrees with the inverse of half the Hessian ({off_by(P_new, expected)})",
            P_UNCHANGED_HINT
            if close(P_new, P0, 1e-15)
            else hints.UPDATE_FINITE_DIFFERENCES_HINT
            if close(P_new, expected, 1e-7 * np.max(np.abs(expected)))
            else "P_new⁻¹ = P⁻¹ + (information the measurement adds); check H and the gain",
        )


@public_check("filter_update", "exact to rounding at a generic attitude: the correction and P_new to 1e-11 relative")
def _(filter_update):
    R = Exp(UPDATE_GENERIC_ROTATION)
    R_new, P_new = _pair(filter_update(R, P0, UPDATE_GENERIC_Y, GRAVITY_W, R_NOISE), "filter_update")
    got = Log(R.T @ R_new)
    for name, value, expected in (("the correction", got, UPDATE_GENERIC_STEP), ("P_new", P_new, UPDATE_GENERIC_P_NEW)):
        scale = np.max(np.abs(expected))
        if not close(value, expected, EXACT * scale):
            raise Mismatch(
                f"{name} at a generic attitude is off ({off_by(value, expected)})",
                hints.UPDATE_FINITE_DIFFERENCES_HINT
                if close(value, expected, 1e-7 * scale)
                else "the checks at the quarter turn above say more",
            )


@public_check("filter_update", "a measurement equal to the prediction leaves R where it is")
def _(filter_update):
    R = Exp([0.4, -1.1, 2.0])
    R_new, _ = _pair(filter_update(R, P0, R.T @ GRAVITY_W, GRAVITY_W, R_NOISE), "filter_update")
    if not close(R_new, R, 1e-12):
        raise Mismatch(
            f"with y = Rᵀ g_w the attitude moved ({off_by(R_new, R)})",
            "no innovation, no correction: the step is proportional to y - Rᵀ g_w",
        )


@public_check("filter_update", "accepts plain lists and nested tuples")
def _(filter_update):
    args = (QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE)
    require_same_with_lists(lambda *a: np.vstack(filter_update(*a)), args, (6, 3), "filter_update(R, P, y, g_w, Rn)")
    require_same_with_lists(
        lambda *a: np.vstack(filter_update(*_as_tuples(a))),
        args,
        (6, 3),
        "filter_update(...) given tuples",
    )
