"""The exception every world raises when its simulation leaves the valid state space."""

from __future__ import annotations


class SimulationStopped(RuntimeError):
    """The simulation left the valid state space; ``reason`` says how.

    Parameters
    ----------
    reason : str
        Why the run stopped (for example "capsized: |heel| > 90 deg").
    time : float
        Simulated time at which it stopped, s.
    """

    def __init__(self, reason: str, time: float):
        super().__init__(f"simulation stopped at t = {time:.3f} s: {reason}")
        self.reason = reason
        self.time = time
