"""The shared diagnosis helpers: each hint fires for the mistake it names and stays quiet otherwise.

The mutation corpus (``test_mutations.py``) checks every hint end to end; these
tests pin the shared helpers of ``coursekit.diagnose`` and the public-check
helpers directly, one answer that triggers each hint and one that must not.
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checking import Mismatch
from coursekit.checks.common import require_same_with_lists
from coursekit.diagnose import jacobian_error_allowed, quaternion_hint, rotation_hint, rotation_vector_hint

AXIS = np.array([2.0, -1.0, 2.0]) / 3.0


def _rot_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


@pytest.mark.parametrize("angle, words", [(np.pi - 1e-6, "near θ = π"), (1e-8, "tiny angle"), (1.0, "clip")])
def test_nan_hint_names_the_angle_where_it_happened(angle, words):
    others = {"near θ = π", "tiny angle"} - {words}
    hint = rotation_vector_hint([np.nan, 0.0, 0.0], angle * AXIS)
    assert words in hint and not any(other in hint for other in others), hint


def test_rotation_vector_hint_is_quiet_for_a_right_or_unrelated_answer():
    w = 0.7 * AXIS
    assert rotation_vector_hint(w, w) is None
    assert rotation_vector_hint(w + [0.1, 0.0, 0.0], w) is None
    assert "opposite" in rotation_vector_hint(-w, w)
    assert "degrees" in rotation_vector_hint(np.rad2deg(w), w)


def test_degrees_hint_fires_for_degrees_only():
    angle = 0.8
    truth = _rot_z(angle)
    degrees = _rot_z(np.deg2rad(angle))
    assert "degrees" in rotation_hint(degrees, truth, degrees_version=degrees)
    assert rotation_hint(_rot_z(angle + 0.1), truth, degrees_version=degrees) is None
    assert "transpose" in rotation_hint(truth.T, truth, degrees_version=degrees)


def test_quaternion_hint_tells_layout_conjugate_and_sign_apart():
    q = Rotation.from_rotvec(0.9 * AXIS).as_quat(scalar_first=True)
    assert "scalar-last" in quaternion_hint(np.roll(q, -1), q)
    assert "conjugate" in quaternion_hint(q * [1, -1, -1, -1], q)
    assert "sign matters" in quaternion_hint(-q, q)
    assert quaternion_hint(q, q) is None
    assert quaternion_hint(q + 0.1, q) is None


def _wavy(x):
    return np.array([np.sin(x[0]) * x[1], np.exp(0.5 * x[2]) + x[0] * x[1]])


def _forward(f, x, step):
    f0 = f(x)
    return np.column_stack([(f(x + step(xj) * e) - f0) / step(xj) for xj, e in zip(x, np.eye(x.size))])


def _central(f, x, h):
    return np.column_stack([(f(x + h * e) - f(x - h * e)) / (2 * h) for e in np.eye(x.size)])


@pytest.mark.parametrize("x", [np.array([1.2, -3.0, 2.5]), np.array([0.0, 0.5, -1.0]), np.array([40.0, 7.0, 3.0])])
def test_numerical_jacobian_rule_accepts_good_schemes_and_rejects_bad_steps(x):
    exact = np.array([[np.cos(x[0]) * x[1], np.sin(x[0]), 0.0], [x[1], x[0], 0.5 * np.exp(0.5 * x[2])]])

    def error(J):
        return np.max(np.abs(J - exact))

    lecture = _forward(_wavy, x, lambda xj: max(abs(1e-4 * xj), 1e-6))
    allowed = jacobian_error_allowed(error(lecture), exact)
    eps = np.finfo(float).eps
    assert error(lecture) <= allowed  # the lecture's rule
    assert error(_forward(_wavy, x, lambda xj: np.sqrt(eps) * max(1.0, abs(xj)))) <= allowed  # the V-curve's bottom
    assert error(_central(_wavy, x, 1e-5)) <= allowed  # central differences
    assert error(_forward(_wavy, x, lambda xj: 1e-2)) > allowed  # far too coarse
    assert error(_forward(_wavy, x, lambda xj: 1e-14)) > allowed  # drowned in rounding


def test_list_check_blames_lists_only_when_they_are_the_difference():
    R = _rot_z(0.3)
    require_same_with_lists(lambda R, p: np.asarray(R) @ np.asarray(p), (R, [1.0, 2.0, 3.0]), (3,), "f")
    require_same_with_lists(
        lambda R, p: -np.asarray(R) @ np.asarray(p), (R, [1.0, 2.0, 3.0]), (3,), "f"
    )  # wrong, not lists
    with pytest.raises(Mismatch, match="lists"):
        require_same_with_lists(lambda R, p: R.T @ p, (R, [1.0, 2.0, 3.0]), (3,), "f")


def test_reflection_hint_needs_an_orthogonal_matrix():
    truth = _rot_z(0.8)
    mirror = truth @ np.diag([1.0, 1.0, -1.0])
    assert "reflection" in rotation_hint(mirror, truth)
    sheared = truth.copy()
    sheared[0, 1] = -sheared[0, 1]  # both sines positive: det < 0 but not orthogonal, so not a reflection
    assert np.linalg.det(sheared) < 0 and "reflection" not in (rotation_hint(sheared, truth) or "")


def test_arccos_hint_only_where_arccos_rounds_to_zero():
    assert "arccos rounds tiny angles" in rotation_vector_hint([0.0, 0.0, 0.0], 1e-9 * AXIS)
    quiet = rotation_vector_hint([0.0, 0.0, 0.0], 0.4 * AXIS)
    assert quiet and "arccos" not in quiet


def _sentences(folder):
    """``{text: [file:line]}`` of every whole string literal of 50 characters or more in ``folder``'s
    modules: docstrings and the parts of f-strings (a hint around a measured number) left out."""
    import ast
    from collections import defaultdict

    found = defaultdict(list)
    for path in sorted(folder.glob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        skipped = {id(value) for node in ast.walk(tree) if isinstance(node, ast.JoinedStr) for value in node.values}
        skipped |= {
            id(node.body[0].value)
            for node in ast.walk(tree)
            if isinstance(node, (ast.Module, ast.FunctionDef, ast.ClassDef))
            and node.body
            and isinstance(node.body[0], ast.Expr)
        }
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Constant)
                and isinstance(node.value, str)
                and len(node.value) >= 50
                and id(node) not in skipped
            ):
                found[node.value].append(f"{path.name}:{node.lineno}")
    return found


def test_a_hint_both_suites_give_is_written_once_in_the_catalogue():
    """A sentence in both the public checks and the hidden suite lives in ``coursekit/hints.py``: two
    copies drift apart (one gets fixed, the student reads the other). 140 did before the catalogue."""
    from autograder.lessons.paths import PACKAGE, SOLUTIONS

    public = _sentences(SOLUTIONS / "coursekit" / "checks")
    hidden = _sentences(PACKAGE / "hidden")
    twice = sorted(set(public) & set(hidden))
    assert not twice, "\n".join(f"{text[:70]!r}: {public[text][0]} and {hidden[text][0]}" for text in twice)
