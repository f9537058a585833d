"""Simulated multifunction DAQ (an NI X-series card): tasks, hardware timing, triggers, buffers.

The device model behind ``mock_devices.daq_grpc``: it knows DAQmx semantics (task states and auto-start,
finite and continuous sample clocks, digital-edge start triggers on relative or absolute terminals, the
input buffer and its overflow, partial reads, the watchdog timer of ``mock_devices.daq_watchdog``) but
nothing of gRPC. One module for one card model (hence its length). The analog world comes from a bench (``mock_devices.world_api.WorldView``): when an AI task
runs, the device asks ``bench.run_record`` for each block of samples, feeding it what AO puts out at
those instants, and turns volts, amps and metres into AI voltages.

Channel wiring: ``ao0`` drives the strip; ``ai0`` reads the drive back, ``ai1`` the current amplifier
(current / gain A/V), ``ai2`` the laser analog output (displacement / m-per-V); other AI inputs read noise.
Time is simulated seconds on ``bench.clock``; read and wait timeouts are wall seconds, as on a real server.
"""

from __future__ import annotations

import logging
import threading
import time
from collections import deque
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from mock_devices.world_api import WorldView
from mock_devices.daq_errors import ERR, ERR_MESSAGES, DaqmxError  # noqa: F401 (re-exported)
from mock_devices.daq_watchdog import Watchdog, WatchdogUnit

# DAQmx enum values (nidaqmx.constants); status codes are in mock_devices.daq_errors under nidaqmx's names
FINITE, CONTINUOUS = 10178, 10123
FILL_BY_SCAN = 1
RISING, FALLING = 10280, 10171
OVERFLOW, NOT_YET, BEYOND_END, WAIT_TIMEOUT = -200279, -200284, -200278, -200560
EAGER_MAX = 2_000_000  # finite records up to this many samples are computed (speculatively) when AI starts
AI_RANGES_V = (0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0)  # X-series input ranges (±)
# digital-edge start trigger sources the card routes (terminal names are case-insensitive in DAQmx)
LOG = logging.getLogger("labrig.sim.daq")  # WARNING lines reach a bare `labrig sim`'s stderr (logging.lastResort)
TERMINALS = {t.lower(): t for t in ("ai/StartTrigger", "ao/StartTrigger", *(f"PFI{i}" for i in range(16)))}


@dataclass
class Chan:
    name: str  # virtual channel name (the physical name unless one was assigned)
    phys: str  # "ai0", "ao0", ...
    lo: float
    hi: float


@dataclass
class Task:
    name: str
    kind: str = ""  # "ai" | "ao" once a channel is added; "wdt" for a watchdog timer task
    chans: list[Chan] = field(default_factory=list)
    rate: float | None = None  # None = on-demand timing
    mode: int = FINITE
    samps: int = 1000
    trigger: str | None = None  # start trigger source as the client gave it ("ai/StartTrigger", "/Dev1/PFI0")
    trig_edge: int = RISING
    state: str = "idle"  # idle | armed | running
    t0: float = 0.0  # simulated start time
    ao_buf: np.ndarray | None = None  # (chans, n) AO samples
    buf_size: int | None = None  # input buffer in use (set at start)
    buf_user: int | None = None  # input buffer the client asked for
    read_all_avail: bool = False
    auto_started: bool = False  # started implicitly by a read: stopped again once the finite record is read
    read_pos: int = 0
    gen_pos: int = 0
    pending: deque = field(default_factory=deque)  # generated AI blocks not yet read
    blocks: list = field(default_factory=list)  # [start index, drive fed to the bench] of blocks still in use
    regen: tuple[int, np.ndarray] | None = None  # (block start, drive kept) when the AO change voided a block
    sticky_error: int | None = None
    debt_s: float = 0.0  # simulated time spent computing the bench: not the client's lag
    wd: Watchdog | None = None

    def n_total(self) -> int | None:
        return self.samps if self.mode == FINITE else None


def _default_input_buffer(rate: float) -> int:
    """DAQmx's default continuous input buffer for a sample rate."""
    for top, size in ((100.0, 1_000), (10_000.0, 10_000), (1_000_000.0, 100_000)):
        if rate <= top:
            return size
    return 1_000_000


class SimDaqDevice:
    """One simulated DAQ card with its tasks. Thread-safe; blocking calls never hold the lock while waiting.

    Causality: an AI sample is computed from what AO puts out at that sample's instant. Samples are computed
    ahead (a finite record when it starts, continuous blocks of ``block_s``) on the assumption that AO keeps
    doing what it is doing; any change of the drive (a write, an AO start or stop, a watchdog expiry) at
    simulated time t first computes the samples before t from the old state and voids those after t, which
    are computed again from the new one when read.
    """

    def __init__(self, bench: WorldView, name: str = "SimDev1", product_type: str = "PXIe-6361",
                 drive_channel: str = "ao0", current_gain_A_per_V: float = 1e-3, displacement_m_per_V: float = 1e-3,
                 noise_V: float = 1e-4, seed: int | None = 0, n_ai: int = 16, n_ao: int = 2, block_s: float = 1.0):
        self.bench, self.name, self.product_type = bench, name, product_type
        self.drive_channel = drive_channel
        self.block_s = block_s  # continuous mode: simulated seconds asked of the bench per call
        self.gain_A_per_V, self.m_per_V, self.noise_V = current_gain_A_per_V, displacement_m_per_V, noise_V
        self.ai_phys = [f"ai{i}" for i in range(n_ai)]
        self.ao_phys = [f"ao{i}" for i in range(n_ao)]
        self.ao_level: dict[str, float] = {p: 0.0 for p in self.ao_phys}  # static output when no task drives
        self.ao_lock: dict[str, tuple[float, float]] = {}  # phys -> (expired at, value): watchdog-locked outputs
        self.tasks: dict[str, Task] = {}
        self.fault: str | None = None
        self.fault_code = -50103
        self._rng = np.random.default_rng(seed)
        self._lock = threading.RLock()
        self._n_unnamed = 0
        self.watchdog = WatchdogUnit(bench.clock, self._lock, self._expire, self._unlock)

    # ---------------------------------------------------------------------------------- faults
    def inject(self, fault: str, code: int | None = None) -> None:
        """``"timeout"`` (reads/waits never complete), ``"overflow"`` (next read), ``"error"`` (next call)."""
        if fault not in ("timeout", "overflow", "error"):
            raise ValueError(f"unknown device fault {fault!r}")
        with self._lock:
            self.fault = fault
            if code is not None:
                self.fault_code = code

    def clear_fault(self) -> None:
        with self._lock:
            self.fault = None

    def check_call_fault(self) -> None:
        """Raise the injected one-shot ``"error"`` on whichever call comes next."""
        with self._lock:
            self.watchdog.poll()  # every call sees an expiry the clock has passed
            if self.fault == "error":
                self.fault = None
                raise DaqmxError(self.fault_code)

    # ---------------------------------------------------------------------------------- tasks
    def create_task(self, name: str, kind: str = "") -> tuple[str, bool]:
        with self._lock:
            if not name:
                self._n_unnamed += 1
                name = f"_unnamedTask<{self._n_unnamed}>"
            if name in self.tasks:  # the server attaches to an existing session of that name
                return name, False
            self.tasks[name] = Task(name, kind)
            return name, True

    def task(self, name: str) -> Task:
        t = self.tasks.get(name)
        if t is None:
            raise DaqmxError(-200088)
        return t

    def clear_task(self, name: str) -> None:
        with self._lock:
            self.stop(name)
            del self.tasks[name]
            self.watchdog.remove(name)

    def clear_all(self, keep_watchdogs: bool = False) -> None:
        """What a dying server process does: every task is cleared, outputs hold their last value.
        ``keep_watchdogs``: a lost link instead; the card's watchdog timers run on in hardware."""
        with self._lock:
            for name in list(self.tasks):
                if not (keep_watchdogs and self.tasks[name].kind == "wdt"):
                    self.clear_task(name)

    def power_off(self) -> None:
        with self._lock:
            self.clear_all()
        self.watchdog.halt()

    def _parse_phys(self, spec: str, kind: str) -> list[str]:
        out: list[str] = []
        for part in (p.strip().lstrip("/") for p in spec.split(",") if p.strip()):
            dev, _, chans = part.partition("/")
            if dev != self.name:
                raise DaqmxError(-200220, f"Device identifier is invalid: {dev!r}")
            lo, _, hi = chans.partition(":")
            if not lo.startswith(kind):
                raise DaqmxError(-200170, f"Physical channel does not exist: {part!r}")
            try:
                a = int(lo[len(kind):])
                b = int(hi[len(kind):] if hi.startswith(kind) else hi) if hi else a
            except ValueError:
                raise DaqmxError(-200170, f"Physical channel does not exist: {part!r}") from None
            names = [f"{kind}{i}" for i in range(a, b + (1 if b >= a else -1), 1 if b >= a else -1)]
            valid = self.ai_phys if kind == "ai" else self.ao_phys
            if any(n not in valid for n in names):
                raise DaqmxError(-200170, f"Physical channel does not exist: {part!r}")
            out += names
        return out

    def add_channels(self, name: str, kind: str, spec: str, assigned: str, lo: float, hi: float) -> None:
        with self._lock:
            t = self.task(name)
            if t.kind and t.kind != kind:
                raise DaqmxError(-200452, "A task holds channels of one type only.")
            phys = self._parse_phys(spec, kind)
            names = [assigned] if assigned and len(phys) == 1 else [
                f"{assigned}{i}" if assigned else f"{self.name}/{p}" for i, p in enumerate(phys)]
            t.kind = kind
            t.chans += [Chan(n, p, lo, hi) for n, p in zip(names, phys)]

    def cfg_timing(self, name: str, rate: float, mode: int, samps: int) -> None:
        with self._lock:
            t = self.task(name)
            if t.state != "idle":
                raise DaqmxError(-200479)
            if not rate > 0 or samps < 1 or mode not in (FINITE, CONTINUOUS):
                raise DaqmxError(-200452, "Invalid sample clock settings.")
            t.rate, t.mode, t.samps = float(rate), mode, int(samps)

    def cfg_start_trigger(self, name: str, source: str | None, edge: int = RISING) -> None:
        """Digital-edge start trigger (``None``: none). Like DAQmx, the source is checked when the task starts."""
        with self._lock:
            t = self.task(name)
            if t.state != "idle":
                raise DaqmxError(-200479)
            t.trigger, t.trig_edge = (source or None), edge

    def resolve_terminal(self, source: str) -> str:
        """``"ai/StartTrigger"`` (relative to this device) or ``"/SimDev1/ai/StartTrigger"`` -> the absolute name."""
        s = source.strip()
        dev, term = s[1:].partition("/")[::2] if s.startswith("/") else (self.name, s)
        canon = TERMINALS.get(term.lower())
        if dev != self.name or canon is None:
            raise DaqmxError(ERR["INVALID_ROUTING_SOURCE_TERMINAL_NAME_ROUTING"],
                             f"Source terminal to be routed could not be found on the device: {source!r}")
        return f"/{self.name}/{canon}"

    # ---------------------------------------------------------------------------------- watchdog
    def create_watchdog(self, session: str, device: str, timeout_s: float) -> tuple[str, bool]:
        with self._lock:
            if device != self.name:
                raise DaqmxError(-200220, f"Device identifier is invalid: {device!r}")
            name, new = self.create_task(session, "wdt")
            t = self.task(name)
            if new:
                try:
                    t.wd = self.watchdog.create(name, timeout_s)
                except DaqmxError:
                    del self.tasks[name]
                    raise
            return name, new

    def watchdog_of(self, name: str) -> Watchdog:
        t = self.task(name)
        if t.wd is None:
            raise DaqmxError(ERR["ACTION_NOT_SUPPORTED_TASK_NOT_WATCHDOG"])
        return t.wd

    def cfg_watchdog_ao(self, name: str, spec: str, states: list[float], types: list[int]) -> None:
        with self._lock:
            wd = self.watchdog_of(name)
            phys = self._parse_phys(spec, "ao")
            if len(states) != len(phys) or len(types) != len(phys):
                raise DaqmxError(ERR["WATCHDOG_CHANNEL_EXPIRATION_STATE_NOT_SPECIFIED"])
            if any(abs(v) > 10.0 for v in states):
                raise DaqmxError(-200561)
            wd.states.update({p: (float(v), int(k)) for p, v, k in zip(phys, states, types)})

    def _expire(self, wd: Watchdog, t_exp: float) -> None:
        """The timer ran out at ``t_exp``: outputs to their expiration states and locked; AO tasks on them fail."""
        locked = {p for p, (_, kind) in wd.states.items() if kind != 10160}  # NO_CHANGE leaves the line alone
        if not locked:
            return
        self._ao_will_change(t_exp)
        was = {p: float(self.ao_values(p, np.array([t_exp]))[0]) for p in locked}
        for phys in locked:
            value = wd.states[phys][0]
            self.ao_lock[phys], self.ao_level[phys] = (t_exp, value), value
        for o in self.tasks.values():
            if o.kind == "ao" and o.state != "idle" and locked & {c.phys for c in o.chans}:
                o.state, o.sticky_error = "idle", ERR["WRITE_FAILED_BECAUSE_WATCHDOG_EXPIRED"]
        LOG.warning("%s: watchdog %s expired at t=%.3f s (%.3f s after its last reset): %s", self.name, wd.name,
                    t_exp, wd.timeout_s, ", ".join(f"{p} {was[p]:g} V -> {wd.states[p][0]:g} V" for p in sorted(locked)))

    def _unlock(self, wd: Watchdog) -> None:
        for phys in wd.states:  # the outputs keep the expiration value until written
            self.ao_lock.pop(phys, None)

    def _check_locked(self, t: Task) -> None:
        if any(c.phys in self.ao_lock for c in t.chans):
            raise DaqmxError(ERR["WRITE_FAILED_BECAUSE_WATCHDOG_EXPIRED"])

    # ---------------------------------------------------------------------------------- output
    def write(self, name: str, flat: np.ndarray, n: int, auto_start: bool, layout: int) -> int:
        with self._lock:
            t = self.task(name)
            if t.kind != "ao":
                raise DaqmxError(-200459)
            nch = len(t.chans)
            data = np.asarray(flat, dtype=float)[: n * nch]
            data = data.reshape(n, nch).T if layout == FILL_BY_SCAN else data.reshape(nch, n)
            for c, row in zip(t.chans, data):
                if row.size and (row.min() < c.lo - 1e-9 or row.max() > c.hi + 1e-9):
                    raise DaqmxError(-200561)
            self._check_locked(t)
            if t.rate is None:  # on-demand: the output changes now
                if t.state == "idle" and not auto_start:
                    raise DaqmxError(ERR["CANNOT_WRITE_WHEN_AUTO_START_FALSE_AND_TASK_NOT_RUNNING"])
                self._check_reserved(t)
                self._ao_will_change(self.bench.clock.now())
                for c, row in zip(t.chans, data):
                    self.ao_level[c.phys] = float(row[-1])
                return n  # an auto-started task is back in its earlier state: the channel is free again
            if t.state == "running":
                self._ao_will_change(self.bench.clock.now())
            t.ao_buf = data.copy()
            if auto_start and t.state == "idle":
                self.start(name)
            return n

    def ao_values(self, phys: str, times: np.ndarray) -> np.ndarray:
        """What AO channel ``phys`` puts out at simulated ``times`` (hold, regenerate, finite end, watchdog)."""
        out = np.full(len(times), self.ao_level.get(phys, 0.0))
        for t in self.tasks.values():
            if t.kind != "ao" or t.state != "running" or t.rate is None or t.ao_buf is None:
                continue
            for j, c in enumerate(t.chans):
                if c.phys != phys:
                    continue
                buf = t.ao_buf[j]
                k = np.floor((times - t.t0) * t.rate + 1e-6).astype(np.int64)
                m = k >= 0
                kk = k[m] if t.mode == CONTINUOUS else np.minimum(k[m], t.samps - 1)
                out[m] = buf[kk % len(buf)]
        lock = self.ao_lock.get(phys)
        if lock is not None:
            out[times >= lock[0]] = lock[1]
        return out

    def _ao_will_change(self, t_c: float) -> None:
        """Call before the drive changes at simulated ``t_c``: AI samples before it come from the old drive,
        samples computed ahead from ``t_c`` on are voided (the block they came from is run again when read)."""
        for t in self.tasks.values():
            if t.kind != "ai" or t.state != "running" or t.rate is None:
                continue
            k_c = max(t.read_pos, int(np.ceil((t_c - t.t0) * t.rate - 1e-6)))
            total = t.n_total()
            if total is not None:
                k_c = min(k_c, total)
            if t.gen_pos < k_c:
                self._generate(t, k_c, exact=True)
            elif t.gen_pos > k_c:
                keep, kept = k_c - t.read_pos, deque()
                for blk in t.pending:
                    if keep <= 0:
                        break
                    kept.append(blk[:, :keep])
                    keep -= blk.shape[1]
                t.pending = kept
                while t.blocks and t.blocks[-1][0] > k_c:
                    t.blocks.pop()
                start, drive = t.blocks.pop()
                t.regen, t.gen_pos = (start, drive[: k_c - start]), k_c

    # ---------------------------------------------------------------------------------- control
    def _check_reserved(self, t: Task) -> None:
        mine = {c.phys for c in t.chans}
        for o in self.tasks.values():
            if o is not t and o.state != "idle" and mine & {c.phys for c in o.chans}:
                if o.rate is None and t.rate is None:
                    continue  # on-demand writers share a channel, as in DAQmx
                raise DaqmxError(-50103, f"The specified resource is reserved by task {o.name!r}.")

    def start(self, name: str) -> None:
        with self._lock:
            t = self.task(name)
            if t.state != "idle":
                raise DaqmxError(-200479)
            if t.wd is not None:
                t.state = "running"
                self.watchdog.start(t.wd)
                return
            self._check_reserved(t)
            if t.kind == "ao":
                self._check_locked(t)
            if t.kind == "ao" and t.rate is not None and t.ao_buf is None:
                raise DaqmxError(-200462)
            src = self.resolve_terminal(t.trigger) if t.trigger else None
            t.read_pos = t.gen_pos = 0
            t.pending.clear()
            t.blocks, t.regen = [], None
            t.sticky_error, t.debt_s, t.auto_started = None, 0.0, False
            if src:
                t.state = "armed"  # waits for the edge of the other task's start trigger (a PFI line never comes)
            else:
                self._begin(t, self.bench.clock.now())

    def _begin(self, t: Task, t0: float) -> None:
        if t.kind == "ao":
            self._ao_will_change(t0)
        t.state, t.t0 = "running", t0
        if t.kind == "ai":
            default = t.samps if t.mode == FINITE else max(t.samps, _default_input_buffer(t.rate or 1.0))
            t.buf_size = t.buf_user or default
        term = f"/{self.name}/{t.kind}/StartTrigger"
        for o in self.tasks.values():
            if o.state == "armed" and o.trigger and self.resolve_terminal(o.trigger) == term:
                self._begin(o, t0)
        if t.kind == "ai" and t.mode == FINITE and t.rate is not None and t.samps <= EAGER_MAX:
            # the whole record ahead (one bench call, the bench then knows the motion while it happens);
            # a later change of the drive voids what follows it (_ao_will_change)
            self._generate(t, t.samps)

    def stop(self, name: str) -> None:
        with self._lock:
            t = self.task(name)
            if t.wd is not None:
                self.watchdog.stop(t.wd)
            elif t.kind == "ao" and t.state == "running" and t.rate is not None:
                now = self.bench.clock.now()
                held = {c.phys: float(self.ao_values(c.phys, np.array([now]))[0]) for c in t.chans}
                self._ao_will_change(now)
                self.ao_level.update(held)  # the output holds what it was putting out when stopped
            t.state = "idle"
            t.pending.clear()
            t.blocks, t.regen = [], None

    # ---------------------------------------------------------------------------------- input
    def acquired(self, t: Task) -> int:
        """Samples per channel the hardware has converted by now."""
        if t.state != "running" or t.rate is None:
            return t.read_pos
        n = int(max(0.0, (self.bench.clock.now() - t.t0) * t.rate))
        total = t.n_total()
        return n if total is None else min(n, total)

    def available(self, t: Task) -> int:
        return max(0, self.acquired(t) - t.read_pos)

    def _generate(self, t: Task, upto: int, exact: bool = False) -> None:
        """Ask the bench for samples [gen_pos, upto), in blocks large enough to keep the bench calls few
        (``exact``: no further than ``upto``). A voided block is run again from its start, with the drive
        it had before the change, so the bench sees one contiguous history."""
        total = t.n_total()
        rate = float(t.rate or 1.0)
        while t.gen_pos < upto:
            start, kept = t.regen if t.regen is not None else (t.gen_pos, np.empty(0))
            t.regen = None
            k = upto - t.gen_pos
            if not exact:
                k = max(k, int(rate * self.block_s) + 1)
                if total is None:
                    k = min(k, max(upto - t.gen_pos, (t.buf_size or k) // 2))
            if total is not None:
                k = min(k, total - t.gen_pos)
            times = t.t0 + (t.gen_pos + np.arange(k)) / rate
            drive = np.concatenate([kept, self.ao_values(self.drive_channel, times)])
            w0 = time.perf_counter()
            rec = self.bench.run_record(t.t0 + start / rate, rate, drive)
            t.debt_s += (time.perf_counter() - w0) * self.bench.clock.time_scale
            skip = len(kept)
            sig = {"ai0": np.asarray(rec["v_V"])[skip:],
                   "ai1": np.asarray(rec["i_A"])[skip:] / self.gain_A_per_V,
                   "ai2": np.asarray(rec["disp_m"])[skip:] / self.m_per_V}
            block = np.empty((len(t.chans), k))
            for i, c in enumerate(t.chans):
                block[i] = sig.get(c.phys, 0.0)
                rng = next((r for r in AI_RANGES_V if r >= max(abs(c.lo), abs(c.hi))), AI_RANGES_V[-1])
                lsb = 2.0 * rng / 65536.0  # 16-bit ADC over the selected range
                if self.noise_V > 0:
                    block[i] += self._rng.normal(0.0, self.noise_V, k)
                np.clip(np.round(block[i] / lsb) * lsb, -rng, rng - lsb, out=block[i])
            t.pending.append(block)
            t.blocks.append((start, drive))
            t.gen_pos += k

    def _take(self, t: Task, n: int) -> np.ndarray:
        self._generate(t, t.read_pos + n)
        parts, need = [], n
        while need > 0:
            blk = t.pending[0]
            if blk.shape[1] <= need:
                parts.append(t.pending.popleft())
                need -= blk.shape[1]
            else:
                parts.append(blk[:, :need])
                t.pending[0] = blk[:, need:]
                need = 0
        t.read_pos += n
        while len(t.blocks) > 1 and t.blocks[1][0] <= t.read_pos:  # drives of blocks read to the end
            t.blocks.pop(0)
        if t.auto_started and t.read_pos == t.n_total():
            self.stop(t.name)  # a finite task a read started returns to its earlier state
        if not parts:
            return np.empty((len(t.chans), 0))
        return parts[0] if len(parts) == 1 else np.concatenate(parts, axis=1)

    def read(self, name: str, n: int, timeout_s: float, alive: Callable[[], bool] = lambda: True) -> np.ndarray:
        """Read ``n`` samples per channel (``-1``: all available); returns (chans, n). Blocks up to ``timeout_s``.

        A timeout with some samples acquired returns them (they are consumed) in a ``DaqmxError`` -200284
        whose ``partial`` holds them, as DAQmx Read does."""
        deadline = None if timeout_s < 0 else time.monotonic() + timeout_s
        while True:
            with self._lock:
                t = self.task(name)
                if t.kind != "ai":
                    raise DaqmxError(-200452, "Read cannot be performed: the task has no input channels.")
                if t.rate is None:
                    raise DaqmxError(-200452, "On-demand (software-timed) AI is not simulated: configure a sample clock.")
                if self.fault == "overflow":
                    self.fault = None
                    raise DaqmxError(OVERFLOW, samps_per_chan_read=0)
                if t.state == "idle":
                    self.start(name)  # DAQmx Read starts an idle task implicitly
                    t.auto_started = True
                if t.sticky_error is not None:
                    raise DaqmxError(t.sticky_error, samps_per_chan_read=0)
                acq, total = self.acquired(t), t.n_total()
                stalled = self.fault == "timeout"  # as if the sample clock stopped: nothing new, no overflow
                behind = acq - t.read_pos - int(t.debt_s * float(t.rate or 1.0))
                if not stalled and total is None and t.buf_size is not None and behind > t.buf_size:
                    t.sticky_error = OVERFLOW  # the hardware stopped: unread samples would be overwritten
                    raise DaqmxError(OVERFLOW, samps_per_chan_read=0)
                if n >= 0:
                    want = n
                elif total is not None and not t.read_all_avail:
                    want = total - t.read_pos
                else:
                    want = acq - t.read_pos
                if total is not None and t.read_pos + want > total:
                    raise DaqmxError(BEYOND_END, samps_per_chan_read=0)
                if not stalled and acq - t.read_pos >= want:
                    return self._take(t, want)
                wait_s = (want - (acq - t.read_pos)) / float(t.rate or 1.0) / self.bench.clock.time_scale
                if (deadline is not None and time.monotonic() >= deadline) or not alive():
                    got = 0 if stalled else acq - t.read_pos
                    part = self._take(t, got) if got > 0 else None
                    raise DaqmxError(NOT_YET, samps_per_chan_read=got, partial=part)
            left = 0.05 if deadline is None else deadline - time.monotonic()
            time.sleep(max(0.0, min(wait_s, left, 0.05)))

    def is_done(self, name: str) -> bool:
        with self._lock:
            t = self.task(name)
            if t.sticky_error is not None and t.kind == "ao":
                raise DaqmxError(t.sticky_error)
            if t.state == "idle" or t.rate is None:
                return True
            if t.state == "armed" or t.mode == CONTINUOUS:
                return False
            return self.bench.clock.now() >= t.t0 + t.samps / t.rate

    def wait_until_done(self, name: str, timeout_s: float, alive: Callable[[], bool] = lambda: True) -> None:
        deadline = None if timeout_s < 0 else time.monotonic() + timeout_s
        while self.fault == "timeout" or not self.is_done(name):
            if (deadline is not None and time.monotonic() >= deadline) or not alive():
                raise DaqmxError(WAIT_TIMEOUT)
            time.sleep(0.002)
