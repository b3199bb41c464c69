"""A boat from its principal dimensions: the rules that derive everything else, each with its source.

A class publishes LOA, LWL, beam, draft, displacement, ballast, the rig's I, J, P, E and its sail
areas; a simulation needs hull lines, keel and rudder, rig heights, inertia, added masses and
damping. :func:`boat_from_dimensions` derives them by the rules below and writes the rule beside
every number (``BoatParams.sources``, printed by ``sailmujoco boat make`` into the boat file,
where a user reads and edits them). Nothing here belongs to one class: the same rules make any
monohull keelboat.

The rules, and where they come from:

* **Canoe body** (:class:`~sailmujoco.boat.hull.HullShape`: parabolic planform, half-elliptic
  sections): length LWL; waterline beam :data:`WATERLINE_BEAM` of the beam, the beam itself at
  the deck (the topsides flare between); canoe-body draft from the displacement by the hull's
  own volume, V = (4 pi / 15) b0 t0 L, the keel's small volume left out; freeboard
  :data:`FREEBOARD_PER_LOA` of LOA where the dimensions do not give it.
* **Mass and CG**: the ballast at :data:`BALLAST_SPAN` of the fin's span below its root,
  the rest of the mass at :data:`REST_HEIGHT` of the freeboard above the waterline; CG at
  midship, where the symmetric canoe body has its LCB.
* **Keel**: a fin from its root (:data:`KEEL_ROOT` of the canoe body's depth, where the model
  hangs it) to the draft, chord :data:`KEEL_CHORD` of LWL, its centre of pressure at
  :data:`FOIL_CP_SPAN` of its span, under the CG.
* **Rudder**: :data:`RUDDER_AREA` of the keel's area at aspect ratio :data:`RUDDER_AR`, at
  :data:`RUDDER_X` of LWL aft of midship.
* **Rig**: sails cambered :data:`RIG_CAMBER` deep (:mod:`sailmujoco.forces.sail_camber`); the
  overhangs split LOA - LWL evenly, so the forestay stands at LOA/2; the mast J aft
  of it; the boom :data:`BOOM_ABOVE_DECK` of P above the deck; the main's luff P, its foot
  from its area (2 A / P), its centroid a third up and a third aft. The headsail's luff on the
  forestay, :data:`JIB_LUFF` of I high, its tack at the deck, sheeted between
  :data:`JIB_ANGLES`.
* **Crew** (when the dimensions give its mass): movable ballast on the weather rail
  (:class:`~sailmujoco.boat.params.Crew`), :data:`CREW_ARM_IN` inboard of the deck edge and
  :data:`CREW_SEAT` above the deck, amidships; it crosses in :data:`CREW_SHIFT`.
* **What the dimensions cannot give** (added masses, damping, the radii of gyration, the
  masses of boom and rudder, the servos): the Wille yacht's (Wille, Hassani & Sprenger 2016a,
  Appendix A, as :func:`sailmujoco.boat.catalogue.wille_yacht` reads it), scaled by Froude
  similarity: a mass or force derivative by the displacement ratio mu, a length by the
  waterline-length ratio s, so an added inertia by mu s^2, a damping in N s/m by mu s^-1/2 and in
  N m s/rad by mu s^3/2; the radii of gyration in roll by the ratio of the rig's height plus the
  draft (the rig and keel hold the roll inertia), in pitch and yaw by s.

Every constant marked "guess" is ours, with the reason beside it; the rest are the parent's or
follow from geometry.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, fields

from .. import constants as c
from . import hull as hull_geometry
from .hull import HullShape
from .params import BoatParams, Crew, Foil, Headsail, Sail

WATERLINE_BEAM = 0.85  # B_WL / B, guess: flared topsides of modern keelboats carry their beam above
# the water (the Wille yacht's is 0.77, the 11:Metre's lines are not public)
FREEBOARD_PER_LOA = 0.075  # freeboard / LOA, guess: 0.7-0.9 m on 9-12 m keelboats
BALLAST_SPAN = 0.6  # ballast centroid / fin span below the canoe body, guess: a fin keel of uniform
# section weighted low (a bulb would put it lower)
REST_HEIGHT = 0.31  # the rest's centroid / freeboard, the Wille yacht's 0.25 m over its 0.8 m freeboard
KEEL_CHORD = 0.09  # mean fin chord / LWL, guess: fins of aspect ratio about 2 on 8-10 m keelboats
FOIL_CP_SPAN = 0.45  # a foil's centre of pressure / its span below its root, guess: a tapered fin
KEEL_ROOT, RUDDER_ROOT = 0.9, 0.5  # the foils' roots / the canoe body's depth t0: where the model hangs
# them (mjcf.py), so the drawn boat and `boat check` have the class's draft
KEEL_THICKNESS = 0.10  # t / c of the fin's NACA section, guess
RUDDER_AREA = 0.33  # rudder area / keel area, guess: spade rudders of fin-keel boats
RUDDER_AR = 2.97  # the Wille yacht's rudder aspect ratio (Appendix A)
RUDDER_X = -0.42  # rudder CP / LWL from midship, the Wille yacht's -3.7 m on 8.8 m (eq. 34)
BOOM_ABOVE_DECK = 0.10  # boom height above the deck / P, guess
JIB_LUFF = 0.95  # the headsail's luff height / I, guess: its head just below the forestay's hounds
JIB_ANGLES = (math.radians(9.0), math.radians(60.0))  # rad, guess: a genoa track's 8-10 deg lead
MAIN_MAX_ANGLE = math.radians(85.0)  # rad, guess: the boom against the shrouds
RIG_CAMBER = 0.10  # camber ratio of main and headsail, guess: upwind sails are cut about a tenth of
# their chord deep (8-14 %); 0 gives the papers' flat plates (forces/sail_camber.py)
CREW_SEAT = 0.3  # m, the crew's centre of mass above the deck, guess: people sitting on the rail
CREW_ARM_IN = 0.3  # m, the crew's centre of mass inboard of the deck edge, guess: sitting on the rail,
# legs over the side, bodies upright (not hiked out)
CREW_SHIFT = 4.0  # s, guess: a crew crossing a 2-3 m deck while the boat tacks
ELEVEN_METRE = "eleven_metre_dimensions.toml"  # sailmujoco/data: the class's figures


@dataclass(frozen=True)
class Dimensions:
    """A monohull keelboat's principal dimensions, as a class publishes them. SI units.

    Parameters
    ----------
    name : str
        The boat's name (an identifier).
    loa, lwl, beam, draft : float
        Length overall, waterline length, maximum beam, draft, m.
    displacement, ballast : float
        Displacement and ballast, kg.
    i, j, p, e : float
        The rig: foretriangle height I and base J, mainsail luff P and foot E, m.
    main_area, jib_area : float
        Sail areas, m^2 (jib 0: the main alone).
    freeboard : float or None
        Freeboard amidships, m; None: :data:`FREEBOARD_PER_LOA` of LOA.
    crew : float
        The crew's mass, kg, on top of the displacement (0: no crew).
    """

    name: str
    loa: float
    lwl: float
    beam: float
    draft: float
    displacement: float
    ballast: float
    i: float
    j: float
    p: float
    e: float
    main_area: float
    jib_area: float = 0.0
    freeboard: float | None = None
    crew: float = 0.0

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name.isidentifier():
            raise ValueError(f"dimensions: name must be an identifier, got {self.name!r}")
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name in ("name", "freeboard") and (f.name == "name" or value is None):
                continue
            may_be_0 = f.name in ("jib_area", "crew")
            low_ok = value >= 0.0 if may_be_0 else value > 0.0
            if not isinstance(value, (int, float)) or not math.isfinite(value) or not low_ok:
                kind = "finite number >= 0" if may_be_0 else "positive finite number"
                raise ValueError(f"dimensions: {f.name} must be a {kind}, got {value!r}")
        if self.lwl > self.loa:
            raise ValueError(f"dimensions: lwl ({self.lwl:g} m) must not exceed loa ({self.loa:g} m)")
        if self.ballast >= self.displacement:
            raise ValueError(f"dimensions: ballast ({self.ballast:g} kg) must be less than the "
                             f"displacement ({self.displacement:g} kg)")


def boat_from_dimensions(d: Dimensions, parent: BoatParams, rho_water: float = c.RHO_WATER,
                         camber: float = RIG_CAMBER) -> BoatParams:
    """The boat of ``d`` by the module's rules, each number's rule in ``sources``.

    Parameters
    ----------
    d : Dimensions
        The principal dimensions.
    parent : BoatParams
        The boat whose unmeasured numbers are scaled (the module docstring): the Wille yacht
        (``get_boat("wille_yacht")``) for ``eleven_metre`` and ``sailmujoco boat make``.
    rho_water : float
        Water density, kg/m^3.
    camber : float
        The sails' camber ratio (:data:`RIG_CAMBER`; 0: flat plates).
    """
    mu, s = d.displacement / parent.mass, d.lwl / parent.hull.length
    hull, sources = _hull(d, rho_water)
    keel_span = d.draft - KEEL_ROOT * hull.canoe_draft
    if keel_span <= 0.0:
        raise ValueError(f"dimensions: draft {d.draft:g} m is not below the canoe body's "
                         f"{hull.canoe_draft:.3f} m: no keel")
    z_ballast = -(KEEL_ROOT * hull.canoe_draft + BALLAST_SPAN * keel_span)
    z_rest = REST_HEIGHT * hull.freeboard
    cg_z = (d.ballast * z_ballast + (d.displacement - d.ballast) * z_rest) / d.displacement
    sources["boat.cg_z"] = (f"ballast {d.ballast:g} kg at {z_ballast:.3f} m ({BALLAST_SPAN:g} of the fin's "
                            f"span below its root), the rest at {z_rest:.3f} m ({REST_HEIGHT:g} of "
                            "the freeboard)")
    keel, rudder, foil_sources = _foils(d, hull, keel_span, parent)
    sail, headsail, rig_sources = _rig(d, hull, parent, camber)
    sources.update(foil_sources | rig_sources)
    added = parent.added_mass
    added_mass = (mu * added[0], mu * added[1], -hull_geometry.heave_added_mass(hull, rho_water),
                  mu * s**2 * added[3], -hull_geometry.pitch_added_inertia(hull, rho_water),
                  mu * s**2 * added[5])
    inertia = _inertia(d, parent, sail, s)
    volume = d.displacement / rho_water
    gm = hull_geometry.gm_transverse(hull, cg_z)
    if gm <= 0.0:
        raise ValueError(f"dimensions: the boat has no initial stability (GM_t {gm:.3f} m): more ballast, "
                         "beam or draft")
    damping = parent.linear_damping
    roll_frequency = math.sqrt(rho_water * c.GRAVITY * volume * gm / (inertia[0] - added_mass[3]))
    scaled = "the Wille yacht's (Appendix A) by Froude similarity"
    sources.update({
        "boat.mass": "displacement", "boat.inertia": f"radii of gyration: {scaled} (module docstring)",
        "boat.added_mass": f"surge, sway, roll, yaw: {scaled}; heave, pitch: strip theory (hull.py)",
        "boat.gm_t": "from the hull's hydrostatics and the CG", "boat.cg_x": "at the LCB (midship)",
        "boat.wetted_surface": "the canoe body's (hull.py)", "boat.form_factor": "the Wille yacht's",
        "boat.linear_damping": scaled, "boat.roll_friction": scaled, "boat.roll_lift": scaled,
        "boat.roll_frequency": "sqrt(rho g V GM_t / (I_xx - K_pdot))",
        "boat.crossflow_cd": "the Wille yacht's",
    })
    return BoatParams(
        name=d.name, mass=d.displacement, inertia=inertia, inertia_xz=0.0, cg_x=0.0, cg_z=cg_z, hull=hull,
        added_mass=added_mass, gm_t=gm, wetted_surface=hull_geometry.wetted_surface(hull),
        form_factor=parent.form_factor,
        linear_damping=(mu * s**-0.5 * damping[0], mu * s**-0.5 * damping[1], mu * s**-0.5 * damping[2],
                        mu * s**1.5 * damping[3], mu * s**1.5 * damping[4]),
        roll_friction=mu * s**1.5 * parent.roll_friction, roll_lift=mu * s * parent.roll_lift,
        roll_frequency=roll_frequency, crossflow_cd=parent.crossflow_cd, keel=keel, rudder=rudder,
        sail=sail, headsail=headsail, rho_water=rho_water, rho_air=parent.rho_air,
        paper_righting=parent.paper_righting, crew=_crew(d, hull, sources), sources=sources)


def _crew(d: Dimensions, hull: HullShape, sources: dict) -> Crew | None:
    """The crew of ``d`` on the weather rail (None without one); its keys' sources into ``sources``."""
    if d.crew <= 0.0:
        return None
    sources.update({
        "crew.mass": "given", "crew.arm": f"half the beam less {CREW_ARM_IN:g} m (guess)",
        "crew.height": f"the deck + {CREW_SEAT:g} m (guess)", "crew.x": "at the CG (midship)",
        "crew.shift_time": f"{CREW_SHIFT:g} s (guess)",
    })
    return Crew(mass=d.crew, arm=0.5 * d.beam - CREW_ARM_IN, height=hull.freeboard + CREW_SEAT, x=0.0,
                shift_time=CREW_SHIFT)


def _hull(d: Dimensions, rho: float) -> tuple[HullShape, dict]:
    """The canoe body of ``d`` and its keys' sources."""
    freeboard = d.freeboard if d.freeboard is not None else FREEBOARD_PER_LOA * d.loa
    half_beam = 0.5 * WATERLINE_BEAM * d.beam
    canoe_draft = d.displacement / rho / (4.0 * math.pi / 15.0 * half_beam * d.lwl)
    hull = HullShape(length=d.lwl, half_beam=half_beam, canoe_draft=canoe_draft, freeboard=freeboard,
                     deck_half_beam=0.5 * d.beam)
    return hull, {
        "hull.length": "LWL", "hull.half_beam": f"{WATERLINE_BEAM:g} of half the beam (guess)",
        "hull.canoe_draft": "the displacement's volume, V = (4 pi / 15) b0 t0 L",
        "hull.freeboard": "given" if d.freeboard is not None else f"{FREEBOARD_PER_LOA:g} LOA (guess)",
        "hull.deck_half_beam": "half the beam",
    }


def _foils(d: Dimensions, hull: HullShape, keel_span: float, parent) -> tuple[Foil, Foil, dict]:
    """Keel and rudder of ``d`` and their keys' sources."""
    keel_area = keel_span * KEEL_CHORD * d.lwl
    keel = Foil(area=keel_area, aspect_ratio=keel_span**2 / keel_area, thickness_ratio=KEEL_THICKNESS,
                x=0.0, z=-(KEEL_ROOT * hull.canoe_draft + FOIL_CP_SPAN * keel_span))
    rudder_area = RUDDER_AREA * keel_area
    rudder_span = math.sqrt(RUDDER_AR * rudder_area)
    x = RUDDER_X * d.lwl
    root = RUDDER_ROOT * hull.canoe_draft
    r = parent.rudder
    rudder = Foil(area=rudder_area, aspect_ratio=RUDDER_AR, thickness_ratio=r.thickness_ratio, x=x,
                  z=-(root + FOIL_CP_SPAN * rudder_span), mass=r.mass * rudder_area / r.area,
                  max_angle=r.max_angle, time_constant=r.time_constant)
    return keel, rudder, {
        "keel.area": f"span (draft - {KEEL_ROOT:g} canoe draft) x chord {KEEL_CHORD:g} LWL (guess)",
        "keel.aspect_ratio": "span^2 / area", "keel.thickness_ratio": "guess",
        "keel.x": "under the CG", "keel.z": f"{FOIL_CP_SPAN:g} of the span below its root (guess)",
        "rudder.area": f"{RUDDER_AREA:g} of the keel's (guess)", "rudder.aspect_ratio": "the Wille yacht's",
        "rudder.x": f"{RUDDER_X:g} LWL, the Wille yacht's",
        "rudder.z": f"{FOIL_CP_SPAN:g} of its span below its root",
        "rudder.mass": "the Wille yacht's per area", "rudder.thickness_ratio": "the Wille yacht's",
        "rudder.max_angle": "the Wille yacht's", "rudder.time_constant": "the Wille yacht's",
    }


def _rig(d: Dimensions, hull: HullShape, parent, camber: float) -> tuple[Sail, Headsail | None, dict]:
    """Main and headsail of ``d`` and their keys' sources."""
    tack_x = 0.5 * d.loa  # the overhangs split LOA - LWL evenly: the stem head at LOA / 2
    boom = hull.freeboard + BOOM_ABOVE_DECK * d.p
    foot = 2.0 * d.main_area / d.p
    ps = parent.sail
    sail = Sail(area=d.main_area, aspect_ratio=d.p**2 / d.main_area, mast_x=tack_x - d.j, ce_aft=foot / 3.0,
                ce_height=boom + d.p / 3.0, mass=ps.mass * d.displacement / parent.mass,
                max_angle=MAIN_MAX_ANGLE, time_constant=ps.time_constant, camber=camber)
    sources = {
        "sail.area": "the class's", "sail.aspect_ratio": "P^2 / area", "sail.mast_x": "LOA / 2 - J",
        "sail.ce_aft": "a third of the foot, 2 area / P",
        "sail.ce_height": f"deck + {BOOM_ABOVE_DECK:g} P + P / 3",
        "sail.mass": "the Wille yacht's per displacement", "sail.max_angle": "guess",
        "sail.time_constant": "the Wille yacht's",
        "sail.camber": (f"{RIG_CAMBER:g} (guess: upwind sails are cut about a tenth deep)"
                        if camber == RIG_CAMBER else "given"),
    }
    if d.jib_area <= 0.0:
        return sail, None, sources
    luff = JIB_LUFF * d.i
    headsail = Headsail(area=d.jib_area, luff_height=luff, head_aft=d.j * luff / d.i, tack_x=tack_x,
                        tack_height=hull.freeboard, min_angle=JIB_ANGLES[0], max_angle=JIB_ANGLES[1])
    sources.update({
        "headsail.area": "the class's", "headsail.luff_height": f"{JIB_LUFF:g} I (guess)",
        "headsail.head_aft": "on the forestay, J luff / I", "headsail.tack_x": "LOA / 2",
        "headsail.tack_height": "the deck", "headsail.min_angle": "guess", "headsail.max_angle": "guess",
    })
    return sail, headsail, sources


def _inertia(d: Dimensions, parent, sail: Sail, s: float) -> tuple[float, float, float]:
    """(Ixx, Iyy, Izz) of ``d``: the parent's radii of gyration scaled (module docstring)."""
    extent = sail.masthead_height + d.draft
    parent_extent = parent.sail.masthead_height + parent.keel.span + parent.hull.canoe_draft
    roll = extent / parent_extent
    ixx, iyy, izz = parent.inertia
    m = d.displacement
    return (m * (ixx / parent.mass) * roll**2, m * (iyy / parent.mass) * s**2, m * (izz / parent.mass) * s**2)


def read_dimensions(path) -> Dimensions:
    """The :class:`Dimensions` of a dimensions file: TOML with one ``[dimensions]`` table of the
    class's numbers (its keys :class:`Dimensions`' fields, SI units); one line per problem.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    """
    from ..tomlfile import read_toml

    data = read_toml(path, "dimensions file")
    table = data.get("dimensions")
    if not isinstance(table, dict):
        raise ValueError(f"dimensions file {str(path)!r} has no [dimensions] table (keys: "
                         f"{', '.join(f.name for f in fields(Dimensions))})")
    known = {f.name for f in fields(Dimensions)}
    unknown = sorted(set(table) - known)
    if unknown:
        raise ValueError(f"dimensions file {str(path)!r}: unknown key(s) {', '.join(unknown)}; the keys are "
                         f"{', '.join(f.name for f in fields(Dimensions))}")
    required = [f.name for f in fields(Dimensions) if f.default is dataclasses.MISSING]
    missing = [name for name in required if name not in table]
    if missing:
        raise ValueError(f"dimensions file {str(path)!r}: missing key(s) {', '.join(missing)}")
    try:
        return Dimensions(**table)
    except (TypeError, ValueError) as err:
        raise ValueError(f"dimensions file {str(path)!r}: {err}") from None


def eleven_metre_dimensions(headsail: bool = True) -> Dimensions:
    """The 11:Metre One Design's class dimensions (Holland/Gyhlenius 1990, shipped in sailmujoco/data).

    Parameters
    ----------
    headsail : bool
        With the class's jib (False: its area 0, the main alone).
    """
    from importlib import resources

    d = read_dimensions(resources.files("sailmujoco.data").joinpath(ELEVEN_METRE))
    return d if headsail else dataclasses.replace(d, jib_area=0.0)
