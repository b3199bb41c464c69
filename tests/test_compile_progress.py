"""The first run says that it compiles: a cold numba cache gives a line on stderr while a kernel
compiles and one when it is done; the same kernel loaded from the cache gives none.

The whole set of kernels takes about a minute to compile on 2 cores, so the subprocesses here
compile two small ones (finite_wing's, into an empty ``NUMBA_CACHE_DIR``, leaving the shared
cache alone) with the first-line delay set to 0, so that any compile at all would print."""

import io
import os
import subprocess
import sys

import pytest

from sailmujoco.jit import notice as compile_notice
from sailmujoco.jit.notice import CompileNotice

SCRIPT = """
from sailmujoco.jit import notice as compile_notice
compile_notice.NOTICE.announce_after = 0.0
from sailmujoco.forces import finite_wing
print(finite_wing.helmbold_lift_slope(6.28, 5.0), finite_wing.viterna_corrigan_cd_max(5.0))
"""


@pytest.fixture(autouse=True)
def _not_quiet(monkeypatch):
    """The notice speaks here even where the suite runs quiet."""
    monkeypatch.delenv(compile_notice.QUIET_ENV, raising=False)


def _run(cache_dir, **env):
    environment = {k: v for k, v in os.environ.items() if k != compile_notice.QUIET_ENV}
    environment.update(NUMBA_CACHE_DIR=str(cache_dir), **env)
    return subprocess.run([sys.executable, "-c", SCRIPT], env=environment, capture_output=True,
                          text=True, timeout=300, check=True)


def test_a_cold_cache_is_announced_and_a_warm_one_is_silent(tmp_path):
    cold = _run(tmp_path)
    lines = cold.stderr.splitlines()
    assert len(lines) == 2, cold.stderr
    assert lines[0] == compile_notice.FIRST + " ..."  # plain lines: stderr is a pipe
    assert lines[1].startswith("compiled sailmujoco's numba kernels in ") and lines[1].endswith(" s")
    assert any(tmp_path.rglob("*finite_wing*.nbi"))  # numba honoured NUMBA_CACHE_DIR
    warm = _run(tmp_path)
    assert warm.stderr == "" and warm.stdout == cold.stdout


def test_the_quiet_setting_silences_it(tmp_path):
    assert _run(tmp_path, **{compile_notice.QUIET_ENV: "1"}).stderr == ""


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def _notice(live):
    stream = _Terminal() if live else io.StringIO()
    return CompileNotice(stream=stream, announce_after=1.0, gap=5.0, clock=lambda: 0.0, ticking=False), stream


@pytest.mark.parametrize("live", [True, False])
def test_a_burst_of_compiles_is_one_announcement(live):
    notice, stream = _notice(live)
    assert notice.live is live
    notice.start("ours", now=0.0)
    notice.start("ours", now=0.1)  # nested: the callee of the outermost compile
    assert notice.poll(now=0.5) and stream.getvalue() == ""  # under a second: not yet
    notice.end(now=0.6)
    assert notice.poll(now=1.5)  # a second and a half: the first line
    if live:  # cut to the width (80 where it is unknown): a wrapped line cannot be redrawn
        line = stream.getvalue()
        assert line.startswith("\r\033[Kcompiling sailmujoco's numba kernels (first run only")
        assert line.endswith("… 2 s") and len(line) - len("\r\033[K") == 79
    else:
        assert stream.getvalue() == f"{compile_notice.FIRST} ...\n"
    notice.end(now=2.0)
    assert stream.getvalue().endswith("\r\033[K" if live else "\n")  # the live line erased
    assert notice.poll(now=3.0)  # idle, for less than the gap
    assert stream.getvalue().endswith("\r\033[K" if live else "\n")  # and not drawn again
    notice.start("numba", now=4.0)  # numba's helpers of a C callback, within the gap: the same burst
    assert notice.poll(now=12.0)
    notice.end(now=12.5)
    notice.start("ours", now=14.0)
    notice.end(now=20.0)
    assert notice.poll(now=24.0)  # idle for less than the gap
    assert not notice.poll(now=25.5)  # closed
    text = stream.getvalue()
    assert text.endswith("compiled sailmujoco's numba kernels in 20 s\n")
    if live:
        assert "… 12 s\r\033[K" in text and text.count("\n") == 1
    else:
        assert text == f"{compile_notice.FIRST} ...\ncompiled sailmujoco's numba kernels in 20 s\n"


def test_short_compiles_and_other_code_pass_without_a_word():
    notice, stream = _notice(False)
    notice.start("other", now=0.0)  # a user's own numba function, and ours inside it
    notice.start("ours", now=0.5)
    notice.end(now=9.0)
    notice.end(now=10.0)
    notice.start("numba", now=11.0)  # numba's helpers with no burst of ours open
    notice.end(now=13.0)
    assert not notice.poll(now=14.0)
    notice.start("ours", now=20.0)  # a new signature, compiled in half a second
    notice.end(now=20.5)
    assert notice.poll(now=21.0)
    assert not notice.poll(now=26.0)
    notice.close()
    assert stream.getvalue() == ""


def test_quiet_set_while_a_burst_is_open_silences_the_rest(monkeypatch):
    notice, stream = _notice(False)
    notice.start("ours", now=0.0)
    notice.poll(now=2.0)
    monkeypatch.setenv(compile_notice.QUIET_ENV, "1")
    notice.end(now=3.0)
    notice.close()
    assert stream.getvalue() == f"{compile_notice.FIRST} ...\n"


def test_a_second_burst_says_more_and_exit_closes_an_open_one():
    notice, stream = _notice(False)
    notice.start("ours", now=0.0)
    notice.poll(now=2.0)
    notice.end(now=3.0)
    assert not notice.poll(now=9.0)
    notice.start("ours", now=100.0)
    notice.poll(now=102.0)
    notice.end(now=104.0)
    notice.close()  # the process exits before the gap has passed
    assert stream.getvalue().splitlines() == [
        f"{compile_notice.FIRST} ...", "compiled sailmujoco's numba kernels in 3 s",
        f"{compile_notice.MORE} ...", "compiled more kernels in 4 s"]


def test_exit_in_the_middle_of_a_compile_says_it_stopped():
    clock = iter([7.0])
    notice = CompileNotice(stream=io.StringIO(), clock=lambda: next(clock), ticking=False)
    notice.start("ours", now=0.0)
    notice.poll(now=2.0)
    notice.close()  # at exit, with the compile still under way
    assert notice.stream.getvalue().splitlines() == [
        f"{compile_notice.FIRST} ...", "stopped compiling sailmujoco's numba kernels after 7 s"]
