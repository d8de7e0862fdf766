"""Typical mistakes and correct alternatives for lesson 09, section 4: compound_pose_covariance."""

from . import Alternative, Mistake

_COMPOUND = """
def compound_pose_covariance(T1, S1, T2, S2):
    T1 = np.asarray(T1, dtype=float)
    T2 = np.asarray(T2, dtype=float)
    S1 = np.asarray(S1, dtype=float)
    S2 = np.asarray(S2, dtype=float)
    A = {adjoint}
    return {pose}, {carried} + S2
"""


def _compound(adjoint="AdSE3(np.linalg.inv(T2))", pose="T1 @ T2", carried="A @ S1 @ A.T"):
    return _COMPOUND.format(adjoint=adjoint, pose=pose, carried=carried)


MISTAKES = [
    Mistake(
        "compound_finite_differences",
        "compound_pose_covariance",
        "ξ1's Jacobian by central differences of the definition instead of derived",
        """
def compound_pose_covariance(T1, S1, T2, S2):
    T1, S1, T2, S2 = (np.asarray(a, dtype=float) for a in (T1, S1, T2, S2))
    inverse = np.linalg.inv(T1 @ T2)
    h = 1e-6
    A = np.column_stack(
        [(LogSE3(inverse @ T1 @ ExpSE3(h * e) @ T2) - LogSE3(inverse @ T1 @ ExpSE3(-h * e) @ T2)) / (2 * h)
         for e in np.eye(6)]
    )
    return T1 @ T2, A @ S1 @ A.T + S2
""",
        hint="which finite differences (good to about 1e-10) cannot reach",
        public_hint="which finite differences (good to about 1e-10) cannot reach",
    ),
    Mistake(
        "compound_no_transport",
        "compound_pose_covariance",
        "S1 + S2: the first twist not carried across T2",
        _compound(carried="S1"),
        hint="your S ignores T2",
        public_hint="your S ignores T2",
        classic=True,
    ),
    Mistake(
        "compound_wrong_way",
        "compound_pose_covariance",
        "Ad(T2) instead of Ad(T2⁻¹)",
        _compound(adjoint="AdSE3(T2)"),
        hint="but not as ξ1 moves",
        public_hint="but not as ξ1 moves",
    ),
    Mistake(
        "compound_other_pose",
        "compound_pose_covariance",
        "Ad(T1⁻¹): the adjoint of the wrong factor",
        _compound(adjoint="AdSE3(np.linalg.inv(T1))"),
        hint="S changes with T1 and should not",
        public_hint="S changes with T1 and should not",
    ),
    Mistake(
        "compound_rotation_only",
        "compound_pose_covariance",
        "diag(R2ᵀ, R2ᵀ): the coupling block forgotten",
        _compound(adjoint="np.kron(np.eye(2), T2[:3, :3].T)"),
        hint="a spin about T1's origin moves",
        public_hint="a spin about T1's origin moves",
    ),
    Mistake(
        "compound_one_sided",
        "compound_pose_covariance",
        "A S1 + S2: the map on one side only",
        _compound(carried="A @ S1"),
        hint="on both sides",
        public_hint="on both sides",
    ),
    Mistake(
        "compound_swapped",
        "compound_pose_covariance",
        "T = T2 T1",
        _compound(pose="T2 @ T1"),
        hint="T2 T1 is the other chain",
        public_hint="T2 T1 is the other chain",
    ),
    Mistake(
        "compound_lists_matmul",
        "compound_pose_covariance",
        "T1 @ T2 on the inputs as given: @ does not work on two lists",
        """
def compound_pose_covariance(T1, S1, T2, S2):
    A = AdSE3(np.linalg.inv(T2))
    return T1 @ T2, A @ S1 @ A.T + S2
""",
        hint="the conventions admit nested lists",
        public_hint="unsupported operand type(s) for @: 'list' and 'list'",
    ),
]

ALTERNATIVES = [
    Alternative(
        "compound_by_blocks",
        "compound_pose_covariance",
        "the adjoint of T2⁻¹ written by blocks",
        """
def compound_pose_covariance(T1, S1, T2, S2):
    T1, T2 = np.asarray(T1, dtype=float), np.asarray(T2, dtype=float)
    R, t = T2[:3, :3].T, -T2[:3, :3].T @ T2[:3, 3]
    A = np.block([[R, skew(t) @ R], [np.zeros((3, 3)), R]])
    S = A @ np.asarray(S1, dtype=float) @ A.T + np.asarray(S2, dtype=float)
    return T1 @ T2, S
""",
    ),
]
