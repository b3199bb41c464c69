"""sailmujoco: a MuJoCo 6-DOF testbed for autonomous sailboat control laws.

The data flow runs one way (see ``../STYLE`` in the README):
params -> mjcf -> forces -> physics -> tasks -> controllers -> studies.
"""

import os as _os

# Offscreen rendering through EGL by default (Mesa llvmpipe on CPU machines, the NVIDIA
# driver on GPUs); set MUJOCO_GL=osmesa before importing to use the OSMesa fallback.
# dm_control reads this variable when it is first imported.
_os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"
