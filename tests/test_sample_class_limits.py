"""The main job again with ``AUTOGRADER_SANDBOX=limits``: resource limits only, asked for explicitly.

It runs in its own file so that the test workers grade the two runs of the sample class in
parallel (``tests/test_sample_class.py`` grades it with this machine's isolation). Both runs are
held to the same golden gradebook (``tests/golden/sample_class_grades.csv``), so every student gets
the same points in both; and the limits run must say so everywhere an instructor looks.
"""

import json
import subprocess
import sys

import pytest

import record_golden
from autograder.lessons.paths import PROJECT_ROOT
from support import grade_sample_class


@pytest.fixture(scope="module")
def limits_run(tmp_path_factory):
    return grade_sample_class(tmp_path_factory.mktemp("grading-limits"), sandbox="limits")


def test_limits_mode_gives_every_student_the_golden_grade(limits_run):
    out, _, rows = limits_run
    changed = record_golden.differences(record_golden.read_golden(), record_golden.verdicts(out / "grades.csv"))
    assert not changed, "limits mode moved verdicts:\n" + "\n".join(changed[:40])
    columns, table = record_golden.verdicts(out / "grades.csv")
    assert any(column.startswith("notebook_") for column in columns)  # nbval ran in this mode too
    for student, row in rows.items():
        assert float(row["score"]) == pytest.approx(sum(float(table[student][c] or 0) for c in columns)), student
    assert float(rows["ada"]["score"]) == float(rows["ada"]["max_score"]) > 0
    assert float(rows["ben"]["score"]) == 0.0
    assert rows["kim"]["status"] == "graded with problems" and "not valid JSON" in rows["kim"]["problems"]


def test_limits_mode_is_loud_everywhere(limits_run):
    out, stdout, rows = limits_run
    assert stdout.splitlines()[0].startswith("No PATH given")
    assert "RESOURCE LIMITS ONLY" in stdout.splitlines()[1]
    status = subprocess.run(
        [sys.executable, "-m", "autograder", "status", "--out", str(out)],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert status.returncode == 0 and status.stdout.startswith(
        f"WARNING: {len(rows)} of {len(rows)} students were graded with resource limits only"
    )
    assert "resource limits only" in (out / "report.html").read_text(encoding="utf-8")
    for page in (out / "feedback").glob("*.html"):
        assert "isolated by resource limits only" in page.read_text(encoding="utf-8"), page.name
    for path in (out / "results").glob("*.json"):
        assert "isolated by resource limits only" in json.loads(path.read_text(encoding="utf-8"))["output"]
