"""Force models: pure functions of a state snapshot and parameters, returning wrenches.

No MuJoCo inside. Body-frame wrenches are (Fx, Fy, Fz, Mx, My, Mz) in the FLU body frame,
moments about CO (see :mod:`sailmujoco.frames`).

======================  ===========================================================
module                  what it computes
======================  ===========================================================
``foil``                keel, rudder and sail lift/drag (Wille eqs. 21-36, Saoud C_N)
``hydrostatics``        buoyancy and restoring: ``paper`` (eq. 20) or ``geometric``
``damping``             hull damping: linear (eq. 13), ITTC surge (15-16), cross-flow
                        (17-18), roll (19)
``added_mass``          the C_A(nu_r) nu_r terms with the Munk moment (eqs. 8-11); the
                        added-mass inertia itself is solved inside the MuJoCo step
``wind``                mean log profile, NORSOK gusts, direction wander, current
======================  ===========================================================
"""
