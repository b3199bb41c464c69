"""The recipes of docs/architecture.md run as written, and do what they say: each block is
executed from the document itself, then checked against first principles."""

import importlib
import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from sailmujoco import suite, sweep
from sailmujoco.boat import catalogue as boats
from sailmujoco.study import run_study
from sailmujoco.tasks.registry import TASKS

DOC = Path(__file__).resolve().parents[1] / "docs" / "architecture.md"


@pytest.fixture(autouse=True)
def _registries_restored():
    """A recipe registers a boat or a task for this process: the other tests see the built-in
    registries only."""
    assert suite.TASKS is TASKS and "heading_hold" in TASKS  # the built-in tasks registered
    held_boats, held_tasks = dict(boats.BOATS), dict(TASKS)
    yield
    boats.BOATS.clear()
    boats.BOATS.update(held_boats)
    TASKS.clear()
    TASKS.update(held_tasks)


def _recipe(heading: str) -> str:
    text = DOC.read_text(encoding="utf-8")
    section = text[text.index(f"### {heading}\n"):]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def _run(heading: str) -> dict:
    namespace = {"__name__": f"recipe_{heading.lower().replace(' ', '_')}"}
    exec(compile(_recipe(heading), f"{DOC.name}: {heading}", "exec"), namespace)
    return namespace


def test_the_document_has_the_four_recipes():
    for heading in ("Add a boat", "Add a controller", "Add a task", "Add a study"):
        assert _recipe(heading).strip()


def test_add_a_boat():
    """A sail 1.5 times larger, same aspect ratio and same state and wind: every force of the
    sail's aerodynamic model is proportional to its area (½ ρ A C |v|², the coefficients depend
    on the angle of attack and the aspect ratio only), so the sail's wrench is 1.5 times."""
    recipe = _run("Add a boat")
    big, small = np.asarray(recipe["big"]), np.asarray(recipe["small"])
    assert np.linalg.norm(small[:3]) > 1.0  # N: the sail is drawing in 6 m/s of wind
    np.testing.assert_allclose(big, 1.5 * small, rtol=1e-9, atol=1e-9)
    assert recipe["env"].physics.params.name == "big_sail_robot"


def test_add_a_controller():
    """The proportional rudder holds the task's heading and the sail drives the boat: after
    40 s the heading is within 15° of the one asked for and the robot makes headway."""
    log = _run("Add a controller")["log"]
    assert log["t"].iloc[-1] == pytest.approx(40.0)
    last = log[log["t"] >= 30.0]
    error = np.angle(np.exp(1j * (last["heading"] - 0.0)))  # heading_hold asks for north
    assert np.max(np.abs(error)) < math.radians(15.0)
    assert last["u"].mean() > 0.3  # m/s


def test_add_a_task():
    """The registered task loads by name, starts on its heading, and its metric is the mean
    speed it defines: on a beam reach in 5 m/s the robot sails at a fraction of the wind."""
    recipe = _run("Add a task")
    env = recipe["env"]
    timestep = env.reset()
    assert math.isclose(float(timestep.observation["heading"]), math.pi / 2, abs_tol=math.radians(6.0))
    controller = sweep.make_controller("pid", env)
    controller.reset(0)
    while not timestep.last():
        timestep = env.step(controller(timestep))
    speed = env.task.metrics()["mean_speed_last_10s"]
    assert 0.2 < speed < 5.0  # m/s: sailing, and slower than the wind on a reach


def test_add_a_study(tmp_path, monkeypatch):
    """The declared study runs on the engine and writes its report; more wind, more speed (the
    drive grows with the wind squared, below the hull's speed)."""
    module = tmp_path / "my_study.py"
    module.write_text(_recipe("Add a study"))
    monkeypatch.syspath_prepend(str(tmp_path))
    sys.modules.pop("my_study", None)
    my_study = importlib.import_module("my_study")
    with sweep.Engine("serial") as engine:
        headline = run_study(my_study.STUDY, tmp_path / "out", engine, progress=False)
    assert headline["surge_6"] > headline["surge_3"] > 0.0
    assert "| 3 |" in (tmp_path / "out" / "report.md").read_text()
    assert (tmp_path / "out" / "speeds.csv").read_text().startswith("wind,mean_surge\n")
