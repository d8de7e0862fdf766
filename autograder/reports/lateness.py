"""Due dates and a late policy, from a small course config file, applied to a graded student.

The config is TOML (``grade --config course.toml``); everything in it is optional::

    timezone = "Europe/Berlin"        # for due dates written without an offset (default UTC)

    [late_policy]                     # for every lesson, unless the lesson says otherwise
    grace_minutes = 15                # this late still counts as on time
    penalty_per_day = 0.10            # fraction of the lesson's points lost per started day late
    max_penalty = 0.50                # never more than this fraction

    [lessons."03"]
    due = 2026-12-01T23:59:00         # TOML date-time, with or without an offset
    penalty_per_day = 0.25            # a lesson may override any policy value

When a lesson was handed in comes from nbgrader's ``timestamp.txt`` (in the
notebook's folder or a parent, up to the student's folder), else from the
notebook file's modification time; ``grade --ignore-mtimes`` takes no time from
files (:attr:`CourseConfig.ignore_file_times`), since copying or downloading a
class resets them (:mod:`autograder.reports.copied_times` warns when they look
like that). The raw points are kept beside the penalised ones
(:class:`~autograder.grading.results.LessonResult`). Due dates and hand-in times
are written in the course's timezone.

Examples
--------
>>> config = parse_config('[lessons."01"]\\ndue = 2026-12-01T12:00:00Z\\n[late_policy]\\npenalty_per_day = 0.1')
>>> config.due["01"].isoformat()
'2026-12-01T12:00:00+00:00'
>>> penalty(config, "01", datetime(2026, 12, 2, 13, 0, tzinfo=timezone.utc))
(0.2, 'handed in 2026-12-02 13:00 UTC, 1 day 1 h after the due date (2026-12-01 12:00 UTC): 2 days late, −20%')
"""

import math
import tomllib
from dataclasses import dataclass, field
from datetime import date, datetime, time, timezone
from pathlib import Path
from zoneinfo import ZoneInfo, ZoneInfoNotFoundError

from dateutil import parser as date_parser

POLICY_KEYS = ("grace_minutes", "penalty_per_day", "max_penalty")


class ConfigError(ValueError):
    """The course config cannot be used; the message says where and why."""


@dataclass(frozen=True)
class LatePolicy:
    grace_minutes: float = 0.0
    penalty_per_day: float = 0.0
    max_penalty: float = 1.0


@dataclass(frozen=True)
class CourseConfig:
    due: dict = field(default_factory=dict)  # lesson number -> aware datetime
    policies: dict = field(default_factory=dict)  # lesson number -> LatePolicy
    default_policy: LatePolicy = LatePolicy()
    source: str = ""  # the file's text (part of the grader's fingerprint)
    zone: ZoneInfo = ZoneInfo("UTC")  # the course's timezone: due dates and hand-in times are shown in it
    ignore_file_times: bool = False  # grade --ignore-mtimes: no lateness from the notebooks' file times

    def policy(self, lesson):
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
    values = {key: table.get(key, getattr(base, key)) for key in POLICY_KEYS}
    for key, value in values.items():
        if not isinstance(value, (int, float)) or value < 0:
            raise ConfigError(f"{where}: {key} must be a number ≥ 0, not {value!r}")
    if values["max_penalty"] > 1:
        raise ConfigError(f"{where}: max_penalty is a fraction of the points, at most 1")
    return LatePolicy(**{key: float(value) for key, value in values.items()})


def parse_config(text, name="course config"):
    """A :class:`CourseConfig` from TOML text; raise :class:`ConfigError` with the place of a mistake."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ConfigError(f"{name} is not valid TOML: {error}") from None
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


def load_config(path):
    """Read ``path`` (see the module docstring)."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as error:
        raise ConfigError(f"cannot read the course config {path}: {error.strerror}") from None
    return parse_config(text, Path(path).name)


def submission_time(notebook, folder):
    """When ``notebook`` was handed in: nbgrader's ``timestamp.txt`` beside it or above it, else its mtime."""
    return recorded_time(notebook, folder) or file_time(notebook)


def recorded_time(notebook, folder):
    """The time in nbgrader's ``timestamp.txt`` beside ``notebook`` or above it (up to ``folder``), or None."""
    notebook, folder = Path(notebook), Path(folder)
    for directory in [notebook.parent, *notebook.parent.parents]:
        stamp = directory / "timestamp.txt"
        if stamp.is_file() and not stamp.is_symlink():
            try:
                moment = date_parser.parse(stamp.read_text(encoding="utf-8", errors="replace").strip()[:100])
                return moment if moment.tzinfo else moment.replace(tzinfo=timezone.utc)
            except (ValueError, OverflowError):
                break  # a damaged timestamp: fall back to the file's own time
        if directory == folder:
            break
    return None


def file_time(notebook):
    """The modification time of ``notebook`` (aware, UTC), or None when it cannot be read."""
    try:
        return datetime.fromtimestamp(Path(notebook).lstat().st_mtime, tz=timezone.utc)
    except OSError:
        return None


def _span(seconds):
    days, rest = divmod(int(seconds), 86400)
    hours, rest = divmod(rest, 3600)
    parts = ([f"{days} day{'s' if days != 1 else ''}"] if days else []) + ([f"{hours} h"] if hours else [])
    return " ".join(parts) or f"{max(1, rest // 60)} min"


def local_time(moment, zone):
    """``moment`` as people read it in the course's timezone ``zone``: ``2026-12-01 23:59 CET``."""
    return moment.astimezone(zone).strftime("%Y-%m-%d %H:%M %Z")


def penalty(config, lesson, handed_in):
    """``(fraction of the lesson's points lost, sentence)``; ``(0.0, "")`` when on time or without a due date."""
    due = config.due.get(lesson)
    if due is None or handed_in is None:
        return 0.0, ""
    policy = config.policy(lesson)
    late = (handed_in - due).total_seconds()
    if late <= policy.grace_minutes * 60:
        return 0.0, ""
    days = math.ceil(late / 86400)
    fraction = round(min(policy.max_penalty, days * policy.penalty_per_day), 4)
    return fraction, (f"handed in {local_time(handed_in, config.zone)}, {_span(late)} after the due date "
                      f"({local_time(due, config.zone)}): "
                      f"{days} day{'s' if days != 1 else ''} late, −{100 * fraction:g}%")


def apply_late_policy(result, folder, config):
    """Record when each lesson was handed in, where that time came from, its due date and, past it, the
    penalty (in place)."""
    for lesson in result.lessons:
        if config is not None and lesson.number in config.due:
            lesson.due = local_time(config.due[lesson.number], config.zone)
        if lesson.status == "missing":
            continue
        notebook = Path(folder) / lesson.notebook
        handed_in, lesson.submitted_from = recorded_time(notebook, folder), "timestamp.txt"
        if handed_in is None and not (config is not None and config.ignore_file_times):
            handed_in, lesson.submitted_from = file_time(notebook), "file time"
        if handed_in is None:
            lesson.submitted_from = ""
            continue
        lesson.submitted_at = handed_in.astimezone(timezone.utc).isoformat(timespec="seconds")
        if config is not None:
            lesson.late_penalty, lesson.late_note = penalty(config, lesson.number, handed_in)
    return result


def late_summary(result):
    """``01 −20%, 03 −10%``: the lessons ``result`` (a StudentResult) handed in late and what each cost."""
    return ", ".join(f"{lesson.number} −{100 * lesson.late_penalty:g}%" for lesson in result.lessons
                     if lesson.late_penalty)


def due_dates(results):
    """``lesson 01 2026-12-01 23:59 CET, lesson 03 ...``: the due dates recorded in ``results`` (StudentResults),
    in the course's timezone; ``""`` when no lesson had one."""
    due = {lesson.number: lesson.due for result in results for lesson in result.lessons if lesson.due}
    return ", ".join(f"lesson {number} {when}" for number, when in sorted(due.items()))
