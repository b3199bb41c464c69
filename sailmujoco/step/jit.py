"""One decorator for the force kernels, and the compiled entry point of a kernel.

Every force model is written once, in plain Python and numpy. ``kernel`` compiles it with
numba (the fast path). With ``NUMBA_DISABLE_JIT=1`` in the environment numba hands back the
plain function, so the very same source runs in the interpreter: that is the readable
reference path the tests compare the compiled one against (to 1e-10).

Compiled kernels are cached on disk. numba invalidates a cached kernel when its own file
changes but not when a kernel it calls (in another file) does, so the cache is cleared here
whenever any kernel source differs from the one it was built from (a module with kernels
outside ``sailmujoco/`` and ``forces/`` calls :func:`clear_stale_cache` for its own).

A compile (a cold cache: the first run) is announced on stderr while it lasts, a kernel loaded
from the cache silently (:mod:`sailmujoco.step.compile_notice`).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numba

from . import compile_notice

_PACKAGE = Path(__file__).resolve().parents[1]
_SOURCES = sorted([_PACKAGE / "step" / "jit.py", _PACKAGE / "boat" / "hull_grid.py",
                   *(_PACKAGE / "forces").glob("*.py"),
                   *(_PACKAGE / "reference").glob("*.py")])  # the paper worlds' kernels call forces/;
# the kernels freeze hull_grid.py's grid size into the sea's scratch size


def _clear_stale_cache(sources=tuple(_SOURCES), cache_dirs=None) -> None:
    """Empty each cache directory (default: those of ``sources``) unless ``sources`` are those
    its kernels were built from."""
    digest = hashlib.sha256(b"".join(p.read_bytes() for p in sources)).hexdigest()
    if cache_dirs is None:
        cache_dirs = {p.parent / "__pycache__" for p in sources}
    for cache_dir in cache_dirs:
        stamp = cache_dir / "sailmujoco-kernels.stamp"
        try:
            if stamp.exists() and stamp.read_text() == digest:
                continue
            if cache_dir.exists():
                for f in [*cache_dir.glob("*.nbi"), *cache_dir.glob("*.nbc")]:
                    f.unlink(missing_ok=True)
            cache_dir.mkdir(exist_ok=True)
            stamp.write_text(digest)
        except OSError:  # read-only install: numba falls back to its own cache location
            pass


_clear_stale_cache()
compile_notice.install()


def clear_stale_cache(module_file: str) -> None:
    """For kernels outside the package's own modules (a controller's): empty the cache beside
    ``module_file`` when it, or any package kernel its kernels may call, has changed."""
    module = Path(module_file).resolve()
    _clear_stale_cache((*_SOURCES, module), {module.parent / "__pycache__"})


def kernel(fn=None, *, inline: bool = False, reassociate: bool = False):
    """Compile ``fn`` with numba (cached on disk), or return it unchanged when JIT is disabled.

    ``@kernel(inline=True)`` inlines the function into its compiled callers (numba IR level):
    for a helper with many array arguments called in the per-step kernel, where the call itself
    would cost measurable time. ``@kernel(reassociate=True)`` lets the compiler reorder sums
    (LLVM's ``reassoc`` and ``contract``, not ``nnan``/``ninf``: a NaN still shows), so that
    a sum over wave components runs on vector registers; its last bits then differ from the
    interpreted path's (the tests compare the two to 1e-10). Only the sea's sums use it: calm
    water's arithmetic stays in its written order.
    """
    def build(f):
        return numba.njit(cache=True, nogil=True, error_model="numpy",
                          inline="always" if inline else "never",
                          fastmath={"reassoc", "contract"} if reassociate else False)(f)

    return build if fn is None else build(fn)


def entry_point(dispatcher):
    """The compiled entry point of a one-signature kernel (skips numba's type dispatch).

    Parameters
    ----------
    dispatcher : numba dispatcher or function
        A kernel made by :func:`kernel`. With NUMBA_DISABLE_JIT it is the plain function,
        handed back unchanged.

    Returns
    -------
    callable
        A :class:`LazyEntry` around the dispatcher, or the plain function.
    """
    if not hasattr(dispatcher, "overloads"):
        return dispatcher
    return LazyEntry(dispatcher)


class LazyEntry:
    """Calls through the dispatcher once, then through the compiled entry point.

    Parameters
    ----------
    dispatcher : numba dispatcher
        The kernel; its first call compiles it (or loads it from the cache).
    """

    def __init__(self, dispatcher):
        self._dispatcher = dispatcher
        self._entry = None

    @property
    def compiled(self) -> bool:
        """Whether calls now go straight to the compiled entry point."""
        return self._entry is not None

    def __call__(self, *args):
        if self._entry is None:
            result = self._dispatcher(*args)
            if len(self._dispatcher.signatures) == 1:
                self._entry = self._dispatcher.overloads[self._dispatcher.signatures[0]].entry_point
            return result
        return self._entry(*args)
