"""The named seams of ``reports/``: the exporters and the late-policy rules are plugins found by name in one
registry (``autograder/reports/plugins.py``).

- the registry lists both kinds, with the built-in ones (``canvas``; ``per_day``, the default, and ``cutoff``);
- ``rule = "cutoff"`` in the course config: on time (and within the grace) a lesson keeps its points, after
  that it scores 0; ``per_day`` stays what every existing config means;
- a rule or exporter the registry does not know is refused with the known names and the close one;
- an exporter registered by a third party is offered by ``export --to NAME`` and writes the file.
"""

import re
import signal
from datetime import datetime, timedelta, timezone

import pytest

from autograder.batch.class_run import Outputs, Stamp, save_result
from autograder.grading.results import GRADED, ExerciseResult, LessonResult, StudentResult
from autograder.grading.submissions import NBGRADER, read_student_folder
from autograder.reports import plugins
from autograder.reports.exports import EXPORTERS, canvas
from autograder.reports.lateness import (
    DEFAULT_RULE,
    ConfigError,
    LatePolicy,
    apply_late_policy,
    cutoff,
    parse_config,
    penalty,
    per_day,
)

DUE = datetime(2026, 12, 1, 12, 0, tzinfo=timezone.utc)
LESSONS = ["01", "02", "03"]  # the config's lessons, given: these tests need no catalog


def config(text):
    return parse_config(text, "course.toml", lessons=LESSONS)


def test_the_registry_lists_both_kinds_with_the_built_in_plugins():
    assert set(plugins.KINDS) == {"exporter", "late_policy"}
    assert "canvas" in plugins.names("exporter") and plugins.lookup("exporter", "canvas") is canvas.write
    assert {"cutoff", "per_day"} <= set(plugins.names("late_policy"))
    assert plugins.lookup("late_policy", "per_day") is per_day and plugins.lookup("late_policy", "cutoff") is cutoff
    assert sorted(EXPORTERS) == plugins.names("exporter") and EXPORTERS["canvas"] is canvas.write
    with pytest.raises(ValueError, match=re.escape("unknown kind of plugin 'exporters'; did you mean 'exporter'?")):
        plugins.names("exporters")


def test_the_default_rule_is_per_day_and_gives_what_it_always_gave():
    assert DEFAULT_RULE == "per_day" and LatePolicy().rule == "per_day"
    old_style = config(
        '[lessons."01"]\ndue = 2026-12-01T12:00:00Z\n[late_policy]\npenalty_per_day = 0.1\n'
        'max_penalty = 0.5\n[lessons."03"]\ndue = 2026-12-01T12:00:00Z\npenalty_per_day = 0.25\n'
    )
    assert old_style.policy("01").rule == old_style.policy("03").rule == "per_day"
    assert penalty(old_style, "01", DUE + timedelta(days=1, hours=1)) == (
        0.2,
        "handed in 2026-12-02 13:00 UTC, 1 day 1 h after the due date (2026-12-01 12:00 UTC): 2 days late, −20%",
    )
    assert penalty(old_style, "01", DUE + timedelta(days=30))[0] == 0.5
    assert penalty(old_style, "03", DUE + timedelta(hours=1))[0] == 0.25
    assert (
        penalty(
            config(
                '[late_policy]\nrule = "per_day"\npenalty_per_day = 0.1\n[lessons."01"]\ndue = 2026-12-01T12:00:00Z\n'
            ),
            "01",
            DUE + timedelta(days=1, hours=1),
        )[0]
        == 0.2
    )


def _handed_in(tmp_path, moment):
    """A student folder in nbgrader's layout whose lesson 01 was handed in at ``moment``, and their result."""
    folder = tmp_path / "ana"
    (folder / "lesson01").mkdir(parents=True)
    (folder / "lesson01" / "01_frames.ipynb").write_text("{}", encoding="utf-8")
    (folder / "lesson01" / "timestamp.txt").write_text(f"{moment:%Y-%m-%d %H:%M:%S.%f} UTC", encoding="utf-8")
    lesson = LessonResult(
        "01",
        "Frames",
        "lesson01/01_frames.ipynb",
        GRADED,
        exercises=[ExerciseResult("rot_z", "01", max_points=4.0, points=4.0)],
    )
    return folder, StudentResult("ana", GRADED, lessons=[lesson])


CUTOFF_CONFIGS = {  # the rule for every lesson, or for lesson 01 only (the others keep per_day)
    "course": '[late_policy]\nrule = "cutoff"\ngrace_minutes = 15\n[lessons."01"]\ndue = 2026-12-01T12:00:00Z\n',
    "lesson": "[late_policy]\npenalty_per_day = 0.1\ngrace_minutes = 15\n"
    '[lessons."01"]\ndue = 2026-12-01T12:00:00Z\nrule = "cutoff"\n',
}


@pytest.mark.parametrize("where", CUTOFF_CONFIGS)
@pytest.mark.parametrize(
    "after, points",
    [(timedelta(hours=-1), 4.0), (timedelta(minutes=14), 4.0), (timedelta(minutes=16), 0.0), (timedelta(days=9), 0.0)],
)
def test_the_cutoff_rule_gives_full_points_before_due_and_grace_and_zero_after(tmp_path, where, after, points):
    course = config(CUTOFF_CONFIGS[where])
    assert course.policy("02").rule == ("cutoff" if where == "course" else "per_day")
    assert course.policy("01").rule == "cutoff" and course.policy("01").grace_minutes == 15
    folder, result = _handed_in(tmp_path, DUE + after)
    student = read_student_folder(folder, layout=NBGRADER)  # timestamp.txt counts in nbgrader's layout only
    lesson = apply_late_policy(result, student, course).lessons[0]
    assert lesson.raw_points == 4.0 and lesson.points == points and result.score == points
    if points:
        assert lesson.late_penalty == 0 and lesson.late_note == ""
    else:
        assert lesson.late_penalty == 1.0 and lesson.late_note.endswith("after the cutoff, −100%"), lesson.late_note


def test_the_cutoff_rule_takes_max_penalty_when_the_config_caps_it():
    course = config('[late_policy]\nrule = "cutoff"\nmax_penalty = 0.5\n[lessons."01"]\ndue = 2026-12-01T12:00:00Z\n')
    assert penalty(course, "01", DUE + timedelta(hours=1))[0] == 0.5


@pytest.mark.parametrize(
    "toml, expected",
    [
        (
            '[late_policy]\nrule = "cut-off"\n',
            "course.toml [late_policy]: unknown late-policy rule 'cut-off'; "
            "did you mean 'cutoff'? (known: cutoff, per_day)",
        ),
        ('[lessons."03"]\nrule = "per_week"\n', """course.toml [lessons."03"]: unknown late-policy rule 'per_week'"""),
        ("[late_policy]\nrule = 3\n", 'rule must be a name in quotes, e.g. rule = "per_day"'),
        ('rule = "cutoff"\n', "unknown key 'rule' (it belongs in [late_policy] or a lesson's table)"),
        ('[late_policy]\nrules = "cutoff"\n', "did you mean 'rule'?"),
    ],
)
def test_an_unknown_rule_is_refused_with_the_known_names(toml, expected):
    with pytest.raises(ConfigError, match=re.escape(expected)) as refused:
        config(toml)
    if "unknown late-policy rule" in expected:
        assert "(known: cutoff, per_day" in str(refused.value)


def test_an_unknown_exporter_names_the_known_ones():
    with pytest.raises(plugins.UnknownPlugin) as refused:
        EXPORTERS["canvass"]
    assert (
        str(refused.value) == f"unknown exporter 'canvass'; did you mean 'canvas'? (known: "
        f"{', '.join(plugins.names('exporter'))})"
    )
    assert isinstance(refused.value, KeyError) and "canvass" not in EXPORTERS  # still a mapping, as the dict was


def test_a_name_cannot_be_taken_twice():
    with pytest.raises(
        ValueError, match="exporter 'canvas' is already registered by autograder.reports.exports.canvas.write"
    ):
        plugins.register("exporter", "canvas")(lambda results, catalog, roster=(), missing="zero": "")


@pytest.fixture
def names_only():
    """A third party's exporter: one student id per line, registered for the test only."""

    @plugins.register("exporter", "names-only")
    def write(results, catalog, roster=(), missing="zero"):
        return "".join(f"{result.student_id} {result.score:g}\n" for result in results)

    yield write
    plugins.unregister("exporter", "names-only")
    assert "names-only" not in plugins.names("exporter")


def test_a_registered_exporter_is_offered_by_the_export_command(names_only, tmp_path, capsys):
    from autograder.cli import build_parser, main

    args = build_parser().parse_args(["export", "--out", str(tmp_path), "--to", "names-only"])
    assert args.to == "names-only" and EXPORTERS["names-only"] is names_only

    outputs = Outputs(tmp_path / "results")
    for student, points in (("ana", 4.0), ("bo", 1.5)):
        lesson = LessonResult(
            "01",
            "Frames",
            "01_frames.ipynb",
            GRADED,
            exercises=[ExerciseResult("rot_z", "01", max_points=4.0, points=points)],
        )
        save_result(
            outputs, StudentResult(student, GRADED, lessons=[lesson]), Stamp("0" * 16, {}), "2026-12-01T12:00:00+00:00"
        )
    before = signal.getsignal(signal.SIGINT)
    try:
        status = main(["export", "--out", str(outputs.root), "--to", "names-only"])
    finally:
        signal.signal(signal.SIGINT, before)  # main installs its own Ctrl-C handler
    assert status == 0, capsys.readouterr()
    assert (outputs.root / "names-only.csv").read_text(encoding="utf-8") == "ana 4\nbo 1.5\n"
    assert "names-only gradebook import format" in capsys.readouterr().out


def test_an_exporter_the_registry_does_not_know_is_refused_by_the_command(tmp_path, capsys):
    from autograder.cli import build_parser

    with pytest.raises(SystemExit):
        build_parser().parse_args(["export", "--out", str(tmp_path), "--to", "names-only"])
    assert "invalid choice: 'names-only' (choose from 'canvas'" in capsys.readouterr().err
