"""Grading that students cannot cheat and faults cannot break.

Every case of :mod:`adversarial_corpus` (and the honest twin of each cheat) is
handed in by one student of lesson 01; the whole class is graded in one run of
``python -m autograder grade`` with the notebook stage, exactly as an
instructor would. Then each case must have its outcome, the batch must have
finished, and nothing outside the sandbox may have changed.
"""

import csv
import json
import os
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from adversarial_corpus import cases, damage_notebook
from autograder.batch.class_run import safe_name
from autograder.grading.results import StudentResult
from autograder.lessons.catalog import load_catalog
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import PROJECT_ROOT, SOLUTIONS
from autograder.sandbox import launcher
from support import build_submission

LESSON = load_catalog().lesson("01")
NAMESPACES = launcher.isolation()[0] == "namespaces"


class Listener:
    """A TCP server on the grader's loopback that records whatever connects."""

    def __init__(self):
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen()
        self.server.settimeout(0.2)
        self.port = self.server.getsockname()[1]
        self.received = []
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        while not self.stop.is_set():
            try:
                connection, _ = self.server.accept()
            except OSError:
                continue
            connection.settimeout(1)
            try:
                self.received.append(connection.recv(1024) or b"(connected)")
            except OSError:
                self.received.append(b"(connected)")
            connection.close()

    def close(self):
        self.stop.set()
        self.thread.join()
        self.server.close()


def _build(case, folder):
    overrides = {case.target: case.source} if case.source else {}
    build_submission(folder, overrides, lessons=("01",))
    notebook = folder / LESSON.filename
    if case.damage == "symlink_notebook":
        notebook.unlink()
        notebook.symlink_to(SOLUTIONS / LESSON.filename)
    elif case.damage == "symlink_folder":
        (folder / "solutions_link").symlink_to(SOLUTIONS, target_is_directory=True)
    elif case.damage:
        text = damage_notebook(case, read_master(notebook), notebook.read_text(encoding="utf-8"))
        notebook.write_bytes(text.encode("latin-1", errors="replace") if case.damage == "latin1" else text.encode("utf-8"))


def _sleepers():
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                if b"31.4159" in Path(f"/proc/{entry}/cmdline").read_bytes():
                    found.append(int(entry))
            except OSError:
                pass
    return found


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    base = tmp_path_factory.mktemp("adversarial")
    class_dir, out = base / "class", base / "out"
    canary = base / "canary.txt"
    canary.write_text("untouched", encoding="utf-8")
    listener = Listener()
    corpus_cases = cases({"out_dir": out, "canary": canary, "port": listener.port})
    try:
        for case in corpus_cases:
            _build(case, class_dir / (case.student_id or case.name))
            if case.twin:
                build_submission(class_dir / f"{case.name}__twin", {case.target: case.twin}, lessons=("01",))
        started = time.monotonic()
        run = subprocess.run([sys.executable, "-m", "autograder", "grade", str(class_dir), "--out", str(out),
                              "--lessons", "01", "--jobs", "2"],
                             cwd=PROJECT_ROOT, capture_output=True, text=True, timeout=1500)
        seconds = time.monotonic() - started
        time.sleep(6)  # give any detached process the time to try its attack
    finally:
        listener.close()
    results = {}
    for path in (out / "students").glob("*.json"):
        result = StudentResult.from_json(json.dumps(json.loads(path.read_text(encoding="utf-8"))["result"]))
        results[result.student_id] = result
    return {"cases": {c.name: c for c in corpus_cases}, "results": results, "run": run, "out": out,
            "canary": canary, "received": listener.received, "seconds": seconds, "class": class_dir}


CASE_NAMES = [c.name for c in cases({"out_dir": Path("/x"), "canary": Path("/x"), "port": 1})]


def _exercise_points(result):
    return {e.name: (e.points, e.max_points) for e in result.exercises}


def test_the_corpus_is_large_enough():
    assert len(CASE_NAMES) >= 20


def test_the_batch_finished(corpus):
    run = corpus["run"]
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    expected = {c.student_id or c.name for c in corpus["cases"].values()}
    expected |= {f"{c.name}__twin" for c in corpus["cases"].values() if c.twin}
    assert set(corpus["results"]) == expected
    with open(corpus["out"] / "grades.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == len(expected)


@pytest.mark.skipif(not NAMESPACES, reason="without namespaces student code can reach the grader's files")
def test_nothing_outside_the_sandbox_changed(corpus):
    assert corpus["canary"].read_text(encoding="utf-8") == "untouched"
    assert "owned" not in (corpus["out"] / "grades.csv").read_text(encoding="utf-8")
    assert not _sleepers(), "a detached student process outlived the grading run"


@pytest.mark.skipif(not NAMESPACES, reason="the loopback is reachable without network namespaces")
def test_no_connection_reached_the_grader_loopback(corpus):
    assert corpus["received"] == []


@pytest.mark.parametrize("name", CASE_NAMES)
def test_case_outcome(name, corpus):
    case = corpus["cases"][name]
    if case.needs_namespaces and not NAMESPACES:
        pytest.skip("needs the namespace sandbox (bubblewrap)")
    result = corpus["results"][case.student_id or case.name]
    points = _exercise_points(result)
    if case.expect == "twin":
        twin = corpus["results"][f"{case.name}__twin"]
        assert result.score <= twin.score, (result.score, twin.score)
        assert points[case.target][0] <= _exercise_points(twin)[case.target][0]
    elif case.expect == "zero":
        assert points[case.target][0] == 0.0
        others = {n: p for n, p in points.items() if n != case.target and p[0] < p[1]}
        assert not others, f"the fault also cost {others}"
    elif case.expect == "full":
        assert all(p[0] == p[1] for p in points.values()), points
    elif case.expect == "lesson_zero":
        assert result.score == 0.0
        lesson = result.lessons[0]
        assert lesson.status != "graded" and case.reason in lesson.reason, lesson.reason
    else:
        raise AssertionError(f"unknown expectation {case.expect}")


def test_html_from_students_is_escaped(corpus):
    page = (corpus["out"] / "feedback" / "html_in_output.html").read_text(encoding="utf-8")
    assert "<script>alert" not in page and "<img src=x" not in page
    assert "&lt;img src=x onerror=alert(1)&gt;" in page


def test_printing_is_capped(corpus):
    page = corpus["out"] / "feedback" / "prints_50_mb.html"
    assert page.stat().st_size < 200_000
    assert "more characters not kept" in page.read_text(encoding="utf-8")


def test_formula_ids_are_escaped_in_the_gradebook(corpus):
    raw = (corpus["out"] / "grades.csv").read_text(encoding="utf-8")
    assert "'+SUM(1;1)" in raw and "'@evil" in raw
    assert (corpus["out"] / "feedback" / f"{safe_name('+SUM(1;1)')}.html").exists()


def test_recreated_and_duplicated_cells_are_reported(corpus):
    recreated = corpus["results"]["recreated_cells"]
    assert recreated.status == "graded with problems"
    assert any("not found by its id" in p for p in recreated.problems)
    duplicate = corpus["results"]["duplicate_grade_id"]
    assert any("the last one was graded" in p for p in duplicate.problems)
