"""ArduPilot's own sailboat code sails the 6-DOF boat: ardurover (``--model JSON``) arms, enters
AUTO on a two-waypoint mission and the boat heads to the first waypoint.

It needs ArduPilot's Rover SITL binary beside the clone (``../shared/ardupilot/ardurover``, with
its parameter files) and pymavlink, neither of which sailmujoco depends on; without them the
test says so in one line and is skipped. The protocol itself is tested against a stand-in in
tests/test_sitl.py.
"""

import math
import shutil
import socket
import subprocess
import threading
import time
from pathlib import Path

import pytest

from sailmujoco.sitl.backend import JsonBackend

ARDUPILOT = Path(__file__).resolve().parents[2] / "shared" / "ardupilot"
HOME = (-35.363261, 149.165230)
EAST_M = 80.0  # the first waypoint, abeam of the wind from the north: a reach, no tack needed


def _free_port(kind=socket.SOCK_DGRAM) -> int:
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture
def mavlink():
    if not (ARDUPILOT / "ardurover").exists():
        pytest.skip("../shared/ardupilot/ardurover is not beside this clone: ArduPilot's own code not run")
    return pytest.importorskip("pymavlink.mavutil",
                               reason="pymavlink is not installed: pip install pymavlink")


def test_ardupilot_arms_goes_auto_and_heads_for_its_first_waypoint(mavlink, tmp_path):
    backend = JsonBackend("wille_yacht", wind_speed=5.0, wind_from_deg=0.0, heading_deg=90.0)
    sim_port, gcs_port = _free_port(), _free_port()
    server = threading.Thread(target=backend.serve, kwargs={"port": sim_port, "timeout": 10.0}, daemon=True)
    server.start()
    assert backend.listening.wait(10.0)
    for name in ("rover.parm", "sailboat.parm", "json_windvane.parm"):
        shutil.copy(ARDUPILOT / name, tmp_path / name)
    ardurover = subprocess.Popen(
        [str(ARDUPILOT / "ardurover"), "--model", "JSON", "-w", "--speedup", "10", "-I", "7",
         "--sim-port-out", str(sim_port), "--defaults", "rover.parm,sailboat.parm,json_windvane.parm",
         "--serial0", f"udpclient:127.0.0.1:{gcs_port}", "--home", f"{HOME[0]},{HOME[1]},0,90"],
        cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        m = mavlink.mavlink_connection(f"udpin:127.0.0.1:{gcs_port}")
        assert m.wait_heartbeat(timeout=60) is not None
        m.mav.request_data_stream_send(m.target_system, m.target_component,
                                       mavlink.mavlink.MAV_DATA_STREAM_ALL, 10, 1)
        deadline = time.time() + 120
        while time.time() < deadline:  # the EKF's position from the GPS (about 40 s simulated)
            msg = m.recv_match(type="EKF_STATUS_REPORT", blocking=True, timeout=1)
            if msg is not None and msg.flags & mavlink.mavlink.EKF_POS_HORIZ_ABS:
                gps = m.recv_match(type="GPS_RAW_INT", blocking=True, timeout=2)
                if gps is not None and gps.fix_type >= 3:
                    break
        target = (HOME[0], HOME[1] + EAST_M / (111320.0 * math.cos(math.radians(HOME[0]))))
        points = [HOME, target]
        m.mav.mission_count_send(m.target_system, m.target_component, len(points), 0)
        for _ in points:
            req = m.recv_match(type=["MISSION_REQUEST_INT", "MISSION_REQUEST"], blocking=True, timeout=10)
            assert req is not None, "ArduPilot asked for no mission item"
            lat, lon = points[req.seq]
            m.mav.mission_item_int_send(m.target_system, m.target_component, req.seq,
                                        mavlink.mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT,
                                        mavlink.mavlink.MAV_CMD_NAV_WAYPOINT, 0, 1, 0, 0, 0, 0,
                                        int(lat * 1e7), int(lon * 1e7), 0, 0)
        ack = m.recv_match(type="MISSION_ACK", blocking=True, timeout=10)
        assert ack is not None and ack.type == mavlink.mavlink.MAV_MISSION_ACCEPTED
        m.arducopter_arm()
        m.set_mode("AUTO")
        start = backend.physics.position()[0]
        deadline, armed_auto = time.time() + 60, False
        while time.time() < deadline and backend.physics.position()[0] - start < 20.0:
            beat = m.recv_match(type="HEARTBEAT", blocking=True, timeout=1)
            if beat is not None and beat.get_srcSystem() == m.target_system:
                armed_auto |= bool(beat.base_mode & mavlink.mavlink.MAV_MODE_FLAG_SAFETY_ARMED) and \
                    beat.custom_mode == 10  # Rover's AUTO
        assert armed_auto, "ArduPilot did not arm and enter AUTO"
        # the boat sails east, towards the waypoint abeam of the wind, under ArduPilot's helm
        assert backend.physics.position()[0] - start >= 20.0
    finally:
        ardurover.terminate()  # ArduPilot first: once the physics stops answering it ignores SIGTERM
        try:
            ardurover.wait(10)
        except subprocess.TimeoutExpired:
            ardurover.kill()
        server.join(15)
    assert backend.counters.refused == 0 and backend.counters.answered > 10_000


@pytest.mark.parametrize("simulator", ["sailboat", "saoud_robot"])
def test_the_comparison_flies_a_mission_with_a_tack_in_either_simulator(mavlink, tmp_path, simulator):
    """The comparison's own flight (studies/ardupilot): 30 m straight upwind and home, in
    ArduPilot's SIM_Sailboat and on the robot let go from its mooring; both get home, tacking
    (the mark lies dead upwind), and only ours heels."""
    from sailmujoco.studies.ardupilot.cases import ours_parameters
    from sailmujoco.studies.ardupilot.measures import measure
    from sailmujoco.studies.ardupilot.mission import Mission, fly

    mission = Mission(upwind=30.0, limit=300.0)
    parameters = {} if simulator == "sailboat" else ours_parameters(simulator)
    flight = fly(simulator, mission, ARDUPILOT / "ardurover", tmp_path, parameters=parameters, instance=5)
    numbers = measure(flight, mission)
    assert numbers["finished"], flight.events
    assert len(flight.autopilot) == 8 and int(flight.autopilot, 16) >= 0  # its git hash, as it reports it
    assert numbers["tacks"] >= 1 and 0 < numbers["mark_s"] < numbers["home_s"] < 300
    if simulator == "sailboat":
        assert numbers["heel_max_deg"] < 1.0  # SIM_Sailboat has no heel
    else:
        assert numbers["heel_max_deg"] > 1.0
        assert "the boat leaves its mooring" in (tmp_path / "sitl.log").read_text()
