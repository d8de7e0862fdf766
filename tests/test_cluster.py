"""Grading on a Dask cluster (``grade --cluster``, autograder/integrations/cluster.py): the same results as local grading,
and faults that cost nothing or are recorded.

Oracle: local grading of the same class (``grade --jobs 2``, the forked pool). Each student's saved result,
``OUT/students/<id>.json``, must be equal byte for byte after removing the only fields that measure time:
``graded_at`` (when the student was graded) and ``seconds`` (how long it took); they differ between any two
runs, local or not. The feedback pages must be equal byte for byte as they are, and the Gradescope
``results/<id>.json`` after removing ``execution_time`` (the same ``seconds``).

Edge cases guarded: a worker process killed mid-student (the student is re-graded elsewhere, every grade is
still right); a student whose task is under two dying workers ("could not grade", the batch finishes); a
missing submissions path and an unreachable scheduler (clear error, exit status 2, nothing written); a
worker whose sandbox is weaker than the driver's (refused, with the reason); a submission's bytes, links
and modification times (the late policy reads them) arriving intact on the worker.

Fast on 2 cores: lesson 01 only, 5 students, 2 worker processes, the notebook stage only where the point is
identical results.
"""

import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import psutil
import pytest

from autograder.grading import submissions
from autograder.integrations.cluster import pack_submission, unpack_submission
from autograder.lessons.paths import PROJECT_ROOT
from autograder.reports.lateness import submission_time
from autograder.sandbox import launcher
from support import STUB, build_submission, mistakes

LESSON = "01"
TIME_FIELDS = ("graded_at", "seconds")


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    """Five students of lesson 01: full marks twice, untouched stubs, a typical mistake, a damaged notebook."""
    root = tmp_path_factory.mktemp("cluster-class")
    build_submission(root / "ada", lessons=(LESSON,))
    build_submission(root / "bob", default=STUB, lessons=(LESSON,))
    build_submission(root / "cy", {"rot_z": mistakes()["rot_z_transposed"].source}, lessons=(LESSON,))
    build_submission(root / "dee", lessons=(LESSON,))
    (root / "eve").mkdir()
    (root / "eve" / "01_frames_and_rotations.ipynb").write_text("{not json", encoding="utf-8")
    return root


def _grade(klass, out, *extra, timeout=420):
    command = [sys.executable, "-m", "autograder", "grade", str(klass), "--out", str(out), "--lessons", LESSON, *extra]
    run = subprocess.run(command, cwd=PROJECT_ROOT, capture_output=True, text=True, timeout=timeout)
    return run


def _without(value, fields):
    if isinstance(value, dict):
        return {k: _without(v, fields) for k, v in value.items() if k not in fields}
    if isinstance(value, list):
        return [_without(v, fields) for v in value]
    return value


def _saved(out, folder="students", fields=TIME_FIELDS):
    """``{file name: canonical JSON text without the time fields}`` of a results folder."""
    return {
        path.name: json.dumps(
            _without(json.loads(path.read_text(encoding="utf-8")), fields), indent=1, sort_keys=True, ensure_ascii=False
        )
        for path in sorted((Path(out) / folder).glob("*.json"))
    }


def _grades(out):
    """``{student: saved result without the time fields}``: what the fault tests compare (the grader's
    fingerprint, also saved, is left out there: it is compared by the first test)."""
    return {name: json.loads(text)["result"] for name, text in _saved(out).items()}


@pytest.fixture(scope="module")
def local_fast(klass, tmp_path_factory):
    """The class graded locally without the notebook stage: the oracle of the fault tests."""
    out = tmp_path_factory.mktemp("local-fast")
    run = _grade(klass, out, "--no-nbval", "--jobs", "2")
    assert run.returncode == 0, run.stderr[-2000:]
    return out


def test_cluster_results_equal_local_results(klass, tmp_path):
    local, cluster = tmp_path / "local", tmp_path / "cluster"
    run = _grade(klass, local, "--jobs", "2")
    assert run.returncode == 0, run.stderr[-2000:]
    run = _grade(klass, cluster, "--cluster", "local:2")
    assert run.returncode == 0, run.stderr[-2000:]
    assert "cluster: 2 worker(s) ready" in run.stdout, run.stdout
    expected = _saved(local)
    assert sorted(expected) == [f"{s}.json" for s in ("ada", "bob", "cy", "dee", "eve")]
    assert _saved(cluster) == expected
    for page in sorted((local / "feedback").glob("*.html")):
        assert (cluster / "feedback" / page.name).read_bytes() == page.read_bytes(), page.name
    gradescope = ("execution_time",)
    assert _saved(cluster, "results", gradescope) == _saved(local, "results", gradescope)
    scores = {
        json.loads(text)["result"]["student_id"]: json.loads(text)["result"]["score"] for text in expected.values()
    }
    assert scores["ada"] == scores["dee"] > scores["cy"] > scores["bob"] == scores["eve"] == 0


@pytest.fixture(scope="module")
def dask_cluster():
    """A LocalCluster of 2 worker processes on loopback, and a client of the test's own to watch it (the fault
    tests share it: a worker that survives keeps its passed check, a restarted one runs it again)."""
    import dask
    from distributed import Client, LocalCluster

    # One task at a time per worker (the scheduler keeps the rest queued): a killed worker then takes down
    # exactly one student's grading, which the fault tests count on. With the default saturation (1.1) a
    # one-thread worker may hold a second, queued task, and its death counts against both.
    with (
        dask.config.set({"distributed.scheduler.worker-saturation": 1.0}),
        LocalCluster(
            n_workers=2, processes=True, threads_per_worker=1, host="127.0.0.1", dashboard_address="127.0.0.1:0"
        ) as cluster,
        Client(cluster) as client,
    ):
        yield cluster, client


def _kill_worker_grading(client, key=None, timeout=240):
    """SIGKILL the worker process that is grading a student (the task ``key``, or any) while its grading
    fork runs; return the task's key.

    Only a worker that holds that one task is killed. A dead worker's task is re-run wherever the scheduler
    sends it, which can be a worker already grading another student; killing that worker would count a death
    against both students, and the fault tests count the deaths of one."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        for address, held in client.processing().items():
            keys = [k for k in held if str(k).startswith("autograder-grade-") and key in (None, k)]
            if not keys or len(held) != 1:
                continue
            try:
                pid = client.run(os.getpid, workers=[address])[address]
                busy = psutil.Process(pid).children()
            except Exception:  # the worker is leaving or restarting
                continue
            if busy:  # the fork that grades the student
                os.kill(pid, signal.SIGKILL)
                return keys[0]
        time.sleep(0.05)
    raise AssertionError(f"no worker was grading {key or 'a student'} within {timeout} s")


def _start_grading(klass, out, address):
    command = [
        sys.executable,
        "-m",
        "autograder",
        "grade",
        str(klass),
        "--out",
        str(out),
        "--lessons",
        LESSON,
        "--no-nbval",
        "--cluster",
        address,
    ]
    return subprocess.Popen(command, cwd=PROJECT_ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def test_a_worker_killed_mid_student_costs_nothing(klass, local_fast, dask_cluster, tmp_path):
    cluster, client = dask_cluster
    out = tmp_path / "out"
    grading = _start_grading(klass, out, cluster.scheduler_address)
    try:
        _kill_worker_grading(client)
        stdout, stderr = grading.communicate(timeout=300)
    finally:
        grading.kill()
    assert grading.returncode == 0, stderr[-2000:]
    assert _grades(out) == _grades(local_fast)


def test_a_student_under_two_dying_workers_could_not_be_graded(klass, local_fast, dask_cluster, tmp_path):
    cluster, client = dask_cluster
    out = tmp_path / "out"
    grading = _start_grading(klass, out, cluster.scheduler_address)
    try:
        key = _kill_worker_grading(client)
        _kill_worker_grading(client, key)  # its retry, on the other worker
        stdout, stderr = grading.communicate(timeout=300)
    finally:
        grading.kill()
    assert grading.returncode == 0, stderr[-2000:]
    saved, expected = _grades(out), _grades(local_fast)
    lost = [name for name in expected if saved[name] != expected[name]]
    assert len(lost) == 1, (lost, stdout[-3000:])
    result = saved[lost[0]]
    assert result["status"] == "could not grade"
    assert "the Dask workers grading this student died 2 times" in result["reason"], result["reason"]
    assert "run grade again to retry" in result["reason"]


def test_a_missing_path_or_scheduler_fails_clearly_and_writes_nothing(klass, tmp_path):
    """There is no shared path in this design (submissions travel as bytes): the only path is the driver's
    SUBMISSIONS, checked before any cluster starts; an unreachable scheduler is the other thing to miss."""
    out = tmp_path / "out"
    run = _grade(tmp_path / "no-such-class", out, "--cluster", "local:2", timeout=60)
    assert run.returncode == 2
    assert "no-such-class is not a folder of student submissions" in run.stderr
    assert "cluster:" not in run.stdout and not out.exists()

    with socket.socket() as probe:  # a loopback port where nothing listens
        probe.bind(("127.0.0.1", 0))
        unused = probe.getsockname()[1]
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "autograder",
            "grade",
            str(klass),
            "--out",
            str(out),
            "--cluster",
            f"tcp://127.0.0.1:{unused}",
        ],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=120,
        env=dict(os.environ, DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="2s"),
    )
    assert run.returncode == 2
    assert f"cannot reach the Dask scheduler at tcp://127.0.0.1:{unused} within 2 s" in run.stderr, run.stderr
    assert not out.exists()

    run = _grade(klass, out, "--cluster", "local:zero", timeout=60)
    assert run.returncode == 2 and "local:N needs a number of worker processes" in run.stderr
    assert not out.exists()


@pytest.mark.skipif(launcher.isolation()[0] != "namespaces", reason="the driver itself has limits only here")
def test_a_worker_with_a_weaker_sandbox_is_refused(klass, tmp_path):
    from distributed import LocalCluster

    out = tmp_path / "out"
    with LocalCluster(
        n_workers=1,
        processes=True,
        threads_per_worker=1,
        host="127.0.0.1",
        dashboard_address="127.0.0.1:0",
        env={"AUTOGRADER_SANDBOX": "limits"},
    ) as cluster:
        run = _grade(klass, out, "--no-nbval", "--cluster", cluster.scheduler_address, timeout=180)
    assert run.returncode == 2
    assert "refused worker" in run.stdout and "its sandbox is weaker than the driver's: limits" in run.stdout
    assert "where the driver isolates student code with namespaces" in run.stdout
    assert "no worker of the cluster can grade, so nothing was graded or written" in run.stderr
    assert not out.exists()


def test_a_packed_submission_arrives_intact(tmp_path):
    """Bytes, names, links (kept as links), nbgrader timestamps and modification times (the late policy
    falls back on them) survive the trip; hidden folders, deep folders and other files stay behind."""
    folder = build_submission(tmp_path / "class" / "zoe", lessons=(LESSON,))
    notebook = next(folder.glob("*.ipynb"))
    os.utime(notebook, ns=(1_700_000_000_123_456_789, 1_700_000_000_123_456_789))
    (folder / "late").mkdir()
    (folder / "late" / "again.ipynb").write_bytes(notebook.read_bytes())
    (folder / "late" / "timestamp.txt").write_text("2026-01-02 03:04:05 UTC")
    (folder / "link.ipynb").symlink_to("../../etc/passwd")
    (folder / ".hidden").mkdir()
    (folder / ".hidden" / "x.ipynb").write_text("{}")
    (folder / "a" / "b" / "c").mkdir(parents=True)
    (folder / "a" / "b" / "c" / "deep.ipynb").write_text("{}")
    (folder / "data.bin").write_bytes(b"\0" * 4096)

    payload = pack_submission(folder)
    names = sorted(entry[0] for entry in payload["entries"])
    assert names == sorted([notebook.name, "late/again.ipynb", "late/timestamp.txt", "link.ipynb"])
    copy = unpack_submission(payload, tmp_path / "worker")
    assert copy.name == "zoe"
    assert submissions.submission_hash(copy) == submissions.submission_hash(folder)
    assert os.readlink(copy / "link.ipynb") == "../../etc/passwd"
    assert (copy / notebook.name).stat().st_mtime_ns == notebook.stat().st_mtime_ns
    for name in (notebook.name, "late/again.ipynb"):
        assert submission_time(copy / name, copy) == submission_time(folder / name, folder)

    for bad in ("../escape.ipynb", "/etc/x.ipynb"):
        evil = dict(payload, entries=[(bad, "file", b"{}", 0)])
        with pytest.raises(ValueError):
            unpack_submission(evil, tmp_path / f"evil-{len(bad)}")
