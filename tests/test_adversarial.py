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
import shutil
import signal
import socket
import stat
import string
import subprocess
import sys
import threading
import time
import unicodedata
from pathlib import Path

import pytest

from adversarial_corpus import cases, damage_notebook
from autograder.batch import class_run
from autograder.batch.class_run import safe_name
from autograder.grading import pipeline, submissions
from autograder.grading.results import LessonResult, StudentResult
from autograder.lessons import cells
from autograder.lessons.notebook_files import (
    NotARegularFile,
    UnreadableNotebook,
    canonical_text,
    parse_notebook,
    read_master,
    read_regular_file,
    read_submission,
)
from autograder.lessons.paths import COURSE, PROJECT_ROOT, SOLUTIONS
from autograder.lessons.untrusted_text import csv_cell, html_text, one_line
from autograder.sandbox import launcher
from support import build_submission
from support import THIS_COURSE

LESSON = THIS_COURSE.catalog.lesson("01")
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
    elif case.damage == "fifo":
        notebook.unlink()
        os.mkfifo(notebook)
    elif case.damage:
        text = damage_notebook(case, read_master(notebook), notebook.read_text(encoding="utf-8"))
        notebook.write_bytes(
            text.encode("latin-1", errors="replace") if case.damage == "latin1" else text.encode("utf-8")
        )


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
        run = subprocess.run(
            [
                sys.executable,
                "-m",
                "autograder",
                "grade",
                str(class_dir),
                "--out",
                str(out),
                "--lessons",
                "01",
                "--jobs",
                "2",
            ],
            cwd=PROJECT_ROOT,
            capture_output=True,
            text=True,
            timeout=1500,
        )
        seconds = time.monotonic() - started
        time.sleep(6)  # give any detached process the time to try its attack
    finally:
        listener.close()
    results = {}
    for path in (out / "students").glob("*.json"):
        result = StudentResult.from_json(json.dumps(json.loads(path.read_text(encoding="utf-8"))["result"]))
        results[result.student_id] = result
    return {
        "cases": {c.name: c for c in corpus_cases},
        "results": results,
        "run": run,
        "out": out,
        "canary": canary,
        "received": listener.received,
        "seconds": seconds,
        "class": class_dir,
    }


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


def test_student_text_reaches_the_terminal_escaped(corpus):
    for stream in (corpus["run"].stdout, corpus["run"].stderr):
        assert "\x1b" not in stream and "\x07" not in stream
        assert not any(line.startswith("forged_row") for line in stream.splitlines())
    assert "nl\\nforged_row" in corpus["run"].stdout


# ------------------------------------------------------------------ the grader's own walls, one step at a time
# (issue 32, item 1: each per-student step outside the sandbox is contained whatever the folder holds;
# tests/test_hostile_class.py grades a whole class of such students, as root and as an ordinary user)

HOSTILE_TEXTS = [
    "esc\x1b[2J\x1b]0;title\x07",
    "two\nlines\r\n",
    "bidi\u202eevil\u202c\u200b",
    "lone\ud800\udcff",
    "nul\0del\x7f",
    "x" * 100_000,
    "=1+1",
    "\t=cmd",
    "é" * 200,
    "%41~" * 50,
]


class _Alarm:
    """Fail instead of hanging: the block must end within ``seconds``."""

    def __init__(self, seconds=10):
        self.seconds = seconds

    def __enter__(self):
        def ring(signum, frame):
            raise AssertionError(f"blocked for more than {self.seconds} s")

        self.previous = signal.signal(signal.SIGALRM, ring)
        signal.alarm(self.seconds)

    def __exit__(self, *exc):
        signal.alarm(0)
        signal.signal(signal.SIGALRM, self.previous)


def _make_special(kind, path):
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "socket":
        server = socket.socket(socket.AF_UNIX)
        server.bind(str(path))
        server.close()
    elif kind == "device":
        if os.geteuid() != 0:
            pytest.skip("only root makes device files")
        os.mknod(path, 0o644 | stat.S_IFCHR, os.makedev(1, 5))  # /dev/zero: endless
    elif kind == "link_to_device":
        path.symlink_to("/dev/zero")
    elif kind == "folder":
        path.mkdir()


@pytest.mark.parametrize("kind", ["fifo", "socket", "device", "link_to_device", "folder"])
def test_only_regular_files_are_ever_opened(kind, tmp_path):
    path = tmp_path / "01_frames_and_rotations.ipynb"
    _make_special(kind, path)
    with _Alarm():
        with pytest.raises(NotARegularFile):
            read_regular_file(path, 1000)
        with pytest.raises(UnreadableNotebook, match="symbolic link|not a regular file"):
            read_submission(path, root=tmp_path)
        submissions.submission_hash(tmp_path)
        files = submissions.match_lessons(tmp_path, THIS_COURSE.catalog, THIS_COURSE.released)
    if kind != "folder":
        assert files.chosen["01"] == path  # graded as unreadable, so the reason reaches the student


def test_reading_is_bounded_whatever_the_file_size(tmp_path):
    path = tmp_path / "01_frames_and_rotations.ipynb"
    with open(path, "wb") as handle:
        handle.truncate(8 * 2**30)  # sparse: 8 GiB that cost no disk
    started = time.monotonic()
    data, size = read_regular_file(path, 1000)
    assert len(data) == 1000 and size == 8 * 2**30
    with pytest.raises(UnreadableNotebook, match="over the"):
        read_submission(path, root=tmp_path)
    submissions.submission_hash(tmp_path)
    assert time.monotonic() - started < 30


def _notebook_with(value_text, where="metadata"):
    nb = read_master(COURSE / LESSON.filename)
    data = json.loads(canonical_text(nb))
    (data if where == "metadata" else data["cells"][0])["metadata"]["hostile"] = "@@"
    return json.dumps(data).replace('"@@"', value_text).encode("utf-8")


@pytest.mark.parametrize(
    "value, words",
    [
        ("[" * 100_000 + "]" * 100_000, "nests its JSON"),
        ('{"a":' * 100_000 + "0" + "}" * 100_000, "nests its JSON"),
        ("[" * 900 + "]" * 900, "nests its JSON"),
        ("[" * 70 + "]" * 70, "nests its JSON"),
        ("[" + ",".join(["{}"] * 300_000) + "]", "JSON lists and objects"),
        ("[" + ",".join(["1e9"] * 1_100_000) + "]", "JSON values"),
    ],
)
def test_notebook_json_is_bounded_in_depth_and_size(value, words):
    for where in ("metadata", "cell"):
        with pytest.raises(UnreadableNotebook, match=words):
            parse_notebook(_notebook_with(value, where))


def test_a_notebook_within_the_bounds_still_reads():
    nb = parse_notebook(_notebook_with("[" * 50 + "]" * 50))
    assert nb.cells and nb.metadata["hostile"]


def test_too_many_cells_is_refused():
    data = json.loads(canonical_text(read_master(COURSE / LESSON.filename)))
    data["cells"] += [{"cell_type": "raw", "metadata": {}, "source": ""}] * 6000
    with pytest.raises(UnreadableNotebook, match="cells"):
        parse_notebook(json.dumps(data).encode())


@pytest.mark.parametrize(
    "source",
    [
        "x = " + "-" * 100_000 + "1",
        "x = y" + ".a" * 100_000,
        "x = f" + "(1)" * 100_000,
        "x = 1" + "**1" * 100_000,
        "x = " + "not " * 100_000 + "y",
        "x = " + "(" * 100_000 + ")" * 100_000,
        "def f():\n    return '\0'\n",
        "def f():\n" + "    x = 1\n" * 100_000,
        "def f(:\n",
    ],
)
def test_any_cell_source_parses_or_gives_none(source):
    assert cells.parse_source(source) is None


def test_an_unexpected_error_on_one_notebook_costs_that_notebook(tmp_path, monkeypatch):
    folder = build_submission(tmp_path / "ada", lessons=("01", "02"))

    def broken(nb, lesson):
        if lesson.number == "01":
            raise KeyError("something the grader did not foresee")
        return original(nb, lesson)

    original = pipeline.extract.lesson_program
    monkeypatch.setattr(pipeline.extract, "lesson_program", broken)
    lessons, _, _ = pipeline._read_lessons(folder, THIS_COURSE, ("01", "02"))
    by_number = {shell.number: (shell, program) for shell, _, program in lessons}
    assert by_number["01"][0].status == "unreadable" and "KeyError" in by_number["01"][0].reason
    assert by_number["02"][0].status == "graded" and by_number["02"][1] is not None


def test_the_walk_of_a_folder_is_bounded_and_lists_what_it_skips(tmp_path):
    folder = build_submission(tmp_path / "ada", lessons=("01",))
    build_submission(folder / ".hidden", lessons=("01",))
    build_submission(folder / "a" / "b" / "c", lessons=("01",))
    (folder / "linked").symlink_to(tmp_path, target_is_directory=True)
    for index in range(submissions.MAX_ENTRIES + 50):
        (folder / f"z{index:05d}.txt").touch()
    for index in range(submissions.MAX_NOTEBOOKS + 5):
        (folder / f"n{index:02d}.ipynb").write_text("{}", encoding="utf-8")
    found = submissions.scan_folder(folder)
    assert folder / LESSON.filename in found.files and len(found.files) == submissions.MAX_NOTEBOOKS
    lines = "\n".join(item.line() for item in found.skipped)
    for words in (
        ".hidden/: a hidden folder",
        "a/b/c/: deeper than",
        "linked: a symbolic link",
        "at most 50 notebooks",
        "more than 10,000 entries",
    ):
        assert words in lines, lines
    assert len(found.skipped) <= submissions.MAX_SKIPPED_LISTED + 1


def test_entries_that_are_not_students_are_listed_with_why(tmp_path):
    build_submission(tmp_path / "ada", lessons=("01",))
    build_submission(tmp_path / ".hidden", lessons=("01",))
    (tmp_path / "stray.ipynb").write_text("{}", encoding="utf-8")
    (tmp_path / "copy").symlink_to(tmp_path / "ada")
    os.mkfifo(tmp_path / "pipe")
    with _Alarm():
        found = submissions.scan_submissions(tmp_path)
    assert [sid for sid, _ in found.files] == ["ada"]
    why = {item.path: item.why for item in found.skipped}
    assert set(why) == {".hidden", "stray.ipynb", "copy", "pipe"}
    assert "hidden" in why[".hidden"] and "symbolic link" in why["copy"] and "FIFO" in why["pipe"]


@pytest.mark.parametrize("text", HOSTILE_TEXTS)
def test_student_text_is_one_line_bounded_and_encodable(text):
    for shown in (one_line(text), csv_cell(text), html_text(text, 300)):
        assert len(shown) < 400
        shown.encode("utf-8")  # never raises
        assert not {c for c in shown if unicodedata.category(c) in ("Cc", "Cf", "Cs", "Zl", "Zp")} - {"\n", "\t"}
    assert "\n" not in one_line(text) and "\t" not in one_line(text)
    assert "<" not in html_text("<b>" + text) and not csv_cell(text).startswith(("=", "+", "-", "@"))


def test_safe_names_are_bounded_portable_and_distinct():
    ids = HOSTILE_TEXTS + [
        "",
        ".",
        "..",
        "../etc/passwd",
        "a/b",
        "aA",
        "a%41",
        "a~b",
        "L" * 250,
        "L" * 249 + "M",
        "S" * 200 + "-one",
        "S" * 200 + "-two",
        "é" * 127,
        "e\u0301",
        "é",
        "\udce9",
        "\ud800",
    ]
    names = [safe_name(i) for i in ids]
    assert len(set(names)) == len(ids)
    for name in names:
        assert 0 < len(name) <= 120 and name not in (".", "..")
        assert set(name) <= set(string.ascii_letters + string.digits + "._-%~")


def _graded(student_id):
    return StudentResult(
        student_id=student_id,
        status="graded",
        lessons=[LessonResult(number="01", title="Frames", notebook="01.ipynb", status="graded")],
    )


def test_a_result_that_cannot_be_saved_still_reaches_the_gradebook(tmp_path, monkeypatch):
    outputs = class_run.Outputs(tmp_path / "out")
    stamp = class_run.Stamp("f", {})
    monkeypatch.setattr(class_run, "save_result", lambda *a: (_ for _ in ()).throw(OSError(28, "No space left")))
    task = class_run.GradingTask("mallory", str(tmp_path / "missing"), None, str(outputs.root), stamp, None)
    result = class_run.record_death(task, "the grading process was killed by SIGKILL")
    assert result.status == "could not grade" and "could not be saved" in result.problems[-1]
    monkeypatch.undo()
    class_run.save_result(outputs, _graded("ada"), stamp, "now")
    results = class_run.write_reports(outputs, THIS_COURSE, ["ada", "mallory"], {"ada", "mallory"}, {"mallory": result})
    assert {r.student_id: r.status for r in results} == {"ada": "graded", "mallory": "could not grade"}
    assert "mallory" in outputs.gradebook.read_text(encoding="utf-8")


def test_the_report_is_written_even_when_the_full_page_fails(tmp_path, monkeypatch):
    from autograder.reports import class_report

    outputs = class_run.Outputs(tmp_path / "out")
    class_run.save_result(outputs, _graded("esc\x1b[2J"), class_run.Stamp("f", {}), "now")
    monkeypatch.setattr(class_report, "class_report_html", lambda *a, **k: 1 / 0)
    class_run.write_reports(outputs, THIS_COURSE, ["esc\x1b[2J"], {"esc\x1b[2J"})
    page = outputs.report.read_text(encoding="utf-8")
    assert "ZeroDivisionError" in page and "esc\\x1b[2J" in page and "\x1b" not in page


def test_a_page_that_cannot_be_made_keeps_the_grade(tmp_path, monkeypatch):
    outputs = class_run.Outputs(tmp_path / "out")
    monkeypatch.setattr(class_run.feedback, "feedback_html", lambda result: 1 / 0)
    class_run.save_result(outputs, _graded("ada"), class_run.Stamp("f", {}), "now")
    assert class_run.load_saved(outputs, "ada").result.status == "graded"
    assert "could not be made" in outputs.feedback_html("ada").read_text(encoding="utf-8")


# ------------------------------------------------------------------ budgets per student (SECURITY.md)
GRADER_MEMORY = 1 << 30  # the project's bound on any one process of the grader (resident high-water mark)


@pytest.fixture(scope="module")
def filled(tmp_path_factory):
    """A student who fills every field they control to its bound, beside an honest one, graded by
    ``python -m autograder grade`` with the grader's memory sampled."""
    from adversarial_corpus import fill_every_field, filled_answer
    from process_memory import PeakMemory, is_grader
    from support import references

    base = tmp_path_factory.mktemp("filled")
    class_dir, out = base / "class", base / "out"
    answers = {name: filled_answer(source) for name, source in references().items()}
    build_submission(class_dir / "fills_every_field", answers, lessons=("01",))
    fill_every_field(class_dir / "fills_every_field")
    build_submission(class_dir / "honest", lessons=("01",))
    command = [sys.executable, "-m", "autograder", "grade", str(class_dir), "--out", str(out)]
    command += ["--lessons", "01", "--jobs", "1", "--no-nbval"]
    process = subprocess.Popen(command, cwd=PROJECT_ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    with PeakMemory(process.pid, only=is_grader) as memory:
        stdout, stderr = process.communicate(timeout=1500)
    return {"out": out, "returncode": process.returncode, "stderr": stderr, "memory": memory}


def _student_bytes(out, student_id):
    outputs = class_run.Outputs(out)
    return {kind: path.stat().st_size for kind, path in outputs.student_files(student_id)}


def test_a_student_who_fills_every_field_is_kept_within_the_budget(filled):
    """Every byte the student can make the grader keep is bounded where it is made: each text is cut with
    its marker, and the saved result, the feedback page and the Gradescope JSON are under their bounds; no
    process of the grader passes the project's 1 GiB while grading them (both figures are printed)."""
    from adversarial_corpus import FILL_MARK
    from autograder.grading import budget

    assert filled["returncode"] == 0, filled["stderr"][-2000:]
    sizes = _student_bytes(filled["out"], "fills_every_field")
    print(f"bytes kept for the student who fills every field: {sizes}, {sum(sizes.values())} in all")
    assert sizes["student"] <= budget.RESULT_BYTES and sizes["feedback"] <= budget.PAGE_BYTES, sizes
    assert sizes["gradescope"] <= budget.GRADESCOPE_BYTES, sizes
    assert sum(sizes.values()) <= budget.STUDENT_BYTES, sizes
    memory = filled["memory"]
    print(f"grader: largest process {memory.largest / 2**20:.0f} MiB, all together {memory.peak / 2**20:.0f} MiB")
    assert 0 < memory.largest < GRADER_MEMORY, memory.largest
    result = class_run.load_saved(class_run.Outputs(filled["out"]), "fills_every_field").result
    assert result.score == result.max_score > 0  # the bound changes no grade
    notes = [note for e in result.exercises for note in e.notes]
    assert notes and all(len(note) <= budget.STRING_CHARS + 40 for note in notes)
    assert any(FILL_MARK in note and "bytes more)" in note for note in notes)
    for texts in (result.problems, result.skipped):  # the long names it made the grader echo
        assert any(FILL_MARK in text for text in texts) and len(texts) <= budget.LIST_ITEMS + 1
        assert all(len(text) <= budget.STRING_CHARS + 40 for text in texts)
    assert result.answers, "the answers the similarity stage compares are kept by the grading process"


def test_saved_results_are_read_with_a_size_cap(filled, tmp_path):
    """``status``, ``export`` and the batch parent read at most RESULT_BYTES of a saved result."""
    from autograder.grading import budget

    out = tmp_path / "out"
    shutil.copytree(filled["out"], out)
    path = class_run.Outputs(out).student_json("honest")
    data = json.loads(path.read_text(encoding="utf-8"))
    data["result"]["reason"] = "r" * budget.RESULT_BYTES
    path.write_text(json.dumps(data), encoding="utf-8")
    assert class_run.load_saved(class_run.Outputs(out), "honest") is None
    results, _ = class_run.collect_results(class_run.Outputs(out), ["honest", "fills_every_field"])
    assert results[0].status == "could not grade" and results[1].score == results[1].max_score


def _forbid_parsing_student_text(monkeypatch, marks, calls):
    """In this process only (forked readers and graders may), refuse to read a notebook or to parse or
    tokenise a text that holds one of ``marks``; record each attempt in ``calls``."""
    from autograder.lessons import cells as cells_module
    from autograder.similarity import answers, fingerprints

    parent = os.getpid()

    def guard(name, function, check=lambda *args, **kwargs: True):
        def guarded(*args, **kwargs):
            if os.getpid() == parent and check(*args, **kwargs):
                calls.append(name)
                raise AssertionError(f"{name} in the similarity stage's parent")
            return function(*args, **kwargs)

        return guarded

    student_text = lambda code, *args, **kwargs: any(mark in code for mark in marks)  # noqa: E731
    monkeypatch.setattr(answers, "read_submission", guard("read_submission", answers.read_submission))
    monkeypatch.setattr(answers, "lesson_program", guard("lesson_program", answers.lesson_program))
    import copydetect.detector

    for module in (fingerprints, copydetect.detector):  # what tokenises, whoever calls it
        if hasattr(module, "filter_code"):
            monkeypatch.setattr(module, "filter_code", guard("filter_code", module.filter_code, student_text))
    monkeypatch.setattr(cells_module, "parse_source", guard("parse_source", cells_module.parse_source, student_text))


def _similarity_class(class_dir):
    from adversarial_corpus import fill_every_field, filled_answer
    from support import references

    mine = {name: source + "\n# mine\n" for name, source in references().items()}
    for student in ("ana", "bo"):
        build_submission(class_dir / student, mine, lessons=("01",))
    answers = {name: filled_answer(source) for name, source in references().items()}
    build_submission(class_dir / "fills_every_field", answers, lessons=("01",))
    fill_every_field(class_dir / "fills_every_field")


def test_the_similarity_stage_parses_nothing_in_the_batch_parent(tmp_path, monkeypatch):
    """Each student's answers are read, parsed and tokenised in their own grading process and kept in
    their result; the parent only hashes the normalised code it is given."""
    from adversarial_corpus import FILL_MARK
    from autograder.grading.pipeline import GradingOptions

    class_dir = tmp_path / "class"
    _similarity_class(class_dir)
    calls, stage = [], class_run._similarity_section

    def watched(*args, **kwargs):
        with pytest.MonkeyPatch.context() as patch:
            _forbid_parsing_student_text(patch, (FILL_MARK, "# mine"), calls)
            return stage(*args, **kwargs)

    monkeypatch.setattr(class_run, "_similarity_section", watched)
    summary = class_run.grade_class(
        class_dir, tmp_path / "out", THIS_COURSE, jobs=1, options=GradingOptions(nbval=False, lessons=("01",))
    )
    assert not calls and summary.similarity is not None, (calls, summary.similarity_note)
    assert summary.similarity.compared["rot_z"] >= 2  # the answers were compared
    assert {"ana", "bo"} <= {pair.first for pair in summary.similarity.reference_matches}


def test_the_similarity_command_reads_each_student_in_a_limited_fork(tmp_path, monkeypatch):
    """``python -m autograder similarity`` without saved results: each student is read in a forked
    process of its own, with limits; the parent parses nothing of a student's."""
    from adversarial_corpus import FILL_MARK
    from autograder.similarity.stage import similarity_of_class

    class_dir = tmp_path / "class"
    _similarity_class(class_dir)
    calls = []
    _forbid_parsing_student_text(monkeypatch, (FILL_MARK, "# mine"), calls)
    findings = similarity_of_class(class_dir, THIS_COURSE, jobs=2)
    assert not calls and not findings.unread, (calls, findings.unread)
    assert {"ana", "bo"} <= {pair.first for pair in findings.reference_matches}
