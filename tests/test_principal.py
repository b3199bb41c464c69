"""A boat from its principal dimensions: the 11:Metre has the class's numbers, floats on its
waterline, its GZ slope is the closed-form GM; another class goes the same route; bad files are
refused in one line; ``boat make`` writes what ``eleven_metre`` is."""

import math

import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.boat import principal
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.boat.hull import column_quadrature
from sailmujoco.boat.schema import read_boat
from sailmujoco.cli.main import main
from sailmujoco.forces import stability

# the 11:Metre One Design's class figures (Holland/Gyhlenius 1990), as the issue and ORC's file give them
CLASS = dict(loa=10.30, lwl=8.20, beam=2.50, draft=1.80, displacement=1600.0, ballast=725.0, i=9.81, j=3.10,
             p=11.00, e=4.00, main_area=22.83, jib_area=15.22, crew=350.0)
RHO = 1025.0


def test_the_eleven_metre_has_the_class_numbers():
    p = get_boat("eleven_metre")
    h = p.hull
    assert p.mass == CLASS["displacement"] and h.length == CLASS["lwl"]
    # the keel hangs from 0.9 of the canoe body's depth, as the model draws it (mjcf.py)
    assert 0.9 * h.canoe_draft + p.keel.span == pytest.approx(CLASS["draft"], rel=1e-12)
    assert 2.0 * h.deck_half_beam == CLASS["beam"]
    assert p.sail.area == CLASS["main_area"] and p.headsail.area == CLASS["jib_area"]
    assert p.sail.luff == pytest.approx(CLASS["p"], rel=1e-12)  # the main's luff is P
    assert p.sail.mast_x - p.headsail.tack_x == pytest.approx(-CLASS["j"], rel=1e-12)  # J between them
    # the canoe body displaces the class's displacement: V = (4 pi / 15) b0 t0 L
    assert 4.0 * math.pi / 15.0 * h.half_beam * h.canoe_draft * h.length * RHO == pytest.approx(1600.0)
    # the ballast's share in the CG: (725 z_b + 875 z_r) / 1600 with z_b below the canoe body
    assert p.cg_z < -h.canoe_draft


def test_it_floats_on_its_waterline_and_its_gz_slope_is_the_closed_form_gm():
    """Parabolic planform b(x) = b0 (1 - (2x/L)^2): I_T = (2/3) b0^3 L (16/35); half-elliptic sections
    with the same fullness: V = (4 pi / 15) b0 t0 L, z_B = -(8 / (7 pi)) t0. GM = z_B + I_T / V - z_G."""
    p = get_boat("eleven_metre")
    h = p.hull
    volume = 4.0 * math.pi / 15.0 * h.half_beam * h.canoe_draft * h.length
    i_t = 2.0 / 3.0 * h.half_beam**3 * h.length * 16.0 / 35.0
    gm = -8.0 / (7.0 * math.pi) * h.canoe_draft + i_t / volume - p.cg_z
    assert p.gm_t == pytest.approx(gm, rel=1e-9)
    columns = column_quadrature(p.hull, 48, 24).array()
    assert abs(stability.equilibrium_heave(p, 0.0, columns)) < 0.005  # m, on the design waterline
    small = math.radians(2.0)
    assert stability.righting_arm(p, small) / math.sin(small) == pytest.approx(gm, rel=0.02)
    assert stability.righting_arm(p, math.radians(30.0)) > 0.5 * gm * math.sin(math.radians(30.0))


def test_another_class_goes_the_same_route_and_sails(tmp_path):
    """A 7.3 m sportboat's published figures (a J/24's): nothing in the rules is the 11:Metre's."""
    d = principal.Dimensions(name="sportboat", loa=7.32, lwl=6.10, beam=2.71, draft=1.22, displacement=1406.0,
                             ballast=431.0, i=8.23, j=2.90, p=8.53, e=3.05, main_area=13.1, jib_area=12.7)
    p = principal.boat_from_dimensions(d, get_boat("wille_yacht"))
    assert p.gm_t > 0.5 and 0.9 * p.hull.canoe_draft + p.keel.span == pytest.approx(1.22)
    env = suite.load(p, "heading_hold", seed=0, wind_speed=5.0)
    env.reset()
    for _ in range(200):
        env.step(np.array([0.0, 0.5]))
    assert np.linalg.norm(env.physics.data.qvel[:2]) > 1.0  # m/s: it sails off


def test_boat_make_writes_the_eleven_metre(tmp_path, capsys):
    out = tmp_path / "made.toml"
    dims = tmp_path / "dims.toml"
    dims.write_text("[dimensions]\nname = \"eleven_metre\"\n"
                    + "".join(f"{k} = {v!r}\n" for k, v in CLASS.items()))
    assert main(["boat", "make", str(dims), "--out", str(out)]) == 0
    made = read_boat(out)
    assert made == get_boat("eleven_metre")
    text = out.read_text()
    assert "canoe_draft = " in text and "the displacement's volume" in text and "(guess)" in text


@pytest.mark.parametrize("text, message", [
    ("[dimensions]\nname = \"x\"\nloa = 10.0\n", "missing key(s) lwl, beam"),
    ("[dimensions]\nname = \"x\"\nloa = 10.0\nlength = 3\n", "unknown key(s) length"),
    ("[boat]\n", "has no [dimensions] table"),
])
def test_a_bad_dimensions_file_is_refused_in_one_line(tmp_path, text, message):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(ValueError) as err:
        principal.read_dimensions(path)
    assert message in str(err.value) and "\n" not in str(err.value)


def test_dimensions_that_make_no_boat_are_refused():
    base = dict(CLASS, name="x")
    with pytest.raises(ValueError, match="lwl .* must not exceed loa"):
        principal.Dimensions(**dict(base, lwl=11.0))
    with pytest.raises(ValueError, match="ballast .* must be less than the displacement"):
        principal.Dimensions(**dict(base, ballast=1700.0))
    with pytest.raises(ValueError, match="draft 0.1 m is not below the canoe body"):
        principal.boat_from_dimensions(principal.Dimensions(**dict(base, draft=0.1)), get_boat("wille_yacht"))
    with pytest.raises(ValueError, match="beam must be a positive finite number"):
        principal.Dimensions(**dict(base, beam=-2.5))


def test_the_main_alone_is_a_boat_option():
    assert get_boat("eleven_metre", headsail=False).headsail is None


def test_the_eleven_metres_switches_change_only_what_they_name():
    built = get_boat("eleven_metre")
    orc = get_boat("eleven_metre", areas="orc")  # ORC's certificates: main 29.43 (roach in), genoa 13.96
    assert (orc.sail.area, orc.headsail.area) == (29.43, 13.96)
    assert orc.sail.luff == pytest.approx(built.sail.luff, rel=1e-12)  # the same hoist, a longer mean foot
    loose = get_boat("eleven_metre", surge_damping=False)
    assert loose.linear_damping == (0.0, *built.linear_damping[1:])
    assert get_boat("eleven_metre", crew=False).crew is None and built.crew.mass == 350.0
    with pytest.raises(ValueError, match="^areas must be one of 'class', 'orc', got 'measured'$"):
        get_boat("eleven_metre", areas="measured")
