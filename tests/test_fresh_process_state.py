"""A student's process starts from nothing: every piece of per-process state it could inherit is fresh.

Oracles, read from inside a student's process through the real grading path (a cold
``StudentSandbox`` and a warm slot's worker) and compared with the grader's own (this test's
process) and with another student's of the same slot:

- the namespaces (``/proc/self/ns``: user, mount, PID, IPC, UTS, network, cgroup) are none of the
  grader's and none of the other student's. Namespace inode numbers are reused once a namespace is
  freed, so the other student is compared while it is still running (a second worker of the same
  slot), never after: two live namespaces with one number are one namespace;
- no key system call works: ``keyctl``, ``add_key`` and ``request_key`` fail with EPERM (the jail's
  seccomp filter), through the native ABI, x86_64's x32 numbers and i386's ``int 0x80`` alike. The
  grader first makes itself a session keyring holding an instructor's key, as an ssh login with
  pam_keyinit, a systemd service or a container gives it one, and plants a key in its user keyring
  (``_uid.N``); student code that knows every serial number (more than a real student would) can
  neither describe nor read nor change nor link any of them, nor list or write into those keyrings,
  nor find the key by name, in both modes: as an ordinary user, where the student is the grader's user
  to the kernel, too. Nothing a student tries to leave in a keyring reaches the next student or the
  grader. Behind the filter, the jail's new empty session keyring (defence in depth) is checked by
  running its step alone, in a new user namespace, in a child of this test;
- only the loopback interface (up), only 0, 1, 2 and the wire's descriptors, every signal at its
  default (but SIGPIPE and SIGXFSZ, which a fresh Python ignores), an empty signal mask, no capability
  in any set, ``no_new_privs``, the default personality, umask 022, the grader's resource limits.

The grader is made "dirty" first, so that an inherited piece of state shows: it ignores SIGHUP and
SIGUSR1, blocks SIGUSR2, has umask 077, the ADDR_NO_RANDOMIZE personality and the keys above.
"""

import ctypes
import json
import os
import platform
import signal

import pytest

from autograder.sandbox import launcher, warm
from autograder.sandbox.child import jail
from autograder.sandbox.session import LessonProgram, StudentSandbox
from support import THIS_COURSE, started_warm_slot

NAMESPACES = ("user", "mnt", "pid", "ipc", "uts", "net", "cgroup")
KEY_SYSCALLS = {"x86_64": (248, 249, 250), "aarch64": (217, 218, 219)}  # add_key, request_key, keyctl
ADDR_NO_RANDOMIZE = 0x0040000
KEY_SPEC_SESSION_KEYRING, KEY_SPEC_USER_KEYRING = -3, -4
REFUSED = "EPERM"  # what every key system call of a student's gets (jail.KEYS_REFUSED_WITH)

pytestmark = [
    pytest.mark.skipif(launcher.isolation()[0] != "namespaces", reason="a student's own namespaces need bubblewrap"),
    pytest.mark.skipif(platform.machine() not in KEY_SYSCALLS, reason="keyctl's syscall number is not known here"),
]

# runs inside the student's process; ``grader`` is what the grader holds (its keyring and key serials)
READ_STATE = r"""
import ctypes, errno, fcntl, mmap, os, platform, resource, socket, struct

ADD_KEY, REQUEST_KEY, KEYCTL = {"x86_64": (248, 249, 250), "aarch64": (217, 218, 219)}[platform.machine()]
libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
libc.personality.restype = ctypes.c_int
REFUSED = "EPERM"

def attempt(result):
    return result if result >= 0 else errno.errorcode.get(ctypes.get_errno(), "?")  # "EPERM", say

def keyctl(*args):
    return attempt(libc.syscall(KEYCTL, *args))

def read_key(serial):
    buffer = ctypes.create_string_buffer(4096)
    size = keyctl(11, serial, buffer, 4096)                                   # KEYCTL_READ
    return buffer.raw[:size].hex() if isinstance(size, int) else size         # bytes do not cross the wire

# keyctl(KEYCTL_GET_KEYRING_ID, @u) through i386's system calls (int 0x80: keyctl is 288 there), in a
# child, which a kernel without i386 emulation kills; its exit code is the errno (0: it worked)
I386_KEYCTL = bytes.fromhex("b820010000" "31db" "b9fcffffff" "31d2" "cd80" "c3")

def i386_keyctl():
    if platform.machine() != "x86_64":
        return REFUSED
    pid = os.fork()
    if pid == 0:
        page = mmap.mmap(-1, 4096, prot=mmap.PROT_READ | mmap.PROT_WRITE | mmap.PROT_EXEC)
        page.write(I386_KEYCTL)
        result = ctypes.CFUNCTYPE(ctypes.c_int)(ctypes.addressof(ctypes.c_char.from_buffer(page)))()
        os._exit(min(-result, 255) if result < 0 else 0)
    status = os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1])
    if status == -11:                                                          # SIGSEGV: no i386 ABI at all
        return REFUSED
    return errno.errorcode.get(status, status) if status > 0 else status

def x32_keyctl():
    if platform.machine() != "x86_64":
        return REFUSED
    return attempt(libc.syscall(KEYCTL | 0x40000000, 0, -4, 0))                # x32's numbers: bit 30 set

def state(grader):
    status = dict(line.split(":", 1) for line in open("/proc/self/status"))
    fds = {}
    for fd in os.listdir("/proc/self/fd"):
        try:
            fds[fd] = os.readlink(f"/proc/self/fd/{fd}")
        except OSError:                                                        # the listing's own descriptor
            pass
    interfaces = [line.split(":")[0].strip() for line in open("/proc/net/dev").read().splitlines()[2:]]
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        lo_flags = struct.unpack("16sH22x", fcntl.ioctl(probe.fileno(), 0x8913, struct.pack("16sH22x", b"lo", 0)))[1]
    umask = os.umask(0o022)
    os.umask(umask)
    description = ctypes.create_string_buffer(256)
    return {
        "ns": {name: os.stat(f"/proc/self/ns/{name}").st_ino for name in os.listdir("/proc/self/ns")},
        "status": {key: value.strip() for key, value in status.items()},
        "fds": fds,
        "interfaces": interfaces,
        "lo_up": bool(lo_flags & 1),
        "hostname": os.uname().nodename,
        "umask": umask,
        "personality": libc.personality(0xFFFFFFFF),
        "limits": {name: resource.getrlimit(getattr(resource, name))[0]
                   for name in ("RLIMIT_FSIZE", "RLIMIT_NOFILE", "RLIMIT_CORE", "RLIMIT_NPROC", "RLIMIT_AS")},
        "keys": {
            "session": keyctl(0, -3, 0),                                       # KEYCTL_GET_KEYRING_ID @s
            "session_holds": read_key(-3),
            "user_keyring": keyctl(0, -4, 0),                                  # @u
            "user_holds": read_key(-4),
            "user_session_holds": read_key(-5),                                # @us
            "grader_key": read_key(grader["key"]),
            "grader_key_described": keyctl(6, grader["key"], description, 256),  # KEYCTL_DESCRIBE
            "grader_session_listed": read_key(grader["session"]),
            "grader_session_described": keyctl(6, grader["session"], description, 256),
            "grader_user_key": read_key(grader["user_key"]),
            "grader_user_key_described": keyctl(6, grader["user_key"], description, 256),
            "grader_user_listed": read_key(grader["user"]),
            "grader_user_described": keyctl(6, grader["user"], description, 256),
            "found_by_name": attempt(libc.syscall(REQUEST_KEY, b"user", b"instructor-key", None, 0)),
            "updated": keyctl(2, grader["key"], b"rewritten", 9),             # KEYCTL_UPDATE
            "linked_grader_key": keyctl(8, grader["key"], -3),                 # KEYCTL_LINK into @s
            "linked_grader_session": keyctl(8, grader["session"], -3),
            "linked_into_grader_user": keyctl(8, -3, grader["user"]),          # @s into the grader's @u
            "added_to_grader_user": attempt(libc.syscall(ADD_KEY, b"user", b"planted", b"x", 1, grader["user"])),
            "left_key": attempt(libc.syscall(REQUEST_KEY, b"user", b"left-behind", None, 0)),
            "x32": x32_keyctl(),
            "i386": i386_keyctl(),
        },
        "proc_keys": open("/proc/keys").read() if os.path.exists("/proc/keys") else "",
    }

def leave():
    return [attempt(libc.syscall(ADD_KEY, b"user", b"left-behind", b"the previous student's work", 27, ring))
            for ring in (-3, -4, -5)]                                          # @s, @u, @us
"""


def _program():
    return {"01": LessonProgram(setup="import numpy as np", cells=[("code", READ_STATE)])}


def _keyctl(*args):
    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    result = libc.syscall(KEY_SYSCALLS[platform.machine()][2], *args)
    if result < 0:
        raise OSError(ctypes.get_errno(), os.strerror(ctypes.get_errno()))
    return result


def _read_key(serial):
    buffer = ctypes.create_string_buffer(4096)
    size = _keyctl(11, serial, buffer, 4096)
    return buffer.raw[:size]


def _serials(held):
    return [int.from_bytes(held[i : i + 4], "little") for i in range(0, len(held), 4)]


@pytest.fixture(scope="module")
def grader():
    """This process, made a grader whose state shows when inherited; put back as it was afterwards."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    add_key = KEY_SYSCALLS[platform.machine()][0]
    session = _keyctl(1, None)  # KEYCTL_JOIN_SESSION_KEYRING: a new anonymous one, as pam_keyinit makes
    key = libc.syscall(add_key, b"user", b"instructor-key", b"secret", 6, KEY_SPEC_SESSION_KEYRING)
    assert key > 0, os.strerror(ctypes.get_errno())
    user = _keyctl(0, KEY_SPEC_USER_KEYRING, 1)  # the user keyring _uid.N, made if this user had none
    user_held = _serials(_read_key(user))
    user_key = libc.syscall(add_key, b"user", b"instructor-user-key", b"secret", 6, user)
    assert user_key > 0, os.strerror(ctypes.get_errno())
    ignored = {number: signal.signal(number, signal.SIG_IGN) for number in (signal.SIGHUP, signal.SIGUSR1)}
    blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGUSR2})
    umask = os.umask(0o077)
    personality = libc.personality(0xFFFFFFFF)
    libc.personality(personality | ADDR_NO_RANDOMIZE)
    ns = {name: os.stat(f"/proc/self/ns/{name}").st_ino for name in NAMESPACES}
    try:
        yield {"session": session, "key": key, "user": user, "user_key": user_key, "ns": ns}
    finally:
        for serial in _serials(_read_key(user)):
            if serial not in user_held:  # the planted key (and a student's, were the wall down)
                _keyctl(9, serial, user)  # KEYCTL_UNLINK
        libc.personality(personality)
        os.umask(umask)
        signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
        for number, handler in ignored.items():
            signal.signal(number, handler)
        _keyctl(7, KEY_SPEC_SESSION_KEYRING)  # KEYCTL_CLEAR: the instructor's key goes


@pytest.fixture(scope="module")
def slot(grader):
    """A warm slot started by the dirty grader (its zygote inherits everything the grader has)."""
    if not warm.enabled():
        pytest.skip("warm slots need the namespace sandbox")
    with started_warm_slot() as started:
        yield started


def _two_students(kind, slot, grader):
    """The states read by two students alive at once: in cold sandboxes, or both forked by one slot."""
    with StudentSandbox(support=THIS_COURSE.support, program=_program(), slot=slot) as first:
        with StudentSandbox(support=THIS_COURSE.support, program=_program(), slot=slot, resets_slot=False) as second:
            states = [box.call("01", "state", [grader]) for box in (first, second)]
            assert all(isinstance(box.process, warm.WarmWorker) == (kind == "warm") for box in (first, second))
    return states


@pytest.fixture(scope="module", params=["cold", "warm"])
def students(request, grader):
    """Two students' states, read while both run, cold or in one warm slot."""
    slot = request.getfixturevalue("slot") if request.param == "warm" else None
    return _two_students(request.param, slot, grader)


def test_every_namespace_is_the_students_own(students, grader):
    first, second = students
    for name in NAMESPACES:
        assert grader["ns"][name] not in (first["ns"][name], second["ns"][name]), (
            f"the {name} namespace is the grader's"
        )
        assert first["ns"][name] != second["ns"][name], f"two students share a {name} namespace"


def test_the_network_is_only_a_loopback_of_its_own(students):
    for state in students:
        assert state["interfaces"] == ["lo"] and state["lo_up"], state["interfaces"]
        assert state["hostname"] == "sandbox", state["hostname"]


def _graders_keys_untouched(grader):
    assert _read_key(grader["key"]) == b"secret", "a student rewrote the instructor's key"
    held = _read_key(KEY_SPEC_SESSION_KEYRING)
    assert held == grader["key"].to_bytes(4, "little"), "a student changed the grader's session keyring"
    assert grader["user_key"] in _serials(_read_key(grader["user"]))
    assert b"planted" not in b"".join(_describe(serial) for serial in _serials(_read_key(grader["user"])))


def _describe(serial):
    buffer = ctypes.create_string_buffer(256)
    size = _keyctl(6, serial, buffer, 256)  # KEYCTL_DESCRIBE
    return buffer.raw[:size]


def test_every_key_system_call_of_a_students_is_refused(students):
    """keyctl, add_key and request_key fail with EPERM, whatever they ask, through any ABI."""
    for state in students:
        refused = {what: result for what, result in state["keys"].items() if result != REFUSED}
        assert not refused, f"key system calls that were not refused: {refused}"
        assert state["proc_keys"] == "", "the kernel's list of keys is readable"


def test_student_code_cannot_reach_the_graders_keys_even_by_serial(students, grader):
    """Neither the instructor's key nor the grader's session and user keyrings can be described, read,
    changed, listed, linked or written into, given their serials, as root and as an ordinary user (where
    the student is the grader's user to the kernel, and only the filter keeps it out)."""
    for state in students:
        for what in ("grader_key", "grader_key_described", "grader_session_listed", "grader_session_described"):
            assert state["keys"][what] == REFUSED, (what, state["keys"][what])
        for what in ("grader_user_key", "grader_user_key_described", "grader_user_listed", "grader_user_described"):
            assert state["keys"][what] == REFUSED, (what, state["keys"][what])
        for what in ("updated", "linked_grader_key", "linked_grader_session", "found_by_name"):
            assert state["keys"][what] == REFUSED, (what, state["keys"][what])
        assert state["keys"]["linked_into_grader_user"] == state["keys"]["added_to_grader_user"] == REFUSED
    _graders_keys_untouched(grader)


def test_the_jail_joins_a_new_empty_session_keyring_in_the_new_user_namespace(grader):
    """Behind the filter, the jail's own step (defence in depth, and what limits mode relies on where no
    filter can be installed): in a new user namespace, a new, empty session keyring, not the grader's,
    and the grader's keys out of reach. Run alone in a child of this test, without the filter."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:
        try:
            os.close(read)
            libc = jail._libc()
            outer = os.getuid(), os.getgid()
            found = {"unshare": libc.unshare(jail.CLONE_NEWUSER)}
            jail._map_user(*outer)
            jail._fresh_session_keyring(libc)
            found["session"] = _keyctl(0, KEY_SPEC_SESSION_KEYRING, 0)
            found["holds"] = _read_key(KEY_SPEC_SESSION_KEYRING).hex()
            found["user"] = _keyctl(0, KEY_SPEC_USER_KEYRING, 1)
            try:
                found["grader_key"] = _read_key(grader["key"]).hex()
            except OSError as error:
                found["grader_key"] = error.errno
            os.write(write, json.dumps(found).encode())
        finally:
            os._exit(0)
    os.close(write)
    with os.fdopen(read, "rb") as answer:
        found = json.loads(answer.read() or b"{}")
    os.waitpid(pid, 0)
    assert found.get("unshare") == 0, found
    assert found["session"] > 0 and found["session"] != grader["session"] and found["holds"] == "", found
    assert found["user"] != grader["user"], "the user keyring of the new user namespace is the grader's"
    assert isinstance(found["grader_key"], int), "a new session keyring still reads the instructor's key"


def test_keys_a_student_leaves_reach_neither_the_next_student_nor_the_grader(slot, grader):
    with StudentSandbox(support=THIS_COURSE.support, program=_program(), slot=slot) as box:
        made = box.call("01", "leave")  # keys in @s, @u and @us
        assert isinstance(box.process, warm.WarmWorker)
    assert made == [REFUSED] * 3, made
    with StudentSandbox(support=THIS_COURSE.support, program=_program(), slot=slot) as box:
        after = box.call("01", "state", [grader])
    assert after["keys"]["left_key"] == REFUSED and after["keys"]["session_holds"] == REFUSED, after["keys"]
    _graders_keys_untouched(grader)


def test_signals_are_at_their_defaults_and_none_is_blocked(students):
    # what a fresh Python ignores itself: SIGPIPE and SIGXFSZ; the grader's SIGHUP and SIGUSR1 are not ignored
    python_ignores = (1 << (signal.SIGPIPE - 1)) | (1 << (signal.SIGXFSZ - 1))
    for state in students:
        assert int(state["status"]["SigIgn"], 16) == python_ignores, state["status"]["SigIgn"]
        assert int(state["status"]["SigBlk"], 16) == 0, state["status"]["SigBlk"]
        assert int(state["status"]["SigPnd"], 16) == 0, state["status"]["SigPnd"]


def test_no_capability_in_any_set_and_no_new_privileges(students):
    for state in students:
        for field in ("CapInh", "CapPrm", "CapEff", "CapBnd", "CapAmb"):
            assert int(state["status"][field], 16) == 0, (field, state["status"][field])
        assert state["status"]["NoNewPrivs"] == "1"


def test_personality_and_umask_are_the_defaults(students):
    for state in students:
        assert state["personality"] == 0, hex(state["personality"])  # PER_LINUX: addresses randomised
        assert state["umask"] == 0o022, oct(state["umask"])


def test_only_the_wires_descriptors_are_open_and_limits_are_the_graders(students):
    limits = launcher.Limits()
    for state in students:
        fds = {int(fd): target for fd, target in state["fds"].items()}
        assert {fd: fds[fd] for fd in (0, 1, 2)} == {0: "/dev/null", 1: "/dev/null", 2: "/dev/null"}, fds
        others = [target for fd, target in fds.items() if fd > 2]
        sockets = {target for target in others if target.startswith("socket:")}
        # the runner's one socket to its feeder (requests and replies), and sys.stdin on /dev/null
        assert len(sockets) == 1 and sorted(others) == sorted([*sockets] * 2 + ["/dev/null"]), fds
        assert state["limits"]["RLIMIT_FSIZE"] == limits.file_bytes
        assert state["limits"]["RLIMIT_NOFILE"] == limits.open_files
        assert state["limits"]["RLIMIT_CORE"] == 0


def test_in_limits_mode_the_student_reaches_no_key_and_gets_fresh_signals_too(grader, monkeypatch):
    """Without namespaces (``limits`` mode) the student is an ordinary process, but it still reaches no
    key (the same filter, on ``no_new_privs``) and gets signals, personality and umask as fresh."""
    monkeypatch.setattr(launcher, "isolation", lambda: ("limits", "asked for by the test"))
    with StudentSandbox(support=THIS_COURSE.support, program=_program()) as box:
        state = box.call("01", "state", [grader])
        made = box.call("01", "leave")
    refused = {what: result for what, result in state["keys"].items() if result != REFUSED}
    assert not refused, f"key system calls that were not refused in limits mode: {refused}"
    assert made == [REFUSED] * 3, made
    assert state["status"]["NoNewPrivs"] == "1"
    python_ignores = (1 << (signal.SIGPIPE - 1)) | (1 << (signal.SIGXFSZ - 1))
    assert int(state["status"]["SigIgn"], 16) == python_ignores and int(state["status"]["SigBlk"], 16) == 0
    assert state["personality"] == 0 and state["umask"] == 0o022
    _graders_keys_untouched(grader)
