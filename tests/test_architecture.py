"""Imports run one way: the library never imports a controller or a study."""

import ast
import re
from pathlib import Path

import sailmujoco

LIBRARY = Path(sailmujoco.__file__).parent
LAYERS = ["params", "mjcf", "forces", "physics", "tasks", "controllers", "studies"]


def _imports(path):
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            yield ("." * node.level) + (node.module or "")
        elif isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name


def test_force_models_do_not_import_mujoco():
    for path in (LIBRARY / "forces").glob("*.py"):
        for name in _imports(path):
            assert not name.startswith("mujoco") and "physics" not in name, f"{path.name}: {name}"


# ---- the project's modules: sailmujoco, sailmujoco.controllers, sailmujoco.studies -------------
REPO = Path(__file__).resolve().parents[1]
PACKAGES = {"sailmujoco": "sailmujoco", "controllers": "sailmujoco.controllers",
            "studies": "sailmujoco.studies"}  # source folder -> installed package
WORLD_TYPES = {"BoatPhysics", "PaperPhysics", "VielPhysics", "Wille4DOF", "VielWorld"}
PHYSICS_NAMES = {"physics", "boat"}  # names that hold a physics object
PHYSICS_ATTRIBUTES = {"physics", "_physics"}  # x.physics, env.physics, self._physics
# the physics' own modules: BoatPhysics and its parts (mixins) and the compiled step
PHYSICS_MODULES = {"sailmujoco/physics.py", "sailmujoco/step/native.py"}


def _modules() -> dict[str, tuple[Path, bool]]:
    """Dotted name -> (file, is a package's __init__) of every project module."""
    out = {}
    for folder, package in PACKAGES.items():
        for path in sorted((REPO / folder).rglob("*.py")):
            parts = [p for p in path.relative_to(REPO / folder).with_suffix("").parts
                     if p != "__init__"]
            out[".".join([package, *parts])] = (path, path.name == "__init__.py")
    return out


MODULES = _modules()


def _rel(path: Path) -> str:
    return path.relative_to(REPO).as_posix()


def _project_imports(name: str, path: Path, is_package: bool):
    """(imported module, imported name or None, line) of every import of a project module in
    ``path``, at any level (module, function, class), relative ones resolved."""
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            targets = [(alias.name, None) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = name.split(".") if is_package else name.split(".")[:-1]
                base = base[:len(base) - (node.level - 1)]
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            targets = [(f"{module}.{alias.name}" if f"{module}.{alias.name}" in MODULES else module,
                        alias.name) for alias in node.names]
        else:
            continue
        for target, imported in targets:
            while target and target not in MODULES:  # a name inside a module: the module
                target = target.rpartition(".")[0]
            if target and target != name:
                yield target, imported, node.lineno


def _import_graph() -> dict[str, dict[str, tuple[str, int]]]:
    """module -> {imported module: (file, line) of the first such import}."""
    graph: dict[str, dict[str, tuple[str, int]]] = {name: {} for name in MODULES}
    for name, (path, is_package) in MODULES.items():
        for target, _, line in _project_imports(name, path, is_package):
            graph[name].setdefault(target, (_rel(path), line))
    return graph


def _cycles(graph) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan, iterative)."""
    index, low, on_stack, stack, found = {}, {}, set(), [], []
    counter = 0
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(graph[root]))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(graph[child])))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_library_does_not_import_controllers_or_studies():
    """The library (sailmujoco, less its controllers and studies) imports neither, at any level;
    it finds controllers and studies through their entry points."""
    lower = ("sailmujoco.controllers", "sailmujoco.studies")
    problems = [f"{file}:{line} imports {target}"
                for name, imports in _import_graph().items() if not name.startswith(lower)
                for target, (file, line) in imports.items() if target.startswith(lower)]
    assert not problems, "the library imports a controller or a study:\n  " + "\n  ".join(problems)


def test_the_cycle_finder_finds_cycles():
    """The finder the cycle test relies on, on graphs whose cycles are known by hand."""
    graph = {"a": {"b": 0}, "b": {"c": 0}, "c": {"a": 0}, "d": {"a": 0}, "e": {"e": 0}, "f": {}}
    assert _cycles(graph) == [["a", "b", "c"]]
    assert _cycles({"a": {"b": 0}, "b": {}}) == []


def test_no_import_cycle():
    """No module imports, at any level (function-level imports included), a module that imports
    it back, directly or through others."""
    graph = _import_graph()
    problems = []
    for component in _cycles(graph):
        members = set(component)
        edges = [f"{file}:{line} imports {target}" for name in component
                 for target, (file, line) in sorted(graph[name].items()) if target in members]
        problems.append(f"cycle among {', '.join(component)}:\n    " + "\n    ".join(edges))
    assert not problems, "import cycles:\n  " + "\n  ".join(problems)


def test_no_private_name_imported_across_modules():
    """``from x import _name`` only within a module's own file: a name with a leading
    underscore is that module's business."""
    problems = [f"{_rel(path)}:{line} imports {imported} from {target}"
                for name, (path, is_package) in MODULES.items()
                for target, imported, line in _project_imports(name, path, is_package)
                if imported and imported.startswith("_") and not imported.startswith("__")]
    assert not problems, "private names imported across modules:\n  " + "\n  ".join(problems)


def _world_type_tests(source: str) -> list[tuple[int, str, str]]:
    """(line, world class, expression) of every isinstance/issubclass/``type(...) is`` test
    against a world's class in ``source``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, (ast.Call, ast.Compare)):
            continue
        if isinstance(node, ast.Call) and not (isinstance(node.func, ast.Name)
                                               and node.func.id in ("isinstance", "issubclass")):
            continue
        names = {n.id for n in ast.walk(node) if isinstance(n, ast.Name)}
        names |= {n.attr for n in ast.walk(node) if isinstance(n, ast.Attribute)}
        if isinstance(node, ast.Compare) and not ("type" in names and any(
                isinstance(op, (ast.Is, ast.IsNot, ast.Eq, ast.NotEq)) for op in node.ops)):
            continue
        for world in sorted(names & WORLD_TYPES):
            found.append((node.lineno, world, ast.unparse(node)))
    return found


def test_the_dispatch_finder_finds_type_tests():
    source = ("def measurement(physics):\n"
              "    if isinstance(physics, BoatPhysics):\n        return 1\n"
              "    if type(physics) is VielPhysics:\n        return 2\n"
              "    return physics.measure()\n")
    assert [(line, world) for line, world, _ in _world_type_tests(source)] == \
        [(2, "BoatPhysics"), (4, "VielPhysics")]
    assert _world_type_tests("def f(physics):\n    return physics.measure()\n") == []


def test_tasks_do_not_dispatch_on_the_world_type():
    """A task drives every world through the World protocol: no isinstance (or issubclass, or
    type(...) is) test against a world's class in sailmujoco/tasks/."""
    problems = [f"{_rel(path)}:{line} tests the type {world}: {expression}"
                for path in sorted((REPO / "sailmujoco" / "tasks").glob("*.py"))
                for line, world, expression in _world_type_tests(path.read_text())]
    assert not problems, "tasks dispatching on the world's type:\n  " + "\n  ".join(problems)


def _is_physics(node) -> bool:
    """Whether an expression names a physics object: ``physics``, ``boat``, ``x.physics``,
    ``self._physics``."""
    if isinstance(node, ast.Name):
        return node.id in PHYSICS_NAMES
    return isinstance(node, ast.Attribute) and node.attr in PHYSICS_ATTRIBUTES


def test_nothing_outside_the_physics_reads_its_private_attributes():
    """``physics._x`` (or ``env.physics._x``, ``boat._x``) only in the physics' own modules:
    everything else goes through its public methods."""
    problems = []
    for path, _ in MODULES.values():
        if _rel(path) in PHYSICS_MODULES:
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if (isinstance(node, ast.Attribute) and node.attr.startswith("_")
                    and not node.attr.startswith("__") and _is_physics(node.value)):
                problems.append(f"{_rel(path)}:{node.lineno} reads {ast.unparse(node)}")
    assert not problems, "private attributes of the physics read outside it:\n  " + \
        "\n  ".join(problems)


def test_no_study_imports_another():
    """A study imports the kit (studies/kit/) and the library, never another study: what two
    studies share lives in the kit."""
    studies = "sailmujoco.studies."
    kit = "sailmujoco.studies.kit"

    def study_of(module: str) -> str | None:
        if not module.startswith(studies) or module.startswith(kit):
            return None
        return module[len(studies):].split(".")[0]

    problems = [f"{file}:{line} imports {target}"
                for name, imports in _import_graph().items() if study_of(name)
                for target, (file, line) in imports.items()
                if study_of(target) and study_of(target) != study_of(name)]
    assert not problems, "a study imports another:\n  " + "\n  ".join(problems)


MAX_MODULE_LINES, MAX_FUNCTION_LINES = 500, 80
ARCHITECTURE = REPO / "docs" / "architecture.md"


def _long_on_purpose() -> set[str]:
    """The modules and functions docs/architecture.md lists as long on purpose, each with why:
    ``path`` or ``path::function`` in its "Long on purpose" section."""
    text = ARCHITECTURE.read_text(encoding="utf-8")
    section = text.split("## Long on purpose", 1)[1].split("\n## ", 1)[0]
    listed = set()
    for item in re.findall(r"^- (.+?)(?=^- |\Z)", section, re.M | re.S):
        paths = re.findall(r"`([\w/]+\.py)((?:::\w+)?)`(?: and `::(\w+)`)?", item)
        for path, function, second in paths:
            listed.add(path + function)
            if second:
                listed.add(f"{path}::{second}")
    return listed


def test_rooms_are_small():
    """No module over 500 lines and no function over 80 in sailmujoco/, controllers/ and
    studies/, except what docs/architecture.md lists as long on purpose (and says why)."""
    exceptions = _long_on_purpose()
    assert "sailmujoco/step/native.py" in exceptions  # the parser reads the section as written
    problems = []
    for path, _ in MODULES.values():
        rel = _rel(path)
        source = path.read_text()
        lines = len(source.splitlines())
        if lines > MAX_MODULE_LINES and rel not in exceptions:
            problems.append(f"{rel}: {lines} lines")
        for node in ast.walk(ast.parse(source)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                length = node.end_lineno - node.lineno + 1
                if length > MAX_FUNCTION_LINES and f"{rel}::{node.name}" not in exceptions:
                    problems.append(f"{rel}:{node.lineno} {node.name}: {length} lines")
    assert not problems, "rooms too long (or list them in docs/architecture.md with why):\n  " + \
        "\n  ".join(problems)
