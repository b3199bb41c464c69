"""What is drawn over the boat: arrows, target circles and buoy in MuJoCo's scene, and the text box.

Scene additions (:func:`decorate`): the true-wind arrow centred just above the masthead (cyan,
pointing where the wind blows to, :data:`WIND_ARROW_PER_MPS` masthead heights per m/s); the
sail, keel and rudder force vectors at their sites (red, green, orange); for position keeping,
the target buoy and the target and pre-arrival circles. Arrows longer than :data:`MAX_ARROW`
masthead heights are clipped (the text keeps the numbers).

Text (:func:`text_lines`, :func:`draw_text`): a box in the upper left with the labels, time,
speed over ground, heel, apparent wind, rudder and sail angles and the distance to the target,
then a colour legend; a red note across the middle for a run that stopped early. PIL draws it.
"""

from __future__ import annotations

import math

import numpy as np

FORCES = ("sail", "keel", "rudder")
COLOURS = {"sail": (0.95, 0.15, 0.1, 1.0), "keel": (0.1, 0.85, 0.25, 1.0),
           "rudder": (1.0, 0.55, 0.0, 1.0), "wind": (0.3, 0.95, 1.0, 1.0),
           "target": (1.0, 0.45, 0.0, 1.0), "target_area": (0.2, 1.0, 0.4, 0.3),
           "prearrival_area": (1.0, 0.9, 0.2, 0.2)}
KNOT = 1852.0 / 3600.0  # m/s per knot
WIND_ARROW_PER_MPS = 0.06  # masthead heights of arrow per m/s of wind
MAX_ARROW = 2.0  # masthead heights: longer arrows are clipped (the text keeps the numbers)


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
        ``{"position": (x, y), "radii": (d_T, d_M)}`` (m).
    h : float
        Masthead height (m): the scale of the buoy.
    """
    import mujoco

    x, y = target["position"]
    d_target, d_pre = target["radii"]
    flat = mujoco.mjtGeom.mjGEOM_CYLINDER
    # cylinder size: (radius, half-height, unused)
    add_geom(scene, flat, (d_pre, 0.01, 0.0), (x, y, 0.02), np.eye(3), COLOURS["prearrival_area"])
    add_geom(scene, flat, (d_target, 0.01, 0.0), (x, y, 0.04), np.eye(3), COLOURS["target_area"])
    for radius in (d_target, d_pre):
        add_ring(scene, x, y, radius, 0.004 * radius + 0.03, (1.0, 1.0, 0.6, 1.0))
    buoy = 0.04 * h + 0.15
    add_geom(scene, mujoco.mjtGeom.mjGEOM_SPHERE, (buoy, 0, 0), (x, y, 0.3 * buoy), np.eye(3),
             COLOURS["target"])


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
        add_arrow(scene, centre - 0.5 * vector, vector, 0.025 * h, COLOURS["wind"], MAX_ARROW * h)
    if forces:
        for name in FORCES:
            force = snap.rotation @ snap.forces[name] * force_scale
            add_arrow(scene, sites[name], force, 0.02 * h, COLOURS[name], MAX_ARROW * h)
    if target is not None:
        add_target(scene, target, h)


# ----------------------------------------------------------------------------- text
def text_lines(snap, labels: str = "", target: dict | None = None) -> list[str]:
    """The text box's lines: labels, time, speed, heel, apparent wind, rudder, sail, distance.

    Parameters
    ----------
    snap : Snapshot
        The state described.
    labels : str
        First line (boat, task, controller); none where empty.
    target : dict, optional
        ``{"position": (x, y), ...}`` (m): adds the distance to it.
    """
    lines = [labels] if labels else []
    lines += [f"t {snap.time:.1f} s    speed {snap.speed:.2f} m/s ({snap.speed / KNOT:.1f} kn)",
              f"heel {math.degrees(snap.heel):+.1f}°    AWA {math.degrees(snap.awa):+.0f}°    "
              f"AWS {snap.aws:.1f} m/s",
              f"rudder {math.degrees(snap.rudder):+.1f}°    sail {math.degrees(snap.sail):+.1f}°"]
    if target is not None:
        distance = float(np.linalg.norm(snap.position[:2] - np.asarray(target["position"])))
        lines.append(f"distance to target {distance:5.1f} m")
    return lines


def legend(forces: bool) -> list[tuple[str, tuple]]:
    """(name, colour) of the legend's entries: the forces drawn (with ``forces``), then the wind.

    Parameters
    ----------
    forces : bool
        Whether the force arrows are drawn.
    """
    entries = [(name, COLOURS[name]) for name in FORCES] if forces else []
    entries.append(("wind", COLOURS["wind"]))
    return entries


def font(height: int):
    """PIL's default font at a size fit for frames ``height`` pixels high.

    Parameters
    ----------
    height : int
        Frame height, pixels.
    """
    from PIL import ImageFont

    return ImageFont.load_default(size=max(9, round(height / 32)))


def draw_text(frame: np.ndarray, typeface, lines: list[str] | None, entries: list,
              note: str | None = None) -> np.ndarray:
    """``frame`` with the text box (``lines`` and the legend ``entries``) and the ``note``.

    Parameters
    ----------
    frame : ndarray
        (height, width, 3) uint8 RGB.
    typeface : PIL font
        From :func:`font`.
    lines : list of str, optional
        The text box's lines; no box without them.
    entries : list of (str, tuple)
        The legend under the lines (:func:`legend`).
    note : str, optional
        A red line across the middle of the frame.
    """
    from PIL import Image, ImageDraw

    height, width = frame.shape[:2]
    image = Image.fromarray(frame)
    draw = ImageDraw.Draw(image, "RGBA")
    size = typeface.size
    pad, step = size // 2, round(1.3 * size)
    if lines is not None:  # a box in the upper left: the lines, then the colour legend
        widths = [size + draw.textlength(name, font=typeface) + size for name, _ in entries]
        box = max(max(draw.textlength(line, font=typeface) for line in lines), sum(widths))
        top = 0
        draw.rectangle((0, 0, box + 2 * pad, (len(lines) + 1) * step + pad), fill=(0, 0, 0, 110))
        for i, line in enumerate(lines):
            draw.text((pad, top + pad + i * step), line, font=typeface, fill=(255, 255, 255, 255))
        x, y = pad, top + pad + len(lines) * step
        for (name, rgba), entry in zip(entries, widths, strict=True):
            colour = tuple(int(255 * c) for c in rgba[:3]) + (255,)
            draw.rectangle((x, y + size // 4, x + size // 2 + 2, y + 3 * size // 4 + 2), fill=colour)
            draw.text((x + size, y), name, font=typeface, fill=(255, 255, 255, 255))
            x += entry
    if note:
        y = height // 2 - size
        draw.rectangle((0, y - pad, width, y + step + pad), fill=(0, 0, 0, 140))
        draw.text((width // 2, y + step // 2), note, font=typeface, fill=(255, 80, 60, 255), anchor="mm")
    return np.asarray(image)
