"""Courses: marks laid to the wind as the layout rotated by hand, a race scored as WRSC 2019's
rules score it (hand-scored synthetic tracks), and the line follower sailing the course."""

import math

import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.tasks.course import crossed, lay, score_race

S = math.sqrt(0.5)


@pytest.mark.parametrize("wind_from_deg, up, across", [
    (0.0, (0.0, 100.0), (10.0, 0.0)),  # a northerly: up is north, starboard (facing it) east
    (90.0, (100.0, 0.0), (0.0, -10.0)),  # an easterly: up is east, starboard south
    (225.0, (-100 * S, -100 * S), (-10 * S, 10 * S)),  # a south-westerly: up is SW, starboard NW
])
def test_a_layout_is_laid_to_the_wind_as_rotated_by_hand(wind_from_deg, up, across):
    world = lay([(0.0, 100.0), (10.0, 0.0)], math.radians(wind_from_deg), origin=(0.0, 0.0))
    np.testing.assert_allclose(world, [up, across], atol=1e-12)
    np.testing.assert_allclose(lay([(0.0, 0.0)], 1.0, origin=(3.0, -4.0)), [(3.0, -4.0)])


def test_the_windward_mark_lies_upwind_of_the_line_for_any_wind():
    env = suite.load("eleven_metre", "upwind_downwind", seed=0, wind_from_deg=30.0, leg=100.0, laps=2)
    task = env.task
    windward = (100 * math.sin(math.radians(30)), 100 * math.cos(math.radians(30)))
    leeward = (-10 * math.sin(math.radians(30)), -10 * math.cos(math.radians(30)))
    np.testing.assert_allclose(task.marks, [windward, leeward, windward], atol=1e-12)
    # the 20 m line across the wind: its ends 10 m either side of the start, square to the wind
    c, s = 10 * math.cos(math.radians(30)), 10 * math.sin(math.radians(30))
    np.testing.assert_allclose(task.finish, [(-c, s), (c, -s)], atol=1e-12)


MARKS = [(0.0, 100.0)]
LINE = [(-10.0, 0.0), (10.0, 0.0)]


def track(*points):
    """A track through ``points``, one a second."""
    return np.arange(len(points), dtype=float), np.array(points, dtype=float)


def test_a_mark_reached_within_5_m_then_the_line_crossed_finishes_at_the_crossing():
    t, xy = track((0, 1), (3, 50), (4.9, 100), (3, 50), (1, 1), (1, -1), (1, -5))
    assert score_race(t, xy, MARKS, LINE) == {"marks_reached": 1, "finished": 1, "finish_time": 5.0}


def test_a_mark_passed_at_5_1_m_is_not_reached_and_crossing_the_line_does_not_finish():
    t, xy = track((0, 1), (5.1, 100), (1, 1), (1, -1))
    result = score_race(t, xy, MARKS, LINE)
    assert result["marks_reached"] == 0 and result["finished"] == 0 and math.isnan(result["finish_time"])


def test_a_line_crossed_outside_its_ends_is_no_finish():
    t, xy = track((0, 1), (0, 100), (15, 1), (15, -1))
    result = score_race(t, xy, MARKS, LINE)
    assert result["marks_reached"] == 1 and result["finished"] == 0 and math.isnan(result["finish_time"])


def test_crossed_needs_the_step_to_cut_the_segment():
    assert crossed((0, 1), (0, -1), (-1, 0), (1, 0))
    assert not crossed((2, 1), (2, -1), (-1, 0), (1, 0))  # beyond the segment's end
    assert not crossed((0, 1), (0, 0.5), (-1, 0), (1, 0))  # stops short


def test_the_distance_to_go_rises_not_falls_at_a_rounding():
    """4 m below the windward mark, on the way up: 4 + 100 m to go; reached, 96 m (to the line)."""
    env = suite.load("eleven_metre", "upwind_downwind", seed=0, wind_from_deg=0.0)
    env.reset()
    task = env.task
    assert task.distance_to_go((0.0, 96.0)) == pytest.approx(104.0)
    task.advance((0.0, 96.0))
    assert task.reached == 1 and task.distance_to_go((0.0, 96.0)) == pytest.approx(96.0)


@pytest.mark.parametrize("boat", ["eleven_metre", "viel_boat", "wille_yacht", "saoud_robot"])
def test_the_line_follower_sails_the_course_with_tacks_in_calm_water(boat):
    from sailmujoco.controllers.factories import line_following

    env = suite.load(boat, "upwind_downwind", seed=0, gusts=False, wander=False)
    table = suite.rollout(env, line_following(env))
    metrics = env.task.metrics()
    assert metrics["marks_reached"] == 1 and metrics["finished"] == 1
    upwind = table[table["t"] <= table["t"][np.argmax(table["y"].to_numpy())]]
    awa = upwind["awa"].to_numpy()
    ahead = np.abs(awa) < math.pi / 2
    assert np.sum((np.sign(awa[1:]) != np.sign(awa[:-1])) & ahead[1:] & ahead[:-1]) >= 2


def test_videos_and_the_map_get_the_courses_marks_and_line():
    from sailmujoco.video.recording import scene_of

    env = suite.load("eleven_metre", "upwind_downwind", seed=0, wind_from_deg=90.0, leg=80.0, laps=2)
    _, _, _, target = scene_of("eleven_metre", env, {})
    np.testing.assert_allclose(target["marks"], [(80.0, 0.0), (-10.0, 0.0), (80.0, 0.0)], atol=1e-12)
    np.testing.assert_allclose(target["line"], [(0.0, 10.0), (0.0, -10.0)], atol=1e-12)  # across the wind
    assert target["radii"] == (5.0, 5.0) and target["position"] == target["marks"][0]


def test_precision_navigations_buoys_lie_downwind_of_the_gate_across_the_wind():
    env = suite.load("eleven_metre", "precision_navigation", seed=0, wind_from_deg=90.0, distance=50.0,
                     gap=20.0, line=10.0)
    # an easterly: downwind is west, across (to starboard, facing east) is south
    np.testing.assert_allclose(env.task.marks, [(-50.0, 10.0), (-50.0, -10.0)], atol=1e-12)
    np.testing.assert_allclose(env.task.finish, [(0.0, 5.0), (0.0, -5.0)], atol=1e-12)


@pytest.mark.parametrize("points, expected", [
    ([(0, -1), (-10, -49), (10, -49), (1, -1), (1, 1)], 10),  # both buoys, back through the gate
    ([(0, -1), (-10, -49), (10, -49), (30, -1), (30, 1)], 8),  # both, back outside the gate
    ([(0, -1), (-10, -49), (10, -40), (1, -1), (1, 1)], 2),  # the second buoy missed by 9 m
    ([(0, -1), (0, -30), (1, -1), (1, 1)], 0),  # neither
])
def test_precision_navigation_scores_as_sailbots_sheet(points, expected):
    """A northerly: buoys at (-10, -50) and (10, -50), the gate from (-5, 0) to (5, 0); one
    point a second along the hand-drawn track (a buoy counts within 5 m)."""
    env = suite.load("eleven_metre", "precision_navigation", seed=0, wind_from_deg=0.0)
    t = np.arange(len(points), dtype=float)
    records = [{"t": ti, "position": np.array(p, dtype=float)} for ti, p in zip(t, points, strict=True)]
    assert env.task.summarise(records)["points"] == expected


def station_track(inside_spans, end=600.0):
    """One point a second, inside the northerly's box (centre (0, 60), half 20) during the spans."""
    t = np.arange(0.0, end + 1.0)
    y = np.where(np.any([(t >= a) & (t < b) for a, b in inside_spans], axis=0), 60.0, 0.0)
    return t, np.stack([np.zeros_like(t), y], axis=1)


@pytest.mark.parametrize("spans, expected", [
    ([(10, 315)], {"entered_at": 10.0, "time_in_box": 300.0, "time_in_box_late": 0.0, "points": 10.0}),
    ([(10, 410)], {"entered_at": 10.0, "time_in_box": 300.0, "time_in_box_late": 70.0,
                   "points": 10.0 - 2.0 * 70.0 / 60.0}),  # out 100 s late: 70 s past the 30 s grace
    ([(10, 130), (190, 310)], {"entered_at": 10.0, "time_in_box": 240.0, "time_in_box_late": 0.0,
                               "points": 8.0}),  # out for a minute in the middle
    ([(10, 40)], {"entered_at": 10.0, "time_in_box": 30.0, "time_in_box_late": 0.0, "points": 1.0}),
])
def test_station_keeping_scores_as_sailbots_sheet(spans, expected):
    from sailmujoco.tasks.station import score_station

    t, xy = station_track(spans)
    result = score_station(t, xy, (0.0, 60.0), 20.0, 0.0)
    assert result == pytest.approx(expected)


def test_a_boat_that_never_enters_the_box_scores_nothing_and_the_box_turns_with_the_wind():
    from sailmujoco.tasks.station import score_station

    t, xy = station_track([(10, 20)])
    xy[:, 0] = 21.0  # a metre beside the box, all along
    assert score_station(t, xy, (0.0, 60.0), 20.0, 0.0)["points"] == 0.0
    env = suite.load("eleven_metre", "station_keeping", seed=0, wind_from_deg=90.0, side=40.0, distance=60.0)
    np.testing.assert_allclose(env.task.center, (60.0, 0.0), atol=1e-12)  # 60 m east, into an easterly
    # an easterly's box: 15 m across (south) and 15 m up (east) is inside; 25 m up is not
    inside = score_station([0.0, 1.0], [(75.0, -15.0), (75.0, -15.0)], env.task.center, 20.0, math.pi / 2)
    outside = score_station([0.0, 1.0], [(85.0, 0.0), (85.0, 0.0)], env.task.center, 20.0, math.pi / 2)
    assert inside["entered_at"] == 0.0 and math.isnan(outside["entered_at"])


def test_area_scanning_counts_the_cells_a_track_falls_in_on_a_grid_laid_to_the_wind():
    from sailmujoco.tasks.scanning import cells_of

    # a northerly's 60 m square about (0, 50), 2.5 m cells: the corner downwind and to port is (0, 0)
    points = [(-29.0, 21.0), (29.0, 79.0), (31.0, 50.0), (-29.5, 21.5)]
    assert cells_of(points, (0.0, 50.0), 30.0, 2.5, 0.0) == {(0, 0), (23, 23)}  # (31, 50) is outside
    # an easterly's: 29 m east and 29 m north of the centre is 29 m up and 29 m to port
    assert cells_of([(79.0, 29.0)], (50.0, 0.0), 30.0, 2.5, math.pi / 2) == {(0, 23)}
    env = suite.load("viel_boat", "area_scanning", seed=0, wind_from_deg=90.0)
    np.testing.assert_allclose(env.task.center, (50.0, 0.0), atol=1e-12)
    assert env.task.cells == 576  # WRSC 2019's 24 x 24
    with pytest.raises(ValueError, match="cell must divide side into whole cells"):
        suite.load("viel_boat", "area_scanning", side=60.0, cell=7.0)


def test_the_line_follower_mows_the_square_in_rows_across_the_wind_from_the_upwind_one_down():
    from sailmujoco.controllers.line_following import mown

    np.testing.assert_allclose(mown((0.0, 0.0), 10.0, 5.0, 0.0), [
        (-7.5, 7.5), (7.5, 7.5), (7.5, 2.5), (-7.5, 2.5), (-7.5, -2.5), (7.5, -2.5), (7.5, -7.5),
        (-7.5, -7.5)], atol=1e-12)


def test_the_second_pass_of_the_mown_square_lies_between_the_first_passs_rows():
    """A 20 m square, rows 5 m apart at 7.5, 2.5, -2.5, -7.5 m up; shifted 2.5 m downwind they
    lie at 5, 0, -5 m (the one at -10 m is the square's edge, left out)."""
    from sailmujoco.controllers.line_following import mown

    rows = sorted({round(y, 9) for _, y in mown((0.0, 0.0), 10.0, 5.0, 0.0, shift=2.5)})
    assert rows == [-5.0, 0.0, 5.0]


def test_a_course_of_ones_own_is_laid_to_the_wind_and_sailed(tmp_path):
    from sailmujoco.controllers.factories import line_following

    path = tmp_path / "triangle.toml"
    path.write_text("[course]\nmarks = [[0, 60], [40, 30]]\nline = 16\nradius = 6\n")
    env = suite.load("viel_boat", "upwind_downwind", seed=0, wind_from_deg=90.0, course=str(path),
                     gusts=False, wander=False)
    # an easterly: up is east, across (starboard, facing east) is south
    np.testing.assert_allclose(env.task.marks, [(60.0, 0.0), (30.0, -40.0)], atol=1e-12)
    np.testing.assert_allclose(env.task.finish, [(0.0, 8.0), (0.0, -8.0)], atol=1e-12)
    assert env.task.radius == 6.0 and env.task.leg == pytest.approx(60.0)
    suite.rollout(env, line_following(env))
    assert env.task.metrics()["marks_reached"] == 2 and env.task.metrics()["finished"] == 1


@pytest.mark.parametrize("text, message", [
    ("[course]\nmarks = [[0, 6000]]\n", "mark 1 at [0.0, 6000.0] lies 6000 m from the start, beyond"),
    ("[course]\nmarks = [[0, 60], [3, 62]]\n", "mark 2 at [3.0, 62.0] lies within the 5 m radius of mark 1"),
    ("[course]\nmarks = [[0, 3]]\n", "mark 1 at [0.0, 3.0] lies within the 5 m radius of the start"),
    ("[course]\nmarks = [0, 60]\n", "marks must be a list of [across, up] pairs"),
    ("[course]\nmarks = [[0, 60]]\nlaps = 2\n", "unknown key 'laps'"),
    ("[course]\nmarks = [[0, 60]]\nline = -1\n", "line"),
    ("marks = [[0, 60]]\n", "the file holds one table, [course]"),
    ("[course\n", "does not parse as TOML"),
])
def test_a_bad_course_file_is_one_line(tmp_path, text, message):
    path = tmp_path / "course.toml"
    path.write_text(text)
    with pytest.raises(ValueError) as err:
        suite.load("viel_boat", "upwind_downwind", course=str(path))
    assert message in str(err.value) and "\n" not in str(err.value)


def test_videos_and_the_map_get_the_box_and_the_square_as_their_corners():
    from sailmujoco.video.recording import scene_of

    env = suite.load("viel_boat", "station_keeping", seed=0, wind_from_deg=90.0, side=40.0, distance=60.0)
    _, _, _, target = scene_of("viel_boat", env, {})
    # an easterly's box about (60, 0): corners downwind-port, downwind-starboard, up-starboard, up-port
    np.testing.assert_allclose(target["corners"], [(40.0, 20.0), (40.0, -20.0), (80.0, -20.0), (80.0, 20.0)],
                               atol=1e-12)


@pytest.mark.parametrize("option", ["leg", "laps", "course"])
def test_precision_navigation_refuses_the_races_own_options_in_one_line(option):
    message = rf"^unknown option '{option}' in suite.load \(accepted: .*distance, "
    with pytest.raises(ValueError, match=message):
        suite.load("viel_boat", "precision_navigation", **{option: 2})
