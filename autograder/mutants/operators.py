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
    "return_type": "the right numbers in the wrong type: an array as a nested list, a float as a 0-d or 1-element "
    "array, a bool as an int or np.bool_, several values as a list",
    "return_dtype": "an array returned in float32, or with an integer dtype where its entries are whole numbers",
    "argument_write": "an argument written for some inputs only: normalised or negated in place under a test",
    "threshold": "a tolerance read another way: a threshold doubled, halved, ×10 or ÷10, or one side of the test "
    "squared (x**2 < tol, the squared norm for the norm)",
    "small_guard": "a small value guarded where the answer needs no guard (x / max(n, 1e-12)), or a guard that "
    "catches only an exact zero (n == 0 for n < 1e-12)",
    "iterations": "an iteration count fixed (range(iters) → range(3), a while loop run 3 times) or a convergence "
    "test loosened",
    "input_form": "an input form dropped: x.astype(float) (tuples and lists fail), np.asarray only for lists "
    "(tuples and integer arrays pass through)",
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


# ---------------------------------------------------------------- the families of issue #43, item 5
ARRAY_RETURNING = {
    "array",
    "asarray",
    "concatenate",
    "hstack",
    "vstack",
    "stack",
    "column_stack",
    "eye",
    "identity",
    "zeros",
    "ones",
    "diag",
    "cross",
    "outer",
    "zeros_like",
    "linalg.solve",
    "linalg.inv",
    "Exp",
    "ExpSE3",
    "skew",
}
ERROR_MEASURES = {"linalg.norm", "sqrt", "max", "abs", "sum"}  # a tolerance on these is on a length or an error
WHOLE_NUMBER_MAKERS = {"eye", "identity", "zeros", "ones"}
TOLERANCE_NAMES = ("tol", "eps")


def _array_like(node, context):
    """Is ``node`` an expression that surely gives an array (a maker, a product with a matrix, a known array name)?"""
    if isinstance(node, ast.Call):
        name = _call_name(node)
        if name.split(".")[-1] in ("copy", "astype", "reshape") and isinstance(node.func, ast.Attribute):
            return True
        return name in ARRAY_RETURNING
    if isinstance(node, ast.Attribute):
        return node.attr == "T"
    if isinstance(node, ast.Name):
        return node.id in context.arrays
    if isinstance(node, ast.BinOp):
        if isinstance(node.op, ast.MatMult):
            return (
                _is_transpose(node.left)
                or _is_transpose(node.right)
                or _array_like(node.left, context)
                and (_array_like(node.right, context))
            )
        return _array_like(node.left, context) or _array_like(node.right, context)
    if isinstance(node, ast.Subscript):
        return isinstance(node.slice, (ast.Slice, ast.Tuple)) and _array_like(node.value, context)
    return False


def _own_expressions(statement):
    """The expression nodes of ``statement`` that belong to no statement nested in it."""
    stack = [child for child in ast.iter_child_nodes(statement) if not isinstance(child, ast.stmt)]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(child for child in ast.iter_child_nodes(node) if not isinstance(child, ast.stmt))


def _method(value, name, *args):
    return ast.Call(func=ast.Attribute(_copy(value), name, ast.Load()), args=list(args), keywords=[])


def _return_type(node, context):
    if not isinstance(node, ast.Return) or node.value is None or id(node) in context.nested:
        return
    value = node.value
    if isinstance(value, ast.Tuple):
        yield Edit("return_type", node, ast.Return(ast.List([_copy(e) for e in value.elts], ast.Load())))
        for position, element in enumerate(value.elts):
            if _array_like(element, context):
                new = _copy(value)
                new.elts[position] = _method(element, "tolist")
                yield Edit("return_type", node, ast.Return(new))
        return
    name = _call_name(value)
    if name == "bool" and len(value.args) == 1:
        yield Edit("return_type", node, ast.Return(_copy(value.args[0])))
        yield Edit("return_type", node, ast.Return(ast.Call(ast.Name("int", ast.Load()), [_copy(value.args[0])], [])))
    elif name == "float" and len(value.args) == 1:
        yield Edit("return_type", node, ast.Return(_np("array", _copy(value.args[0]))))
        yield Edit("return_type", node, ast.Return(_np("array", ast.List([_copy(value.args[0])], ast.Load()))))
    elif isinstance(value, (ast.Compare, ast.BoolOp)):
        yield Edit("return_type", node, ast.Return(ast.Call(ast.Name("int", ast.Load()), [_copy(value)], [])))
    elif _array_like(value, context):
        yield Edit("return_type", node, ast.Return(_method(value, "tolist")))


def _whole_numbers(node):
    """``node`` with every whole float constant made an int, or None when it holds a constant that is no number."""
    new = _copy(node)
    changed = False
    for part in ast.walk(new):
        if isinstance(part, ast.Constant):
            if not _is_number(part):
                return None
            if isinstance(part.value, float) and part.value.is_integer():
                part.value = int(part.value)
                changed = True
        elif not isinstance(part, (ast.List, ast.Tuple, ast.UnaryOp, ast.USub, ast.Load)):
            return None
    return new if changed else None


def _return_dtype(node, context):
    if not isinstance(node, ast.Return) or node.value is None or id(node) in context.nested:
        return
    values = node.value.elts if isinstance(node.value, ast.Tuple) else [node.value]
    for value in values:
        if not _array_like(value, context):
            continue
        yield Edit(
            "return_dtype",
            value,
            _np("asarray", _copy(value), dtype=_expr("np.float32")),
            what=f"{ast.unparse(value)} returned as float32",
        )
        name = _call_name(value)
        if name in ("array", "asarray") and value.args:
            whole = _whole_numbers(value.args[0])
            if whole is not None:
                new = _copy(value)
                new.args[0] = whole
                new.keywords = [k for k in new.keywords if k.arg != "dtype"]
                yield Edit("return_dtype", value, new)
        if name in WHOLE_NUMBER_MAKERS:
            new = _copy(value)
            new.keywords = [k for k in new.keywords if k.arg != "dtype"] + [
                ast.keyword(arg="dtype", value=ast.Name("int", ast.Load()))
            ]
            yield Edit("return_dtype", value, new)


def _scalar_like(node):
    return isinstance(node, ast.Name) or (
        isinstance(node, ast.Call) and _call_name(node) in ("linalg.norm", "sqrt", "float", "sum", "abs", "sin")
    )


def _argument_write(statement, context):
    """Writes into the caller's array under a test: ``x = e`` in an if-body → ``x[...] = e``; ``x / n`` →
    ``if n != 1.0: x /= n`` before the statement, then ``x``."""
    if (
        isinstance(statement, ast.Assign)
        and len(statement.targets) == 1
        and isinstance(statement.targets[0], ast.Name)
        and statement.targets[0].id in context.writable | context.views
        and not any(_call_name(n) in ARRAY_MAKERS for n in ast.walk(statement.value))  # a conversion: a copy
        and id(statement) not in context.nested
    ):
        name = statement.targets[0].id
        conditional = id(statement) in context.conditional
        if conditional or any(isinstance(n, ast.Name) and n.id == name for n in ast.walk(statement.value)):
            target = ast.Subscript(ast.Name(name, ast.Load()), ast.Constant(Ellipsis), ast.Store())
            yield Edit(
                "argument_write",
                statement,
                ast.Assign(targets=[target], value=_copy(statement.value)),
                what=f"{ast.unparse(statement)} written into the caller's array ({name}[...] = ...)"
                + (" under a test" if conditional else ""),
            )
    if isinstance(statement, (ast.FunctionDef, ast.Expr)) or id(statement) in context.nested:
        return
    for node in _own_expressions(statement):
        if (
            isinstance(node, ast.BinOp)
            and isinstance(node.op, ast.Div)
            and isinstance(node.left, ast.Name)
            and node.left.id in context.writable
            and _scalar_like(node.right)
        ):
            name = node.left.id
            guard = ast.If(
                test=ast.Compare(_copy(node.right), [ast.NotEq()], [ast.Constant(1.0)]),
                body=[ast.AugAssign(ast.Name(name, ast.Store()), ast.Div(), _copy(node.right))],
                orelse=[],
            )
            yield Edit(
                "argument_write",
                statement,
                [guard, _replace(statement, node, ast.Name(name, ast.Load()))],
                what=f"{ast.unparse(node)} → if {ast.unparse(node.right)} != 1.0: {name} /= "
                f"{ast.unparse(node.right)} (in place)",
            )


def _threshold_side(node):
    """0 or 1: which side of a one-operator comparison is the threshold (a positive float, a tolerance name)."""
    if not isinstance(node, ast.Compare) or len(node.ops) != 1:
        return None
    if not isinstance(node.ops[0], (ast.Lt, ast.LtE, ast.Gt, ast.GtE)):
        return None
    sides = [node.left, node.comparators[0]]

    def is_threshold(side):
        if _is_number(side) and isinstance(side.value, float) and side.value > 0:
            return True
        return any(isinstance(n, ast.Name) and n.id.lower() in TOLERANCE_NAMES for n in ast.walk(side))

    found = [position for position, side in enumerate(sides) if is_threshold(side)]
    if len(found) != 1 or _is_number(sides[1 - found[0]]):
        return None
    return found[0]


def _with_sides(node, sides):
    return ast.Compare(left=sides[0], ops=[_copy(node.ops[0])], comparators=[sides[1]])


def _threshold(node, context):
    side = _threshold_side(node)
    if side is None:
        return
    sides = [node.left, node.comparators[0]]
    threshold, value = sides[side], sides[1 - side]
    if _is_number(threshold):
        factors = () if threshold.value <= 0.1 else (2.0, 0.5, 10.0, 0.1)
        moved = [ast.Constant(float(f"{threshold.value * factor:.12g}")) for factor in factors]
    else:
        moved = [ast.BinOp(_copy(threshold), ast.Mult(), ast.Constant(factor)) for factor in (2, 0.5, 10, 0.1)]
    for new_threshold in moved:
        new_sides = [_copy(node.left), _copy(node.comparators[0])]
        new_sides[side] = new_threshold
        yield Edit("threshold", node, _with_sides(node, new_sides))
    if not (
        isinstance(threshold, ast.BinOp | ast.Name)
        or _call_name(value) in ERROR_MEASURES
        or isinstance(value, ast.BinOp)
        and isinstance(value.op, ast.MatMult)
    ):
        return  # a small-angle threshold on an angle: its square is a moved threshold (small_constant)
    squared = (
        _copy(value.args[0])
        if _call_name(value) == "sqrt" and len(value.args) == 1
        else ast.BinOp(_copy(value), ast.Pow(), ast.Constant(2))
    )
    new_sides = [_copy(node.left), _copy(node.comparators[0])]
    new_sides[1 - side] = squared
    yield Edit("threshold", node, _with_sides(node, new_sides))


def _small_guard(node, context):
    if (
        isinstance(node, ast.BinOp)
        and isinstance(node.op, ast.Div)
        and (_scalar_like(node.right) or isinstance(node.right, ast.BinOp) and isinstance(node.right.op, ast.MatMult))
        and _call_name(node.right) not in ("linalg.norm", "sqrt", "sum")  # zero only for inputs ruled out
        and not (isinstance(node.right, ast.Name) and node.right.id in context.lengths)
        and not any(ast.unparse(node.right) in text for text in context.compared)
        and _call_name(node.right) not in ("max", "maximum")
    ):
        guarded = ast.Call(ast.Name("max", ast.Load()), [_copy(node.right), ast.Constant(1e-12)], [])
        yield Edit("small_guard", node, ast.BinOp(_copy(node.left), ast.Div(), guarded))
    side = _threshold_side(node)
    if (
        side == 1
        and _is_number(node.comparators[0])
        and node.comparators[0].value <= 1e-3
        and _call_name(node.left) not in ("linalg.norm", "sqrt")  # a convergence test: exact 0 is never met
    ):
        below = isinstance(node.ops[0], (ast.Lt, ast.LtE))
        new = ast.Compare(
            left=_copy(node.left), ops=[ast.Eq() if below else ast.NotEq()], comparators=[ast.Constant(0.0)]
        )
        yield Edit("small_guard", node, new, what=f"{ast.unparse(node)} → {ast.unparse(new)} (only an exact zero)")


def _iterations(statement, context):
    """A loop's count fixed (range(iters) → range(3), range(100) → range(3), a while loop run 3 times),
    or its convergence test loosened ×1000."""
    if isinstance(statement, ast.For) and _call_name(statement.iter) == "range":
        call = statement.iter
        for position, argument in enumerate(call.args):
            if (isinstance(argument, ast.Name) and len(call.args) == 1) or (
                _is_number(argument) and isinstance(argument.value, int) and argument.value >= 5
            ):
                new = _copy(call)
                new.args[position] = ast.Constant(3)
                yield Edit("iterations", call, new)
    if isinstance(statement, ast.While):
        stop = ast.If(test=ast.UnaryOp(ast.Not(), _copy(statement.test)), body=[ast.Break()], orelse=[])
        loop = ast.For(
            target=ast.Name("_", ast.Store()),
            iter=_expr("range(3)"),
            body=[stop] + [_copy(s) for s in statement.body],
            orelse=[_copy(s) for s in statement.orelse],
        )
        yield Edit("iterations", statement, loop, what=f"`while {ast.unparse(statement.test)}` run 3 times")
    if isinstance(statement, (ast.For, ast.While)):
        for inner in ast.walk(statement):
            if (
                isinstance(inner, ast.If)
                and any(isinstance(s, (ast.Break, ast.Return)) for s in inner.body)
                and _threshold_side(inner.test) is not None
            ):
                test = inner.test
                side = _threshold_side(test)
                sides = [_copy(test.left), _copy(test.comparators[0])]
                threshold = sides[side]
                sides[side] = (
                    ast.Constant(float(f"{threshold.value * 1000:.12g}"))
                    if _is_number(threshold)
                    else ast.BinOp(threshold, ast.Mult(), ast.Constant(1000))
                )
                yield Edit("iterations", test, _with_sides(test, sides), what=f"{ast.unparse(test)} loosened ×1000")


def _input_form(node, context):
    if (
        _call_name(node) in ARRAY_MAKERS
        and node.args
        and isinstance(node.args[0], ast.Name)
        and node.args[0].id in context.parameters
        and _dtype_keyword(node) is not None
    ):
        name = node.args[0]
        yield Edit("input_form", node, _method(name, "astype", ast.Name("float", ast.Load())))
        only_lists = ast.IfExp(
            test=ast.Call(ast.Name("isinstance", ast.Load()), [_copy(name), ast.Name("list", ast.Load())], []),
            body=_copy(node),
            orelse=_copy(name),
        )
        yield Edit("input_form", node, only_lists, what=f"{ast.unparse(node)} only for a list")
    if isinstance(node, ast.ExceptHandler) and isinstance(node.type, ast.Tuple) and len(node.type.elts) >= 2:
        for kept in node.type.elts:
            new = _copy(node)
            new.type = _copy(kept)
            yield Edit("input_form", node, new, what=f"except {ast.unparse(node.type)} → except {ast.unparse(kept)}")
    if (
        isinstance(node, ast.If)
        and isinstance(node.test, ast.BoolOp)
        and isinstance(node.test.op, ast.Or)
        and node.body
        and isinstance(node.body[-1], ast.Return)
    ):
        for position, dropped in enumerate(node.test.values):
            rest = [_copy(v) for k, v in enumerate(node.test.values) if k != position]
            new = _copy(node)
            new.test = rest[0] if len(rest) == 1 else ast.BoolOp(ast.Or(), rest)
            yield Edit("input_form", node, new, what=f"input test `{ast.unparse(dropped)}` dropped")


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
    _return_type,
    _return_dtype,
    _threshold,
    _small_guard,
    _input_form,
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
    arrays: set = frozenset()  # local names every assignment of which surely gives an array
    writable: set = frozenset()  # array arguments, and names bound to them by np.asarray (the caller's array)
    views: set = frozenset()  # names bound to a part of a writable name (Rs[k], x[:3]): a view of the caller's array
    conditional: set = frozenset()  # ids of the statements in the body of an if
    lengths: set = frozenset()  # names bound to a root, a norm or a max (positive, or guarded already)
    nested: set = frozenset()  # ids of the nodes of helper functions defined inside the answer
    compared: tuple = ()  # the source of every comparison (a quantity compared somewhere is guarded)


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
    context.nested = {id(n) for f in nested for n in ast.walk(f)}
    context.compared = tuple(ast.unparse(n) for n in ast.walk(main) if isinstance(n, ast.Compare))
    context.arrays = _array_names(main, context)
    context.writable = _writable_names(main, context)
    context.views = {
        name
        for name, values in _assignments(main, context).items()
        if any(
            isinstance(v, ast.Subscript) and isinstance(v.value, ast.Name) and v.value.id in context.writable
            for v in values
        )
    }
    context.lengths = {
        name
        for name, values in _assignments(main, context).items()
        if all(
            v is not None and any(_call_name(n) in ("sqrt", "linalg.norm", "max") for n in ast.walk(v)) for v in values
        )
    }
    context.conditional = {
        id(s) for n in ast.walk(main) if isinstance(n, ast.If) for s in n.body + n.orelse if id(n) not in context.nested
    }
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
                found.extend(_argument_write(node, context))
                found.extend(_iterations(node, context))
            for operator in EXPRESSION_OPERATORS:
                found.extend(operator(node, context))
    found.extend(_early_returns(main, context))
    return found


def _assignments(main, context):
    """``{name: [values]}`` of the plain ``name = value`` assignments of the answer (helpers left out)."""
    found = {}
    for node in ast.walk(main):
        if id(node) in context.nested:
            continue
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    found.setdefault(target.id, []).append(node.value)
                elif isinstance(target, ast.Tuple):
                    for element in target.elts:
                        if isinstance(element, ast.Name):
                            found.setdefault(element.id, []).append(None)  # unpacked: unknown
        elif isinstance(node, (ast.For, ast.comprehension)) and isinstance(node.target, ast.Name):
            found.setdefault(node.target.id, []).append(None)
    return found


def _array_names(main, context):
    """Local names all of whose assignments give arrays (found by rounds, as one array name makes another)."""
    assignments = _assignments(main, context)
    names = set()
    for _ in range(4):
        context.arrays = names
        names = {
            name
            for name, values in assignments.items()
            if name not in context.parameters and all(v is not None and _array_like(v, context) for v in values)
        }
    return names


def _writable_names(main, context):
    """Arguments used as arrays (subscripted, or given to np.asarray) and names bound to them by np.asarray."""
    subscripted = {n.value.id for n in ast.walk(main) if isinstance(n, ast.Subscript) and isinstance(n.value, ast.Name)}
    converted = set()
    aliases = set()
    for name, values in _assignments(main, context).items():
        for value in values:
            if (
                value is not None
                and _call_name(value) == "asarray"
                and value.args
                and isinstance(value.args[0], ast.Name)
                and value.args[0].id in context.parameters
            ):
                converted.add(value.args[0].id)
                aliases.add(name)
    return (set(context.parameters) & (subscripted | converted)) | aliases


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
