"""Typical mistakes for lesson 01: frames, points and rotation matrices."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "rot_z_transposed",
        "rot_z",
        "minus sign on the wrong sine (the transpose)",
        """
def rot_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])
""",
        hint="transpose",
        public_hint="transpose",
    ),
    Mistake(
        "rot_y_sign_top_right",
        "rot_y",
        "rot_y written like rot_x and rot_z, minus sign top-right",
        """
def rot_y(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0.0, -s], [0.0, 1.0, 0.0], [s, 0.0, c]])
""",
        hint="transpose",
        public_hint="transpose",
    ),
    Mistake(
        "rot_x_degrees",
        "rot_x",
        "treats the angle as degrees",
        hint="degrees",
        public_hint="degrees",
        source="""
def rot_x(a):
    c, s = np.cos(np.deg2rad(a)), np.sin(np.deg2rad(a))
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
""",
    ),
    Mistake(
        "rot_y_degrees",
        "rot_y",
        "treats the angle as degrees",
        hint="degrees",
        public_hint="degrees",
        source="""
def rot_y(a):
    a = np.radians(a)
    return np.array([[np.cos(a), 0.0, np.sin(a)], [0.0, 1.0, 0.0], [-np.sin(a), 0.0, np.cos(a)]])
""",
    ),
    Mistake(
        "rot_z_degrees",
        "rot_z",
        "treats the angle as degrees",
        hint="degrees",
        public_hint="degrees",
        source="""
def rot_z(a):
    a = a * np.pi / 180
    return np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0.0, 0.0, 1.0]])
""",
    ),
    Mistake(
        "rot2d_clockwise",
        "rot2d",
        "clockwise instead of counter-clockwise",
        """
def rot2d(theta):
    return np.array([[np.cos(theta), np.sin(theta)], [-np.sin(theta), np.cos(theta)]])
""",
        hint="transpose",
        public_hint="transpose",
    ),
    Mistake(
        "is_rotation_no_det",
        "is_rotation_matrix",
        "checks orthogonality only, so accepts reflections",
        hint="det(M) > 0",
        public_hint="det = +1",
        source="""
def is_rotation_matrix(M, tol=1e-9):
    try:
        M = np.asarray(M, dtype=float)
    except (TypeError, ValueError):
        return False
    if M.ndim != 2 or M.shape[0] != M.shape[1]:
        return False
    return bool(np.max(np.abs(M.T @ M - np.eye(M.shape[0]))) <= tol)
""",
    ),
    Mistake(
        "is_rotation_squares",
        "is_rotation_matrix",
        "tests M @ M against I instead of MᵀM: accepts only the identity and half turns",
        hint="a quarter turn times itself",
        public_hint="a quarter turn times itself",
        source="""
def is_rotation_matrix(M, tol=1e-9):
    try:
        M = np.asarray(M, dtype=float)
    except (TypeError, ValueError):
        return False
    if M.ndim != 2 or M.shape[0] != M.shape[1]:
        return False
    return bool(np.max(np.abs(M @ M - np.eye(M.shape[0]))) <= tol and np.linalg.det(M) > 0)
""",
    ),
    Mistake(
        "is_rotation_crashes_on_shape",
        "is_rotation_matrix",
        "no shape check: crashes on a 3×4 matrix",
        """
def is_rotation_matrix(M, tol=1e-9):
    M = np.asarray(M, dtype=float)
    return bool(np.max(np.abs(M.T @ M - np.eye(3))) <= tol and np.linalg.det(M) > 0)
""",
        hint="check M's shape first",
        public_hint="check M's shape first",
    ),
    Mistake(
        "rotate_point_transposed",
        "rotate_point",
        "uses R_wb.T (the inverse rotation)",
        """
def rotate_point(R_wb, p_b):
    return np.asarray(p_b, dtype=float) @ np.asarray(R_wb, dtype=float)
""",
        hint="R.T (the inverse)",
        public_hint="transpose of R_wb",
    ),
    Mistake(
        "rotate_point_single_only",
        "rotate_point",
        "R @ p: right for one point, wrong for rows",
        """
def rotate_point(R_wb, p_b):
    R_wb = np.asarray(R_wb, dtype=float)
    p_b = np.asarray(p_b, dtype=float)
    return R_wb @ p_b
""",
        hint="works for one point",
        public_hint="works for one point",
    ),
    Mistake(
        "rotate_point_square_batch_as_columns",
        "rotate_point",
        "tells one point from a batch by shape[0] == 3, so a batch of 3 points is read as columns",
        """
def rotate_point(R_wb, p_b):
    R_wb = np.asarray(R_wb, dtype=float)
    p_b = np.asarray(p_b, dtype=float)
    if p_b.shape[0] == 3:
        return R_wb @ p_b
    return p_b @ R_wb.T
""",
        hint="read as 3 columns",
        public_hint="read as 3 columns",
    ),
    Mistake(
        "compose_reversed",
        "compose",
        "multiplies in the wrong order",
        """
def compose(R_ab, R_bc):
    return np.asarray(R_bc, dtype=float) @ np.asarray(R_ab, dtype=float)
""",
        hint="order is reversed",
        public_hint="b meets b",
    ),
    Mistake(
        "invert_rotation_identity",
        "invert_rotation",
        "returns the rotation itself",
        """
def invert_rotation(R_ab):
    return np.array(R_ab, dtype=float)
""",
        hint="returned R itself",
        public_hint="returned R itself",
    ),
    Mistake(
        "nearest_rotation_reflection",
        "nearest_rotation",
        "U Vᵀ without the determinant fix",
        """
def nearest_rotation(M):
    U, _, Vt = np.linalg.svd(np.asarray(M, dtype=float))
    return U @ Vt
""",
        hint="flip the last column",
        public_hint="flip the sign of the last column",
        classic=True,
    ),
    Mistake(
        "rot2d_degrees",
        "rot2d",
        "treats the angle as degrees",
        """
def rot2d(theta):
    c, s = np.cos(np.radians(theta)), np.sin(np.radians(theta))
    return np.array([[c, -s], [s, c]])
""",
        hint="degrees",
        public_hint="degrees",
    ),
    Mistake(
        "rot2d_sin_cos_swapped",
        "rot2d",
        "sine and cosine swapped",
        """
def rot2d(theta):
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[s, -c], [c, s]])
""",
        hint="swapped",
        public_hint="swapped",
    ),
    Mistake(
        "rot2d_no_minus",
        "rot2d",
        "forgets the minus sign",
        """
def rot2d(theta):
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, s], [s, c]])
""",
        hint="same sign",
        public_hint="same sign",
    ),
    Mistake(
        "rot_x_transposed",
        "rot_x",
        "minus sign on the lower sine (the transpose)",
        """
def rot_x(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]])
""",
        hint="transpose",
        public_hint="transpose",
    ),
    Mistake(
        "rot_x_about_z",
        "rot_x",
        "the block in the wrong corner: a rotation about z",
        """
def rot_x(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
""",
        hint="is a rotation about z",
        public_hint="is a rotation about z",
    ),
    Mistake(
        "rot_x_no_minus",
        "rot_x",
        "both sines positive",
        """
def rot_x(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, s, c]])
""",
        hint="same sign",
        public_hint="same sign",
    ),
    Mistake(
        "rot_y_no_minus",
        "rot_y",
        "both sines positive",
        """
def rot_y(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [s, 0.0, c]])
""",
        hint="same sign",
        public_hint="same sign",
    ),
    Mistake(
        "rot_y_about_x",
        "rot_y",
        "the block in the wrong place: a rotation about x",
        """
def rot_y(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
""",
        hint="is a rotation about x",
        public_hint="is a rotation about x",
    ),
    Mistake(
        "rot_z_no_minus",
        "rot_z",
        "both sines positive",
        """
def rot_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
""",
        hint="same sign",
        public_hint="same sign",
    ),
    Mistake(
        "rot_z_corner_zero",
        "rot_z",
        "a zero where the 1 of the z axis belongs",
        """
def rot_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 0.0]])
""",
        hint="must be 1",
        public_hint="must be 1",
    ),
    Mistake(
        "is_rotation_allclose_rtol",
        "is_rotation_matrix",
        "np.allclose(MᵀM, I, atol=tol): the default rtol accepts diag(1, 1, 1 + 1e-6)",
        """
def is_rotation_matrix(M, tol=1e-9):
    try:
        M = np.asarray(M, dtype=float)
    except (TypeError, ValueError):
        return False
    if M.ndim != 2 or M.shape[0] != M.shape[1] or not np.all(np.isfinite(M)):
        return False
    return bool(np.allclose(M.T @ M, np.eye(M.shape[0]), atol=tol) and np.linalg.det(M) > 0)
""",
        hint="rtol",
        public_hint="rtol",
    ),
    Mistake(
        "is_rotation_fixed_tol",
        "is_rotation_matrix",
        "ignores tol and uses 1e-6",
        """
def is_rotation_matrix(M, tol=1e-9):
    try:
        M = np.asarray(M, dtype=float)
    except (TypeError, ValueError):
        return False
    if M.ndim != 2 or M.shape[0] != M.shape[1] or not np.all(np.isfinite(M)):
        return False
    return bool(np.max(np.abs(M.T @ M - np.eye(M.shape[0]))) <= 1e-6 and np.linalg.det(M) > 0)
""",
        hint="tol argument",
        public_hint="tol argument",
    ),
    Mistake(
        "is_rotation_det_only",
        "is_rotation_matrix",
        "checks det = 1 only, so accepts shears",
        """
def is_rotation_matrix(M, tol=1e-9):
    try:
        M = np.asarray(M, dtype=float)
    except (TypeError, ValueError):
        return False
    if M.ndim != 2 or M.shape[0] != M.shape[1]:
        return False
    return bool(abs(np.linalg.det(M) - 1.0) <= tol)
""",
        hint="a shear has det 1",
        public_hint="a shear has det 1",
    ),
    Mistake(
        "rotate_point_no_asarray",
        "rotate_point",
        "R_wb @ p_b without np.asarray: fails on lists",
        """
def rotate_point(R_wb, p_b):
    return p_b @ R_wb.T
""",
        hint="np.asarray",
        public_hint="np.asarray",
    ),
    Mistake(
        "rotate_point_elementwise",
        "rotate_point",
        "R * p (elementwise) instead of R @ p",
        """
def rotate_point(R_wb, p_b):
    return (np.asarray(R_wb, dtype=float) * np.asarray(p_b, dtype=float)).sum(axis=-1)
""",
        hint="could not broadcast R * P",
        public_hint="could not broadcast R * P",
    ),
    Mistake(
        "compose_elementwise",
        "compose",
        "R_ab * R_bc (elementwise) instead of @",
        """
def compose(R_ab, R_bc):
    return np.asarray(R_ab, dtype=float) * np.asarray(R_bc, dtype=float)
""",
        hint="elementwise product",
        public_hint="elementwise product",
    ),
    Mistake(
        "compose_transposes_first",
        "compose",
        "R_abᵀ R_bc (inverts the first)",
        """
def compose(R_ab, R_bc):
    return np.asarray(R_ab, dtype=float).T @ np.asarray(R_bc, dtype=float)
""",
        hint="first factor is transposed",
        public_hint="first factor is transposed",
    ),
    Mistake(
        "compose_no_asarray",
        "compose",
        "np.matmul on lists of lists... then .T.T",
        """
def compose(R_ab, R_bc):
    return (R_ab @ R_bc).T.T
""",
        hint="np.asarray",
        public_hint="np.asarray",
    ),
    Mistake(
        "invert_rotation_negated",
        "invert_rotation",
        "returns -R",
        """
def invert_rotation(R_ab):
    return -np.asarray(R_ab, dtype=float)
""",
        hint="every entry negated",
        public_hint="every entry negated",
    ),
    Mistake(
        "invert_rotation_no_asarray",
        "invert_rotation",
        "R_ab.T without np.asarray: fails on lists",
        """
def invert_rotation(R_ab):
    return R_ab.T.copy()
""",
        hint="np.asarray",
        public_hint="np.asarray",
    ),
    Mistake(
        "invert_rotation_flipped",
        "invert_rotation",
        "reverses the rows instead of transposing",
        """
def invert_rotation(R_ab):
    return np.asarray(R_ab, dtype=float)[::-1].copy()
""",
        hint="order of the rows",
        public_hint="order of the rows",
    ),
    Mistake(
        "nearest_rotation_normalised_columns",
        "nearest_rotation",
        "divides each column by its length",
        """
def nearest_rotation(M):
    M = np.asarray(M, dtype=float)
    return M / np.linalg.norm(M, axis=0)
""",
        hint="dividing each column",
        public_hint="dividing each column",
    ),
    Mistake(
        "nearest_rotation_transposed",
        "nearest_rotation",
        "V Uᵀ instead of U Vᵀ",
        """
def nearest_rotation(M):
    U, _, Vt = np.linalg.svd(np.asarray(M, dtype=float))
    D = np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))])
    return (U @ D @ Vt).T
""",
        hint="V Uᵀ",
        public_hint="V Uᵀ",
    ),
    Mistake(
        "nearest_rotation_fix_on_rows",
        "nearest_rotation",
        "the determinant fix on the wrong side of U: flips U's last row (a rotation, not the nearest)",
        """
def nearest_rotation(M):
    U, _, Vt = np.linalg.svd(np.asarray(M, dtype=float))
    d = np.sign(np.linalg.det(U @ Vt))
    return np.diag([1.0, 1.0, d]) @ U @ Vt
""",
        hint="the sign fix goes between U and Vᵀ",
        public_hint="the sign fix goes between U and Vᵀ",
    ),
    Mistake(
        "nearest_rotation_qr",
        "nearest_rotation",
        "the Q of a QR decomposition (orthogonal, not nearest)",
        """
def nearest_rotation(M):
    Q, R = np.linalg.qr(np.asarray(M, dtype=float))
    Q = Q @ np.diag(np.sign(np.diag(R)))
    return Q * np.sign(np.linalg.det(Q))
""",
        hint="QR decomposition",
        public_hint="QR decomposition",
    ),
    Mistake(
        "rot2d_endless_loop",
        "rot2d",
        "an endless loop",
        """
def rot2d(theta):
    while theta == theta:
        theta = theta + 0.0
    return np.eye(2)
""",
        kind="fault",
    ),
    Mistake(
        "compose_exits",
        "compose",
        "calls os._exit when called",
        """
import os

def compose(R_ab, R_bc):
    os._exit(1)
""",
        kind="fault",
    ),
    Mistake(
        "invert_rotation_recursion",
        "invert_rotation",
        "unbounded recursion",
        """
def invert_rotation(R_ab):
    return invert_rotation(R_ab).T
""",
        kind="fault",
    ),
    Mistake(
        "rot_x_small_angle_series",
        "rot_x",
        "sin a ≈ a and cos a ≈ 1 - a²/2 below 1e-2, to save the trig calls",
        hint="truncated series",
        public_hint="truncated series",
        source="""
def rot_x(a):
    if abs(a) < 1e-2:
        c, s = 1.0 - a * a / 2.0, a
    else:
        c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
""",
    ),
    Mistake(
        "rot_z_float32",
        "rot_z",
        "stores the matrix in float32 (single precision)",
        hint="float32 rounding",
        public_hint="float32 rounding",
        source="""
def rot_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]], dtype=np.float32)
""",
    ),
    Mistake(
        "compose_float32",
        "compose",
        "converts both factors to float32 to save memory",
        hint="float32 rounding",
        public_hint="float32 rounding",
        source="""
def compose(R_ab, R_bc):
    return np.asarray(R_ab, dtype=np.float32) @ np.asarray(R_bc, dtype=np.float32)
""",
    ),
    Mistake(
        "is_rotation_frobenius_norm",
        "is_rotation_matrix",
        "compares the Frobenius norm of MᵀM - I with tol, not its largest entry (tol read another way)",
        """
def is_rotation_matrix(M, tol=1e-9):
    try:
        M = np.asarray(M, dtype=float)
    except (TypeError, ValueError):
        return False
    if M.ndim != 2 or M.shape[0] != M.shape[1] or not np.all(np.isfinite(M)):
        return False
    return bool(np.linalg.norm(M.T @ M - np.eye(M.shape[0])) <= tol and np.linalg.det(M) > 0)
""",
        hint="equal to tol must pass",
        public_hint="equal to tol must pass",
    ),
    Mistake(
        "compose_returns_list",
        "compose",
        "the right numbers as nested lists (.tolist()): R_ac @ p then fails in the caller",
        """
def compose(R_ab, R_bc):
    return (np.asarray(R_ab, dtype=float) @ np.asarray(R_bc, dtype=float)).tolist()
""",
        hint="a list is not an array",
        public_hint="a list is not an array",
    ),
]

ALTERNATIVES = [
    Alternative(
        "rot2d_complex",
        "rot2d",
        "from the complex number e^{iθ}",
        """
def rot2d(theta):
    z = np.exp(1j * theta)
    return np.array([[z.real, -z.imag], [z.imag, z.real]])
""",
    ),
    Alternative(
        "rot_x_block",
        "rot_x",
        "np.block with the 2D rotation",
        """
def rot_x(a):
    c, s = np.cos(a), np.sin(a)
    return np.block([[np.ones((1, 1)), np.zeros((1, 2))], [np.zeros((2, 1)), np.array([[c, -s], [s, c]])]])
""",
    ),
    Alternative(
        "rot_y_lists",
        "rot_y",
        "written as nested lists, then made an array",
        """
def rot_y(a):
    return np.array([[np.cos(a), 0.0, np.sin(a)], [0.0, 1.0, 0.0], [-np.sin(a), 0.0, np.cos(a)]])
""",
    ),
    Alternative(
        "rot_z_rodrigues",
        "rot_z",
        "Rodrigues' formula about e_z",
        """
def rot_z(a):
    K = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    return np.eye(3) + np.sin(a) * K + (1.0 - np.cos(a)) * (K @ K)
""",
    ),
    Alternative(
        "is_rotation_numpy_bool",
        "is_rotation_matrix",
        "returns a numpy bool; catches what is not a matrix with one except clause; .max() and len(M)",
        """
def is_rotation_matrix(M, tol=1e-9):
    try:
        M = np.array(M, dtype=float)
    except Exception:
        return False
    if M.ndim != 2 or M.shape[0] != M.shape[1] or not np.isfinite(M).all():
        return False
    return np.abs(M.T @ M - np.eye(len(M))).max() <= tol and np.linalg.det(M) > 0
""",
    ),
    Alternative(
        "rotate_point_einsum",
        "rotate_point",
        "einsum over the last axis",
        """
def rotate_point(R_wb, p_b):
    return np.einsum("ij,...j->...i", np.asarray(R_wb, dtype=float), np.asarray(p_b, dtype=float))
""",
    ),
    Alternative(
        "compose_dot_lists",
        "compose",
        "np.dot, the first factor converted to float (the second may stay a list)",
        """
def compose(R_ab, R_bc):
    return np.dot(np.array(R_ab, dtype=float), R_bc)
""",
    ),
    Alternative(
        "invert_rotation_inv",
        "invert_rotation",
        "np.linalg.inv",
        """
def invert_rotation(R_ab):
    return np.linalg.inv(np.asarray(R_ab, dtype=float))
""",
    ),
    Alternative(
        "nearest_rotation_flip_vt",
        "nearest_rotation",
        "flips the last row of Vᵀ instead of U's column",
        """
def nearest_rotation(M):
    U, _, Vt = np.linalg.svd(np.asarray(M, dtype=float))
    if np.linalg.det(U) * np.linalg.det(Vt) < 0:
        Vt[-1] *= -1.0
    return U @ Vt
""",
    ),
]

SAMPLE = {
    "dev": ["rot_z_transposed", "rotate_point_transposed"],
    "emma": ["rot_x_degrees", "rot_y_degrees", "rot_z_degrees"],
    "farid": ["is_rotation_no_det", "nearest_rotation_reflection"],
    "ivy": ["rot2d_endless_loop", "compose_exits", "invert_rotation_recursion"],
}
