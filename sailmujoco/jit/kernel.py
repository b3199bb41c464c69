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
from the cache silently (:mod:`sailmujoco.jit.notice`).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numba

from . import notice

_PACKAGE = Path(__file__).resolve().parents[1]
# Every file whose code is compiled into a cached kernel: the kernels and the step (step/), the
# paper worlds' kernels (which call forces/), the compiled closed loop's pieces (loop/), this
# decorator's flags, frames.wrap_angle (inlined where it is called) and hull_grid.py (its grid
# size is frozen into the sea's scratch size).
_SOURCES = sorted([*(_PACKAGE / "step").glob("*.py"), *(_PACKAGE / "forces").glob("*.py"),
                   *(_PACKAGE / "reference").glob("*.py"), *(_PACKAGE / "loop").glob("*.py"),
                   _PACKAGE / "jit" / "kernel.py",
                   _PACKAGE / "jit" / "ordered.py",
                   _PACKAGE / "frames.py", _PACKAGE / "boat" / "hull_grid.py"])


def _clear_stale_cache(sources=tuple(_SOURCES), cache_dirs=None, module: str = "") -> None:
    """Empty each cache directory (default: those of ``sources``) unless ``sources`` are those
    its kernels were built from; with ``module``, only that module's cache files, under a stamp
    of its own."""
    digest = hashlib.sha256(b"".join(p.read_bytes() for p in sources)).hexdigest()
    if cache_dirs is None:
        cache_dirs = {p.parent / "__pycache__" for p in sources}
    stamp_name = f"sailmujoco-kernels-{module}.stamp" if module else "sailmujoco-kernels.stamp"
    files = f"{module}.*" if module else "*"
    for cache_dir in cache_dirs:
        stamp = cache_dir / stamp_name
        try:
            if stamp.exists() and stamp.read_text() == digest:
                continue
            if cache_dir.exists():
                for f in [*cache_dir.glob(f"{files}.nbi"), *cache_dir.glob(f"{files}.nbc")]:
                    f.unlink(missing_ok=True)
            cache_dir.mkdir(exist_ok=True)
            stamp.write_text(digest)
        except OSError:  # read-only install: numba falls back to its own cache location
            pass


_clear_stale_cache()
notice.install()


def clear_stale_cache(module_file: str, *also) -> None:
    """For kernels outside the package's own modules (a controller's): empty their cache when
    their module, any file in ``also``, or any package kernel they may call has changed.

    Parameters
    ----------
    module_file : str
        The path of the module whose kernels are cached (its ``__file__``). Its numba cache
        files (``<module>.*.nbi``, ``.nbc``) in the ``__pycache__`` folder beside it are deleted
        unless that module's stamp there (``sailmujoco-kernels-<module>.stamp``) matches the
        SHA-256 digest of the package's kernel sources, this file and ``also``; the new digest is
        then written as the stamp. On a read-only install nothing is done (numba caches elsewhere).
    *also : str or pathlib.Path
        Other files the module's kernels compile in (a law whose functions they inline).
    """
    module = Path(module_file).resolve()
    sources = (*_SOURCES, module, *(Path(p).resolve() for p in also))
    _clear_stale_cache(sources, {module.parent / "__pycache__"}, module.stem)


def kernel(fn=None, *, inline: bool = False):
    """Compile ``fn`` with numba (cached on disk), or return it unchanged when JIT is disabled.

    ``@kernel(inline=True)`` inlines the function into its compiled callers (numba IR level):
    for a helper with many array arguments called in the per-step kernel, where the call itself
    would cost measurable time.

    No kernel lets the compiler reorder or fuse floating-point operations (no fastmath flag):
    LLVM then keeps every sum in its written order and never contracts a multiply and an add
    into one FMA, so a kernel gives the same bits whatever CPU numba compiles it for (the
    host's, with AVX-512 and FMA, or a generic x86-64): ``tests/test_cpu_targets.py``. Where a
    long sum should run on vector lanes, write the lanes out (``forces/lane_math.lane_sum``).

    Every kernel is compiled with ``cache=True``, ``nogil=True`` and ``error_model="numpy"``
    (a division by zero gives inf or NaN, as in numpy, rather than raising).

    Parameters
    ----------
    fn : function, optional
        The kernel's Python function. None when the decorator is written with arguments
        (``@kernel(inline=True)``).
    inline : bool, optional
        Inline the kernel into its compiled callers (numba's ``inline="always"``); default
        False (``inline="never"``).

    Returns
    -------
    numba dispatcher or callable
        The compiled kernel (the plain function with NUMBA_DISABLE_JIT); with ``fn`` None, the
        decorator that compiles the function it is given.
    """
    def build(f):
        return numba.njit(cache=True, nogil=True, error_model="numpy",
                          inline="always" if inline else "never", fastmath=False)(f)

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
        """Call the kernel: through the dispatcher the first time (which compiles it or loads it
        from the cache), then, if it has exactly one signature, straight through its compiled
        entry point (no type dispatch: the arguments must then have that signature's types).

        Parameters
        ----------
        *args
            The kernel's positional arguments, as its signature takes them (numpy arrays,
            floats, ints, bools).

        Returns
        -------
        object
            What the kernel returns.
        """
        if self._entry is None:
            result = self._dispatcher(*args)
            if len(self._dispatcher.signatures) == 1:
                self._entry = self._dispatcher.overloads[self._dispatcher.signatures[0]].entry_point
            return result
        return self._entry(*args)
