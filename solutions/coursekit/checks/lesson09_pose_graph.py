"""Public checks for lesson 09, section 7: the residual of a pose-graph edge and its two Jacobians.

r = Log(T_ij⁻¹ T_i⁻¹ T_j) (twists [ρ, φ]); the Jacobians are those of r with respect to right perturbations
T_i Exp(δ_i) and T_j Exp(δ_j). The checks take central differences of that definition (coursekit.lie's ExpSE3 and
LogSE3) at an edge whose residual is large (|φ| ≈ 1.7 rad, |ρ| ≈ 2.3 m), where a Jacobian that assumes a small
residual is visibly wrong, and at a consistent edge (r = 0). The values the usual slips return at the check's edge
are stored as numbers (``tests/test_public_check_constants_lesson09_pose_graph.py`` recomputes them).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import ExpSE3, LogSE3
from .common import off_by, require_same_with_lists, require_shape

EDGE_T_I = ExpSE3([0.5, -1.0, 2.0, 0.3, -0.2, 0.9])
EDGE_T_IJ = ExpSE3([1.0, 0.5, -0.5, 0.2, 0.4, -0.3])
EDGE_RESIDUAL = np.array([1.0, -2.0, 0.5, 1.2, -0.8, 0.9])
EDGE_T_J = EDGE_T_I @ EDGE_T_IJ @ ExpSE3(EDGE_RESIDUAL)  # so that the edge's residual is EDGE_RESIDUAL

# What the usual slips return at that edge.
EDGE_I_NO_JR = np.array(
    [
        [
            -0.7418969057076252,
            0.18773222777691648,
            -0.643696816797603,
            1.1472280515171418,
            2.365036553046503,
            -0.6324893180453773,
        ],
        [
            0.6035688747501331,
            -0.23116279757301955,
            -0.7630651180935168,
            0.7011478034240134,
            0.6501030023602877,
            0.35765147107207884,
        ],
        [
            0.29205067151833314,
            0.954631013361776,
            -0.058189634760492055,
            1.4652729561984004,
            -0.3076727531684825,
            2.3065963418881745,
        ],
        [-0.0, -0.0, -0.0, -0.7418969057076251, 0.18773222777691645, -0.6436968167976034],
        [-0.0, -0.0, -0.0, 0.6035688747501331, -0.2311627975730195, -0.7630651180935172],
        [-0.0, -0.0, -0.0, 0.29205067151833314, 0.9546310133617759, -0.05818963476049211],
    ]
)
EDGE_I_ADJOINT_INVERTED = np.array(
    [
        [
            -0.5513393308877534,
            0.8833342680593775,
            -0.23720260493807108,
            0.6594705021024173,
            0.7086786776103331,
            0.1636743749301544,
        ],
        [
            0.3061183503439446,
            0.541236795429084,
            0.9118124171951482,
            3.159898446962114,
            1.1235084121766898,
            -1.5099801953722343,
        ],
        [
            -0.7925414742756297,
            -0.44950822650397293,
            0.6094204261443779,
            0.85843909693613,
            1.9998099441051116,
            3.0953556723655162,
        ],
        [0.0, 0.0, 0.0, -0.5513393308877534, 0.8833342680593775, -0.2372026049380712],
        [0.0, 0.0, 0.0, 0.30611835034394447, 0.5412367954290838, 0.9118124171951483],
        [0.0, 0.0, 0.0, -0.7925414742756296, -0.44950822650397293, 0.6094204261443779],
    ]
)
EDGE_I_MEASUREMENT_ADJOINT = np.array(
    [
        [
            -0.485571569488629,
            0.6395279764375152,
            0.70409074767337,
            1.513250921711544,
            -0.1502995525849524,
            1.4976713510382647,
        ],
        [
            -0.34874357755855584,
            -0.8267575665273703,
            0.6425709615258857,
            0.11268894362040109,
            -0.27286732558955584,
            0.019099400095021965,
        ],
        [
            -0.8962164010480522,
            -0.17718089058955622,
            -0.6057854277267647,
            -1.2867395289453276,
            1.0289358355028915,
            1.095760821409235,
        ],
        [0.0, 0.0, 0.0, -0.4855715694886291, 0.6395279764375152, 0.70409074767337],
        [0.0, 0.0, 0.0, -0.34874357755855606, -0.8267575665273703, 0.6425709615258857],
        [0.0, 0.0, 0.0, -0.8962164010480523, -0.1771808905895563, -0.6057854277267646],
    ]
)
EDGE_J_NOT_INVERTED = np.array(
    [
        [
            0.7909452422463014,
            0.21313460091726483,
            0.4681926555980559,
            -0.5227590083822179,
            -0.4210719173190582,
            0.7685343422140168,
        ],
        [
            -0.48995193532216225,
            0.675604686244261,
            0.36491785709111474,
            -0.4111326858929761,
            -0.3697018503783893,
            -0.15966653107334844,
        ],
        [
            -0.15677315439254633,
            -0.572530857894788,
            0.7001145543946944,
            -0.4378420826111917,
            -0.4068166433346569,
            -0.7093207268096362,
        ],
        [0.0, 0.0, 0.0, 0.7909452422463014, 0.21313460091726483, 0.4681926555980559],
        [0.0, 0.0, 0.0, -0.48995193532216225, 0.675604686244261, 0.36491785709111474],
        [0.0, 0.0, 0.0, -0.15677315439254633, -0.572530857894788, 0.7001145543946944],
    ]
)
NO_JR_HINT = (
    "that Jacobian holds only for a small residual: at a large one, Log's own Jacobian at r sits "
    "between the perturbation and the residual"
)
ADJOINT_INVERTED_HINT = "the adjoint is of the wrong pose, or inverted: move δ_i across T_i⁻¹ T_j the other way"
MEASUREMENT_ADJOINT_HINT = (
    "the adjoint of T_ij⁻¹ alone moves δ_i across the measurement, but δ_i must cross the "
    "whole of T_i⁻¹ T_j (which is T_ij Exp(r))"
)
NOT_INVERTED_HINT = hints.EDGE_NOT_INVERTED_HINT
SIGN_HINT = hints.EDGE_SIGN_HINT
REVERSED_HINT = "that is the residual of the reversed edge, -r: the residual is Log(T_ij⁻¹ T_i⁻¹ T_j)"


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _residual(T_i, T_j, T_ij):
    return LogSE3(np.linalg.inv(T_ij) @ np.linalg.inv(T_i) @ T_j)


def _edge(pose_graph_edge, T_i, T_j, T_ij):
    value = pose_graph_edge(T_i, T_j, T_ij)
    if not isinstance(value, (tuple, list)) or len(value) != 3:
        raise Mismatch(
            f"pose_graph_edge returned {type(value).__name__}, not a triple (r, J_i, J_j)",
            "return all three: r, J_i, J_j",
        )
    return (
        require_shape(value[0], (6,), "pose_graph_edge's r"),
        require_shape(value[1], (6, 6), "J_i"),
        require_shape(value[2], (6, 6), "J_j"),
    )


@public_check("pose_graph_edge", "the residual is Log(T_ij⁻¹ T_i⁻¹ T_j), twist [ρ, φ]")
def _(pose_graph_edge):
    r, _, _ = _edge(pose_graph_edge, EDGE_T_I, EDGE_T_J, EDGE_T_IJ)
    if not close(r, EDGE_RESIDUAL, 1e-9):
        hint = REVERSED_HINT if close(r, -EDGE_RESIDUAL, 1e-9) else "r = Log(T_ij⁻¹ T_i⁻¹ T_j), with LogSE3"
        raise Mismatch(f"the residual is off ({off_by(r, EDGE_RESIDUAL)})", hint)


@public_check("pose_graph_edge", "J_j matches central differences at a large residual (|φ| ≈ 1.7 rad)")
def _(pose_graph_edge):
    _, _, J_j = _edge(pose_graph_edge, EDGE_T_I, EDGE_T_J, EDGE_T_IJ)
    numeric = _central(lambda d: _residual(EDGE_T_I, EDGE_T_J @ ExpSE3(d), EDGE_T_IJ), 6)
    if not close(J_j, numeric, 1e-7):
        hint = None
        if close(J_j, np.eye(6), 1e-12):
            hint = NO_JR_HINT
        elif close(J_j, EDGE_J_NOT_INVERTED, 1e-9):
            hint = NOT_INVERTED_HINT
        raise Mismatch(
            f"J_j disagrees with finite differences ({off_by(J_j, numeric)})",
            hint or "perturb T_j on the right inside the residual and use Log's Jacobian at r",
        )


@public_check("pose_graph_edge", "J_i matches central differences at a large residual (|φ| ≈ 1.7 rad)")
def _(pose_graph_edge):
    _, J_i, _ = _edge(pose_graph_edge, EDGE_T_I, EDGE_T_J, EDGE_T_IJ)
    numeric = _central(lambda d: _residual(EDGE_T_I @ ExpSE3(d), EDGE_T_J, EDGE_T_IJ), 6)
    if not close(J_i, numeric, 1e-7):
        slips = [
            (EDGE_I_NO_JR, NO_JR_HINT),
            (EDGE_I_ADJOINT_INVERTED, ADJOINT_INVERTED_HINT),
            (EDGE_I_MEASUREMENT_ADJOINT, MEASUREMENT_ADJOINT_HINT),
            (-numeric, SIGN_HINT),
            (EDGE_J_NOT_INVERTED @ EDGE_I_NO_JR, NOT_INVERTED_HINT),
        ]
        hint = next((h for value, h in slips if close(J_i, value, 1e-7)), None)
        raise Mismatch(
            f"J_i disagrees with finite differences ({off_by(J_i, numeric)})",
            hint or "move δ_i out of the middle of the product with an adjoint, then use Log's Jacobian at r",
        )


@public_check("pose_graph_edge", "a consistent edge: r = 0, and the Jacobians match central differences there")
def _(pose_graph_edge):
    T_i, T_ij = ExpSE3([2.0, 1.0, -1.0, -0.4, 1.1, 0.2]), ExpSE3([0.3, -0.6, 0.2, 0.9, 0.1, -0.5])
    T_j = T_i @ T_ij
    r, J_i, J_j = _edge(pose_graph_edge, T_i, T_j, T_ij)
    if np.max(np.abs(r)) > 1e-12:
        raise Mismatch(
            f"T_j = T_i T_ij gave a residual of size {np.max(np.abs(r)):.2g}",
            "a measurement that agrees with the poses leaves no residual",
        )
    numeric_i = _central(lambda d: _residual(T_i @ ExpSE3(d), T_j, T_ij), 6)
    numeric_j = _central(lambda d: _residual(T_i, T_j @ ExpSE3(d), T_ij), 6)
    if not (close(J_i, numeric_i, 1e-7) and close(J_j, numeric_j, 1e-7)):
        raise Mismatch(
            f"at r = 0 the Jacobians disagree with finite differences ({off_by(np.hstack([J_i, J_j]), np.hstack([numeric_i, numeric_j]))})",
            SIGN_HINT
            if close(J_i, -numeric_i, 1e-7)
            else "at r = 0, Log's Jacobian is I: what is left is how δ_i crosses T_i⁻¹ T_j",
        )


@public_check("pose_graph_edge", "accepts plain lists")
def _(pose_graph_edge):
    require_same_with_lists(
        lambda *a: np.vstack([np.reshape(pose_graph_edge(*a)[0], (1, 6)), *pose_graph_edge(*a)[1:]]),
        (EDGE_T_I, EDGE_T_J, EDGE_T_IJ),
        (13, 6),
        "pose_graph_edge(T_i, T_j, T_ij)",
    )
