"""The closed loop compiled: observation, controller, task and world in one native call.

A control step through the task API costs the physics plus the Python around it (the truth,
the observation's dicts, the controller, the record, the reward, dm_control's TimeStep). Where
the control period is short the Python dominates: Viel's controller at 100 Hz in Viel's 3-DOF
world spends about nine tenths of its step there, on a 6-DOF boat about two thirds. Here such a pair runs as one compiled
function per episode, step for step the operations of the Python path, which stays the
reference: the trajectory, records, metrics and the controller's memory are the same to the last
bit (``tests/test_closed_loop.py``).

* :mod:`sailmujoco.loop.episode`: which pairs a compiled loop covers, running it, and handing
  the episode back to the Python path in the state that path would have reached;
* :mod:`sailmujoco.loop.truth`: a world's true state as one vector (Viel's world, a 6-DOF MuJoCo
  boat); :mod:`sailmujoco.loop.viel_control` and :mod:`sailmujoco.loop.position_task`: Viel's
  law and the position-keeping task on it;
* :mod:`sailmujoco.loop.viel_world`, :mod:`sailmujoco.loop.mujoco_world`: the episode kernels.

The sweep runner (:func:`sailmujoco.sweep.runs.execute`, and so every study) uses it wherever it
applies; ``SAILMUJOCO_PYTHON_LOOP=1`` turns it off (the Python path everywhere).
"""

from pathlib import Path as _Path

import sailmujoco.controllers.viel as _viel_law

from ..jit.kernel import _SOURCES, _clear_stale_cache

# The loops' cached kernels inline this folder's helpers, the package's kernels and the Viel
# controller's law (outside the package's kernel sources): their cache is emptied whenever any of
# those differs from what it was built from (numba itself checks only the kernel's own file).
_HERE = _Path(__file__).resolve().parent
_clear_stale_cache((*_SOURCES, _Path(_viel_law.__file__).resolve(), *sorted(_HERE.glob("*.py"))),
                   {_HERE / "__pycache__"})
