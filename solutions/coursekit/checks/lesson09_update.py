"""Public checks for lesson 09, section 6: the attitude filter's update with a measured direction.

The error state is the right perturbation, R_true = R Exp(ε). The update is compared with the minimiser and the
inverse Hessian of its linearised MAP cost, the measurement Jacobian taken here by central differences of
(R Exp(ε))ᵀ g_w (scipy's Exp), never a closed form. The steps the usual slips take at the checks' fixed inputs are
stored as numbers (``tests/test_public_check_constants_lesson09_update.py`` recomputes them).
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

# The step Log(Rᵀ R_new) that the usual slips take in filter_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE).
UPDATE_SIGN_STEP = np.array([-0.07951038259168974, 0.006147640176339267, -0.0520504716485234])
UPDATE_NO_R_STEP = np.array([-0.022168626738025207, -0.04519060476755945, 0.0144176174847466])
UPDATE_LEFT_STEP = np.array([0.07884941040238526, -0.05202786526636899, 0.02608735195162375])
SIGN_HINT = (
    "the step moves away from the measurement: check the sign of your measurement Jacobian, (R Exp(ε))ᵀ = Exp(-ε) Rᵀ"
)
NO_R_HINT = "the measurement Jacobian must depend on the attitude R: the body sees g_w through Rᵀ"
LEFT_JACOBIAN_HINT = (
    "that measurement Jacobian belongs to a left (world-frame) error; this filter's error is on the right, R Exp(ε)"
)
LEFT_UPDATE_HINT = hints.UPDATE_WRONG_SIDE_HINT
UPDATE_SLIPS = [(UPDATE_SIGN_STEP, SIGN_HINT), (UPDATE_NO_R_STEP, NO_R_HINT), (UPDATE_LEFT_STEP, LEFT_JACOBIAN_HINT)]
P_UNCHANGED_HINT = "a measurement adds information: the covariance must shrink along the directions it sees"


def _as_tuples(args):
    """The plain lists among ``args`` as nested tuples (array_like, as the docstring allows); arrays kept."""

    def tuples(a):
        return tuple(tuples(x) for x in a) if isinstance(a, list) else a

    return [tuples(a) for a in args]


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _pair(value, what):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Mismatch(
            f"{what} returned {type(value).__name__}, not a pair (R_new, P_new)", "return both: R_new, P_new"
        )
    return (require_shape(value[0], (3, 3), f"{what}'s R_new"), require_shape(value[1], (3, 3), f"{what}'s P_new"))


# ---------------------------------------------------------------- filter_update
def _map_update(R, P, y, g_w, Rn):
    """Minimiser and inverse Hessian of |ε|²_P⁻¹ + |y - h(0) - H ε|²_Rn⁻¹, H by central differences."""
    H = _central(lambda e: (R @ Exp(e)).T @ g_w, 3)
    information = np.linalg.inv(P) + H.T @ np.linalg.solve(Rn, H)
    step = np.linalg.solve(information, H.T @ np.linalg.solve(Rn, y - R.T @ g_w))
    return step, np.linalg.inv(information)


@public_check("filter_update", "the correction minimises the linearised MAP cost, applied on the right")
def _(filter_update):
    R_new, _ = _pair(filter_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE), "filter_update")
    step, _ = _map_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE)
    got = Log(QUARTER_X.T @ R_new)
    if not close(got, step, 1e-10 * np.max(np.abs(step))):  # the oracle's differences are good to 1e-12
        hint = next((h for value, h in UPDATE_SLIPS if close(got, value, 1e-8)), None)
        if hint is None and close(Log(R_new @ QUARTER_X.T), step, 1e-8):
            hint = LEFT_UPDATE_HINT
        raise Mismatch(
            f"the correction Log(Rᵀ R_new) is not the minimiser of the MAP cost ({off_by(got, step)})",
            hint or "linearise the predicted measurement in ε, then minimise the two weighted squares",
        )


@public_check("filter_update", "P_new is the inverse Hessian of the linearised MAP cost")
def _(filter_update):
    _, P_new = _pair(filter_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE), "filter_update")
    _, expected = _map_update(QUARTER_X, P0, Y_ACCEL, GRAVITY_W, R_NOISE)
    if not close(P_new, expected, 1e-10 * np.max(np.abs(expected))):
        raise Mismatch(
            f"P_new disagrees with the inverse Hessian ({off_by(P_new, expected)})",
            P_UNCHANGED_HINT
            if close(P_new, P0, 1e-15)
            else "P_new⁻¹ = P⁻¹ + (information the measurement adds); check H and the gain",
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
