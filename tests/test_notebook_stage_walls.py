"""The notebook stage's verdict cannot be produced from inside the student's code.

The notebook (nbval) runs in a kernel that holds no student code: answer cells are bindings to the
student's functions in their own sandbox (autograder/grading/nbval_stage.py). Oracle: a submission
whose ``rotate_point`` is right on every hidden check but raises on the one point a demonstration
of lesson 01 uses, and whose answer cell also tries what worked against a kernel that runs it (an
IPython input transformer that turns every later cell into ``pass``, reading the notebook's recorded
outputs to replay them): full hidden marks, and the notebook point is lost, naming the cell that
raised. The same answer with the replay code but without the flaw keeps the point: had that code run in
the kernel, it would have replaced every later cell (a grader that runs answers in the kernel loses the
point there: the test was tried against one), so it proves the student's code never ran in the kernel.
"""

import pytest

from autograder.sandbox import launcher
from support import build_submission, grade, references

TRAP = """
import glob, json

def _replay_everything():
    try:
        shell = get_ipython()            # only exists in a kernel
    except NameError:
        return "no kernel here"
    recorded = {}
    for path in glob.glob("*.ipynb"):    # the merged notebook, with the master's outputs
        for cell in json.load(open(path))["cells"]:
            recorded["".join(cell.get("source", ""))] = cell.get("outputs", [])
    def replay(lines):                   # every later cell: show what the master recorded, run nothing
        outputs = recorded.get("".join(lines), [])
        data = [output["data"] for output in outputs if "data" in output]
        return ["from IPython.display import publish_display_data as _show\\n",
                f"for _data in {data!r}: _show(_data)\\n"]
    shell.input_transformers_post.append(replay)
    return "installed"

_replay_everything()

"""


def _rotate_point(trap):
    source = references()["rotate_point"]
    body = source.replace(
        "    R_wb = np.asarray(R_wb, dtype=float)",
        "    if np.array_equal(np.asarray(p_b, dtype=float), [0.5, 0.3, 2.0]):\n"
        '        raise RuntimeError("only on the demonstration\'s point")\n'
        "    R_wb = np.asarray(R_wb, dtype=float)",
        1,
    )
    assert body != source
    return (TRAP if trap else "") + body


@pytest.mark.skipif(launcher.isolation()[0] != "namespaces", reason="needs the namespace sandbox")
@pytest.mark.parametrize("trap", [True, False], ids=["with_the_replay_attack", "plain"])
def test_a_demonstration_that_raises_costs_the_notebook_point(tmp_path, trap):
    folder = build_submission(tmp_path / "student", {"rotate_point": _rotate_point(trap)}, lessons=("01",))
    result = grade(folder, lessons=("01",), nbval=True)
    lesson = result.lessons[0]
    assert all(e.points == e.max_points for e in lesson.exercises), "right on every hidden check"
    assert lesson.run.points == 0 and lesson.run.status == "failed", lesson.run
    assert any("rotate_point" in f or "R_rc" in f for f in lesson.run.failures), lesson.run.failures


@pytest.mark.skipif(launcher.isolation()[0] != "namespaces", reason="needs the namespace sandbox")
def test_the_same_answer_without_its_flaw_keeps_the_point(tmp_path):
    folder = build_submission(
        tmp_path / "student", {"rotate_point": TRAP + references()["rotate_point"]}, lessons=("01",)
    )
    lesson = grade(folder, lessons=("01",), nbval=True).lessons[0]
    assert lesson.run.points == lesson.run.max_points, lesson.run
