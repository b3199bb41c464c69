"""The courses study: its analysis names a cause from runs scored by hand, and its smoke pass
sails Viel's boat round the race and into the box and writes the report."""

import math

import pytest
from sailmujoco.studies import courses
from sailmujoco.studies.courses.analysis import analyse, change
from test_reports import layout_problems

from sailmujoco import sweep
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.study import Results, run_study


def _item(task, arm, seed, score, finished=1):
    metric = {"upwind_downwind": "finish_time", "station_keeping": "points"}[task]
    metrics = {metric: score, "duration": 100.0}
    if task == "upwind_downwind":
        metrics["finished"] = finished
    return {"boat": "viel_boat", "task": task, "arm": arm, "seed": seed, "metrics": metrics, "tacks": 2,
            "astern": 0.0, "track": [[0.0, 0.0, 0.0]], "scene": None}


def test_a_case_loses_on_the_worse_side_of_its_paired_interval_and_the_switch_that_loses_names_it():
    """Station points 8, 9, 10 calm; 5, 6, 7 in the sea with typical instruments: 3 worse on every
    seed (the interval is the single value 3); the sea alone 5, 6, 7 loses as well, the
    instruments alone 8, 9, 10 do not: the cause is the sea."""
    arms = {"calm, perfect": (8, 9, 10), "sea, typical": (5, 6, 7), "sea alone": (5, 6, 7),
            "instruments alone": (8, 9, 10)}
    items = [_item("station_keeping", arm, seed, s) for arm, scores in arms.items()
             for seed, s in enumerate(scores)]
    a = analyse(Results(jobs={"runs": items}, seeds=(0, 1, 2)), smoke=False)
    hard = a.changes.set_index("arm").loc["sea, typical"]
    assert hard["worse"] == pytest.approx(3.0) and bool(hard["loses"])
    assert not bool(a.changes.set_index("arm").loc["instruments alone"]["loses"])
    assert a.causes.to_dict("records") == [{"task": "station_keeping", "boat": "viel_boat", "sea alone": True,
                                            "instruments alone": False, "cause": "sea"}]


def test_a_race_with_fewer_finishers_loses_whatever_the_finishers_times():
    """A faster time on the seed that finished does not save an arm that left one unfinished."""
    base = [_item("upwind_downwind", "calm, perfect", s, 200.0) for s in range(2)]
    other = [_item("upwind_downwind", "sea, typical", 0, 150.0),
             _item("upwind_downwind", "sea, typical", 1, None, finished=0)]
    rows = analyse(Results(jobs={"runs": base + other}, seeds=(0, 1)), smoke=False).runs
    got = change(rows[rows["arm"] == "calm, perfect"], rows[rows["arm"] == "sea, typical"], "upwind_downwind")
    assert got["fewer_finished"] == 1 and got["loses"] and got["worse"] == pytest.approx(-50.0)


def test_the_smoke_pass_sails_viels_boat_round_the_race_and_into_the_box(tmp_path):
    with sweep.Engine("serial") as engine:
        out = run_study(courses.STUDY, tmp_path, engine, smoke=True, progress=False)
    key = "upwind_downwind viel_boat calm, perfect"
    assert out[f"{key} finished"] == "2/2"
    # no faster than the 200 m of the course at the hull speed, 1.25 sqrt(g L_wl) (a displacement hull)
    hull_speed = 1.25 * math.sqrt(9.81 * get_boat("viel_boat").hull.length)
    assert 200.0 / hull_speed < out[key] < 250.0
    assert 0.0 < out["station_keeping viel_boat calm, perfect"] <= 10.0  # in the box, SailBot's 10 at most
    text = (tmp_path / "report.md").read_text()
    assert layout_problems(text) == []
    for name in ("runs.csv", "summary.csv", "tracks.png", "scores.png"):
        assert (tmp_path / name).stat().st_size > 100
