"""Typical mistakes for lesson 08: estimating a rotation."""

from . import Mistake

MISTAKES = [
    Mistake("align_svd_reflection", "align_svd", "U Vᵀ without the determinant fix", '''
def align_svd(P, Q):
    U, _, Vt = np.linalg.svd(np.asarray(Q, dtype=float).T @ np.asarray(P, dtype=float))
    return U @ Vt
'''),
    Mistake("align_svd_transposed", "align_svd", "correlation matrix Pᵀ Q instead of Qᵀ P (returns Rᵀ)", '''
def align_svd(P, Q):
    U, _, Vt = np.linalg.svd(np.asarray(P, dtype=float).T @ np.asarray(Q, dtype=float))
    d = np.sign(np.linalg.det(U @ Vt))
    return U @ np.diag([1.0, 1.0, d]) @ Vt
'''),
    Mistake("align_svd_least_squares", "align_svd", "unconstrained least squares: not a rotation", '''
def align_svd(P, Q):
    X, *_ = np.linalg.lstsq(np.asarray(P, dtype=float), np.asarray(Q, dtype=float), rcond=None)
    return X.T
'''),
    Mistake("align_gauss_newton_left_jacobian", "align_gauss_newton",
            "left Jacobian -[R p]× with the right update R Exp(δ)", '''
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
'''),
    Mistake("align_gauss_newton_additive", "align_gauss_newton", "additive update R + R [δ]× (leaves SO(3))", '''
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
'''),
    Mistake("align_gauss_newton_wrong_sign", "align_gauss_newton", "steps uphill: δ = +H⁻¹ g", '''
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
'''),
    Mistake("rotation_mean_chordal", "rotation_mean", "chordal mean (projected arithmetic mean) instead of geodesic", '''
def rotation_mean(Rs):
    U, _, Vt = np.linalg.svd(np.mean(np.asarray(Rs, dtype=float), axis=0))
    return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt
'''),
    Mistake("rotation_mean_one_step", "rotation_mean", "stops after one iteration", '''
def rotation_mean(Rs):
    Rs = np.asarray(Rs, dtype=float)
    M = Rs[0]
    delta = np.mean([Log(M.T @ R) for R in Rs], axis=0)
    return M @ Exp(delta)
'''),
    Mistake("rotation_mean_log_average", "rotation_mean", "averages Log(R_i) about the identity", '''
def rotation_mean(Rs):
    return Exp(np.mean([Log(R) for R in np.asarray(Rs, dtype=float)], axis=0))
'''),
]

SAMPLE = {
    "dev": ["align_svd_transposed"],
    "farid": ["align_svd_reflection"],
    "chloe": ["align_gauss_newton_left_jacobian"],
}
