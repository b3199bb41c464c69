"""A reference polar read from a file: a class's published polar to hold a boat's own against.

The file is CSV with ``#`` comment lines (kept as its source) and a header row. Its columns, by
name, each with its unit in the name:

=================  ==========================================================================
``tws_kn``         true wind speed, knots (or ``tws_ms``, m/s), at the file's reference height
``twa_deg``        true wind angle off the bow, degrees
``boat_speed_kn``  boat speed through the water, knots (or ``boat_speed_ms``, m/s)
``point``          optional: ``fixed`` (a fixed angle), ``beat`` or ``run`` (the angle of the
                   best VMG upwind or downwind); absent: every row is ``fixed``
=================  ==========================================================================

The form is that of ORC's certificate polars as shipped in ``sailmujoco/data`` (ORC gives the
wind at 10 m). A reference height other than 10 m is taken to this project's 10 m wind (the
``wind_speed`` of every task, U10 of Wille 2016a eq. 40) along the same log profile the wind
model uses: U10 = U(h) ln(10 / z0) / ln(h / z0), with z0 that of
:func:`sailmujoco.forces.wind.log_profile`.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import numpy as np
import pandas as pd

from ..forces.wind import roughness_length

KNOT = 1852.0 / 3600.0  # m/s, the international knot (1852 m per hour)
REFERENCE_HEIGHT = 10.0  # m, the height of a task's wind_speed (U10, Wille 2016a eq. 40)
POINTS = ("fixed", "beat", "run")
ORC_ELEVEN_METRE = "orc_polar_eleven_metre.csv"  # the package's copy of ORC's 11:Metre polar

_SPEEDS = {"tws_kn": KNOT, "tws_ms": 1.0}
_BOAT_SPEEDS = {"boat_speed_kn": KNOT, "boat_speed_ms": 1.0}


def wind_at_reference(speed, height: float):
    """The 10 m wind of a wind measured at ``height`` along the log profile, m/s.

    Parameters
    ----------
    speed : float or array_like
        The wind at ``height``, m/s.
    height : float
        Its height above the water, m (above the roughness length).
    """
    z0 = roughness_length()
    if not height > z0:
        raise ValueError(f"reference height must be above the roughness length {z0:.4f} m, got {height!r}")
    return np.asarray(speed, dtype=float) * (math.log(REFERENCE_HEIGHT / z0) / math.log(height / z0))


@dataclass(frozen=True)
class ReferencePolar:
    """A reference polar in this project's units.

    Parameters
    ----------
    table : pandas.DataFrame
        One row per point: ``tws`` (m/s at 10 m), ``twa`` (deg), ``point`` (fixed, beat, run),
        ``speed`` (m/s), ``vmg`` (m/s, speed times |cos TWA|, the VMG along the wind), and the file's
        own ``tws_file`` (its wind in its own unit and height).
    source : str
        The file's comment lines (where the numbers come from).
    name : str
        The file's name.
    """

    table: pd.DataFrame
    source: str
    name: str

    def fixed(self) -> pd.DataFrame:
        """The fixed-angle points."""
        return self.table[self.table["point"] == "fixed"]

    def optimum(self, point: str) -> pd.DataFrame:
        """The ``beat`` or ``run`` points (the VMG optima), one per TWS.

        Parameters
        ----------
        point : {"beat", "run"}
            Which optimum.
        """
        return self.table[self.table["point"] == point]


def read_reference_polar(path, height: float = REFERENCE_HEIGHT) -> ReferencePolar:
    """Read a reference polar file (this module's form); one clear line for a bad file.

    Parameters
    ----------
    path : str or os.PathLike
        The file; ``"orc:eleven_metre"`` is the package's copy of ORC's 11:Metre polar.
    height : float
        The height its wind speeds are measured at, m (ORC: 10).
    """
    if str(path) == "orc:eleven_metre":
        text = resources.files("sailmujoco.data").joinpath(ORC_ELEVEN_METRE).read_text()
        name = ORC_ELEVEN_METRE
    else:
        name = Path(path).name
        try:
            text = Path(path).read_text()
        except FileNotFoundError:
            raise ValueError(f"reference polar {str(path)!r} does not exist") from None
        except (OSError, UnicodeDecodeError) as err:
            raise ValueError(f"reference polar {str(path)!r} cannot be read: {err}") from None
    lines = text.splitlines()
    source = "\n".join(line.lstrip("# ") for line in lines if line.startswith("#"))
    data = "\n".join(line for line in lines if line.strip() and not line.startswith("#"))
    table = _table(list(csv.DictReader(io.StringIO(data))), name)
    table["tws"] = wind_at_reference(table["tws"].to_numpy(), height)
    return ReferencePolar(table=table, source=source, name=name)


def _table(rows: list[dict], name: str) -> pd.DataFrame:
    if not rows:
        raise ValueError(f"reference polar {name}: no rows under a header")
    columns = set(rows[0])
    wind = _one_of(columns, _SPEEDS, name)
    boat = _one_of(columns, _BOAT_SPEEDS, name)
    if "twa_deg" not in columns:
        raise ValueError(f"reference polar {name}: no 'twa_deg' column (has {sorted(columns)})")
    out = {"tws": [], "tws_file": [], "twa": [], "point": [], "speed": []}
    for number, row in enumerate(rows, start=2):
        where = f"reference polar {name}, data row {number - 1}"
        tws, twa, speed = (_number(row, key, where) for key in (wind, "twa_deg", boat))
        point = (row.get("point") or "fixed").strip()
        if point not in POINTS:
            raise ValueError(f"{where}: point must be one of {', '.join(POINTS)}, got {point!r}")
        if not (tws > 0 and 0 <= twa <= 180 and speed >= 0):
            raise ValueError(f"{where}: wind speed must be > 0, TWA in [0, 180] deg and boat speed "
                             f">= 0, got {tws:g}, {twa:g}, {speed:g}")
        out["tws"].append(tws * _SPEEDS[wind])
        out["tws_file"].append(tws)
        out["twa"].append(twa)
        out["point"].append(point)
        out["speed"].append(speed * _BOAT_SPEEDS[boat])
    table = pd.DataFrame(out)
    table["vmg"] = table["speed"] * np.abs(np.cos(np.radians(table["twa"].to_numpy())))
    return table


def _one_of(columns: set, names: dict, name: str) -> str:
    found = [n for n in names if n in columns]
    if len(found) != 1:
        raise ValueError(f"reference polar {name}: needs exactly one of the columns "
                         f"{' or '.join(names)}, has {sorted(columns)}")
    return found[0]


def _number(row: dict, key: str, where: str) -> float:
    raw = (row.get(key) or "").strip()
    try:
        value = float(raw)
    except ValueError:
        raise ValueError(f"{where}: {key} must be a number, got {raw!r}") from None
    if not math.isfinite(value):
        raise ValueError(f"{where}: {key} must be finite, got {raw!r}")
    return value
