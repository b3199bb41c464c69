"""The scene of a frame: the state drawn (:class:`Snapshot`), the display copy of the boat
(:func:`display_model`) and :class:`SceneRenderer`, which poses it, places the camera and draws.

What is drawn is a display copy of the boat, compiled from the same parameters and given the
simulated pose each frame; the simulation's own model is never touched. The display copy
closes the hull's deck and winds its faces outward (the generated canoe body is open at the
deck and wound inward, which OpenGL's back-face culling shows as a sliver).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import overlays
from .gl import import_gl, offscreen_renderer
from .overlays import FORCES

CAMERAS = ("follow", "top", "side")
FORCE_SITES = {"sail": "sail_ce", "keel": "keel_cp", "rudder": "rudder_cp"}
REFERENCE_WIND = 10.0  # m/s: a force of 0.5 rho_air A_sail (10 m/s)^2 ...
FORCE_ARROW = 1.5  # ... is drawn this many masthead heights long
SEA_ALPHA = 0.45  # opacity of the display sea (the scene's 0.85 hides the keel and rudder)


# ----------------------------------------------------------------------------- state to draw
@dataclass
class Snapshot:
    """What one frame draws, in world ENU and body FLU frames, SI units.

    Parameters
    ----------
    time : float
        Simulated time, s.
    position : numpy.ndarray, shape (3,)
        Position of CO in the world frame, m.
    rotation : numpy.ndarray, shape (3, 3)
        Rotation from the body frame to the world frame.
    rudder, sail : float
        Rudder and sail angles, rad.
    speed : float
        Speed over ground, m/s.
    heel : float
        Heel, rad, positive starboard down.
    awa : float
        Apparent wind angle at the masthead, rad, positive from starboard.
    aws : float
        Apparent wind speed at the masthead, m/s.
    wind : numpy.ndarray, shape (3,)
        True wind velocity in the world frame, m/s.
    forces : dict
        Force model name -> its force in the body frame, shape (3,), N.
    """

    time: float
    position: np.ndarray
    rotation: np.ndarray
    rudder: float
    sail: float
    speed: float
    heel: float
    awa: float
    aws: float
    wind: np.ndarray
    forces: dict = field(default_factory=dict)


def snapshot_physics(physics) -> Snapshot:
    """The state of a :class:`~sailmujoco.physics.BoatPhysics` now (also between control steps).

    Parameters
    ----------
    physics : BoatPhysics
        The simulation.
    """
    terms = physics.force_terms()  # brings kinematics and forces up to the current state
    return Snapshot(time=float(physics.data.time), position=physics.position(),
                    rotation=physics.rotation(), rudder=physics.rudder_angle(),
                    sail=physics.sail_angle(), speed=physics.speed_over_ground(),
                    heel=physics.heel(), awa=physics.apparent_wind_angle(),
                    aws=physics.apparent_wind_speed(), wind=np.asarray(physics.true_wind(), float),
                    forces={name: np.asarray(terms[name][:3], float) for name in FORCES})


def snapshot_observation(observation) -> Snapshot:
    """The state from a task observation (:func:`sailmujoco.tasks.base.measure`), for any world.

    Parameters
    ----------
    observation : dict
        A task's observation, with its ``true_state``.
    """
    from ..frames import matrix_from_euler, yaw_from_heading

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


def yaw_of(rotation: np.ndarray) -> float:
    """Yaw (rad, ENU, counter-clockwise from east) of a body -> world rotation matrix.

    Parameters
    ----------
    rotation : ndarray
        (3, 3) body -> world.
    """
    return math.atan2(rotation[1, 0], rotation[0, 0])


def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


# ----------------------------------------------------------------------------- display model
def close_outward(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A mesh closed (each boundary loop capped by a fan from its centroid) and wound outward.

    Parameters
    ----------
    vertices : array_like
        Flat or (n, 3) vertex coordinates.
    faces : array_like
        Flat or (m, 3) vertex indices of the triangles.

    Returns
    -------
    tuple of ndarray
        Flat (vertices, faces). A closed, outward mesh comes back unchanged.
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

    Parameters
    ----------
    params : BoatParams
        The boat.
    sail_mode : str
        As the simulated boat.
    width, height : int
        Smallest offscreen buffer, pixels.
    """
    import mujoco

    from .. import mjcf

    spec = mjcf.boat_spec(params, sail_mode, dofs=6)
    hull = spec.mesh("hull_mesh")
    hull.uservert, hull.userface = (a.tolist() for a in close_outward(hull.uservert, hull.userface))
    model = mujoco.MjModel.from_xml_string(
        mjcf.scene_for(params), assets={f"{params.name}.xml": spec.to_xml().encode()})
    sea = model.material("sea")
    square = params.hull.length / 8.0  # m, one checker square
    model.mat_texrepeat[sea.id] = 1.0 / (2.0 * square)  # texuniform: repeats per metre
    model.mat_rgba[sea.id, 3] = SEA_ALPHA
    model.vis.quality.shadowsize = 0
    model.vis.global_.offwidth = max(int(model.vis.global_.offwidth), int(width))
    model.vis.global_.offheight = max(int(model.vis.global_.offheight), int(height))
    return model


class SceneRenderer:
    """Draws snapshots (:class:`Snapshot`) of one boat with one camera into RGB frames.

    Parameters
    ----------
    params : BoatParams
        The boat drawn (its display model is compiled here).
    width, height : int
        Frame size, pixels.
    camera : {"follow", "top", "side"}
        See :mod:`sailmujoco.video`.
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
        Camera settings (:mod:`sailmujoco.video`); distances in m, lag in s.
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
            mujoco = import_gl()
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
            self._renderer = offscreen_renderer(m, self.width, self.height)  # GL context
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
        yaw = yaw_of(snap.rotation)
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
        """Pose the display model (``self.data``) as ``snap``.

        Parameters
        ----------
        snap : Snapshot
            The state drawn.
        """
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

    def decorate(self, scene, snap: Snapshot) -> None:
        """Add the wind arrow, force arrows, target and circles to MuJoCo's scene.

        Parameters
        ----------
        scene : mujoco.MjvScene
            The scene drawn (posed by :meth:`pose`).
        snap : Snapshot
            The state drawn.
        """
        xpos = self.data.site_xpos
        overlays.decorate(scene, snap, masthead=xpos[self._masthead],
                          sites={name: xpos[site] for name, site in self._sites.items()},
                          h=self.h, force_scale=self.force_scale, forces=self.show_forces,
                          target=self.target)

    def text_lines(self, snap: Snapshot) -> list[str]:
        """The text box's lines: labels, time, speed, heel, apparent wind, rudder, sail.

        Parameters
        ----------
        snap : Snapshot
            The state described.
        """
        return overlays.text_lines(snap, self.labels, self.target)

    # ---- a frame
    def render(self, snap: Snapshot, note: str | None = None) -> np.ndarray:
        """One RGB frame (height, width, 3) uint8 of ``snap``.

        Parameters
        ----------
        snap : Snapshot
            The state drawn.
        note : str, optional
            A red line across the frame.
        """
        if self._renderer is None:
            raise RuntimeError("this SceneRenderer was made with offscreen=False: no GL context to draw")
        self.pose(snap)
        self._place_camera(snap)
        renderer = self._renderer
        renderer.update_scene(self.data, self._camera, self._option)
        self.decorate(renderer.scene, snap)
        frame = renderer.render()
        if self.show_overlay or note:
            if self._font is None:
                self._font = overlays.font(self.height)
            lines = self.text_lines(snap) if self.show_overlay else None
            frame = overlays.draw_text(frame, self._font, lines, overlays.legend(self.show_forces), note)
        return np.ascontiguousarray(frame)
