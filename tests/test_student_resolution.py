"""The students' install list resolves, from wheels only, for every Python it promises × every system.

Oracle: pip's own resolver, asked as the student's machine would ask (``pip install --dry-run
--only-binary=:all: --python-version X --platform P``): Pythons from the floor to the newest released
(``student_install.PYTHONS``) × Linux x86-64 (glibc 2.17 to 2.35, Ubuntu 22.04's), macOS 12 on
Intel and on Apple silicon, Windows x86-64. Wheels only: a package that would need a compiler on the
student's machine counts as a failure.

20 resolutions against PyPI, run 5 at a time (4 at a time took 38 min and 6 CPU-minutes on 2 cores under heavy other load,
each waiting on the network most of its time); so the tests are skipped unless
``STUDENT_INSTALL_MATRIX=1``; ``.ci/run`` runs this file in the background beside the test suite, as
``python3 tests/test_student_resolution.py`` (standard library only, no venv needed). A resolution
that pip has not finished within ``TIMEOUT`` seconds (a starved CPU or a slow index, not an answer)
is asked once more on its own before it counts as a failure; every other case keeps its result.
"""

import concurrent.futures
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from student_floor import student_install

TIMEOUT = 1800  # seconds for one pip resolution (about 20 s of CPU each; CI runs them beside the suite)

PLATFORMS = {
    "linux-x86_64": [f"manylinux_2_{minor}_x86_64" for minor in (5, 12, 17, 24, 27, 28, 31, 34, 35)]
    + ["manylinux1_x86_64", "manylinux2010_x86_64", "manylinux2014_x86_64", "linux_x86_64"],
    "macos-x86_64": ["macosx_12_0_x86_64"],  # pip adds every older macOS and universal2
    "macos-arm64": ["macosx_12_0_arm64"],
    "windows-amd64": ["win_amd64"],
}


def resolve(python, platform, requirements, timeout=TIMEOUT):
    """``(ok, seconds, the end of pip's complaint)`` for one Python version on one platform; ``ok`` is
    None when pip gave no answer within ``timeout`` seconds."""
    with tempfile.TemporaryDirectory() as target:
        command = [
            sys.executable,
            "-m",
            "pip",
            "install",
            "--dry-run",
            "--quiet",
            "--ignore-installed",
            "--disable-pip-version-check",
            "--only-binary=:all:",
            "--python-version",
            python,
            "--target",
            target,
            "-r",
            str(requirements),
        ]
        for tag in PLATFORMS[platform]:
            command += ["--platform", tag]
        start = time.monotonic()
        try:
            run = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, round(time.monotonic() - start, 1), f"pip gave no answer within {timeout} s"
    complaint = [line for line in run.stderr.splitlines() if not line.startswith("WARNING: Location")]
    return run.returncode == 0, round(time.monotonic() - start, 1), "\n".join(complaint[-6:])


def _requirements_file(folder):
    path = Path(folder) / "requirements.txt"
    path.write_text(student_install().requirements_text(), encoding="utf-8")
    return path


def _cases():
    return [(python, platform) for python in student_install().PYTHONS for platform in PLATFORMS]


if __name__ != "__main__":
    import pytest

    @pytest.mark.skipif(
        os.environ.get("STUDENT_INSTALL_MATRIX") != "1",
        reason="network-heavy: set STUDENT_INSTALL_MATRIX=1 (.ci/run runs it in the background)",
    )
    @pytest.mark.parametrize(("python", "platform"), _cases())
    def test_the_student_list_resolves_from_wheels(python, platform, tmp_path):
        ok, _, complaint = resolve(python, platform, _requirements_file(tmp_path))
        assert ok is True, f"Python {python} on {platform}:\n{complaint}"


def main(jobs=5):
    """Resolve every case, ``jobs`` at a time; print one line each; exit status 1 if any failed."""
    with tempfile.TemporaryDirectory() as folder:
        requirements = _requirements_file(folder)
        cases = _cases()
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            results = list(pool.map(lambda case: resolve(*case, requirements), cases))
        for index, (ok, _, _) in enumerate(results):
            if ok is None:  # no answer is not a verdict: ask once more, alone
                results[index] = resolve(*cases[index], requirements)
    for (python, platform), (ok, seconds, complaint) in zip(cases, results):
        print(f"Python {python} {platform}: {'ok' if ok else 'FAILED'} ({seconds} s)")
        if ok is not True:
            print("    " + complaint.replace("\n", "\n    "))
    failed = sum(ok is not True for ok, _, _ in results)
    print(f"student install matrix: {len(cases) - failed}/{len(cases)} resolve")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
