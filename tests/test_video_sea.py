"""The moving sea of the videos: a height field that follows the waves' elevation around the boat."""

import math
import os

os.environ.setdefault("MUJOCO_GL", "egl")

import numpy as np
import pytest

from sailmujoco.forces.waves import WaveConfig
from sailmujoco.params import get_boat
from sailmujoco.video import SceneRenderer, Snapshot

GRAVITY = 9.81
FORCES = {name: np.array([200.0, 80.0, 0.0]) for name in ("sail", "keel", "rudder")}


def snap(time, position=(3.0, -2.0, 0.0)):
    return Snapshot(time=time, position=np.array(position, float), rotation=np.eye(3), rudder=0.05,
                    sail=0.4, speed=2.0, heel=0.0, awa=1.4, aws=5.0, wind=np.array([0.0, -5.0, 0.0]),
                    forces=FORCES)


@pytest.fixture(scope="module")
def boat():
    return get_boat("wille_yacht")


def renderer(boat, waves, **kw):
    try:
        return SceneRenderer(boat, 96, 64, overlay=False, forces=False, waves=waves, **kw)
    except Exception as err:  # no GL platform here
        pytest.skip(f"no offscreen rendering: {err}")


def test_heights_are_the_regular_wave_at_the_grid_points(boat):
    """A regular wave from the west (travelling east): eta = H/2 cos(k x - omega t), k = omega^2/g,
    after the ramp (3 T). MuJoCo stores h in [0, 1] and draws z = z_geom + size[2] h: the decoded
    heights match within 1e-6 of the range, and a ray from above meets the drawn surface there."""
    import mujoco

    H, T = 1.2, 5.0
    waves = WaveConfig(spectrum="regular", hs=H, tp=T, direction_from=1.5 * math.pi)  # from the west
    with renderer(boat, waves) as r:
        t = 4.0 * T + 1.3
        r.pose(snap(t, position=(41.0, -13.0, 0.0)))
        sea = r.sea
        assert r.model.geom_contype[sea.geom_id] == 0 and r.model.geom_conaffinity[sea.geom_id] == 0
        omega = 2.0 * math.pi / T
        k = omega**2 / GRAVITY
        x, y = sea.grid()
        expected = 0.5 * H * np.cos(k * x - omega * t)
        inside = sea.window == 1.0  # the faded outer tile excepted
        assert inside.sum() > 0.25 * inside.size
        range_ = r.model.hfield_size[sea.hfield_id][2]
        assert range_ == pytest.approx(H)  # 2 A, A = H/2
        error = np.abs(sea.heights() - expected)[inside].max()
        assert error < 1e-6 * range_
        # the boat is inside the exact region, a hull length or more from its edge
        half = sea.layout.half - sea.layout.tile
        assert abs(41.0 - sea.centre[0]) < half - boat.hull.length
        assert abs(-13.0 - sea.centre[1]) < half - boat.hull.length
        # where MuJoCo draws it: rays straight down onto a few grid points
        mujoco.mj_kinematics(r.model, r.data)
        rows, cols = np.nonzero(inside)
        for i in np.linspace(0, rows.size - 1, 7).astype(int):
            px, py = x[rows[i], cols[i]], y[rows[i], cols[i]]
            geomid = np.array([-1], np.int32)
            dist = mujoco.mj_ray(r.model, r.data, np.array([px, py, 10.0]), np.array([0.0, 0.0, -1.0]),
                                 None, 1, -1, geomid)
            assert geomid[0] == sea.geom_id
            assert 10.0 - dist == pytest.approx(expected[rows[i], cols[i]], abs=1e-4)


def test_quarter_period_apart_the_water_moves(boat):
    T = 6.0
    waves = WaveConfig(spectrum="regular", hs=1.5, tp=T, direction_from=0.5 * math.pi)
    camera = (np.array([3.0, -2.0, 0.5]), 25.0, 60.0, -25.0)
    with renderer(boat, waves) as r:
        a = r.render(snap(20.0), camera=camera).astype(float)
        b = r.render(snap(20.0 + 0.25 * T), camera=camera).astype(float)
        c = r.render(snap(20.0 + T), camera=camera).astype(float)
    water = slice(a.shape[0] // 2, None)  # the lower half: water only
    assert np.abs(a[water] - b[water]).mean() > 2.0  # grey levels
    assert np.abs(a[water] - c[water]).mean() < 0.25 * np.abs(a[water] - b[water]).mean()


def test_without_a_sea_the_flat_surface_is_drawn(boat):
    """waves=None, calm water and no keyword draw the same frame: the flat plane, no height field."""
    frames = []
    for kw in ({}, {"waves": None}, {"waves": WaveConfig(hs=0.0)}):
        with renderer(boat, kw.get("waves")) if kw else SceneRenderer(
                boat, 96, 64, overlay=False, forces=False) as r:
            assert r.sea is None and r.model.nhfield == 0
            assert r.model.geom("sea_surface").id >= 0
            frames.append(r.render(snap(20.0)))
    assert np.array_equal(frames[0], frames[1]) and np.array_equal(frames[0], frames[2])
