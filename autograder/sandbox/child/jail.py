"""Drop root before any student code runs (copied into every sandbox).

When the grader runs as root, bubblewrap needs no user namespace and starts
our worker as root inside fresh PID, network and mount namespaces. The worker
then calls :func:`drop_privileges` first thing: it becomes ``nobody`` with no
capabilities, so it cannot undo the mounts, and RLIMIT_NPROC applies to it
(the kernel exempts root from that limit).
"""

import ctypes
import os

NOBODY = 65534
PR_SET_NO_NEW_PRIVS = 38


def drop_privileges(uid=NOBODY):
    """Become ``uid`` (and its group) if running as root; forbid regaining privileges."""
    if os.getuid() == 0:
        os.setgroups([])
        os.setgid(uid)
        os.setuid(uid)
    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0)
    except (OSError, AttributeError):
        pass
