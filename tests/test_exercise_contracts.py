"""The contract is the test (issue #43): each exercise's docstring, as ``coursekit/exercise_contracts.json``,
and the checks generated from it in both suites.

- the file equals what the masters' docstrings say (``python -m autograder contracts --check``), every catalog
  exercise has a contract, and ``release`` ships it with coursekit;
- the parser is strict: a docstring it cannot read exactly is an error, not a guess;
- wrong answers (a list, float32, int64 for integer input, an error on tuples or lists, a write into the
  argument) lose points in the real sandbox and fail the public line, each with its own hint; right variants
  (``np.asarray(x, dtype=float)``, ``np.array(x, float)``, a comprehension then ``np.array``) pass both.
"""

import pytest

from autograder.authoring.contracts_file import (
    CONTRACTS_FILE,
    ContractError,
    build_contracts,
    contract_of,
    parse_parameter,
    parse_returns,
    parse_shape,
    write_contracts,
)
from public_runner import run_public_checks
from support import THIS_COURSE, build_submission, grade, points_by_exercise

DESCRIPTION = "keeps its docstring's contract"


def test_the_contract_file_matches_the_docstrings():
    in_sync, problems = write_contracts(THIS_COURSE.solutions, check=True)
    assert not problems, problems
    assert in_sync, "run: python -m autograder contracts"


def test_every_catalog_exercise_has_a_contract():
    contracts, _ = build_contracts(THIS_COURSE.solutions)
    missing = [e.name for e in THIS_COURSE.catalog.exercises if e.name not in contracts["exercises"]]
    assert not missing, missing


def test_release_ships_the_contract_file():
    from autograder.authoring.release import planned_files

    planned = planned_files(THIS_COURSE.solutions)
    assert any(path.replace("\\", "/").endswith(CONTRACTS_FILE.as_posix()) for _, path in planned), sorted(planned)[:5]


def test_the_parser_reads_the_course_forms():
    assert parse_shape("(3,) or (N, 3)") == [[3], ["N", 3]]
    assert parse_parameter("p, q : array_like, shape (4,)") == [
        {"name": n, "kind": "array_like", "optional": False, "shapes": [[4]]} for n in "pq"
    ]
    assert parse_parameter("boxplus : callable, optional")[0]["optional"]
    assert parse_returns(["ndarray, same shape as ``p_b``"]) == {
        "type": "ndarray",
        "dtype": "float64",
        "shape_like": "p_b",
    }
    assert parse_returns(["tuple of three floats"])["items"] == [{"type": "float"}] * 3
    pair = parse_returns(["J1, J2 : ndarray, shape (3, 3) each"])
    assert [i["name"] for i in pair["items"]] == ["J1", "J2"] and pair["type"] == "tuple"


@pytest.mark.parametrize(
    "line",
    ["x : array_like, shape 3 by 3", "x : matrix", "x : float, between 0 and 1", "x: float", "x : array_like, (3,)"],
)
def test_the_parser_is_strict_on_parameters(line):
    with pytest.raises(ContractError):
        parse_parameter(line)


@pytest.mark.parametrize("lines", [["an array"], ["ndarray"], ["ndarray, shape (3, 3)", "float"], ["list of floats"]])
def test_the_parser_is_strict_on_returns(lines):
    with pytest.raises(ContractError):
        parse_returns(lines)


def test_a_docstring_that_disagrees_with_the_signature_is_an_error():
    source = 'def f(a, b):\n    """F.\n\n    Parameters\n    ----------\n    a : float\n\n    Returns\n    -------\n    float\n    """\n'
    with pytest.raises(ContractError, match="differ from the signature"):
        contract_of("f", source)


# rotate_point(R_wb, p_b): p_b of shape (3,) or (N, 3), returns an ndarray of p_b's shape (lesson 01)
WRONG = {
    "returns float32": (
        "def rotate_point(R_wb, p_b):\n"
        "    R, p = np.asarray(R_wb, dtype=float), np.asarray(p_b, dtype=float)\n"
        "    return (p @ R.T).astype(np.float32)\n",
        "float32",
    ),
    "int64 for integer input": (
        "def rotate_point(R_wb, p_b):\n    return np.asarray(p_b) @ np.asarray(R_wb).T\n",
        "int64",
    ),
    "fails on tuples": (
        "def rotate_point(R_wb, p_b):\n"
        "    if isinstance(p_b, tuple) or isinstance(R_wb, tuple):\n"
        "        raise TypeError('expected an array or a list')\n"
        "    return np.asarray(p_b, dtype=float) @ np.asarray(R_wb, dtype=float).T\n",
        "with tuples as input",
    ),
    "fails on lists": (
        "def rotate_point(R_wb, p_b):\n    return (R_wb @ p_b.T).T + 0.0\n",
        "with nested lists as input",
    ),
    "writes into its argument": (  # harmless on the values (times 1), caught only because the wire keeps read-only
        "def rotate_point(R_wb, p_b):\n"
        "    p = np.asarray(p_b, dtype=float)\n"
        "    p *= 1.0\n"
        "    return p @ np.asarray(R_wb, dtype=float).T\n",
        "writes into an argument",
    ),
    "returns nested lists": (
        "def rotate_point(R_wb, p_b):\n"
        "    return (np.asarray(p_b, dtype=float) @ np.asarray(R_wb, dtype=float).T).tolist()\n",
        "returned a list",
    ),
}
RIGHT = {
    "asarray": "def rotate_point(R_wb, p_b):\n"
    "    return np.asarray(p_b, dtype=float) @ np.asarray(R_wb, dtype=float).T\n",
    "array float": "def rotate_point(R_wb, p_b):\n    R = np.array(R_wb, float)\n    p = np.array(p_b, float)\n"
    "    return (R @ p.T).T\n",
    "comprehension": "def rotate_point(R_wb, p_b):\n"
    "    R = [[float(x) for x in row] for row in R_wb]\n"
    "    p = np.array(p_b, dtype=float)\n"
    "    rows = [[sum(R[i][k] * q[k] for k in range(3)) for i in range(3)] for q in np.atleast_2d(p)]\n"
    "    return np.array(rows).reshape(p.shape)\n",
}


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """Each answer of WRONG and RIGHT graded in the real sandbox: ``{label: StudentResult}``."""
    results = {}
    for label, source in [(k, v[0]) for k, v in WRONG.items()] + list(RIGHT.items()):
        folder = build_submission(
            tmp_path_factory.mktemp(label.replace(" ", "_")), {"rotate_point": source}, lessons=("01",)
        )
        results[label] = grade(folder, lessons=("01",))
    return results


@pytest.mark.parametrize("label", sorted(WRONG))
def test_a_wrong_form_loses_points_and_fails_the_public_line(label, graded):
    source, told = WRONG[label]
    earned, available = points_by_exercise(graded[label])["rotate_point"]
    assert earned < available, f"{label}: kept full marks"
    failed = [c for e in graded[label].exercises if e.name == "rotate_point" for c in e.checks if not c.passed]
    contract = [c for c in failed if c.description.startswith(DESCRIPTION)]
    assert contract, [(c.description, c.reason) for c in failed]
    assert told in contract[0].reason, contract[0].reason
    assert contract[0].hint, contract[0]
    ok, out = run_public_checks(THIS_COURSE, "rotate_point", source)
    line = next(line for line in out.splitlines() if DESCRIPTION in line)
    assert not ok and "✗" in line and told in line, out
    assert "hint:" in out.split(line, 1)[1].splitlines()[1], out


def test_the_hints_tell_the_failures_apart(graded):
    hints = {
        label: next(
            c.hint
            for e in graded[label].exercises
            for c in e.checks
            if c.description.startswith(DESCRIPTION) and not c.passed
        )
        for label in WRONG
    }
    assert hints["returns float32"] != hints["int64 for integer input"] != hints["fails on tuples"]
    for hint in hints.values():
        assert "R_wb" not in hint and "@" not in hint  # names what failed, never the formula


@pytest.mark.parametrize("label", sorted(RIGHT))
def test_a_right_variant_keeps_full_marks_and_passes_the_public_line(label, graded):
    earned, available = points_by_exercise(graded[label])["rotate_point"]
    failed = [(c.description, c.reason) for e in graded[label].exercises for c in e.checks if not c.passed]
    assert earned == available, failed
    ok, out = run_public_checks(THIS_COURSE, "rotate_point", RIGHT[label])
    assert ok and f"✓ {DESCRIPTION}" in out, out


def test_a_write_into_a_read_only_argument_fails_the_public_line():
    import numpy as np

    from coursekit.exercise_contracts import contract_problem

    def rotate_point(R_wb, p_b):
        p = np.asarray(p_b, dtype=float)
        p *= 1.0  # in place: a write into the caller's float array
        return p @ np.asarray(R_wb, dtype=float).T

    reason, hint = contract_problem("rotate_point", rotate_point)
    assert "writes into an argument" in reason and "never write into an argument" in hint


def test_a_bool_return_may_be_a_numpy_bool():
    import numpy as np

    from coursekit.exercise_contracts import contract_problem

    def is_rotation_matrix(M, tol=1e-9):
        M = np.asarray(M, dtype=float)
        return M.shape == (3, 3) and np.all(np.abs(M.T @ M - np.eye(3)) <= tol) and np.linalg.det(M) > 0

    assert contract_problem("is_rotation_matrix", is_rotation_matrix) is None
    reason, _ = contract_problem("is_rotation_matrix", lambda M, tol=1e-9: int(is_rotation_matrix(M, tol)))
    assert "returned an int" in reason and "bool" in reason


def test_lists_for_arrays_is_one_switch(monkeypatch):
    """An ndarray means a float64 ndarray (LISTS_FOR_ARRAYS is False): a nested list of the right numbers breaks the
    contract; the one switch would accept it."""
    import numpy as np

    from coursekit import exercise_contracts

    def rotate_point(R_wb, p_b):
        return (np.asarray(p_b, dtype=float) @ np.asarray(R_wb, dtype=float).T).tolist()

    assert exercise_contracts.LISTS_FOR_ARRAYS is False
    reason, hint = exercise_contracts.contract_problem("rotate_point", rotate_point)
    assert "returned a list" in reason and "numpy array" in hint
    monkeypatch.setattr(exercise_contracts, "LISTS_FOR_ARRAYS", True)
    assert exercise_contracts.contract_problem("rotate_point", rotate_point) is None


def test_a_branch_for_a_special_rotation_keeps_the_contract_too():
    """The identity and half turns are sampled as well: a small-angle branch that returns a list is caught there,
    and a correct answer with such branches keeps the contract."""
    import numpy as np

    from coursekit.exercise_contracts import contract_problem, sample_sets

    regimes = [regime for regime, _ in sample_sets("log_so3")]
    assert regimes[0] == "quarter turns" and {"the identity", "half turns", "a 53° turn"} <= set(regimes)

    def log_so3(R, lists_at_zero=False):
        R = np.array(R, dtype=float)
        theta = np.arccos(np.clip((np.trace(R) - 1) / 2, -1.0, 1.0))
        if theta < 1e-8:
            return [0.0, 0.0, 0.0] if lists_at_zero else np.zeros(3)
        if np.pi - theta < 1e-6:
            B = (R + np.eye(3)) / 2
            k = int(np.argmax(np.diag(B)))
            return theta * B[:, k] / np.linalg.norm(B[:, k])
        return theta / (2 * np.sin(theta)) * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])

    assert contract_problem("log_so3", log_so3) is None
    reason, hint = contract_problem("log_so3", lambda R: log_so3(R, lists_at_zero=True))
    assert "at the identity" in reason and "returned a list" in reason, reason
