"""The rooms of the package: imports run one way (the library never imports a controller, a study
or the command line; the model never imports what is built on it), no name has two homes, and
every room is small."""

import ast
import re
from pathlib import Path

import sailmujoco

LIBRARY = Path(sailmujoco.__file__).parent
# the rooms, as dotted names: the model (a boat's parameters, the force models) at the bottom, and
# what is built on the simulation (which the model never imports)
MODEL_ROOMS = ("sailmujoco.jit", "sailmujoco.boat", "sailmujoco.forces", "sailmujoco.step")
CLIENT_ROOMS = ("sailmujoco.gym", "sailmujoco.cli", "sailmujoco.video", "sailmujoco.viewer",
                "sailmujoco.sweep", "sailmujoco.sitl")
COMMAND_LINE = ("sailmujoco.cli",)
MAX_TOP_LEVEL_MODULES = 15  # sailmujoco/*.py, __init__.py and __main__.py included


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
PHYSICS_MODULES = {"sailmujoco/physics.py", "sailmujoco/step/native.py", "sailmujoco/step/closed_loop.py"}


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


def _from_module(name: str, is_package: bool, node: ast.ImportFrom) -> str:
    """The dotted module a ``from ... import`` in module ``name`` reads, relative ones resolved."""
    if not node.level:
        return node.module or ""
    base = name.split(".") if is_package else name.split(".")[:-1]
    base = base[:len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _project_imports(name: str, path: Path, is_package: bool, modules=None):
    """(imported module, imported name or None, line) of every import of a project module in
    ``path``, at any level (module, function, class), relative ones resolved; ``modules``: the
    project's dotted names (default: all of them)."""
    modules = MODULES if modules is None else modules
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            targets = [(alias.name, None) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            module = _from_module(name, is_package, node)
            targets = [(f"{module}.{alias.name}" if f"{module}.{alias.name}" in modules else module,
                        alias.name) for alias in node.names]
        else:
            continue
        for target, imported in targets:
            while target and target not in modules:  # a name inside a module: the module
                target = target.rpartition(".")[0]
            if target and target != name:
                yield target, imported, node.lineno


def test_the_import_reader_resolves_what_the_rules_rely_on(tmp_path):
    """Relative imports at both levels, from a package's __init__, of a module or of a name in
    it, at module and at function level, all land on the project module they name."""
    modules = {"sailmujoco", "sailmujoco.cli", "sailmujoco.cli.arguments", "sailmujoco.video",
               "sailmujoco.video.scene"}
    source = tmp_path / "scene.py"
    source.write_text("import numpy\nfrom ..cli.arguments import setting\nfrom .. import cli\n"
                      "import sailmujoco.cli.arguments\nfrom . import other\n"
                      "def f():\n    from ..cli import arguments\n")
    found = sorted((line, target) for target, _, line in
                   _project_imports("sailmujoco.video.scene", source, False, modules))
    assert found == [(2, "sailmujoco.cli.arguments"), (3, "sailmujoco.cli"),
                     (4, "sailmujoco.cli.arguments"), (5, "sailmujoco.video"),
                     (7, "sailmujoco.cli.arguments")]
    package = tmp_path / "__init__.py"
    package.write_text("from .scene import x\nfrom ..cli import arguments\n")
    assert sorted(target for target, _, _ in _project_imports("sailmujoco.video", package, True, modules)) \
        == ["sailmujoco.cli.arguments", "sailmujoco.video.scene"]


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


def _in(module: str, rooms) -> bool:
    """Whether ``module`` is one of ``rooms`` (dotted names) or lies inside one."""
    return any(module == room or module.startswith(room + ".") for room in rooms)


def _crossings(graph, importer, imported) -> list[str]:
    """``file:line imports target`` for each edge of ``graph`` from a module that ``importer``
    accepts to one that ``imported`` accepts (both predicates on dotted names)."""
    return [f"{file}:{line} imports {target}" for name, imports in graph.items() if importer(name)
            for target, (file, line) in imports.items() if imported(target)]


def test_the_room_rules_read_rooms_by_their_dotted_names():
    """A room holds itself and what lies under it, not a module whose name only begins alike;
    an edge is reported from its importer's file and line."""
    assert _in("sailmujoco.cli", COMMAND_LINE) and _in("sailmujoco.cli.video", COMMAND_LINE)
    assert not _in("sailmujoco.client", COMMAND_LINE) and not _in("sailmujoco", COMMAND_LINE)
    graph = {"sailmujoco.boat.mjcf": {"sailmujoco.sweep.engine": ("b.py", 3),
                                    "sailmujoco.sweeps": ("b.py", 4)},
             "sailmujoco.gym.env": {"sailmujoco.video": ("g.py", 5)}}
    found = _crossings(graph, lambda m: _in(m, MODEL_ROOMS), lambda m: _in(m, CLIENT_ROOMS))
    assert found == ["b.py:3 imports sailmujoco.sweep.engine"]


def test_the_model_does_not_import_what_is_built_on_it():
    """Nothing under sailmujoco/jit/, boat/, forces/ or step/ imports, at any level, the
    Gymnasium adapter, the command line, the videos, the viewer or the sweeps."""
    problems = _crossings(_import_graph(), lambda m: _in(m, MODEL_ROOMS), lambda m: _in(m, CLIENT_ROOMS))
    assert not problems, "the model imports a room built on it:\n  " + "\n  ".join(problems)


def test_nothing_outside_the_command_line_imports_it():
    """Nothing outside sailmujoco/cli/ imports it, at any level, but the ``__main__`` modules
    (``python -m sailmujoco``, ``python -m sailmujoco.video``): each command's parser and main
    live there, and the library takes plain arguments."""
    problems = _crossings(_import_graph(),
                          lambda m: not _in(m, COMMAND_LINE) and m.rpartition(".")[2] != "__main__",
                          lambda m: _in(m, COMMAND_LINE))
    assert not problems, "the command line imported from outside it:\n  " + "\n  ".join(problems)


def test_options_import_nothing_from_the_force_models():
    """sailmujoco/options.py, which the force models read, imports nothing from sailmujoco/forces/:
    the configurations it holds live at its level or below."""
    problems = _crossings(_import_graph(), lambda m: m == "sailmujoco.options",
                          lambda m: _in(m, ("sailmujoco.forces",)))
    assert not problems, "options imports the force models:\n  " + "\n  ".join(problems)


def test_the_top_level_holds_at_most_15_modules():
    """sailmujoco/ itself holds at most 15 modules; the rest lives in its sub-packages."""
    top = sorted(path.name for path in LIBRARY.glob("*.py"))
    assert len(top) <= MAX_TOP_LEVEL_MODULES, f"{len(top)} modules at the top of sailmujoco/: {top}"


def test_every_folder_of_modules_is_a_package():
    """Every folder of modules in sailmujoco/, controllers/ and studies/ has its ``__init__.py``: a
    folder without one is a namespace package, which ``pkgutil.walk_packages`` (the docstring
    test) and the API reference pass over."""
    folders = {path.parent for folder in PACKAGES for path in (REPO / folder).rglob("*.py")}
    missing = sorted(_rel(folder) for folder in folders if not (folder / "__init__.py").exists())
    assert not missing, "folders of modules without __init__.py:\n  " + "\n  ".join(missing)


def _module_level_imports(tree: ast.Module):
    """The import statements of a module outside its functions and classes (in ``if`` and
    ``try`` blocks too)."""
    todo = list(tree.body)
    while todo:
        node = todo.pop(0)
        if isinstance(node, ast.ImportFrom):
            yield node
        elif isinstance(node, (ast.If, ast.Try, ast.With)):
            todo.extend(node.body + getattr(node, "orelse", []) + getattr(node, "finalbody", [])
                        + [stmt for handler in getattr(node, "handlers", []) for stmt in handler.body])


def _reexported(name: str, source: str, is_package: bool, roots, modules) -> list[tuple[int, str]]:
    """(line, name) of every name that module ``name`` imports from a project module (``from x
    import y``, at module level, ``x`` in one of the packages ``roots``) and never uses: unused,
    or only listed in its ``__all__``. Importing a module itself (``from . import tasks``, a
    member of ``modules``) is not a name: it may run for its effect."""
    tree = ast.parse(source)
    used = {node.id for node in ast.walk(tree) if isinstance(node, ast.Name)}
    found = []
    for node in _module_level_imports(tree):
        module = _from_module(name, is_package, node)
        if not _in(module, roots):
            continue
        for alias in node.names:
            bound = alias.asname or alias.name
            if f"{module}.{alias.name}" not in modules and bound not in used:
                found.append((node.lineno, bound))
    return found


def test_the_reexport_finder_finds_names_imported_and_not_used():
    """The finder the re-export test relies on, on a module whose imports are known by hand."""
    modules = {"sailmujoco", "sailmujoco.a", "sailmujoco.a.b", "sailmujoco.a.tasks"}
    source = ("from __future__ import annotations\nimport numpy as np\nfrom numpy import pi\n"
              "from .b import used, unused, listed\nfrom . import tasks\n"
              "from .b import renamed as alias\n"
              "try:\n    from .b import in_try\nexcept ImportError:\n    pass\n"
              "__all__ = ['listed', 'f']\n"
              "def f(x: used) -> None:\n    from .b import local\n    return alias\n")
    assert _reexported("sailmujoco.a.c", source, False, ("sailmujoco",), modules) == \
        [(4, "unused"), (4, "listed"), (8, "in_try")]


def test_no_name_has_two_homes():
    """A name imported into a library module that is not a package's ``__init__`` is used there:
    no module passes on a name it does not use (unused, or only in its ``__all__``), so every
    name is imported from its home. ``__init__`` modules list a package's public API."""
    lower = ("sailmujoco.controllers", "sailmujoco.studies")
    problems = [f"{_rel(path)}:{line} imports {bound} and does not use it"
                for name, (path, is_package) in MODULES.items()
                if not is_package and not _in(name, lower)
                for line, bound in _reexported(name, path.read_text(), is_package,
                                               tuple(PACKAGES.values()), MODULES)]
    assert not problems, "names passed on by a module that does not use them (import them from " \
        "their home):\n  " + "\n  ".join(problems)


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
NUMBA_DECORATORS = {"kernel", "njit", "jit", "cfunc"}  # @kernel (sailmujoco.jit.kernel), numba's own
ARCHITECTURE = REPO / "docs" / "architecture.md"


def _long_on_purpose(text: str) -> set[str]:
    """The functions docs/architecture.md lists as long on purpose, each with why: ``path::function``
    (or ``path::f`` and ``::g``) in the items of its "Long on purpose" section."""
    section = text.split("## Long on purpose", 1)[1].split("\n## ", 1)[0]
    listed = set()
    for item in re.findall(r"^- (.+?)(?=^- |\Z)", section, re.M | re.S):
        paths = re.findall(r"`([\w/]+\.py)((?:::\w+)?)`(?: and `::(\w+)`)?", item)
        for path, function, second in paths:
            listed.add(path + function)
            if second:
                listed.add(f"{path}::{second}")
    return listed


def test_the_long_on_purpose_reader_reads_the_items():
    text = ("# A\n## Long on purpose\n\nIntro `not/an/item.py`.\n\n- `a/b.py::f` (why): more\n"
            "  on a second line.\n- `a/c.py::g` and `::h` (why).\n\n## Next\n\n- `x/y.py::z`\n")
    assert _long_on_purpose(text) == {"a/b.py::f", "a/c.py::g", "a/c.py::h"}


def _is_kernel(function: ast.FunctionDef) -> bool:
    """Whether ``function`` is decorated as a numba kernel (``@kernel``, ``@kernel(...)``,
    ``@numba.njit(...)``, ``@njit``, ``@numba.cfunc(...)``)."""
    for decorator in function.decorator_list:
        target = decorator.func if isinstance(decorator, ast.Call) else decorator
        name = target.id if isinstance(target, ast.Name) else getattr(target, "attr", None)
        if name in NUMBA_DECORATORS:
            return True
    return False


def _long_functions(source: str) -> list[tuple[int, str, int, bool]]:
    """(line, name, lines, is a numba kernel) of every function over the limit in ``source``, its
    docstring included, nested ones too."""
    return [(node.lineno, node.name, node.end_lineno - node.lineno + 1, _is_kernel(node))
            for node in ast.walk(ast.parse(source))
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
            and node.end_lineno - node.lineno + 1 > MAX_FUNCTION_LINES]


def test_the_size_reader_measures_functions_and_knows_kernels():
    def body(n: int, indent: str = "    ") -> str:
        return "".join(f"{indent}x{i} = {i}\n" for i in range(n))

    over = body(MAX_FUNCTION_LINES)  # with its def line: one line over the limit
    source = (f"@kernel\ndef a():\n{over}@kernel(inline=True)\ndef b():\n{over}"
              f"@numba.njit(cache=True)\ndef c():\n{over}@numba.cfunc(sig)\ndef d():\n{over}"
              f"@functools.cache\ndef e():\n{over}"
              f"def at_the_limit():\n{body(MAX_FUNCTION_LINES - 1)}"
              f"def g():\n    def h():\n{body(MAX_FUNCTION_LINES, ' ' * 8)}    return h\n")
    found = {name: (lines, kernel) for _, name, lines, kernel in _long_functions(source)}
    assert found == {"a": (81, True), "b": (81, True), "c": (81, True), "d": (81, True),
                     "e": (81, False), "g": (83, False), "h": (81, False)}


def test_rooms_are_small():
    """No module over 500 lines in sailmujoco/, controllers/ and studies/, and no function over 80
    but a numba kernel (one compiled function keeps its arithmetic in its written order, which
    the reports follow to the last bit) that docs/architecture.md lists as long on purpose, with
    why; the list names nothing else."""
    listed = _long_on_purpose(ARCHITECTURE.read_text(encoding="utf-8"))
    problems, kernels = [], set()
    for path, _ in MODULES.values():
        rel = _rel(path)
        source = path.read_text()
        lines = len(source.splitlines())
        if lines > MAX_MODULE_LINES:
            problems.append(f"{rel}: {lines} lines")
        for line, name, length, kernel in _long_functions(source):
            if kernel and f"{rel}::{name}" in listed:
                kernels.add(f"{rel}::{name}")
            else:
                why = "not a numba kernel" if not kernel else "not listed in docs/architecture.md"
                problems.append(f"{rel}:{line} {name}: {length} lines ({why})")
    problems += [f"docs/architecture.md lists {item} as long on purpose: it is not a numba kernel "
                 f"over {MAX_FUNCTION_LINES} lines" for item in sorted(listed - kernels)]
    assert not problems, "rooms too long:\n  " + "\n  ".join(problems)


def _named_paths(text: str) -> set[str]:
    """The project paths docs/architecture.md names in backquotes, from the repository's root
    (``sailmujoco/...``, ``controllers/...``, ``studies/...``, ``tests/...``), less any
    ``::function``."""
    return set(re.findall(r"`((?:sailmujoco|controllers|studies|tests)/[\w/.]*?)(?:::\w+)?`", text))


def test_the_path_reader_finds_the_paths():
    text = ("| x | `sailmujoco/forces/sail.py`, `camera.py`, `sailmujoco/video/` |\n"
            "- `sailmujoco/forces/boat.py::boat_forces` (why)\n`studies/<study>/x.py` `xml/a`")
    assert _named_paths(text) == {"sailmujoco/forces/sail.py", "sailmujoco/video/",
                                  "sailmujoco/forces/boat.py"}


def test_the_architecture_page_names_paths_that_exist():
    """Every path docs/architecture.md names from the repository's root exists: its tables and
    lists follow the rooms as they are."""
    missing = sorted(path for path in _named_paths(ARCHITECTURE.read_text(encoding="utf-8"))
                     if not (REPO / path).exists())
    assert not missing, "docs/architecture.md names paths that do not exist:\n  " + "\n  ".join(missing)


def test_every_package_of_the_source_ships_with_pip_install():
    """pyproject.toml names its packages one by one: a new room left out of the list imports
    in a source tree (and here, editable) but is missing after ``pip install .``."""
    import tomllib

    listed = set(tomllib.loads((REPO / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {name for name, (_, is_package) in MODULES.items() if is_package}
    assert found - listed == set()
