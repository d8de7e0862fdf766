"""Mutants that are correct answers, each with why: listed once, by hand, by key.

``python -m autograder mutants`` prints the key of every survivor (the exercise
and a hash of the mutant's source), so an entry goes stale, and the tool says
so, when the reference answer changes. A mutant belongs here only when it is a
correct answer to its exercise: it returns what the docstring promises for
every input the docstring allows, to the tolerance that the exercise promises
(stated in each hidden test module's docstring). "The tests happen to miss it"
is a survivor, never an entry. ``tests/test_mutants.py`` grades a sample of
these entries and requires full marks and every public check passed.

Each reason is written once below and named by the entries it covers.
"""

INTEGERS = (
    "without dtype=float an integer input stays integer only until its first operation with a float "
    "(a trig function, a float constant, a division, a float matrix), which gives the same float values; "
    "no float is written into the integer array, and integer outputs hold the same real values"
)
LISTS = (
    "numpy converts a plain list where this code uses it (unpacking, np.linalg, ufuncs, @ with an array on "
    "either side, division by a numpy scalar), so lists give the same values as arrays"
)
VECTORS = (
    "both operands are 1-D: .T of a 1-D array is the array itself, and u @ a equals a @ u (the same sum, "
    "in the same order)"
)
FLOAT32_EXACT = (
    "zeros, ones and identities are exact in float32, and the first operation with a float64 array "
    "gives float64 again: the same values"
)
BOUNDARY = (
    "< for <= (or the reverse) differs only when the two sides are exactly equal, where both branches are "
    "right (both series and closed form are accurate at the threshold; at θ = π/2 both log branches hold; "
    "at u·a = 0, w = 0 or d = 0 both signs are valid). Not a tolerance argument: 'at most tol' is the "
    "docstrings' own reading, and the tests call exactly at tol (coursekit/checks/tolerance.py)"
)
EMPTY_MATRIX = (
    "a 0×0 matrix is of the docstring's shape (n, n) with n = 0, and the docstring gives it no verdict: the tests "
    "do not ask, so an answer may crash there or answer either way"
)
SQUARE = "the matrix is square by then (checked above, or by the docstring), so shape[0] == shape[1] == shape[-1]"
NAN_REJECTED = (
    "NaN and inf entries are rejected anyway: they make the orthogonality error NaN or inf, and NaN <= tol is False"
)
GRAM = (
    "MᵀM = I and MMᵀ = I hold together for a square M; for M = I + E both errors are E + Eᵀ + O(|E|²), so "
    "at tol = 1e-9 the verdicts can differ only for an error within 1e-18 of tol"
)
VIEW = (
    "returns a view of the transposed input instead of a copy; the docstring promises an array with the "
    "inverse's values, not a new one, and the input itself is not changed"
)
DET_OF_PRODUCT = "det(Vᵀ U) = det(Uᵀ V) = det(U Vᵀ) = det(U) det(V): the sign test sees the same number"
DIAGONAL_T = "the transpose of a diagonal matrix is the matrix itself"
DET_NEVER_ZERO = (
    "det(U Vᵀ) is ±1 for the orthogonal factors of an SVD, never 0, so np.sign of it is ±1 and the "
    "d == 0 guard never fires"
)
ALL_PAIRS = "closure checks op over all ordered pairs (a, b), so op(b, a) runs over the same set of products"
SYMMETRIC_EQUAL = "equal(x, y) compares max |x - y| with tol, which is symmetric in x and y"
POWERS_COMMUTE = "each term is a power of W, and Wᵏ W = W Wᵏ: the same sum (to the last bits of rounding)"
CLOSED_FORM_BELOW = (
    "a smaller small-angle threshold: the closed form is used down to it, and at these angles it "
    "stays within the exercise's promised tolerance (its cancellation is O(ε) in a coefficient "
    "multiplied by θ or θ², or the formula has none), measured at every decade"
)
SERIES_WITHIN_PROMISE = (
    "the series term changed or dropped (or a larger threshold for an already long series) is of "
    "order θ⁴ or smaller below the threshold and multiplies [w]× or [w]×²: the result moves by "
    "less than the exercise's promised tolerance at every angle (the every-decade check passes)"
)
SHIFT_ARGMIN = "subtracting the same constant from every |λ - 1| leaves argmin unchanged"
UNIT_ALREADY = (
    "the vector is a unit vector already (np.linalg.eig's eigenvectors, Shepperd's quaternion, slerp of "
    "unit quaternions, q ⊗ Exp_q(δ)), so the final normalisation changes it only by rounding, within "
    "the promised tolerance"
)
SCALAR_DISCARDED = (
    "the slip changes only the scalar part of the second product, which quat_rotate discards, and in "
    "the first product it multiplies the pure quaternion's zero scalar"
)
NLERP_BELOW_PRECISION = (
    "normalised linear interpolation is used only for Ω below 1e-4 (a degrees or sin-free test "
    "is the same below 6e-11): there it differs from slerp by O(Ω³) t(1 - t), below the "
    "promised 2e-15"
)
POSITIVE_SCALE = "the whole blend is scaled by a positive number (1/sin Ω, 1/Ω or none) and normalised afterwards"
LOCK_REBUILDS = (
    "a stricter gimbal-lock test (1e-15 for 1e-12): between them the general formulas still give angles "
    "that rebuild R within the promised 1e-11, which is all the docstring promises next to the lock"
)
WRAP_IN_RANGE = (
    "the wrap's fast path is skipped, and π - mod(π - a, 2π) returns every a in (-π, π] itself (to the "
    "last bit of rounding)"
)
STEP_AS_ACCURATE = (
    "another step size (or float32 storage of the steps and columns) that is still at least as "
    "accurate as the lecture's rule: the course accepts any such scheme "
    "(coursekit.diagnose.jacobian_error_allowed, 5e-6 (1 + |p|) on manifolds)"
)
REBOUND = "the name is rebound by the next assignment (R = R @ Exp(...)), so the caller's array is never written"
CONVERGED = (
    "the Karcher iteration converges to the same mean from any of the samples, well within its 100 "
    "steps, and a stop at |δ| < 1e-7 … 1e-15 (or none) moves the result by less than the promised "
    "tolerance"
)

SYMMETRIC_INPUT = "Sigma is a covariance, symmetric by the docstring, so Sigma.T is Sigma and the product is the same"
NEGATED_FACTOR = "J Σ Jᵀ does not change when J is negated ((-J) Σ (-J)ᵀ = J Σ Jᵀ), and [p]×ᵀ = -[p]× only negates J"
ANY_HALF_TURN_AXIS = (
    "for opposite vectors the answer is a half turn about any axis perpendicular to a: the "
    "docstring names no particular one, and b = -a (up to rounding) or a × helper with the "
    "factors swapped gives another perpendicular axis, [0, ±u] with w = 0"
)
IRLS_CONVERGED = (
    "the reweighted Gauss-Newton iteration has converged long before its 500 steps (to the last bits), "
    "so one step more or fewer, or a stop at |ξ| < 1e-15 (or none), returns the same pose"
)
PRECONDITIONER = (
    "H only sets the step: the iteration stops where the weighted gradient g (kept in float64) vanishes, "
    "so a float32 H or an unweighted JᵀJ changes the path, not the answer, and still converges well "
    "within the 500 steps (gradient below 1e-13 per point)"
)


EQUIVALENT = {
    # ALL_PAIRS
    "check_group_axioms.2a50ce1a": ALL_PAIRS,  # op(a, b) → op(b, a) (line 44)
    # BOUNDARY
    "align_svd.296c78e0": BOUNDARY,  # np.linalg.det(U @ Vt) >= 0 → np.linalg.det(U @ Vt) > 0 (line 28)
    "axis_angle.4c8ba8c4": BOUNDARY,  # u @ a < 0.0 → u @ a <= 0.0 (line 35)
    "axis_angle.4d710c3f": BOUNDARY,  # c > 0.0 → c >= 0.0 (line 28)
    "exp_se3.9bab5ebb": BOUNDARY,  # theta < 0.01 → theta <= 0.01 (line 26)
    "exp_so3.ab558f89": BOUNDARY,  # theta < 0.0001 → theta <= 0.0001 (line 22)
    "is_rotation_matrix.08620832": EMPTY_MATRIX,  # input test `M.shape[0] == 0` dropped (line 24)
    "is_rotation_matrix.86c7073c": BOUNDARY,  # np.linalg.det(M) > 0 → np.linalg.det(M) >= 0 (line 29)
    "log_se3.9a87a94f": BOUNDARY,  # theta < 0.01 → theta <= 0.01 (line 24)
    "log_so3.be2851f4": BOUNDARY,  # u @ a < 0.0 → u @ a <= 0.0 (line 37)
    "log_so3.9f7a82af": BOUNDARY,  # c > 0.0 → c >= 0.0 (line 30)
    "matrix_to_euler_zyx.5906010e": BOUNDARY,  # cos_pitch < 1e-12 → cos_pitch <= 1e-12 (line 30)
    "matrix_to_quat.5103fb4a": BOUNDARY,  # q[0] < 0 → q[0] <= 0 (line 40)
    "quat_boxplus.8f34173a": BOUNDARY,  # angle < 1e-08 → angle <= 1e-08 (line 23)
    "quat_slerp.ba12cfcc": BOUNDARY,  # np.sin(omega) < 1e-12 → np.sin(omega) <= 1e-12 (line 28)
    "quat_slerp.c8d82dc6": BOUNDARY,  # d < 0.0 → d <= 0.0 (line 25)
    "quat_to_euler_zyx.441d3c2f": BOUNDARY,  # b < 1e-12 → b <= 1e-12 (line 34)
    "quat_to_euler_zyx.4add451c": BOUNDARY,  # a < 1e-12 → a <= 1e-12 (line 36)
    "quat_to_euler_zyx.d203bdde": BOUNDARY,  # -np.pi < angle <= np.pi → -np.pi < angle < np.pi (line 27)
    "right_jacobian_inv_so3.8d562ff3": BOUNDARY,  # theta < 0.001 → theta <= 0.001 (line 25)
    "right_jacobian_so3.716b9216": BOUNDARY,  # theta < 0.001 → theta <= 0.001 (line 25)
    "rotation_mean.1d24b903": BOUNDARY,  # np.linalg.norm(delta) < 1e-12 → np.linalg.norm(delta) <= 1e-12 (line 25)
    # CLOSED_FORM_BELOW
    "exp_se3.5ea5d8ef": CLOSED_FORM_BELOW,  # 0.01 → 1e-05 (line 26)
    "exp_se3.918bd84b": CLOSED_FORM_BELOW,  # 0.01 → 0.001 (line 26)
    "exp_se3.03e8fb28": CLOSED_FORM_BELOW,  # 0.01 → 0.0001 (line 26)
    "exp_so3.2127285d": CLOSED_FORM_BELOW,  # 0.0001 → 1e-05 (line 22)
    "exp_so3.401ffa40": CLOSED_FORM_BELOW,  # 0.0001 → 1e-08 (line 22)
    "exp_so3.7685df50": CLOSED_FORM_BELOW,  # 0.0001 → 1e-06 (line 22)
    "exp_so3.c26b5719": CLOSED_FORM_BELOW,  # 0.0001 → 1e-07 (line 22)
    "exp_so3.d461dbae": CLOSED_FORM_BELOW,  # 0.0001 → 1e-15 (line 22)
    "log_se3.1f7ebf92": CLOSED_FORM_BELOW,  # 0.01 → 1e-08 (line 24)
    "log_se3.34406e5c": CLOSED_FORM_BELOW,  # 0.01 → 1e-15 (line 24)
    "log_se3.43d493c4": CLOSED_FORM_BELOW,  # 0.01 → 0.0001 (line 24)
    "log_se3.53c85662": CLOSED_FORM_BELOW,  # 0.01 → 0.001 (line 24)
    "log_se3.6340f92e": CLOSED_FORM_BELOW,  # 0.01 → 1e-06 (line 24)
    "log_se3.7de6ce1e": CLOSED_FORM_BELOW,  # 0.01 → 1e-05 (line 24)
    "log_se3.d6ba2aeb": CLOSED_FORM_BELOW,  # 0.01 → 1e-07 (line 24)
    "quat_boxplus.5d6a18c1": CLOSED_FORM_BELOW,  # 1e-08 → 1e-15 (line 23)
    "quat_slerp.1a27afae": CLOSED_FORM_BELOW,  # 1e-12 → 1e-15 (line 28)
    "right_jacobian_inv_so3.4bc92873": CLOSED_FORM_BELOW,  # 0.001 → 1e-05 (line 25)
    "right_jacobian_inv_so3.8817019e": CLOSED_FORM_BELOW,  # 0.001 → 1e-15 (line 25)
    "right_jacobian_inv_so3.b1ed1c39": CLOSED_FORM_BELOW,  # 0.001 → 1e-06 (line 25)
    "right_jacobian_inv_so3.b79b426e": CLOSED_FORM_BELOW,  # 0.001 → 0.0001 (line 25)
    "right_jacobian_inv_so3.ccec1b64": CLOSED_FORM_BELOW,  # 0.001 → 1e-08 (line 25)
    "right_jacobian_inv_so3.d4508078": CLOSED_FORM_BELOW,  # 0.001 → 1e-07 (line 25)
    "right_jacobian_so3.65a50ef7": CLOSED_FORM_BELOW,  # 0.001 → 1e-07 (line 25)
    "right_jacobian_so3.88533905": CLOSED_FORM_BELOW,  # 0.001 → 0.0001 (line 25)
    "right_jacobian_so3.f3c523d2": CLOSED_FORM_BELOW,  # 0.001 → 1e-15 (line 25)
    "right_jacobian_so3.2f78299d": CLOSED_FORM_BELOW,  # 0.001 → 1e-05 (line 25)
    "right_jacobian_so3.8852dfdb": CLOSED_FORM_BELOW,  # 0.001 → 1e-08 (line 25)
    "right_jacobian_so3.e84a7005": CLOSED_FORM_BELOW,  # 0.001 → 1e-06 (line 25)
    # CONVERGED
    "rotation_mean.17da64e0": CONVERGED,  # 1e-12 → 1e-15 (line 25)
    "rotation_mean.29b47a30": CONVERGED,  # range(100) → range(100 + 1) (line 22)
    "rotation_mean.5e6064b2": CONVERGED,  # range(100) → range(1, 100) (line 22)
    "rotation_mean.82949c63": CONVERGED,  # Rs[0] → Rs[1] (line 21)
    "rotation_mean.a90a623d": CONVERGED,  # Rs[0] → Rs[-1] (line 21)
    "rotation_mean.aabaf180": CONVERGED,  # 1e-12 → 1e-07 (line 25)
    "rotation_mean.df028641": CONVERGED,  # 1e-12 → 1e-08 (line 25)
    "rotation_mean.ea6f18b4": CONVERGED,  # `np.linalg.norm(delta) < 1e-12` always False (line 25)
    "rotation_mean.ec0c81a9": CONVERGED,  # range(100) → range(100 - 1) (line 22)
    "rotation_mean.fe3b4591": CONVERGED,  # np.linalg.norm(delta) < 1e-12 loosened ×1000 (1e-09; line 25)
    # DET_NEVER_ZERO
    "align_svd.6e4671df": DET_NEVER_ZERO,  # 1.0 if np.linalg.det(U @ Vt) >= 0 else -1.0 → np.sign(np.linalg.det(U @ Vt))
    "nearest_rotation.7dcd517a": DET_NEVER_ZERO,  # `d == 0` always False (line 23)
    "nearest_rotation.92af0d0f": DET_NEVER_ZERO,  # return before `if d == 0:` (line 23)
    # DET_OF_PRODUCT
    "align_svd.8802b779": DET_OF_PRODUCT,  # U @ Vt → U.T @ Vt (line 28)
    "align_svd.d21ecd92": DET_OF_PRODUCT,  # U @ Vt → U @ Vt.T (line 28)
    "align_svd.f1ded8c3": DET_OF_PRODUCT,  # U @ Vt → Vt @ U (line 28)
    "nearest_rotation.00361f62": DET_OF_PRODUCT,  # U @ Vt → U @ Vt.T (line 22)
    "nearest_rotation.67bc6387": DET_OF_PRODUCT,  # U @ Vt → U.T @ Vt (line 22)
    "nearest_rotation.abd3483b": DET_OF_PRODUCT,  # U @ Vt → Vt @ U (line 22)
    # DIAGONAL_T
    "align_svd.1d881e58": DIAGONAL_T,  # U @ np.diag([1.0, 1.0, d]) → U @ np.diag([1.0, 1.0, d]).T (line 29)
    "nearest_rotation.80241582": DIAGONAL_T,  # U @ np.diag([1.0, 1.0, d]) → U @ np.diag([1.0, 1.0, d]).T (line 25)
    # FLOAT32_EXACT
    "axis_angle.7bd1179e": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 32)
    "exp_se3.4c596540": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 32)
    "exp_series.48e2f0d7": FLOAT32_EXACT,  # np.zeros_like(term) → np.zeros_like(term, dtype=np.float32) (line 23)
    "exp_series.509ca343": FLOAT32_EXACT,  # np.eye(W.shape[0]) → np.eye(W.shape[0], dtype=np.float32) (line 22)
    "exp_so3.57477daf": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 29)
    "is_rotation_matrix.11bbee82": FLOAT32_EXACT,  # np.eye(M.shape[0]) → np.eye(M.shape[0], dtype=np.float32) (line 28)
    "log_se3.f00bd202": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 28)
    "log_so3.ab3b9fbd": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 34)
    "right_jacobian_inv_so3.360217dd": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 30)
    "right_jacobian_so3.5211015c": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 32)
    "to_homogeneous.ee82d81c": FLOAT32_EXACT,  # np.ones(P.shape[:-1] + (1,)) → np.ones(P.shape[:-1] + (1,), dtype=np.float32
    # GRAM
    "is_rotation_matrix.229ccbcc": GRAM,  # M.T @ M → M @ M.T (line 28)
    # INTEGERS
    "align_gauss_newton.001aff6b": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 29)
    "align_gauss_newton.8ea7efb2": INTEGERS,  # np.asarray(Q, dtype=float) → np.asarray(Q) (line 30)
    "align_gauss_newton.bfd60e09": INTEGERS,  # np.array(R0, dtype=float) → np.array(R0) (line 31)
    "align_svd.d2107646": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 25)
    "align_svd.e4db84d5": INTEGERS,  # np.asarray(Q, dtype=float) → np.asarray(Q) (line 26)
    "axis_angle.22bcc58b": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 23)
    "axis_from_eigen.45dcb39f": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 20)
    "boxminus.95794844": INTEGERS,  # np.asarray(R_b, dtype=float) → np.asarray(R_b) (line 20)
    "boxminus.e5836156": INTEGERS,  # np.asarray(R_a, dtype=float) → np.asarray(R_a) (line 20)
    "boxplus_left.3f43975a": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 20)
    "boxplus_right.de49eb14": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 21)
    "bracket.8b82ffc5": INTEGERS,  # np.asarray(A, dtype=float) → np.asarray(A) (line 18)
    "bracket.8ca1ff5e": INTEGERS,  # np.asarray(B, dtype=float) → np.asarray(B) (line 19)
    "check_group_axioms.0ddb3573": INTEGERS,  # np.asarray(y, dtype=float) → np.asarray(y) (line 41)
    "check_group_axioms.d21c8b6b": INTEGERS,  # np.asarray(x, dtype=float) → np.asarray(x) (line 41)
    "commutes.3b825d29": INTEGERS,  # np.asarray(op(b, a), dtype=float) → np.asarray(op(b, a)) (line 25)
    "commutes.d20bfde2": INTEGERS,  # np.asarray(op(a, b), dtype=float) → np.asarray(op(a, b)) (line 24)
    "compose.2052a92a": INTEGERS,  # np.asarray(R_bc, dtype=float) → np.asarray(R_bc) (line 21)
    "compose.5a9999ce": INTEGERS,  # np.asarray(R_ab, dtype=float) → np.asarray(R_ab) (line 21)
    "exp_se3.20e59b56": INTEGERS,  # np.asarray(xi, dtype=float) → np.asarray(xi) (line 22)
    "exp_series.de88fb18": INTEGERS,  # np.asarray(W, dtype=float) → np.asarray(W) (line 21)
    "exp_so3.0b9d24e4": INTEGERS,  # np.asarray(w, dtype=float) → np.asarray(w) (line 19)
    "from_homogeneous.40fdcd56": INTEGERS,  # np.asarray(P_h, dtype=float) → np.asarray(P_h) (line 19)
    "hat.a27cc2d8": INTEGERS,  # np.asarray(w, dtype=float) → np.asarray(w) (line 20)
    "is_rotation_matrix.d9253760": INTEGERS,  # np.asarray(M, dtype=float) → np.asarray(M) (line 21)
    "jacobian_rotate_point.366a3f48": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 23)
    "log_se3.0893951f": INTEGERS,  # np.asarray(T, dtype=float) → np.asarray(T) (line 20)
    "log_so3.4a01c2e3": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 25)
    "make_pose.04436a74": INTEGERS,  # np.asarray(t, dtype=float) → np.asarray(t) (line 26)
    "make_pose.4802188b": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 25)
    "matrix_to_euler_zyx.e3debac7": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 21)
    "matrix_to_quat.d5c414a6": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 21)
    "nearest_rotation.8705a615": INTEGERS,  # np.asarray(M, dtype=float) → np.asarray(M) (line 21)
    "numerical_jacobian.955a5af4": INTEGERS,  # np.asarray(f(x), dtype=float) → np.asarray(f(x)) (line 30)
    "numerical_jacobian.b6eb4046": INTEGERS,  # np.asarray(f(moved), dtype=float) → np.asarray(f(moved)) (line 38)
    "numerical_jacobian.df98948e": INTEGERS,  # np.asarray(f(boxplus(x, d)), dtype=float) → np.asarray(f(boxplus(x, d))) (li
    "pose_compose.45ca0029": INTEGERS,  # np.asarray(T_bc, dtype=float) → np.asarray(T_bc) (line 20)
    "pose_compose.dacc8f36": INTEGERS,  # np.asarray(T_ab, dtype=float) → np.asarray(T_ab) (line 20)
    "pose_inverse.283a316e": INTEGERS,  # np.asarray(T, dtype=float) → np.asarray(T) (line 22)
    "quat_boxplus.9dcafcbb": INTEGERS,  # np.asarray(d, dtype=float) → np.asarray(d) (line 21)
    "quat_from_axis_angle.4b1b191f": INTEGERS,  # np.asarray(u, dtype=float) → np.asarray(u) (line 21)
    "quat_inverse.c3566a5c": INTEGERS,  # np.asarray(q, dtype=float) → np.asarray(q) (line 19)
    "quat_multiply.692e808d": INTEGERS,  # np.asarray(p, dtype=float) → np.asarray(p) (line 19)
    "quat_multiply.6c4bd4f4": INTEGERS,  # np.asarray(q, dtype=float) → np.asarray(q) (line 20)
    "quat_rotate.26f54d9a": INTEGERS,  # np.asarray(v, dtype=float) → np.asarray(v) (line 27)
    "quat_rotate.b4c2772e": INTEGERS,  # np.asarray(q, dtype=float) → np.asarray(q) (line 26)
    "quat_slerp.2174a0f1": INTEGERS,  # np.asarray(q0, dtype=float) → np.asarray(q0) (line 22)
    "quat_slerp.c5e9d896": INTEGERS,  # np.asarray(q1, dtype=float) → np.asarray(q1) (line 23)
    "quat_to_euler_zyx.3bf19d28": INTEGERS,  # np.asarray(q, dtype=float) → np.asarray(q) (line 22)
    "right_jacobian_inv_so3.f3fb3da8": INTEGERS,  # np.asarray(w, dtype=float) → np.asarray(w) (line 22)
    "right_jacobian_so3.a8721d38": INTEGERS,  # np.asarray(w, dtype=float) → np.asarray(w) (line 22)
    "rotate_point.2da6376e": INTEGERS,  # np.asarray(p_b, dtype=float) → np.asarray(p_b) (line 23)
    "rotate_point.f00eb355": INTEGERS,  # np.asarray(R_wb, dtype=float) → np.asarray(R_wb) (line 22)
    "rotation_mean.30dae44a": INTEGERS,  # np.asarray(Rs, dtype=float) → np.asarray(Rs) (line 20)
    "to_homogeneous.a69dd1f2": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 21)
    "transform_points.1993187a": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 24)
    "transform_points.d1f11995": INTEGERS,  # np.asarray(T, dtype=float) → np.asarray(T) (line 23)
    "vee.13b21f34": INTEGERS,  # np.asarray(W, dtype=float) → np.asarray(W) (line 19)
    # LISTS
    "align_gauss_newton.670ec93c": LISTS,  # np.asarray(Q, dtype=float) → Q (line 30)
    "align_gauss_newton.8484f4fa": LISTS,  # np.asarray(P, dtype=float) → P (line 29)
    "align_svd.84a09fa2": LISTS,  # np.asarray(P, dtype=float) → P (line 25)
    "axis_from_eigen.db4a7904": LISTS,  # np.asarray(R, dtype=float) → R (line 20)
    "boxminus.fe7bec30": LISTS,  # np.asarray(R_a, dtype=float) → R_a (line 20)
    "boxplus_left.f8fcbd65": LISTS,  # np.asarray(R, dtype=float) → R (line 20)
    "boxplus_right.6916718e": LISTS,  # np.asarray(R, dtype=float) → R (line 21)
    "bracket.9a06dab0": LISTS,  # np.asarray(A, dtype=float) → A (line 18)
    "bracket.b9a3680c": LISTS,  # np.asarray(B, dtype=float) → B (line 19)
    "compose.cba79442": LISTS,  # np.asarray(R_ab, dtype=float) → R_ab (line 21)
    "compose.f6c4302d": LISTS,  # np.asarray(R_bc, dtype=float) → R_bc (line 21)
    "hat.f3b66d6f": LISTS,  # np.asarray(w, dtype=float) → w (line 20)
    "make_pose.5457e60b": LISTS,  # np.asarray(R, dtype=float) → R (line 25)
    "nearest_rotation.dd74e670": LISTS,  # np.asarray(M, dtype=float) → M (line 21)
    "pose_compose.65eb86d9": LISTS,  # np.asarray(T_bc, dtype=float) → T_bc (line 20)
    "pose_compose.813d844b": LISTS,  # np.asarray(T_ab, dtype=float) → T_ab (line 20)
    "quat_from_axis_angle.f45473ee": LISTS,  # np.asarray(u, dtype=float) → u (line 21)
    "quat_rotate.dabaef96": LISTS,  # np.asarray(v, dtype=float) → v (line 27)
    "quat_to_euler_zyx.6786b20a": LISTS,  # np.asarray(q, dtype=float) → q (line 22)
    "right_jacobian_inv_so3.f3c64936": LISTS,  # np.asarray(w, dtype=float) → w (line 22)
    "right_jacobian_so3.db355d9c": LISTS,  # np.asarray(w, dtype=float) → w (line 22)
    "rotate_point.a0cdf681": LISTS,  # np.asarray(p_b, dtype=float) → p_b (line 23)
    "transform_points.662ddf71": LISTS,  # np.asarray(P, dtype=float) → P (line 24)
    # LOCK_REBUILDS
    "matrix_to_euler_zyx.2bc84f64": LOCK_REBUILDS,  # 1e-12 → 1e-15 (line 30)
    "quat_to_euler_zyx.b1fa2600": LOCK_REBUILDS,  # 1e-12 → 1e-15 (line 34)
    "quat_to_euler_zyx.fac464c0": LOCK_REBUILDS,  # 1e-12 → 1e-15 (line 36)
    # NAN_REJECTED
    "is_rotation_matrix.89f19478": NAN_REJECTED,  # `not np.all(np.isfinite(M))` always False (line 26)
    "is_rotation_matrix.a04820bf": NAN_REJECTED,  # orthogonality_error <= tol → not orthogonality_error > tol (line 29)
    "is_rotation_matrix.b19cf0d0": NAN_REJECTED,  # M → tol (line 26)
    # NLERP_BELOW_PRECISION
    "quat_slerp.9b22d904": NLERP_BELOW_PRECISION,  # 1e-12 → 1e-08 (line 28)
    "quat_slerp.a0e683b8": NLERP_BELOW_PRECISION,  # 1e-12 → 1e-05 (line 28)
    "quat_slerp.db37cd8f": NLERP_BELOW_PRECISION,  # 1e-12 → 1e-06 (line 28)
    "quat_slerp.dd80196f": NLERP_BELOW_PRECISION,  # np.sin(omega) → omega (line 28)
    "quat_slerp.e0f71f64": NLERP_BELOW_PRECISION,  # 1e-12 → 0.0001 (line 28)
    "quat_slerp.f4290637": NLERP_BELOW_PRECISION,  # 1e-12 → 1e-07 (line 28)
    "quat_slerp.fca15ec1": NLERP_BELOW_PRECISION,  # np.sin(omega) → np.sin(np.deg2rad(omega)) (line 28)
    # POSITIVE_SCALE
    "quat_slerp.5ac45412": POSITIVE_SCALE,  # (np.sin((1.0 - t) * omega) * q0 + np.sin(t * omega) * q1) / np.sin(omega) →
    "quat_slerp.e20b188c": POSITIVE_SCALE,  # np.sin(omega) → omega (line 31)
    "quat_slerp.e5470d82": POSITIVE_SCALE,  # np.sin(omega) → np.sin(np.deg2rad(omega)) (line 31)
    # POWERS_COMMUTE
    "exp_series.8df0e89a": POWERS_COMMUTE,  # term @ W → W @ term (line 26)
    "right_jacobian_se3.3accef9e": POWERS_COMMUTE,  # A @ S → S @ A (line 30); S is a polynomial in A
    # REBOUND
    "align_gauss_newton.9ff006cd": REBOUND,  # np.array(R0, dtype=float) → np.asarray(R0, dtype=float) (line 31)
    "rotation_mean.cb6be289": REBOUND,  # Rs[0].copy() → Rs[0] (line 21)
    # SCALAR_DISCARDED
    "quat_rotate.7835eff4": SCALAR_DISCARDED,  # a[0] → a[-1] (line 23)
    "quat_rotate.85174c49": SCALAR_DISCARDED,  # a[0] → a[1] (line 23)
    "quat_rotate.859ee7f7": SCALAR_DISCARDED,  # a[0] * b[0] → b[0] (line 23)
    # SERIES_WITHIN_PROMISE
    "exp_se3.4634a8c9": SERIES_WITHIN_PROMISE,  # 1.0 / 6.0 - theta ** 2 / 120.0 + theta ** 4 / 5040.0 → 1.0 / 6.0 - theta **
    "exp_se3.f48fbf15": SERIES_WITHIN_PROMISE,  # 0.5 - theta ** 2 / 24.0 + theta ** 4 / 720.0 → 0.5 - theta ** 2 / 24.0 - the
    "exp_se3.221a14b4": SERIES_WITHIN_PROMISE,  # 0.5 - theta ** 2 / 24.0 + theta ** 4 / 720.0 → 0.5 - theta ** 2 / 24.0 (line
    "exp_se3.129b081d": SERIES_WITHIN_PROMISE,  # 1.0 / 6.0 - theta ** 2 / 120.0 + theta ** 4 / 5040.0 → 1.0 / 6.0 - theta **
    "exp_so3.38908c64": SERIES_WITHIN_PROMISE,  # 0.5 - t2 / 24.0 → 0.5 + t2 / 24.0 (line 25)
    "exp_so3.4d791364": SERIES_WITHIN_PROMISE,  # 0.0001 → 0.001 (line 22)
    "exp_so3.4fa920ef": SERIES_WITHIN_PROMISE,  # t2 / 24.0 → t2 (line 25)
    "exp_so3.a0445829": SERIES_WITHIN_PROMISE,  # 0.5 - t2 / 24.0 → 0.5 (line 25)
    "log_se3.56ab413f": SERIES_WITHIN_PROMISE,  # 1.0 / 12.0 + theta ** 2 / 720.0 + theta ** 4 / 30240.0 → 1.0 / 12.0 + theta
    "log_se3.5f9cac8f": SERIES_WITHIN_PROMISE,  # 0.01 → 0.1 (line 24)
    "log_se3.d56d9145": SERIES_WITHIN_PROMISE,  # 1.0 / 12.0 + theta ** 2 / 720.0 + theta ** 4 / 30240.0 → 1.0 / 12.0 + theta
    "quat_boxplus.4bb17ac4": SERIES_WITHIN_PROMISE,  # 1e-08 → 1e-05 (line 23)
    "quat_boxplus.9a2097e9": SERIES_WITHIN_PROMISE,  # np.concatenate([[1.0], 0.5 * d]) → np.concatenate([[1.0], 0.5 * d], dtype=np
    "quat_boxplus.a78d16f5": SERIES_WITHIN_PROMISE,  # 1e-08 → 1e-06 (line 23)
    "quat_boxplus.c9b94b0e": SERIES_WITHIN_PROMISE,  # 1e-08 → 1e-07 (line 23)
    "right_jacobian_inv_so3.19744e68": SERIES_WITHIN_PROMISE,  # 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0 → 1.0 / 12.0 + t2 / 720.0 (line
    "right_jacobian_inv_so3.2fa475c5": SERIES_WITHIN_PROMISE,  # 0.001 → 0.01 (line 25)
    "right_jacobian_inv_so3.607a6f4f": SERIES_WITHIN_PROMISE,  # 1.0 / 12.0 + t2 / 720.0 → 1.0 / 12.0 - t2 / 720.0 (line 27)
    "right_jacobian_inv_so3.72cc74b8": SERIES_WITHIN_PROMISE,  # 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0 → 1.0 / 12.0 + t2 / 720.0 - t2 *
    "right_jacobian_inv_so3.79ae6767": SERIES_WITHIN_PROMISE,  # 1.0 / 12.0 + t2 / 720.0 → 1.0 / 12.0 (line 27)
    "right_jacobian_inv_so3.95a08731": SERIES_WITHIN_PROMISE,  # t2 * t2 / 30240.0 → t2 * t2 (line 27)
    "right_jacobian_inv_so3.a88587a3": SERIES_WITHIN_PROMISE,  # 0.001 → 0.1 (line 25)
    "right_jacobian_inv_so3.d9b43f5e": SERIES_WITHIN_PROMISE,  # t2 * t2 → t2 (line 27)
    "right_jacobian_so3.94eaccee": SERIES_WITHIN_PROMISE,  # t2 * t2 / 720.0 → t2 * t2 (line 27)
    "right_jacobian_so3.b392695e": SERIES_WITHIN_PROMISE,
    "right_jacobian_so3.ab065ef4": SERIES_WITHIN_PROMISE,  # 1.0 / 6.0 - t2 / 120.0 → 1.0 / 6.0 + t2 / 120.0 (line 28)  # t2 * t2 → t2 (line 28)
    "right_jacobian_so3.ba874863": SERIES_WITHIN_PROMISE,  # 0.5 - t2 / 24.0 + t2 * t2 / 720.0 → 0.5 - t2 / 24.0 - t2 * t2 / 720.0 (line
    "right_jacobian_so3.32b074e9": SERIES_WITHIN_PROMISE,  # 1.0 / 6.0 - t2 / 120.0 → 1.0 / 6.0 (line 28)
    "right_jacobian_so3.993523ee": SERIES_WITHIN_PROMISE,  # t2 * t2 / 5040.0 → t2 * t2 (line 28)
    "right_jacobian_so3.3cc788d2": SERIES_WITHIN_PROMISE,  # 0.001 → 0.01 (line 25)
    "right_jacobian_so3.9757a423": SERIES_WITHIN_PROMISE,  # 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 → 1.0 / 6.0 - t2 / 120.0 - t2 * t2
    "right_jacobian_so3.7b2b1f28": SERIES_WITHIN_PROMISE,  # 0.5 - t2 / 24.0 + t2 * t2 / 720.0 → 0.5 - t2 / 24.0 (line 27)
    "right_jacobian_so3.8d88b9a5": SERIES_WITHIN_PROMISE,  # 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 → 1.0 / 6.0 - t2 / 120.0 (line 28)
    # SHIFT_ARGMIN
    "axis_from_eigen.c1c82352": SHIFT_ARGMIN,  # np.abs(values - 1.0) → np.abs(values - 1.0) - 1e-05 * np.abs(1.0) (line 21)
    # SQUARE
    "exp_series.852b996b": SQUARE,  # W.shape[0] → W.shape[-1] (line 22)
    "exp_series.f260de5d": SQUARE,  # W.shape[0] → W.shape[1] (line 22)
    "is_rotation_matrix.51f0d0a7": SQUARE,  # M.shape[0] → M.shape[-1] (line 28)
    "is_rotation_matrix.5d1b1e8c": SQUARE,  # M.shape[0] → M.shape[-1] (line 24)
    "is_rotation_matrix.79ffe058": SQUARE,  # M.shape[0] → M.shape[1] (line 24)
    "is_rotation_matrix.ae6acece": SQUARE,  # M.shape[0] → M.shape[1] (line 28)
    # STEP_AS_ACCURATE
    "numerical_jacobian.0570c71c": STEP_AS_ACCURATE,  # 0.0001 → 1e-08 (line 35)
    "numerical_jacobian.08126359": STEP_AS_ACCURATE,  # np.zeros(3) → np.zeros(3, dtype=np.float32) (line 43)
    "numerical_jacobian.2244e61f": STEP_AS_ACCURATE,  # 1e-06 → 1e-07 (line 40)
    "numerical_jacobian.440afcb9": STEP_AS_ACCURATE,  # 1e-06 → 1e-08 (line 40)
    "numerical_jacobian.4e2a9efb": STEP_AS_ACCURATE,  # 0.0001 → 1e-06 (line 35)
    "numerical_jacobian.5c0ad2cf": STEP_AS_ACCURATE,  # 1e-06 → 1e-08 (line 35)
    "numerical_jacobian.71863487": STEP_AS_ACCURATE,  # 1e-06 → 1e-07 (line 35)
    "numerical_jacobian.881cf898": STEP_AS_ACCURATE,  # 0.0001 → 1e-07 (line 35)
    "numerical_jacobian.9cc67d6d": STEP_AS_ACCURATE,  # 0.0001 → 1e-05 (line 35)
    "numerical_jacobian.c8b52cf4": STEP_AS_ACCURATE,  # 1e-06 → 1e-05 (line 40)
    "numerical_jacobian.dc7ce6b5": STEP_AS_ACCURATE,  # 0.0001 → 1e-15 (line 35)
    # SYMMETRIC_EQUAL
    "check_group_axioms.54749e23": SYMMETRIC_EQUAL,  # equal(op(inverse(a), a), identity) → equal(identity, op(inverse(a), a)) (lin
    "check_group_axioms.8801d642": SYMMETRIC_EQUAL,  # equal(op(a, inverse(a)), identity) → equal(identity, op(a, inverse(a))) (lin
    "check_group_axioms.9ad0234b": SYMMETRIC_EQUAL,  # equal(op(a, identity), a) → equal(a, op(a, identity)) (line 46)
    "check_group_axioms.be2c5908": SYMMETRIC_EQUAL,  # equal(op(identity, a), a) → equal(a, op(identity, a)) (line 46)
    "check_group_axioms.c6140999": SYMMETRIC_EQUAL,  # equal(op(op(a, b), c), op(a, op(b, c))) → equal(op(a, op(b, c)), op(op(a, b)
    # UNIT_ALREADY
    "axis_from_eigen.e10edcdf": UNIT_ALREADY,  # u / np.linalg.norm(u) → u (line 23)
    "matrix_to_quat.ef257f23": UNIT_ALREADY,  # q / np.linalg.norm(q) → q (line 42)
    "quat_boxplus.58c23b88": UNIT_ALREADY,  # result / np.linalg.norm(result) → result (line 28)
    "quat_slerp.d8b85e52": UNIT_ALREADY,  # q / np.linalg.norm(q) → q (line 32)
    # VECTORS
    "align_gauss_newton.4941cdfc": VECTORS,  # J.T @ r → J.T @ r.T (line 39)
    "align_gauss_newton.ae1aa468": VECTORS,  # R @ p → R @ p.T (line 36)
    "axis_angle.6c6acd94": VECTORS,  # u @ a → a @ u (line 35)
    "axis_angle.7538588a": VECTORS,  # a @ a → a @ a.T (line 25)
    "axis_angle.a2c23c9b": VECTORS,  # B[:, j] @ B[:, j] → B[:, j].T @ B[:, j] (line 34)
    "axis_angle.b5a565de": VECTORS,  # a @ a → a.T @ a (line 25)
    "axis_angle.c5987bb5": VECTORS,  # u @ a → u @ a.T (line 35)
    "axis_angle.e94266ee": VECTORS,  # u @ a → u.T @ a (line 35)
    "axis_angle.fb7588d7": VECTORS,  # B[:, j] @ B[:, j] → B[:, j] @ B[:, j].T (line 34)
    "exp_se3.b5078607": VECTORS,  # V @ rho → V @ rho.T (line 35)
    "exp_so3.26f4397e": VECTORS,  # w @ w → w.T @ w (line 20)
    "exp_so3.347f0de6": VECTORS,  # w @ w → w @ w.T (line 20)
    "log_se3.f988bdee": VECTORS,  # V_inv @ T[:3, 3] → V_inv @ T[:3, 3].T (line 29)
    "log_so3.99c8a6fb": VECTORS,  # B[:, j] @ B[:, j] → B[:, j] @ B[:, j].T (line 36)
    "log_so3.d557db9a": VECTORS,  # B[:, j] @ B[:, j] → B[:, j].T @ B[:, j] (line 36)
    "log_so3.e7633a3b": VECTORS,  # u @ a → u.T @ a (line 37)
    "log_so3.2fc0a7c6": VECTORS,  # a @ a → a @ a.T (line 27)
    "log_so3.cb0fdd3c": VECTORS,  # u @ a → u @ a.T (line 37)
    "log_so3.c44f6cd3": VECTORS,  # a @ a → a.T @ a (line 27)
    "log_so3.d16ab424": VECTORS,  # u @ a → a @ u (line 37)
    "pose_inverse.b5f1a548": VECTORS,  # -R.T @ t → -R.T @ t.T (line 26)
    "quat_inverse.0f4f184e": VECTORS,  # q @ q → q @ q.T (line 20)
    "quat_inverse.dc9b654f": VECTORS,  # q @ q → q.T @ q (line 20)
    "quat_multiply.21ed2a39": VECTORS,  # pv @ qv → pv @ qv.T (line 23)
    "quat_multiply.5c2dfbb2": VECTORS,  # pv @ qv → pv.T @ qv (line 23)
    "quat_multiply.bcae80ed": VECTORS,  # pv @ qv → qv @ pv (line 23)
    "quat_rotate.6d1457af": VECTORS,  # a[1:] @ b[1:] → a[1:] @ b[1:].T (line 23)
    "quat_rotate.97add061": VECTORS,  # a[1:] @ b[1:] → a[1:].T @ b[1:] (line 23)
    "quat_rotate.b530edf5": VECTORS,  # a[1:] @ b[1:] → b[1:] @ a[1:] (line 23)
    "quat_slerp.86baa2c6": VECTORS,  # q0 @ q1 → q0 @ q1.T (line 24)
    "quat_slerp.e33af681": VECTORS,  # q0 @ q1 → q1 @ q0 (line 24)
    "quat_slerp.f709aa49": VECTORS,  # q0 @ q1 → q0.T @ q1 (line 24)
    # VIEW
    "invert_rotation.ff07dd9f": VIEW,  # np.asarray(R_ab, dtype=float).T.copy() → np.asarray(R_ab, dtype=float).T (li
    # WRAP_IN_RANGE
    "quat_to_euler_zyx.50df4cd8": WRAP_IN_RANGE,  # -np.pi → np.pi (line 27)
    "quat_to_euler_zyx.7582657e": WRAP_IN_RANGE,  # `-np.pi < angle <= np.pi` always False (line 27)
    # the exercises of lesson 09 and the thinking exercises (first listed 2026-11-25)
    "quat_from_two_vectors.43fe6d35": ANY_HALF_TURN_AXIS,  # a → b (line 39)
    "quat_from_two_vectors.37798de3": ANY_HALF_TURN_AXIS,  # np.cross(a, helper) → np.cross(helper, a) (line 39)
    "quat_from_two_vectors.a142088a": ANY_HALF_TURN_AXIS,  # a → b (line 38)
    "align_pose_robust.a9ee2bcc": BOUNDARY,  # size <= k → size < k (line 34)
    "quat_from_two_vectors.4a1cf116": BOUNDARY,  # a @ b > 0.0 → a @ b >= 0.0 (line 36)
    "weighted_rotation_mean.3e834c2b": CONVERGED,  # range(100) → range(100 - 1) (line 26)
    "weighted_rotation_mean.876e9577": CONVERGED,  # 1e-13 → 1e-08 (line 29)
    "weighted_rotation_mean.74f35747": CONVERGED,  # np.linalg.norm(delta) < 1e-13 loosened ×1000 (1e-10; line 29)
    "weighted_rotation_mean.a9ca7d6a": CONVERGED,  # range(100) → range(100 + 1) (line 26)
    "weighted_rotation_mean.b4c3eb22": CONVERGED,  # 1e-13 → 1e-15 (line 29)
    "weighted_rotation_mean.bbaae590": CONVERGED,  # np.linalg.norm(delta) < 1e-13 → np.linalg.norm(delta) <= 1e-13 (line 29)
    "weighted_rotation_mean.db62aab1": CONVERGED,  # `np.linalg.norm(delta) < 1e-13` always False (line 29)
    "weighted_rotation_mean.ff77c17e": CONVERGED,  # range(100) → range(1, 100) (line 26)
    "quat_from_two_vectors.1dda287b": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 38)
    "quat_power.67b3faca": FLOAT32_EXACT,  # np.array([1.0, 0.0, 0.0]) → np.array([1.0, 0.0, 0.0], dtype=np.float32) (line 28)
    "right_jacobian_se3.05b48a5a": FLOAT32_EXACT,  # np.eye(6) → np.eye(6, dtype=np.float32) (line 28)
    "right_jacobian_se3.01bfbcfb": FLOAT32_EXACT,  # np.eye(6) → np.eye(6, dtype=np.float32) (line 30)
    "adjoint_se3.2ad162ed": INTEGERS,  # np.asarray(T, dtype=float) → np.asarray(T) (line 19)
    "align_pose_gauss_newton.5b330214": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 25)
    "align_pose_gauss_newton.60b2758e": INTEGERS,  # np.asarray(Q, dtype=float) → np.asarray(Q) (line 26)
    "align_pose_gauss_newton.ba3b4708": INTEGERS,  # np.array(T0, dtype=float) → np.array(T0) (line 27)
    "align_pose_robust.2349dd3d": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 24)
    "align_pose_robust.68e7a416": INTEGERS,  # np.array(T0, dtype=float) → np.array(T0) (line 26)
    "align_pose_robust.f7f72e9a": INTEGERS,  # np.asarray(Q, dtype=float) → np.asarray(Q) (line 25)
    "body_angular_velocity.61749678": INTEGERS,  # np.asarray(R_dot, dtype=float) → np.asarray(R_dot) (line 22)
    "body_angular_velocity.e71c9d33": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 21)
    "covariance_left_to_right.b2cffc00": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 24)
    "covariance_left_to_right.d1f312c6": INTEGERS,  # np.asarray(Sigma_left, dtype=float) → np.asarray(Sigma_left) (line 25)
    "integrate_gyro.c5df4719": INTEGERS,  # np.array(R0, dtype=float) → np.array(R0) (line 24)
    "pose_graph_edge.fb107bdc": INTEGERS,  # np.asarray(T, dtype=float) → np.asarray(T) (line 29)
    "integrate_gyro.eb1a3c22": INTEGERS,  # np.asarray(omegas_b, dtype=float) → np.asarray(omegas_b) (line 25)
    "jacobian_point_to_body.08be5bef": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 21)
    "jacobian_point_to_body.ac6d7ecf": INTEGERS,  # np.asarray(p_w, dtype=float) → np.asarray(p_w) (line 22)
    "jacobian_transform_point.44174c15": INTEGERS,  # np.asarray(T, dtype=float) → np.asarray(T) (line 21)
    "quat_from_two_vectors.1e392d14": INTEGERS,  # np.asarray(b, dtype=float) → np.asarray(b) (line 29)
    "quat_from_two_vectors.7a177d9a": INTEGERS,  # np.asarray(a, dtype=float) → np.asarray(a) (line 28)
    "quat_power.cd322c53": INTEGERS,  # np.asarray(q, dtype=float) → np.asarray(q) (line 24)
    "relative_pose.2e77ed47": INTEGERS,  # np.asarray(T_wa, dtype=float) → np.asarray(T_wa) (line 20)
    "relative_pose.dff0d878": INTEGERS,  # np.asarray(T_wb, dtype=float) → np.asarray(T_wb) (line 21)
    "right_jacobian_se3.c6d6e3bc": INTEGERS,  # np.asarray(xi, dtype=float) → np.asarray(xi) (line 22)
    "rotated_point_covariance.9c0cf3e2": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 25)
    "rotated_point_covariance.e88f6bef": INTEGERS,  # np.asarray(Sigma, dtype=float) → np.asarray(Sigma) (line 26)
    "weighted_rotation_mean.84dca0ee": INTEGERS,  # np.asarray(weights, dtype=float) → np.asarray(weights) (line 24)
    "weighted_rotation_mean.b74ca0de": INTEGERS,  # np.asarray(Rs, dtype=float) → np.asarray(Rs) (line 23)
    "align_pose_gauss_newton.a5717bbe": LISTS,  # np.asarray(P, dtype=float) → P (line 25)
    "align_pose_gauss_newton.e151f9ca": LISTS,  # np.asarray(Q, dtype=float) → Q (line 26)
    "align_pose_robust.1b308ee3": LISTS,  # np.asarray(P, dtype=float) → P (line 24)
    "align_pose_robust.dd5815e9": LISTS,  # np.asarray(Q, dtype=float) → Q (line 25)
    "body_angular_velocity.a817d2c6": LISTS,  # np.asarray(R_dot, dtype=float) → R_dot (line 22)
    "covariance_left_to_right.aa7bc1ce": LISTS,  # np.asarray(Sigma_left, dtype=float) → Sigma_left (line 25)
    "jacobian_point_to_body.67a0df3c": LISTS,  # np.asarray(p_w, dtype=float) → p_w (line 22)
    "quat_from_two_vectors.afa1fd8d": LISTS,  # np.asarray(b, dtype=float) → b (line 29)
    "quat_from_two_vectors.c5a36c58": LISTS,  # np.asarray(a, dtype=float) → a (line 28)
    "rotated_point_covariance.c762480c": LISTS,  # np.asarray(Sigma, dtype=float) → Sigma (line 26)
    "weighted_rotation_mean.c5f0a1fa": LISTS,  # np.asarray(weights, dtype=float) → weights (line 24)
    "rotated_point_covariance.4db46332": NEGATED_FACTOR,  # -np.asarray(R, dtype=float) @ skew(p) → -np.asarray(R, dtype=float) @ skew(p).T (line 25)
    "rotated_point_covariance.c1dd1466": NEGATED_FACTOR,  # -np.asarray(R, dtype=float) → np.asarray(R, dtype=float) (line 25)
    "align_pose_gauss_newton.e6fc19b3": REBOUND,  # np.array(T0, dtype=float) → np.asarray(T0, dtype=float) (line 27)
    "align_pose_robust.e61b88af": REBOUND,  # np.array(T0, dtype=float) → np.asarray(T0, dtype=float) (line 26)
    "integrate_gyro.01a6d898": REBOUND,  # np.array(R0, dtype=float) → np.asarray(R0, dtype=float) (line 24)
    "covariance_left_to_right.f8079b4c": SYMMETRIC_INPUT,  # R.T @ np.asarray(Sigma_left, dtype=float) → R.T @ np.asarray(Sigma_left, dtype=float).T (line 25)
    "rotated_point_covariance.57f7682f": SYMMETRIC_INPUT,  # J @ np.asarray(Sigma, dtype=float) → J @ np.asarray(Sigma, dtype=float).T (line 26)
    "align_pose_gauss_newton.58b41c45": VECTORS,  # J.T @ r → J.T @ r.T (line 35)
    "align_pose_gauss_newton.9a36386d": VECTORS,  # R @ p → R @ p.T (line 33)
    "align_pose_robust.20b9d917": VECTORS,  # R @ p → R @ p.T (line 32)
    "align_pose_robust.4430ae29": VECTORS,  # xi @ xi → xi.T @ xi (line 39)
    "align_pose_robust.8c5b7074": VECTORS,  # r @ r → r @ r.T (line 33)
    "align_pose_robust.aa96ec54": VECTORS,  # xi @ xi → xi @ xi.T (line 39)
    "align_pose_robust.fd1b3c94": VECTORS,  # r @ r → r.T @ r (line 33)
    "align_pose_robust.fe42d240": VECTORS,  # J.T @ r → J.T @ r.T (line 36)
    "jacobian_point_to_body.5c0deebb": VECTORS,  # R.T @ np.asarray(p_w, dtype=float) → R.T @ np.asarray(p_w, dtype=float).T (line 22)
    "quat_from_two_vectors.fea30c4a": VECTORS,  # a @ b → b @ a (line 41)
    "quat_from_two_vectors.096b668f": VECTORS,  # axis @ a → axis.T @ a (line 33)
    "quat_from_two_vectors.5d78f166": VECTORS,  # axis @ a → a @ axis (line 33)
    "quat_from_two_vectors.78640265": VECTORS,  # a @ b → a.T @ b (line 41)
    "quat_from_two_vectors.75ce2f4c": VECTORS,  # a @ b → a @ b.T (line 41)
    "quat_from_two_vectors.813b23a4": VECTORS,  # a @ b → a @ b.T (line 36)
    "quat_from_two_vectors.14ac2484": VECTORS,  # axis @ a → axis @ a.T (line 33)
    "quat_from_two_vectors.65dcd69f": VECTORS,  # a @ b → a.T @ b (line 36)
    "quat_from_two_vectors.e418e08d": VECTORS,  # a @ b → b @ a (line 36)
    "quat_power.60c7c917": VECTORS,  # v @ v → v.T @ v (line 26)
    "quat_power.46f1cc1b": VECTORS,  # v @ v → v @ v.T (line 26)
    "relative_pose.18eca3f5": VECTORS,  # R_aw @ (T_wb[:3, 3] - T_wa[:3, 3]) → R_aw @ (T_wb[:3, 3] - T_wa[:3, 3]).T (line 25)
    "jacobians_of_compose.0a884ae7": VIEW,  # R2.T.copy() → R2.T (line 21)
    "align_pose_robust.84283cba": IRLS_CONVERGED,  # range(500) → range(500 - 1) (line 27)
    "align_pose_robust.f58ecf92": IRLS_CONVERGED,  # range(500) → range(500 + 1) (line 27)
    "align_pose_robust.2fc74aa3": IRLS_CONVERGED,  # range(500) → range(1, 500) (line 27)
    "align_pose_robust.2cdac8f5": IRLS_CONVERGED,  # `np.sqrt(xi @ xi) < 1e-13` always False (line 39)
    "align_pose_robust.a98f589e": IRLS_CONVERGED,  # np.sqrt(xi @ xi) < 1e-13 → np.sqrt(xi @ xi) <= 1e-13 (line 39)
    "align_pose_robust.2b23b18f": IRLS_CONVERGED,  # 1e-13 → 1e-15 (line 39)
    "align_pose_robust.28bbb93f": PRECONDITIONER,  # np.zeros((6, 6)) → np.zeros((6, 6), dtype=np.float32) (line 29)
    "align_pose_robust.4700c7d4": PRECONDITIONER,  # weight * (J.T @ J) → J.T @ J (line 35)
}


# --- lessons 01-04 ---
PERPENDICULAR_ALREADY = (
    "a × b is perpendicular to a already: the projection that removes its a-component (with "
    "its sign, a term or a vector slipped) only moves the rounding of a × b, by about 1e-16, "
    "which the promise allows (angle and action to 1e-14; 1e-15 / (π − θ) next to opposite "
    "directions, where the axis is ill-conditioned anyway)"
)
OPPOSITE_THRESHOLD = (
    "s < 1e-15 instead of 1e-14: between the two, θ = atan2(s, a · b) and the axis (a × b) / s "
    "are used; next to parallel directions θ ≈ s is accurate to 1e-14, and next to opposite ones "
    "the action is promised only to 1e-15 / (π − θ) ≈ 1e-15 / s ≥ 0.1, which the half turn meets"
)

EQUIVALENT.update(
    {
        "quat_from_two_vectors.d8c34a4e": PERPENDICULAR_ALREADY,  # axis - axis @ a * a → axis + axis @ a * a (line 33)
        "quat_from_two_vectors.2d4de54c": PERPENDICULAR_ALREADY,  # axis - axis @ a * a → axis (line 33)
        "quat_from_two_vectors.f433d884": PERPENDICULAR_ALREADY,  # axis @ a * a → axis @ a (line 33)
        "quat_from_two_vectors.35d66cf2": PERPENDICULAR_ALREADY,  # axis @ a * a → axis @ a * b (line 25)
        "quat_from_two_vectors.56449adc": PERPENDICULAR_ALREADY,  # axis @ a * a → axis @ b * a (line 25)
        "quat_from_two_vectors.1ce066f2": BOUNDARY,  # s < 1e-14 → s <= 1e-14 (line 35)
        "quat_from_two_vectors.8a6fd91c": OPPOSITE_THRESHOLD,  # 1e-14 → 1e-15 (line 35)
    }
)

# Not a correct answer: normalised linear interpolation below sin Ω = 1e-4 is off from slerp by up to 1.6e-14 (at
# Ω just below 1e-4, t = 0.3), above the promised 2e-15; the hidden suite now tries half-angles just below each
# decade and kills it.
del EQUIVALENT["quat_slerp.e0f71f64"]  # 1e-12 → 0.0001 (line 28)

# --- lesson 09: filter_predict, attitude_nees, filter_update, compound_pose_covariance, hand_eye_rotation (#42) ---
SYMMETRIC_P = "P is a covariance, symmetric by the docstring, so P.T is P and the product is the same"
SYMMETRIC_Q = "Q is the gyro noise's covariance, symmetric by the docstring, so Q.T is Q and the product is the same"
SCALAR_INSIDE = "a scalar factor moved into the matrix product: (c W) W and W (c W) are the same matrix, to rounding"
JR_SERIES_ABOVE = (
    "the series I - W/2 + W²/6 of the right Jacobian used up to θ = 1e-5 or 1e-4: there it differs from the "
    "closed form by θ³/24 in the W term and less in the W² term, at most 4.2e-14 of I, so P_new moves by less "
    "than the promised 2e-12 of max |P_new| (up to 1e-3 or 1e-2 it would not: those mutants are killed)"
)
JR_SERIES_SQUARE = (
    "the series is used only below θ = 1e-6, where its W² term is at most θ²/6 < 1.7e-13 of I: changing its "
    "sign or size, or dropping it, moves P_new by far less than the promised 1e-7 of max |P_new|"
)
BOOLEAN_WEIGHTS = "boolean weights multiply as 0 and 1: a * w[:, None] gives the same matrix as with w * 1.0"
SAME_PROPOSALS = (
    "the outer loop over i runs one step short or long only where the inner range(i + 1, n) is empty "
    "(i = n - 1, i = n): the same proposals, in the same order"
)
REFIT_FIXED_POINT = (
    "the refit stops where its kept set repeats, a fixed point: there X = fit(keep) gives the same misfits and the "
    "same set again, so running on (no break) or a bound of 99, 101 rounds returns the same X; the set repeats "
    "within a few rounds on every dataset the suites draw, far from the bound"
)
MORE_PROPOSALS = (
    "every pair of pairs (i, j), i < j, is still proposed, besides repeats and one-pair fits: the consensus "
    "still finds a proposal that all good pairs agree with, and the refit on the pairs within three robust "
    "deviations settles on the same set, so X is as accurate (the answer is judged by its angle only)"
)
DESIGN_WITHIN_BOUND = (
    "another estimator for an open design exercise, graded by its result alone (the angle of X within 4 σ_X of the "
    "truth on every grader-drawn dataset): proposing from fewer pairs, a tighter consensus, fewer refits or a "
    "tighter refit threshold keeps fewer good pairs or iterates less, and still meets the bound on every dataset "
    "both suites draw; the docstring promises that bound, not a method"
)
TUPLES_CONVERTED = (
    "converted only when it is a list: this argument is used only where numpy converts a tuple as it does a list "
    "(@, + or - with an array on the other side, np.linalg.solve, iteration into coursekit's Log), and an integer "
    "or float32 array gives the same values (the first operation with a float64 array is float64)"
)

EQUIVALENT.update(
    {
        "filter_predict.f851d4ea": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 36)
        "filter_predict.5043f4d0": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 37)
        "filter_predict.0573a085": INTEGERS,  # np.asarray(Q, dtype=float) → np.asarray(Q) (line 38)
        "filter_predict.09567b79": INTEGERS,  # np.asarray(omega_meas, dtype=float) → np.asarray(omega_meas) (line 39)
        "filter_predict.d14ecf80": LISTS,  # np.asarray(R, dtype=float) → R (line 36)
        "filter_predict.61fba306": LISTS,  # np.asarray(P, dtype=float) → P (line 37)
        "filter_predict.2d73fbe8": LISTS,  # np.asarray(Q, dtype=float) → Q (line 38)
        "filter_update.26fef8cd": INTEGERS,  # np.asarray(R, dtype=float) → np.asarray(R) (line 38)
        "filter_update.4a057b74": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 38)
        "filter_update.14c1e348": INTEGERS,  # np.asarray(g_w, dtype=float) → np.asarray(g_w) (line 39)
        "filter_update.9298c7a5": INTEGERS,  # np.asarray(Rn, dtype=float) → np.asarray(Rn) (line 41)
        "filter_update.101a42eb": INTEGERS,  # np.asarray(y, dtype=float) → np.asarray(y) (line 43)
        "filter_update.1b4553d1": LISTS,  # np.asarray(P, dtype=float) → P (line 38)
        "filter_update.f1f24f67": LISTS,  # np.asarray(g_w, dtype=float) → g_w (line 39)
        "filter_update.b02fa83f": LISTS,  # np.asarray(Rn, dtype=float) → Rn (line 41)
        "filter_update.7f4597d3": LISTS,  # np.asarray(y, dtype=float) → y (line 43)
        "filter_update.db075ffe": VECTORS,  # R.T @ np.asarray(g_w, dtype=float) → R.T @ np.asarray(g_w, dtype=float).T (line 39)
        "filter_update.2919f9d4": VECTORS,  # K @ (np.asarray(y, dtype=float) - g_b) → K @ (np.asarray(y, dtype=float) - g_b).T (line 43)
        "filter_update.b8364f09": SYMMETRIC_P,  # H @ P → H @ P.T (line 41)
        "filter_update.a7f4da58": SYMMETRIC_P,  # H @ P → H @ P.T (line 42)
        "filter_update.7b439eb4": SYMMETRIC_P,  # (np.eye(3) - K @ H) @ P → (np.eye(3) - K @ H) @ P.T (line 44)
        "filter_update.ecd30a8e": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 44)
        "filter_update.341c2e44": TUPLES_CONVERTED,  # np.asarray(P, dtype=float) only for a list (line 38)
        "filter_update.21dcef60": TUPLES_CONVERTED,  # np.asarray(g_w, dtype=float) only for a list (line 39)
        "filter_update.dbfc516a": TUPLES_CONVERTED,  # np.asarray(Rn, dtype=float) only for a list (line 41)
        "filter_update.d77d9cd6": TUPLES_CONVERTED,  # np.asarray(y, dtype=float) only for a list (line 43)
        "compound_pose_covariance.b0d4a5cf": INTEGERS,  # np.asarray(T1, dtype=float) → np.asarray(T1) (line 27)
        "compound_pose_covariance.d8fd795d": LISTS,  # np.asarray(T1, dtype=float) → T1 (line 27)
        "compound_pose_covariance.7c2d397e": TUPLES_CONVERTED,  # np.asarray(T1, dtype=float) only for a list (line 27)
        "filter_predict.c47a9f4a": TUPLES_CONVERTED,  # np.asarray(R, dtype=float) only for a list (line 36)
        "filter_predict.517fc4c0": TUPLES_CONVERTED,  # np.asarray(P, dtype=float) only for a list (line 37)
        "filter_predict.fdfcfcaf": TUPLES_CONVERTED,  # np.asarray(Q, dtype=float) only for a list (line 38)
        "filter_predict.1da9c265": VECTORS,  # phi @ phi → phi.T @ phi (line 41)
        "filter_predict.7b55863a": VECTORS,  # phi @ phi → phi @ phi.T (line 41)
        "filter_predict.a3c2e304": BOUNDARY,  # theta < 1e-06 → theta <= 1e-06 (line 43)
        "filter_predict.55e41cc7": CLOSED_FORM_BELOW,  # theta < 1e-06 → theta == 0.0 (only an exact zero) (line 43)
        "filter_predict.0f6b46b0": CLOSED_FORM_BELOW,  # 1e-06 → 1e-15 (line 43)
        "filter_predict.5831732a": CLOSED_FORM_BELOW,  # 1e-06 → 1e-08 (line 43)
        "filter_predict.a61797a1": CLOSED_FORM_BELOW,  # 1e-06 → 1e-07 (line 43)
        "filter_predict.b1d197b0": JR_SERIES_ABOVE,  # 1e-06 → 1e-05 (line 43)
        "filter_predict.272d3357": JR_SERIES_ABOVE,  # 1e-06 → 0.0001 (line 43)
        "filter_predict.5e335784": JR_SERIES_SQUARE,  # np.eye(3) - W / 2 + W @ W / 6 → np.eye(3) - W / 2 - W @ W / 6 (line 44)
        "filter_predict.d1b660f5": JR_SERIES_SQUARE,  # np.eye(3) - W / 2 + W @ W / 6 → np.eye(3) - W / 2 (line 44)
        "filter_predict.56d4560e": JR_SERIES_SQUARE,  # W @ W / 6 → W @ W (line 44)
        "filter_predict.94a89249": JR_SERIES_SQUARE,  # W @ W → W.T @ W (line 44)
        "filter_predict.5a131b8b": JR_SERIES_SQUARE,  # W @ W → W @ W.T (line 44)
        "filter_predict.d5fa0da7": SCALAR_INSIDE,  # (theta - np.sin(theta)) / theta ** 3 * W @ W → W @ ((theta - np.sin(theta)) / theta ** 3 * W) (line 47)
        "filter_predict.5fa11e6c": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 44)
        "filter_predict.359f1833": FLOAT32_EXACT,  # np.eye(3) → np.eye(3, dtype=np.float32) (line 47)
        "filter_predict.ed53c8ff": SYMMETRIC_P,  # step.T @ P → step.T @ P.T (line 49)
        "filter_predict.9b9fc36c": SYMMETRIC_Q,  # G @ Q → G @ Q.T (line 49)
        "attitude_nees.d3b8c435": INTEGERS,  # np.asarray(R_true, dtype=float) → np.asarray(R_true) (line 23)
        "attitude_nees.cccd349a": INTEGERS,  # np.asarray(R_est, dtype=float) → np.asarray(R_est) (line 23)
        "attitude_nees.e81f686a": INTEGERS,  # np.asarray(P, dtype=float) → np.asarray(P) (line 24)
        "attitude_nees.d6f82477": LISTS,  # np.asarray(R_true, dtype=float) → R_true (line 23)
        "attitude_nees.5657e967": LISTS,  # np.asarray(P, dtype=float) → P (line 24)
        "attitude_nees.8fbfc8b6": TUPLES_CONVERTED,  # np.asarray(R_true, dtype=float) only for a list (line 23)
        "attitude_nees.c4e02f28": TUPLES_CONVERTED,  # np.asarray(P, dtype=float) only for a list (line 24)
        "attitude_nees.0b23444c": VECTORS,  # eps @ np.linalg.solve(P, eps) → np.linalg.solve(P, eps) @ eps (line 24)
        "attitude_nees.3cc74f74": VECTORS,  # eps @ np.linalg.solve(P, eps) → eps.T @ np.linalg.solve(P, eps) (line 24)
        "attitude_nees.ef10f856": VECTORS,  # eps @ np.linalg.solve(P, eps) → eps @ np.linalg.solve(P, eps).T (line 24)
        "hand_eye_rotation.c71538f6": INTEGERS,  # np.asarray(As, dtype=float) → np.asarray(As) (line 28)
        "hand_eye_rotation.01e7e7a9": INTEGERS,  # np.asarray(Bs, dtype=float) → np.asarray(Bs) (line 29)
        "hand_eye_rotation.e827b696": LISTS,  # np.asarray(As, dtype=float) → As (line 28)
        "hand_eye_rotation.f62269b7": LISTS,  # np.asarray(Bs, dtype=float) → Bs (line 29)
        "hand_eye_rotation.84846119": TUPLES_CONVERTED,  # np.asarray(As, dtype=float) only for a list (line 28)
        "hand_eye_rotation.257aebe3": TUPLES_CONVERTED,  # np.asarray(Bs, dtype=float) only for a list (line 29)
        "hand_eye_rotation.3cae15f4": DET_OF_PRODUCT,  # U @ Vt → Vt @ U (line 33)
        "hand_eye_rotation.37cef270": DET_OF_PRODUCT,  # U @ Vt → U.T @ Vt (line 33)
        "hand_eye_rotation.367417b0": DET_OF_PRODUCT,  # U @ Vt → U @ Vt.T (line 33)
        "hand_eye_rotation.583f3e0a": DIAGONAL_T,  # U @ np.diag([1.0, 1.0, det]) → U @ np.diag([1.0, 1.0, det]).T (line 33)
        "hand_eye_rotation.e7894db0": BOOLEAN_WEIGHTS,  # np.isin(np.arange(n), [i, j]) * 1.0 → np.isin(...) (line 40)
        "hand_eye_rotation.21a559f1": BOUNDARY,  # misfits(X) < 0.1 → misfits(X) <= 0.1 (line 41)
        "hand_eye_rotation.2913e7ff": SAME_PROPOSALS,  # range(n) → range(n - 1) (line 40)
        "hand_eye_rotation.dd3504af": SAME_PROPOSALS,  # range(n) → range(n + 1) (line 40)
        "hand_eye_rotation.bad21bd1": MORE_PROPOSALS,  # i + 1 → i - 1 (line 40)
        "hand_eye_rotation.48d31b1a": MORE_PROPOSALS,  # i + 1 → i (line 40)
        "hand_eye_rotation.8465ec87": MORE_PROPOSALS,  # i + 1 → 1 (line 40)
        "hand_eye_rotation.f2a6c750": BOUNDARY,  # misfits(X) < 0.1 → misfits(X) <= 0.1 (line 43)
        "hand_eye_rotation.efa02a4d": BOUNDARY,  # r <= 3.0 * 1.4826 * np.median(r) → r < ... (line 47)
        "hand_eye_rotation.4ecac195": BOOLEAN_WEIGHTS,  # keep * 1.0 → keep (line 45)
        "hand_eye_rotation.a1d80cef": REFIT_FIXED_POINT,  # range(100) → range(100 - 1) (line 44)
        "hand_eye_rotation.f405391d": REFIT_FIXED_POINT,  # range(100) → range(100 + 1) (line 44)
        "hand_eye_rotation.77a6915d": REFIT_FIXED_POINT,  # range(100) → range(1, 100) (line 44)
        "hand_eye_rotation.2b0dd936": REFIT_FIXED_POINT,  # `np.array_equal(new_keep, keep)` always False (line 48)
        "compound_pose_covariance.104dd216": INTEGERS,  # np.asarray(T2, dtype=float) → np.asarray(T2) (line 28)
        "compound_pose_covariance.fe64894a": INTEGERS,  # np.asarray(S2, dtype=float) → np.asarray(S2) (line 30)
        "compound_pose_covariance.60f0d029": INTEGERS,  # np.asarray(S1, dtype=float) → np.asarray(S1) (line 30)
        "compound_pose_covariance.1a9cde5a": LISTS,  # np.asarray(T2, dtype=float) → T2 (line 28)
        "compound_pose_covariance.edb02281": LISTS,  # np.asarray(S2, dtype=float) → S2 (line 30)
        "compound_pose_covariance.48acab06": LISTS,  # np.asarray(S1, dtype=float) → S1 (line 30)
        "compound_pose_covariance.55f64504": TUPLES_CONVERTED,  # np.asarray(T2, dtype=float) only for a list (line 28)
        "compound_pose_covariance.86377548": TUPLES_CONVERTED,  # np.asarray(S2, dtype=float) only for a list (line 30)
        "compound_pose_covariance.cfa4e689": TUPLES_CONVERTED,  # np.asarray(S1, dtype=float) only for a list (line 30)
        "compound_pose_covariance.9a2ec9bd": SYMMETRIC_P,  # A @ np.asarray(S1, dtype=float) → A @ np.asarray(S1, dtype=float).T (line 30)
        "hand_eye_rotation.1a40b760": DESIGN_WITHIN_BOUND,  # range(n) → range(1, n) (line 40)
        "hand_eye_rotation.875f42bd": DESIGN_WITHIN_BOUND,  # 0.1 → 0.01 (line 41)
        "hand_eye_rotation.3ae30e51": DESIGN_WITHIN_BOUND,  # range(100) → range(3) (line 44)
        "hand_eye_rotation.eaee9ba6": DESIGN_WITHIN_BOUND,  # `np.array_equal(new_keep, keep)` always True (line 48)
        "hand_eye_rotation.a1839d92": DESIGN_WITHIN_BOUND,  # 3.0 * 1.4826 * np.median(r) → np.median(r) (line 47)
        "hand_eye_rotation.3a144602": DESIGN_WITHIN_BOUND,  # 3.0 * 1.4826 → 3.0 (line 47)
        "hand_eye_rotation.c58971c3": DESIGN_WITHIN_BOUND,  # 3.0 * 1.4826 → 1.4826 (line 47)
    }
)

NUMPY_BOOL = (
    "numpy.bool_ for bool: the contract accepts it where a docstring promises a bool (coursekit/exercise_contracts.py, "
    "both suites), and the sandbox's wire returns it as a bool"
)
EQUIVALENT.update(
    {
        "is_rotation_matrix.fb2b11f0": NUMPY_BOOL,  # return bool(...) → return ... (line 29)
        "commutes.0a7f2f9c": NUMPY_BOOL,  # return bool(...) → return ... (line 28)
        "rotate_point.b5f80176": TUPLES_CONVERTED,  # np.asarray(p_b, dtype=float) only for a list (line 23)
        "compose.6aba9786": TUPLES_CONVERTED,  # np.asarray(R_ab, dtype=float) only for a list (line 21)
        "compose.9750aa72": TUPLES_CONVERTED,  # np.asarray(R_bc, dtype=float) only for a list (line 21)
        "nearest_rotation.cb6bb7f6": TUPLES_CONVERTED,  # np.asarray(M, dtype=float) only for a list (line 21)
    }
)

UNPACKED_OR_ITERATED = (
    "converted only when it is a list: a tuple or an integer array is only unpacked or iterated into numbers and "
    "rows that meet a float64 array (@, skew, a float literal in np.array) before anything else, so every admitted "
    "form gives the same float64 values"
)
STOP_WITHIN_PROMISE = (
    "a looser stop (a step below 1e-10 instead of 1e-13): the iteration contracts, so what is left after such a "
    "step is of its size or smaller, and the answer still meets the docstring's promise (the Huber gradient "
    "vanishes to 1e-10 per point), measured on every grader-drawn dataset"
)
EQUIVALENT.update(
    {
        "hat.1fbe4a97": UNPACKED_OR_ITERATED,  # np.asarray(w, dtype=float) only for a list (line 20)
        "bracket.7a38c8dc": TUPLES_CONVERTED,  # np.asarray(A, dtype=float) only for a list (line 18)
        "bracket.bf3d0dcd": TUPLES_CONVERTED,  # np.asarray(B, dtype=float) only for a list (line 19)
        "exp_so3.8452fbac": CLOSED_FORM_BELOW,  # theta < 0.0001 → theta == 0.0 (only an exact zero) (line 22)
        "covariance_left_to_right.faec3a06": TUPLES_CONVERTED,  # np.asarray(Sigma_left, ...) only for a list (line 25)
        "align_pose_gauss_newton.cb14b8a3": UNPACKED_OR_ITERATED,  # np.asarray(P, dtype=float) only for a list
        "align_pose_gauss_newton.b98c0433": UNPACKED_OR_ITERATED,  # np.asarray(Q, dtype=float) only for a list
        "align_pose_robust.1ad17d64": UNPACKED_OR_ITERATED,  # np.asarray(P, dtype=float) only for a list (line 24)
        "align_pose_robust.6d1aefc7": UNPACKED_OR_ITERATED,  # np.asarray(Q, dtype=float) only for a list (line 25)
        "align_pose_robust.e446411e": STOP_WITHIN_PROMISE,  # np.sqrt(xi @ xi) < 1e-13 loosened ×1000 (line 39)
    }
)

ALL_FORMS_MEASURED = (
    "converted only when it is a list: every other admitted form (a tuple, an integer or float32 array, a read-only "
    "array) meets a float64 operand before anything depends on its type, so the values are the same; measured, not "
    "assumed: the contract check calls it with each form at quarter turns, the identity, half turns, both pitch locks "
    "and a 53° turn, in both suites, and it passes"
)
EQUIVALENT.update(
    {
        "axis_from_eigen.ceebbccc": ALL_FORMS_MEASURED,  # np.asarray(R, dtype=float) only for a list (line 20)
        "body_angular_velocity.d280cc96": ALL_FORMS_MEASURED,  # np.asarray(R_dot, ...) only for a list (line 22)
        "quat_from_axis_angle.2528a6e7": ALL_FORMS_MEASURED,  # np.asarray(u, dtype=float) only for a list (line 21)
        "quat_rotate.422f5365": ALL_FORMS_MEASURED,  # np.asarray(v, dtype=float) only for a list (line 27)
        "quat_from_two_vectors.67fea111": ALL_FORMS_MEASURED,  # np.asarray(a, dtype=float) only for a list (line 28)
        "quat_from_two_vectors.2d819ba1": ALL_FORMS_MEASURED,  # np.asarray(b, dtype=float) only for a list (line 29)
        "quat_to_euler_zyx.72454c3b": ALL_FORMS_MEASURED,  # np.asarray(q, dtype=float) only for a list (line 22)
        "boxplus_right.1c1e40ce": ALL_FORMS_MEASURED,  # np.asarray(R, dtype=float) only for a list (line 21)
        "boxplus_left.b7d01d53": ALL_FORMS_MEASURED,  # np.asarray(R, dtype=float) only for a list (line 20)
        "boxminus.5be74976": ALL_FORMS_MEASURED,  # np.asarray(R_a, dtype=float) only for a list (line 20)
        "right_jacobian_so3.92a7e6b6": ALL_FORMS_MEASURED,  # np.asarray(w, dtype=float) only for a list (line 22)
        "right_jacobian_inv_so3.c6f28225": ALL_FORMS_MEASURED,  # np.asarray(w, dtype=float) only for a list (line 22)
        "jacobian_point_to_body.80715307": ALL_FORMS_MEASURED,  # np.asarray(p_w, ...) only for a list (line 22)
        "make_pose.7b557fd2": ALL_FORMS_MEASURED,  # np.asarray(R, dtype=float) only for a list (line 25)
        "transform_points.8ec27b36": ALL_FORMS_MEASURED,  # np.asarray(P, dtype=float) only for a list (line 24)
        "pose_compose.711cc3b0": ALL_FORMS_MEASURED,  # np.asarray(T_ab, dtype=float) only for a list (line 20)
        "pose_compose.b47efe15": ALL_FORMS_MEASURED,  # np.asarray(T_bc, dtype=float) only for a list (line 20)
        "align_svd.76a952f2": ALL_FORMS_MEASURED,  # np.asarray(P, dtype=float) only for a list (line 25)
        "align_gauss_newton.47aca3b1": ALL_FORMS_MEASURED,  # np.asarray(P, dtype=float) only for a list (line 29)
        "align_gauss_newton.fa8c10d9": ALL_FORMS_MEASURED,  # np.asarray(Q, dtype=float) only for a list (line 30)
        "weighted_rotation_mean.e2034312": ALL_FORMS_MEASURED,  # np.asarray(weights, ...) only for a list (line 24)
        "integrate_gyro.aca4e42c": ALL_FORMS_MEASURED,  # np.array(R0, dtype=float) only for a list (line 24)
        "rotated_point_covariance.f59ad5fa": ALL_FORMS_MEASURED,  # np.asarray(Sigma, ...) only for a list (line 26)
        "quat_slerp.80fa3c71": CLOSED_FORM_BELOW,  # np.sin(omega) < 1e-12 → == 0.0: sin(tΩ)/sin(Ω) stays accurate
        "quat_boxplus.a7070782": CLOSED_FORM_BELOW,  # angle < 1e-08 → angle == 0.0: sin(θ/2)/θ stays accurate
        "right_jacobian_so3.6c8d710c": CLOSED_FORM_BELOW,  # theta < 0.001 → theta == 0.0 (line 25)
        "right_jacobian_inv_so3.a12efa69": CLOSED_FORM_BELOW,  # theta < 0.001 → theta == 0.0 (line 25)
        "quat_from_two_vectors.e9dc89c4": CLOSED_FORM_BELOW,  # s < 1e-14 → s == 0.0 (line 35)
    }
)

STEP_NEVER_TINY = "a floor of 1e-12 under a step that the step rule never lets fall below 1e-6: it never acts"
EQUIVALENT.update(
    {
        "numerical_jacobian.e4c3870c": STEP_NEVER_TINY,  # ... / step → ... / max(step, 1e-12) (line 38)
        "numerical_jacobian.60b61ba4": STEP_NEVER_TINY,  # ... / step → ... / max(step, 1e-12) (line 45)
    }
)
