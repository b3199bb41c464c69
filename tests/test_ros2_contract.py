"""The bridge's remap file and its command line's bad input: one line each, no ROS needed."""

import subprocess
import sys

import pytest

from sailmujoco.ros2.contract import COMMANDS, TOPICS, check_topic_name, read_remap


def test_a_remap_file_renames_what_it_names_and_keeps_the_rest(tmp_path):
    path = tmp_path / "topics.toml"
    path.write_text('[topics]\n"/gps/fix" = "/sensors/gnss/fix"\n"/sail/command" = "/actuators/sheet"\n')
    names = read_remap(path)
    assert set(names) == set(TOPICS) | set(COMMANDS)
    assert names["/gps/fix"] == "/sensors/gnss/fix" and names["/sail/command"] == "/actuators/sheet"
    assert all(names[t] == t for t in names if t not in ("/gps/fix", "/sail/command"))


@pytest.mark.parametrize("text, message", [
    ('[topics]\n"/gps/fixx" = "/a"\n', "'/gps/fixx' is not a topic of the bridge"),
    ('[topics]\n"/gps/fix" = "gps fix"\n', "the name of '/gps/fix' must be a ROS 2 topic name"),
    ('[topics]\n"/gps/fix" = "/a//b"\n', "must be a ROS 2 topic name"),
    ('[topics]\n"/gps/fix" = 3\n', "must be a ROS 2 topic name"),
    ('[topics]\n"/gps/fix" = "/imu/data"\n', "'/gps/fix' and '/imu/data' are both named '/imu/data'"),
    ('[topic]\n"/gps/fix" = "/a"\n', "unknown table or key 'topic'"),
    ('topics = "/a"\n', "topics must be a table"),
    ('[topics\n', "does not parse as TOML"),
])
def test_a_bad_remap_file_is_one_line_naming_the_problem(tmp_path, text, message):
    path = tmp_path / "topics.toml"
    path.write_text(text)
    with pytest.raises(ValueError, match="remap file") as err:
        read_remap(path)
    assert message in str(err.value) and "\n" not in str(err.value)


@pytest.mark.parametrize("name, ok", [("/gps/fix", True), ("/a_1/b", True), ("gps/fix", False),
                                      ("/gps/", False), ("/1gps", False), ("/gps__fix", False)])
def test_topic_names_follow_ros2s_rules(name, ok):
    if ok:
        assert check_topic_name(name, "x") == name
    else:
        with pytest.raises(ValueError, match="ROS 2 topic name"):
            check_topic_name(name, "x")


@pytest.mark.parametrize("args, message", [
    (["--remap", "missing.toml"], "remap file 'missing.toml' does not exist"),
    (["--record", "run.csv"], "--record must end in .mcap"),
    (["--origin", "95,10"], "latitude must lie in (-90, 90)"),
    (["--rate", "0"], "--rate"),
    (["--timeout", "-1"], "--timeout"),
    (["--set", "wind_sped=3"], "wind_sped"),
])
def test_bad_input_to_the_bridge_is_one_line_before_any_ros(tmp_path, args, message):
    code = ("import sys; sys.modules['rclpy'] = None; from sailmujoco.cli.main import main; "
            f"sys.exit(main(['ros2', 'eleven_metre', *{args!r}]))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                          cwd=tmp_path)
    assert done.returncode == 2
    errors = [line for line in done.stderr.splitlines() if "error:" in line]  # after argparse's usage
    assert len(errors) == 1 and message in errors[0] and "Traceback" not in done.stderr, done.stderr
