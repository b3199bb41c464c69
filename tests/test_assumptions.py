"""The assumption study: each metric on a case with a known answer, then the study in smoke mode."""

import math

import numpy as np
import pandas as pd
import pytest
from conftest import CALM, load
from test_reports import layout_problems

from sailmujoco.tasks.sailing import diagnostic_summary


def accessor_diagnostic_record(physics) -> dict:
    """The diagnostic record built from the named accessors (the reference)."""
    c_n, c_t = physics.sail_coefficients()
    terms = physics.force_terms()
    p = physics.params
    rates = physics.angular_velocity()
    ixx, iyy, izz = p.inertia
    heel = physics.heel()
    weight_body = physics.rotation().T @ np.array([0.0, 0.0, -p.mass * 9.81])
    gravity_mx = -p.cg_z * weight_body[1]
    restoring = terms["hydrostatics"][3] + gravity_mx
    terms = dict(terms, hydrostatics=np.array([0, 0, 0, restoring, 0, 0]))
    return {
        "ct_cn": abs(c_t) / abs(c_n) if abs(c_n) > 0.05 else float("nan"),
        "pitch": physics.pitch(), "heave": float(physics.position()[2]),
        "drift": physics.drift_angle(), "keel_aoa": physics.angle_of_attack("keel"),
        **{f"mx_{name}": float(terms[name][3]) for name in
           ("sail", "keel", "rudder", "hydrostatics", "damping", "added_mass")},
        "omega3_term": (izz - iyy) * rates[2] ** 2 * math.tan(heel),
        "restoring": float(restoring),
    }


@pytest.mark.parametrize("boat,dofs,hydrostatics", [("wille_yacht", 6, "geometric"),
                                                    ("saoud_robot", 6, "paper"),
                                                    ("wille_yacht", 4, "geometric"),
                                                    ("saoud_robot", 4, "paper")])
def test_diagnostic_record_equals_the_accessors_bit_for_bit(boat, dofs, hydrostatics):
    """The lean record (one rotation, the kernel's arrays) against the accessor-built one, on a
    heeled, turning, gusty run; each value the same float (NaN where the reference has NaN)."""
    from sailmujoco.forces.wind import WindConfig
    from sailmujoco.physics import BoatPhysics, ForceSwitches

    wind = WindConfig(speed=10.0, direction_from=math.radians(70.0), seed=4, current_east=0.3)
    physics = BoatPhysics.load(boat, wind=wind, dofs=dofs,
                               forces=ForceSwitches(hydrostatics=hydrostatics))
    physics.place((1.0, 2.0), 0.5, 1.5)
    low, high = physics.model.actuator_ctrlrange.T
    rng = np.random.default_rng(5)
    heels = []
    for _ in range(60):
        physics.set_control(rng.uniform(low, high))
        physics.step(int(rng.integers(1, 25)))
        new = physics.diagnostic_record()
        physics._fresh = False  # the reference refreshes the state again
        ref = accessor_diagnostic_record(physics)
        assert list(new) == list(ref)
        for key in ref:
            assert type(new[key]) is type(ref[key]), key
            assert new[key] == ref[key] or (new[key] != new[key] and ref[key] != ref[key]), key
        heels.append(abs(physics.heel()))
    assert max(heels) > math.radians(3.0)


def _rows(physics, steps=200):
    rows = []
    for _ in range(steps):
        physics.step(5)
        rows.append(physics.diagnostic_record())
    return rows


def test_ct_off_gives_a_force_exactly_normal_to_the_sail():
    from sailmujoco.forces.wind import WindConfig

    wind = WindConfig(speed=5.0, direction_from=math.radians(90.0), gusts=False, wander=False)
    on = load("saoud_robot", wind=wind, hydrostatics="paper")
    off = load("saoud_robot", wind=wind, hydrostatics="paper", sail_tangential=False)
    for physics in (on, off):
        physics.set_control([0.0, math.radians(40.0)])
    assert diagnostic_summary(_rows(off, 50))["ct_cn_ratio"] == 0.0
    assert diagnostic_summary(_rows(on, 50))["ct_cn_ratio"] > 0.0


def test_omega3_term_vanishes_at_zero_heel():
    physics = load("wille_yacht", hydrostatics="geometric", sail=False)
    physics.place((0, 0), 0.0, 2.0)
    physics.data.qvel[5] = 0.3  # turning hard, upright
    row = physics.diagnostic_record()
    assert row["omega3_term"] == 0.0


def test_zero_drift_when_nothing_pushes_sideways():
    """Motoring straight in calm water: drift angle and keel angle of attack are zero."""
    physics = load("wille_yacht", wind=CALM, hydrostatics="geometric", sail=False)
    physics.place((0, 0), 0.3, 2.0)
    physics.set_external_wrench([300.0, 0, 0, 0, 0, 0])
    summary = diagnostic_summary(_rows(physics, 100))
    assert abs(summary["drift_angle"]) < 1e-9 and summary["keel_aoa"] < 1e-9


def test_heave_and_pitch_held_have_no_amplitude():
    from sailmujoco.forces.wind import WindConfig

    wind = WindConfig(speed=8.0, direction_from=math.radians(60.0), seed=1)
    physics = load("wille_yacht", wind=wind, hydrostatics="paper")
    held = load("wille_yacht", wind=wind, hydrostatics="paper")
    held = type(held).load("wille_yacht", wind=wind, forces=held.switches, dofs=4)
    for p in (physics, held):
        p.set_control([0.0, -0.5])
    free, fixed = diagnostic_summary(_rows(physics)), diagnostic_summary(_rows(held))
    assert fixed["pitch_amplitude"] < 1e-12 and fixed["heave_amplitude"] < 1e-12
    assert free["pitch_amplitude"] > 0.0 and free["heave_amplitude"] > 0.0


def test_roll_shares_sum_to_one_and_restoring_balances_a_heeled_hull():
    """A hull heeled and released in calm water: only the restoring moment acts at first."""
    from sailmujoco import frames

    physics = load("saoud_robot", wind=CALM, hydrostatics="geometric", sail=False, keel=False,
                   rudder=False, damping=False)
    with physics.reset_context():
        physics.data.qpos[3:7] = frames.quat_from_euler(math.radians(5.0), 0.0, 0.0)
    summary = diagnostic_summary([physics.diagnostic_record()])
    shares = [v for k, v in summary.items() if k.startswith("roll_share_")]
    assert sum(shares) == pytest.approx(1.0)
    assert summary["roll_share_hydrostatics"] == pytest.approx(1.0)
    # the restoring moment about CO is buoyancy plus the weight acting at the (deep) CG:
    # weight's roll moment = m g z_G sin(phi), which here does most of the righting
    p = physics.params
    restoring = physics.diagnostic_record()["restoring"]
    buoyancy = physics.force_term("hydrostatics")[3]
    weight = p.mass * 9.81 * p.cg_z * math.sin(math.radians(5.0))
    assert restoring - buoyancy == pytest.approx(weight, rel=1e-9)
    assert restoring < 0.0 and abs(weight) > abs(buoyancy)


def test_study_smoke(tmp_path):
    from sailmujoco.studies import assumptions

    from sailmujoco import study, sweep

    with sweep.Engine() as engine:
        headline = study.run_study(assumptions.STUDY, tmp_path, engine, smoke=True, progress=False)
    assert headline["rows"] == 16
    for config in ("paper_hydrostatics", "friction_only", "paper_foils", "no_downwash", "no_windage"):
        assert np.isfinite(headline[f"{config}_speed_effect_max"]), config
    # every row's verdict is one of the three words, decided on intervals over the smoke's 2 seeds
    verdicts = [v for k, v in headline.items() if k.startswith("verdict_")]
    assert len(verdicts) == 16 and all(v in ("holds", "breaks", "undecided at 2 seeds") for v in verdicts)
    # the wind plane keeps every seed's row, and each switch is compared on both seeds at every point
    plane_rows = pd.read_csv(tmp_path / "wind_plane.csv")
    assert (plane_rows.groupby(["boat", "config", "tws", "twa"])["seed"].apply(tuple) == (0, 1)).all()
    points = pd.read_csv(tmp_path / "effect_points.csv")
    assert (points["n"] == 2).all() and (points["speed_rel_low"] <= points["speed_rel_high"]).all()
    # Viel's 3-DOF model balances the sail by the keel with no leeway (Viel eq. 5): its mean
    # lateral speed is ~0, while the 6-DOF robot drifts (the 6-DOF minus 3-DOF interval above 0)
    assert headline["verdict_lateral"] == "breaks" and headline["lateral_speed_6dof"] > 0.05
    for sim in ("sim1", "sim2", "sim3"):
        for resistance in ("dsyhs", "friction"):
            assert headline[f"table1_{sim}_{resistance}_surge"] > 1.0, (sim, resistance)
    for key in ("ct_cn_max", "pitch_amplitude_max_deg", "omega3_ratio_max", "keel_roll_share_max",
                "phi_star_error_max_deg", "lateral_speed_6dof"):
        assert np.isfinite(headline[key]), key
    # C_T is small against C_N but not zero; the omega3 term is small; pitch is small
    assert 0.0 < headline["ct_cn_max"] < 0.1
    assert headline["omega3_ratio_max"] < 0.1
    assert headline["pitch_amplitude_max_deg"] < 5.0
    # switching C_T off changes the speed a little (not nothing, not much)
    assert 0.0 < headline["ct_speed_effect_max"] < 0.2
    # Wille's sin cos restoring differs from the geometric yacht over the heel reached, by less
    # than 25 %: the yacht keeps >= 0.8 of eq. 20 to 30 deg (test_hull_form), and
    # |eq20 - geo| / geo <= 1 / 0.8 - 1 there
    assert 0.0 < headline["wille_yacht_restoring_error"] < 0.25
    report = (tmp_path / "report.md").read_text()
    assert layout_problems(report) == []  # title, summary, main table
    assert report.count("\n| ") >= 10 and (tmp_path / "wind_plane.png").stat().st_size > 30_000
    # the sea: its sections, each with a table, its CSVs, its figures
    from sailmujoco.studies.assumptions.sea_cases import SAILING, TABLE1

    sections = ["The sea against calm water: the wind plane", "Wille's roll controller in a sea (Table 1)",
                "Saoud's optimal sail in a sea", "Why a sea rolls the boats",
                "Where each difference comes from"]
    at = [report.index(f"\n## {s}\n") for s in sections]
    assert at == sorted(at) and at[0] > report.index("\n## Wille's eq. 4 as printed\n")
    for start, end in zip(at, [*at[1:], len(report)], strict=True):
        assert "\n| " in report[start:end]
    for name in ("sea_wind_plane.png", "sea_heights.png"):
        assert (tmp_path / name).stat().st_size > 20_000
    # every run in a sea kept: one row per case and seed (smoke: 2 seeds, the seas differ)
    plane = pd.read_csv(tmp_path / "sea_wind_plane.csv")
    assert sorted(plane["boat"]) == ["saoud_robot"] * 2 + ["wille_yacht"] * 2  # one point each, 2 seeds
    table1, saoud = pd.read_csv(tmp_path / "sea_table1.csv"), pd.read_csv(tmp_path / "sea_saoud.csv")
    for table in (plane, table1, saoud):
        assert len(table) in (2, 4) and sorted(table["seed"]) == sorted([0, 1] * (len(table) // 2))
    for table, metrics in ((plane, SAILING), (table1, TABLE1), (saoud, SAILING)):
        for metric in metrics:
            assert np.isfinite(table[f"{metric}_calm"]).all() and np.isfinite(table[f"{metric}_sea"]).all()
    # the calm runs of the wind plane are deterministic (steady wind, exact start): the same on
    # both seeds, while the two seas give two different runs
    for _, group in plane.groupby("boat"):
        assert group["speed_calm"].nunique() == 1 and group["roll_sd_sea"].nunique() == 2
    # Table 1's calm run on seed 0 is the study's own Table 1 run (seed 0), to the bit; on seed 1
    # its gusts differ
    assert table1.loc[table1["seed"] == 0, "surge_calm"].iloc[0] == headline["table1_sim3_dsyhs_surge"]
    assert table1["surge_calm"].nunique() == 2
    # each case's numbers are means over its seeds: Table 1's roll in the sea has an interval
    # that holds its two seeds' mean
    cases = pd.read_csv(tmp_path / "sea_cases.csv")
    t1 = cases[cases["series"] == "table1"].iloc[0]
    if t1["n_kept"] == 2:
        assert t1["roll_sd_sea_low"] < t1["roll_sd_sea"] < t1["roll_sd_sea_high"]
        assert t1["roll_sd_sea"] == pytest.approx(table1["roll_sd_sea"].mean(), rel=1e-12)
    assert set(cases["roll_sd_verdict"]) <= {"holds", "breaks", "undecided at 2 seeds", "undecided at 1 seed",
                                             "lost its heading"}
    # the runs that lost their heading: a share of cases x seeds with Wilson's interval about it
    low, rate, high = (headline[f"sea_lost_heading_rate{end}"] for end in ("_low", "", "_high"))
    assert 0.0 <= low <= rate <= high <= 1.0 and high > low
    # a sea of 0.2-0.7 m rolls both boats more than calm water
    assert (plane["roll_sd_sea"] > plane["roll_sd_calm"]).all()
    # every run's heading error is measured, and a case is lost where one exceeds the threshold
    for table in (plane, table1, saoud):
        rms = table[["heading_rms_calm", "heading_rms_sea"]].to_numpy()
        assert np.isfinite(rms).all() and (rms >= 0.0).all()
        assert (table["lost_heading"].notna() == (rms > 10.0).any(axis=1)).all()  # "" reads as NaN
    # smoke: the one largest difference is rerun with each mechanism off
    mechanisms = pd.read_csv(tmp_path / "sea_mechanisms.csv")
    assert len(mechanisms) == 1 and abs(mechanisms["rel"].iloc[0]) > 0.1
    assert headline["sea_mechanism_rows"] == 1
    # sensors and actuators as fitted: every scenario in each arm on both seeds, the perfect arm
    # being the same runs as the loop without instruments; each change beyond 10 % rerun with
    # each of its arm's switches on both seeds; the section, its table and its figure
    from sailmujoco.studies.assumptions.fitted import ARMS, SCENARIOS, SWITCHES, relative

    fitted = pd.read_csv(tmp_path / "fitted_runs.csv", keep_default_na=False)
    arms = fitted[fitted["switch"] == ""]
    assert len(arms) == len(SCENARIOS) * len(ARMS) * 2 and np.isfinite(arms["value"].astype(float)).all()
    changes = pd.read_csv(tmp_path / "fitted_changes.csv", keep_default_na=False)
    for row in changes[changes["switch"] == ""].itertuples():
        values = arms[(arms["scenario"] == row.scenario)].pivot(index="seed", columns="arm", values="value")
        floor = SCENARIOS[row.scenario]["floor"]
        per_seed = [relative(values.loc[s, row.arm], values.loc[s, "perfect"], floor) for s in (0, 1)]
        assert row.change == pytest.approx(np.mean(per_seed), rel=1e-9, abs=1e-12)
        reruns = fitted[(fitted["scenario"] == row.scenario) & (fitted["arm"] == row.arm)
                        & (fitted["switch"] != "")]
        assert len(reruns) == (2 * len(SWITCHES[row.arm]) if abs(row.change) > 0.1 else 0)
    section = report[report.index("\n## Sensors and actuators as fitted\n"):]
    assert section.count("\n| ") == 1 + len(SCENARIOS) * 2 and "fitted_changes.png" in section
    assert (tmp_path / "fitted_changes.png").stat().st_size > 20_000


def test_wind_plane_seas_are_the_fetch_limited_seas_of_each_points_wind():
    """Every point of the wind plane in a sea: Hs and Tp of the JONSWAP growth laws for the
    boat's fetch (Shore Protection Manual 1984 eqs. 3-33, 3-34: chi = g F/U^2,
    g Hs/U^2 = 1.6e-3 chi^(1/2), g Tp/U = 0.2857 chi^(1/3)), each capped at the fully developed
    Pierson-Moskowitz sea (Hs = 0.21 U19.5^2/g, Tp = 2 pi U19.5/(0.877 g), U19.5 = 1.026 U10),
    the waves from the wind's bearing; computed here from the formulas."""
    from sailmujoco.studies.assumptions import sea

    g = 9.81
    specs = sea.plane_sea_specs(smoke=False)
    for boat, fetch in sea.FETCH.items():
        z = specs[(boat, "sea")]["zip"]
        assert len(z["waves.hs"]) == 30  # the whole wind plane, 5 speeds x 6 angles
        points = zip(z["task.wind_speed"], z["task.wind_from_deg"], z["waves.hs"], z["waves.tp"],
                     z["waves.direction_from_deg"], strict=True)
        for u, wind_from, hs, tp, wave_from in points:
            chi = g * fetch / u**2
            u195 = 1.026 * u
            assert hs == pytest.approx(min(1.6e-3 * chi**0.5 * u**2 / g, 0.21 * u195**2 / g), rel=1e-12)
            assert tp == pytest.approx(min(0.2857 * chi ** (1 / 3) * u / g, 2 * math.pi * u195 / (0.877 * g)),
                                       rel=1e-12)
            assert wave_from == wind_from
        assert specs[(boat, "sea")]["options"]["waves.spectrum"] == "jonswap"
        calm = specs[(boat, "calm")]
        assert not any(key.startswith("waves.") for key in {**calm["options"], **calm["zip"]})
    # the lake's 2 km fetch limits the robot's sea: at 14 m/s far below full development (4.4 m)
    robot = specs[("saoud_robot", "sea")]["zip"]
    assert max(robot["waves.hs"]) == pytest.approx(1.6e-3 * (g * 2000.0 / 14.0**2) ** 0.5 * 14.0**2 / g)
    assert max(robot["waves.hs"]) < 0.4


def test_fully_developed_seas_of_a_height():
    """A Pierson-Moskowitz sea of height Hs: the wind U19.5 = sqrt(g Hs/0.21) raises it, its peak
    period 2 pi U19.5/(0.877 g), about 5.0 sqrt(Hs) s (Stewart 2008 eqs. 16.30, 16.33)."""
    from sailmujoco.studies.assumptions import sea

    for hs in sea.SEA_HS:
        got_hs, tp = sea.developed_sea(hs)
        assert got_hs == hs
        assert tp == pytest.approx(2 * math.pi * math.sqrt(9.81 * hs / 0.21) / (0.877 * 9.81), rel=1e-12)
        assert tp == pytest.approx(5.0 * math.sqrt(hs), rel=0.01)
    jobs = sea.table1_sea_jobs(smoke=False)
    wanted = [(s, h) for s in ("sim1", "sim2", "sim3") for h in sea.SEA_HS]
    assert [(j["sim"], j["hs"]) for j in jobs] == wanted
    # Table 1's beam reach: wind from the west, heading north; the waves from the wind
    assert all(j["run"]["env"]["waves"]["direction_from_deg"] == 270.0 for j in jobs)
    assert all(j["run"]["env"]["resistance"] == "dsyhs" for j in jobs)  # the boat as built


def test_differences_are_relative_to_calm_or_to_the_floor():
    from sailmujoco.studies.assumptions.sea_cases import TABLE1, compare

    calm = [{"status": "ok", "stopped": "", "roll_sd": 0.2, "surge": 4.0, "heel": 10.0, "heading_rms": 2.0}]
    sea_ = [{"status": "stopped", "stopped": "capsized", "roll_sd": 0.5, "surge": 3.0, "heel": 10.5,
             "heading_rms": 12.0}]
    row = compare([{"case": "a"}], calm, sea_, TABLE1).iloc[0]
    assert row["roll_sd_rel"] == pytest.approx(0.3 / 1.0)  # calm 0.2 deg below the 1 deg floor
    assert row["surge_rel"] == pytest.approx(-0.25) and row["heel_rel"] == pytest.approx(0.05)
    assert row["status"] == "stopped" and row["stopped"] == "capsized"
    assert row["lost_heading"] == "sea"  # 12 deg RMS beyond 10 deg, 2 deg within


def test_window_statistics_of_a_known_signal():
    """A sine of amplitude A and period T about a mean heel, sampled at 10 Hz: its standard
    deviation is A/sqrt(2) whatever the window, its zero-up-crossing period T; a constant
    heading error e has RMS |e|; only the last ``window`` seconds count."""
    from sailmujoco.studies.assumptions.sea import window_statistics

    t = np.arange(0.0, 100.0, 0.1)
    a, period = math.radians(6.0), 1.7
    heel = math.radians(5.0) + a * np.sin(2 * math.pi * t / period + 0.3)
    error = np.where(t < 50.0, 1.0, math.radians(-4.0))  # 1 rad off before the window
    for window in (20.0, 40.0):
        stats = window_statistics(t, heel, error, window)
        assert stats["roll_sd"] == pytest.approx(6.0 / math.sqrt(2.0), rel=0.01)
        assert stats["roll_period"] == pytest.approx(period, rel=0.01)
        assert stats["heading_rms"] == pytest.approx(4.0, rel=1e-12)


def test_developed_seas_are_equally_steep():
    """Pierson-Moskowitz seas with Tp = 4.99 sqrt(Hs): Hs^2 omega_p^4 is the same for every Hs,
    so the slope variance, the integral of (omega^2/g)^2 S(omega) over the simulated band
    0.5-5 omega_p, is too; the components' RMS slope against that integral (trapezoid rule)."""
    from sailmujoco.studies.assumptions import sea
    from sailmujoco.studies.assumptions.sea_analysis import roll_resonance

    g = 9.81
    seas = roll_resonance(32)["seas"]
    for _, row in seas.iterrows():
        wp = 2 * math.pi / row["tp"]
        w = np.linspace(0.5 * wp, 5.0 * wp, 20001)
        slope = (w**2 / g) ** 2 * 5 / 16 * row["hs"] ** 2 * wp**4 * w**-5 * np.exp(-1.25 * (wp / w) ** 4)
        variance = float(np.sum(0.5 * (slope[1:] + slope[:-1]) * np.diff(w)))
        assert row["rms_slope"] == pytest.approx(math.degrees(math.atan(math.sqrt(variance))), rel=0.05)
    assert seas["rms_slope"].max() - seas["rms_slope"].min() < 1e-9
    assert list(seas["hs"]) == list(sea.SEA_HS)


def test_attribution_names_the_switch_that_removes_the_difference():
    """Synthetic cases over seeds: every difference whose verdict is *breaks* is picked, the
    largest of each series and metric marked; the mechanism whose switch brings the metric back
    to calm on every seed (its share's interval wholly above one half) is named; none where the
    share's interval straddles one half or no switch removes half."""
    from sailmujoco.studies.assumptions.sea_attribution import attribute, differing_cases, largest_cases

    verdicts = {m: ["holds"] * 4 for m in ("speed", "heel", "drift", "pitch_sd")}
    table = pd.DataFrame({"case_index": [0, 1, 2, 3], "n_kept": [3, 3, 3, 0],
                          "roll_sd_rel": [0.05, 2.0, -0.5, float("nan")],
                          "roll_sd_verdict": ["holds", "breaks", "breaks", "lost its heading"],
                          **{f"{m}_verdict": v for m, v in verdicts.items()}})
    selected = differing_cases({"saoud": table}, smoke=False)
    assert selected == [("saoud", "roll_sd", 1), ("saoud", "roll_sd", 2)]  # the lost case d has none
    assert largest_cases({"saoud": table}, selected) == [("saoud", "roll_sd", 1)]
    calm, sea_value = [1.0, 1.0, 1.0], [3.0, 3.2, 2.8]  # the roll, deg, on three seeds
    # the pressure decay's switch removes 90 %, 91 %, 89 %; the foil flow's 5 % on each seed
    named, removed = attribute(calm, sea_value, {"wave_foil_flow": [2.9, 3.09, 2.71],
                                                 "wave_pressure_decay": [1.2, 1.2, 1.2]})
    assert named == "wave_pressure_decay"
    assert removed["wave_pressure_decay"].mean == pytest.approx((0.9 + 1 - 0.2 / 2.2 + 1 - 0.2 / 1.8) / 3)
    assert removed["wave_pressure_decay"].low > 0.5 and removed["wave_foil_flow"].high < 0.5
    assert removed["wave_foil_flow"].mean == pytest.approx(0.05)
    # a share of 90 % on one seed and 10 % on another: the interval straddles one half, no name
    named, removed = attribute([1.0, 1.0], [3.0, 3.0], {"a": [1.2, 2.8]})
    assert named is None and removed["a"].mean == pytest.approx(0.5)
    assert removed["a"].low < 0.5 < removed["a"].high
    # a falling metric (speed lost in the sea) the same way
    named, _ = attribute([2.0, 2.0], [1.0, 1.1], {"wave_foil_flow": [1.95, 1.96], "wave_damping": [1.1, 1.2]})
    assert named == "wave_foil_flow"


def test_a_difference_takes_the_path_whose_switch_removes_it():
    """The sea's two paths (hull, foils): the one whose switch surely removes more than half of a
    difference (its share's interval over seeds above one half) is the path it takes; where both
    surely remove at most half, each path alone makes more than half; where that path's rerun
    lost its heading on every seed, the other path's switch surely removing at most half means
    the lost one alone makes at least half (both off is the calm boat); where an interval
    straddles one half, the path is undecided."""
    from sailmujoco.studies.assumptions import sea_mechanisms
    from sailmujoco.studies.assumptions.sea_attribution import path_taken

    from sailmujoco import stats

    def share(low, high):
        return stats.Interval(0.5 * (low + high), low, high, 2)

    nothing = stats.Interval(float("nan"), float("nan"), float("nan"), 0)
    fine = {"wave_hull": (0, 2), "wave_foil_flow": (0, 2)}
    assert path_taken({"wave_hull": share(0.8, 1.0), "wave_foil_flow": share(-0.1, 0.2)}, fine) == "hull"
    assert path_taken({"wave_hull": share(0.1, 0.3), "wave_foil_flow": share(0.9, 1.2)}, fine) == "foils"
    assert path_taken({"wave_hull": share(0.1, 0.4), "wave_foil_flow": share(0.2, 0.3)}, fine) == "either"
    assert path_taken({"wave_hull": share(0.3, 0.7), "wave_foil_flow": share(0.0, 0.1)}, fine) == "undecided"
    lost = {**fine, "wave_hull": (2, 2)}
    assert path_taken({"wave_hull": nothing, "wave_foil_flow": share(0.0, 0.1)}, lost) == "hull alone"
    assert path_taken({"wave_hull": nothing, "wave_foil_flow": share(0.4, 0.9)}, lost) == "stalled"
    assert sea_mechanisms.path_of({"path": "hull alone"}) == "hull"
    assert sea_mechanisms.path_of({"path": "undecided"}) == "undecided"
