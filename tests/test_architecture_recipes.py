"""The recipes of docs/architecture.md run as written, and do what they say: each block is
executed from the document itself, then checked against first principles."""

import importlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import sailmujoco
from sailmujoco import suite, sweep
from sailmujoco.boat import catalogue as boats
from sailmujoco.boat import mjcf
from sailmujoco.measurement.observation import OBSERVATION, TRUE_STATE
from sailmujoco.study import run_study
from sailmujoco.tasks.registry import TASKS

DOC = Path(__file__).resolve().parents[1] / "docs" / "architecture.md"
KNOT = 1852.0 / 3600.0  # m/s: one nautical mile (1852 m) an hour


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


def _section(heading: str) -> str:
    """The recipe under ``### heading``, up to the next heading."""
    text = DOC.read_text(encoding="utf-8")
    section = text[text.index(f"### {heading}\n") + 1:]
    return section[:section.index("\n##")]


def _recipe(heading: str) -> str:
    return re.search(r"```python\n(.*?)```", _section(heading), re.S).group(1)


def _run(heading: str) -> dict:
    namespace = {"__name__": f"recipe_{heading.lower().replace(' ', '_')}"}
    exec(compile(_recipe(heading), f"{DOC.name}: {heading}", "exec"), namespace)
    return namespace


def test_the_document_has_the_four_recipes():
    for heading in ("Add a boat", "Add a controller", "Add a task", "Add a study", "Add a measurement"):
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
    report = (tmp_path / "out" / "report.md").read_text()
    assert re.search(r"\| 3 \| [0-9.]+ \[[0-9.]+, [0-9.]+\] \|", report)  # mean [low, high]
    csv = (tmp_path / "out" / "speeds.csv").read_text().splitlines()
    assert csv[0] == "wind,mean_surge,low,high,n" and csv[1].endswith(",5")  # the study's own N


@pytest.fixture
def _tables_restored():
    """A recipe adds a key for this process: the other tests see the built-in observation only."""
    held = dict(OBSERVATION), dict(TRUE_STATE)
    yield
    for table, keys in zip((OBSERVATION, TRUE_STATE), held, strict=True):
        table.clear()
        table.update(keys)


def _stepped(env, steps: int = 40):
    """The observation after ``steps`` control steps with the rudder amidships and the sail
    eased a little (the boat gathers way)."""
    env.reset()
    action = np.array([0.0, 0.3 * float(env.action_spec().maximum[1])])
    for _ in range(steps):
        timestep = env.step(action)
    return timestep.observation


def test_add_a_measurement(_tables_restored):
    """The toy key is in the observation of the MuJoCo boat and of Wille's paper world, with the
    speed over ground in knots: the length of the ground velocity, from MuJoCo's free joint
    (qvel's first two entries are the world velocity of the body) and from Wille's eq. 4 (the
    heading turns (u, v cos phi) into the world plane, which keeps its length)."""
    recipe = _run("Add a measurement")
    boat, paper = recipe["boat"], recipe["paper"]

    observation = _stepped(boat)
    qvel = np.array(boat.physics.data.qvel)
    expected = math.hypot(qvel[0], qvel[1]) / KNOT
    assert expected > 0.5  # kn: the boat is under way
    value = observation["speed_over_ground_kn"]
    assert isinstance(value, np.ndarray) and value.shape == () and value.dtype == np.float64
    assert float(value) == pytest.approx(expected, rel=1e-12)
    assert boat.observation_spec()["speed_over_ground_kn"].shape == ()

    observation = _stepped(paper)
    _, _, phi, _, u, v = paper.physics.world.state[:6]
    expected = math.hypot(u, v * math.cos(phi)) / KNOT
    assert expected > 0.5
    assert float(observation["speed_over_ground_kn"]) == pytest.approx(expected, rel=1e-12)
    assert list(observation).index("speed_over_ground_kn") < list(observation).index("true_state")


BLOCK = re.compile(r"```(python|diff) file=(\S+)\n(.*?)```", re.S)


def apply_blocks(section: str, root: Path) -> list[str]:
    """Apply a recipe's blocks under ``root``: a ``python file=PATH`` block is a new file, a
    ``diff file=PATH`` block an edit (its context and ``-`` lines, found once, become its
    context and ``+`` lines). Returns the paths, in order."""
    touched = []
    for kind, name, body in BLOCK.findall(section):
        target = root / name
        if kind == "python":
            assert not target.exists(), f"{name} exists already"
            target.write_text(body, encoding="utf-8")
        else:
            lines = body.rstrip("\n").split("\n")
            old = "\n".join(line[1:] for line in lines if line[:1] in (" ", "-")) + "\n"
            new = "\n".join(line[1:] for line in lines if line[:1] in (" ", "+")) + "\n"
            text = target.read_text(encoding="utf-8")
            assert text.count(old) == 1, f"{name}: the block's lines are not found once:\n{old}"
            target.write_text(text.replace(old, new), encoding="utf-8")
        touched.append(name)
    return touched


TOW_CHECK = """
import json
import sys

import mujoco
import numpy as np

from sailmujoco.forces.wind import WindConfig
from sailmujoco.options import ForceSwitches
from sailmujoco.physics import BoatPhysics

out = {}
for tow in (False, True):  # added mass off: M is then MuJoCo's rigid-body mass matrix alone
    physics = BoatPhysics.load("saoud_robot", wind=WindConfig(speed=0.0, gusts=False, wander=False),
                               forces=ForceSwitches(tow=tow, added_mass=False))
    start = physics.data.qvel.copy()
    physics.step(1)
    mass = np.zeros((physics.model.nv, physics.model.nv))
    mujoco.mj_fullM(physics.model.ptr, physics.data.ptr, mass)
    out[str(tow)] = dict(dv=(physics.data.qvel - start).tolist(), term=physics.force_term("tow").tolist(),
                         mass=mass.tolist(), dt=float(physics.model.opt.timestep), source=sys.modules[
                             "sailmujoco.forces.tow"].__file__)
print(json.dumps(out))
"""


def test_add_a_force(tmp_path):
    """The recipe's three files, applied to a copy of the package, give the tow its term and its
    effect. The wrench is the pull along body x through CO: (T, 0, 0) and no moment (r x F = 0
    for r on the x axis). The boat at rest in still air, added mass off: Newton's second law
    says one step changes the velocity by M^-1 f dt, f the pull as a generalised force
    (world x = body x at rest) and M MuJoCo's rigid-body mass matrix; the other forces answer
    the motion the tow starts within the 5 ms step, by about 1 %, hence 3 %."""
    section = _section("Add a force")
    package = tmp_path / "sailmujoco"
    shutil.copytree(Path(sailmujoco.__file__).parent, package, ignore=shutil.ignore_patterns("__pycache__"))
    if not (package / "xml").is_dir():  # an editable install: the MJCF comes from the checkout
        shutil.copytree(mjcf.xml_root(), package / "xml")
    touched = apply_blocks(section, tmp_path)
    assert sorted(set(touched)) == ["sailmujoco/forces/boat.py", "sailmujoco/forces/tow.py",
                                    "sailmujoco/options.py"]  # three files, no more
    env = {**os.environ, "PYTHONPATH": str(tmp_path), "NUMBA_DISABLE_JIT": "1"}
    result = subprocess.run([sys.executable, "-c", TOW_CHECK], env=env, cwd=tmp_path, capture_output=True,
                            text=True, timeout=600)
    assert result.returncode == 0, result.stderr[-2000:]
    runs = json.loads(result.stdout)
    assert Path(runs["True"]["source"]).resolve() == (package / "forces" / "tow.py").resolve()
    pull = 20.0  # N, the recipe's TOW_PULL
    np.testing.assert_array_equal(runs["True"]["term"], [pull, 0.0, 0.0, 0.0, 0.0, 0.0])
    np.testing.assert_array_equal(runs["False"]["term"], np.zeros(6))
    on, off = runs["True"], runs["False"]
    force = np.zeros(len(on["dv"]))
    force[0] = pull
    expected = np.linalg.solve(np.array(on["mass"]), force) * on["dt"]
    change = np.array(on["dv"]) - np.array(off["dv"])
    assert expected[0] > 1.5 * pull * on["dt"] / 15.0  # the pull above the deep CG pitches the robot too
    np.testing.assert_allclose(change[[0, 4]], expected[[0, 4]], rtol=0.03)  # surge and pitch
    np.testing.assert_allclose(change[[1, 3, 5]], 0.0, atol=1e-12)  # no sway, roll or yaw
