"""Scale-out on a dask.distributed cluster: connect, and run a batch of sessions one task per session.

``--scheduler ADDRESS`` (or the environment variable ``DASK_SCHEDULER_ADDRESS``) names a running scheduler
(``dask scheduler`` + ``dask worker ADDRESS`` on each machine, or any dask deployment). With one session, the
GA / NSGA-II populations go to the cluster (labrig.fit.executors.PopulationMap); with several, each session is
one task and its populations run in the worker that has it. Workers read the session files by path (a shared
filesystem); results come back to the client, which alone writes them into the files: a task that is retried
after its worker died never writes twice.

No session is lost when a worker dies: the scheduler reschedules the tasks that worker held (up to its
``allowed-failures``), and a task that raises is retried ``retries`` times before its error is reported for that
session only.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from labrig.errors import BadInput

ENV = "DASK_SCHEDULER_ADDRESS"


def scheduler_address(option: str | None) -> str | None:
    return option or os.environ.get(ENV) or None


def connect(address: str | None, timeout_s: float = 10.0) -> Any:
    """A dask Client on ``address`` (or None without one); one clear line when dask is missing or unreachable."""
    if not address:
        return None
    try:
        from distributed import Client
    except ImportError:
        raise BadInput("--scheduler needs dask.distributed: pip install 'labrig[cluster]'") from None
    try:
        return Client(address, timeout=timeout_s)
    except (OSError, TimeoutError) as exc:
        raise BadInput(f"--scheduler {address}: cannot reach the dask scheduler ({exc})") from None


@dataclass
class Outcome:
    """One session's result, or the one-line reason it has none."""

    path: str
    result: Any = None
    error: str | None = None
    bad_input: bool = False


def _call(fn: Callable, path: str, kwargs: dict) -> Outcome:
    try:
        return Outcome(path, fn(path, **kwargs))
    except BadInput as exc:  # bad input is that session's answer, not a failure to retry
        return Outcome(path, error=str(exc), bad_input=True)


def run_batch(fn: Callable[..., Any], paths: list[str], client: Any = None, retries: int = 2, **kwargs: Any) -> list[Outcome]:
    """``fn(path, **kwargs)`` for every path, in order, one Outcome each. On ``client`` every path is a task
    (``retries`` on an exception; a dead worker's tasks are rescheduled by dask); without one, in turn here."""
    if client is None:
        return [_call(fn, p, kwargs) for p in paths]
    futures = [client.submit(_call, fn, p, kwargs, retries=retries, pure=False) for p in paths]
    out = []
    for p, fut in zip(paths, futures):
        try:
            out.append(fut.result())
        except Exception as exc:  # retries used up, or the task killed every worker it ran on
            out.append(Outcome(p, error=f"{p}: failed on the cluster ({type(exc).__name__}: {exc})"))
    return out
