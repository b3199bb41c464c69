"""The physics step: the compiled RK4 control step, batches of boats, the 4-DOF stage, and the numba
kernels' compilation (cache, progress notice)."""
