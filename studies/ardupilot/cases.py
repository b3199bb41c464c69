"""The flights the comparison makes: each simulator, calm and in the sea, on its seeds.

ArduPilot's parameters are its rover and sailboat defaults, except on our boats
``SAIL_ANGLE_IDEAL`` (the angle of attack ArduPilot sheets the sail to, 25 deg by default), set to
the angle at which the boat's sail stalls (its ``sail.suction_stall``, 15 deg on both: Saoud (2015)
§VII-A's flat sail). At 25 deg both sails are stalled; the robot, sheeted so, cannot hold a
close-hauled course and makes no ground to windward. One case keeps the default on the robot to
show it.
SIM_Sailboat keeps every default: it is what ArduPilot's sailboat defaults are tuned against.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

SIMULATORS = (("sailboat", "ArduPilot's SIM_Sailboat"), ("wille_yacht", "wille_yacht, 6-DOF"),
              ("saoud_robot", "saoud_robot, 6-DOF"))
ROBOT_MOTOR_N = 10.0  # the robot's auxiliary motor in the sea, N at full throttle (about 1 kgf)


@dataclass(frozen=True)
class Case:
    """One flight to make.

    Parameters
    ----------
    simulator : str
        ``"sailboat"`` or one of our boats.
    sea : bool
        The 1 m sea.
    seed : int
        Its seed.
    tuned : bool
        ``SAIL_ANGLE_IDEAL`` set to the sail's stall angle (our boats).
    parameters : dict
        Further ArduPilot parameters.
    motor : float
        Our boat's auxiliary motor, N at full throttle (0: none).
    """

    simulator: str
    sea: bool
    seed: int
    tuned: bool = True
    parameters: dict = field(default_factory=dict)
    motor: float = 0.0

    @property
    def name(self) -> str:
        """The simulator's name in the report."""
        name = dict(SIMULATORS)[self.simulator]
        if self.motor:
            name = f"{name}, {self.motor:g} N motor"
        return name if self.tuned or self.simulator == "sailboat" else f"{name}, SAIL_ANGLE_IDEAL 25"

    @property
    def label(self) -> str:
        """The case (without the seed)."""
        return f"{self.name}, {'1 m sea' if self.sea else 'calm'}"

    @property
    def folder(self) -> str:
        """The flight's folder under ``flights/``."""
        tag = "" if self.tuned or self.simulator == "sailboat" else "_default_ideal"
        tag += f"_motor{self.motor:g}" if self.motor else ""
        return f"{self.simulator}{tag}_{'sea' if self.sea else 'calm'}_seed{self.seed}"


def cases(seeds: int) -> list[Case]:
    """Every flight: calm twice (nothing is drawn in a steady wind: the two show it), the sea on
    seeds ``0 .. seeds-1`` for our boats (their sea's phases) and twice for SIM_Sailboat (one sine,
    nothing drawn); in the sea the robot carries a ``ROBOT_MOTOR_N`` motor, which ArduPilot runs
    to finish a tack that takes longer than 5 s (without it, twice: its tacks stall in the waves);
    and the robot once with ArduPilot's own ``SAIL_ANGLE_IDEAL``.

    Parameters
    ----------
    seeds : int
        N, the flights of each of our boats in the sea.
    """
    out = []
    for simulator, _ in SIMULATORS:
        out += [Case(simulator, False, seed) for seed in range(2)]
        if simulator == "saoud_robot":
            out += [Case(simulator, True, seed, motor=ROBOT_MOTOR_N) for seed in range(seeds)]
            out += [Case(simulator, True, seed) for seed in range(2)]
        else:
            out += [Case(simulator, True, seed) for seed in range(2 if simulator == "sailboat" else seeds)]
    out.append(Case("saoud_robot", False, 0, tuned=False))
    return out


def ours_parameters(boat: str) -> dict:
    """ArduPilot's parameters for one of our boats: ``SAIL_ANGLE_IDEAL`` at its sail's stall.

    Parameters
    ----------
    boat : str
        A registered boat or a boat file.
    """
    from sailmujoco.boat.catalogue import get_boat

    return {"SAIL_ANGLE_IDEAL": round(math.degrees(get_boat(boat).sail.suction_stall), 1)}
