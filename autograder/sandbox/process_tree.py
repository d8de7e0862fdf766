"""Find and kill every process a sandbox left behind, detached ones included.

The grading process makes itself a *child subreaper* (Linux
``PR_SET_CHILD_SUBREAPER``): when a student's code double-forks or calls
``setsid`` and its parent exits, the orphan is re-parented to us instead of to
init, so walking our descendants in ``/proc`` finds it.
"""

from __future__ import annotations

import ctypes
import os
import signal

PR_SET_CHILD_SUBREAPER = 36


def become_subreaper() -> bool:
    """Ask Linux to re-parent orphaned descendants to this process; True if it worked."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        return libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def _parent_map():
    parents = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as handle:
                stat = handle.read().decode("ascii", "replace")
        except OSError:
            continue
        # the command name is in parentheses and may contain spaces: split after the last ')'
        fields = stat[stat.rfind(")") + 2 :].split()
        if len(fields) > 1:
            parents[int(entry)] = int(fields[1])
    return parents


def descendants(pid: int | None = None) -> list[int]:
    """PIDs of every live descendant of ``pid`` (default: this process)."""
    root = os.getpid() if pid is None else pid
    children = {}
    for child, parent in _parent_map().items():
        children.setdefault(parent, []).append(child)
    found, stack = [], list(children.get(root, []))
    while stack:
        current = stack.pop()
        found.append(current)
        stack.extend(children.get(current, []))
    return found


def kill_descendants(pid: int | None = None, keep: tuple[int, ...] = ()) -> int:
    """SIGKILL every descendant of ``pid`` except those in ``keep``; return how many."""
    victims = [p for p in descendants(pid) if p not in keep]
    for victim in victims:
        try:
            os.kill(victim, signal.SIGKILL)
        except ProcessLookupError:
            pass
    for victim in victims:  # reap the ones that are our own children
        try:
            os.waitpid(victim, os.WNOHANG)
        except ChildProcessError:
            pass
    return len(victims)
