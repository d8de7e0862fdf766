"""Typical mistakes for lesson 08: estimating a rotation."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "align_svd_reflection",
        "align_svd",
        "U Vᵀ without the determinant fix",
        """
def align_svd(P, Q):
    U, _, Vt = np.linalg.svd(np.asarray(Q, dtype=float).T @ np.asarray(P, dtype=float))
    return U @ Vt
""",
        hint="determinant fix",
        public_hint="determinant fix",
        classic=True,
    ),
    Mistake(
        "align_svd_transposed",
        "align_svd",
        "correlation matrix Pᵀ Q instead of Qᵀ P (returns Rᵀ)",
        """
def align_svd(P, Q):
    U, _, Vt = np.linalg.svd(np.asarray(P, dtype=float).T @ np.asarray(Q, dtype=float))
    d = np.sign(np.linalg.det(U @ Vt))
    return U @ np.diag([1.0, 1.0, d]) @ Vt
""",
        hint="Pᵀ Q gives Rᵀ",
        public_hint="Pᵀ Q gives Rᵀ",
    ),
    Mistake(
        "align_svd_least_squares",
        "align_svd",
        "unconstrained least squares: not a rotation",
        """
def align_svd(P, Q):
    X, *_ = np.linalg.lstsq(np.asarray(P, dtype=float), np.asarray(Q, dtype=float), rcond=None)
    return X.T
""",
        hint="unconstrained least-squares",
        public_hint="unconstrained least-squares",
    ),
    Mistake(
        "align_gauss_newton_left_jacobian",
        "align_gauss_newton",
        "left Jacobian -[R p]× with the right update R Exp(δ)",
        """
def align_gauss_newton(P, Q, R0, iters=10):
    R = np.array(R0, dtype=float)
    for _ in range(iters):
        H, g = np.zeros((3, 3)), np.zeros(3)
        for p, q in zip(np.asarray(P, dtype=float), np.asarray(Q, dtype=float)):
            J = -skew(R @ p)
            H += J.T @ J
            g += J.T @ (R @ p - q)
        R = R @ Exp(np.linalg.solve(H, -g))
    return R
""",
        hint="mixes two conventions",
        public_hint="mixes two conventions",
    ),
    Mistake(
        "align_gauss_newton_additive",
        "align_gauss_newton",
        "additive update R + R [δ]× (leaves SO(3))",
        """
def align_gauss_newton(P, Q, R0, iters=10):
    R = np.array(R0, dtype=float)
    for _ in range(iters):
        H, g = np.zeros((3, 3)), np.zeros(3)
        for p, q in zip(np.asarray(P, dtype=float), np.asarray(Q, dtype=float)):
            J = -R @ skew(p)
            H += J.T @ J
            g += J.T @ (R @ p - q)
        R = R + R @ skew(np.linalg.solve(H, -g))
    return R
""",
        hint="by adding R [δ]×",
        public_hint="by adding R [δ]×",
    ),
    Mistake(
        "align_gauss_newton_wrong_sign",
        "align_gauss_newton",
        "steps uphill: δ = +H⁻¹ g",
        """
def align_gauss_newton(P, Q, R0, iters=10):
    R = np.array(R0, dtype=float)
    for _ in range(iters):
        H, g = np.zeros((3, 3)), np.zeros(3)
        for p, q in zip(np.asarray(P, dtype=float), np.asarray(Q, dtype=float)):
            J = -R @ skew(p)
            H += J.T @ J
            g += J.T @ (R @ p - q)
        R = R @ Exp(np.linalg.solve(H, g))
    return R
""",
        hint="uphill",
        public_hint="uphill",
    ),
    Mistake(
        "rotation_mean_chordal",
        "rotation_mean",
        "chordal mean (projected arithmetic mean) instead of geodesic",
        """
def rotation_mean(Rs):
    U, _, Vt = np.linalg.svd(np.mean(np.asarray(Rs, dtype=float), axis=0))
    return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt
""",
        hint="chordal mean",
        public_hint="chordal mean",
        classic=True,
    ),
    Mistake(
        "rotation_mean_one_step",
        "rotation_mean",
        "stops after one iteration",
        """
def rotation_mean(Rs):
    Rs = np.asarray(Rs, dtype=float)
    M = Rs[0]
    delta = np.mean([Log(M.T @ R) for R in Rs], axis=0)
    return M @ Exp(delta)
""",
        hint="single step from Rs[0]",
        public_hint="single step from Rs[0]",
    ),
    Mistake(
        "rotation_mean_summed_steps",
        "rotation_mean",
        "starts at the identity and steps by the sum of the residuals, not their average",
        """
def rotation_mean(Rs):
    Rs = np.asarray(Rs, dtype=float)
    M = np.eye(3)
    for _ in range(100):
        delta = np.sum([Log(M.T @ R) for R in Rs], axis=0)
        M = M @ Exp(delta)
        if np.linalg.norm(delta) < 1e-13:
            break
    return M
""",
        hint="never overshoot",
        public_hint="never overshoot",
    ),
    Mistake(
        "rotation_mean_log_average",
        "rotation_mean",
        "averages Log(R_i) about the identity",
        """
def rotation_mean(Rs):
    return Exp(np.mean([Log(R) for R in np.asarray(Rs, dtype=float)], axis=0))
""",
        hint="about the identity",
        public_hint="about the identity",
    ),
    Mistake(
        "align_svd_ignores_Q",
        "align_svd",
        "SVD of Pᵀ P (ignores Q)",
        """
def align_svd(P, Q):
    P = np.asarray(P, dtype=float)
    U, _, Vt = np.linalg.svd(P.T @ P)
    return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt
""",
        hint="as if Q were ignored",
        public_hint="as if Q were ignored",
    ),
    Mistake(
        "align_gauss_newton_one_step",
        "align_gauss_newton",
        "takes one Gauss-Newton step, whatever iters says",
        """
def align_gauss_newton(P, Q, R0, iters=10):
    R = np.array(R0, dtype=float)
    H, g = np.zeros((3, 3)), np.zeros(3)
    for p, q in zip(np.asarray(P, dtype=float), np.asarray(Q, dtype=float)):
        J = -R @ skew(p)
        H += J.T @ J
        g += J.T @ (R @ p - q)
    return R @ Exp(np.linalg.solve(H, -g))
""",
        hint="whatever iters says",
        public_hint="whatever iters says",
        classic=True,
    ),
    Mistake(
        "rotation_mean_first_sample",
        "rotation_mean",
        "returns the first rotation",
        """
def rotation_mean(Rs):
    return np.array(Rs[0], dtype=float)
""",
        hint="first rotation Rs[0]",
        public_hint="first rotation Rs[0]",
    ),
]

ALTERNATIVES = [
    Alternative(
        "align_svd_quaternion_horn",
        "align_svd",
        "Horn's quaternion method (top eigenvector of a 4×4 matrix)",
        """
def align_svd(P, Q):
    M = np.asarray(Q, dtype=float).T @ np.asarray(P, dtype=float)
    t = np.trace(M)
    K = np.array([[t, M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1]],
                  [M[2, 1] - M[1, 2], 2 * M[0, 0] - t, M[0, 1] + M[1, 0], M[0, 2] + M[2, 0]],
                  [M[0, 2] - M[2, 0], M[0, 1] + M[1, 0], 2 * M[1, 1] - t, M[1, 2] + M[2, 1]],
                  [M[1, 0] - M[0, 1], M[0, 2] + M[2, 0], M[1, 2] + M[2, 1], 2 * M[2, 2] - t]])
    w, x, y, z = np.linalg.eigh(K)[1][:, -1]
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
""",
    ),
    Alternative(
        "align_gauss_newton_left",
        "align_gauss_newton",
        "left perturbation: J_i = -[R p_i]×, R ← Exp(δ) R",
        """
def align_gauss_newton(P, Q, R0, iters=10):
    R = np.array(R0, dtype=float)
    P, Q = np.asarray(P, dtype=float), np.asarray(Q, dtype=float)
    for _ in range(iters):
        H, g = np.zeros((3, 3)), np.zeros(3)
        for p, q in zip(P, Q):
            J = -skew(R @ p)
            H += J.T @ J
            g += J.T @ (R @ p - q)
        R = Exp(np.linalg.solve(H, -g)) @ R
    return R
""",
    ),
    Alternative(
        "rotation_mean_until_converged",
        "rotation_mean",
        "starts from the chordal mean, stops when |δ| < 1e-14",
        """
def rotation_mean(Rs):
    Rs = [np.asarray(R, dtype=float) for R in Rs]
    U, _, Vt = np.linalg.svd(sum(Rs) / len(Rs))
    M = U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt
    for _ in range(200):
        delta = sum(Log(M.T @ R) for R in Rs) / len(Rs)
        M = M @ Exp(delta)
        if np.linalg.norm(delta) < 1e-14:
            break
    return M
""",
    ),
]

SAMPLE = {
    "dev": ["align_svd_transposed"],
    "farid": ["align_svd_reflection"],
    "chloe": ["align_gauss_newton_left_jacobian"],
}
