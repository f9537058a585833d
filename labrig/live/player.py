"""A recorded session's event stream with its original timing, for ``labrig replay --live``.

Times are rig-clock seconds: a step starts at its stored ``t_start`` and ends at ``t_end``; the rows of
a time series are released as their ``t_s`` passes (in slices of ``slice_s``), an impedance spectrum
arrives when its step ends (as the runner emits it). ``play`` sleeps ``dt / speed`` between events
(``speed`` 0: no sleeping at all).
"""

from __future__ import annotations

import math
import threading
import time
from typing import Callable, Iterator

import numpy as np

from labrig.events import Block, Column, Event, RunStart, RunStop, StepEnd, StepPlan, StepStart, StreamSpec
from labrig.store.reader import SessionReader


def _spec(name: str, data) -> StreamSpec:
    cols = tuple(Column(c, data.units.get(c, "")) for c in data)
    return StreamSpec(name, cols, data.signal, data.axis, data.expected_rows)


def session_events(path: str, slice_s: float = 0.25) -> list[tuple[float, Event]]:
    """Every event of the session at its rig time, in order (read into memory: sessions are per run)."""
    out: list[tuple[float, Event]] = []
    with SessionReader(path) as r:
        uid, steps = r.uid, r.steps()
        streams = {s.index: {name: r.stream(s, name) for name in s.rows} for s in steps}
        plans = tuple(StepPlan(s.index, s.name, s.kind, s.metadata, tuple(_spec(n, d) for n, d in streams[s.index].items())) for s in steps)
        started = [s.t_start for s in steps if math.isfinite(s.t_start)]
        t_first = min(started) if started else 0.0
        out.append((t_first, RunStart(uid, r.protocol, r.config, r.rig, r.sample, r.software, plans, t=t_first)))
        t_last = t_first
        for s in steps:
            if not math.isfinite(s.t_start):
                continue  # never started
            t_end = s.t_end if math.isfinite(s.t_end) else s.t_start
            out.append((s.t_start, StepStart(uid, s.index, s.t_start)))
            for name, data in streams[s.index].items():
                out.extend(_blocks(uid, s.index, name, data, s.t_start, t_end, slice_s))
            if s.status not in ("planned", "running"):
                out.append((t_end, StepEnd(uid, s.index, s.status, t_end, s.summary)))  # type: ignore[arg-type]
            t_last = max(t_last, t_end)
        status = r.exit_status
        if status is not None:
            out.append((t_last, RunStop(uid, status, r.reason, t_last)))  # type: ignore[arg-type]
    out.sort(key=lambda p: p[0])  # stable: a step's start stays before its blocks and its end
    return out


def _blocks(uid: str, index: int, name: str, data, t0: float, t_end: float, slice_s: float) -> Iterator[tuple[float, Block]]:
    n = data.rows
    if n == 0:
        return
    if "t_s" not in data:  # a spectrum: the runner emits it whole when the sweep is done
        yield t_end, Block(uid, index, name, {c: np.asarray(v) for c, v in data.items()})
        return
    t = np.asarray(data["t_s"])
    edges = np.searchsorted(t, np.arange(slice_s, t[-1] + slice_s, slice_s), side="right")
    start, seq = 0, 0
    for stop in [*edges, n]:
        if stop <= start:
            continue
        yield min(t0 + float(t[stop - 1]), t_end), Block(uid, index, name, {c: np.asarray(v[start:stop]) for c, v in data.items()}, seq=seq)
        start, seq = stop, seq + 1


def play(events: list[tuple[float, Event]], sink: Callable[[Event], None], speed: float = 1.0,
         stop: threading.Event | None = None) -> int:
    """Feed ``events`` to ``sink`` at ``speed`` x their rig-time spacing; returns how many were sent."""
    if not events:
        return 0
    t0, wall0 = events[0][0], time.monotonic()
    sent = 0
    for t, ev in events:
        if stop is not None and stop.is_set():
            break
        if speed > 0:
            delay = (t - t0) / speed - (time.monotonic() - wall0)
            if delay > 0:
                if stop is not None:
                    stop.wait(delay)
                else:
                    time.sleep(delay)
        sink(ev)
        sent += 1
    return sent
