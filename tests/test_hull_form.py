"""The geometric hulls against the papers' hydrostatics, by a midpoint grid over the hull solid
(conftest.hull_solid_below_water), independent of hull.py's closed forms and of the column
quadrature the physics integrates.

Paper values: displacement m / rho and GM_t (Wille 2016a Appendix A: 1600 kg, GM_t = 2.4 m;
Saoud 2015 Table I: 15 kg, GM_t = l_phi = 1 m), LCB = LCG (a boat at rest floats level). Eq. 20
(Wille 2016a) gives the righting moment rho g V GM_t sin(phi) cos(phi).
"""

import math

import numpy as np
import pytest
from conftest import BOATS, hull_solid_below_water

from sailmujoco import frames
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.constants import GRAVITY
from sailmujoco.forces import stability

# m: Wille Appendix A; Saoud l_phi = 1 m; viel_boat's design GM (Viel's planar model has none:
# xml/viel_boat/README.md)
PAPER_GM = {"wille_yacht": 2.4, "saoud_robot": 1.0, "viel_boat": 1.05}
# kg: Wille Appendix A; Saoud Table I; Viel Table 1 p9
PAPER_MASS = {"wille_yacht": 1600.0, "saoud_robot": 15.0, "viel_boat": 300.0}


def _waterplane_inertia(h, n=(2000, 2000)):
    """Transverse second moment of the upright waterplane, int y^2 dA, by a midpoint grid over
    the planform |y| < b0 (1 - (2x/L)^2)."""
    nx, ny = n
    x = (np.arange(nx) + 0.5) / nx * h.length - h.length / 2
    y = (np.arange(ny) + 0.5) / ny * 2 * h.half_beam - h.half_beam
    inside = np.abs(y)[None, :] < h.half_beam * (1 - (2 * x[:, None] / h.length) ** 2)
    cell = (h.length / nx) * (2 * h.half_beam / ny)
    return float(np.sum(inside * y[None, :] ** 2) * cell)


@pytest.mark.parametrize("boat", BOATS)
def test_displacement_lcb_and_gm_match_the_paper(boat):
    """Upright at the design waterline: V = m / rho, LCB = LCG, GM_t = z_B + BM - z_G = the
    paper's, each within 2 %, from the grid over the solid and the grid over the waterplane."""
    p = get_boat(boat)
    volume, moment = hull_solid_below_water(p, 0.0, 0.0, 0.0)
    paper_volume = PAPER_MASS[boat] / 1025.0  # rho_water of both papers, kg/m^3
    assert volume == pytest.approx(paper_volume, rel=0.02)
    assert abs(moment[0] / volume - p.cg_x) < 1e-3 * p.hull.length
    z_b = moment[2] / volume
    bm = _waterplane_inertia(p.hull) / volume
    assert z_b + bm - p.cg_z == pytest.approx(PAPER_GM[boat], rel=0.02)


def test_yacht_is_in_the_delft_series_ranges_with_a_ballast_keel():
    """L_WL/B_WL 2.7-5.0, B_WL/T_c 2.5-19, C_p 0.52-0.60 (the ranges of the Delft Systematic
    Yacht Hull Series, Keuning & Sonnenberg), the CG below the waterline and the maximum beam
    at the deck, from the grid over the solid."""
    p = get_boat("wille_yacht")
    h = p.hull
    volume, _ = hull_solid_below_water(p, 0.0, 0.0, 0.0)
    # midship section area below the waterline, midpoint rule across the half-ellipse
    y = (np.arange(4000) + 0.5) / 4000 * 2 * h.half_beam - h.half_beam
    section = float(np.sum(h.canoe_draft * np.sqrt(1 - (y / h.half_beam) ** 2))) * (
        2 * h.half_beam / 4000)
    prismatic = volume / (section * h.length)
    assert 2.7 <= h.length / (2 * h.half_beam) <= 5.0
    assert 2.5 <= 2 * h.half_beam / h.canoe_draft <= 19.0
    assert 0.52 <= prismatic <= 0.60
    assert p.cg_z < -0.3  # ballast keel: the CG well below the waterline
    assert h.flare > 1.0


def _grid_righting(p, heel, heave, trim):
    """(volume, righting moment about the CG, N m) of the grid solid at a pose."""
    volume, moment = hull_solid_below_water(p, heave, trim, heel, n=(300, 240, 160))
    rot = frames.matrix_from_euler(heel, trim, 0.0)
    lever = rot @ (moment / volume - np.array([p.cg_x, 0.0, p.cg_z]))
    return volume, -p.rho_water * GRAVITY * volume * lever[1]


@pytest.mark.parametrize("heel_deg", [20.0, 30.0])
def test_yacht_keeps_its_righting_moment_to_large_heel(heel_deg):
    """At the heave and trim that float it (stability.floating_pose), the yacht's righting
    moment about its CG is at least 0.8 of eq. 20's, both as the physics integrates it and by
    the independent grid (which also checks that the pose displaces the weight)."""
    p = get_boat("wille_yacht")
    heel = math.radians(heel_deg)
    eq20 = p.rho_water * GRAVITY * p.displaced_volume * PAPER_GM["wille_yacht"] * math.sin(
        heel) * math.cos(heel)
    columns = stability._columns(p, 24, 16)
    heave, trim = stability.floating_pose(p, heel, columns)
    volume, righting = _grid_righting(p, heel, heave, trim)
    assert volume == pytest.approx(p.displaced_volume, rel=0.01)
    assert righting >= 0.8 * eq20
    table = stability.floating_table(p, max_heel=math.radians(35.0))
    assert np.interp(heel, table.heel, table.righting) >= 0.8 * eq20
    assert np.interp(heel, table.heel, table.righting) == pytest.approx(righting, rel=0.02)


def test_gz_curves_and_figure(tmp_path):
    """Eq. 66 (read as the tangent of eq. 20 at phi_w) touches eq. 20 at phi_w with its slope;
    the figure script writes a PNG where it is told to (never into the tree)."""
    p = get_boat("wille_yacht")
    w = math.radians(10.0)
    heels = np.array([w - 1e-4, w, w + 1e-4])
    c = stability.gz_curves(p, heels, (w,))
    assert c["eq66_10"][1] == pytest.approx(c["eq20"][1], rel=1e-12)
    assert np.diff(c["eq66_10"]) == pytest.approx(np.diff(c["eq20"]), rel=1e-4)
    assert c["geometric"][1] == pytest.approx(
        stability.righting_moment(p, w) / (p.rho_water * GRAVITY * p.displaced_volume), rel=0.01)
    path = tmp_path / "gz.png"
    stability.gz_figure(path, "saoud_robot")
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
