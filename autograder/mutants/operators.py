"""Mutation operators: small edits of an answer's syntax tree, each modelling a slip students make.

An operator looks at one reference answer (its parsed cell) and proposes
:class:`Edit` s: "replace this node by that one". Each edit becomes one mutant
(:mod:`autograder.mutants.generate`). The operators are grouped in families
named after the mistakes they model; the families, and the slips each stands
for, are listed in :data:`FAMILIES`.

Every operator is generic (it knows Python and numpy, not the exercise), except
``delegation``, which replaces an answer by a call of the library version of
the map it asks for (the table :data:`DELEGATIONS`).

Examples
--------
>>> import ast
>>> tree = ast.parse("def f(a):\\n    return np.cos(a) - 1.0\\n")
>>> sorted({edit.family for edit in edits(tree, "f")})[:3]
['degrees', 'drop_term', 'sign']
"""

from __future__ import annotations

import ast
import copy
from dataclasses import dataclass

FAMILIES = {
    "sign": "a flipped sign: a minus dropped or added, + for -",
    "drop_term": "a series term, a summand or a factor left out (first-order or one-term series, no normalisation, "
    "no half angle)",
    "small_constant": "a small constant (a small-angle threshold, a step) moved by decades, 1e-15 and 1e-8 … 1e-1",
    "comparison": "an off-by-one comparison (< for <=, > for >=) or a reversed one",
    "swap_args": "arguments swapped (arctan2(x, y), np.cross(b, a), zip(Q, P)) or the parts of a concatenation",
    "matmul": "a product in the wrong order, a transpose added or dropped, a batch of rows read as columns",
    "index": "an index off by one, a transposed entry, a slice off by one (scalar last, q[1:] for q[:3])",
    "degrees": "degrees for radians: np.cos(np.deg2rad(a)), np.rad2deg(np.arctan2(...))",
    "float32": "single precision: dtype=np.float32",
    "integer_lists": "no dtype=float: integer lists stay integers",
    "lists": "no np.asarray: plain lists are used as they come",
    "in_place": "an argument changed in place: x /= n, x[1:] *= -1, a .copy() dropped",
    "sign_det": "np.sign of a determinant where it can be 0, or a sign test turned into np.sign",
    "abs_real": "np.abs for np.real, or np.real dropped (a complex result)",
    "branch": "a branch always or never taken (a missing small-angle, near-π or gimbal-lock branch)",
    "early_return": "a return before the last steps (the canonical sign, the normalisation, the wrap)",
    "clip_removed": "a clip, min or max removed (arccos of 1 + 1e-16, the step rule's floor)",
    "small_angle": "sin x ≈ x, tan x ≈ x, cos x ≈ 1; every sin of a formula replaced (nlerp for slerp)",
    "range": "a loop one step short or long, or starting at 1 (n_terms = 0 is the empty sum)",
    "init": "a sum started at its first term instead of zero",
    "name_swap": "one argument used for another (q0 for q1, P for Q)",
    "nan_blind": "a tolerance test that NaN passes: not (x > tol) for x <= tol",
    "relative_tolerance": "a relative tolerance (np.allclose's rtol=1e-5) where the text says absolute",
    "unwrap": "a helper that wraps an angle into (-π, π] (or another one-argument helper) left out",
    "delegation": "the exercise handed to the library (coursekit.lie, scipy's Rotation, expm)",
}

# the library versions of the maps that exercises ask for (the ``delegation`` family); each is a whole
# answer, written as a student who delegates would write it
DELEGATIONS = {
    "hat": "def hat(w):\n    from coursekit.lie import skew\n    return skew(w)\n",
    "vee": "def vee(W):\n    from coursekit.lie import unskew\n    return unskew(W)\n",
    "exp_series": "def exp_series(W, n_terms):\n    from scipy.linalg import expm\n    return expm(np.asarray(W, dtype=float))\n",
    "exp_so3": "def exp_so3(w):\n    from coursekit.lie import Exp\n    return Exp(w)\n",
    "log_so3": "def log_so3(R):\n    from coursekit.lie import Log\n    return Log(R)\n",
    "axis_angle": (
        "def axis_angle(R):\n    from coursekit.lie import Log\n    w = Log(R)\n"
        "    theta = float(np.linalg.norm(w))\n"
        "    return (w / theta if theta > 0 else np.array([1.0, 0.0, 0.0])), theta\n"
    ),
    "quat_multiply": "def quat_multiply(p, q):\n    from coursekit.lie import quat_product\n    return quat_product(p, q)\n",
    "quat_rotate": (
        "def quat_rotate(q, v):\n    from scipy.spatial.transform import Rotation\n"
        "    return Rotation.from_quat(q, scalar_first=True).apply(np.asarray(v, dtype=float))\n"
    ),
    "quat_from_axis_angle": (
        "def quat_from_axis_angle(u, theta):\n    from scipy.spatial.transform import Rotation\n"
        "    u = np.asarray(u, dtype=float)\n"
        "    q = Rotation.from_rotvec(theta * u / np.linalg.norm(u)).as_quat(scalar_first=True)\n"
        "    return q if np.cos(theta / 2) * q[0] >= 0 else -q\n"
    ),
    "quat_to_matrix": (
        "def quat_to_matrix(q):\n    from scipy.spatial.transform import Rotation\n"
        "    return Rotation.from_quat(q, scalar_first=True).as_matrix()\n"
    ),
    "matrix_to_quat": (
        "def matrix_to_quat(R):\n    from scipy.spatial.transform import Rotation\n"
        "    q = Rotation.from_matrix(R).as_quat(scalar_first=True)\n    return q if q[0] >= 0 else -q\n"
    ),
    "quat_slerp": (
        "def quat_slerp(q0, q1, t):\n    from scipy.spatial.transform import Rotation, Slerp\n"
        "    q0 = np.asarray(q0, dtype=float)\n"
        "    turns = Rotation.from_quat([q0, np.asarray(q1, dtype=float)], scalar_first=True)\n"
        "    q = Slerp([0.0, 1.0], turns)([t]).as_quat(scalar_first=True)[0]\n"
        "    return q if q @ q0 >= 0 else -q\n"
    ),
    "euler_zyx_to_matrix": (
        "def euler_zyx_to_matrix(yaw, pitch, roll):\n    from scipy.spatial.transform import Rotation\n"
        "    return Rotation.from_euler('ZYX', [yaw, pitch, roll]).as_matrix()\n"
    ),
    "matrix_to_euler_zyx": (
        "def matrix_to_euler_zyx(R):\n    from scipy.spatial.transform import Rotation\n"
        "    yaw, pitch, roll = Rotation.from_matrix(R).as_euler('ZYX')\n"
        "    return float(yaw), float(pitch), float(roll)\n"
    ),
    "euler_zyx_to_quat": (
        "def euler_zyx_to_quat(yaw, pitch, roll):\n    from scipy.spatial.transform import Rotation\n"
        "    return Rotation.from_euler('ZYX', [yaw, pitch, roll]).as_quat(scalar_first=True)\n"
    ),
    "quat_to_euler_zyx": (
        "def quat_to_euler_zyx(q):\n    from scipy.spatial.transform import Rotation\n"
        "    yaw, pitch, roll = Rotation.from_quat(q, scalar_first=True).as_euler('ZYX')\n"
        "    return float(yaw), float(pitch), float(roll)\n"
    ),
}

SYMMETRIC = {
    "hypot",
    "maximum",
    "minimum",
    "max",
    "min",
    "add",
    "multiply",
    "allclose",
    "isclose",
    "array_equal",
    "dot",
    "outer",
    "full",
    "isfinite",
}
TRIG = {"cos", "sin", "tan"}
INVERSE_TRIG = {"arctan2", "arccos", "arcsin", "arctan"}
DECADES = (1e-15, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1)
ARRAY_MAKERS = {"array", "asarray"}


@dataclass
class Edit:
    """Replace ``node`` (a node of the original tree) by ``replacement`` (a node, a list of statements)."""

    family: str
    node: ast.AST
    replacement: object
    what: str = ""  # how to say it, when not "old → new"


def _expr(text):
    return ast.parse(text, mode="eval").body


def _np(name, *args, **keywords):
    return ast.Call(
        func=_expr(f"np.{name}"), args=list(args), keywords=[ast.keyword(arg=k, value=v) for k, v in keywords.items()]
    )


def _call_name(node):
    """``"cos"`` for ``np.cos(...)`` and ``cos(...)``; ``"linalg.norm"`` for ``np.linalg.norm``; else ''."""
    if not isinstance(node, ast.Call):
        return ""
    func = node.func
    parts = []
    while isinstance(func, ast.Attribute):
        parts.append(func.attr)
        func = func.value
    if isinstance(func, ast.Name):
        parts.append(func.id)
    parts = parts[::-1]
    if parts and parts[0] in ("np", "numpy"):
        parts = parts[1:]
    return ".".join(parts)


def _is_number(node):
    return isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool)


def _copy(node):
    return copy.deepcopy(node)


# ---------------------------------------------------------------- expression operators
def _sign(node, context):
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        yield Edit("sign", node, _copy(node.operand))
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
        op = ast.Sub() if isinstance(node.op, ast.Add) else ast.Add()
        yield Edit("sign", node, ast.BinOp(_copy(node.left), op, _copy(node.right)))


def _drop_term(node, context):
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub, ast.Mult, ast.Div)):
        yield Edit("drop_term", node, _copy(node.left))
        if isinstance(node.op, (ast.Add, ast.Mult)):
            yield Edit("drop_term", node, _copy(node.right))


def _small_constant(node, context):
    if _is_number(node) and isinstance(node.value, float) and 0.0 < node.value <= 0.1:
        for value in DECADES:
            if abs(value - node.value) > 1e-3 * node.value:
                yield Edit("small_constant", node, ast.Constant(value))


COMPARISON_SWAPS = {ast.Lt: ast.LtE, ast.LtE: ast.Lt, ast.Gt: ast.GtE, ast.GtE: ast.Gt}
COMPARISON_FLIPS = {ast.Lt: ast.Gt, ast.LtE: ast.GtE, ast.Gt: ast.Lt, ast.GtE: ast.LtE}


def _comparison(node, context):
    if not isinstance(node, ast.Compare):
        return
    for position, op in enumerate(node.ops):
        for table in (COMPARISON_SWAPS, COMPARISON_FLIPS):
            if type(op) in table:
                new = _copy(node)
                new.ops[position] = table[type(op)]()
                yield Edit("comparison", node, new)


def _swap_args(node, context):
    name = _call_name(node)
    if name.split(".")[-1] in SYMMETRIC or not name:
        return
    if len(node.args) >= 2 and not any(isinstance(a, ast.Starred) for a in node.args[:2]):
        new = _copy(node)
        new.args[0], new.args[1] = new.args[1], new.args[0]
        if ast.dump(new) != ast.dump(node):
            yield Edit("swap_args", node, new)
    if (
        name in ("concatenate", "stack", "hstack", "vstack")
        and node.args
        and isinstance(node.args[0], ast.List)
        and len(node.args[0].elts) == 2
    ):
        new = _copy(node)
        new.args[0].elts.reverse()
        yield Edit("swap_args", node, new)


def _transposed(node):
    return ast.Attribute(value=_copy(node), attr="T", ctx=ast.Load())


def _is_transpose(node):
    return isinstance(node, ast.Attribute) and node.attr == "T"


def _matmul(node, context):
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult):
        yield Edit("matmul", node, ast.BinOp(_copy(node.right), ast.MatMult(), _copy(node.left)))
        for side in ("left", "right"):
            part = getattr(node, side)
            if not _is_transpose(part):
                new = _copy(node)
                setattr(new, side, _transposed(part))
                yield Edit("matmul", node, new)
        if _is_transpose(node.right):  # P @ R.T, rows, read as R @ P: the batch as columns
            yield Edit("matmul", node, ast.BinOp(_copy(node.right.value), ast.MatMult(), _copy(node.left)))
    if _is_transpose(node):
        yield Edit("matmul", node, _copy(node.value))


def _index(node, context):
    if not isinstance(node, ast.Subscript):
        return
    index = node.slice
    if (
        isinstance(index, ast.Tuple)
        and len(index.elts) == 2
        and all(_is_number(e) for e in index.elts)
        and index.elts[0].value != index.elts[1].value
    ):
        new = _copy(node)
        new.slice.elts.reverse()
        yield Edit("index", node, new)
    numbers = [n for n in ast.walk(index) if _is_number(n) and isinstance(n.value, int)]
    for number in numbers:
        for step in (1, -1):
            value = number.value + step
            if value < -4 or value > 4:
                continue
            new = _copy(node)
            for old, replacement in zip(ast.walk(index), ast.walk(new.slice)):
                if old is number:
                    replacement.value = value
            yield Edit("index", node, new)


def _degrees(node, context):
    name = _call_name(node)
    if name in TRIG and len(node.args) == 1:
        new = _copy(node)
        new.args[0] = _np("deg2rad", _copy(node.args[0]))
        yield Edit("degrees", node, new)
    if name in INVERSE_TRIG:
        yield Edit("degrees", node, _np("rad2deg", _copy(node)))


def _dtype_keyword(node):
    for keyword in getattr(node, "keywords", []):
        if keyword.arg == "dtype" and isinstance(keyword.value, ast.Name) and keyword.value.id == "float":
            return keyword
    return None


def _float32(node, context):
    name = _call_name(node)
    if name in ARRAY_MAKERS | {"eye", "zeros", "ones", "concatenate", "zeros_like"}:
        new = _copy(node)
        new.keywords = [k for k in new.keywords if k.arg != "dtype"] + [
            ast.keyword(arg="dtype", value=_expr("np.float32"))
        ]
        yield Edit("float32", node, new)


def _integer_lists(node, context):
    if _call_name(node) in ARRAY_MAKERS and _dtype_keyword(node) is not None:
        new = _copy(node)
        new.keywords = [k for k in new.keywords if k.arg != "dtype"]
        yield Edit("integer_lists", node, new)


def _lists(node, context):
    if (
        _call_name(node) in ARRAY_MAKERS
        and node.args
        and isinstance(node.args[0], ast.Name)
        and node.args[0].id in context.parameters
    ):
        yield Edit("lists", node, _copy(node.args[0]))


def _in_place_expression(node, context):
    if _call_name(node).endswith("copy") and isinstance(node.func, ast.Attribute) and not node.args:
        yield Edit("in_place", node, _copy(node.func.value))
    if (
        _call_name(node) == "array"
        and node.args
        and isinstance(node.args[0], ast.Name)
        and node.args[0].id in context.parameters
    ):
        new = _copy(node)
        new.func = _expr("np.asarray")
        yield Edit("in_place", node, new)


AUGMENTABLE = (ast.Add, ast.Sub, ast.Mult, ast.Div)


def _in_place_statement(statement, context):
    """For an argument x (or its np.asarray alias, which is the caller's array when that is already a float
    array): x = x OP e → x OP= e; return x OP e → x OP= e; return x; -x[s] → x[s] *= -1 first."""
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1 and isinstance(statement.targets[0], ast.Name):
        value, name = statement.value, statement.targets[0].id
        if (
            isinstance(value, ast.BinOp)
            and isinstance(value.op, AUGMENTABLE)
            and isinstance(value.left, ast.Name)
            and value.left.id == name
            and name in context.parameters
        ):
            yield Edit(
                "in_place",
                statement,
                ast.AugAssign(target=ast.Name(name, ast.Store()), op=type(value.op)(), value=_copy(value.right)),
            )
    if (
        isinstance(statement, ast.Return)
        and isinstance(statement.value, ast.BinOp)
        and isinstance(statement.value.op, AUGMENTABLE)
        and isinstance(statement.value.left, ast.Name)
        and statement.value.left.id in context.parameters
    ):
        name = statement.value.left.id
        yield Edit(
            "in_place",
            statement,
            [
                ast.AugAssign(
                    target=ast.Name(name, ast.Store()),
                    op=type(statement.value.op)(),
                    value=_copy(statement.value.right),
                ),
                ast.Return(value=ast.Name(name, ast.Load())),
            ],
        )
    for node in ast.walk(statement):
        if (
            isinstance(node, ast.UnaryOp)
            and isinstance(node.op, ast.USub)
            and isinstance(node.operand, ast.Subscript)
            and isinstance(node.operand.value, ast.Name)
            and node.operand.value.id in context.parameters
        ):
            target = _copy(node.operand)
            target.ctx = ast.Store()
            new_statement = _replace(statement, node, _copy(node.operand))
            yield Edit(
                "in_place",
                statement,
                [ast.AugAssign(target=target, op=ast.Mult(), value=ast.Constant(-1)), new_statement],
                what=f"{ast.unparse(node)} negated in place",
            )


def _sign_det(node, context):
    if isinstance(node, ast.IfExp) and isinstance(node.test, ast.Compare) and len(node.test.ops) == 1:
        values = [node.body, node.orelse]
        if all(_is_number(v) or (isinstance(v, ast.UnaryOp) and _is_number(v.operand)) for v in values):
            yield Edit("sign_det", node, _np("sign", _copy(node.test.left)))


def _abs_real(node, context):
    if _call_name(node) == "real" and len(node.args) == 1:
        yield Edit("abs_real", node, _np("abs", _copy(node.args[0])))
        yield Edit("abs_real", node, _copy(node.args[0]))


def _branch(node, context):
    if isinstance(node, (ast.If, ast.IfExp)):
        for value in (True, False):
            new = _copy(node)
            new.test = ast.Constant(value)
            yield Edit("branch", node, new, what=f"`{ast.unparse(node.test)}` always {value}")


def _clip_removed(node, context):
    if _call_name(node) in ("min", "max", "clip", "minimum", "maximum") and node.args:
        yield Edit("clip_removed", node, _copy(node.args[0]))


def _small_angle(node, context):
    name = _call_name(node)
    if name in ("sin", "tan") and len(node.args) == 1:
        yield Edit("small_angle", node, _copy(node.args[0]))
    if name == "cos" and len(node.args) == 1:
        yield Edit("small_angle", node, ast.Constant(1.0))


def _range(node, context):
    if _call_name(node) == "range" and len(node.args) == 1:
        n = node.args[0]
        for variant in (
            ast.BinOp(_copy(n), ast.Sub(), ast.Constant(1)),
            ast.BinOp(_copy(n), ast.Add(), ast.Constant(1)),
        ):
            yield Edit("range", node, ast.Call(func=_copy(node.func), args=[variant], keywords=[]))
        yield Edit("range", node, ast.Call(func=_copy(node.func), args=[ast.Constant(1), _copy(n)], keywords=[]))


def _init(node, context):
    if _call_name(node) == "zeros_like" and node.args:
        yield Edit(
            "init", node, ast.Call(func=ast.Attribute(_copy(node.args[0]), "copy", ast.Load()), args=[], keywords=[])
        )


def _name_swap(node, context):
    if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and node.id in context.parameters:
        for other in context.parameters:
            if other != node.id:
                yield Edit("name_swap", node, ast.Name(other, ast.Load()))


def _nan_blind(node, context):
    if (
        isinstance(node, ast.Compare)
        and len(node.ops) == 1
        and isinstance(node.ops[0], (ast.LtE, ast.Lt))
        and any(isinstance(n, ast.Name) and n.id == "tol" for n in ast.walk(node.comparators[0]))
    ):
        flipped = ast.Compare(
            left=_copy(node.left),
            ops=[ast.Gt() if isinstance(node.ops[0], ast.LtE) else ast.GtE()],
            comparators=[_copy(node.comparators[0])],
        )
        yield Edit("nan_blind", node, ast.UnaryOp(ast.Not(), flipped))


def _relative_tolerance(node, context):
    if (
        _call_name(node) == "abs"
        and len(node.args) == 1
        and isinstance(node.args[0], ast.BinOp)
        and isinstance(node.args[0].op, ast.Sub)
    ):
        rtol = ast.BinOp(ast.Constant(1e-05), ast.Mult(), _np("abs", _copy(node.args[0].right)))
        yield Edit("relative_tolerance", node, ast.BinOp(_copy(node), ast.Sub(), rtol))


def _unwrap(node, context):
    if (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id in context.helpers
        and len(node.args) == 1
    ):
        yield Edit("unwrap", node, _copy(node.args[0]))


EXPRESSION_OPERATORS = (
    _sign,
    _drop_term,
    _small_constant,
    _comparison,
    _swap_args,
    _matmul,
    _index,
    _degrees,
    _float32,
    _integer_lists,
    _lists,
    _in_place_expression,
    _sign_det,
    _abs_real,
    _branch,
    _clip_removed,
    _small_angle,
    _range,
    _init,
    _name_swap,
    _nan_blind,
    _relative_tolerance,
    _unwrap,
)


# ---------------------------------------------------------------- statement operators
def _early_returns(function, context):
    """A copy of the last return inserted before an earlier top-level statement, once its names exist."""
    body = function.body
    last = body[-1] if body and isinstance(body[-1], ast.Return) and body[-1].value is not None else None
    if last is None:
        return
    needed = {n.id for n in ast.walk(last.value) if isinstance(n, ast.Name)}
    known = set(context.parameters) | context.globals
    first = 1 if body and _docstring(body[0]) else 0
    for position, statement in enumerate(body[:-1]):
        rest = body[position:-1]
        if (
            position > first
            and needed <= known
            and not all(_is_conversion(s, context) for s in rest)
            and not isinstance(statement, (ast.FunctionDef, ast.Expr))
        ):
            yield Edit(
                "early_return",
                statement,
                [_copy(last), _copy(statement)],
                what=f"return before `{ast.unparse(statement).splitlines()[0]}`",
            )
        for node in ast.walk(statement):
            if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
                known.add(node.id)


def _is_conversion(statement, context):
    """``x = np.asarray(x, ...)`` for a parameter x: skipping it is the ``lists`` family, not an early return."""
    return (
        isinstance(statement, ast.Assign)
        and len(statement.targets) == 1
        and isinstance(statement.targets[0], ast.Name)
        and statement.targets[0].id in context.parameters
        and _call_name(statement.value) in ARRAY_MAKERS
    )


def _nlerp(statement, context):
    """Every np.sin(x) of one statement replaced by x (slerp becomes nlerp)."""
    sines = [n for n in ast.walk(statement) if _call_name(n) == "sin" and len(n.args) == 1]
    if len(sines) >= 2:
        new = _replace_many(statement, [(sine, _copy(sine.args[0])) for sine in sines])
        yield Edit("small_angle", statement, new, what="every sin x of the formula replaced by x")


# ---------------------------------------------------------------- applying edits
@dataclass
class Context:
    parameters: tuple  # the parameter names of the function being mutated (and of its helpers)
    helpers: set  # names of one-argument helper functions defined inside it
    globals: set  # names that need no assignment (np, the setup's imports)


def _replace(tree, target, replacement):
    """A copy of ``tree`` with the node ``target`` replaced by ``replacement``."""
    return _replace_many(tree, [(target, replacement)])


def _replace_many(tree, pairs):
    """A copy of ``tree`` with each ``(node, replacement)`` of ``pairs`` made (nodes of ``tree`` itself)."""
    memo = {}
    new_tree = copy.deepcopy(tree, memo)
    wanted = {id(memo[id(node)]): replacement for node, replacement in pairs}

    class Swap(ast.NodeTransformer):
        def visit(self, node):
            if id(node) in wanted:
                return wanted[id(node)]
            return self.generic_visit(node)

    return Swap().visit(new_tree)


def _docstring(node):
    return isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str)


def edits(tree: ast.Module, exercise: str, known_globals: tuple[str, ...] = ("np",)) -> list[Edit]:
    """Every :class:`Edit` of the function ``exercise`` in ``tree`` (docstrings are left alone)."""
    functions = [n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)]
    main = next((f for f in functions if f.name == exercise), None)
    if main is None:
        return []
    nested = [f for f in ast.walk(main) if isinstance(f, ast.FunctionDef) and f is not main]
    context = Context(
        parameters=tuple(a.arg for a in main.args.args),
        helpers={f.name for f in nested if len(f.args.args) == 1},
        globals=set(known_globals) | {f.name for f in nested},
    )
    found = []
    for statement in main.body:
        if _docstring(statement):
            continue
        for node in ast.walk(statement):
            if _docstring(node):
                continue
            if isinstance(node, ast.stmt) and not isinstance(node, ast.FunctionDef):
                found.extend(_in_place_statement(node, context))
                found.extend(_nlerp(node, context))
            for operator in EXPRESSION_OPERATORS:
                found.extend(operator(node, context))
    found.extend(_early_returns(main, context))
    return found


def apply(tree: ast.Module, edit: Edit) -> str:
    """The source of ``tree`` with ``edit`` made (``ast.unparse``: comments and layout are not kept)."""
    new_tree = _replace(tree, edit.node, edit.replacement)
    ast.fix_missing_locations(new_tree)
    return ast.unparse(new_tree)


def describe(edit: Edit, limit: int = 110) -> str:
    """One line: what the edit does, ``old → new`` or its own words, with the line number."""
    if edit.what:
        text = edit.what
    else:
        new = edit.replacement
        new_text = "; ".join(ast.unparse(n) for n in new) if isinstance(new, list) else ast.unparse(new)
        text = f"{ast.unparse(edit.node).splitlines()[0]} → {new_text.splitlines()[0] if new_text else new_text}"
    text = " ".join(text.split())
    if len(text) > limit:
        text = text[: limit - 1] + "…"
    line = getattr(edit.node, "lineno", None)
    return f"{text} (line {line})" if line else text
