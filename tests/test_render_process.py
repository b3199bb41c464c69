"""Frames are drawn in a child process: the caller's process maps no GL library and no LLVM.

Mesa's EGL (llvmpipe) loads Mesa's LLVM into the process that renders, with RTLD_GLOBAL, and
PyTorch's triton imported after it binds its own LLVM calls to Mesa's copy and crashes the
process. So record(), the Gymnasium environments' "rgb_array" frames and the sitl film draw in a
child process (sailmujoco.video.ChildRenderer). The checks read /proc/self/maps (the shared
libraries a process has mapped) and /proc/self/task/*/children (its living and unreaped
children) in a fresh interpreter, with MUJOCO_GL unset (EGL by default) and set to egl. With
MUJOCO_GL=egl, MuJoCo's own import loads libEGL, which maps no driver and no LLVM until a
display is initialised; dm_control would initialise one at its import, and sailmujoco defers it.
"""

import json
import os
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from sailmujoco import suite, video

GL_LIBRARIES = ("libEGL", "libGL.", "libGLX", "libGLdispatch", "libOSMesa")
DRIVERS = ("libLLVM", "_dri.so", "libgallium")  # a GL driver and the LLVM it brings (Mesa's libLLVM-NN)
LOADED_BY_GL = GL_LIBRARIES + DRIVERS

SCRIPT = textwrap.dedent("""
    import gc, glob, json, os
    import gymnasium
    import sailmujoco.gym
    from sailmujoco import video

    def mapped():
        return sorted({line.split()[-1] for line in open("/proc/self/maps")
                       if any(name in line for name in NAMES)})

    def children():
        return sorted(int(pid) for path in glob.glob("/proc/self/task/*/children")
                      for pid in open(path).read().split())

    seen = {"before": children()}
    env = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", render_mode="rgb_array",
                         render_width=64, render_height=48)
    env.reset(seed=0)
    frame = env.render()
    seen.update(frame_shape=list(frame.shape), frame_spread=float(frame.std()),
                after_frame=mapped(), children_while_open=children())
    env.close()
    seen["children_after_close"] = children()

    forgotten = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", render_mode="rgb_array",
                               render_width=64, render_height=48)
    forgotten.reset(seed=0)
    forgotten.render()
    seen["children_of_a_forgotten_env"] = children()
    del forgotten
    gc.collect()
    seen["children_after_it_is_collected"] = children()

    rec = video.record("saoud_robot", "heading_hold", "pid", "out.mp4", seconds=0.4, fps=5,
                       width=64, height=48)
    seen.update(recorded=rec.frames, after_record=mapped(), children_after_record=children())

    video.check_rendering()  # the control: drawing in this process maps its GL library here
    seen["after_drawing_here"] = mapped()
    print(json.dumps(seen))
""").replace("NAMES", repr(LOADED_BY_GL))


@pytest.fixture(scope="module", params=[None, "egl"], ids=["MUJOCO_GL unset", "MUJOCO_GL=egl"])
def seen(request, tmp_path_factory) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "PYOPENGL_PLATFORM")}
    if request.param is not None:
        env["MUJOCO_GL"] = request.param
    result = subprocess.run([sys.executable, "-c", SCRIPT], env=env, cwd=tmp_path_factory.mktemp("child"),
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr[-3000:]
    return dict(json.loads(result.stdout.strip().splitlines()[-1]), platform=request.param)


def _not_allowed(seen: dict, paths: list) -> list:
    """The mapped ``paths`` that drawing must not have brought: any GL library with MUJOCO_GL
    unset; with it set, the driver and its LLVM (MuJoCo's import loaded libEGL already)."""
    names = LOADED_BY_GL if seen["platform"] is None else DRIVERS
    return [path for path in paths if any(name in path for name in names)]


def test_a_gymnasium_frame_maps_no_gl_driver_and_no_llvm_here(seen):
    assert seen["frame_shape"] == [48, 64, 3] and seen["frame_spread"] > 1.0  # a picture
    assert _not_allowed(seen, seen["after_frame"]) == [], seen["after_frame"]


def test_a_recorded_video_maps_no_gl_driver_and_no_llvm_here(seen):
    assert seen["recorded"] == 2  # 0.4 s at 5 frames a second
    assert _not_allowed(seen, seen["after_record"]) == [], seen["after_record"]


def test_the_check_would_see_a_gl_library_drawn_here(seen):
    """The control: a context made in this process maps a GL library, and more than drawing
    through the child left mapped (Mesa's driver and libLLVM here)."""
    drawn_here, before = set(seen["after_drawing_here"]), set(seen["after_record"])
    assert any(name in path for path in drawn_here for name in GL_LIBRARIES), drawn_here
    assert drawn_here > before, drawn_here


def test_closing_the_environment_ends_and_reaps_its_renderer(seen):
    assert seen["before"] == []
    assert len(seen["children_while_open"]) == 1
    assert seen["children_after_close"] == []  # a zombie would still be listed


def test_an_environment_never_closed_ends_its_renderer_when_collected(seen):
    assert len(seen["children_of_a_forgotten_env"]) == 1
    assert seen["children_after_it_is_collected"] == []
    assert seen["children_after_record"] == []


# ----------------------------------------------------------------------------- same pixels
def _snapshots(n: int) -> list:
    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=5.0)
    env.reset()
    snaps = []
    for step in range(n):
        env.step(np.array([0.2 * (-1) ** step, 0.5]))
        snaps.append(video.snapshot_physics(env.physics, env.task.references(env.physics)))
    return env.physics.params, snaps


def test_the_child_draws_the_pixels_this_process_draws():
    """The same renderer fed the same snapshots in the same order: the same frames, bit for bit
    (panel, track and the follow camera's lag included)."""
    params, snaps = _snapshots(4)
    with video.SceneRenderer(params, 96, 64, "follow") as here:
        expected = [here.render(snap) for snap in snaps]
        expected.append(here.render(snaps[-1], note="stopped"))
    with video.ChildRenderer().open(params, 96, 64, "follow") as child:
        drawn = [child.render(snap) for snap in snaps]
        drawn.append(child.render(snaps[-1], note="stopped"))
    assert (child.width, child.height) == (96, 64)
    for want, got in zip(expected, drawn, strict=True):
        assert got.dtype == np.uint8 and got.shape == (64, 96, 3)
        np.testing.assert_array_equal(got, want)
    assert not np.array_equal(drawn[0], drawn[-2])  # the boat moved: frames that differ


# ----------------------------------------------------------------------------- errors, one line
def test_a_bad_argument_comes_back_as_its_own_error_in_one_line():
    params, snaps = _snapshots(1)
    with video.ChildRenderer() as child:
        with pytest.raises(ValueError, match="unknown camera 'drone'") as err:
            child.open(params, 64, 48, "drone")
        assert "\n" not in str(err.value)
        with pytest.raises(RuntimeError, match=r"needs open\(\) first"):
            child.render(snaps[0])
        assert child.open(params, 64, 48, "top").render(snaps[0]).shape == (48, 64, 3)  # still serving


def test_a_renderer_that_dies_is_named_in_one_line_and_reaped():
    params, snaps = _snapshots(1)
    child = video.ChildRenderer().open(params, 64, 48)
    os.kill(child.pid, signal.SIGKILL)
    with pytest.raises(RuntimeError) as err:
        child.render(snaps[0])
    message = str(err.value)
    assert "\n" not in message and f"renderer's process (pid {child.pid}) was killed by SIGKILL" in message
    assert not os.path.exists(f"/proc/{child.pid}")  # waited for: no zombie
    with pytest.raises(RuntimeError, match="closed"):
        child.render(snaps[0])
    child.close()  # closing again is harmless


def test_no_gl_platform_is_one_line_naming_the_fixes(monkeypatch):
    monkeypatch.setenv("MUJOCO_GL", "no-such-platform")
    with pytest.raises(video.RenderingUnavailable) as err:
        video.ChildRenderer()
    message = str(err.value)
    assert "\n" not in message and "MUJOCO_GL='no-such-platform'" in message
    assert "MUJOCO_GL=egl" in message and "libosmesa6" in message


FORK = textwrap.dedent("""
    import os, sys
    from sailmujoco import suite, video

    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=1.0)
    env.reset()
    snap = video.snapshot_physics(env.physics)
    child = video.ChildRenderer().open(env.physics.params, 32, 24)
    first = child.render(snap)
    pid = os.fork()
    if pid == 0:  # the forked copy: refused; its exit runs the finalizers, which leave the child alone
        try:
            child.render(snap)
        except RuntimeError as err:
            print("fork:", err, flush=True)
        sys.exit(0)
    os.waitpid(pid, 0)
    again = child.render(snap)  # the maker still draws
    print("maker:", bool((again == first).all()), flush=True)
    child.close()
""")


def test_a_forked_copy_cannot_use_the_makers_renderer_and_the_maker_keeps_drawing():
    """A forked copy shares the socket: were it to draw, its messages and the maker's would
    interleave; at its exit it must not close the maker's child either."""
    result = subprocess.run([sys.executable, "-c", FORK], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr[-3000:]
    lines = result.stdout.strip().splitlines()
    assert lines[0].startswith("fork: this ChildRenderer belongs to the process that made it"), lines
    assert lines[1] == "maker: True", lines
