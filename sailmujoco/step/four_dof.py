"""The 4-DOF boat's stage: the hull held at heave and pitch, moving in x, y, yaw and roll.

A part of :class:`sailmujoco.physics.BoatPhysics` (a mixin, in a module of its own): the force
kernel sees the hull as if free (a pseudo free-joint qpos/qvel), and the forces and added mass
it gives are mapped back onto MuJoCo's x, y, yaw and roll joints. With geometric hydrostatics
the held pose would over-displace the heeled hull, so the hydrostatics come from the freely
floating hull at the current heel (:class:`sailmujoco.forces.stability.FloatingTable`).

The compiled stage is :func:`sailmujoco.step.native.forces_4dof`; the methods here are its Python
reference (``BoatPhysics.compiled_loop`` False), the same operations in Python and numpy.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ..boat.params import BoatParams
from ..forces import boat as kernels
from ..forces import stability
from ..forces.boat_parameters import HYDROSTATIC_MODES, P_G, P_HYDRO_MODE, P_K_HEAVE
from ..jit.kernel import entry_point
from ..jit.ordered import mat_mat, mat_t_vec, mat_vec
from . import native, registry

# the compiled 4-DOF stage, called past numba's type dispatch (one signature)
FORCES_4DOF = entry_point(native.forces_4dof)


@functools.lru_cache(maxsize=8)
def floating_table(params: BoatParams) -> stability.FloatingTable:
    """The floating table of a boat, built once per process (about 0.25 s).

    Parameters
    ----------
    params : BoatParams
        The boat.

    Returns
    -------
    stability.FloatingTable
        Heave, trim, volume and righting moment of the freely floating hull against heel.
    """
    return stability.floating_table(params)


def csr_address(m, i: int, j: int) -> int:
    """Address of entry (i, j), j <= i, of MuJoCo's sparse lower-triangular mass matrix.

    Parameters
    ----------
    m : mujoco.MjModel
        The compiled model.
    i, j : int
        Row and column (dof indices), ``j <= i``.

    Returns
    -------
    int
        The entry's index in ``MjData.M``.
    """
    row = m.M_rowadr[i]
    cols = m.M_colind[row:row + m.M_rownnz[i]]
    return int(row + np.nonzero(cols == j)[0][0])


class FourDofStage:
    """The 4-DOF part of :class:`~sailmujoco.physics.BoatPhysics` (see the module docstring)."""

    def _setup_4dof(self, params, forces, m) -> None:
        """The pseudo free-joint arrays, the joint map and the hydrostatics of the 4-DOF boat."""
        self._csr_addr = np.zeros(9, dtype=np.int64)
        self._csr4 = [(i, j, csr_address(m, i, j)) for i in range(4) for j in range(i + 1)]
        self._q7 = np.zeros(9)
        self._q7[3] = 1.0
        self._v6 = np.zeros(8)
        self._qfrc8 = np.zeros(8)
        self._kidx = np.array([7, 6, 8, 7], dtype=np.int64)
        self._a_diag = params.added_mass_diagonal if forces.added_mass else np.zeros(6)
        self._floating = None
        if forces.hydrostatics == "geometric":
            # the held pose (heave 0, trim 0) over-displaces the heeled hull; the 4-DOF
            # boat floats at every heel: its hydrostatics come from the freely floating
            # hull at the current heel (stability.FloatingTable), added in _forces_4dof
            self._floating = floating_table(params)
            self._P[P_HYDRO_MODE] = HYDROSTATIC_MODES.index("off")
        elif forces.hydrostatics == "paper":
            # the joints hold CO's height, not the CG's: heeled, a CG off the waterline
            # moves by z_G (cos(phi) - 1) and the heave spring, acting through the CG, would
            # add a roll moment k_z z_G^2 (1 - cos(phi)) sin(phi) (+26 % of eq. 4 at 10 deg
            # on the robot with l_phi = 1 m, 3.3x at 30 deg). The reduced models hold the
            # CG's height: buoyancy = weight through the CG, eq. 20 / eq. 4 alone.
            self._P[P_K_HEAVE] = 0.0

    def _four_dof_row(self, d) -> np.ndarray:
        """The registry row of the 4-DOF stage: MuJoCo's arrays and the stage's own."""
        table = self._floating
        self._bound_4dof = (  # held: the registry row holds only their addresses
            np.ascontiguousarray(self._a_diag, dtype=float),
            np.array(self._csr4, dtype=np.int64).reshape(-1, 3),
            np.array([self.params.mass, self.params.cg_x, self.params.cg_z], dtype=float),
            np.zeros(0) if table is None else np.ascontiguousarray(table.heel, dtype=float),
            np.zeros(0) if table is None else np.ascontiguousarray(table.righting, dtype=float))
        return registry.registry_row(self._args, d.act, self._warnings,
                                   (d.qpos, d.qvel, d.qfrc_applied), self._bound_4dof)

    def _fill_pseudo(self) -> np.ndarray:
        """4-DOF model: the hull's pose and velocity in free-joint layout; returns R."""
        d = self.data.ptr
        x, y, yaw, roll = d.qpos[0:4]
        xd, yd, yawd, rolld = d.qvel[0:4]
        cy, sy, cr, sr = math.cos(yaw), math.sin(yaw), math.cos(roll), math.sin(roll)
        rot = np.array([[cy, -sy * cr, sy * sr], [sy, cy * cr, -cy * sr], [0.0, sr, cr]])
        q7, v6 = self._q7, self._v6
        q7[0], q7[1], q7[2] = x, y, 0.0
        # quaternion of Rz(yaw) Rx(roll)
        q7[3:7] = (math.cos(yaw / 2) * math.cos(roll / 2), math.cos(yaw / 2) * math.sin(roll / 2),
                   math.sin(yaw / 2) * math.sin(roll / 2), math.sin(yaw / 2) * math.cos(roll / 2))
        q7[7], q7[8] = d.qpos[4], d.qpos[5]
        v6[0], v6[1], v6[2] = xd, yd, 0.0
        v6[3:6] = mat_t_vec(rot, np.array([0.0, 0.0, yawd])) + np.array([rolld, 0.0, 0.0])
        v6[6], v6[7] = d.qvel[4], d.qvel[5]
        return rot

    def _floating_hydrostatics(self, rot) -> None:
        """4-DOF geometric mode: the hydrostatic wrench of the hull floating freely at this heel.

        Buoyancy equal to the weight, vertical through the CG, plus the righting moment of the
        hull at the heave and trim that float it (quasi-static), about the horizontal heading
        axis, which in 4 DOF is body x. Added to the term and to the pseudo free-joint forces.
        """
        table, p = self._floating, self.params
        heel = float(self.data.ptr.qpos[3])
        righting = float(np.interp(heel, table.heel, table.righting))
        force_b = p.mass * self._P[P_G] * rot[2, :]  # the weight, world vertical, body axes
        # (cg_x, 0, cg_z) x force_b, the products and differences np.cross forms (bit for bit;
        # np.cross itself costs 10 us, a third of this stage)
        (fx, fy, fz), cx, cz = force_b, p.cg_x, p.cg_z
        wrench = np.array([fx, fy, fz, 0.0 * fz - cz * fy, cz * fx - cx * fz, cx * fy - 0.0 * fx])
        wrench[3] -= righting
        self._terms[kernels.T_HYDRO] = wrench
        self._qfrc8[0:3] += mat_vec(rot, force_b)
        self._qfrc8[3:6] += wrench[3:]

    def _forces_4dof(self, add_mass: bool) -> int:
        """Forces (and added mass) of the heave-and-pitch-held model on its x, y, yaw, roll joints:
        compiled (native.forces_4dof), or with ``compiled_loop`` False the Python reference."""
        if not self.compiled_loop:
            return self._forces_4dof_python(add_mass)
        return FORCES_4DOF(self.data.ptr.time, self._row, add_mass)

    def _forces_4dof_python(self, add_mass: bool) -> int:
        """The reference of native.forces_4dof: the same operations in Python and numpy."""
        d = self.data.ptr
        rot = self._fill_pseudo()
        status = self._kernel(d.time, *self._args, False)
        if status != kernels.STATUS_OK:
            return status
        if self._floating is not None:
            self._floating_hydrostatics(rot)
        f = self._qfrc8
        torque_world = mat_vec(rot, f[3:6])
        qfrc = d.qfrc_applied
        qfrc[0], qfrc[1], qfrc[2], qfrc[3] = f[0], f[1], torque_world[2], f[3]
        qfrc[4], qfrc[5] = f[6], f[7]
        a = self._a_diag
        if a[4] != a[5]:
            # the rotational added-mass rate term the pseudo free-joint kernel cannot see: with
            # omega_b = (roll_dot, sin(phi) yaw_dot, cos(phi) yaw_dot), d(omega_b)/dt has the
            # part (0, cos(phi), -sin(phi)) roll_dot yaw_dot beyond J q_ddot; -A2 times it, on
            # the yaw joint: (a66 - a55) sin(phi) cos(phi) roll_dot yaw_dot (Lagrange's equation
            # of T = 1/2 omega^T A2 omega gives the same; nothing on the roll joint).
            heel = d.qpos[3]
            qfrc[2] += (a[5] - a[4]) * math.sin(heel) * math.cos(heel) * d.qvel[3] * d.qvel[2]
        if add_mass:
            # J maps (xd, yd, yawd, rolld) to the body velocity (u, v, w, p, q, r) at CO
            jac = np.zeros((6, 4))
            jac[0:3, 0:2] = rot.T[:, 0:2]
            jac[3:6, 2] = rot.T[:, 2]
            jac[3, 3] = 1.0
            added = mat_mat(jac.T, self._a_diag[:, None] * jac)
            for i, j, a in self._csr4:
                d.M[a] += added[i, j]
        return status
