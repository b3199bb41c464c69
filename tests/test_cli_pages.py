"""What the command line tells a user who has not read the README: `sailmujoco list`, every
command's help (a description, examples, every option explained), the sweep file's keys in
`sweep --help`, an example sweep file that runs as printed, `--version` and `python -m sailmujoco`."""

import argparse
import subprocess
import sys
import tomllib
from importlib import metadata

import pandas as pd
import pytest

from sailmujoco import sweep
from sailmujoco.cli import main as cli
from sailmujoco.cli.main import main


def _section(out: str, heading: str) -> dict:
    """name -> description of the lines under ``heading`` in ``sailmujoco list``'s output."""
    lines = out.split("\n\n")
    block = next(b for b in lines if b.startswith(heading))
    rows = [row.split(None, 1) for row in block.splitlines()[1:]]
    return {row[0]: row[1] if len(row) > 1 else "" for row in rows}


def test_list_names_every_boat_task_world_controller_and_study_on_one_line(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    boats = _section(out, "boats")
    assert set(boats) == {"wille_yacht", "saoud_robot", "viel_boat", "eleven_metre"}
    # the papers' numbers: Wille (2016a) App. A, 1600 kg; Saoud (2015) Table I, 15 kg; Viel
    # (2019) Table 1, p9 = 300 kg
    assert "1600 kg" in boats["wille_yacht"] and "Wille" in boats["wille_yacht"]
    assert "15 kg" in boats["saoud_robot"] and "Saoud" in boats["saoud_robot"]
    assert "300 kg" in boats["viel_boat"] and "Viel" in boats["viel_boat"]
    assert "8.80 m" in boats["wille_yacht"]  # Wille's 8.8 m yacht
    tasks = _section(out, "tasks")
    assert list(tasks) == ["heading_hold", "course_hold", "beam_reach_roll", "speed_trial",
                           "position_keeping", "upwind_downwind", "precision_navigation",
                           "station_keeping", "area_scanning"]
    assert tasks["heading_hold"] == "Hold a compass heading in a steady, gusty wind."
    assert set(_section(out, "worlds")) == {"mujoco", "paper"}
    controllers = _section(out, "controllers")
    entry_points = {ep.name for ep in metadata.entry_points(group="sailmujoco.controllers")}
    assert set(controllers) == entry_points
    assert controllers["pid"] == "PID heading controller with the leeward rule-of-thumb sail."
    studies = _section(out, "studies")
    assert set(studies) == {ep.name for ep in metadata.entry_points(group="sailmujoco.studies")}
    assert all(text for section in (boats, tasks, controllers, studies) for text in section.values())


def test_list_shows_a_controller_registered_in_this_process(capsys):
    def heading_law(env, gain: float = 1.0):
        """A law of one's own, registered at run time."""

    sweep.register_controller("my_law", heading_law)
    try:
        assert main(["list", "controllers"]) == 0
    finally:
        sweep.controllers._REGISTERED.pop("my_law", None)
    out = capsys.readouterr().out
    assert _section(out, "controllers")["my_law"] == "A law of one's own, registered at run time."
    assert "boats" not in out


def test_version_is_the_installed_distributions(capsys):
    with pytest.raises(SystemExit) as done:
        main(["--version"])
    assert done.value.code == 0
    assert capsys.readouterr().out.strip() == f"sailmujoco {metadata.version('sailmujoco')}"


def test_python_dash_m_runs_the_command(tmp_path):
    out = subprocess.run([sys.executable, "-m", "sailmujoco", "list", "worlds"], capture_output=True,
                         text=True, cwd=tmp_path, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines()[0] == "worlds:" and len(out.stdout.splitlines()) == 3
    bad = subprocess.run([sys.executable, "-m", "sailmujoco", "check", "--boat", "dinghy"],
                         capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert bad.returncode == 2 and "unknown boat 'dinghy'" in bad.stderr


def _subparsers() -> dict:
    parser = cli.build_parser()
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(action.choices)


def test_every_command_explains_every_option_and_shows_examples():
    """Every option of every command has a help text, and every command a description and
    an epilog with examples: enough to use it without the README."""
    for name, parser in _subparsers().items():
        assert parser.description, name
        assert "examples:\n  sailmujoco " + name in parser.epilog, name
        for action in parser._actions:
            assert action.help, f"{name} {action.option_strings or action.dest}"


def test_help_shows_defaults(capsys):
    with pytest.raises(SystemExit):
        main(["polar", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert "seconds per point (default: 60)" in out
    assert "(default: 2,4,6; with --reference: the file's)" in out and "(default: saoud)" in out


def test_sweep_help_lists_every_key_and_namespace_of_a_sweep_file(capsys):
    with pytest.raises(SystemExit) as done:
        main(["sweep", "--help"])
    assert done.value.code == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    for key in sweep.TOP_KEYS:
        assert any(line.split()[:1] == [key] for line in lines), key
    for namespace in sweep.NAMESPACES:
        assert any(line.split()[:1] == [namespace + "."] for line in lines), namespace
    text = " ".join(out.split())
    for option in sweep.env_options():
        assert option in text
    assert "hydrostatics (off|paper|geometric)" in text


def test_the_example_sweep_file_runs_as_printed(tmp_path, capsys):
    """Printed, saved and run: every run finishes, and the robot makes headway in each."""
    assert main(["sweep", "--example"]) == 0
    text = capsys.readouterr().out
    path = tmp_path / "example.toml"
    path.write_text(text)
    example = tomllib.loads(text)
    assert set(example) == set(sweep.TOP_KEYS) - {"trajectory_rate"}  # every key but one shown
    assert {key.split(".")[0] for table in ("options", "grid", "zip") for key in example[table]} \
        == set(sweep.NAMESPACES) - {"boat", "waves", "sensors", "actuators"}
    assert '# "waves.hs" = ' in text  # shown, commented out: a sea makes the example slow
    assert '# "sensors.preset" = ' in text and '# "actuators.preset" = ' in text  # shown, as options
    out = tmp_path / "out"
    assert main(["sweep", str(path), "--scheduler", "serial", "--out", str(out), "--no-progress"]) == 0
    table = pd.read_parquet(out / "results.parquet")
    runs = len(example["seeds"]) * len(example["grid"]["controller.kp"]) \
        * len(example["zip"]["task.wind_from_deg"])
    assert len(table) == runs and set(table["status"]) == {"ok"}
    assert (table["mean_surge"] > 0.3).all()  # under sail, not drifting
    # summary.csv: each combination's mean over its seeds with Student's t interval,
    # mean ± t(0.975, n-1) s / sqrt(n) (t(0.975, 2) = 4.302653 for three seeds)
    summary = pd.read_csv(out / "summary.csv")
    assert len(summary) == runs // len(example["seeds"]) and (summary["n"] == len(example["seeds"])).all()
    first = summary.iloc[0]
    same = table[(table["controller.kp"] == first["controller.kp"])
                 & (table["task.wind_from_deg"] == first["task.wind_from_deg"])]["mean_surge"]
    assert len(example["seeds"]) == 3 and len(same) == 3
    half = 4.302653 * same.std(ddof=1) / len(same) ** 0.5
    assert first["mean_surge"] == pytest.approx(same.mean(), rel=1e-12)
    assert (first["mean_surge_low"], first["mean_surge_high"]) == pytest.approx(
        (same.mean() - half, same.mean() + half), rel=1e-6)
    assert "mean_surge: mean [95 % interval] over 3 seed(s) per combination" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["sweep"], "give a sweep FILE (TOML); 'sailmujoco sweep --example' prints one"),
    (["sweep", "x.toml", "--example"], "give a sweep FILE or --example, not both"),
])
def test_sweep_wants_a_file_or_the_example(argv, message, capsys):
    assert main(argv) == 2
    assert capsys.readouterr().err == f"sailmujoco: error: {message}\n"
