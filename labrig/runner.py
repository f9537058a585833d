"""The protocol runner: materialise the plan, validate it against the rig, run it, emit events.

Safety: every drive and clamp force is checked against the rig's limits before anything moves; the
current and the clamp force are checked while running. A trip, an instrument fault, a stop request or
any exception puts the drive at 0 V first (``rig.safe()``), then records what happened. A first stop
request (Ctrl-C, the live window's Stop button) ends the run at the next safe point; a second Ctrl-C
raises KeyboardInterrupt at once and is handled the same way.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from typing import Any, Iterable

import numpy as np

from drivers.errors import InstrumentError
from drivers.transcript import Transcript as DriverTranscript
from labrig import __version__
from labrig.errors import BadInput, SafetyTrip
from labrig.events import Block, Event, Pause, RunStart, RunStop, StepEnd, StepPlan, StepStart, Subscriber, Transcript, new_uid
from labrig.rig import Rig
from labrig.suspenders import PauseControl, SuspendCfg, Suspenders, wait_pause_answer
from protocols.registry import LoadedProtocol
from protocols.steps import Impedance, Record, SetClamp, Settle, Step, peak_drive

BLOCK_ROWS = 20000  # rows per data block of a record (what a crash can lose at most)


class _Hold(Exception):
    """A pause or a failed suspender at a safe point inside a step: the step stops and starts over later."""


@dataclass
class RunResult:
    uid: str
    exit_status: str
    reason: str
    exit_code: int
    steps_done: list[str] = field(default_factory=list)
    noop: bool = False  # nothing was run (resume of a finished session); ``reason`` says why


def validate(steps: Iterable[Step], rig: Rig, source: str) -> None:
    """Refuse, before anything moves, a plan that would break the rig's safety limits."""
    lim = rig.limits
    for s in steps:
        a = s.action
        if isinstance(a, Record):
            peak = peak_drive(s)
            if peak > lim.max_drive_V:
                raise BadInput(f"{source}: step {s.name}: drive {peak:.3g} V exceeds the rig's safety.max_drive_V = {lim.max_drive_V:g} V")
            if not np.all(np.isfinite(a.drive_V)) or a.fs_Hz <= 0:
                raise BadInput(f"{source}: step {s.name}: drive is not finite or fs_Hz <= 0")
        elif isinstance(a, SetClamp) and a.force_N > lim.max_force_N:
            raise BadInput(f"{source}: step {s.name}: clamp force {a.force_N:.3g} N exceeds the rig's safety.max_force_N = {lim.max_force_N:g} N")
        elif isinstance(a, Impedance) and abs(a.ac_V) + abs(a.bias_V) > lim.max_drive_V:
            raise BadInput(f"{source}: step {s.name}: impedance drive exceeds safety.max_drive_V = {lim.max_drive_V:g} V")


class Runner:
    def __init__(
        self,
        rig: Rig,
        protocol: LoadedProtocol,
        subscribers: Iterable[Subscriber] = (),
        *,
        force_rate_Hz: float = 10.0,
        done: Iterable[str] = (),
        resumed_from: str | None = None,
        uid: str | None = None,
        pauses: PauseControl | None = None,
    ):
        self.rig, self.protocol = rig, protocol
        self.subscribers = list(subscribers)
        self.force_rate_Hz = force_rate_Hz
        self.done = set(done)
        self.resumed_from = resumed_from
        self.uid = uid or new_uid()
        self.stop_requested = threading.Event()
        self.stop_reason = "stopped by the operator"
        self.pauses = pauses or PauseControl()
        self.suspenders = Suspenders(getattr(rig.config.safety, "suspend", None) or SuspendCfg(), rig)
        self._tr_pos = 0  # exchanges of rig.transcript already emitted
        self._emit_lock = threading.Lock()
        self.steps: list[Step] = []

    # ------------------------------------------------------------------------------ events
    def emit(self, ev: Event) -> None:
        with self._emit_lock:  # the force logger emits from its own thread
            for sub in self.subscribers:
                sub(ev)

    def subscribe(self, sub: Subscriber) -> None:
        """Add a subscriber (the one way to attach after construction: ``subscribers`` is the runner's own list)."""
        with self._emit_lock:
            self.subscribers.append(sub)

    def request_stop(self) -> None:
        """Stop at the next safe point (Ctrl-C once, or the Stop button)."""
        self.stop_requested.set()

    def plan(self) -> list[Step]:
        self.steps = self.protocol.plan(self.rig.clamp_area_m2)
        validate(self.steps, self.rig, self.protocol.source)
        return self.steps

    def run_start(self) -> RunStart:
        plans = tuple(
            StepPlan(i, s.name, s.kind, dict(s.metadata), s.streams(self.force_rate_Hz)) for i, s in enumerate(self.steps)
        )
        return RunStart(
            uid=self.uid,
            protocol=self.protocol.name,
            config=self.protocol.as_dict(),
            rig=self.rig.describe(),
            sample=self.rig.sample_info(),
            user=self.rig.user_info() if hasattr(self.rig, "user_info") else {},
            software={"labrig": __version__, "numpy": np.__version__},
            steps=plans,
            t=self.rig.clock.now(),
            resumed_from=self.resumed_from,
        )

    # ------------------------------------------------------------------------------ run
    def run(self) -> RunResult:
        steps = self.steps or self.plan()
        self.emit(self.run_start())
        finished: list[str] = []
        status, reason, code = "success", "all steps done", 0
        current: int | None = None
        todo = [i for i, s in enumerate(steps) if s.name not in self.done]
        try:
            k = 0
            while k < len(todo):
                i, step = todo[k], steps[todo[k]]
                if not self.stop_requested.is_set():
                    self._hold_if_asked(in_step=False)  # a pause or a failed suspender between steps
                if self.stop_requested.is_set():
                    status, reason, code = "abort", self.stop_reason, 1
                    break
                current = i
                self.emit(StepStart(self.uid, i, self.rig.clock.now()))
                try:
                    summary = self._run_step(i, step)
                except _Hold:
                    self._hold(i)  # the step starts over once the hold ends
                    if self.stop_requested.is_set():  # aborted while held: the step is recorded as aborted
                        status, reason, code = "abort", self.stop_reason, 1
                        break
                    current = None
                    continue
                if isinstance(step.action, SetClamp):
                    self.suspenders.clamp_target_N = step.action.force_N
                self.emit(StepEnd(self.uid, i, "done", self.rig.clock.now(), summary))
                self._flush_transcripts(i)
                finished.append(step.name)
                current = None
                k += 1
        except SafetyTrip as exc:
            status, reason, code = "fail", f"safety trip: {exc}", 3
        except InstrumentError as exc:
            status, reason, code = "fail", f"instrument fault: {exc}", 3
        except KeyboardInterrupt:
            status, reason, code = "abort", "interrupted by the operator", 1
        except BaseException as exc:
            status, reason, code = "fail", f"{type(exc).__name__}: {exc}", 1
        finally:
            problems = self.rig.safe()  # 0 V on the drive before anything is written about it
            if problems:
                reason += "; while making safe: " + "; ".join(problems)
            if current is not None:
                self.emit(StepEnd(self.uid, current, "aborted" if status == "abort" else "failed", self.rig.clock.now(), {"reason": reason}))
            self._flush_transcripts(current)
            self.emit(RunStop(self.uid, status, reason, self.rig.clock.now()))
        return RunResult(self.uid, status, reason, code, finished)

    def _flush_transcripts(self, index: int | None) -> None:
        """The instrument traffic since the last flush, as the run goes (a crash keeps what was flushed)."""
        tr = self.rig.transcript
        new = tr.exchanges[self._tr_pos:]
        self._tr_pos += len(new)
        for dev in sorted({e.device for e in new}):
            self.emit(Transcript(self.uid, dev, DriverTranscript(e for e in new if e.device == dev).dumps(), index))

    # ------------------------------------------------------------------------------ pause, suspension
    def _hold_reason(self) -> tuple[str, str] | None:
        why = self.pauses.pending()
        if why is not None:
            return "pause", why
        if self.suspenders.active and (why := self.suspenders.failing()) is not None:
            return "suspend", why
        return None

    def _hold_if_asked(self, in_step: bool) -> None:
        """At a safe point: hold here if asked to (between steps) or raise ``_Hold`` (inside a step)."""
        if self._hold_reason() is None:
            return
        if in_step:
            raise _Hold()
        self._hold(None)

    def _hold(self, index: int | None) -> None:
        """Drive at 0 V, record the hold, wait until it may go on (or a stop), record the continuation."""
        hold = self._hold_reason() or ("pause", self.pauses.reason or "paused")
        kind, why = hold
        self.rig.safe()
        self.emit(Pause(self.uid, kind, why, index, self.rig.clock.now()))
        clock, cfg = self.rig.clock, self.suspenders.cfg
        if kind == "pause":
            where = f"paused at step {index + 1}" if index is not None else "paused between steps"
            answer = wait_pause_answer(self.pauses, f"{where} ({why})") if self.pauses.ask else "pause"
            if answer == "abort":
                self.stop_reason = "aborted by the operator while paused"
                self.stop_requested.set()
            elif answer == "resume":
                self.pauses.resume()
            while not self.stop_requested.is_set() and not self.pauses.may_resume():
                clock.wait(self.stop_requested, cfg.poll_s)
        else:
            t0, good_since = clock.now(), None
            while not self.stop_requested.is_set():
                if self.suspenders.failing() is None:
                    good_since = clock.now() if good_since is None else good_since
                    if clock.now() - good_since >= cfg.resume_after_s:
                        break
                else:
                    good_since = None
                if clock.now() - t0 > cfg.max_hold_s:
                    raise SafetyTrip(f"suspended for more than safety.suspend.max_hold_s = {cfg.max_hold_s:g} s: {why}")
                clock.wait(self.stop_requested, cfg.poll_s)
        if not self.stop_requested.is_set():
            self.emit(Pause(self.uid, kind, why, index, self.rig.clock.now(), resumed=True))

    # ------------------------------------------------------------------------------ steps
    def _run_step(self, index: int, step: Step) -> dict[str, Any]:
        logger = _ForceLogger(self, index)
        logger.start()
        try:
            a = step.action
            if isinstance(a, SetClamp):
                return self._clamp(a)
            if isinstance(a, Settle):
                return self._settle(a.duration_s, logger)
            if isinstance(a, Impedance):
                return self._impedance(index, a)
            if isinstance(a, Record):
                return self._record(index, a)
            raise TypeError(f"unknown action {a!r}")
        finally:
            logger.stop()
            logger.raise_if_tripped()

    def _clamp(self, a: SetClamp) -> dict[str, Any]:
        rig = self.rig
        rig.clamp.request(a.force_N)
        reading = rig.loadcell.wait_stable(a.force_N, a.tol_N, a.hold_s, a.timeout_s, rig.clock)
        return {"force_N": reading.force_N, "target_N": a.force_N}

    def _settle(self, duration_s: float, logger: "_ForceLogger") -> dict[str, Any]:
        clock = self.rig.clock
        end = clock.now() + duration_s
        while clock.now() < end and not self.stop_requested.is_set():
            clock.sleep(min(1.0, end - clock.now()))
            logger.raise_if_tripped()
            self._hold_if_asked(in_step=True)  # a safe point: a pause or a failed suspender interrupts the settle
        return {"duration_s": duration_s}

    def _impedance(self, index: int, a: Impedance) -> dict[str, Any]:
        an = self.rig.analyzer
        an.configure_list(np.array(a.freqs_Hz), a.ac_V, a.bias_V)
        f, z = an.measure()
        cols = {"f_Hz": f, "z_re_ohm": z.real, "z_im_ohm": z.imag}
        self.emit(Block(self.uid, index, "eis", {k: np.ascontiguousarray(v, float) for k, v in cols.items()}))
        return {"points": int(f.size), "z_min_ohm": float(np.min(np.abs(z)))}

    def _record(self, index: int, a: Record) -> dict[str, Any]:
        rig = self.rig
        laser_before = rig.laser.read_displacement()
        out = rig.daq.run_finite(a.drive_V, a.fs_Hz)
        i_peak = float(np.max(np.abs(out["current_A"])))
        cols = {"t_s": out["t_s"], "v_V": out["voltage_V"], "i_A": out["current_A"], "disp_m": out["displacement_m"]}
        # the data measured so far is stored before a trip is declared: nothing measured is lost
        for k, start in enumerate(range(0, a.drive_V.size, BLOCK_ROWS)):
            block = {c: np.ascontiguousarray(v[start : start + BLOCK_ROWS], float) for c, v in cols.items()}
            self.emit(Block(self.uid, index, "daq", block, seq=k))
        if i_peak > rig.limits.max_current_A:
            raise SafetyTrip(f"current {i_peak:.3g} A exceeded safety.max_current_A = {rig.limits.max_current_A:g} A")
        laser_after = rig.laser.read_displacement()
        return {"i_peak_A": i_peak, "disp_peak_m": float(np.max(np.abs(out["displacement_m"]))), "laser_before_m": laser_before, "laser_after_m": laser_after}


class _ForceLogger:
    """Reads the load cell through the whole step and emits ``force`` blocks; trips on over-force."""

    def __init__(self, runner: Runner, index: int):
        self.r, self.index = runner, index
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._loop, name="force-logger", daemon=True)
        self._t: list[float] = []
        self._f: list[float] = []
        self._t0 = runner.rig.clock.now()
        self._trip: BaseException | None = None
        self._seq = 0

    def start(self) -> None:
        self._sample()
        self._thread.start()

    def _sample(self) -> None:
        rig = self.r.rig
        try:
            reading = rig.loadcell.force()
        except InstrumentError as exc:
            self._trip = exc
            return
        self._t.append(rig.clock.now() - self._t0)
        self._f.append(reading.force_N)
        if reading.force_N > rig.limits.max_force_N:
            self._trip = SafetyTrip(f"clamp force {reading.force_N:.3g} N exceeded safety.max_force_N = {rig.limits.max_force_N:g} N")

    def _loop(self) -> None:
        clock = self.r.rig.clock
        period_wall = max(1.0 / (self.r.force_rate_Hz * clock.time_scale), 0.005)
        last_emit = clock.now()
        while not self._stop.wait(period_wall):
            self._sample()
            if self._trip is not None:
                self.r.rig.safe()  # over-force or a dead load cell: drive to 0 V now, not at step end
                return
            if clock.now() - last_emit > 5.0:
                self._flush()
                last_emit = clock.now()

    def _flush(self) -> None:
        if self._t:
            t, f = np.array(self._t), np.array(self._f)
            self._t, self._f = [], []
            self.r.emit(Block(self.r.uid, self.index, "force", {"t_s": t, "force_N": f}, seq=self._seq))
            self._seq += 1

    def stop(self) -> None:
        self._stop.set()
        self._thread.join()
        if self._trip is None:
            self._sample()
        self._flush()

    def raise_if_tripped(self) -> None:
        if self._trip is not None:
            trip, self._trip = self._trip, None
            raise trip
