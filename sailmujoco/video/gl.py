"""The OpenGL platform of offscreen rendering, and the one error that names its fixes.

The platform is the one ``MUJOCO_GL`` names, or EGL when it is unset (Mesa's llvmpipe on the
CPU, the NVIDIA driver on a GPU); it is loaded at the first render
(:mod:`sailmujoco.gl_platform`), never when sailmujoco is imported.
"""

from __future__ import annotations

import atexit
import os
import weakref

from .. import gl_platform

FIX = ("leave MUJOCO_GL unset or set MUJOCO_GL=egl (Mesa's EGL renders on the CPU: apt-get install "
       "libegl1 libegl-mesa0 libgl1-mesa-dri; on a GPU the NVIDIA driver provides EGL), or "
       "apt-get install libosmesa6 and set MUJOCO_GL=osmesa")


class RenderingUnavailable(RuntimeError):
    """No OpenGL platform could be loaded for offscreen rendering; the message names the fix."""


def _unavailable(err: BaseException) -> RenderingUnavailable:
    backend = os.environ.get("MUJOCO_GL")
    named = f"MUJOCO_GL={backend!r}" if backend is not None else f"MUJOCO_GL unset ({gl_platform.DEFAULT})"
    return RenderingUnavailable(
        f"cannot render offscreen: no OpenGL platform could be loaded with {named} "
        f"({type(err).__name__}: {err}). Fix: {FIX}.")


def import_gl():
    """Import MuJoCo with its offscreen renderer on the requested GL platform, loading it.

    Returns
    -------
    module
        ``mujoco``.

    Raises
    ------
    RenderingUnavailable
        The GL platform cannot load.
    """
    try:
        mujoco = gl_platform.use_platform()
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
        renderer = mujoco.Renderer(model, height, width, max_geom=2000)
    except Exception as err:  # GL context or MjrContext creation
        raise _unavailable(err) from err
    if not _LIVE:
        # MuJoCo's EGL registers eglTerminate at exit when it makes its first context; exit
        # handlers run last-registered first, so this one frees the renderers still open (a
        # Gymnasium environment nobody closed) before it, instead of their __del__ raising
        # EGLError after it
        atexit.register(_close_live)
    _LIVE.add(renderer)
    return renderer


_LIVE: weakref.WeakSet = weakref.WeakSet()  # offscreen renderers not yet garbage-collected


def _close_live() -> None:
    for renderer in list(_LIVE):
        renderer.close()
    _LIVE.clear()


def check_rendering() -> None:
    """Raise :class:`RenderingUnavailable` unless an offscreen GL context can be made here."""
    mujoco = import_gl()
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><visual><global offwidth="16" offheight="16"/></visual>'
        '<worldbody><geom size="1"/></worldbody></mujoco>')
    offscreen_renderer(model, 16, 16).close()
