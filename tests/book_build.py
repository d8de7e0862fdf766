"""One build of the book per test run, shared by every test file that reads it.

The book executes every lesson (about two minutes), so ``tests/test_book.py``
and ``tests/test_accessibility.py`` read the same build: the first worker to
ask builds it under a lock in the run's shared temporary folder (xdist's
recipe: the parent of each worker's base temp), the others wait and reuse it.
"""

import fcntl
import subprocess
import sys

from autograder.lessons.paths import PROJECT_ROOT


def shared_book(tmp_path_factory, worker_input=None):
    """Path of the built book (``OUT/index.html``), built once per run; fails with sphinx's own report."""
    root = tmp_path_factory.getbasetemp()
    if worker_input is not None:  # an xdist worker: its base temp is popen-gwN/ inside the run's folder
        root = root.parent
    out, done = root / "shared-book" / "book", root / "shared-book.done"
    with open(root / "shared-book.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not done.exists():
            run = subprocess.run(
                [sys.executable, "-m", "autograder", "book", "--out", str(out)],
                cwd=PROJECT_ROOT,
                capture_output=True,
                text=True,
                timeout=900,
            )
            assert run.returncode == 0, run.stderr[-3000:]
            done.write_text("built\n", encoding="utf-8")
    return out
