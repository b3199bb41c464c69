"""The manual works as written: the API reference builds with Sphinx, warnings as errors, and
docs/extending.md runs from its own text, block by block, in an empty folder.

How docs/extending.md is read (the page says the same to its reader):

* a fenced block whose preceding non-blank line ends with a file name in backticks and a colon,
  "`my_ctrl.py`:", is that file's content: it is written into the folder, not run;
* every other ``python`` block is executed, in the order of the page, in one namespace, with the
  folder as the working directory and first on ``sys.path`` (as a Python session started there);
* every line of a ``bash`` or ``console`` block that starts with ``sailmujoco`` runs through the
  installed ``sailmujoco`` command (the one beside this Python) in the folder, and must succeed;
  other lines (comments, ``mkdir``) are not run.

Any other block fails the test, so that nothing on the page escapes it. After the page has run,
what it made is checked against first principles: the controller holds its heading, a 20 %
larger sail gives a 20 % larger sail force, the files the commands promise exist.
"""

import math
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sailmujoco import suite, sweep

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
EXTENDING = DOCS / "extending.md"
COMMAND = Path(sys.executable).with_name("sailmujoco")

FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```[ \t]*$", re.S | re.M)
FILE_LINE = re.compile(r"`([\w./-]+)`:\s*$")


def blocks(text: str) -> list[tuple[str, str, str | None]]:
    """(language, code, file name or None) of every fenced block of ``text``, in order."""
    found = []
    for match in FENCE.finditer(text):
        before = [line for line in text[:match.start()].splitlines() if line.strip()]
        named = FILE_LINE.search(before[-1]) if before else None
        found.append((match.group(1), match.group(2), named.group(1) if named else None))
    return found


def commands(code: str) -> list[str]:
    """The ``sailmujoco`` command lines of a shell block, continuation lines joined."""
    joined = re.sub(r"\s*\\\n\s*", " ", code)
    return [line.strip() for line in joined.splitlines() if line.strip().startswith("sailmujoco ")]


def run_command(line: str, folder: Path) -> None:
    argv = [str(COMMAND), *shlex.split(line)[1:]]
    done = subprocess.run(argv, cwd=folder, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"{line}\n--- exit {done.returncode}\n{done.stdout}\n{done.stderr}"


def test_the_page_reading_finds_files_python_and_commands():
    """The reader of the page itself, on a page of its own: a named block is a file, a python
    block code, a bash block's sailmujoco lines commands (continuations joined)."""
    page = ("Intro.\n\n`a.py`:\n\n```python\nX = 1\n```\n\nThen:\n\n```python\nimport a\n```\n\n"
            "```bash\nmkdir -p out\nsailmujoco sweep s.toml \\\n    --out out\n```\n")
    assert blocks(page) == [("python", "X = 1\n", "a.py"), ("python", "import a\n", None),
                            ("bash", "mkdir -p out\nsailmujoco sweep s.toml \\\n    --out out\n", None)]
    assert commands(blocks(page)[2][1]) == ["sailmujoco sweep s.toml --out out"]


def test_api_reference_builds_without_warnings(tmp_path):
    """sphinx-build -W over docs/: every docstring of the public modules is valid reST. Built from
    a copy without the generated pages (a stale page of a renamed module would be an orphan),
    in a folder of its own, so the package is the installed one (as the reader's is)."""
    source, out = tmp_path / "docs", tmp_path / "html"
    shutil.copytree(DOCS, source, ignore=shutil.ignore_patterns("_build", "generated"))
    done = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                           str(source), str(out)], cwd=tmp_path, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    suite_page = (out / "api" / "generated" / "sailmujoco.suite.html").read_text(encoding="utf-8")
    assert "rollout" in suite_page and "load_batch" in suite_page
    base_page = (out / "api" / "generated" / "sailmujoco.controllers.base.html").read_text(encoding="utf-8")
    assert "apparent_wind_angle" in base_page  # the observation table made it through


@pytest.fixture
def ran_the_page(tmp_path, monkeypatch):
    """docs/extending.md run in an empty folder; its Python namespace and the folder."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.syspath_prepend(str(tmp_path))
    namespace = {"__name__": "extending"}
    held = dict(sweep.controllers._REGISTERED)
    try:
        for index, (language, code, name) in enumerate(blocks(EXTENDING.read_text(encoding="utf-8"))):
            if name is not None:
                (tmp_path / name).write_text(code, encoding="utf-8")
            elif language == "python":
                exec(compile(code, f"{EXTENDING.name}, block {index}", "exec"), namespace)
            elif language in ("bash", "console"):
                for line in commands(code):
                    run_command(line, tmp_path)
            else:
                pytest.fail(f"block {index} ({language or 'no language'}) is neither a named file, "
                            f"python nor bash: the page would show what the test does not run")
        yield namespace, tmp_path
    finally:
        sweep.controllers._REGISTERED.clear()
        sweep.controllers._REGISTERED.update(held)
        sys.modules.pop("my_ctrl", None)


def test_extending_runs_as_written_and_does_what_it_says(ran_the_page):
    namespace, folder = ran_the_page

    # your controller: it holds the ordered heading (0, north) on the robot in both worlds; a
    # proportional rudder leaves a small steady error against the heeled sail's weather helm
    for log in (namespace["log"], namespace["paper_log"], namespace["composite_log"]):
        assert len(log) > 250  # 30 s at 10 Hz, sailed to the end (no capsize)
        assert np.degrees(np.sqrt(np.mean(np.angle(np.exp(1j * log["heading"][100:])) ** 2))) < 10.0
    assert namespace["metrics"]["heading_error_rms"] < math.radians(10.0)
    assert namespace["metrics"]["steady_speed"] > 0.5  # m/s: the sail drives it
    # the sweep: one row per gain, both sailed; the stiffer rudder holds the heading closer
    table = pd.read_parquet(folder / "sweeps" / "my_gain" / "results.parquet").sort_values("controller.gain")
    assert list(table["controller.gain"]) == [0.5, 2.0] and set(table["status"]) == {"ok"}
    assert table["heading_error_rms"].iloc[1] < table["heading_error_rms"].iloc[0]
    video = (folder / "my_ctrl.mp4").read_bytes()
    assert video[4:8] == b"ftyp" and len(video) > 10_000  # an mp4 with frames in it
    assert (folder / "polar_mine" / "polar_make.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

    # through instruments: the GNSS fix is off the true position by a receiver's error (2.5 m
    # CEP: within 15 m) but not zero, and the two instruments' keys are there
    first = namespace["first"]
    error = np.hypot(*(first["position"] - np.zeros(2)))  # the boat starts at the origin
    assert 0.0 < error < 15.0
    assert {"speed_through_water", "true_wind_estimate"} <= set(first)

    # your boat: the file holds the robot with a sail 1.2 times larger, and the sail's force is
    # 1.2 times the robot's (½ ρ A C |v|²: same state and wind, coefficients that do not depend
    # on the area)
    mine = suite.load(str(folder / "my_boat.toml"), "heading_hold", seed=0)
    robot = suite.load("saoud_robot", "heading_hold", seed=0)
    mine.reset()
    robot.reset()
    assert mine.physics.params.sail.area == pytest.approx(1.2 * robot.physics.params.sail.area, rel=1e-12)
    assert mine.physics.params.mass == robot.physics.params.mass
    big, small = np.asarray(mine.physics.force_term("sail")), np.asarray(robot.physics.force_term("sail"))
    assert np.linalg.norm(small[:3]) > 0.1  # N: the sail draws
    np.testing.assert_allclose(big, 1.2 * small, rtol=1e-9, atol=1e-9)
    assert (folder / "my_boat_check" / "gz.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(namespace["boat_log"]) > 250
    boats = pd.read_parquet(folder / "sweeps" / "my_boat_wind" / "results.parquet")
    boats = boats.sort_values("task.wind_speed")
    assert set(boats["status"]) == {"ok"}
    assert boats["steady_speed"].iloc[1] > boats["steady_speed"].iloc[0]  # more wind, faster

    # its instruments and actuators: the file holds the edited figures over the typical preset
    fitted = suite.load(str(folder / "my_fitted_boat.toml"), "heading_hold")
    assert fitted.task.sensors.compass_noise_deg == 4.0 and fitted.task.sensors.gnss_cep == 2.5
    assert fitted.task.actuators.rudder_60deg_s == 0.25 and fitted.task.actuators.sail_full_range_s == 1.3
    assert fitted.physics.params.sail.area == mine.physics.params.sail.area  # my_boat, fitted
    video = (folder / "my_fitted_boat.mp4").read_bytes()
    assert video[4:8] == b"ftyp" and len(video) > 10_000
    # Gymnasium read the instruments: the speed log and the true-wind estimate are there
    assert {"speed_through_water", "true_wind_estimate"} <= set(namespace["gym_observation"])
    # each sweep run is the file's boat with the grid's figure over the file's figures: the same
    # run from Python, with that figure given to the task, gives the same metric to the bit
    runs = pd.read_parquet(folder / "sweeps" / "my_fitted_boat" / "results.parquet")
    assert len(runs) == 4 and set(runs["status"]) == {"ok"}
    row = runs[(runs["task.sensors"].astype(str) == str({"compass_noise_deg": 4.0})) & (runs["seed"] == 1)]
    assert len(row) == 1
    again = suite.load(str(folder / "my_fitted_boat.toml"), "heading_hold", seed=1, time_limit=20.0,
                       sensors={"compass_noise_deg": 4.0})
    suite.rollout(again, sweep.make_controller("my_ctrl.py:make", again))
    assert again.task.metrics()["heading_error_rms"] == row["heading_error_rms"].iloc[0]
