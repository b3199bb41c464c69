"""Where runs execute: :class:`Engine`, one worker pool (an embedded Dask LocalCluster, an
existing Dask scheduler, or this process) shared by any number of sweeps and job lists."""

from __future__ import annotations

import itertools
import logging
import os

from .. import __version__
from .errors import SweepError, check_count

CONNECT_TIMEOUT_S = 3.0  # to reach a Dask scheduler given by address
# worker processes of an embedded cluster: more than a few per core only queue for the cores and
# cost memory (--workers 100000 tried to start as many processes and hung)
MAX_LOCAL_WORKERS = 4 * (os.cpu_count() or 1)


def _connect(address: str):
    """A Dask client of the scheduler at ``address``, or one line saying it cannot be reached."""
    from dask.distributed import Client

    _quiet_dask()
    try:
        return Client(address, timeout=CONNECT_TIMEOUT_S)
    except Exception as err:  # OSError (timeout, refused), ValueError (malformed), DNS errors
        why = (str(err).strip().splitlines() or [type(err).__name__])[0][:120]
        raise SweepError(f"cannot reach the Dask scheduler at {address!r} within "
                         f"{CONNECT_TIMEOUT_S:g} s ({why}); check --scheduler, or leave it out for "
                         "the embedded cluster") from None


def _quiet_dask() -> None:
    for name in ("distributed", "distributed.scheduler", "distributed.nanny", "distributed.worker",
                 "distributed.client", "distributed.core", "distributed.comm"):
        logging.getLogger(name).setLevel(logging.ERROR)


def _with_retries(task, r: dict, retries: int, again) -> dict:
    record = task(r)
    attempt = 0
    while record["status"] == "failed" and again(record) and attempt < retries:
        attempt += 1
        record = task(r)
    record["attempts"] = attempt + 1
    return record


_BATCHES = itertools.count()


class Engine:
    """Where runs execute, shared by any number of sweeps and job lists (one worker pool).

    ``scheduler``: ``None``, an embedded Dask LocalCluster of ``workers`` processes (``None``
    or 0: one per core), started on first use and kept until :meth:`close`; ``"serial"``: in
    this process; ``"tcp://host:port"``: an existing Dask scheduler, reached now (within
    ``CONNECT_TIMEOUT_S``, else a one-line :class:`SweepError`). A context manager.

    Parameters
    ----------
    scheduler : str, optional
        None (an embedded cluster), ``"serial"`` or a scheduler's address.
    workers : int, optional
        Worker processes of the embedded cluster (None or 0: one per core).
    """

    def __init__(self, scheduler: str | None = None, workers: int | None = None):
        self.check(scheduler, workers)
        self.scheduler, self.workers = scheduler, workers
        self._client = self._cluster = None
        if not self.serial and scheduler is not None:
            self._client = _connect(scheduler)

    @staticmethod
    def check(scheduler, workers) -> None:
        """Refuse, in one line, a scheduler or a worker count the engine cannot take.

        Parameters
        ----------
        scheduler : str or None
            As :class:`Engine` takes it.
        workers : int or None
            As :class:`Engine` takes it.
        """
        check_count("workers", workers, "(0: all cores)", none_ok=True, high=MAX_LOCAL_WORKERS)
        if scheduler is not None and not isinstance(scheduler, str):
            raise SweepError(f"scheduler must be an address tcp://host:port, 'serial' or None, "
                             f"got {scheduler!r}")

    @property
    def serial(self) -> bool:
        """Whether runs execute in this process."""
        return self.scheduler == "serial"

    @property
    def started(self) -> bool:
        """Whether a Dask client is open (an embedded cluster starts on the first runs)."""
        return self._client is not None

    def client(self):
        """The Dask client (starting the embedded cluster on the first call)."""
        if self._client is None:
            from dask.distributed import Client, LocalCluster

            _quiet_dask()
            # Ctrl-C reaches every process of the terminal's group: the worker processes are
            # started with SIGINT ignored (a child keeps an ignored signal, and Python then
            # installs no KeyboardInterrupt handler), so only this process stops, closes the
            # cluster and says so in one line instead of each worker printing its traceback. The
            # scheduler's HTTP server takes a free port (":0"), not 8787, which a second cluster
            # on the machine holds.
            previous = _ignore_sigint()
            try:
                self._cluster = LocalCluster(n_workers=self.workers or os.cpu_count() or 1,
                                             threads_per_worker=1, processes=True,
                                             dashboard_address=None,
                                             scheduler_kwargs={"dashboard_address": ":0"},
                                             silence_logs=logging.ERROR)
            finally:
                _restore_sigint(previous)
            self._client = Client(self._cluster)
        return self._client

    def close(self) -> None:
        """Close the Dask client and the embedded cluster, if open."""
        if self._client is not None:
            self._client.close()
        if self._cluster is not None:
            self._cluster.close()
        self._client = self._cluster = None

    def __enter__(self) -> Engine:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def execute(self, items: list[tuple], bar) -> None:
        """For each ``(task, r, store, retries, again)`` of ``items``: ``task(r)`` (a record
        with ``status``), tried again, up to ``retries`` times, while it fails and
        ``again(record)`` says a new attempt could end otherwise; each final record is written
        to its ``store`` as it finishes (and counted on ``bar``).

        A task that raises in its worker is recorded as failed by the task itself; only an
        exception from the cluster (the worker died: ``KilledWorker``; its connection closed;
        the task could not be run) comes back here, and is recorded as ``lost``.

        Parameters
        ----------
        items : list of tuple
            ``(task, r, store, retries, again)``: a picklable function, its argument (with a
            ``run_id``), the :class:`~sailmujoco.sweep.store.ResultStore` of its record, the
            extra attempts it gets, and which failed records get them (a function of the
            record; a sweep's: :func:`~sailmujoco.sweep.errors.lost`).
        bar : Progress
            Counts each finished record (``bar.update(status=1)``).
        """
        if self.serial:
            for task, r, store, retries, again in items:
                record = _with_retries(task, r, retries, again)
                store.write(record)
                bar.update(**{record["status"]: 1})
        elif items:
            self._run_dask(items, bar)

    def _run_dask(self, items, bar):
        from dask.distributed import as_completed

        client = self.client()
        batch = f"{os.getpid()}-{next(_BATCHES)}"  # keys unique over the batches of one client
        attempts = [1] * len(items)
        owner = {}
        pending = []
        for i, (task, r, *_) in enumerate(items):
            future = client.submit(task, r, key=f"run-{batch}-{i}-{r['run_id']}-0", pure=False)
            owner[future.key] = i
            pending.append(future)
        queue = as_completed(pending)
        for future in queue:
            i = owner[future.key]
            task, r, store, retries, again = items[i]
            try:
                record = future.result()
            except Exception as err:  # a worker died too often, or the task could not run
                record = {**r, "status": "failed", "error": f"{type(err).__name__}: {err}",
                          "lost": True, "metrics": {}, "version": __version__,
                          "wall_time": float("nan")}
            if record["status"] == "failed" and again(record) and attempts[i] <= retries:
                n = attempts[i]
                attempts[i] = n + 1
                retry = client.submit(task, r, key=f"run-{batch}-{i}-{r['run_id']}-{n}", pure=False)
                owner[retry.key] = i
                queue.add(retry)
                continue
            record["attempts"] = attempts[i]
            store.write(record)
            bar.update(**{record["status"]: 1})


def _ignore_sigint():
    """Ignore SIGINT (in the main thread only; elsewhere nothing); return what to restore."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        return None
    return signal.signal(signal.SIGINT, signal.SIG_IGN)


def _restore_sigint(previous) -> None:
    import signal

    if previous is not None:
        signal.signal(signal.SIGINT, previous)
