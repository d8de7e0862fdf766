"""Typical mistakes and correct alternatives for lesson 09, section 7: the residual of a pose-graph edge."""

from . import Alternative, Mistake

_EDGE = """
def pose_graph_edge(T_i, T_j, T_ij):
    T_i, T_j, T_ij = (np.asarray(T, dtype=float) for T in (T_i, T_j, T_ij))
    between = np.linalg.solve(T_i, T_j)
    r = {residual}
    Jr = JrSE3(LogSE3(np.linalg.solve(T_ij, between)))
    Jr_inv = np.linalg.inv(Jr)
    return r, {J_i}, {J_j}
"""


def _edge(
    residual="LogSE3(np.linalg.solve(T_ij, between))", J_i="-Jr_inv @ AdSE3(np.linalg.inv(between))", J_j="Jr_inv"
):
    return _EDGE.format(residual=residual, J_i=J_i, J_j=J_j)


MISTAKES = [
    Mistake(
        "edge_small_residual",
        "pose_graph_edge",
        "J_j = I and J_i = -Ad: Log's Jacobian at r taken as I",
        _edge(J_i="-AdSE3(np.linalg.inv(between))", J_j="np.eye(6)"),
        hint="holds only for a small residual",
        public_hint="holds only for a small residual",
        classic=True,
    ),
    Mistake(
        "edge_adjoint_inverted",
        "pose_graph_edge",
        "J_i = -J_r(r)⁻¹ Ad(T_i⁻¹ T_j): the adjoint inverted",
        _edge(J_i="-Jr_inv @ AdSE3(between)"),
        hint="the adjoint is of the wrong pose, or inverted",
        public_hint="the adjoint is of the wrong pose, or inverted",
    ),
    Mistake(
        "edge_measurement_adjoint",
        "pose_graph_edge",
        "J_i = -J_r(r)⁻¹ Ad(T_ij⁻¹): δ_i moved across the measurement only",
        _edge(J_i="-Jr_inv @ AdSE3(np.linalg.inv(T_ij))"),
        hint="right at r = 0 but not at this residual",
        public_hint="right at r = 0 but not at this residual",
    ),
    Mistake(
        "edge_jr_not_inverted",
        "pose_graph_edge",
        "J_r(r) where its inverse belongs",
        _edge(J_i="-Jr @ AdSE3(np.linalg.inv(between))", J_j="Jr"),
        hint="is the inverse of Exp's right Jacobian",
        public_hint="is the inverse of Exp's right Jacobian",
    ),
    Mistake(
        "edge_sign_i",
        "pose_graph_edge",
        "J_i without its minus sign",
        _edge(J_i="Jr_inv @ AdSE3(np.linalg.inv(between))"),
        hint="T_i appears inverted in the residual",
        public_hint="T_i appears inverted in the residual",
    ),
    Mistake(
        "edge_residual_reversed",
        "pose_graph_edge",
        "r = Log(T_j⁻¹ T_i T_ij): the reversed edge",
        _edge(residual="LogSE3(np.linalg.solve(T_j, T_i) @ T_ij)"),
        hint="the residual of the reversed edge",
        public_hint="the residual of the reversed edge",
    ),
    Mistake(
        "edge_finite_difference_jacobians",
        "pose_graph_edge",
        "both Jacobians by central differences of the residual (the page's tool for checking them), not derived",
        """
def pose_graph_edge(T_i, T_j, T_ij):
    T_i, T_j, T_ij = (np.asarray(T, dtype=float) for T in (T_i, T_j, T_ij))

    def residual(A, B):
        return LogSE3(np.linalg.inv(T_ij) @ np.linalg.inv(A) @ B)

    h = 1e-6
    J_i = np.column_stack(
        [(residual(T_i @ ExpSE3(h * e), T_j) - residual(T_i @ ExpSE3(-h * e), T_j)) / (2 * h) for e in np.eye(6)]
    )
    J_j = np.column_stack(
        [(residual(T_i, T_j @ ExpSE3(h * e)) - residual(T_i, T_j @ ExpSE3(-h * e))) / (2 * h) for e in np.eye(6)]
    )
    return residual(T_i, T_j), J_i, J_j
""",
        hint="agrees with finite differences but not to rounding",
        public_hint="agrees with finite differences but not to rounding",
    ),
    Mistake(
        "edge_lists_inverse_by_hand",
        "pose_graph_edge",
        "an inverse written by hand with T[:3, :3] on the inputs as given: lists take no 2-D slice",
        """
def pose_graph_edge(T_i, T_j, T_ij):
    def inverse(T):
        R, t = T[:3, :3], T[:3, 3]
        out = np.eye(4)
        out[:3, :3] = R.T
        out[:3, 3] = -R.T @ t
        return out
    between = inverse(T_i) @ T_j
    r = LogSE3(inverse(T_ij) @ between)
    Jr_inv = np.linalg.inv(JrSE3(r))
    return r, -Jr_inv @ AdSE3(inverse(between)), Jr_inv
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "edge_left_jacobian",
        "pose_graph_edge",
        "J_i = -J_l(r)⁻¹ Ad(T_ij⁻¹) with J_l(r) = J_r(-r), inverses by solve",
        """
def pose_graph_edge(T_i, T_j, T_ij):
    T_i, T_j, T_ij = (np.asarray(T, dtype=float) for T in (T_i, T_j, T_ij))
    r = LogSE3(np.linalg.inv(T_ij) @ np.linalg.inv(T_i) @ T_j)
    J_i = -np.linalg.solve(JrSE3(-r), AdSE3(np.linalg.inv(T_ij)))
    J_j = np.linalg.solve(JrSE3(r), np.eye(6))
    return r, J_i, J_j
""",
    ),
]
