"""Typical mistakes for lesson 07: poses and rigid-body transformations."""

from . import Mistake

MISTAKES = [
    Mistake("make_pose_t_in_bottom_row", "make_pose", "puts t in the bottom row (the transposed layout)", '''
def make_pose(R, t):
    T = np.eye(4)
    T[:3, :3] = np.asarray(R, dtype=float)
    T[3, :3] = np.asarray(t, dtype=float)
    return T
'''),
    Mistake("pose_inverse_transpose", "pose_inverse", "inverts a pose with the plain transpose of T", '''
def pose_inverse(T):
    return np.asarray(T, dtype=float).T.copy()
'''),
    Mistake("pose_inverse_negates_t", "pose_inverse", "transposes R but negates t without turning it", '''
def pose_inverse(T):
    T = np.asarray(T, dtype=float)
    T_inv = np.eye(4)
    T_inv[:3, :3] = T[:3, :3].T
    T_inv[:3, 3] = -T[:3, 3]
    return T_inv
'''),
    Mistake("pose_compose_reversed", "pose_compose", "multiplies the poses in the wrong order", '''
def pose_compose(T_ab, T_bc):
    return np.asarray(T_bc, dtype=float) @ np.asarray(T_ab, dtype=float)
'''),
    Mistake("to_homogeneous_appends_zero", "to_homogeneous", "appends 0 (a direction) where a point needs 1", '''
def to_homogeneous(P):
    P = np.asarray(P, dtype=float)
    return np.concatenate([P, np.zeros(P.shape[:-1] + (1,))], axis=-1)
'''),
    Mistake("from_homogeneous_no_divide", "from_homogeneous", "drops the last coordinate without dividing", '''
def from_homogeneous(P_h):
    return np.asarray(P_h, dtype=float)[..., :3]
'''),
    Mistake("transform_points_T_transposed", "transform_points", "uses T.T: multiplies rows by T instead of T.T", '''
def transform_points(T, P):
    T = np.asarray(T, dtype=float)
    P = np.asarray(P, dtype=float)
    P_h = np.concatenate([P, np.ones(P.shape[:-1] + (1,))], axis=-1)
    moved = P_h @ T
    return moved[..., :3] / moved[..., 3:]
'''),
    Mistake("transform_points_no_translation", "transform_points", "rotates the points but forgets the shift", '''
def transform_points(T, P):
    T = np.asarray(T, dtype=float)
    return np.asarray(P, dtype=float) @ T[:3, :3].T
'''),
    Mistake("exp_se3_forgets_V", "exp_se3", "uses rho as the translation (forgets V)", '''
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float)
    T = np.eye(4)
    T[:3, :3] = Exp(xi[3:])
    T[:3, 3] = xi[:3]
    return T
'''),
    Mistake("exp_se3_phi_first", "exp_se3", "reads xi as [phi, rho] (rotation part first)", '''
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
'''),
    Mistake("exp_se3_nan_at_zero", "exp_se3", "no small-angle branch: 0/0 at phi = 0", '''
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
'''),
    Mistake("log_se3_forgets_V_inverse", "log_se3", "returns t itself as rho (forgets V⁻¹)", '''
def log_se3(T):
    T = np.asarray(T, dtype=float)
    return np.concatenate([T[:3, 3], Log(T[:3, :3])])
'''),
    Mistake("log_se3_phi_first", "log_se3", "returns [phi, rho] (rotation part first)", '''
def log_se3(T):
    T = np.asarray(T, dtype=float)
    phi = Log(T[:3, :3])
    theta = np.linalg.norm(phi)
    W = skew(phi)
    c = 1.0 / 12.0 if theta < 1e-2 else (1.0 - (theta / 2.0) / np.tan(theta / 2.0)) / theta**2
    rho = (np.eye(3) - 0.5 * W + c * W @ W) @ T[:3, 3]
    return np.concatenate([phi, rho])
'''),
    Mistake("log_se3_cancellation", "log_se3", "closed form of c with 1 - cos θ everywhere except θ = 0", '''
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
'''),
]

SAMPLE = {
    "dev": ["pose_inverse_transpose", "transform_points_T_transposed"],
    "chloe": ["from_homogeneous_no_divide"],
}
