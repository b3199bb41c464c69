"""The named SI accessors of a MuJoCo boat, and its measurement for the task.

A part of :class:`sailmujoco.physics.BoatPhysics` (a mixin, in a module of its own): every
quantity a task, a controller or a study reads from the boat, in our frames (world x east,
y north, z up; body x forward, y port, z up) and SI units. They read the hull's state in
free-joint layout (``_free_state``, which also serves the 4-DOF boat), the force kernel's
outputs (``_terms``, ``_diag``) after bringing them up to the current state
(``_ensure_fresh``), and the joint addresses of rudder and sail (``_idx``): members that
:mod:`sailmujoco.physics` defines.

:meth:`BoatAccessors.truth` is the boat's side of :meth:`sailmujoco.tasks.world.World.truth`:
its true state for :mod:`sailmujoco.measurement.observation`, read from one rotation matrix and
the physics' arrays (no accessor called twice, none re-deriving the rotation or the Euler
angles), the accessors' numbers bit for bit. :meth:`BoatAccessors.diagnostic_record`
is what the assumption study measures at one step.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from .. import frames
from ..forces import boat as kernels
from ..jit.ordered import mat_t_vec
from .observation import Truth, euler_of, euler_of_entries, observation_and_record, rotation_of, wrench_rows

_SITE = mujoco.mjtObj.mjOBJ_SITE
_WRENCH_KEYS, _WRENCH_ROWS = wrench_rows(kernels.TERMS)
_N_TERMS = len(kernels.TERMS)
_D_WIND = kernels.D_WIND_X
_D_FLOW = kernels.D_SAIL_FLOW_X
_TERM = {name: i for i, name in enumerate(kernels.TERMS)}
_WRENCH_INDEX = _WRENCH_ROWS.tolist()
_WRENCHES_ARE_TERMS = max(_WRENCH_INDEX) < _N_TERMS  # every wrench is a force term of the physics


class BoatAccessors:
    """The accessors of :class:`~sailmujoco.physics.BoatPhysics` (see the module docstring)."""

    def _free_state(self):
        """(qpos, qvel) of the hull in free-joint layout: pos, quat, world velocity, body rates."""
        if self.dofs == 6:
            return self.data.ptr.qpos, self.data.ptr.qvel
        self._fill_pseudo()
        return self._q7, self._v6

    def rotation(self) -> np.ndarray:
        """Body->world rotation of the hull (3x3)."""
        out = np.empty(9)
        mujoco.mju_quat2Mat(out, self._free_state()[0][3:7])
        return out.reshape(3, 3)

    def _euler(self):
        return frames.euler_from_matrix(self.rotation())

    def position(self) -> np.ndarray:
        """World position (x east, y north, z up) of CO, m."""
        return self._free_state()[0][0:3].copy()

    def heel(self) -> float:
        """Heel (roll) angle phi, rad, positive starboard down."""
        return float(self._euler()[0])

    def pitch(self) -> float:
        """Pitch angle, rad, positive bow up."""
        return float(self._euler()[1])

    def yaw(self) -> float:
        """ENU yaw, rad, counter-clockwise from east."""
        return float(self._euler()[2])

    def heading(self) -> float:
        """Compass heading, rad, clockwise from north (Wille's psi)."""
        return float(frames.heading_from_yaw(self.yaw()))

    def body_velocity(self) -> np.ndarray:
        """Body-frame linear velocity of CO (u, v, w), m/s."""
        return mat_t_vec(self.rotation(), self._free_state()[1][0:3])

    def angular_velocity(self) -> np.ndarray:
        """Body-frame angular velocity (p, q, r), rad/s."""
        return self._free_state()[1][3:6].copy()

    def surge_speed(self) -> float:
        """Surge u: body-x velocity of CO, m/s."""
        return float(self.body_velocity()[0])

    def sway_speed(self) -> float:
        """Sway v: body-y velocity of CO, m/s (positive to port)."""
        return float(self.body_velocity()[1])

    def roll_rate(self) -> float:
        """Roll rate p about body x, rad/s."""
        return float(self.angular_velocity()[0])

    def yaw_rate(self) -> float:
        """Yaw rate r about body z, rad/s (positive turning to port)."""
        return float(self.angular_velocity()[2])

    def drift_angle(self) -> float:
        """Drift angle beta = atan2(v cos(phi), u), Wille eq. 45 (FLU sign: positive to port)."""
        u, v, _ = self.body_velocity()
        return float(math.atan2(v * math.cos(self.heel()), u))

    def ground_velocity(self) -> np.ndarray:
        """World (east, north) velocity of CO, m/s."""
        return self._free_state()[1][0:2].copy()

    def place(self, position=(0.0, 0.0), yaw: float = 0.0, surge: float = 0.0) -> None:
        """Put the boat upright on its waterline; the rudder and sail keep their angles.

        Parameters
        ----------
        position : tuple of float
            World (east, north) position of CO, m.
        yaw : float
            ENU yaw, rad, counter-clockwise from east.
        surge : float
            Speed ahead, m/s.
        """
        d = self.data.ptr
        d.qvel[:] = 0.0
        if self.dofs == 6:
            d.qpos[0:3] = (position[0], position[1], 0.0)
            d.qpos[3:7] = (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))
            d.qvel[0:2] = (surge * math.cos(yaw), surge * math.sin(yaw))
        else:
            d.qpos[0:4] = (position[0], position[1], yaw, 0.0)
            d.qvel[0:2] = (surge * math.cos(yaw), surge * math.sin(yaw))
        mujoco.mj_forward(self.model.ptr, d)
        self._fresh = False
        self._ensure_fresh()

    def sail_wind(self) -> np.ndarray:
        """World wind velocity at the sail's centre of effort, m/s."""
        self._ensure_fresh()
        return self._diag[kernels.D_WIND_X:kernels.D_WIND_Z + 1].copy()

    def apparent_wind_ce(self) -> np.ndarray:
        """Air velocity relative to the sail CE, body x-y (FLU), m/s."""
        self._ensure_fresh()
        return self._diag[kernels.D_SAIL_FLOW_X:kernels.D_SAIL_FLOW_Y + 1].copy()

    def course(self) -> float:
        """Course over ground: ENU direction of the horizontal velocity of CO, rad."""
        vx, vy = self._free_state()[1][0:2]
        return float(math.atan2(vy, vx))

    def speed_over_ground(self) -> float:
        """Horizontal speed of CO over ground, m/s."""
        return math.hypot(*self._free_state()[1][0:2])

    def rudder_angle(self) -> float:
        """Rudder angle, rad, positive trailing edge to port."""
        return float(self.data.ptr.qpos[self._idx[0]])

    def sail_angle(self) -> float:
        """Sail (boom) angle, rad, positive trailing edge to port."""
        return float(self.data.ptr.qpos[self._idx[2]])

    def sheet_tension(self) -> float:
        """The sheet's tension, N (>= 0: a sheet only pulls), from its actuator's force at the
        last step; 0 for an actuated sail (no sheet)."""
        if self.sail_mode != "sheeted":
            return 0.0
        return max(0.0, -float(self.data.ptr.actuator_force[1]))

    def true_wind(self, height: float | None = None) -> np.ndarray:
        """World wind velocity (m/s) at the current time.

        Parameters
        ----------
        height : float, optional
            Height above the water, m (default: the masthead's).
        """
        self._ensure_fresh()
        if height is None:
            height = float(self.data.ptr.site_xpos[self.model.ptr.site("masthead").id][2])
        return self.wind.velocity(self.data.ptr.time, height)

    def apparent_wind_masthead(self) -> np.ndarray:
        """Apparent wind velocity at the masthead in the body frame, m/s (air relative to it)."""
        self._ensure_fresh()
        m, d = self.model.ptr, self.data.ptr
        site = m.site("masthead").id
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_SITE, site, vel, 0)
        air = self.wind.velocity(d.time, float(d.site_xpos[site][2])) - vel[3:]
        return mat_t_vec(self.rotation(), air)

    def apparent_wind_angle(self) -> float:
        """AWA at the masthead, rad, positive when the wind comes from starboard."""
        return frames.apparent_wind_angle(self.apparent_wind_masthead())

    def apparent_wind_speed(self) -> float:
        """Apparent wind speed at the masthead in the body x-y plane, m/s."""
        return math.hypot(*self.apparent_wind_masthead()[:2])

    def angle_of_attack(self, foil: str) -> float:
        """Angle of attack (rad) of one foil now.

        Parameters
        ----------
        foil : str
            'sail', 'keel' or 'rudder'.
        """
        index = {"sail": kernels.D_ALPHA_SAIL, "keel": kernels.D_ALPHA_KEEL,
                 "rudder": kernels.D_ALPHA_RUDDER}
        if foil not in index:
            raise ValueError(f"unknown foil {foil!r}; choose one of {sorted(index)}")
        self._ensure_fresh()
        return float(self._diag[index[foil]])

    def force_term(self, name: str) -> np.ndarray:
        """Body-frame wrench (Fx, Fy, Fz, Mx, My, Mz) about CO of one force model, N and N m.

        Parameters
        ----------
        name : str
            One of :data:`sailmujoco.forces.boat.TERMS`.
        """
        if name not in kernels.TERMS:
            raise ValueError(f"unknown force term {name!r}; choose one of {kernels.TERMS}")
        self._ensure_fresh()
        return self._terms[kernels.TERMS.index(name)].copy()

    def force_terms(self) -> dict[str, np.ndarray]:
        """Every force model's body-frame wrench about CO (see :meth:`force_term`), by name."""
        self._ensure_fresh()
        return {name: self._terms[i].copy() for i, name in enumerate(kernels.TERMS)}

    def floating_pose(self) -> tuple[float, float]:
        """(height of CO in m, trim in rad) at which the hydrostatics are evaluated: the hull's
        own in 6 DOF; in 4 DOF with geometric hydrostatics, the heave and trim that float the
        hull at the current heel (the held joints stay at 0)."""
        if self.dofs == 4 and self._floating is not None:
            heel, table = float(self.data.ptr.qpos[3]), self._floating
            return (float(np.interp(heel, table.heel, table.heave)),
                    float(np.interp(heel, table.heel, table.trim)))
        return float(self.position()[2]), self.pitch()

    def submerged_volume(self) -> float:
        """Submerged volume (geometric hydrostatics only), m^3; in 4 DOF, at the floating pose."""
        self._ensure_fresh()
        if self.dofs == 4 and self._floating is not None:
            table = self._floating
            return float(np.interp(self.data.ptr.qpos[3], table.heel, table.volume))
        return float(self._diag[kernels.D_SUBMERGED])

    def sail_coefficients(self) -> tuple[float, float]:
        """(C_N, C_T) of the sail at the last force evaluation."""
        self._ensure_fresh()
        return float(self._diag[kernels.D_CN]), float(self._diag[kernels.D_CT])

    # ------------------------------------------------------------------ the task's measurement
    def truth(self) -> Truth:
        """The boat's true state now, for :mod:`sailmujoco.measurement.observation`.

        Equal, bit for bit, to :func:`~sailmujoco.measurement.observation.accessor_truth` of
        the boat (the accessors' values), read from one rotation matrix and the physics' arrays.

        Returns
        -------
        Truth
            The boat's true state.
        """
        d = self.data.ptr
        held = self.__dict__.get("_truth_held")
        if held is None or held[0] is not d:
            held = self._hold_truth_arrays(d)
        _, qvel, m, site, joints, site_xpos, rudder_at, sail_at, flat, rot, vel = held
        if self.dofs == 6:  # _free_state()
            qpos = joints
        else:
            qpos, qvel = self._free_state()
        mujoco.mju_quat2Mat(flat, qpos[3:7])  # rotation_of(qpos), into the held matrix
        body = mat_t_vec(rot, qvel[0:3])  # body_velocity()
        rates = qvel[3:6]  # angular_velocity(), read before _ensure_fresh refills it (4 DOF): same values
        wind = self.wind
        current = wind.current
        current_body = mat_t_vec(rot, current)
        t = d.time
        heel, pitch, yaw = euler_of_entries(flat.tolist())  # euler_of(rot)
        heading = frames.wrap_angle(math.pi / 2.0 - yaw)  # frames.heading_from_yaw
        rudder, sail = float(joints[rudder_at]), float(joints[sail_at])

        self._ensure_fresh()  # the force terms and diagnostics of this very state
        diag = self._diag
        # apparent_wind_masthead(): the air relative to the masthead, body axes
        mujoco.mj_objectVelocity(m, d, _SITE, site, vel, 0)  # writes all six
        air = wind.velocity(t, float(site_xpos[site, 2])) - vel[3:]
        flow_x, flow_y, _ = mat_t_vec(rot, air).tolist()
        awa = math.atan2(flow_y, -flow_x)  # frames.apparent_wind_angle
        aws = math.hypot(flow_x, flow_y)
        return Truth._make((  # in the order of its fields
            t, qpos[0:2].copy(), qvel[0:2].copy(), body, current_body, rates, yaw, heel, pitch, heading,
            rudder, sail, awa, aws, diag[_D_WIND:_D_WIND + 2].copy(), diag[_D_FLOW:_D_FLOW + 2].copy(),
            wind.config.speed, wind.direction_from(t), np.array(current[:2], dtype=np.float64),
            self._wrenches()))

    def _hold_truth_arrays(self, d) -> tuple:
        """What :meth:`truth` reads of MjData ``d`` and its model, looked up once per MjData
        (MuJoCo's buffers are stable per MjData), and the arrays it writes and reads within one
        call: (d, qvel, model, masthead site id, qpos, site_xpos, rudder and sail qpos addresses,
        the rotation's 9 entries, the transpose of the rotation (a view of them), a 6-vector)."""
        m = self.model.ptr
        flat = np.empty(9)
        rudder_at, _, sail_at, _ = self._idx.tolist()
        self._truth_held = (d, d.qvel, m, mujoco.mj_name2id(m, _SITE, "masthead"), d.qpos, d.site_xpos,
                            rudder_at, sail_at, flat, flat.reshape(3, 3), np.empty(6))
        return self._truth_held

    def _wrenches(self) -> dict:
        """The observation's wrenches (``"<key>_wrench"`` -> (6,) array, in :data:`_WRENCH_KEYS`
        order): rows of a copy of the force terms (a row of zeros for one the physics lacks)."""
        if _WRENCHES_ARE_TERMS:
            terms = self._terms.copy()
        else:
            terms = np.zeros((_N_TERMS + 1, 6))
            terms[:_N_TERMS] = self._terms
        return dict(zip(_WRENCH_KEYS, map(terms.__getitem__, _WRENCH_INDEX), strict=True))

    def measure(self) -> tuple[dict, dict]:
        """(observation, record) of the boat now:
        :func:`~sailmujoco.measurement.observation.observation_and_record` of its :meth:`truth`.

        Returns
        -------
        observation : dict
            The observation of the controllers (without the task's references).
        record : dict
            The task's per-step record.
        """
        return observation_and_record(self)

    def diagnostic_record(self) -> dict:
        """What the assumption study measures at one step of the boat (our frames, SI).

        Read from one rotation and the force kernel's arrays (as :meth:`truth` reads the
        true state); the named accessors (``sail_coefficients``, ``force_terms``,
        ``rotation``, ``heel``, ``pitch``, ``drift_angle``, ...) give the same values bit for
        bit at a few times the cost (tests/test_assumptions.py keeps them as the reference).

        Returns
        -------
        dict
            ``ct_cn`` (|C_T| / |C_N| of the sail), ``pitch`` (rad), ``heave`` (m), ``drift``
            (rad), ``keel_aoa`` (rad), ``mx_<term>`` (roll moment of each force term, N m;
            ``mx_hydrostatics`` is buoyancy plus weight), ``omega3_term`` (N m) and
            ``restoring`` (N m).
        """
        self._ensure_fresh()  # the force terms and diagnostics of this very state
        diag, terms = self._diag, self._terms
        c_n, c_t = float(diag[kernels.D_CN]), float(diag[kernels.D_CT])
        p = self.params
        qpos, qvel = self._free_state()
        rates = qvel[3:6]
        ixx, iyy, izz = p.inertia
        rot = rotation_of(qpos)  # rotation(), without filling the 4-DOF pseudo state again
        heel, pitch, _ = euler_of(rot)
        # MuJoCo applies the weight itself, at the CG: its roll moment about CO completes the
        # restoring moment (buoyancy + weight) that the papers' g(eta) stands for
        weight_body = mat_t_vec(rot, np.array([0.0, 0.0, -p.mass * 9.81]))
        gravity_mx = -p.cg_z * weight_body[1]  # (r_G x F)_x with r_G = (cg_x, 0, cg_z)
        restoring = terms[kernels.T_HYDRO][3] + gravity_mx
        u, v, _ = mat_t_vec(rot, qvel[0:3])  # body velocity
        return {
            "ct_cn": abs(c_t) / abs(c_n) if abs(c_n) > 0.05 else float("nan"),
            "pitch": pitch, "heave": float(qpos[2]),
            "drift": float(math.atan2(v * math.cos(heel), u)),  # Wille eq. 45, FLU sign
            "keel_aoa": float(diag[kernels.D_ALPHA_KEEL]),
            # roll moments about body x (N m) of each term ("hydrostatics": buoyancy + weight)
            **{f"mx_{name}": float(restoring if name == "hydrostatics" else terms[_TERM[name]][3])
               for name in ("sail", "keel", "rudder", "hydrostatics", "damping", "added_mass")},
            # Saoud §III: (J33 - J22)/J11 w3^2 tan(phi), as a moment, against the restoring one
            "omega3_term": (izz - iyy) * rates[2] ** 2 * math.tan(heel),
            "restoring": float(restoring),
        }
