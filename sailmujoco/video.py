"""Offscreen video of a task run: a boat sailing under a controller, written as an H.264 mp4.

Example::

    from sailmujoco import video
    video.record("wille_yacht", "beam_reach_roll", "wille_roll", "beam_reach.mp4", seconds=30)

or ``sailmujoco video wille_yacht beam_reach_roll --controller wille_roll --seconds 30
--out beam_reach.mp4`` (``python -m sailmujoco.video ...`` takes the same arguments).

What a frame shows
    The boat as MuJoCo draws it (hull, keel, mast, boom and sail on the ``sail`` joint, rudder
    blade on the ``rudder`` joint), heeling and pitching with the hull, on the sea plane whose
    checker grid (squares of 1/8 hull length) shows the speed. Added to MuJoCo's scene: the
    true-wind arrow centred just above the masthead (cyan, pointing where the wind blows to,
    6 % of the masthead height per m/s); with ``forces``, the sail, keel and rudder force
    vectors at ``sail_ce``, ``keel_cp`` and ``rudder_cp`` (red, green, orange; 1.5 masthead
    heights for 0.5 rho_air A_sail (10 m/s)^2, clipped at 2); for position keeping, the target
    buoy and the target and pre-arrival circles. With ``overlay``, a text box (time, speed over
    ground, heel, apparent wind angle and speed at the masthead, rudder and sail angles,
    distance to the target) and a colour legend are drawn with PIL. The sea is drawn
    see-through so that the keel, the rudder blade and their forces show.

Cameras (``camera``)
    ``"follow"``: chases the boat from ``follow_distance`` m (default 2.3 masthead heights) at
    ``follow_bearing_deg`` from the bow (counter-clockwise, default 150: the port quarter) and
    ``follow_elevation_deg`` above the horizon; its azimuth follows the heading through a
    first-order lag of ``follow_lag`` s, so a turn shows as the hull turning on the grid.
    ``"top"``: looks straight down, north up. For tasks with a target (position keeping) it is
    fixed over the target area, start and circles; otherwise it rides above the boat. Give
    ``top_center=(x, y)`` (m) and ``top_extent`` (m, half-height of the view on the water) for
    any fixed view. ``"side"``: the boat model's own ``side`` camera (tracks the hull's centre
    of mass, fixed orientation).

Timing
    Frame k shows the state at t = k / fps whatever the control rate. In the MuJoCo world each
    control step's physics sub-steps are split at the frame times, which leaves the trajectory
    unchanged bit for bit (:meth:`sailmujoco.physics.BoatPhysics.step`). A paper world moves by
    whole control steps (its integrator is adaptive), so frame k shows the state at the end of
    the control step that contains t = k / fps (the text box gives that state's time). A
    ``seconds`` run gives ``round(seconds * fps)`` frames; a run that stops early (capsize)
    ends with its last frame, marked with the reason, held for one second.

What is drawn is a display copy of the boat, compiled from the same parameters and given the
simulated pose each frame; the simulation's own model is never touched. The display copy
closes the hull's deck and winds its faces outward (the generated canoe body is open at the
deck and wound inward, which OpenGL's back-face culling shows as a sliver).

Rendering needs an OpenGL platform, named by ``MUJOCO_GL`` before Python starts. sailmujoco
sets ``MUJOCO_GL=egl`` unless it is set: Mesa's llvmpipe renders on the CPU (Debian packages
``libegl1 libegl-mesa0 libgl1-mesa-dri``), the NVIDIA driver on a GPU. The fallback is OSMesa:
``apt-get install libosmesa6`` and ``MUJOCO_GL=osmesa``. Without a platform,
:class:`RenderingUnavailable` says so and names these fixes. Shadows and reflections are off.
The mp4 is encoded by the ffmpeg binary that the ``imageio-ffmpeg`` package ships.
"""

from __future__ import annotations

import argparse
import ast
import math
import os
import sys
import time
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .progress import Progress

CAMERAS = ("follow", "top", "side")
FORCES = ("sail", "keel", "rudder")
FORCE_SITES = {"sail": "sail_ce", "keel": "keel_cp", "rudder": "rudder_cp"}
COLOURS = {"sail": (0.95, 0.15, 0.1, 1.0), "keel": (0.1, 0.85, 0.25, 1.0),
           "rudder": (1.0, 0.55, 0.0, 1.0), "wind": (0.3, 0.95, 1.0, 1.0),
           "target": (1.0, 0.45, 0.0, 1.0), "target_area": (0.2, 1.0, 0.4, 0.3),
           "prearrival_area": (1.0, 0.9, 0.2, 0.2)}
KNOT = 1852.0 / 3600.0  # m/s per knot
WIND_ARROW_PER_MPS = 0.06  # masthead heights of arrow per m/s of wind
REFERENCE_WIND = 10.0  # m/s: a force of 0.5 rho_air A_sail (10 m/s)^2 ...
FORCE_ARROW = 1.5  # ... is drawn this many masthead heights long
MAX_ARROW = 2.0  # masthead heights: longer arrows are clipped (the text keeps the numbers)
SEA_ALPHA = 0.45  # opacity of the display sea (the scene's 0.85 hides the keel and rudder)

FIX = ("set MUJOCO_GL=egl before starting Python (Mesa's EGL renders on the CPU: apt-get install "
       "libegl1 libegl-mesa0 libgl1-mesa-dri; on a GPU the NVIDIA driver provides EGL), or "
       "apt-get install libosmesa6 and set MUJOCO_GL=osmesa")


class RenderingUnavailable(RuntimeError):
    """No OpenGL platform could be loaded for offscreen rendering; the message names the fix."""


def _loaded_platform() -> str | None:
    """The GL platform mujoco loaded when it was imported ('egl', 'glfw', 'osmesa'), if any."""
    mujoco = sys.modules.get("mujoco")
    context = getattr(mujoco, "GLContext", None)
    return context.__module__.split(".")[1] if context is not None else None


def _unavailable(err: BaseException) -> RenderingUnavailable:
    backend = os.environ.get("MUJOCO_GL", "")
    loaded = _loaded_platform()
    late = ""
    if loaded is not None and loaded != backend.lower():
        late = (f" mujoco was imported before MUJOCO_GL was set and loaded {loaded!r}: set MUJOCO_GL "
                "in the environment, or import sailmujoco before mujoco.")
    return RenderingUnavailable(
        f"cannot render offscreen: no OpenGL platform could be loaded with MUJOCO_GL={backend!r} "
        f"({type(err).__name__}: {err}).{late} Fix: {FIX}.")


def _import_gl():
    """Import MuJoCo with its offscreen renderer; a GL platform that cannot load raises
    :class:`RenderingUnavailable` (mujoco loads the MUJOCO_GL platform when it is imported)."""
    try:
        import mujoco
    except Exception as err:  # AttributeError, OSError, RuntimeError... from PyOpenGL/mujoco
        raise _unavailable(err) from err
    if not hasattr(mujoco, "Renderer"):
        raise _unavailable(ImportError("mujoco has no offscreen Renderer for this GL platform"))
    return mujoco


def _renderer(model, width: int, height: int):
    """A ``mujoco.Renderer`` (its GL context is made here) or :class:`RenderingUnavailable`."""
    mujoco = _import_gl()
    try:
        return mujoco.Renderer(model, height, width, max_geom=2000)
    except Exception as err:  # GL context or MjrContext creation
        raise _unavailable(err) from err


def check_rendering() -> None:
    """Raise :class:`RenderingUnavailable` unless an offscreen GL context can be made here."""
    mujoco = _import_gl()
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><visual><global offwidth="16" offheight="16"/></visual>'
        '<worldbody><geom size="1"/></worldbody></mujoco>')
    _renderer(model, 16, 16).close()


# ----------------------------------------------------------------------------- state to draw
@dataclass
class Snapshot:
    """What one frame draws, in world ENU and body FLU frames, SI units."""

    time: float  # s
    position: np.ndarray  # (3,) m, CO
    rotation: np.ndarray  # (3, 3) body -> world
    rudder: float  # rad
    sail: float  # rad
    speed: float  # m/s over ground
    heel: float  # rad
    awa: float  # rad, apparent wind angle at the masthead
    aws: float  # m/s
    wind: np.ndarray  # (3,) m/s, true wind, world
    forces: dict = field(default_factory=dict)  # name -> (3,) N, body frame


def snapshot_physics(physics) -> Snapshot:
    """The state of a :class:`~sailmujoco.physics.BoatPhysics` now (also between control steps)."""
    terms = physics.force_terms()  # brings kinematics and forces up to the current state
    return Snapshot(time=float(physics.data.time), position=physics.position(),
                    rotation=physics.rotation(), rudder=physics.rudder_angle(),
                    sail=physics.sail_angle(), speed=physics.speed_over_ground(),
                    heel=physics.heel(), awa=physics.apparent_wind_angle(),
                    aws=physics.apparent_wind_speed(), wind=np.asarray(physics.true_wind(), float),
                    forces={name: np.asarray(terms[name][:3], float) for name in FORCES})


def snapshot_observation(observation) -> Snapshot:
    """The state from a task observation (:func:`sailmujoco.tasks.base.measure`), for any world."""
    from .frames import matrix_from_euler, yaw_from_heading

    ts = observation["true_state"]
    position = np.zeros(3)
    position[:2] = observation["position"]
    heel = float(observation["heel"])
    rotation = matrix_from_euler(heel, float(ts.get("pitch", 0.0)),
                                 float(yaw_from_heading(float(observation["heading"]))))
    wind = np.zeros(3)
    wind[:2] = np.asarray(ts["true_wind"], float)[:2]
    return Snapshot(time=float(ts["time"]), position=position, rotation=rotation,
                    rudder=float(ts["rudder"]), sail=float(ts["sail"]),
                    speed=float(np.linalg.norm(observation["velocity"])), heel=heel,
                    awa=float(observation["apparent_wind_angle"]),
                    aws=float(observation["apparent_wind_speed"]), wind=wind,
                    forces={name: np.asarray(ts.get(f"{name}_wrench", np.zeros(6)), float)[:3]
                            for name in FORCES})


# ----------------------------------------------------------------------------- display model
def _close_outward(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A mesh closed (each boundary loop capped by a fan from its centroid) and wound outward.

    Returns flat (vertices, faces) arrays. A closed, outward mesh comes back unchanged.
    """
    verts = [tuple(v) for v in np.asarray(vertices, float).reshape(-1, 3)]
    tris = [tuple(int(i) for i in f) for f in np.asarray(faces, int).reshape(-1, 3)]
    directed = {(t[a], t[b]) for t in tris for a, b in ((0, 1), (1, 2), (2, 0))}
    following = {a: b for a, b in directed if (b, a) not in directed}
    while following:
        start = next(iter(following))
        loop, node = [start], following.pop(start)
        while node != start and node in following:
            loop.append(node)
            node = following.pop(node)
        centre = len(verts)
        verts.append(tuple(np.mean([verts[i] for i in loop], axis=0)))
        # the cap runs each boundary edge (a, b) backwards, as a consistent neighbour must
        tris += [(loop[(i + 1) % len(loop)], loop[i], centre) for i in range(len(loop))]
    v, f = np.array(verts), np.array(tris)
    volume = np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]])).sum() / 6.0
    if volume < 0.0:
        f = f[:, ::-1]
    return v.ravel(), f.ravel()


def display_model(params, sail_mode: str = "actuated", width: int = 640, height: int = 480):
    """The boat and scene compiled for drawing only (raw ``mujoco.MjModel``, 6 DOF).

    Display changes (none touches a simulation): the hull mesh closed and wound outward, the
    sea's checker squares 1/8 of the hull length and opacity :data:`SEA_ALPHA`, shadows off,
    an offscreen buffer of at least ``width`` x ``height``.
    """
    import mujoco

    from . import mjcf

    spec = mjcf.boat_spec(params, sail_mode, dofs=6)
    hull = spec.mesh("hull_mesh")
    hull.uservert, hull.userface = (a.tolist() for a in _close_outward(hull.uservert, hull.userface))
    model = mujoco.MjModel.from_xml_string(
        mjcf.scene_xml(params.name), assets={f"{params.name}.xml": spec.to_xml().encode()})
    sea = model.material("sea")
    square = params.hull.length / 8.0  # m, one checker square
    model.mat_texrepeat[sea.id] = 1.0 / (2.0 * square)  # texuniform: repeats per metre
    model.mat_rgba[sea.id, 3] = SEA_ALPHA
    model.vis.quality.shadowsize = 0
    model.vis.global_.offwidth = max(int(model.vis.global_.offwidth), int(width))
    model.vis.global_.offheight = max(int(model.vis.global_.offheight), int(height))
    return model


def _yaw_of(rotation: np.ndarray) -> float:
    return math.atan2(rotation[1, 0], rotation[0, 0])


def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


class SceneRenderer:
    """Draws snapshots (:class:`Snapshot`) of one boat with one camera into RGB frames.

    Parameters
    ----------
    params : BoatParams
        The boat drawn (its display model is compiled here).
    width, height : int
        Frame size, pixels.
    camera : {"follow", "top", "side"}
        See the module docstring.
    forces, overlay : bool
        Force arrows; text box.
    sail_mode : str
        As the simulated boat (the sheeted rig has the same joints).
    target : dict, optional
        ``{"position": (x, y), "radii": (d_T, d_M), "start": (x, y)}`` (m) to draw the target
        buoy and circles, and to frame the top view.
    labels : str
        First line of the text box (boat, task, controller).
    follow_distance, follow_bearing_deg, follow_elevation_deg, follow_lag, top_center, top_extent
        Camera settings (module docstring); distances in m, lag in s.
    offscreen : bool
        Make the offscreen GL context that :meth:`render` draws with. Without it the display
        model, :meth:`pose`, :meth:`decorate` and :meth:`text_lines` serve a window that has its
        own context (``sailmujoco view``).
    """

    def __init__(self, params, width: int = 640, height: int = 480, camera: str = "follow",
                 forces: bool = True, overlay: bool = True, sail_mode: str = "actuated",
                 target: dict | None = None, labels: str = "",
                 follow_distance: float | None = None, follow_bearing_deg: float = 150.0,
                 follow_elevation_deg: float = -14.0, follow_lag: float = 3.0,
                 top_center=None, top_extent: float | None = None, offscreen: bool = True):
        if camera not in CAMERAS:
            raise ValueError(f"unknown camera {camera!r}; choose one of {CAMERAS}")
        if offscreen:
            mujoco = _import_gl()
        else:
            import mujoco
        self._mujoco = mujoco
        self.params = params
        self.width, self.height = int(width), int(height)
        self.camera_name = camera
        self.show_forces, self.show_overlay = forces, overlay
        self.target = target
        self.labels = labels
        m = self.model = display_model(params, sail_mode, width, height)
        self.data = mujoco.MjData(m)
        self._rudder = m.jnt_qposadr[m.joint("rudder").id]
        self._sail = m.jnt_qposadr[m.joint("sail").id]
        self._sites = {name: m.site(site).id for name, site in FORCE_SITES.items()}
        self._masthead = m.site("masthead").id
        self.h = float(m.site_pos[self._masthead][2])  # m, masthead height: the scale of drawings
        reference = 0.5 * params.rho_air * params.sail.area * REFERENCE_WIND**2  # N
        self.force_scale = FORCE_ARROW * self.h / reference  # m per N
        self.follow_distance = follow_distance or 2.3 * self.h
        self.follow_bearing = math.radians(follow_bearing_deg)
        self.follow_elevation = follow_elevation_deg
        self.follow_lag = follow_lag
        self._yaw_smooth = None
        self._last_time = None
        self._fovy = float(m.vis.global_.fovy)
        self.top_pose = self._top_pose(top_center, top_extent)
        self._camera = mujoco.MjvCamera()
        if camera == "side":
            self._camera.type = mujoco.mjtCamera.mjCAMERA_FIXED
            self._camera.fixedcamid = m.camera("side").id
        else:
            self._camera.type = mujoco.mjtCamera.mjCAMERA_FREE
        self._option = mujoco.MjvOption()
        self._option.sitegroup[:] = 0  # the force points are drawn as arrows, not as sites
        self._font = None
        self._renderer = None
        if offscreen:
            self._renderer = _renderer(m, self.width, self.height)  # GL context
            flags = self._renderer.scene.flags
            flags[mujoco.mjtRndFlag.mjRND_SHADOW] = 0
            flags[mujoco.mjtRndFlag.mjRND_REFLECTION] = 0

    def close(self) -> None:
        """Free the GL context (the renderer cannot draw afterwards)."""
        if self._renderer is not None:
            self._renderer.close()

    def __enter__(self) -> SceneRenderer:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # ---- cameras
    def _top_pose(self, center, extent):
        """(lookat, distance) of a fixed top view, or None for a top view riding the boat."""
        aspect = self.width / self.height
        if center is None and self.target is not None:
            points = [np.asarray(self.target["position"], float)]
            if self.target.get("start") is not None:
                points.append(np.asarray(self.target["start"], float))
            r = max(self.target["radii"])
            low = np.min(points, axis=0) - r
            high = np.max(points, axis=0) + r
            center = 0.5 * (low + high)
            if extent is None:
                extent = 1.15 * max(0.5 * (high[1] - low[1]), 0.5 * (high[0] - low[0]) / aspect)
        if center is None:
            return None
        extent = extent or 3.0 * self.params.hull.length
        distance = extent / math.tan(math.radians(self._fovy) / 2.0)
        return np.array([center[0], center[1], 0.0]), distance

    def _place_camera(self, snap: Snapshot) -> None:
        if self.camera_name == "side":
            return
        if self.camera_name == "top":
            if self.top_pose is None:
                lookat = np.array([snap.position[0], snap.position[1], 0.0])
                distance = 3.0 * self.params.hull.length / math.tan(math.radians(self._fovy) / 2.0)
            else:
                lookat, distance = self.top_pose
            self._set_free(lookat, distance, 90.0, -90.0)  # north up
            return
        yaw = _yaw_of(snap.rotation)
        if self._yaw_smooth is None or self.follow_lag <= 0.0:
            self._yaw_smooth = yaw
        else:
            dt = max(snap.time - self._last_time, 0.0)
            self._yaw_smooth += _wrap(yaw - self._yaw_smooth) * (1.0 - math.exp(-dt / self.follow_lag))
        self._last_time = snap.time
        # the camera sits at bearing b from the bow, so it looks along yaw + b + pi
        azimuth = math.degrees(self._yaw_smooth + self.follow_bearing + math.pi)
        lookat = snap.position + np.array([0.0, 0.0, 0.45 * self.h])
        self._set_free(lookat, self.follow_distance, azimuth, self.follow_elevation)

    def _set_free(self, lookat, distance: float, azimuth_deg: float, elevation_deg: float) -> None:
        """MuJoCo free camera: looks at ``lookat`` along azimuth (ENU, deg) and elevation (deg)."""
        cam = self._camera
        cam.lookat[:] = lookat
        cam.distance = distance
        cam.azimuth = azimuth_deg
        cam.elevation = elevation_deg

    # ---- the scene
    def pose(self, snap: Snapshot) -> None:
        """Pose the display model (``self.data``) as ``snap``."""
        mujoco = self._mujoco
        m, d = self.model, self.data
        d.qpos[0:3] = snap.position
        quat = np.empty(4)
        mujoco.mju_mat2Quat(quat, np.ascontiguousarray(snap.rotation, dtype=float).ravel())
        d.qpos[3:7] = quat
        d.qpos[self._rudder] = snap.rudder
        d.qpos[self._sail] = snap.sail
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_camlight(m, d)

    def _geom(self, scene, kind, size, pos, mat, rgba):
        if scene.ngeom >= scene.maxgeom:
            return None
        geom = scene.geoms[scene.ngeom]
        self._mujoco.mjv_initGeom(geom, kind, np.asarray(size, float), np.asarray(pos, float),
                                  np.asarray(mat, float).ravel(), np.asarray(rgba, np.float32))
        geom.emission = 0.35  # vivid whatever the light
        scene.ngeom += 1
        return geom

    def _arrow(self, scene, start, vector, width, rgba) -> None:
        length = float(np.linalg.norm(vector))
        if length < 1e-6:
            return
        vector = vector * min(1.0, MAX_ARROW * self.h / length)
        mujoco = self._mujoco
        geom = self._geom(scene, mujoco.mjtGeom.mjGEOM_ARROW, np.zeros(3), np.zeros(3), np.eye(3), rgba)
        if geom is not None:
            mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_ARROW, width, np.asarray(start, float),
                                 np.asarray(start, float) + vector)

    def decorate(self, scene, snap: Snapshot) -> None:
        """Add the wind arrow, force arrows, target and circles to MuJoCo's scene."""
        mujoco, d = self._mujoco, self.data
        wind = np.array([snap.wind[0], snap.wind[1], 0.0])
        speed = float(np.linalg.norm(wind))
        if speed > 1e-6:  # a wind vane: centred just above the masthead
            centre = d.site_xpos[self._masthead] + np.array([0.0, 0.0, 0.1 * self.h])
            vector = WIND_ARROW_PER_MPS * self.h * wind
            self._arrow(scene, centre - 0.5 * vector, vector, 0.025 * self.h, COLOURS["wind"])
        if self.show_forces:
            for name in FORCES:
                force = snap.rotation @ snap.forces[name] * self.force_scale
                self._arrow(scene, d.site_xpos[self._sites[name]], force, 0.02 * self.h, COLOURS[name])
        if self.target is not None:
            x, y = self.target["position"]
            d_target, d_pre = self.target["radii"]
            flat = mujoco.mjtGeom.mjGEOM_CYLINDER
            # cylinder size: (radius, half-height, unused)
            self._geom(scene, flat, (d_pre, 0.01, 0.0), (x, y, 0.02), np.eye(3),
                       COLOURS["prearrival_area"])
            self._geom(scene, flat, (d_target, 0.01, 0.0), (x, y, 0.04), np.eye(3),
                       COLOURS["target_area"])
            for radius in (d_target, d_pre):
                self._ring(scene, x, y, radius, 0.004 * radius + 0.03, (1.0, 1.0, 0.6, 1.0))
            buoy = 0.04 * self.h + 0.15
            self._geom(scene, mujoco.mjtGeom.mjGEOM_SPHERE, (buoy, 0, 0), (x, y, 0.3 * buoy), np.eye(3),
                       COLOURS["target"])

    def _ring(self, scene, x, y, radius, width, rgba, segments: int = 48) -> None:
        mujoco = self._mujoco
        angles = np.linspace(0.0, 2.0 * np.pi, segments + 1)
        points = np.stack([x + radius * np.cos(angles), y + radius * np.sin(angles),
                           np.full_like(angles, 0.06)], axis=1)
        for a, b in zip(points[:-1], points[1:], strict=True):
            geom = self._geom(scene, mujoco.mjtGeom.mjGEOM_CAPSULE, np.zeros(3), np.zeros(3),
                              np.eye(3), rgba)
            if geom is None:
                return
            mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_CAPSULE, width, a, b)

    # ---- a frame
    def render(self, snap: Snapshot, note: str | None = None) -> np.ndarray:
        """One RGB frame (height, width, 3) uint8 of ``snap``; ``note`` adds a red line."""
        if self._renderer is None:
            raise RuntimeError("this SceneRenderer was made with offscreen=False: no GL context to draw")
        self.pose(snap)
        self._place_camera(snap)
        renderer = self._renderer
        renderer.update_scene(self.data, self._camera, self._option)
        self.decorate(renderer.scene, snap)
        frame = renderer.render()
        if self.show_overlay or note:
            frame = self._text(frame, snap, note)
        return np.ascontiguousarray(frame)

    def text_lines(self, snap: Snapshot) -> list[str]:
        """The text box's lines: labels, time, speed, heel, apparent wind, rudder, sail."""
        lines = [self.labels] if self.labels else []
        lines += [f"t {snap.time:.1f} s    speed {snap.speed:.2f} m/s ({snap.speed / KNOT:.1f} kn)",
                  f"heel {math.degrees(snap.heel):+.1f}°    AWA {math.degrees(snap.awa):+.0f}°    "
                  f"AWS {snap.aws:.1f} m/s",
                  f"rudder {math.degrees(snap.rudder):+.1f}°    sail {math.degrees(snap.sail):+.1f}°"]
        if self.target is not None:
            distance = float(np.linalg.norm(snap.position[:2] - np.asarray(self.target["position"])))
            lines.append(f"distance to target {distance:5.1f} m")
        return lines

    def _text(self, frame: np.ndarray, snap: Snapshot, note: str | None) -> np.ndarray:
        from PIL import Image, ImageDraw, ImageFont

        if self._font is None:
            self._font = ImageFont.load_default(size=max(9, round(self.height / 32)))
        font = self._font
        image = Image.fromarray(frame)
        draw = ImageDraw.Draw(image, "RGBA")
        size = font.size
        pad, step = size // 2, round(1.3 * size)
        if self.show_overlay:  # a box in the upper left: the lines, then the colour legend
            lines = self.text_lines(snap)
            legend = [(name, COLOURS[name]) for name in FORCES] if self.show_forces else []
            legend.append(("wind", COLOURS["wind"]))
            entries = [size + draw.textlength(name, font=font) + size for name, _ in legend]
            width = max(max(draw.textlength(line, font=font) for line in lines), sum(entries))
            top = 0
            draw.rectangle((0, 0, width + 2 * pad, (len(lines) + 1) * step + pad), fill=(0, 0, 0, 110))
            for i, line in enumerate(lines):
                draw.text((pad, top + pad + i * step), line, font=font, fill=(255, 255, 255, 255))
            x, y = pad, top + pad + len(lines) * step
            for (name, rgba), entry in zip(legend, entries, strict=True):
                colour = tuple(int(255 * c) for c in rgba[:3]) + (255,)
                draw.rectangle((x, y + size // 4, x + size // 2 + 2, y + 3 * size // 4 + 2), fill=colour)
                draw.text((x + size, y), name, font=font, fill=(255, 255, 255, 255))
                x += entry
        if note:
            y = self.height // 2 - size
            draw.rectangle((0, y - pad, self.width, y + step + pad), fill=(0, 0, 0, 140))
            draw.text((self.width // 2, y + step // 2), note, font=font, fill=(255, 80, 60, 255),
                      anchor="mm")
        return np.asarray(image)


# ----------------------------------------------------------------------------- recording
@dataclass
class Recording:
    """What :func:`record` wrote."""

    path: Path
    frames: int
    fps: float
    sim_time: float  # s simulated
    wall_time: float  # s, all of it (loading the boat and the controller included)
    loop_time: float  # s, from the first frame to the end (simulating, drawing, encoding)
    metrics: dict  # the task's metrics (``stopped`` holds the reason of an early end)

    @property
    def render_rate(self) -> float:
        """Frames per wall-clock second while recording (simulation, drawing and encoding)."""
        return self.frames / self.loop_time if self.loop_time > 0 else float("nan")


@contextmanager
def _frames_between_substeps(physics, emit: Callable[[], None], due: Callable[[], float | None]):
    """Split each ``physics.step(n)`` at the times returned by ``due()`` and call ``emit()`` there.

    ``BoatPhysics`` gives the same trajectory whatever the split (forces before every sub-step).
    """
    original = physics.step
    dt = float(physics.timestep())

    def step(nstep: int = 1) -> None:
        remaining = int(nstep)
        while remaining > 0:
            t_frame = due()
            if t_frame is None:
                original(remaining)
                return
            # sub-steps until the time is within half a step of the frame time
            count = math.ceil((t_frame - float(physics.data.time)) / dt - 0.5)
            count = min(max(count, 1), remaining)
            original(count)
            remaining -= count
            while (t := due()) is not None and float(physics.data.time) >= t - 0.5 * dt:
                emit()

    physics.step = step
    try:
        yield
    finally:
        del physics.step


def _even(name: str, value: int) -> int:
    value = int(value)
    if value < 16 or value % 2:
        raise ValueError(f"{name} must be an even number of pixels >= 16 (H.264, yuv420p), got {value}")
    return value


def scene_of(boat: str, env, options: dict) -> tuple[bool, object, str, dict | None]:
    """What a scene of ``env`` draws: (whether it is the MuJoCo world, the boat's parameters,
    the sail mode, the task's target area or None). A paper world is drawn as the named boat
    with an actuated sail."""
    from .params import get_boat
    from .physics import BoatPhysics

    physics = env.physics
    mujoco_world = isinstance(physics, BoatPhysics)
    if mujoco_world:
        params, sail_mode = physics.params, physics.sail_mode
    else:
        params, sail_mode = get_boat(boat, **(options.get("boat_options") or {})), "actuated"
    target = None
    if getattr(env.task, "target", None) is not None:
        target = {"position": tuple(env.task.target), "start": getattr(env.task, "start", None),
                  "radii": (env.task.d_target, env.task.d_prearrival)}
    return mujoco_world, params, sail_mode, target


def record(boat: str, task: str, controller, out_path, seconds: float | None = None,
           world: str = "mujoco", fps: float = 25, width: int = 640, height: int = 480,
           camera: str = "follow", overlay: bool = True, forces: bool = True, seed: int = 0, *,
           controller_options: dict | None = None, still=None, quality: float = 6.0,
           progress: bool = False, follow_distance: float | None = None,
           follow_bearing_deg: float = 150.0, follow_elevation_deg: float = -14.0,
           follow_lag: float = 3.0, top_center=None, top_extent: float | None = None,
           **options) -> Recording:
    """Run ``task`` on ``boat`` under ``controller`` and write the video to ``out_path`` (mp4).

    Parameters
    ----------
    boat, task, world : str
        As :func:`sailmujoco.suite.load`. In a paper world the drawn boat is ``boat``.
    controller : str or callable
        A registered controller name (:func:`sailmujoco.sweep.make_controller`, with
        ``controller_options``) or a factory ``factory(env) -> controller``.
    out_path : path
        The mp4 (H.264, yuv420p); written to a temporary name and renamed when complete.
    seconds : float, optional
        Simulated time (default: the task's duration); ``round(seconds * fps)`` frames.
    fps : float
        Frames per simulated second, independent of the control rate.
    width, height : int
        Frame size, even pixels.
    camera : {"follow", "top", "side"}
        See the module docstring.
    overlay, forces : bool
        Text box; sail/keel/rudder force arrows.
    seed : int
        Seeds the task (initial state, wind) and the controller.
    still : path, optional
        Also write the last frame as a PNG.
    quality : float
        imageio-ffmpeg quality, 1-10 (6: x264 CRF 20).
    progress : bool
        Progress over frames on stderr: a bar on a terminal, a plain line per tenth elsewhere.
    follow_distance, follow_bearing_deg, follow_elevation_deg, follow_lag, top_center, top_extent
        Camera settings, see :class:`SceneRenderer`.
    options
        Passed to :func:`sailmujoco.suite.load`: environment options (``hydrostatics``,
        ``dofs``, ``control_timestep``, ``boat_options`` ...) and task options (``case=3``...).

    Returns
    -------
    Recording
        Path, frame count, simulated and wall time, and the task's metrics.

    Raises
    ------
    RenderingUnavailable
        No OpenGL platform (the message names the fix: ``MUJOCO_GL=egl`` or OSMesa).
    """
    if camera not in CAMERAS:
        raise ValueError(f"unknown camera {camera!r}; choose one of {CAMERAS}")
    try:
        fps = float(fps)
    except (TypeError, ValueError):
        raise ValueError(f"fps must be a positive number, got {fps!r}") from None
    if not (math.isfinite(fps) and fps > 0):
        raise ValueError(f"fps must be a positive number, got {fps!r}")
    if seconds is not None and not (math.isfinite(seconds) and seconds > 0):
        raise ValueError(f"seconds must be a positive number of simulated seconds, got {seconds!r}")
    width, height = _even("width", width), _even("height", height)
    if follow_distance is not None and not (math.isfinite(follow_distance) and follow_distance > 0):
        raise ValueError(f"follow_distance (--distance) must be a number > 0 m, got {follow_distance!r}")
    if not math.isfinite(follow_bearing_deg):
        raise ValueError(f"follow_bearing_deg (--bearing) must be a finite angle in degrees, "
                         f"got {follow_bearing_deg!r}")
    for key, option in (("time_limit", "seconds (--seconds)"), ("seed", "seed (--seed)")):
        if key in options:
            raise ValueError(f"{key} is set by the argument {option}, not as an environment option")
    if not 1 <= quality <= 10:
        raise ValueError(f"quality must be between 1 and 10, got {quality!r}")
    _import_gl()
    try:
        import imageio_ffmpeg
    except ImportError as err:
        raise ImportError("video needs imageio-ffmpeg: pip install imageio-ffmpeg") from err
    from .suite import load
    from .sweep import make_controller

    start_wall = time.perf_counter()
    env = load(boat, task, world, seed=seed, time_limit=seconds, **options)
    if isinstance(controller, str):
        name = controller
        policy = make_controller(controller, env, **(controller_options or {}))
    else:
        name = getattr(controller, "__name__", type(controller).__name__)
        policy = controller(env)
    if hasattr(policy, "reset"):
        policy.reset(seed)
    physics = env.physics
    mujoco_world, params, sail_mode, target = scene_of(boat, env, options)
    duration = float(seconds) if seconds is not None else float(env.task.duration)
    n_frames = max(1, round(duration * fps))
    renderer = SceneRenderer(params, width, height, camera, forces=forces, overlay=overlay,
                             sail_mode=sail_mode, target=target,
                             labels=f"{boat} · {task} · {name} ({world})",
                             follow_distance=follow_distance, follow_bearing_deg=follow_bearing_deg,
                             follow_elevation_deg=follow_elevation_deg, follow_lag=follow_lag,
                             top_center=top_center, top_extent=top_extent)
    out_path = Path(out_path)
    out_path.parent.mkdir(parents=True, exist_ok=True)
    partial = out_path.with_name(f".{out_path.stem}.partial{out_path.suffix or '.mp4'}")
    writer = imageio_ffmpeg.write_frames(str(partial), (width, height), fps=fps, codec="libx264",
                                         quality=quality, macro_block_size=1,
                                         ffmpeg_log_level="error",
                                         output_params=["-preset", "faster", "-movflags", "+faststart"])
    writer.send(None)
    bar = Progress(n_frames, "video", show=progress, unit="frame")
    state = {"count": 0, "last": None}

    def due() -> float | None:
        return state["count"] / fps if state["count"] < n_frames else None

    def emit(snap: Snapshot) -> None:
        frame = renderer.render(snap)
        writer.send(frame)
        state["count"] += 1
        state["last"] = (snap, frame)
        bar.update()

    ok = False
    try:
        timestep = env.reset()
        start_loop = time.perf_counter()
        emit(snapshot_physics(physics) if mujoco_world else snapshot_observation(timestep.observation))
        hook = (_frames_between_substeps(physics, lambda: emit(snapshot_physics(physics)), due)
                if mujoco_world else _no_hook())
        with hook:
            while not timestep.last():
                timestep = env.step(policy(timestep))
                if not mujoco_world:  # sample and hold at the control steps
                    snap = snapshot_observation(timestep.observation)
                    while (t := due()) is not None and snap.time >= t - 1e-9:
                        emit(snap)
        metrics = env.task.metrics()
        final = state["last"][1]
        if metrics.get("stopped"):
            snap = state["last"][0]
            final = renderer.render(snap, note=f"stopped at t = {snap.time:.1f} s: {metrics['stopped']}")
            for _ in range(max(1, round(fps))):
                writer.send(final)
                state["count"] += 1
        if still is not None:
            from PIL import Image

            Path(still).parent.mkdir(parents=True, exist_ok=True)
            Image.fromarray(final).save(still, optimize=True)
        ok = True
    finally:
        writer.close()
        renderer.close()
        bar.close()
        if ok:
            os.replace(partial, out_path)
        else:
            partial.unlink(missing_ok=True)
    end = time.perf_counter()  # the encoder has finished
    return Recording(path=out_path, frames=state["count"], fps=fps, sim_time=float(physics.time()),
                     wall_time=end - start_wall, loop_time=end - start_loop, metrics=metrics)


@contextmanager
def _no_hook():
    yield


def record_study_scenario(out, boat: str, task: str, controller, *, seconds: float = 60.0,
                          name: str | None = None, **kwargs) -> Recording:
    """The video a study writes for its ``--video`` option: ``<out>/<name>.mp4``.

    A thin wrapper over :func:`record` (every keyword goes there: ``world``, ``camera``, task
    options...). ``name`` defaults to ``<boat>_<task>_<controller>``. In a study::

        if video:
            from sailmujoco.video import record_study_scenario
            record_study_scenario(out, "wille_yacht", "beam_reach_roll", "wille_roll", seconds=60)

    Raises :class:`RenderingUnavailable` where no OpenGL platform loads.
    """
    label = controller if isinstance(controller, str) else getattr(controller, "__name__", "controller")
    path = Path(out) / f"{name or f'{boat}_{task}_{label}'}.mp4"
    return record(boat, task, controller, path, seconds=seconds, **kwargs)


# ----------------------------------------------------------------------------- command line
def _value(text: str):
    """A ``--set`` value: a Python literal, TOML's true/false, or else the text itself."""
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


def _setting(text: str) -> tuple[str, object]:
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    return key.strip(), _value(value.strip())


def add_parser(subparsers) -> argparse.ArgumentParser:
    """Add ``video`` to the ``sailmujoco`` sub-commands; returns its parser."""
    from .cli import SEED

    parser = subparsers.add_parser(
        "video", help="record a task run as an mp4 (offscreen MuJoCo rendering)",
        description="Run TASK on BOAT under a controller and write an H.264 mp4. Needs an OpenGL "
                    f"platform: {FIX}.")
    parser.add_argument("boat")
    parser.add_argument("task")
    parser.add_argument("--controller", required=True, help="registered controller (pid, saoud, ...)")
    parser.add_argument("--world", default="mujoco", choices=("mujoco", "paper"))
    parser.add_argument("--seconds", type=float, default=30.0, help="simulated seconds (default 30)")
    parser.add_argument("--out", required=True, help="output file (.mp4); missing folders are made")
    parser.add_argument("--fps", type=float, default=25.0, help="frames per simulated second")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--camera", default="follow", choices=CAMERAS)
    parser.add_argument("--distance", type=float, help="follow camera distance, m")
    parser.add_argument("--bearing", type=float, default=150.0,
                        help="follow camera bearing from the bow, deg counter-clockwise (150)")
    parser.add_argument("--no-forces", action="store_true", help="no force arrows")
    parser.add_argument("--no-overlay", action="store_true", help="no text box")
    parser.add_argument("--seed", type=SEED, default=0)
    parser.add_argument("--still", help="also write the last frame as this PNG")
    parser.add_argument("--set", type=_setting, action="append", default=[], metavar="KEY=VALUE",
                        help="task or environment option, e.g. case=3 or hydrostatics=paper "
                             "(repeatable)")
    parser.add_argument("--no-progress", action="store_true")
    parser.set_defaults(func=run_cli)
    return parser


def check_settings(settings) -> None:
    """``--set`` of ``video`` and ``view``: the episode's seed and length have options of their own."""
    for key, option in (("time_limit", "--seconds"), ("seed", "--seed")):
        if key in dict(settings):
            raise ValueError(f"--set {key}=... is the option {option}")


def _file_argument(option: str, text: str, example: str) -> None:
    """A file to write, its missing folders made; a folder there, a file among its parents or a
    folder that cannot be made is one line."""
    path = Path(text)
    if path.is_dir():
        raise ValueError(f"{option} {text!r} is a folder; give a file name such as "
                         f"{str(path / example)!r}")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except (FileExistsError, NotADirectoryError):
        raise ValueError(f"{option} {text!r}: {str(path.parent)!r} is (or lies under) a file, "
                         f"not a folder") from None
    except OSError as err:  # no permission, a read-only or virtual file system
        raise ValueError(f"{option} {text!r}: cannot make the folder {str(path.parent)!r}: "
                         f"{err.strerror}") from None


def run_cli(args) -> int:
    """The ``video`` sub-command."""
    check_settings(args.set)
    _file_argument("--out", args.out, "run.mp4")
    if args.still:
        _file_argument("--still", args.still, "last.png")
    try:
        rec = record(args.boat, args.task, args.controller, args.out, seconds=args.seconds,
                     world=args.world, fps=args.fps, width=args.width, height=args.height,
                     camera=args.camera, overlay=not args.no_overlay, forces=not args.no_forces,
                     seed=args.seed, still=args.still, progress=not args.no_progress,
                     follow_distance=args.distance, follow_bearing_deg=args.bearing,
                     **dict(args.set))
    except RenderingUnavailable as err:
        print(f"sailmujoco video: error: {err}", file=sys.stderr)
        return 1
    stopped = rec.metrics.get("stopped")
    print(f"wrote {rec.path}: {rec.frames} frames at {rec.fps:g} fps, {rec.sim_time:.1f} s simulated, "
          f"{rec.wall_time:.1f} s wall ({rec.render_rate:.1f} frames/s while recording)"
          + (f"; stopped: {stopped}" if stopped else ""))
    if args.still:
        print(f"wrote {args.still}")
    return 0


def main(argv=None) -> int:
    """``python -m sailmujoco.video BOAT TASK --controller NAME --out FILE.mp4 ...``"""
    parser = argparse.ArgumentParser(prog="python -m sailmujoco.video")
    add_parser(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args(["video", *(sys.argv[1:] if argv is None else argv)])
    try:
        return args.func(args)
    except ValueError as err:
        print(f"sailmujoco video: error: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
