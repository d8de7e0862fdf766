"""Classes for the similarity tests: an honest class and a planted one, built as notebooks.

The honest class: for each exercise, answers written independently in different styles (the correct
alternatives of :mod:`autograder.mistakes` and the answers below), one per student. The planted class
is the honest class plus students who copied an answer and disguised it (:func:`disguise`): renamed
identifiers, reworded comments, reformatting, reordered independent lines, inserted dead code.
:data:`PLANTED` says which findings must be reported.
"""

import ast
import random
from pathlib import Path

from autograder.authoring.sample_class import rename_locals
from autograder.lessons import cells
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.lessons.paths import COURSE
from autograder.lessons.reference import answer_sources
from autograder.mistakes import all_alternatives
from support import THIS_COURSE

# More independently written answers, in styles the alternatives do not use.
OWN_ANSWERS = {
    "rot_z": """
def rot_z(a):
    R = np.eye(3)
    R[0, 0] = R[1, 1] = np.cos(a)
    R[1, 0] = np.sin(a)
    R[0, 1] = -R[1, 0]
    return R
""",
    "quat_multiply": """
def quat_multiply(p, q):
    a1, b1, c1, d1 = (float(x) for x in p)
    a2, b2, c2, d2 = (float(x) for x in q)
    return np.array([a1*a2 - b1*b2 - c1*c2 - d1*d2,
                     a1*b2 + b1*a2 + c1*d2 - d1*c2,
                     a1*c2 - b1*d2 + c1*a2 + d1*b2,
                     a1*d2 + b1*c2 - c1*b2 + d1*a2])
""",
    "hat": """
def hat(w):
    out = np.zeros((3, 3))
    for i in range(3):
        e = np.zeros(3)
        e[i] = 1.0
        out[:, i] = np.cross(w, e)
    return out
""",
    "compose": """
def compose(*rotations):
    result = np.identity(3)
    for matrix in rotations:
        result = np.einsum("ij,jk->ik", result, np.asarray(matrix, dtype=float))
    return result
""",
    "exp_so3": """
def exp_so3(w):
    w = np.asarray(w, dtype=float)
    K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    total, term = np.eye(3), np.eye(3)
    for n in range(1, 30):
        term = term @ K / n
        total = total + term
    return total
""",
    "to_homogeneous": """
def to_homogeneous(points):
    coordinates = np.array(points, dtype=float)
    padding = [(0, 0)] * (coordinates.ndim - 1) + [(0, 1)]
    return np.pad(coordinates, padding, constant_values=1.0)
""",
}


def _code_without_docstring(source):
    function = ast.parse(source).body[0]
    body = function.body
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
        body = body[1:]
    return [ast.dump(node) for node in body]


def honest_answers():
    """``{student: {exercise: source}}``: each student writes a different style of each exercise (an
    alternative whose code is the reference's, docstring aside, is not one: it is left out)."""
    references = answer_sources(THIS_COURSE.solutions)
    styles = {}
    for alternative in sorted(all_alternatives().values(), key=lambda a: a.name):
        if _code_without_docstring(alternative.source.strip("\n")) == _code_without_docstring(
            references[alternative.exercise]
        ):
            continue
        styles.setdefault(alternative.exercise, []).append(alternative.source.strip("\n") + "\n")
    for exercise, source in OWN_ANSWERS.items():
        styles.setdefault(exercise, []).append(source.strip("\n") + "\n")
    students = {}
    for exercise, sources in styles.items():
        for number, source in enumerate(sources):
            students.setdefault(f"honest{number + 1}", {})[exercise] = source
    return students


# -- disguises ---------------------------------------------------------------------------------------


def rename(source, seed=0):
    """Every local variable renamed (the signature, attributes and keywords left alone)."""
    return rename_locals(source, prefix=random.Random(seed).choice(["val_", "tmp_", "acc_", "aux_", "my_"]))


def reword_comments(source, seed=0):
    """Comments rewritten and new ones added at the end of some lines."""
    lines = []
    for number, line in enumerate(source.splitlines()):
        code = line.split("  #")[0].rstrip() if "  #" in line else line
        if number > 0 and code.strip() and number % 3 == seed % 3 and not code.rstrip().endswith(("\\", '"""')):
            code += f"  # note {number}: see lecture"
        lines.append(code)
    return "\n".join(lines) + "\n"


def reformat(source):
    """The code as ``ast.unparse`` writes it: other line breaks, spacing and quotes, comments gone."""
    return ast.unparse(ast.parse(source)) + "\n"


def reorder(source):
    """The first two adjacent independent assignments of the function swapped."""
    tree = ast.parse(source)
    body = tree.body[0].body
    lines = source.splitlines()
    for first, second in zip(body, body[1:]):
        if not (isinstance(first, ast.Assign) and isinstance(second, ast.Assign)):
            continue
        written = [{n.id for t in s.targets for n in ast.walk(t) if isinstance(n, ast.Name)} for s in (first, second)]
        read = [{n.id for n in ast.walk(s.value) if isinstance(n, ast.Name)} for s in (first, second)]
        if written[0] & read[1] or written[1] & read[0] or written[0] & written[1]:
            continue
        a = lines[first.lineno - 1 : first.end_lineno]
        b = lines[second.lineno - 1 : second.end_lineno]
        lines[first.lineno - 1 : second.end_lineno] = b + a
        return "\n".join(lines) + "\n"
    return source


def insert_dead_code(source):
    """A loop that never runs and an unused list, after the docstring (or the ``def`` line)."""
    tree = ast.parse(source)
    function = tree.body[0]
    first = function.body[0]
    docstring = isinstance(first, ast.Expr) and isinstance(getattr(first, "value", None), ast.Constant)
    at = first.end_lineno if docstring else first.lineno - 1
    indent = " " * first.col_offset
    dead = [
        f"{indent}unused_steps = [0.0 for _ in range(2)]",
        f"{indent}for _ in range(0):",
        f"{indent}    unused_steps.append(1.0)",
    ]
    lines = source.splitlines()
    lines[at:at] = dead
    return "\n".join(lines) + "\n"


DISGUISES = {
    "rename": lambda s, seed: rename(s, seed),
    "comments": lambda s, seed: reword_comments(s, seed),
    "reformat": lambda s, seed: reformat(s),
    "reorder": lambda s, seed: reorder(s),
    "dead code": lambda s, seed: insert_dead_code(s),
}


def disguise(source, kinds, seed=0):
    """``source`` with each disguise of ``kinds`` (names of :data:`DISGUISES`) applied in turn."""
    for kind in kinds:
        source = DISGUISES[kind](source, seed)
    return source


# -- the planted class -------------------------------------------------------------------------------


def planted_answers():
    """``(answers, planted)``: the honest class plus copies; ``planted`` lists the findings to report:
    ``("cluster", members, exercises)`` and ``("reference", student, exercise)``."""
    students = honest_answers()
    planted = []
    copies = [
        ("pair_rename", ["rename"], "quat_multiply"),
        ("pair_comments", ["comments", "rename"], "exp_so3"),
        ("pair_reformat", ["reformat"], "quat_slerp"),
        ("pair_reorder", ["reorder", "rename"], "right_jacobian_so3"),
        ("pair_dead", ["dead code"], "matrix_to_euler_zyx"),
    ]
    for seed, (student, kinds, exercise) in enumerate(copies):
        original = students["honest1"].pop(exercise)  # its writer is a student of their own
        students[f"{student}_source"] = {exercise: original}
        students[student] = {exercise: disguise(original, kinds, seed)}
        planted.append(("cluster", (student, f"{student}_source"), (exercise,)))
    five = [f"ring{i}" for i in range(1, 6)]
    kinds = [
        ["rename"],
        ["comments"],
        ["reformat", "rename"],
        ["reorder", "dead code"],
        ["rename", "comments", "dead code"],
    ]
    original = students["honest2"].pop("numerical_jacobian")
    for seed, (student, chosen) in enumerate(zip(five, kinds)):
        students[student] = {"numerical_jacobian": disguise(original, chosen, seed + 10)}
    planted.append(("cluster", tuple(five), ("numerical_jacobian",)))
    students["refcopy"] = {"quat_to_matrix": rename(answer_sources(THIS_COURSE.solutions)["quat_to_matrix"], seed=3)}
    planted.append(("reference", "refcopy", "quat_to_matrix"))
    return students, planted


def write_class(folder, students):
    """Each student's answers into the released notebooks (other answers left as the stub)."""
    folder = Path(folder)
    for lesson in THIS_COURSE.catalog.graded_lessons:
        names = {e.name for e in lesson.exercises}
        for student, answers in students.items():
            if not names & set(answers):
                continue
            nb = read_master(COURSE / lesson.filename)
            for cell in nb.cells:
                if cells.is_answer_cell(cell) and cells.grade_id(cell) in answers:
                    cell.source = answers[cells.grade_id(cell)]
            (folder / student).mkdir(parents=True, exist_ok=True)
            (folder / student / lesson.filename).write_text(canonical_text(nb), encoding="utf-8")
    return folder
