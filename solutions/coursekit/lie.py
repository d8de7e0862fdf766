"""Library versions of the rotation maps, for the lessons after you wrote your own.

Lesson 03 asks you to write ``hat``, ``exp_so3`` and ``log_so3`` yourself,
and lesson 07 ``exp_se3`` and ``log_se3``. Later lessons use these versions
instead, so that a slip in an earlier exercise never breaks a later lesson. ``Exp`` and ``Log`` are
built on ``scipy.spatial.transform.Rotation``, which handles every edge case
(tiny angles, angles at π) carefully; scipy is imported at their first call,
not with this module (it takes a quarter of a second, which the grader would
otherwise spend on every student whose code never calls them).
"""

import numpy as np

__all__ = ["skew", "unskew", "Exp", "Log", "ExpSE3", "LogSE3", "AdSE3", "JrSE3", "quat_product"]


def skew(v):
    """The 3×3 cross-product matrix [v]×, so that ``skew(v) @ u == np.cross(v, u)``.

    Examples
    --------
    >>> skew([1.0, 2.0, 3.0]) @ [4.0, 5.0, 6.0]
    array([-3.,  6., -3.])
    """
    x, y, z = np.asarray(v, dtype=float)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def unskew(S):
    """The vector v of a skew-symmetric matrix S = [v]× (the antisymmetric part is used)."""
    S = np.asarray(S, dtype=float)
    return 0.5 * np.array([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]])


def Exp(w):
    """Rotation matrix of the rotation vector ``w`` (shape (3,)): angle |w| about w/|w|.

    Examples
    --------
    >>> np.round(Exp([0.0, 0.0, np.pi / 2]) @ [1.0, 0.0, 0.0], 12)
    array([0., 1., 0.])
    """
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def Log(R):
    """Rotation vector of the rotation matrix ``R`` (shape (3, 3)), angle in [0, π]."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_matrix(np.asarray(R, dtype=float)).as_rotvec()


def _twist_matrix(xi):
    """The 4×4 matrix ξ^ = [[[φ]×, ρ], [0, 0]] of a twist ξ = [ρ, φ]."""
    xi = np.asarray(xi, dtype=float).reshape(6)
    M = np.zeros((4, 4))
    M[:3, :3] = skew(xi[3:])
    M[:3, 3] = xi[:3]
    return M


def ExpSE3(xi):
    """The pose exp(ξ^) of a twist ``xi = [rho, phi]`` (translation part first), shape (4, 4).

    Computed with scipy's general matrix exponential of the 4×4 twist matrix.

    Examples
    --------
    >>> np.round(ExpSE3([1.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])[:3, 3], 4)   # forward while turning left
    array([0.6366, 0.6366, 0.    ])
    """
    from scipy.linalg import expm

    T = expm(_twist_matrix(xi))
    T[3] = [0.0, 0.0, 0.0, 1.0]
    return T


def LogSE3(T):
    """The twist ``[rho, phi]`` of a pose ``T`` (shape (4, 4)), with the angle of ``phi`` in [0, π].

    ``phi = Log(R)``; ``rho`` is the translation part whose ``ExpSE3([rho, phi])`` lands on ``t``
    (that translation is linear in ``rho``: its matrix is read off ``ExpSE3`` of the three unit shifts).

    Examples
    --------
    >>> T = ExpSE3([0.5, -1.0, 2.0, 0.3, -0.2, 0.9])
    >>> np.round(LogSE3(T), 6)
    array([ 0.5, -1. ,  2. ,  0.3, -0.2,  0.9])
    """
    pose = np.asarray(T, dtype=float)
    rotation_vector = Log(pose[:3, :3])
    shifts = np.column_stack([ExpSE3(np.concatenate([e, rotation_vector]))[:3, 3] for e in np.eye(3)])
    return np.concatenate([np.linalg.solve(shifts, pose[:3, 3]), rotation_vector])


def _vee_twist(M):
    """The twist [ρ, φ] of a 4×4 twist matrix (the inverse of ``_twist_matrix``)."""
    return np.concatenate([M[:3, 3], unskew(M[:3, :3])])


def AdSE3(T):
    """The adjoint of a pose ``T`` (shape (4, 4)): the 6×6 matrix with T Exp(ξ) T⁻¹ = Exp(Ad_T ξ).

    Twists are written ``[rho, phi]``, translation part first. Computed from the Jacobians of Exp at
    ξ = Log(T): moving a small step from the right of Exp(ξ) to its left, Exp(ξ) Exp(J_r(ξ) d) ≈
    Exp(ξ + d) ≈ Exp(J_r(−ξ) d) Exp(ξ), so Ad_T J_r(ξ) = J_r(−ξ) (no block of the matrix is written out).

    Examples
    --------
    >>> T = ExpSE3([0.5, -1.0, 2.0, 0.3, -0.2, 0.9])
    >>> xi = np.array([0.1, 0.2, -0.3, 0.05, 0.0, -0.1])
    >>> bool(np.allclose(T @ ExpSE3(xi) @ np.linalg.inv(T), ExpSE3(AdSE3(T) @ xi)))
    True
    """
    twist = LogSE3(T)
    return np.linalg.solve(JrSE3(twist).T, JrSE3(-twist).T).T


def JrSE3(xi):
    """The right Jacobian of SE(3) at the twist ``xi = [rho, phi]``, shape (6, 6).

    Defined by Exp(ξ + dξ) ≈ Exp(ξ) Exp(J_r(ξ) dξ) for small dξ, and computed from that definition:
    column j is the twist of Exp(ξ)⁻¹ times the derivative of Exp along e_j, read exactly from the
    exponential of the block matrix [[ξ^, e_j^], [0, ξ^]] (Van Loan's way to differentiate expm; no
    formula for J_r is written out). These six and Exp(−ξ), the inverse, are taken in one batched call.
    Its inverse is the Jacobian of Log: Log(Exp(ξ) Exp(δ)) ≈ ξ + J_r(ξ)⁻¹ δ.

    Examples
    --------
    >>> xi = np.array([0.5, -1.0, 2.0, 0.3, -0.2, 0.9]); d = 1e-6 * np.array([1.0, 2, 3, 4, 5, 6])
    >>> step = LogSE3(np.linalg.inv(ExpSE3(xi)) @ ExpSE3(xi + d))
    >>> bool(np.allclose(step, JrSE3(xi) @ d, atol=1e-11))
    True
    """
    from scipy.linalg import expm

    twist = np.asarray(xi, dtype=float).reshape(6)
    # A long rho is scaled to length 1 first, for accuracy: the pose map diag(c, c, c, 1) scales the translation
    # part of every twist by c and leaves phi alone, so it scales the columns and rows of J_r that mix the two.
    size = max(1.0, float(np.linalg.norm(twist[:3])))
    base = _twist_matrix(np.concatenate([twist[:3] / size, twist[3:]]))
    blocks = np.zeros((7, 8, 8))
    blocks[:6, :4, :4] = blocks[:6, 4:, 4:] = base
    for j, direction in enumerate(np.eye(6)):
        blocks[j, :4, 4:] = _twist_matrix(direction)
    blocks[6, :4, :4] = -base  # its exponential is the pose's inverse
    exponentials = expm(blocks)
    inverse, derivatives = exponentials[6, :4, :4], exponentials[:6, :4, 4:]
    J = np.column_stack([_vee_twist(inverse @ derivative) for derivative in derivatives])
    J[:3, 3:] *= size
    return J


def quat_product(p, q):
    """Hamilton product p ⊗ q of two quaternions stored scalar first, ``[w, x, y, z]``.

    Lesson 04 asks you to write this yourself as ``quat_multiply``; later
    lessons use this copy.

    Examples
    --------
    >>> quat_product([0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0])   # i ⊗ j = k
    array([0., 0., 0., 1.])
    """
    pw, px, py, pz = np.asarray(p, dtype=float)
    qw, qx, qy, qz = np.asarray(q, dtype=float)
    return np.array([pw * qw - px * qx - py * qy - pz * qz,
                     pw * qx + px * qw + py * qz - pz * qy,
                     pw * qy - px * qz + py * qw + pz * qx,
                     pw * qz + px * qy - py * qx + pz * qw])
