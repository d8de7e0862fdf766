"""The students' floor, for real: the oldest Python here, the oldest tested versions, every solved lesson.

Creates a fresh venv with the oldest Python on this machine that the course supports (or ``--python``),
installs the hand-out's ``requirements.txt`` held at its floors (``-c floors.txt``, from
``autograder/authoring/student_install.py``), and runs every solved lesson (the masters of
``solutions/``, with the hand-out's ``coursekit`` beside them) top to bottom in that venv's kernel,
``--jobs`` at a time. Writes to ``--out``:

- ``executed/NN_*.ipynb``: each lesson as it ran, outputs and all (``tests/test_student_floor_grading.py``
  grades these: a notebook last run under the floor versions);
- ``summary.json``: the Python, the versions installed, the install's and each lesson's seconds and
  errors, ``ok``; written last, so its presence means the run is over.

Standard library only, so ``.ci/run`` can start it before the project's own venv exists. Exit status 0
when every lesson ran without an error.

Examples
--------
$ python3 tests/student_floor.py --out /tmp/floor --jobs 2
$ python3 tests/student_floor.py --out /tmp/floor --python /usr/bin/python3 --lessons 01 03
$ python3 tests/student_floor.py --out /tmp/debian --python /usr/bin/python3 --newest   # a student's install
$ python3 tests/student_floor.py --out /tmp/floor --record tests/student_floor.lock.json --if-recorded 03 05

``--record FILE`` keeps a full run's result in the repository (``tests/student_floor.lock.json``), keyed by a hash of
everything the run reads from it: the floors and the Python floor, the Python it ran with (its full version), this
file, the code cells of every solved master and the hand-out's ``coursekit``. When the record is of the same key,
ran clean and is at most ``MAX_AGE_DAYS`` old, only the lessons of ``--if-recorded`` run (the ones
``tests/test_student_floor_grading.py`` grades), and ``summary.json`` carries the record for the rest. A change to a
master's code, to coursekit, to a floor or to this machine's oldest Python runs every lesson again. What the record
does not pin: the versions pip picks for the packages that are not direct requirements (they move on PyPI), hence the
age limit; and outputs, markdown and metadata of the masters, which do not change what runs.
"""

import argparse
import concurrent.futures
import datetime
import glob
import hashlib
import importlib.util
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MAX_AGE_DAYS = 30  # the longest a clean record of the same key stands in for a full run

# Run inside the floor venv: execute one notebook with nbclient (a jupyterlab dependency), save it, and
# print its errors as JSON. MPLBACKEND=Agg as in grading: no front end, no figures to draw twice.
RUN_ONE = r"""
import json, sys
import nbformat
from nbclient import NotebookClient
source, target, cwd = sys.argv[1:4]
nb = nbformat.read(source, as_version=4)
client = NotebookClient(nb, timeout=300, kernel_name="python3", allow_errors=True,
                        resources={"metadata": {"path": cwd}})
client.execute()
nbformat.write(nb, target)
errors = [(i, o.get("ename"), str(o.get("evalue"))[:300]) for i, c in enumerate(nb.cells)
          for o in c.get("outputs", []) if o.get("output_type") == "error"]
print(json.dumps(errors))
"""


def student_install():
    """``autograder/authoring/student_install.py``, loaded by path (no package import, any Python 3)."""
    spec = importlib.util.spec_from_file_location(
        "student_install", ROOT / "autograder" / "authoring" / "student_install.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def version_of(python):
    """``(3, 11, 2)`` for a Python executable, or None when it does not run."""
    try:
        out = subprocess.run(
            [python, "-c", "import sys; print(*sys.version_info[:3])"], capture_output=True, text=True, timeout=30
        )
    except OSError:
        return None
    return tuple(int(part) for part in out.stdout.split()) if out.returncode == 0 else None


def oldest_python(floor):
    """The oldest Python on this machine at or above ``floor`` (pyenv's, ``pythonX.Y`` on PATH, Debian's)."""
    pyenv = Path(os.environ.get("PYENV_ROOT", Path.home() / ".pyenv")) / "versions"
    candidates = set(glob.glob(str(pyenv / "*" / "bin" / "python3")))
    candidates |= {shutil.which(f"python3.{minor}") or "" for minor in range(floor[1], 20)}
    candidates |= {"/usr/bin/python3", sys.executable}
    found = sorted(
        (version, path) for path in candidates if path and (version := version_of(path)) and version[:2] >= floor
    )
    if not found:
        raise SystemExit(f"no Python {floor[0]}.{floor[1]} or newer found")
    return found[0][1]


def install(python, out, module, floors=True):
    """A fresh venv in ``out/venv`` with the student list (at its floors, or as pip picks for a student);
    returns its Python and the seconds."""
    venv = out / "venv"
    shutil.rmtree(venv, ignore_errors=True)
    (out / "requirements.txt").write_text(module.requirements_text(), encoding="utf-8")
    (out / "floors.txt").write_text(module.floors_text(), encoding="utf-8")
    start = time.monotonic()
    subprocess.run([python, "-m", "venv", str(venv)], check=True)
    floor_python = str(venv / "bin" / "python")
    pip = subprocess.run(
        [floor_python, "-m", "pip", "install", "-q", "--disable-pip-version-check", "-r", str(out / "requirements.txt")]
        + (["-c", str(out / "floors.txt")] if floors else []),
        capture_output=True,
        text=True,
    )
    if pip.returncode != 0:
        noise = "WARNING: Location"  # a local mirror that pip's configuration names but this machine lacks
        raise SystemExit(
            "the student list did not install:\n"
            + "\n".join(line for line in pip.stderr.splitlines() if not line.startswith(noise))
        )
    return floor_python, time.monotonic() - start


def installed_versions(floor_python, module):
    names = [name for name, *_ in module.PACKAGES] + ["nbclient"]
    code = (
        "import json, sys\nfrom importlib import metadata\n"
        "print(json.dumps({n: metadata.version(n) for n in sys.argv[1:]}))"
    )
    out = subprocess.run([floor_python, "-c", code, *names], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def lessons_folder(out, only=()):
    """``out/lessons``: the solved masters and the hand-out's coursekit; returns the notebooks to run."""
    folder = out / "lessons"
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(ROOT / "course" / "coursekit", folder / "coursekit", ignore=shutil.ignore_patterns("__pycache__"))
    notebooks = []
    for path in sorted((ROOT / "solutions").glob("[0-9][0-9]_*.ipynb")):
        if not only or path.name[:2] in only:
            shutil.copy(path, folder / path.name)
            notebooks.append(folder / path.name)
    return notebooks


def run_lesson(floor_python, notebook, out):
    executed = out / "executed" / notebook.name
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONHASHSEED="0")
    env.pop("PYTHONPATH", None)
    start = time.monotonic()
    run = subprocess.run(
        [floor_python, "-c", RUN_ONE, str(notebook), str(executed), str(notebook.parent)],
        capture_output=True,
        text=True,
        env=env,
        cwd=notebook.parent,
    )
    seconds = round(time.monotonic() - start, 1)
    if run.returncode != 0:
        return {"seconds": seconds, "errors": [[None, "RunnerFailed", run.stderr[-800:]]]}
    return {"seconds": seconds, "errors": json.loads(run.stdout.strip().splitlines()[-1])}


def running(out):
    """True while the floor run writing to ``out`` is alive (its ``pid`` file names a live process)."""
    try:
        os.kill(int((Path(out) / "pid").read_text(encoding="utf-8")), 0)
    except (OSError, ValueError):
        return False
    return True


def masters():
    return sorted((ROOT / "solutions").glob("[0-9][0-9]_*.ipynb"))


def run_key(module, python_version):
    """A digest of what a full floor run reads: floors, Python, this file, the masters' code cells, coursekit."""
    digest = hashlib.sha256()

    def part(name, data):
        digest.update(f"{name}\0{len(data)}\0".encode() + data)

    part("floors", json.dumps([list(p[:3]) for p in module.PACKAGES] + [list(module.PYTHON_FLOOR)]).encode())
    part("python", ".".join(map(str, python_version)).encode())
    part("runner", Path(__file__).read_bytes())
    for path in masters():
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        code = [
            "".join(c["source"]) if isinstance(c["source"], list) else c["source"]
            for c in cells
            if c["cell_type"] == "code"
        ]
        part(path.name, json.dumps(code).encode())
    kit = ROOT / "course" / "coursekit"
    for path in sorted(p for p in kit.rglob("*") if p.is_file() and "__pycache__" not in p.parts):
        part(str(path.relative_to(kit)), path.read_bytes())
    return digest.hexdigest()[:20]


def read_record(path):
    try:
        return json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def record_stands(record, key, today=None):
    """``(True, why)`` when ``record`` is a clean full run of ``key`` at most ``MAX_AGE_DAYS`` old."""
    if not record or record.get("key") != key:
        return False, "no record of this content, these floors and this Python"
    if not record.get("ok") or {p.name for p in masters()} - set(record.get("lessons", {})):
        return False, "the recorded run failed or left lessons out"
    age = ((today or datetime.date.today()) - datetime.date.fromisoformat(record["date"])).days
    if age > MAX_AGE_DAYS:
        return False, f"the record is {age} days old (over {MAX_AGE_DAYS})"
    return True, f"every lesson ran clean on {record['date']} with the same key"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, type=Path)
    parser.add_argument("--python", help="the Python to build the venv with (default: the oldest here)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--lessons", nargs="*", default=(), help="two-digit numbers (default: all)")
    parser.add_argument(
        "--newest",
        action="store_true",
        help="install as a student does, the newest versions for this Python, not the floors",
    )
    parser.add_argument("--record", type=Path, help="the record of the last full run (read, and written after one)")
    parser.add_argument(
        "--if-recorded", nargs="*", default=None, help="with --record: the lessons to run when the record stands"
    )
    args = parser.parse_args(argv)
    module = student_install()
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    (out / "summary.json").unlink(missing_ok=True)
    (out / "pid").write_text(
        f"{os.getpid()}\n", encoding="utf-8"
    )  # tests/test_student_floor_grading.py waits while it lives
    start = time.monotonic()
    python = args.python or oldest_python(module.PYTHON_FLOOR)
    key = run_key(module, version_of(python))
    recorded = None
    if args.record and not args.newest and not args.lessons:
        stands, why = record_stands(read_record(args.record), key)
        print(f"floor run: {why}; " + (f"running lessons {args.if_recorded or []} only" if stands else "every lesson"))
        if stands and args.if_recorded is not None:
            recorded = read_record(args.record)
            args.lessons = args.if_recorded
    floor_python, install_seconds = install(python, out, module, floors=not args.newest)
    notebooks = lessons_folder(out, tuple(args.lessons))
    shutil.rmtree(out / "executed", ignore_errors=True)
    (out / "executed").mkdir()
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        runs = dict(zip((n.name for n in notebooks), pool.map(lambda n: run_lesson(floor_python, n, out), notebooks)))
    summary = {
        "python": ".".join(map(str, version_of(floor_python))),
        "python_path": python,
        "floors": not args.newest,
        "versions": installed_versions(floor_python, module),
        "install_seconds": round(install_seconds, 1),
        "seconds": round(time.monotonic() - start, 1),
        "lessons": runs,
        "ok": all(not run["errors"] for run in runs.values()),
        "key": key,
        "recorded": recorded,  # the record that stands in for the lessons not run, or None
    }
    if run_key(module, version_of(python)) != key:
        print("floor run: the masters or coursekit changed while it ran; nothing recorded")
    elif args.record and not args.newest and not args.lessons and recorded is None:
        record = {
            "key": key,
            "date": datetime.date.today().isoformat(),
            "ok": summary["ok"],
            "python": summary["python"],
            "versions": summary["versions"],
            "lessons": {name: len(run["errors"]) for name, run in runs.items()},
        }
        args.record.write_text(json.dumps(record, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    (out / "summary.json").write_text(json.dumps(summary, indent=1), encoding="utf-8")
    for name, run in runs.items():
        print(f"{name}: {run['seconds']} s, {len(run['errors'])} error(s) {run['errors'][:2] if run['errors'] else ''}")
    print(
        f"floor run: Python {summary['python']} ({python}), install {summary['install_seconds']} s, "
        f"all {summary['seconds']} s, {'ok' if summary['ok'] else 'FAILED'}"
    )
    return 0 if summary["ok"] else 1


if __name__ == "__main__":
    sys.exit(main())
