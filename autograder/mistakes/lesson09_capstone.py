"""Typical mistakes and correct alternatives for lesson 09, section 7: the capstone hand_eye_rotation (design)."""

from . import Alternative, Mistake

_ROBUST = """
def hand_eye_rotation(As, Bs):
    a = np.array([Log(A) for A in np.asarray(As, dtype=float)])      # A X = X B turns axes: Log(A) = X Log(B)
    b = np.array([Log(B) for B in np.asarray(Bs, dtype=float)])

    def weighted_alignment(w):
        U, _, Vt = np.linalg.svd((a * w[:, None]).T @ b)
        return U @ np.diag([1.0, 1.0, np.linalg.det(U @ Vt)]) @ Vt

    def misfits(X):
        return np.sqrt(np.sum((a - b @ X.T) ** 2, axis=1))

    # every pair of pairs proposes an X; keep the one most pairs agree with (within 0.1 rad)
    n = len(a)
    proposals = [weighted_alignment(np.isin(np.arange(n), [i, j]) * 1.0) for i in range(n) for j in range(i + 1, n)]
    X = max(proposals, key=lambda X: np.sum(misfits(X) < 0.1))
    # then refit on the pairs within three robust standard deviations, until that set stops changing
    keep = misfits(X) < 0.1
    for _ in range(100):
        X = weighted_alignment(keep * 1.0)
        r = misfits(X)
        new_keep = r <= 3.0 * 1.4826 * np.median(r)
        if np.array_equal(new_keep, keep):
            break
        keep = new_keep
    return X
"""

MISTAKES = [
    Mistake(
        "hand_eye_least_squares",
        "hand_eye_rotation",
        "one equally weighted fit of every pair: the outliers pull it away",
        """
def hand_eye_rotation(As, Bs):
    a = np.array([Log(A) for A in np.asarray(As, dtype=float)])
    b = np.array([Log(B) for B in np.asarray(Bs, dtype=float)])
    U, _, Vt = np.linalg.svd(a.T @ b)
    return U @ np.diag([1.0, 1.0, np.linalg.det(U @ Vt)]) @ Vt
""",
        hint="the wrong pairs pulled X away",
        public_hint="the wrong pairs pulled the answer away",
        classic=True,
    ),
    Mistake(
        "hand_eye_transposed",
        "hand_eye_rotation",
        "returns Xᵀ (fits B X = X A)",
        _ROBUST.replace("    return X\n", "    return X.T\n"),
        hint="that is Xᵀ",
        public_hint="that is Xᵀ",
    ),
    Mistake(
        "hand_eye_first_pairs",
        "hand_eye_rotation",
        "X from the first two pairs only",
        """
def hand_eye_rotation(As, Bs):
    a = np.array([Log(A) for A in np.asarray(As, dtype=float)[:2]])
    b = np.array([Log(B) for B in np.asarray(Bs, dtype=float)[:2]])
    U, _, Vt = np.linalg.svd(a.T @ b)
    return U @ np.diag([1.0, 1.0, np.linalg.det(U @ Vt)]) @ Vt
""",
        hint="use all the good ones",
        public_hint="the first pairs alone",
    ),
    Mistake(
        "hand_eye_not_projected",
        "hand_eye_rotation",
        "a linear least-squares 3×3 fit, never projected onto SO(3)",
        """
def hand_eye_rotation(As, Bs):
    a = np.array([Log(A) for A in np.asarray(As, dtype=float)])
    b = np.array([Log(B) for B in np.asarray(Bs, dtype=float)])
    return np.linalg.lstsq(b, a, rcond=None)[0].T
""",
        hint="X must be a rotation",
        public_hint="X must be a rotation",
    ),
]

ALTERNATIVES = [
    Alternative(
        "hand_eye_huber_irls",
        "hand_eye_rotation",
        "best single-pair-pair proposal by median misfit, then Huber-weighted refits to convergence",
        """
def hand_eye_rotation(As, Bs):
    a = [Log(A) for A in np.asarray(As, dtype=float)]
    b = [Log(B) for B in np.asarray(Bs, dtype=float)]
    a, b = np.array(a), np.array(b)

    def fit(w):
        U, _, Vt = np.linalg.svd((w[:, None] * a).T @ b)
        return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt

    n = len(a)
    best, best_score = None, np.inf
    for i in range(n):
        for j in range(i + 1, n):
            w = np.zeros(n)
            w[i] = w[j] = 1.0
            X = fit(w)
            score = np.median(np.linalg.norm(a - b @ X.T, axis=1))
            if score < best_score:
                best, best_score = X, score
    X = best
    for _ in range(300):
        r = np.linalg.norm(a - b @ X.T, axis=1)
        k = 1.4826 * np.median(r) + 1e-300
        w = np.where(r <= k, 1.0, k / np.maximum(r, 1e-300))
        w[r > 5 * k] = 0.0
        X = fit(w)
    return X
""",
    ),
]
