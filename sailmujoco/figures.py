"""What every figure of the package shares: layout, saving, robust colour limits, the wind arrow,
units chosen by magnitude, and a check that a figure is readable.

:func:`problems` draws a figure and lists what a reader would trip over: an axis that shows
numbers without saying what they are and in which unit (``[unit]`` or ``(unit)`` in its label),
a legend or a text box on top of plotted data, text cut off at the canvas edge. :func:`save`
runs it and warns (:class:`FigureWarning`; the test suite turns that warning into an error).
"""

from __future__ import annotations

import math
import re
import warnings
from pathlib import Path

import numpy as np

UNIT = re.compile(r"\[[^\]]+\]|\([^)]*[A-Za-z°%/][^)]*\)")
ROBUST_PERCENTILES = (2.0, 98.0)
MIN_ROBUST = 10  # fewer values (a smoke grid): no value is an outlier of the others


class FigureWarning(UserWarning):
    """A figure has a problem a reader would trip over (see :func:`problems`)."""


def pyplot():
    """matplotlib.pyplot on the file-only Agg backend, with the package's style."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams.update({"figure.dpi": 110, "axes.grid": True, "grid.alpha": 0.3,
                         "legend.fontsize": 8, "figure.constrained_layout.use": True})
    return plt


def save(fig, path, dpi: float | None = None) -> Path:
    """Check, write (tight bounding box: nothing clipped) and close a figure.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : path
        The file written.
    dpi : float, optional
        Resolution; matplotlib's default without it.

    Returns
    -------
    Path
        ``path``.
    """
    import matplotlib.pyplot as plt

    for problem in problems(fig):
        warnings.warn(f"{Path(path).name}: {problem}", FigureWarning, stacklevel=2)
    fig.savefig(path, dpi=dpi, bbox_inches="tight", pad_inches=0.1)
    plt.close(fig)
    return Path(path)


def legend_below(fig, axes=None, ncol: int = 3, **kwargs):
    """One legend for the figure, below the axes (outside the data), of the unique labels of ``axes``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    axes : Axes or list of Axes, optional
        Whose labels (default: every axes of the figure).
    ncol : int
        Columns of the legend.
    **kwargs
        Passed to ``fig.legend``.
    """
    handles, labels = [], []
    for ax in (fig.axes if axes is None else np.atleast_1d(axes).ravel()):
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            if label not in labels:
                handles.append(handle)
                labels.append(label)
    return fig.legend(handles, labels, loc="outside lower center", ncol=min(ncol, max(len(labels), 1)),
                      **kwargs)


def robust_limits(values, percentiles=ROBUST_PERCENTILES) -> tuple[float, float, str]:
    """Colour limits that one outlier cannot take over.

    The ``percentiles`` of the finite values (a single extreme cell of a grid lies beyond them) when
    the full range is more than twice as wide and there are at least ``MIN_ROBUST`` values, else the
    full range.

    Parameters
    ----------
    values : array_like
        The values coloured.
    percentiles : tuple of float
        Lower and upper percentile.

    Returns
    -------
    tuple
        (vmin, vmax, extend) with extend as matplotlib's colorbar takes it ('neither', 'min', 'max',
        'both': which ends are clipped).
    """
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    if finite.size == 0:
        return 0.0, 1.0, "neither"
    full_low, full_high = float(finite.min()), float(finite.max())
    low = float(np.percentile(finite, percentiles[0], method="higher"))
    high = float(np.percentile(finite, percentiles[1], method="lower"))
    if finite.size < MIN_ROBUST or high <= low or (full_high - full_low) <= 2.0 * (high - low):
        low, high = full_low, full_high
    if high <= low:
        low, high = low - 0.5, high + 0.5
        return low, high, "neither"
    extend = {(False, False): "neither", (True, False): "min", (False, True): "max",
              (True, True): "both"}[(full_low < low, full_high > high)]
    return low, high, extend


def moment_unit(largest: float) -> tuple[float, str]:
    """(divisor, unit) for a moment: N m below 1 kN m (a 15 kg robot), kN m above (a yacht).

    Parameters
    ----------
    largest : float
        The moment's largest magnitude (N m).
    """
    return (1e3, "kN m") if abs(largest) >= 1e3 else (1.0, "N m")


def wind_arrow(ax, towards_deg: float, text: str, *, length: float = 0.16, swing_deg: float = 0.0,
               color: str = "red") -> None:
    """An arrow showing where the wind blows *to*, in the corner where the data leave the most room.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Axes whose x is east and y north.
    towards_deg : float
        Where the wind blows to (compass deg: 0 north, 90 east).
    text : str
        The label (say the speed and 'from ...').
    length : float
        Arrow length, fraction of the axes.
    swing_deg : float
        The direction's swing, drawn as two thin arrows (deg; none at 0).
    color : str
        Colour.
    """
    corner = _emptiest_corner(ax)
    x0, y0 = corner
    for swing, alpha, lw in ((0.0, 1.0, 2.5), (swing_deg, 0.45, 1.2), (-swing_deg, 0.45, 1.2)):
        if alpha < 1.0 and not swing_deg:
            continue
        a = math.radians(towards_deg + swing)
        dx, dy = 0.5 * length * math.sin(a), 0.5 * length * math.cos(a)
        ax.annotate("", xy=(x0 + dx, y0 + dy), xytext=(x0 - dx, y0 - dy), xycoords="axes fraction",
                    arrowprops=dict(arrowstyle="-|>", color=color, lw=lw, alpha=alpha))
    right = x0 > 0.5
    ax.text(x0 + (-0.1 if right else 0.1), y0, text, transform=ax.transAxes, color=color, fontsize=7,
            va="center", ha="right" if right else "left",
            bbox=dict(facecolor="white", edgecolor="none", alpha=0.8, pad=1.0))


def _emptiest_corner(ax) -> tuple[float, float]:
    """Of the four corners, the one whose arrow-and-text strip (0.55 wide from the side, 0.34
    high, in axes fraction) holds the fewest plotted data points."""
    corners = [(0.1, 0.8), (0.9, 0.8), (0.1, 0.2), (0.9, 0.2)]
    ax.get_xlim(), ax.get_ylim()  # settles pending autoscaling before data are mapped
    points = np.concatenate([_data_points(ax, artist) for artist in _data_artists(ax)] or [np.empty((0, 2))])
    if points.size:
        points = ax.transAxes.inverted().transform(points)

    def count(corner):
        if not points.size:
            return 0
        x = points[:, 0] if corner[0] < 0.5 else 1.0 - points[:, 0]
        return int(np.sum((x < 0.55) & (np.abs(points[:, 1] - corner[1]) < 0.17)))
    return min(corners, key=count)


# ----------------------------------------------------------------------------- the check
def problems(fig) -> list[str]:
    """What a reader would trip over in ``fig`` (drawn here).

    Axes without a unit, legends and text boxes over plotted data, text outside the canvas.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.

    Returns
    -------
    list of str
        Empty when the figure is clean.
    """
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    found = []
    canvas = fig.bbox
    for ax in fig.axes:
        found += [f"{_name(ax)}: {p}" for p in _unit_problems(ax)]
    legends = list(fig.legends) + [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    for legend in legends:
        box = legend.get_window_extent(renderer)
        for ax in fig.axes:
            hits = _hits(ax, box)
            if hits:
                found.append(f"legend ({_legend_labels(legend)}) over {hits} data point(s) of {_name(ax)}")
    for ax in fig.axes:
        for text in ax.texts:
            if len(text.get_text().strip()) < 4 or text.get_bbox_patch() is None:
                continue  # marks (✓, ×) are placed on data on purpose; boxed notes must not be
            hits = _hits(ax, text.get_window_extent(renderer))
            if hits:
                found.append(f"text {text.get_text()!r} over {hits} data point(s) of {_name(ax)}")
    for text in _texts(fig):
        if not text.get_visible() or not str(text.get_text()).strip():
            continue
        box = text.get_window_extent(renderer)
        if box.width and not _inside(box, canvas):
            found.append(f"text {str(text.get_text())[:40]!r} outside the canvas")
    return found


def _texts(fig):
    """The text a figure's author placed: titles, axis labels, notes, legend entries (tick
    labels are matplotlib's, laid out by it)."""
    yield from fig.texts
    if getattr(fig, "_suptitle", None) is not None:
        yield fig._suptitle
    for ax in fig.axes:
        yield from (ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label)
        yield from ax.texts
    for legend in list(fig.legends) + [ax.get_legend() for ax in fig.axes if ax.get_legend()]:
        yield from legend.get_texts()


def _name(ax) -> str:
    return repr(ax.get_title() or ax.get_label() or "axes")


def _legend_labels(legend) -> str:
    texts = [t.get_text() for t in legend.get_texts()]
    return ", ".join(texts[:2]) + ("…" if len(texts) > 2 else "")


def _inside(box, canvas, tolerance: float = 1.0) -> bool:
    return (box.x0 >= canvas.x0 - tolerance and box.y0 >= canvas.y0 - tolerance
            and box.x1 <= canvas.x1 + tolerance and box.y1 <= canvas.y1 + tolerance)


def _unit_problems(ax) -> list[str]:
    if not ax.get_visible() or ax.name == "polar":
        return []
    out = []
    for which, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
        shown = [t.get_text() for t in axis.get_ticklabels() if t.get_visible() and t.get_text()]
        if not shown or not axis.get_visible() or not any(_is_number(t) for t in shown):
            continue  # no numbers shown (shared axis, categories): nothing to name
        label = axis.get_label_text()
        if not label.strip():
            out.append(f"{which} axis shows numbers but has no label")
        elif not UNIT.search(label):
            out.append(f"{which} label {label!r} names no unit ([unit] or (unit))")
    return out


def _is_number(text: str) -> bool:
    try:
        float(text.replace("\N{MINUS SIGN}", "-").replace("°", "").replace("%", "").strip("$"))
    except ValueError:
        return False
    return True


def _data_artists(ax):
    """The artists that show data in data coordinates: lines, markers, scatter, bars, patches
    (reference lines and spans drawn in axes coordinates, and outlines of unfilled patches, are
    not data)."""
    for line in ax.lines:
        if line.get_visible() and line.get_transform() == ax.transData:
            yield line
    for collection in ax.collections:
        if collection.get_visible() and len(collection.get_offsets()):
            yield collection
    for patch in ax.patches:
        if patch.get_visible() and patch.get_fill() and not _spans_axes(ax, patch):
            yield patch


def _spans_axes(ax, patch) -> bool:
    return patch.get_data_transform() != ax.transData


def _data_points(ax, artist) -> np.ndarray:
    """Display coordinates of an artist's data, lines densified to a point every ~2 px, inside
    the axes only."""
    from matplotlib.collections import Collection
    from matplotlib.lines import Line2D

    if isinstance(artist, Line2D):
        xy = artist.get_transform().transform(np.asarray(artist.get_xydata(), dtype=float))
        xy = xy[np.all(np.isfinite(xy), axis=1)]
        if artist.get_linestyle() not in ("None", "", " ", "none") and len(xy) > 1:
            seg = np.diff(xy, axis=0)
            n = np.clip(np.ceil(np.hypot(*seg.T) / 2.0).astype(int), 1, 2000)
            steps = [xy[i] + np.outer(np.arange(k) / k, seg[i]) for i, k in enumerate(n)]
            xy = np.vstack(steps + [xy[-1:]])
    elif isinstance(artist, Collection):
        xy = artist.get_offset_transform().transform(np.asarray(artist.get_offsets(), dtype=float))
    else:  # a patch: its outline and centre
        path = artist.get_transform().transform_path(artist.get_path())
        xy = np.asarray(path.vertices, dtype=float)
        if len(xy):
            xy = np.vstack([xy, xy.mean(axis=0)])
    box = ax.bbox
    keep = ((xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1) & (xy[:, 1] >= box.y0) & (xy[:, 1] <= box.y1)) \
        if len(xy) else np.zeros(0, bool)
    return xy[keep].reshape(-1, 2)


def _hits(ax, box) -> int:
    """How many of ``ax``'s data points lie inside the display box ``box``."""
    total = 0
    for artist in _data_artists(ax):
        xy = _data_points(ax, artist)
        if len(xy):
            total += int(np.sum((xy[:, 0] > box.x0) & (xy[:, 0] < box.x1)
                                & (xy[:, 1] > box.y0) & (xy[:, 1] < box.y1)))
    return total
