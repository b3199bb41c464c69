"""Importing sailmujoco loads no OpenGL library; the first render loads one.

Mesa's EGL brings Mesa's own LLVM into the process, and PyTorch's triton, loaded after it,
crashes the process with its own: so no GL library may be mapped until something is drawn.
Each check runs in a fresh interpreter, whose /proc/self/maps lists the shared libraries
it has loaded.
"""

import os
import subprocess
import sys
import textwrap

GL_LIBRARIES = ("libEGL", "libGL.", "libGLX", "libGLdispatch", "libOSMesa")
DRIVERS = ("libLLVM", "_dri.so", "libgallium")  # what initialising Mesa's EGL maps

SCRIPT = textwrap.dedent("""
    import os, json
    import sailmujoco, sailmujoco.suite, sailmujoco.gym, sailmujoco.sweep, sailmujoco.video

    def mapped():
        return sorted({line.split()[-1] for line in open("/proc/self/maps")
                       if any(name in line for name in NAMES)})

    after_import = mapped()
    variable = os.environ.get("MUJOCO_GL")
    env = sailmujoco.suite.load("saoud_robot", "heading_hold", seed=0, time_limit=1.0)
    env.reset()
    pixels = env.physics.render(24, 32)  # dm_control's own render, on the deferred platform
    sailmujoco.video.check_rendering()  # the videos' renderer
    print(json.dumps({"after_import": after_import, "variable": variable, "after_render": mapped(),
                      "shape": list(pixels.shape), "spread": float(pixels.std())}))
""").replace("NAMES", repr(GL_LIBRARIES + DRIVERS))


def _run(**variables) -> dict:
    import json

    env = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "PYOPENGL_PLATFORM")}
    env.update(variables)
    result = subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True, text=True,
                            timeout=600)
    assert result.returncode == 0, result.stderr[-3000:]
    return json.loads(result.stdout.strip().splitlines()[-1])


def test_import_loads_no_gl_and_a_render_loads_egl():
    seen = _run()
    assert seen["after_import"] == [], seen["after_import"]
    assert seen["variable"] is None  # the environment is left as it was found
    assert any("libEGL" in path for path in seen["after_render"]), seen["after_render"]
    assert seen["shape"] == [24, 32, 3] and seen["spread"] > 1.0  # a picture, not a blank frame


def test_a_platform_the_user_names_is_respected():
    """MUJOCO_GL=egl set by the user: MuJoCo loads libEGL at import, as it documents, and
    renders with it; dm_control's import, which would initialise an EGL display and so map
    Mesa's driver and LLVM, is made to wait for the first render."""
    seen = _run(MUJOCO_GL="egl")
    assert seen["variable"] == "egl"
    assert any("libEGL" in path for path in seen["after_import"])
    assert not [path for path in seen["after_import"] if any(name in path for name in DRIVERS)]
    assert seen["shape"] == [24, 32, 3] and seen["spread"] > 1.0


def test_a_renderer_left_open_exits_quietly():
    """A Gymnasium environment rendered and never closed: MuJoCo's EGL terminates its display at
    exit, and the renderer still open is freed before that, not in a __del__ that raises after."""
    script = textwrap.dedent("""
        import gymnasium, sailmujoco.gym
        env = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", render_mode="rgb_array",
                             render_width=64, render_height=48)
        env.reset(seed=0)
        print(env.render().shape)
    """)
    env = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "PYOPENGL_PLATFORM")}
    result = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True,
                            timeout=600)
    assert result.returncode == 0 and result.stdout.strip() == "(48, 64, 3)", result.stderr[-3000:]
    assert "Exception ignored" not in result.stderr and "EGLError" not in result.stderr, result.stderr
