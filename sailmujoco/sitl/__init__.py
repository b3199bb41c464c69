"""The 6-DOF boat as ArduPilot's physics: the JSON backend of ArduPilot's SITL, in lock-step.

ArduPilot's software-in-the-loop build (``ardurover --model JSON``) sends one binary servo packet
per frame to UDP port 9002 and waits for one JSON line with the vehicle's state before its next
frame (``libraries/SITL/SIM_JSON.cpp``, ``libraries/SITL/examples/JSON/readme.md``). Here each
packet advances the boat by one physics step and is answered with its state:

* :mod:`.protocol`: the servo packet (magic 18458 with 16 channels, 29569 with 32) and the JSON
  state line, read and written;
* :mod:`.servos`: ArduPilot's sailboat outputs as the boat's commands (ground steering ->
  rudder, mainsail -> sheet);
* :mod:`.state`: the boat's state in ArduPilot's frames (NED, body FRD; the frames themselves
  in :mod:`sailmujoco.frames`) and its wind vane;
* :mod:`.backend`: the lock-step loop (:class:`JsonBackend`), its errors in one line each.

``sailmujoco sitl BOAT`` runs it from the command line; docs/ardupilot.md is the recipe.
"""
