"""What every study shares: running an episode, the Markdown report, progress.

A study is a module of this package with::

    NAME = "saoud_fig6"
    TITLE = "..."
    def run(out: Path, smoke: bool = False, workers: int | None = None,
            progress: bool = True, video: bool = False) -> dict

``run`` writes PNG figures, CSV data and ``report.md`` into ``out`` (results/<study>/) and
returns the headline numbers (the tests assert on them in smoke mode). It is registered under
the ``sailmujoco.studies`` entry points, so ``sailmujoco study NAME`` finds it.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path

from sailmujoco import suite, sweep
from sailmujoco.progress import Progress

from . import verdict


def run_episode(boat: str, task: str, world: str, controller, *, seed: int = 0,
                controller_options: dict | None = None, **options):
    """One episode; returns (metrics dict, per-step DataFrame, env).

    ``controller`` is a registered name (see ``sailmujoco.sweep.controller_factories``) or a
    callable ``factory(env) -> controller``. ``options`` go to :func:`sailmujoco.suite.load`.
    """
    env = suite.load(boat, task, world, seed=seed, **options)
    if isinstance(controller, str):
        policy = sweep.make_controller(controller, env, **(controller_options or {}))
    else:
        policy = controller(env)
    trajectory = suite.rollout(env, policy)
    return env.task.metrics(), trajectory, env


@dataclass
class Report:
    """A Markdown report: paragraphs, tables of paper vs ours, figures."""

    title: str
    parts: list = field(default_factory=list)

    def paragraph(self, text: str) -> None:
        self.parts.append(text.strip() + "\n")

    def table(self, rows: list[dict], columns: list[str] | None = None) -> None:
        if not rows:
            return
        columns = columns or list(rows[0])
        lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
        for row in rows:
            lines.append("| " + " | ".join(_cell(row.get(c, "")) for c in columns) + " |")
        self.parts.append("\n".join(lines) + "\n")

    def comparison(self, rows: list[dict]) -> None:
        """Rows of quantity / paper / world / ours / cause, with the difference of
        :func:`studies.verdict.difference` (a row may give its ``floor`` and ``unit``), flagged ⚠
        beyond 10 %."""
        table = []
        for row in rows:
            diff = verdict.difference(row["ours"], row.get("paper"), floor=row.get("floor", 0.0),
                                      unit=row.get("unit", ""))
            flag = " ⚠" if diff.finite and diff.beyond(verdict.TOLERANCE) else ""
            table.append({**row, "difference": diff.text() + flag})
        self.table(table, ["quantity", "world", "paper", "ours", "difference", "cause"])
        self.paragraph(verdict.DIFFERENCE_NOTE)

    def figure(self, path: Path, caption: str) -> None:
        self.parts.append(f"![{caption}]({Path(path).name})\n\n*{caption}*\n")

    def write(self, out: Path) -> Path:
        path = Path(out) / "report.md"
        path.write_text(f"# {self.title}\n\n" + "\n".join(self.parts))
        return path


def _cell(value) -> str:
    if value is None:
        return "—"
    if isinstance(value, float):
        if not math.isfinite(value):
            return "—"
        return f"{value:.3g}"
    return str(value).replace("|", "\\|")


def parallel_map(fn, items: list, workers: int | None = None, progress: bool = True,
                 label: str = "simulations") -> list:
    """``[fn(item) for item in items]`` in ``workers`` spawned processes (MuJoCo and numba state
    stay per process; 1 worker: in this process), with a progress bar; results in input order."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    workers = workers or multiprocessing.cpu_count() or 1
    bar = Progress(len(items), label, show=progress, unit="sim")
    results = [None] * len(items)
    if workers <= 1 or len(items) <= 1:
        for i, item in enumerate(items):
            results[i] = fn(item)
            bar.update()
    else:
        context = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=min(workers, len(items)), mp_context=context) as pool:
            futures = {pool.submit(fn, item): i for i, item in enumerate(items)}
            for future in as_completed(futures):
                results[futures[future]] = future.result()
                bar.update()
    bar.close()
    return results


def setup_matplotlib():
    """matplotlib.pyplot for a study's figures (Agg, constrained layout, the package's style)."""
    from sailmujoco import figures

    return figures.pyplot()


def save_figure(fig, path: Path) -> Path:
    """Check (:func:`sailmujoco.figures.problems`), write with nothing clipped, close; returns
    its path."""
    from sailmujoco import figures

    return figures.save(fig, path)


def timer():
    start = time.perf_counter()
    return lambda: time.perf_counter() - start
