"""The scene of a frame: the state drawn (:class:`Snapshot`), the display copy of the boat
(:func:`display_model`) and :class:`SceneRenderer`, which poses it, places the camera
(:mod:`sailmujoco.video.camera`), draws the scene and, beside it, the panel
(:mod:`sailmujoco.video.panel`).

What is drawn is a display copy of the boat, compiled from the same parameters and given the
simulated pose each frame; the simulation's own model is never touched. The display copy
closes the hull's deck and winds its faces outward (the generated canoe body is open at the
deck and wound inward, which OpenGL's back-face culling shows as a sliver).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import overlays, panel, sea, water
from .camera import DISTANCE_MASTHEADS, ELEVATION_DEG, FollowCamera, boom_angle, top_pose, yaw_of
from .gl import import_gl, offscreen_renderer
from .headsail import add_headsail, pose_headsail
from .overlays import FORCES

CAMERAS = ("follow", "top", "side")
FORCE_SITES = {"sail": "sail_ce", "keel": "keel_cp", "rudder": "rudder_cp"}
FORCE_ARROW = 1.3  # masthead heights of arrow for a force of 0.5 rho_air A_sail U^2, U the run's
REFERENCE_WIND = 3.0  # true wind speed at its first frame, but at least this, m/s
SAIL_ALPHA = 0.6  # opacity of the display sail: its force arrow, to leeward, shows through it
REFERENCES = ("desired_heading", "desired_course", "target_position")  # what the map shows


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
    references : dict
        The task's references (``desired_heading``, ``desired_course`` in rad, compass;
        ``target_position`` in m), as its observation gives them.
    measured : dict or None
        What the boat's instruments last reported (:func:`sailmujoco.video.panel.measured_of`),
        drawn beside the truth; None for perfect sensors.
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
    references: dict = field(default_factory=dict)
    measured: dict | None = None



def snapshot_physics(physics, references: dict | None = None) -> Snapshot:
    """The state of a :class:`~sailmujoco.physics.BoatPhysics` now (also between control steps).

    Parameters
    ----------
    physics : BoatPhysics
        The simulation.
    references : dict, optional
        The task's references (``task.references(physics)``).
    """
    terms = physics.force_terms()  # brings kinematics and forces up to the current state
    return Snapshot(time=float(physics.data.time), position=physics.position(),
                    rotation=physics.rotation(), rudder=physics.rudder_angle(),
                    sail=physics.sail_angle(), speed=physics.speed_over_ground(),
                    heel=physics.heel(), awa=physics.apparent_wind_angle(),
                    aws=physics.apparent_wind_speed(), wind=np.asarray(physics.true_wind(), float),
                    forces={name: np.asarray(terms[name][:3], float) for name in FORCES},
                    references=dict(references or {}))


def snapshot_observation(observation) -> Snapshot:
    """The state from a task observation (:mod:`sailmujoco.measurement.observation`), for any world.

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
                            for name in FORCES},
                    references={key: observation[key] for key in REFERENCES if key in observation})


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


def display_model(params, sail_mode: str = "actuated", width: int = 640, height: int = 480,
                  waves=None):
    """The boat and scene compiled for drawing only (raw ``mujoco.MjModel``, 6 DOF).

    Display changes (none touches a simulation): the hull mesh closed and wound outward, the
    sea's wave texture and opacity and the deep water under it (:mod:`sailmujoco.video.water`),
    the sail see-through (:data:`SAIL_ALPHA`: the follow camera sits to windward, and the
    sail's force points to leeward), shadows off, an offscreen buffer of at least ``width`` x ``height``;
    with a sea, the moving surface in place of the flat one, a low sun over the waves' bearing and
    a fainter texture (:mod:`sailmujoco.video.sea`).

    Parameters
    ----------
    params : BoatParams
        The boat.
    sail_mode : str
        As the simulated boat.
    width, height : int
        Smallest offscreen buffer, pixels.
    waves : WaveConfig, optional
        The sea drawn; None or ``hs = 0``: the flat sea.
    """
    import mujoco

    from ..boat import mjcf

    boat = mjcf.boat_spec(params, sail_mode, dofs=6)
    hull = boat.mesh("hull_mesh")
    hull.uservert, hull.userface = (a.tolist() for a in close_outward(hull.uservert, hull.userface))
    spec = mujoco.MjSpec.from_string(mjcf.scene_for(params),
                                     include={f"{params.name}.xml": boat.to_xml().encode()})
    deepest = params.hull.canoe_draft + max(params.keel.span, params.rudder.span)  # m, the foils' tips
    water.add_deep_water(spec, deepest + 0.25 * params.hull.length)
    add_headsail(spec, params)
    if sea.has_sea(waves):
        sea.add_sea_surface(spec, sea.SeaLayout(waves, params.hull.length))
    model = spec.compile()
    if sea.has_sea(waves):
        sea.paint_the_sea(model, params.hull.length)
        sea.light_the_sea(model, waves)
    else:
        water.paint_sea(model, params.hull.length)
    model.mat_rgba[model.material("sailcloth").id, 3] = SAIL_ALPHA
    model.vis.quality.shadowsize = 0
    model.vis.global_.offwidth = max(int(model.vis.global_.offwidth), int(width))
    model.vis.global_.offheight = max(int(model.vis.global_.offheight), int(height))
    return model


class SceneRenderer:
    """Draws snapshots (:class:`Snapshot`) of one boat with one camera into RGB frames.

    With ``overlay``, the frame is the scene on the left and the panel (map and numbers,
    :mod:`sailmujoco.video.panel`) in a band of its own on the right: nothing is drawn over the
    scene. Each frame drawn adds the boat's position to the track that the map shows.

    Parameters
    ----------
    params : BoatParams
        The boat drawn (its display model is compiled here).
    width, height : int
        Frame size, pixels.
    camera : {"follow", "top", "side"}
        See :mod:`sailmujoco.video`.
    forces, overlay : bool
        Force arrows; panel.
    sail_mode : str
        As the simulated boat (the sheeted rig has the same joints).
    target : dict, optional
        ``{"position": (x, y), "radii": (d_T, d_M), "start": (x, y)}`` (m) to draw the target
        buoy and circles, and to frame the top view.
    labels : str
        The panel's first lines (boat, task, controller).
    follow_distance, follow_bearing_deg, follow_elevation_deg, follow_lag, top_center, top_extent
        Camera settings (:mod:`sailmujoco.video.camera`); distances in m, lag in s;
        ``follow_bearing_deg=None`` takes the bearing that shows the sail's face.
    offscreen : bool
        Make the offscreen GL context that :meth:`render` draws with. Without it the display
        model, :meth:`pose`, :meth:`decorate` and :meth:`camera_pose` serve a window that has
        its own context (``sailmujoco view``).
    waves : WaveConfig, optional
        The sea drawn (:mod:`sailmujoco.video.sea`): a height field around the boat that
        follows :func:`~sailmujoco.forces.waves.elevation`, set by :meth:`pose` (``self.sea``;
        a window with its own context uploads it after each pose, ``viewer.update_hfield(
        self.sea.hfield_id)``). None or ``hs = 0``: the flat sea (``self.sea`` is None).
    """

    def __init__(self, params, width: int = 640, height: int = 480, camera: str = "follow",
                 forces: bool = True, overlay: bool = True, sail_mode: str = "actuated",
                 target: dict | None = None, labels: str = "",
                 follow_distance: float | None = None, follow_bearing_deg: float | None = None,
                 follow_elevation_deg: float = ELEVATION_DEG, follow_lag: float = 3.0,
                 top_center=None, top_extent: float | None = None, offscreen: bool = True,
                 waves=None):
        if camera not in CAMERAS:
            raise ValueError(f"unknown camera {camera!r}; choose one of {CAMERAS}")
        if offscreen:
            mujoco = import_gl()
        else:
            import mujoco
        self._mujoco = mujoco
        self.params = params
        self.width, self.height = int(width), int(height)
        self.panel = panel.panel_width(self.width) if overlay else 0
        self.camera_name = camera
        self.show_forces, self.show_overlay = forces, overlay
        self.target, self.labels = target, labels
        m = self.model = display_model(params, sail_mode, width, height, waves)
        self.sea = sea.SeaSurface(m, waves, sea.SeaLayout(waves, params.hull.length)) \
            if sea.has_sea(waves) else None
        self.data = mujoco.MjData(m)
        self._rudder = m.jnt_qposadr[m.joint("rudder").id]
        self._sail = m.jnt_qposadr[m.joint("sail").id]
        self._sites = {name: m.site(site).id for name, site in FORCE_SITES.items()}
        self._masthead = m.site("masthead").id
        self._boom = (m.site("mast_step").id, m.site("boom_end").id)
        self.h = float(m.site_pos[self._masthead][2])  # m, masthead height: the scale of drawings
        self.force_scale = None  # m per N, set by the first state drawn (:meth:`scale_forces`)
        self.follow = FollowCamera(follow_distance or DISTANCE_MASTHEADS * self.h, 0.4 * self.h,
                                   follow_elevation_deg, follow_bearing_deg, follow_lag)
        self._fovy = float(m.vis.global_.fovy)
        self.top_pose = self._top_pose(top_center, top_extent)
        self.track: list[tuple[float, float]] = []
        self.fixes: list[tuple[float, float]] = []  # the GNSS fixes reported so far (measured)
        self._track_time = -np.inf
        self._camera = mujoco.MjvCamera()
        if camera == "side":
            self._camera.type = mujoco.mjtCamera.mjCAMERA_FIXED
            self._camera.fixedcamid = m.camera("side").id
        else:
            self._camera.type = mujoco.mjtCamera.mjCAMERA_FREE
        self._option = mujoco.MjvOption()
        self._option.sitegroup[:] = 0  # the force points are drawn as arrows, not as sites
        self._renderer = None
        if offscreen:  # the scene's part of the frame; the panel is drawn beside it
            self._renderer = offscreen_renderer(m, self.width - self.panel, self.height)  # GL context
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
        aspect = (self.width - self.panel) / self.height
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
        return top_pose(center, extent or 3.0 * self.params.hull.length, self._fovy)

    def camera_pose(self, snap: Snapshot) -> tuple[np.ndarray, float, float, float]:
        """(look-at point, distance, azimuth deg, elevation deg) of the follow camera for ``snap``,
        the display model posed as ``snap`` (:meth:`pose`); it advances the camera's lags.

        Parameters
        ----------
        snap : Snapshot
            The state drawn.
        """
        xpos = self.data.site_xpos
        boom = boom_angle(snap.rotation, xpos[self._boom[0]], xpos[self._boom[1]])
        return self.follow.pose(snap.time, snap.position, snap.rotation, boom)

    def _place_camera(self, snap: Snapshot) -> None:
        if self.camera_name == "side":
            return
        if self.camera_name == "top":
            pose = self.top_pose or top_pose(snap.position[:2], 3.0 * self.params.hull.length, self._fovy)
            self._set_free(pose[0], pose[1], 90.0, -90.0)  # north up
            return
        self._set_free(*self.camera_pose(snap))

    def _set_free(self, lookat, distance: float, azimuth_deg: float, elevation_deg: float) -> None:
        """MuJoCo free camera: looks at ``lookat`` along azimuth (ENU, deg) and elevation (deg)."""
        cam = self._camera
        cam.lookat[:] = lookat
        cam.distance = distance
        cam.azimuth = azimuth_deg
        cam.elevation = elevation_deg

    # ---- the scene
    def pose(self, snap: Snapshot) -> None:
        """Pose the display model (``self.data``) as ``snap`` and add its position to the track.

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
        pose_headsail(m, d, self.params, snap.position, snap.rotation, snap.sail)
        if self.sea is not None:
            self.sea.update(snap.time, snap.position)
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_camlight(m, d)
        if snap.time < self._track_time:  # a new run
            self.track.clear()
            self.fixes.clear()
        if snap.time > self._track_time:
            self.track.append((float(snap.position[0]), float(snap.position[1])))
            self._track_time = snap.time
        if snap.measured is not None:
            fix = tuple(float(v) for v in snap.measured["position"])
            if not self.fixes or self.fixes[-1] != fix:  # a new fix (a held one is drawn once)
                self.fixes.append(fix)

    def decorate(self, scene, snap: Snapshot) -> None:
        """Add the wind arrow, force arrows, target and circles to MuJoCo's scene.

        Parameters
        ----------
        scene : mujoco.MjvScene
            The scene drawn (posed by :meth:`pose`).
        snap : Snapshot
            The state drawn.
        """
        if self.force_scale is None:
            self.scale_forces(float(np.hypot(snap.wind[0], snap.wind[1])))
        xpos = self.data.site_xpos
        overlays.decorate(scene, snap, masthead=xpos[self._masthead],
                          sites={name: xpos[site] for name, site in self._sites.items()},
                          h=self.h, force_scale=self.force_scale, forces=self.show_forces,
                          target=self.target)

    def scale_forces(self, wind_speed: float) -> None:
        """Scale the force arrows: :data:`FORCE_ARROW` masthead heights for the force
        0.5 rho_air A_sail U^2 of a wind U = ``wind_speed`` (at least :data:`REFERENCE_WIND`).

        Parameters
        ----------
        wind_speed : float
            True wind speed, m/s (the first state drawn gives it when this is not called).
        """
        speed = max(float(wind_speed), REFERENCE_WIND)
        reference = 0.5 * self.params.rho_air * self.params.sail.area * speed**2  # N
        self.force_scale = FORCE_ARROW * self.h / reference

    def map_view(self, snap: Snapshot) -> panel.MapView:
        """What the panel's map shows for ``snap``: the track so far, heading, wind, references.

        Parameters
        ----------
        snap : Snapshot
            The state drawn.
        """
        from ..frames import heading_from_yaw

        return panel.MapView(track=np.array(self.track or [tuple(snap.position[:2])]),
                             position=np.asarray(snap.position[:2], float),
                             heading=float(heading_from_yaw(yaw_of(snap.rotation))),
                             wind=np.asarray(snap.wind[:2], float), hull_length=self.params.hull.length,
                             references=snap.references, target=self.target,
                             fixes=np.array(self.fixes) if snap.measured is not None else None)

    def text_lines(self, snap: Snapshot) -> list[str]:
        """The panel's numbers for ``snap`` (:func:`sailmujoco.video.panel.text_lines`).

        Parameters
        ----------
        snap : Snapshot
            The state described.
        """
        return panel.text_lines(snap, snap.references, self.target)

    # ---- a frame
    def render(self, snap: Snapshot, note: str | None = None, camera=None) -> np.ndarray:
        """One RGB frame (height, width, 3) uint8 of ``snap``: the scene, and the panel beside it.

        Parameters
        ----------
        snap : Snapshot
            The state drawn.
        note : str, optional
            A red note: in the panel, or across the top of a frame without one.
        camera : tuple, optional
            (look-at point (3,), distance, azimuth deg, elevation deg) of a free camera to draw
            with instead of this renderer's own.
        """
        if self._renderer is None:
            raise RuntimeError("this SceneRenderer was made with offscreen=False: no GL context to draw")
        self.pose(snap)
        if camera is None:
            self._place_camera(snap)
        else:
            self._camera.type = self._mujoco.mjtCamera.mjCAMERA_FREE
            self._set_free(*camera)
        renderer = self._renderer
        if self.sea is not None:
            self.sea.upload(renderer)
        renderer.update_scene(self.data, self._camera, self._option)
        self.decorate(renderer.scene, snap)
        scene = renderer.render()
        if not self.show_overlay:
            return np.ascontiguousarray(overlays.draw_note(scene, note) if note else scene)
        frame = np.empty((self.height, self.width, 3), np.uint8)
        return panel.draw_panel(frame, scene, self.labels, self.text_lines(snap),
                                overlays.legend(self.show_forces, snap.measured is not None),
                                self.map_view(snap), note)
