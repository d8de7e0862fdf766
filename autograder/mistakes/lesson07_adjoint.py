"""Typical mistakes and correct alternatives for lesson 07, section 10: the adjoint and three Jacobians."""

from . import Alternative, Mistake


def _adjoint(coupling, rotation_first=False):
    block = "Ad[3:, :3]" if rotation_first else "Ad[:3, 3:]"
    return f"""
def adjoint_se3(T):
    T = np.asarray(T, dtype=float)
    R, t = T[:3, :3], T[:3, 3]
    Ad = np.zeros((6, 6))
    Ad[:3, :3] = R
    Ad[3:, 3:] = R
    {block} = {coupling}
    return Ad
"""


_SERIES = """
def right_jacobian_se3(xi):
    xi = np.asarray(xi, dtype=float).reshape(6)
    ad = np.zeros((6, 6))
    ad[:3, :3] = skew(xi[3:])
    ad[3:, 3:] = skew(xi[3:])
    ad[:3, 3:] = skew(xi[:3])
    A = {sign}ad
    S = np.eye(6)
    for k in range({terms}, 0, -1):
        S = np.eye(6) + A @ S / (k + 1)
    {finish}
    return S
"""


def _series(sign="-", terms=30, finish="pass"):
    return _SERIES.format(sign=sign, terms=terms, finish=finish)


# The SO(3) right Jacobian of lesson 06, with its small-angle series, for the diagonal blocks.
_JR_SO3 = """
    def jr_so3(w):
        theta = np.linalg.norm(w)
        W = skew(w)
        if theta < 1e-2:
            a = 0.5 - theta**2 / 24.0 + theta**4 / 720.0
            b = 1.0 / 6.0 - theta**2 / 120.0 + theta**4 / 5040.0
        else:
            a = (1.0 - np.cos(theta)) / theta**2
            b = (theta - np.sin(theta)) / theta**3
        return np.eye(3) - a * W + b * (W @ W)
"""

MISTAKES = [
    # ------------------------------------------------------------ adjoint_se3
    Mistake(
        "adjoint_rotation_first",
        "adjoint_se3",
        "the coupling block bottom-left (rotation-first layout)",
        _adjoint("skew(t) @ R", rotation_first=True),
        hint="came out with a spin",
        public_hint="came out with a spin",
    ),
    Mistake(
        "adjoint_no_coupling",
        "adjoint_se3",
        "diag(R, R): forgets the coupling of spin and shift",
        _adjoint("np.zeros((3, 3))"),
        hint="came out with no translation part",
        public_hint="came out with no translation part",
        classic=True,
    ),
    Mistake(
        "adjoint_coupling_without_R",
        "adjoint_se3",
        "coupling block [t]× without R",
        _adjoint("skew(t)"),
        hint="stays the same when T turns",
        public_hint="stays the same when T turns",
    ),
    Mistake(
        "adjoint_coupling_sign",
        "adjoint_se3",
        "coupling block -[t]× R",
        _adjoint("-skew(t) @ R"),
        hint="is the negative of that of (T ξ^ T⁻¹)∨",
        public_hint="is the negative of that of (T ξ^ T⁻¹)∨",
    ),
    Mistake(
        "adjoint_coupling_order",
        "adjoint_se3",
        "coupling block R [t]×: the factors swapped",
        _adjoint("R @ skew(t)"),
        hint="try a pure spin",
        public_hint="try a pure spin",
    ),
    # ------------------------------------------------------------ jacobian_transform_point
    Mistake(
        "point_left",
        "jacobian_transform_point",
        "[I, -[T p]×]: the Jacobian of the left perturbation",
        """
def jacobian_transform_point(T, p):
    T = np.asarray(T, dtype=float)
    return np.hstack([np.eye(3), -skew(T[:3, :3] @ np.asarray(p, dtype=float) + T[:3, 3])])
""",
        hint="left perturbation Exp(xi) T",
        public_hint="a left (world-frame) perturbation",
        classic=True,
    ),
    Mistake(
        "point_rotation_first",
        "jacobian_transform_point",
        "[-R [p]×, R]: rotation columns first",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([-R @ skew(p), R])
""",
        hint="the first three columns are for",
        public_hint="the first three columns are for",
    ),
    Mistake(
        "point_translation_identity",
        "jacobian_transform_point",
        "[I, -R [p]×]: the shift not turned by R",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([np.eye(3), -R @ skew(p)])
""",
        hint="the rho block is off",
        public_hint="the rho block is off",
    ),
    Mistake(
        "point_sign",
        "jacobian_transform_point",
        "[R, R [p]×]: the sign of [phi]× p = -[p]× phi lost",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([R, R @ skew(p)])
""",
        hint="the phi columns of J are the negative of the finite differences",
        public_hint="the phi columns of J are the negative of the finite differences",
    ),
    Mistake(
        "point_world_rotation",
        "jacobian_transform_point",
        "[R, -[R p]×]: a left rotation block",
        """
def jacobian_transform_point(T, p):
    R = np.asarray(T, dtype=float)[:3, :3]
    return np.hstack([R, -skew(R @ np.asarray(p, dtype=float))])
""",
        hint="-[R p]× is the rotation block of a left perturbation",
        public_hint="turns the point about the world's axes",
    ),
    # ------------------------------------------------------------ right_jacobian_se3
    Mistake(
        "jr_se3_no_coupling",
        "right_jacobian_se3",
        "diag(J_r(phi), J_r(phi)): the SO(3) Jacobian on the diagonal, the coupling block zero",
        """
def right_jacobian_se3(xi):
    xi = np.asarray(xi, dtype=float).reshape(6)
"""
        + _JR_SO3
        + """
    J = np.zeros((6, 6))
    J[:3, :3] = jr_so3(xi[3:])
    J[3:, 3:] = jr_so3(xi[3:])
    return J
""",
        hint="a change of phi never reaches the translation part",
        public_hint="a change of phi never reaches the translation part",
        classic=True,
    ),
    Mistake(
        "jr_se3_left",
        "right_jacobian_se3",
        "the left Jacobian: the series in +ad instead of -ad",
        _series(sign="+"),
        hint="the left Jacobian",
        public_hint="the left Jacobian",
    ),
    Mistake(
        "jr_se3_coupling_sign",
        "right_jacobian_se3",
        "the coupling block with the wrong sign",
        _series(finish="S[:3, 3:] = -S[:3, 3:]"),
        hint="the phi columns of J's translation rows are the negative",
        public_hint="the phi columns of J's translation rows are the negative",
    ),
    Mistake(
        "jr_se3_short_series",
        "right_jacobian_se3",
        "I - ad/2 + ad²/6 - ad³/24: a series cut off after four terms",
        _series(terms=3),
        hint="a series cut off after a few terms",
        public_hint="a series cut off after a few terms",
    ),
    Mistake(
        "jr_se3_forward_differences",
        "right_jacobian_se3",
        "forward differences of the definition with h = 1e-6",
        """
def right_jacobian_se3(xi):
    xi = np.asarray(xi, dtype=float).reshape(6)
    base_inverse = np.linalg.inv(exp_se3(xi))
    h = 1e-6
    return np.column_stack([log_se3(base_inverse @ exp_se3(xi + h * e)) / h for e in np.eye(6)])
""",
        hint="finite differences stop short of rounding",
        public_hint="finite differences stop short of rounding",
    ),
    Mistake(
        "jr_se3_inverse",
        "right_jacobian_se3",
        "the inverse: the Jacobian of Log instead of that of Exp",
        "\n" + _series(finish="S = np.linalg.inv(S)").strip() + "\n",
        hint="the Jacobian of Log",
        public_hint="the Jacobian of Log",
    ),
    Mistake(
        "adjoint_lists_sliced",
        "adjoint_se3",
        "T[:3, :3] on the input as given: a nested list takes no 2-D slice",
        """
def adjoint_se3(T):
    R, t = T[:3, :3], T[:3, 3]
    Ad = np.zeros((6, 6))
    Ad[:3, :3] = R
    Ad[:3, 3:] = skew(t) @ R
    Ad[3:, 3:] = R
    return Ad
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "transform_point_jacobian_lists_sliced",
        "jacobian_transform_point",
        "T[:3, :3] on the input as given: a nested list takes no 2-D slice",
        """
def jacobian_transform_point(T, p):
    R = T[:3, :3]
    return np.hstack([R, -R @ skew(p)])
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
    Mistake(
        "right_jacobian_se3_lists_reshaped",
        "right_jacobian_se3",
        "xi.reshape(6) on the input as given: a list has no reshape",
        """
def right_jacobian_se3(xi):
    xi = xi.reshape(6)
    ad = np.zeros((6, 6))
    ad[:3, :3] = skew(xi[3:])
    ad[3:, 3:] = skew(xi[3:])
    ad[:3, 3:] = skew(xi[:3])
    A = -ad
    S = np.eye(6)
    for k in range(30, 0, -1):
        S = np.eye(6) + A @ S / (k + 1)
    return S
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "adjoint_block",
        "adjoint_se3",
        "np.block with the cross products written as matrices",
        """
def adjoint_se3(T):
    T = np.asarray(T, dtype=float)
    R, t = T[:3, :3], T[:3, 3]
    coupling = np.column_stack([np.cross(t, R[:, j]) for j in range(3)])
    return np.block([[R, coupling], [np.zeros((3, 3)), R]])
""",
    ),
    Alternative(
        "point_generators",
        "jacobian_transform_point",
        "T times each of the six generators of se(3)",
        """
def jacobian_transform_point(T, p):
    T = np.asarray(T, dtype=float)
    p_h = np.append(np.asarray(p, dtype=float), 1.0)
    columns = []
    for j in range(6):
        G = np.zeros((4, 4))
        if j < 3:
            G[j, 3] = 1.0
        else:
            G[:3, :3] = skew(np.eye(3)[j - 3])
        columns.append((T @ G @ p_h)[:3])
    return np.column_stack(columns)
""",
    ),
    Alternative(
        "jr_se3_closed_form",
        "right_jacobian_se3",
        "Barfoot's closed form of the coupling block, Q(-rho, -phi), with series below 1e-2",
        """
def right_jacobian_se3(xi):
    xi = np.asarray(xi, dtype=float).reshape(6)
    rho, phi = -xi[:3], -xi[3:]
    theta = np.linalg.norm(phi)
    W, P = skew(phi), skew(rho)
    if theta < 1e-2:
        c1 = 1.0 / 6.0 - theta**2 / 120.0 + theta**4 / 5040.0
        c2 = 1.0 / 24.0 - theta**2 / 720.0 + theta**4 / 40320.0
        c3 = 1.0 / 120.0 - theta**2 / 2520.0 + theta**4 / 120960.0
        a = 0.5 - theta**2 / 24.0 + theta**4 / 720.0
    else:
        c1 = (theta - np.sin(theta)) / theta**3
        c2 = (theta**2 + 2.0 * np.cos(theta) - 2.0) / (2.0 * theta**4)
        c3 = (2.0 * theta - 3.0 * np.sin(theta) + theta * np.cos(theta)) / (2.0 * theta**5)
        a = (1.0 - np.cos(theta)) / theta**2
    Q = (0.5 * P + c1 * (W @ P + P @ W + W @ P @ W) + c2 * (W @ W @ P + P @ W @ W - 3.0 * W @ P @ W)
         + c3 * (W @ P @ W @ W + W @ W @ P @ W))
    Jr = np.eye(3) + a * W + c1 * (W @ W)        # J_r(-phi) written with W = [-phi]×: I - a [phi]× + ...
    J = np.zeros((6, 6))
    J[:3, :3] = Jr
    J[3:, 3:] = Jr
    J[:3, 3:] = Q
    return J
""",
    ),
    Alternative(
        "jr_se3_quadrature",
        "right_jacobian_se3",
        "Gauss-Legendre quadrature of the integral of Ad(Exp(-s xi)) over s in [0, 1], 20 nodes",
        """
def right_jacobian_se3(xi):
    xi = np.asarray(xi, dtype=float).reshape(6)
    rho, phi = xi[:3], xi[3:]
    nodes, weights = np.polynomial.legendre.leggauss(20)
    J = np.zeros((6, 6))
    for x, w in zip(nodes, weights):
        s = (x + 1.0) / 2.0
        # Exp(-s xi): rotation Exp(-s phi) and translation V(-s phi) (-s rho), V as a series-free integral
        R = Exp(-s * phi)
        u_nodes, u_weights = np.polynomial.legendre.leggauss(20)
        V = sum(uw / 2.0 * Exp(-s * (ux + 1.0) / 2.0 * phi) for ux, uw in zip(u_nodes, u_weights))
        t = V @ (-s * rho)
        Ad = np.zeros((6, 6))
        Ad[:3, :3] = R
        Ad[3:, 3:] = R
        Ad[:3, 3:] = skew(t) @ R
        J += w / 2.0 * Ad
    return J
""",
    ),
    Alternative(
        "jr_se3_series_lists",
        "right_jacobian_se3",
        "the series term by term until the terms vanish, from a list",
        """
def right_jacobian_se3(xi):
    xi = [float(x) for x in xi]
    ad = np.zeros((6, 6))
    ad[:3, :3] = skew(xi[3:])
    ad[3:, 3:] = skew(xi[3:])
    ad[:3, 3:] = skew(xi[:3])
    term = np.eye(6)
    J = np.eye(6)
    for k in range(1, 60):
        term = term @ (-ad) / (k + 1)
        J = J + term
    return J
""",
    ),
]

SAMPLE = {}
