"""Force models: pure functions of a state snapshot and parameters, returning wrenches.

No MuJoCo inside. Body-frame wrenches are (Fx, Fy, Fz, Mx, My, Mz) in the FLU body frame,
moments about CO (see :mod:`sailmujoco.frames`).

======================  ===========================================================
module                  what it computes
======================  ===========================================================
``foil``                the foil conventions; every foil name below, importable from here
``foil_geometry``       the flow in a foil's section plane, lift and drag on its axes
                        (Wille eqs. 21-22)
``foil_sections``       the NACA 0015 section table, the keel's and rudder's C_L, C_D
                        (Wille eqs. 23-24)
``sail``                the sail's C_N (Saoud), C_T and force
``finite_wing``         finite-wing forms (``foils = "finite"``): Helmbold's slope,
                        Viterna & Corrigan post-stall, end plate, keel downwash
``hydrostatics``        buoyancy and restoring: ``paper`` (eq. 20) or ``geometric``
``damping``             hull damping: linear (eq. 13), ITTC surge (15-16), cross-flow
                        (17-18), roll (19)
``added_mass``          the C_A(nu_r) nu_r terms with the Munk moment (eqs. 8-11); the
                        added-mass inertia itself is solved inside the MuJoCo step
``wind``                the wind's configuration, NORSOK spectrum, log profile and its
                        seeded field (gust tables, wander series), current
``wind_kernels``        the compiled wind velocity at a time and height (eqs. 39-43)
``waves``               the sea state's configuration and its seeded field: elevation,
                        orbital velocity, dynamic pressure of deep-water Airy waves
                        (read by the 6-DOF boat's forces)
``wave_spectra``        Pierson-Moskowitz and JONSWAP spectra, cos-2s spreading, the
                        sea a wind raises (fully developed, fetch-limited)
``boat``                every force on the boat at one instant (one compiled kernel)
``boat_parameters``     the boat's parameters packed into the kernel's flat array
======================  ===========================================================
"""
