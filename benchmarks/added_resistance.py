"""Added resistance in regular head waves: sigma_aw against lambda/L at two Froude numbers,
measured on the 6-DOF boat, with the references beside it.

Run: python benchmarks/added_resistance.py [--boat wille_yacht] [--froude 0.2 0.3]
     [--ratios 0.5 0.75 ...] [--couplings impulse manoeuvring] [--out results/added_resistance]

Each point is :func:`sailmujoco.design.added_resistance.measure`: the boat (no sail, no windage)
held on its heading and at its mean speed by a thrust in regular head waves of steepness
k zeta_a = 0.03; sigma_aw = R_aw / (rho g zeta_a^2 B^2 / L). Beside it:

* STAwave-2 (ITTC 7.5-04-01-01.1), the empirical formula for ships
  (:func:`sailmujoco.design.wave_references.stawave2`), with the boat's L, B, canoe-body draft,
  C_B and pitch gyradius;
* Gerritsma and Beukelman's radiated energy
  (:func:`sailmujoco.design.wave_references.gerritsma_beukelman`) from the measured heave and
  pitch and the boat's own heave damping d33, shared along the hull as b(x)^2 (the strip
  added mass's distribution), and its strip added mass rho pi b^2 / 2: what the simulated
  motions radiate through the model's damping. The relative velocity is the section's
  vertical velocity less the water's, Smith-corrected to the section's mean depth, followed
  along the hull at the speed U (Salvesen, Tuck & Faltinsen 1970): i omega_e (z + x theta) -
  U theta - i omega eta(x) e^(-k T_m). The method holds where the motions carry the added
  resistance (lambda/L of about 0.8 and longer); in shorter waves it sums the incident wave's
  own orbital motion through the damping and overestimates, so the figure draws it from
  lambda/L 0.9 (the CSV keeps every point).

It writes ``added_resistance.csv`` (one row per point and coupling) and ``added_resistance.png``
into ``--out``, and prints each curve's peak against STAwave-2's.

``--irregular`` adds the yacht in a JONSWAP head sea (Hs 0.58 m, Tp 3.4 s: the sea its own
10 m/s wind raises over the assumption study's fetch), for ``--seeds`` realisations: R_aw held
at 1.5 m/s against STAwave-2's spectral mean R = 2 int sigma_aw(omega) rho g B^2/L S(omega)
d omega, and the speed lost at the calm water's thrust for 1.5 m/s.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

import numpy as np
from scipy.integrate import trapezoid

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.constants import GRAVITY
from sailmujoco.design.added_resistance import CONTROL_DT, K_ZETA, hold_heading, measure, tow
from sailmujoco.design.wave_references import gerritsma_beukelman, stawave2
from sailmujoco.forces.wave_spectra import spectrum_density
from sailmujoco.forces.wind import WindConfig
from sailmujoco.options import ForceSwitches, WaveConfig
from sailmujoco.physics import BoatPhysics

RATIOS = (0.5, 0.75, 0.9, 1.0, 1.1, 1.25, 1.4, 1.6, 1.8, 2.0, 2.5, 3.0)
GB_FROM = 0.9  # lambda/L from which the radiated-energy estimate is drawn (module docstring)


def hull_numbers(boat: str) -> dict:
    """L, B, T (canoe body), C_B and k_yy of a boat, for the references."""
    p = get_boat(boat)
    h = p.hull
    length, beam, draft = h.length, 2.0 * h.half_beam, h.canoe_draft
    return dict(length=length, beam=beam, draft=draft,
                block=p.displaced_volume / (length * beam * draft),
                gyradius=math.sqrt(p.inertia[1] / p.mass) / length)


def gb_sigma(boat: str, point) -> float:
    """The Gerritsma-Beukelman sigma_aw of one measured point (module docstring)."""
    p = get_boat(boat)
    h = p.hull
    x = point.stations
    b = h.half_beam * h.fullness(x)
    share = b**2 / np.sum(b**2 * (x[1] - x[0]))
    damping = p.linear_damping[2] * share  # N s/m per m
    slope = p.rho_water * math.pi * b * (-8.0 * h.half_beam * x / h.length**2)  # d(rho pi b^2/2)/dx
    k, omega_e = point.wavenumber, point.encounter_frequency
    mean_depth = math.pi / 4.0 * h.canoe_draft * h.fullness(x)  # half-ellipse: area / beam
    heave, pitch = point.motion
    speed = point.froude * math.sqrt(GRAVITY * h.length)
    # D/Dt = d/dt - U d/dx along the hull: the section's own rate i omega_e (z + x theta), the
    # pitch's forward-speed part - U theta, and the water's rate at a fixed point, i omega eta
    omega = omega_e - k * speed
    relative = np.abs(1j * omega_e * (heave + x * pitch) - speed * pitch
                      - 1j * omega * np.exp(-k * mean_depth) * point.water)
    r_aw = gerritsma_beukelman(x, relative, damping, slope, speed, k, omega_e)
    zeta = K_ZETA / k
    return r_aw / (p.rho_water * GRAVITY * zeta**2 * (2.0 * h.half_beam) ** 2 / h.length)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--boat", default="wille_yacht")
    parser.add_argument("--froude", type=float, nargs="+", default=[0.2, 0.3])
    parser.add_argument("--ratios", type=float, nargs="+", default=list(RATIOS))
    parser.add_argument("--couplings", nargs="+", default=["impulse", "manoeuvring"],
                        help="added_mass_coupling forms to measure (the first is drawn solid)")
    parser.add_argument("--reflection", choices=("on", "off", "both"), default="on",
                        help="the short-wave reflection term (wave_reflection)")
    parser.add_argument("--out", default="results/added_resistance")
    parser.add_argument("--irregular", action="store_true", help="also the JONSWAP head sea")
    parser.add_argument("--seeds", type=int, default=3, help="sea realisations of --irregular")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    hull = hull_numbers(args.boat)
    reflections = {"on": [True], "off": [False], "both": [True, False]}[args.reflection]
    rows = []
    for coupling in args.couplings:
        for reflection in reflections:
            forces = ForceSwitches(added_mass_coupling=coupling, wave_reflection=reflection)
            for fn in args.froude:
                calm = None
                for ratio in args.ratios:
                    point = measure(args.boat, ratio, fn, forces=forces, calm_resistance=calm)
                    calm = point.calm_resistance
                    speed = fn * math.sqrt(GRAVITY * hull["length"])
                    row = dict(coupling=coupling, reflection=reflection, froude=fn, ratio=ratio,
                               sigma_aw=point.sigma_aw, heave=point.heave, pitch=point.pitch,
                               speed=point.speed, gerritsma_beukelman=gb_sigma(args.boat, point),
                               stawave2=float(stawave2(**hull, speed=speed, wavelength_ratio=ratio)))
                    rows.append(row)
                    print(f"{coupling:12s} reflection {'on ' if reflection else 'off'} Fn {fn:.2f} "
                          f"lambda/L {ratio:4.2f}: sigma_aw {point.sigma_aw:6.2f} (GB "
                          f"{row['gerritsma_beukelman']:5.2f}, STAwave-2 {row['stawave2']:5.2f}), "
                          f"heave {point.heave:4.2f}, pitch {point.pitch:4.2f}", flush=True)
    with open(out / "added_resistance.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print()
    for coupling in args.couplings:
        for reflection in reflections:
            for fn in args.froude:
                curve = [r for r in rows if r["coupling"] == coupling and r["froude"] == fn
                         and r["reflection"] == reflection]
                top = max(curve, key=lambda r: r["sigma_aw"])
                speed = fn * math.sqrt(GRAVITY * hull["length"])
                fine = np.linspace(min(args.ratios), max(args.ratios), 400)
                ref = stawave2(**hull, speed=speed, wavelength_ratio=fine)
                print(f"{coupling} (reflection {'on' if reflection else 'off'}), Fn {fn:.2f}: peak "
                      f"{top['sigma_aw']:.2f} at lambda/L {top['ratio']:.2f}; STAwave-2 "
                      f"{ref.max():.2f} at {fine[ref.argmax()]:.2f}: ratio {top['sigma_aw'] / ref.max():.2f}")
    plot(rows, args, hull, out / "added_resistance.png")
    print(f"wrote {out / 'added_resistance.csv'} and {out / 'added_resistance.png'}")
    if args.irregular:
        irregular(args.boat, hull, args.seeds)
    return 0


IRREGULAR = dict(hs=0.58, tp=3.4, speed=1.5)  # m, s, m/s


def irregular(boat: str, hull: dict, seeds: int) -> None:
    """R_aw in a JONSWAP head sea at a held speed against STAwave-2, and the speed lost at the
    calm water's thrust (module docstring)."""
    calm = WindConfig(speed=0.0, gusts=False, wander=False)
    forces = ForceSwitches(sail=False, windage=False)
    speed = IRREGULAR["speed"]
    p = get_boat(boat)
    omega = np.linspace(0.3, 12.0, 4000)
    k = omega**2 / GRAVITY
    sea = WaveConfig(spectrum="jonswap", hs=IRREGULAR["hs"], tp=IRREGULAR["tp"], direction_from=math.pi / 2)
    sigma = stawave2(**hull, speed=speed, wavelength_ratio=2.0 * math.pi / k / hull["length"])
    reference = 2.0 * trapezoid(sigma * p.rho_water * GRAVITY * hull["beam"] ** 2 / hull["length"]
                                   * spectrum_density(sea, omega), omega)
    omega_p = 2.0 * math.pi / IRREGULAR["tp"]
    period = 2.0 * math.pi / (omega_p + omega_p**2 / GRAVITY * speed)  # the peak's encounter period
    thrust_calm = tow(BoatPhysics.load(boat, wind=calm, forces=forces), speed, 160.0, period, 60.0)[0]
    print(f"\nJONSWAP head sea Hs {IRREGULAR['hs']} m, Tp {IRREGULAR['tp']} s, {boat} (no sail): "
          f"calm thrust for {speed} m/s {thrust_calm:.1f} N; STAwave-2's R_aw {reference:.1f} N")
    for seed in range(seeds):
        waves = WaveConfig(spectrum="jonswap", hs=IRREGULAR["hs"], tp=IRREGULAR["tp"],
                           direction_from=math.pi / 2, seed=seed)
        held = tow(BoatPhysics.load(boat, wind=calm, forces=forces, waves=waves), speed, 600.0, period,
                   400.0)[0] - thrust_calm
        physics = BoatPhysics.load(boat, wind=calm, forces=forces, waves=waves)
        lost = coast(physics, thrust_calm, speed, 600.0)
        print(f"  seed {seed}: R_aw at {speed} m/s {held:6.1f} N ({held / reference:.2f} x STAwave-2); "
              f"at the calm thrust {lost:.3f} m/s ({100.0 * (1.0 - lost / speed):.1f} % lost)", flush=True)


def coast(physics, thrust: float, speed: float, seconds: float) -> float:
    """Mean speed over the last two thirds of ``seconds`` at a constant ``thrust``, heading held."""
    physics.place(yaw=0.0, surge=speed)
    physics.set_external_wrench([thrust, 0.0, 0.0, 0.0, 0.0, 0.0])
    steps = int(round(CONTROL_DT / physics.model.opt.timestep))
    n = int(round(seconds / CONTROL_DT))
    u = np.empty(n)
    for i in range(n):
        hold_heading(physics)
        physics.step(steps)
        u[i] = physics.surge_speed()
    return float(u[n // 3:].mean())


def plot(rows, args, hull, path) -> None:
    """sigma_aw against lambda/L, one panel per Froude number."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(args.froude), figsize=(5.2 * len(args.froude), 4.2),
                             layout="constrained", sharey=True, squeeze=False)
    fine = np.linspace(min(args.ratios), max(args.ratios), 400)
    styles = ["-o", "--s", ":^", "-.v"]
    for ax, fn in zip(axes[0], args.froude, strict=True):
        speed = fn * math.sqrt(GRAVITY * hull["length"])
        ax.plot(fine, stawave2(**hull, speed=speed, wavelength_ratio=fine), color="k", lw=1.5,
                label="STAwave-2 (ITTC, ships)")
        first = True
        for n, coupling in enumerate(args.couplings):
            for reflection in sorted({r["reflection"] for r in rows}, reverse=True):
                curve = [r for r in rows if r["coupling"] == coupling and r["froude"] == fn
                         and r["reflection"] == reflection]
                ratio = [r["ratio"] for r in curve]
                label = f"6-DOF, added mass {coupling}" + ("" if reflection else ", no reflection")
                ax.plot(ratio, [r["sigma_aw"] for r in curve], styles[n % len(styles)], ms=4,
                        label=label)
                if first:
                    valid = [r for r in curve if r["ratio"] >= GB_FROM]
                    ax.plot([r["ratio"] for r in valid], [r["gerritsma_beukelman"] for r in valid],
                            color="tab:gray", ls="--", lw=1,
                            label=f"Gerritsma-Beukelman from the {coupling} motions")
                    first = False
        ax.set_title(f"{args.boat}, head waves, Fn {fn:.2f}, k zeta_a {K_ZETA}")
        ax.set_xlabel("lambda / L")
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("sigma_aw = R_aw / (rho g zeta_a^2 B^2 / L)")
    axes[0][-1].legend(fontsize=8)
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
