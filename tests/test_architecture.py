"""Imports run one way: the library never imports a controller or a study."""

import ast
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


def test_library_does_not_import_controllers_or_studies():
    for path in LIBRARY.rglob("*.py"):
        rel = path.relative_to(LIBRARY)
        if rel.parts[0] in ("controllers", "studies"):
            continue
        for name in _imports(path):
            assert "controllers" not in name and "studies" not in name, f"{rel} imports {name}"


def test_force_models_do_not_import_mujoco():
    for path in (LIBRARY / "forces").glob("*.py"):
        for name in _imports(path):
            assert not name.startswith("mujoco") and "physics" not in name, f"{path.name}: {name}"
