"""The lock-step loop: ArduPilot's SITL sends a servo packet, the boat advances one physics step
and the state goes back as one JSON line; nothing moves between packets.

* Each new frame (its ``frame_count`` one more than the last, or more when frames were lost)
  sets the rudder and the sheet from the packet's channels (:class:`~.servos.ServoMap`),
  advances the boat by one step of its model (``BoatPhysics.timestep()``, 5 ms: SITL adapts its
  own frame time to the timestamps it is sent) and answers.
* A frame sent again (the same ``frame_count``: SITL resends after a silence) gets the same
  answer again, and the boat does not move.
* A ``frame_count`` lower than the last is a SITL that restarted: the boat is reset to its start
  and the timestamps begin again at 0 (a timestamp that goes backwards is SITL's sign of a
  physics reset); nothing of the last run stays.
* A datagram that is not a servo packet is refused, unanswered, with one line (once per kind).
* With ``hold``, the boat lies moored at its start (upright, at rest, nothing stepped; the
  timestamps go on) until ArduPilot steers, its steering pulse more than ``HOLD_DEADBAND_US``
  off the middle for ``HOLD_STEER_S`` of SITL's time: a disarmed ArduPilot holds the middle, one
  in AUTO steers at once (a single frame off the middle is ArduPilot 90700977 setting up its
  outputs, 1.9 s after its start, and lets nothing go). A boat that cannot bear away from rest
  (the robot: let go beam-on at rest, it luffs from 90 to 23 deg off the wind in 15 s with its
  rudder hard over to bear away, never faster than 0.5 m/s) is then launched from a heading of
  the user's choice rather than left to drift beam-on through ArduPilot's start-up.

:meth:`JsonBackend.handle` is the protocol without a socket (the tests drive it);
:meth:`JsonBackend.serve` listens on UDP and answers the address each packet came from.
"""

from __future__ import annotations

import math
import socket
import threading
import time
from dataclasses import dataclass, field

import numpy as np

from ..boat.fitted import sensor_options
from ..boat.geometry import sheet_length
from ..errors import SimulationStopped, check_number
from ..forces.wind import WindConfig
from ..frames import wrap_angle, yaw_from_heading
from ..jit.ordered import mat_vec
from ..measurement.instruments import Instruments
from ..measurement.observation import observe
from ..physics import BoatPhysics
from ..ros2.contract import step_row
from .film import FILM_RATE_HZ
from .protocol import ProtocolError, parse_servo_packet, state_line
from .servos import ServoMap
from .state import boat_state

DEFAULT_PORT = 9002  # ArduPilot's JSON backend; SITL instance -I N uses 9002 + 10 N
RECORD_RATE_HZ = 10.0  # rows of the trajectory table per simulated second
HOLD_DEADBAND_US = 10  # a held boat is let go when the steering pulse is further than this off its middle
HOLD_STEER_S = 0.1  # ... for this long (s of SITL's time)


class SitlError(RuntimeError):
    """A run that cannot go on: one line saying why and what to do."""


@dataclass
class Counters:
    """What a run did: packets answered, resent, refused, resets, wall time.

    Parameters
    ----------
    answered, resent, refused, resets : int
        Frames answered with a step, frames answered again, datagrams refused, SITL restarts.
    wall : float
        Seconds spent serving.
    lock_step : float
        Seconds from the first frame answered to the last: the lock-step's own time, without the
        wait for SITL to come or the silence after it stopped.
    refusals : dict
        A refusal's text -> how often.
    """

    answered: int = 0
    resent: int = 0
    refused: int = 0
    resets: int = 0
    wall: float = 0.0
    lock_step: float = 0.0
    refusals: dict = field(default_factory=dict)


class JsonBackend:
    """A boat as ArduPilot SITL's JSON physics backend.

    Parameters
    ----------
    boat : str or os.PathLike
        A registered boat or a boat file; it sails with its sheeted sail (the mainsail channel is
        a sheet).
    wind_speed : float
        True wind at 10 m, m/s.
    wind_from_deg : float
        Compass bearing the wind comes from, deg.
    gusts : bool
        Gusts and the wind's wander (seeded by ``seed``); False: a steady wind.
    waves : WaveConfig, optional
        The sea (None: calm water); its phases are drawn by its own ``seed``.
    sensors : str, dict or SensorOptions
        The wind vane's figures (:func:`sailmujoco.boat.fitted.sensor_options`; default the
        boat's own). SITL models its own GPS, compass and IMU from the state it is sent.
    servos : ServoMap
        Which channels drive the rudder and the sheet.
    heading_deg : float
        Compass heading the boat starts on, deg.
    seed : int
        Seeds the wind's gusts and the vane's noise.
    hold : bool
        The boat lies moored at its start until ArduPilot first steers (see the module's notes).
    motor_thrust : float
        An auxiliary motor's thrust at full throttle ahead, N (0: none, as our boats are built):
        the throttle channel's fraction of it pushes the hull along its own axis, applied at the
        hull's centre of mass (``xfrc_applied``: outside the force models, so a boat without a
        motor steps exactly as before). ArduPilot runs it to finish a slow tack.
    film : bool
        Keep the boat's state ``FILM_RATE_HZ`` times a simulated second (``self.films``, one list
        per run) for :func:`sailmujoco.sitl.film.film`.
    log : callable, optional
        Called with each one-line report (``print`` on the command line).
    mcap : McapLog, optional
        Each row of the trajectory table also written as ROS 2 messages
        (:class:`sailmujoco.ros2.record.McapLog`, made with no environment): the truth, and the
        vane's reading as the apparent wind; stamped with SITL's clock.
    """

    def __init__(self, boat="saoud_robot", *, wind_speed: float = 5.0, wind_from_deg: float = 0.0,
                 gusts: bool = False, waves=None, sensors=None, servos: ServoMap | None = None,
                 heading_deg: float = 0.0, seed: int = 0, hold: bool = False, motor_thrust: float = 0.0,
                 film: bool = False, log=None, mcap=None):
        wind = WindConfig(speed=float(wind_speed), direction_from=math.radians(wind_from_deg),
                          gusts=bool(gusts), wander=bool(gusts), seed=int(seed))
        self.physics = BoatPhysics.load(boat, sail_mode="sheeted", wind=wind, waves=waves)
        self.params = self.physics.params
        self.sensors = sensor_options(sensors, base=self.params.sensors)
        self.servos = servos or ServoMap()
        self.heading = math.radians(heading_deg)
        self.seed = int(seed)
        self.hold = bool(hold)
        self.motor_thrust = check_number("motor_thrust", motor_thrust, 0.0, 1e4)
        self._hull = int(self.physics.model.ptr.body("hull").id)
        self.film = bool(film)
        self.films: list[list] = []  # the snapshots of each run, when filmed
        self.dt = float(self.physics.timestep())
        low, high = self.physics.action_bounds()
        self._max_rudder, self._sheet_range = float(high[0]), (float(low[1]), float(high[1]))
        self.log = log or (lambda line: None)
        self.mcap = mcap
        self.counters = Counters()
        self.listening = threading.Event()  # set once serve() holds its port
        self.runs: list[list[dict]] = []
        self.reset()

    # ---- the protocol, without a socket
    def reset(self) -> None:
        """The boat at its start (upright, at rest, on its heading); a new trajectory table."""
        self.physics.reset()
        self.physics.place((0.0, 0.0), float(yaw_from_heading(self.heading)), 0.0)
        self._instruments = (None if self.sensors.perfect else
                             Instruments(self.sensors, self.dt, self.seed, len(self.runs)))
        self._last_count = None
        self._last_line = b""
        self._velocity = None
        self._next_row = 0.0
        self._held = self.hold
        self._steered = 0.0  # s the steering has been off its middle while held
        self._moored = 0.0  # s spent moored: SITL's clock is this plus the boat's
        self._next_snapshot = 0.0
        self._thrust = 0.0  # N, the motor's push this step
        self.runs.append([])
        self.films.append([])

    def time(self) -> float:
        """SITL's clock: the time the boat has sailed plus the time it lay moored, s."""
        return self._moored + float(self.physics.data.time)

    def handle(self, data: bytes) -> bytes:
        """The answer to one datagram from SITL.

        Parameters
        ----------
        data : bytes
            A servo packet.

        Returns
        -------
        bytes
            The JSON state line.

        Raises
        ------
        ProtocolError
            ``data`` is not a servo packet (nothing moved).
        SimulationStopped
            The boat stopped (capsized, or its state left the finite numbers).
        """
        packet = parse_servo_packet(data)
        if self._last_count is not None and packet.frame_count < self._last_count:
            self.counters.resets += 1
            self.log(f"sitl: frame {packet.frame_count} after {self._last_count}: SITL restarted, "
                     "the boat starts again")
            self.reset()
        elif packet.frame_count == self._last_count:
            self.counters.resent += 1
            return self._last_line
        steering = packet.channel(self.servos.steering_channel)
        mainsail = packet.channel(self.servos.mainsail_channel)
        if self._held:
            off = abs(steering - 0.5 * (self.servos.pwm_min + self.servos.pwm_max)) > HOLD_DEADBAND_US
            self._steered = self._steered + self.dt if off else 0.0
            if self._steered < HOLD_STEER_S - 1e-9:
                return self._answer_moored(packet.frame_count)
            self._held = False
            self.log(f"sitl: ArduPilot steered at t = {self.time():.2f} s; the boat leaves its mooring")
        throttle = packet.channel(self.servos.throttle_channel)
        self._push(self.motor_thrust * self.servos.throttle(throttle))
        rudder = self.servos.rudder(steering, self._max_rudder)
        boom = self.servos.sail_angle(mainsail)
        sheet = float(np.clip(sheet_length(self.params, boom), *self._sheet_range))
        before = mat_vec(self.physics.rotation(), self.physics.body_velocity())
        self.physics.set_control([rudder, sheet])
        self.physics.step(1)
        vane = self._vane()
        state = boat_state(self.physics, before if self._velocity is not None else None, self.dt, vane)
        state["timestamp"] = self.time()
        self._velocity = before
        self._last_count, self._last_line = packet.frame_count, state_line(state)
        self.counters.answered += 1
        self._record(steering, mainsail, throttle, sheet, vane)
        if self.film and self.physics.data.time + 1e-9 >= self._next_snapshot:
            self._next_snapshot += 1.0 / FILM_RATE_HZ
            from ..video.scene import snapshot_physics

            self.films[-1].append(snapshot_physics(self.physics))
        return self._last_line

    def _answer_moored(self, frame_count: int) -> bytes:
        """The answer while the boat lies moored: SITL's clock advances one frame, nothing moves."""
        self._moored += self.dt
        state = boat_state(self.physics, None, self.dt, self._vane())
        state["timestamp"] = self.time()
        self._last_count, self._last_line = frame_count, state_line(state)
        self.counters.answered += 1
        return self._last_line

    def _vane(self) -> tuple[float, float]:
        """(direction rad clockwise from the bow, speed m/s) the masthead vane reads now."""
        truth = self.physics.truth()
        if self._instruments is None:
            return float(wrap_angle(truth.apparent_wind_angle)), float(truth.apparent_wind_speed)
        reading = self._instruments.read(truth)
        return float(reading["apparent_wind_angle"]), float(reading["apparent_wind_speed"])

    def _push(self, thrust: float) -> None:
        """The motor's thrust (N, along the hull's axis) on the hull for the coming step."""
        force = self.physics.data.xfrc_applied[self._hull]
        force[:] = 0.0
        if thrust:
            force[:3] = thrust * self.physics.rotation()[:, 0]
        self._thrust = thrust

    def _record(self, steering: int, mainsail: int, throttle: int, sheet: float, vane) -> None:
        """A row of the trajectory table, ``RECORD_RATE_HZ`` times a simulated second."""
        p = self.physics
        t = self.time()
        if t + 1e-9 < self._next_row:
            return
        self._next_row = t + 1.0 / RECORD_RATE_HZ
        x, y, _ = p.position()
        self.runs[-1].append({
            "t": t, "x": float(x), "y": float(y), "heading_deg": math.degrees(p.heading()) % 360.0,
            "heel_deg": math.degrees(p.heel()), "u": p.surge_speed(),
            "rudder_deg": math.degrees(p.rudder_angle()),
            "sail_deg": math.degrees(p.sail_angle()), "sheet": sheet, "steering_pwm": steering,
            "mainsail_pwm": mainsail, "throttle_pwm": throttle, "thrust": self._thrust,
            "vane_deg": math.degrees(vane[0]), "vane_speed": vane[1],
            "awa_deg": math.degrees(p.apparent_wind_angle()), "aws": p.apparent_wind_speed()})
        if self.mcap is not None:
            observation = observe(p.truth())
            observation["apparent_wind_angle"], observation["apparent_wind_speed"] = vane
            self.mcap.write({**step_row(observation, p.position()), "t": t})

    # ---- the socket
    def serve(self, port: int = DEFAULT_PORT, host: str = "127.0.0.1", timeout: float = 30.0,
              seconds: float | None = None) -> Counters:
        """Answer SITL on UDP ``host:port`` until it stops sending for ``timeout`` s, or the
        boat has sailed ``seconds`` of simulated time.

        Parameters
        ----------
        port : int
            The UDP port SITL sends to (9002, or 9002 + 10 N for ``ardurover -I N``).
        host : str
            The address to listen on.
        timeout : float
            Seconds without a packet after which the run ends (before the first packet: an
            error, SITL never came).
        seconds : float, optional
            Simulated seconds after which the run ends.

        Returns
        -------
        Counters

        Raises
        ------
        SitlError
            The port is in use, or no packet came within ``timeout`` s.
        """
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            sock.bind((host, int(port)))
        except OSError as err:
            sock.close()
            raise SitlError(f"cannot listen on UDP {host}:{port} ({err.strerror or err}): another "
                            "sailmujoco sitl or simulator holds it; give another --port (ardurover -I N "
                            "sends to 9002 + 10 N)") from None
        sock.settimeout(timeout)
        self.listening.set()
        start = time.perf_counter()
        try:
            self._loop(sock, port, timeout, seconds)
        finally:
            sock.close()
            self.listening.clear()
            self.counters.wall += time.perf_counter() - start
        return self.counters

    def _loop(self, sock, port: int, timeout: float, seconds: float | None) -> None:
        first = None
        while seconds is None or self.time() < seconds - 1e-9:
            try:
                data, address = sock.recvfrom(4096)
            except TimeoutError:
                if self.counters.answered == 0:
                    raise SitlError(f"no servo packet on UDP {port} in {timeout:g} s: start ArduPilot with "
                                    "--model JSON (docs/ardupilot.md), or give its port") from None
                self.log(f"sitl: SITL stopped sending: no packet for {timeout:g} s, the run ends at "
                         f"t = {self.time():.2f} s")
                return
            try:
                answer = self.handle(data)
            except ProtocolError as err:
                self._refuse(str(err), address)
                continue
            except SimulationStopped as err:
                self.log(f"sitl: the boat stopped at t = {self.time():.2f} s: {err}; the run ends")
                return
            sock.sendto(answer, address)
            now = time.perf_counter()
            first = now if first is None else first
            self.counters.lock_step = now - first

    def _refuse(self, reason: str, address) -> None:
        """Count a refused datagram; its first of a kind in one line."""
        self.counters.refused += 1
        seen = self.counters.refusals.get(reason, 0)
        self.counters.refusals[reason] = seen + 1
        if not seen:
            self.log(f"sitl: refused {reason}, from {address[0]}:{address[1]}; no answer, nothing moved")

    def trajectory(self, run: int = -1):
        """The trajectory table of a run (the last by default): one row per 0.1 s.

        Parameters
        ----------
        run : int
            Which run (a SITL restart begins a new one).
        """
        import pandas as pd

        return pd.DataFrame(self.runs[run])
