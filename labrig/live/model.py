"""What the live window shows, fed from the runner's event stream without ever blocking it.

``LiveModel`` is a runner subscriber. It only copies samples into fixed-size ring buffers and appends
small control records, under a lock held for microseconds; the GUI thread takes snapshots on its own
timer. A GUI that lags therefore draws fewer frames, but every sample reaches the rings (and the store
gets the same events whether or not a window is attached). Drawing uses min/max decimation per pixel
column so a 60 s window at 10 kS/s costs the same as one at 200 S/s.
"""

from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from labrig.events import Block, Event, RunStart, RunStop, StepEnd, StepStart, planned_seconds
from labrig.records import SINE_KINDS

TRACE_COLUMNS = ("v_V", "i_A", "disp_m")  # daq ring columns after the time column
FRF_KINDS = SINE_KINDS  # records demodulated at their frequency_Hz when they finish


class Ring:
    """Fixed-capacity ring of rows of ``width`` float64 columns (oldest rows overwritten)."""

    def __init__(self, capacity: int, width: int):
        self.buf = np.full((width, int(capacity)), np.nan)
        self.capacity = int(capacity)
        self.head = 0  # next write position
        self.size = 0
        self.total = 0  # rows ever appended (never decreases: no sample is skipped)

    def append(self, cols: list[np.ndarray]) -> None:
        n = len(cols[0])
        if n == 0:
            return
        start = max(0, n - self.capacity)  # a block bigger than the ring keeps its newest rows
        k = n - start
        first = min(k, self.capacity - self.head)
        for row, c in zip(self.buf, cols):
            row[self.head : self.head + first] = c[start : start + first]
            row[: k - first] = c[start + first : n]
        self.head = (self.head + k) % self.capacity
        self.size = min(self.capacity, self.size + k)
        self.total += n

    def ordered(self) -> np.ndarray:
        """A (width, size) copy, oldest row first."""
        if self.size < self.capacity:
            return self.buf[:, : self.size].copy()
        return np.concatenate((self.buf[:, self.head :], self.buf[:, : self.head]), axis=1)

    def rows_since(self, cutoff: float) -> int:
        """How many of the newest rows have first column >= ``cutoff`` (column 0 ascending)."""
        if self.size < self.capacity:
            segs = [self.buf[0, : self.size]]
        else:
            segs = [self.buf[0, self.head :], self.buf[0, : self.head]]
        return sum(len(s) - int(np.searchsorted(s, cutoff)) for s in segs)

    def tail_since(self, cutoff: float) -> np.ndarray:
        """A (width, k) copy of the newest rows whose first column is >= ``cutoff``."""
        return self.tail(self.rows_since(cutoff))

    def tail(self, k: int) -> np.ndarray:
        """A (width, k) copy of the newest ``k`` rows, oldest first."""
        k = min(int(k), self.size)
        if k <= self.head:
            return self.buf[:, self.head - k : self.head].copy()
        rest = k - self.head
        return np.concatenate((self.buf[:, self.capacity - rest :], self.buf[:, : self.head]), axis=1)

    def last(self) -> float:
        return float(self.buf[0, self.head - 1]) if self.size else math.nan

    def clear(self) -> None:
        self.head = self.size = 0


def minmax_decimate(x: np.ndarray, y: np.ndarray, bins: int) -> tuple[np.ndarray, np.ndarray]:
    """Down to ~2 points per bin (the min and the max, in the order they occur): peaks stay visible.

    Arrays of at most ``2 * bins`` points come back unchanged. Bins hold equal sample counts, which
    is equal time for a uniformly sampled trace.
    """
    n = len(x)
    if n <= 2 * bins:
        return np.asarray(x, float), np.asarray(y, float)
    per = math.ceil(n / bins)
    m = (n // per) * per
    yy = y[:m].reshape(-1, per)
    lo, hi = np.argmin(yy, axis=1), np.argmax(yy, axis=1)
    first, second = np.minimum(lo, hi), np.maximum(lo, hi)
    base = np.arange(yy.shape[0]) * per
    idx = np.stack((base + first, base + second), axis=1).ravel()
    if m < n:  # the last partial bin
        tail = np.arange(m, n)
        a, b = tail[np.argmin(y[m:])], tail[np.argmax(y[m:])]
        idx = np.concatenate((idx, [min(a, b), max(a, b)]))
    return np.asarray(x, float)[idx], np.asarray(y, float)[idx]


def envelope_decimate(t: np.ndarray, lo: np.ndarray, hi: np.ndarray, bins: int) -> tuple[np.ndarray, np.ndarray]:
    """``minmax_decimate`` for data already reduced to (min, max) pairs: min of mins, max of maxes."""
    n = len(t)
    per = max(1, math.ceil(n / bins))
    pad = (-n) % per
    if pad:  # repeat the last row: it changes neither a min nor a max
        t, lo, hi = (np.concatenate((a, np.repeat(a[-1:], pad))) for a in (t, lo, hi))
    lo2, hi2 = lo.reshape(-1, per), hi.reshape(-1, per)
    a, b = np.argmin(lo2, axis=1), np.argmax(hi2, axis=1)
    tt = t.reshape(-1, per)
    rows = np.arange(lo2.shape[0])
    lo_first = a <= b
    x = np.stack((tt[rows, np.where(lo_first, a, b)], tt[rows, np.where(lo_first, b, a)]), axis=1).ravel()
    y = np.stack((np.where(lo_first, lo2[rows, a], hi2[rows, b]), np.where(lo_first, hi2[rows, b], lo2[rows, a])), axis=1).ravel()
    return x, y


class Envelope:
    """Min/max of every ``group`` consecutive rows (t of the group's first row): what a long window draws."""

    def __init__(self, capacity: int, channels: int, group: int):
        self.group, self.ring = group, Ring(capacity, 1 + 2 * channels)
        self._pending: list[np.ndarray] | None = None

    def append(self, t: np.ndarray, chans: list[np.ndarray]) -> None:
        cols = [np.asarray(t, float), *(np.asarray(c, float) for c in chans)]
        if self._pending is not None:
            cols = [np.concatenate((p, c)) for p, c in zip(self._pending, cols)]
        m = (len(cols[0]) // self.group) * self.group
        self._pending = [c[m:] for c in cols] if m < len(cols[0]) else None
        if m == 0:
            return
        out = [cols[0][:m:self.group]]
        for c in cols[1:]:
            g = c[:m].reshape(-1, self.group)
            out += [g.min(axis=1), g.max(axis=1)]
        self.ring.append(out)


@dataclass
class FrfRecord:
    """A finished sine record waiting to be demodulated (in the GUI thread, not the runner's)."""

    index: int
    name: str
    metadata: dict[str, Any]
    t: np.ndarray
    v: np.ndarray
    i: np.ndarray
    d: np.ndarray


@dataclass
class Snapshot:
    """A consistent copy of what the window needs for one frame."""

    daq: np.ndarray  # (4, n): t, v, i, d (rig seconds, SI); empty when ``envelope`` is given
    envelope: np.ndarray | None  # (7, m): t, then min and max of v, i, d per group (long windows)
    force: np.ndarray  # (2, n): t, force
    eis: list[tuple[float | None, np.ndarray]]  # (pressure_kPa, (3, n) f, z_re, z_im) per spectrum
    frf: list[FrfRecord]  # records finished since the last snapshot
    status: str
    version: int
    finished: bool


@dataclass
class _StepInfo:
    name: str
    kind: str
    metadata: dict[str, Any]
    planned_s: float
    t0: float = math.nan
    done: bool = False
    parts: list[list[np.ndarray]] = field(default_factory=list)  # sine records: daq blocks kept to demodulate


class LiveModel:
    """Runner subscriber that feeds the live window (thread-safe; never blocks for long)."""

    def __init__(self, capacity: int = 1 << 20, force_capacity: int = 1 << 16, group: int = 64, raw_limit: int = 1 << 16):
        self._lock = threading.Lock()
        self.daq = Ring(capacity, 4)
        self.env = Envelope(capacity // group, 3, group)
        self.raw_limit = raw_limit  # windows with more rows than this are drawn from the envelope
        self.force = Ring(force_capacity, 2)
        self.steps: dict[int, _StepInfo] = {}
        self.eis: list[tuple[float | None, np.ndarray]] = []
        self._frf: list[FrfRecord] = []
        self.current: int | None = None
        self.protocol = ""
        self.exit: str | None = None
        self.version = 0
        self._t_run0 = math.nan  # rig clock at RunStart
        self._wall0 = math.nan  # wall clock (monotonic) when RunStart arrived here
        self._rig_now = math.nan

    # ------------------------------------------------------------------ subscriber (runner thread)
    def __call__(self, ev: Event) -> None:
        with self._lock:
            self._take(ev)
            self.version += 1

    def _take(self, ev: Event) -> None:
        if isinstance(ev, RunStart):
            self.steps = {p.index: _StepInfo(p.name, p.kind, dict(p.metadata), planned_seconds(p.kind, p.metadata, p.streams)) for p in ev.steps}
            self.protocol, self.exit = ev.protocol, None
            self._t_run0, self._wall0, self._rig_now = ev.t, time.monotonic(), ev.t
        elif isinstance(ev, StepStart):
            self.current = ev.index
            self.steps[ev.index].t0 = ev.t
            self._rig_now = ev.t
        elif isinstance(ev, Block):
            self._block(ev)
        elif isinstance(ev, StepEnd):
            st = self.steps.get(ev.index)
            if st is not None:
                st.done = True
                self._rig_now = ev.t
                if st.kind in FRF_KINDS and st.parts and ev.status == "done" and "frequency_Hz" in st.metadata:
                    t, v, i, d = (np.concatenate(c) for c in zip(*st.parts))
                    self._frf.append(FrfRecord(ev.index, st.name, st.metadata, t, v, i, d))
                st.parts = []
        elif isinstance(ev, RunStop):
            self.exit = ev.exit_status
            self.current = None

    def _block(self, ev: Block) -> None:
        st = self.steps.get(ev.index)
        t0 = st.t0 if st is not None and not math.isnan(st.t0) else 0.0
        d = ev.data
        if ev.stream == "daq":
            t = np.asarray(d["t_s"], float)
            self.daq.append([t0 + t, d["v_V"], d["i_A"], d["disp_m"]])
            self.env.append(t0 + t, [d["v_V"], d["i_A"], d["disp_m"]])
            if st is not None and st.kind in FRF_KINDS:
                st.parts.append([t, np.asarray(d["v_V"]), np.asarray(d["i_A"]), np.asarray(d["disp_m"])])
            if len(t):
                self._rig_now = max(self._rig_now, t0 + float(t[-1]))
        elif ev.stream == "force":
            self.force.append([t0 + np.asarray(d["t_s"], float), d["force_N"]])
        elif ev.stream == "eis":
            p = st.metadata.get("pressure_kPa") if st is not None else None
            self.eis.append((p, np.vstack([d["f_Hz"], d["z_re_ohm"], d["z_im_ohm"]]).astype(float)))

    # ------------------------------------------------------------------ GUI side
    def status_text(self) -> str:
        """Step, pressure and ETA (wall seconds, from the rig-seconds-per-wall-second seen so far)."""
        if not self.steps:
            return "waiting for the run to start"
        n = len(self.steps)
        if self.exit is not None:
            return f"{self.protocol}: run {self.exit} ({sum(s.done for s in self.steps.values())}/{n} steps)"
        idx = self.current
        st = self.steps.get(idx) if idx is not None else None
        left = sum(s.planned_s for s in self.steps.values() if not s.done)
        rate = (self._rig_now - self._t_run0) / max(time.monotonic() - self._wall0, 1e-6)
        eta = f"ETA {left / rate:.0f} s" if rate > 0 and math.isfinite(rate) else "ETA --"
        where = f"step {idx + 1}/{n} {st.name}" if st is not None else "between steps"
        p = st.metadata.get("pressure_kPa") if st is not None else None
        press = f" · {p:g} kPa" if p is not None else ""
        return f"{self.protocol}: {where}{press} · {eta}"

    def snapshot(self, window_s: float | None = None) -> Snapshot:
        """Copy what changed (the lock is held only for the copies)."""
        with self._lock:
            env = None
            if window_s is None:
                daq, force = self.daq.ordered(), self.force.ordered()
            else:  # copy only the visible window, not the whole ring; long windows come from the envelope
                cut = self.daq.last() - window_s
                if self.daq.rows_since(cut) > self.raw_limit:
                    daq, env = np.empty((4, 0)), self.env.ring.tail_since(cut)
                else:
                    daq = self.daq.tail_since(cut)
                force = self.force.tail_since(self.force.last() - window_s)
            frf, self._frf = self._frf, []
            eis = list(self.eis)
            status, version, finished = self.status_text(), self.version, self.exit is not None
        return Snapshot(daq, env, force, eis, frf, status, version, finished)
