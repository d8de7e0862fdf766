"""A control group per sandbox, when the grader runs as root: memory and process caps for the whole tree.

Resource limits (``setrlimit``) apply per process: 64 processes × 2 GiB each
would still be too much for one student. A cgroup caps the sandbox as a whole
(``memory`` and ``pids`` controllers) and lists every process in it, so
killing a sandbox cannot miss one. cgroup v2 is used when its controllers are
available, else v1; without either (not root, or a container without them)
the sandbox simply has no cgroup and says so.

Examples
--------
>>> group = SandboxCgroup.create("demo", memory_bytes=2**30, pids=64)   # doctest: +SKIP
>>> # in the child, before exec: group.join()                            # doctest: +SKIP
>>> group.kill_all(); group.remove()                                     # doctest: +SKIP
"""

from __future__ import annotations

import functools
import itertools
import os
import signal
import time
from pathlib import Path

ROOT = Path("/sys/fs/cgroup")
_counter = itertools.count()


def _write(path, text):
    with open(path, "w") as handle:
        handle.write(text)


@functools.lru_cache(maxsize=1)
def flavour() -> str | None:
    """``"v2"``, ``"v1"`` or ``None``: which cgroup interface this grader can use."""
    if os.geteuid() != 0:
        return None
    controllers = ROOT / "cgroup.controllers"
    if controllers.exists() and {"memory", "pids"} <= set(controllers.read_text().split()):
        try:
            base = ROOT / "autograder"
            base.mkdir(exist_ok=True)
            _write(ROOT / "cgroup.subtree_control", "+memory +pids")
            _write(base / "cgroup.subtree_control", "+memory +pids")
            return "v2"
        except OSError:
            pass
    if (ROOT / "memory" / "cgroup.procs").exists() and (ROOT / "pids" / "cgroup.procs").exists():
        try:
            probe = ROOT / "memory" / f"autograder-probe-{os.getpid()}"
            probe.mkdir(exist_ok=True)
            probe.rmdir()
            return "v1"
        except OSError:
            pass
    return None


class SandboxCgroup:
    """The cgroup directories (one for v2, two for v1) of one sandbox."""

    def __init__(self, directories):
        self.directories = directories

    @classmethod
    def create(cls, label: str, memory_bytes: int, pids: int) -> SandboxCgroup | None:
        """A new cgroup with the limits, or None when cgroups are not usable here."""
        kind = flavour()
        name = f"autograder-{os.getpid()}-{next(_counter)}-{label}"
        try:
            if kind == "v2":
                directory = ROOT / "autograder" / name
                directory.mkdir()
                _write(directory / "memory.max", str(memory_bytes))
                if (directory / "memory.swap.max").exists():
                    _write(directory / "memory.swap.max", "0")
                _write(directory / "pids.max", str(pids))
                return cls([directory])
            if kind == "v1":
                memory, processes = ROOT / "memory" / name, ROOT / "pids" / name
                memory.mkdir()
                processes.mkdir()
                _write(memory / "memory.limit_in_bytes", str(memory_bytes))
                _write(processes / "pids.max", str(pids))
                return cls([memory, processes])
        except OSError:
            return None
        return None

    def join(self) -> None:
        """Move the calling process into the cgroup (call in the child before exec)."""
        for directory in self.directories:
            _write(directory / "cgroup.procs", str(os.getpid()))

    def pids(self) -> list[int]:
        found = set()
        for directory in self.directories:
            try:
                found.update(int(line) for line in (directory / "cgroup.procs").read_text().split())
            except OSError:
                pass
        return found

    def kill_all(self) -> None:
        """SIGKILL every process in the cgroup, until none is left (new ones may be forking)."""
        for _ in range(50):
            pids = self.pids()
            if not pids:
                return
            for pid in pids:
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            time.sleep(0.01)

    def remove(self) -> None:
        for directory in self.directories:
            for _ in range(50):
                try:
                    directory.rmdir()
                    break
                except FileNotFoundError:
                    break
                except OSError:
                    time.sleep(0.02)
