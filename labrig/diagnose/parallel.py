"""The catalogue's candidates scored on every core the process may use.

Each effect's family is fitted and scored independently of the others, and the fits are single-threaded numpy and
scipy: on the 2-core machine half the diagnosis' wall time is the second core. Workers are forked, so they start
with the scorer's contexts and caches as they are and nothing is sent to them but an effect's name; what comes back
is a candidate with its form as an index into the family (some forms are closures, which do not pickle).

``LABRIG_DIAGNOSE_WORKERS`` sets the number of workers (1: in this process, as before). Where forking is not
possible (no fork start method, or a daemonic process, which may not have children) the scoring runs in this
process; a worker lost on the way does the same, so the answer never depends on the pool.
"""

from __future__ import annotations

import multiprocessing
import os
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from typing import Any

_TASK: Callable[[Any], Any] | None = None  # what forked workers run: set just before the pool forks them


def workers() -> int:
    """Workers for a scoring round: ``LABRIG_DIAGNOSE_WORKERS``, else the cores this process may use (at most 4)."""
    env = os.environ.get("LABRIG_DIAGNOSE_WORKERS", "").strip()
    if env:
        return max(1, int(env))
    return max(1, min(4, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)))


def _run(item: Any) -> Any:
    assert _TASK is not None
    return _TASK(item)


def forked_map(fn: Callable[[Any], Any], items: Sequence[Any]) -> list[Any]:
    """``[fn(x) for x in items]``, in order, over forked workers when more than one is allowed."""
    global _TASK
    n = min(workers(), len(items))
    if n < 2 or "fork" not in multiprocessing.get_all_start_methods() or multiprocessing.current_process().daemon:
        return [fn(x) for x in items]
    _TASK = fn
    try:
        with ProcessPoolExecutor(n, mp_context=multiprocessing.get_context("fork")) as pool:
            return list(pool.map(_run, items))
    except (BrokenProcessPool, OSError):
        return [fn(x) for x in items]
    finally:
        _TASK = None
