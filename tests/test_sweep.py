"""The sweep engine: Dask = serial, worker and driver deaths lose nothing, bad files exit 2."""

import json
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time

import pandas as pd
import pytest

from sailmujoco import sweep
from sailmujoco.cli.main import main

SPEC = {
    "name": "t",
    "boat": "saoud_robot",
    "task": "heading_hold",
    "world": "mujoco",
    "controller": "pid",
    "duration": 8.0,
    "seeds": [0, 1],
    "metrics": ["mean_surge", "heading_error_rms"],
    "options": {"env.hydrostatics": "geometric"},
    "grid": {"task.wind_speed": [3.0, 6.0]},
    "zip": {"task.wind_from_deg": [60.0, 120.0], "controller.kp": [0.8, 1.2]},
}


def _metrics(table):
    cols = ["run_id", "mean_surge", "heading_error_rms"]
    return table[cols].sort_values("run_id").reset_index(drop=True)


def test_expand_crosses_grid_and_zips_axes():
    runs = sweep.expand(sweep.validate(SPEC))
    assert len(runs) == 2 * 2 * 2  # grid x zip rows x seeds
    assert len({r["run_id"] for r in runs}) == len(runs)
    pairs = {(r["task_options"]["wind_from_deg"], r["controller_options"]["kp"]) for r in runs}
    assert pairs == {(60.0, 0.8), (120.0, 1.2)}  # zipped, not crossed


def test_dask_local_cluster_equals_serial(tmp_path, recwarn):
    serial = sweep.run(SPEC, tmp_path / "serial", scheduler="serial", progress=False)
    busy = socket.socket()  # Dask's default dashboard port taken, as by a second sweep
    try:
        busy.bind(("127.0.0.1", 8787))
        busy.listen()
    except OSError:  # already taken by someone else: the case under test all the same
        pass
    try:
        parallel = sweep.run(SPEC, tmp_path / "dask", workers=2, progress=False)
    finally:
        busy.close()
    assert not [w for w in recwarn if "8787" in str(w.message)]  # no dashboard warning in the log
    assert len(serial) == len(parallel) == 8
    assert (serial["status"] == "ok").all() and (parallel["status"] == "ok").all()
    pd.testing.assert_frame_equal(_metrics(serial), _metrics(parallel))  # bit for bit
    table = pd.read_parquet(tmp_path / "dask" / "results.parquet")
    assert set(table["run_id"]) == set(serial["run_id"])
    assert table["mean_surge"].notna().all()


def test_capsizes_are_stopped_not_failed(tmp_path):
    spec = dict(SPEC, grid={}, seeds=[0], duration=20.0,
                boat="saoud_robot", controller="fixed_sail",
                zip={"controller.sail_deg": [30.0, 20.0], "task.wind_speed": [4.0, 16.0]},
                options={"env.hydrostatics": "paper", "boat.l_phi": 0.1})
    table = sweep.run(spec, tmp_path, scheduler="serial", retries=1, progress=False)
    by_wind = {row["task.wind_speed"]: row for _, row in table.iterrows()}
    assert by_wind[4.0]["status"] == "ok"
    capsized = by_wind[16.0]
    assert capsized["status"] == "stopped" and "capsized" in capsized["error"]
    assert capsized["attempts"] == 1  # a stop is a result, not retried


def test_failures_are_recorded_once_and_the_sweep_goes_on(tmp_path):
    """Viel's position keeper on a heading task has no target: it raises on its first step,
    which no up-front check can know; the run is recorded as failed, not retried (the same seed
    raises the same error)."""
    spec = dict(SPEC, controller="viel", grid={}, zip={}, options={}, seeds=[0, 1], duration=1.0)
    table = sweep.run(spec, tmp_path, scheduler="serial", retries=1, progress=False)
    assert list(table["status"]) == ["failed", "failed"]
    assert table["error"].str.startswith("ValueError: VielController: no target").all()
    assert list(table["attempts"]) == [1, 1]  # its own error: not retried
    record = json.loads((tmp_path / "runs" / f"{table['run_id'][0]}.json").read_text())
    assert record["attempts"] == 1 and not record.get("lost")  # its own failure, not the cluster's
    assert sweep.failures(table) == [
        "failed 2 of 2 runs: ValueError: VielController: no target: pass target=(x, y) or give "
        f"observation['target_position'] (e.g. run 0, {table['run_id'][0]}: seed=0)"]


def test_killing_a_worker_loses_and_duplicates_nothing(tmp_path):
    from dask.distributed import Client, LocalCluster

    spec = dict(SPEC, duration=30.0, seeds=[0, 1, 2], grid={"task.wind_speed": [3.0, 5.0]})
    n_runs = len(sweep.expand(sweep.validate(spec)))
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        result = {}
        thread = threading.Thread(target=lambda: result.update(
            table=sweep.run(spec, tmp_path, scheduler=cluster.scheduler_address, progress=False)))
        thread.start()
        runs_dir = tmp_path / "runs"
        deadline = time.time() + 120
        while time.time() < deadline and len(list(runs_dir.glob("*.json"))) < 2:
            time.sleep(0.05)
        assert len(list(runs_dir.glob("*.json"))) < n_runs, "sweep finished before the kill"
        pids = client.run(os.getpid)
        os.kill(next(iter(pids.values())), signal.SIGKILL)  # a worker dies mid-sweep
        thread.join(timeout=300)
    table = result["table"]
    assert len(table) == n_runs
    assert table["run_id"].is_unique
    assert (table["status"] == "ok").all()


def test_killing_the_driver_then_resume_runs_only_the_missing(tmp_path):
    spec = dict(SPEC, duration=30.0, seeds=[0, 1, 2, 3], grid={"task.wind_speed": [3.0, 5.0]})
    spec_file = tmp_path / "sweep.toml"
    spec_file.write_text(_toml(spec))
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "sailmujoco.cli.main", "sweep", str(spec_file), "--out", str(out),
           "--scheduler", "serial", "--no-progress"]
    # run outside the checkout: from its root, `python -m` would import the source tree
    # instead of the installed package
    driver = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              start_new_session=True, cwd=tmp_path)
    deadline = time.time() + 120
    while time.time() < deadline and len(list((out / "runs").glob("*.json"))) < 3:
        assert driver.poll() is None, "the sweep driver exited before it was killed"
        time.sleep(0.05)
    os.killpg(driver.pid, signal.SIGKILL)
    driver.wait()
    before = {p.name: p.read_text() for p in (out / "runs").glob("*.json")}
    n_runs = len(sweep.expand(sweep.validate(spec)))
    assert 3 <= len(before) < n_runs
    assert main(["sweep", str(spec_file), "--out", str(out), "--scheduler", "serial",
                 "--resume", "--no-progress"]) == 0
    after = {p.name: p.read_text() for p in (out / "runs").glob("*.json")}
    assert len(after) == n_runs
    assert all(after[name] == text for name, text in before.items())  # untouched
    sessions = {json.loads(text)["session"] for name, text in after.items() if name not in before}
    assert len(sessions) == 1 and not sessions & {json.loads(t)["session"] for t in before.values()}
    assert len(pd.read_parquet(out / "results.parquet")) == n_runs


def _toml(spec):
    lines = []
    for key in ("name", "boat", "task", "world", "controller"):
        lines.append(f'{key} = "{spec[key]}"')
    lines.append(f"duration = {spec['duration']}")
    lines.append(f"seeds = {spec['seeds']}")
    lines.append("metrics = [" + ", ".join(f'"{m}"' for m in spec["metrics"]) + "]")
    for table in ("options", "grid", "zip"):
        lines.append(f"[{table}]")
        for key, value in spec[table].items():
            lines.append(f'"{key}" = {json.dumps(value)}')
    return "\n".join(lines) + "\n"


HEAD = 'boat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\ncontroller = "pid"\n'


@pytest.mark.parametrize("body,message", [
    ('boat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\ncontroller = "pid"\nspeed = 3\n',
     "unknown key 'speed' in sweep file "),
    ('boat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\ncontroller = "pid"\n'
     '[grid]\n"task.wind_speed" = []\n', "must be a non-empty list"),
    ('boat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\ncontroller = "pid"\nseeds = "0"\n',
     "seeds must be a non-empty list of integers"),
    ('boat = "dinghy"\ntask = "heading_hold"\nworld = "mujoco"\ncontroller = "pid"\n',
     "boat = 'dinghy' is not one of: eleven_metre, saoud_robot, viel_boat, wille_yacht"),
    ('boat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\ncontroller = "pid"\n'
     '[grid]\n"task.wind_sped" = [1]\n', "unknown task option 'wind_sped'"),
    ('boat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\ncontroller = "pid"\n'
     '[options]\n"boat.l_phi" = -1\n', "l_phi"),
    ('boat = [unclosed\n', "does not parse as TOML"),
    # every run's values are checked before any run, not the first run's only
    (HEAD + '[grid]\n"boat.l_phi" = [0.1, -1.0]\n',
     "boat options {'l_phi': -1.0}: l_phi (metacentric height) must be positive, got -1.0"),
    (HEAD + '[grid]\n"task.wind_speed" = [3.0, 500.0]\n',
     "task options {'wind_speed': 500.0}: wind_speed must be a finite number >= 0 and <= 100 m/s"),
    (HEAD + '[grid]\n"env.hydrostatics" = ["paper", "bogus"]\n',
     "env.hydrostatics = 'bogus' is not one of ('off', 'paper', 'geometric')"),
    (HEAD + '[zip]\n"env.control_timestep" = [0.1, -0.1]\n',
     "control_timestep must be a positive time in s, got -0.1"),
    (HEAD + '[options]\n"env.windage" = "yes"\n', "env.windage = 'yes': must be true or false"),
    # controller options: unknown names list the accepted ones, bad values are named
    (HEAD + '[options]\n"controller.kpp" = 1.0\n',
     "unknown controller option 'kpp' in [options] key 'controller.kpp' of sweep file "),
    (HEAD + '[grid]\n"controller.kp" = [1.0, nan]\n', "controller.kp = nan: must be a finite number"),
    (HEAD + '[grid]\n"controller.kd" = [1.0, "2"]\n', "controller.kd = '2': must be a finite number"),
    (HEAD.replace('"pid"', '"saoud"') + '[grid]\n"controller.wind_source" = ["ce", "gps"]\n',
     "unknown wind source 'gps'; known: saoud_v, ce, masthead"),
])
def test_bad_sweep_files_exit_2_with_one_clear_message(tmp_path, capsys, body, message):
    path = tmp_path / "bad.toml"
    path.write_text(body)
    assert main(["sweep", str(path), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert message in err
    assert err.count("\n") == 1  # one line
    assert not (tmp_path / "o").exists()  # refused before anything is written


def test_the_library_checks_workers_and_retries(tmp_path):
    most = 4 * (os.cpu_count() or 1)
    for kwargs, message in [({"workers": -1}, f"workers must be an integer >= 0 and <= {most} (0: all "
                                              "cores), got -1"),
                            ({"workers": 10**5}, f"and <= {most} (0: all cores), got 100000"),
                            ({"workers": 1.5}, "workers must be an integer >= 0"),
                            ({"retries": -1}, "retries must be an integer >= 0, got -1")]:
        with pytest.raises(sweep.SweepError, match=re.escape(message)):
            sweep.run(dict(SPEC, duration=1.0), tmp_path / "o", **kwargs)
    assert not (tmp_path / "o").exists()


def test_a_sweep_without_world_runs_in_mujoco_and_a_missing_key_lists_the_choices():
    spec = {"boat": "saoud_robot", "task": "heading_hold", "controller": "pid", "duration": 1.0}
    assert sweep.validate(spec)["world"] == "mujoco"
    with pytest.raises(sweep.SweepError,
                       match=r"^missing key 'boat' \(one of: eleven_metre, saoud_robot, viel_boat, "
                             r"wille_yacht\)$"):
        sweep.validate({"task": "heading_hold", "controller": "pid"})


@pytest.mark.parametrize("name", ["../../etc", "a/b", ".hidden", "", "two words"])
def test_a_sweep_name_is_a_folder_name_not_a_path(name):
    """The name becomes results/sweeps/<name>: a path such as '../../etc' would write outside
    results/."""
    spec = {"name": name, "boat": "saoud_robot", "task": "heading_hold", "controller": "pid"}
    with pytest.raises(sweep.SweepError, match=re.escape(f"(a folder name, not a path), got {name!r}")):
        sweep.validate(spec)
    assert sweep.validate(dict(spec, name="lphi_0.1-v2"))["name"] == "lphi_0.1-v2"
