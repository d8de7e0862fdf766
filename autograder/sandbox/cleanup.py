"""Remove a folder that student code wrote into, whatever it made there.

Student code controls the shape of what it leaves: a tree 10,000 levels deep,
folders made unreadable (``chmod 0``), paths longer than ``PATH_MAX``, links
pointing anywhere. :func:`remove_tree` walks it iteratively (no recursion to
exhaust), relative to open folder descriptors (no path length limit), never
following a link, and with at most two descriptors open at a time (it climbs
back with ``..``). With bubblewrap, students write in a tmpfs of their own
that never reaches the disk; this is for ``limits`` mode and for the
grader's own temporary folders.

Examples
--------
>>> remove_tree("/tmp/autograder-sandbox-x1y2")          # doctest: +SKIP
True
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
import os
import re
import stat
import tempfile

_DIR_FLAGS = os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC


def _open_child(parent_fd, name):
    """Open folder ``name`` of ``parent_fd`` (made readable first if a student locked it), or None."""
    for attempt in range(2):
        try:
            return os.open(name, _DIR_FLAGS, dir_fd=parent_fd)
        except PermissionError:
            if attempt:
                return None
            try:
                os.chmod(name, 0o700, dir_fd=parent_fd, follow_symlinks=False)
            except (OSError, NotImplementedError):
                return None
        except OSError:
            return None
    return None


def _first_entry(fd):
    """One entry of folder ``fd``: (name, is a real folder), or None when it is empty."""
    with os.scandir(fd) as entries:
        for entry in entries:
            try:
                return entry.name, entry.is_dir(follow_symlinks=False)
            except OSError:
                return entry.name, False
    return None


def remove_tree(path: str | os.PathLike) -> bool:
    """Remove ``path`` and everything under it; return True when it is gone.

    Never raises for what is inside (a file that cannot be removed is left, and the result is False).
    """
    try:
        info = os.lstat(path)
    except FileNotFoundError:
        return True
    if not stat.S_ISDIR(info.st_mode):
        try:
            os.unlink(path)
        except OSError:
            return False
        return True
    parent, name = os.path.split(os.path.abspath(path))
    try:
        top_parent = os.open(parent, _DIR_FLAGS)
    except OSError:
        return False
    try:
        fd = _open_child(top_parent, name)
        if fd is None:
            return False
        depth, stuck = 0, set()
        while True:
            entry = _first_entry(fd)
            while entry is not None and (depth, entry[0]) in stuck:
                entry = _next_unstuck(fd, depth, stuck)
            if entry is not None:
                child, is_dir = entry
                if is_dir:
                    inner = _open_child(fd, child)
                    if inner is None:
                        stuck.add((depth, child))
                        continue
                    os.close(fd)
                    fd, depth = inner, depth + 1
                    continue
                try:
                    os.unlink(child, dir_fd=fd)
                except OSError:
                    stuck.add((depth, child))
                continue
            # empty (or only what cannot be removed): climb back, removing it
            if depth == 0:
                os.close(fd)
                fd = None
                try:
                    os.rmdir(name, dir_fd=top_parent)
                except OSError:
                    return False
                return True
            up = os.open("..", _DIR_FLAGS, dir_fd=fd)
            here = os.fstat(fd)
            os.close(fd)
            fd, depth = up, depth - 1
            _remove_child_folder(fd, here, depth, stuck)
    finally:
        os.close(top_parent)
        if "fd" in locals() and fd is not None:
            try:
                os.close(fd)
            except OSError:
                pass


def _next_unstuck(fd, depth, stuck):
    with os.scandir(fd) as entries:
        for entry in entries:
            if (depth, entry.name) not in stuck:
                try:
                    return entry.name, entry.is_dir(follow_symlinks=False)
                except OSError:
                    return entry.name, False
    return None


def _remove_child_folder(fd, child_stat, depth, stuck):
    """Remove the (now empty) folder of ``fd`` whose identity is ``child_stat``; note it if that fails."""
    with os.scandir(fd) as entries:
        for entry in entries:
            try:
                same = entry.is_dir(follow_symlinks=False) and entry.inode() == child_stat.st_ino
            except OSError:
                same = False
            if same:
                try:
                    os.rmdir(entry.name, dir_fd=fd)
                except OSError:
                    stuck.add((depth, entry.name))
                return


def private_folder(kind: str) -> str:
    """A new folder under the temporary directory, named for this process (``autograder-KIND-pPID-…``),
    so that :func:`sweep_stale` can tell one a killed grader left behind. Only the grader's user may enter it
    (0700, whatever the umask): what the grader puts there for a sandbox cannot be read or swapped by another
    account (:func:`~autograder.sandbox.launcher.prepare_dirs` keeps it so)."""
    path = tempfile.mkdtemp(prefix=f"autograder-{kind}-p{os.getpid()}-")
    os.chmod(path, 0o700)
    return path


@contextlib.contextmanager
def private_folder_for(kind: str) -> Iterator[str]:
    """:func:`private_folder` for a ``with`` block, removed (whatever is in it) at its end."""
    path = private_folder(kind)
    try:
        yield path
    finally:
        remove_tree(path)


_OURS = re.compile(r"^autograder-[a-z0-9]+-p(\d+)-")


def sweep_stale() -> int:
    """Remove the folders of :func:`private_folder` whose process is gone (a grader killed mid-batch).
    Returns how many were removed."""
    removed = 0
    base = tempfile.gettempdir()
    for name in os.listdir(base):
        match = _OURS.match(name)
        if not match or int(match[1]) == os.getpid():
            continue
        try:
            os.kill(int(match[1]), 0)
            continue  # its grader still runs
        except ProcessLookupError:
            pass
        except PermissionError:
            continue  # another user's grader, alive
        removed += remove_tree(os.path.join(base, name))
    return removed
