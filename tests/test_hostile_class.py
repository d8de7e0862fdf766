"""A class where every student is hostile in a different way grades every honest student as a clean run does.

The class of :mod:`hostile_class` (FIFOs, sockets, devices and links named
like notebooks; names of 250 bytes, with escape sequences, newlines, bytes
that are not UTF-8; JSON and Python nested 100,000 deep; millions of tiny JSON
lists, thousands of cells, files and notebooks; lone surrogates; metadata of
the wrong types; stray entries beside the students) is graded with
``python -m autograder grade`` in a subprocess, as root and as an ordinary
user (``nobody``, see :mod:`ordinary_user`), with the notebook stage. Then:

- the run ends normally within :data:`TIME_BOUND` seconds, and no process of
  the grader (the sandboxes are not the grader) goes past
  :data:`MEMORY_BOUND` bytes of resident memory;
- ``grades.csv`` and ``report.html`` are written, with one row per student;
- every honest student's row equals the one of a clean run of the honest
  students alone;
- each hostile student gets what its case says, never "could not grade";
- student text reaches the terminal, the CSV and the pages escaped, on one line;
- every entry the grader skipped is listed with why in the run's output, in
  ``status``, in ``OUT/skipped.json`` and in the report.

``benchmarks/hostile_class.py`` prints the time and memory figures.
"""

import csv
import json
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import pytest

import ordinary_user
from autograder.grading.results import COULD_NOT_GRADE, StudentResult
from autograder.lessons.paths import PROJECT_ROOT
from autograder.lessons.untrusted_text import csv_cell, safe_name
from hostile_class import CASES, HONEST, build_class, build_honest, commands, unlock
from process_memory import PeakMemory, is_grader

TIME_BOUND = 1800  # seconds for the whole hostile class (about 45 students), on a loaded 2-core machine
MEMORY_BOUND = 1024 * 2**20  # resident bytes of any one process of the grader (its sandboxes excepted)
MODES = ["root", "ordinary user"] if ordinary_user.running_as_root() else ["ordinary user"]
CONTROL = {chr(c) for c in range(32) if chr(c) not in "\n"} | {"\x7f", "\u202e"}


@pytest.fixture(scope="module")
def workspace():
    base = Path(tempfile.mkdtemp(prefix="hostile-class-", dir="/tmp"))
    base.chmod(0o755)  # nobody must reach the class and the outputs
    build_honest(base / "honest")
    shutil.copytree(base / "honest", base / "class", symlinks=True)  # the same files, the same times
    built = build_class(base / "class")
    yield {"base": base, "built": built}
    unlock(base)
    shutil.rmtree(base, ignore_errors=True)


def grade(base, class_dir, out, mode):
    """Run ``python -m autograder grade`` as ``mode`` and then ``status``; what they printed and cost."""
    command, status, env = commands(base, class_dir, out, mode)
    started = time.monotonic()
    process = subprocess.Popen(command, cwd=PROJECT_ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    with PeakMemory(process.pid, interval=0.1, only=is_grader) as memory:
        try:
            stdout, stderr = process.communicate(timeout=TIME_BOUND)
        except subprocess.TimeoutExpired:
            process.kill()
            stdout, stderr = process.communicate()
            pytest.fail(f"grading the class took longer than {TIME_BOUND} s:\n{stdout[-3000:]}{stderr[-3000:]}")
    seconds = time.monotonic() - started
    shown = subprocess.run(status, cwd=PROJECT_ROOT, env=env, capture_output=True, timeout=300)
    return {
        "returncode": process.returncode,
        "stdout": stdout.decode("utf-8", "replace"),
        "stderr": stderr.decode("utf-8", "replace"),
        "seconds": seconds,
        "largest": memory.largest,
        "peak": memory.peak,
        "status": shown.stdout.decode("utf-8", "replace"),
        "out": out,
    }


def _results(out):
    found = {}
    for path in (out / "students").glob("*.json"):
        result = StudentResult.from_json(json.dumps(json.loads(path.read_text(encoding="utf-8"))["result"]))
        found[result.student_id] = result
    return found


def _rows(out):
    with open(out / "grades.csv", newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


@pytest.fixture(scope="module")
def clean(workspace):
    mode = MODES[0]
    return grade(workspace["base"], workspace["base"] / "honest", workspace["base"] / "out-clean", mode)


@pytest.fixture(scope="module", params=MODES)
def hostile(request, workspace):
    run = grade(
        workspace["base"], workspace["base"] / "class", workspace["base"] / f"out-{request.param}", request.param
    )
    run["results"] = _results(run["out"])
    run["mode"] = request.param
    print(
        f"\nhostile class, {request.param}: {run['seconds']:.0f} s, largest grader process "
        f"{run['largest'] / 2**20:.0f} MiB, grader processes together {run['peak'] / 2**20:.0f} MiB"
    )
    return run


def _students(workspace):
    return set(HONEST) | {sid for sid in workspace["built"].values() if sid is not None}


def test_the_corpus_covers_every_family():
    families = {c.family for c in CASES}
    assert {"file type", "name", "depth", "size", "encoding", "types"} <= families
    assert len({c.name for c in CASES}) == len(CASES)


def test_the_run_ends_normally_and_writes_the_gradebook_and_report(hostile, workspace):
    assert hostile["returncode"] == 0, hostile["stdout"][-3000:] + hostile["stderr"][-3000:]
    assert "Traceback" not in hostile["stderr"], hostile["stderr"][-3000:]
    students = _students(workspace)
    assert set(hostile["results"]) == students
    assert len(_rows(hostile["out"])) == len(students)
    assert (hostile["out"] / "report.html").stat().st_size > 0
    names = [p.name for p in (hostile["out"] / "feedback").iterdir()]
    assert len(names) == len(students) and all(len(n.encode()) <= 130 for n in names)
    assert {safe_name(s) + ".html" for s in students} == set(names)


def test_bounded_time_and_grader_memory(hostile):
    assert hostile["seconds"] < TIME_BOUND
    assert 0 < hostile["largest"] < MEMORY_BOUND, hostile["largest"]


def _comparable(row):
    return {k: v for k, v in row.items() if k not in ("graded_at", "timestamp")}


def test_honest_students_grade_exactly_as_in_a_clean_run(hostile, clean):
    assert clean["returncode"] == 0, clean["stdout"][-3000:] + clean["stderr"][-3000:]
    wanted = {row["student_id"]: _comparable(row) for row in _rows(clean["out"])}
    got = {row["student_id"]: _comparable(row) for row in _rows(hostile["out"]) if row["student_id"] in HONEST}
    assert set(wanted) == set(HONEST)
    assert got == wanted


def _said(result):
    lines = [result.reason, *result.problems, *result.skipped]
    for lesson in result.lessons:
        lines.append(lesson.reason)
        if lesson.run is not None and lesson.run.points < lesson.run.max_points:
            lines += [f"notebook {lesson.number} ({lesson.run.status}): {failure}" for failure in lesson.run.failures]
        for exercise in lesson.exercises:
            lines += exercise.notes
            lines += [check.reason for check in exercise.checks if not check.passed]
    return "\n".join(lines)


@pytest.mark.parametrize("name", [c.name for c in CASES])
def test_each_hostile_case_costs_only_itself(name, hostile, workspace):
    hostile_case = next(c for c in CASES if c.name == name)
    student = workspace["built"][name]
    if hostile_case.expect == "skipped":
        assert student is None
        listed = json.loads((hostile["out"] / "skipped.json").read_text(encoding="utf-8"))
        assert any(hostile_case.says in item["why"] for item in listed), listed
        return
    result = hostile["results"][student]
    assert result.status != COULD_NOT_GRADE, result.reason
    assert hostile_case.says in _said(result), _said(result)
    if hostile_case.expect == "full":
        assert result.max_score > 0 and result.score == result.max_score, (result.score, _said(result))
    if hostile_case.expect == "exercises":
        assert result.exercises and all(e.points == e.max_points for e in result.exercises), _said(result)


def test_student_text_reaches_the_terminal_escaped_on_one_line(hostile):
    for stream in ("stdout", "stderr", "status"):
        text = hostile[stream]
        assert not CONTROL & set(text), (stream, sorted(CONTROL & set(text)))
        assert "\ufffd" not in text, stream  # nothing was printed that could not be encoded
    table = hostile["stdout"]
    assert not any(line.startswith("zz_victim") for line in table.splitlines())
    assert "forger\\nzz_victim" in table and "esc\\x1b[2J" in table


def test_student_text_reaches_the_csv_escaped_on_one_line(hostile):
    raw = (hostile["out"] / "grades.csv").read_text(encoding="utf-8")
    rows = _rows(hostile["out"])
    for row in rows:
        for value in row.values():
            assert not CONTROL & set(value or ""), value
            assert "\n" not in (value or "")
            assert not (value or "").startswith(("=", "+", "-", "@")), value
    assert csv_cell('=HYPERLINK("http:∕∕x.invalid∕?"&A1,"ok")') in {row["student_id"] for row in rows}
    assert raw.count("\n") == len(rows) + 1


def test_student_text_reaches_the_pages_escaped(hostile):
    pages = [hostile["out"] / "report.html", *(hostile["out"] / "feedback").iterdir()]
    for page in pages:
        text = page.read_text(encoding="utf-8")
        assert not {"\x1b", "\x07", "\x00", "\u202e"} & set(text), page.name
    feedback = (hostile["out"] / "feedback" / f"{safe_name('raises_surrogates')}.html").read_text(encoding="utf-8")
    assert "\\x1b[2J\\x1b]0;owned\\x07" in feedback  # the message, shown (its lone surrogate made encodable)


def test_everything_skipped_is_listed_with_why(hostile, workspace):
    listed = {
        item["path"]: item["why"] for item in json.loads((hostile["out"] / "skipped.json").read_text(encoding="utf-8"))
    }
    for entry in ("grades.csv", "pipe", "sock", "copycat", "nowhere", ".hidden_student"):
        assert entry in listed, listed
        assert f"{entry}: {listed[entry]}" in hostile["stdout"]
        assert f"{entry}: {listed[entry]}" in hostile["status"]
        assert entry in (hostile["out"] / "report.html").read_text(encoding="utf-8")
    too_deep = hostile["results"]["too_deep"]
    assert any(line.startswith("a/b/c/: deeper than 2 folders") for line in too_deep.skipped), too_deep.skipped
    assert "too_deep" in hostile["status"] and "a/b/c/: deeper than" in hostile["status"]
    if hostile["mode"] == "ordinary user" and ordinary_user.running_as_root():
        locked = hostile["results"]["mode_000"]
        assert any(line.startswith("locked/: cannot be read") for line in locked.skipped), locked.skipped
        assert "Permission denied" in locked.lessons[0].reason
        unlisted = hostile["results"]["locked_student"]
        assert unlisted.status == "missing" and unlisted.skipped == [
            "./: cannot be read (Permission denied), not searched"
        ], unlisted.skipped
