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
"""

import argparse
import concurrent.futures
import glob
import importlib.util
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

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
    args = parser.parse_args(argv)
    module = student_install()
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    (out / "summary.json").unlink(missing_ok=True)
    start = time.monotonic()
    python = args.python or oldest_python(module.PYTHON_FLOOR)
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
    }
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
