"""The closed loop compiled: measurement, controller, task and world in one native call.

A control step through the task API costs the physics plus the Python around it (the truth,
the observation's dicts, the controller, the record, the reward, dm_control's TimeStep). Where
the control period is short the Python dominates: Viel's controller at 100 Hz spends about nine
tenths of its step there in Viel's 3-DOF world and about two thirds on a 6-DOF boat. A
controller that offers a compiled episode (``compiled_episode(env)``) runs the whole episode as
one compiled function, step for step the operations of the Python path, which stays the
reference: the trajectory, records, rewards, metrics and the controller's memory are the same to
the last bit (``tests/test_closed_loop.py``).

* :mod:`sailmujoco.loop.episode`: the protocol, and handing the episode back to the Python path
  in the state that path would have reached;
* :mod:`sailmujoco.loop.truth`: a world's true state as one vector (Viel's world, a 6-DOF MuJoCo
  boat); :mod:`sailmujoco.loop.worlds`: each world's control step;
  :mod:`sailmujoco.loop.position_task`: the position-keeping task's reward.

The controllers bring their laws: ``controllers/viel_loop.py`` (Viel's position keeping). The
sweep runner, ``suite.rollout`` (its default rows) and the studies take a compiled episode
wherever one is offered; ``SAILMUJOCO_PYTHON_LOOP=1`` turns them off (the Python path
everywhere).
"""
