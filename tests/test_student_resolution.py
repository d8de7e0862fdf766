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

The last result is kept in the repository, ``tests/student_resolution.lock.json``: the hash of what the matrix
depends on (the install list, ``student_install.PYTHONS``, ``PLATFORMS``, pip's flags below) and each case's
verdict. ``.ci/run`` runs ``python3 tests/test_student_resolution.py --if-changed``: the matrix again only when that
hash differs from the record's, the record failed, or it is older than ``MAX_AGE_DAYS`` (PyPI moves under a list
that does not: a yanked wheel, a release that drops a Python). ``test_the_recorded_matrix_is_of_the_current_list``
(not network-heavy, never skipped) fails when the list or the matrix changed and nobody re-ran it: run
``python3 tests/test_student_resolution.py`` and commit the record it writes. What the record guarantees: this list
resolved for every case on the record's date; not that PyPI still serves the same wheels today.
"""

import concurrent.futures
import datetime
import hashlib
import json
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


RECORD = Path(__file__).resolve().with_name("student_resolution.lock.json")
MAX_AGE_DAYS = 30  # the longest .ci/run trusts a record of an unchanged list


def pip_flags():
    """The flags every resolution passes to ``pip install`` (part of what the record is a record of)."""
    return ["--dry-run", "--quiet", "--ignore-installed", "--disable-pip-version-check", "--only-binary=:all:"]


def matrix_key():
    """A digest of everything a resolution's verdict depends on in this repository."""
    module = student_install()
    parts = {
        "requirements": module.requirements_text(),
        "pythons": list(module.PYTHONS),
        "platforms": PLATFORMS,
        "pip flags": pip_flags(),
    }
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()[:20]


def read_record(path=RECORD):
    try:
        return json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def record_is_current(record, today=None, max_age_days=MAX_AGE_DAYS):
    """``(True, why)`` when ``record`` is of the current list and matrix, all resolved, within ``max_age_days``."""
    if not record or record.get("key") != matrix_key():
        return False, "the install list or the matrix changed since the record"
    if not record.get("ok"):
        return False, "the recorded run failed"
    today = today or datetime.date.today()
    age = (today - datetime.date.fromisoformat(record["date"])).days
    if age > max_age_days:
        return False, f"the record is {age} days old (over {max_age_days})"
    return True, f"unchanged since {record['date']} ({record['summary']})"


def resolve(python, platform, requirements, timeout=TIMEOUT):
    """``(ok, seconds, the end of pip's complaint)`` for one Python version on one platform; ``ok`` is
    None when pip gave no answer within ``timeout`` seconds."""
    with tempfile.TemporaryDirectory() as target:
        command = [
            sys.executable,
            "-m",
            "pip",
            "install",
            *pip_flags(),
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

    def test_the_recorded_matrix_is_of_the_current_list():
        record = read_record()
        assert record is not None, f"no record in {RECORD.name}: run python3 tests/test_student_resolution.py"
        assert record["key"] == matrix_key(), (
            "the install list or the matrix changed since the recorded run: "
            "run python3 tests/test_student_resolution.py and commit tests/student_resolution.lock.json"
        )
        assert record["ok"] and set(record["cases"]) == {f"{python} {platform}" for python, platform in _cases()}
        assert all(verdict == "ok" for verdict in record["cases"].values()), record["cases"]

    def test_a_record_is_trusted_only_when_current_complete_and_recent():
        record = {"key": matrix_key(), "ok": True, "date": "2026-11-01", "summary": "20/20 resolve"}
        assert record_is_current(record, today=datetime.date(2026, 11, 28))[0]
        assert not record_is_current(record, today=datetime.date(2026, 12, 2))[0]  # 31 days
        assert not record_is_current(dict(record, ok=False), today=datetime.date(2026, 11, 2))[0]
        assert not record_is_current(dict(record, key="other"), today=datetime.date(2026, 11, 2))[0]
        assert not record_is_current(None)[0]


def main(argv=None, jobs=5):
    """Resolve every case, ``jobs`` at a time; print one line each; record the result in ``RECORD``;
    exit status 1 if any failed. ``--if-changed``: do nothing when the record is current."""
    argv = sys.argv[1:] if argv is None else argv
    if "--if-changed" in argv:
        current, why = record_is_current(read_record())
        if current:
            print(f"student install matrix: not run, {why}; the record: {RECORD.name}")
            return 0
        print(f"student install matrix: running, {why}")
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
    summary = f"{len(cases) - failed}/{len(cases)} resolve"
    print(f"student install matrix: {summary}")
    record = {
        "key": matrix_key(),
        "date": datetime.date.today().isoformat(),
        "ok": not failed,
        "summary": summary,
        "cases": {
            f"{python} {platform}": {True: "ok", None: "no answer"}.get(ok, "FAILED")
            for (python, platform), (ok, _, _) in zip(cases, results)
        },
    }
    RECORD.write_text(json.dumps(record, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
