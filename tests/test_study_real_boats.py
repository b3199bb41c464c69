"""The real-boats study: its canoe bodies take the tank hulls' ratios, the tank's numbers are read
as printed, and its smoke pass runs and writes its report against ORC."""

import math

import pytest
from sailmujoco.studies import real_boats
from sailmujoco.studies.real_boats import scenario
from test_reports import layout_problems

from sailmujoco import sweep
from sailmujoco.boat import hull as hull_geometry
from sailmujoco.study import run_study


def test_the_canoe_body_takes_a_tank_hulls_slenderness_and_length_beam_ratio():
    h = scenario.canoe_body(4.78, 3.17)  # the series' parent: L/V^(1/3) 4.78, L/B 3.17
    volume = hull_geometry.volume(h)
    assert h.length / volume ** (1.0 / 3.0) == pytest.approx(4.78, rel=1e-12)
    assert h.length / (2.0 * h.half_beam) == pytest.approx(3.17, rel=1e-12)
    # its B/T follows: V = (2 pi / 15) B T L
    assert 2.0 * h.half_beam / h.canoe_draft == pytest.approx(
        (2.0 * math.pi / 15.0) * (h.length / 3.17) ** 2 * h.length / volume, rel=1e-12)


def test_the_tank_data_are_read_as_printed():
    data = scenario.tank()
    hulls = data.groupby(["lcb", "cp", "l_over_displ13", "b_over_t", "l_over_b"]).ngroups
    assert len(data) == 308 and hulls == 22
    first = data.iloc[0]  # the file's first row: the parent at Fn 0.125 gives 0.11
    assert (first["lcb"], first["cp"], first["fn"]) == (-2.3, 0.568, 0.125)
    assert first["rr_per_weight_x1000"] == 0.11


def test_the_smoke_pass_holds_the_boat_against_orc(tmp_path):
    with sweep.Engine("serial") as engine:
        out = run_study(real_boats.STUDY, tmp_path, engine, smoke=True, progress=False)
    assert out["points"] == 3  # 10 kn: 52 and 90 deg, and the beat
    assert 0.3 < out["ratio_min"] <= out["ratio_max"] < 1.5
    text = (tmp_path / "report.md").read_text()
    assert layout_problems(text) == []
    assert "| 10 | boat speed | 52 / 52 |" in text
    for name in ("orc.csv", "checks.csv", "tank.csv", "polar_eleven_metre.png", "tank.png"):
        assert (tmp_path / name).stat().st_size > 100
