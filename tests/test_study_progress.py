"""`study all` says where it is (study k of n, elapsed, ETA) and ends with the time each study
took; where output is not a terminal, progress is plain lines, never carriage returns."""

import time
from types import SimpleNamespace

from sailmujoco import sweep
from sailmujoco.cli import main as cli
from sailmujoco.cli import study as study_runner
from sailmujoco.study import Runs, Study


def _fake_study(seconds):
    """The entry point of a declared study that simulates nothing and takes ``seconds``."""
    def runs(smoke):
        time.sleep(seconds)
        return Runs()

    fake = Study(name="fake", title="A fake study", runs=runs, analyse=lambda results, smoke: None,
                 write=lambda analysis, out: None, report=lambda analysis, smoke: "# fake\n",
                 headline=lambda analysis: {"answer": 42})
    return SimpleNamespace(load=lambda: fake, module=__name__)


def test_study_all_prints_progress_eta_and_a_timing_table(monkeypatch, tmp_path, capsys):
    monkeypatch.setattr(study_runner, "studies",
                        lambda: {"fast_a": _fake_study(0.0), "fast_b": _fake_study(0.05)})
    assert cli.main(["study", "all", "--smoke", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    assert "\r" not in out
    # per study: a start line and a done line; then the table (header, rule, 2 rows, total), the end
    assert len(lines) == 2 * 2 + 5 + 1
    assert lines[0].startswith("[1/2] study fast_a (smoke)") and "ETA after the first study" in lines[0]
    assert lines[2].startswith("[2/2] study fast_b (smoke)") and "ETA 0:00:00 (1 left" in lines[2]
    table = lines[4:9]
    assert table[0].split() == ["study", "time", "[s]", "share"]
    assert [row.split()[0] for row in table[2:4]] == ["fast_a", "fast_b"]
    assert float(table[3].split()[1]) >= 0.05  # fast_b slept 0.05 s
    assert table[4].startswith("total (wall)")
    assert lines[-1].startswith("all done in")


def test_job_progress_in_a_log_has_no_carriage_return(tmp_path, capsys):
    assert sweep.run_jobs("operator:abs", [-1, -2, -3], tmp_path, progress=True, label="runs") == [1, 2, 3]
    err = capsys.readouterr().err
    assert "\r" not in err
    # 3 items cross a tenth at each: 1/3 (33 %), 2/3 (67 %), 3/3 (100 %)
    assert [line.split(";")[0].strip() for line in err.splitlines()] == [
        "runs: 1/3 (33 %)", "runs: 2/3 (67 %)", "runs: 3/3 (100 %)"]
