"""Typical mistakes and correct alternatives for lesson 09, section 6: the attitude filter and its NEES."""

from . import Alternative, Mistake

_PREDICT = """
def filter_predict(R, P, omega_meas, dt, Q):
    R = np.asarray(R, dtype=float)
    P = np.asarray(P, dtype=float)
    Q = np.asarray(Q, dtype=float)
    phi = np.asarray(omega_meas, dtype=float) * dt
    step = Exp(phi)
    theta = np.sqrt(phi @ phi)
    W = skew(phi)
    if theta < 1e-6:
        Jr = np.eye(3) - W / 2 + W @ W / 6
    else:
        Jr = np.eye(3) - {first} * W + (theta - np.sin(theta)) / theta**3 * W @ W
    G = {noise_jacobian}
    return {R_new}, {carried} + {noise}
"""


def _predict(
    noise_jacobian="Jr * dt",
    R_new="R @ step",
    carried="step.T @ P @ step",
    noise="G @ Q @ G.T",
    first="2 * np.sin(theta / 2) ** 2 / theta**2",
):
    return _PREDICT.format(noise_jacobian=noise_jacobian, R_new=R_new, carried=carried, noise=noise, first=first)


_NEES = """
def attitude_nees(R_true, R_est, P):
    R_true = np.asarray(R_true, dtype=float)
    R_est = np.asarray(R_est, dtype=float)
    P = np.asarray(P, dtype=float)
    eps = {error}
    return {value}
"""


def _nees(error="Log(R_est.T @ R_true)", value="float(eps @ np.linalg.solve(P, eps))"):
    return _NEES.format(error=error, value=value)


MISTAKES = [
    Mistake(
        "predict_closed_form_cancels",
        "filter_predict",
        "J_r's first coefficient as (1 - cos θ)/θ² right above a small-step branch at 1e-6, where it loses its digits",
        _predict(first="(1 - np.cos(theta)) / theta**2"),
        hint="subtracts nearly equal numbers there",
        public_hint="subtracts nearly equal numbers there",
    ),
    Mistake(
        "predict_finite_differences",
        "filter_predict",
        "the two Jacobians by central differences of the definition instead of derived",
        """
def filter_predict(R, P, omega_meas, dt, Q):
    R, P, omega, Q = (np.asarray(a, dtype=float) for a in (R, P, omega_meas, Q))
    R_new = R @ Exp(omega * dt)
    h = 1e-6

    def error(x):
        return Log(R_new.T @ R @ Exp(x[:3]) @ Exp((omega - x[3:]) * dt))

    J = np.column_stack([(error(h * e) - error(-h * e)) / (2 * h) for e in np.eye(6)])
    F, G = J[:, :3], J[:, 3:]
    return R_new, F @ P @ F.T + G @ Q @ G.T
""",
        hint="which finite differences cannot reach",
        public_hint="which finite differences cannot reach",
    ),
    # ------------------------------------------------------------ filter_predict
    Mistake(
        "predict_no_transport",
        "filter_predict",
        "P + G Q Gᵀ: P not carried across the step",
        _predict(carried="P"),
        hint="P was not carried across the step",
        public_hint="P was not carried through the step",
        classic=True,
    ),
    Mistake(
        "predict_wrong_way",
        "filter_predict",
        "Exp(ω dt) P Exp(ω dt)ᵀ: carried the wrong way",
        _predict(carried="step @ P @ step.T"),
        hint="the wrong way round",
        public_hint="but not as the error turns",
    ),
    Mistake(
        "predict_noise_dt",
        "filter_predict",
        "noise covariance scaled by dt instead of dt²",
        _predict(noise="G @ Q @ G.T / dt"),
        hint="check the units of the noise's part",
        public_hint="Q is in (rad/s)² and P_new in rad²",
    ),
    Mistake(
        "predict_no_jr",
        "filter_predict",
        "noise term dt² Q: the Jacobian of Exp taken as I",
        _predict(noise_jacobian="np.eye(3) * dt"),
        hint="right for a short step and wrong for a long one",
        public_hint="right for a short step and wrong for a long one",
    ),
    Mistake(
        "predict_no_noise",
        "filter_predict",
        "forgets the gyro noise",
        _predict(noise="0.0 * Q"),
        hint="must add to P",
        public_hint="must grow by the covariance",
    ),
    Mistake(
        "predict_left_jacobian",
        "filter_predict",
        "the left Jacobian of Exp for the noise",
        _predict(noise_jacobian="Jr.T * dt"),
        hint="in the axes the body had before the step",
        public_hint="in the axes the body had before the step",
    ),
    Mistake(
        "predict_left_update",
        "filter_predict",
        "R ← Exp(ω dt) R: body rates applied on the left",
        _predict(R_new="step @ R"),
        hint="the step goes on the right of R",
        public_hint="apply the step on the right of R",
    ),
    # ------------------------------------------------------------ attitude_nees
    Mistake(
        "nees_left_error",
        "attitude_nees",
        "ε = Log(R_true R_estᵀ): the world-frame error",
        _nees(error="Log(R_true @ R_est.T)"),
        hint="a turn in world axes",
        public_hint="a turn in world axes",
        classic=True,
    ),
    Mistake(
        "nees_not_inverted",
        "attitude_nees",
        "εᵀ P ε: P not inverted",
        _nees(value="float(eps @ P @ eps)"),
        hint="uses P's inverse",
        public_hint="uses P's inverse",
    ),
    Mistake(
        "nees_sqrt",
        "attitude_nees",
        "the Mahalanobis distance, not its square",
        _nees(value="float(np.sqrt(eps @ np.linalg.solve(P, eps)))"),
        hint="Mahalanobis distance",
        public_hint="Mahalanobis distance",
    ),
    Mistake(
        "nees_diagonal",
        "attitude_nees",
        "only the variances of P",
        _nees(value="float(eps @ (eps / np.diag(P)))"),
        hint="off-diagonal entries of P count too",
        public_hint="off-diagonal entries of P count too",
    ),
    Mistake(
        "nees_lists_transposed",
        "attitude_nees",
        "R_est.T @ R_true on the inputs as given: plain lists have no .T",
        """
def attitude_nees(R_true, R_est, P):
    eps = Log(R_est.T @ R_true)
    return float(eps @ np.linalg.solve(P, eps))
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "predict_lists_scaled",
        "filter_predict",
        "omega_meas * dt on the input as given: a list times a float is an error",
        """
def filter_predict(R, P, omega_meas, dt, Q):
    phi = omega_meas * dt
    step = Exp(phi)
    theta = np.sqrt(phi @ phi)
    W = skew(phi)
    if theta < 1e-6:
        Jr = np.eye(3) - W / 2 + W @ W / 6
    else:
        Jr = np.eye(3) - 2 * np.sin(theta / 2) ** 2 / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
    G = Jr * dt
    return R @ step, step.T @ P @ step + G @ Q @ G.T
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "predict_returns_lists",
        "filter_predict",
        "the right R_new and P_new, returned as a list of nested lists",
        """
def filter_predict(R, P, omega_meas, dt, Q):
    R, P, Q = (np.asarray(x, dtype=float) for x in (R, P, Q))
    phi = np.asarray(omega_meas, dtype=float) * dt
    theta, W = np.sqrt(phi @ phi), skew(phi)
    if theta < 1e-6:
        Jr = np.eye(3) - W / 2 + W @ W / 6
    else:
        Jr = np.eye(3) - 2 * np.sin(theta / 2) ** 2 / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
    step, G = Exp(phi), Jr * dt
    return [(R @ step).tolist(), (step.T @ P @ step + G @ Q @ G.T).tolist()]
""",
        hint="a list is not an array",
        public_hint="a list is not an array",
    ),
]

ALTERNATIVES = [
    Alternative(
        "predict_by_integral",
        "filter_predict",
        "the Jacobian of Exp as the integral of Exp(-s φ) ds (Simpson's rule on a fine grid)",
        """
def filter_predict(R, P, omega_meas, dt, Q):
    phi = np.asarray(omega_meas, dtype=float) * dt
    step = Exp(phi)
    s = np.linspace(0.0, 1.0, 2001)
    weights = np.ones_like(s)
    weights[1:-1:2], weights[2:-1:2] = 4.0, 2.0
    Jr = sum(w * Exp(-t * phi) for w, t in zip(weights, s)) / (3.0 * (len(s) - 1))
    G = Jr * dt
    R_new = np.asarray(R, dtype=float) @ step
    P_new = step.T @ np.asarray(P, dtype=float) @ step + G @ np.asarray(Q, dtype=float) @ G.T
    return R_new, P_new
""",
    ),
    Alternative(
        "nees_other_sign",
        "attitude_nees",
        "ε = Log(R_trueᵀ R_est) (the opposite sign) and the inverse of P",
        """
def attitude_nees(R_true, R_est, P):
    eps = Log(np.asarray(R_true, dtype=float).T @ np.asarray(R_est, dtype=float))
    return eps @ np.linalg.inv(np.asarray(P, dtype=float)) @ eps
""",
    ),
]
