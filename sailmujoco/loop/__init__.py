"""The closed loop compiled: observation, controller, task and world in one native call.

A control step through the task API costs the physics plus the Python around it (the truth,
the observation's dicts, the controller, the record, the reward, dm_control's TimeStep). Where
the control period is short the Python dominates: Viel's controller at 100 Hz in Viel's 3-DOF
world spends about nine tenths of its step there. Here such a pair runs as one compiled
function per episode, step for step the operations of the Python path, which stays the
reference: the trajectory, records, metrics and the controller's memory are the same to the last
bit (``tests/test_closed_loop.py``).

* :mod:`sailmujoco.loop.episode`: which pairs a compiled loop covers, running it, and handing
  the episode back to the Python path in the state that path would have reached;
* :mod:`sailmujoco.loop.viel_paper`: Viel's position keeping in Viel's world.

The sweep runner (:func:`sailmujoco.sweep.runs.execute`, and so every study) uses it wherever it
applies; ``SAILMUJOCO_PYTHON_LOOP=1`` turns it off (the Python path everywhere).
"""
