"""Boat files: every built-in boat exported, read back equal and sailing bit for bit; bad files
refused one line per key; ``boat check``'s numbers against closed forms of the hull."""

import dataclasses
import math
import tomllib

import numpy as np
import pytest
from conftest import BOATS

from sailmujoco import suite, sweep
from sailmujoco.boat import file as boat_file
from sailmujoco.boat import hull, mjcf
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.boat.fitted_file import FITTED
from sailmujoco.boat.schema import KEYS, OPTIONAL_KEYS, SECTION_TYPES
from sailmujoco.cli.main import main
from sailmujoco.constants import GRAVITY
from sailmujoco.design.check import check_boat

RHO = 1025.0  # kg/m^3, the built-in boats' sea water


def _export(name, tmp_path, file_name="boat.toml"):
    path = tmp_path / file_name
    boat_file.write_boat(name, path)
    return path


def _qpos(boat, steps=200):
    """qpos after each of ``steps`` control steps of heading_hold under a fixed, varying action."""
    env = suite.load(boat, "heading_hold", seed=0)
    env.reset()
    out = [env.physics.data.qpos.copy()]
    for k in range(steps):
        env.step(np.array([0.1 * math.sin(0.05 * k), 0.4]))
        out.append(env.physics.data.qpos.copy())
    return np.array(out)


def test_the_schema_covers_every_field_of_the_parameter_types():
    # the sections of their own
    nested = {"hull", "keel", "rudder", "sail", "headsail", "crew", "sources", "sensors", "actuators"}
    for section, kind in SECTION_TYPES.items():
        names = {f.name for f in dataclasses.fields(kind)} - (nested if section == "boat" else set())
        assert names == {k.name for k in {**KEYS, **OPTIONAL_KEYS}[section]}, section


@pytest.mark.parametrize("name", BOATS)
def test_exported_and_read_back_equals_the_built_in(name, tmp_path):
    path = _export(name, tmp_path)
    text = path.read_text()
    data = tomllib.loads(text)
    assert set(data) == {*KEYS, *FITTED, "sources"}
    assert data["sensors"]["perfect"] is True and data["actuators"]["perfect"] is True  # as built
    for line in text.splitlines():  # every key carries its unit
        if line and not line.startswith(("#", "[")):
            assert "  # [" in line or line.split(" = ")[0] in data["sources"], line
    params = get_boat(path)
    assert params == get_boat(name)
    assert params.sources["boat.mass"]  # a source for the mass, carried in its comment
    # written again from what was read: the same text
    assert boat_file.boat_toml(params) == text


@pytest.mark.parametrize("name", BOATS)
def test_an_exported_boat_sails_bit_for_bit_like_the_built_in(name, tmp_path):
    path = _export(name, tmp_path)
    assert np.array_equal(_qpos(name), _qpos(str(path)))


def test_a_renamed_boat_file_sails_bit_for_bit_too(tmp_path):
    text = boat_file.boat_toml(get_boat("viel_boat"), name="my_keelboat")
    path = tmp_path / "mine.toml"
    path.write_text(text)
    params = get_boat(path)
    assert params.name == "my_keelboat"
    assert "viel_boat.xml" in mjcf.scene_for(params) or "my_keelboat.xml" in mjcf.scene_for(params)
    assert np.array_equal(_qpos("viel_boat", 100), _qpos(path, 100))


def _edit(path, section, key, value):
    """Replace ``key = ...`` in ``[section]`` of a boat file by ``key = value``."""
    lines, current = path.read_text().splitlines(), None
    for i, line in enumerate(lines):
        if line.startswith("["):
            current = line[1:line.index("]")]
        elif current == section and line.startswith(f"{key} = "):
            lines[i] = f"{key} = {value}" if value is not None else ""
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("edit,expected", [
    (("keel", "area", "-1.0"), "[keel] area must be a positive number in m^2, got -1.0"),
    (("boat", "mass", "-300.0"), "[boat] mass must be a positive number in kg, got -300.0"),
    (("boat", "mass", '"heavy"'), "[boat] mass must be a positive number in kg, got 'heavy'"),
    (("boat", "inertia", "[1.0, 2.0]"), "[boat] inertia must be an array of 3 positive numbers"),
    (("boat", "added_mass", "[-1.0, -1.0, 5.0, -1.0, -1.0, -1.0]"), "added_mass must be an array"),
    (("rudder", "max_angle", "35.0"), "(degrees? 35 deg is 0.610865 rad)"),
    (("rudder", "mass", "0.0"), "[rudder] mass must be a positive number in kg, got 0.0"),
    (("boat", "paper_righting", '"cos"'), "paper_righting must be one of 'sin_cos', 'sin'"),
    (("boat", "name", '"my boat"'), "[boat] name must be an identifier"),
    (("hull", "length", None), "[hull] missing key 'length' (waterline length L, in m)"),
    (("hull", "deck_half_beam", "0.1"), "[hull] hull deck_half_beam must be >= half_beam"),
])
def test_a_bad_key_is_one_line_naming_the_file_section_and_key(tmp_path, edit, expected):
    path = _export("wille_yacht", tmp_path)
    _edit(path, *edit)
    with pytest.raises(ValueError) as err:
        get_boat(path)
    message = str(err.value)
    assert "\n" not in message and message.startswith(str(path)), message
    assert expected in message


def test_a_misspelled_key_is_one_line_with_the_nearest_name(tmp_path):
    path = _export("wille_yacht", tmp_path)
    path.write_text(path.read_text().replace("\nwetted_surface = ", "\nwetted_surfase = "))
    with pytest.raises(ValueError, match=r"^unknown key 'wetted_surfase' in .*boat.toml \[boat\]; "
                                         r"did you mean 'wetted_surface'\?") as err:
        get_boat(path)
    assert "\n" not in str(err.value)


def test_a_missing_section_is_one_line(tmp_path):
    path = _export("saoud_robot", tmp_path)
    text = path.read_text()
    path.write_text(text[:text.index("[rudder]")] + text[text.index("[sail]"):])
    with pytest.raises(ValueError, match=r"boat.toml: missing section \[rudder\] \(the rudder"):
        get_boat(path)


def test_each_problem_of_a_file_is_a_line_of_its_own(tmp_path):
    path = _export("saoud_robot", tmp_path)
    _edit(path, "boat", "mass", "-15.0")
    _edit(path, "sail", "area", "0.0")
    with pytest.raises(ValueError) as err:
        get_boat(path)
    lines = str(err.value).splitlines()
    assert len(lines) == 2 and "[boat] mass" in lines[0] and "[sail] area" in lines[1]


def test_a_boat_file_takes_no_options_and_a_missing_file_is_one_line(tmp_path):
    path = _export("saoud_robot", tmp_path)
    with pytest.raises(ValueError, match="takes no boat options, got l_phi"):
        get_boat(path, l_phi=0.5)
    with pytest.raises(ValueError, match="boat file .*nope.toml' does not exist"):
        suite.load(str(tmp_path / "nope.toml"), "heading_hold")


def test_optional_keys_take_the_dataclass_defaults(tmp_path):
    path = _export("wille_yacht", tmp_path)
    for key in ("rho_air", "nu_water", "paper_righting"):
        _edit(path, "boat", key, None)
    for key in ("suction_efficiency", "friction_coefficient"):
        _edit(path, "sail", key, None)
    assert get_boat(path) == get_boat("wille_yacht")  # its values are the defaults


@pytest.fixture(scope="module")
def checks(tmp_path_factory):
    """boat check of each built-in boat's exported file: a single 60 s speed run at TWA 90."""
    out = {}
    for name in BOATS:
        folder = tmp_path_factory.mktemp(name)
        path = _export(name, folder)
        out[name] = (get_boat(name), check_boat(path, wind=6.0, out=folder / "check",
                                                twa_deg=(45.0, 90.0), duration=60.0))
    return out


@pytest.mark.parametrize("name", BOATS)
def test_check_hydrostatics_against_the_closed_forms(checks, name):
    p, c = checks[name]
    h = p.hull
    volume = math.pi / 2 * h.half_beam * h.canoe_draft * h.length * 8 / 15  # half-ellipse hull
    assert c.mass == p.mass and c.volume == pytest.approx(p.mass / RHO, rel=1e-12)
    assert c.hull_volume == pytest.approx(volume, rel=1e-12)
    assert abs(c.sinkage) < 1e-9  # built to float on its design waterline
    assert abs(c.lcb) < 1e-9  # the planform is fore-aft symmetric
    z_b = -8 / (7 * math.pi) * h.canoe_draft
    gm_t = z_b + 32 / 105 * h.half_beam**3 * h.length / volume - p.cg_z
    gm_l = z_b + h.half_beam * h.length**3 / 15 / volume - p.cg_z
    assert c.gm_t == pytest.approx(gm_t, rel=1e-12) and c.gm_t == pytest.approx(p.gm_t, rel=1e-9)
    assert c.gm_l == pytest.approx(gm_l, rel=1e-12)
    # the draft is the MuJoCo model's lowest appendage: keel box or rudder blade bottom
    model = mjcf.compile_model(p)
    bottoms = []
    for geom, body in (("keel", "hull"), ("rudder_blade", "rudder")):
        g = model.geom(geom)
        bottoms.append(-(model.body(body).pos[2] + g.pos[2] - g.size[2]))
    assert c.draft == pytest.approx(max(bottoms), rel=1e-5)  # the MJCF keeps 6 digits


@pytest.mark.parametrize("name", BOATS)
def test_check_gz_slope_is_gm_and_the_periods_are_spring_mass(checks, name):
    p, c = checks[name]
    one_deg = int(np.argmin(abs(c.heel - math.radians(1.0))))
    assert abs(c.gz[0]) < 1e-12
    assert c.gz[one_deg] / math.sin(c.heel[one_deg]) == pytest.approx(p.gm_t, rel=2e-3)
    assert c.heel[-1] == pytest.approx(math.pi) and c.gz_max == c.gz.max()
    weight = RHO * GRAVITY * p.mass / RHO  # rho g V
    alone = 2 * math.pi * math.sqrt((p.inertia[0] - p.added_mass[3]) / (weight * p.gm_t))
    # free sway: eliminate the sway of CO from [[m + A22, -m z_G], [-m z_G, I_G + m z_G^2 + A44]]
    a22 = -p.added_mass[1]
    roll = 2 * math.pi * math.sqrt((p.inertia[0] - p.added_mass[3]
                                    + p.cg_z**2 * p.mass * a22 / (p.mass + a22)) / (weight * p.gm_t))
    heave = 2 * math.pi * math.sqrt((p.mass - p.added_mass[2])
                                    / (RHO * GRAVITY * 4 / 3 * p.hull.half_beam * p.hull.length))
    pitch = 2 * math.pi * math.sqrt((p.inertia[1] - p.added_mass[4]) / (weight * c.gm_l))
    assert c.roll_period == pytest.approx(roll, rel=1e-9)
    assert c.roll_period_uncoupled == pytest.approx(alone, rel=1e-9)
    assert c.heave_period == pytest.approx(heave, rel=1e-12)
    assert c.pitch_period == pytest.approx(pitch, rel=1e-12)
    # eq. 19's omega_roll_n, where the boat computes it from its mass and GM_t: roll alone
    if name != "wille_yacht":  # (the yacht's is the paper's 2.4 rad/s)
        assert 2 * math.pi / p.roll_frequency == pytest.approx(c.roll_period_uncoupled, rel=0.08)


def test_check_vanishing_stability_is_where_gz_changes_sign(checks):
    _, c = checks["wille_yacht"]  # flared deck, ballast 0.6 m below the waterline
    assert math.radians(120) < c.vanishing_heel < math.radians(170)
    before = c.gz[c.heel < c.vanishing_heel - 1e-9]
    after = c.gz[(c.heel > c.vanishing_heel + 1e-9) & (c.heel < math.radians(175))]
    assert before[1:].min() > 0 and after.max() < 0
    for name in ("saoud_robot", "viel_boat"):  # deep ballast, narrow deck: right from any heel
        assert checks[name][1].vanishing_heel == math.pi
        assert checks[name][1].gz[1:-1].min() > 0


def test_check_speeds_and_the_figure(checks):
    for name, (p, c) in checks.items():
        slow, fast = c.speed
        assert 0.3 < slow < fast < 6.0, name  # beam reach faster than close-hauled, below the wind
        assert c.figure.name == "gz.png" and c.figure.stat().st_size > 10_000
        text = c.text()
        assert f"displacement  {p.mass:.6g} kg" in text and "TWA    90 deg" in text
        assert f"roll {c.roll_period:.2f} s, the free boat's" in text
        assert f"roll {c.roll_period_uncoupled:.2f} s if it rolled alone" in text


def test_a_heavier_boat_floats_deeper_by_its_extra_volume_over_the_waterplane(tmp_path):
    path = _export("viel_boat", tmp_path)
    _edit(path, "boat", "mass", "306.0")  # +2 %
    p = get_boat(path)
    c = check_boat(p, twa_deg=(90.0,), duration=20.0)
    expected = 6.0 / RHO / hull.waterplane_area(p.hull)  # wall-sided, first order
    assert c.sinkage == pytest.approx(expected, rel=0.05)
    assert "below its design waterline" in c.text()


def test_boat_export_and_check_on_the_command_line(tmp_path, capsys):
    assert main(["boat", "export", "saoud_robot"]) == 0
    assert tomllib.loads(capsys.readouterr().out)["boat"]["mass"] == 15.0
    path = tmp_path / "sub" / "robot.toml"
    assert main(["boat", "export", "saoud_robot", "--out", str(path)]) == 0
    bad = tmp_path / "bad.toml"
    bad.write_text(path.read_text().replace("\nmass = 15.0", "\nmass = -15.0"))
    capsys.readouterr()
    assert main(["boat", "check", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "[boat] mass must be a positive number in kg, got -15.0" in err


def test_a_sweep_file_takes_a_boat_file_relative_to_itself(tmp_path, monkeypatch):
    folder = tmp_path / "study"
    folder.mkdir()
    _export("saoud_robot", folder, "my_boat.toml")
    body = ('task = "heading_hold"\ncontroller = "pid"\nduration = 2.0\n'
            'metrics = ["mean_surge"]\n')
    (folder / "mine.toml").write_text(f'boat = "my_boat.toml"\n{body}')
    (folder / "theirs.toml").write_text(f'boat = "saoud_robot"\n{body}')
    monkeypatch.chdir(tmp_path)  # elsewhere: the boat is found beside the sweep file
    spec = sweep.load_spec(folder / "mine.toml")
    assert spec["boat"] == str((folder / "my_boat.toml").resolve())
    mine = sweep.run(folder / "mine.toml", tmp_path / "a", scheduler="serial", progress=False)
    theirs = sweep.run(folder / "theirs.toml", tmp_path / "b", scheduler="serial", progress=False)
    assert list(mine["status"]) == ["ok"]
    assert mine["mean_surge"].iloc[0] == theirs["mean_surge"].iloc[0]  # bit for bit
    (folder / "opts.toml").write_text(f'boat = "my_boat.toml"\n{body}[options]\n"boat.l_phi" = 0.5\n')
    with pytest.raises(sweep.SweepError, match=r"unknown boat option 'l_phi' .*\(accepted: none\)"):
        sweep.load_spec(folder / "opts.toml")  # a boat file takes no boat options: edit the file
    (folder / "lost.toml").write_text(f'boat = "gone.toml"\n{body}')
    with pytest.raises(sweep.SweepError, match=r"^boat file '.*study/gone.toml' does not exist$"):
        sweep.load_spec(folder / "lost.toml")
    (folder / "self.toml").write_text(f'boat = "self.toml"\n{body}')
    with pytest.raises(sweep.SweepError, match=r"self.toml is not a boat file: it has none of"):
        sweep.load_spec(folder / "self.toml")
