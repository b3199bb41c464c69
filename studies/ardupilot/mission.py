"""One mission flown by ArduPilot's Rover (sailboat mode) in one simulator, recorded over MAVLink.

The simulator is ``sailboat`` (ArduPilot's own kinematic SIM_Sailboat, ``--model sailboat``) or a
boat of ours (``ardurover --model JSON`` against ``sailmujoco sitl BOAT --hold``). Either way the
same MAVLink client gives the same mission, arms, goes AUTO and records, ten times a second of
simulated time: position from home, heading, roll, ground speed, the waypoint sought and ArduPilot's
own messages (tacks begun and timed out, waypoints reached). The record is the same for both
simulators, so every measure (:mod:`.measures`) is taken the same way.

It needs ArduPilot's ``ardurover`` built for SITL, with its ``rover.parm`` and ``sailboat.parm``
beside it, and pymavlink; sailmujoco depends on neither.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

HOME = (-35.363261, 149.165230)  # ArduPilot's SITL home (Canberra model-flying field)
M_PER_DEG_LAT = 111320.0  # m per degree of latitude (spherical Earth, as SITL's own offsets)
ROVER_AUTO = 10  # Rover's custom_mode for AUTO
START_HEADING_DEG = 135.0  # every boat starts on a broad reach, moored until ArduPilot steers


@dataclass(frozen=True)
class Mission:
    """The course, the wind and the sea: the same for every simulator.

    Parameters
    ----------
    upwind : float
        The first waypoint's distance straight upwind of home, m; the second is home.
    wind_speed : float
        True wind, m/s, from ``wind_from_deg``.
    wind_from_deg : float
        Compass bearing the wind comes from, deg.
    sea : bool
        A 1 m sea from the wind's direction (ours: JONSWAP hs 1 m, tp 6 s; SIM_Sailboat: its one
        sine of 1 m at the same period's deep-water length and speed).
    limit : float
        Simulated seconds after AUTO after which an unfinished mission is stopped.
    """

    upwind: float = 100.0
    wind_speed: float = 5.0
    wind_from_deg: float = 0.0
    sea: bool = False
    limit: float = 1200.0

    def waypoints(self, start=(0.0, 0.0)) -> list[tuple[float, float]]:
        """(north, east) of the start, the upwind mark and the start again, m from home.

        Parameters
        ----------
        start : tuple of float
            Where the boat is when the mission starts, (north, east) m from home: ours lie
            moored at home; SIM_Sailboat's boat sails off during ArduPilot's start-up (its
            sheet hauled in while disarmed), so its mission is laid from where it is.
        """
        bearing = math.radians(self.wind_from_deg)
        n0, e0 = float(start[0]), float(start[1])
        mark = (n0 + self.upwind * math.cos(bearing), e0 + self.upwind * math.sin(bearing))
        return [(n0, e0), mark, (n0, e0)]


SEA_TP = 6.0  # s, the sea's peak period (sailmujoco's default) and SIM_Sailboat's wave period
GRAVITY = 9.80665


def sim_sailboat_sea() -> dict:
    """SIM_Sailboat's wave parameters for the 1 m sea: one sine, 1 m high (its WAVE_AMP enters its
    slope as half the height), the deep-water length and speed of a ``SEA_TP`` wave."""
    length = GRAVITY * SEA_TP ** 2 / (2.0 * math.pi)
    return {"SIM_WAVE_ENABLE": 1, "SIM_WAVE_AMP": 1.0, "SIM_WAVE_LENGTH": round(length, 2),
            "SIM_WAVE_SPEED": round(length / SEA_TP, 2)}


@dataclass
class Flight:
    """What one mission recorded.

    Parameters
    ----------
    rows : list of dict
        Ten a simulated second from AUTO: ``t`` (s), ``north``, ``east`` (m from home),
        ``heading`` (deg), ``roll`` (deg, starboard down positive), ``speed`` (m/s over ground),
        ``wp`` (the waypoint sought).
    events : list of (float, str)
        ArduPilot's messages and the waypoints reached, with their time from AUTO.
    reached : dict
        Waypoint number -> time from AUTO it was reached, s.
    waypoints : list of (float, float)
        The mission as laid, (north, east) m from home (:meth:`Mission.waypoints`).
    wall : float
        Wall-clock seconds of the whole flight (start-up included).
    sim_log : str
        The last lines ``sailmujoco sitl`` printed ("" for SIM_Sailboat).
    autopilot : str
        ArduPilot's git hash as it reports it (AUTOPILOT_VERSION), "" if it did not.
    """

    rows: list = field(default_factory=list)
    events: list = field(default_factory=list)
    reached: dict = field(default_factory=dict)
    waypoints: list = field(default_factory=list)
    wall: float = 0.0
    sim_log: str = ""
    autopilot: str = ""


def parm_text(values: dict) -> str:
    """An ArduPilot parameter file's text.

    Parameters
    ----------
    values : dict
        Parameter name -> value.
    """
    return "".join(f"{name} {value}\n" for name, value in values.items())


def _stop(process, grace: float = 10.0) -> None:
    if process is None or process.poll() is not None:
        return
    process.terminate()
    try:
        process.wait(grace)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait(5)


def fly(simulator: str, mission: Mission, ardurover: Path, work: Path, *, seed: int = 0,
        parameters: dict | None = None, speedup: int = 10, instance: int = 0, motor: float = 0.0,
        say=print) -> Flight:
    """Fly ``mission`` in ``simulator`` and record it.

    Parameters
    ----------
    simulator : str
        ``"sailboat"`` (ArduPilot's SIM_Sailboat) or a boat of ours (name or boat file).
    mission : Mission
        The course, wind and sea.
    ardurover : Path
        ArduPilot's Rover SITL program; ``rover.parm`` and ``sailboat.parm`` beside it.
    work : Path
        The run's folder (ArduPilot's eeprom and logs, our trajectory table, the logs).
    seed : int
        Seeds our wind, sea and instruments (SIM_Sailboat has no seed).
    parameters : dict, optional
        ArduPilot parameters over its rover and sailboat defaults.
    speedup : int
        ArduPilot's ``--speedup``.
    instance : int
        ArduPilot's ``-I``: its ports move by 10 per instance.
    motor : float
        Our boat's auxiliary motor, N at full throttle (``sailmujoco sitl --motor``; 0: none).
    say : callable
        Gets one line when something goes wrong.
    """
    from pymavlink import mavutil

    work.mkdir(parents=True, exist_ok=True)
    folder = ardurover.parent
    ours = simulator != "sailboat"
    values = dict(parameters or {})
    if ours:
        values.update({"WNDVN_TYPE": 11, "WNDVN_SPEED_TYPE": 11})  # the vane reads the JSON backend
    else:
        # SIM_WIND_T stays sailboat.parm's 1: the wind at the boat's height is SIM_WIND_SPD
        values.update({"SIM_WIND_SPD": mission.wind_speed, "SIM_WIND_DIR": mission.wind_from_deg})
        if mission.sea:
            values.update(sim_sailboat_sea(), SIM_WAVE_DIR=(mission.wind_from_deg + 180.0) % 360.0)
    (work / "mission.parm").write_text(parm_text(values))
    gcs_port = 14550 + 10 * instance
    sim_port = 9002 + 10 * instance
    start = time.perf_counter()
    backend = None
    if ours:
        command = [sys.executable, "-m", "sailmujoco", "sitl", str(simulator), "--wind-speed",
                   str(mission.wind_speed), "--wind-from", str(mission.wind_from_deg), "--seed", str(seed),
                   "--hold", "--heading", str(START_HEADING_DEG), "--port", str(sim_port), "--timeout", "10",
                   "--out", str(work)]
        if mission.sea:
            command += ["--waves", "hs=1"]
        if motor:
            command += ["--motor", str(motor)]
        backend = subprocess.Popen(command, stdout=open(work / "sitl.log", "w"), stderr=subprocess.STDOUT)
        time.sleep(3.0)  # its port open before ArduPilot's first packet
    defaults = ",".join(str(p) for p in (folder / "rover.parm", folder / "sailboat.parm", work / "mission.parm"))
    pilot = subprocess.Popen(
        [str(ardurover), "--model", "JSON" if ours else "sailboat", "-w", "--speedup", str(speedup),
         "-I", str(instance), "--sim-port-out", str(sim_port), "--defaults", defaults,
         "--serial0", f"udpclient:127.0.0.1:{gcs_port}",
         "--home", f"{HOME[0]},{HOME[1]},0,{START_HEADING_DEG:g}"],
        cwd=work, stdout=open(work / "ardurover.log", "w"), stderr=subprocess.STDOUT)
    flight = Flight()
    link = None
    try:
        link = mavutil.mavlink_connection(f"udpin:127.0.0.1:{gcs_port}")
        _fly(link, mavutil, mission, flight, say)
    finally:
        if link is not None:
            link.close()
        _stop(pilot)  # ArduPilot first: with its physics gone it would wait on it for ever
        _stop(backend)
        flight.wall = time.perf_counter() - start
        if ours:
            flight.sim_log = "".join((work / "sitl.log").read_text().splitlines(True)[-3:])
    return flight


def _fly(m, mavutil, mission: Mission, flight: Flight, say) -> None:
    """Upload, arm, AUTO, then record (:func:`_record`)."""
    if m.wait_heartbeat(timeout=60) is None:
        raise RuntimeError("no heartbeat from ardurover in 60 s (see its ardurover.log)")
    m.mav.command_long_send(m.target_system, m.target_component,
                            mavutil.mavlink.MAV_CMD_REQUEST_AUTOPILOT_CAPABILITIES, 0, 1, 0, 0, 0, 0, 0, 0)
    version = m.recv_match(type="AUTOPILOT_VERSION", blocking=True, timeout=5)
    if version is not None:  # its git hash, the first 8 hex digits
        flight.autopilot = bytes(version.flight_custom_version).rstrip(b"\0").decode("ascii", "replace")
    m.mav.request_data_stream_send(m.target_system, m.target_component, mavutil.mavlink.MAV_DATA_STREAM_ALL,
                                   10, 1)
    deadline = time.time() + 300
    while time.time() < deadline:  # the EKF's position from the GPS, about 40 s simulated after start
        msg = m.recv_match(type="EKF_STATUS_REPORT", blocking=True, timeout=1)
        if msg is not None and msg.flags & mavutil.mavlink.EKF_POS_HORIZ_ABS:
            gps = m.recv_match(type="GPS_RAW_INT", blocking=True, timeout=2)
            if gps is not None and gps.fix_type >= 3:
                break
    else:
        raise RuntimeError("ArduPilot's EKF never used the GPS (see ardurover.log)")
    here = m.recv_match(type="GLOBAL_POSITION_INT", blocking=True, timeout=10)
    start = (0.0, 0.0) if here is None else _north_east(here)
    flight.waypoints = mission.waypoints(start)
    points = [(HOME[0] + n / M_PER_DEG_LAT, HOME[1] + e / (M_PER_DEG_LAT * math.cos(math.radians(HOME[0]))))
              for n, e in flight.waypoints]
    m.mav.mission_count_send(m.target_system, m.target_component, len(points), 0)
    asked = set()
    while len(asked) < len(points):
        req = m.recv_match(type=["MISSION_REQUEST_INT", "MISSION_REQUEST"], blocking=True, timeout=10)
        if req is None:
            raise RuntimeError("ArduPilot stopped asking for mission items")
        lat, lon = points[req.seq]
        m.mav.mission_item_int_send(m.target_system, m.target_component, req.seq,
                                    mavutil.mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                                    mavutil.mavlink.MAV_CMD_NAV_WAYPOINT, 0, 1, 0, 0, 0, 0,
                                    int(round(lat * 1e7)), int(round(lon * 1e7)), 0, 0)
        asked.add(req.seq)
    m.recv_match(type="MISSION_ACK", blocking=True, timeout=10)
    m.arducopter_arm()
    m.set_mode("AUTO")
    _record(m, mavutil, mission, flight, len(points), say)


def _record(m, mavutil, mission: Mission, flight: Flight, n_points: int, say) -> None:
    """Record from AUTO until the last of ``n_points`` waypoints is reached or the limit."""
    auto_ms = None
    state = {"roll": math.nan, "speed": math.nan, "wp": 1}
    next_row = 0.0
    last_wall = time.time()
    while True:
        msg = m.recv_match(blocking=True, timeout=1)
        if msg is None:
            if time.time() - last_wall > 30:
                raise RuntimeError("ArduPilot went silent for 30 s")
            continue
        last_wall = time.time()
        kind = msg.get_type()
        if kind == "HEARTBEAT" and auto_ms is None and msg.get_srcSystem() == m.target_system:
            if msg.custom_mode == ROVER_AUTO and msg.base_mode & mavutil.mavlink.MAV_MODE_FLAG_SAFETY_ARMED:
                auto_ms = -1  # the next timed message starts the clock
        elif kind == "ATTITUDE":
            state["roll"] = math.degrees(msg.roll)
        elif kind == "VFR_HUD":
            state["speed"] = float(msg.groundspeed)
        elif kind == "MISSION_CURRENT":
            state["wp"] = int(msg.seq)
        elif kind == "STATUSTEXT" and auto_ms is not None and auto_ms >= 0:
            flight.events.append((round(flight.rows[-1]["t"] if flight.rows else 0.0, 1), msg.text))
        elif kind == "MISSION_ITEM_REACHED" and auto_ms is not None and auto_ms >= 0 and flight.rows:
            flight.reached.setdefault(int(msg.seq), flight.rows[-1]["t"])
            if int(msg.seq) == n_points - 1:
                return
        elif kind == "GLOBAL_POSITION_INT":
            if auto_ms == -1:
                auto_ms = msg.time_boot_ms
            if auto_ms is None or auto_ms < 0:
                continue
            t = (msg.time_boot_ms - auto_ms) / 1000.0
            if t > mission.limit:
                say(f"  not home after {mission.limit:g} s: stopped")
                return
            if t + 1e-6 >= next_row:
                next_row = t + 0.1
                north, east = _north_east(msg)
                flight.rows.append({"t": round(t, 3), "north": north, "east": east,
                                    "heading": msg.hdg / 100.0, "roll": state["roll"],
                                    "speed": state["speed"], "wp": state["wp"]})


def _north_east(msg) -> tuple[float, float]:
    """(north, east) m from home of a GLOBAL_POSITION_INT."""
    north = (msg.lat / 1e7 - HOME[0]) * M_PER_DEG_LAT
    east = (msg.lon / 1e7 - HOME[1]) * M_PER_DEG_LAT * math.cos(math.radians(HOME[0]))
    return north, east


def environment_ready() -> str | None:
    """Why a flight cannot run here (one line), or None."""
    try:
        import pymavlink  # noqa: F401
    except ImportError:
        return "pymavlink is not installed (pip install pymavlink; sailmujoco does not depend on it)"
    return None


def find_ardurover(given: str | os.PathLike | None) -> Path | str:
    """The ardurover program: ``given`` (the program or its folder), else ``$SAILMUJOCO_ARDUROVER``,
    else ``ardurover`` on the PATH; a one-line reason where none is found.

    Parameters
    ----------
    given : str or os.PathLike, optional
        ``--ardurover``.
    """
    import shutil

    candidate = given or os.environ.get("SAILMUJOCO_ARDUROVER") or shutil.which("ardurover")
    if not candidate:
        return ("no ardurover: give --ardurover PATH (ArduPilot's Rover built for SITL, with rover.parm "
                "and sailboat.parm beside it) or set SAILMUJOCO_ARDUROVER")
    path = Path(candidate)
    if path.is_dir():
        path = path / "ardurover"
    if not path.is_file() or not os.access(path, os.X_OK):
        return f"--ardurover {candidate}: not an executable ardurover program"
    missing = [name for name in ("rover.parm", "sailboat.parm") if not (path.parent / name).is_file()]
    if missing:
        return (f"--ardurover {candidate}: {' and '.join(missing)} not beside it (ArduPilot's "
                "Tools/autotest/default_params/)")
    return path
