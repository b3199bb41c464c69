"""One decorator for the force kernels.

Every force model is written once, in plain Python and numpy. ``kernel`` compiles it with
numba (the fast path). With ``NUMBA_DISABLE_JIT=1`` in the environment numba hands back the
plain function, so the very same source runs in the interpreter: that is the readable
reference path the tests compare the compiled one against (to 1e-10).
"""

from __future__ import annotations

import numba


def kernel(fn):
    """Compile ``fn`` with numba (cached on disk), or return it unchanged when JIT is disabled."""
    return numba.njit(cache=True, nogil=True, error_model="numpy")(fn)
