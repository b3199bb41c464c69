"""The side panel of a frame: a map of the run seen from above and the numbers, beside the scene.

The panel is a band of its own at the right edge of the frame (:func:`panel_width`); the 3-D
scene is rendered into the rest, so no text or map ever covers the boat or its arrows.

The map (:func:`draw_map`), north up: the track so far (yellow), the boat (a white wedge along
its heading, with a white heading line), the desired heading or course (dashed green) or, for
position keeping, the target buoy, its target and pre-arrival circles and a dashed line to it;
and under the map a north arrow, a scale bar and the true wind (a cyan arrow where it blows
to, its speed beside it, m/s). The map is centred on the boat and reaches the whole track,
the start and the target, at least :data:`MAP_HULLS` hull lengths each way.

With instruments that are not perfect the map also shows the GNSS fixes reported so far
(pink dots) beside the true track, and the text what the instruments read beside the truth:
the fix's distance from the true position, the compass against the true heading, the vane
against the true apparent wind at the masthead.

The text (:func:`text_lines`) under the map: the labels, time, heading with its reference,
speed, heel, true and apparent wind, rudder and sail; then the colour key; then, for a run that
stopped early, the reason in red. Compass angles are printed as three digits, clockwise from
north; other angles signed. PIL draws it all.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

KNOT = 1852.0 / 3600.0  # m/s per knot
PANEL_SHARE = 0.32  # of the frame's width
MAP_HULLS = 2.5  # the map shows at least this many hull lengths each way from its centre
BACKGROUND = (16, 26, 40)
MAP_WATER = (24, 66, 108)
WHITE = (255, 255, 255)
TRACK = (255, 214, 90)
DESIRED = (120, 255, 140)
WIND = (77, 242, 255)
RED = (255, 90, 70)
FIXES = (255, 120, 220)  # the GNSS fixes (measured) beside the true track


def panel_width(width: int) -> int:
    """Width of the panel, pixels (even), for a frame ``width`` pixels wide.

    Parameters
    ----------
    width : int
        Frame width, pixels.
    """
    return 2 * round(PANEL_SHARE * width / 2)


@dataclass
class MapView:
    """What the map shows, world x east, y north, m; angles compass (rad, clockwise from north).

    Parameters
    ----------
    track : numpy.ndarray, shape (n, 2)
        The boat's positions so far, m.
    position : numpy.ndarray, shape (2,)
        The boat now, m.
    heading : float
        rad, compass.
    wind : numpy.ndarray, shape (2,)
        True wind velocity (where it blows to), m/s, east and north.
    hull_length : float
        m: the smallest map spans :data:`MAP_HULLS` of them each way.
    references : dict
        The task's references: ``desired_heading`` or ``desired_course`` (rad, compass) or
        ``target_position`` (m).
    target : dict, optional
        ``{"position": (x, y), "radii": (d_T, d_M), "start": (x, y)}``, m.
    fixes : numpy.ndarray, shape (k, 2), optional
        The GNSS fixes reported so far, m (None: perfect sensors, nothing measured to draw).
    """

    track: np.ndarray
    position: np.ndarray
    heading: float
    wind: np.ndarray
    hull_length: float
    references: dict
    target: dict | None = None
    fixes: np.ndarray | None = None


def compass(angle: float) -> str:
    """A compass angle (rad) as three digits of degrees, 000-359.

    Parameters
    ----------
    angle : float
        rad, clockwise from north.
    """
    return f"{round(math.degrees(angle)) % 360:03d}°"


def wind_from(wind) -> float:
    """Compass direction (rad) the wind comes from, for its velocity (east, north), m/s.

    Parameters
    ----------
    wind : array_like
        (east, north) velocity, where it blows to, m/s.
    """
    return math.atan2(-float(wind[0]), -float(wind[1])) % (2.0 * math.pi)


def measured_of(observation) -> dict | None:
    """What the instruments reported in a task's ``observation``: the GNSS fix ``position``
    (m, world x-y), the compass ``heading`` (rad) and the vane's ``awa`` (rad) and ``aws``
    (m/s); None where the observation holds the truth (perfect sensors: no speed log in it).

    Parameters
    ----------
    observation : dict or None
        A task's observation (the last one handed to the controller).
    """
    if observation is None or "speed_through_water" not in observation:
        return None
    return {"position": np.asarray(observation["position"], float)[:2].copy(),
            "heading": float(observation["heading"]), "awa": float(observation["apparent_wind_angle"]),
            "aws": float(observation["apparent_wind_speed"])}


def text_lines(snap, references: dict, target: dict | None = None) -> list[str]:
    """The panel's numbers: time, heading and its reference, speed, heel, winds, rudder, sail.

    Parameters
    ----------
    snap : Snapshot
        The state described (:class:`sailmujoco.video.Snapshot`).
    references : dict
        The task's references (:class:`MapView`).
    target : dict, optional
        The target area (:class:`MapView`).
    """
    from ..frames import heading_from_yaw
    from .camera import yaw_of

    heading = float(heading_from_yaw(yaw_of(snap.rotation)))
    if "desired_heading" in references:
        aim = f"heading {compass(heading)}, desired {compass(references['desired_heading'])}"
    elif "desired_course" in references:
        aim = f"heading {compass(heading)}, course desired {compass(references['desired_course'])}"
    else:
        aim = f"heading {compass(heading)}"
    lines = [f"t {snap.time:.2f} s", aim]
    goal = references.get("target_position", None if target is None else target["position"])
    what = "target"
    if "next_mark" in references:  # a course: the leg's end
        goal, what = references["next_mark"], "next mark"
    if goal is not None:
        offset = np.asarray(goal, float)[:2] - snap.position[:2]
        lines.append(f"{what} {np.hypot(*offset):.1f} m at {compass(math.atan2(offset[0], offset[1]))}")
    speed = float(np.hypot(snap.wind[0], snap.wind[1]))
    lines += [f"speed {snap.speed:.2f} m/s ({snap.speed / KNOT:.1f} kn)",
              f"heel {math.degrees(snap.heel):+.1f}°",
              f"true wind {speed:.1f} m/s from {compass(wind_from(snap.wind))}",
              f"apparent {snap.aws:.1f} m/s, AWA {math.degrees(snap.awa):+.0f}°",
              f"rudder {math.degrees(snap.rudder):+.1f}°  sail {math.degrees(snap.sail):+.1f}°"]
    measured = snap.measured
    if measured is not None:
        off = float(np.hypot(*(np.asarray(measured["position"], float) - snap.position[:2])))
        error = math.degrees(math.remainder(measured["heading"] - heading, 2.0 * math.pi))
        lines += [f"GNSS {off:.1f} m off, compass {error:+.1f}°",
                  f"vane {measured['aws']:.1f} m/s, AWA {math.degrees(measured['awa']):+.0f}°"]
    return lines


def font(size: int):
    """PIL's default font, ``size`` pixels.

    Parameters
    ----------
    size : int
        Pixels.
    """
    from PIL import ImageFont

    return ImageFont.load_default(size=max(8, int(size)))


def _wrap(draw, text: str, typeface, width: float) -> list[str]:
    """``text`` split at " · " (then at spaces) into lines no wider than ``width`` pixels."""
    lines: list[str] = []
    for part in text.split(" · "):
        if lines and draw.textlength(lines[-1] + " · " + part, font=typeface) <= width:
            lines[-1] += " · " + part
        else:
            lines.append(part)
    out: list[str] = []
    for line in lines:
        words, current = line.split(" "), ""
        for word in words:
            trial = f"{current} {word}".strip()
            if current and draw.textlength(trial, font=typeface) > width:
                out.append(current)
                current = word
            else:
                current = trial
        out.append(current)
    return out


def _dashed(draw, start, end, fill, width: int, dash: float) -> None:
    """A dashed line from ``start`` to ``end`` (pixels)."""
    start, end = np.asarray(start, float), np.asarray(end, float)
    length = float(np.linalg.norm(end - start))
    if length < 1e-6:
        return
    step = (end - start) / length
    for s in np.arange(0.0, length, 2.0 * dash):
        a, b = start + s * step, start + min(s + dash, length) * step
        draw.line((*a, *b), fill=fill, width=width)


def _arrow(draw, tail, head, fill, width: int, barb: float) -> None:
    """A line from ``tail`` to ``head`` (pixels) with a filled head ``barb`` pixels long."""
    tail, head = np.asarray(tail, float), np.asarray(head, float)
    along = head - tail
    length = float(np.linalg.norm(along))
    if length < 1e-6:
        return
    along /= length
    across = np.array([-along[1], along[0]])
    base = head - barb * along
    draw.line((*tail, *base), fill=fill, width=width)
    draw.polygon([tuple(head), tuple(base + 0.5 * barb * across), tuple(base - 0.5 * barb * across)],
                 fill=fill)


def nice_length(length: float) -> float:
    """The largest 1, 2 or 5 times a power of ten not over ``length``.

    Parameters
    ----------
    length : float
        > 0.
    """
    power = 10.0 ** math.floor(math.log10(length))
    return max(m * power for m in (1.0, 2.0, 5.0) if m * power <= length)


def map_frame(view: MapView) -> tuple[np.ndarray, float]:
    """(centre (2,), half-width) of the map, m: centred on the boat (its heading line always
    shows), wide enough for the track, the GNSS fixes, the start and the target's outer circle.

    Parameters
    ----------
    view : MapView
        What the map shows.
    """
    centre = np.asarray(view.position, float)[:2]
    points = [np.asarray(view.track, float).reshape(-1, 2)]
    if view.fixes is not None and len(view.fixes):
        points.append(np.asarray(view.fixes, float).reshape(-1, 2))
    reach = 0.0
    if view.target is not None:
        goal = np.asarray(view.target["position"], float)
        reach = max(view.target["radii"])
        points.append(goal[None])
        if view.target.get("start") is not None:
            points.append(np.asarray(view.target["start"], float)[None])
    far = np.abs(np.concatenate(points) - centre).max() + reach
    return centre, max(1.15 * far + 0.5 * view.hull_length, MAP_HULLS * view.hull_length)


def _map_target(draw, target: dict, to_px, scale: float, position, line: int) -> None:
    """The target buoy, its circles, and a dashed line from the boat to it."""
    x, y = target["position"]
    cx, cy = to_px((x, y))
    if target.get("corners"):  # a box or a square
        draw.polygon([to_px(corner) for corner in target["corners"]], outline=DESIRED, width=line)
        return
    for radius, colour in zip(target["radii"], (DESIRED, TRACK), strict=True):
        r = radius * scale
        draw.ellipse((cx - r, cy - r, cx + r, cy + r), outline=colour, width=line)
    _dashed(draw, to_px(position), (cx, cy), DESIRED, line, 3 * line)
    r = 2.5 * line
    draw.ellipse((cx - r, cy - r, cx + r, cy + r), fill=(255, 115, 0))
    for mark in target.get("marks", [])[1:]:  # a course's other marks and its line
        mx, my = to_px(mark)
        draw.ellipse((mx - r, my - r, mx + r, my + r), fill=(255, 115, 0))
    if target.get("line"):
        (ax, ay), (bx, by) = (to_px(end) for end in target["line"])
        draw.line((ax, ay, bx, by), fill=DESIRED, width=line)


def _map_boat(draw, view: MapView, to_px, size: int, line: int) -> None:
    """The boat's wedge, its heading line and the desired heading or course (dashed)."""
    x, y = to_px(view.position)
    reach = 0.3 * size
    for key in ("desired_heading", "desired_course"):
        if key in view.references:
            a = float(view.references[key])
            _dashed(draw, (x, y), (x + reach * math.sin(a), y - reach * math.cos(a)), DESIRED, line,
                    3 * line)
    a = view.heading
    ahead, side = np.array([math.sin(a), -math.cos(a)]), np.array([math.cos(a), math.sin(a)])
    draw.line((x, y, x + reach * ahead[0], y + reach * ahead[1]), fill=WHITE, width=line)
    length = 5.0 * line
    bow = np.array([x, y]) + length * ahead
    stern = np.array([x, y]) - 0.6 * length * ahead
    draw.polygon([tuple(bow), tuple(stern + 0.45 * length * side), tuple(stern - 0.45 * length * side)],
                 fill=WHITE, outline=(0, 0, 0))


def _compass_rose(draw, centre, unit: float, line: int, typeface) -> None:
    """A north arrow with its "N", centred on ``centre`` (pixels)."""
    x, y = centre
    _arrow(draw, (x, y + 0.9 * unit), (x, y - 0.5 * unit), WHITE, max(2, line), 0.7 * unit)
    draw.text((x, y - 0.6 * unit), "N", font=typeface, fill=WHITE, anchor="mb")


def draw_map(draw, box: tuple[int, int, int], view: MapView, typeface) -> int:
    """The map in the square ``box`` = (left, top, size) pixels, and under it a strip with the
    north arrow, the scale bar and the true wind (see the module doc).

    Parameters
    ----------
    draw : PIL.ImageDraw.ImageDraw
        Draws on the frame.
    box : tuple of int
        (left, top, size), pixels, of the map's square.
    view : MapView
        What it shows.
    typeface : PIL font
        For the labels.

    Returns
    -------
    int
        The y (pixels) under the strip.
    """
    left, top, size = box
    draw.rectangle((left, top, left + size, top + size), fill=MAP_WATER, outline=(90, 120, 150))
    centre, half = map_frame(view)
    scale = 0.5 * size / half  # pixels per m

    def to_px(point):
        return (left + 0.5 * size + scale * (point[0] - centre[0]),
                top + 0.5 * size - scale * (point[1] - centre[1]))

    line = max(1, round(size / 110))
    if view.target is not None:
        _map_target(draw, view.target, to_px, scale, view.position, line)
    if len(view.track) > 1:
        draw.line([to_px(p) for p in view.track], fill=TRACK, width=line, joint="curve")
    if view.fixes is not None:
        dot = max(1.5, 1.2 * line)
        for x, y in (to_px(p) for p in view.fixes):
            draw.ellipse((x - dot, y - dot, x + dot, y + dot), fill=FIXES)
    _map_boat(draw, view, to_px, size, line)
    unit = typeface.size
    mid = top + size + 1.5 * unit  # the strip's middle
    _compass_rose(draw, (left + 0.6 * unit, mid + 0.2 * unit), unit, line, typeface)
    metres = nice_length(0.22 * size / scale)  # scale bar
    x0 = left + 1.8 * unit
    draw.line((x0, mid + 0.6 * unit, x0 + metres * scale, mid + 0.6 * unit), fill=WHITE, width=max(2, line))
    for x in (x0, x0 + metres * scale):
        draw.line((x, mid + 0.3 * unit, x, mid + 0.9 * unit), fill=WHITE, width=line)
    draw.text((x0, mid + 0.2 * unit), f"{metres:g} m", font=typeface, fill=WHITE, anchor="lb")
    speed = float(np.hypot(*view.wind[:2]))  # true wind: where it blows to
    label = f"{speed:.1f} m/s"
    centre_w = np.array([left + size - 1.0 * unit, mid])
    if speed > 1e-6:
        to = np.array([view.wind[0], -view.wind[1]]) / speed * 0.9 * unit
        _arrow(draw, centre_w - to, centre_w + to, WIND, max(2, 2 * line), 0.8 * unit)
    draw.text((centre_w[0] - 1.3 * unit, mid), label, font=typeface, fill=WIND, anchor="rm")
    return round(top + size + 3.2 * unit)


def _key_rows(draw, width: float, typeface, entries) -> list[list[tuple[float, tuple]]]:
    """The colour key's entries in rows no wider than ``width`` pixels: (x offset, entry)."""
    size = typeface.size
    rows: list[list[tuple[float, tuple]]] = [[]]
    cursor = 0.0
    for entry in entries:
        room = 1.6 * size + draw.textlength(entry[0], font=typeface)
        if rows[-1] and cursor + room > width:
            rows.append([])
            cursor = 0.0
        rows[-1].append((cursor, entry))
        cursor += room + 0.8 * size
    return rows


def _key(draw, x: int, y: int, rows, typeface) -> int:
    """The colour key (:func:`_key_rows`) from (x, y) down; returns the y under it."""
    size = typeface.size
    step = round(1.3 * size)
    for row in rows:
        mid = y + 0.55 * size
        for offset, (name, colour, kind) in row:
            at = x + offset
            if kind == "box":
                draw.rectangle((at, mid - 0.3 * size, at + 0.6 * size, mid + 0.3 * size), fill=colour)
            elif kind == "dash":
                _dashed(draw, (at, mid), (at + 1.2 * size, mid), colour, 2, 0.25 * size)
            elif kind == "dot":
                for dx in (0.2, 0.6, 1.0):
                    r = 0.12 * size
                    draw.ellipse((at + dx * size - r, mid - r, at + dx * size + r, mid + r), fill=colour)
            else:
                draw.line((at, mid, at + 1.2 * size, mid), fill=colour, width=2)
            draw.text((at + 1.6 * size, y), name, font=typeface, fill=(225, 225, 225))
        y += step
    return y


def draw_panel(frame: np.ndarray, scene: np.ndarray, labels: str, lines: list[str], entries: list,
               view: MapView | None, note: str | None = None) -> np.ndarray:
    """``frame`` (height, width, 3) uint8 made of ``scene`` on the left and the panel beside it.

    Parameters
    ----------
    frame : ndarray
        (height, width, 3) uint8, written in place and returned.
    scene : ndarray
        (height, width - panel width, 3) uint8, the rendered scene.
    labels : str
        Boat, task, controller (wrapped at " · ").
    lines : list of str
        The numbers (:func:`text_lines`).
    entries : list of (str, tuple, str)
        The colour key: name, RGB 0-255 and ``"box"``, ``"line"`` or ``"dash"``.
    view : MapView, optional
        The map; none without it.
    note : str, optional
        A red note at the bottom (why the run stopped).
    """
    from PIL import Image, ImageDraw

    height, width = frame.shape[:2]
    left = scene.shape[1]
    frame[:, :left] = scene
    frame[:, left:] = BACKGROUND
    image = Image.fromarray(frame)
    draw = ImageDraw.Draw(image)
    room = width - left
    typeface = font(min(round(height / 34), round(room / 14)))
    pad = max(4, typeface.size // 2)
    text_width = room - 2 * pad
    label_lines = _wrap(draw, labels, typeface, text_width) if labels else []
    words = label_lines + lines
    while typeface.size > 8 and max(draw.textlength(s, font=typeface) for s in words) > text_width:
        typeface = font(typeface.size - 1)
    step = round(1.3 * typeface.size)
    rows = _key_rows(draw, text_width, typeface, entries)
    notes = _wrap(draw, note, typeface, text_width) if note else []
    text_height = (len(words) + len(rows) + len(notes)) * step + step // 3
    y = pad
    if view is not None:
        size = max(0, min(room - 2 * pad, height - text_height - 3 * pad - round(3.2 * typeface.size)))
        if size >= 60:
            y = draw_map(draw, (left + pad, y, size), view, typeface) + pad
    for i, text in enumerate(words):
        colour = (200, 215, 235) if i < len(label_lines) else WHITE
        draw.text((left + pad, y), text, font=typeface, fill=colour)
        y += step
    y = _key(draw, left + pad, y + step // 3, rows, typeface)
    for text in notes:
        draw.text((left + pad, y), text, font=typeface, fill=RED)
        y += step
    return np.asarray(image)
