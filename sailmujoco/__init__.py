"""sailmujoco: a MuJoCo 6-DOF testbed for autonomous sailboat control laws.

The data flow runs one way (see ``../STYLE`` in the README):
params -> mjcf -> forces -> physics -> tasks -> controllers -> studies.

Importing sailmujoco changes nothing in the process: no environment variable is set and no
OpenGL platform is initialised until something is rendered (:mod:`sailmujoco.gl_platform`);
videos and the Gymnasium environments' frames are drawn in a child process
(:mod:`sailmujoco.video.child`).
"""

__version__ = "0.1.0"
