"""Typical mistakes and correct alternatives for lesson 09: estimation on Lie groups."""

from . import Alternative, Mistake


_GN_POSE = """
def align_pose_gauss_newton(P, Q, T0, iters=10):
    P = np.asarray(P, dtype=float)
    Q = np.asarray(Q, dtype=float)
    T = np.array(T0, dtype=float)
    for _ in range({iterations}):
        R, t = T[:3, :3], T[:3, 3]
        H, g = np.zeros((6, 6)), np.zeros(6)
        for p, q in zip(P, Q):
            J = np.hstack([R, -R @ skew(p)])
            r = R @ p + t - q
            H += J.T @ J
            g += J.T @ r
        xi = np.linalg.solve(H, {sign}g)
        {update}
    return T
"""


def _gn_pose(update="T = T @ ExpSE3(xi)", sign="-", iterations="iters"):
    return _GN_POSE.format(update=update, sign=sign, iterations=iterations)


_ROBUST = """
def align_pose_robust(P, Q, T0, k):
    P = np.asarray(P, dtype=float)
    Q = np.asarray(Q, dtype=float)
    T = np.array(T0, dtype=float)
    for _ in range({iterations}):
        R, t = T[:3, :3], T[:3, 3]
        H, g = np.zeros((6, 6)), np.zeros(6)
        for p, q in zip(P, Q):
            J = np.hstack([R, -R @ skew(p)])
            r = R @ p + t - q
            size = np.sqrt(r @ r)
            weight = {weight}
            H += weight * (J.T @ J)
            g += weight * (J.T @ r)
        xi = np.linalg.solve(H, -g)
        T = T @ ExpSE3(xi)
        if np.sqrt(xi @ xi) < 1e-13:
            break
    return T
"""


def _robust(weight="1.0 if size <= k else k / size", iterations="500"):
    return _ROBUST.format(weight=weight, iterations=iterations)


MISTAKES = [
    # ------------------------------------------------------------ integrate_gyro
    Mistake(
        "gyro_no_copy",
        "integrate_gyro",
        "R = R0 with no conversion: no samples hands back the caller's list",
        """
def integrate_gyro(R0, omegas_b, dt):
    R = R0
    for omega in np.asarray(omegas_b, dtype=float).reshape(-1, 3):
        R = R @ Exp(omega * dt)
    return R
""",
        hint="the docstring promises an ndarray",
        public_hint="R0 itself is never handed back",
    ),
    Mistake(
        "gyro_world_side",
        "integrate_gyro",
        "R ← Exp(ω_b dt) R: body rates used as world rates",
        """
def integrate_gyro(R0, omegas_b, dt):
    R = np.array(R0, dtype=float)
    for omega in np.asarray(omegas_b, dtype=float).reshape(-1, 3):
        R = Exp(omega * dt) @ R
    return R
""",
        hint="turned about the world's axes",
        public_hint="turned about the world's axes",
        classic=True,
    ),
    Mistake(
        "gyro_no_dt",
        "integrate_gyro",
        "forgets dt: each sample turns by ω radians",
        """
def integrate_gyro(R0, omegas_b, dt):
    R = np.array(R0, dtype=float)
    for omega in np.asarray(omegas_b, dtype=float).reshape(-1, 3):
        R = R @ Exp(omega)
    return R
""",
        hint="multiply the rates by dt",
        public_hint="multiply the rates by dt",
    ),
    Mistake(
        "gyro_summed",
        "integrate_gyro",
        "one Exp of the summed rates",
        """
def integrate_gyro(R0, omegas_b, dt):
    omegas = np.asarray(omegas_b, dtype=float).reshape(-1, 3)
    return np.array(R0, dtype=float) @ Exp(omegas.sum(axis=0) * dt)
""",
        hint="one Exp of the summed rates",
        public_hint="one Exp of the summed rates",
    ),
    Mistake(
        "gyro_first_order",
        "integrate_gyro",
        "R ← R (I + [ω dt]×): drifts off SO(3)",
        """
def integrate_gyro(R0, omegas_b, dt):
    R = np.array(R0, dtype=float)
    for omega in np.asarray(omegas_b, dtype=float).reshape(-1, 3):
        R = R @ (np.eye(3) + skew(omega * dt))
    return R
""",
        hint="is only first order",
        public_hint="is only first order",
    ),
    # ------------------------------------------------------------ rotated_point_covariance
    Mistake(
        "covariance_without_R",
        "rotated_point_covariance",
        "[p]× Σ [p]×ᵀ: the body-frame covariance",
        """
def rotated_point_covariance(R, Sigma, p):
    S = skew(p)
    return S @ np.asarray(Sigma, dtype=float) @ S.T
""",
        hint="covariance in the body frame",
        public_hint="covariance in the body frame",
    ),
    Mistake(
        "covariance_left_jacobian",
        "rotated_point_covariance",
        "[R p]× Σ [R p]×ᵀ: the left Jacobian",
        """
def rotated_point_covariance(R, Sigma, p):
    S = skew(np.asarray(R, dtype=float) @ np.asarray(p, dtype=float))
    return S @ np.asarray(Sigma, dtype=float) @ S.T
""",
        hint="world-frame (left) perturbation",
        public_hint="world-frame (left) perturbation",
        classic=True,
    ),
    Mistake(
        "covariance_of_the_turn",
        "rotated_point_covariance",
        "R Σ Rᵀ: the covariance of the turn",
        """
def rotated_point_covariance(R, Sigma, p):
    R = np.asarray(R, dtype=float)
    return R @ np.asarray(Sigma, dtype=float) @ R.T
""",
        hint="covariance of the turn",
        public_hint="covariance of the turn",
    ),
    Mistake(
        "covariance_one_sided",
        "rotated_point_covariance",
        "J Σ without Jᵀ",
        """
def rotated_point_covariance(R, Sigma, p):
    J = -np.asarray(R, dtype=float) @ skew(p)
    return J @ np.asarray(Sigma, dtype=float)
""",
        hint="takes the Jacobian on both sides",
        public_hint="takes the Jacobian on both sides",
    ),
    Mistake(
        "covariance_transposed",
        "rotated_point_covariance",
        "Jᵀ Σ J instead of J Σ Jᵀ",
        """
def rotated_point_covariance(R, Sigma, p):
    J = -np.asarray(R, dtype=float) @ skew(p)
    return J.T @ np.asarray(Sigma, dtype=float) @ J
""",
        hint="the Jacobian on the wrong sides",
        public_hint="the Jacobian on the wrong sides",
    ),
    # ------------------------------------------------------------ covariance_left_to_right
    Mistake(
        "left_to_right_wrong_way",
        "covariance_left_to_right",
        "R Σ Rᵀ: converts right to left",
        """
def covariance_left_to_right(R, Sigma_left):
    R = np.asarray(R, dtype=float)
    return R @ np.asarray(Sigma_left, dtype=float) @ R.T
""",
        hint="converts right to left",
        public_hint="converts right to left",
        classic=True,
    ),
    Mistake(
        "left_to_right_unchanged",
        "covariance_left_to_right",
        "returns Σ_L unchanged",
        """
def covariance_left_to_right(R, Sigma_left):
    return np.array(Sigma_left, dtype=float)
""",
        hint="must change frame",
        public_hint="must change frame",
    ),
    Mistake(
        "left_to_right_one_side",
        "covariance_left_to_right",
        "Rᵀ Σ_L: the map on one side only",
        """
def covariance_left_to_right(R, Sigma_left):
    return np.asarray(R, dtype=float).T @ np.asarray(Sigma_left, dtype=float)
""",
        hint="on both sides",
        public_hint="on both sides",
    ),
    Mistake(
        "left_to_right_other_side",
        "covariance_left_to_right",
        "Σ_L R: the map on one side only",
        """
def covariance_left_to_right(R, Sigma_left):
    return np.asarray(Sigma_left, dtype=float) @ np.asarray(R, dtype=float)
""",
        hint="on both sides",
        public_hint="on both sides",
    ),
    # ------------------------------------------------------------ align_pose_gauss_newton
    Mistake(
        "pose_gn_one_step",
        "align_pose_gauss_newton",
        "one Gauss-Newton step, whatever iters says",
        _gn_pose(iterations="1"),
        hint="whatever iters says",
        public_hint="whatever iters says",
        classic=True,
    ),
    Mistake(
        "pose_gn_wrong_sign",
        "align_pose_gauss_newton",
        "steps uphill: xi = +H⁻¹ g",
        _gn_pose(sign=""),
        hint="uphill",
        public_hint="uphill",
    ),
    Mistake(
        "pose_gn_left_update",
        "align_pose_gauss_newton",
        "T ← Exp(xi) T with the right Jacobian",
        _gn_pose(update="T = ExpSE3(xi) @ T"),
        hint="goes with the left Jacobian",
        public_hint="on the same side",
    ),
    Mistake(
        "pose_gn_first_order_update",
        "align_pose_gauss_newton",
        "T ← T (I + xi^): leaves SE(3)",
        _gn_pose(update="T = T @ (np.eye(4) + np.block([[skew(xi[3:]), xi[:3, None]], [np.zeros((1, 4))]]))"),
        hint="drifted off SE(3)",
        public_hint="not a pose",
    ),
    # ------------------------------------------------------------ align_pose_robust
    Mistake(
        "robust_least_squares",
        "align_pose_robust",
        "minimises the squared cost (ignores k)",
        _robust(weight="1.0"),
        hint="minimises the squared cost",
        public_hint="minimises the squared cost",
        classic=True,
    ),
    Mistake(
        "robust_two_steps",
        "align_pose_robust",
        "stops after two reweighted steps",
        _robust(iterations="2"),
        hint="the gradient is not zero yet",
        public_hint="the gradient is not zero yet",
    ),
    Mistake(
        "robust_returns_start",
        "align_pose_robust",
        "returns T0",
        """
def align_pose_robust(P, Q, T0, k):
    return np.array(T0, dtype=float)
""",
        hint="returned T0 unchanged",
        public_hint="returned T0 unchanged",
    ),
    Mistake(
        "robust_squared_weights",
        "align_pose_robust",
        "weights (k/|r|)² beyond k: a log tail, not Huber's",
        _robust(weight="1.0 if size <= k else (k / size) ** 2"),
        hint="less than Huber's linear tail",
        public_hint="less than Huber's linear tail",
    ),
    Mistake(
        "point_covariance_lists_negated",
        "rotated_point_covariance",
        "-R @ skew(p) on the input as given: a list cannot be negated",
        """
def rotated_point_covariance(R, Sigma, p):
    J = -R @ skew(p)
    return J @ Sigma @ J.T
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "align_start_copied",
        "align_pose_gauss_newton",
        "T0.copy() keeps a list a list: T[:3, :3] then fails on a plain-list start",
        """
def align_pose_gauss_newton(P, Q, T0, iters=10):
    P = np.asarray(P, dtype=float)
    Q = np.asarray(Q, dtype=float)
    T = T0.copy()
    for _ in range(iters):
        R, t = T[:3, :3], T[:3, 3]
        H, g = np.zeros((6, 6)), np.zeros(6)
        for p, q in zip(P, Q):
            J = np.hstack([R, -R @ skew(p)])
            r = R @ p + t - q
            H += J.T @ J
            g += J.T @ r
        T = T @ ExpSE3(np.linalg.solve(H, -g))
    return T
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "gyro_with_quaternions",
        "integrate_gyro",
        "integrates a quaternion, converts at the end",
        """
def integrate_gyro(R0, omegas_b, dt):
    from scipy.spatial.transform import Rotation
    omegas = np.asarray(omegas_b, dtype=float).reshape(-1, 3)
    if len(omegas) == 0:
        return np.array(R0, dtype=float)
    q = Rotation.from_matrix(np.asarray(R0, dtype=float)).as_quat(scalar_first=True)
    for omega in omegas:
        angle = np.linalg.norm(omega * dt)
        if angle > 0.0:
            q = quat_product(q, np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * omega * dt / angle]))
    return Rotation.from_quat(q, scalar_first=True).as_matrix()
""",
    ),
    Alternative(
        "covariance_in_two_steps",
        "rotated_point_covariance",
        "body-frame covariance, then turned by R",
        """
def rotated_point_covariance(R, Sigma, p):
    R = np.asarray(R, dtype=float)
    body = skew(p) @ np.asarray(Sigma, dtype=float) @ skew(p).T
    return R @ body @ R.T
""",
    ),
    Alternative(
        "left_to_right_einsum",
        "covariance_left_to_right",
        "einsum over the indices",
        """
def covariance_left_to_right(R, Sigma_left):
    R = np.asarray(R, dtype=float)
    return np.einsum("ki,kl,lj->ij", R, np.asarray(Sigma_left, dtype=float), R)
""",
    ),
    Alternative(
        "pose_gn_left",
        "align_pose_gauss_newton",
        "left perturbation: J = [I, -[T p]×], T ← Exp(xi) T",
        """
def align_pose_gauss_newton(P, Q, T0, iters=10):
    T = np.array(T0, dtype=float)
    for _ in range(iters):
        R, t = T[:3, :3], T[:3, 3]
        H, g = np.zeros((6, 6)), np.zeros(6)
        for p, q in zip(np.asarray(P, dtype=float), np.asarray(Q, dtype=float)):
            y = R @ p + t
            J = np.hstack([np.eye(3), -skew(y)])
            H += J.T @ J
            g += J.T @ (y - q)
        T = ExpSE3(np.linalg.solve(H, -g)) @ T
    return T
""",
    ),
    Alternative(
        "robust_weighted_svd",
        "align_pose_robust",
        "iteratively reweighted closed form (weighted Kabsch)",
        """
def align_pose_robust(P, Q, T0, k):
    P = np.asarray(P, dtype=float)
    Q = np.asarray(Q, dtype=float)
    T = np.array(T0, dtype=float)
    for _ in range(2000):
        r = np.linalg.norm(P @ T[:3, :3].T + T[:3, 3] - Q, axis=1)
        w = np.where(r <= k, 1.0, k / np.maximum(r, 1e-300))
        p_mean, q_mean = w @ P / w.sum(), w @ Q / w.sum()
        M = ((Q - q_mean) * w[:, None]).T @ (P - p_mean)
        U, _, Vt = np.linalg.svd(M)
        R = U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt
        new = np.eye(4)
        new[:3, :3], new[:3, 3] = R, q_mean - R @ p_mean
        step = np.max(np.abs(new - T))
        T = new
        if step < 1e-15:
            break
    return T
""",
    ),
]

SAMPLE = {
    "dev": ["left_to_right_wrong_way"],
    "chloe": ["gyro_world_side"],
}
