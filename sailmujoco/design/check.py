"""What a designer wants first from a boat: displacement, draft, stability, periods, speed.

:func:`check_boat` (``sailmujoco boat check FILE``) reports, for a boat file, a registered boat
or a :class:`~sailmujoco.boat.params.BoatParams`:

* displacement (mass and volume) and where the hull floats against its design waterline;
* draft (canoe body and the deepest appendage tip, as the MJCF model draws them);
* LCB and LCG, the transverse and longitudinal metacentric heights GM_t and GM_L of the hull
  (:mod:`sailmujoco.boat.hull`'s closed forms);
* the righting-arm curve GZ against heel from 0 to 180 deg
  (:func:`sailmujoco.forces.stability.righting_arm`), its maximum and its angle of vanishing
  stability, as a figure ``gz.png``;
* the natural periods of roll, heave and pitch;
* the steady speed at a few true wind angles in one wind: short 6-DOF runs with the saoud sail
  law and heading rudder, on the polar's sweep (:func:`sailmujoco.design.polar.compute`).
"""

from __future__ import annotations

import math
import tempfile
import textwrap
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..boat import hull as hull_geometry
from ..boat.catalogue import get_boat
from ..boat.file import write_boat
from ..boat.fitted_file import fitted_summary
from ..boat.params import BoatParams
from ..constants import GRAVITY
from ..forces import stability
from ..forces.hydrostatics import submerged_volume
from ..frames import matrix_from_euler
from . import polar

DEFAULT_TWA_DEG = (45.0, 60.0, 90.0, 120.0, 150.0)  # deg, true wind angles of the speed runs
SPEED_RUN_S = 90.0  # s per speed run; the speed is the mean over the last polar.STEADY_WINDOW_S
KNOT = 1852.0 / 3600.0  # m/s
SPEED_CONTROLLER = "saoud"  # Saoud (2015)'s sail law with a heading rudder, the polar's default
GZ_HEELS_DEG = np.arange(0.0, 180.5, 1.0)  # deg


@dataclass(frozen=True, eq=False)
class BoatCheck:
    """The numbers of :func:`check_boat` (SI, angles in rad); :meth:`text` prints them.

    Parameters
    ----------
    name : str
        The boat's name.
    mass : float
        Displacement (mass), kg.
    volume : float
        Displaced volume m / rho_water, m^3.
    hull_volume : float
        Volume of the canoe body below its design waterline, m^3.
    sinkage : float
        Height of the design waterline above the water when the boat floats upright at its
        weight, m (0: it floats on its design waterline; negative: it floats higher).
    canoe_draft : float
        Depth of the canoe body, m.
    draft : float
        Depth of the deepest appendage tip (keel or rudder) below the design waterline, m.
    lcb, lcg : float
        Centre of buoyancy and centre of gravity forward of CO, m.
    gm_t, gm_l : float
        Transverse and longitudinal metacentric heights of the hull at the boat's CG, m.
    gm_t_file : float
        The boat's own ``gm_t`` (what the reduced models' righting uses), m.
    heel, gz : numpy.ndarray
        The righting-arm curve: heel (rad), GZ (m).
    gz_max, gz_max_heel : float
        Largest GZ (m) and the heel where it occurs (rad).
    vanishing_heel : float
        Angle of vanishing stability (rad): where GZ falls through zero; pi when it stays
        positive to inverted.
    roll_period : float
        Natural roll period of the free-floating boat, roll coupled with sway
        (:func:`natural_periods`), s.
    roll_period_uncoupled : float
        Roll alone about the CG, the sway added mass left out, 2 pi sqrt((I_G + A44) / C44), s.
    heave_period, pitch_period : float
        Natural periods of heave and pitch, s.
    wind : float
        True wind speed of the speed runs, m/s.
    duration : float
        Simulated seconds of each speed run.
    twa : tuple of float
        True wind angles of the speed runs, rad.
    speed, steady_heel : tuple of float
        Steady speed (m/s) and heel (rad) at each TWA; NaN where the run did not finish.
    sensors, actuators : str
        The boat's instruments and actuators as fitted, one line each
        (:func:`sailmujoco.boat.fitted_file.fitted_summary`).
    crew : str
        The crew in a line (:func:`crew_summary`; empty without one).
    figure : Path or None
        The GZ figure written.
    """

    name: str
    mass: float
    volume: float
    hull_volume: float
    sinkage: float
    canoe_draft: float
    draft: float
    lcb: float
    lcg: float
    gm_t: float
    gm_l: float
    gm_t_file: float
    heel: np.ndarray
    gz: np.ndarray
    gz_max: float
    gz_max_heel: float
    vanishing_heel: float
    roll_period: float
    roll_period_uncoupled: float
    heave_period: float
    pitch_period: float
    wind: float
    duration: float
    twa: tuple
    speed: tuple
    steady_heel: tuple
    sensors: str = ""
    actuators: str = ""
    crew: str = ""
    figure: Path | None = None

    def text(self) -> str:
        """The report, one plain line per quantity."""
        deg = math.degrees
        floats = ("on its design waterline" if abs(self.sinkage) < 5e-4 else
                  f"{abs(self.sinkage) * 1e3:.0f} mm {'below' if self.sinkage > 0 else 'above'} "
                  "its design waterline (mass and hull volume disagree)")
        vanishing = ("none: GZ stays positive to 180 deg" if self.vanishing_heel >= math.pi
                     else f"{deg(self.vanishing_heel):.0f} deg")
        lines = [
            f"{self.name}",
            f"displacement  {self.mass:.6g} kg, {self.volume:.4g} m^3 "
            f"(canoe body at its design waterline: {self.hull_volume:.4g} m^3)",
            f"floats        {floats}",
            f"draft         {self.draft:.3f} m to the deepest appendage tip "
            f"(canoe body {self.canoe_draft:.3f} m)",
            f"LCB           {_signed(self.lcb)} m forward of CO (LCG {_signed(self.lcg)} m)",
            f"GM_t          {self.gm_t:.3f} m from the hull and CG (the file's gm_t: "
            f"{self.gm_t_file:.3f} m); GM_L {self.gm_l:.2f} m",
            f"GZ            max {self.gz_max:.3f} m at {deg(self.gz_max_heel):.0f} deg heel; "
            f"vanishing stability {vanishing}"
            + (f" ({self.figure})" if self.figure else ""),
            f"periods       roll {self.roll_period:.2f} s, the free boat's: roll with sway "
            "(T = 2 pi sqrt((I_G + A44 + z_G^2 m A22 / (m + A22)) / C44))",
            f"              roll {self.roll_period_uncoupled:.2f} s if it rolled alone about its "
            "CG, no sway added mass (T = 2 pi sqrt((I_G + A44) / C44))",
            f"              heave {self.heave_period:.2f} s, pitch {self.pitch_period:.2f} s "
            "(T = 2 pi sqrt((I + A) / C))",
            *([_wrapped("crew", self.crew)] if self.crew else []),
            _wrapped("sensors", self.sensors),
            _wrapped("actuators", self.actuators),
            f"steady speed  in {self.wind:g} m/s true wind ({SPEED_CONTROLLER} sail law + heading "
            f"rudder; mean of the last {polar.STEADY_WINDOW_S:g} s of {self.duration:g} s runs):",
        ]
        for twa, speed, heel in zip(self.twa, self.speed, self.steady_heel, strict=True):
            lines.append(f"  TWA {deg(twa):5.0f} deg: " + ("did not finish" if not np.isfinite(speed)
                         else f"{speed:.2f} m/s ({speed / KNOT:.2f} kn), heel {deg(abs(heel)):.1f} deg"))
        return "\n".join(lines)


def crew_summary(p: BoatParams) -> str:
    """The crew in a line (empty without one): where it sits and the moment it rights the boat by.

    Parameters
    ----------
    p : BoatParams
        The boat.
    """
    if not p.carries_crew:
        return ""
    c = p.crew
    return (f"{c.mass:g} kg on the weather rail, {c.arm:.2f} m off the centreline and {c.height:.2f} m "
            f"above the waterline, crossing in {c.shift_time:g} s; beyond the GZ above (the boat's own) it "
            f"rights the boat by m g arm cos(heel), {c.mass * GRAVITY * c.arm / 1e3:.2f} kN m upright")


def _wrapped(label: str, text: str) -> str:
    """``label`` in the report's first 14 columns and ``text`` wrapped at 100 beside it."""
    return textwrap.fill(text, 100, initial_indent=f"{label:14s}", subsequent_indent=" " * 14)


def _signed(x: float) -> str:
    """``x`` to the millimetre with its sign, never ``-0.000``."""
    return f"{round(x, 3) + 0.0:+.3f}"


def check_boat(path_or_params, wind: float = 6.0, out=None, *, twa_deg=DEFAULT_TWA_DEG,
               duration: float = SPEED_RUN_S, log=None) -> BoatCheck:
    """Check a boat: hydrostatics, GZ curve, natural periods and steady speeds.

    The natural periods are undamped (:func:`natural_periods`): heave and pitch those of a
    mass on a spring, T = 2 pi sqrt((I + A) / C), with I the rigid-body mass or inertia, A the
    added mass (-Z_wdot, -M_qdot) and C the hydrostatic stiffness: heave C33 = rho g A_wp;
    pitch C55 = rho g V GM_L (V = m / rho, the hull's GM at the boat's CG). Roll, with
    C44 = rho g V GM_t, is coupled with the free sway through the CG's height z_G above CO:
    T4 = 2 pi sqrt((I_G + A44 + z_G^2 m A22 / (m + A22)) / C44); the uncoupled
    2 pi sqrt((I_G + A44) / C44) is reported beside it.

    Parameters
    ----------
    path_or_params : str, os.PathLike or BoatParams
        A boat file, a registered boat, or a boat's parameters.
    wind : float
        True wind speed of the speed runs, m/s.
    out : str or os.PathLike, optional
        Folder for ``gz.png`` and the speed runs' sweep; None: no figure, runs in a temporary
        folder.
    twa_deg : iterable of float
        True wind angles of the speed runs, deg.
    duration : float
        Simulated seconds per speed run.
    log : callable, optional
        Called with a line of progress before each slow part (``print`` on the command line).

    Returns
    -------
    BoatCheck
    """
    say = log or (lambda line: None)
    p = path_or_params if isinstance(path_or_params, BoatParams) else get_boat(path_or_params)
    if not (isinstance(wind, (int, float)) and math.isfinite(wind) and wind > 0):
        raise ValueError(f"wind must be a positive speed in m/s, got {wind!r}")
    say(f"{p.name}: hydrostatics and GZ curve 0-180 deg")
    heel = np.radians(GZ_HEELS_DEG)
    gz = gz_curve(p, heel)
    folder = Path(out) if out is not None else None
    if folder is not None:
        folder.mkdir(parents=True, exist_ok=True)
    say(f"{p.name}: steady speeds, {len(tuple(twa_deg))} runs of {duration:g} s in {wind:g} m/s")
    speeds = steady_speeds(path_or_params, p, wind, twa_deg, duration, folder)
    i_max = int(np.argmax(gz))
    result = BoatCheck(
        name=p.name, **_hydrostatics(p), heel=heel, gz=gz, gz_max=float(gz[i_max]),
        gz_max_heel=float(heel[i_max]), vanishing_heel=vanishing_angle(heel, gz),
        **natural_periods(p), wind=float(wind), duration=float(duration),
        twa=tuple(math.radians(a) for a in twa_deg), speed=speeds[0], steady_heel=speeds[1],
        sensors=fitted_summary(p.sensors, "sensors"), actuators=fitted_summary(p.actuators, "actuators"),
        crew=crew_summary(p),
        figure=None if folder is None else folder / "gz.png")
    if folder is not None:
        plot_gz(result, folder / "gz.png")
    return result


def _columns(p: BoatParams) -> np.ndarray:
    """The hull's 48 x 48 column quadrature as :func:`sailmujoco.forces.stability.righting_arm` takes it."""
    return hull_geometry.column_quadrature(p.hull, 48, 48).array()


def gz_curve(p: BoatParams, heel) -> np.ndarray:
    """Righting arms GZ (m) at ``heel`` (rad, 0 to pi), trim level.

    Parameters
    ----------
    p : BoatParams
        The boat.
    heel : array_like
        Heels, rad.
    """
    columns = _columns(p)
    return np.array([stability.righting_arm(p, h, columns) for h in np.asarray(heel, dtype=float)])


def vanishing_angle(heel, gz) -> float:
    """The heel (rad) past the maximum where GZ first falls through zero (linear between
    points); pi when it stays positive to the last heel before inverted.

    Parameters
    ----------
    heel, gz : numpy.ndarray
        The curve (rad, m), heel ascending from 0 to pi.
    """
    start = int(np.argmax(gz))
    for i in range(start, len(heel) - 2):  # GZ is 0 at pi itself (inverted): stop before it
        if gz[i] > 0.0 >= gz[i + 1]:
            return float(heel[i] + (heel[i + 1] - heel[i]) * gz[i] / (gz[i] - gz[i + 1]))
    return math.pi


def _hydrostatics(p: BoatParams) -> dict:
    """Displacement, flotation, draft, LCB/LCG and metacentric heights of ``p``."""
    h = p.hull
    columns = _columns(p)
    upright = matrix_from_euler(0.0, 0.0, 0.0)
    heave = stability.equilibrium_heave(p, 0.0, columns)  # CO's height above the water
    vol, qx, _, _ = submerged_volume(heave, upright, columns)
    keel_tip = 0.9 * h.canoe_draft + p.keel.span  # the MJCF keel box hangs from 0.9 t0
    rudder_tip = 0.5 * h.canoe_draft + p.rudder.span  # the rudder blade from 0.5 t0
    return {"mass": p.mass, "volume": p.displaced_volume, "hull_volume": hull_geometry.volume(h),
            "sinkage": -heave, "canoe_draft": h.canoe_draft,
            "draft": max(h.canoe_draft, keel_tip, rudder_tip), "lcb": qx / vol, "lcg": p.cg_x,
            "gm_t": hull_geometry.gm_transverse(h, p.cg_z),
            "gm_l": hull_geometry.gm_longitudinal(h, p.cg_z), "gm_t_file": p.gm_t}


def natural_periods(p: BoatParams) -> dict:
    """Undamped natural periods (s) of roll, heave and pitch of the free-floating boat.

    Heave and pitch are those of a mass on a spring, T = 2 pi sqrt((I + A) / C). Roll is
    coupled with sway: the added mass acts at CO (where the mass matrix holds it), the CG
    sits z_G below or above it, and sway has no spring. With q = (sway of CO, roll), the mass
    matrix about CO is [[m + A22, -m z_G], [-m z_G, I_G + m z_G^2 + A44]] and the only
    stiffness is C44 in roll; eliminating the free sway leaves::

        T4 = 2 pi sqrt((I_G + A44 + z_G^2 m A22 / (m + A22)) / C44)

    (``roll_period``). The boat rolls about a point between its CG and CO: the water's sway
    inertia A22 resists the CG's sideways swing. ``roll_period_uncoupled`` is roll alone about
    the CG, 2 pi sqrt((I_G + A44) / C44), the spring-mass form, which leaves that out.

    Parameters
    ----------
    p : BoatParams
        The boat: rigid-body inertia about the CG, added mass (SNAME, <= 0) about CO, hull
        and CG.

    Returns
    -------
    dict
        ``roll_period``, ``roll_period_uncoupled``, ``heave_period``, ``pitch_period``.
    """
    h, a = p.hull, p.added_mass_diagonal
    weight = p.rho_water * GRAVITY * p.displaced_volume  # rho g V
    c44 = weight * hull_geometry.gm_transverse(h, p.cg_z)  # C44 = rho g V GM_t
    sway = p.cg_z**2 * p.mass * a[1] / (p.mass + a[1])  # z_G^2 m A22 / (m + A22), kg m^2
    springs = {"roll_period": (p.inertia[0] + a[3] + sway, c44),
               "roll_period_uncoupled": (p.inertia[0] + a[3], c44),
               "heave_period": (p.mass + a[2],  # C33 = rho g A_wp
                                p.rho_water * GRAVITY * hull_geometry.waterplane_area(h)),
               "pitch_period": (p.inertia[1] + a[4],  # C55 = rho g V GM_L
                                weight * hull_geometry.gm_longitudinal(h, p.cg_z))}
    return {k: 2.0 * math.pi * math.sqrt(i / c) if c > 0 else math.inf
            for k, (i, c) in springs.items()}


def steady_speeds(boat, p: BoatParams, wind: float, twa_deg, duration: float, folder) -> tuple:
    """(speeds in m/s, heels in rad) at each TWA: the polar's runs, serial, in ``folder``.

    Parameters
    ----------
    boat : str, os.PathLike or BoatParams
        The boat as given to :func:`check_boat`.
    p : BoatParams
        Its parameters (written to a boat file when ``boat`` is one, for the sweep).
    wind : float
        True wind speed, m/s.
    twa_deg : iterable of float
        True wind angles, deg.
    duration : float
        Seconds per run.
    folder : Path or None
        Where the sweep writes (``<folder>/speeds``); None: a temporary folder.
    """
    twa_deg = [float(a) for a in twa_deg]
    with tempfile.TemporaryDirectory() as scratch:
        where = Path(scratch) if folder is None else folder / "speeds"
        where.mkdir(parents=True, exist_ok=True)
        if isinstance(boat, BoatParams):
            boat = write_boat(p, where / f"{p.name}.toml")
        frame = polar.compute(str(boat), SPEED_CONTROLLER, where, tws=[wind], twa=twa_deg,
                              duration=duration, scheduler="serial", progress=False)
    rows = {float(r.twa): r for r in frame.itertuples()}
    nan = float("nan")
    return (tuple(float(rows[a].speed) if a in rows else nan for a in twa_deg),
            tuple(float(rows[a].heel) if a in rows else nan for a in twa_deg))


def plot_gz(check: BoatCheck, path) -> Path:
    """The GZ curve against heel, with the GM_t tangent, the maximum and the vanishing angle.

    Parameters
    ----------
    check : BoatCheck
        The boat's check.
    path : str or os.PathLike
        The PNG written.

    Returns
    -------
    Path
        ``path``.
    """
    from .. import figures

    plt = figures.pyplot()
    deg = np.degrees(check.heel)
    fig, ax = plt.subplots(figsize=(7.0, 4.4))
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.plot(deg, check.gz, "k", lw=2.0, label="GZ of the hull (trim level, floating at its weight)")
    one_rad = math.degrees(1.0)
    ax.plot([0.0, one_rad], [0.0, check.gm_t], "C0--", lw=1.2,
            label=f"tangent at 0: GM_t = {check.gm_t:.3f} m at 1 rad ({one_rad:.1f} deg)")
    ax.plot([one_rad, one_rad], [0.0, check.gm_t], "C0:", lw=1.0)
    ax.plot(math.degrees(check.gz_max_heel), check.gz_max, "o", color="C1",
            label=f"max GZ {check.gz_max:.3f} m at {math.degrees(check.gz_max_heel):.0f} deg")
    if check.vanishing_heel < math.pi:
        ax.plot(math.degrees(check.vanishing_heel), 0.0, "s", color="C3",
                label=f"vanishing stability at {math.degrees(check.vanishing_heel):.0f} deg")
    else:
        ax.plot([], [], " ", label="no vanishing angle: GZ > 0 up to 180 deg")
    ax.set_xlim(0.0, 180.0)
    ax.set_xticks(np.arange(0, 181, 30))
    top = max(check.gz_max, check.gm_t)
    ax.set_ylim(min(float(check.gz.min()), 0.0) - 0.1 * top, 1.15 * top)
    ax.set_xlabel("heel φ [deg]")
    ax.set_ylabel("righting arm GZ [m]")
    ax.set_title(f"{check.name}: righting arm against heel "
                 f"(displacement {check.mass:.6g} kg)")
    figures.legend_below(fig, ax, ncol=2)
    return figures.save(fig, path, dpi=120)
