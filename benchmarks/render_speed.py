"""Offscreen rendering speed: frames per second at 640x480, with and without the overlays.

Run: python benchmarks/render_speed.py [--width 640 --height 480 --frames 40 --camera follow]

All in this run, on the platform MUJOCO_GL names (sailmujoco's default: EGL; Mesa's llvmpipe
on a CPU machine), for one state of wille_yacht on a beam reach:

* ``scene + wind arrow``: :class:`sailmujoco.video.SceneRenderer` (``mujoco.Renderer`` of the
  display model, shadows and reflections off) with only the wind arrow added;
* ``+ force arrows``: with the sail, keel and rudder force arrows;
* ``+ force arrows + panel``: with the side panel too (map, numbers, colour key: what ``record`` draws);
* ``... in a child process``: the same frame drawn by :class:`sailmujoco.video.child.ChildRenderer`,
  as ``record()`` and the Gymnasium environments draw it (the snapshot sent to the child, the
  pixels sent back); its ratio to the line above is the cost of keeping GL out of the caller's
  process. Starting the child (a fresh interpreter, the GL platform, the scene) is timed apart,
  and so is the round trip alone (the snapshot out, the frame's bytes back, over the same kind of
  socket pair with the same calls, to a child that draws nothing), which llvmpipe's frame-to-frame
  spread on a shared machine would hide;
* ``record()``: the whole pipeline (simulation, drawing in the child, H.264 encoding by ffmpeg),
  in video frames per wall-clock second.

Rendering on llvmpipe uses every core; on a shared machine the load average is printed with
the result.
"""

from __future__ import annotations

import argparse
import math
import os
import socket
import subprocess
import sys
import tempfile
import time
from multiprocessing.connection import Connection
from pathlib import Path

import numpy as np

from sailmujoco import suite, sweep, video

ECHO = """
import sys
from multiprocessing.connection import Connection
import numpy as np
conn = Connection(int(sys.argv[1]))
frame = np.full(tuple(int(n) for n in sys.argv[2:]), 7, np.uint8)
while True:
    try:
        conn.recv()
    except EOFError:
        break
    conn.send(("ok", frame.shape))
    conn.send_bytes(frame.reshape(-1))
"""


def best_rates(calls: dict, frames: int, repeats: int) -> dict:
    """Frames per second of each call: the fastest of ``repeats`` runs of ``frames`` calls,
    the calls taking turns so that a change of machine load hits them alike."""
    for fn in calls.values():  # warm up (shader compilation, texture upload)
        for _ in range(3):
            fn()
    best = dict.fromkeys(calls, math.inf)
    for _ in range(repeats):
        for name, fn in calls.items():
            start = time.perf_counter()
            for _ in range(frames):
                fn()
            best[name] = min(best[name], time.perf_counter() - start)
    return {name: frames / seconds for name, seconds in best.items()}


def round_trip_s(snap, width: int, height: int, frames: int, repeats: int) -> float:
    """Seconds of one frame's round trip with nothing drawn: ``snap`` sent to a child process,
    ``height x width x 3`` bytes back, as ``ChildRenderer.render`` does it; the best of
    ``repeats`` runs of ``frames``."""
    ours, theirs = socket.socketpair()
    with theirs:
        command = [sys.executable, "-c", ECHO, str(theirs.fileno()), str(height), str(width), "3"]
        child = subprocess.Popen(command, pass_fds=(theirs.fileno(),))
    conn = Connection(ours.detach())
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(frames):
            conn.send(("render", snap, None, None))
            frame = np.empty(conn.recv()[1], np.uint8)
            conn.recv_bytes_into(frame.reshape(-1))
        best = min(best, (time.perf_counter() - start) / frames)
    conn.close()
    child.wait()
    assert frame.shape == (height, width, 3) and frame[0, 0, 0] == 7
    return best


def gl_renderer_name() -> str:
    try:
        from OpenGL import GL

        return GL.glGetString(GL.GL_RENDERER).decode()
    except Exception as err:  # informative only
        return f"unknown ({type(err).__name__})"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--frames", type=int, default=20, help="frames per timed run")
    parser.add_argument("--repeats", type=int, default=5, help="timed runs per case (best kept)")
    parser.add_argument("--camera", default="follow", choices=video.CAMERAS)
    parser.add_argument("--seconds", type=float, default=4.0, help="simulated seconds for record()")
    args = parser.parse_args()

    env = suite.load("wille_yacht", "beam_reach_roll", seed=0)
    policy = sweep.make_controller("pid", env)
    policy.reset(0)
    timestep = env.reset()
    while env.physics.time() < 10.0 - 1e-9:
        timestep = env.step(policy(timestep))
    snap = video.snapshot_physics(env.physics)

    renderers = {name: video.SceneRenderer(env.physics.params, args.width, args.height, args.camera,
                                           forces=forces, overlay=overlay)
                 for name, forces, overlay in (("scene + wind arrow", False, False),
                                               ("+ force arrows", True, False),
                                               ("+ force arrows + panel", True, True))}
    start = time.perf_counter()
    child = video.ChildRenderer().open(env.physics.params, args.width, args.height, args.camera)
    child_start = time.perf_counter() - start
    calls = {name: (lambda r=r: r.render(snap)) for name, r in renderers.items()}
    calls["+ force arrows + panel, in a child process"] = lambda: child.render(snap)
    rates = best_rates(calls, args.frames, args.repeats)
    platform = gl_renderer_name()  # the last in-process renderer's context is current
    for renderer in [*renderers.values(), child]:
        renderer.close()

    with tempfile.TemporaryDirectory() as tmp:
        rec = video.record("wille_yacht", "beam_reach_roll", "pid", Path(tmp) / "bench.mp4",
                           seconds=args.seconds, width=args.width, height=args.height,
                           camera=args.camera)
    rates["record() (sim + draw + encode)"] = rec.render_rate

    print(f"offscreen rendering, {args.width}x{args.height}, camera {args.camera}, "
          f"MUJOCO_GL={os.environ.get('MUJOCO_GL', 'unset (egl)')}, GL renderer: {platform}")
    print(f"cores {os.cpu_count()}, load average {os.getloadavg()[0]:.1f} (shared machines: "
          "rendering on llvmpipe competes for every core)")
    width = max(len(k) for k in rates)
    for name, rate in rates.items():
        print(f"  {name:{width}s}  {rate:6.1f} frames/s  ({1e3 / rate:6.1f} ms/frame)")
    ratio = rates["+ force arrows + panel, in a child process"] / rates["+ force arrows + panel"]
    trip = round_trip_s(snap, args.width, args.height, 10 * args.frames, args.repeats)
    print(f"  in a child process / in this one: {ratio:.3f}; starting the child and its scene: "
          f"{child_start:.2f} s; the round trip alone: {1e3 * trip:.2f} ms/frame "
          f"({trip * rates['+ force arrows + panel']:.1%} of a frame drawn here)")
    print(f"  record(): {rec.frames} frames of {rec.sim_time:.1f} s simulated in {rec.loop_time:.1f} s "
          f"({rec.wall_time:.1f} s with loading the boat and the controller)")


if __name__ == "__main__":
    main()
