"""Run a command as an ordinary user (``nobody``) from a test that runs as root.

Instructors grade on laptops as ordinary users: bubblewrap then makes a user namespace, and every
sandbox runs as the instructor. CI runs as root. So that every wall is tested both ways in one run,
:func:`as_ordinary_user` runs a command as ``nobody`` in a private mount namespace in which the
Python installation is reachable (a Python under ``/root``, as pyenv installs it, is not readable by
other users: the folders above it are covered by a tmpfs that holds only the way down to it).

Examples
--------
>>> subprocess.run(as_ordinary_user([sys.executable, "-m", "pytest", "tests/test_sandbox.py"]))  # doctest: +SKIP
"""

import os
import shlex
import shutil
import sys

NOBODY = 65534


def possible():
    """Whether this process can run a command as ``nobody`` (root, with unshare and setpriv)."""
    return os.geteuid() == 0 and bool(shutil.which("unshare")) and bool(shutil.which("setpriv"))


def _hidden_ancestor(path):
    """The highest folder above ``path`` that ``nobody`` cannot traverse (mode without o+x), or None."""
    parts = os.path.realpath(path).split(os.sep)
    for depth in range(2, len(parts)):
        folder = os.sep.join(parts[:depth])
        if not os.stat(folder).st_mode & 0o001:
            return folder
    return None


def as_ordinary_user(command, env=None):
    """The argv that runs ``command`` as ``nobody`` with this Python reachable (see the module docstring)."""
    prefix = os.path.realpath(sys.base_prefix)
    lines = ["set -e"]
    hidden = _hidden_ancestor(prefix)
    if hidden is not None:
        keep = f"/tmp/.python-for-nobody-{os.getpid()}"
        lines += [f"mkdir -p {keep}", f"mount --bind {shlex.quote(prefix)} {keep}",
                  f"mount -t tmpfs -o mode=0755 tmpfs {shlex.quote(hidden)}",
                  f"mkdir -p {shlex.quote(prefix)}", f"mount --bind {keep} {shlex.quote(prefix)}"]
    variables = " ".join(f"{k}={shlex.quote(v)}" for k, v in {"HOME": "/tmp", **(env or {})}.items())
    lines.append(f"exec setpriv --reuid {NOBODY} --regid {NOBODY} --clear-groups --inh-caps=-all -- "
                 f"env {variables} " + " ".join(shlex.quote(str(a)) for a in command))
    return ["unshare", "-m", "sh", "-c", "\n".join(lines)]
