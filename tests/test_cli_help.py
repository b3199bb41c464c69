"""What `sailmujoco study --help` and `sailmujoco check` tell a new user: every study by name with
what it reproduces, and what each column of the health report means."""

from importlib import metadata

import pytest

from sailmujoco.cli.main import main


def test_study_help_lists_every_registered_study_with_its_title(capsys):
    with pytest.raises(SystemExit) as done:
        main(["study", "--help"])
    assert done.value.code == 0
    out = capsys.readouterr().out
    names = [ep.name for ep in metadata.entry_points(group="sailmujoco.studies")]
    assert len(names) == 9  # the eight paper and boat studies and the courses
    for name in names:
        line = next((x for x in out.splitlines() if x.split()[:1] == [name]), None)
        assert line is not None, name
        # the one-line description is the study's own TITLE (the report's heading)
        title = __import__(f"sailmujoco.studies.{name}", fromlist=["TITLE"]).TITLE
        assert line.split(None, 1)[1].strip() == title
    assert any(x.split()[:1] == ["all"] for x in out.splitlines())


def test_check_explains_its_columns(capsys):
    assert main(["check", "--seconds", "0.5", "--boat", "saoud_robot"]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    legend = {x.split()[0] for x in lines if x.startswith("  ") and x.split()}
    assert {"max|heel|", "mean", "V/V0", "us/step"} <= legend
    assert "submerged hull volume" in out and "design displacement volume" in out
    rows = [x.split() for x in lines if x.startswith("saoud_robot")]
    by_mode = {r[1]: r for r in rows}
    assert by_mode["paper"][5] == "-"  # no hull volume with the paper's restoring formula
    assert 0.5 < float(by_mode["geometric"][5]) < 2.0  # a floating hull, near its design volume


def test_check_help_has_the_legend(capsys):
    with pytest.raises(SystemExit):
        main(["check", "--help"])
    assert "V/V0" in capsys.readouterr().out
