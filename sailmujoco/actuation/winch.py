"""A sheet winch whose pull is limited by its motor's torque against the sheet's load.

A DC motor's torque falls linearly with its speed, from the stall torque at rest to zero at the
no-load speed. Hauling in against a sheet load ``T`` on a drum of radius ``r`` takes the torque
``T r``, so the winch hauls in at

    v_in = v_free (1 - T r / tau_stall)        (0 once T r >= tau_stall: it cannot pull in),

and eases out, the load helping, at up to its no-load speed ``v_free`` (the linear torque-speed
line of a permanent-magnet DC motor at a fixed voltage; Hughes and Drury, *Electric Motors and
Drives*, ch. 3). A sail winch of the RMG 280D class goes from full in to full out in about 1.3 s.
"""

from __future__ import annotations

import math


class SheetWinch:
    """Sheet length following a command at the speed its torque allows.

    Parameters
    ----------
    free_speed : float
        No-load sheet speed, m/s, > 0.
    stall_torque : float
        Torque at stall, N m, > 0.
    drum_radius : float
        Drum radius, m, > 0.
    dt : float
        The step, s, > 0.
    """

    def __init__(self, free_speed: float, stall_torque: float, drum_radius: float, dt: float):
        for name, value in (("free_speed", free_speed), ("stall_torque", stall_torque),
                            ("drum_radius", drum_radius), ("dt", dt)):
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise ValueError(f"winch {name} must be a finite number > 0, got {value!r}")
        self.free_speed, self.stall_force = float(free_speed), float(stall_torque) / float(drum_radius)
        self.dt = float(dt)
        self.length = None

    def haul_speed(self, load: float) -> float:
        """The speed (m/s) at which it hauls in against a sheet load.

        Parameters
        ----------
        load : float
            The sheet's tension, N (>= 0).
        """
        return self.free_speed * max(0.0, 1.0 - max(load, 0.0) / self.stall_force)

    def step(self, command: float, load: float) -> float:
        """The sheet length after one step towards ``command``.

        Parameters
        ----------
        command : float
            The commanded sheet length, m.
        load : float
            The sheet's tension, N.
        """
        if self.length is None:
            self.length = command
            return self.length
        change = command - self.length
        if change < 0.0:  # hauling in: shorter sheet, against the load
            self.length += max(change, -self.haul_speed(load) * self.dt)
        else:  # easing out
            self.length += min(change, self.free_speed * self.dt)
        return self.length
