"""What our side of ArduPilot's lock-step costs a frame, against the bare step of the same model.

Run: python benchmarks/sitl_frame_cost.py [--frames N] [--rounds R]

For each boat, a frame of ``sailmujoco sitl`` without the socket (``JsonBackend.handle``: parse
the servo packet, set rudder and sheet, one 5 ms physics step, the vane, the state in NED/FRD,
the JSON line, the trajectory row) on a beam reach, against the bare ``mujoco.mj_step`` of the
boat's compiled sheeted model, interleaved round by round in one run (medians). The simulated
seconds our side could answer per wall-clock second bound the lock-step's speed from above;
ArduPilot's own frame takes the rest (docs/ardupilot.md gives the whole loop's speed).
"""

from __future__ import annotations

import argparse
import statistics
import time

import mujoco

from sailmujoco.physics import BoatPhysics
from sailmujoco.sitl.backend import JsonBackend
from sailmujoco.sitl.protocol import servo_packet

BOATS = ("saoud_robot", "wille_yacht")


def frame_seconds(backend: JsonBackend, frames: int, start: int) -> float:
    """Seconds per answered frame over ``frames`` frames numbered from ``start``."""
    pwm = [1500] * 16
    pwm[3] = 1400  # the sheet a little in: sailing
    packets = [servo_packet(pwm, 200, start + k) for k in range(frames)]
    t0 = time.perf_counter()
    for packet in packets:
        backend.handle(packet)
    return (time.perf_counter() - t0) / frames


def bare_seconds(boat: str, steps: int) -> float:
    """Seconds per bare mj_step of the boat's compiled sheeted model."""
    model = BoatPhysics.load(boat, sail_mode="sheeted").model.ptr
    data = mujoco.MjData(model)
    t0 = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return (time.perf_counter() - t0) / steps


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--frames", type=int, default=4000)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    print("boat          bare mj_step   sitl frame   frame/bare   simulated s per wall s (our side)")
    for boat in BOATS:
        backend = JsonBackend(boat, wind_speed=5.0, wind_from_deg=90.0)
        count = 0
        frame_seconds(backend, 400, count)  # warm-up
        count += 400
        frames, bare = [], []
        for _ in range(args.rounds):
            bare.append(bare_seconds(boat, args.frames))
            frames.append(frame_seconds(backend, args.frames, count))
            count += args.frames
        f, b = statistics.median(frames), statistics.median(bare)
        print(f"{boat:12s} {b * 1e6:10.1f} us {f * 1e6:10.1f} us {f / b:10.1f} {backend.dt / f:16.0f}")
    print(f"(mujoco {mujoco.__version__}; medians of {args.rounds} rounds of {args.frames} frames)")


if __name__ == "__main__":
    main()
