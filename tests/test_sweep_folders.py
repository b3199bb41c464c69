"""A sweep folder holds one sweep: another description is refused (command line), the table
never mixes sweeps, names its sweep and the hash of its description, times every run, and
``--resume`` re-runs the runs a dying worker lost (and only those)."""

import hashlib
import json
import time

import pandas as pd
import pytest

from sailmujoco import sweep
from sailmujoco.cli.main import main

SPEC = {"name": "tiny", "boat": "saoud_robot", "task": "heading_hold", "world": "mujoco",
        "controller": "pid", "duration": 1.0, "seeds": [0, 1], "metrics": ["mean_surge"],
        "options": {"task.gusts": False}}


def _toml(duration: float, seeds=(0, 1)) -> str:
    return ('name = "tiny"\nboat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\n'
            f'controller = "pid"\nduration = {duration}\nseeds = {list(seeds)}\n'
            'metrics = ["mean_surge"]\n[options]\n"task.gusts" = false\n')


def _sweep(path, out, *extra):
    return main(["sweep", str(path), "--out", str(out), "--scheduler", "serial", "--no-progress",
                 *extra])


def test_another_spec_in_the_folder_is_refused_the_same_one_resumes(tmp_path, capsys):
    first, other, out = tmp_path / "a.toml", tmp_path / "b.toml", tmp_path / "out"
    first.write_text(_toml(1.0))
    other.write_text(_toml(1.5))  # one number differs
    assert _sweep(first, out) == 0
    held = pd.read_parquet(out / "results.parquet")
    runs = {p.name: p.read_text() for p in (out / "runs").glob("*.json")}
    capsys.readouterr()
    for extra in ((), ("--resume",)):
        assert _sweep(other, out, *extra) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "Traceback" not in err
        assert (f"holds sweep {held['sweep_id'][0]} with a different spec" in err
                and "use --out elsewhere or delete it" in err)
    pd.testing.assert_frame_equal(pd.read_parquet(out / "results.parquet"), held)  # untouched
    assert _sweep(first, out, "--resume") == 0  # the same description resumes: nothing to run
    assert {p.name: p.read_text() for p in (out / "runs").glob("*.json")} == runs


def test_the_table_names_its_sweep_hashes_its_spec_and_times_each_run(tmp_path):
    start = time.perf_counter()
    table = sweep.run(SPEC, tmp_path, scheduler="serial", progress=False)
    elapsed = time.perf_counter() - start
    stored = json.loads((tmp_path / "sweep.json").read_text())  # the description as run
    digest = hashlib.sha256(json.dumps(stored, sort_keys=True).encode()).hexdigest()[:16]
    assert list(table["spec_hash"]) == [digest, digest]
    assert list(table["sweep_id"]) == [f"tiny-{digest[:8]}"] * 2
    other = sweep.run(dict(SPEC, duration=1.5), tmp_path / "b", scheduler="serial", progress=False)
    assert other["spec_hash"][0] != digest
    # wall seconds per run: each positive, together no more than the whole sweep took
    assert (table["wall_time"] > 0).all() and table["wall_time"].sum() < elapsed


def test_the_library_refuses_another_spec_in_a_folder_unless_told_to_share(tmp_path):
    """As the command line, the library refuses a folder holding another sweep by default
    (studies keep one folder per sweep); ``exclusive=False`` shares it."""
    sweep.run(SPEC, tmp_path, scheduler="serial", progress=False)
    with pytest.raises(sweep.SweepError, match="with a different spec"):
        sweep.run(dict(SPEC, seeds=[2]), tmp_path, scheduler="serial", progress=False)
    assert len(list((tmp_path / "runs").glob("*.json"))) == 2  # refused before any run


def test_sweeps_sharing_a_folder_do_not_mix_in_the_table(tmp_path):
    """With ``exclusive=False`` sweeps share a folder; each table is its own."""
    sweep.run(SPEC, tmp_path, scheduler="serial", progress=False)
    table = sweep.run(dict(SPEC, seeds=[2]), tmp_path, scheduler="serial", progress=False,
                      exclusive=False)
    assert list(table["seed"]) == [2] and table["sweep_id"].nunique() == 1
    assert list(pd.read_parquet(tmp_path / "results.parquet")["seed"]) == [2]
    assert len(list((tmp_path / "runs").glob("*.json"))) == 3  # every run is kept


def test_resume_reruns_the_runs_a_dead_worker_lost_and_only_those(tmp_path):
    """Runs recorded as failed because their worker died (Dask's KilledWorker, as a sweep on a
    cluster writes them) run again on --resume; a run that failed in its own simulation and a
    finished one are kept."""
    table = sweep.run(dict(SPEC, seeds=[0, 1, 2, 3]), tmp_path, scheduler="serial", progress=False)
    ids = list(table["run_id"])
    records = {rid: json.loads((tmp_path / "runs" / f"{rid}.json").read_text()) for rid in ids}
    lost = {"status": "failed", "metrics": {}, "wall_time": float("nan")}
    killed = dict(records[ids[0]], **lost, error="KilledWorker: Attempted to run task "
                  f"'run-{ids[0]}-0' on 4 different workers, but all those workers died")
    no_worker = dict(records[ids[1]], **lost, lost=True, error="CancelledError: run-x")
    own = dict(records[ids[2]], **lost, error="ValueError: its own simulation failed")
    for record in (killed, no_worker, own):
        (tmp_path / "runs" / f"{record['run_id']}.json").write_text(json.dumps(record))
    kept = (tmp_path / "runs" / f"{ids[3]}.json").read_text()
    resumed = sweep.run(dict(SPEC, seeds=[0, 1, 2, 3]), tmp_path, scheduler="serial",
                        resume=True, progress=False).set_index("run_id")
    assert list(resumed.loc[ids, "status"]) == ["ok", "ok", "failed", "ok"]
    assert list(resumed.loc[ids[:2], "mean_surge"]) == list(table["mean_surge"][:2])  # same runs
    assert resumed.loc[ids[2], "error"] == "ValueError: its own simulation failed"
    assert (tmp_path / "runs" / f"{ids[3]}.json").read_text() == kept
