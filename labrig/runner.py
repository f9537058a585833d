"""The protocol runner: materialise the plan, validate it against the rig, run it, emit events.

Safety: every drive and clamp force is checked against the rig's limits before anything moves; the
current, the drive and the clamp force are checked while running, block by block as the DAQ delivers
them (``labrig.limits``). A trip, an instrument fault, a stop request or any exception puts the drive
at 0 V first (``rig.safe()``, which reads it back), then records what happened: the rows of the step in
flight are kept and the step is marked failed with what was kept and why. A first stop request (Ctrl-C,
the live window's Stop button) ends the run at the next safe point; a second Ctrl-C raises
KeyboardInterrupt at once and is handled the same way. See docs/safety.md.
"""

from __future__ import annotations

import math
import threading
import time
from contextlib import closing
from dataclasses import dataclass, field
from typing import Any, Iterable

import numpy as np

from drivers.daq import KEYS as DAQ_COLUMNS
from drivers.errors import InstrumentError, InstrumentErrorReply, Overload
from drivers.impedance_analyzer import estimate_sweep_s
from drivers.transcript import Transcript as DriverTranscript
from drivers.analyser_models import out_of_range
from labrig import __version__
from labrig.errors import BadInput, SafetyTrip
from labrig.events import Block, Event, Pause, RunStart, RunStop, StepEnd, StepPlan, StepStart, Subscriber, Transcript, new_uid
from labrig.limits import GARBLED_WINDOW_FRAMES, check_daq_block, check_force, check_impedance, check_laser, check_stream
from labrig.instrument_kind import REPLY_RIG_S, REPLY_WALL_S, rig_timeout
from labrig.rig import Rig
from labrig.suspenders import PauseControl, SuspendCfg, Suspenders, wait_pause_answer
from protocols.registry import LoadedProtocol
from protocols.steps import Impedance, Record, SetClamp, Settle, Step, peak_drive

BLOCK_ROWS = 20000  # rows per stored data block of a record at most
EMIT_WALL_S = 0.02  # DAQ blocks read within this many wall seconds are stored as one (a 1000x bench reads
# a block every ~2 ms; a real one every 0.25 s): what a kill -9 can lose at most. A fault stores them at once.


class _Hold(Exception):
    """A pause or a failed suspender at a safe point inside a step: the step stops and starts over later."""


@dataclass
class RunResult:
    uid: str
    exit_status: str
    reason: str
    exit_code: int
    steps_done: list[str] = field(default_factory=list)
    drive: str = ""  # the drive's state as read back after the run (``SafeState.line()``)
    noop: bool = False  # nothing was run (resume of a finished session); ``reason`` says why


def validate(steps: Iterable[Step], rig: Rig, source: str) -> None:
    """Refuse, before anything moves, a plan that would break the rig's safety limits."""
    lim = rig.limits
    for s in steps:
        a = s.action
        peak = peak_drive(s)
        if not math.isfinite(peak) or (isinstance(a, Record) and a.fs_Hz <= 0):
            raise BadInput(f"{source}: step {s.name}: drive is not finite or fs_Hz <= 0")
        if peak > lim.max_drive_V:
            raise BadInput(f"{source}: step {s.name}: {'impedance ' if isinstance(a, Impedance) else ''}drive {peak:.3g} V exceeds "
                           f"the rig's safety.max_drive_V = {lim.max_drive_V:g} V")
        if isinstance(a, SetClamp) and a.force_N > lim.max_force_N:  # per strip: the force is pressure x its clamp area
            area, strip = rig.clamp_area_m2, rig.config.sample.preset
            raise BadInput(f"{source}: step {s.name}: clamp force {a.force_N:.3g} N on strip {strip!r} (clamp area {area * 1e6:.3g} mm^2) "
                           f"exceeds the rig's safety.max_force_N = {lim.max_force_N:g} N: this strip allows at most "
                           f"{lim.max_force_N / area / 1e3:.0f} kPa")
        if isinstance(a, Impedance) and (problem := out_of_range(rig.config.instruments.impedance.model, a.freqs_Hz)):
            raise BadInput(f"{source}: step {s.name}: {problem}")


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
        self._inflight: dict[str, Any] = {}  # what the step in flight has stored so far (for its StepEnd)
        self._recording = threading.Event()  # a record is streaming: its loop checks the force logger per block
        self._record_gate = threading.Lock()  # the force logger's "not recording: make safe now" is one act
        self._wd_failures = self._watchdog_failures()  # the DAQ watchdog's failed resets when the run began

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
            state = self.rig.safe()  # 0 V on the drive (read back) before anything is written about it
            if state.problems:
                reason += "; while making safe: " + "; ".join(state.problems)
            if not state.verified and code == 0:
                status, reason, code = "fail", "the drive could not be verified at 0 V after the run", 3
            if current is not None:
                summary = {"reason": reason, **self._inflight}
                self.emit(StepEnd(self.uid, current, "aborted" if status == "abort" else "failed", self.rig.clock.now(), summary))
            self._flush_transcripts(current)
            self.emit(RunStop(self.uid, status, reason, self.rig.clock.now()))
        return RunResult(self.uid, status, reason, code, finished, state.line())

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
        self._inflight = {"rows_kept": {}}
        logger = _ForceLogger(self, index)
        logger.start()
        try:
            summary = self._act(index, step.action, logger)
        except BaseException:
            self.rig.safe()  # 0 V first, before the force logger's last rows are written (run() verifies again)
            raise
        finally:
            logger.stop()  # an error already on its way up is not replaced by the logger's
        logger.raise_if_tripped()
        return summary

    def _act(self, index: int, a: Any, logger: "_ForceLogger") -> dict[str, Any]:
        """Run one action through the command table (one handler per action type)."""
        try:
            handler = _HANDLERS[type(a)]
        except KeyError:
            raise TypeError(f"unknown action {a!r}") from None
        return handler(self, index, a, logger)

    def _clamp(self, index: int, a: SetClamp, logger: "_ForceLogger") -> dict[str, Any]:
        rig = self.rig
        rig.clamp.request(a.force_N)
        reading = rig.loadcell.wait_stable(a.force_N, a.tol_N, a.hold_s, a.timeout_s, rig.clock)
        return {"force_N": reading.force_N, "target_N": a.force_N}

    def _settle(self, index: int, a: Settle, logger: "_ForceLogger") -> dict[str, Any]:
        clock, duration_s = self.rig.clock, a.duration_s
        end = clock.now() + duration_s
        while clock.now() < end and not self.stop_requested.is_set():
            clock.sleep(min(1.0, end - clock.now()))
            logger.raise_if_tripped()
            self._hold_if_asked(in_step=True)  # a safe point: a pause or a failed suspender interrupts the settle
        return {"duration_s": duration_s}

    def _impedance(self, index: int, a: Impedance, logger: "_ForceLogger") -> dict[str, Any]:
        an = self.rig.analyzer
        # the sweep's wait in rig seconds: twice its generous estimate (plus a reply's), as wall seconds
        an.sweep_timeout_s = rig_timeout(self.rig.clock, REPLY_RIG_S + 2.0 * estimate_sweep_s(np.array(a.freqs_Hz)), REPLY_WALL_S)
        an.configure_list(np.array(a.freqs_Hz), a.ac_V, a.bias_V)
        f, z = an.measure()
        cols = {"f_Hz": f, "z_re_ohm": z.real, "z_im_ohm": z.imag}
        self.emit(Block(self.uid, index, "eis", {k: np.ascontiguousarray(v, float) for k, v in cols.items()}))
        self._inflight["rows_kept"]["eis"] = int(f.size)
        check_impedance(z)  # stored first: an overloaded spectrum is still what was measured
        return {"points": int(f.size), "z_min_ohm": float(np.min(np.abs(z)))}

    def _watchdog_failures(self) -> int:
        wd = getattr(self.rig.daq, "watchdog", None)
        return 0 if wd is None else int(wd.failed_resets)

    def _check_watchdog(self) -> None:
        """A watchdog reset the card refused: it may cut the drive at any moment (or has): a DAQ fault."""
        n = self._watchdog_failures() - self._wd_failures
        if n > 0:
            if getattr(self.rig.daq.watchdog, "expired_seen", False):  # the record would go on with no drive
                raise InstrumentErrorReply(self.rig.daq.name, "the drive's watchdog expired (the host was too slow to "
                                           "reset it): the card cut the drive to 0 V")
            raise InstrumentErrorReply(self.rig.daq.name, f"the drive's watchdog could not be reset ({n} failure(s)): the card may cut the drive")

    def _record(self, index: int, a: Record, logger: "_ForceLogger") -> dict[str, Any]:
        """Stream the record block by block: each block is checked against the limits as it arrives (a trip
        puts 0 V out before the block is stored) and stored within ``EMIT_WALL_S``; a fault keeps every row read."""
        rig = self.rig
        laser_before = check_laser(rig.laser.read_displacement())
        self._check_watchdog()
        emitter = _BlockEmitter(self, index)
        i_peak = d_peak = 0.0
        with self._record_gate:  # after the logger's own safe(), if it tripped first: never during the record
            self._recording.set()
        try:
            logger.raise_if_tripped()  # tripped before the record began: no drive at all
            with closing(rig.daq.stream_finite(a.drive_V, a.fs_Hz)) as stream:
                for out in stream:
                    block = {k: out[k] for k in DAQ_COLUMNS}  # the driver's names are the stored ones
                    try:
                        check_daq_block(block, rig.limits)
                        logger.raise_if_tripped()
                        self._check_watchdog()
                    except BaseException:
                        stream.close()  # 0 V on the drive first (the stream aborts when closed early)...
                        emitter.add(block)  # ...then the rows that showed the fault are kept
                        emitter.flush()
                        raise
                    i_peak = max(i_peak, float(np.max(np.abs(block["i_A"]))))
                    d_peak = max(d_peak, float(np.max(np.abs(block["disp_m"]))))
                    emitter.add(block)
        finally:
            self._recording.clear()
            emitter.flush()  # an instrument error mid-record: what was read is stored too
        laser_after = check_laser(rig.laser.read_displacement())
        return {"i_peak_A": i_peak, "disp_peak_m": d_peak, "laser_before_m": laser_before, "laser_after_m": laser_after}


class _BlockEmitter:
    """Collects a record's DAQ blocks and emits them as ``Block`` events every ``EMIT_WALL_S`` (or ``BLOCK_ROWS``)."""

    def __init__(self, runner: Runner, index: int):
        self.r, self.index = runner, index
        self._parts: list[dict[str, np.ndarray]] = []
        self._rows = self._seq = 0
        self._since = time.monotonic()
        runner._inflight["rows_kept"]["daq"] = 0

    def add(self, block: dict[str, np.ndarray]) -> None:
        self._parts.append(block)
        self._rows += len(block["t_s"])
        if self._rows >= BLOCK_ROWS or time.monotonic() - self._since >= EMIT_WALL_S:
            self.flush()

    def flush(self) -> None:
        if self._parts:
            cols = {c: np.ascontiguousarray(np.concatenate([p[c] for p in self._parts]), float) for c in self._parts[0]}
            self._parts, self._rows = [], 0
            self.r.emit(Block(self.r.uid, self.index, "daq", cols, seq=self._seq))
            self._seq += 1
            kept = self.r._inflight["rows_kept"]
            kept["daq"] = kept.get("daq", 0) + len(cols["t_s"])
            self.r._inflight["kept_until_s"] = float(cols["t_s"][-1])
        self._since = time.monotonic()


# the command table: what each action of a plan does on the rig (Bluesky's RunEngine dispatches the same way)
_HANDLERS = {SetClamp: Runner._clamp, Settle: Runner._settle, Impedance: Runner._impedance, Record: Runner._record}


class _ForceLogger:
    """Logs each new load-cell frame once (at most ``force_rate_Hz``) as ``force`` blocks, and trips on over-force,
    overload, a non-finite force and a silent or garbled stream (``LoadCell.latest()`` raises once no valid frame
    came for its staleness limit, in rig seconds). A frame is never logged twice: no frame, no row."""

    def __init__(self, runner: Runner, index: int):
        self.r, self.index = runner, index
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._loop, name="force-logger", daemon=True)
        self._t: list[float] = []
        self._f: list[float] = []
        self._t0 = runner.rig.clock.now()
        self._trip: BaseException | None = None
        self._seq = 0
        self._last: int | None = None  # sequence number of the last frame looked at
        self._raised = False
        self._base = (0, 0)  # (frame seq, unparseable bytes) when the present garble window began

    def start(self) -> None:
        self._sample()
        self._thread.start()

    def _sample(self) -> None:
        rig = self.r.rig
        lc = rig.loadcell
        try:
            newest = lc.latest()  # stale, garbled, overloaded or gone: raises
            if self._last is None:
                self._base = (newest.seq, lc.bytes_skipped)
            check_stream(newest.seq - self._base[0], lc.bytes_skipped - self._base[1], len(newest.raw), lc.name)
            if newest.seq - self._base[0] >= GARBLED_WINDOW_FRAMES:  # a new window
                self._base = (newest.seq, lc.bytes_skipped)
            frames = lc.frames_since(newest.seq - 1 if self._last is None else self._last)
            if not frames:
                return  # nothing new since the last look: nothing to log
            self._last = frames[-1].seq
            for fr in frames:
                if fr.status == "OL":
                    raise Overload(lc.name, f"overload: {fr.raw!r}")
                check_force(fr.force_N, rig.limits, lc.name)
        except (InstrumentError, SafetyTrip) as exc:
            self._trip = exc
            return
        fr = frames[-1]
        own_clock = getattr(lc, "clock", None) is rig.clock  # frames stamped in rig time
        self._t.append((fr.t_wall if own_clock else rig.clock.now()) - self._t0)
        self._f.append(fr.force_N)

    def _loop(self) -> None:
        clock = self.r.rig.clock
        period_wall = max(1.0 / (self.r.force_rate_Hz * clock.time_scale), 0.005)
        last_emit = clock.now()
        while not self._stop.wait(period_wall):
            self._sample()
            if self._trip is not None:
                with self.r._record_gate:  # a record's loop acts on it within a block, in order
                    if not self.r._recording.is_set():
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
            kept = self.r._inflight.setdefault("rows_kept", {})
            kept["force"] = kept.get("force", 0) + len(t)

    def stop(self) -> None:
        self._stop.set()
        self._thread.join()
        if self._trip is None:
            self._sample()
        self._flush()

    def raise_if_tripped(self) -> None:
        if self._trip is not None and not self._raised:
            self._raised = True
            raise self._trip
