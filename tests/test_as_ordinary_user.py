"""Every wall holds as an ordinary user too: the security tests, run again as ``nobody``.

As root (CI, servers) the sandboxes run as unprivileged uids of their own; as an ordinary user (an
instructor's laptop) bubblewrap makes a user namespace and every sandbox is that user. This test runs
the files that test the walls a second time as ``nobody`` (tests/ordinary_user.py) and requires them to
pass. When the whole suite already runs as an ordinary user, it is skipped: those files ran that way.
"""

import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

import ordinary_user

ROOT = Path(__file__).resolve().parent.parent
# what only root can do or see, the reasons a wall's test may give for skipping as nobody
ONLY_AS_ROOT = ("as an ordinary user every sandbox runs as that user", "only root makes device files")
WALLS = [
    "test_sandbox.py",
    "test_sandbox_view.py",
    "test_warm_slots.py",
    "test_fresh_process_state.py",
    "test_feeder.py",
    "test_watching.py",
    "test_cleanup.py",
    "test_class_layout.py",
    "test_notebook_stage_walls.py",
    "test_adversarial.py",
]


@pytest.mark.skipif(
    not ordinary_user.running_as_root() or ordinary_user.available() is not None,
    reason="runs only as root; as an ordinary user the files ran that way already",
)
def test_the_walls_hold_as_an_ordinary_user():
    work = Path(tempfile.mkdtemp(prefix="walls-as-nobody-"))  # not under pytest's root-only folder
    (work / "holds").mkdir()
    work.chmod(0o777)
    files = [str(ROOT / "tests" / name) for name in WALLS if (ROOT / "tests" / name).exists()]
    # --basetemp: pytest's own clean-up of older numbered folders is recursive, and these tests make deep trees
    command = [
        sys.executable,
        "-m",
        "pytest",
        *files,
        "-p",
        "no:cacheprovider",
        "-n",
        "1",
        "-q",
        "--rootdir",
        str(ROOT),
        "-o",
        "addopts=",
        "--basetemp",
        str(work / "tmp"),
        "-rs",
    ]
    try:
        # -u: an earlier test of this worker may have left the variable set, and -n needs xdist loaded
        wrapped = ["env", "-u", "PYTEST_DISABLE_PLUGIN_AUTOLOAD", "HOME=/tmp", *command]
        argv = ordinary_user.as_ordinary_user(wrapped, reach=[ROOT, work], holds=work / "holds")
        done = subprocess.run(argv, cwd=work, capture_output=True, text=True, timeout=2400)
    finally:
        subprocess.run(["rm", "-rf", str(work)], check=False)
    summary = (done.stdout.strip().splitlines() or [""])[-1]
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-2000:]
    assert "passed" in summary, summary
    skipped = [line for line in done.stdout.splitlines() if line.startswith("SKIPPED")]
    unexpected = [line for line in skipped if not any(reason in line for reason in ONLY_AS_ROOT)]
    assert not unexpected, "skipped as an ordinary user, for a reason that is not the mode's:\n" + "\n".join(unexpected)
