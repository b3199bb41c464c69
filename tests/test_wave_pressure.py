"""The Froude-Krylov wave force on the hull's columns against closed forms.

Expected values come from integrating the linear wave pressure over simple bodies by hand
(box, vertical cylinder), from the long-wave limit (buoyancy tilted with the wave slope), and
from a Gauss-Legendre integration of the force density along each column, written here
independently of the kernel's closed forms. Linear theory holds to O(ka): the kernel cuts each
column at the local surface and stretches the pressure to it, so each tolerance is ka times the
force's scale (derived per test).
"""

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.special import j1

from sailmujoco import frames
from sailmujoco.boat import hull
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.constants import GRAVITY
from sailmujoco.forces.hydrostatics import geometric_buoyancy
from sailmujoco.forces.wave_pressure import froude_krylov

RHO = 1025.0  # kg/m^3
G = GRAVITY  # m/s^2


def box_columns(length, beam, draft, nx=4000, ny=4, top=2.0):
    """A box L x B x T on a midpoint grid, CO at the centre of its waterplane."""
    x = (np.arange(nx) + 0.5) / nx * length - length / 2
    y = (np.arange(ny) + 0.5) / ny * beam - beam / 2
    xx, yy = np.meshgrid(x, y, indexing="ij")
    area = np.full(xx.size, length * beam / (nx * ny))
    return np.ascontiguousarray(np.vstack([xx.ravel(), yy.ravel(), area,
                                           np.full(xx.size, -draft), np.full(xx.size, top)]))


def cylinder_columns(radius, draft, nr=40, ntheta=128, top=2.0):
    """A vertical cylinder: Gauss-Legendre in r, midpoint rule in the angle (periodic)."""
    xg, wg = np.polynomial.legendre.leggauss(nr)
    r, wr = 0.5 * radius * (xg + 1.0), 0.5 * radius * wg
    th = (np.arange(ntheta) + 0.5) * 2 * np.pi / ntheta
    rr, tt = np.meshgrid(r, th, indexing="ij")
    area = (wr[:, None] * r[:, None] * np.full((nr, ntheta), 2 * np.pi / ntheta)).ravel()
    return np.ascontiguousarray(np.vstack([(rr * np.cos(tt)).ravel(), (rr * np.sin(tt)).ravel(),
                                           area, np.full(area.size, -draft),
                                           np.full(area.size, top)]))


def regular_wave(k, a, direction=0.0, phase=0.0):
    """One deep-water component as the kernel's arrays: (a, omega, k, beta, phi)."""
    return (np.array([a]), np.array([math.sqrt(G * k)]), np.array([k]), np.array([direction]),
            np.array([phase]))


def wrench(columns, sea, time=0.0, pos=(0.0, 0.0, 0.0), rot=None):
    out = np.zeros(6)
    rot = np.eye(3) if rot is None else rot
    vol = froude_krylov(np.asarray(pos, float), rot, columns, *sea, time, RHO, G, out)
    return out, vol


def hull_columns(boat):
    return hull.column_quadrature(get_boat(boat).hull).array()


# --- box and cylinder: vertical force with the crest over the centre ---------------------------
@pytest.mark.parametrize("length_over_lambda", [0.1, 0.5, 0.8, 1.0, 1.3, 1.5])
def test_box_vertical_force_crest_over_centre(length_over_lambda):
    """Delta F_z = rho g a B integral_{-L/2}^{L/2} exp(-kT) cos(kx) dx
    = rho g a B L exp(-kT) sinc(kL/2), the dynamic pressure on the bottom (the sides' pressure
    is horizontal). It changes sign at L = lambda.

    The kernel evaluates the bottom pressure at the stretched depth -T - eta, a factor
    exp(-k eta) in [exp(-ka), exp(ka)], so it differs from the linear value by at most
    ka exp(ka) of the scale S = rho g a B L exp(-kT).
    """
    length, beam, draft = 2.0, 0.6, 0.4
    k = 2 * math.pi * length_over_lambda / length
    ka = 0.01
    a = ka / k
    out, vol = wrench(box_columns(length, beam, draft), regular_wave(k, a))
    still = RHO * G * length * beam * draft
    x = k * length / 2
    expected = RHO * G * a * beam * length * math.exp(-k * draft) * math.sin(x) / x
    scale = RHO * G * a * beam * length * math.exp(-k * draft)
    assert abs((out[2] - still) - expected) <= ka * math.exp(ka) * scale
    if abs(expected) > 2 * ka * scale:
        assert np.sign(out[2] - still) == np.sign(expected)
    assert abs(out[0]) < 1e-9 * scale and abs(out[4]) < 1e-9 * scale * length  # symmetric


@pytest.mark.parametrize("kr", [0.5, 2.0, 3.8317, 5.0])
def test_cylinder_vertical_force_crest_over_axis(kr):
    """Delta F_z = rho g a exp(-kT) integral_disc cos(k r cos(t)) r dr dt
    = rho g a pi R^2 exp(-kT) 2 J1(kR) / (kR); 3.8317 is J1's first zero. Tolerance as for the
    box: ka exp(ka) of rho g a pi R^2 exp(-kT)."""
    radius, draft = 1.0, 0.8
    k = kr / radius
    ka = 0.01
    a = ka / k
    out, _ = wrench(cylinder_columns(radius, draft), regular_wave(k, a))
    still = RHO * G * math.pi * radius ** 2 * draft
    scale = RHO * G * a * math.pi * radius ** 2 * math.exp(-k * draft)
    expected = scale * 2 * j1(kr) / kr
    assert abs((out[2] - still) - expected) <= ka * math.exp(ka) * scale
    assert abs(out[0]) < 1e-9 * scale and abs(out[1]) < 1e-9 * scale


# --- box: horizontal force with a node over the centre -----------------------------------------
def box_horizontal_closed_form(k, a, length, beam, draft):
    """-integral_V dp_d/dx dV at omega t = pi/2 (eta = a sin(kx), node over the centre):
    -dp_d/dx = rho g a k exp(kz) sin(kx - pi/2) = -rho g a k exp(kz) cos(kx), so
    F_x = -rho g a k B [(1 - exp(-kT)) / k] [2 sin(kL/2) / k]
        = -rho g a B (1 - exp(-kT)) (2/k) sin(kL/2).
    Negative: the surface rises toward +x at the centre, the higher water pushes toward -x."""
    return -RHO * G * a * beam * (1 - math.exp(-k * draft)) * 2 / k * math.sin(k * length / 2)


@pytest.mark.parametrize("length_over_lambda", [0.1, 0.5, 1.0, 1.5, 2.0])
def test_box_horizontal_force_node_over_centre(length_over_lambda):
    """Against the closed form above. The kernel's wet length T + eta differs from T at first
    order in a/T, but eta = a sin(kx) is odd and the pressure gradient even in x, so that part
    cancels over the box; what is left (stretching, the a^2 terms) is below ka of the scale
    S = rho g a B L (1 - exp(-kT)) when a < T."""
    length, beam, draft = 2.0, 0.6, 0.4
    k = 2 * math.pi * length_over_lambda / length
    ka = 0.01
    a = ka / k
    assert a < draft
    sea = regular_wave(k, a)
    out, _ = wrench(box_columns(length, beam, draft), sea, time=math.pi / 2 / sea[1][0])
    expected = box_horizontal_closed_form(k, a, length, beam, draft)
    scale = RHO * G * a * beam * length * (1 - math.exp(-k * draft))
    assert abs(out[0] - expected) <= ka * scale
    assert abs(out[1]) < 1e-9 * scale


@pytest.mark.parametrize("kl", [0.02, 0.005])
def test_long_wave_limit_tilts_the_buoyancy_with_the_slope(kl):
    """For kL, kT -> 0: F_x -> -rho g V k a, the buoyancy rho g V tilted by the slope
    d eta/dx = k a (what rolls a boat with the wave). The closed form differs from the limit by
    the factors (1 - exp(-kT)) / (kT) >= 1 - kT/2 and sinc(kL/2) >= 1 - (kL)^2/24, so the
    relative error is at most kT/2 + (kL)^2/24, and it vanishes with k."""
    length, beam, draft = 2.0, 0.6, 0.4
    k = kl / length
    a = 0.001  # m: ka, a/T << 1
    sea = regular_wave(k, a)
    out, vol = wrench(box_columns(length, beam, draft, nx=200), sea,
                      time=math.pi / 2 / sea[1][0])
    limit = -RHO * G * length * beam * draft * k * a
    bound = k * draft / 2 + kl ** 2 / 24
    assert abs(out[0] / limit - 1) <= bound
    # the wave force is the buoyancy tilted: F_x / F_z -> -slope
    assert abs(out[0] / out[2] / (-k * a) - 1) <= bound + 2 * a / draft


# --- one column: the wet length follows the local surface ----------------------------------------
def test_column_submerged_under_crest_and_emerging_at_trough():
    """A column from z = -1 to 0.2 (area 0.1) in a wave a = 0.5: under the crest it is wholly
    wet (the deck at 0.2 is below eta = 0.5) and F_z = A (p(-1) - p(0.2)); at the trough
    (eta = -0.5) it is wet to -0.5 and F_z = A p(-1), with p(z) = -rho g z + rho g a
    exp(k (z - eta)) cos(theta)."""
    area, zb, zt, a, k = 0.1, -1.0, 0.2, 0.5, 0.3
    col = np.array([[0.0], [0.0], [area], [zb], [zt]])
    sea = regular_wave(k, a)

    def p(z, eta, cos_theta):
        return -RHO * G * z + RHO * G * a * math.exp(k * (z - eta)) * cos_theta

    crest, vol = wrench(col, sea)
    assert vol == pytest.approx(area * (zt - zb), rel=1e-14)
    assert crest[2] == pytest.approx(area * (p(zb, a, 1.0) - p(zt, a, 1.0)), rel=1e-12)
    trough, vol = wrench(col, sea, time=math.pi / sea[1][0])
    assert vol == pytest.approx(area * (-a - zb), rel=1e-12)
    assert trough[2] == pytest.approx(area * p(zb, -a, -1.0), rel=1e-12)
    assert abs(crest[0]) < 1e-9 * crest[2] and abs(trough[0]) < 1e-9 * trough[2]


# --- random sea, tilted hull: the kernel's closed forms against quadrature along each column --
def random_sea(rng, m=5, scale=0.3):
    omega = rng.uniform(0.6, 2.5, m)
    return (rng.uniform(0.2, 1.0, m) * scale, omega, omega ** 2 / G, rng.uniform(-np.pi, np.pi, m),
            rng.uniform(-np.pi, np.pi, m))


def quadrature_wrench(pos, rot, columns, sea, time, nodes=60):
    """World force and moment about CO: buoyancy of each column wet to the local surface plus
    the linearised -grad p_d integrated along its axis by Gauss-Legendre (``nodes`` points)."""
    a, omega, k, beta, phi = sea
    xg, wg = np.polynomial.legendre.leggauss(nodes)
    force, moment = np.zeros(3), np.zeros(3)
    for x, y, area, zb, zt in columns.T:
        axis = rot @ np.array([x, y, 0.0])  # the column's point on the body plane z = 0
        theta = k * ((pos[0] + axis[0]) * np.cos(beta) + (pos[1] + axis[1]) * np.sin(beta)) \
            - omega * time + phi
        eta = np.sum(a * np.cos(theta))
        h = pos[2] + axis[2]
        zw = (eta - h) / rot[2, 2]  # the hull stays upright enough here: rot[2, 2] > 0
        lo, hi = zb, min(zt, zw)
        if hi <= lo:
            continue
        zeta = 0.5 * (hi - lo) * xg + 0.5 * (hi + lo)
        w = 0.5 * (hi - lo) * wg
        points = axis[:, None] + rot[:, 2:3] * zeta[None, :]  # world offsets from CO
        zs = h + rot[2, 2] * zeta - eta
        direction = np.array([np.cos(beta) * np.sin(theta), np.sin(beta) * np.sin(theta),
                              -np.cos(theta)])  # (3, m)
        strength = a[:, None] * k[:, None] * np.exp(k[:, None] * zs[None, :])  # (m, nodes)
        density = RHO * G * direction @ strength  # (3, nodes), N/m^3
        density[2] += RHO * G  # the hydrostatic part, rho g e_z
        f = area * density * w[None, :]
        force += f.sum(axis=1)
        moment += np.cross(points.T, f.T).sum(axis=0)
    return force, moment


def test_random_poses_match_quadrature_along_the_columns():
    """Wille's hull, heeled, trimmed and heaved in a five-component sea: the kernel's closed
    forms (exp integrals, their centroids, the frames) against Gauss-Legendre quadrature of
    the force density along each tilted column, to 1e-9 of the buoyancy."""
    rng = np.random.default_rng(7)
    columns = hull_columns("wille_yacht")
    weight = RHO * G * get_boat("wille_yacht").displaced_volume
    for _ in range(6):
        rot = frames.matrix_from_euler(rng.uniform(-0.6, 0.6), rng.uniform(-0.2, 0.2),
                                       rng.uniform(-np.pi, np.pi))
        pos = rng.normal(size=3) * [20.0, 20.0, 0.2]
        sea = random_sea(rng)
        time = rng.uniform(0.0, 100.0)
        out, _ = wrench(columns, sea, time, pos, rot)
        force, moment = quadrature_wrench(pos, rot, columns, sea, time)
        assert np.max(np.abs(rot @ out[:3] - force)) < 1e-9 * weight
        assert np.max(np.abs(rot @ out[3:] - moment)) < 1e-9 * weight * 10.0


# --- calm water is today's buoyancy, bit for bit -----------------------------------------------
def calm_matches(seed=3, n=20):
    """For random poses of every boat, whether the kernel with every amplitude zero (three
    components, and no component at all) returns exactly geometric_buoyancy's wrench and
    volume."""
    rng = np.random.default_rng(seed)
    same = []
    for boat in ("wille_yacht", "saoud_robot", "viel_boat"):
        columns = hull_columns(boat)
        draft = get_boat(boat).hull.canoe_draft
        for _ in range(n):
            rot = frames.matrix_from_euler(*rng.uniform(-math.pi, math.pi, 3))
            pos = rng.normal(size=3) * [30.0, 30.0, draft]
            reference = np.zeros(6)
            vol = geometric_buoyancy(pos[2], rot, columns, RHO, G, reference)
            for sea in (random_sea(rng, 3, 0.0), random_sea(rng, 0)):
                out, wet = wrench(columns, sea, rng.uniform(0, 50), pos, rot)
                same.append(bool(np.array_equal(out, reference) and wet == vol))
    return same


def test_calm_water_is_geometric_buoyancy_exactly():
    """np.array_equal, not a tolerance: with every amplitude zero the surface is eta = 0 and the
    kernel cuts each column with the same operations in the same order as geometric_buoyancy;
    the wave terms it adds are exact zeros, which leave every float unchanged."""
    same = calm_matches()
    assert len(same) == 120 and all(same)


# --- the compiled kernel and the interpreted source agree ----------------------------------------
def evaluate(seed=11):
    """Wave wrenches for random poses and seas (compiled or interpreted, by NUMBA_DISABLE_JIT),
    and the calm-water bit-identity flags of that path."""
    rng = np.random.default_rng(seed)
    columns = hull_columns("viel_boat")
    rows = []
    for _ in range(20):
        rot = frames.matrix_from_euler(*rng.uniform(-1.0, 1.0, 3))
        pos = rng.normal(size=3) * [20.0, 20.0, 0.1]
        out, vol = wrench(columns, random_sea(rng, 6, 0.2), rng.uniform(0, 60), pos, rot)
        rows.append([*out, vol])
    return {"rows": rows, "calm": calm_matches(n=4)}


def test_compiled_equals_interpreted(tmp_path):
    fast = evaluate()
    script = (f"import json, sys; sys.path.insert(0, {str(Path(__file__).parent)!r});"
              f"from test_wave_pressure import evaluate;"
              f"json.dump(evaluate(), open({str(tmp_path / 'r.json')!r}, 'w'))")
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    subprocess.run([sys.executable, "-c", script], check=True, env=env, timeout=600, cwd=tmp_path)
    reference = json.loads((tmp_path / "r.json").read_text())
    a, b = np.array(fast["rows"]), np.array(reference["rows"])
    assert np.max(np.abs(a - b) / np.maximum(1.0, np.abs(b))) < 1e-10
    assert np.ptp(a[:, 0]) > 0.0  # the poses were not all alike
    assert all(reference["calm"]) and all(fast["calm"])
