"""Physical constants, SI units. Each paper's air density is named separately.

Boats carry their own densities in :mod:`sailmujoco.params`; these are the sources.
"""

GRAVITY = 9.81  # m/s^2, Saoud Table I and Wille (both use 9.81)
RHO_WATER = 1025.0  # kg/m^3, sea water, Wille (2016a) Appendix A
RHO_AIR_WILLE = 1.23  # kg/m^3, Wille (2016a) Appendix A
RHO_AIR_SAOUD = 1.225  # kg/m^3, Saoud et al. (2015) Table I
NU_WATER = 1.19e-6  # m^2/s, kinematic viscosity of sea water at 15 C (ITTC 2011)
NU_AIR = 1.48e-5  # m^2/s, kinematic viscosity of air at 15 C
KARMAN_K = 0.0026  # -, surface drag coefficient of the log wind profile, Wille (2016a) eq. 40
NORSOK_N = 0.468  # -, exponent of the NORSOK wind spectrum, Wille (2016a) eq. 37
