"""Progress: plain milestone lines where the output is not a terminal (a log, CI), a bar on a
terminal, and a sweep that counts a capsize as stopped, not failed."""

import io

from sailmujoco.cli.main import main
from sailmujoco.progress import Progress


class Terminal(io.StringIO):
    def isatty(self):
        return True


def test_off_a_terminal_1000_updates_give_ten_plain_lines_with_the_counts():
    log = io.StringIO()
    bar = Progress(1000, "sweep x", log, counts=("ok", "stopped", "failed"))
    for i in range(1000):
        bar.update(**({"ok": 1} if i % 20 else {"stopped": 1}))  # every 20th stops
    bar.close()
    text = log.getvalue()
    assert "\r" not in text
    lines = text.splitlines()
    assert len(lines) == 10  # one per 10 %; the end line is the 100 % one
    assert lines[0].startswith("sweep x: 100/1000 (10 %), ok 95, stopped 5, failed 0; ")
    assert lines[-1].startswith("sweep x: 1000/1000 (100 %), ok 950, stopped 50, failed 0; ")
    assert "left" in lines[0] and "left" not in lines[-1]


def test_a_resumed_job_counts_from_where_it_was_and_prints_the_end_once():
    log = io.StringIO()
    bar = Progress(40, "sweep y", log, initial=30, counts={"ok": 29, "failed": 1})
    for _ in range(10):
        bar.update(ok=1)
    bar.close()
    bar.close()
    lines = log.getvalue().splitlines()
    assert [line.split(";")[0] for line in lines] == ["sweep y: 32/40 (80 %), ok 31, failed 1",
                                                      "sweep y: 36/40 (90 %), ok 35, failed 1",
                                                      "sweep y: 40/40 (100 %), ok 39, failed 1"]


def test_nothing_to_do_still_says_so_and_show_false_says_nothing():
    log = io.StringIO()
    Progress(5, "z", log, initial=5).close()
    assert log.getvalue().startswith("z: 5/5 (100 %)")
    quiet = io.StringIO()
    bar = Progress(5, "z", quiet, show=False)
    bar.update(3, ok=3)
    bar.close()
    assert quiet.getvalue() == ""


def test_on_a_terminal_a_bar_with_the_counts():
    term = Terminal()
    with Progress(4, "sweep t", term, counts=("ok", "stopped")) as bar:
        for _ in range(4):
            bar.update(stopped=1)
    text = term.getvalue()
    assert "\r" in text and "4/4" in text and "stopped=4" in text


def test_a_capsized_run_is_counted_stopped_not_failed(tmp_path, capsys):
    """A 60 m/s wind capsizes the robot within a second (test_bad_input); 4 m/s does not."""
    path = tmp_path / "s.toml"
    path.write_text('name = "cap"\nboat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\n'
                    'controller = "pid"\nduration = 2.0\n[options]\n"task.gusts" = false\n'
                    '"task.wander" = false\n[zip]\n"task.wind_speed" = [4.0, 60.0]\n')
    assert main(["sweep", str(path), "--out", str(tmp_path / "o"), "--scheduler", "serial"]) == 0
    out, err = capsys.readouterr()
    assert "status: ok 1, stopped 1, failed 0" in out
    lines = err.splitlines()  # captured: not a terminal, so plain lines
    assert len(lines) == 2 and "\r" not in err
    assert lines[-1].startswith("sweep cap: 2/2 (100 %), ok 1, stopped 1, failed 0; ")
