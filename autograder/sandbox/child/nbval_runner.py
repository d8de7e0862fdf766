"""Run nbval on a student's merged notebooks, inside the sandbox (copied there).

Usage: ``python -I nbval_runner.py NOTEBOOK...`` in the folder that holds the
notebooks. The kernels nbval starts inherit ``/dev/null`` as their output;
the summary goes out on the original stdout as one JSON line:
``{"notebooks": {name: {"cells": n, "failures": ["cell 7: ...", ...]}}}``.

Speed: the kernels are forks of one warm process that has imported ipykernel,
numpy, scipy and matplotlib once (``fork_kernel.py``; each lesson still gets a
fresh kernel, and ordinary kernels are used if that process cannot start);
they use matplotlib's non-interactive ``agg`` backend (no figure is
rasterised; the outputs nbval compares are display text); and the runner does
not import ``rfc3987_syntax`` (a grammar built at import time that only checks
a string format no notebook uses).

No student code runs here: the answer cells of the notebooks are bindings to
the student's functions, which run in the student's own sandbox
(``student_client.py``); ``--channels`` names each lesson's two pipes to it.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from collections.abc import Iterator

# Speed: nbval -> nbformat -> jsonschema imports rfc3987_syntax when it is installed, which builds
# a grammar at import time (~1.2 s per run). It only checks the "iri" string format, which no
# notebook schema uses; without it jsonschema simply does not register that check.
sys.modules.setdefault("rfc3987_syntax", None)

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import fork_kernel
import jail

if "--keep-user" in sys.argv:
    sys.argv.remove("--keep-user")
else:
    jail.drop_privileges(jail.sandbox_uid(sys.argv))
# the kernels reopen the student's pipes through /proc/<this process>/fd (student_client.py): a change of
# uid made this process undumpable, and so its /proc entries root's; no student code runs here
import ctypes

ctypes.CDLL(None).prctl(4, 1, 0, 0, 0)  # PR_SET_DUMPABLE


ANSI = re.compile(r"\x1b\[[0-9;]*m")
ERROR_LINE = re.compile(r"^([A-Za-z_][\w.]*(Error|Exception|Failed|Exit|Interrupt)): ?(.*)$")


def describe_failure(source: str, longrepr: object) -> str:
    """One line for a failed cell: its first line of code and what went wrong."""
    lines = [line for line in (source or "").strip().splitlines() if line.strip()]
    first = lines[0].strip() if lines else "(empty cell)"
    first = first if len(first) <= 70 else first[:69] + "…"
    text = ANSI.sub("", longrepr)
    if "Cell outputs differ" in text:
        what = "printed something different from the reference notebook"
    elif "Timeout" in text or "timed out" in text:
        what = "did not finish in time (an endless loop?)"
    elif "Kernel dead" in text or "Kernel died" in text:
        what = "could not run: the kernel had stopped (os._exit, sys.exit or a crash in an earlier cell)"
    else:
        errors = [m for m in (ERROR_LINE.match(line.strip()) for line in text.splitlines()) if m]
        what = "raised " + (f"{errors[-1].group(1)}: {errors[-1].group(3)}".rstrip(": ") if errors else "an error")
    return f"the cell `{first}` {' '.join(what.split())[:240]}"


class Summary:
    """pytest plugin: count cells and keep one line per failing cell.

    It also tells nbval to ignore printed text (stdout and stderr) when it
    compares outputs: the demonstrations show their results as display
    outputs (``coursekit.show``), so a student's debugging print or a
    library warning never fails a cell.
    """

    def __init__(self):
        self.notebooks = {}

    def pytest_collection_modifyitems(
        self, session: pytest.Session, config: pytest.Config, items: list[pytest.Item]
    ) -> None:
        for item in items:
            notebook = item.parent
            if hasattr(notebook, "skip_compare") and "text" not in notebook.skip_compare:
                notebook.skip_compare = tuple(notebook.skip_compare) + ("text",)

    @pytest.hookimpl(hookwrapper=True)
    def pytest_runtest_makereport(self, item: pytest.Item, call: pytest.CallInfo) -> Iterator[None]:
        outcome = yield
        report = outcome.get_result()
        if report.when != "call" and not (report.failed and report.when == "setup"):
            return
        name = report.nodeid.split("::")[0]
        entry = self.notebooks.setdefault(name, {"cells": 0, "failures": []})
        entry["cells"] += 1
        if report.failed:
            source = getattr(getattr(item, "cell", None), "source", "")
            entry["failures"].append(describe_failure(source, str(report.longrepr)))


def use_forked_kernels(timeout: float = 30.0) -> subprocess.Popen | None:
    """Start the fork server and make nbval's kernels come from it; return its process, or None.

    None (nbval then starts ordinary kernels) when the server cannot start or
    is not ready within ``timeout`` seconds.
    """
    import select
    import subprocess

    import ipykernel.kernelspec

    socket_path = os.path.join(os.getcwd(), ".kernels")
    if len(socket_path) > 100:  # a Unix socket's path must be short
        return None
    try:
        server = subprocess.Popen(
            [sys.executable, fork_kernel.__file__, "serve", socket_path],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        )
    except OSError:
        return None
    ready, _, _ = select.select([server.stdout], [], [], timeout)
    if not ready or server.stdout.readline().strip() != b"ready":
        server.kill()
        return None
    ordinary = ipykernel.kernelspec.get_kernel_dict

    def forked_kernel_dict(*args, **kwargs):
        spec = ordinary(*args, **kwargs)
        spec["argv"] = fork_kernel.kernel_argv(socket_path)
        return spec

    ipykernel.kernelspec.get_kernel_dict = forked_kernel_dict  # read by nbval for --nbval-current-env
    return server


def main(notebooks: list[str]) -> None:
    # No rasterising: figures are never compared, so the kernels draw nothing. With a
    # non-interactive backend plt.show() is a no-op, where ipykernel's default (inline) would
    # render every figure to PNG (about 1 CPU-second per lesson). The launcher's environment
    # sets it too; saying it here keeps it true whoever starts this runner.
    os.environ["MPLBACKEND"] = "agg"
    out = os.fdopen(os.dup(1), "w")
    devnull = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        os.dup2(devnull, fd)
    server = use_forked_kernels()
    summary = Summary()
    # a cell may call a student function thousands of times, each a round trip to their sandbox (about
    # 0.3 ms); every call has its own time limit there, so the cell's limit only has to be generous
    args = [
        "--nbval-lax",
        "--nbval-current-env",
        "--nbval-cell-timeout=60",
        "--nbval-kernel-startup-timeout=60",
        "-p",
        "no:cacheprovider",
        "-q",
        "-o",
        "addopts=",
        "--rootdir",
        os.getcwd(),
    ]
    if os.path.exists(os.path.join(HERE, "nbval_sanitize.cfg")):
        args += ["--nbval-sanitize-with", os.path.join(HERE, "nbval_sanitize.cfg")]
    pytest.main(args + notebooks, plugins=[summary])
    if server is not None:
        server.stdin.close()  # the fork server exits, and takes any kernel still running with it
    out.write(json.dumps({"notebooks": summary.notebooks}) + "\n")
    out.flush()
    os._exit(0)


def _take_option(arguments, name):
    """Remove ``name VALUE`` from ``arguments``; return VALUE (or None)."""
    if name not in arguments:
        return None
    position = arguments.index(name)
    value = arguments[position + 1]
    del arguments[position : position + 2]
    return value


if __name__ == "__main__":
    arguments = sys.argv[1:]
    _take_option(arguments, "--uid")
    channels = json.loads(_take_option(arguments, "--channels") or "{}")
    # each lesson's pipes to the student's sandbox, as the kernels find them (student_client.py)
    os.environ["AUTOGRADER_CHANNELS"] = json.dumps({lesson: [os.getpid(), *fds] for lesson, fds in channels.items()})
    main(arguments)
