"""A boat file that keeps a built-in boat's name but not its parameters is warned about, once,
in one line; an unedited export or a renamed boat is not."""

import pytest

from sailmujoco.boat import file as boat_file
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.cli.main import main
from sailmujoco.design import check as boat_check
from sailmujoco.jit import notice as compile_notice


def _edited(tmp_path, name=None):
    """saoud_robot's file with its mass 2 % up, under its own ``name`` or (None) the built-in's."""
    path = tmp_path / "my_robot.toml"
    boat_file.write_boat("saoud_robot", path)
    text = path.read_text().replace("\nmass = 15.0", "\nmass = 15.3")
    if name is not None:
        text = text.replace('name = "saoud_robot"', f'name = "{name}"')
    path.write_text(text)
    return path


def test_an_edited_copy_under_the_built_in_name_is_warned_about(tmp_path):
    path = _edited(tmp_path)
    params = get_boat(path)
    assert params.name == "saoud_robot" and params.mass == 15.3
    warning = boat_file.name_clash(params, path)
    assert warning is not None and "\n" not in warning
    assert warning.startswith(f"warning: {path}: name = \"saoud_robot\" is a built-in boat's")
    assert 'name = "my_robot"' in warning


@pytest.mark.parametrize("case", ["unedited", "renamed"])
def test_an_unedited_export_or_a_renamed_boat_is_not(tmp_path, case):
    if case == "unedited":
        path = tmp_path / "robot.toml"
        boat_file.write_boat("saoud_robot", path)
    else:
        path = _edited(tmp_path, name="my_robot")
    assert boat_file.name_clash(get_boat(path), path) is None


def test_boat_check_prints_the_warning_once_on_stderr(tmp_path, capsys, monkeypatch):
    checked = []

    class Stub:
        def text(self):
            return "checked"

    def stub(boat, **kwargs):  # the warning is the CLI's: the numbers are tested elsewhere
        checked.append(boat)
        return Stub()

    monkeypatch.setattr(boat_check, "check_boat", stub)
    monkeypatch.setenv(compile_notice.QUIET_ENV, "1")  # stderr holds the warning alone, cache cold or warm
    path = _edited(tmp_path)
    assert main(["boat", "check", str(path), "--out", str(tmp_path / "check")]) == 0
    out, err = capsys.readouterr()
    assert checked == [str(path)] and out.strip() == "checked"
    assert err.count("\n") == 1 and err.startswith(f"warning: {path}: name = \"saoud_robot\"")
    renamed = _edited(tmp_path, name="my_robot")
    assert main(["boat", "check", str(renamed), "--out", str(tmp_path / "check2")]) == 0
    assert capsys.readouterr().err == ""
