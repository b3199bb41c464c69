"""A window's picture as it is on the X screen (``sailmujoco view --screenshot``), found through Xlib."""

from __future__ import annotations

import ctypes
import ctypes.util
import os
from pathlib import Path


def window_rect(title_prefix: str) -> tuple[int, int, int, int] | None:
    """(x, y, width, height) on the X screen of the first window whose name starts with
    ``title_prefix``, found through Xlib; None where Xlib or the window cannot be found.

    Parameters
    ----------
    title_prefix : str
        The start of the window's name.
    """
    name = ctypes.util.find_library("X11")
    if not name:
        return None
    x = ctypes.CDLL(name)
    x.XOpenDisplay.restype = ctypes.c_void_p
    x.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x.XDefaultRootWindow.restype = ctypes.c_ulong
    x.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
    window_p = ctypes.POINTER(ctypes.c_ulong)
    x.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, window_p, window_p,
                             ctypes.POINTER(window_p), ctypes.POINTER(ctypes.c_uint)]
    x.XFetchName.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_char_p)]
    x.XGetGeometry.argtypes = [ctypes.c_void_p, ctypes.c_ulong, window_p] + \
        [ctypes.POINTER(ctypes.c_int)] * 2 + [ctypes.POINTER(ctypes.c_uint)] * 4
    x.XTranslateCoordinates.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_ulong,
                                        ctypes.c_int, ctypes.c_int, ctypes.POINTER(ctypes.c_int),
                                        ctypes.POINTER(ctypes.c_int), window_p]
    x.XFree.argtypes = [ctypes.c_void_p]
    x.XCloseDisplay.argtypes = [ctypes.c_void_p]
    display = x.XOpenDisplay(None)
    if not display:
        return None
    root = x.XDefaultRootWindow(display)

    def find(window: int, depth: int = 0):
        title = ctypes.c_char_p()
        if x.XFetchName(display, window, ctypes.byref(title)) and title.value is not None:
            found = title.value.decode(errors="replace").startswith(title_prefix)
            x.XFree(title)
            if found:
                return window
        if depth > 3:
            return None
        root_r, parent, children, count = ctypes.c_ulong(), ctypes.c_ulong(), window_p(), ctypes.c_uint()
        if not x.XQueryTree(display, window, ctypes.byref(root_r), ctypes.byref(parent),
                            ctypes.byref(children), ctypes.byref(count)):
            return None
        try:
            for i in range(count.value):
                hit = find(children[i], depth + 1)
                if hit is not None:
                    return hit
        finally:
            if children:
                x.XFree(children)
        return None

    try:
        window = find(root)
        if window is None:
            return None
        ints = [ctypes.c_int() for _ in range(2)]
        uints = [ctypes.c_uint() for _ in range(4)]
        root_r = ctypes.c_ulong()
        x.XGetGeometry(display, window, ctypes.byref(root_r), *(ctypes.byref(v) for v in ints),
                       *(ctypes.byref(v) for v in uints))
        left, top, child = ctypes.c_int(), ctypes.c_int(), ctypes.c_ulong()
        x.XTranslateCoordinates(display, window, root, 0, 0, ctypes.byref(left), ctypes.byref(top),
                                ctypes.byref(child))
        return left.value, top.value, uints[0].value, uints[1].value
    finally:
        x.XCloseDisplay(display)


def screenshot(path, title_prefix: str = "MuJoCo") -> str:
    """Save a window as it is on the X screen (``DISPLAY``) to ``path`` (PNG).

    Parameters
    ----------
    path : str or path
        The PNG; missing folders are made.
    title_prefix : str
        The start of the window's name (MuJoCo's viewer: "MuJoCo").

    Returns
    -------
    str
        What was saved: the window, or the whole screen where the window cannot be found.
    """
    from PIL import ImageGrab

    image = ImageGrab.grab(xdisplay=os.environ.get("DISPLAY"))
    rect = window_rect(title_prefix)
    what = "the whole screen"
    if rect is not None:
        left, top, width, height = rect
        box = (max(left, 0), max(top, 0), min(left + width, image.width), min(top + height, image.height))
        if box[2] > box[0] and box[3] > box[1]:
            image = image.crop(box)
            what = f"the window ({box[2] - box[0]} x {box[3] - box[1]} px)"
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    image.convert("RGB").save(path)
    return what
