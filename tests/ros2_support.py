"""A Python with rclpy for the ROS 2 tests, and a network namespace to run DDS in.

rclpy comes from the PyPI build the ``ros2`` extra names (its ``ros-*`` requirements, read from
pyproject.toml), in a venv of its own: its bootstrapper re-executes every Python of the
environment it is installed in, which the project's own environment should not have. That venv
sees the project's environment through a ``.pth`` file (the installed sailmujoco, mujoco,
rosbags), with its own numpy pinned to the project's. It is built once per set of requirements
under ``~/.cache/sailmujoco-tests`` (about 30 s and 300 MB from PyPI) and reused.

DDS discovery multicasts on every interface: every process that starts a DDS participant runs
inside a network namespace that has only loopback (``unshare --net``, root, as CI is), with
``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST`` and a fixed ``ROS_DOMAIN_ID``; never on the host
network. Where ``unshare`` is not permitted the ROS 2 tests skip with one line, and fail on CI
(``CI`` set).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import sysconfig
import tomllib
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
CYCLONE = "cyclonedds==11.0.1"  # an independent DDS for the wire check (0.10.x has no cp311 wheel)
DOMAIN = 42


def ros_requirements() -> list[str]:
    """The ``ros2`` extra's rclpy and message wheels, and the Cyclone DDS reader's."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    return [r for r in project["optional-dependencies"]["ros2"] if r.startswith("ros-")] + [CYCLONE]


def namespace_problem() -> str | None:
    """Why a loopback-only network namespace cannot be made here, or None."""
    if shutil.which("unshare") is None:
        return "unshare is not installed"
    probe = subprocess.run(["unshare", "--net", "sh", "-c", "ip link set lo up"], capture_output=True,
                           text=True)
    if probe.returncode != 0:
        return f"unshare --net is not permitted here ({probe.stderr.strip().splitlines()[-1:]})"
    return None


def need_namespace() -> None:
    """Skip (fail on CI) where DDS cannot be kept off the host network."""
    problem = namespace_problem()
    if problem:
        message = f"the ROS 2 tests run DDS only in a loopback network namespace: {problem}"
        if os.environ.get("CI"):
            pytest.fail(message + ": on CI the bridge must be tested")
        pytest.skip(message)


def ros_python() -> Path:
    """The venv's Python with rclpy and Cyclone DDS that also sees the project's environment."""
    requirements = ros_requirements() + [f"numpy=={np.__version__}"]
    site = [sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]]
    key = hashlib.sha256("\n".join(requirements + site + [sys.version]).encode()).hexdigest()[:12]
    home = Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "sailmujoco-tests"
    venv = home / f"ros2-{key}"
    python = venv / "bin" / "python"
    if python.exists():
        return python
    building = home / f"ros2-{key}.building-{os.getpid()}"
    shutil.rmtree(building, ignore_errors=True)
    subprocess.run([sys.executable, "-m", "venv", str(building)], check=True)
    pip = subprocess.run([str(building / "bin" / "pip"), "install", "-q", "--disable-pip-version-check",
                          *requirements], capture_output=True, text=True)
    if pip.returncode != 0:
        pytest.fail(f"could not install rclpy for the ROS 2 tests: {pip.stderr.strip()[-500:]}")
    pth = "import site; " + "; ".join(f"site.addsitedir({p!r})" for p in dict.fromkeys(site))
    target = building / "lib" / f"python{sys.version_info.major}.{sys.version_info.minor}" / "site-packages"
    (target / "zz_sailmujoco_project.pth").write_text(pth + "\n")
    # a venv's scripts and pyvenv.cfg name its folder: build in place of the final name
    if not venv.exists():
        building.rename(venv)
        _relocate(building, venv)
    else:
        shutil.rmtree(building, ignore_errors=True)
    return python


def _relocate(old: Path, new: Path) -> None:
    """A venv renamed: its pyvenv.cfg and scripts name the old folder."""
    for path in [new / "pyvenv.cfg", *(new / "bin").iterdir()]:
        if path.is_file() and not path.is_symlink():
            try:
                text = path.read_text()
            except UnicodeDecodeError:
                continue
            if str(old) in text:
                path.write_text(text.replace(str(old), str(new)))


def in_namespace(args, timeout: float, cwd: Path = ROOT, env: dict | None = None):
    """Run ``args`` in a new network namespace with only loopback up; its CompletedProcess."""
    environment = {**os.environ, "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
                   "ROS_DOMAIN_ID": str(DOMAIN), "SAILMUJOCO_QUIET": "1", **(env or {})}
    command = ["unshare", "--net", "sh", "-c", 'ip link set lo up && exec "$@"', "sh", *map(str, args)]
    return subprocess.run(command, capture_output=True, text=True, timeout=timeout, cwd=cwd,
                          env=environment)
