"""The ArduPilot comparison's measures, from first principles on tracks whose answers are known:
the true wind angle's side, tacks against gybes and abandoned tacks, the cross-track distance, a
flight's numbers and its report; the sea given to SIM_Sailboat from deep-water dispersion; and
the one-line reasons it gives where ArduPilot is not there. The flights themselves need
ArduPilot's ardurover (tests/test_ardupilot.py flies it where it is present)."""

import math

import numpy as np
import pytest
from sailmujoco.studies.ardupilot.cases import Case, cases, ours_parameters
from sailmujoco.studies.ardupilot.measures import cross_track, measure, tacks, true_wind_angle
from sailmujoco.studies.ardupilot.mission import Flight, Mission, find_ardurover, sim_sailboat_sea
from sailmujoco.studies.ardupilot.report import load_flight, save_flight, summary, write_all


def test_the_true_wind_angle_is_negative_with_the_wind_over_the_port_side():
    # wind from the north: heading north-east it comes over the port bow, north-west over starboard
    np.testing.assert_allclose(true_wind_angle([45.0, 315.0, 180.0, 0.0], 0.0), [-45.0, 45.0, -180.0, 0.0])
    np.testing.assert_allclose(true_wind_angle([100.0], 90.0), [-10.0])


def test_a_tack_is_the_bow_through_the_wind_from_one_tack_to_the_other():
    assert tacks([45, 30, 10, 0, 350, 330, 315], 0.0) == 1
    assert tacks([45, 40, 30, 20, 10, 5, 10, 30, 45], 0.0) == 0  # begun and abandoned
    assert tacks([45, 90, 135, 180, 225, 270, 315], 0.0) == 0  # round by the stern: a gybe
    assert tacks([45, 0, 315, 0, 45, 0, 315], 0.0) == 3
    assert tacks([315, 0, 45], 0.0) == 1 and tacks([135, 90, 45], 90.0) == 1


def test_the_cross_track_error_is_the_distance_from_the_legs_line():
    np.testing.assert_allclose(cross_track([50.0, 20.0], [7.0, -3.0], (0.0, 0.0), (100.0, 0.0)), [7.0, 3.0])
    # a leg to the north-east: the point (0, 10) lies 10 sin 45 deg off it
    np.testing.assert_allclose(cross_track([0.0], [10.0], (0.0, 0.0), (50.0, 50.0)), [10.0 / math.sqrt(2.0)])


def test_the_mission_and_the_sim_sailboat_sea():
    assert Mission().waypoints() == [(0.0, 0.0), (100.0, 0.0), (0.0, 0.0)]
    # laid from where the boat is
    assert Mission().waypoints((-34.0, 34.0)) == [(-34.0, 34.0), (66.0, 34.0), (-34.0, 34.0)]
    north, east = Mission(wind_from_deg=90.0).waypoints()[1]
    assert north == pytest.approx(0.0, abs=1e-12) and east == pytest.approx(100.0)
    sea = sim_sailboat_sea()  # deep water: L = g T^2 / (2 pi), c = L / T; T = 6 s
    assert sea["SIM_WAVE_LENGTH"] == pytest.approx(56.19, abs=0.01)
    assert sea["SIM_WAVE_SPEED"] == pytest.approx(9.36, abs=0.01)
    assert sea["SIM_WAVE_AMP"] == 1.0  # SIM_Sailboat's slope takes half of it: 1 m high


def test_our_boats_sheet_to_their_sails_stall_and_the_cases_are_all_there():
    assert ours_parameters("saoud_robot") == {"SAIL_ANGLE_IDEAL": 15.0}
    assert ours_parameters("wille_yacht") == {"SAIL_ANGLE_IDEAL": 15.0}
    all_cases = cases(4)
    assert len(all_cases) == (2 + 2) + (2 + 4) + (2 + 4 + 2) + 1
    motored = [c for c in all_cases if c.motor]
    assert len(motored) == 4 and all(c.sea and c.simulator == "saoud_robot" for c in motored)
    assert motored[0].label == "saoud_robot, 6-DOF, 10 N motor, 1 m sea"
    assert len({c.folder for c in all_cases}) == len(all_cases)
    assert Case("saoud_robot", False, 0, tuned=False).label == "saoud_robot, 6-DOF, SAIL_ANGLE_IDEAL 25, calm"


def _zigzag_flight() -> Flight:
    """Up a 100 m leg north in four 20-m-wide boards (3 tacks), heel 10 deg except 2 s at 20 deg,
    then straight home; 0.1 s rows."""
    rows, t = [], 0.0
    north, east, heading = 0.0, 0.0, 45.0
    for board in range(4):
        heading = 45.0 if board % 2 == 0 else 315.0
        for _ in range(250):  # 25 s a board at 1 m/s: 17.7 m north, 17.7 m across
            north += 0.1 * math.cos(math.radians(heading))
            east += 0.1 * math.sin(math.radians(heading))
            roll = 20.0 if 10.0 <= t < 12.0 else 10.0
            rows.append({"t": round(t, 1), "north": north, "east": east, "heading": heading, "roll": roll,
                         "speed": 1.0, "wp": 1})
            t += 0.1
    mark = t
    for _ in range(100):
        north -= 0.7
        rows.append({"t": round(t, 1), "north": north, "east": east, "heading": 180.0, "roll": -5.0,
                     "speed": 7.0, "wp": 2})
        t += 0.1
    events = [(25.0, "Sailboat: Tacking"), (50.0, "Sailboat: Tacking"), (75.0, "Sailboat: Tacking"),
              (80.0, "Sailboat: Tacking timed out")]
    return Flight(rows=rows, events=events, reached={1: mark, 2: round(t - 0.1, 1)}, wall=12.0)


def test_a_flights_numbers_from_a_known_track():
    m = measure(_zigzag_flight(), Mission())
    assert m["finished"] and m["mark_s"] == pytest.approx(100.0) and m["home_s"] == pytest.approx(109.9)
    assert m["tacks"] == 3 and m["tacks_begun"] == 3 and m["tacks_timed_out"] == 1
    assert m["heel_max_deg"] == pytest.approx(20.0)
    assert m["over_heel_max_pct"] == pytest.approx(100.0 * 20 / 1100, rel=1e-3)  # 2 s of 110 s
    assert m["xte_max_m"] == pytest.approx(25.0 * math.sin(math.radians(45.0)), rel=1e-6)
    shifted = _zigzag_flight()  # the same track, the mission laid 5 m to the west of it
    shifted.waypoints = Mission().waypoints((0.0, -5.0))
    xte = measure(shifted, Mission())["xte_max_m"]
    assert xte == pytest.approx(5.0 + 25.0 * math.sin(math.radians(45.0)))


def test_a_flight_kept_reads_back_and_the_report_tables_it(tmp_path):
    flight = _zigzag_flight()
    save_flight(flight, tmp_path / "one")
    back = load_flight(tmp_path / "one")
    assert back.reached == flight.reached and back.events == flight.events
    assert len(back.rows) == len(flight.rows)
    assert load_flight(tmp_path / "none") is None
    slow = _zigzag_flight()
    slow.reached = {1: 100.0}  # never home
    flights = [(Case("wille_yacht", False, 0), Mission(), flight),
               (Case("wille_yacht", False, 1), Mission(), flight),
               (Case("sailboat", False, 0), Mission(), slow)]
    rows = write_all(flights, tmp_path / "out")
    table = {e["case"]: e for e in summary(rows)}
    yacht = table["wille_yacht, 6-DOF, calm"]
    assert (yacht["n"], yacht["finished"]) == (2, 2) and yacht["home_s"].mean == pytest.approx(109.9)
    assert table["ArduPilot's SIM_Sailboat, calm"]["finished"] == 0
    text = (tmp_path / "out" / "report.md").read_text()
    row = ("| wille_yacht, 6-DOF, calm | 2 | 2 of 2 | 100 (all 2 equal) | 110 (all 2 equal) "
           "| 3.0 (all 2 equal) |")
    assert row in text
    assert "| ArduPilot's SIM_Sailboat, calm | 1 | 0 of 1 | — | — |" in text
    for name in ("tracks.png", "heel.png"):
        assert (tmp_path / "out" / name).stat().st_size > 10_000
    assert len((tmp_path / "out" / "flights.csv").read_text().splitlines()) == 4


def test_without_ardurover_it_says_why_in_one_line(tmp_path, monkeypatch):
    monkeypatch.delenv("SAILMUJOCO_ARDUROVER", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))
    assert "give --ardurover PATH" in find_ardurover(None)
    assert "not an executable ardurover" in find_ardurover(tmp_path / "nothing")
    program = tmp_path / "ardurover"
    program.write_text("#!/bin/sh\n")
    program.chmod(0o755)
    reason = find_ardurover(tmp_path)
    assert "rover.parm and sailboat.parm not beside it" in reason and "\n" not in reason
    (tmp_path / "rover.parm").write_text("")
    (tmp_path / "sailboat.parm").write_text("")
    assert find_ardurover(tmp_path) == program
