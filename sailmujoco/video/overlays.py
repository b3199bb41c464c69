"""What is drawn over the boat: arrows, target circles and buoy in MuJoCo's scene, and the text box.

Scene additions (:func:`decorate`): the true-wind arrow centred just above the masthead (cyan,
pointing where the wind blows to, :data:`WIND_ARROW_PER_MPS` masthead heights per m/s); the
sail, keel and rudder force vectors at their sites (red, green, orange); for position keeping,
the target buoy and the target and pre-arrival circles. Arrows longer than :data:`MAX_ARROW`
masthead heights are clipped (the text keeps the numbers).

The colour key of the side panel (:func:`legend`; the panel itself is
:mod:`sailmujoco.video.panel`), and the note of a run that stopped early on a frame without a
panel (:func:`draw_note`).
"""

from __future__ import annotations

import numpy as np

from .panel import FIXES

FORCES = ("sail", "keel", "rudder")
COLOURS = {"sail": (0.95, 0.15, 0.1, 1.0), "keel": (0.45, 1.0, 0.1, 1.0),
           "rudder": (1.0, 0.55, 0.0, 1.0), "wind": (0.3, 0.95, 1.0, 1.0),
           "target": (1.0, 0.45, 0.0, 1.0), "target_area": (0.2, 1.0, 0.4, 0.3),
           "prearrival_area": (1.0, 0.9, 0.2, 0.2)}
WIND_ARROW_PER_MPS = 0.12  # masthead heights of arrow per m/s of wind
MAX_ARROW = 2.2  # masthead heights: longer arrows are clipped (the text keeps the numbers)
ARROW_WIDTH = 0.03  # masthead heights: shaft width of every arrow


# ----------------------------------------------------------------------------- MuJoCo scene
def add_geom(scene, kind, size, pos, mat, rgba):
    """Append a geom to ``scene`` (a ``mujoco.MjvScene``); None where the scene is full.

    Parameters
    ----------
    scene : mujoco.MjvScene
        The scene drawn.
    kind : mujoco.mjtGeom
        The geom type.
    size, pos : array_like
        (3,) size and world position (m).
    mat : array_like
        (3, 3) orientation.
    rgba : tuple of float
        Colour.
    """
    import mujoco

    if scene.ngeom >= scene.maxgeom:
        return None
    geom = scene.geoms[scene.ngeom]
    mujoco.mjv_initGeom(geom, kind, np.asarray(size, float), np.asarray(pos, float),
                        np.asarray(mat, float).ravel(), np.asarray(rgba, np.float32))
    geom.emission = 0.35  # vivid whatever the light
    geom.specular = 0.0  # no white glare: the colour stays the key's
    scene.ngeom += 1
    return geom


def add_arrow(scene, start, vector, width: float, rgba, longest: float) -> None:
    """An arrow from ``start`` along ``vector`` (m, world), clipped to ``longest`` m.

    Parameters
    ----------
    scene : mujoco.MjvScene
        The scene drawn.
    start, vector : array_like
        (3,) tail and length vector (m, world).
    width : float
        Shaft width (m).
    rgba : tuple of float
        Colour.
    longest : float
        Longer arrows are shortened to this length (m).
    """
    import mujoco

    length = float(np.linalg.norm(vector))
    if length < 1e-6:
        return
    vector = vector * min(1.0, longest / length)
    geom = add_geom(scene, mujoco.mjtGeom.mjGEOM_ARROW, np.zeros(3), np.zeros(3), np.eye(3), rgba)
    if geom is not None:
        mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_ARROW, width, np.asarray(start, float),
                             np.asarray(start, float) + vector)


def add_ring(scene, x: float, y: float, radius: float, width: float, rgba, segments: int = 48) -> None:
    """A circle on the water as ``segments`` capsules.

    Parameters
    ----------
    scene : mujoco.MjvScene
        The scene drawn.
    x, y : float
        Centre (m, world).
    radius, width : float
        Circle radius and line width (m).
    rgba : tuple of float
        Colour.
    segments : int
        Capsules around the circle.
    """
    import mujoco

    angles = np.linspace(0.0, 2.0 * np.pi, segments + 1)
    points = np.stack([x + radius * np.cos(angles), y + radius * np.sin(angles),
                       np.full_like(angles, 0.06)], axis=1)
    for a, b in zip(points[:-1], points[1:], strict=True):
        geom = add_geom(scene, mujoco.mjtGeom.mjGEOM_CAPSULE, np.zeros(3), np.zeros(3), np.eye(3), rgba)
        if geom is None:
            return
        mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_CAPSULE, width, a, b)


def add_target(scene, target: dict, h: float) -> None:
    """The target and pre-arrival areas, their circles and the target buoy.

    Parameters
    ----------
    scene : mujoco.MjvScene
        The scene drawn.
    target : dict
        ``{"position": (x, y), "radii": (d_T, d_M)}`` (m); a course adds ``"marks"`` (its marks,
        the first at ``position``, each ringed at d_T) and ``"line"`` (its line's two ends); a
        box or a square, ``"corners"`` (its four corners, drawn instead of the circles).
    h : float
        Masthead height (m): the scale of the buoy.
    """
    import mujoco

    x, y = target["position"]
    d_target, d_pre = target["radii"]
    if target.get("corners"):  # a box or a square: its sides as ropes on the water
        corners = [np.array([cx, cy, 0.06]) for cx, cy in target["corners"]]
        for a, b in zip(corners, corners[1:] + corners[:1], strict=True):
            geom = add_geom(scene, mujoco.mjtGeom.mjGEOM_CAPSULE, np.zeros(3), np.zeros(3), np.eye(3),
                            (1.0, 1.0, 0.6, 1.0))
            if geom is not None:
                mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_CAPSULE, 0.004 * d_target + 0.03, a, b)
        return
    flat = mujoco.mjtGeom.mjGEOM_CYLINDER
    # cylinder size: (radius, half-height, unused)
    add_geom(scene, flat, (d_pre, 0.01, 0.0), (x, y, 0.02), np.eye(3), COLOURS["prearrival_area"])
    add_geom(scene, flat, (d_target, 0.01, 0.0), (x, y, 0.04), np.eye(3), COLOURS["target_area"])
    for radius in (d_target, d_pre):
        add_ring(scene, x, y, radius, 0.004 * radius + 0.03, (1.0, 1.0, 0.6, 1.0))
    buoy = 0.04 * h + 0.15
    add_geom(scene, mujoco.mjtGeom.mjGEOM_SPHERE, (buoy, 0, 0), (x, y, 0.3 * buoy), np.eye(3),
             COLOURS["target"])
    for mx, my in target.get("marks", [])[1:]:  # a course's other marks
        add_ring(scene, mx, my, d_target, 0.004 * d_target + 0.03, (1.0, 1.0, 0.6, 1.0))
        add_geom(scene, mujoco.mjtGeom.mjGEOM_SPHERE, (buoy, 0, 0), (mx, my, 0.3 * buoy), np.eye(3),
                 COLOURS["target"])
    if target.get("line"):  # a start and finish line: a buoy at each end, a rope between
        ends = [np.array([ex, ey, 0.06]) for ex, ey in target["line"]]
        for end in ends:
            add_geom(scene, mujoco.mjtGeom.mjGEOM_SPHERE, (0.7 * buoy, 0, 0), end + (0, 0, 0.2 * buoy),
                     np.eye(3), COLOURS["target"])
        geom = add_geom(scene, mujoco.mjtGeom.mjGEOM_CAPSULE, np.zeros(3), np.zeros(3), np.eye(3),
                        (1.0, 1.0, 0.6, 1.0))
        if geom is not None:
            mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_CAPSULE, 0.02 * h + 0.02, *ends)


def decorate(scene, snap, *, masthead, sites: dict, h: float, force_scale: float, forces: bool,
             target: dict | None) -> None:
    """Add the wind arrow, force arrows, target and circles to MuJoCo's scene.

    Parameters
    ----------
    scene : mujoco.MjvScene
        The scene drawn.
    snap : Snapshot
        The state drawn (:class:`sailmujoco.video.Snapshot`).
    masthead : array_like
        (3,) world position of the masthead (m).
    sites : dict
        Force name -> (3,) world position of its point of action (m).
    h : float
        Masthead height (m): the scale of the drawings.
    force_scale : float
        Arrow length per newton (m/N).
    forces : bool
        Draw the force arrows.
    target : dict, optional
        See :func:`add_target`; nothing without it.
    """
    wind = np.array([snap.wind[0], snap.wind[1], 0.0])
    speed = float(np.linalg.norm(wind))
    if speed > 1e-6:  # a wind vane: centred just above the masthead
        centre = masthead + np.array([0.0, 0.0, 0.1 * h])
        vector = WIND_ARROW_PER_MPS * h * wind
        add_arrow(scene, centre - 0.5 * vector, vector, ARROW_WIDTH * h, COLOURS["wind"], MAX_ARROW * h)
    if forces:
        for name in FORCES:
            force = snap.rotation @ snap.forces[name] * force_scale
            add_arrow(scene, sites[name], force, ARROW_WIDTH * h, COLOURS[name], MAX_ARROW * h)
    if target is not None:
        add_target(scene, target, h)


# ----------------------------------------------------------------------------- key and note
def legend(forces: bool, measured: bool = False) -> list[tuple[str, tuple, str]]:
    """The colour key of the panel: the arrows drawn (the sail, keel and rudder forces with
    ``forces``, the true wind), and the map's track, heading and desired heading or course, and
    with ``measured`` the GNSS fixes.

    Parameters
    ----------
    forces : bool
        Whether the force arrows are drawn.
    measured : bool
        Whether the instruments' readings are drawn beside the truth.

    Returns
    -------
    list of (str, tuple, str)
        Name, RGB (0-255) and how it is drawn: ``"box"`` (an arrow's colour), ``"line"`` or
        ``"dash"`` (a line on the map).
    """
    def rgb(rgba):
        return tuple(int(255 * c) for c in rgba[:3])

    entries = [(name, rgb(COLOURS[name]), "box") for name in FORCES] if forces else []
    entries.append(("wind", rgb(COLOURS["wind"]), "box"))
    entries += [("track", (255, 214, 90), "line"), ("heading", (255, 255, 255), "line"),
                ("desired", (120, 255, 140), "dash")]
    if measured:
        entries.append(("GNSS fixes", FIXES, "dot"))
    return entries


def draw_note(frame: np.ndarray, note: str) -> np.ndarray:
    """``frame`` with ``note`` in red on a dark band across its top (a frame without a panel).

    Parameters
    ----------
    frame : ndarray
        (height, width, 3) uint8 RGB.
    note : str
        The note (why the run stopped).
    """
    from PIL import Image, ImageDraw, ImageFont

    height, width = frame.shape[:2]
    image = Image.fromarray(frame)
    draw = ImageDraw.Draw(image, "RGBA")
    typeface = ImageFont.load_default(size=max(8, round(height / 32)))
    step = round(1.6 * typeface.size)
    draw.rectangle((0, 0, width, step), fill=(0, 0, 0, 160))
    draw.text((width // 2, step // 2), note, font=typeface, fill=(255, 80, 60, 255), anchor="mm")
    return np.asarray(image)
