"""Due dates and a late policy, from a small course config file, applied to a graded student.

The config is TOML (``grade --config late.toml``); everything in it is optional::

    timezone = "Europe/Berlin"        # for due dates written without an offset (default UTC)

    [late_policy]                     # for every lesson, unless the lesson says otherwise
    rule = "per_day"                  # how lateness costs points: "per_day" (the default) or "cutoff"
    grace_minutes = 15                # this late still counts as on time
    penalty_per_day = 0.10            # per_day: fraction of the lesson's points lost per started day late
    max_penalty = 0.50                # never more than this fraction

    [lessons."03"]
    due = 2026-12-01T23:59:00         # TOML date-time, with or without an offset
    penalty_per_day = 0.25            # a lesson may override any policy value

    [lessons."09"]
    due = 2026-12-20T23:59:00
    rule = "cutoff"                   # past the due date and the grace, the lesson loses max_penalty (all of it)

The rules are late-policy plugins (:mod:`autograder.reports.plugins`, kind ``"late_policy"``): a function
``rule(policy, late) -> (fraction, reason)`` called with the :class:`LatePolicy` and the seconds after the due
date, only past the grace. ``per_day`` (:func:`per_day`) takes ``penalty_per_day`` for every started day, at most
``max_penalty``; ``cutoff`` (:func:`cutoff`) takes ``max_penalty`` at once (by default 1: the lesson scores 0),
whatever ``penalty_per_day`` says. Another rule is registered with ``@register("late_policy", "NAME")`` and
chosen with ``rule = "NAME"``; a rule the registry does not know is refused with the known ones.

When a lesson was handed in comes from one trusted source: in nbgrader's layout only
(declared, or nbgrader's course root: :func:`~autograder.grading.submissions.detect_layout`),
nbgrader's ``timestamp.txt`` at the top of the submission (``<student>/<assignment>/``),
else the notebook file's modification time as collected; never a file inside
the student's own folders (:func:`~autograder.grading.submissions.handed_in_at`). A time outside
1970..2200, or text that is no date, is refused for that lesson: it is graded, its lateness "unknown"
with the reason.
``grade --ignore-mtimes`` takes no time from files
(:attr:`CourseConfig.ignore_file_times`), since copying or downloading a class
resets them (:mod:`autograder.reports.copied_times` warns when they look like
that). The raw points are kept beside the penalised ones
(:class:`~autograder.grading.results.LessonResult`). Due dates and hand-in times
are written in the course's timezone.

Examples
--------
>>> config = parse_config('[lessons."01"]\\ndue = 2026-12-01T12:00:00Z\\n[late_policy]\\npenalty_per_day = 0.1', "course.toml", ["01"])
>>> config.due["01"].isoformat()
'2026-12-01T12:00:00+00:00'
>>> penalty(config, "01", datetime(2026, 12, 2, 13, 0, tzinfo=timezone.utc))
(0.2, 'handed in 2026-12-02 13:00 UTC, 1 day 1 h after the due date (2026-12-01 12:00 UTC): 2 days late, −20%')
"""

from __future__ import annotations

import difflib
import math
import tomllib
from dataclasses import dataclass, field
from datetime import date, datetime, time, timezone  # noqa: F401 (timezone: the examples use it)
from pathlib import Path
from zoneinfo import ZoneInfo, ZoneInfoNotFoundError

from autograder.grading.results import StudentResult
from autograder.grading.submissions import (
    FOLDERS,
    StudentFolder,
    collected_time,
    handed_in_at,
    nbgrader_timestamp,
    read_student_folder,
)
from autograder.reports.plugins import UnknownPlugin, did_you_mean, lookup, register

DEFAULT_RULE = "per_day"
NUMBER_KEYS = ("grace_minutes", "penalty_per_day", "max_penalty")
POLICY_KEYS = ("rule", *NUMBER_KEYS)
# The config's schema: the keys each table may hold (values are checked where they are read).
TOP_KEYS = ("timezone", "late_policy", "lessons")
LESSON_KEYS = ("due", *POLICY_KEYS)


class ConfigError(ValueError):
    """The course config cannot be used; the message says where and why."""


@dataclass(frozen=True)
class LatePolicy:
    """The late policy of a lesson: its values from the config, and the name of the rule that reads them."""

    grace_minutes: float = 0.0
    penalty_per_day: float = 0.0
    max_penalty: float = 1.0
    rule: str = DEFAULT_RULE  # the name of a registered late-policy rule (autograder.reports.plugins)


@dataclass(frozen=True)
class CourseConfig:
    due: dict = field(default_factory=dict)  # lesson number -> aware datetime
    policies: dict = field(default_factory=dict)  # lesson number -> LatePolicy
    default_policy: LatePolicy = LatePolicy()
    source: str = ""  # the file's text (part of the grader's fingerprint)
    zone: ZoneInfo = ZoneInfo("UTC")  # the course's timezone: due dates and hand-in times are shown in it
    ignore_file_times: bool = False  # grade --ignore-mtimes: no lateness from the notebooks' file times

    def policy(self, lesson: str) -> LatePolicy:
        return self.policies.get(lesson, self.default_policy)


def _aware(value, zone, where):
    if isinstance(value, datetime):
        moment = value
    elif isinstance(value, date):
        moment = datetime.combine(value, time(23, 59, 59))
    else:
        raise ConfigError(f"{where}: a due date must be a TOML date-time such as 2026-12-01T23:59:00")
    return moment if moment.tzinfo else moment.replace(tzinfo=zone)


def _policy(table, base, where):
    values = {key: table.get(key, getattr(base, key)) for key in NUMBER_KEYS}
    for key, value in values.items():
        if not isinstance(value, (int, float)) or value < 0:
            raise ConfigError(f"{where}: {key} must be a number ≥ 0, not {value!r}")
    if values["max_penalty"] > 1:
        raise ConfigError(f"{where}: max_penalty is a fraction of the points, at most 1")
    rule = table.get("rule", base.rule)
    if not isinstance(rule, str):
        raise ConfigError(f'{where}: rule must be a name in quotes, e.g. rule = "{DEFAULT_RULE}"')
    try:
        lookup("late_policy", rule)
    except UnknownPlugin as error:
        raise ConfigError(f"{where}: {error}") from None
    return LatePolicy(rule=rule, **{key: float(value) for key, value in values.items()})


def _check_keys(table, known, where):
    """Raise :class:`ConfigError` for the first key of ``table`` that the schema does not know, with the close name."""
    for key in table:
        if key not in known:
            elsewhere = (
                " (it belongs in [late_policy] or a lesson's table)"
                if key in POLICY_KEYS
                else ' (it belongs in a lesson\'s table, [lessons."03"])'
                if key == "due"
                else ""
            )
            raise ConfigError(
                f"{where}: unknown key {key!r}{elsewhere or did_you_mean(key, known)} (known here: {', '.join(known)})"
            )


def _check_lesson(number, lessons, name):
    """Raise :class:`ConfigError` unless ``number`` is one of ``lessons``; ``3`` suggests ``"03"``."""
    if number in lessons:
        return
    padded = number.zfill(2) if number.isdigit() else number
    close = padded if padded in lessons else (difflib.get_close_matches(number, lessons, n=1) or [None])[0]
    hint = f'; did you mean [lessons."{close}"] (quoted, two digits)?' if close else ""
    raise ConfigError(f"{name}: unknown lesson {number!r} under [lessons]{hint} (the lessons are {' '.join(lessons)})")


def parse_config(text: str, name: str, lessons: list[str]) -> CourseConfig:
    """A :class:`CourseConfig` from TOML text; raise :class:`ConfigError` with the place of a mistake.

    Every key is checked against the schema (``TOP_KEYS``, ``POLICY_KEYS``, ``LESSON_KEYS``) and every lesson
    against ``lessons`` (the course's graded lesson numbers); a misspelt name gets the close one. A
    ``rule`` must be a registered late-policy rule (:func:`autograder.reports.plugins.names`).
    """
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ConfigError(f"{name} is not valid TOML: {error}") from None
    _check_keys(data, TOP_KEYS, name)
    for key in ("late_policy", "lessons"):
        if not isinstance(data.get(key, {}), dict):
            raise ConfigError(f"{name}: {key} must be a table ([{key}])")
    if not isinstance(data.get("timezone", "UTC"), str):
        raise ConfigError(f'{name}: timezone must be a name in quotes, e.g. timezone = "Europe/Berlin"')
    _check_keys(data.get("late_policy", {}), POLICY_KEYS, f"{name} [late_policy]")
    for number, table in data.get("lessons", {}).items():
        _check_lesson(number, lessons, name)
        if isinstance(table, dict):
            _check_keys(table, LESSON_KEYS, f'{name} [lessons."{number}"]')
    try:
        zone = ZoneInfo(data.get("timezone", "UTC"))
    except (ZoneInfoNotFoundError, ValueError):
        raise ConfigError(f"{name}: unknown timezone {data.get('timezone')!r} (e.g. Europe/Berlin)") from None
    default = _policy(data.get("late_policy", {}), LatePolicy(), f"{name} [late_policy]")
    due, policies = {}, {}
    for number, table in data.get("lessons", {}).items():
        where = f'{name} [lessons."{number}"]'
        if not isinstance(table, dict):
            raise ConfigError(f"{where} must be a table")
        if "due" in table:
            due[number] = _aware(table["due"], zone, where)
        if any(key in table for key in POLICY_KEYS):
            policies[number] = _policy(table, default, where)
    return CourseConfig(due=due, policies=policies, default_policy=default, source=text, zone=zone)


def load_config(path: str | Path, lessons: list[str]) -> CourseConfig:
    """Read ``path`` (see the module docstring); ``lessons``: the course's graded lesson numbers."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as error:
        raise ConfigError(f"cannot read the course config {path}: {error.strerror}") from None
    return parse_config(text, Path(path).name, lessons)


def submission_time(notebook: Path, folder: Path, layout: str = FOLDERS) -> datetime | None:
    """When ``notebook`` was handed in: one trusted source per ``layout`` (see
    :func:`autograder.grading.submissions.handed_in_at`)."""
    return handed_in_at(notebook, folder, layout)


def recorded_time(notebook: Path, folder: Path) -> datetime | None:
    """The time nbgrader recorded for ``notebook`` (``<student>/<assignment>/timestamp.txt``), or None; only
    meaningful in nbgrader's layout."""
    return nbgrader_timestamp(notebook, folder)


def file_time(notebook: Path) -> datetime | None:
    """The modification time of ``notebook`` as collected (aware, UTC), or None when it cannot be read."""
    return collected_time(notebook)


def _span(seconds):
    days, rest = divmod(int(seconds), 86400)
    hours, rest = divmod(rest, 3600)
    parts = ([f"{days} day{'s' if days != 1 else ''}"] if days else []) + ([f"{hours} h"] if hours else [])
    return " ".join(parts) or f"{max(1, rest // 60)} min"


def local_time(moment: datetime, zone: ZoneInfo) -> str:
    """``moment`` as people read it in the course's timezone ``zone``: ``2026-12-01 23:59 CET``."""
    return moment.astimezone(zone).strftime("%Y-%m-%d %H:%M %Z")


@register("late_policy", DEFAULT_RULE)
def per_day(policy: LatePolicy, late: float) -> tuple[float, str]:
    """The default rule: ``penalty_per_day`` for every started day ``late`` (seconds past the due date), at most
    ``max_penalty``; ``(fraction, "2 days late")``.

    Examples
    --------
    >>> per_day(LatePolicy(penalty_per_day=0.1, max_penalty=0.5), 90_000)
    (0.2, '2 days late')
    """
    days = math.ceil(late / 86400)
    fraction = round(min(policy.max_penalty, days * policy.penalty_per_day), 4)
    return fraction, f"{days} day{'s' if days != 1 else ''} late"


@register("late_policy", "cutoff")
def cutoff(policy: LatePolicy, late: float) -> tuple[float, str]:
    """Past the due date and the grace, the lesson loses ``max_penalty`` at once (by default all its points);
    ``penalty_per_day`` plays no part.

    Examples
    --------
    >>> cutoff(LatePolicy(rule="cutoff"), 60)
    (1.0, 'after the cutoff')
    """
    return round(policy.max_penalty, 4), "after the cutoff"


def penalty(config: CourseConfig, lesson: str, handed_in: datetime | None) -> tuple[float, str]:
    """``(fraction of the lesson's points lost, sentence)``; ``(0.0, "")`` when on time or without a due date.

    Past the grace, the lesson's rule (:attr:`LatePolicy.rule`, a registered late-policy plugin) says the fraction.
    """
    due = config.due.get(lesson)
    if due is None or handed_in is None:
        return 0.0, ""
    policy = config.policy(lesson)
    late = (handed_in - due).total_seconds()
    if late <= policy.grace_minutes * 60:
        return 0.0, ""
    fraction, reason = lookup("late_policy", policy.rule)(policy, late)
    return fraction, (
        f"handed in {local_time(handed_in, config.zone)}, {_span(late)} after the due date "
        f"({local_time(due, config.zone)}): {reason}, −{100 * fraction:g}%"
    )


def apply_late_policy(
    result: StudentResult, folder: Path | StudentFolder, config: CourseConfig | None
) -> StudentResult:
    """Record when each lesson was handed in, where that time came from, its due date and, past it, the
    penalty (in place).

    ``folder``: the student's folder as read once (:class:`~autograder.grading.submissions.StudentFolder`:
    its layout decides whether nbgrader's ``timestamp.txt`` is read), or a path read in the one-folder-per-student
    layout. A time that cannot be used (out of 1970..2200, not a date) leaves that lesson graded, its lateness
    unknown with the reason (``submitted_from`` ``"unknown"``, ``late_note``, a line of ``problems``).
    """
    student = folder if isinstance(folder, StudentFolder) else read_student_folder(folder)
    file_times = not (config is not None and config.ignore_file_times)
    for lesson in result.lessons:
        if config is not None and lesson.number in config.due:
            lesson.due = local_time(config.due[lesson.number], config.zone)
        if lesson.status == "missing":
            continue
        hand_in = student.hand_in(lesson.notebook, file_times)
        if hand_in.moment is None:
            lesson.submitted_from = "unknown" if hand_in.problem else ""
            if hand_in.problem:
                lesson.late_note = f"lateness unknown: {hand_in.problem}"
                result.problems.append(f"lesson {lesson.number}: {lesson.late_note}")
            continue
        lesson.submitted_from = hand_in.source
        lesson.submitted_at = hand_in.moment.isoformat(timespec="seconds")
        if config is not None:
            try:
                lesson.late_penalty, lesson.late_note = penalty(config, lesson.number, hand_in.moment)
            except (OverflowError, ValueError) as error:  # bounded times make this unreachable; still, this lesson only
                lesson.late_penalty, lesson.late_note = 0.0, f"lateness unknown: {error}"
                result.problems.append(f"lesson {lesson.number}: {lesson.late_note}")
    return result


def late_summary(result: StudentResult) -> str:
    """``01 −20%, 03 −10%``: the lessons ``result`` (a StudentResult) handed in late and what each cost."""
    return ", ".join(
        f"{lesson.number} −{100 * lesson.late_penalty:g}%" for lesson in result.lessons if lesson.late_penalty
    )


def due_dates(results: list[StudentResult]) -> str:
    """``lesson 01 2026-12-01 23:59 CET, lesson 03 ...``: the due dates recorded in ``results`` (StudentResults),
    in the course's timezone; ``""`` when no lesson had one."""
    due = {lesson.number: lesson.due for result in results for lesson in result.lessons if lesson.due}
    return ", ".join(f"lesson {number} {when}" for number, when in sorted(due.items()))
