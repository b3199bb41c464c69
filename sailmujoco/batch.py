"""Many boats stepped together: one compiled call per control step, on all cores.

:class:`BoatBatch` holds N :class:`~sailmujoco.physics.BoatPhysics` (any boats, seeds, winds
and force switches, 6 or 4 DOF) and steps all of them with :func:`sailmujoco.step.native.batch_steps`:
numba threads over the boats, each running MuJoCo's step with the compiled stage callback.
Each boat's trajectory is the one it has stepped alone, bit for bit (tests/test_batch.py):
the boats share nothing but the callback, which finds each boat's arrays by its MjData.

A boat that stops (capsized, non-finite) keeps its stop reason and its last good state, as
alone; the others go on. Example::

    from sailmujoco.batch import BoatBatch
    from sailmujoco.physics import BoatPhysics
    from sailmujoco.forces.wind import WindConfig
    boats = [BoatPhysics.load("saoud_robot", wind=WindConfig(speed=3.0, seed=s)) for s in range(100)]
    batch = BoatBatch(boats)
    batch.set_controls(controls)        # (100, 2)
    batch.step(20)                      # 0.1 s for all of them
"""

from __future__ import annotations

import numpy as np

from .forces import boat as kernels
from .physics import RK4, BoatPhysics
from .step import native


class BoatBatch:
    """N boats (6 or 4 DOF) stepped in one compiled call (see the module docstring).

    Parameters
    ----------
    boats : list of BoatPhysics
        The boats, each once; they may differ in boat, wind, force switches and DOFs but not in
        integrator.
    """

    def __init__(self, boats: list[BoatPhysics]):
        boats = list(boats)
        if not boats:
            raise ValueError("a batch needs at least one boat")
        for i, boat in enumerate(boats):
            if not isinstance(boat, BoatPhysics):
                raise ValueError(f"boat {i}: a batch holds BoatPhysics only, got {boat!r}")
        if len({id(b.data.ptr) for b in boats}) != len(boats):
            raise ValueError("a boat appears twice in the batch")
        if not native.AVAILABLE:
            raise RuntimeError("batched stepping needs numba's JIT (NUMBA_DISABLE_JIT is set)")
        self.boats = boats
        n = len(boats)
        self._status = np.zeros(n, dtype=np.int64)
        self._done = np.zeros(n, dtype=np.int64)
        self._warned = np.zeros(n, dtype=np.bool_)
        width = max(b.model.nq + b.model.nv + b.model.na for b in boats)
        self._saved = np.zeros((n, width))

    def __len__(self) -> int:
        return len(self.boats)

    def set_controls(self, controls) -> None:
        """Actuator commands, one row per boat (each checked as ``BoatPhysics.set_control``).

        Parameters
        ----------
        controls : array_like, shape (N, nu)
            Row i: boat i's [rudder angle (rad), sail angle (rad) or sheet length (m)]; rows of
            stopped boats are ignored.
        """
        controls = np.asarray(controls, dtype=float)
        if controls.ndim != 2 or controls.shape[0] != len(self.boats):
            raise ValueError(f"controls must have one row per boat ({len(self.boats)}), "
                             f"got shape {controls.shape}")
        for boat, control_row in zip(self.boats, controls, strict=True):
            if boat.stop_reason is None:
                boat.set_control(control_row)

    @property
    def stop_reasons(self) -> list[str | None]:
        """Why each boat stopped (None: still running)."""
        return [b.stop_reason for b in self.boats]

    @property
    def running(self) -> np.ndarray:
        """Whether each boat still runs (bool array)."""
        return np.array([b.stop_reason is None for b in self.boats])

    def step(self, nstep: int = 1, which=None) -> np.ndarray:
        """Advance every running boat (of those ``which`` selects) ``nstep`` sub-steps.

        A boat that stops during the call records its reason (``stop_reasons``); its state is
        the one before the offending sub-step, as when it steps alone.

        Parameters
        ----------
        nstep : int
            Sub-steps of each boat's ``model.opt.timestep`` seconds.
        which : array_like of bool, shape (N,), optional
            The boats to step; default all.

        Returns
        -------
        numpy.ndarray of bool, shape (N,)
            Which boats still run.
        """
        boats = self.boats
        which = np.ones(len(boats), dtype=bool) if which is None else np.asarray(which, dtype=bool)
        if which.shape != (len(boats),):
            raise ValueError(f"which must be one bool per boat ({len(boats)}), got {which.shape}")
        rk4 = {b.model.ptr.opt.integrator == RK4 for b in boats}
        if len(rk4) != 1:
            raise ValueError("all boats of a batch must use the same integrator")
        rk4 = rk4.pop()
        active = [i for i, (boat, chosen) in enumerate(zip(boats, which, strict=True))
                  if chosen and boat.stop_reason is None]  # a stopped boat does not step again
        self._status[:] = -1
        rows = {}
        for i in active:
            rows[i] = boats[i].begin_batch_step(nstep)
            self._status[i] = kernels.STATUS_OK
        if not active:
            return self.running
        models = np.array([b.model.ptr._address for b in boats], dtype=np.int64)
        datas = np.array([b.data.ptr._address for b in boats], dtype=np.int64)
        slots = np.zeros(len(boats), dtype=np.int64)
        with native.Stepping([int(datas[i]) for i in active], [rows[i] for i in active]) as held:
            slots[active] = held
            native.batch_steps(models, datas, nstep, slots, rk4, self._saved, self._status,
                               self._done, self._warned)
        for i, boat in enumerate(boats):
            if self._status[i] == -1:
                continue
            boat.end_batch_step(int(self._status[i]), bool(self._warned[i]))
        return self.running


class BatchEnvironment:
    """N environments of the suite stepped together: ``step(actions)`` gives N TimeSteps.

    Each environment is a :class:`~sailmujoco.tasks.environment.SailEnvironment` as ``suite.load``
    builds it (its own seed and options). Their MuJoCo boats (6 or 4 DOF) step in one compiled
    call per control step (:class:`BoatBatch`); the paper worlds step one at a time behind the
    same interface. Every environment gives exactly the TimeSteps it gives
    alone (tests/test_batch.py). An environment whose episode ended resets on its next step, as
    dm_env's contract says.

    Parameters
    ----------
    envs : iterable of SailEnvironment
        The environments, all with the same control timestep.
    """

    def __init__(self, envs):
        self.envs = list(envs)
        if not self.envs:
            raise ValueError("a batch needs at least one environment")
        steps = {env._n_sub_steps for env in self.envs}
        if len(steps) != 1:
            raise ValueError("every environment of a batch needs the same number of physics steps per "
                             "control step: the same control_timestep and timestep")
        self._n_sub_steps = steps.pop()
        physics = [env.physics for env in self.envs]
        batched = all(isinstance(p, BoatPhysics) for p in physics)
        self.batch = BoatBatch(physics) if batched and native.AVAILABLE else None

    def __len__(self) -> int:
        return len(self.envs)

    @property
    def batched(self) -> bool:
        """Whether the physics steps in one compiled call (False: one at a time)."""
        return self.batch is not None

    def reset(self) -> list:
        return [env.reset() for env in self.envs]

    def step(self, actions) -> list:
        """One control step of every environment with its row of ``actions``.

        Parameters
        ----------
        actions : sequence of array_like, length N
            Row i: environment i's action [rudder (rad), sail (rad) or sheet (m)].

        Returns
        -------
        list of dm_env.TimeStep
        """
        if len(actions) != len(self.envs):
            raise ValueError(f"actions must have one row per environment ({len(self.envs)}), "
                             f"got {len(actions)}")
        if self.batch is None:
            return [env.step(action) for env, action in zip(self.envs, actions, strict=True)]
        out = [None] * len(self.envs)
        stepping = np.zeros(len(self.envs), dtype=bool)
        for i, (env, action) in enumerate(zip(self.envs, actions, strict=True)):
            if env._reset_next_step:
                out[i] = env.reset()
            else:
                env.before_physics(action)
                stepping[i] = True
        self.batch.step(self._n_sub_steps, which=stepping)
        for i in np.flatnonzero(stepping):
            env = self.envs[i]
            reason = env.physics.stop_reason
            out[i] = env.stopped_step(reason) if reason is not None else env.after_physics()
        return out
