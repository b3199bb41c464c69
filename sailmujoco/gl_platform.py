"""Which OpenGL platform renders, chosen when something is first rendered, not at import.

MuJoCo's Python bindings and dm_control each pick an OpenGL platform when they are imported,
from the environment variable ``MUJOCO_GL``; dm_control, with the variable unset, even calls
``glfw.init()`` then and falls back to EGL, and with ``MUJOCO_GL=egl`` it initialises an EGL
display at import. Initialising Mesa's EGL maps Mesa's own LLVM into the process, and a
process that then loads PyTorch's triton (with another LLVM) crashes with a segmentation fault.
So importing sailmujoco initialises no GL platform, and the frames of videos and of the
Gymnasium environments are drawn in a child process (:mod:`sailmujoco.video.child`):

- :func:`import_dm_control_mujoco` imports dm_control with its renderer left unchosen (the
  variable is set to ``disable`` for that import only, then put back as it was found);
  dm_control's first ``Physics.render`` loads :func:`requested`'s platform.
- ``MUJOCO_GL`` set by the user: that platform renders. MuJoCo's own import loads its library
  (``libEGL``, which loads no driver and no LLVM until a display is initialised).
- ``MUJOCO_GL`` unset: the first render (:func:`use_platform`, or dm_control's
  ``Physics.render``) loads :data:`DEFAULT`, EGL: Mesa's llvmpipe on a CPU machine, the NVIDIA
  driver on a GPU. EGL needs no display, so the same default works on a laptop, a headless
  server and a cluster.

The choice is process-wide, like MuJoCo's and dm_control's own, and is owned here.
"""

from __future__ import annotations

import importlib
import os
import sys

DEFAULT = "egl"  # the platform used when MUJOCO_GL is unset
PLATFORMS = ("egl", "osmesa", "glfw")  # the platforms MuJoCo's Python bindings offer on Linux
_OFF = ("disable", "disabled", "off", "false", "0")  # MuJoCo's and dm_control's names for none


def requested() -> str:
    """The platform to render with: ``MUJOCO_GL`` as set now, lower case, or :data:`DEFAULT`."""
    return os.environ.get("MUJOCO_GL", "").strip().lower() or DEFAULT


def import_dm_control_mujoco():
    """Import ``dm_control.mujoco`` without initialising a GL platform.

    dm_control's renderer is imported with no platform and replaced by one that loads
    :func:`requested` when ``Physics.render`` first makes a context; ``MUJOCO_GL`` is left as
    it was found. Where dm_control's renderer was imported before (by the caller), it keeps the
    platform it chose.

    Returns
    -------
    module
        ``dm_control.mujoco``.
    """
    if "dm_control._render" not in sys.modules:
        found = os.environ.get("MUJOCO_GL")
        os.environ["MUJOCO_GL"] = "disable"
        try:
            from dm_control import _render
        finally:
            if found is None:
                del os.environ["MUJOCO_GL"]
            else:
                os.environ["MUJOCO_GL"] = found
        _render.BACKEND = None
        _render.Renderer = _deferred_dm_control_context
    return importlib.import_module("dm_control.mujoco")


def _deferred_dm_control_context(*args, **kwargs):
    """dm_control's ``Renderer`` factory, choosing the platform at the first context."""
    from dm_control import _render

    platform = requested()
    for names, importer in _render._ALL_RENDERERS:
        if platform in names:
            _render.Renderer = importer()
            _render.BACKEND = names[0]
            return _render.Renderer(*args, **kwargs)
    raise _refused(platform)


def _refused(platform: str) -> RuntimeError:
    """The error for a ``MUJOCO_GL`` that names no platform (off, or unknown)."""
    if platform in _OFF:
        return RuntimeError(f"MUJOCO_GL={platform!r} turns rendering off")
    return RuntimeError(f"MUJOCO_GL must be one of {', '.join(PLATFORMS)}: got {platform!r}")


def use_platform():
    """Make MuJoCo's ``mujoco.Renderer`` draw on :func:`requested`'s platform, loading it now.

    MuJoCo chose a ``GLContext`` class when it was imported (GLFW's, with ``MUJOCO_GL``
    unset); when that is not the requested platform, the requested one is imported and put in
    its place.

    Returns
    -------
    module
        ``mujoco``, with ``mujoco.Renderer`` making contexts on the requested platform.

    Raises
    ------
    ImportError, OSError, RuntimeError, AttributeError
        The platform's library cannot be loaded (the caller names the fixes).
    """
    import mujoco
    from mujoco.rendering.classic import gl_context

    platform = requested()
    if platform not in PLATFORMS:
        raise _refused(platform)
    current = getattr(gl_context, "GLContext", None)
    if current is None or current.__module__.split(".")[1] != platform:
        chosen = importlib.import_module(f"mujoco.{platform}").GLContext
        gl_context.GLContext = chosen
        mujoco.GLContext = chosen
    return mujoco

