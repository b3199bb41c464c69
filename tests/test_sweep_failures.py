"""A sweep whose runs fail says so: exit status 1 and one line per distinct reason with its count
and an example run, the finished runs still summarised over seeds, and one more line when no run
finished; a run that raised in its own simulation runs once (same seed, same code, same error), a
run the cluster lost is tried again; a refused sweep file names the nearest accepted value and a
refused sea option in one line."""

import re
import textwrap

import pandas as pd
import pytest

from sailmujoco import sweep
from sailmujoco.cli.main import main
from sailmujoco.sweep.engine import Engine

LAW = textwrap.dedent('''
    """Rudder and sail amidships; with gain above 1.5 it raises on its first step, noting each
    call that raises (one line) in the file ``marker``."""
    import numpy as np


    def make(env, gain: float = 1.0, marker: str = "raised.txt"):
        def law(timestep):
            if gain > 1.5:
                with open(marker, "a") as f:
                    f.write(f"{gain}\\n")
                raise ValueError("controller blew up")
            return np.zeros(2)
        return law
''')


@pytest.fixture
def failing_sweep(tmp_path):
    """A sweep file of two runs of the smallest boat, 0.3 s each: gain 1.0 sails, gain 2.0 raises."""
    (tmp_path / "law.py").write_text(LAW)
    path = tmp_path / "fail.toml"
    path.write_text(textwrap.dedent(f"""
        boat = "saoud_robot"
        task = "heading_hold"
        controller = "law.py:make"
        duration = 0.3
        metrics = ["mean_surge"]
        [options]
        "controller.marker" = "{tmp_path / 'raised.txt'}"
        [grid]
        "controller.gain" = [1.0, 2.0]
    """))
    return path


def test_a_failing_run_exits_1_says_why_once_and_runs_once(failing_sweep, tmp_path, capsys):
    out = tmp_path / "out"
    code = main(["sweep", str(failing_sweep), "--out", str(out), "--scheduler", "serial",
                 "--no-progress"])  # the default --retries 2
    captured = capsys.readouterr()
    assert code == 1, captured.err
    assert "status: ok 1, stopped 0, failed 1" in captured.out
    table = pd.read_csv(out / "results.csv")
    run_id = table.loc[table["status"] == "failed", "run_id"].item()
    assert captured.err.splitlines() == [
        f"sailmujoco sweep: failed 1 of 2 runs: ValueError: controller blew up (e.g. run 1, "
        f"{run_id}: controller.gain=2.0)"]
    assert (tmp_path / "raised.txt").read_text() == "2.0\n"  # raised once: not retried
    assert table.set_index("controller.gain").loc[2.0, "attempts"] == 1
    # the run that finished is still summarised: the mean of its one seed is its own value
    finished = table.set_index("controller.gain").loc[1.0, "mean_surge"]
    summary = pd.read_csv(out / "summary.csv")
    assert list(summary["controller.gain"]) == [1.0] and list(summary["n"]) == [1]
    assert summary["mean_surge"].item() == pytest.approx(finished, rel=1e-12)
    assert "  mean_surge: mean [95 % interval] over 1 seed(s) per combination" in captured.out
    assert "over seeds: summary.csv" in captured.out


EVERY_RUN_FAILS = textwrap.dedent('''
    """Raises on its first step, naming its gain: one reason per gain."""


    def make(env, gain: float = 1.0):
        def law(timestep):
            raise ValueError(f"gain {gain} is too high")
        return law
''')


def test_a_sweep_whose_every_run_fails_says_why_once_per_reason_and_exits_1(tmp_path, capsys):
    (tmp_path / "law.py").write_text(EVERY_RUN_FAILS)
    path = tmp_path / "all_fail.toml"
    path.write_text(textwrap.dedent("""
        boat = "saoud_robot"
        task = "heading_hold"
        controller = "law.py:make"
        duration = 0.3
        seeds = [0, 1]
        metrics = ["mean_surge"]
        [grid]
        "controller.gain" = [2.0, 3.0]
    """))
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.csv").write_text("left from an earlier sweep\n")
    code = main(["sweep", str(path), "--out", str(out), "--scheduler", "serial", "--no-progress"])
    captured = capsys.readouterr()
    assert code == 1, captured.err
    assert "status: ok 0, stopped 0, failed 4" in captured.out
    assert "  mean_surge: no finished run" in captured.out
    assert "over seeds: none (no run finished)" in captured.out
    table = pd.read_csv(out / "results.csv")
    assert list(table["status"]) == ["failed"] * 4

    def first(gain):  # the first run of this gain, in the sweep's order: (its position, its id)
        position = int(table.index[table["controller.gain"] == gain][0])
        return position, table.loc[position, "run_id"], table.loc[position, "seed"]

    lines = []
    for gain in sorted((2.0, 3.0), key=first):  # two runs (seeds) each: a tie, so first seen first
        position, run_id, seed = first(gain)
        lines.append(f"sailmujoco sweep: failed 2 of 4 runs: ValueError: gain {gain} is too high "
                     f"(e.g. run {position}, {run_id}: seed={seed} controller.gain={gain})")
    assert captured.err.splitlines() == lines + ["sailmujoco sweep: no run finished (4 of 4 runs failed)"]
    assert not (out / "summary.csv").exists()  # nothing finished: no summary, not a stale one


def test_over_seeds_of_a_sweep_with_no_finished_run_is_empty_with_its_columns():
    table = pd.DataFrame({"run_id": ["a", "b", "c"], "boat": ["saoud_robot"] * 3,
                          "seed": [0, 1, 0], "status": ["failed", "stopped", "failed"],
                          "error": ["ValueError: x", "capsized", "ValueError: x"],
                          "controller.gain": [1.0, 1.0, 2.0], "mean_surge": [None, 0.4, None]})
    summary = sweep.over_seeds(table, ["mean_surge", "not_a_column"])
    assert summary.empty
    assert list(summary.columns) == ["boat", "controller.gain", "mean_surge", "mean_surge_low",
                                     "mean_surge_high", "n"]
    assert sweep.summary.lines(summary, "mean_surge", table) == ["mean_surge: no finished run"]
    table["status"] = ["ok", "ok", "failed"]  # two seeds of gain 1.0 finished
    table["mean_surge"] = [0.2, 0.4, None]
    summary = sweep.over_seeds(table, ["mean_surge"])
    assert list(summary["controller.gain"]) == [1.0] and list(summary["n"]) == [2]
    assert summary["mean_surge"].item() == pytest.approx(0.3, rel=1e-12)


def test_on_workers_a_failing_run_runs_once_too(failing_sweep, tmp_path):
    table = sweep.run(failing_sweep, tmp_path / "out", workers=1, retries=2, progress=False)
    assert list(table["status"]) == ["ok", "failed"] and list(table["attempts"]) == [1, 1]
    assert (tmp_path / "raised.txt").read_text() == "2.0\n"
    assert sweep.failures(table) == [
        f"failed 1 of 2 runs: ValueError: controller blew up (e.g. run 1, {table['run_id'][1]}: "
        "controller.gain=2.0)"]


def test_a_sweep_without_failures_has_no_failure_lines(failing_sweep, tmp_path, capsys):
    text = failing_sweep.read_text().replace("[1.0, 2.0]", "[0.5, 1.0]")
    failing_sweep.write_text(text)
    assert main(["sweep", str(failing_sweep), "--out", str(tmp_path / "out"), "--scheduler",
                 "serial", "--no-progress"]) == 0
    assert capsys.readouterr().err == ""
    assert not (tmp_path / "raised.txt").exists()


_CALLS: list = []


def _lost_then_ok(r: dict) -> dict:
    """A task the cluster loses on its first attempt (as when its worker dies), then runs."""
    _CALLS.append(r["run_id"])
    if len(_CALLS) == 1:
        return {**r, "status": "failed", "error": "KilledWorker: worker died", "lost": True}
    return {**r, "status": "ok", "error": None}


def _raises(r: dict) -> dict:
    """A task whose own simulation raised: its record, as :func:`sweep.execute` writes it."""
    _CALLS.append(r["run_id"])
    return {**r, "status": "failed", "error": "ValueError: controller blew up\nTraceback ..."}


class _Bar:
    def __init__(self):
        self.counts = {}

    def update(self, **counts):
        for status, n in counts.items():
            self.counts[status] = self.counts.get(status, 0) + n


class _Store:
    def __init__(self):
        self.records = []

    def write(self, record):
        self.records.append(record)


def test_a_lost_run_is_tried_again_a_raised_one_is_not():
    _CALLS.clear()
    store, bar = _Store(), _Bar()
    Engine("serial").execute([(_lost_then_ok, {"run_id": "lost"}, store, 2, sweep.lost),
                              (_raises, {"run_id": "raised"}, store, 2, sweep.lost)], bar)
    assert _CALLS == ["lost", "lost", "raised"]
    assert [(r["run_id"], r["status"], r["attempts"]) for r in store.records] == [
        ("lost", "ok", 2), ("raised", "failed", 1)]
    assert bar.counts == {"ok": 1, "failed": 1}


def test_failures_counts_each_reason_once_most_frequent_first():
    errors = ["ValueError: a\nTraceback", None, "RuntimeError: b", "ValueError: a\nother trace",
              "ValueError: a"]
    table = pd.DataFrame({"run_id": [f"id{i}" for i in range(5)],
                          "status": ["failed", "ok", "failed", "failed", "failed"],
                          "error": errors, "seed": [0, 0, 1, 1, 0],
                          "task.wind_speed": [3.0, 4.0, 3.0, 4.0, 5.0],
                          "env.dofs": [6, 6, 6, 6, 6], "mean_surge": [None, 1.0, None, None, None]})
    assert sweep.failures(table) == [
        "failed 3 of 5 runs: ValueError: a (e.g. run 0, id0: seed=0 task.wind_speed=3.0)",
        "failed 1 of 5 runs: RuntimeError: b (e.g. run 2, id2: seed=1 task.wind_speed=3.0)"]
    table["status"] = "stopped"  # a capsize is a result, not a failure
    assert sweep.failures(table) == []
    many = pd.DataFrame({"run_id": [f"id{i}" for i in range(8)], "status": ["failed"] * 8,
                         "error": [f"ValueError: reason {i}" for i in range(8)], "seed": [0] * 8})
    lines = sweep.failures(many)
    assert len(lines) == 6
    assert lines[0] == "failed 1 of 8 runs: ValueError: reason 0 (e.g. run 0, id0: seed=0)"
    assert lines[-1] == "failed 3 of 8 runs for 3 other reasons (the error column of the table)"


HEAD = 'boat = "saoud_robot"\ntask = "heading_hold"\ncontroller = "pid"\nduration = 0.3\n'


@pytest.mark.parametrize("body,message", [
    (HEAD.replace('"saoud_robot"', '"saoud_robo"'),
     "boat = 'saoud_robo' is not one of: eleven_metre, saoud_robot, viel_boat, wille_yacht, or a boat "
     "file ending in .toml; did you mean 'saoud_robot'?"),
    (HEAD.replace('"heading_hold"', '"heading_hol"'), "; did you mean 'heading_hold'?"),
    (HEAD + 'world = "mujoc"\n', "world = 'mujoc' is not one of: mujoco, paper; did you mean 'mujoco'?"),
    (HEAD + '[grid]\n"env.hydrostatics" = ["paper", "geometrc"]\n',
     "env.hydrostatics = 'geometrc' is not one of ('off', 'paper', 'geometric'), in {source}; "
     "did you mean 'geometric'?"),
    (HEAD + 'duraton = 1.0\n', "unknown key 'duraton' in {source}; did you mean 'duration'?"),
    (HEAD + '[options]\n"waves.hs" = -1.0\n', "waves.hs must be >= 0 m, got -1.0, in {source}"),
    # every run's sea is checked, not the first run's only
    (HEAD + '[grid]\n"waves.hs" = [0.5, -1.0]\n', "waves.hs must be >= 0 m, got -1.0, in {source}"),
    (HEAD + '[options]\n"waves.hs" = 0.5\n"waves.spectrum" = "jonswp"\n',
     "unknown spectrum 'jonswp' in waves.spectrum; did you mean 'jonswap'?"),
])
def test_a_refused_sweep_file_is_one_line_with_the_nearest_name(tmp_path, capsys, body, message):
    path = tmp_path / "bad.toml"
    path.write_text(body)
    assert main(["sweep", str(path), "--out", str(tmp_path / "o")]) == 2
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 1
    assert re.fullmatch(r"sailmujoco: error: .*" + re.escape(message.format(source=f"sweep file '{path}'"))
                        + ".*", lines[0]), lines[0]
    assert not (tmp_path / "o").exists()
