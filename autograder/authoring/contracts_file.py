"""Each exercise's contract, read from its answer function's numpydoc docstring (issue #43).

The masters' docstrings are the single source of truth: :func:`build_contracts` parses the
``Parameters`` and ``Returns`` sections of every exercise's answer function and
:func:`write_contracts` keeps ``solutions/coursekit/exercise_contracts.json`` equal to them
(``python -m autograder contracts [--check]``). ``release`` ships the file with the rest of
coursekit; the public checks and the hidden suite both test the forms it admits
(:mod:`coursekit.exercise_contracts`).

The parser is strict: a line it does not understand is a :class:`ContractError` naming the
exercise and the line, never a guess. The forms it reads::

    name : float | int | bool | callable | list | element [, optional]
    name : array_like [, shape (3,) | (N, 3) | (3,) or (N, 3)] [, optional]
    a, b : array_like, shape (4,)            (several parameters, one description)

    ndarray, shape (3, 3)                   (one return)
    ndarray, same shape as ``p_b``
    ndarray, shape (4,) or (N, 4)           (its shape follows the parameter that has alternatives)
    bool | float | dict | tuple of three floats
    u : ndarray, shape (3,)                 (named returns: the function returns a tuple of them)
    J1, J2 : ndarray, shape (3, 3) [each]

A return of type ``ndarray`` promises dtype float64 (the course's arrays), ``real`` included.
A ``bool`` return is a Python ``bool`` or a ``numpy.bool_`` (the grader's wire cannot tell them apart).
"""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

from autograder.lessons.catalog import load_catalog
from autograder.lessons.reference import answer_sources

CONTRACTS_FILE = Path("coursekit") / "exercise_contracts.json"  # under solutions/
VERSION = 1
SCALAR_KINDS = ("float", "int", "bool", "callable", "list", "element")
WORDS = {"two": 2, "three": 3, "four": 4}
_SHAPE = re.compile(r"\(([^()]*)\)")
_SECTION = re.compile(r"^([A-Z][A-Za-z ]+)\n-{3,}$", re.M)


class ContractError(ValueError):
    """A docstring the parser cannot read exactly."""


def _sections(doc: str) -> dict[str, list[str]]:
    marks = list(_SECTION.finditer(doc))
    sections = {}
    for i, mark in enumerate(marks):
        end = marks[i + 1].start() if i + 1 < len(marks) else len(doc)
        sections[mark.group(1).strip()] = doc[mark.end() : end].strip("\n").splitlines()
    return sections


def _headers(lines: list[str]) -> list[str]:
    """The section's unindented lines (each names one entry; indented lines describe it)."""
    return [line.rstrip() for line in lines if line.strip() and not line[0].isspace()]


def parse_shape(text: str) -> list:
    """``"(N, 3)"`` -> ``[["N", 3]]``; ``"(3,) or (N, 3)"`` -> ``[[3], ["N", 3]]``; strict."""
    shapes = []
    parts = [p.strip() for p in text.split(" or ")]
    for part in parts:
        match = _SHAPE.fullmatch(part)
        if not match:
            raise ContractError(f"cannot read the shape {text!r}")
        dims = [d.strip() for d in match.group(1).split(",") if d.strip()]
        if not dims:
            raise ContractError(f"empty shape in {text!r}")
        shape = []
        for d in dims:
            if d.isdigit():
                shape.append(int(d))
            elif re.fullmatch(r"[A-Za-z]", d):
                shape.append(d)
            else:
                raise ContractError(f"cannot read the dimension {d!r} in {text!r}")
        shapes.append(shape)
    return shapes


def parse_parameter(line: str) -> list[dict]:
    """One ``Parameters`` header line -> one entry per parameter it names."""
    names, sep, spec = line.partition(" : ")
    if not sep:
        raise ContractError(f"parameter line without ' : ' type: {line!r}")
    names = [n.strip() for n in names.split(",")]
    if not all(n.isidentifier() for n in names):
        raise ContractError(f"cannot read the parameter names in {line!r}")
    parts = [p.strip() for p in spec.split(",", 1)]
    kind, rest = parts[0], parts[1] if len(parts) > 1 else ""
    optional = False
    if rest == "optional" or rest.endswith(", optional"):
        optional, rest = True, rest.removesuffix("optional").rstrip(", ").strip()
    entry = {"kind": kind, "optional": optional}
    if kind == "array_like":
        if rest:
            if not rest.startswith("shape "):
                raise ContractError(f"cannot read {rest!r} in {line!r} (expected 'shape (...)')")
            entry["shapes"] = parse_shape(rest.removeprefix("shape "))
        else:
            entry["shapes"] = None  # any shape: the docstring does not say
    elif kind in SCALAR_KINDS:
        if rest:
            raise ContractError(f"cannot read {rest!r} after {kind!r} in {line!r}")
    else:
        raise ContractError(f"unknown parameter kind {kind!r} in {line!r}")
    return [{"name": n, **entry} for n in names]


def _ndarray(spec: str, line: str) -> dict:
    """``"shape (3, 3)"``, ``"same shape as ``p_b``"``, ``"shape (3,), real"``, ``"shape (3, 3) each"``."""
    spec = spec.strip().removesuffix(" each").removesuffix(", real").strip()
    same = re.fullmatch(r"same shape as ``(\w+)``", spec)
    if same:
        return {"type": "ndarray", "dtype": "float64", "shape_like": same.group(1)}
    if spec.startswith("shape "):
        return {"type": "ndarray", "dtype": "float64", "shapes": parse_shape(spec.removeprefix("shape "))}
    raise ContractError(f"cannot read the array return {line!r} (expected 'shape (...)' or 'same shape as ``x``')")


def _unnamed_return(spec: str, line: str) -> dict:
    if spec in ("bool", "float", "int", "dict"):
        return {"type": spec}
    tuple_of = re.fullmatch(r"tuple of (two|three|four) (floats|ints)", spec)
    if tuple_of:
        item = {"type": tuple_of.group(2)[:-1]}
        return {"type": "tuple", "items": [dict(item) for _ in range(WORDS[tuple_of.group(1)])]}
    kind, sep, rest = spec.partition(",")
    if kind == "ndarray" and sep:
        return _ndarray(rest, line)
    raise ContractError(f"cannot read the return {line!r}")


def parse_returns(lines: list[str]) -> dict:
    """The ``Returns`` header lines -> the return's contract (a tuple when the entries are named)."""
    if not lines:
        raise ContractError("no Returns section")
    named = [" : " in line for line in lines]
    if not any(named):
        if len(lines) != 1:
            raise ContractError(f"several unnamed returns {lines!r}")
        return _unnamed_return(lines[0].strip(), lines[0])
    if not all(named):
        raise ContractError(f"named and unnamed returns mixed: {lines!r}")
    items = []
    for line in lines:
        names, _, spec = line.partition(" : ")
        for name in (n.strip() for n in names.split(",")):
            if not name.isidentifier():
                raise ContractError(f"cannot read the return names in {line!r}")
            items.append({"name": name, **_unnamed_return(spec.strip(), line)})
    return {"type": "tuple", "items": items}


def contract_of(name: str, source: str) -> dict:
    """The contract of exercise ``name`` from its answer cell's ``source``."""
    tree = ast.parse(source)
    functions = [node for node in tree.body if isinstance(node, ast.FunctionDef) and node.name == name]
    if not functions:
        raise ContractError(f"{name}: the answer cell defines no function {name}")
    function = functions[0]
    doc = ast.get_docstring(function) or ""
    sections = _sections(doc)
    if "Parameters" not in sections or "Returns" not in sections:
        raise ContractError(f"{name}: the docstring needs numpydoc 'Parameters' and 'Returns' sections")
    params = []
    for line in _headers(sections["Parameters"]):
        params.extend(parse_parameter(line))
    args = function.args
    signature = [a.arg for a in args.posonlyargs + args.args]
    documented = [p["name"] for p in params]
    if sorted(documented) != sorted(signature) or len(set(documented)) != len(documented):
        raise ContractError(f"{name}: the docstring's parameters {documented} differ from the signature {signature}")
    params.sort(key=lambda p: signature.index(p["name"]))  # "T1, T2 : ..." groups may list them out of order
    defaults = dict(zip(reversed(signature), reversed(args.defaults)))
    for p in params:
        if p["name"] in defaults:
            p["default"] = ast.unparse(defaults[p["name"]])
    returns = parse_returns(_headers(sections["Returns"]))
    for item in returns.get("items", [returns]):
        like = item.get("shape_like")
        if like and like not in signature:
            raise ContractError(f"{name}: the return's shape follows {like!r}, which is not a parameter")
    return {"params": params, "returns": returns}


def build_contracts(solutions_dir: Path) -> tuple[dict, list[str]]:
    """``(contracts, problems)``: every exercise's contract, and one line per docstring that could not be read."""
    catalog = load_catalog(Path(solutions_dir))
    sources = answer_sources(Path(solutions_dir))
    exercises, problems = {}, []
    for exercise in catalog.exercises:
        try:
            contract = contract_of(exercise.name, sources.get(exercise.name, ""))
        except (ContractError, SyntaxError) as error:
            problems.append(f"{exercise.name} (lesson {exercise.lesson}): {error}")
            continue
        exercises[exercise.name] = {"lesson": exercise.lesson, **contract}
    return {"version": VERSION, "exercises": exercises}, problems


def contracts_text(contracts: dict) -> str:
    return json.dumps(contracts, indent=1, ensure_ascii=False) + "\n"


def write_contracts(solutions_dir: Path, check: bool = False) -> tuple[bool, list[str]]:
    """``(in_sync, problems)``; writes the file unless ``check`` (then only compares)."""
    contracts, problems = build_contracts(Path(solutions_dir))
    path = Path(solutions_dir) / CONTRACTS_FILE
    text = contracts_text(contracts)
    old = path.read_text(encoding="utf-8") if path.exists() else None
    if check:
        return old == text, problems
    if old != text:
        path.write_text(text, encoding="utf-8")
    return True, problems
