"""Where runs are kept: ``<out>/runs/<run_id>.json`` (written atomically), the consolidated
Parquet/CSV table, and the lossless JSON form of a job's values (:func:`encode`, :func:`decode`)."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np

from .errors import SweepError
from .spec import NAMESPACES, plain


class ResultStore:
    """``<out>/runs/<run_id>.json``, written atomically; a consolidated Parquet/CSV table.

    Parameters
    ----------
    out : str or Path
        The results folder (made if missing).
    indent : int or None
        JSON indent of the records (None: one line, for a job's long results).
    """

    def __init__(self, out, indent: int | None = 1):
        self.out = Path(out)
        self.indent = indent  # None: one line (a job's result can hold long trajectories)
        self.runs_dir = self.out / "runs"
        try:
            self.runs_dir.mkdir(parents=True, exist_ok=True)
        except (FileExistsError, NotADirectoryError):
            raise SweepError(f"results folder {str(self.out)!r} is (or lies under) a file, "
                             "not a folder") from None
        except OSError as err:  # no permission, a read-only or virtual file system
            raise SweepError(f"cannot make the results folder {str(self.out)!r}: "
                             f"{err.strerror}") from None

    def path(self, rid: str) -> Path:
        """The record file of run ``rid``.

        Parameters
        ----------
        rid : str
            A run id (:func:`~sailmujoco.sweep.spec.run_id`, :func:`~sailmujoco.sweep.runs.job_id`).
        """
        return self.runs_dir / f"{rid}.json"

    def write(self, record: dict) -> None:
        """Write ``record`` atomically (a temporary file, then renamed over the record's file).

        Parameters
        ----------
        record : dict
            A run's record, with its ``run_id``.
        """
        tmp = self.runs_dir / f".{record['run_id']}.{os.getpid()}.tmp"
        tmp.write_text(json.dumps(record, default=plain, indent=self.indent))
        os.replace(tmp, self.path(record["run_id"]))

    def done(self) -> dict:
        """``{run_id: record}`` of every record stored."""
        out = {}
        for path in self.runs_dir.glob("*.json"):
            try:
                record = json.loads(path.read_text())
            except (OSError, json.JSONDecodeError):
                continue  # a torn file cannot exist (atomic writes), but be safe: rerun it
            out[record["run_id"]] = record
        return out

    def table(self, metrics: list | None = None, run_ids=None):
        """The consolidated table (pandas DataFrame), one row per run (of ``run_ids`` only, when
        given: the runs of one sweep).

        Parameters
        ----------
        metrics : list of str, optional
            The metric columns kept (default: every metric).
        run_ids : iterable of str, optional
            The runs kept (default: every run stored).
        """
        import pandas as pd

        rows = []
        keep = None if run_ids is None else set(run_ids)
        for record in sorted(self.done().values(), key=lambda r: r.get("index", 0)):
            if keep is not None and record["run_id"] not in keep:
                continue
            row = {"sweep_id": record.get("sweep_id"), "spec_hash": record.get("spec_hash")}
            row.update({k: record[k] for k in ("run_id", "boat", "task", "world", "controller", "seed",
                                               "status", "error", "wall_time")})
            row["attempts"] = record.get("attempts")
            row["version"] = record["version"]
            for ns in NAMESPACES:
                for k, v in record.get(f"{ns}_options", {}).items():
                    row[f"{ns}.{k}"] = v
            for k, v in record.get("metrics", {}).items():
                if metrics is None or k in metrics:
                    row[k] = v
            rows.append(row)
        return pd.DataFrame(rows)

    def consolidate(self, metrics: list | None = None, run_ids=None) -> Path:
        """Write :meth:`table` to ``results.parquet`` (atomically) and ``results.csv``; return
        the Parquet file's path.

        Parameters
        ----------
        metrics, run_ids
            As :meth:`table`.
        """
        frame = self.table(metrics, run_ids)
        path = self.out / "results.parquet"
        tmp = self.out / ".results.parquet.tmp"
        frame.to_parquet(tmp, index=False)
        os.replace(tmp, path)
        frame.to_csv(self.out / "results.csv", index=False)
        return path


def encode(value):
    """``value`` as plain JSON (dict keys strings, lists, numbers, text, None), losslessly:
    tuples, dicts with other keys, numpy scalars and arrays and pandas DataFrames are tagged
    (``{"__tuple__": [...]}``, ...) so that :func:`decode` gives them back; floats keep every
    bit (JSON writes the shortest repr, NaN and infinities as Python's json does).

    Parameters
    ----------
    value : object
        Plain JSON, tuples, dicts, numpy scalars and arrays, pandas DataFrames, nested.
    """
    if isinstance(value, np.generic):  # before float: np.float64 is one (and divides by 0)
        return {"__scalar__": value.item(), "dtype": value.dtype.str}
    if value is None or isinstance(value, (bool, str, int, float)):
        return value
    if isinstance(value, tuple):
        return {"__tuple__": [encode(v) for v in value]}
    if isinstance(value, list):
        return [encode(v) for v in value]
    if isinstance(value, dict):
        if all(isinstance(k, str) for k in value) and not any(k.startswith("__") for k in value):
            return {k: encode(v) for k, v in value.items()}
        return {"__dict__": [[encode(k), encode(v)] for k, v in value.items()]}
    if isinstance(value, np.ndarray):
        return {"__array__": encode(value.tolist()), "dtype": value.dtype.str,
                "shape": list(value.shape)}
    import pandas as pd

    if isinstance(value, pd.DataFrame):
        if (not value.index.equals(pd.RangeIndex(len(value)))
                or not all(isinstance(c, str) for c in value.columns) or not value.columns.is_unique):
            raise SweepError("a DataFrame in a job's value must have the default index and "
                             "distinct text column names")
        return {"__frame__": {c: encode(value[c].to_numpy()) for c in value.columns},
                "columns": list(value.columns)}
    raise SweepError(f"a job's value of type {type(value).__name__} cannot be stored "
                     "(plain JSON, tuples, numpy, pandas DataFrames)")


def decode(value):
    """The inverse of :func:`encode`.

    Parameters
    ----------
    value : object
        What :func:`encode` gave (after a JSON round trip).
    """
    if isinstance(value, list):
        return [decode(v) for v in value]
    if not isinstance(value, dict):
        return value
    if "__scalar__" in value:
        return np.dtype(value["dtype"]).type(value["__scalar__"])
    if "__tuple__" in value:
        return tuple(decode(v) for v in value["__tuple__"])
    if "__dict__" in value:
        return {decode(k): decode(v) for k, v in value["__dict__"]}
    if "__array__" in value:
        dtype = np.dtype(value["dtype"])
        data = decode(value["__array__"])
        if dtype.kind == "O":
            out = np.empty(len(data), dtype=object)
            out[:] = data
            return out.reshape(value["shape"])
        return np.array(data, dtype=dtype).reshape(value["shape"])
    if "__frame__" in value:
        import pandas as pd

        return pd.DataFrame({c: decode(value["__frame__"][c]) for c in value["columns"]},
                            columns=value["columns"])
    return {k: decode(v) for k, v in value.items()}
