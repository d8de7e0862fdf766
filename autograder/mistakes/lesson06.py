"""Typical mistakes for lesson 06: perturbations and Jacobians."""

from . import Mistake

MISTAKES = [
    Mistake("boxplus_right_on_the_left", "boxplus_right", "multiplies Exp(δ) on the left (the left perturbation)", '''
def boxplus_right(R, d):
    return Exp(d) @ np.asarray(R, dtype=float)
'''),
    Mistake("boxplus_right_first_order", "boxplus_right", "R (I + [δ]×): the first-order step, not a rotation", '''
def boxplus_right(R, d):
    return np.asarray(R, dtype=float) @ (np.eye(3) + skew(d))
'''),
    Mistake("boxplus_left_on_the_right", "boxplus_left", "multiplies Exp(δ) on the right", '''
def boxplus_left(R, d):
    return np.asarray(R, dtype=float) @ Exp(d)
'''),
    Mistake("boxminus_swapped", "boxminus", "Log(R_aᵀ R_b): the arguments swapped (the step back)", '''
def boxminus(R_a, R_b):
    return Log(np.asarray(R_a, dtype=float).T @ np.asarray(R_b, dtype=float))
'''),
    Mistake("boxminus_left_difference", "boxminus", "Log(R_a R_bᵀ): the difference of the left perturbation", '''
def boxminus(R_a, R_b):
    return Log(np.asarray(R_a, dtype=float) @ np.asarray(R_b, dtype=float).T)
'''),
    Mistake("quat_boxplus_not_normalised", "quat_boxplus", "q ⊗ [1, δ/2] without normalising", '''
def quat_boxplus(q, d):
    d = np.asarray(d, dtype=float)
    return quat_product(q, np.concatenate([[1.0], d / 2.0]))
'''),
    Mistake("quat_boxplus_full_angle", "quat_boxplus", "uses |δ| instead of |δ|/2 (turns twice as far)", '''
def quat_boxplus(q, d):
    d = np.asarray(d, dtype=float)
    angle = np.linalg.norm(d)
    if angle == 0.0:
        return np.asarray(q, dtype=float)
    dq = np.concatenate([[np.cos(angle)], np.sin(angle) * d / angle])
    return quat_product(q, dq)
'''),
    Mistake("numerical_jacobian_tiny_step", "numerical_jacobian", "a fixed step of 1e-12: rounding noise dominates", '''
def numerical_jacobian(f, x, boxplus=None):
    h = 1e-12
    f0 = np.asarray(f(x), dtype=float)
    if boxplus is None:
        x = np.asarray(x, dtype=float)
        columns = []
        for j in range(x.size):
            moved = x.copy()
            moved[j] += h
            columns.append((np.asarray(f(moved), dtype=float) - f0) / h)
        return np.column_stack(columns)
    columns = []
    for j in range(3):
        d = np.zeros(3)
        d[j] = h
        columns.append((np.asarray(f(boxplus(x, d)), dtype=float) - f0) / h)
    return np.column_stack(columns)
'''),
    Mistake("numerical_jacobian_matrix_entries", "numerical_jacobian",
            "perturbs the entries of x (9 for a matrix) and ignores boxplus", '''
def numerical_jacobian(f, x, boxplus=None):
    x = np.asarray(x, dtype=float)
    f0 = np.asarray(f(x), dtype=float)
    flat = x.ravel()
    columns = []
    for j in range(flat.size):
        step = max(abs(1e-4 * flat[j]), 1e-6)
        moved = flat.copy()
        moved[j] += step
        columns.append((np.asarray(f(moved.reshape(x.shape)), dtype=float) - f0) / step)
    return np.column_stack(columns)
'''),
    Mistake("numerical_jacobian_central", "numerical_jacobian",
            "central differences with the lecture's steps, not the forward differences asked for", '''
def numerical_jacobian(f, x, boxplus=None):
    if boxplus is None:
        x = np.asarray(x, dtype=float)
        columns = []
        for j in range(x.size):
            step = max(abs(1e-4 * x[j]), 1e-6)
            ahead, behind = x.copy(), x.copy()
            ahead[j] += step
            behind[j] -= step
            columns.append((np.asarray(f(ahead), dtype=float) - np.asarray(f(behind), dtype=float)) / (2 * step))
        return np.column_stack(columns)
    columns = []
    for j in range(3):
        d = np.zeros(3)
        d[j] = 1e-6
        columns.append((np.asarray(f(boxplus(x, d)), dtype=float) - np.asarray(f(boxplus(x, -d)), dtype=float)) / 2e-6)
    return np.column_stack(columns)
'''),
    Mistake("jacobian_rotate_point_left", "jacobian_rotate_point", "-[R p]×: the Jacobian of the left perturbation", '''
def jacobian_rotate_point(R, p):
    return -skew(np.asarray(R, dtype=float) @ np.asarray(p, dtype=float))
'''),
    Mistake("jacobian_rotate_point_sign", "jacobian_rotate_point", "R [p]×: the sign lost in [δ]× p = -[p]× δ", '''
def jacobian_rotate_point(R, p):
    return np.asarray(R, dtype=float) @ skew(p)
'''),
    Mistake("right_jacobian_is_left", "right_jacobian_so3", "the left Jacobian: + sign on the [w]× term", '''
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-6:
        return np.eye(3) + 0.5 * W
    return np.eye(3) + (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
'''),
    Mistake("right_jacobian_naive", "right_jacobian_so3",
            "closed form everywhere except exactly 0: (1 - cos θ)/θ² loses its digits at tiny angles", '''
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    if theta == 0.0:
        return np.eye(3)
    W = skew(w)
    return np.eye(3) - (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
'''),
    Mistake("right_jacobian_inv_naive", "right_jacobian_inv_so3", "the closed form with no small-angle branch: NaN at w = 0", '''
def right_jacobian_inv_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    c = 1 / theta**2 - (1 + np.cos(theta)) / (2 * theta * np.sin(theta))
    return np.eye(3) + 0.5 * W + c * W @ W
'''),
    Mistake("right_jacobian_inv_transpose", "right_jacobian_inv_so3", "Jr(w)ᵀ: the transpose taken for the inverse", '''
def right_jacobian_inv_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-3:
        a, b = 0.5 - theta**2 / 24, 1 / 6 - theta**2 / 120
    else:
        a, b = (1 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
    return (np.eye(3) - a * W + b * W @ W).T
'''),
]

SAMPLE = {
    "dev": ["boxplus_right_on_the_left", "jacobian_rotate_point_left", "right_jacobian_is_left"],
    "emma": ["quat_boxplus_full_angle"],
    "farid": ["boxplus_right_first_order", "quat_boxplus_not_normalised"],
    "chloe": ["boxminus_swapped"],
}
