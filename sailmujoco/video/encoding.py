"""Frames to an mp4: the writer that draws snapshots and sends them to ffmpeg (the binary the
``imageio-ffmpeg`` package ships), and the hidden file it writes until the film is complete."""

from __future__ import annotations

import os
from contextlib import contextmanager
from pathlib import Path

from ..progress import Progress
from .child import ChildRenderer
from .scene import SceneRenderer, Snapshot


def encoder():
    """The ``imageio_ffmpeg`` module (its ffmpeg binary encodes the mp4)."""
    try:
        import imageio_ffmpeg
    except ImportError as err:
        raise ImportError("video needs imageio-ffmpeg: pip install imageio-ffmpeg") from err
    return imageio_ffmpeg


class FrameWriter:
    """The frames of one recording: when the next one is due, drawing it and sending it to ffmpeg.

    Parameters
    ----------
    renderer : SceneRenderer or ChildRenderer
        Draws each snapshot (closed with the writer).
    path : Path
        The mp4 written.
    fps : float
        Frames per second of video (and per simulated second, for :meth:`due`).
    n_frames : int
        Frames the recording will hold.
    quality : float
        imageio-ffmpeg quality, 1-10.
    progress : bool
        A progress bar.
    """

    def __init__(self, renderer: SceneRenderer | ChildRenderer, path: Path, fps: float, n_frames: int,
                 quality: float, progress: bool):
        self.renderer, self.fps, self.n_frames = renderer, fps, n_frames
        self.count = 0
        self.last = None  # (snapshot, frame) of the last frame drawn
        self.writer = encoder().write_frames(
            str(path), (renderer.width, renderer.height), fps=fps, codec="libx264", quality=quality,
            macro_block_size=1, ffmpeg_log_level="error",
            output_params=["-preset", "faster", "-movflags", "+faststart"])
        self.writer.send(None)
        self.bar = Progress(n_frames, "video", show=progress, unit="frame")

    def due(self) -> float | None:
        return self.count / self.fps if self.count < self.n_frames else None

    def emit(self, snap: Snapshot) -> None:
        """Draw ``snap`` as the next frame.

        Parameters
        ----------
        snap : Snapshot
            The state drawn.
        """
        frame = self.renderer.render(snap)
        self.writer.send(frame)
        self.count += 1
        self.last = (snap, frame)
        self.bar.update()

    def hold(self, frame, n: int) -> None:
        """Send ``frame`` ``n`` more times.

        Parameters
        ----------
        frame : numpy.ndarray
            An RGB frame already drawn.
        n : int
            How many more times.
        """
        for _ in range(n):
            self.writer.send(frame)
            self.count += 1

    def close(self) -> None:
        self.writer.close()
        self.renderer.close()
        self.bar.close()


@contextmanager
def partial_file(out_path: Path):
    """A hidden name beside ``out_path`` (its folders made) to write to; renamed to ``out_path``
    when the block ends without error, removed otherwise.

    Parameters
    ----------
    out_path : Path
        The file the block makes.
    """
    out_path.parent.mkdir(parents=True, exist_ok=True)
    partial = out_path.with_name(f".{out_path.stem}.partial{out_path.suffix or '.mp4'}")
    ok = False
    try:
        yield partial
        ok = True
    finally:
        if ok:
            os.replace(partial, out_path)
        else:
            partial.unlink(missing_ok=True)
