"""Studies run on the sweep engine: jobs named by import path, stored like sweep runs (so a
resume runs only what is missing), one worker pool for ``study all``, and ``study --resume``
skipping the studies whose report finished. Every registered study is a declared ``Study``."""

import importlib
import json
import math
import os
import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from sailmujoco import study, sweep
from sailmujoco.cli import main as cli
from sailmujoco.cli import study as study_runner
from sailmujoco.study import Results, Runs, Study, run_study

HERE = f"{Path(__file__).stem}"


def counted(job: dict) -> dict:
    """A job that leaves one file per execution in ``job["log"]`` (counts runs, not time)."""
    log = Path(job["log"])
    log.mkdir(exist_ok=True)
    (log / f"{job['n']}-{len(list(log.iterdir()))}").touch()
    if job.get("fail"):
        raise ValueError("this job fails")
    return {"n": job["n"], "square": np.float64(job["n"]) ** 2, "key": (job["n"], "x")}


def test_values_round_trip_through_the_store_bit_for_bit():
    frame = pd.DataFrame({"t": [0.0, 0.1, 1 / 3], "x": [np.nan, -0.0, 1e-300], "n": [1, 2, 3],
                          "flag": [True, False, True], "why": [None, "capsize", "x"]})
    value = {"frame": frame, "key": ("main", "paper", 0), "by_tuple": {("a", 1): 2.5},
             "scalar": np.float64(0.1) + np.float64(0.2), "int": np.int64(7),
             "array": np.arange(6.0).reshape(2, 3),
             "nested": [1, {"inf": math.inf}], "__odd": None}
    back = sweep.decode(json.loads(json.dumps(sweep.encode(value))))
    got = back["frame"]
    assert list(got.columns) == ["t", "x", "n", "flag", "why"]
    assert [str(d) for d in got.dtypes][:4] == ["float64", "float64", "int64", "bool"]
    assert got["why"].dtype == frame["why"].dtype  # text (pandas' own inference both times)
    for column in ("t", "x"):  # every bit, the sign of zero and NaN included
        assert got[column].to_numpy().tobytes() == frame[column].to_numpy().tobytes()
    assert got["why"].equals(frame["why"]) and list(got["why"])[1:] == ["capsize", "x"]
    assert back["key"] == ("main", "paper", 0) and back["by_tuple"] == {("a", 1): 2.5}
    assert type(back["scalar"]) is np.float64 and back["scalar"] == 0.30000000000000004
    assert type(back["int"]) is np.int64 and back["array"].shape == (2, 3)
    assert back["nested"][1]["inf"] == math.inf and back["__odd"] is None
    with pytest.raises(sweep.SweepError, match="cannot be stored"):
        sweep.encode({"x": object()})


def test_jobs_are_stored_and_resume_runs_only_the_missing_one(tmp_path):
    log = tmp_path / "log"
    jobs = [{"n": n, "log": str(log)} for n in range(4)]
    store = tmp_path / "store"
    results = sweep.run_jobs(f"{HERE}:counted", jobs, store, progress=False)
    assert [r["square"] for r in results] == [0.0, 1.0, 4.0, 9.0]
    assert results[3]["key"] == (3, "x")
    assert len(list(log.iterdir())) == 4
    records = sorted((store / "runs").glob("*.json"))
    assert len(records) == 4
    records[0].unlink()  # as if the run had been interrupted before this job finished
    again = sweep.run_jobs(f"{HERE}:counted", jobs, store, resume=True, progress=False)
    assert again == results
    assert len(list(log.iterdir())) == 5  # one job ran again, the three stored ones did not
    fresh = sweep.run_jobs(f"{HERE}:counted", jobs, store, progress=False)  # no resume: all
    assert fresh == results and len(list(log.iterdir())) == 9


def test_a_failing_job_is_named_and_the_finished_ones_stay_stored(tmp_path):
    jobs = [{"n": 0, "log": str(tmp_path / "log")}, {"n": 1, "log": str(tmp_path / "log"), "fail": True}]
    with pytest.raises(sweep.SweepError, match=r"job 1 .*ValueError: this job fails"):
        sweep.run_jobs(f"{HERE}:counted", jobs, tmp_path / "store", retries=1, progress=False)
    assert len(list((tmp_path / "log").iterdir())) == 3  # the failing one tried twice
    with pytest.raises(sweep.SweepError, match="cannot find the job function 'no_such_module:f'"):
        sweep.run_jobs("no_such_module:f", jobs, tmp_path / "store", progress=False)


def _fake_study(name: str, interrupt: bool = False):
    """The entry point of a declared study that simulates nothing (Ctrl-C in its analysis with
    ``interrupt``)."""
    def analyse(results, smoke):
        if interrupt:
            raise KeyboardInterrupt

    fake = Study(name=name, title=f"The {name} study", runs=lambda smoke: Runs(), analyse=analyse,
                 write=lambda analysis, out: None, report=lambda analysis, smoke: "# fake\n",
                 headline=lambda analysis: {"answer": 42})
    return SimpleNamespace(load=lambda: fake, module=__name__)


def _record_runs(monkeypatch, calls: list) -> None:
    """Record the folder, engine and resume flag of every study's runs (:func:`study.execute`)."""
    execute = study.execute

    def recorded(runs, out, engine, **options):
        calls.append({"out": Path(out).name, "engine": engine, "resume": options.get("resume", False)})
        return execute(runs, out, engine, **options)

    monkeypatch.setattr(study, "execute", recorded)


def test_study_all_shares_one_engine_and_resume_skips_the_finished_studies(monkeypatch, tmp_path):
    calls = []
    studies = {"first": _fake_study("first"), "second": _fake_study("second", interrupt=True)}
    monkeypatch.setattr(study_runner, "studies", lambda: studies)
    _record_runs(monkeypatch, calls)
    argv = ["study", "all", "--smoke", "--out", str(tmp_path), "--no-progress"]
    assert cli.main(argv) == cli.INTERRUPTED  # Ctrl-C in the second study
    assert [c["out"] for c in calls] == ["first", "second"]
    assert calls[0]["engine"] is calls[1]["engine"] and not calls[0]["engine"].serial
    assert not calls[0]["engine"].started  # the fakes simulate nothing: no cluster was started
    marker = json.loads((tmp_path / "first" / "done.json").read_text())
    assert marker["study"] == "first" and marker["smoke"] is True and len(marker["code"]) == 16
    assert not (tmp_path / "second" / "done.json").exists()
    studies["second"] = _fake_study("second")
    calls.clear()
    assert cli.main(argv + ["--resume"]) == 0
    assert [(c["out"], c["resume"]) for c in calls] == [("second", True)]  # the first is kept
    calls.clear()
    assert cli.main(argv + ["--resume"]) == 0 and calls == []  # all finished
    monkeypatch.setattr(study_runner, "study_code_digest", lambda: "another code")
    assert cli.main(argv + ["--resume"]) == 0  # the code changed: both again (resuming)
    assert [(c["out"], c["resume"]) for c in calls] == [("first", True), ("second", True)]
    calls.clear()
    assert cli.main(argv[:2] + ["--out", str(tmp_path), "--no-progress", "--resume"]) == 0  # not smoke
    assert [c["out"] for c in calls] == ["first", "second"]
    calls.clear()
    assert cli.main(argv + ["--workers", "1"]) == 0  # no resume: both again, in this process
    assert [c["resume"] for c in calls] == [False, False] and calls[0]["engine"].serial


def test_an_entry_point_that_names_no_study_is_refused(monkeypatch, tmp_path):
    def run(out):  # a function, not a declared Study
        return {}
    entry = SimpleNamespace(load=lambda: run, module=__name__)
    monkeypatch.setattr(study_runner, "studies", lambda: {"plain": entry})
    with pytest.raises(TypeError, match="not a sailmujoco.study.Study"):
        study_runner.run_studies(["plain"], tmp_path, workers=1, progress=False)


WALL = re.compile(r"\d+(\.\d+)? s\b|wall|took")


def _counting_study(log: Path, n: int = 4) -> Study:
    """A declared study of ``n`` :func:`counted` jobs (each leaves a file in ``log``), whose
    second pass runs one job more for every job of the first; its report lists the squares."""
    def runs(smoke):
        return Runs(jobs={"first": (f"{HERE}:counted", [{"n": i, "log": str(log)} for i in range(n)])})

    def more_runs(results, smoke):
        items = [{"n": 10 + r["n"], "log": str(log)} for r in results.jobs["first"]]
        return Runs(jobs={"second": (f"{HERE}:counted", items)})

    def analyse(results, smoke):
        return [r["square"] for r in results.jobs["first"] + results.jobs["second"]]

    return Study(name="counting", title="Counting jobs", runs=runs, analyse=analyse,
                 write=lambda squares, out: (Path(out) / "squares.csv").write_text(str(squares)),
                 report=lambda squares, smoke: f"# squares\n\n{squares}\n",
                 headline=lambda squares: {"total": float(sum(squares))}, more_runs=more_runs)


def test_run_study_runs_both_passes_and_a_resume_runs_nothing_new(tmp_path):
    log, out = tmp_path / "log", tmp_path / "out"
    study = _counting_study(log)
    with sweep.Engine("serial") as engine:
        headline = run_study(study, out, engine, smoke=True, progress=False)
        assert headline == {"total": float(sum(n * n for n in [0, 1, 2, 3, 10, 11, 12, 13]))}
        assert len(list(log.iterdir())) == 8  # both passes
        assert (out / "report.md").read_text().startswith("# squares")
        assert (out / "squares.csv").exists()
        assert run_study(study, out, engine, smoke=True, resume=True, progress=False) == headline
        assert len(list(log.iterdir())) == 8  # everything was stored: nothing ran again
        sorted((out / "jobs" / "second" / "runs").glob("*.json"))[0].unlink()
        assert run_study(study, out, engine, smoke=True, resume=True, progress=False) == headline
        assert len(list(log.iterdir())) == 9  # only the missing job
        assert run_study(study, out, engine, smoke=True, progress=False) == headline
        assert len(list(log.iterdir())) == 17  # no resume: all again


def test_an_interrupted_study_resumes_only_its_missing_job(monkeypatch, tmp_path, capsys):
    """A declared study through the command: one stored job record and the marker deleted (the
    run interrupted there); --resume runs that job alone and writes the same report."""
    log = tmp_path / "log"
    study = _counting_study(log)
    monkeypatch.setattr(study_runner, "studies",
                        lambda: {"counting": SimpleNamespace(load=lambda: study, module=__name__)})
    argv = ["study", "counting", "--smoke", "--workers", "1", "--out", str(tmp_path / "results"),
            "--no-progress"]
    assert cli.main(argv) == 0
    out = tmp_path / "results" / "counting"
    report = (out / "report.md").read_text()
    records = sorted((out / "jobs" / "first" / "runs").glob("*.json"))
    assert len(records) == 4 and len(list(log.iterdir())) == 8
    before = {p.name: os.stat(p).st_mtime_ns for p in records}
    records[1].unlink()
    (out / "done.json").unlink()
    capsys.readouterr()
    assert cli.main(argv + ["--resume"]) == 0
    assert "(resumed)" in capsys.readouterr().out
    after = {p.name: os.stat(p).st_mtime_ns for p in (records[0].parent).glob("*.json")}
    rewritten = {name for name in after if before.get(name) != after[name]}
    assert rewritten == {records[1].name} and len(list(log.iterdir())) == 9  # only the missing job ran
    same = [line for line in report.splitlines() if not WALL.search(line)]
    assert [line for line in (out / "report.md").read_text().splitlines() if not WALL.search(line)] == same
    assert (out / "done.json").exists()


def test_video_films_the_declared_scenario_clamped_in_smoke_mode(monkeypatch, tmp_path, capsys):
    from dataclasses import replace

    from sailmujoco import video

    filmed = []

    def record(out, **scenario):
        filmed.append(scenario)
        return SimpleNamespace(path=Path(out) / "study.mp4")

    monkeypatch.setattr(video, "record_study_scenario", record)
    study = replace(_counting_study(tmp_path / "log", n=1),
                    video={"boat": "saoud_robot", "task": "speed_trial", "seconds": 60.0})
    monkeypatch.setattr(study_runner, "studies",
                        lambda: {"counting": SimpleNamespace(load=lambda: study, module=__name__)})
    argv = ["study", "counting", "--workers", "1", "--out", str(tmp_path), "--no-progress", "--video"]
    assert cli.main(argv + ["--smoke"]) == 0 and cli.main(argv) == 0
    assert filmed == [{"boat": "saoud_robot", "task": "speed_trial", "seconds": 5.0},
                      {"boat": "saoud_robot", "task": "speed_trial", "seconds": 60.0}]
    assert f"video: {tmp_path / 'counting' / 'study.mp4'}" in capsys.readouterr().out


def test_every_registered_study_is_declared_and_its_title_is_read_without_importing_it():
    found = study_runner.studies()
    assert set(study_runner.STUDY_ORDER) <= set(found)
    titles = study_runner.study_titles()
    for name, entry in found.items():
        declared = entry.load()
        assert isinstance(declared, Study), name
        assert declared.name == name and declared.title and titles[name] == declared.title
        for part in ("runs", "analyse", "write", "report", "headline"):
            assert callable(getattr(declared, part)), (name, part)
        assert declared.more_runs is None or callable(declared.more_runs)
        assert declared.video is None or isinstance(declared.video.get("boat"), str)
        for smoke in (True, False):
            runs = declared.runs(smoke)
            assert isinstance(runs, Runs)
            for function, items in runs.jobs.values():
                module, _, attribute = function.partition(":")
                assert callable(getattr(importlib.import_module(module), attribute)), function
                assert isinstance(items, list)
    assert isinstance(Results().merged(Results(jobs={"a": [1]})), Results)


TINY = {"name": "tiny", "boat": "saoud_robot", "task": "heading_hold", "world": "mujoco",
        "controller": "pid", "duration": 1.0, "seeds": [0, 1], "metrics": ["mean_surge"],
        "options": {"task.gusts": False}}


def test_sweeps_and_jobs_share_one_cluster_and_match_the_serial_runs(tmp_path):
    """Two batches (a sweep beside a job list, then another sweep) on one embedded cluster give
    what the same runs give in this process, bit for bit."""
    negate = [("operator:neg", [1.5, -2.0], tmp_path / "j1")]
    serial, (jobs_serial,) = sweep.run_many([(TINY, tmp_path / "s1")], negate, scheduler="serial",
                                            progress=False)
    with sweep.Engine(workers=1) as engine:
        assert not engine.started
        tables, (jobs,) = sweep.run_many([(TINY, tmp_path / "d1")], negate, engine=engine, progress=False)
        client = engine.client()
        other = sweep.run(dict(TINY, seeds=[2]), tmp_path / "d2", engine=engine, progress=False)
        assert engine.client() is client and len(client.scheduler_info()["workers"]) == 1
    assert not engine.started  # closed with the block
    assert jobs == jobs_serial == [-1.5, 2.0]
    assert list(tables[0]["mean_surge"]) == list(serial[0]["mean_surge"])
    assert list(other["seed"]) == [2] and list(other["status"]) == ["ok"]
    with pytest.raises(sweep.SweepError, match="not both"):
        sweep.run(TINY, tmp_path / "x", engine=sweep.Engine("serial"), workers=2)


def _seeded_study(n: int = 5) -> Study:
    """A declared study whose runs are one job per seed; its headline is the seeds it saw."""
    def runs(smoke, seeds):
        return Runs(jobs={"draws": (f"{HERE}:counted", [{"n": s, "log": "unused"} for s in seeds])})

    def analyse(results, smoke):
        return {"seeds": results.seeds, "ran": [r["n"] for r in results.jobs["draws"]]}

    return Study(name="seeded", title="Seeded", runs=runs, analyse=analyse, write=lambda a, out: None,
                 report=lambda a, smoke: "# seeded\n", headline=lambda a: a, seeds=n)


def test_a_study_runs_its_own_seeds_smoke_runs_two_and_seeds_overrides_both(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # the jobs' logs
    seeded = _seeded_study(5)
    with sweep.Engine("serial") as engine:
        assert run_study(seeded, tmp_path / "a", engine, progress=False)["ran"] == [0, 1, 2, 3, 4]
        assert run_study(seeded, tmp_path / "b", engine, smoke=True, progress=False)["seeds"] == (0, 1)
        got = run_study(seeded, tmp_path / "c", engine, smoke=True, seeds=7, progress=False)
        assert got["seeds"] == tuple(range(7)) and got["ran"] == list(range(7))
    assert study.SMOKE_SEEDS == 2 and _seeded_study(1).seeds_for(smoke=True) == (0,)


def test_seeds_is_checked_in_one_line_and_kept_in_the_finished_marker(capsys):
    with pytest.raises(SystemExit):
        cli.main(["study", "saoud_fig6", "--seeds", "0"])
    assert "argument --seeds: must be an integer >= 1 and <= 1000, got '0'" in capsys.readouterr().err
    assert study_runner.marker("x", False, "c", 10) != study_runner.marker("x", False, "c", None)


def gusty_surge(job: dict) -> dict:
    """One short episode of the robot in gusts: its mean surge (the gusts and start are the seed's)."""
    from sailmujoco.studies.kit import run_episode

    metrics, _, _ = run_episode("saoud_robot", "heading_hold", "mujoco", "pid", seed=job["seed"],
                                time_limit=6.0)
    return {"seed": job["seed"], "surge": metrics["mean_surge"]}


def _gusty_study() -> Study:
    from sailmujoco import stats

    def runs(smoke, seeds):
        return Runs(jobs={"surge": (f"{HERE}:gusty_surge", [{"seed": s} for s in seeds])})

    def analyse(results, smoke):
        return stats.mean_interval([r["surge"] for r in results.jobs["surge"]])

    return Study(name="gusty", title="Gusty", runs=runs, analyse=analyse, write=lambda a, out: None,
                 report=lambda a, smoke: f"# gusty\n\nsurge {a.mean!r} [{a.low!r}, {a.high!r}], N={a.n}\n",
                 headline=lambda a: {"surge": a.mean}, seeds=3)


def test_the_same_seeds_give_the_same_report_bit_for_bit_and_another_n_another_interval(tmp_path):
    gusty = _gusty_study()
    with sweep.Engine("serial") as engine:
        for name, seeds in (("a", 3), ("b", 3), ("c", 4)):
            run_study(gusty, tmp_path / name, engine, seeds=seeds, progress=False)
    a, b, c = ((tmp_path / n / "report.md").read_text() for n in "abc")
    assert a == b and "N=3" in a  # a run is a pure function of its seeds, printed to 17 digits
    assert c != a and "N=4" in c
