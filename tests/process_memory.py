"""Sample the resident memory of a process tree while it runs (for benchmarks and bound checks).

:class:`PeakMemory` polls ``/proc`` for every descendant of a process and keeps
the peak of their summed resident memory (``peak``: forked processes count the
pages they share once each, so it overstates) and the largest high-water mark
(``VmHWM``) of any one of them (``largest``). ``only(cmdline)`` restricts both
to some of the processes, e.g. the grader's own processes and not the
sandboxes they start.

Examples
--------
>>> process = subprocess.Popen([sys.executable, "-m", "autograder", "grade", ...])   # doctest: +SKIP
>>> with PeakMemory(process.pid, only=is_grader) as memory:                          # doctest: +SKIP
...     process.wait()
>>> memory.largest / 2**20                                                            # doctest: +SKIP
231.5
"""

import os
import threading


def _field_kib(pid, name):
    try:
        with open(f"/proc/{pid}/status", encoding="ascii", errors="replace") as status:
            for line in status:
                if line.startswith(name):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return 0


def cmdline(pid):
    """The arguments of process ``pid`` (empty when it is gone)."""
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as handle:
            return [part.decode("utf-8", "replace") for part in handle.read().split(b"\0") if part]
    except OSError:
        return []


def is_grader(arguments):
    """Whether a process runs ``python -m autograder grade`` (the grader and its forks; not its sandboxes)."""
    return "autograder" in arguments and "grade" in arguments and "-m" in arguments


class PeakMemory:
    """Samples the resident memory of a process and all its descendants (see the module docstring)."""

    def __init__(self, pid, interval=0.2, only=None):
        self.pid, self.interval, self.only = pid, interval, only
        self.peak = self.largest = 0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def __enter__(self):
        self._thread.start()
        return self

    def __exit__(self, *exc):
        self._stop.set()
        self._thread.join()

    def _tree(self):
        children = {}
        for entry in os.listdir("/proc"):
            if entry.isdigit():
                try:
                    with open(f"/proc/{entry}/stat", encoding="ascii", errors="replace") as handle:
                        stat = handle.read()
                    children.setdefault(int(stat[stat.rfind(")") + 2 :].split()[1]), []).append(int(entry))
                except (OSError, ValueError, IndexError):
                    pass
        found, stack = [self.pid], [self.pid]
        while stack:
            for child in children.get(stack.pop(), []):
                found.append(child)
                stack.append(child)
        return found

    def _run(self):
        while not self._stop.is_set():
            pids = [p for p in self._tree() if self.only is None or self.only(cmdline(p))]
            self.peak = max(self.peak, sum(_field_kib(p, "VmRSS:") for p in pids))
            self.largest = max([self.largest] + [_field_kib(p, "VmHWM:") for p in pids])
            self._stop.wait(self.interval)
