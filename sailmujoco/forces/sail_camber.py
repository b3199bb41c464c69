"""A cambered sail: the lift its camber adds to the flat sail's force (``Sail.camber`` > 0).

Thin-aerofoil theory splits a thin section's load into that of its incidence (the flat plate,
:func:`sailmujoco.forces.sail.sail_force`) and that of its camber line; a parabolic camber line of
camber ratio f (depth over chord) adds C_L = 2 pi 2 f at every incidence, with its zero-lift angle
at -2 f, and at the ideal incidence its flow enters the luff smoothly, so that lift stands normal
to the flow (Abbott & von Doenhoff, *Theory of Wing Sections*, 1959, §4.3). On a wing of finite
aspect ratio the slope 2 pi becomes the finite wing's a (Helmbold, as the flat sail's), so the
camber adds C_L,f = 2 a f, normal to the in-plane flow, on the side the incidence loads.

Choices of ours, each a guess that the 11:Metre's polar against ORC's tests (the `real_boats`
study): a soft sail holds its camber only when filled, so the camber's lift grows with |alpha| up
to |alpha| = 2 f and is full beyond; it fades out linearly between the suction-stall angle and
twice it, where the flow has left the leeward side; the rig's lift coefficient (flat part and
camber together) is held at :data:`MAX_LIFT`, the peak of the IMS/ORC rig coefficients (a main
1.43, a jib 1.50: Hazen 1980, as ORC's VPP documentation tabulates them). ``camber`` 0 adds
nothing: the flat sail, the papers' form, bit for bit.
"""

from __future__ import annotations

from ..jit.kernel import kernel

MAX_LIFT = 1.5  # -, the rig's largest lift coefficient (Hazen 1980 / ORC VPP tables: 1.43-1.50)


@kernel
def camber_filled(alpha, camber, stall):
    """The share of its camber a sail at incidence ``alpha`` holds, 0 to 1 (module docstring).

    Parameters
    ----------
    alpha : float
        Angle of attack, rad.
    camber : float
        Camber ratio f, -.
    stall : float
        The suction-stall angle, rad.
    """
    size = abs(alpha)
    filled = min(size / (2.0 * camber), 1.0)
    if size <= stall:
        return filled
    return filled * max(0.0, 2.0 - size / stall)


@kernel
def add_camber_lift(flow, chord, normal, alpha, speed, camber, slope, stall, rho_air, area, out):
    """Add the camber's lift to a sail's force ``out`` (from :func:`sailmujoco.forces.sail.sail_force`).

    Parameters
    ----------
    flow : numpy.ndarray, shape (3,)
        The air's velocity relative to the sail at its centre of effort, m/s.
    chord, normal : numpy.ndarray, shape (3,)
        The sail's chord and normal axes, as ``sail_force`` left them.
    alpha, speed : float
        Its angle of attack (rad) and in-plane air speed (m/s), as ``sail_force`` returned them.
    camber, slope, stall : float
        Camber ratio f (-), the finite wing's lift slope a (1/rad), the suction-stall angle (rad).
    rho_air, area : float
        Air density (kg/m^3) and sail area (m^2).
    out : numpy.ndarray, shape (3,)
        The sail's force, N; gains the camber's lift.
    """
    if camber <= 0.0 or speed <= 0.0:
        return
    w_c = flow[0] * chord[0] + flow[1] * chord[1] + flow[2] * chord[2]
    w_n = flow[0] * normal[0] + flow[1] * normal[1] + flow[2] * normal[2]
    # in-plane unit normal to the flow, on the side the incidence loads (that of -sign(alpha) n)
    p_c, p_n = -w_n / speed, w_c / speed
    if p_n * (1.0 if alpha >= 0.0 else -1.0) > 0.0:
        p_c, p_n = -p_c, -p_n
    px = p_c * chord[0] + p_n * normal[0]
    py = p_c * chord[1] + p_n * normal[1]
    pz = p_c * chord[2] + p_n * normal[2]
    q_area = 0.5 * rho_air * speed * speed * area
    lift = 2.0 * slope * camber * camber_filled(alpha, camber, stall)
    flat = (out[0] * px + out[1] * py + out[2] * pz) / q_area  # the flat sail's lift coefficient
    lift = max(0.0, min(lift, MAX_LIFT - flat))
    out[0] += q_area * lift * px
    out[1] += q_area * lift * py
    out[2] += q_area * lift * pz
