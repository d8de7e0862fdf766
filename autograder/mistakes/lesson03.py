"""Typical mistakes for lesson 03: the Lie algebra so(3), exp and log."""

from . import Mistake

MISTAKES = [
    Mistake("hat_transposed", "hat", "the signs of [w]× swapped (the transpose, -[w]×)", '''
def hat(w):
    w1, w2, w3 = np.asarray(w, dtype=float)
    return np.array([[0.0, w3, -w2], [-w3, 0.0, w1], [w2, -w1, 0.0]])
'''),
    Mistake("vee_wrong_sign", "vee", "reads the entries above the diagonal, returning -w", '''
def vee(W):
    W = np.asarray(W, dtype=float)
    return np.array([W[1, 2], W[2, 0], W[0, 1]])
'''),
    Mistake("bracket_anticommutator", "bracket", "AB + BA instead of AB - BA", '''
def bracket(A, B):
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    return A @ B + B @ A
'''),
    Mistake("bracket_elementwise", "bracket", "A * B - B * A with the entry-wise product (always zero)", '''
def bracket(A, B):
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    return A * B - B * A
'''),
    Mistake("exp_series_starts_at_one", "exp_series", "the sum starts at k = 1 (the identity is missing)", '''
def exp_series(W, n_terms):
    W = np.asarray(W, dtype=float)
    total = np.zeros_like(W)
    term = np.eye(W.shape[0])
    for k in range(1, n_terms + 1):
        term = term @ W / k
        total = total + term
    return total
'''),
    Mistake("exp_series_entrywise_power", "exp_series", "W ** k (entry-wise power) instead of the matrix power", '''
def exp_series(W, n_terms):
    from math import factorial
    W = np.asarray(W, dtype=float)
    return sum(W ** k / factorial(k) for k in range(n_terms))
'''),
    Mistake("exp_so3_identity_below_threshold", "exp_so3", "returns I when the angle is small", '''
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    if theta < 1e-6:
        return np.eye(3)
    k = w / theta
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(theta) * K + (1 - np.cos(theta)) * K @ K
'''),
    Mistake("exp_so3_transposed", "exp_so3", "minus sign on the sin θ term (the inverse rotation)", '''
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    if theta == 0:
        return np.eye(3)
    k = w / theta
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) - np.sin(theta) * K + (1 - np.cos(theta)) * K @ K
'''),
    Mistake("log_so3_arccos_no_pi_branch", "log_so3",
            "arccos of the trace and division by sin θ, without a branch at π (Modern Robotics' MatrixLog3)", '''
def log_so3(R):
    R = np.asarray(R, dtype=float)
    c = (np.trace(R) - 1.0) / 2.0
    if c >= 1.0:
        return np.zeros(3)
    theta = np.arccos(max(c, -1.0))
    if np.sin(theta) == 0.0:
        return np.zeros(3)
    W = theta / (2.0 * np.sin(theta)) * (R - R.T)
    return np.array([W[2, 1], W[0, 2], W[1, 0]])
'''),
    Mistake("log_so3_axis_sign_not_fixed", "log_so3",
            "near π takes the axis from (R + Rᵀ)/2 but never fixes its sign", '''
def log_so3(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = np.arctan2(s, c)
    if c > 0.0:
        return a if s == 0.0 else (theta / s) * a
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    return theta * B[:, j] / np.linalg.norm(B[:, j])
'''),
    Mistake("axis_angle_nan_at_zero", "axis_angle", "u = w / θ without a θ = 0 case (NaN for the identity)", '''
def axis_angle(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = float(np.arctan2(s, c))
    if c > 0.0:
        with np.errstate(invalid="ignore", divide="ignore"):
            return a / s, theta
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.linalg.norm(B[:, j])
    return (-u if u @ a < 0 else u), theta
'''),
    Mistake("axis_angle_degrees", "axis_angle", "returns the angle in degrees", '''
def axis_angle(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = float(np.degrees(np.arctan2(s, c)))
    if c > 0.0:
        return (np.array([1.0, 0.0, 0.0]) if s == 0.0 else a / s), theta
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.linalg.norm(B[:, j])
    return (-u if u @ a < 0 else u), theta
'''),
    Mistake("axis_angle_arccos_unclipped", "axis_angle",
            "θ = arccos((tr R - 1)/2) without clipping: NaN when rounding pushes the trace above 3", '''
def axis_angle(R):
    R = np.asarray(R, dtype=float)
    theta = float(np.arccos((np.trace(R) - 1.0) / 2.0))
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    if theta < np.pi / 2:
        s = np.linalg.norm(a)
        return (np.array([1.0, 0.0, 0.0]) if s == 0.0 else a / s), theta
    B = 0.5 * (R + R.T) - np.cos(theta) * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.linalg.norm(B[:, j])
    return (-u if u @ a < 0 else u), theta
'''),
    Mistake("axis_from_eigen_row", "axis_from_eigen", "takes a row of the eigenvector matrix instead of a column", '''
def axis_from_eigen(R):
    values, vectors = np.linalg.eig(np.asarray(R, dtype=float))
    k = int(np.argmin(np.abs(values - 1.0)))
    u = np.real(vectors[k])
    return u / np.linalg.norm(u)
'''),
    Mistake("axis_from_eigen_first", "axis_from_eigen", "takes the first eigenvector, whatever its eigenvalue", '''
def axis_from_eigen(R):
    values, vectors = np.linalg.eig(np.asarray(R, dtype=float))
    u = np.real(vectors[:, 0])
    return u / np.linalg.norm(u)
'''),
]

SAMPLE = {
    "dev": ["hat_transposed", "exp_so3_transposed", "axis_from_eigen_row"],   # transposes matrices
    "emma": ["axis_angle_degrees"],                                            # works in degrees
}
