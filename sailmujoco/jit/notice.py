"""A line on stderr while numba compiles sailmujoco's kernels: what a first run spends its time on.

The force kernels, the compiled control step and the paper worlds' models are compiled by
numba on their first call and cached on disk (:mod:`sailmujoco.jit.kernel`); a later process loads
them in a fraction of a second. A cold cache (a first run, an upgrade, an edited kernel) costs
one to two minutes on 2 cores, and without a word a user takes it for a hang. So while numba
compiles one of our kernels (a cache miss: numba's ``numba:compile`` event, which a kernel
loaded from the cache never sends) this module writes, once the compiling has gone on for
:data:`ANNOUNCE_AFTER_S`, the line::

    compiling sailmujoco's numba kernels (first run only, cached afterwards; about 1-2 min on 2 cores) ...

on a terminal as a live line with the seconds so far (cut to the terminal's width), anywhere else
(a log, a pipe, a worker process) as a plain line; then, when no compile has run
for :data:`GAP_S` (or at exit), ``compiled sailmujoco's numba kernels in 66 s``. A kernel that
comes from the cache prints nothing. Everything goes to stderr; ``SAILMUJOCO_QUIET=1`` in the
environment (read at every line, and inherited by worker processes) silences it.

:func:`install` (called by :mod:`sailmujoco.jit.kernel`) only registers the listener with numba;
nothing is printed and no thread is started before a kernel actually compiles.
"""

from __future__ import annotations

import atexit
import io
import multiprocessing
import os
import sys
import threading
import time

from ..progress import duration, is_terminal

QUIET_ENV = "SAILMUJOCO_QUIET"
ANNOUNCE_AFTER_S = 1.0  # compiles shorter than this (one new signature) pass without a word
GAP_S = 5.0  # compiles closer than this are one burst (a first run's: seconds apart, building models between)
TICK_S = 0.5  # redraw period of the live line
# measured with an empty cache on a 2-core machine (docs/performance.md, "The first run")
ESTIMATE = "about 1-2 min on 2 cores"
FIRST = f"compiling sailmujoco's numba kernels (first run only, cached afterwards; {ESTIMATE})"
MORE = "compiling more of sailmujoco's numba kernels (first run only, cached afterwards)"
OUR_PACKAGES = ("sailmujoco", "controllers", "studies")


def quiet() -> bool:
    """Whether the environment asks for no compile notice (``SAILMUJOCO_QUIET`` set, not 0)."""
    return os.environ.get(QUIET_ENV, "").strip() not in ("", "0")


def kind(dispatcher) -> str:
    """Whose code a compiling numba dispatcher holds: ``"ours"``, ``"numba"`` or ``"other"``.

    Parameters
    ----------
    dispatcher : numba dispatcher
        The dispatcher of a ``numba:compile`` event.
    """
    module = getattr(getattr(dispatcher, "py_func", None), "__module__", None) or ""
    package = module.split(".")[0]
    if package in OUR_PACKAGES:
        return "ours"
    return "numba" if package == "numba" else "other"


class CompileNotice:
    """The announcement state of one process: open compile "bursts", the line on screen.

    A burst starts with an outermost compile of one of our kernels and takes in every
    outermost compile that follows within ``gap`` seconds (numba's own helpers compiled for
    a C callback count too, but never start one). Its first line is written once it has
    lasted ``announce_after`` seconds (from its first compile's start to the end of its latest);
    its last line when it closes. On a terminal the first line is live, drawn only while a
    compile is under way.

    Parameters
    ----------
    stream : file, optional
        Where to write (default: ``sys.stderr`` when a line is written).
    live : bool, optional
        A live line redrawn in place (default: ``stream`` is a terminal and this is not a child
        process, whose line would fight its siblings').
    announce_after : float
        Seconds of compiling before the first line.
    gap : float
        Seconds without a compile that end a burst.
    clock : callable
        Monotonic seconds.
    ticking : bool
        A daemon thread calls :meth:`poll` while a burst is open, and the last line is written
        at exit (``False``: the caller polls).
    """

    def __init__(self, stream=None, live=None, announce_after: float = ANNOUNCE_AFTER_S,
                 gap: float = GAP_S, clock=time.monotonic, ticking: bool = True):
        self._stream = stream
        self._live = live
        self.announce_after = announce_after
        self.gap = gap
        self.clock = clock
        self.ticking = ticking
        self.lock = threading.RLock()
        self.local = threading.local()  # nesting depth of numba's compile events, per thread
        self.burst_start = None  # when the open burst's first compile started
        self.active_since = None  # start of the outermost compile under way (None: idle)
        self.last_end = None
        self.announced = False  # the open burst's first line is out
        self.bursts = 0  # bursts announced in this process
        self.drawn = False  # a live line is on the screen
        self.thread = None
        self.exit_hook = False

    @property
    def stream(self):
        """The stream written to."""
        return sys.stderr if self._stream is None else self._stream

    @property
    def live(self) -> bool:
        """Whether the first line is a live line redrawn in place."""
        if self._live is None:
            self._live = is_terminal(self.stream) and multiprocessing.parent_process() is None
        return self._live

    def start(self, who: str, now: float | None = None) -> None:
        """A compile event starts.

        Parameters
        ----------
        who : str
            :func:`kind` of its dispatcher.
        now : float, optional
            The time (default: ``clock()``).
        """
        depth = getattr(self.local, "depth", 0)
        self.local.depth = depth + 1
        if depth > 0:  # a callee compiled inside the outermost compile: part of it
            return
        counted = (who == "ours" or (who == "numba" and self.burst_start is not None)) and not quiet()
        self.local.counted = counted
        if not counted:
            return
        now = self.clock() if now is None else now
        with self.lock:
            if self.burst_start is None:
                self.burst_start = now
            self.active_since = now
            if self.ticking and self.thread is None:
                self._start_thread()

    def end(self, now: float | None = None) -> None:
        """A compile event ends.

        Parameters
        ----------
        now : float, optional
            The time (default: ``clock()``).
        """
        self.local.depth = getattr(self.local, "depth", 1) - 1
        if self.local.depth > 0 or not getattr(self.local, "counted", False):
            return
        self.local.counted = False
        with self.lock:
            self.active_since = None
            self.last_end = self.clock() if now is None else now
            self._erase()  # between compiles the screen belongs to the program again

    def poll(self, now: float | None = None) -> bool:
        """One tick: write the first line when due, redraw the live line, close an idle burst.

        Parameters
        ----------
        now : float, optional
            The time (default: ``clock()``).

        Returns
        -------
        bool
            Whether a burst is still open.
        """
        now = self.clock() if now is None else now
        with self.lock:
            if self.burst_start is None:
                self.thread = None
                return False
            active = self.active_since is not None
            self._announce_if_due(now if active else self.last_end)
            if active:
                if self.announced and self.live:
                    self._write("\r\033[K" + self._fit(f"{self._first_line()} ...",
                                                        f" {duration(now - self.burst_start)}"))
                    self.drawn = True
                return True
            if now - self.last_end < self.gap:
                return True
            self.close()
            self.thread = None  # the ticking thread ends; the next burst starts another
            return False

    def close(self) -> None:
        """End the open burst (at the latest at exit): its last line, if its first was written."""
        with self.lock:
            if self.burst_start is None:
                return
            stopped = self.active_since is not None  # the process ends in a compile (Ctrl-C)
            end = self.clock() if stopped else self.last_end
            self._announce_if_due(end)
            if self.announced:
                self._erase()
                what = "sailmujoco's numba kernels" if self.bursts == 1 else "more kernels"
                took = duration(end - self.burst_start)
                self._write(f"stopped compiling {what} after {took}\n" if stopped
                            else f"compiled {what} in {took}\n")
            self.burst_start = self.active_since = self.last_end = None
            self.announced = False

    def _announce_if_due(self, until: float) -> None:
        """The burst's first line once it has lasted ``announce_after`` (a live one is drawn by
        :meth:`poll`)."""
        if self.announced or until - self.burst_start < self.announce_after:
            return
        self.announced = True
        self.bursts += 1
        if not self.live:
            self._write(f"{self._first_line()} ...\n")

    def _fit(self, text: str, suffix: str) -> str:
        """``text + suffix`` cut to the terminal's width (a wrapped line cannot be redrawn)."""
        try:
            width = os.get_terminal_size(self.stream.fileno()).columns
        except (AttributeError, ValueError, OSError, io.UnsupportedOperation):
            width = 80
        room = max(width - 1 - len(suffix), 8)
        return (text if len(text) <= room else text[:room - 1] + "…") + suffix

    def _first_line(self) -> str:
        return FIRST if self.bursts <= 1 else MORE

    def _erase(self) -> None:
        if self.drawn:
            self._write("\r\033[K")
            self.drawn = False

    def _write(self, text: str) -> None:
        if quiet():  # set while a burst was open: nothing more from it
            return
        try:
            self.stream.write(text)
            self.stream.flush()
        except (ValueError, OSError):  # a closed stream at exit: nothing to tell
            pass

    def _start_thread(self) -> None:
        """Start the ticking thread (under ``lock``, with none running)."""
        if not self.exit_hook:
            atexit.register(self.close)
            self.exit_hook = True

        def tick():
            while True:
                time.sleep(TICK_S)
                if not self.poll():
                    return

        self.thread = threading.Thread(target=tick, name="sailmujoco-compile-notice", daemon=True)
        self.thread.start()


NOTICE = CompileNotice()
_INSTALLED = []


def install() -> None:
    """Register the notice with numba's ``numba:compile`` events (once per process)."""
    if _INSTALLED:
        return
    from numba.core import event

    class Listener(event.Listener):
        def on_start(self, evt):
            NOTICE.start(kind(evt.data.get("dispatcher") if evt.data else None))

        def on_end(self, evt):
            NOTICE.end()

    listener = Listener()
    event.register("numba:compile", listener)
    _INSTALLED.append(listener)
