"""Drop root, and give each student a process that starts from nothing (copied into every sandbox).

:func:`drop_privileges` is the old, simple wall: when the grader runs as root,
bubblewrap starts our processes as root inside fresh PID, network and mount
namespaces, and a process that runs grader-side helpers becomes an
unprivileged user with no capabilities first thing, so RLIMIT_NPROC applies
(the kernel exempts root from it).

:func:`enter_student_jail` is what every student's code runs in, cold or
forked from a warm slot. A process inherits much more than its files from the
one that made it (fork(2), execve(2), credentials(7), keyrings(7)); every
piece of it is made fresh or empty here, for this student, before any of the
student's code runs (SECURITY.md, "What a student's process inherits"):

- fresh **user, IPC, mount, PID, network, UTS and cgroup** namespaces, with a
  fresh ``tmpfs`` on ``/tmp``, a network of its own loopback only (up, as
  bubblewrap leaves it) and the host name ``sandbox``;
- a new, empty, anonymous **session keyring**, made inside the new user
  namespace (so the grader's session keyring, and whatever an ssh login, a
  systemd service or a container put there, is no longer possessed); the
  user and user-session keyrings are those of the new user namespace, and
  ``/proc/keys`` and ``/proc/key-users`` are covered;
- no descriptor but the wire's and 0, 1, 2; every signal at its default (but
  SIGPIPE and SIGXFSZ ignored, as a fresh Python has them), an empty signal
  mask, no interval timer; the default personality (PER_LINUX: address space
  randomisation on); umask 022;
- no capability (effective, permitted, inheritable, ambient, and an empty
  bounding set) and ``no_new_privs``;
- last, a seccomp filter (:func:`key_filter`) under which ``add_key``,
  ``request_key`` and ``keyctl`` fail with EPERM, as do system calls of a
  foreign ABI (i386's on x86_64): keys are not namespaced, and as an ordinary
  user the student is the grader's user to the kernel, so without it student
  code that guessed the serial of one of that user's keyrings could describe
  it, list it and write into the user keyring. No answer needs keys.

In ``limits`` mode, where no namespace can be made, :func:`start_afresh` still gives
the student a new session keyring and fresh signals, timers, personality and umask,
then ``no_new_privs`` and the same filter.

So the reset between two students of a slot is by construction, not by a list
of things to clean: when the student's first process (the *feeder*, see
``feeder.py``) ends, the kernel kills the rest and frees all of it. Nothing the
student writes reaches the host's disk. The resource limits are the grader's
(``launcher.Limits``), set before this runs.

The student's uid inside is 1000, mapped to the sandbox's unprivileged user
outside.

Examples
--------
>>> status_of_child = enter_student_jail(uid=4394304)      # doctest: +SKIP
>>> # here: PID 1 of the student's namespaces, /tmp empty and writable, no capabilities, an empty @s
"""

from __future__ import annotations

import ctypes
import fcntl
import os
import platform
import signal
import socket
import stat
import struct

NOBODY = 65534
INNER_UID = 1000
PR_SET_DUMPABLE = 4
PR_SET_NO_NEW_PRIVS = 38
PR_CAPBSET_DROP = 24
PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL = 47, 4
PER_LINUX = 0

CLONE_NEWNS = 0x00020000
CLONE_NEWCGROUP = 0x02000000
CLONE_NEWUTS = 0x04000000
CLONE_NEWIPC = 0x08000000
CLONE_NEWUSER = 0x10000000
CLONE_NEWPID = 0x20000000
CLONE_NEWNET = 0x40000000
STUDENT_NAMESPACES = CLONE_NEWIPC | CLONE_NEWNS | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWUTS | CLONE_NEWCGROUP
HOSTNAME = b"sandbox"
SIOCGIFFLAGS, SIOCSIFFLAGS, IFF_UP = 0x8913, 0x8914, 0x1

# keyctl(2) has no libc wrapper: the syscall's number, per architecture (add_key, request_key, keyctl)
KEY_SYSCALLS = {
    "x86_64": (248, 249, 250),
    "aarch64": (217, 218, 219),
    "riscv64": (217, 218, 219),
    "loongarch64": (217, 218, 219),
    "ppc64le": (269, 270, 271),
    "ppc64": (269, 270, 271),
    "s390x": (278, 279, 280),
    "i386": (286, 287, 288),
    "i586": (286, 287, 288),
    "i686": (286, 287, 288),
    "armv6l": (309, 310, 311),
    "armv7l": (309, 310, 311),
    "armv8l": (309, 310, 311),
}
# the architecture a system call's ``seccomp_data.arch`` names (AUDIT_ARCH_*, linux/audit.h), per machine:
# the filter lets through only the native ABI's calls (not i386's ``int 0x80`` on x86_64, nor arm32's on arm64)
AUDIT_ARCHES = {
    "x86_64": 0xC000003E,
    "aarch64": 0xC00000B7,
    "riscv64": 0xC00000F3,
    "loongarch64": 0xC0000102,
    "ppc64le": 0xC0000015,
    "ppc64": 0x80000015,
    "s390x": 0x80000016,
    "i386": 0x40000003,
    "i586": 0x40000003,
    "i686": 0x40000003,
    "armv6l": 0x40000028,
    "armv7l": 0x40000028,
    "armv8l": 0x40000028,
}
AUDIT_ARCH_64BIT = 0x80000000
X32_SYSCALL_BIT = 0x40000000  # x86_64's x32 ABI: the same arch, numbers with this bit
PR_SET_SECCOMP, SECCOMP_MODE_FILTER = 22, 2
BPF_LD_W_ABS, BPF_JEQ_K, BPF_JGE_K, BPF_RET_K = 0x20, 0x15, 0x35, 0x06
SECCOMP_RET_ALLOW, SECCOMP_RET_ERRNO = 0x7FFF0000, 0x00050000
KEYS_REFUSED_WITH = 1  # EPERM, as Docker's default profile and most containers answer keyctl
KEY_SPEC_SESSION_KEYRING = -3
KEYCTL_GET_KEYRING_ID, KEYCTL_JOIN_SESSION_KEYRING, KEYCTL_READ, KEYCTL_SET_REQKEY_KEYRING = 0, 1, 11, 14
# what a fresh Python ignores itself (Python/pylifecycle.c): a write to a closed pipe or past RLIMIT_FSIZE
# raises an OSError instead of killing the process
PYTHON_IGNORES = (signal.SIGPIPE, signal.SIGXFSZ)
# the kernel's list of every key and keyring this user may see, with serials: covered, so that a key of the
# grader's own user (as an ordinary user the student is that user to the kernel) cannot be looked up by it
KEY_LISTS = ("/proc/keys", "/proc/key-users")
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
        if stat.S_ISDIR(os.fstat(fd).st_mode):
            os.makedirs(point, mode=0o755, exist_ok=True)
        else:  # the allow-list binds single files too (a module, a shared library): their mount point is a file
            os.makedirs(os.path.dirname(point), mode=0o755, exist_ok=True)
            os.close(os.open(point, os.O_WRONLY | os.O_CREAT | os.O_CLOEXEC, 0o644))
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
    """Empty the bounding and ambient sets, then the effective, permitted and inheritable ones (capset,
    version 3): no capability now, and none that an execve could give back."""
    for number in range(64):
        if libc.prctl(PR_CAPBSET_DROP, number, 0, 0, 0) != 0 and ctypes.get_errno() == 22:
            break  # EINVAL: past the kernel's last capability
    libc.prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0)  # EINVAL on kernels before 4.3: none there
    header = (ctypes.c_uint32 * 2)(0x20080522, 0)
    data = (ctypes.c_uint32 * 6)()
    _check(libc.capset(header, data), "drop capabilities")


def _key_syscall(libc, which, *args):
    """``add_key``/``request_key``/``keyctl`` (``which`` 0, 1, 2) by number."""
    libc.syscall.restype = ctypes.c_long
    return libc.syscall(KEY_SYSCALLS[platform.machine()][which], *args)


def _fresh_session_keyring(libc, strict=True):
    """Join a new anonymous session keyring, empty, and make it where request_key(2) puts keys.

    The session keyring is inherited by fork and kept by execve and by a new user namespace, so without
    this the student would possess the grader's (an ssh login's, a service's): read its keys, change
    them, leave some for later. Where keyrings cannot be used at all (a kernel without them, a seccomp
    filter that refuses keyctl), there is nothing to possess; if the join fails while the old session
    keyring can still be reached, no student may run here. On a machine whose keyctl number is not
    known here, ``strict`` refuses too (the namespaces probe then says so, and the grader falls back to
    limits mode, loudly); limits mode itself (not ``strict``) goes on without.
    """
    if platform.machine() not in KEY_SYSCALLS:
        if strict:
            raise JailError(38, f"a new session keyring: keyctl's number on {platform.machine()} is not known")
        return
    if _key_syscall(libc, 2, KEYCTL_JOIN_SESSION_KEYRING, None) < 0:
        number = ctypes.get_errno()
        if _key_syscall(libc, 2, KEYCTL_GET_KEYRING_ID, KEY_SPEC_SESSION_KEYRING, 0) >= 0:
            raise JailError(number, f"a new session keyring: {os.strerror(number)}")
        return
    _key_syscall(libc, 2, KEYCTL_SET_REQKEY_KEYRING, 0)  # KEY_REQKEY_DEFL_DEFAULT
    held = _key_syscall(libc, 2, KEYCTL_READ, KEY_SPEC_SESSION_KEYRING, None, 0)
    if held != 0:
        raise JailError(0, f"the new session keyring is not empty ({held} bytes of serials)")


class _SockFprog(ctypes.Structure):
    """``struct sock_fprog``: the number of instructions, and where they are (``struct sock_filter[]``)."""

    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def key_filter(machine: str) -> list[tuple[int, int, int, int]]:
    """The seccomp program (classic BPF: ``(code, jt, jf, k)``) that refuses ``add_key``, ``request_key``
    and ``keyctl`` with EPERM, and every call of a foreign ABI (their numbers differ), and allows the rest.

    >>> len(key_filter("x86_64")), key_filter("x86_64")[-1]
    (10, (6, 0, 0, 327681))
    """
    refuse = SECCOMP_RET_ERRNO | KEYS_REFUSED_WITH
    checks = [(BPF_JGE_K, X32_SYSCALL_BIT)] if machine == "x86_64" else []
    checks += [(BPF_JEQ_K, number) for number in KEY_SYSCALLS[machine]]
    program = [
        (BPF_LD_W_ABS, 0, 0, 4),  # seccomp_data.arch
        (BPF_JEQ_K, 1, 0, AUDIT_ARCHES[machine]),
        (BPF_RET_K, 0, 0, refuse),
        (BPF_LD_W_ABS, 0, 0, 0),  # seccomp_data.nr
    ]
    for index, (code, k) in enumerate(checks):
        program.append((code, len(checks) - index, 0, k))  # to the last instruction: refuse
    return program + [(BPF_RET_K, 0, 0, SECCOMP_RET_ALLOW), (BPF_RET_K, 0, 0, refuse)]


def _native_key_filter():
    """:func:`key_filter` for this machine as prctl(2) takes it (a ``struct sock_fprog`` and the
    ``struct sock_filter[]`` it points to), or None when its numbers are not known here (a 32-bit Python
    on a 64-bit kernel calls another ABI than uname's)."""
    machine = platform.machine()
    if machine not in KEY_SYSCALLS or machine not in AUDIT_ARCHES:
        return None
    if bool(AUDIT_ARCHES[machine] & AUDIT_ARCH_64BIT) != (struct.calcsize("P") == 8):
        return None
    program = key_filter(machine)
    instructions = ctypes.create_string_buffer(b"".join(struct.pack("=HBBI", *line) for line in program))
    return _SockFprog(len(program), ctypes.addressof(instructions)), instructions


# made on import: in a warm slot once, by the zygote (which never installs it), not in each worker
KEY_FILTER = _native_key_filter()


def _refuse_keys(libc, strict=True):
    """Install :func:`key_filter` on this process (kept by its children, never removable): no key or
    keyring of anyone's can be reached by serial number, not even one of the grader's own user (as an
    ordinary user the student is that user to the kernel). ``no_new_privs`` must be set.

    On a machine whose numbers are not known here, or whose kernel takes no filter while keyrings can be
    used, ``strict`` refuses (the namespaces probe then says so, and the grader falls back to limits mode,
    loudly); limits mode itself (not ``strict``) goes on without.
    """
    if KEY_FILTER is None:
        if strict:
            raise JailError(38, f"a filter of keyctl: the system calls' numbers on {platform.machine()} are not known")
        return
    if libc.prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.byref(KEY_FILTER[0]), 0, 0) != 0:
        number = ctypes.get_errno()
        if strict and _key_syscall(libc, 2, KEYCTL_GET_KEYRING_ID, KEY_SPEC_SESSION_KEYRING, 0) >= 0:
            raise JailError(number, f"a filter of keyctl: {os.strerror(number)}")


def _loopback_up():
    """Bring up ``lo`` of the new network namespace, as bubblewrap does for its own (a student's code
    may talk to itself over 127.0.0.1, as a notebook can; nothing else is reachable). Where the kernel
    will not (no IPv4), ``lo`` stays down: the namespace is the student's either way."""
    try:
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
            request = struct.pack("16sH22x", b"lo", 0)
            flags = struct.unpack("16sH22x", fcntl.ioctl(probe.fileno(), SIOCGIFFLAGS, request))[1]
            fcntl.ioctl(probe.fileno(), SIOCSIFFLAGS, struct.pack("16sH22x", b"lo", flags | IFF_UP))
    except OSError:
        pass


def _fresh_process_state(libc):
    """Signals, timers, personality and umask as a fresh process has them, whatever the grader had.

    Ignored signals and the signal mask survive fork and execve (signal(7)), so does an interval timer
    across execve (setitimer(2)), and so does the personality (personality(2); ADDR_NO_RANDOMIZE, under
    ``setarch -R`` or a debugger, would turn off address randomisation for the student's processes).
    """
    for number in signal.valid_signals():
        try:
            signal.signal(number, signal.SIG_IGN if number in PYTHON_IGNORES else signal.SIG_DFL)
        except (OSError, ValueError):  # SIGKILL and SIGSTOP cannot be changed
            pass
    signal.pthread_sigmask(signal.SIG_SETMASK, ())
    for timer in (signal.ITIMER_REAL, signal.ITIMER_VIRTUAL, signal.ITIMER_PROF):
        signal.setitimer(timer, 0)
    libc.personality(PER_LINUX)
    os.umask(0o022)


def _cover_key_lists(libc):
    """Cover the kernel's lists of keys of the student's own /proc (see :data:`KEY_LISTS`)."""
    for path in KEY_LISTS:
        if os.path.exists(path):
            _check(libc.mount(b"/dev/null", path.encode(), None, MS_BIND, None), f"cover {path}")


def start_afresh() -> None:
    """What can be made fresh without namespaces (``limits`` mode): a new, empty session keyring, and
    signals, timers, personality and umask as a fresh process has them; then ``no_new_privs`` and the
    filter that refuses every key system call (:func:`key_filter`).

    Raises
    ------
    JailError
        The grader's session keyring could not be left.
    """
    libc = _libc()
    _fresh_session_keyring(libc, strict=False)
    _fresh_process_state(libc)
    libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
    _refuse_keys(libc, strict=False)


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
    _check(libc.unshare(STUDENT_NAMESPACES), "new IPC, mount, PID, network, UTS and cgroup namespaces")
    _fresh_session_keyring(libc)  # inside the new user namespace: the student's own, not the grader's
    _check(libc.sethostname(HOSTNAME, len(HOSTNAME)), "a host name of its own")
    _loopback_up()
    _check(libc.mount(None, b"/", None, MS_REC | MS_PRIVATE, None), "private mounts")
    _fresh_tmp(libc, tmp_bytes)
    _hide(libc, sandbox_folder, HIDDEN_FILES)
    os.chdir("/tmp")
    _fresh_process_state(libc)
    libc.prctl(PR_SET_DUMPABLE, 0, 0, 0, 0)
    pid = os.fork()
    if pid:
        _wait_and_mirror(pid)
    close_all_but(keep_fds)
    # PID 1 of the student's namespaces: a /proc of its own, when this kernel allows one here (as root,
    # bubblewrap's /proc has covered folders and a new one is refused; the old one shows no student)
    libc.mount(b"proc", b"/proc", b"proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, None)
    _cover_key_lists(libc)
    _drop_capabilities(libc)
    libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
    _refuse_keys(libc)


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
