"""MJCF of a boat, built from its :class:`~sailmujoco.boat.params.BoatParams` with ``mujoco.MjSpec``.

``xml/<boat>/<boat>.xml`` is :func:`boat_spec` of the default parameters, written by
``python -m sailmujoco.boat.mjcf`` (a test checks the committed file is up to date);
``xml/<boat>/scene.xml`` (hand-written) adds water, sky, light and a fixed camera and
includes it. At run time the boat is rebuilt from its (possibly changed) parameters. Its
shapes and mass properties (hull mesh, inertia of each body, sheet geometry) come from
:mod:`sailmujoco.boat.geometry`.

Bodies: ``hull`` (free joint ``root``; the keel is part of it) with children ``rudder``
(hinge ``rudder`` about the stock) and ``boom`` (hinge ``sail`` about the mast). Both hinge
axes point down (-z), so a positive angle swings the trailing edge to port, Wille's sign for
sigma and lambda (eqs. 26, 35): positive rudder turns the boat to port.

Sites: ``sail_ce``, ``keel_cp``, ``rudder_cp``, ``masthead``, ``mast_step``, and for the
sheeted sail ``sheet_block`` (hull) and ``boom_end`` (boom).

Sail modes:

- ``actuated``: a position servo with first-order lag T_lambda on the command (MuJoCo's
  ``timeconst``), saturated at lambda_sat (Wille §2.1, Saoud Assumption 5).
- ``sheeted``: the boom hinge is free: the sail turns under its own aerodynamic moment about
  the mast, and a sheet (spatial tendon from ``sheet_block`` to ``boom_end``)
  limits its swing. The command is the sheet length; the sheet only pulls
  (force range [-F, 0]), with the same lag T_lambda (Wille 2016b §2.1, eqs. 61-62;
  Viel eq. 12).
"""

from __future__ import annotations

import functools
import math
from importlib import resources
from pathlib import Path

import mujoco
import numpy as np

from ..constants import GRAVITY
from ..options import Dofs, SailMode, choices
from .catalogue import BUILT_IN, get_boat
from .geometry import hull_inertial, hull_mesh, rig_inertia, sheet_geometry, sheet_length
from .params import BoatParams

__all__ = ["REFERENCE_WIND", "SAIL_MODES", "SERVO_ERROR", "SERVO_FREQUENCY", "TIMESTEP", "boat_spec",
           "boat_xml", "compile_model", "hull_inertial", "scene_for", "scene_xml",
           "sheet_geometry", "sheet_length", "write_default_xml", "xml_root"]

SAIL_MODES = choices(SailMode)
TIMESTEP = 0.005  # s, physics step of every boat unless the ``timestep`` option gives another
SERVO_FREQUENCY = 30.0  # rad/s, bandwidth of the rudder and sail servos (>> 1/T)
SERVO_ERROR = math.radians(1.0)  # rad, static error of the sail servo at the reference load
REFERENCE_WIND = 15.0  # m/s, apparent wind of the reference sail load


def _sail_reference_moment(p: BoatParams) -> float:
    """Aerodynamic moment about the mast at REFERENCE_WIND with C_N = 1.25 (its maximum)."""
    s = p.sail
    return 0.5 * p.rho_air * REFERENCE_WIND**2 * s.area * 1.25 * s.ce_aft


def boat_spec(p: BoatParams, sail_mode: str = "actuated", dofs: int = 6,
              timestep: float | None = None) -> mujoco.MjSpec:
    """The boat as an MjSpec (no scene).

    ``dofs=6``: the hull is free. ``dofs=4``: heave and pitch held, as in Wille's and Saoud's
    reduced models: slide x, slide y, hinge yaw (world z), hinge roll (the yawed body x), so
    R = Rz(yaw) Rx(roll) with CO on the waterline.

    Parameters
    ----------
    p : BoatParams
        The boat.
    sail_mode : {"actuated", "sheeted"}
        See the module docstring.
    dofs : {6, 4}
        The hull's degrees of freedom.
    timestep : float, optional
        The physics step, s (the ``timestep`` option); None: :data:`TIMESTEP`.

    Returns
    -------
    mujoco.MjSpec
        Built part by part, in this order (the order fixes the model's element ids): options,
        materials, hull, keel, mast, hull sites, cameras, rudder, boom and sail, the crew (its
        slide the last joint), rudder servo, sail servo or sheet, home keyframe.
    """
    if sail_mode not in SAIL_MODES:
        raise ValueError(f"unknown sail mode {sail_mode!r}; choose one of {SAIL_MODES}")
    if dofs not in choices(Dofs):
        raise ValueError(f"dofs must be 6 (free hull) or 4 (heave and pitch held), got {dofs!r}")
    spec = _empty_spec(p, timestep)
    visual = _visual_default(spec)
    hull = _add_hull(spec, p, dofs, visual)
    _add_keel(hull, p, visual)
    mast_radius = _add_mast(hull, p, visual)
    _add_hull_sites(hull, p)
    _add_cameras(hull, p)
    _add_rudder(hull, p, visual)
    _add_boom_and_sail(spec, hull, p, visual, mast_radius)
    if p.carries_crew:
        if dofs != 6:
            raise ValueError(f"boat {p.name!r} carries a crew, whose slide needs the free hull: dofs=6, "
                             "or the boat without its crew")
        _add_crew(spec, hull, p, visual)
    _add_rudder_servo(spec, p)
    home_ctrl = _add_sail_servo(spec, p) if sail_mode == "actuated" else _add_sheet(spec, p)
    key = spec.add_key(name="home")
    key.qpos = ([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0] + [0.0] * p.carries_crew if dofs == 6
                else [0.0] * 6)
    key.ctrl = home_ctrl
    key.act = home_ctrl
    return spec


def _empty_spec(p: BoatParams, timestep: float | None = None) -> mujoco.MjSpec:
    """The spec's compiler settings and physics options (the step ``timestep``, s, or
    :data:`TIMESTEP`), nothing in its world yet."""
    spec = mujoco.MjSpec()
    spec.modelname = p.name
    spec.compiler.degree = False
    spec.compiler.inertiafromgeom = mujoco.mjtInertiaFromGeom.mjINERTIAFROMGEOM_FALSE
    spec.compiler.autolimits = True
    spec.option.timestep = TIMESTEP if timestep is None else timestep
    # RK4: an undamped free oscillation keeps its energy (first-order integrators drift by up
    # to 17 % in 60 s at this step); the forces run at each stage, see physics.py
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_RK4
    spec.option.gravity = [0.0, 0.0, -GRAVITY]
    # No contacts: the boat meets nothing but water, which our force models handle.
    spec.option.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    # A non-finite state must stop the run with its reason (physics.SimulationStopped), not be
    # silently reset to the keyframe by MuJoCo.
    spec.option.disableflags |= mujoco.mjtDisableBit.mjDSBL_AUTORESET
    return spec


def _visual_default(spec: mujoco.MjSpec):
    """The ``visual`` default class (no contacts, no mass, group 2) and the three materials."""
    visual = spec.add_default("visual", spec.default)
    visual.geom.contype = 0
    visual.geom.conaffinity = 0
    visual.geom.group = 2
    visual.geom.mass = 0.0
    spec.add_material(name="hull_white", rgba=[0.93, 0.93, 0.9, 1.0])
    spec.add_material(name="foil_dark", rgba=[0.15, 0.17, 0.2, 1.0])
    spec.add_material(name="sailcloth", rgba=[0.97, 0.95, 0.85, 0.92])
    return visual


def _add_hull(spec: mujoco.MjSpec, p: BoatParams, dofs: int, visual):
    """The hull body: its mesh, its inertia (the boat's less the turning parts), its joints."""
    verts, faces = hull_mesh(p)
    mesh = spec.add_mesh(name="hull_mesh")
    mesh.uservert = verts.tolist()
    mesh.userface = faces.tolist()

    mh, ch, ih = hull_inertial(p)
    hull = spec.worldbody.add_body(name="hull", pos=[0.0, 0.0, 0.0])
    hull.explicitinertial = True
    hull.mass = mh
    hull.ipos = ch.tolist()
    hull.fullinertia = [ih[0, 0], ih[1, 1], ih[2, 2], ih[0, 1], ih[0, 2], ih[1, 2]]
    if dofs == 6:
        hull.add_freejoint(name="root")
    else:
        hull.add_joint(name="x", type=mujoco.mjtJoint.mjJNT_SLIDE, axis=[1.0, 0.0, 0.0])
        hull.add_joint(name="y", type=mujoco.mjtJoint.mjJNT_SLIDE, axis=[0.0, 1.0, 0.0])
        hull.add_joint(name="yaw", type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0.0, 0.0, 1.0])
        hull.add_joint(name="roll", type=mujoco.mjtJoint.mjJNT_HINGE, axis=[1.0, 0.0, 0.0])
    hull.add_geom(name="hull", default=visual, type=mujoco.mjtGeom.mjGEOM_MESH,
                  meshname="hull_mesh", material="hull_white")
    return hull


def _add_keel(hull, p: BoatParams, visual) -> None:
    """The keel: a box below the canoe body, part of the hull."""
    k = p.keel
    top = -p.hull.canoe_draft * 0.9
    hull.add_geom(name="keel", default=visual, type=mujoco.mjtGeom.mjGEOM_BOX,
                  pos=[k.x, 0.0, top - 0.5 * k.span],
                  size=[0.5 * k.chord, 0.5 * k.thickness_ratio * k.chord, 0.5 * k.span],
                  material="foil_dark")


def _add_mast(hull, p: BoatParams, visual) -> float:
    """The mast, from half the freeboard to the masthead; returns its radius (m)."""
    s = p.sail
    mast_radius = 0.012 * s.luff
    hull.add_geom(name="mast", default=visual, type=mujoco.mjtGeom.mjGEOM_CYLINDER,
                  fromto=[s.mast_x, 0.0, 0.5 * p.hull.freeboard, s.mast_x, 0.0, s.masthead_height],
                  size=[mast_radius, 0, 0], material="foil_dark")
    return mast_radius


def _add_hull_sites(hull, p: BoatParams) -> None:
    """``keel_cp``, ``masthead``, ``mast_step`` and ``cog`` on the hull."""
    k, s = p.keel, p.sail
    hull.add_site(name="keel_cp", pos=[k.x, 0.0, k.z])
    hull.add_site(name="masthead", pos=[s.mast_x, 0.0, s.masthead_height])
    hull.add_site(name="mast_step", pos=[s.mast_x, 0.0, s.boom_height])
    hull.add_site(name="cog", pos=[p.cg_x, 0.0, p.cg_z])


def _add_cameras(hull, p: BoatParams) -> None:
    """The ``follow`` and ``side`` cameras, tracking the hull's centre of mass."""
    scale = p.hull.length
    hull.add_camera(name="follow", mode=mujoco.mjtCamLight.mjCAMLIGHT_TRACKCOM,
                    pos=[-1.6 * scale, -1.4 * scale, 0.9 * scale],
                    xyaxes=[0.66, -0.75, 0.0, 0.3, 0.27, 0.91])
    hull.add_camera(name="side", mode=mujoco.mjtCamLight.mjCAMLIGHT_TRACKCOM,
                    pos=[0.0, -2.2 * scale, 0.4 * scale], xyaxes=[1.0, 0.0, 0.0, 0.0, 0.18, 0.98])


def _add_rudder(hull, p: BoatParams, visual) -> None:
    """The rudder body on its ``rudder`` hinge (axis down), its blade and ``rudder_cp``."""
    _, (mr, cr, i_r) = rig_inertia(p)
    r = p.rudder
    rudder = hull.add_body(name="rudder", pos=[r.x, 0.0, 0.0])
    rudder.explicitinertial = True
    rudder.mass = mr
    rudder.ipos = [0.0, 0.0, r.z]
    rudder.inertia = np.diag(i_r).tolist()
    rudder_limit = 1.05 * r.max_angle
    rudder.add_joint(name="rudder", type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0.0, 0.0, -1.0],
                     range=[-rudder_limit, rudder_limit])
    rudder_top = -0.5 * p.hull.canoe_draft
    rudder.add_geom(name="rudder_blade", default=visual, type=mujoco.mjtGeom.mjGEOM_BOX,
                    pos=[0.0, 0.0, rudder_top - 0.5 * r.span],
                    size=[0.5 * r.chord, 0.5 * r.thickness_ratio * r.chord, 0.5 * r.span],
                    material="foil_dark")
    rudder.add_site(name="rudder_cp", pos=[0.0, 0.0, r.z])


def _add_boom_and_sail(spec: mujoco.MjSpec, hull, p: BoatParams, visual, mast_radius: float) -> None:
    """The boom body on its ``sail`` hinge about the mast (axis down): boom, triangular sail,
    ``sail_ce`` and ``boom_end``; and the sheet's block ``sheet_block`` on the hull."""
    (ms, cs, i_s), _ = rig_inertia(p)
    s = p.sail
    boom = hull.add_body(name="boom", pos=[s.mast_x, 0.0, s.boom_height])
    boom.explicitinertial = True
    boom.mass = ms
    boom.ipos = (cs - np.array([s.mast_x, 0.0, s.boom_height])).tolist()
    boom.inertia = np.diag(i_s).tolist()
    boom.add_joint(name="sail", type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0.0, 0.0, -1.0],
                   range=[-s.max_angle, s.max_angle])
    boom.add_geom(name="boom", default=visual, type=mujoco.mjtGeom.mjGEOM_CAPSULE,
                  fromto=[0.0, 0.0, 0.0, -s.foot, 0.0, 0.0], size=[0.8 * mast_radius, 0, 0],
                  material="foil_dark")
    sail_mesh = spec.add_mesh(name="sail_mesh")
    thickness = 0.002 * s.luff
    sail_mesh.uservert = [0.0, -thickness, 0.0, -s.foot, -thickness, 0.0, 0.0, -thickness, s.luff,
                          0.0, thickness, 0.0, -s.foot, thickness, 0.0, 0.0, thickness, s.luff]
    boom.add_geom(name="sail", default=visual, type=mujoco.mjtGeom.mjGEOM_MESH,
                  meshname="sail_mesh", material="sailcloth")
    boom.add_site(name="sail_ce", pos=[-s.ce_aft, 0.0, s.ce_height - s.boom_height])
    block, boom_end = sheet_geometry(p)
    boom.add_site(name="boom_end", pos=boom_end.tolist())
    hull.add_site(name="sheet_block", pos=block.tolist())


def _add_crew(spec: mujoco.MjSpec, hull, p: BoatParams, visual) -> None:
    """The crew: a body on the slide ``crew`` across the deck (axis +y), starting on the centreline.

    Its mass is the crew's, on top of the boat's; its inertia is that of a mass spread 2 m fore
    and aft along the rail (m L^2 / 12 about y and z, a tenth of it about x): ours, it matters
    little beside the boat's. Its drive is the force kernel's (:mod:`sailmujoco.forces.crew`).
    """
    c = p.crew
    spec.add_material(name="crew_red", rgba=[0.8, 0.2, 0.15, 1.0])
    crew = hull.add_body(name="crew", pos=[c.x, 0.0, c.height])
    crew.explicitinertial = True
    crew.mass = c.mass
    crew.ipos = [0.0, 0.0, 0.0]
    spread = c.mass * 2.0**2 / 12.0
    crew.inertia = [0.1 * spread, spread, spread]
    crew.add_joint(name="crew", type=mujoco.mjtJoint.mjJNT_SLIDE, axis=[0.0, 1.0, 0.0])
    crew.add_geom(name="crew", default=visual, type=mujoco.mjtGeom.mjGEOM_CAPSULE,
                  fromto=[-0.8, 0.0, 0.0, 0.8, 0.0, 0.0], size=[0.18, 0, 0], material="crew_red")


def _add_rudder_servo(spec: mujoco.MjSpec, p: BoatParams) -> None:
    """The rudder's position servo: natural frequency SERVO_FREQUENCY, critically damped, on
    the blade's inertia plus an armature (the motor's reflected inertia)."""
    _, (mr, _, i_r) = rig_inertia(p)
    r = p.rudder
    rudder_arm = max(0.0, 0.2 * mr * r.chord**2)
    rudder_kp = (rudder_arm + i_r[2, 2]) * SERVO_FREQUENCY**2
    act = spec.add_actuator(name="rudder", target="rudder", trntype=mujoco.mjtTrn.mjTRN_JOINT)
    act.set_to_position(kp=rudder_kp, kv=2.0 * math.sqrt(rudder_kp * (rudder_arm + i_r[2, 2])),
                        timeconst=r.time_constant)
    act.ctrlrange = [-r.max_angle, r.max_angle]
    act.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
    spec.joint("rudder").armature = rudder_arm


def _add_sail_servo(spec: mujoco.MjSpec, p: BoatParams) -> list[float]:
    """The actuated sail's position servo: it holds the reference aerodynamic moment within
    SERVO_ERROR; the armature makes that stiffness stable at SERVO_FREQUENCY. Returns the home
    controls."""
    (ms, _, i_s), _ = rig_inertia(p)
    s = p.sail
    boom_inertia = i_s[2, 2] + ms * s.ce_aft**2
    kp = _sail_reference_moment(p) / SERVO_ERROR
    armature = max(0.0, kp / SERVO_FREQUENCY**2 - boom_inertia)
    spec.joint("sail").armature = armature
    act = spec.add_actuator(name="sail", target="sail", trntype=mujoco.mjtTrn.mjTRN_JOINT)
    act.set_to_position(kp=kp, kv=2.0 * math.sqrt(kp * (armature + boom_inertia)),
                        timeconst=s.time_constant)
    act.ctrlrange = [-s.max_angle, s.max_angle]
    act.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
    return [0.0, 0.0]


def _add_sheet(spec: mujoco.MjSpec, p: BoatParams) -> list[float]:
    """The sheeted sail: a sheet from ``sheet_block`` to ``boom_end`` and its length servo.

    A stiff rope: it stretches 1 cm under the reference load, and only pulls. Returns the
    home controls (the sheet let out to the sail's largest angle).
    """
    (ms, _, _), _ = rig_inertia(p)
    s = p.sail
    sheet = spec.add_tendon(name="sheet")
    sheet.wrap_site("sheet_block")
    sheet.wrap_site("boom_end")
    load = _sail_reference_moment(p) / s.foot
    kp = load / 0.01
    act = spec.add_actuator(name="sheet", target="sheet", trntype=mujoco.mjtTrn.mjTRN_TENDON)
    act.set_to_position(kp=kp, kv=2.0 * math.sqrt(kp * ms), timeconst=s.time_constant)
    length_max = float(sheet_length(p, s.max_angle))
    length_min = float(sheet_length(p, 0.0))
    act.ctrlrange = [length_min, length_max]
    act.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
    act.forcerange = [-20.0 * load, 0.0]
    act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
    return [0.0, length_max]


def boat_xml(p: BoatParams, sail_mode: str = "actuated", dofs: int = 6,
             timestep: float | None = None) -> str:
    """MJCF text of the boat (what ``xml/<boat>/<boat>.xml`` holds for default parameters).

    Parameters
    ----------
    p : BoatParams
        The boat.
    sail_mode : {"actuated", "sheeted"}
        See the module docstring.
    dofs : {6, 4}
        The hull's degrees of freedom.
    timestep : float, optional
        The physics step, s; None: :data:`TIMESTEP`.
    """
    spec = boat_spec(p, sail_mode, dofs, timestep)
    spec.compile()  # validates
    return spec.to_xml()


def xml_root():
    """Where the boats' MJCF lives: ``sailmujoco/xml`` when installed, ``xml/`` in a checkout.

    ``xml/`` is no Python package (an ``__init__.py`` there would shadow the standard
    library's ``xml`` for anything run from the repository root), so it is found as data.
    """
    installed = resources.files("sailmujoco").joinpath("xml")
    if installed.is_dir():
        return installed
    checkout = Path(__file__).resolve().parents[2] / "xml"  # editable install
    if checkout.is_dir():
        return checkout
    raise FileNotFoundError("sailmujoco's xml/ folder is missing from this installation")


def scene_xml(boat: str) -> str:
    """The hand-written ``xml/<boat>/scene.xml`` shipped with the package.

    Parameters
    ----------
    boat : str
        The boat's name.
    """
    path = xml_root().joinpath(boat, "scene.xml")
    if not path.is_file():
        raise ValueError(f"no scene for boat {boat!r} in {xml_root()}")
    return path.read_text()


@functools.cache
def _built_in_lengths() -> dict:
    """The built-in boats' hull lengths [m], built once per process."""
    return {name: get_boat(name).hull.length for name in BUILT_IN}


def scene_for(p: BoatParams) -> str:
    """The scene (sea, sky, light, cameras) of boat ``p``: its own ``xml/<name>/scene.xml``, or,
    for a boat registered at run time, the scene of the built-in boat nearest in hull length
    (cameras and visual extent are set for that size) including ``<name>.xml`` instead.

    Parameters
    ----------
    p : BoatParams
        The boat.
    """
    if xml_root().joinpath(p.name, "scene.xml").is_file():
        return scene_xml(p.name)
    lengths = _built_in_lengths()
    nearest = min(lengths, key=lambda name: abs(lengths[name] - p.hull.length))
    text = scene_xml(nearest)
    return (text.replace(f'<include file="{nearest}.xml"/>', f'<include file="{p.name}.xml"/>')
            .replace(f'<mujoco model="{nearest} scene">', f'<mujoco model="{p.name} scene">'))


def compile_model(p: BoatParams, sail_mode: str = "actuated", dofs: int = 6,
                  timestep: float | None = None) -> mujoco.MjModel:
    """Compile scene + boat for parameters ``p`` (a raw ``mujoco.MjModel``).

    Parameters
    ----------
    p : BoatParams
        The boat.
    sail_mode : {"actuated", "sheeted"}
        See the module docstring.
    dofs : {6, 4}
        The hull's degrees of freedom.
    timestep : float, optional
        The physics step, s (the ``timestep`` option); None: :data:`TIMESTEP`.
    """
    return mujoco.MjModel.from_xml_string(
        scene_for(p), assets={f"{p.name}.xml": boat_xml(p, sail_mode, dofs, timestep).encode()})


def write_default_xml(root) -> list:
    """Write ``<root>/<boat>/<boat>.xml`` for every registered boat.

    Parameters
    ----------
    root : path
        The ``xml/`` folder.

    Returns
    -------
    list of Path
        The files written.
    """
    from .catalogue import BOATS

    paths = []
    for name in BOATS:
        path = Path(root) / name / f"{name}.xml"
        path.write_text(boat_xml(get_boat(name)))
        paths.append(path)
    return paths


if __name__ == "__main__":  # python -m sailmujoco.boat.mjcf [xml-dir]
    import sys

    for written in write_default_xml(sys.argv[1] if len(sys.argv) > 1 else "xml"):
        print(f"wrote {written}")
