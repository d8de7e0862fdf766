"""The hints that a public check and the hidden suite both give, written once.

A student whose answer makes a known mistake reads the same sentence in the
notebook (a public check, :mod:`coursekit.checks`) and in the feedback of the
hidden suite. Only the words are shared: each side decides for itself when
the mistake is there (the public checks never compute answers). Grouped by
the lesson whose public checks use them.

Examples
--------
>>> from coursekit import hints
>>> hints.SIGN_FIX_GOES_BETWEEN_HINT.startswith("the sign fix goes between U and Vᵀ")
True
"""


# ---------------------------------------------------------------- checks/lesson01.py
BOTH_SINES_HAVE_SAME_HINT = ("both sines have the same sign, so the columns are not orthogonal: exactly one of them "
                             "carries the minus")
CHECK_M_S_SHAPE_HINT = ("check M's shape first (2-D and square, else return False) and compare MᵀM with "
                        "np.eye(M.shape[0]), not np.eye(3)")
DIVIDING_EACH_COLUMN_LENGTH_HINT = ("dividing each column by its length does not make the columns orthogonal: project "
                                    "with the SVD M = U Σ Vᵀ, R = U Vᵀ")
ELEMENTWISE_PRODUCT_HINT = "looks like A * B, the elementwise product: compose with the matrix product @"
FIRST_FACTOR_TRANSPOSED_HINT = "looks like R_abᵀ R_bc: the first factor is transposed (inverted); multiply them as they are"
NEGATED_NOT_TRANSPOSED_HINT = ("returned -R (every entry negated): the inverse of a rotation is its transpose, not "
                               "its negative")
NUMPY_COULD_BROADCAST_R_HINT = ("numpy could not broadcast R * P: an elementwise product is not a rotation of the "
                                "rows; use the matrix product, P @ R.T")
ONE_POINT_NOT_ROWS_HINT = "R @ p works for one point, not for rows: for P of shape (N, 3) use P @ R.T"
QR_NOT_NEAREST_HINT = ("looks like the Q of a QR decomposition: orthogonal, but it keeps the first column's "
                        "direction, so it is not the nearest rotation; use the SVD")
REVERSED_ORDER_ROWS_R_HINT = ("reversed the order of the rows (R[::-1]): the inverse is the transpose R.T (rows "
                              "become columns)")
SIGN_FIX_GOES_BETWEEN_HINT = ("the sign fix goes between U and Vᵀ, R = U diag(1, 1, d) Vᵀ: it flips the last column "
                              "of U, the direction of the smallest singular value")
SINE_COSINE_SWAPPED_COS_HINT = "sine and cosine are swapped: cos θ goes on the diagonal, ±sin θ off it"

# ---------------------------------------------------------------- checks/lesson02.py
CLOSURE_ASKS_MEMBER_OP_B_HINT = ("closure asks is_member(op(a, b)) for every ordered pair: here R₁ + R₂ is not a "
                                 "rotation")
CLOSURE_ASKS_MEMBER_OP_HINT = "closure asks is_member(op(a, b)) for every ordered pair"
CLOSURE_TESTED_INSTEAD_OP_HINT = ("closure was tested with @ instead of the op you are given (R₁ @ R₂ is a rotation, "
                                  "R₁ + R₂ is not): use is_member(op(a, b))")
COMMUTES_NAN_CAME_OUT_HINT = "commutes(NaN, 2, ×) came out True although NaN · 2 is NaN both ways"
LEFT_IDENTITY_UNCHECKED_HINT = "a ∘ 1 = a, but 1 ∘ a = 1: check op(identity, a) as well as op(a, identity)"
RETURN_CLOSURE_IDENTITY_INVERSE_HINT = ("return {\"closure\": ..., \"identity\": ..., \"inverse\": ..., \"associativity\": "
                                        "...}")
RIGHT_IDENTITY_UNCHECKED_HINT = "1 ∘ a = a, but a ∘ 1 = 1: check op(a, identity) as well as op(identity, a)"
USE_EXACTLY_KEYS_CLOSURE_HINT = "use exactly the keys closure, identity, inverse, associativity"

# ---------------------------------------------------------------- checks/lesson03.py
AB_BA_BRACKET_DIFFERENCE_HINT = "that is AB + BA: the bracket is the difference AB - BA"
ANGLE_FORMULA_HINT = "θ must be the rotation angle in radians, in [0, π], accurate at tiny angles and near π alike"
AXIS_AT_ZERO_ANGLE_HINT = ("the axis read off R - Rᵀ divides by sin θ, 0/0 at θ = 0: the axis is arbitrary there, "
                           "return [1, 0, 0]")
COEFFICIENTS_SWAPPED_R_I_HINT = ("the coefficients are swapped: the K term and the K² term carry each other's "
                                 "coefficient; compare them with Rodrigues' formula on the page, term by term")
COMPARE_ENTRY_ENTRY_W3_HINT = ("compare entry by entry with the matrix [w]× on the page: check which component "
                               "of w sits in each off-diagonal entry, and its sign")
DEGREES_VALUE_RADIANS_COURSE_HINT = "θ is in degrees (57.3 × the value in radians): the course works in radians"
ENTRYWISE_POWER_HINT = "W ** k is an entry-wise power: use the matrix product (term = term @ W / k)"
FACTORIAL_MISSING_HINT = "the 1/k! is missing: the terms are W^k / k! (term = term @ W / k)"
GOT_ZERO_MULTIPLIES_ENTRY_HINT = "got zero: * multiplies entry by entry (A * B = B * A), use @ for the matrix product"
IDENTITY_TERM_MISSING_SUM_HINT = "the identity term is missing: the sum starts at k = 0 (W⁰ = I)"
LOG_FORMULA_HINT = ("w must satisfy exp(w) = R with |w| in [0, π]: check the axis (R leaves it fixed), the angle "
                    "and the sense of the turn")
LOG_OFF_NEAR_TAKE_HINT = ("the log is off near π, where sin θ → 0 and R - Rᵀ no longer knows the axis: section 5 says "
                          "which part of R still holds it there, and the turn's sense must come out right too")
MINUS_SIGNS_MISSING_SYMMETRIC_HINT = ("the minus signs are missing (a symmetric matrix): [w]× is antisymmetric, "
                                      "each entry above the diagonal is minus its mirror below it")
NAN_AT_ZERO_ANGLE_HINT = ("NaN or inf at θ = 0: θ/sin θ is 0/0 there; tiny angles need a branch that divides by "
                          "nothing that vanishes, as exact as the closed form (relative error 1e-10)")
NAN_NEAR_PI_HINT = ("NaN or inf near θ = π, where sin θ → 0: the log needs a branch there that does not divide by "
                    "sin θ (section 5 says which part of R still holds the axis)")
NP_LINALG_EIGH_ASSUMES_HINT = ("np.linalg.eigh assumes a symmetric matrix (it reads one triangle of R): use "
                               "np.linalg.eig")
ONE_TERM_TOO_FEW_HINT = "one term too few: n_terms terms means k = 0 … n_terms - 1"
ONE_TERM_TOO_MANY_HINT = "one term too many: n_terms terms means k = 0 … n_terms - 1"
ONLY_AB_BRACKET_SUBTRACTS_HINT = "that is only AB: the bracket subtracts BA, [A, B] = AB - BA"
OPPOSITE_ROTATION_CHECK_SIGN_HINT = ("the opposite rotation: check the sign of the axis (Exp of your answer turns "
                                     "the other way than R; the order of R and Rᵀ in R - Rᵀ decides it)")
LOG_AXIS_SIGN_NEAR_PI_HINT = ("near π the axis has the wrong sign: Exp of your answer turns the other way. Only at "
                              "θ = π are θu and -θu one rotation; just below π, R still tells them apart, so the sign "
                              "of the axis must come from R")
RETURNED_ZERO_TINY_ROTATION_HINT = ("returned zero for a tiny rotation: arccos rounds tiny angles to 0, so the angle "
                                    "must come from numbers that keep it")
RODRIGUES_FORMULA_HINT = ("not a turn by |w| about w/|w|: compare your matrix with Rodrigues' formula on the page, "
                          "term by term, at a simple w such as [0, 0, π/2]")
RODRIGUES_FORMULA_NEEDS_UNIT_HINT = ("Rodrigues' formula needs the unit axis: K = [w/θ]×, not [w]× (θ = |w| is in sin "
                                     "θ and cos θ)")
ROW_EIGENVECTOR_MATRIX_EIGENVECTORS_HINT = ("that is a row of the eigenvector matrix: eigenvectors are its columns, "
                                            "vectors[:, k]")
SUM_TERMS_W_K_HINT = "sum the terms W^k / k! for k = 0 … n_terms - 1, with matrix products"
SVD_NULL_SPACE_R_HINT = "that is the SVD null space of R, but R is invertible: the axis spans the null space of R - I"
TWICE_ROTATION_VECTOR_VEE_HINT = ("twice the rotation vector: every component is doubled; check the factor that turns "
                                  "vee(R - Rᵀ) into θ u on a quarter turn about z")
U_POINTS_WRONG_WAY_HINT = ("u points the wrong way: R turns by +θ about your -u; the order of R and Rᵀ in R - Rᵀ "
                           "decides the sign")
W_SITS_DIAGONAL_W_HINT = "w sits on the diagonal: [w]× has zeros there and w in the off-diagonal entries"
AXIS_AT_HALF_TURN_HINT = ("at θ = π, R - Rᵀ is zero up to rounding and carries no axis: section 5 says which part "
                          "of R still does")

# ---------------------------------------------------------------- checks/lesson03_body_rates.py
RATE_TURNED_INTO_BODY_HINT = ("right at R = I, wrong at this R: your ω_b is written in the wrong axes, one change "
                              "of axes too many (at R = I a change of axes changes nothing, so it cannot show there)")
BODY_RATE_IS_WORLD_RATE_HINT = ("that is the world rate ω_w, the spin written in world axes; the gyroscope's rate "
                                "ω_b is the same spin in the body's own axes (section 8)")

# ---------------------------------------------------------------- checks/lesson04.py
NO_GUARD_FOR_SHORT_Q_HINT = ("wrong only for a short q: every non-zero quaternion has an inverse, so nothing in it "
                             "needs a floor on |q|² (float64 holds |q|² = 1e-24 with all its digits)")
ARRAY_REVERSED_ONLY_SCALAR_HINT = "the array was reversed: only the scalar moves, x, y, z keep their order"
CONJUGATE_MISSING_Q_V_HINT = "the conjugate is missing: q ⊗ [0, v] ⊗ q does not rotate v; use q ⊗ [0, v] ⊗ q*"
CONSTANT_SPEED_NORMALISED_LINEAR_HINT = ("not at constant speed: a normalised linear blend (nlerp) runs fast in the "
                                         "middle; use the weights sin((1 - t)Ω)/sin Ω and sin(tΩ)/sin Ω")
CONSTANT_SPEED_TURN_Q0_HINT = ("not at constant speed: the turn from q0 must grow as t × the whole angle; use the "
                               "weights sin((1 - t)Ω)/sin Ω and sin(tΩ)/sin Ω")
DIVIDE_U_NORM_FIRST_HINT = "divide u by its norm first: the axis must be a unit vector"
FIRST_ROW_W_X_HINT = "the first row is [w, -x, -y, -z]: its minus signs are missing"
MULTIPLIED_ENTRY_ENTRY_EVERY_HINT = ("multiplied entry by entry: every component of p ⊗ q mixes all four components "
                                     "of p and q")
PRODUCT_DIVIDED_NORM_P_HINT = ("the product is divided by its norm: p ⊗ q of quaternions that are not unit has norm "
                               "|p| |q|; return the product itself")
RETURNED_Q_KEEP_SCALAR_HINT = "returned -q: keep the scalar w, negate only x, y, z"
RETURNED_Q_Q_ONLY_HINT = "returned -q / |q|²: only the vector part changes sign, q⁻¹ = q* / |q|²"
RETURNED_Q_UNCHANGED_NEGATE_HINT = "returned q unchanged: negate the vector part x, y, z"
SCALAR_LAST_HINT = "q was read as scalar last [x, y, z, w]: this course stores [w, x, y, z]"
SECOND_ORDER_TERM_MISSING_HINT = ("the second-order term is missing: your v' is right to first order in the vector "
                                  "part of q, but q ⊗ [0, v] ⊗ q* also has terms quadratic in it; multiply the "
                                  "sandwich out in full")
SIN_COS_SWAPPED_SCALAR_HINT = "sin and cos are swapped: the scalar is cos(θ/2), the vector part u sin(θ/2)"
SLERP_STAYS_UNIT_SPHERE_HINT = "slerp stays on the unit sphere: the sine weights keep it there"
TOOK_Q_ENTRY_ENTRY_HINT = "took 1/q entry by entry: the inverse of a quaternion is q* / |q|²"

# ---------------------------------------------------------------- checks/lesson04_two_vectors.py
ARCCOS_LOSES_SMALL_ANGLES_HINT = ("arccos loses small angles (cos θ rounds to 1): a turn of 1e-10 rad came out "
                                  "as none; the angle must come from numbers that keep it at tiny angles")
OPPOSITE_DIRECTIONS_ANSWER_HALF_HINT = ("for opposite directions the answer is a half turn, [0, u] with u "
                                        "perpendicular to a")

# ---------------------------------------------------------------- checks/lesson04_powers.py
POWER_ARCCOS_HINT = ("arccos(w) rounds small half-angles to 0 (cos α is 1.0 below about 1e-8): the angle must keep "
                     "its digits at every size, as your Log of lesson 03 had to")
POWER_DEFINITION_HINT = "q^t = Exp_q(t Log_q q): write q as [cos α, sin α u] with α in [0, π], then apply the definition"
POWER_HALF_ANGLE_HINT = "q¹ must come back as q, and q^½ ⊗ q^½ as q: check how the half angle enters q and Log_q"
POWER_IDENTITY_HINT = "at the identity |v| = 0: guard the division (any axis will do there)"
POWER_SIGN_FLIP_HINT = ("q and -q are one rotation but not one quaternion: -q has half-angle π - α about -u, so its "
                        "powers turn the other way; do not flip the sign of q")
POWER_UNIT_AXIS_HINT = ("the axis of the power is not a unit vector: the vector part of q has length sin α, "
                        "not 1")

# ---------------------------------------------------------------- checks/lesson05.py
ANGLES_MUST_SATISFY_R_HINT = ("the angles must satisfy R = Rz(yaw) Ry(pitch) Rx(roll): rebuild R from your angles with "
                              "your euler_zyx_to_matrix and compare entry by entry to see which angle is off")
COLUMNS_ORDER_ROLL_PITCH_HINT = ("the columns are in the order [roll, pitch, yaw]: E multiplies [yaw_rate, "
                                 "pitch_rate, roll_rate]")
LOCK_ONLY_YAW_ROLL_DEFINED_HINT = ("at the lock only yaw ∓ roll is defined and these angles do give the rotation: the "
                                   "course sets roll = 0 and gives the whole turn to yaw")
LOCK_ONLY_YAW_ROLL_HINT = ("at the lock only yaw ∓ roll is defined and these angles do give R: the course sets roll = "
                           "0 and gives the whole turn to yaw")
MIXED_PRODUCTS_LOST_THEIR_HINT = ("the mixed products lost their minus signs: w = c c c + s s s, x = c c s - s s c, y "
                                  "= c s c + s c s, z = s c c - c s s (c, s of yaw/2, pitch/2, roll/2 in that order)")
NON_UNIT_Q_STANDS_HINT = "a non-unit q stands for the same rotation: divide q by its norm first"
NO_GIMBAL_LOCK_BRANCH_HINT = ("no gimbal-lock branch, or a lock test too strict to fire: at |pitch| = π/2 both "
                              "arguments of the atan2 formulas for yaw and roll are rounding noise (about 1e-16, "
                              "seldom exactly 0); call it locked below about 1e-12, and there set roll = 0 and give "
                              "the whole turn to yaw")
NO_SEPARATE_GIMBAL_LOCK_HINT = ("no separate gimbal-lock branch, or a lock test too strict to fire: at pitch ±π/2, "
                                "R[0, 0], R[1, 0], R[2, 1], R[2, 2] are rounding noise, seldom exactly 0; below the "
                                "docstring's threshold set roll = 0")
PITCH_ARCSIN_R_LOSES_HINT = ("pitch = arcsin(-R[2, 0]) loses digits near ±1 (an error ε in R[2, 0] moves the angle by "
                             "√(2ε)): next to the lock the pitch must still be right to about 1e-12, and arcsin of "
                             "R[2, 0] cannot give that")
PITCH_TURNS_WRONG_WAY_HINT = ("the pitch turns the wrong way: Ry(pitch) = [[cos, 0, sin], [0, 1, 0], [-sin, 0, cos]] "
                              "(about y the minus sign sits bottom-left)")
ROLL_SIGNS_FLIPPED_EXPRESS_HINT = ("the roll signs are flipped: every entry with sin(roll) has the wrong sign; the "
                                   "axes are turned the wrong way into the body frame (try roll = π/2 with a pure "
                                   "yaw rate and a finite difference)")
TREATED_ROTATION_NEXT_LOCK_HINT = ("treated a rotation next to the lock as locked (roll = 0): call it gimbal lock "
                                   "only when cos(pitch) is below about 1e-12")
YAW_ROLL_SWAPPED_YAW_HINT = "yaw and roll are swapped: yaw turns about z, roll about x"

# ---------------------------------------------------------------- checks/lesson05_world_rates.py
COLUMNS_GO_ORDER_RATES_HINT = "the columns go in the order of the rates: [yaw_rate, pitch_rate, roll_rate]"

# ---------------------------------------------------------------- checks/lesson06.py
AXIS_TIMES_SIN_VEE_HINT = ("that is the axis times sin θ, right only to first order: the difference needs the "
                           "Log of the relative rotation, whose length is the angle θ itself")
CLOSED_FORM_LOSES_DIGITS_HINT = ("the closed form loses its digits at tiny θ: a coefficient that subtracts nearly "
                                 "equal numbers keeps fewer digits as θ shrinks, and comes out 0 instead of its limit "
                                 "once the two round to the same number; below a threshold use the Taylor series of "
                                 "each coefficient, with its θ² term")
CLOSED_FORM_USE_TAYLOR_HINT = "the closed form is 0/0 at θ = 0: use the Taylor series below a small angle"
COEFFICIENTS_SWAPPED_COS_MULTIPLIES_HINT = ("the coefficients are swapped: [w]× and [w]×² carry each other's; "
                                            "compare their limits at θ → 0 with the first terms of your series")
FACTORS_WRONG_ORDER_R_HINT = ("the frames are mixed: a turn moves the world point R p at right angles to itself, so "
                              "every column of J must be perpendicular to R p; yours are perpendicular to the "
                              "body coordinates p instead")
FIRST_ORDER_PART_ONLY_HINT = ("that is I + [w]×/2, only the first-order part: the [w]×² term of the formula on the "
                              "page is missing")
JACOBIAN_TRANSPOSE_NOT_INVERSE_HINT = "that is Jr(w)ᵀ: Jr is not orthogonal, its transpose is not its inverse"
ROTATED_POINT_SIGN_FLIPPED_HINT = ("the sign is flipped: J is the negative of the finite differences of R Exp(δ) p in "
                                   "every column; check each column's sign on a sanity case, R = I and p = x, where a "
                                   "turn about z moves p towards +y")
ROTATED_POINT_R_MISSING_HINT = ("right at R = I, wrong at a generic R: your J stays the same whatever the attitude, "
                                "but how the world point R Exp(δ) p moves changes with R; compare with finite "
                                "differences at a generic R")
LEFT_DIFFERENCE_STEP_RIGHT_HINT = "that is the left difference Log(R_a R_bᵀ); the step goes on the right, R_b Exp(δ) = R_a"
LEFT_JACOBIAN_OF_ROTATED_POINT_HINT = ("that is the Jacobian of the left perturbation, Exp(δ) R p; here δ turns the "
                                       "body about its own axes, R Exp(δ) p")
LEFT_QUAT_PERTURBATION_HINT = "that is Exp_q(δ) ⊗ q, the left perturbation; multiply on the right: q ⊗ Exp_q(δ)"
LEFT_UPDATE_IS_A_ROTATION_HINT = "Exp(δ) is a rotation and so is Exp(δ) @ R: build the result from it"
LOGS_DO_NOT_SUBTRACT_HINT = ("that is Log(R_a) - Log(R_b): rotation vectors do not subtract (rotations do not "
                             "commute); take the Log of the relative rotation from R_b to R_a")
Q_WITHOUT_NORMALISING_NORM_HINT = ("that is q ⊗ [1, δ/2] without normalising: its norm is √(1 + |δ|²/4), not 1; use "
                                   "the exact quaternion exponential of the page")
RETURNED_SHAPE_F_R3_HINT = "returned shape 3×2 for f: R³ → R²: the Jacobian is transposed"
RIGHT_JACOBIAN_FORMULA_HINT = ("Jr must satisfy Exp(w + dw) ≈ Exp(w) Exp(Jr dw): check your closed form against the "
                               "first terms of your series and a numerical Jacobian of dw ↦ Log(Exp(w)ᵀ Exp(w + dw))")
RIGHT_JACOBIAN_INVERSE_FORMULA_HINT = ("Jr(w) times your Jr⁻¹(w) is not I: compare each term with the formula on "
                                       "the page")
RIGHT_UPDATE_IS_A_ROTATION_HINT = "Exp(δ) is a rotation and so is R @ Exp(δ): build the result from it"
ROW_I_OUTPUT_F_HINT = "row i is output f_i, column j is input x_j: shape (len(f(x)), n)"
ROW_I_OUTPUT_F_I_HINT = "row i is output f_i, column j is the direction δ_j: that is the transpose of the Jacobian"
R_ROTATIONS_DO_ADD_HINT = ("that is R + [δ]×: rotations do not add, the sum is not a rotation; compose with Exp(δ) "
                           "instead")
TRANSPOSE_R_P_ROW_HINT = "that is the transpose of the Jacobian: row i is output i, column j is δ_j"
TURNED_CHECK_SIGN_EXP_HINT = "turned by -δ: check the sign (Exp(δ) @ R, not Exp(δ)ᵀ @ R)"
TURNED_CHECK_SIGN_R_HINT = "turned by -δ: check the sign (R @ Exp(δ), not R @ Exp(δ)ᵀ)"
TURNED_TWICE_FAR_QUATERNION_HINT = "turned twice as far: a quaternion holds the half angle, cos(|δ|/2) and sin(|δ|/2)"
USE_BELOW_TINY_ANGLE_HINT = "δ/|δ| is 0/0 at δ = 0: use [1, δ/2] below a tiny angle"

LEFT_JACOBIAN_WORKS_ON_LEFT_HINT = ("this J works on the left, Exp(J dw) Exp(w) ≈ Exp(w + dw): that is the left "
                                    "Jacobian; the right one puts the small turn after Exp(w)")

# ---------------------------------------------------------------- checks/lesson06_point_to_body.py
LEFT_PERTURBATION_POINT_JACOBIAN_HINT = ("that Jacobian belongs to the left perturbation Exp(δ) R, a turn about the "
                                         "world's axes; here δ turns the body about its own axes, R Exp(δ)")
POINT_SEEN_BODY_RT_HINT = ("your J fits the finite differences only at the identity attitude: it stays the same "
                           "for every R, yet the body-frame point (R Exp(δ))ᵀ p_w, and how it moves, change with R")
POINT_TO_BODY_SIGN_HINT = ("the sign is flipped: J is the negative of the finite differences of (R Exp(δ))ᵀ p_w in "
                           "every column; check the sign on a sanity case, R = I and p_w = x: a turn about z makes x "
                           "seem to swing to -y")

# ---------------------------------------------------------------- checks/lesson06_compose.py
COMPOSE_IGNORES_R2_HINT = ("your J1 fits only when R2 = I: it does not change with R2, but how the turn of R1 shows "
                           "up at the end of the product does; compare with finite differences at a generic R2")
COMPOSE_LEFT_HINT = ("those are the left Jacobians (the turn on the left of R1 and of R2); here both the input and "
                     "the output are perturbed on the right")
COMPOSE_SWAPPED_HINT = "J1 and J2 are swapped: return (J1, J2), the first for a turn of R1, the second for a turn of R2"
COMPOSE_TRANSPOSE_HINT = ("your J1 is the transpose of what finite differences give: R1 Exp(d) R2 must equal "
                          "R1 R2 Exp(J1 d); try R1 = I, R2 a quarter turn and d along one axis, and see which axis "
                          "the turn ends on")
COMPOSE_WRONG_FACTOR_HINT = ("your J1 fits the product taken the other way round, R2 R1: try R2 = I, where the "
                             "turn of R1 already stands at the end of the product, and compare with finite "
                             "differences")
INVERSE_LEFT_HINT = ("that is the Jacobian for perturbations on the left of R and of R⁻¹; here both turns sit on "
                     "the right, R Exp(d) and R⁻¹ Exp(J d)")
INVERSE_NOT_MOVED_HINT = ("right at R = I but not at this R: your J does not change with R, while (R Exp(d))⁻¹ "
                          "does; compare with finite differences at a generic R")
INVERSE_AT_IDENTITY_HINT = ("wrong at R = I: compare (Exp(d))⁻¹ with Exp(J d) for a small d along one axis")
INVERSE_SIGN_HINT = ("J is the negative of the finite differences of Log(R (R Exp(d))⁻¹): inverting R Exp(d) must "
                     "undo that small turn; check the sign at R = I first, comparing (Exp(d))⁻¹ with Exp(J d)")
INVERSE_TRANSPOSE_HINT = ("wrong in two ways at once: at R = I your J fails (Exp(d))⁻¹ = Exp(J d), and at this R "
                          "flipping its sign alone still leaves the turn on the wrong axis")

# ---------------------------------------------------------------- checks/lesson07.py
DIVIDED_FIRST_COORDINATE_X_HINT = "divided by the first coordinate: [x, y, z, w] is the point [x/w, y/w, z/w]"
HOMOGENEOUS_ROWS_TRANSPOSE_HINT = "P_h @ T applies the transpose of T; rows need P_h @ T.T"
INVERSE_R_T_RT_HINT = ("the inverse must undo the pose: T_ba (R p + t) = p for every point p; solve "
                       "p_a = R p_b + t for p_b and read off the blocks")
KEPT_T_UNCHANGED_INVERSE_HINT = "kept t unchanged: the inverse must undo the shift as well as the turn"
MULTIPLIED_LAST_COORDINATE_DIVIDE_HINT = "multiplied by the last coordinate: divide by it, [x/w, y/w, z/w]"
ROTATION_BLOCK_INVERSE_RT_HINT = ("the rotation block of the inverse is still R: T_ba T_ab must have the identity "
                                  "as its rotation block, so the inverse must undo the turn")
SERIES_VALUE_AT_ZERO_ONLY_HINT = ("c(θ) = 1/12 is only its value at θ = 0: above θ = 1e-2 use the closed form of "
                                  "c(θ), below it the series with its θ² and θ⁴ terms (both on the page)")
SMALL_ANGLE_SERIES_HINT = ("below θ = 1e-2 use the series c = 1/12 + … of the page, with its θ² and θ⁴ terms: the "
                           "closed form is 0/0 at θ = 0 and cancels catastrophically just above it")
TRANSFORM_ROWS_FORMULA_HINT = "p_a = R p_b + t: for rows P of shape (N, 3), P @ R.T + t"
TRANSPOSES_T_AB_T_HINT = "transposes T_ab: T_ac = T_ab @ T_bc, with no transpose"
INVERSE_TRANSLATION_FRAME_HINT = ("the rotation block is right, but the translation is not: T_ba (T_ab p) must give "
                                  "p back; try p = 0, b's origin, and see where it lands")
EXP_SE3_TRANSLATION_IS_RHO_HINT = (
    "your translation is rho itself although phi ≠ 0: a body that turns while it drives does not end "
    "at rho; compare your pose with expm of the 4×4 twist matrix ξ^"
)
V_SERIES_TINY_ANGLE_HINT = ("below θ = 1e-2 the closed forms of V's two coefficients lose digits as θ shrinks (at "
                            "θ = 1e-4 about half of them, at 1e-8 all): there use the Taylor series of each "
                            "coefficient, with its θ² term")

# ---------------------------------------------------------------- checks/lesson07_adjoint.py
# adjoint_se3: each hint names the twist that fails (a pure shift [rho, 0] or a pure spin [0, phi]) and what its
# image under Ad_T does that the twist of T ξ^ T⁻¹ does not
ADJOINT_DEFINITION_HINT = ("Ad_T ξ must be the twist of T ξ^ T⁻¹ for every ξ: try a pure shift [rho, 0] and a pure "
                           "spin [0, phi] on their own, first at a pure turn (t = 0), then at a pure shift (R = I)")
ADJOINT_SPIN_FROM_SHIFT_HINT = ("a pure shift ξ = [rho, 0] came out with a spin: conjugating by T turns and moves a "
                                "shift, but cannot make it a turn (a formula written for twists with the rotation "
                                "part first does this)")
ADJOINT_SPIN_WITHOUT_SHIFT_HINT = ("a pure spin ξ = [0, phi] at a pose with t ≠ 0 came out with no translation part, "
                                   "but (T ξ^ T⁻¹)∨ has one: a body spinning away from the world's origin carries the "
                                   "point there around")
ADJOINT_COUPLING_WITHOUT_R_HINT = ("for a pure spin ξ = [0, phi], the translation part of your Ad_T ξ stays the same "
                                   "when T turns with the same t, but that of (T ξ^ T⁻¹)∨ turns with it: compare at "
                                   "one t with two turns")
ADJOINT_SPIN_SHIFT_SIGN_HINT = ("for a pure spin ξ = [0, phi], the translation part of Ad_T ξ is the negative of that "
                                "of (T ξ^ T⁻¹)∨: check its sign on a spin about z at a pose shifted along x, not "
                                "turned")
ADJOINT_COUPLING_IDENTITY_HINT = ("for a pure spin ξ = [0, phi], the translation part of Ad_T ξ misses that of (T ξ^ "
                                  "T⁻¹)∨ (a pure shift comes out right): try a pure spin at a pose that both turns "
                                  "and shifts")
# right_jacobian_se3
JR_SE3_NO_COUPLING_HINT = ("in your J a change of phi never reaches the translation part (the phi columns' translation "
                           "rows are zero), yet with rho ≠ 0 a change of phi moves the translation of Exp(ξ)")
JR_SE3_COUPLING_SIGN_HINT = ("the phi columns of J's translation rows are the negative of the finite differences of "
                             "Log(Exp(ξ)⁻¹ Exp(ξ + dξ)) there, and the rest matches: check that part's sign on a "
                             "sanity case")
JR_SE3_DIFFERENCES_HINT = ("close but not exact ({error}): finite differences stop short of rounding (forward near "
                           "1e-8, central near 1e-11 (1 + |ρ|) at best); use an exact route: closed form, series or "
                           "quadrature")

# ---------------------------------------------------------------- checks/lesson07_relative_pose.py
INVERSE_POSE_TRANSPOSE_T1_HINT = ("the inverse of a pose is not its transpose: Tᵀ puts t in the bottom row and "
                                  "never undoes the shift")
SHIFT_IN_WORLD_AXES_HINT = ("the rotation block is right, but the translation is not b's origin as a sees it: "
                            "T_wa T_ab must equal T_wb; compare the translation columns with T_wa turned")
RELATIVE_POSE_CHAIN_HINT = "T_wa T_ab must equal T_wb: poses compose only where the inner letters match"
RELATIVE_POSE_COLLEAGUE_HINT = ("that is what the colleague's function returns: T_wa times it misses T_wb as soon as "
                                "the poses turn; find out what it computes before you write yours")
RELATIVE_POSE_REVERSED_HINT = "that is T_ba, a seen from b: swap the roles of a and b"

# ---------------------------------------------------------------- checks/lesson08.py
ALIGNMENT_SVD_FORMULA_HINT = "R = U diag(1, 1, d) Vᵀ from the SVD of M = Qᵀ P = Σ q_i p_iᵀ, with d = det(U Vᵀ)"
COPIES_NOT_KEPT_HINT = ("copies of one rotation average to it, yet your answer moved away: follow your steps on them; "
                       "each step must shrink toward zero as the estimate arrives, never overshoot")
AVERAGING_LOG_R_I_HINT = ("averaging Log(R_i) about the identity is not bi-invariant: the mean of the turned samples "
                          "A R_i B must be A M B, and at the mean the residuals balance, Σ Log(Mᵀ R_i) = 0")
INVERSE_ROTATION_TRANSPOSE_USE_HINT = ("that is the inverse rotation (the transpose): use M = Qᵀ P = Σ q_i p_iᵀ (Pᵀ Q "
                                       "gives Rᵀ)")
RETURNED_FIRST_ROTATION_RS_HINT = "returned the first rotation Rs[0]: the mean must weigh all of them"
RETURNED_IDENTITY_IF_Q_HINT = ("returned the identity, as if Q were ignored (the SVD of Pᵀ P gives I): M = Qᵀ P = Σ "
                               "q_i p_iᵀ")
RETURNED_R0_UNCHANGED_DO_HINT = "returned R0 unchanged: do iters updates R ← R Exp(δ)"
UNCONSTRAINED_LEAST_SQUARES_MATRIX_HINT = ("that is the unconstrained least-squares matrix, which need not be a "
                                           "rotation: take R = U diag(1, 1, d) Vᵀ from the SVD of M = Qᵀ P")
UPDATED_ADDING_R_R_HINT = "updated by adding R [δ]× to R, which leaves SO(3): use R ← R Exp(δ)"
WEIGHT_RATIOS_HINT = "only the ratios of the weights matter: scaling every weight must not move the mean"

# ---------------------------------------------------------------- checks/lesson09.py
CONVERT_INPUTS_NP_ASARRAY_HINT = "convert the inputs with np.asarray(..., dtype=float)"
COVARIANCE_TAKES_LINEAR_MAP_HINT = "a covariance takes the linear map on both sides: Cov(A ε) = A Σ Aᵀ"
LEFT_TO_RIGHT_WITH_ADJOINT_HINT = ("Σ_R is the covariance of ε_R, defined by Exp(ε_L) R = R Exp(ε_R): find the linear "
                                   "map that takes ε_L to ε_R, then how a covariance changes under a linear map")
MINIMISES_SQUARED_COST_LEAST_HINT = ("that minimises the squared cost (least squares): the Huber cost counts "
                                     "residuals above k linearly, so large residuals must pull less")
RETURNED_R0_UNCHANGED_APPLY_HINT = "returned R0 unchanged: apply one update per sample"
RETURNED_T0_UNCHANGED_DO_HINT = "returned T0 unchanged: do iters updates T ← T Exp(xi)"
RETURNED_T0_UNCHANGED_ITERATE_HINT = ("returned T0 unchanged: iterate from T0 until the gradient of the Huber cost "
                                      "vanishes")
SIGN_ROTATION_BLOCK_PHI_HINT = ("the phi columns of J are the negative of the finite differences of T Exp(ξ) p (the "
                                "rho columns match): check their sign on a sanity case, T = I and p = x, where a turn "
                                "about z moves p to +y")
TURNED_ABOUT_WORLD_S_HINT = ("that turned about the world's axes, but gyroscope rates are body rates, measured in the "
                             "body's own axes: check on which side of R each sample's small turn belongs (lesson 03)")
ROBUST_SLOWER_TAIL_HINT = ("your pose is a stationary point of another cost, one that counts residuals beyond k for "
                           "less than Huber's linear tail does (it grows like log r there, not like r)")

ROBUST_GRADIENT_NOT_ZERO_HINT = ("the Huber cost's gradient is not zero at your pose: compute it there (finite "
                                 "differences will do) and find what stops your iteration short of it")

# ---------------------------------------------------------------- checks/lesson09_filter.py, _update.py
# the derive exercises of lesson 09 have closed forms, held to rounding: finite differences and cancelling closed
# forms come close
PREDICT_FINITE_DIFFERENCES_HINT = ("P_new is right to several digits but not to rounding: it has a closed form, held "
                                   "here to 2e-12 of its largest entry, which finite differences cannot reach; derive "
                                   "how ε and n enter ε_new")
PREDICT_CANCELS_HINT = ("P_new loses digits at this small step: a closed-form coefficient used just above its "
                        "small-step branch subtracts nearly equal numbers there; move the branch, or rewrite the "
                        "coefficient")
PREDICT_NOISE_SHORT_STEP_HINT = ("the noise's part of P_new is right for a short step and wrong for a long one: look "
                                 "again at where the noise enters the step, and what carries it from there to the new "
                                 "attitude's error")
PREDICT_NOISE_OLD_AXES_HINT = ("the noise's part of P_new is written in the axes the body had before the step: right "
                               "when the step does not turn, wrong when it does; ε_new is a turn about the body axes "
                               "of R_new")
UPDATE_FINITE_DIFFERENCES_HINT = ("right to several digits but not to rounding: the checks hold the correction and P_new "
                                  "to 1e-11 relative, which a Jacobian taken by finite differences cannot reach; "
                                  "derive H")
UPDATE_SIGN_HINT = ("the step moves away from the measurement: compare the sign of your H with a central difference "
                    "of h(δ) = (R Exp(δ))ᵀ g_w at δ = 0")
NEES_NOT_DIVIDED_HINT = "the NEES is the full quadratic form, not divided by the dimension"
PREDICT_NO_TURN_R_HINT = "with ω = 0 the step turns nothing: R_new must be R itself, to the last bits"
PREDICT_NO_TURN_P_HINT = ("with ω = 0 the step turns nothing: P grows only by the turn the gyro noise makes over one "
                          "step of dt")
UPDATE_WRONG_SIDE_HINT = "the correction is applied on the wrong side: the error state is R_true = R Exp(ε)"

# ---------------------------------------------------------------- checks/lesson09_compound.py
COMPOUND_FINITE_DIFFERENCES_HINT = ("S is right to several digits but not to rounding: it has a closed form, held here "
                                    "to 1e-11 relative, which finite differences (good to about 1e-10) cannot reach; "
                                    "use them to test a derivation")
COMPOUND_PAIR_REASON = "compound_pose_covariance must return a pair (T, S)"
# which part of S is wrong, told from the student's own S with S2 = 0 (the part from S1) and with S1 = 0
COMPOUND_S1_PART_HINT = ("the part of S that comes from S1 (your S with S2 = 0) disagrees with the linearised "
                         "definition; the part from S2 (your S with S1 = 0) is right")
COMPOUND_S2_PART_HINT = ("the part of S that comes from S2 (your S with S1 = 0) disagrees with the linearised "
                         "definition; the part from S1 (your S with S2 = 0) is right")
COMPOUND_BOTH_PARTS_HINT = ("both parts of S are off, the one that comes from S1 (your S with S2 = 0) and the one from "
                            "S2 (your S with S1 = 0): compare each with simulated chains")
COMPOUND_NOT_A_SUM_HINT = ("your S with S2 = 0 and your S with S1 = 0 are both right, but S is not their sum: ξ1 and ξ2 "
                           "are independent, so their contributions to the covariance add")
COMPOUND_IGNORES_T2_HINT = ("your S ignores T2: it is right when T2 = I and wrong otherwise, yet ξ1 is a twist in "
                            "T1's body frame and ξ one in the frame at the end of the chain")
COMPOUND_INVERTED_T2_HINT = ("S is right when T2 = I and wrong for a turned or shifted T2: the part from S1 is moved "
                             "to the end of the chain, but not as ξ1 moves; compare it with the spread of simulated chains")
COMPOUND_DEPENDS_ON_T1_HINT = ("S changes with T1 and should not, and misses what T2 does; compare it with the spread "
                               "of simulated chains")
COMPOUND_SHIFT_IGNORED_HINT = ("S is right for a T2 that only turns and wrong once T2 also shifts: a spin about T1's "
                               "origin moves T2's origin too; compare with simulated chains")
COMPOUND_PRECISION_HINT = (
    "with T2 = I, S must be S1 + S2 to double precision: your S lost digits (single precision somewhere?)"
)

# ---------------------------------------------------------------- checks/lesson09_capstone.py
HAND_EYE_LISTS_REASON = "hand_eye_rotation answers differently for plain lists"
HAND_EYE_NOT_A_ROTATION_HINT = "X must be a rotation: XᵀX = I and det X = +1"

# ---------------------------------------------------------------- checks/lesson09_pose_graph.py
EDGE_FINITE_DIFFERENCES_HINT = ("your Jacobian agrees with finite differences but not to rounding: the docstring "
                                "asks for the exact Jacobian; finite differences check a derivation, they do not "
                                "replace it")
EDGE_NOT_INVERTED_HINT = "Log's Jacobian at r is the inverse of Exp's right Jacobian there, not the Jacobian itself"
EDGE_SIGN_HINT = ("the sign: your J_i is the negative of a central difference of the residual in δ_i (T_i appears inverted "
                  "in the residual)")
EDGE_SMALL_RESIDUAL_HINT = ("that Jacobian holds only for a small residual: J must be right at a large one too "
                            "(compare it with a central difference of the residual at this edge)")

