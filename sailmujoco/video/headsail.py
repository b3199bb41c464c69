"""The headsail drawn: a display-only body that follows the hull and the trim rule.

The headsail has no joint in the simulated model (its sheet leads to the deck: its force goes to
the hull, :mod:`sailmujoco.forces.headsail`), so the display model carries it as a mocap body
with the sail's triangle, posed each frame from the hull's pose and the main's angle.
"""

from __future__ import annotations

import math

import numpy as np

from ..forces.headsail import headsail_angle

BODY = "headsail"


def add_headsail(spec, params) -> None:
    """Add the headsail's mocap body and triangle to the display model's spec (nothing without one).

    Parameters
    ----------
    spec : mujoco.MjSpec
        The scene's spec, before it is compiled.
    params : BoatParams
        The boat.
    """
    import mujoco

    if not params.carries_headsail:
        return
    h = params.headsail
    thickness = 0.002 * h.luff_height
    mesh = spec.add_mesh(name="headsail_mesh")
    mesh.uservert = [0.0, -thickness, 0.0, -h.foot, -thickness, 0.0, -h.head_aft, -thickness, h.luff_height,
                     0.0, thickness, 0.0, -h.foot, thickness, 0.0, -h.head_aft, thickness, h.luff_height]
    body = spec.worldbody.add_body(name=BODY, mocap=True)
    body.add_geom(name=BODY, type=mujoco.mjtGeom.mjGEOM_MESH, meshname="headsail_mesh",
                  material="sailcloth", contype=0, conaffinity=0, group=1)


def pose_headsail(model, data, params, position, rotation, main_angle: float) -> None:
    """Put the drawn headsail at its tack on the posed hull, turned by the trim rule.

    Parameters
    ----------
    model, data : mujoco.MjModel, mujoco.MjData
        The display model and its data.
    params : BoatParams
        The boat.
    position : numpy.ndarray, shape (3,)
        CO in the world, m.
    rotation : numpy.ndarray, shape (3, 3)
        Body to world.
    main_angle : float
        The main's angle lambda, rad.
    """
    import mujoco

    if not params.carries_headsail:
        return
    h = params.headsail
    delta, _ = headsail_angle(main_angle, 0.0, h.min_angle, h.max_angle)
    c, s = math.cos(delta), math.sin(delta)
    turn = np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])  # about z by -delta: clew to +y
    mocap = model.body_mocapid[model.body(BODY).id]
    data.mocap_pos[mocap] = position + rotation @ np.array([h.tack_x, 0.0, h.tack_height])
    quat = np.empty(4)
    mujoco.mju_mat2Quat(quat, np.ascontiguousarray(rotation @ turn).ravel())
    data.mocap_quat[mocap] = quat
