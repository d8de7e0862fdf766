"""Named seams: the gradebook exporters and the late-policy rules, each found by its name in one registry.

Two kinds of plugin, :data:`KINDS`:

``"exporter"``
    ``write(results, catalog, roster, missing="zero") -> str``, the text of an LMS import file
    (:mod:`autograder.reports.exports`); ``python -m autograder export --to NAME`` offers every one.
``"late_policy"``
    ``rule(policy, late) -> (fraction, reason)``: the fraction of a lesson's points lost when it was handed in
    ``late`` seconds after its due date, past the grace, under ``policy`` (a
    :class:`~autograder.reports.lateness.LatePolicy`), and the words for it (``"2 days late"``); chosen by
    ``rule = "NAME"`` in the course config (:mod:`autograder.reports.lateness`).

A plugin registers itself with the :func:`register` decorator when its module is imported; the built-in ones
are imported with :mod:`autograder.reports.exports` (``canvas``) and :mod:`autograder.reports.lateness`
(``per_day``, the default, and ``cutoff``). A name the registry does not know raises :class:`UnknownPlugin`,
which lists the known names and the close one.

Examples
--------
>>> @register("exporter", "names-only")
... def write(results, catalog, roster=(), missing="zero"):
...     return "".join(f"{result.student_id}\\n" for result in results)
>>> lookup("exporter", "names-only") is write
True
>>> "names-only" in names("exporter")
True
>>> lookup("exporter", "names_only")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
autograder.reports.plugins.UnknownPlugin: unknown exporter 'names_only'; did you mean 'names-only'? (known: ...)
>>> unregister("exporter", "names-only")
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterator, Mapping
from typing import Any, TypeVar

KINDS = {"exporter": "exporter", "late_policy": "late-policy rule"}  # kind -> what the messages call one

_REGISTRY: dict[str, dict[str, Any]] = {kind: {} for kind in KINDS}

Plugin = TypeVar("Plugin", bound=Callable[..., Any])


class UnknownPlugin(KeyError):
    """No plugin of that kind has that name; the message lists the known ones (and the close one)."""

    def __str__(self) -> str:  # KeyError would show the message in quotes
        return str(self.args[0]) if self.args else ""


def did_you_mean(given: str, known: list[str] | tuple[str, ...]) -> str:
    """``"; did you mean 'penalty_per_day'?"`` when one of ``known`` is close to ``given``, else ``""``.

    Examples
    --------
    >>> did_you_mean("penalty_per_days", ("grace_minutes", "penalty_per_day"))
    "; did you mean 'penalty_per_day'?"
    >>> did_you_mean("deadline", ("due",))
    ''
    """
    close = difflib.get_close_matches(given, known, n=1, cutoff=0.6)
    return f"; did you mean {close[0]!r}?" if close else ""


def _plugins(kind: str) -> dict[str, Any]:
    if kind not in _REGISTRY:
        raise ValueError(
            f"unknown kind of plugin {kind!r}{did_you_mean(kind, tuple(KINDS))} (the kinds are {', '.join(KINDS)})"
        )
    return _REGISTRY[kind]


def _origin(plugin: Any) -> str:
    return f"{getattr(plugin, '__module__', '?')}.{getattr(plugin, '__qualname__', repr(plugin))}"


def register(kind: str, name: str) -> Callable[[Plugin], Plugin]:
    """A decorator that registers a function as the plugin ``name`` of ``kind`` and returns it unchanged.

    Parameters
    ----------
    kind : str
        One of :data:`KINDS`: ``"exporter"`` or ``"late_policy"``.
    name : str
        What the user writes: ``export --to NAME``, ``rule = "NAME"``.

    Returns
    -------
    Callable
        The decorator.

    Raises
    ------
    ValueError
        For an unknown ``kind``, an empty name, or a name another function of that kind already has
        (registering the same function again, as a reloaded module does, is allowed).

    Examples
    --------
    >>> @register("late_policy", "half-off")
    ... def half_off(policy, late):
    ...     return min(policy.max_penalty, 0.5), "late"
    >>> unregister("late_policy", "half-off")
    """
    plugins = _plugins(kind)
    if not isinstance(name, str) or not name.strip():
        raise ValueError(f"a {KINDS[kind]} needs a name, not {name!r}")

    def decorator(plugin: Plugin) -> Plugin:
        existing = plugins.get(name)
        if existing is not None and _origin(existing) != _origin(plugin):
            raise ValueError(f"{KINDS[kind]} {name!r} is already registered by {_origin(existing)}")
        plugins[name] = plugin
        return plugin

    return decorator


def unregister(kind: str, name: str) -> None:
    """Forget the plugin ``name`` of ``kind`` (a test's own, say); nothing happens when there is none."""
    _plugins(kind).pop(name, None)


def names(kind: str) -> list[str]:
    """The names registered for ``kind``, sorted.

    Examples
    --------
    >>> import autograder.reports.exports, autograder.reports.lateness  # the built-in plugins
    >>> names("late_policy")
    ['cutoff', 'per_day']
    """
    return sorted(_plugins(kind))


def lookup(kind: str, name: str) -> Any:
    """The plugin ``name`` of ``kind``.

    Raises
    ------
    UnknownPlugin
        When ``kind`` has no plugin of that name; the message names the close one and all the known ones.

    Examples
    --------
    >>> from autograder.reports import lateness
    >>> lookup("late_policy", "per_day") is lateness.per_day
    True
    >>> lookup("late_policy", "cut_off")
    Traceback (most recent call last):
    ...
    autograder.reports.plugins.UnknownPlugin: unknown late-policy rule 'cut_off'; did you mean 'cutoff'? (known: cutoff, per_day)
    """
    plugins = _plugins(kind)
    if name not in plugins:
        known = sorted(plugins)
        hint = did_you_mean(name, known) if isinstance(name, str) else ""
        raise UnknownPlugin(f"unknown {KINDS[kind]} {name!r}{hint} (known: {', '.join(known) or 'none'})")
    return plugins[name]


class Registered(Mapping):
    """A live, read-only view of one kind: ``{name: plugin}``, always as registered now.

    ``EXPORTERS = Registered("exporter")`` keeps ``sorted(EXPORTERS)`` and ``EXPORTERS[name]`` working for an
    exporter registered after the view was made.

    Examples
    --------
    >>> from autograder.reports.exports import EXPORTERS
    >>> "canvas" in EXPORTERS and sorted(EXPORTERS) == names("exporter")
    True
    """

    def __init__(self, kind: str) -> None:
        _plugins(kind)
        self.kind = kind

    def __getitem__(self, name: str) -> Any:
        return lookup(self.kind, name)

    def __iter__(self) -> Iterator[str]:
        return iter(names(self.kind))

    def __len__(self) -> int:
        return len(_plugins(self.kind))

    def __repr__(self) -> str:
        return f"Registered({self.kind!r}: {', '.join(names(self.kind))})"
