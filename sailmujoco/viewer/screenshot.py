"""``sailmujoco view --screenshot``: the picture of the state at the time it names.

The viewer draws on a thread of its own, at its own pace; a grab of the screen shows whatever
frame it drew last, which under load can be a state from a second or more before. The
screenshot is therefore drawn here, offscreen, from the state itself (:func:`render_state`):
the viewer's camera as it is at that moment, the scene of the videos
(:class:`sailmujoco.video.SceneRenderer`) at the window's size, with the panel (map, track,
numbers) beside it. The PNG carries the state's time and the camera in its text chunks
(:data:`TIME_KEY`, :data:`CAMERA_KEY`), so that a reader can check which state it shows.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

TIME_KEY = "sailmujoco:time"  # PNG text: the simulated time of the state drawn, s (repr of a float)
CAMERA_KEY = "sailmujoco:camera"  # PNG text: JSON [lookat x, y, z, distance, azimuth, elevation]


def render_state(scene, snap, camera, width: int, height: int) -> np.ndarray:
    """The frame of ``snap`` (height, width, 3) uint8, drawn offscreen like the videos.

    Parameters
    ----------
    scene : SceneRenderer
        The window's scene (without an offscreen context): its boat, options, track so far and
        force scale are drawn.
    snap : Snapshot
        The state drawn.
    camera : tuple
        (lookat (3,), distance, azimuth deg, elevation deg) of MuJoCo's free camera.
    width, height : int
        Frame size, pixels.
    """
    from ..video import SceneRenderer

    offscreen = SceneRenderer(scene.params, width, height, "follow", forces=scene.show_forces,
                              overlay=scene.show_overlay, target=scene.target, labels=scene.labels)
    try:
        offscreen.track = list(scene.track)
        offscreen.force_scale = scene.force_scale
        return offscreen.render(snap, camera=camera)
    finally:
        offscreen.close()


def save_frame(path, frame: np.ndarray, time: float, camera) -> str:
    """Write ``frame`` as a PNG with the state's time and the camera in its text chunks.

    Parameters
    ----------
    path : str or path
        The PNG; missing folders are made.
    frame : ndarray
        (height, width, 3) uint8 RGB.
    time : float
        Simulated time of the state drawn, s.
    camera : tuple
        (lookat (3,), distance, azimuth deg, elevation deg).

    Returns
    -------
    str
        What was saved, for the command's last line.
    """
    from PIL import Image
    from PIL.PngImagePlugin import PngInfo

    info = PngInfo()
    info.add_text(TIME_KEY, repr(float(time)))
    lookat, distance, azimuth, elevation = camera
    info.add_text(CAMERA_KEY, json.dumps([*map(float, lookat), float(distance), float(azimuth),
                                          float(elevation)]))
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(frame).save(path, pnginfo=info)
    return (f"the state at t = {time:.2f} s from the window's camera, {frame.shape[1]} x "
            f"{frame.shape[0]} px")


def read_stamp(path) -> tuple[float, tuple]:
    """(time, camera) written by :func:`save_frame` into a PNG.

    Parameters
    ----------
    path : str or path
        The PNG.
    """
    from PIL import Image

    with Image.open(path) as image:
        text = image.text
    values = json.loads(text[CAMERA_KEY])
    return float(text[TIME_KEY]), (np.array(values[:3]), *values[3:])
