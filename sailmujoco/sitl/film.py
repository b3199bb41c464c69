"""A lock-step run filmed: the boat's state kept ``FILM_RATE_HZ`` times a simulated second while
ArduPilot flies it (a snapshot costs far less than a physics step's share of the lock-step, so the
run keeps its speed), drawn and encoded once the run is over by the same renderer as
``sailmujoco video`` (:class:`sailmujoco.video.scene.SceneRenderer`, in a child process): the boat
heeling, its sail and rudder, the force arrows, the sea, and the panel with its track.

The film plays at ``PLAYBACK_FPS``: ``PLAYBACK_FPS / FILM_RATE_HZ`` times faster than the boat
sailed (a mission of several minutes is a film of about one).
"""

from __future__ import annotations

from pathlib import Path

FILM_RATE_HZ = 5.0  # snapshots per simulated second
PLAYBACK_FPS = 25.0  # frames per second of film: five times faster than real time


def film(snapshots, params, path, *, waves=None, labels: str = "", width: int = 640, height: int = 480,
         progress: bool = True) -> int:
    """Draw ``snapshots`` and encode them as an mp4 at ``path``.

    Parameters
    ----------
    snapshots : list of Snapshot
        The run's states, in time order (:func:`sailmujoco.video.scene.snapshot_physics`).
    params : BoatParams
        The boat.
    path : str or Path
        The mp4 (its folders are made; written under a hidden name and renamed when complete).
    waves : WaveConfig, optional
        The sea drawn (the run's).
    labels : str
        The panel's title.
    width, height : int
        Frame size, pixels (even).
    progress : bool
        A progress bar (plain lines where the output is not a terminal).

    Returns
    -------
    int
        Frames written.
    """
    from ..video.child import ChildRenderer
    from ..video.encoding import FrameWriter, partial_file

    path = Path(path)
    with ChildRenderer() as renderer, partial_file(path) as partial:
        renderer.open(params, width=width, height=height, sail_mode="sheeted", waves=waves, labels=labels)
        frames = FrameWriter(renderer, partial, PLAYBACK_FPS, len(snapshots), quality=6,
                             progress=progress)
        try:
            for snap in snapshots:
                frames.emit(snap)
        finally:
            frames.close()
    return len(snapshots)
