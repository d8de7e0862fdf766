"""Typical mistakes of every lesson against the contracts beyond the value (``coursekit.contracts``).

- **Arguments changed in place**: the docstrings promise that an argument is
  left alone (a later cell that reuses it would print wrong values); the
  checks watch every call and a change costs the exercise a quarter of its
  points, with its own check line and hint in both suites.
- **Delegation**: where an exercise asks for its own implementation of a map,
  a call of the library version (``coursekit.lie``, scipy's ``Rotation``)
  earns the exercise nothing, and both suites say which function it called.
- **The documented dtype**: a real answer returned as complex numbers.

They live apart from the lessons' own lists so that adding them leaves the
benchmark's class (``tests/support.py: benchmark_class``), which draws
mistakes from the lessons' lists in order, as it was.
"""

from . import Mistake

MISTAKES = [
    Mistake(
        "rotate_point_in_place",
        "rotate_point",
        "writes the rotated point into the caller's array p_b",
        """
def rotate_point(R_wb, p_b):
    p_b = np.asarray(p_b, dtype=float)
    p_b[...] = p_b @ np.asarray(R_wb, dtype=float).T
    return p_b
""",
        hint="work on a copy",
        public_hint="work on a copy",
    ),
    Mistake(
        "hat_delegates",
        "hat",
        "a one-line wrapper around coursekit.lie.skew",
        """
def hat(w):
    from coursekit.lie import skew
    return skew(w)
""",
        hint="write the exercise with numpy yourself",
        public_hint="write the exercise with numpy yourself",
    ),
    Mistake(
        "exp_so3_delegates",
        "exp_so3",
        "a one-line wrapper around coursekit.lie.Exp",
        """
def exp_so3(w):
    from coursekit.lie import Exp
    return Exp(w)
""",
        hint="write the exercise with numpy yourself",
        public_hint="write the exercise with numpy yourself",
    ),
    Mistake(
        "log_so3_delegates",
        "log_so3",
        "scipy's Rotation does the work",
        """
def log_so3(R):
    from scipy.spatial.transform import Rotation
    return Rotation.from_matrix(np.asarray(R, dtype=float)).as_rotvec()
""",
        hint="write the exercise with numpy yourself",
        public_hint="write the exercise with numpy yourself",
    ),
    Mistake(
        "right_jacobian_inverts_the_printed_inverse",
        "right_jacobian_so3",
        "inverts the closed form of J_r⁻¹ that the lesson prints for Exercise 8 instead of deriving J_r",
        """
def right_jacobian_so3(w):
    w = np.asarray(w, dtype=float)
    theta = np.linalg.norm(w)
    W = skew(w)
    if theta < 1e-3:
        c = 1.0 / 12.0 + theta**2 / 720.0
    else:
        c = 1.0 / theta**2 - (1.0 + np.cos(theta)) / (2.0 * theta * np.sin(theta))
    return np.linalg.inv(np.eye(3) + W / 2.0 + c * (W @ W))
""",
        hint="a general inverse or solver finds the numbers",
        public_hint="a general inverse or solver finds the numbers",
    ),
    Mistake(
        "pose_inverse_general_inverse",
        "pose_inverse",
        "np.linalg.inv of the 4×4 matrix, where the exercise asks for the blocks built from R and t",
        """
def pose_inverse(T):
    return np.linalg.inv(np.asarray(T, dtype=float))
""",
        hint="a general inverse or solver finds the numbers",
        public_hint="a general inverse or solver finds the numbers",
    ),
    Mistake(
        "exp_se3_solves_with_the_printed_V_inverse",
        "exp_se3",
        "solves with the V⁻¹ that the lesson prints for the logarithm instead of deriving V",
        """
def exp_se3(xi):
    xi = np.asarray(xi, dtype=float).reshape(6)
    rho, phi = xi[:3], xi[3:]
    theta = np.linalg.norm(phi)
    W = skew(phi)
    if theta < 1e-2:
        c = 1.0 / 12.0 + theta**2 / 720.0
    else:
        c = (1.0 - theta / 2.0 / np.tan(theta / 2.0)) / theta**2
    T = np.eye(4)
    T[:3, :3] = Exp(phi)
    T[:3, 3] = np.linalg.solve(np.eye(3) - W / 2.0 + c * (W @ W), rho)
    return T
""",
        hint="a general inverse or solver finds the numbers",
        public_hint="a general inverse or solver finds the numbers",
    ),
    Mistake(
        "axis_from_eigen_complex",
        "axis_from_eigen",
        "np.linalg.eig's complex eigenvector returned as it comes (dtype complex128, zero imaginary part)",
        """
def axis_from_eigen(R):
    values, vectors = np.linalg.eig(np.asarray(R, dtype=float))
    u = vectors[:, int(np.argmin(np.abs(values - 1.0)))]
    return u / np.linalg.norm(u)
""",
        hint="return np.real(...) of it",
        public_hint="return np.real(...) of it",
    ),
    Mistake(
        "quat_conjugate_in_place",
        "quat_conjugate",
        "negates the caller's vector part in place",
        """
def quat_conjugate(q):
    q = np.asarray(q, dtype=float)
    q[1:] *= -1
    return q
""",
        hint="work on a copy",
        public_hint="work on a copy",
    ),
    Mistake(
        "quat_from_axis_angle_normalises_in_place",
        "quat_from_axis_angle",
        "normalises the caller's axis in place",
        """
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float)
    u /= np.linalg.norm(u)
    return np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])
""",
        hint="work on a copy",
        public_hint="work on a copy",
    ),
    Mistake(
        "quat_multiply_delegates",
        "quat_multiply",
        "a one-line wrapper around coursekit.lie.quat_product",
        """
def quat_multiply(p, q):
    from coursekit.lie import quat_product
    return quat_product(p, q)
""",
        hint="write the exercise with numpy yourself",
        public_hint="write the exercise with numpy yourself",
    ),
    Mistake(
        "align_gauss_newton_updates_R0",
        "align_gauss_newton",
        "iterates in the caller's R0 (np.asarray, then R[...] = ...)",
        """
def align_gauss_newton(P, Q, R0, iters=10):
    P = np.asarray(P, dtype=float)
    Q = np.asarray(Q, dtype=float)
    R = np.asarray(R0, dtype=float)
    for _ in range(iters):
        H = np.zeros((3, 3))
        g = np.zeros(3)
        for p, q in zip(P, Q):
            J = -R @ skew(p)
            H += J.T @ J
            g += J.T @ (R @ p - q)
        R[...] = R @ Exp(np.linalg.solve(H, -g))
    return R
""",
        hint="work on a copy",
        public_hint="work on a copy",
    ),
]
