"""Public checks for lesson 09, section 7: the residual of a pose-graph edge and its two Jacobians.

r = Log(T_ij⁻¹ T_i⁻¹ T_j) (twists [ρ, φ]); the Jacobians are those of r with respect to right perturbations
T_i Exp(δ_i) and T_j Exp(δ_j). The checks compare them with numbers stored here, the Jacobians at two fixed edges:
one whose residual is large (|φ| ≈ 1.7 rad, |ρ| ≈ 2.3 m), where a Jacobian that assumes a small residual is
visibly wrong, and a consistent one (r = 0). The values the usual slips return at the large edge are stored too
(all recomputed by ``tests/test_public_check_constants_lesson09_pose_graph.py``, by central differences of the
residual with coursekit.lie's ExpSE3 and LogSE3, and with its JrSE3 and AdSE3). Nothing here computes a Jacobian
for other edges.
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import ExpSE3
from .common import off_by, require_same_with_lists, require_shape

EDGE_T_I = ExpSE3([0.5, -1.0, 2.0, 0.3, -0.2, 0.9])
EDGE_T_IJ = ExpSE3([1.0, 0.5, -0.5, 0.2, 0.4, -0.3])
EDGE_RESIDUAL = np.array([1.0, -2.0, 0.5, 1.2, -0.8, 0.9])
EDGE_T_J = EDGE_T_I @ EDGE_T_IJ @ ExpSE3(EDGE_RESIDUAL)  # so that the edge's residual is EDGE_RESIDUAL

# The answer's J_i and J_j of pose_graph_edge(EDGE_T_I, EDGE_T_J, EDGE_T_IJ): the derivatives of r in δ_i and δ_j.
EDGE_J_I = np.array(
    [
        [-1.0591783397591608, -0.004142993549259889, -0.13654172582268445,
         -0.11926250050245622, 1.0474289518612723, -0.7441196528957421],
        [0.019453306872388602, -0.7499133471732153, -0.8095054897146117,
         -0.3522485400633821, 0.9873287367757575, -1.1684067734461785],
        [0.19587874547349607, 0.7493530421520589, -0.7756767530569124,
         1.3255038994784725, 0.9233525987040672, 0.8308380431514338],
        [0.0, 0.0, 0.0, -1.059178339759161, -0.004142993549260034, -0.13654172582268428],
        [0.0, 0.0, 0.0, 0.01945330687238867, -0.7499133471732152, -0.8095054897146119],
        [0.0, 0.0, 0.0, 0.19587874547349626, 0.749353042152059, -0.7756767530569124],
    ]
)
EDGE_J_J = np.array(
    [
        [0.8729148337233061, -0.5341391445693976, -0.3053434623594282,
         -0.3744521485175597, -0.5404662771915515, -0.8572798169050632],
        [0.3658608554306027, 0.8027988799154749, -0.6631043584270483,
         -0.040466277191549896, -0.3126715796765836, -0.7003207194417062],
        [0.4946565376405724, 0.5368956415729522, 0.817698520099639,
         1.1427201830949385, 0.2996792805582957, -0.5124836775686414],
        [0.0, 0.0, 0.0, 0.8729148337233061, -0.5341391445693976, -0.30534346235942816],
        [0.0, 0.0, 0.0, 0.3658608554306027, 0.8027988799154749, -0.6631043584270483],
        [0.0, 0.0, 0.0, 0.4946565376405724, 0.5368956415729522, 0.817698520099639],
    ]
)

# A consistent edge, T_j = T_i T_ij (r = 0), and the answer's J_i of pose_graph_edge(CONSISTENT_T_I,
# CONSISTENT_T_I @ CONSISTENT_T_IJ, CONSISTENT_T_IJ); its J_j is the identity.
CONSISTENT_T_I = ExpSE3([2.0, 1.0, -1.0, -0.4, 1.1, 0.2])
CONSISTENT_T_IJ = ExpSE3([0.3, -0.6, 0.2, 0.9, 0.1, -0.5])
CONSISTENT_J_I = np.array(
    [
        [-0.8811860369779735, 0.37435609633214884, 0.2887363527060775,
         -0.1484506882721521, 0.05118720292817765, -0.5194181950071699],
        [-0.45661191688585956, -0.5156046122948148, -0.7250223728535102,
         0.4164647339728493, 0.14632900740256577, -0.36634824188750037],
        [0.12254275006247589, 0.7707200509389052, -0.6252790396997624,
         0.4843214860059338, 0.07302997967986262, 0.18493464377754817],
        [0.0, 0.0, 0.0, -0.8811860369779735, 0.3743560963321489, 0.2887363527060775],
        [0.0, 0.0, 0.0, -0.45661191688585956, -0.5156046122948148, -0.7250223728535102],
        [0.0, 0.0, 0.0, 0.12254275006247589, 0.7707200509389052, -0.6252790396997624],
    ]
)

# What the usual slips return at the large edge.
EDGE_I_SMALL_RESIDUAL = np.array(
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

EDGE_I_NOT_INVERTED = np.array(  # J_i with Log's Jacobian taken the wrong way round, as a student might
    [
        [
            -0.3214224370933829,
            0.5461683510309201,
            -0.6990084737406962,
            2.101001821077228,
            2.5979878970367385,
            1.2689778226647146,
        ],
        [
            0.8778422902258313,
            0.10020746606139194,
            -0.22138430536452286,
            0.4815632249302828,
            -0.9759610464999972,
            1.9492808940371824,
        ],
        [
            -0.024783361766702556,
            0.7712675278092482,
            0.49705329692273825,
            0.31670983699016014,
            -1.6236802032634026,
            2.1428127708653304,
        ],
        [
            0.0,
            0.0,
            0.0,
            -0.3214224370933828,
            0.5461683510309201,
            -0.6990084737406965,
        ],
        [
            0.0,
            0.0,
            0.0,
            0.8778422902258312,
            0.10020746606139193,
            -0.22138430536452292,
        ],
        [
            0.0,
            0.0,
            0.0,
            -0.024783361766702584,
            0.7712675278092481,
            0.4970532969227384,
        ],
    ]
)
SMALL_RESIDUAL_HINT = hints.EDGE_SMALL_RESIDUAL_HINT
ADJOINT_INVERTED_HINT = (
    "the adjoint is of the wrong pose, or inverted: J_i disagrees with a central difference of the residual in δ_i "
    "even for a consistent edge (r = 0), while J_j agrees"
)
MEASUREMENT_ADJOINT_HINT = (
    "J_i is right at r = 0 but not at this residual, while J_j is right at both: compare J_i with a central "
    "difference of the residual in δ_i as the residual grows"
)
NOT_INVERTED_HINT = hints.EDGE_NOT_INVERTED_HINT
SIGN_HINT = hints.EDGE_SIGN_HINT
REVERSED_HINT = "that is the residual of the reversed edge, -r: the residual is Log(T_ij⁻¹ T_i⁻¹ T_j)"


EXACT = 1e-11  # relative to 1 + the largest translation, as the hidden checks hold it: derived Jacobians, not differences
FINITE_DIFFERENCES_HINT = hints.EDGE_FINITE_DIFFERENCES_HINT


def _tolerance(*poses):
    return EXACT * (1.0 + max(np.linalg.norm(T[:3, 3]) for T in poses))


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


@public_check("pose_graph_edge", "J_j, the derivative of r in δ_j, at a large residual (|φ| ≈ 1.7 rad)")
def _(pose_graph_edge):
    _, _, J_j = _edge(pose_graph_edge, EDGE_T_I, EDGE_T_J, EDGE_T_IJ)
    expected = EDGE_J_J
    if not close(J_j, expected, _tolerance(EDGE_T_I, EDGE_T_J, EDGE_T_IJ)):
        hint = None
        if close(J_j, np.eye(6), 1e-12):
            hint = SMALL_RESIDUAL_HINT
        elif close(J_j, EDGE_J_NOT_INVERTED, 1e-9):
            hint = NOT_INVERTED_HINT
        elif close(J_j, expected, 1e-7):
            hint = FINITE_DIFFERENCES_HINT
        raise Mismatch(
            f"J_j disagrees with the derivative of the residual ({off_by(J_j, expected)})",
            hint or "compare J_j column by column with a central difference of the residual in δ_j, here and at r = 0",
        )


@public_check("pose_graph_edge", "J_i, the derivative of r in δ_i, at a large residual (|φ| ≈ 1.7 rad)")
def _(pose_graph_edge):
    _, J_i, _ = _edge(pose_graph_edge, EDGE_T_I, EDGE_T_J, EDGE_T_IJ)
    expected = EDGE_J_I
    if not close(J_i, expected, _tolerance(EDGE_T_I, EDGE_T_J, EDGE_T_IJ)):
        slips = [
            (EDGE_I_SMALL_RESIDUAL, SMALL_RESIDUAL_HINT),
            (EDGE_I_ADJOINT_INVERTED, ADJOINT_INVERTED_HINT),
            (EDGE_I_MEASUREMENT_ADJOINT, MEASUREMENT_ADJOINT_HINT),
            (-expected, SIGN_HINT),
            (EDGE_I_NOT_INVERTED, NOT_INVERTED_HINT),
        ]
        hint = next((h for value, h in slips if close(J_i, value, 1e-7)), None)
        if hint is None and close(J_i, expected, 1e-7):
            hint = FINITE_DIFFERENCES_HINT
        raise Mismatch(
            f"J_i disagrees with the derivative of the residual ({off_by(J_i, expected)})",
            hint or "compare J_i column by column with a central difference of the residual in δ_i, here and at r = 0",
        )


@public_check("pose_graph_edge", "a consistent edge: r = 0, and both Jacobians there")
def _(pose_graph_edge):
    T_i, T_ij = CONSISTENT_T_I, CONSISTENT_T_IJ
    T_j = T_i @ T_ij
    r, J_i, J_j = _edge(pose_graph_edge, T_i, T_j, T_ij)
    if np.max(np.abs(r)) > 1e-12:
        raise Mismatch(
            f"T_j = T_i T_ij gave a residual of size {np.max(np.abs(r)):.2g}",
            "a measurement that agrees with the poses leaves no residual",
        )
    expected_i, expected_j = CONSISTENT_J_I, np.eye(6)
    tolerance = _tolerance(T_i, T_j, T_ij)
    if not (close(J_i, expected_i, tolerance) and close(J_j, expected_j, tolerance)):
        off = off_by(np.hstack([J_i, J_j]), np.hstack([expected_i, expected_j]))
        raise Mismatch(
            f"at r = 0 the Jacobians disagree with the derivatives of the residual ({off})",
            SIGN_HINT
            if close(J_i, -expected_i, 1e-7)
            else FINITE_DIFFERENCES_HINT
            if close(J_i, expected_i, 1e-7) and close(J_j, expected_j, 1e-7)
            else "at r = 0 both Jacobians must agree with central differences of the residual (in δ_i and in δ_j)",
        )


@public_check("pose_graph_edge", "accepts plain lists")
def _(pose_graph_edge):
    require_same_with_lists(
        lambda *a: np.vstack([np.reshape(pose_graph_edge(*a)[0], (1, 6)), *pose_graph_edge(*a)[1:]]),
        (EDGE_T_I, EDGE_T_J, EDGE_T_IJ),
        (13, 6),
        "pose_graph_edge(T_i, T_j, T_ij)",
    )
