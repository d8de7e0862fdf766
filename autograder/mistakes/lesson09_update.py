"""Typical mistakes and correct alternatives for lesson 09, section 6: the filter's update with a measured direction."""

from . import Alternative, Mistake

_UPDATE = """
def filter_update(R, P, y, g_w, Rn):
    R, P = np.asarray(R, dtype=float), np.asarray(P, dtype=float)
    g_w = np.asarray(g_w, dtype=float)
    g_b = R.T @ g_w
    H = {H}
    S = H @ P @ H.T + np.asarray(Rn, dtype=float)
    K = np.linalg.solve(S, H @ P).T
    delta = K @ (np.asarray(y, dtype=float) - g_b)
    return {R_new}, {P_new}
"""


def _update(H="skew(g_b)", R_new="R @ Exp(delta)", P_new="(np.eye(3) - K @ H) @ P"):
    return _UPDATE.format(H=H, R_new=R_new, P_new=P_new)


MISTAKES = [
    Mistake(
        "update_finite_difference_jacobian",
        "filter_update",
        "the measurement Jacobian by central differences of (R Exp(ε))ᵀ g_w, not derived",
        """
def filter_update(R, P, y, g_w, Rn):
    R, P, y, g_w, Rn = (np.asarray(a, dtype=float) for a in (R, P, y, g_w, Rn))
    h = 1e-6
    H = np.column_stack([((R @ Exp(h * e)).T @ g_w - (R @ Exp(-h * e)).T @ g_w) / (2 * h) for e in np.eye(3)])
    information = np.linalg.inv(P) + H.T @ np.linalg.solve(Rn, H)
    step = np.linalg.solve(information, H.T @ np.linalg.solve(Rn, y - R.T @ g_w))
    return R @ Exp(step), np.linalg.inv(information)
""",
        hint="which a Jacobian taken by finite differences cannot reach",
        public_hint="which a Jacobian taken by finite differences cannot reach",
    ),
    Mistake(
        "update_left_jacobian",
        "filter_update",
        "H = Rᵀ [g_w]×: the measurement Jacobian of a left error",
        _update(H="R.T @ skew(g_w)"),
        hint="belongs to a left (world-frame) error",
        public_hint="belongs to a left (world-frame) error",
        classic=True,
    ),
    Mistake(
        "update_sign",
        "filter_update",
        "H = -[Rᵀ g_w]×: the sign of Exp(-ε) lost",
        _update(H="-skew(g_b)"),
        hint="moves away from the measurement",
        public_hint="moves away from the measurement",
    ),
    Mistake(
        "update_no_attitude",
        "filter_update",
        "H = [g_w]×: the attitude forgotten",
        _update(H="skew(g_w)"),
        hint="must depend on the attitude R",
        public_hint="must depend on the attitude R",
    ),
    Mistake(
        "update_left_correction",
        "filter_update",
        "R ← Exp(δ) R: the correction applied on the left",
        _update(R_new="Exp(delta) @ R"),
        hint="applied on the wrong side",
        public_hint="applied on the wrong side",
    ),
    Mistake(
        "update_covariance_kept",
        "filter_update",
        "P_new = P: the covariance not updated",
        _update(P_new="P"),
        hint="a measurement adds information",
        public_hint="a measurement adds information",
    ),
    Mistake(
        "update_lists_transposed",
        "filter_update",
        "R.T @ g_w on the inputs as given: plain lists have no .T",
        """
def filter_update(R, P, y, g_w, Rn):
    g_b = R.T @ g_w
    H = skew(g_b)
    S = H @ P @ H.T + Rn
    K = np.linalg.solve(S, H @ P).T
    delta = K @ (y - g_b)
    return R @ Exp(delta), (np.eye(3) - K @ H) @ P
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "update_innovation_is_y",
        "filter_update",
        "the correction K y from the measurement itself, not from the innovation y - Rᵀ g_w",
        """
def filter_update(R, P, y, g_w, Rn):
    R, P = np.asarray(R, dtype=float), np.asarray(P, dtype=float)
    g_b = R.T @ np.asarray(g_w, dtype=float)
    H = skew(g_b)
    S = H @ P @ H.T + np.asarray(Rn, dtype=float)
    K = np.linalg.solve(S, H @ P).T
    delta = K @ np.asarray(y, dtype=float)
    return R @ Exp(delta), (np.eye(3) - K @ H) @ P
""",
        hint="the gain multiplies the innovation y - Rᵀ g_w",
        public_hint="no innovation, no correction",
    ),
]

ALTERNATIVES = [
    Alternative(
        "update_information_form",
        "filter_update",
        "the information form (P⁻¹ + Hᵀ Rn⁻¹ H)⁻¹, H by the cross product of the predicted direction",
        """
def filter_update(R, P, y, g_w, Rn):
    R = np.asarray(R, dtype=float)
    predicted = R.T @ np.asarray(g_w, dtype=float)
    H = -np.column_stack([np.cross(e, predicted) for e in np.eye(3)])
    information = np.linalg.inv(np.asarray(P, dtype=float)) + H.T @ np.linalg.solve(np.asarray(Rn, dtype=float), H)
    P_new = np.linalg.inv(information)
    delta = P_new @ H.T @ np.linalg.solve(np.asarray(Rn, dtype=float), np.asarray(y, dtype=float) - predicted)
    return R @ Exp(delta), P_new
""",
    ),
    Alternative(
        "update_joseph_form",
        "filter_update",
        "the Joseph form (I - K H) P (I - K H)ᵀ + K Rn Kᵀ of the same covariance",
        """
def filter_update(R, P, y, g_w, Rn):
    R, P, Rn = (np.asarray(a, dtype=float) for a in (R, P, Rn))
    predicted = R.T @ np.asarray(g_w, dtype=float)
    H = skew(predicted)
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + Rn)
    A = np.eye(3) - K @ H
    return R @ Exp(K @ (np.asarray(y, dtype=float) - predicted)), A @ P @ A.T + K @ Rn @ K.T
""",
    ),
]
