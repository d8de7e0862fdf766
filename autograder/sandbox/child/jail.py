"""Drop root, and give each student a world of their own (copied into every sandbox).

:func:`drop_privileges` is the old, simple wall: when the grader runs as root,
bubblewrap starts our processes as root inside fresh PID, network and mount
namespaces, and a process that runs grader-side helpers becomes an
unprivileged user with no capabilities first thing, so RLIMIT_NPROC applies
(the kernel exempts root from it).

:func:`enter_student_jail` is what every student's code runs in, cold or
forked from a warm slot: fresh **user, IPC, mount and PID** namespaces and a
fresh ``tmpfs`` on ``/tmp``, made for this student and gone with them. So the
reset between two students of a slot is by construction, not by a list of
things to clean: System V and POSIX IPC live in the IPC namespace, the user
and user-session keyrings in the user namespace, every file the student can
write in the tmpfs, every process in the PID namespace; when its first
process (the *feeder*, see ``feeder.py``) ends, the kernel kills the rest and
frees all of it. Nothing the student writes reaches the host's disk.

The student's uid inside is 1000, mapped to the sandbox's unprivileged user
outside; no capability survives into the feeder or the student's process,
and ``no_new_privs`` is set.

Examples
--------
>>> status_of_child = enter_student_jail(uid=4394304)      # doctest: +SKIP
>>> # here: PID 1 of the student's namespaces, /tmp empty and writable, no capabilities
"""

from __future__ import annotations

import ctypes
import os

NOBODY = 65534
INNER_UID = 1000
PR_SET_DUMPABLE = 4
PR_SET_NO_NEW_PRIVS = 38

CLONE_NEWNS = 0x00020000
CLONE_NEWIPC = 0x08000000
CLONE_NEWUSER = 0x10000000
CLONE_NEWPID = 0x20000000
MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC = 1, 2, 4, 8
MS_REMOUNT, MS_BIND, MS_REC, MS_PRIVATE = 32, 4096, 16384, 1 << 18
TMP_BYTES = 256 * 1024**2
# grader-side files of /sandbox that student code has no business reading (the probes implement
# operations some exercises ask for; the feeder reads them through a descriptor it opened first)
HIDDEN_FILES = ("probes.py", "zygote.py", "nbval_runner.py", "fork_kernel.py")


class JailError(OSError):
    """The student's namespaces could not be made: a fault of this machine, never of the student."""


def _libc():
    libc = ctypes.CDLL(None, use_errno=True)
    libc.mount.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p]
    return libc


def _check(result, what):
    if result != 0:
        number = ctypes.get_errno()
        raise JailError(number, f"{what}: {os.strerror(number)}")


def sandbox_uid(argv: list[str]) -> int:
    """The uid given as ``--uid N`` on the command line, else nobody."""
    if "--uid" in argv:
        return int(argv[argv.index("--uid") + 1])
    return NOBODY


def drop_privileges(uid: int = NOBODY) -> None:
    """Become ``uid`` (and its group) if running as root; forbid regaining privileges.

    The grader gives each concurrent sandbox its own uid, so that the process
    limit (RLIMIT_NPROC, counted per user) of one student never starves another.
    """
    if os.getuid() == 0:
        os.setgroups([])
        os.setgid(uid)
        os.setuid(uid)
    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
    except (OSError, AttributeError):
        pass


def _mount_points_under(folder):
    """Mount points below ``folder`` (read-only binds of a Python installed under /tmp, say), shallow first."""

    def unescape(path):  # mountinfo writes spaces and the like as octal escapes: \040
        out, i = [], 0
        while i < len(path):
            if path[i] == "\\" and path[i + 1 : i + 4].isdigit():
                out.append(chr(int(path[i + 1 : i + 4], 8)))
                i += 4
            else:
                out.append(path[i])
                i += 1
        return "".join(out)

    with open("/proc/self/mountinfo") as mounts:
        points = {unescape(line.split()[4]) for line in mounts if len(line.split()) > 4}
    inside = [p for p in points if p.startswith(folder.rstrip("/") + "/")]
    return sorted(inside, key=lambda p: (p.count("/"), p))


def _fresh_tmp(libc, size):
    """A new tmpfs on /tmp that keeps the read-only mounts below it (a Python installed under /tmp)."""
    kept = [(point, os.open(point, os.O_PATH | os.O_CLOEXEC)) for point in _mount_points_under("/tmp")]
    _check(
        libc.mount(b"tmpfs", b"/tmp", b"tmpfs", MS_NOSUID | MS_NODEV, f"size={size},mode=0777".encode()),
        "mount a tmpfs on /tmp",
    )
    for point, fd in kept:
        os.makedirs(point, mode=0o755, exist_ok=True)
        _check(
            libc.mount(f"/proc/self/fd/{fd}".encode(), point.encode(), None, MS_BIND | MS_REC, None), f"keep {point}"
        )
        libc.mount(None, point.encode(), None, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV, None)
        os.close(fd)
    # the folders made to reach those mount points belong to the sandbox's user; the student must not
    # be able to replace a Python installed there
    for point, _ in kept:
        parent = os.path.dirname(point)
        while parent not in ("/tmp", "/"):
            os.chmod(parent, 0o755)
            parent = os.path.dirname(parent)


def _hide(libc, folder, names):
    """Cover grader-only files of ``folder`` with an empty read-only file."""
    for name in names:
        path = os.path.join(folder, name)
        if os.path.exists(path):
            _check(libc.mount(b"/dev/null", path.encode(), None, MS_BIND, None), f"hide {path}")


def _map_user(outer_uid, outer_gid):
    with open("/proc/self/setgroups", "w") as handle:
        handle.write("deny")
    with open("/proc/self/uid_map", "w") as handle:
        handle.write(f"{INNER_UID} {outer_uid} 1")
    with open("/proc/self/gid_map", "w") as handle:
        handle.write(f"{INNER_UID} {outer_gid} 1")


def _drop_capabilities(libc):
    """Clear the effective, permitted and inheritable capability sets (capset, version 3)."""
    header = (ctypes.c_uint32 * 2)(0x20080522, 0)
    data = (ctypes.c_uint32 * 6)()
    _check(libc.capset(header, data), "drop capabilities")


def enter_student_jail(
    uid: int = NOBODY,
    keep_user: bool = False,
    sandbox_folder: str = "/sandbox",
    tmp_bytes: int = TMP_BYTES,
    keep_fds: tuple[int, ...] = (),
) -> None:
    """Make this process's student namespaces and return in PID 1 of them; the calling process never
    returns: it waits for that PID 1 and exits with its status (killed by the same signal).

    As root, this process first becomes ``uid`` (unless ``keep_user``), so RLIMIT_NPROC still
    counts the student's processes. ``keep_fds`` stay open in the returned process; every
    other descriptor but 0, 1 and 2 is closed.

    Raises
    ------
    JailError
        The namespaces could not be made (nothing of the student's has run yet).
    """
    libc = _libc()
    if os.getuid() == 0 and not keep_user:
        os.setgroups([])
        os.setgid(uid)
        os.setuid(uid)
    libc.prctl(PR_SET_DUMPABLE, 1, 0, 0, 0)  # a change of uid made /proc/self root's: take it back to map
    outer_uid, outer_gid = os.getuid(), os.getgid()
    _check(libc.unshare(CLONE_NEWUSER), "a new user namespace")
    _map_user(outer_uid, outer_gid)
    _check(libc.unshare(CLONE_NEWIPC | CLONE_NEWNS | CLONE_NEWPID), "new IPC, mount and PID namespaces")
    _check(libc.mount(None, b"/", None, MS_REC | MS_PRIVATE, None), "private mounts")
    _fresh_tmp(libc, tmp_bytes)
    _hide(libc, sandbox_folder, HIDDEN_FILES)
    os.chdir("/tmp")
    libc.prctl(PR_SET_DUMPABLE, 0, 0, 0, 0)
    pid = os.fork()
    if pid:
        _wait_and_mirror(pid)
    close_all_but(keep_fds)
    # PID 1 of the student's namespaces: a /proc of its own, when this kernel allows one here (as root,
    # bubblewrap's /proc has covered folders and a new one is refused; the old one shows no student)
    libc.mount(b"proc", b"/proc", b"proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, None)
    _drop_capabilities(libc)
    libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)


def close_all_but(keep_fds: tuple[int, ...] | list[int]) -> None:
    """Close every file descriptor but 0, 1, 2 and ``keep_fds``."""
    keep = sorted(set(keep_fds) | {0, 1, 2})
    for low, high in zip(keep, keep[1:] + [1 << 20]):
        os.closerange(low + 1, high)


def _wait_and_mirror(pid):
    """Wait for ``pid`` and end this process the way it ended."""
    import signal

    for number in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(number, signal.SIG_DFL)
    _, status = os.waitpid(pid, 0)  # retried by Python itself when a signal interrupts it (PEP 475)
    if os.WIFSIGNALED(status):
        signal.signal(os.WTERMSIG(status), signal.SIG_DFL)
        os.kill(os.getpid(), os.WTERMSIG(status))
    os._exit(os.WEXITSTATUS(status) if os.WIFEXITED(status) else 70)
