"""Typical mistakes for lesson 03: the Lie algebra so(3), exp and log."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "hat_transposed",
        "hat",
        "the signs of [w]× swapped (the transpose, -[w]×)",
        """
def hat(w):
    w1, w2, w3 = np.asarray(w, dtype=float)
    return np.array([[0.0, w3, -w2], [-w3, 0.0, w1], [w2, -w1, 0.0]])
""",
        hint="the transpose",
        public_hint="the transpose",
    ),
    Mistake(
        "vee_wrong_sign",
        "vee",
        "reads the entries above the diagonal, returning -w",
        """
def vee(W):
    W = np.asarray(W, dtype=float)
    return np.array([W[1, 2], W[2, 0], W[0, 1]])
""",
        hint="negative of w",
        public_hint="negative of w",
    ),
    Mistake(
        "bracket_anticommutator",
        "bracket",
        "AB + BA instead of AB - BA",
        """
def bracket(A, B):
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    return A @ B + B @ A
""",
        hint="that is AB + BA",
        public_hint="that is AB + BA",
    ),
    Mistake(
        "bracket_elementwise",
        "bracket",
        "A * B - B * A with the entry-wise product (always zero)",
        """
def bracket(A, B):
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    return A * B - B * A
""",
        hint="entry by entry",
        public_hint="entry by entry",
    ),
    Mistake(
        "exp_series_starts_at_one",
        "exp_series",
        "the sum starts at k = 1 (the identity is missing)",
        """
def exp_series(W, n_terms):
    W = np.asarray(W, dtype=float)
    total = np.zeros_like(W)
    term = np.eye(W.shape[0])
    for k in range(1, n_terms + 1):
        term = term @ W / k
        total = total + term
    return total
""",
        hint="identity term is missing",
        public_hint="identity term is missing",
    ),
    Mistake(
        "exp_series_entrywise_power",
        "exp_series",
        "W ** k (entry-wise power) instead of the matrix power",
        """
def exp_series(W, n_terms):
    from math import factorial
    W = np.asarray(W, dtype=float)
    return sum(W ** k / factorial(k) for k in range(n_terms))
""",
        hint="entry-wise power",
        public_hint="entry-wise power",
        classic=True,
    ),
    Mistake(
        "exp_so3_identity_below_threshold",
        "exp_so3",
        "returns I when the angle is small",
        """
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    if theta < 1e-6:
        return np.eye(3)
    k = w / theta
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(theta) * K + (1 - np.cos(theta)) * K @ K
""",
        hint="returned exactly I",
        public_hint="never return I",
    ),
    Mistake(
        "exp_so3_transposed",
        "exp_so3",
        "minus sign on the sin θ term (the inverse rotation)",
        """
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    if theta == 0:
        return np.eye(3)
    k = w / theta
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) - np.sin(theta) * K + (1 - np.cos(theta)) * K @ K
""",
        hint="sign of the sin θ term",
        public_hint="sign of the sin θ term",
    ),
    Mistake(
        "log_so3_arccos_no_pi_branch",
        "log_so3",
        "arccos of the trace and division by sin θ, without a branch at π (Modern Robotics' MatrixLog3)",
        """
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
""",
        hint="its own branch near π",
        public_hint="its own branch near π",
        classic=True,
    ),
    Mistake(
        "log_so3_axis_sign_not_fixed",
        "log_so3",
        "near π takes the axis from (R + Rᵀ)/2 but never fixes its sign",
        """
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
""",
        hint="sign of the axis",
        public_hint="sign of the axis",
    ),
    Mistake(
        "axis_angle_nan_at_zero",
        "axis_angle",
        "u = w / θ without a θ = 0 case (NaN for the identity)",
        """
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
""",
        hint="0/0",
        public_hint="0/0",
    ),
    Mistake(
        "axis_angle_degrees",
        "axis_angle",
        "returns the angle in degrees",
        """
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
""",
        hint="in degrees",
        public_hint="in degrees",
    ),
    Mistake(
        "axis_angle_arccos_unclipped",
        "axis_angle",
        "θ = arccos((tr R - 1)/2) without clipping: NaN when rounding pushes the trace above 3",
        """
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
""",
        hint="clip (tr R - 1)/2",
        public_hint="clip (tr R - 1)/2",
    ),
    Mistake(
        "axis_from_eigen_row",
        "axis_from_eigen",
        "takes a row of the eigenvector matrix instead of a column",
        """
def axis_from_eigen(R):
    values, vectors = np.linalg.eig(np.asarray(R, dtype=float))
    k = int(np.argmin(np.abs(values - 1.0)))
    u = np.real(vectors[k])
    return u / np.linalg.norm(u)
""",
        hint="a row of the eigenvector matrix",
        public_hint="a row of the eigenvector matrix",
    ),
    Mistake(
        "axis_from_eigen_first",
        "axis_from_eigen",
        "takes the first eigenvector, whatever its eigenvalue",
        """
def axis_from_eigen(R):
    values, vectors = np.linalg.eig(np.asarray(R, dtype=float))
    u = np.real(vectors[:, 0])
    return u / np.linalg.norm(u)
""",
        hint="the first eigenvector",
        public_hint="the first eigenvector",
    ),
    Mistake(
        "hat_symmetric",
        "hat",
        "no minus signs: a symmetric matrix",
        """
def hat(w):
    x, y, z = np.asarray(w, dtype=float)
    return np.array([[0.0, z, y], [z, 0.0, x], [y, x, 0.0]])
""",
        hint="minus signs are missing",
        public_hint="minus signs are missing",
    ),
    Mistake(
        "hat_swapped_components",
        "hat",
        "w1 and w3 swapped",
        """
def hat(w):
    x, y, z = np.asarray(w, dtype=float)
    return np.array([[0.0, -x, y], [x, 0.0, -z], [-y, z, 0.0]])
""",
        hint="permuted",
        public_hint="permuted",
    ),
    Mistake(
        "hat_diagonal",
        "hat",
        "puts w on the diagonal",
        """
def hat(w):
    return np.diag(np.asarray(w, dtype=float))
""",
        hint="sits on the diagonal",
        public_hint="sits on the diagonal",
    ),
    Mistake(
        "vee_upper_entries",
        "vee",
        "reads W[0, 1], W[0, 2], W[1, 2]",
        """
def vee(W):
    W = np.asarray(W, dtype=float)
    return np.array([W[0, 1], W[0, 2], W[1, 2]])
""",
        hint="in row order",
        public_hint="in row order",
    ),
    Mistake(
        "vee_no_half",
        "vee",
        "vee of W - Wᵀ without the 1/2 (returns 2w)",
        """
def vee(W):
    W = np.asarray(W, dtype=float)
    D = W - W.T
    return np.array([D[2, 1], D[0, 2], D[1, 0]])
""",
        hint="twice w",
        public_hint="twice w",
    ),
    Mistake(
        "vee_diagonal",
        "vee",
        "returns the diagonal",
        """
def vee(W):
    return np.diag(np.asarray(W, dtype=float)).copy()
""",
        hint="the diagonal of W",
        public_hint="the diagonal of W",
    ),
    Mistake(
        "bracket_reversed",
        "bracket",
        "BA - AB",
        """
def bracket(A, B):
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    return B @ A - A @ B
""",
        hint="order is reversed",
        public_hint="not BA - AB",
    ),
    Mistake(
        "bracket_product_only",
        "bracket",
        "only AB",
        """
def bracket(A, B):
    return np.asarray(A, dtype=float) @ np.asarray(B, dtype=float)
""",
        hint="only AB",
        public_hint="only AB",
    ),
    Mistake(
        "exp_series_one_extra",
        "exp_series",
        "sums k = 0 … n_terms (one term too many)",
        """
def exp_series(W, n_terms):
    W = np.asarray(W, dtype=float)
    term, total = np.eye(len(W)), np.zeros((len(W), len(W)))
    for k in range(n_terms + 1):
        total = total + term
        term = term @ W / (k + 1)
    return total
""",
        hint="one term too many",
        public_hint="n_terms terms means",
    ),
    Mistake(
        "exp_series_no_factorial",
        "exp_series",
        "forgets the 1/k! (sums W^k)",
        """
def exp_series(W, n_terms):
    W = np.asarray(W, dtype=float)
    term, total = np.eye(len(W)), np.zeros((len(W), len(W)))
    for k in range(n_terms):
        total = total + term
        term = term @ W
    return total
""",
        hint="1/k! is missing",
        public_hint="1/k! is missing",
    ),
    Mistake(
        "exp_so3_unnormalised_axis",
        "exp_so3",
        "uses [w]× instead of the unit axis's [u]× in Rodrigues",
        """
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    return np.eye(3) + np.sin(theta) * W + (1 - np.cos(theta)) * W @ W
""",
        hint="unit axis",
        public_hint="unit axis",
    ),
    Mistake(
        "exp_so3_sin_cos_swapped",
        "exp_so3",
        "(1 - cos θ) on K and sin θ on K²",
        """
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    if theta == 0:
        return np.eye(3)
    k = w / theta
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + (1 - np.cos(theta)) * K + np.sin(theta) * K @ K
""",
        hint="coefficients are swapped",
        public_hint="coefficients are swapped",
    ),
    Mistake(
        "log_so3_nan_at_identity",
        "log_so3",
        "θ/(2 sin θ) with no θ = 0 case: NaN for the identity",
        """
def log_so3(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = np.arctan2(s, c)
    if c > 0.0:
        with np.errstate(invalid="ignore", divide="ignore"):
            return (theta / s) * a
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.linalg.norm(B[:, j])
    return theta * (u if u @ a >= 0.0 else -u)
""",
        hint="0/0",
        public_hint="0/0",
    ),
    Mistake(
        "log_so3_arccos_tiny",
        "log_so3",
        "θ = arccos((tr R - 1)/2): tiny angles round to 0",
        """
def log_so3(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = np.arctan2(s, c)
    theta = np.arccos(np.clip(c, -1.0, 1.0))
    if c > 0.0:
        return np.zeros(3) if theta == 0.0 else (theta / np.sin(theta)) * a
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.linalg.norm(B[:, j])
    return theta * (u if u @ a >= 0.0 else -u)
""",
        hint="arccos loses accuracy",
        public_hint="arccos loses accuracy",
    ),
    Mistake(
        "log_so3_no_half",
        "log_so3",
        "θ/sin θ · vee(R - Rᵀ) without the 1/2 (twice the vector)",
        """
def log_so3(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = np.arctan2(s, c)
    if c > 0.0:
        return np.zeros(3) if s == 0.0 else (2.0 * theta / s) * a
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.linalg.norm(B[:, j])
    return theta * (u if u @ a >= 0.0 else -u)
""",
        hint="twice the rotation vector",
        public_hint="twice the rotation vector",
    ),
    Mistake(
        "log_so3_first_order_small",
        "log_so3",
        "below θ = 1e-2 returns vee(R - Rᵀ)/2, dropping the θ²/6 term",
        """
def log_so3(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = np.arctan2(s, c)
    if c > 0.0:
        return a if theta < 1e-2 else (theta / s) * a
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.linalg.norm(B[:, j])
    return theta * (u if u @ a >= 0.0 else -u)
""",
        hint="lost its relative accuracy",
        public_hint="lost its relative accuracy",
    ),
    Mistake(
        "axis_angle_no_pi_branch",
        "axis_angle",
        "u = vee(R - Rᵀ)/(2 sin θ) at every angle (lost at π)",
        """
def axis_angle(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    s = np.linalg.norm(a)
    c = 0.5 * (np.trace(R) - 1.0)
    theta = np.arctan2(s, c)
    if s < 1e-300:
        return np.array([1.0, 0.0, 0.0]), float(theta)
    return a / s, float(theta)
""",
        hint="carries no axis",
        public_hint="carries no axis",
    ),
    Mistake(
        "axis_from_eigen_null_space_of_R",
        "axis_from_eigen",
        "the SVD null space of R instead of R - I",
        """
def axis_from_eigen(R):
    return np.linalg.svd(np.asarray(R, dtype=float))[2][-1]
""",
        hint="SVD null space of R",
        public_hint="SVD null space of R",
    ),
    Mistake(
        "axis_from_eigen_eigh",
        "axis_from_eigen",
        "np.linalg.eigh, which assumes a symmetric matrix",
        """
def axis_from_eigen(R):
    values, vectors = np.linalg.eigh(np.asarray(R, dtype=float))
    return vectors[:, int(np.argmin(np.abs(values - 1.0)))]
""",
        hint="eigh assumes",
        public_hint="eigh assumes",
    ),
    Mistake(
        "log_so3_pi_branch_fixed_column",
        "log_so3",
        "has the near-π branch, but always takes column 0 of (R + Rᵀ)/2 - cos θ I for the axis",
        """
def log_so3(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])   # sin θ · u
    s = np.sqrt(a @ a)                                                              # sin θ
    c = 0.5 * (np.trace(R) - 1.0)                                                   # cos θ
    theta = np.arctan2(s, c)
    if c > 0.0:                                   # θ < π/2: the antisymmetric part is reliable
        if s == 0.0:
            return np.zeros(3)
        return (theta / s) * a
    B = 0.5 * (R + R.T) - c * np.eye(3)            # (1 - cos θ) u uᵀ
    j = 0
    u = B[:, j] / np.sqrt(B[:, j] @ B[:, j])       # ± u
    if u @ a < 0.0:
        u = -u
    return theta * u
""",
        hint="one fixed column fails near π",
        public_hint="one fixed column fails near π",
    ),
    Mistake(
        "axis_angle_list_methods",
        "axis_angle",
        "R.trace() and R[:, j] on the input as given: a nested list has neither",
        """
def axis_angle(R):
    a = 0.5 * np.array([R[2][1] - R[1][2], R[0][2] - R[2][0], R[1][0] - R[0][1]])
    s = np.sqrt(a @ a)
    c = 0.5 * (R.trace() - 1.0)
    theta = float(np.arctan2(s, c))
    if c > 0.0:
        if s == 0.0:
            return np.array([1.0, 0.0, 0.0]), 0.0
        return a / s, theta
    B = 0.5 * (R + R.T) - c * np.eye(3)
    j = int(np.argmax(np.diag(B)))
    u = B[:, j] / np.sqrt(B[:, j] @ B[:, j])
    if u @ a < 0.0:
        u = -u
    return u, theta
""",
        hint="the conventions admit nested lists",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "vee_list_indexing",
        "vee",
        "W[2, 1] on the input as given: a nested list takes one index at a time",
        """
def vee(W):
    return 0.5 * np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]])
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "hat_from_cross",
        "hat",
        "columns are w × e_j",
        """
def hat(w):
    return np.cross(np.asarray(w, dtype=float), np.eye(3)).T
""",
    ),
    Alternative(
        "vee_antisymmetric_part",
        "vee",
        "from the antisymmetric part, read with list indexing",
        """
def vee(W):
    A = 0.5 * (np.asarray(W, dtype=float) - np.asarray(W, dtype=float).T)
    return np.array([A[2][1], A[0][2], A[1][0]], dtype=float)
""",
    ),
    Alternative(
        "bracket_lists",
        "bracket",
        "np.dot (of lists too)",
        """
def bracket(A, B):
    return np.asarray(np.dot(A, B) - np.dot(B, A), dtype=float)
""",
    ),
    Alternative(
        "exp_series_matrix_power",
        "exp_series",
        "matrix_power and math.factorial",
        """
def exp_series(W, n_terms):
    import math
    W = np.asarray(W, dtype=float)
    return sum((np.linalg.matrix_power(W, k) / math.factorial(k) for k in range(n_terms)), np.zeros(W.shape))
""",
    ),
    Alternative(
        "exp_so3_quaternion",
        "exp_so3",
        "through the unit quaternion (cos θ/2, sin θ/2 u)",
        """
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    half = 0.5 * np.sinc(theta / (2 * np.pi))                     # sin(θ/2)/θ, exact at 0
    x, y, z = half * w
    s = np.cos(theta / 2)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - s * z), 2 * (x * z + s * y)],
                     [2 * (x * y + s * z), 1 - 2 * (x * x + z * z), 2 * (y * z - s * x)],
                     [2 * (x * z - s * y), 2 * (y * z + s * x), 1 - 2 * (x * x + y * y)]])
""",
    ),
    Alternative(
        "log_so3_quaternion",
        "log_so3",
        "through Shepperd's quaternion: 2 atan2(|v|, w) v/|v|",
        """
def log_so3(R):
    R = np.asarray(R, dtype=float)
    t = np.trace(R)
    k = int(np.argmax([t, R[0, 0], R[1, 1], R[2, 2]]))
    if k == 0:
        q = np.array([1 + t, R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    elif k == 1:
        q = np.array([R[2, 1] - R[1, 2], 1 + 2 * R[0, 0] - t, R[0, 1] + R[1, 0], R[0, 2] + R[2, 0]])
    elif k == 2:
        q = np.array([R[0, 2] - R[2, 0], R[0, 1] + R[1, 0], 1 + 2 * R[1, 1] - t, R[1, 2] + R[2, 1]])
    else:
        q = np.array([R[1, 0] - R[0, 1], R[0, 2] + R[2, 0], R[1, 2] + R[2, 1], 1 + 2 * R[2, 2] - t])
    q = q / np.linalg.norm(q)
    if q[0] < 0:
        q = -q
    n = np.linalg.norm(q[1:])
    if n == 0.0:
        return np.zeros(3)
    return 2.0 * np.arctan2(n, q[0]) * q[1:] / n
""",
    ),
    Alternative(
        "axis_angle_list",
        "axis_angle",
        "axis from the symmetric part near π, built with list methods",
        """
def axis_angle(R):
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    c = 0.5 * (np.trace(R) - 1.0)
    theta = float(np.arctan2(np.linalg.norm(a), c))
    if theta == 0.0:
        return np.array([1.0, 0.0, 0.0]), theta
    if c > 0.0:
        return a / np.linalg.norm(a), theta
    B = 0.5 * (R + R.T) - c * np.eye(3)
    u = B[:, int(np.argmax(np.diag(B)))]
    u = u / np.linalg.norm(u)
    return (-u if u @ a < 0 else u), theta
""",
    ),
    Alternative(
        "axis_from_eigen_svd",
        "axis_from_eigen",
        "the SVD null space of R - I",
        """
def axis_from_eigen(R):
    return np.linalg.svd(np.asarray(R, dtype=float) - np.eye(3))[2][-1]
""",
    ),
    Alternative(
        "exp_so3_three_term_series",
        "exp_so3",
        "another series order: three terms of each coefficient below 1e-3",
        """
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    if theta < 1e-3:
        t2 = theta * theta
        a = 1.0 - t2 / 6.0 + t2 * t2 / 120.0
        b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0
    else:
        a = np.sin(theta) / theta
        b = (1.0 - np.cos(theta)) / (theta * theta)
    return np.eye(3) + a * W + b * (W @ W)
""",
    ),
]

SAMPLE = {
    "dev": ["hat_transposed", "exp_so3_transposed", "axis_from_eigen_row"],  # transposes matrices
    "emma": ["axis_angle_degrees"],  # works in degrees
}
