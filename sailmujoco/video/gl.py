"""The OpenGL platform of offscreen rendering, and the one error that names its fixes.

MuJoCo loads the platform named by ``MUJOCO_GL`` when it is imported; sailmujoco sets it to
``egl`` unless it is set (Mesa's llvmpipe on the CPU, the NVIDIA driver on a GPU).
"""

from __future__ import annotations

import os
import sys

FIX = ("set MUJOCO_GL=egl before starting Python (Mesa's EGL renders on the CPU: apt-get install "
       "libegl1 libegl-mesa0 libgl1-mesa-dri; on a GPU the NVIDIA driver provides EGL), or "
       "apt-get install libosmesa6 and set MUJOCO_GL=osmesa")


class RenderingUnavailable(RuntimeError):
    """No OpenGL platform could be loaded for offscreen rendering; the message names the fix."""


def _loaded_platform() -> str | None:
    """The GL platform mujoco loaded when it was imported ('egl', 'glfw', 'osmesa'), if any."""
    mujoco = sys.modules.get("mujoco")
    context = getattr(mujoco, "GLContext", None)
    return context.__module__.split(".")[1] if context is not None else None


def _unavailable(err: BaseException) -> RenderingUnavailable:
    backend = os.environ.get("MUJOCO_GL", "")
    loaded = _loaded_platform()
    late = ""
    if loaded is not None and loaded != backend.lower():
        late = (f" mujoco was imported before MUJOCO_GL was set and loaded {loaded!r}: set MUJOCO_GL "
                "in the environment, or import sailmujoco before mujoco.")
    return RenderingUnavailable(
        f"cannot render offscreen: no OpenGL platform could be loaded with MUJOCO_GL={backend!r} "
        f"({type(err).__name__}: {err}).{late} Fix: {FIX}.")


def import_gl():
    """Import MuJoCo with its offscreen renderer.

    Returns
    -------
    module
        ``mujoco``.

    Raises
    ------
    RenderingUnavailable
        The GL platform cannot load (mujoco loads the MUJOCO_GL platform when it is imported).
    """
    try:
        import mujoco
    except Exception as err:  # AttributeError, OSError, RuntimeError... from PyOpenGL/mujoco
        raise _unavailable(err) from err
    if not hasattr(mujoco, "Renderer"):
        raise _unavailable(ImportError("mujoco has no offscreen Renderer for this GL platform"))
    return mujoco


def offscreen_renderer(model, width: int, height: int):
    """A ``mujoco.Renderer`` (its GL context is made here).

    Parameters
    ----------
    model : mujoco.MjModel
        The model drawn.
    width, height : int
        Frame size, pixels.

    Raises
    ------
    RenderingUnavailable
        No GL context can be made.
    """
    mujoco = import_gl()
    try:
        return mujoco.Renderer(model, height, width, max_geom=2000)
    except Exception as err:  # GL context or MjrContext creation
        raise _unavailable(err) from err


def check_rendering() -> None:
    """Raise :class:`RenderingUnavailable` unless an offscreen GL context can be made here."""
    mujoco = import_gl()
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><visual><global offwidth="16" offheight="16"/></visual>'
        '<worldbody><geom size="1"/></worldbody></mujoco>')
    offscreen_renderer(model, 16, 16).close()
