"""Typical mistakes for lesson 06: perturbations and Jacobians."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "boxplus_right_on_the_left",
        "boxplus_right",
        "multiplies Exp(δ) on the left (the left perturbation)",
        """
def boxplus_right(R, d):
    return Exp(d) @ np.asarray(R, dtype=float)
""",
        hint="left perturbation Exp(δ) R",
        public_hint="left perturbation Exp(δ) R",
        classic=True,
    ),
    Mistake(
        "boxplus_right_first_order",
        "boxplus_right",
        "R (I + [δ]×): the first-order step, not a rotation",
        """
def boxplus_right(R, d):
    return np.asarray(R, dtype=float) @ (np.eye(3) + skew(d))
""",
        hint="first-order approximation",
        public_hint="first-order approximation",
    ),
    Mistake(
        "boxplus_left_on_the_right",
        "boxplus_left",
        "multiplies Exp(δ) on the right",
        """
def boxplus_left(R, d):
    return np.asarray(R, dtype=float) @ Exp(d)
""",
        hint="right perturbation R Exp(δ)",
        public_hint="right perturbation R Exp(δ)",
    ),
    Mistake(
        "boxminus_swapped",
        "boxminus",
        "Log(R_aᵀ R_b): the arguments swapped (the step back)",
        """
def boxminus(R_a, R_b):
    return Log(np.asarray(R_a, dtype=float).T @ np.asarray(R_b, dtype=float))
""",
        hint="arguments swapped",
        public_hint="arguments swapped",
    ),
    Mistake(
        "boxminus_left_difference",
        "boxminus",
        "Log(R_a R_bᵀ): the difference of the left perturbation",
        """
def boxminus(R_a, R_b):
    return Log(np.asarray(R_a, dtype=float) @ np.asarray(R_b, dtype=float).T)
""",
        hint="left difference",
        public_hint="left difference",
    ),
    Mistake(
        "quat_boxplus_not_normalised",
        "quat_boxplus",
        "q ⊗ [1, δ/2] without normalising",
        """
def quat_boxplus(q, d):
    d = np.asarray(d, dtype=float)
    return quat_product(q, np.concatenate([[1.0], d / 2.0]))
""",
        hint="without normalising",
        public_hint="without normalising",
    ),
    Mistake(
        "quat_boxplus_full_angle",
        "quat_boxplus",
        "uses |δ| instead of |δ|/2 (turns twice as far)",
        """
def quat_boxplus(q, d):
    d = np.asarray(d, dtype=float)
    angle = np.linalg.norm(d)
    if angle == 0.0:
        return np.asarray(q, dtype=float)
    dq = np.concatenate([[np.cos(angle)], np.sin(angle) * d / angle])
    return quat_product(q, dq)
""",
        hint="half angle",
        public_hint="half angle",
    ),
    Mistake(
        "numerical_jacobian_list_with_boxplus",
        "numerical_jacobian",
        "the boxplus path returns its rows as nested lists",
        """
def numerical_jacobian(f, x, boxplus=None):
    f0 = np.asarray(f(x), dtype=float)
    if boxplus is None:
        x = np.asarray(x, dtype=float)
        J = np.zeros((f0.size, x.size))
        for j in range(x.size):
            step = max(abs(1e-4 * x[j]), 1e-6)
            moved = x.copy()
            moved[j] += step
            J[:, j] = (np.asarray(f(moved), dtype=float) - f0) / step
        return J
    columns = []
    for j in range(3):
        d = np.zeros(3)
        d[j] = 1e-6
        columns.append((np.asarray(f(boxplus(x, d)), dtype=float) - f0) / 1e-6)
    return np.column_stack(columns).tolist()
""",
        hint="on every path",
        public_hint="on every path",
    ),
    Mistake(
        "numerical_jacobian_tiny_step",
        "numerical_jacobian",
        "a fixed step of 1e-12: rounding noise dominates",
        """
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
""",
        hint="far too small",
        public_hint="far too small",
    ),
    Mistake(
        "numerical_jacobian_matrix_entries",
        "numerical_jacobian",
        "perturbs the entries of x (9 for a matrix) and ignores boxplus",
        """
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
""",
        hint="one column per stored number",
        public_hint="perturb the 3-vector δ",
    ),
    Mistake(
        "jacobian_rotate_point_left",
        "jacobian_rotate_point",
        "-[R p]×: the Jacobian of the left perturbation",
        """
def jacobian_rotate_point(R, p):
    return -skew(np.asarray(R, dtype=float) @ np.asarray(p, dtype=float))
""",
        hint="Jacobian of the left perturbation",
        public_hint="Jacobian of the left perturbation",
        classic=True,
    ),
    Mistake(
        "jacobian_rotate_point_sign",
        "jacobian_rotate_point",
        "R [p]×: the sign lost in [δ]× p = -[p]× δ",
        """
def jacobian_rotate_point(R, p):
    return np.asarray(R, dtype=float) @ skew(p)
""",
        hint="sign is flipped",
        public_hint="sign is flipped",
    ),
    Mistake(
        "right_jacobian_is_left",
        "right_jacobian_so3",
        "the left Jacobian: + sign on the [w]× term",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-6:
        return np.eye(3) + 0.5 * W
    return np.eye(3) + (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
""",
        hint="left Jacobian",
        public_hint="left Jacobian",
    ),
    Mistake(
        "right_jacobian_naive",
        "right_jacobian_so3",
        "closed form everywhere except exactly 0: (1 - cos θ)/θ² loses its digits at tiny angles",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    if theta == 0.0:
        return np.eye(3)
    W = skew(w)
    return np.eye(3) - (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
""",
        hint="loses its digits",
        public_hint="loses its digits",
    ),
    Mistake(
        "right_jacobian_inv_naive",
        "right_jacobian_inv_so3",
        "the closed form with no small-angle branch: NaN at w = 0",
        """
def right_jacobian_inv_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    c = 1 / theta**2 - (1 + np.cos(theta)) / (2 * theta * np.sin(theta))
    return np.eye(3) + 0.5 * W + c * W @ W
""",
        hint="0/0",
        public_hint="0/0",
    ),
    Mistake(
        "right_jacobian_inv_transpose",
        "right_jacobian_inv_so3",
        "Jr(w)ᵀ: the transpose taken for the inverse",
        """
def right_jacobian_inv_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-3:
        a, b = 0.5 - theta**2 / 24, 1 / 6 - theta**2 / 120
    else:
        a, b = (1 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
    return (np.eye(3) - a * W + b * W @ W).T
""",
        hint="transpose is not its inverse",
        public_hint="transpose is not its inverse",
    ),
    Mistake(
        "boxplus_right_adds",
        "boxplus_right",
        "R + [δ]×: adds in the algebra",
        """
def boxplus_right(R, d):
    return np.asarray(R, dtype=float) + skew(d)
""",
        hint="rotations do not add",
        public_hint="rotations do not add",
    ),
    Mistake(
        "boxplus_right_minus",
        "boxplus_right",
        "R Exp(-δ)",
        """
def boxplus_right(R, d):
    return np.asarray(R, dtype=float) @ Exp(-np.asarray(d, dtype=float))
""",
        hint="turned by -δ",
        public_hint="turned by -δ",
    ),
    Mistake(
        "boxplus_left_first_order",
        "boxplus_left",
        "(I + [δ]×) R: first order, not a rotation",
        """
def boxplus_left(R, d):
    return (np.eye(3) + skew(d)) @ np.asarray(R, dtype=float)
""",
        hint="first-order approximation",
        public_hint="first-order approximation",
    ),
    Mistake(
        "boxplus_left_minus",
        "boxplus_left",
        "Exp(-δ) R",
        """
def boxplus_left(R, d):
    return Exp(-np.asarray(d, dtype=float)) @ np.asarray(R, dtype=float)
""",
        hint="turned by -δ",
        public_hint="turned by -δ",
    ),
    Mistake(
        "boxplus_left_transposed",
        "boxplus_left",
        "Exp(δ) Rᵀ",
        """
def boxplus_left(R, d):
    return Exp(d) @ np.asarray(R, dtype=float).T
""",
        hint="R got transposed",
        public_hint="R got transposed",
    ),
    Mistake(
        "boxminus_difference",
        "boxminus",
        "Log(R_a) - Log(R_b): subtracts rotation vectors",
        """
def boxminus(R_a, R_b):
    return Log(R_a) - Log(R_b)
""",
        hint="do not subtract",
        public_hint="do not subtract",
    ),
    Mistake(
        "boxminus_vee_of_difference",
        "boxminus",
        "vee(R_bᵀ R_a - I): first order only",
        """
def boxminus(R_a, R_b):
    D = np.asarray(R_b, dtype=float).T @ np.asarray(R_a, dtype=float)
    return 0.5 * np.array([D[2, 1] - D[1, 2], D[0, 2] - D[2, 0], D[1, 0] - D[0, 1]])
""",
        hint="axis times sin θ",
        public_hint="axis times sin θ",
    ),
    Mistake(
        "quat_boxplus_left",
        "quat_boxplus",
        "Exp_q(δ) ⊗ q: the left perturbation",
        """
def quat_boxplus(q, d):
    d = np.asarray(d, dtype=float)
    angle = np.linalg.norm(d)
    dq = np.concatenate([[np.cos(angle / 2)], np.sinc(angle / (2 * np.pi)) / 2 * d])
    return quat_product(dq, q)
""",
        hint="left perturbation",
        public_hint="left perturbation",
    ),
    Mistake(
        "quat_boxplus_first_order_normalised",
        "quat_boxplus",
        "normalise(q ⊗ [1, δ/2]) for every δ",
        """
def quat_boxplus(q, d):
    dq = np.concatenate([[1.0], 0.5 * np.asarray(d, dtype=float)])
    out = quat_product(q, dq)
    return out / np.linalg.norm(out)
""",
        hint="rescaled to unit length",
        public_hint="rescaled to unit length",
    ),
    Mistake(
        "numerical_jacobian_big_step",
        "numerical_jacobian",
        "a fixed forward step of 1e-2: biased",
        """
def numerical_jacobian(f, x, boxplus=None):
    h = 1e-2
    f0 = np.asarray(f(x), dtype=float)
    if boxplus is None:
        x = np.asarray(x, dtype=float)
        columns = []
        for j in range(x.size):
            moved = x.copy()
            moved[j] += h
            columns.append((np.asarray(f(moved), dtype=float) - f0) / h)
        return np.column_stack(columns)
    return np.column_stack([(np.asarray(f(boxplus(x, h * e)), dtype=float) - f0) / h for e in np.eye(3)])
""",
        hint="far too large",
        public_hint="far too large",
    ),
    Mistake(
        "numerical_jacobian_transposed",
        "numerical_jacobian",
        "one row per input: the transpose",
        """
def numerical_jacobian(f, x, boxplus=None):
    h = 1e-6
    f0 = np.asarray(f(x), dtype=float)
    if boxplus is None:
        x = np.asarray(x, dtype=float)
        rows = []
        for j in range(x.size):
            moved = x.copy()
            moved[j] += h
            rows.append((np.asarray(f(moved), dtype=float) - f0) / h)
        return np.array(rows)
    return np.array([(np.asarray(f(boxplus(x, h * e)), dtype=float) - f0) / h for e in np.eye(3)])
""",
        hint="row i is output",
        public_hint="row i is output",
    ),
    Mistake(
        "numerical_jacobian_no_floor",
        "numerical_jacobian",
        "δ_j = 1e-4 |x_j| without the floor: 0/0 at x_j = 0",
        """
def numerical_jacobian(f, x, boxplus=None):
    f0 = np.asarray(f(x), dtype=float)
    if boxplus is None:
        x = np.asarray(x, dtype=float)
        columns = []
        for j in range(x.size):
            step = abs(1e-4 * x[j])
            moved = x.copy()
            moved[j] += step
            with np.errstate(invalid="ignore", divide="ignore"):
                columns.append((np.asarray(f(moved), dtype=float) - f0) / step)
        return np.column_stack(columns)
    return np.column_stack([(np.asarray(f(boxplus(x, 1e-6 * e)), dtype=float) - f0) / 1e-6 for e in np.eye(3)])
""",
        hint="keep the floor",
        public_hint="keep the floor",
    ),
    Mistake(
        "jacobian_rotate_point_transposed",
        "jacobian_rotate_point",
        "(-R [p]×)ᵀ: the transpose",
        """
def jacobian_rotate_point(R, p):
    return (-np.asarray(R, dtype=float) @ skew(p)).T
""",
        hint="transpose of the Jacobian",
        public_hint="transpose of the Jacobian",
    ),
    Mistake(
        "jacobian_rotate_point_no_R",
        "jacobian_rotate_point",
        "-[p]×: forgets R",
        """
def jacobian_rotate_point(R, p):
    return -skew(p)
""",
        hint="right at R = I, wrong at a generic R",
        public_hint="right at R = I, wrong at a generic R",
    ),
    Mistake(
        "right_jacobian_guard_only_at_zero_series",
        "right_jacobian_so3",
        "below 1e-2 uses I only (drops -[w]×/2)",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-2:
        return np.eye(3)
    return np.eye(3) - (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
""",
        hint="-[w]×/2 is missing",
        public_hint="-[w]×/2 is missing",
    ),
    Mistake(
        "right_jacobian_swapped_coefficients",
        "right_jacobian_so3",
        "the two coefficients swapped",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-4:
        return np.eye(3) - W / 6 + W @ W / 2
    return np.eye(3) - (theta - np.sin(theta)) / theta**3 * W + (1 - np.cos(theta)) / theta**2 * W @ W
""",
        hint="coefficients are swapped",
        public_hint="coefficients are swapped",
    ),
    Mistake(
        "right_jacobian_inv_is_jr",
        "right_jacobian_inv_so3",
        "returns Jr itself",
        """
def right_jacobian_inv_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-3:
        a, b = 0.5 - theta**2 / 24, 1 / 6 - theta**2 / 120
    else:
        a, b = (1 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
    return np.eye(3) - a * W + b * W @ W
""",
        hint="itself, not its inverse",
        public_hint="itself, not its inverse",
    ),
    Mistake(
        "right_jacobian_inv_first_order",
        "right_jacobian_inv_so3",
        "I + [w]×/2 at every angle",
        """
def right_jacobian_inv_so3(w):
    return np.eye(3) + 0.5 * skew(w)
""",
        hint="only the first-order part",
        public_hint="only the first-order part",
    ),
    Mistake(
        "right_jacobian_one_term_below_1e_2",
        "right_jacobian_so3",
        "the one-term series I - [w]×/2 + [w]×²/6 below 1e-2 (off by 4e-8 just below it)",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-2:
        return np.eye(3) - W / 2 + W @ W / 6
    return np.eye(3) - (1 - np.cos(theta)) / theta**2 * W + (theta - np.sin(theta)) / theta**3 * W @ W
""",
        hint="a one-term series of each coefficient",
        public_hint="without it the error grows like θ³",
    ),
    Mistake(
        "right_jacobian_inv_one_term_below_1e_2",
        "right_jacobian_inv_so3",
        "the one-term series c = 1/12 below 1e-2",
        """
def right_jacobian_inv_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    c = 1 / 12 if theta < 1e-2 else 1 / theta**2 - (1 + np.cos(theta)) / (2 * theta * np.sin(theta))
    return np.eye(3) + 0.5 * W + c * W @ W
""",
        hint="one-term series I + [w]×/2 + [w]×²/12",
        public_hint="the one-term c = 1/12 is off",
    ),
    Mistake(
        "quat_boxplus_shortcut_below_1e_3",
        "quat_boxplus",
        "q ⊗ [1, δ/2], normalised, used below 1e-3 (off by 4e-11 just below it)",
        """
def quat_boxplus(q, d):
    d = np.asarray(d, dtype=float)
    angle = np.linalg.norm(d)
    if angle < 1e-3:
        dq = np.concatenate([[1.0], 0.5 * d])
    else:
        dq = np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * d / angle])
    result = quat_product(q, dq)
    return result / np.linalg.norm(result)
""",
        hint="keep that shortcut for |δ| below about 1e-8",
        public_hint="exact to rounding only below about 1e-8",
    ),
    Mistake(
        "boxplus_left_adjoint_with_R",
        "boxplus_left",
        "moves Exp(δ) to the right of R with R δ instead of Rᵀ δ",
        """
def boxplus_left(R, d):
    R = np.asarray(R, dtype=float)
    return R @ Exp(R @ np.asarray(d, dtype=float))
""",
        hint="R Exp(R δ)",
        public_hint="Rᵀ, not R",
    ),
    Mistake(
        "boxminus_lists_transposed",
        "boxminus",
        "R_b.T @ R_a on the inputs as given: plain lists have no .T",
        """
def boxminus(R_a, R_b):
    return Log(R_b.T @ R_a)
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "right_jacobian_first_coefficient_unguarded",
        "right_jacobian_so3",
        "the series guards only the second coefficient: the half-angle form of the first is 0/0 at θ = 0",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    a = 0.5 * (np.sin(0.5 * theta) / (0.5 * theta)) ** 2   # the stable form: no series needed, or so it seems
    if theta < 1e-3:
        t2 = theta * theta
        b = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0
    else:
        b = (theta - np.sin(theta)) / theta**3
    return np.eye(3) - a * W + b * (W @ W)
""",
        hint="the closed form is 0/0 at θ = 0",
        public_hint="the closed form is 0/0 at θ = 0",
    ),
    Mistake(
        "boxminus_column",
        "boxminus",
        "returns the difference as a 3×1 column, as on paper",
        """
def boxminus(R_a, R_b):
    return Log(np.asarray(R_b, dtype=float).T @ np.asarray(R_a, dtype=float)).reshape(3, 1)
""",
        hint="keep the shape the docstring promises",
        public_hint="keep the shape the docstring promises",
    ),
]

ALTERNATIVES = [
    Alternative(
        "boxplus_left_rodrigues",
        "boxplus_left",
        "Rodrigues written out for Exp(δ)",
        """
def boxplus_left(R, d):
    d = np.asarray(d, dtype=float)
    theta = np.linalg.norm(d)
    K = skew(d)
    a = np.sinc(theta / np.pi)                                    # sin θ / θ
    b = 0.5 * np.sinc(theta / (2 * np.pi)) ** 2                   # (1 - cos θ) / θ²
    return (np.eye(3) + a * K + b * K @ K) @ np.asarray(R, dtype=float)
""",
    ),
    Alternative(
        "quat_boxplus_sinc",
        "quat_boxplus",
        "Exp_q(δ) with np.sinc, no branch",
        """
def quat_boxplus(q, d):
    d = np.asarray(d, dtype=float)
    theta = np.linalg.norm(d)
    dq = np.concatenate([[np.cos(theta / 2)], 0.5 * np.sinc(theta / (2 * np.pi)) * d])
    return np.array(list(quat_product(np.asarray(q, dtype=float), dq)))
""",
    ),
    Alternative(
        "boxplus_right_quaternion",
        "boxplus_right",
        "through quaternions",
        """
def boxplus_right(R, d):
    return np.asarray(R, dtype=float) @ Exp(d)
""",
    ),
    Alternative(
        "boxminus_quaternion",
        "boxminus",
        "the log of R_bᵀ R_a written out with atan2",
        """
def boxminus(R_a, R_b):
    return Log(np.asarray(R_b, dtype=float).T @ np.asarray(R_a, dtype=float))
""",
    ),
    Alternative(
        "numerical_jacobian_central",
        "numerical_jacobian",
        "central differences with the lecture's steps",
        """
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
""",
    ),
    Alternative(
        "numerical_jacobian_sqrt_eps",
        "numerical_jacobian",
        "forward steps √ε·max(1, |x_j|) (the V-curve's bottom)",
        """
def numerical_jacobian(f, x, boxplus=None):
    f0 = np.asarray(f(x), dtype=float)
    if boxplus is not None:
        h = np.sqrt(np.finfo(float).eps)
        return np.column_stack([(np.asarray(f(boxplus(x, h * e)), dtype=float) - f0) / h for e in np.eye(3)])
    x = np.asarray(x, dtype=float)
    columns = []
    for j in range(x.size):
        moved = x.copy()
        moved[j] += np.sqrt(np.finfo(float).eps) * max(1.0, abs(x[j]))
        columns.append((np.asarray(f(moved), dtype=float) - f0) / (moved[j] - x[j]))
    return np.column_stack(columns)
""",
    ),
    Alternative(
        "jacobian_rotate_point_cross",
        "jacobian_rotate_point",
        "R [p]×ᵀ built from cross products",
        """
def jacobian_rotate_point(R, p):
    p = np.asarray(p, dtype=float)
    return np.asarray(R, dtype=float) @ np.column_stack([np.cross(e, p) for e in np.eye(3)])
""",
    ),
    Alternative(
        "right_jacobian_left_of_minus",
        "right_jacobian_so3",
        "Jr(w) = Jl(-w) with the half-angle form",
        """
def right_jacobian_so3(w):
    w = -np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-4:
        return np.eye(3) + W / 2 + W @ W / 6
    a = 2.0 * np.sin(theta / 2) ** 2 / theta**2
    b = (theta - np.sin(theta)) / theta**3
    return np.eye(3) + a * W + b * W @ W
""",
    ),
    Alternative(
        "right_jacobian_inv_solve",
        "right_jacobian_inv_so3",
        "inverts the series-accurate Jr with solve",
        """
def right_jacobian_inv_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-4:
        return np.eye(3) + W / 2 + W @ W / 12
    a = 2.0 * np.sin(theta / 2) ** 2 / theta**2
    b = (theta - np.sin(theta)) / theta**3
    return np.linalg.solve(np.eye(3) - a * W + b * W @ W, np.eye(3))
""",
    ),
    Alternative(
        "right_jacobian_two_terms_below_1e_4",
        "right_jacobian_so3",
        "another series order: two terms below 1e-4",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-4:
        a, b = 0.5 - theta**2 / 24.0, 1.0 / 6.0 - theta**2 / 120.0
    else:
        a, b = (1.0 - np.cos(theta)) / theta**2, (theta - np.sin(theta)) / theta**3
    return np.eye(3) - a * W + b * (W @ W)
""",
    ),
]

SAMPLE = {
    "dev": ["boxplus_right_on_the_left", "jacobian_rotate_point_left", "right_jacobian_is_left"],
    "emma": ["quat_boxplus_full_angle"],
    "farid": ["boxplus_right_first_order", "quat_boxplus_not_normalised"],
    "chloe": ["boxminus_swapped"],
}
