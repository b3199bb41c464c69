"""Jaulin and Le Bars' line following with tacking: the law most robotic sailboats descend from.

L. Jaulin, F. Le Bars, "An interval approach for stability analysis: application to sailboat
robotics", IEEE Trans. Robotics 29(1), 2013; the same law as "A simple controller for line
following of sailboats" (Jaulin, Le Bars, IRSC 2012) and on VAIMOS (Le Bars, Jaulin, WRSC 2012).
The T-RO text itself could not be read here: the steps below are numbered as the IRSC 2012
listing is numbered in the implementations that cite it step by step, and the law's form was
checked against Le Bars' own VAIMOS software (ENSTA Bretagne's UxVCtrl). Its frame is Jaulin's:
x east, y north, angles counter-clockwise from east, and psi the direction the wind blows *to*.

Inputs: the boat's position m, its heading theta, the wind's direction psi, the line from a to
b; state: the tack q in {-1, 1}. Parameters: the cut-off distance r, the close-hauled angle zeta
(half the no-go cone, from the wind's eye), the incidence angle gamma_inf (the angle at which a
boat far from the line heads back to it), the largest rudder angle and the sail's beta.

1. e = det((b - a)/|b - a|, m - a)                   (signed distance, > 0 left of a -> b)
2. if |e| > r/2: q = sign(e)                          (the hysteresis: the tack keeps until then)
3. phi = angle(b - a)
4. theta* = phi - (2 gamma_inf / pi) atan(e / r)     (the heading that brings the boat to the line)
5. if cos(psi - theta*) + cos(zeta) < 0               (theta* lies in the no-go cone)
6.    or (|e| < r and cos(psi - phi) + cos(zeta) < 0) (or the line does, and the boat is near it)
7.    then theta_bar = pi + psi - q zeta              (close-hauled on tack q)
8.    else theta_bar = theta*
9. (end if)
10-11. the rudder from theta - theta_bar: here delta_r = (delta_r_max / pi) sawtooth(theta -
   theta_bar), sawtooth(x) = 2 atan(tan(x / 2)) in (-pi, pi], Jaulin's book form (the IRSC
   listing's sin/sign rudder differs only in its gain); a positive delta_r turns the boat
   clockwise in Jaulin's model, so the package's rudder (positive: to port) is -delta_r.
12. delta_s_max = (pi/2) ((cos(psi - theta_bar) + 1) / 2) ** (log(pi / (2 beta)) / log 2)
   (the sheet's length as an angle: beta abeam, pi/2 before the wind, 0 head to wind); the
   package's sail angle is delta_s_max to leeward.

The defaults are IRSC 2012's as its citing implementations carry them (zeta = pi/3, gamma_inf =
pi/4, the tack's threshold r/2) with beta = pi/4 (the book's, for which step 12 reduces to the
IRSC listing's (pi/4)(cos + 1)); the cut-off r is the boat's to choose (the authors' runs used 5
to 50 m): 10 m here, about a hull length of the 11:Metre, two of Wille's yacht.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


def sawtooth(x: float) -> float:
    """``x`` wrapped to (-pi, pi]: 2 atan(tan(x/2)) without its poles."""
    wrapped = (x + math.pi) % (2.0 * math.pi) - math.pi
    return math.pi if wrapped == -math.pi else wrapped


@dataclass(frozen=True)
class LineFollowingGains:
    """The law's parameters (Jaulin and Le Bars' names).

    Parameters
    ----------
    r : float
        Cut-off distance, m: the corridor's half-width and the scale of the return to the line.
    zeta : float
        Close-hauled angle, rad: half the no-go cone, from the wind's eye.
    gamma_inf : float
        Incidence angle, rad: the heading's angle to the line far from it.
    delta_r_max : float
        The largest rudder angle, rad.
    beta : float
        The sail's angle with the wind abeam, rad.
    """

    r: float = 10.0
    zeta: float = math.pi / 3.0
    gamma_inf: float = math.pi / 4.0
    delta_r_max: float = math.radians(35.0)
    beta: float = math.pi / 4.0


def line_following(m, theta: float, psi: float, a, b, q: int,
                   gains: LineFollowingGains = LineFollowingGains()) -> tuple[float, float, float, int]:
    """One step of the law in Jaulin's frame (see the module docstring for the steps).

    Parameters
    ----------
    m : array_like, shape (2,)
        The boat's position (east, north), m.
    theta : float
        Its heading, rad counter-clockwise from east.
    psi : float
        The direction the wind blows to, rad counter-clockwise from east.
    a, b : array_like, shape (2,)
        The line, from a to b (east, north), m.
    q : int
        The tack kept so far, -1 or 1.
    gains : LineFollowingGains
        The parameters.

    Returns
    -------
    tuple
        (delta_r, delta_s_max, theta_bar, q): Jaulin's rudder (positive turns clockwise), the
        sheet's largest angle, the heading steered, the tack kept.
    """
    ux, uy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(ux, uy)
    e = (ux * (m[1] - a[1]) - uy * (m[0] - a[0])) / length  # 1
    if abs(e) > gains.r / 2.0:  # 2
        q = 1 if e > 0 else -1
    phi = math.atan2(uy, ux)  # 3
    theta_star = phi - 2.0 * gains.gamma_inf / math.pi * math.atan(e / gains.r)  # 4
    no_go = math.cos(gains.zeta)
    if (math.cos(psi - theta_star) + no_go < 0.0  # 5
            or (abs(e) < gains.r and math.cos(psi - phi) + no_go < 0.0)):  # 6
        theta_bar = math.pi + psi - q * gains.zeta  # 7
    else:
        theta_bar = theta_star  # 8
    delta_r = gains.delta_r_max / math.pi * sawtooth(theta - theta_bar)  # 10-11
    exponent = math.log(math.pi / (2.0 * gains.beta)) / math.log(2.0)
    delta_s_max = math.pi / 2.0 * ((math.cos(psi - theta_bar) + 1.0) / 2.0) ** exponent  # 12
    return delta_r, delta_s_max, theta_bar, q
