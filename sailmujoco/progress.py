"""Progress of a long job: a tqdm bar on a terminal, a few plain lines anywhere else.

A carriage-return bar written to a file (a batch job's log, CI) becomes thousands of half
lines, so where the stream is not a terminal :class:`Progress` prints one plain line per
milestone instead (every ``every`` percent of the total, and at the end)::

    bar = Progress(len(runs), "sweep lphi", stream=sys.stderr)
    for record in results:
        bar.update(**{record["status"]: 1})   # counts by name: ok, stopped, failed, ...
    bar.close()

gives, in a log, lines such as
``sweep lphi: 50/100 (50 %), ok 47, stopped 2, failed 1; 12 s elapsed, about 12 s left``.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Mapping


def is_terminal(stream) -> bool:
    """Whether ``stream`` is an interactive terminal (what tqdm's ``disable=None`` checks).

    Parameters
    ----------
    stream : file
        The stream.
    """
    isatty = getattr(stream, "isatty", None)
    try:
        return bool(isatty and isatty())
    except (ValueError, OSError):  # a closed or detached stream
        return False


def duration(seconds: float) -> str:
    """A duration as a person reads it: ``"42 s"``, ``"7 min"``, ``"2.5 h"``, ``"?"`` if unknown.

    Parameters
    ----------
    seconds : float
        The duration, s.
    """
    if not math.isfinite(seconds):
        return "?"
    seconds = max(0.0, seconds)
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


class Progress:
    """Done out of ``total`` with named counts and the time left.

    Parameters
    ----------
    total : int
        Units of work in all (runs, studies, frames).
    label : str
        What is counted, first on every line.
    stream : file
        Where to write (default ``sys.stderr``). A terminal gets a tqdm bar; anything else
        plain lines at the milestones.
    initial : int
        Units already done (a resumed sweep), counted in the fraction but not in the rate.
    show : bool
        ``False``: write nothing.
    unit : str
        The unit's name on the bar.
    every : float
        Percent of ``total`` between two plain lines (10: at most about 10 lines).
    counts : mapping or sequence of str
        Counts shown from the start (a mapping: with these values; names: as 0), in this order;
        others appear when first updated.
    """

    def __init__(self, total: int, label: str, stream=None, *, initial: int = 0, show: bool = True,
                 unit: str = "run", every: float = 10.0, counts=()):
        self.total = int(total)
        self.label = label
        self.stream = sys.stderr if stream is None else stream
        self.done = int(initial)
        self.initial = int(initial)
        self.counts = dict(counts) if isinstance(counts, Mapping) else dict.fromkeys(counts, 0)
        self.show = show
        self.every = float(every)
        self.start = time.perf_counter()
        self.bar = None
        self.printed = None  # `done` at the last plain line
        self.closed = False
        if show and is_terminal(self.stream):
            from tqdm import tqdm

            self.bar = tqdm(total=self.total, initial=self.initial, desc=label, unit=unit,
                            file=self.stream, dynamic_ncols=True)
            if self.counts:
                self.bar.set_postfix(self.counts, refresh=False)

    def update(self, n: int = 1, **counts: int) -> None:
        """``n`` more units done; ``counts`` add to the named tallies (e.g. ``stopped=1``).

        Parameters
        ----------
        n : int
            Units done.
        **counts : int
            Added to the named tallies.
        """
        self.done += n
        for name, value in counts.items():
            self.counts[name] = self.counts.get(name, 0) + value
        if self.bar is not None:
            if self.counts:
                self.bar.set_postfix(self.counts, refresh=False)
            self.bar.update(n)
        elif self.show and self._milestone():
            self._line()

    def _milestone(self) -> bool:
        if self.total <= 0:
            return False
        step = max(1.0, self.total * self.every / 100.0)
        last = self.initial if self.printed is None else self.printed
        return self.done >= self.total or math.floor(self.done / step) > math.floor(last / step)

    def line(self) -> str:
        """The plain progress line as it stands."""
        elapsed = time.perf_counter() - self.start
        fraction = self.done / self.total if self.total > 0 else 1.0
        text = f"{self.label}: {self.done}/{self.total} ({100 * fraction:.0f} %)"
        if self.counts:
            text += ", " + ", ".join(f"{name} {value}" for name, value in self.counts.items())
        text += f"; {duration(elapsed)} elapsed"
        new = self.done - self.initial
        if 0 < new and self.done < self.total:
            text += f", about {duration(elapsed / new * (self.total - self.done))} left"
        return text

    def _line(self) -> None:
        print(self.line(), file=self.stream, flush=True)
        self.printed = self.done

    def close(self) -> None:
        """End the bar; off a terminal, print the final line unless it is already out."""
        if self.closed:
            return
        self.closed = True
        if self.bar is not None:
            self.bar.close()
        elif self.show and self.printed != self.done:
            self._line()

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
