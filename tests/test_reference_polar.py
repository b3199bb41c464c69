"""A reference polar file: its units and heights converted by hand, bad files refused in one line,
the comparison's ratios, and the ``polar --reference`` command end to end."""

import math

import pandas as pd
import pytest

from sailmujoco.cli.main import main
from sailmujoco.design import reference_compare as rc
from sailmujoco.design import reference_polar as rp

# Wille (2016a) eq. 40: U(z) = U10 (5/2) sqrt(k) ln(z / z0), k = 0.0026, so that U(10) = U10
# gives ln(10 / z0) = 2 / (5 sqrt k) = 2 / (5 x 0.05099020) = 7.844645 and
# ln(5 / z0) = 7.844645 - ln 2 = 7.151498: a wind read at 5 m is 7.844645 / 7.151498 = 1.096924
# times slower than at 10 m.
LN_10_OVER_Z0 = 7.844645
FIVE_TO_TEN = 1.096924


def test_knots_and_the_orc_file_in_si():
    assert rp.KNOT == pytest.approx(0.514444, abs=1e-6)  # 1852 m / 3600 s
    polar = rp.read_reference_polar("orc:eleven_metre")
    table = polar.table
    beam = table[(table["tws_file"] == 10) & (table["twa"] == 90) & (table["point"] == "fixed")]
    assert float(beam["speed"].iloc[0]) == pytest.approx(7.35 * 0.514444, rel=1e-5)  # ORC: 7.35 kn
    assert float(beam["tws"].iloc[0]) == pytest.approx(10 * 0.514444, rel=1e-5)  # at 10 m: unchanged
    beat = polar.optimum("beat")
    at_10 = beat[beat["tws_file"] == 10].iloc[0]
    # ORC's beat at 10 kn: 39.0 deg, VMG 4.67 kn (boat speed 6.01 kn printed to 0.01 kn)
    assert at_10["twa"] == 39.0
    assert at_10["vmg"] / rp.KNOT == pytest.approx(4.67, abs=0.01)
    assert sorted(set(table["tws_file"])) == [4, 6, 8, 10, 12, 14, 16, 20, 24]  # ORC's winds
    assert "ORC" in polar.source and "11 Metre" in polar.source


def test_a_wind_read_at_another_height_is_taken_to_10_m_along_the_log_profile():
    assert math.log(10.0 / rp.roughness_length()) == pytest.approx(LN_10_OVER_Z0, abs=1e-6)
    assert float(rp.wind_at_reference(5.0, 5.0)) == pytest.approx(5.0 * FIVE_TO_TEN, rel=1e-6)
    assert float(rp.wind_at_reference(5.0, 10.0)) == 5.0
    with pytest.raises(ValueError, match="reference height must be above the roughness length"):
        rp.wind_at_reference(5.0, 0.001)


def test_a_file_in_metres_per_second_at_5_m(tmp_path):
    path = tmp_path / "mine.csv"
    path.write_text("# my boat's log\ntws_ms,twa_deg,boat_speed_ms\n5,90,2.5\n5,60,2.0\n")
    polar = rp.read_reference_polar(path, height=5.0)
    assert list(polar.table["point"]) == ["fixed", "fixed"]
    assert polar.table["tws"].to_numpy() == pytest.approx([5.0 * FIVE_TO_TEN] * 2, rel=1e-6)
    assert polar.table["speed"].tolist() == [2.5, 2.0]
    assert polar.table["vmg"].to_numpy() == pytest.approx([0.0, 1.0], abs=1e-12)  # 2 cos 60 = 1
    assert polar.source == "my boat's log"


@pytest.mark.parametrize("text, message", [
    ("twa_deg,boat_speed_kn\n90,5\n", "needs exactly one of the columns tws_kn or tws_ms"),
    ("tws_kn,tws_ms,twa_deg,boat_speed_kn\n6,3,90,5\n", "needs exactly one of the columns tws_kn or"),
    ("tws_kn,boat_speed_kn\n6,5\n", "no 'twa_deg' column"),
    ("tws_kn,twa_deg,boat_speed_kn\n6,ninety,5\n", "data row 1: twa_deg must be a number, got 'ninety'"),
    ("tws_kn,twa_deg,boat_speed_kn,point\n6,90,5,reach\n", "point must be one of fixed, beat, run"),
    ("tws_kn,twa_deg,boat_speed_kn\n6,90,5\n6,190,5\n", "data row 2: wind speed must be > 0, TWA in"),
    ("# nothing\n", "no rows under a header"),
])
def test_a_bad_file_is_refused_in_one_line(tmp_path, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]")) as err:
        rp.read_reference_polar(path)
    assert "\n" not in str(err.value) and "bad.csv" in str(err.value)


def test_a_missing_file_is_refused_in_one_line(tmp_path):
    with pytest.raises(ValueError, match="reference polar '.*nope.csv' does not exist"):
        rp.read_reference_polar(tmp_path / "nope.csv")


def test_the_comparison_ratios_and_the_beat_as_a_vmg_optimum(tmp_path):
    """The reference at 10 kn, ours beside it, the ratios by hand. Ours at 60 and 90 deg; the beat
    is ours' best v cos(TWA) over our upwind angles against the file's beat row's VMG."""
    path = tmp_path / "ref.csv"
    path.write_text("tws_kn,twa_deg,boat_speed_kn,point\n10,60,6,fixed\n10,90,8,fixed\n10,120,9,fixed\n"
                    "10,40,5,beat\n")
    reference = rp.read_reference_polar(path)
    tws = 10 * rp.KNOT
    assert rc.polar_axes(reference) == ([pytest.approx(tws)], [36.0, 39.0, 42.0, 45.0, 48.0, 60.0, 90.0])
    ours = pd.DataFrame({"tws": [tws] * 3, "twa": [45.0, 60.0, 90.0],
                         "speed": [5.0 * rp.KNOT, 5.4 * rp.KNOT, 9.2 * rp.KNOT]})
    table = rc.reference_table(ours, reference)
    assert list(table["point"]) == ["fixed", "fixed", "beat"]  # 120 deg: a spinnaker's, left out
    assert table["ratio"].to_numpy()[:2] == pytest.approx([0.9, 1.15])
    # ours' beat: 5 cos 45 = 3.5355 kn (> 5.4 cos 60 = 2.7) against 5 cos 40 = 3.8302 kn
    beat = table.iloc[2]
    assert (beat["twa"], beat["twa_reference"]) == (45.0, 40.0)
    assert beat["ratio"] == pytest.approx(5 * math.cos(math.radians(45)) / (5 * math.cos(math.radians(40))))
    text = rc.reference_markdown(table, "ref.csv")
    assert "| speed | 10 | 60 / 60 | 5.40 | 6.00 | 0.90 |" in text
    assert "1 of 3 points are more than 10% from the reference." in text  # 1.15 only


def test_polar_command_holds_a_boat_against_a_reference(tmp_path, capsys):
    path = tmp_path / "ref.csv"
    path.write_text("# a made-up reference\ntws_ms,twa_deg,boat_speed_ms\n4,90,1.0\n")
    code = main(["polar", "saoud_robot", "--controller", "saoud", "--reference", str(path), "--twa", "90",
                 "--duration", "25", "--scheduler", "serial", "--out", str(tmp_path / "out"),
                 "--no-progress"])
    assert code == 0
    out = tmp_path / "out"
    ours = pd.read_csv(out / "polar_saoud.csv")
    table = pd.read_csv(out / "reference.csv")
    assert list(ours["tws"]) == [4.0]  # the file's wind, at 10 m already
    assert table["ratio"].iloc[0] == pytest.approx(ours["speed"].iloc[0] / 1.0)
    assert (out / "reference.png").stat().st_size > 20_000
    assert "> a made-up reference" in (out / "reference.md").read_text()
    assert "against ref.csv" in capsys.readouterr().out


def test_polar_refuses_a_bad_reference_height(capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["polar", "saoud_robot", "--reference", "orc:eleven_metre", "--reference-height", "0"])
    assert exit_.value.code == 2
    assert "argument --reference-height: must be a number > 0 m, got '0'" in capsys.readouterr().err
