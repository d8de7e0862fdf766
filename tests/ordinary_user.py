"""Run the grader as an ordinary user, as on an instructor's laptop, from tests that run as root.

As root, :func:`as_ordinary_user` wraps a command so that it runs as
``nobody`` (uid and gid 65534, no supplementary groups) through ``setpriv``.
``nobody`` must reach Python, the project and the test's folders; where an
installation sits under a folder it may not enter (pyenv's ``/root/.pyenv``
under ``/root``, mode 0700), the command runs in a private mount namespace
(``unshare --mount``) in which that folder is an empty tmpfs with mode 0755
holding only the needed entry, bind-mounted from the original. Nothing
changes on the host. As an ordinary user already, the command is returned
as it is: the tests then cover that mode directly.

Examples
--------
>>> argv = as_ordinary_user([sys.executable, "-m", "autograder", "grade", ...],
...                         reach=[PROJECT_ROOT, class_dir], holds=scratch)          # doctest: +SKIP
"""

import os
import shlex
import shutil
import stat
import sys
from pathlib import Path

NOBODY = 65534


def running_as_root():
    return os.geteuid() == 0


def available():
    """Why the ordinary-user mode cannot run here, or ``None`` when it can."""
    if not running_as_root():
        return None
    missing = [tool for tool in ("setpriv", "unshare", "mount") if shutil.which(tool) is None]
    return f"missing {', '.join(missing)}" if missing else None


def _blocked(paths):
    """``{folder: {child names}}`` for folders on the way to ``paths`` that others may not enter."""
    blocked = {}
    for path in paths:
        path = Path(os.path.realpath(path))
        for parent, child in zip(reversed(path.parents), list(reversed(path.parents))[1:] + [path]):
            if not os.stat(parent).st_mode & stat.S_IXOTH:
                blocked.setdefault(parent, set()).add(child.name)
    return blocked


def give_to_ordinary_user(*paths):
    """Make ``paths`` (folders the grader writes: its output, caches) belong to ``nobody`` when root."""
    if running_as_root():
        for path in paths:
            os.chown(path, NOBODY, NOBODY)


def as_ordinary_user(argv, reach, holds):
    """``argv`` wrapped to run as ``nobody`` (see the module docstring).

    Parameters
    ----------
    argv : list of str
        The command.
    reach : list of path-like
        Everything ``nobody`` must be able to reach (Python's prefixes are added).
    holds : path-like
        An empty folder of the test's for the mount points that keep a hidden folder's entries.
    """
    if not running_as_root():
        return list(argv)
    needed = [sys.base_prefix, sys.prefix, os.path.realpath(sys.executable), *reach]
    lines = ["set -e"]
    for index, (folder, children) in enumerate(sorted(_blocked(needed).items(), key=lambda kv: len(kv[0].parts))):
        kept = []
        for number, child in enumerate(sorted(children)):
            hold = Path(holds) / f"{index}-{number}"
            hold.mkdir(parents=True, exist_ok=True)
            kept.append((child, hold))
            lines.append(f"mount --bind {shlex.quote(str(folder / child))} {shlex.quote(str(hold))}")
        lines.append(f"mount -t tmpfs -o mode=0755,size=1m tmpfs {shlex.quote(str(folder))}")
        for child, hold in kept:
            make = "mkdir" if (folder / child).is_dir() else "touch"
            lines.append(f"{make} {shlex.quote(str(folder / child))}")
            lines.append(f"mount --bind {shlex.quote(str(hold))} {shlex.quote(str(folder / child))}")
    lines.append(f'exec setpriv --reuid {NOBODY} --regid {NOBODY} --clear-groups -- "$@"')
    return ["unshare", "--mount", "--propagation", "private", "--", "sh", "-c", "\n".join(lines), "sh", *argv]
