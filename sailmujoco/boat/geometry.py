"""The shapes and mass properties the boat's MJCF is built from (:mod:`sailmujoco.boat.mjcf`).

The hull mesh, the split of the paper's whole-boat mass and inertia among the hull, rudder and
boom bodies, and the sheet's geometry of the sheeted sail.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.ordered import elementwise
from .params import BoatParams


def rig_inertia(p: BoatParams):
    """Mass, CG (body frame) and inertia about its CG of the boom+sail and of the rudder.

    Parameters
    ----------
    p : BoatParams
        The boat.

    Returns
    -------
    tuple
        ((m_sail, c_sail, I_sail), (m_rudder, c_rudder, I_rudder)): kg, (3,) m, (3, 3) kg m^2.
    """
    s = p.sail
    ms = s.mass
    cs = np.array([s.mast_x - s.ce_aft, 0.0, s.ce_height])  # triangle centroid = CE
    # thin triangle in the boom's x-z plane (+1 % on the in-plane axes for the boom's bulk)
    bulk = 0.01 * (s.luff**2 + s.foot**2)
    i_s = ms / 18.0 * np.diag([s.luff**2 + bulk, s.luff**2 + s.foot**2, s.foot**2 + bulk])
    r = p.rudder
    mr = r.mass
    cr = np.array([r.x, 0.0, r.z])
    t = r.thickness_ratio * r.chord  # a solid blade: span x chord x thickness box
    i_r = mr / 12.0 * np.diag([r.span**2 + t**2, r.span**2 + r.chord**2, r.chord**2 + t**2])
    return (ms, cs, i_s), (mr, cr, i_r)


def _shift(inertia, mass, d):
    """Parallel-axis term: inertia of a body about a point ``d`` away from its CG."""
    d = np.asarray(d, dtype=float)
    return inertia + mass * ((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * np.eye(3) - np.outer(d, d))


def hull_inertial(p: BoatParams):
    """(mass, CG, full inertia) of the hull body so that hull + rudder + boom matches ``p``.

    The papers give the whole boat's mass and inertia about its CG; the turning parts are
    subtracted (parallel-axis theorem) so the composite rigid body is exactly the paper's.

    Parameters
    ----------
    p : BoatParams
        The boat.

    Returns
    -------
    tuple
        Mass (kg), CG (3,) in the body frame (m), inertia (3, 3) about that CG (kg m^2).
    """
    (ms, cs, i_s), (mr, cr, i_r) = rig_inertia(p)
    m = p.mass
    c = np.array([p.cg_x, 0.0, p.cg_z])
    ixx, iyy, izz = p.inertia
    total = np.array([[ixx, 0.0, p.inertia_xz], [0.0, iyy, 0.0], [p.inertia_xz, 0.0, izz]])
    mh = m - ms - mr
    ch = (m * c - ms * cs - mr * cr) / mh
    ih = total - _shift(i_s, ms, cs - c) - _shift(i_r, mr, cr - c)
    ih = _shift(ih, -mh, ch - c)
    eig = np.linalg.eigvalsh(ih)
    if mh <= 0 or eig.min() <= 0 or 2 * eig.max() > eig.sum() + 1e-9:
        raise ValueError(f"{p.name}: the rig is too heavy for the given total mass/inertia")
    return mh, ch, ih


def hull_mesh(p: BoatParams, n_stations: int = 25, n_section: int = 12):
    """Vertices and faces of the hull: half-ellipse sections, straight topsides flared out to
    the deck edge at k b(x) (vertical when k = 1), flat deck.

    Parameters
    ----------
    p : BoatParams
        The boat.
    n_stations : int
        Sections along the hull.
    n_section : int
        Points on each section's half-ellipse.

    Returns
    -------
    tuple of ndarray
        Flat vertices (m) and faces (vertex indices, wound outward).
    """
    h = p.hull
    xs = np.linspace(-0.5 * h.length, 0.5 * h.length, n_stations)
    verts, rings = [], []
    theta = np.linspace(-0.5 * np.pi, 0.5 * np.pi, n_section)
    for x in xs:
        f = max(h.fullness(x), 0.03)
        b, t = h.half_beam * f, h.canoe_draft * f
        ring = [(x, -h.flare * b, h.freeboard)]
        ring += [(x, b * math.sin(th), -t * math.cos(th)) for th in theta]
        ring += [(x, h.flare * b, h.freeboard)]
        rings.append(list(range(len(verts), len(verts) + len(ring))))
        verts += ring
    # wound outward (positive signed volume), so back-face culling shows the outside; the
    # ring wraps from the port deck edge to the starboard one, which closes the deck
    faces = []
    for a, b in zip(rings[:-1], rings[1:], strict=True):
        k = len(a)
        for i in range(k):
            j = (i + 1) % k
            faces += [(a[i], b[j], b[i]), (a[i], a[j], b[j])]
    for ring, flip in ((rings[0], True), (rings[-1], False)):
        for i in range(1, len(ring) - 1):
            tri = (ring[0], ring[i], ring[i + 1])
            faces.append(tri[::-1] if flip else tri)
    return np.array(verts, dtype=float).ravel(), np.array(faces, dtype=int).ravel()


def sheet_geometry(p: BoatParams):
    """(block, boom_end) positions: the sheet block on the hull, the boom end on the boom.

    The block sits on the centreline below the boom end's position at lambda = 0, so the sheet
    length is L(lambda) = sqrt((2 l sin(lambda/2))^2 + dz^2) with l the boom length: it grows
    monotonically with |lambda| up to 180 deg.

    Parameters
    ----------
    p : BoatParams
        The boat.

    Returns
    -------
    tuple of ndarray
        The block in the hull frame and the boom end in the boom frame, (3,) each (m).
    """
    s = p.sail
    boom = s.foot
    block = np.array([s.mast_x - boom, 0.0, max(s.boom_height - 0.15 * boom, 0.5 * p.hull.freeboard)])
    boom_end = np.array([-boom, 0.0, 0.0])  # in the boom body frame
    return block, boom_end


def sheet_length(p: BoatParams, angle):
    """Sheet length (m) that lets the boom out to ``angle`` (rad).

    Parameters
    ----------
    p : BoatParams
        The boat.
    angle : float or array_like
        Boom angle (rad).
    """
    block, end = sheet_geometry(p)
    dz = p.sail.boom_height - block[2]
    sine = elementwise(math.sin, 0.5 * np.asarray(angle))[()]  # the C library's: numpy's varies by CPU
    return np.sqrt((2.0 * p.sail.foot * sine) ** 2 + dz**2)


def sheet_angle(p: BoatParams, length):
    """Largest boom angle (rad) a sheet of ``length`` allows (inverse of :func:`sheet_length`).

    Parameters
    ----------
    p : BoatParams
        The boat.
    length : float or array_like
        Sheet length (m).
    """
    block, _ = sheet_geometry(p)
    dz = p.sail.boom_height - block[2]
    horizontal = np.sqrt(np.maximum(np.asarray(length) ** 2 - dz**2, 0.0))
    return 2.0 * elementwise(math.asin, np.clip(horizontal / (2.0 * p.sail.foot), 0.0, 1.0))[()]
