"""Typical mistakes for lesson 08, section 6: the weighted geodesic mean."""

from . import Alternative, Mistake

_ITERATION = """
def weighted_rotation_mean(Rs, weights):
    Rs = np.asarray(Rs, dtype=float)
    w = np.asarray(weights, dtype=float){extra}
    M = Rs[0]
    for _ in range({steps}):
        delta = sum(wi * Log(M.T @ R) for wi, R in zip(w, Rs)) / np.sum(w)
        M = M @ Exp(delta)
        if np.linalg.norm(delta) < 1e-13:
            break
    return M
"""

MISTAKES = [
    Mistake(
        "weighted_mean_ignores_weights",
        "weighted_rotation_mean",
        "ignores the weights",
        _ITERATION.format(extra="\n    w = np.ones(len(Rs))", steps=100),
        hint="the weights were ignored",
        public_hint="the weights were ignored",
        classic=True,
    ),
    Mistake(
        "weighted_mean_chordal",
        "weighted_rotation_mean",
        "the weighted chordal mean",
        """
def weighted_rotation_mean(Rs, weights):
    Rs = np.asarray(Rs, dtype=float)
    w = np.asarray(weights, dtype=float)
    U, _, Vt = np.linalg.svd(np.einsum("i,ijk->jk", w, Rs))
    return U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt
""",
        hint="weighted chordal mean",
        public_hint="weighted chordal mean",
    ),
    Mistake(
        "weighted_mean_one_step",
        "weighted_rotation_mean",
        "stops after one weighted step",
        _ITERATION.format(extra="", steps=1),
        hint="a single step from Rs[0]",
        public_hint="a single step from Rs[0]",
    ),
    Mistake(
        "weighted_mean_squared_weights",
        "weighted_rotation_mean",
        "weights squared",
        _ITERATION.format(extra="\n    w = w ** 2", steps=100),
        hint="the weights were squared",
        public_hint="the weights were squared",
    ),
    Mistake(
        "weighted_mean_lists",
        "weighted_rotation_mean",
        "M.T @ R on the rotations as given: an element of a list of lists has no .T",
        """
def weighted_rotation_mean(Rs, weights):
    M = Rs[int(np.argmax(weights))]
    for _ in range(100):
        delta = sum(wi * Log(M.T @ R) for wi, R in zip(weights, Rs)) / np.sum(weights)
        M = M @ Exp(delta)
        if np.linalg.norm(delta) < 1e-13:
            break
    return M
""",
        hint="the conventions admit nested lists",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "weighted_mean_from_chordal",
        "weighted_rotation_mean",
        "starts from the weighted chordal mean",
        """
def weighted_rotation_mean(Rs, weights):
    Rs = [np.asarray(R, dtype=float) for R in Rs]
    w = [float(x) for x in weights]
    U, _, Vt = np.linalg.svd(sum(wi * R for wi, R in zip(w, Rs)))
    M = U @ np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))]) @ Vt
    for _ in range(200):
        delta = sum(wi * Log(M.T @ R) for wi, R in zip(w, Rs)) / sum(w)
        M = M @ Exp(delta)
        if np.linalg.norm(delta) < 1e-14:
            break
    return M
""",
    ),
]

SAMPLE = {"chloe": ["weighted_mean_ignores_weights"]}
