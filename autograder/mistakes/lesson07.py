"""Typical mistakes for lesson 07: poses and rigid-body transformations."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "exp_se3_one_term_below_1e_2",
        "exp_se3",
        "V's one-term series I + W/2 + W²/6 below 1e-2 (off by 4e-8 |rho| just below it)",
        """
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    rho, phi = xi[:3], xi[3:]
    theta = np.linalg.norm(phi)
    W = skew(phi)
    if theta < 1e-2:
        V = np.eye(3) + W / 2 + W @ W / 6
    else:
        V = np.eye(3) + (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
    T = np.eye(4)
    T[:3, :3] = Exp(phi)
    T[:3, 3] = V @ rho
    return T
""",
        hint="V's one-term series I + W/2 + W²/6",
        public_hint="keep its θ² and θ⁴ terms",
    ),
    Mistake(
        "make_pose_t_in_bottom_row",
        "make_pose",
        "puts t in the bottom row (the transposed layout)",
        """
def make_pose(R, t):
    T = np.eye(4)
    T[:3, :3] = np.asarray(R, dtype=float)
    T[3, :3] = np.asarray(t, dtype=float)
    return T
""",
        hint="not the bottom row",
        public_hint="not the bottom row",
    ),
    Mistake(
        "pose_inverse_transpose",
        "pose_inverse",
        "inverts a pose with the plain transpose of T",
        """
def pose_inverse(T):
    return np.asarray(T, dtype=float).T.copy()
""",
        hint="plain transpose of T",
        public_hint="plain transpose of T",
        classic=True,
    ),
    Mistake(
        "pose_inverse_negates_t",
        "pose_inverse",
        "transposes R but negates t without turning it",
        """
def pose_inverse(T):
    T = np.asarray(T, dtype=float)
    T_inv = np.eye(4)
    T_inv[:3, :3] = T[:3, :3].T
    T_inv[:3, 3] = -T[:3, 3]
    return T_inv
""",
        hint="try p = 0, b's origin",
        public_hint="try p = 0, b's origin",
    ),
    Mistake(
        "pose_compose_reversed",
        "pose_compose",
        "multiplies the poses in the wrong order",
        """
def pose_compose(T_ab, T_bc):
    return np.asarray(T_bc, dtype=float) @ np.asarray(T_ab, dtype=float)
""",
        hint="order is reversed",
        public_hint="order is reversed",
    ),
    Mistake(
        "to_homogeneous_appends_zero",
        "to_homogeneous",
        "appends 0 (a direction) where a point needs 1",
        """
def to_homogeneous(P):
    P = np.asarray(P, dtype=float)
    return np.concatenate([P, np.zeros(P.shape[:-1] + (1,))], axis=-1)
""",
        hint="marks a direction",
        public_hint="marks a direction",
    ),
    Mistake(
        "from_homogeneous_no_divide",
        "from_homogeneous",
        "drops the last coordinate without dividing",
        """
def from_homogeneous(P_h):
    return np.asarray(P_h, dtype=float)[..., :3]
""",
        hint="before dropping it",
        public_hint="before dropping it",
    ),
    Mistake(
        "transform_points_T_transposed",
        "transform_points",
        "uses T.T: multiplies rows by T instead of T.T",
        """
def transform_points(T, P):
    T = np.asarray(T, dtype=float)
    P = np.asarray(P, dtype=float)
    P_h = np.concatenate([P, np.ones(P.shape[:-1] + (1,))], axis=-1)
    moved = P_h @ T
    return moved[..., :3] / moved[..., 3:]
""",
        hint="P_h @ T.T",
        public_hint="P_h @ T.T",
    ),
    Mistake(
        "transform_points_square_batch_as_columns",
        "transform_points",
        "tells one point from a batch by shape[0] == 3, so a batch of 3 points is read as columns",
        """
def transform_points(T, P):
    T = np.asarray(T, dtype=float)
    P = np.asarray(P, dtype=float)
    if P.shape[0] == 3:
        return T[:3, :3] @ P + (T[:3, 3:] if P.ndim == 2 else T[:3, 3])
    return P @ T[:3, :3].T + T[:3, 3]
""",
        hint="read as 3 columns",
        public_hint="read as 3 columns",
    ),
    Mistake(
        "transform_points_no_translation",
        "transform_points",
        "rotates the points but forgets the shift",
        """
def transform_points(T, P):
    T = np.asarray(T, dtype=float)
    return np.asarray(P, dtype=float) @ T[:3, :3].T
""",
        hint="translation is missing",
        public_hint="translation is missing",
    ),
    Mistake(
        "exp_se3_forgets_V",
        "exp_se3",
        "uses rho as the translation (forgets V)",
        """
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    T = np.eye(4)
    T[:3, :3] = Exp(xi[3:])
    T[:3, 3] = xi[:3]
    return T
""",
        hint="your translation is rho itself although phi ≠ 0",
        public_hint="your translation is rho itself although phi ≠ 0",
        classic=True,
    ),
    Mistake(
        "exp_se3_phi_first",
        "exp_se3",
        "reads xi as [phi, rho] (rotation part first)",
        """
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    phi, rho = xi[:3], xi[3:]
    theta = np.linalg.norm(phi)
    W = skew(phi)
    if theta < 1e-2:
        a, b = 0.5 - theta**2 / 24.0, 1.0 / 6.0 - theta**2 / 120.0
    else:
        a, b = (1.0 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
    T = np.eye(4)
    T[:3, :3] = Exp(phi)
    T[:3, 3] = (np.eye(3) + a * W + b * W @ W) @ rho
    return T
""",
        hint="xi = [rho, phi]",
        public_hint="xi = [rho, phi]",
    ),
    Mistake(
        "exp_se3_nan_at_zero",
        "exp_se3",
        "no small-angle branch: 0/0 at phi = 0",
        """
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    rho, phi = xi[:3], xi[3:]
    theta = np.linalg.norm(phi)
    W = skew(phi)
    V = np.eye(3) + (1.0 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
    T = np.eye(4)
    T[:3, :3] = Exp(phi)
    T[:3, 3] = V @ rho
    return T
""",
        hint="below θ = 1e-2",
        public_hint="below θ = 1e-2",
    ),
    Mistake(
        "log_se3_forgets_V_inverse",
        "log_se3",
        "returns t itself as rho (forgets V⁻¹)",
        """
def log_se3(T):
    T = np.asarray(T, dtype=float)
    return np.concatenate([T[:3, 3], Log(T[:3, :3])])
""",
        hint="V(phi)⁻¹ t, not t itself",
        public_hint="V(phi)⁻¹ t, not t itself",
    ),
    Mistake(
        "log_se3_phi_first",
        "log_se3",
        "returns [phi, rho] (rotation part first)",
        """
def log_se3(T):
    T = np.asarray(T, dtype=float)
    phi = Log(T[:3, :3])
    theta = np.linalg.norm(phi)
    W = skew(phi)
    c = 1.0 / 12.0 if theta < 1e-2 else (1.0 - (theta / 2.0) / np.tan(theta / 2.0)) / theta**2
    rho = (np.eye(3) - 0.5 * W + c * W @ W) @ T[:3, 3]
    return np.concatenate([phi, rho])
""",
        hint="xi = [rho, phi]",
        public_hint="xi = [rho, phi]",
    ),
    Mistake(
        "log_se3_cancellation",
        "log_se3",
        "closed form of c with 1 - cos θ everywhere except θ = 0",
        """
def log_se3(T):
    T = np.asarray(T, dtype=float)
    phi = Log(T[:3, :3])
    theta = np.linalg.norm(phi)
    W = skew(phi)
    if theta == 0.0:
        c = 1.0 / 12.0
    else:
        c = (1.0 - theta * np.sin(theta) / (2.0 * (1.0 - np.cos(theta)))) / theta**2
    rho = (np.eye(3) - 0.5 * W + c * W @ W) @ T[:3, 3]
    return np.concatenate([rho, phi])
""",
        hint="use the series c = 1/12",
        public_hint="use the series c = 1/12",
    ),
    Mistake(
        "make_pose_R_transposed",
        "make_pose",
        "puts Rᵀ in the top-left block",
        """
def make_pose(R, t):
    T = np.eye(4)
    T[:3, :3] = np.asarray(R, dtype=float).T
    T[:3, 3] = t
    return T
""",
        hint="not its transpose",
        public_hint="not its transpose",
    ),
    Mistake(
        "make_pose_bottom_zero",
        "make_pose",
        "a zero matrix with R and t, bottom-right 0",
        """
def make_pose(R, t):
    T = np.zeros((4, 4))
    T[:3, :3] = R
    T[:3, 3] = t
    return T
""",
        hint="np.eye(4)",
        public_hint="np.eye(4)",
    ),
    Mistake(
        "make_pose_integer_lists",
        "make_pose",
        "np.hstack of lists without dtype: fails on a list t",
        """
def make_pose(R, t):
    return np.vstack([np.hstack([R, t.reshape(3, 1)]), [0.0, 0.0, 0.0, 1.0]])
""",
        hint="np.asarray",
        public_hint="np.asarray",
    ),
    Mistake(
        "pose_inverse_t_unchanged",
        "pose_inverse",
        "transposes R and keeps t",
        """
def pose_inverse(T):
    T = np.asarray(T, dtype=float)
    out = np.eye(4)
    out[:3, :3] = T[:3, :3].T
    out[:3, 3] = T[:3, 3]
    return out
""",
        hint="kept t unchanged",
        public_hint="kept t unchanged",
    ),
    Mistake(
        "pose_inverse_R_not_transposed",
        "pose_inverse",
        "keeps R, uses -R t",
        """
def pose_inverse(T):
    T = np.asarray(T, dtype=float)
    out = np.eye(4)
    out[:3, :3] = T[:3, :3]
    out[:3, 3] = -T[:3, :3] @ T[:3, 3]
    return out
""",
        hint="rotation block of the inverse is still R",
        public_hint="rotation block of the inverse is still R",
    ),
    Mistake(
        "pose_compose_elementwise",
        "pose_compose",
        "T_ab * T_bc entry by entry",
        """
def pose_compose(T_ab, T_bc):
    return np.asarray(T_ab, dtype=float) * np.asarray(T_bc, dtype=float)
""",
        hint="entry by entry",
        public_hint="entry by entry",
    ),
    Mistake(
        "pose_compose_adds_translations",
        "pose_compose",
        "R_ab R_bc and t_ab + t_bc (forgets to turn t_bc)",
        """
def pose_compose(T_ab, T_bc):
    A, B = np.asarray(T_ab, dtype=float), np.asarray(T_bc, dtype=float)
    out = np.eye(4)
    out[:3, :3] = A[:3, :3] @ B[:3, :3]
    out[:3, 3] = A[:3, 3] + B[:3, 3]
    return out
""",
        hint="turned by R_ab",
        public_hint="turned by R_ab",
    ),
    Mistake(
        "pose_compose_inverts_first",
        "pose_compose",
        "T_abᵀ T_bc",
        """
def pose_compose(T_ab, T_bc):
    return np.asarray(T_ab, dtype=float).T @ np.asarray(T_bc, dtype=float)
""",
        hint="transposes T_ab",
        public_hint="transposes T_ab",
    ),
    Mistake(
        "to_homogeneous_prepends",
        "to_homogeneous",
        "puts the 1 first",
        """
def to_homogeneous(P):
    P = np.asarray(P, dtype=float)
    return np.concatenate([np.ones(P.shape[:-1] + (1,)), P], axis=-1)
""",
        hint="the 1 goes last",
        public_hint="the 1 goes last",
    ),
    Mistake(
        "to_homogeneous_rows_only",
        "to_homogeneous",
        "np.column_stack: a single point becomes a column",
        """
def to_homogeneous(P):
    P = np.atleast_2d(np.asarray(P, dtype=float))
    return np.column_stack([P, np.ones(len(P))])
""",
        hint="became a batch",
        public_hint="became a batch",
    ),
    Mistake(
        "to_homogeneous_appends_row",
        "to_homogeneous",
        "appends a row of ones instead of a column",
        """
def to_homogeneous(P):
    P = np.asarray(P, dtype=float)
    if P.ndim == 1:
        return np.append(P, 1.0)
    return np.vstack([P, np.ones(P.shape[1])])
""",
        hint="append a column",
        public_hint="append a column",
    ),
    Mistake(
        "from_homogeneous_divides_all",
        "from_homogeneous",
        "divides by the first coordinate",
        """
def from_homogeneous(P_h):
    P_h = np.asarray(P_h, dtype=float)
    return P_h[..., 1:] / P_h[..., :1]
""",
        hint="divided by the first coordinate",
        public_hint="divided by the first coordinate",
    ),
    Mistake(
        "from_homogeneous_multiplies",
        "from_homogeneous",
        "multiplies by the last coordinate",
        """
def from_homogeneous(P_h):
    P_h = np.asarray(P_h, dtype=float)
    return P_h[..., :-1] * P_h[..., -1:]
""",
        hint="multiplied by the last coordinate",
        public_hint="multiplied by the last coordinate",
    ),
    Mistake(
        "from_homogeneous_single_only",
        "from_homogeneous",
        "P_h[:3] / P_h[3]: right for one point only",
        """
def from_homogeneous(P_h):
    P_h = np.asarray(P_h, dtype=float)
    return P_h[:3] / P_h[3]
""",
        hint="one point only",
        public_hint="one point only",
    ),
    Mistake(
        "transform_points_translation_first",
        "transform_points",
        "R (p + t): shifts before turning",
        """
def transform_points(T, P):
    T, P = np.asarray(T, dtype=float), np.asarray(P, dtype=float)
    return (P + T[:3, 3]) @ T[:3, :3].T
""",
        hint="rotate first, then shift",
        public_hint="rotate first, then shift",
    ),
    Mistake(
        "transform_points_no_asarray",
        "transform_points",
        "T[:3, :3] on a list fails",
        """
def transform_points(T, P):
    return np.asarray(P, dtype=float) @ T[:3, :3].T + T[:3, 3]
""",
        hint="np.asarray",
        public_hint="np.asarray",
    ),
    Mistake(
        "exp_se3_guarded_only_at_zero",
        "exp_se3",
        "V's closed form everywhere except θ = 0 (W coefficient 0 at tiny θ)",
        """
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    rho, phi = xi[:3], xi[3:]
    theta = np.linalg.norm(phi)
    W = skew(phi)
    if theta == 0.0:
        V = np.eye(3)
    else:
        V = np.eye(3) + (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
    T = np.eye(4)
    T[:3, :3] = Exp(phi)
    T[:3, 3] = V @ rho
    return T
""",
        hint="below θ = 1e-2",
        public_hint="below θ = 1e-2",
    ),
    Mistake(
        "log_se3_c_constant",
        "log_se3",
        "c = 1/12 at every angle",
        """
def log_se3(T):
    T = np.asarray(T, dtype=float)
    phi = Log(T[:3, :3])
    W = skew(phi)
    return np.concatenate([(np.eye(3) - 0.5 * W + W @ W / 12.0) @ T[:3, 3], phi])
""",
        hint="only its value at θ = 0",
        public_hint="only its value at θ = 0",
    ),
    Mistake(
        "log_se3_unit_axis",
        "log_se3",
        "V⁻¹ written with the unit axis phi/θ: 0/0 at θ = 0 although c has its series",
        """
def log_se3(T):
    T = np.asarray(T, dtype=float)
    phi = Log(T[:3, :3])
    theta = np.linalg.norm(phi)
    U = skew(phi / theta)
    if theta < 1e-2:
        c = 1.0 / 12.0 + theta**2 / 720.0 + theta**4 / 30240.0
    else:
        c = (1.0 - (theta / 2.0) / np.tan(theta / 2.0)) / theta**2
    V_inv = np.eye(3) - 0.5 * theta * U + c * theta**2 * (U @ U)
    return np.concatenate([V_inv @ T[:3, 3], phi])
""",
        hint="use the series c = 1/12",
        public_hint="use the series c = 1/12",
    ),
]

ALTERNATIVES = [
    Alternative(
        "to_homogeneous_pad",
        "to_homogeneous",
        "np.pad with a constant 1",
        """
def to_homogeneous(P):
    P = np.asarray(P, dtype=float)
    return np.pad(P, [(0, 0)] * (P.ndim - 1) + [(0, 1)], constant_values=1.0)
""",
    ),
    Alternative(
        "from_homogeneous_list",
        "from_homogeneous",
        "divides everything, then drops the 1",
        """
def from_homogeneous(P_h):
    P_h = np.asarray(P_h, dtype=float)
    return (P_h / P_h[..., -1:])[..., :3]
""",
    ),
    Alternative(
        "pose_compose_blocks",
        "pose_compose",
        "blocks: R_ab R_bc and R_ab t_bc + t_ab",
        """
def pose_compose(T_ab, T_bc):
    A, B = np.asarray(T_ab, dtype=float), np.asarray(T_bc, dtype=float)
    out = np.eye(4)
    out[:3, :3] = A[:3, :3] @ B[:3, :3]
    out[:3, 3] = A[:3, :3] @ B[:3, 3] + A[:3, 3]
    return out
""",
    ),
    Alternative(
        "make_pose_block_list",
        "make_pose",
        "np.block",
        """
def make_pose(R, t):
    R = np.asarray(R, dtype=float)
    t = np.asarray(t, dtype=float).reshape(3, 1)
    return np.block([[R, t], [np.zeros((1, 3)), np.ones((1, 1))]])
""",
    ),
    Alternative(
        "transform_points_homogeneous",
        "transform_points",
        "through homogeneous coordinates",
        """
def transform_points(T, P):
    P = np.asarray(P, dtype=float)
    P_h = np.concatenate([P, np.ones(P.shape[:-1] + (1,))], axis=-1)
    return (P_h @ np.asarray(T, dtype=float).T)[..., :3]
""",
    ),
    Alternative(
        "exp_se3_expm_free_sinc",
        "exp_se3",
        "V from the half-angle forms with np.sinc (no branch)",
        """
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    rho, phi = xi[:3], xi[3:]
    theta = np.linalg.norm(phi)
    W = skew(phi)
    a = 0.5 * np.sinc(theta / (2 * np.pi)) ** 2                     # (1 - cos θ)/θ² = sin²(θ/2)/(θ²/2)
    b = 1 / 6 - theta**2 / 120 + theta**4 / 5040 if theta < 1e-2 else (theta - np.sin(theta)) / theta**3
    T = np.eye(4)
    T[:3, :3] = Exp(phi)
    T[:3, 3] = (np.eye(3) + a * W + b * W @ W) @ rho
    return T
""",
    ),
    Alternative(
        "log_se3_solve",
        "log_se3",
        "rho = solve(V, t) with V's series below 1e-2",
        """
def log_se3(T):
    T = np.asarray(T, dtype=float)
    phi = Log(T[:3, :3])
    theta = np.linalg.norm(phi)
    W = skew(phi)
    if theta < 1e-2:
        a, b = 0.5 - theta**2 / 24 + theta**4 / 720, 1 / 6 - theta**2 / 120 + theta**4 / 5040
    else:
        a, b = (1 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
    return np.concatenate([np.linalg.solve(np.eye(3) + a * W + b * W @ W, T[:3, 3]), phi])
""",
    ),
]

SAMPLE = {
    "dev": ["pose_inverse_transpose", "transform_points_T_transposed"],
    "chloe": ["from_homogeneous_no_divide"],
}
