"""The boat as ArduPilot SITL's JSON backend, against a stand-in for SITL: the servo packet and
the JSON line (ArduPilot's libraries/SITL/examples/JSON/readme.md), the frames from first
principles, the servo mapping at its ends, and the lock-step over real UDP (one answer per
packet, no step without one, resends, a restart, a malformed packet, a port in use, a SITL that
stops)."""

import json
import math
import socket
import threading

import numpy as np
import pytest

from sailmujoco import frames
from sailmujoco.constants import GRAVITY
from sailmujoco.sitl.backend import JsonBackend, SitlError
from sailmujoco.sitl.protocol import (
    MAGIC_16,
    MAGIC_32,
    ProtocolError,
    parse_servo_packet,
    servo_packet,
    state_line,
)
from sailmujoco.sitl.servos import ServoMap
from sailmujoco.sitl.state import boat_state

NEUTRAL = [1500] * 16


# ---- the packet and the line
def test_a_servo_packet_reads_back_with_16_or_32_channels():
    pwm = list(range(1000, 1016))
    packet = servo_packet(pwm, 1200, 77)
    assert len(packet) == 40 and int.from_bytes(packet[:2], "little") == MAGIC_16
    got = parse_servo_packet(packet)
    assert (got.frame_rate, got.frame_count, got.pwm) == (1200, 77, tuple(pwm))
    assert got.channel(1) == 1000 and got.channel(4) == 1003
    wide = servo_packet(list(range(1100, 1132)), 400, 3)
    assert len(wide) == 72 and int.from_bytes(wide[:2], "little") == MAGIC_32
    assert parse_servo_packet(wide).channel(32) == 1131


@pytest.mark.parametrize("data", [b"", b"\x1a\x48", servo_packet(NEUTRAL)[:-2],
                                  b"\x00\x00" + servo_packet(NEUTRAL)[2:], servo_packet(NEUTRAL) + b"\x00"])
def test_a_malformed_packet_is_refused_in_one_line(data):
    with pytest.raises(ProtocolError) as err:
        parse_servo_packet(data)
    assert "\n" not in str(err.value) and "40 bytes with magic 18458" in str(err.value)


def test_the_state_line_is_one_json_object_between_newlines_in_the_compact_form_sitl_parses():
    line = state_line({"timestamp": 1.5, "imu": {"gyro": np.array([0.0, 1.0, 2.0])},
                       "position": (1, 2, 3)}).decode()
    assert line.startswith("\n") and line.endswith("\n") and line.count("\n") == 2
    assert '"gyro":[0.0,1.0,2.0]' in line  # SITL reads the value right after the colon, "[%f, %f, %f]"
    assert ": " not in line
    expected = {"timestamp": 1.5, "imu": {"gyro": [0.0, 1.0, 2.0]}, "position": [1.0, 2.0, 3.0]}
    assert json.loads(line) == expected
    with pytest.raises(ValueError, match="non-finite"):
        state_line({"timestamp": math.nan})


# ---- the frames
@pytest.fixture(scope="module")
def robot():
    return JsonBackend("saoud_robot", wind_speed=0.0)


def test_a_boat_heading_east_at_2_m_s_moves_north_east_down_0_2_0(robot):
    physics = robot.physics
    physics.reset()
    physics.place((3.0, 4.0), float(frames.yaw_from_heading(math.pi / 2)), 2.0)
    state = boat_state(physics, None, robot.dt, (0.0, 0.0))
    np.testing.assert_allclose(state["velocity"], [0.0, 2.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(state["position"][:2], [4.0, 3.0], atol=1e-12)  # north 4, east 3
    roll, pitch, yaw = frames.euler_from_ned_quaternion(state["quaternion"])
    assert yaw == pytest.approx(math.pi / 2, abs=1e-12)  # NED yaw is the compass heading


def test_a_level_boat_at_rest_feels_the_water_push_up_minus_g_in_frd(robot):
    physics = robot.physics
    physics.reset()
    physics.place((0.0, 0.0), float(frames.yaw_from_heading(0.3)), 0.0)
    state = boat_state(physics, None, robot.dt, (0.0, 0.0))
    np.testing.assert_allclose(state["imu"]["accel_body"], [0.0, 0.0, -GRAVITY], atol=1e-9)
    np.testing.assert_allclose(state["imu"]["gyro"], [0.0, 0.0, 0.0], atol=1e-12)
    # an acceleration of 1 m/s^2 north over the step, heading north: +1 on FRD x
    physics.place((0.0, 0.0), float(frames.yaw_from_heading(0.0)), 0.0)
    state = boat_state(physics, np.array([0.0, -robot.dt, 0.0]), robot.dt, (0.0, 0.0))
    np.testing.assert_allclose(state["imu"]["accel_body"], [1.0, 0.0, -GRAVITY], atol=1e-9)


@pytest.mark.parametrize("heel, pitch, heading", [(0.3, 0.0, 0.0), (-0.2, 0.05, 2.5), (0.6, -0.1, -1.2),
                                                  (0.0, 0.0, math.pi - 1e-3)])
def test_the_quaternion_round_trips_to_heel_pitch_and_heading(heel, pitch, heading):
    """ArduPilot's roll is our heel (starboard down positive, as FRD's roll), its pitch bow up,
    its yaw the compass heading."""
    q = frames.ned_frd_quaternion(frames.matrix_from_euler(heel, pitch, frames.yaw_from_heading(heading)))
    assert np.linalg.norm(q) == pytest.approx(1.0, abs=1e-12)
    roll, p, yaw = frames.euler_from_ned_quaternion(q)
    assert (roll, p) == (pytest.approx(heel, abs=1e-12), pytest.approx(pitch, abs=1e-12))
    assert math.remainder(yaw - heading, 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
    # body FRD x (the bow) in NED from the quaternion's matrix: north and east of the heading
    w, x, y, z = q
    bow = [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)]
    np.testing.assert_allclose(bow[:2], np.array([math.cos(heading), math.sin(heading)]) * math.cos(pitch),
                               atol=1e-12)
    assert bow[2] == pytest.approx(-math.sin(pitch), abs=1e-12)  # bow up: negative down


def test_a_boat_turning_to_starboard_has_a_positive_frd_yaw_rate(robot):
    physics = robot.physics
    physics.reset()
    physics.place((0.0, 0.0), 0.0, 0.0)
    physics.data.qvel[5] = -0.2  # ENU/FLU z up: negative is clockwise seen from above, to starboard
    physics.data.qvel[3] = 0.1  # rolling to starboard (starboard down)
    state = boat_state(physics, None, robot.dt, (0.0, 0.0))
    assert state["imu"]["gyro"][2] == pytest.approx(0.2, abs=1e-12)
    assert state["imu"]["gyro"][0] == pytest.approx(0.1, abs=1e-12)


# ---- the servos
def test_steering_and_mainsail_at_their_ends_and_middle():
    servos = ServoMap()
    r = math.radians(30.0)
    assert servos.rudder(1500, r) == 0.0
    assert servos.rudder(2000, r) == pytest.approx(-r)  # steer to starboard: trailing edge to starboard
    assert servos.rudder(1000, r) == pytest.approx(r)
    assert servos.rudder(2500, r) == pytest.approx(-r)  # clipped to the range
    assert servos.sail_angle(1000) == 0.0  # sheeted in
    assert servos.sail_angle(2000) == pytest.approx(math.pi / 2)  # SAIL_ANGLE_MAX 90 deg
    assert servos.sail_angle(1500) == pytest.approx(math.pi / 4)
    flipped = ServoMap(steering_reversed=True, mainsail_reversed=True, sail_angle_max_deg=60.0)
    assert flipped.rudder(2000, r) == pytest.approx(r)
    assert flipped.sail_angle(1000) == pytest.approx(math.pi / 3)
    with pytest.raises(ValueError, match="servos.steering_channel must be a channel from 1 to 32"):
        ServoMap(steering_channel=0)


# ---- the lock-step over UDP, against a stand-in for SITL
def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class StandIn:
    """SITL's side: sends servo packets, reads one line each."""

    def __init__(self, backend, timeout=1.0, seconds=None):
        self.port = _free_port()
        self.log = []
        backend.log = self.log.append
        self.result = {}

        def run():
            try:
                self.result["counters"] = backend.serve(port=self.port, timeout=timeout, seconds=seconds)
            except SitlError as err:
                self.result["error"] = err

        self.thread = threading.Thread(target=run, daemon=True)
        self.thread.start()
        assert backend.listening.wait(10.0)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.settimeout(0.3)

    def send(self, pwm, count, raw=None):
        self.sock.sendto(raw if raw is not None else servo_packet(pwm, 400, count), ("127.0.0.1", self.port))
        try:
            return self.sock.recv(65536)
        except TimeoutError:
            return None

    def close(self):
        self.thread.join(5.0)
        self.sock.close()


def test_lock_step_one_answer_per_packet_resends_and_a_restart():
    other = JsonBackend("saoud_robot", wind_speed=5.0, wind_from_deg=90.0)
    fresh = other.handle(servo_packet(NEUTRAL, 400, 0))  # a first answer, made before the clock runs:
    backend = JsonBackend("saoud_robot", wind_speed=5.0, wind_from_deg=90.0)  # 0.5 s of silence ends it
    sitl = StandIn(backend, timeout=0.5)
    lines = [sitl.send(NEUTRAL, k) for k in range(50)]
    assert all(line is not None for line in lines)
    stamps = [json.loads(line)["timestamp"] for line in lines]
    np.testing.assert_allclose(stamps, backend.dt * np.arange(1, 51), rtol=0, atol=1e-12)  # a step each
    again = sitl.send(NEUTRAL, 49)  # the last frame sent again: the same answer, the boat still
    assert again == lines[-1] and backend.physics.data.time == pytest.approx(50 * backend.dt)
    restart = sitl.send(NEUTRAL, 0)  # SITL restarted: the boat starts again, nothing stale
    assert json.loads(restart)["timestamp"] == pytest.approx(backend.dt)  # backwards: SITL's reset
    assert restart == fresh
    for k in range(1, 5):
        assert sitl.send(NEUTRAL, k) is not None
    sitl.close()  # no packet for 0.5 s: the run ends, in one line
    counters = sitl.result["counters"]
    assert (counters.answered, counters.resent, counters.resets) == (55, 1, 1)
    assert 0 < counters.lock_step < counters.wall - 0.45  # the 0.5 s of silence at the end is not lock-step
    assert len(backend.runs) == 2 and sitl.log[-1].startswith("sitl: SITL stopped sending")
    assert any("SITL restarted" in line for line in sitl.log)


def test_a_malformed_packet_gets_no_answer_and_moves_nothing():
    backend = JsonBackend("saoud_robot", wind_speed=0.0)
    sitl = StandIn(backend, timeout=2.0)  # longer than the stand-in's wait for each unanswered packet
    assert sitl.send(NEUTRAL, 0) is not None
    assert sitl.send(None, 0, raw=b"\x00" * 10) is None  # no answer
    assert sitl.send(None, 0, raw=b"\x00" * 10) is None
    assert backend.physics.data.time == pytest.approx(backend.dt)
    assert json.loads(sitl.send(NEUTRAL, 1))["timestamp"] == pytest.approx(2 * backend.dt)
    sitl.close()
    refusals = [line for line in sitl.log if "refused" in line]
    assert len(refusals) == 1 and "a packet of 10 bytes" in refusals[0]  # once per kind
    assert sitl.result["counters"].refused == 2


def test_a_port_in_use_and_a_sitl_that_never_comes_are_one_line():
    taken = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    taken.bind(("127.0.0.1", 0))
    port = taken.getsockname()[1]
    backend = JsonBackend("saoud_robot", wind_speed=0.0)
    with pytest.raises(SitlError, match=f"cannot listen on UDP 127.0.0.1:{port}") as err:
        backend.serve(port=port, timeout=0.2)
    assert "\n" not in str(err.value) and "--port" in str(err.value)
    taken.close()
    with pytest.raises(SitlError, match="no servo packet on UDP .* in 0.2 s: start ArduPilot with"):
        backend.serve(port=_free_port(), timeout=0.2)


def test_steering_to_starboard_turns_the_boat_to_starboard():
    """A full starboard steering pulse sets a negative rudder (trailing edge to starboard): the
    boat, sailing on a beam reach, turns clockwise; SITL's gyro reads a positive yaw rate and
    its heading grows."""
    backend = JsonBackend("saoud_robot", wind_speed=6.0, wind_from_deg=90.0, heading_deg=0.0)
    eased = list(NEUTRAL)
    eased[3] = 1500
    for k in range(400):  # 2 s straight, the sail drawing
        backend.handle(servo_packet(eased, 200, k))
    first = json.loads(backend.handle(servo_packet(eased, 200, 400)))
    start = frames.euler_from_ned_quaternion(first["quaternion"])[2]
    turn = list(eased)
    turn[0] = 2000
    for k in range(401, 801):
        line = json.loads(backend.handle(servo_packet(turn, 200, k)))
    end = frames.euler_from_ned_quaternion(line["quaternion"])[2]
    assert backend.physics.rudder_angle() < -0.3
    assert line["imu"]["gyro"][2] > 0.05 and math.remainder(end - start, 2 * math.pi) > 0.2


def test_a_held_boat_lies_still_with_sitls_clock_running_until_ardupilot_steers():
    """Moored: SITL's clock advances a frame per packet while the boat stays upright at rest at
    home (the accelerometer reads -g, nothing else moves), whatever the disarmed sail does; the
    first steering pulse off the middle lets it go, the clock running on, and a SITL restart moors
    it again."""
    log = []
    backend = JsonBackend("saoud_robot", wind_speed=6.0, wind_from_deg=90.0, hold=True, log=log.append)
    pwm = list(NEUTRAL)
    for k in range(200):
        pwm[3] = 1000 + 5 * k  # the mainsail moves (start-up, disarmed): not a release
        line = json.loads(backend.handle(servo_packet(pwm, 400, k)))
        assert line["timestamp"] == pytest.approx((k + 1) * backend.dt, abs=1e-12)
        np.testing.assert_allclose(line["position"], [0.0, 0.0, 0.0], atol=1e-4)  # afloat at home
        np.testing.assert_allclose(line["velocity"], [0.0, 0.0, 0.0], atol=1e-12)
        np.testing.assert_allclose(line["imu"]["accel_body"], [0.0, 0.0, -GRAVITY], atol=1e-9)
        np.testing.assert_allclose(line["imu"]["gyro"], [0.0, 0.0, 0.0], atol=1e-12)
    assert backend.physics.data.time == 0.0 and log == []
    pwm[0] = 1500 + 10  # within the deadband: still held
    backend.handle(servo_packet(pwm, 400, 200))
    pwm[0] = 1000  # one frame off the middle (ArduPilot setting up its outputs): still held
    backend.handle(servo_packet(pwm, 400, 201))
    pwm[0] = 1500
    backend.handle(servo_packet(pwm, 400, 202))
    assert backend.physics.data.time == 0.0
    pwm[0] = 1600  # steering: let go after 0.1 s of it (20 frames), the 20th frame the first step
    moving = [json.loads(backend.handle(servo_packet(pwm, 400, k))) for k in range(203, 603)]
    assert moving[18]["timestamp"] == pytest.approx(222 * backend.dt, abs=1e-12)
    assert moving[19]["timestamp"] == pytest.approx(223 * backend.dt, abs=1e-12)
    assert backend.physics.data.time == pytest.approx(381 * backend.dt)
    assert np.hypot(*moving[-1]["velocity"][:2]) > 0.05  # the wind on the beam has moved it
    assert len(log) == 1 and "ArduPilot steered at t = 1.11 s; the boat leaves its mooring" in log[0]
    assert backend.runs[-1][0]["t"] == pytest.approx(223 * backend.dt)  # the table keeps SITL's clock
    again = json.loads(backend.handle(servo_packet(NEUTRAL, 400, 0)))  # SITL restarted: moored again
    assert again["timestamp"] == pytest.approx(backend.dt)
    np.testing.assert_allclose(again["velocity"], [0.0, 0.0, 0.0], atol=1e-12)


def test_a_filmed_run_keeps_five_states_a_second_and_films_them_without_changing_the_run(tmp_path):
    """Filming keeps a snapshot every 0.2 s of the boat's time and leaves every answer to SITL as
    it was; the film has one frame per snapshot."""
    imageio = pytest.importorskip("imageio.v3")
    pytest.importorskip("imageio_ffmpeg")
    from sailmujoco.sitl.film import FILM_RATE_HZ, film

    filmed = JsonBackend("wille_yacht", wind_speed=6.0, wind_from_deg=90.0, film=True)
    plain = JsonBackend("wille_yacht", wind_speed=6.0, wind_from_deg=90.0)
    pwm = list(NEUTRAL)
    pwm[0] = 1700
    for k in range(400):  # 2 s
        assert filmed.handle(servo_packet(pwm, 200, k)) == plain.handle(servo_packet(pwm, 200, k))
    snaps = filmed.films[-1]
    # the first step, then every 0.2 s
    assert FILM_RATE_HZ == 5.0 and len(snaps) == 11 and plain.films == [[]]
    np.testing.assert_allclose([s.time for s in snaps], [0.005, *(0.2 * np.arange(1, 11))], atol=1e-9)
    assert np.hypot(*(snaps[-1].position - snaps[0].position)[:2]) > 0.1  # the wind on the beam moves it
    out = tmp_path / "run.mp4"
    assert film(snaps, filmed.params, out, width=160, height=120, progress=False) == 11
    frames = imageio.imread(out, plugin="FFMPEG", index=None)
    assert frames.shape == (11, 120, 160, 3) and frames[0].std() > 10


@pytest.mark.parametrize("stop", ["SIGINT", "SIGTERM"])
def test_the_command_line_run_ends_on_ctrl_c_or_sigterm_with_its_table_and_film(tmp_path, stop):
    """``sailmujoco sitl`` as a user runs it: it answers a stand-in SITL, and Ctrl-C (SIGINT) or
    SIGTERM ends it with exit 0, its summary, the trajectory table and the film written."""
    import signal
    import subprocess
    import sys

    pytest.importorskip("imageio_ffmpeg")
    port = _free_port()
    out = tmp_path / "run"
    command = [sys.executable, "-m", "sailmujoco", "sitl", "saoud_robot", "--port", str(port), "--hold",
               "--heading", "135", "--out", str(out), "--video", str(out / "film.mp4")]
    # Ctrl-C as in a user's shell: the command gets SIGINT's default disposition, whatever this
    # test process holds at the moment (the sweep engine ignores SIGINT while it starts workers,
    # and a child inherits an ignored signal ignored)
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.settimeout(0.5)
    try:
        answer, tries = None, 0
        while answer is None and tries < 60:  # the command starting: ask until it answers
            sock.sendto(servo_packet(NEUTRAL, 400, 0), ("127.0.0.1", port))
            try:
                answer = sock.recv(65536)
            except TimeoutError:
                tries += 1
        assert answer is not None, "sailmujoco sitl never answered"
        # frame 0 may have gone out more than once while the command started (a slow machine):
        # each copy is answered, so take every answer still to come before counting frames
        try:
            while True:
                sock.recv(65536)
        except TimeoutError:
            pass
        steer = list(NEUTRAL)
        steer[0] = 1600
        for k in range(1, 601):  # 3 s: 0.1 s held (steering), then sailing
            sock.sendto(servo_packet(steer, 400, k), ("127.0.0.1", port))
            assert sock.recv(65536)
        process.send_signal(getattr(signal, stop))
        text, _ = process.communicate(timeout=120)
    finally:
        sock.close()
        if process.poll() is None:
            process.kill()
    assert process.returncode == 0, text
    how = "interrupted" if stop == "SIGINT" else "terminated"
    assert f"sitl: {how} at t = 3.00 s" in text and "Traceback" not in text
    assert "ArduPilot steered at t = 0.10 s; the boat leaves its mooring" in text
    assert "601 frames (3.0 s simulated)" in text and "filming 15 frames" in text
    rows = (out / "trajectory.csv").read_text().splitlines()
    assert rows[0].startswith("t,x,y,heading_deg") and len(rows) == 1 + 30  # 0.105 s to 3.005 s
    assert (out / "film.mp4").stat().st_size > 1000


def test_the_command_lines_seed_draws_the_sea_and_the_sea_it_draws_moves_the_boat():
    """``--seed`` draws the sea's phases (unless ``--waves`` gives its own seed), from the wind's
    direction; two seeds are two seas, so the boat heaves differently on each."""
    from sailmujoco.cli.main import build_parser
    from sailmujoco.cli.sitl import sea_of

    parse = build_parser().parse_args
    assert sea_of(parse(["sitl", "saoud_robot"])) is None
    sea = sea_of(parse(["sitl", "saoud_robot", "--waves", "hs=1", "--seed", "3", "--wind-from", "90"]))
    assert (sea.hs, sea.seed) == (1.0, 3) and sea.direction_from == pytest.approx(math.pi / 2)
    own = parse(["sitl", "saoud_robot", "--waves", "hs=1", "--waves", "seed=5", "--seed", "3"])
    assert sea_of(own).seed == 5
    heave = []
    for seed in (0, 1):
        backend = JsonBackend("saoud_robot", wind_speed=5.0, waves=sea_of(parse(
            ["sitl", "saoud_robot", "--waves", "hs=1", "--seed", str(seed)])))
        lines = [json.loads(backend.handle(servo_packet(NEUTRAL, 200, k))) for k in range(2000)]  # 10 s
        heave.append([line["position"][2] for line in lines])
    assert np.ptp(heave[0]) > 0.1 and np.ptp(heave[1]) > 0.1  # a 1 m sea lifts the boat
    assert np.max(np.abs(np.subtract(heave[0], heave[1]))) > 0.05


def test_a_motor_pushes_along_the_hull_in_proportion_to_the_throttle_and_is_nothing_when_stopped():
    """The throttle channel's fraction of ``motor_thrust`` pushes the hull along its axis: from rest
    in still air the first 0.05 s are pure impulse (no drag yet), so the speed it gains doubles
    with the thrust and reverses with the throttle, and lies below Newton's F t / m (the water's
    added mass only slows it) and above F t / 2m (a slender hull's surge added mass is a tenth of
    its mass); a stopped motor (the middle), or none, leaves every answer as without one."""
    def speeds(thrust, throttle_pwm, frames=10):
        backend = JsonBackend("saoud_robot", wind_speed=0.0, heading_deg=90.0, motor_thrust=thrust)
        pwm = list(NEUTRAL)
        pwm[2] = throttle_pwm
        lines = [json.loads(backend.handle(servo_packet(pwm, 200, k))) for k in range(frames)]
        return backend, np.array(lines[-1]["velocity"]), [json.dumps(line) for line in lines]

    backend, ahead, _ = speeds(5.0, 2000)
    _, double, _ = speeds(10.0, 2000)
    _, astern, _ = speeds(5.0, 1000)
    _, half, _ = speeds(5.0, 1750)
    mass = backend.params.mass
    t = 10 * backend.dt
    assert ahead[1] > 0 and abs(ahead[0]) < 1e-3 * ahead[1]  # heading east: NED east only
    assert 5.0 * t / (2 * mass) < ahead[1] < 5.0 * t / mass
    assert double[1] == pytest.approx(2 * ahead[1], rel=1e-3)
    assert astern[1] == pytest.approx(-ahead[1], rel=1e-3)
    assert half[1] == pytest.approx(0.5 * ahead[1], rel=1e-3)
    assert backend.runs[-1][-1]["thrust"] == 5.0 and backend.runs[-1][-1]["throttle_pwm"] == 2000
    assert speeds(5.0, 1500)[2] == speeds(0.0, 1500)[2] == speeds(0.0, 2000)[2]


def test_a_film_that_cannot_be_made_is_said_before_the_run(capsys):
    from sailmujoco.cli.main import main

    assert main(["sitl", "saoud_robot", "--video", "run.avi"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == "sailmujoco sitl: --video run.avi: the film is an .mp4 file"
