"""Drop root before any student code runs (copied into every sandbox).

When the grader runs as root, bubblewrap needs no user namespace and starts
our worker as root inside fresh PID, network and mount namespaces. The worker
then calls :func:`drop_privileges` first thing: it becomes an unprivileged user with no
capabilities, so it cannot undo the mounts, and RLIMIT_NPROC applies to it
(the kernel exempts root from that limit).
"""

import ctypes
import os

NOBODY = 65534
PR_SET_NO_NEW_PRIVS = 38


def sandbox_uid(argv):
    """The uid given as ``--uid N`` on the command line, else nobody."""
    if "--uid" in argv:
        return int(argv[argv.index("--uid") + 1])
    return NOBODY


def drop_privileges(uid=NOBODY):
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
