"""Population evaluation over an executor (seed 001's GA / NSGA-II populations, labrig.fit.hammerstein).

``PopulationMap(fn, args, executor)(X)`` splits the population X (P, n) into chunks, evaluates
``fn(chunk, *args) -> (p, k)`` for each chunk and stacks the results in order. ``fn`` must be a
module-level function and ``args`` plain picklable values: they travel to other processes or machines.

Executors:
* ``"auto"`` (default): a local ProcessPoolExecutor, created on first use, when P >= ``pool_min_rows``;
  in-process below that: the vectorised time loop costs per numpy call, not per row, so a population
  of 100 takes as long as half of it and shipping chunks only adds (bench/hammerstein.py);
* ``"inline"``: always in-process;  ``"process"``: always the local pool;
* any ``concurrent.futures.Executor`` you pass (you keep ownership; args are pickled every call);
* a ``dask.distributed.Client``: args are scattered once (each under a key of its own) and chunks go through
  ``client.map`` / ``client.gather``; recognised by duck typing, so dask is imported only by its user.
For a local pool, args are installed once per worker by the pool initializer rather than per call.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from concurrent.futures import Executor, ProcessPoolExecutor
from typing import Any

import numpy as np

_WORKER_ARGS: dict[int, tuple] = {}  # in a pool worker: key -> args installed by the initializer


def _install(key: int, args: tuple) -> None:
    _WORKER_ARGS[key] = args


def _run_installed(fn: Callable, key: int, X: np.ndarray) -> np.ndarray:
    return fn(X, *_WORKER_ARGS[key])


def _run(fn: Callable, X: np.ndarray, *args: Any) -> np.ndarray:
    return fn(X, *args)


def is_dask_client(obj: Any) -> bool:
    return all(hasattr(obj, a) for a in ("scatter", "gather", "map", "scheduler_info"))


class PopulationMap:
    """Callable X (P, n) -> fn(X, *args) evaluated chunk-wise over an executor; counts rows evaluated."""

    def __init__(
        self,
        fn: Callable[..., np.ndarray],
        args: tuple = (),
        executor: Any = "auto",
        *,
        n_workers: int | None = None,
        pool_min_rows: int = 300,
        min_chunk: int = 8,
        max_chunk: int = 256,
    ) -> None:
        self.fn, self.args, self.executor = fn, tuple(args), executor
        self.n_workers = n_workers or os.cpu_count() or 1
        self.pool_min_rows, self.min_chunk, self.max_chunk = pool_min_rows, min_chunk, max_chunk
        self.n_evals = 0
        self._pool: ProcessPoolExecutor | None = None
        self._scattered: list | None = None
        if executor is None:
            self.executor = "auto"
        if isinstance(self.executor, str) and self.executor not in ("auto", "inline", "process"):
            raise ValueError(f"unknown executor {executor!r} (auto, inline, process, an Executor or a dask Client)")

    # -- chunking -------------------------------------------------------------------------------
    def _chunks(self, X: np.ndarray, n_workers: int) -> list[np.ndarray]:
        """One chunk per worker (not fewer than min_chunk rows each), more if a chunk would pass max_chunk."""
        n = max(1, min(n_workers, len(X) // self.min_chunk), -(-len(X) // self.max_chunk))
        return [c for c in np.array_split(X, n) if len(c)]

    def _local_pool(self) -> ProcessPoolExecutor:
        if self._pool is None:
            key = id(self)
            self._pool = ProcessPoolExecutor(self.n_workers, initializer=_install, initargs=(key, self.args))
        return self._pool

    def __call__(self, X: np.ndarray) -> np.ndarray:
        X = np.atleast_2d(np.asarray(X, float))
        self.n_evals += len(X)
        ex = self.executor
        if ex == "inline" or (ex == "auto" and len(X) < self.pool_min_rows):
            # in bounded chunks: a few hundred candidates' (P, R, N) arrays already fill the caches
            step = self.max_chunk
            return np.concatenate([self.fn(X[s:s + step], *self.args) for s in range(0, len(X), step)])
        if ex in ("auto", "process"):
            chunks = self._chunks(X, self.n_workers)
            pool = self._local_pool()
            parts = list(pool.map(_run_installed, [self.fn] * len(chunks), [id(self)] * len(chunks), chunks))
        elif is_dask_client(ex):
            if self._scattered is None:  # ship the data once; later calls pass futures. A key of its own
                # (hash=False): a content-hashed key is shared with an earlier map of the same data, whose release can
                # forget it mid-scatter ("lost dependencies"); no broadcast (replicate() is fragile, dask/distributed
                # #6578): each worker fetches it once, with its first chunk
                self._scattered = [ex.scatter(a, hash=False) for a in self.args]
            n = sum(w.get("nthreads", 1) for w in ex.scheduler_info()["workers"].values()) or 1
            chunks = self._chunks(X, n)
            futs = [ex.submit(_run, self.fn, c, *self._scattered, pure=False) for c in chunks]
            parts = ex.gather(futs)
        elif isinstance(ex, Executor):
            chunks = self._chunks(X, self.n_workers)
            parts = [f.result() for f in [ex.submit(_run, self.fn, c, *self.args) for c in chunks]]
        else:
            raise TypeError(f"executor {ex!r} is neither an Executor nor a dask Client")
        return np.concatenate(parts, axis=0)

    def close(self) -> None:
        """Shut down the pool this object created (never a user's executor or client)."""
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None
        self._scattered = None

    def __enter__(self) -> "PopulationMap":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
