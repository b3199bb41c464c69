"""Ctrl-C during a sweep: one line (no traceback from the command or its Dask workers), exit
status 130, a folder whose table holds the runs that finished, and ``--resume`` runs the rest.
Dask's default port 8787 held by another program (a second cluster) adds no warning."""

import os
import signal
import socket
import subprocess
import sys
import time

import pandas as pd

TOML = ('name = "ctrl_c"\nboat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\n'
        'controller = "pid"\nduration = 10.0\nseeds = [0, 1, 2, 3]\n'
        'metrics = ["mean_surge"]\n')


def test_ctrl_c_during_a_sweep_is_one_line_and_resume_finishes_it(tmp_path):
    held = socket.socket()  # port 8787 taken, as by a second cluster's dashboard
    try:
        held.bind(("", 8787))
        held.listen()
    except OSError:
        pass  # another program holds it already: the same situation
    try:
        _interrupt_and_resume(tmp_path)
    finally:
        held.close()


def _interrupt_and_resume(tmp_path):
    spec, out, err_path = tmp_path / "ctrl_c.toml", tmp_path / "out", tmp_path / "err.txt"
    spec.write_text(TOML)
    command = [sys.executable, "-m", "sailmujoco", "sweep", str(spec), "--out", str(out),
               "--workers", "1"]
    with open(err_path, "w") as err:
        # its own process group, as a terminal's foreground job: Ctrl-C signals every process in it
        # with Ctrl-C's default action, as a terminal gives its foreground job, whatever this
        # process has (a runner that started it in the background passes SIGINT on ignored)
        proc = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err, cwd=tmp_path,
                                start_new_session=True,
                                preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        deadline = time.monotonic() + 120
        while "1/4" not in err_path.read_text() and time.monotonic() < deadline:
            assert proc.poll() is None, err_path.read_text()
            time.sleep(0.1)
        os.killpg(proc.pid, signal.SIGINT)
        code = proc.wait(timeout=60)
    text = err_path.read_text()
    lines = [line for line in text.splitlines() if not line.startswith("sweep ctrl_c: ")]
    assert code == 130, text
    assert "Traceback" not in text and "KeyboardInterrupt" not in text, text
    assert len(lines) == 1, text  # the progress lines, then one line saying what was kept
    saved = len(list((out / "runs").glob("*.json")))
    assert 1 <= saved < 4
    assert lines[0] == (f"sailmujoco sweep: interrupted; {saved} of 4 runs are saved in {out} "
                        f"(results.parquet holds them); 'sailmujoco sweep {spec} --out {out} "
                        "--resume' runs the rest")
    table = pd.read_parquet(out / "results.parquet")
    assert len(table) == saved and set(table["status"]) == {"ok"}

    done = subprocess.run([*command[:-2], "--scheduler", "serial", "--resume", "--no-progress"],
                          capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert done.returncode == 0, done.stderr
    table = pd.read_parquet(out / "results.parquet")
    assert sorted(table["seed"]) == [0, 1, 2, 3]
    assert set(table["status"]) == {"ok"}
