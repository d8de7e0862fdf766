"""The tree shows the grader's stages, and imports point one way (docs/ARCHITECTURE.md).

Each stage package of ``autograder/`` says in its ``__init__`` docstring what it
does and, on a line ``May import: a, b.``, which other parts of ``autograder``
its modules may import. This test reads every module of every stage, lazy
imports inside functions included, and fails on an import the rule does not
allow, so ``integrations → batch → reports → grading → sandbox → lessons``
cannot quietly grow a cycle. Only the entry points (``cli.py``,
``__main__.py``) sit at the top.
"""

import ast
import re

import pytest

from autograder.lessons.paths import PACKAGE, PROJECT_ROOT

STAGES = ("lessons", "authoring", "sandbox", "grading", "reports", "similarity", "batch", "integrations", "mutants")
DATA = ("hidden", "mistakes")  # the hidden suite and the mistake corpus: content, not stages


def _allowed(stage):
    doc = ast.get_docstring(ast.parse((PACKAGE / stage / "__init__.py").read_text(encoding="utf-8"))) or ""
    found = re.search(r"^May import: (.+?)\.?$", doc, re.M)
    assert found, f"autograder/{stage}/__init__.py does not say what it may import ('May import: ...')"
    words = found[1].strip()
    return set() if words.startswith("nothing") else {w.strip() for w in words.split(",")}


def _imported_names(path):
    """The dotted ``autograder...`` names a module imports, relative imports resolved."""
    module = ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = module.split(".")[: -node.level]
                name = ".".join(base + ([node.module] if node.module else []))
            else:
                name = node.module or ""
            names = [name] + ([f"{name}.{alias.name}" for alias in node.names] if name == "autograder" else [])
        else:
            continue
        found.update(name for name in names if name.split(".")[0] == "autograder")
    return found


def _imported_parts(path):
    """The ``autograder`` sub-packages a module imports (``"autograder"`` itself for the root package)."""
    return {(name.split(".") + ["autograder"])[1] if "." in name else "autograder" for name in _imported_names(path)}


@pytest.mark.parametrize("stage", STAGES)
def test_a_stage_imports_only_what_its_init_allows(stage):
    allowed = _allowed(stage) | {stage, "autograder", "MINIMUM_PYTHON"}
    wrong = {}
    for path in sorted((PACKAGE / stage).rglob("*.py")):
        if "child" in path.parts:  # runs inside the sandbox with its own sys.path; imports no autograder code
            continue
        extra = _imported_parts(path) - allowed
        if extra:
            wrong[str(path.relative_to(PACKAGE.parent))] = sorted(extra)
    assert not wrong, f"imports that autograder/{stage}/__init__.py does not allow: {wrong}"


def test_the_rule_has_no_cycle():
    graph = {stage: _allowed(stage) & set(STAGES) for stage in STAGES}
    done, active = set(), []

    def visit(stage):
        assert stage not in active, f"the stages' import rules form a cycle: {' → '.join(active + [stage])}"
        if stage in done:
            return
        active.append(stage)
        for other in graph[stage]:
            visit(other)
        active.pop()
        done.add(stage)

    for stage in STAGES:
        visit(stage)


def test_only_entry_points_sit_at_the_top():
    top = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert top == ["__init__.py", "__main__.py", "cli.py"], top
    packages = sorted(p.name for p in PACKAGE.iterdir() if (p / "__init__.py").exists())
    assert packages == sorted(STAGES + DATA), packages


def test_the_sandbox_child_imports_no_grader_code():
    """The worker runs student code; it must not be able to reach the grader's modules."""
    for path in sorted((PACKAGE / "sandbox" / "child").glob("*.py")):
        outside = {n for n in _imported_names(path) if not n.startswith("autograder.sandbox.child")}
        assert not outside, f"{path.name} imports grader code: {outside}"


def test_the_slowest_first_order_names_real_test_files():
    """conftest's ``SLOWEST_FILES_FIRST`` schedules the heavy files first: a renamed file would
    silently fall back to the end of the run."""
    import conftest

    present = {path.name for path in (PROJECT_ROOT / "tests").glob("test_*.py")}
    assert set(conftest.SLOWEST_FILES_FIRST) <= present, set(conftest.SLOWEST_FILES_FIRST) - present
    assert len(set(conftest.SLOWEST_FILES_FIRST)) == len(conftest.SLOWEST_FILES_FIRST)


def test_no_private_name_is_imported_from_another_stage():
    """A stage's seam is its public names: ``from autograder.batch.class_run import _helper`` outside ``batch``
    reaches past it. Checked for every module of ``autograder/`` (the CLI once imported ``_prewarm``)."""
    wrong = []
    for path in sorted(PACKAGE.rglob("*.py")):
        here = path.relative_to(PACKAGE).parts[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and not node.level and (node.module or "").startswith("autograder."):
                stage = node.module.split(".")[1]
                private = [a.name for a in node.names if a.name.startswith("_") and not a.name.startswith("__")]
                if stage != here and private:
                    wrong.append(f"{path.relative_to(PACKAGE.parent)}: {node.module} {private}")
    assert not wrong, "private names imported across stages:\n" + "\n".join(wrong)


def _module_level_names(tree):
    names = set()
    for node in tree.body:
        targets = (
            node.targets
            if isinstance(node, ast.Assign)
            else [node.target]
            if isinstance(node, (ast.AnnAssign, ast.AugAssign))
            else []
        )
        names.update(t.id for t in targets if isinstance(t, ast.Name))
    return names


def _keyed_by_id(node):
    """True when ``node`` is ``id(...)``: an object's address, reused once the object is gone."""
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "id"


def test_no_hidden_state_is_handed_over_through_module_globals():
    """What a grader works with is passed to it: no ``global`` statement rebinds a module's name (a warm
    slot was once handed to the sandbox that way), and no module-level cache is keyed by ``id()`` (the
    reference's transcripts once were: an id is reused by the next object at that address)."""
    wrong = []
    for path in sorted(PACKAGE.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        where = path.relative_to(PACKAGE.parent)
        module_names = _module_level_names(tree)
        for node in ast.walk(tree):
            if isinstance(node, ast.Global):
                wrong.append(f"{where}:{node.lineno}: global {', '.join(node.names)}")
            key = None
            if isinstance(node, ast.Subscript):
                owner, key = node.value, node.slice
            elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.args:
                owner, key = node.func.value, node.args[0]
            if key is not None and _keyed_by_id(key) and isinstance(owner, ast.Name) and owner.id in module_names:
                wrong.append(f"{where}:{node.lineno}: module-level {owner.id} keyed by id()")
    assert not wrong, "hidden state in module globals:\n" + "\n".join(wrong)


def _submodules_imported(path, module):
    """``package.name`` for every ``from package import name`` (relative or not): ``name`` may be a module."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(module.split(".")[: -node.level] + ([base] if base else []))
            found.update(f"{base}.{alias.name}" for alias in node.names if base.startswith("autograder"))
    return found


def _module_graph():
    """``{module: {modules it imports}}`` over ``autograder/``, lazy imports included."""
    modules = {
        ".".join(p.relative_to(PACKAGE.parent).with_suffix("").parts).removesuffix(".__init__"): p
        for p in PACKAGE.rglob("*.py")
    }
    graph = {}
    for module, path in modules.items():
        targets = set()
        for name in _imported_names(path) | _submodules_imported(path, module):
            parts = name.split(".")
            while parts and ".".join(parts) not in modules:
                parts.pop()
            if parts and ".".join(parts) != module:
                targets.add(".".join(parts))
        graph[module] = targets
    return graph


def test_no_two_modules_import_each_other_through_a_loop():
    """A loop of imports (a canary -> pipeline -> suite -> transcript cache -> canary one was) hides which
    module is the base; lazy imports inside functions count, as they do for the reader."""
    graph, loops = _module_graph(), []
    index, low, stack, on_stack, counter = {}, {}, [], set(), [0]

    def visit(node):  # Tarjan's strongly connected components
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        on_stack.add(node)
        for target in graph.get(node, ()):
            if target not in index:
                visit(target)
                low[node] = min(low[node], low[target])
            elif target in on_stack:
                low[node] = min(low[node], index[target])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                loops.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    assert not loops, "modules that import each other in a loop:\n" + "\n".join(" ↔ ".join(c) for c in loops)


# every stage, the jail's programs included
TYPED = ("lessons", "authoring", "sandbox", "grading", "reports", "similarity", "batch", "integrations", "mutants")


@pytest.mark.parametrize("stage", TYPED)
def test_public_functions_say_their_types(stage):
    """Every public function and method of a typed stage annotates its parameters and its return (the
    functions nested in them are their own business)."""
    bare = []
    for path in sorted((PACKAGE / stage).rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        methods = [
            item
            for node in tree.body
            if isinstance(node, ast.ClassDef) and not node.name.startswith("_")
            for item in node.body
        ]
        for node in tree.body + methods:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and not node.name.startswith("_"):
                arguments = [
                    a
                    for a in node.args.posonlyargs + node.args.args + node.args.kwonlyargs
                    if a.arg not in ("self", "cls")
                ]
                if node.returns is None or any(a.annotation is None for a in arguments):
                    bare.append(f"{path.relative_to(PACKAGE.parent)}:{node.lineno} {node.name}")
    assert not bare, "public functions without type hints:\n" + "\n".join(bare)


def test_no_module_below_the_cli_reads_the_course_paths():
    """Which course is graded is a value (``lessons.course.Course``) the CLI builds and passes down: only the CLI
    reads ``lessons/paths.py`` (this repository's course, the default ``--course``)."""
    readers = set()
    for path in sorted(PACKAGE.rglob("*.py")):
        where = path.relative_to(PACKAGE).as_posix()
        if where in ("cli.py", "lessons/paths.py"):
            continue
        if any(
            name.startswith("autograder.lessons.paths")
            for name in _imported_names(path)
            | _submodules_imported(path, ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts))
        ):
            readers.add(where)
    assert not readers, f"modules below the CLI that read lessons/paths.py (take a Course instead): {sorted(readers)}"


def test_only_the_course_puts_its_support_package_on_the_import_path():
    """``sys.path.insert`` hides an import from the import-graph tests above: the grader's modules never do it,
    except ``Course.use_support_package`` (the course's coursekit) and the jail's own programs (run as scripts)."""
    allowed = {"lessons/course.py"}
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        where = path.relative_to(PACKAGE).as_posix()
        if where in allowed or where.startswith("sandbox/child/"):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (
                isinstance(node, ast.Attribute)
                and node.attr in ("insert", "append")
                and ast.unparse(node.value) == "sys.path"
            ):
                found.append(f"{where}:{node.lineno}")
    assert not found, f"sys.path changed below the CLI: {found}"
