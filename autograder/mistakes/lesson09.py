"""Typical mistakes and correct alternatives for lesson 09: estimation on Lie groups."""

from . import Alternative, Mistake


def _adjoint(coupling, rotation_first=False):
    block = "Ad[3:, :3]" if rotation_first else "Ad[:3, 3:]"
    return f"""
def adjoint_se3(T):
    T = np.asarray(T, dtype=float)
    R, t = T[:3, :3], T[:3, 3]
    Ad = np.zeros((6, 6))
    Ad[:3, :3] = R
    Ad[3:, 3:] = R
    {block} = {coupling}
    return Ad
"""


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
    # ------------------------------------------------------------ adjoint_se3
    Mistake(
        "adjoint_rotation_first",
        "adjoint_se3",
        "the coupling block bottom-left (rotation-first layout)",
        _adjoint("skew(t) @ R", rotation_first=True),
        hint="written rotation first",
        public_hint="written rotation first",
    ),
    Mistake(
        "adjoint_no_coupling",
        "adjoint_se3",
        "diag(R, R): forgets the coupling of spin and shift",
        _adjoint("np.zeros((3, 3))"),
        hint="adjoint of a pure rotation",
        public_hint="adjoint of a pure rotation",
        classic=True,
    ),
    Mistake(
        "adjoint_coupling_without_R",
        "adjoint_se3",
        "coupling block [t]× instead of [t]× R",
        _adjoint("skew(t)"),
        hint="turned by R before it meets t",
        public_hint="turned by R before it meets t",
    ),
    Mistake(
        "adjoint_coupling_sign",
        "adjoint_se3",
        "coupling block -[t]× R",
        _adjoint("-skew(t) @ R"),
        hint="wrong sign",
        public_hint="wrong sign",
    ),
    Mistake(
        "adjoint_coupling_order",
        "adjoint_se3",
        "coupling block R [t]× instead of [t]× R",
        _adjoint("R @ skew(t)"),
        hint="R [t]× is not [t]× R",
        public_hint="R [t]× is not [t]× R",
    ),
    # ------------------------------------------------------------ jacobians_of_compose
    Mistake(
        "compose_transposed",
        "jacobians_of_compose",
        "J1 = R2 instead of R2ᵀ",
        """
def jacobians_of_compose(R1, R2):
    return np.asarray(R2, dtype=float), np.eye(3)
""",
        hint="transpose of what is needed",
        public_hint="transpose of what is needed",
        classic=True,
    ),
    Mistake(
        "compose_identity",
        "jacobians_of_compose",
        "J1 = J2 = I: ignores the factor the turn crosses",
        """
def jacobians_of_compose(R1, R2):
    return np.eye(3), np.eye(3)
""",
        hint="only after crossing R2",
        public_hint="only after crossing R2",
    ),
    Mistake(
        "compose_left",
        "jacobians_of_compose",
        "the left Jacobians (I, R1)",
        """
def jacobians_of_compose(R1, R2):
    return np.eye(3), np.asarray(R1, dtype=float)
""",
        hint="left Jacobians",
        public_hint="left Jacobians",
    ),
    Mistake(
        "compose_swapped",
        "jacobians_of_compose",
        "returns (J2, J1)",
        """
def jacobians_of_compose(R1, R2):
    return np.eye(3), np.asarray(R2, dtype=float).T
""",
        hint="swapped",
        public_hint="swapped",
    ),
    Mistake(
        "compose_wrong_factor",
        "jacobians_of_compose",
        "J1 = R1ᵀ: the transpose of the wrong factor",
        """
def jacobians_of_compose(R1, R2):
    return np.asarray(R1, dtype=float).T, np.eye(3)
""",
        hint="not on R1",
        public_hint="not on R1",
    ),
    Mistake(
        "compose_jacobian_float32",
        "jacobians_of_compose",
        "J1 = R2ᵀ stored in float32",
        """
def jacobians_of_compose(R1, R2):
    return np.asarray(R2, dtype=np.float32).T, np.eye(3)
""",
        hint="float32 rounding",
        public_hint="float32 rounding",
    ),
    # ------------------------------------------------------------ jacobian_of_inverse
    Mistake(
        "inverse_left",
        "jacobian_of_inverse",
        "-Rᵀ: the Jacobian of the left perturbations",
        """
def jacobian_of_inverse(R):
    return -np.asarray(R, dtype=float).T
""",
        hint="perturbations on the left of R and of R⁻¹",
        public_hint="perturbations on the left of R and of R⁻¹",
        classic=True,
    ),
    Mistake(
        "inverse_not_moved",
        "jacobian_of_inverse",
        "-I: Exp(-d) left on the left of Rᵀ",
        """
def jacobian_of_inverse(R):
    return -np.eye(3)
""",
        hint="sits on the left of Rᵀ",
        public_hint="sits on the left of Rᵀ",
    ),
    Mistake(
        "inverse_sign",
        "jacobian_of_inverse",
        "+R: the sign of the inverted turn lost",
        """
def jacobian_of_inverse(R):
    return np.asarray(R, dtype=float).copy()
""",
        hint="Exp(d)⁻¹ = Exp(-d)",
        public_hint="Exp(d)⁻¹ = Exp(-d)",
    ),
    Mistake(
        "inverse_transpose",
        "jacobian_of_inverse",
        "Rᵀ: the inverse of R instead of its Jacobian",
        """
def jacobian_of_inverse(R):
    return np.asarray(R, dtype=float).T.copy()
""",
        hint="neither the sign nor the side",
        public_hint="neither the sign nor the side",
    ),
    Mistake(
        "inverse_jacobian_float32",
        "jacobian_of_inverse",
        "-R stored in float32",
        """
def jacobian_of_inverse(R):
    return -np.asarray(R, dtype=np.float32)
""",
        hint="float32 rounding",
        public_hint="float32 rounding",
    ),
    # ------------------------------------------------------------ jacobian_transform_point
    Mistake(
        "point_left",
        "jacobian_transform_point",
        "[I, -[T p]×]: the Jacobian of the left perturbation",
        """
def jacobian_transform_point(T, p):
    T = np.asarray(T, dtype=float)
    return np.hstack([np.eye(3), -skew(T[:3, :3] @ np.asarray(p, dtype=float) + T[:3, 3])])
""",
        hint="left perturbation Exp(xi) T",
        public_hint="left perturbation Exp(xi) T",
        classic=True,
    ),
    Mistake(
        "point_rotation_first",
        "jacobian_transform_point",
        "[-R [p]×, R]: rotation columns first",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([-R @ skew(p), R])
""",
        hint="the first three columns are for",
        public_hint="the first three columns are for",
    ),
    Mistake(
        "point_translation_identity",
        "jacobian_transform_point",
        "[I, -R [p]×]: the shift not turned by R",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([np.eye(3), -R @ skew(p)])
""",
        hint="its block is R, not I",
        public_hint="its block is R, not I",
    ),
    Mistake(
        "point_sign",
        "jacobian_transform_point",
        "[R, R [p]×]: the sign of [phi]× p = -[p]× phi lost",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([R, R @ skew(p)])
""",
        hint="[phi]× p = -[p]× phi",
        public_hint="[phi]× p = -[p]× phi",
    ),
    Mistake(
        "point_world_rotation",
        "jacobian_transform_point",
        "[R, -[R p]×]: a left rotation block",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([R, -skew(R @ np.asarray(p, dtype=float))])
""",
        hint="-[R p]× is the rotation block of a left perturbation",
        public_hint="-[R p]× is the rotation block of a left perturbation",
    ),
    # ------------------------------------------------------------ quat_power
    Mistake(
        "power_full_angle",
        "quat_power",
        "[cos 2tα, sin 2tα u]: the full rotation angle in place of α",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    s = np.linalg.norm(q[1:])
    theta = 2.0 * np.arctan2(s, q[0])
    axis = q[1:] / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[np.cos(t * theta)], np.sin(t * theta) * axis])
""",
        hint="already holds the half angle",
        public_hint="already holds the half angle",
    ),
    Mistake(
        "power_arccos",
        "quat_power",
        "α = arccos(w): small angles are lost",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    s = np.linalg.norm(q[1:])
    alpha = np.arccos(np.clip(q[0], -1.0, 1.0))
    axis = q[1:] / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * axis])
""",
        hint="arccos(w) loses small angles",
        public_hint="arccos(w) rounds small angles",
        classic=True,
    ),
    Mistake(
        "power_canonical_sign",
        "quat_power",
        "flips q to w >= 0 first (q and -q get one power)",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    if q[0] < 0.0:
        q = -q
    s = np.linalg.norm(q[1:])
    alpha = np.arctan2(s, q[0])
    axis = q[1:] / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * axis])
""",
        hint="do not flip the sign of q",
        public_hint="do not flip the sign of q",
    ),
    Mistake(
        "power_axis_not_unit",
        "quat_power",
        "uses v = sin α u as the axis",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    alpha = np.arctan2(np.linalg.norm(q[1:]), q[0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * q[1:]])
""",
        hint="divide the vector part by its length",
        public_hint="divide the vector part by its length",
    ),
    Mistake(
        "power_identity_nan",
        "quat_power",
        "divides by |v| = 0 at the identity",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    s = np.linalg.norm(q[1:])
    alpha = np.arctan2(s, q[0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * q[1:] / s])
""",
        hint="guard the division",
        public_hint="guard the division",
    ),
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
        hint="weights (k/r)² beyond k",
        public_hint="weights (k/r)² beyond k",
    ),
]

ALTERNATIVES = [
    Alternative(
        "adjoint_by_blocks",
        "adjoint_se3",
        "np.block with the cross products written as matrices",
        """
def adjoint_se3(T):
    T = np.asarray(T, dtype=float)
    R, t = T[:3, :3], T[:3, 3]
    coupling = np.column_stack([np.cross(t, R[:, j]) for j in range(3)])
    return np.block([[R, coupling], [np.zeros((3, 3)), R]])
""",
    ),
    Alternative(
        "compose_by_inverse",
        "jacobians_of_compose",
        "J1 = inv(R2), returned as a list",
        """
def jacobians_of_compose(R1, R2):
    return [np.linalg.inv(np.asarray(R2, dtype=float)), np.identity(3)]
""",
    ),
    Alternative(
        "inverse_by_adjoint",
        "jacobian_of_inverse",
        "minus the adjoint of R, built from its columns",
        """
def jacobian_of_inverse(R):
    R = np.asarray(R, dtype=float)
    return -np.column_stack([R @ e for e in np.eye(3)])
""",
    ),
    Alternative(
        "point_by_generators",
        "jacobian_transform_point",
        "T times each of the six generators of se(3)",
        """
def jacobian_transform_point(T, p):
    T = np.asarray(T, dtype=float)
    p_h = np.append(np.asarray(p, dtype=float), 1.0)
    columns = []
    for j in range(6):
        G = np.zeros((4, 4))
        if j < 3:
            G[j, 3] = 1.0
        else:
            G[:3, :3] = skew(np.eye(3)[j - 3])
        columns.append((T @ G @ p_h)[:3])
    return np.column_stack(columns)
""",
    ),
    Alternative(
        "power_by_complex_numbers",
        "quat_power",
        "w + i|v| raised to t with Python's complex power",
        """
def quat_power(q, t):
    w, x, y, z = np.asarray(q, dtype=float)
    s = np.sqrt(x * x + y * y + z * z)
    power = complex(w, s) ** t              # the principal branch: the angle of w + i s is α in [0, π]
    axis = np.array([x, y, z]) / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[power.real], power.imag * axis])
""",
    ),
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
