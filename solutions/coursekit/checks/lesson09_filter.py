"""Public checks for lesson 09, section 6: the attitude filter's prediction and its consistency test (NEES).

The error state is the right perturbation, R_true = R Exp(ε). The prediction's covariance is compared, at the
checks' fixed inputs (one long step, and steps |ω Δt| from 1e-12 to π about one axis), with numbers stored here:
the first-order covariance of its definition there, and what the usual slips return there (all recomputed by
``tests/test_public_check_constants_lesson09_filter.py``, from the definition by central differences and in closed
form). Nothing here computes a covariance for other inputs. The NEES is checked with its value where P = L Lᵀ and
ε = L u (so that the NEES is |u|²) and with its invariance under a common turn.
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import Exp
from .common import off_by, require_same_with_lists, require_shape

QUARTER_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
QUARTER_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
P0 = np.array([[4.0, 1.0, 0.0], [1.0, 3.0, -1.0], [0.0, -1.0, 2.0]]) * 1e-3
OMEGA = np.array([2.0, -1.0, 3.0])  # rad/s
DT = 0.25  # s: a long step, so that every first-order term shows
Q_GYRO = np.array([[9.0, 0.0, 2.0], [0.0, 1.0, 0.0], [2.0, 0.0, 4.0]]) * 1e-2

# The answer's P_new of filter_predict(QUARTER_Z, P0, OMEGA, DT, Q_GYRO): the first-order covariance of the new error.
PREDICT_P_NEW = np.array(
    [
        [0.008828372741831247, -0.002498945318521843, 8.229463737750788e-05],
        [-0.0024989453185218433, 0.0032269548409475995, -0.00027771507319584955],
        [8.229463737750831e-05, -0.0002777150731958495, 0.005381660758881648],
    ]
)

# What the usual slips return for filter_predict(QUARTER_Z, P0, OMEGA, DT, Q_GYRO)'s covariance.
PREDICT_NOT_CARRIED = np.array(
    [
        [0.009100175052334604, -0.000451088209824607, 0.0011357971902082997],
        [-0.0004510882098246072, 0.004152836377555839, -0.0009969586808962075],
        [0.0011357971902082997, -0.0009969586808962075, 0.0041839769117700525],
    ]
)
PREDICT_WRONG_WAY = np.array(
    [
        [0.0075462786076198815, -0.001365231216613687, 0.0020319417246335014],
        [-0.0013652312166136866, 0.0056052875231580885, 0.0007630712356061859],
        [0.0020319417246335014, 0.000763071235606186, 0.0042854222108825255],
    ]
)
PREDICT_NOISE_SHORT_STEP_ONLY = np.array(
    [
        [0.009353197689496644, -0.0010478571086972358, 0.00019649744716920825],
        [-0.0010478571086972358, 0.00269911846339176, -0.00028075639229964216],
        [0.00019649744716920868, -0.00028075639229964205, 0.0056976838471115955],
    ]
)
PREDICT_NOISE_DT = np.array(
    [
        [0.024128897898835055, -0.006852209947995664, 0.0034896862080024066],
        [-0.006852209947995664, 0.006685463973615118, -0.0002685911158844717],
        [0.0034896862080024075, -0.0002685911158844717, 0.011933591494191808],
    ]
)
PREDICT_NO_NOISE = np.array(
    [
        [0.0037281976894966437, -0.0010478571086972358, -0.0010535025528307918],
        [-0.0010478571086972358, 0.00207411846339176, -0.00028075639229964216],
        [-0.0010535025528307913, -0.00028075639229964205, 0.0031976838471115955],
    ]
)
PREDICT_NOISE_OLD_AXES = np.array(
    [
        [0.00825342713624529, 0.00013404522039368676, 0.0007141248518997437],
        [0.00013404522039368676, 0.003111152451000655, -0.00013585714551084323],
        [0.0007141248518997441, -0.00013585714551084304, 0.006072408754414548],
    ]
)
PREDICT_SLIPS = [
    (
        PREDICT_NOT_CARRIED,
        "P was not carried through the step: P_new is right when the step does not turn, and wrong when it does",
    ),
    (
        PREDICT_WRONG_WAY,
        "the old error's part of P_new is turned, but not as the error turns: right when the step does not turn, "
        "wrong when it does; follow one small error through the step",
    ),
    (PREDICT_NOISE_SHORT_STEP_ONLY, hints.PREDICT_NOISE_SHORT_STEP_HINT),
    (
        PREDICT_NOISE_DT,
        "the noise's part of P_new has the wrong size: Q is in (rad/s)² and P_new in rad², so check the units "
        "of what you add",
    ),
    (
        PREDICT_NO_NOISE,
        "the gyro's noise makes the truth drift from the estimate: P must grow by the covariance it adds",
    ),
    (PREDICT_NOISE_OLD_AXES, hints.PREDICT_NOISE_OLD_AXES_HINT),
]

# attitude_nees: P = L Lᵀ and ε = L u, so that εᵀ P⁻¹ ε = |u|² = 1.69.
NEES_L = np.array([[0.1, 0.0, 0.0], [0.05, 0.2, 0.0], [-0.1, 0.1, 0.3]])
NEES_U = np.array([0.3, -0.4, 1.2])
NEES_SLIP_DIAGONAL = 0.9539572192513368  # Σ ε_i² / P_ii
# an error of 0.6 rad about the body's x axis of a quarter turn about z, P = diag(0.01, 0.04, 0.09) rad².
NEES_R_EST = QUARTER_Z
NEES_P = np.diag([0.01, 0.04, 0.09])
NEES_SLIPS = [
    (
        9.0,
        "that is a turn in world axes, Log(R_true R_estᵀ); P is the covariance of the body-frame (right) error "
        "Log(R_estᵀ R_true)",
    ),
    (0.0036, "the NEES uses P's inverse, not P itself"),
    (12.0, hints.NEES_NOT_DIVIDED_HINT),
    (6.0, "the NEES is the square of the Mahalanobis distance: do not take its square root"),
    (27.636399339621907, "rotation vectors do not subtract: Log(R_true) - Log(R_est) is not the error between them"),
]


R_GENERIC = Exp([0.4, -1.1, 2.0])
STEPS = (1e-12, 1e-9, 9.9e-7, 1e-6, 9.9e-4, 1e-3, 1e-2, 9.9e-2, 0.1, 0.7, 2.0, 3.0, np.pi - 1e-9)  # |ω Δt|, rad
EXACT = 2e-12  # of max |P_new|, as the hidden checks hold it: the closed form to rounding, not by differences
# The answer's P_new of filter_predict(QUARTER_Z, P0, step / DT * OMEGA / |OMEGA|, DT, Q_GYRO), one per step of STEPS.
PREDICT_SWEEP_P_NEW = np.array(
    [
        [  # 1e-12
            [0.009625000000001938, 0.0009999999999972607, 0.0012499999999977117],
            [0.0009999999999972607, 0.003624999999997327, -0.001000000000000802],
            [0.0012499999999977117, -0.001000000000000802, 0.004500000000000736],
        ],
        [  # 1e-09
            [0.009625000001937644, 0.0009999999972605722, 0.0012499999977115756],
            [0.0009999999972605722, 0.003624999997327388, -0.0010000000008017838],
            [0.0012499999977115756, -0.0010000000008017838, 0.004500000000734968],
        ],
        [  # 9.9e-07
            [0.009625001918265236, 0.000999997287964105, 0.0012499977344600172],
            [0.000999997287964105, 0.0036249973541147345, -0.0010000007937639205],
            [0.0012499977344600172, -0.0010000007937639207, 0.004500000727619668],
        ],
        [  # 1e-06
            [0.009625001937641632, 0.0009999972605697776, 0.0012499977115757771],
            [0.0009999972605697779, 0.0036249973273886306, -0.0010000008017817176],
            [0.0012499977115757771, -0.0010000008017817174, 0.004500000734969371],
        ],
        [  # 0.00099
            [0.009626915940761142, 0.0009972855245145471, 0.0012477346185622619],
            [0.0009972855245145471, 0.0036223551445996255, -0.0010007917974471034],
            [0.0012477346185622619, -0.0010007917974471034, 0.004500728553664917],
        ],
        [  # 0.001
            [0.009626935269944754, 0.0009972580806636227, 0.0012477117375529478],
            [0.0009972580806636225, 0.0036223284394267135, -0.0010007997753147698],
            [0.0012477117375529478, -0.00100079977531477, 0.0045007359223249764],
        ],
        [  # 0.01
            [0.009644137876584354, 0.000972357426948343, 0.001227133049888232],
            [0.000972357426948343, 0.0035983808531302296, -0.001007816798201265],
            [0.0012271330498882323, -0.001007816798201265, 0.004507444440051037],
        ],
        [  # 0.099
            [0.009792368987763273, 0.000705368849702858, 0.0010262029252786093],
            [0.000705368849702858, 0.003372607184374368, -0.001059536631190122],
            [0.0010262029252786093, -0.0010595366311901221, 0.0045814152636555455],
        ],
        [  # 0.1
            [0.009793798206554526, 0.0007021648630729667, 0.0010239825881787439],
            [0.0007021648630729667, 0.0033702014962897027, -0.0010599346119219081],
            [0.0010239825881787439, -0.0010599346119219081, 0.004582318488900855],
        ],
        [  # 0.7
            [0.00953281798400266, -0.0016501300208546397, 0.00010391434921466118],
            [-0.0016501300208546397, 0.0028279041931939817, -0.0006521253173535881],
            [0.00010391434921466097, -0.0006521253173535882, 0.005211731076964373],
        ],
        [  # 2.0
            [0.004709110757536582, -0.0023908158413960125, 0.0016777460125826044],
            [-0.0023908158413960125, 0.006781703459252152, 6.835549487317887e-05],
            [0.0016777460125826044, 6.835549487317882e-05, 0.004968974551473922],
        ],
        [  # 3.0
            [0.004830089715632334, 0.0002201987077629214, 0.0016426429721058382],
            [0.0002201987077629214, 0.005437102278625733, -0.001813003240083137],
            [0.001642642972105838, -0.0018130032400831377, 0.005017622064903084],
        ],
        [  # 3.141592652589793
            [0.005051104914092672, 0.0002621835354922363, 0.0014486544795950817],
            [0.00026218353549223696, 0.004890822850300141, -0.0019296415705798335],
            [0.0014486544795950817, -0.0019296415705798335, 0.005179643161853124],
        ],
    ]
)


def _as_tuples(args):
    """The plain lists among ``args`` as nested tuples (array_like, as the docstrings allow); arrays kept."""

    def tuples(a):
        return tuple(tuples(x) for x in a) if isinstance(a, list) else a

    return [tuples(a) for a in args]


def _pair(value, what):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Mismatch(
            f"{what} returned {type(value).__name__}, not a pair (R_new, P_new)", "return both: R_new, P_new"
        )
    return (require_shape(value[0], (3, 3), f"{what}'s R_new"), require_shape(value[1], (3, 3), f"{what}'s P_new"))


# ---------------------------------------------------------------- filter_predict
@public_check("filter_predict", "the attitude takes one gyro step on the body side, R Exp(ω Δt) (two attitudes)")
def _(filter_predict):
    for R in (QUARTER_Z, R_GENERIC):  # a quarter turn's entries are exact in any precision; R_GENERIC's are not
        R_new, _ = _pair(filter_predict(R, P0, OMEGA, DT, Q_GYRO), "filter_predict")
        expected = R @ Exp(OMEGA * DT)
        if not close(R_new, expected, 1e-12):
            hint = (
                "that is the step on the world side, Exp(ω Δt) R: a gyro measures body rates, so apply the step "
                "on the right of R"
                if close(R_new, Exp(OMEGA * DT) @ R, 1e-12)
                else "R_new = R Exp(ω Δt), as in integrate_gyro"
            )
            raise Mismatch(f"R_new is not R Exp(ω Δt) ({off_by(R_new, expected)})", hint)


@public_check("filter_predict", "P_new is the first-order covariance of the new error")
def _(filter_predict):
    _, P_new = _pair(filter_predict(QUARTER_Z, P0, OMEGA, DT, Q_GYRO), "filter_predict")
    expected = PREDICT_P_NEW
    if not close(P_new, expected, EXACT * np.max(np.abs(expected))):
        hint = next((h for value, h in PREDICT_SLIPS if close(P_new, value, 1e-9)), None)
        if hint is None and close(P_new, expected, 1e-7 * np.max(np.abs(expected))):
            hint = hints.PREDICT_FINITE_DIFFERENCES_HINT
        raise Mismatch(
            f"P_new disagrees with the first-order covariance of the definition ({off_by(P_new, expected)})",
            hint
            or "write the new error in terms of ε and n, keep first-order terms, and propagate: "
            "Cov(A ε + B n) = A P Aᵀ + B Q Bᵀ",
        )


@public_check(
    "filter_predict", "P_new for steps |ω Δt| at every decade from 1e-12 to π (and just below 1e-6, 1e-3, 0.1)"
)
def _(filter_predict):
    axis = OMEGA / np.linalg.norm(OMEGA)
    for step, expected in zip(STEPS, PREDICT_SWEEP_P_NEW):
        omega = step / DT * axis
        _, P_new = _pair(filter_predict(QUARTER_Z, P0, omega, DT, Q_GYRO), "filter_predict")
        if not close(P_new, expected, EXACT * np.max(np.abs(expected))):
            _, P_long = _pair(filter_predict(QUARTER_Z, P0, OMEGA, DT, Q_GYRO), "filter_predict")
            right_for_long = close(P_long, PREDICT_P_NEW, EXACT * np.max(np.abs(PREDICT_P_NEW)))
            if not right_for_long:
                hint = "the check with one long step above says more"
            elif step < 1e-2 and close(P_new, expected, 1e-7 * np.max(np.abs(expected))):
                hint = hints.PREDICT_CANCELS_HINT
            else:
                hint = (
                    f"right for a long step but not for {step:.3g} rad: check the branch your answer takes for "
                    "steps this small, and where it switches"
                )
            raise Mismatch(
                f"P_new for a step of {step:.3g} rad disagrees with the first-order covariance "
                f"({off_by(P_new, expected)})",
                hint,
            )


@public_check("filter_predict", "no gyro noise and no turn: the covariance is carried unchanged")
def _(filter_predict):
    R_new, P_new = _pair(filter_predict(QUARTER_X, P0, np.zeros(3), 0.01, np.zeros((3, 3))), "filter_predict")
    if not close(P_new, P0, 1e-15) or not close(R_new, QUARTER_X, 1e-15):
        raise Mismatch(
            f"with ω = 0 and Q = 0 the prediction changed (P off by {np.max(np.abs(P_new - P0)):.2g})",
            "a step that does not turn and adds no noise leaves R and P as they are",
        )


@public_check("filter_predict", "with ω = 0: R_new = R, and P_new is P plus one step's gyro noise, to 1e-14")
def _(filter_predict):
    R_new, P_new = _pair(filter_predict(R_GENERIC, P0, np.zeros(3), DT, Q_GYRO), "filter_predict")
    if not close(R_new, R_GENERIC, 1e-14):
        raise Mismatch(f"with ω = 0 R_new is not R ({off_by(R_new, R_GENERIC)})", hints.PREDICT_NO_TURN_R_HINT)
    expected = P0 + DT * DT * Q_GYRO
    if not close(P_new, expected, 1e-14 * np.max(np.abs(expected))):
        raise Mismatch(f"with ω = 0 P_new is off ({off_by(P_new, expected)})", hints.PREDICT_NO_TURN_P_HINT)


@public_check("filter_predict", "accepts plain lists and nested tuples")
def _(filter_predict):
    args = (QUARTER_Z, P0, OMEGA, DT, Q_GYRO)
    require_same_with_lists(
        lambda *a: np.vstack(filter_predict(*a)), args, (6, 3), "filter_predict(R, P, omega_meas, dt, Q)"
    )
    require_same_with_lists(
        lambda *a: np.vstack(filter_predict(*_as_tuples(a))),
        args,
        (6, 3),
        "filter_predict(...) given tuples",
    )


# ---------------------------------------------------------------- attitude_nees
def _nees(attitude_nees, R_true, R_est, P):
    value = attitude_nees(R_true, R_est, P)
    if isinstance(value, np.ndarray):
        raise Mismatch(
            f"attitude_nees(R_true, R_est, P) returned a numpy array of shape {value.shape}, not a float",
            "the NEES is one number: return it as a float",
        )
    return float(require_shape(value, (), "attitude_nees(R_true, R_est, P)"))


@public_check("attitude_nees", "0.6 rad about the body's x axis with P = diag(0.01, 0.04, 0.09) gives 36")
def _(attitude_nees):
    got = _nees(attitude_nees, NEES_R_EST @ Exp([0.6, 0.0, 0.0]), NEES_R_EST, NEES_P)
    if abs(got - 36.0) > 1e-9:
        hint = next((h for value, h in NEES_SLIPS if abs(got - value) < 1e-9 * max(1.0, value)), None)
        raise Mismatch(f"gave {got:.6g}, expected 0.36 / 0.01 = 36", hint or "ε = Log(R_estᵀ R_true), then εᵀ P⁻¹ ε")


@public_check("attitude_nees", "with P = L Lᵀ and ε = L u, the NEES is |u|² (a P with correlations)")
def _(attitude_nees):
    R_est = Exp([0.3, -0.2, 1.4])
    got = _nees(attitude_nees, R_est @ Exp(NEES_L @ NEES_U), R_est, NEES_L @ NEES_L.T)
    if abs(got - 1.69) > 1e-9:
        hint = (
            "only the variances of P were used: the off-diagonal entries of P count too"
            if abs(got - NEES_SLIP_DIAGONAL) < 1e-9
            else None
        )
        raise Mismatch(f"gave {got:.6g}, expected |u|² = 1.69", hint or "εᵀ P⁻¹ ε with the whole of P")


@public_check("attitude_nees", "unchanged when both attitudes turn by the same world rotation")
def _(attitude_nees):
    P = np.array([[4.0, 1.0, 0.5], [1.0, 3.0, -1.0], [0.5, -1.0, 2.0]]) * 1e-2
    R_est, R_true = Exp([0.3, -0.2, 1.4]), Exp([0.45, -0.35, 1.2])
    turn = Exp([1.0, 2.0, -0.5])
    a, b = _nees(attitude_nees, R_true, R_est, P), _nees(attitude_nees, turn @ R_true, turn @ R_est, P)
    if abs(a - b) > 1e-9 * max(1.0, a):
        raise Mismatch(
            f"turning both attitudes by the same world rotation changed the NEES from {a:.6g} to {b:.6g}",
            "that error is a turn in world axes: the body-frame error R_estᵀ R_true does not change "
            "when both attitudes turn together",
        )


@public_check("attitude_nees", "accepts plain lists and nested tuples")
def _(attitude_nees):
    args = (R_GENERIC, NEES_R_EST, NEES_P)
    require_same_with_lists(attitude_nees, args, (), "attitude_nees(R_true, R_est, P)")
    require_same_with_lists(lambda *a: attitude_nees(*_as_tuples(a)), args, (), "attitude_nees(...) given tuples")
