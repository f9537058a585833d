"""Replay a recorded session: into the live window, or against the runner (``--check``).

``check(path)`` re-runs the session's protocol (its stored config) on a rig whose drivers answer from
the session's own transcripts, each instrument stood in by its entry of ``labrig.instruments`` (the DAQ
from its recorded calls, the laser and the clamp motor through ``ReplaySerial``, the analyser through
``ReplayMessages``, the load cell through ``drivers.stream_replay.StreamReplay``). The clock is virtual (``sleep`` advances it at once), so nothing waits. Every
command the protocol sends must match the recording exactly (else ``ReplayMismatch`` names it) and
every ``daq`` and ``eis`` block the runner emits must equal the stored rows bit for bit. The load-cell
stream depends on when it was polled, so ``force`` is compared loosely: each replayed value must lie
within the step's recorded range widened by ``FORCE_SLACK_N``.

Regenerate the recorded test sessions: ``python tests/regenerate_sessions.py tests/data/sessions``.
"""

from __future__ import annotations

import hashlib
import math
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from drivers.errors import ReplayMismatch
from drivers.stream_replay import StreamReplay  # noqa: F401 - where tests and tools have always found it
from drivers.transcript import Exchange, Transcript
from labrig.errors import BadInput
from labrig.events import Block, Event, RunStart, StepStart
from labrig.instrument_kind import Replaying
from labrig.rig import Rig, kinds, parse_rig
from labrig.store.reader import SessionReader

FORCE_SLACK_N = 1.0
EXACT_STREAMS = ("daq", "eis")


class VirtualClock:
    """A rig clock that never waits: ``sleep`` advances simulated time at once (thread-safe)."""

    time_scale = 1e6  # the force logger derives its wall polling period from this: keep it at its floor

    def __init__(self, t0: float = 0.0):
        self._t, self._lock = float(t0), threading.Lock()

    def now(self) -> float:
        return self._t

    def sleep(self, seconds: float) -> None:
        if seconds > 0:
            with self._lock:
                self._t += seconds

    def sleep_until(self, t: float) -> None:
        self.sleep(t - self.now())

    def wait(self, event: threading.Event, seconds: float) -> bool:
        if event.is_set():
            return True
        self.sleep(seconds)
        return event.is_set()


@dataclass
class ReplayRig:
    rig: Rig
    replayers: dict[str, Any]  # device -> CallReplayer / ReplaySerial / ReplayMessages (their exhausted flags)

    def close(self) -> None:
        # nothing real to release; closing a driver with a recorded conversation would send traffic the recording
        # does not hold, so only the others close (the load cell's replayed stream, an operator clamp)
        for name, dev in self.rig.instruments.items():
            if name not in self.replayers:
                dev.close()


def with_rows(tr: Transcript, reader: SessionReader) -> Transcript:
    """The transcript with each result stored by reference (``meta.result_rows``) filled in from the
    session's rows, checked against the SHA-256 the writer recorded (``ReplayMismatch`` if they differ)."""
    if not any("result_rows" in e.meta for e in tr.exchanges):
        return tr
    cache: dict[tuple[int, str], Any] = {}
    out = []
    for e in tr.exchanges:
        ref = e.meta.get("result_rows")
        if isinstance(ref, dict):
            key = (int(ref["step"]), str(ref["stream"]))
            if key not in cache:
                cache[key] = reader.stream(*key)
            data, a, n = cache[key], int(ref["start"]), int(ref["count"])
            payload = b"".join(np.asarray(data[c][a:a + n], dtype="<f8").tobytes() for c in ref["columns"])
            if hashlib.sha256(payload).hexdigest() != ref.get("sha256"):
                raise ReplayMismatch(e.device, f"the stored rows {a}..{a + n} of step {key[0]} {key[1]} differ from "
                                                f"what the instrument returned (SHA-256 mismatch)")
            e = Exchange(e.t, e.device, e.op, payload, e.meta)
        out.append(e)
    return Transcript(out)


def _as_recorded(name: str, table: Any) -> Any:
    """An instrument's table as an older labrig recorded it, read as today's by its kind (unknown kinds as they are)."""
    kind = kinds().get(name)
    return kind.as_recorded(table) if kind is not None and kind.as_recorded and isinstance(table, dict) else table


def replay_rig(reader: SessionReader) -> ReplayRig:
    """A Rig whose drivers answer from the session's transcripts (instrument settings from its rig config)."""
    data = {k: v for k, v in reader.rig.items() if k in ("clock", "sample", "safety", "instruments")}
    if isinstance(data.get("instruments"), dict):
        data["instruments"] = {name: _as_recorded(name, t) for name, t in data["instruments"].items()}
    cfg = parse_rig(data, f"{reader.path} (rig as recorded)")
    start = [s.t_start for s in reader.steps() if math.isfinite(s.t_start)]
    clock = VirtualClock(min(start) if start else 0.0)
    recorded = {dev: with_rows(Transcript.loads(reader.transcript(dev)), reader) for dev in kinds()}
    replaying = Replaying(cfg, clock, recorded)
    instruments = {name: kind.replay(getattr(cfg.instruments, name), replaying) for name, kind in kinds().items()}
    return ReplayRig(Rig(cfg, clock, instruments), replaying.replayers)


@dataclass
class CheckResult:
    ok: bool
    message: str
    steps: int = 0
    blocks: int = 0
    notes: list[str] = field(default_factory=list)


class _Comparer:
    """Runner subscriber: each new block against the recorded rows of the same step and stream."""

    def __init__(self, reader: SessionReader, stop: Any):
        self.reader, self.stop = reader, stop
        self.recorded = {s.index: s for s in reader.steps()}
        self._data: dict[tuple[int, str], Any] = {}
        self.offset: dict[tuple[int, str], int] = {}
        self.first: str | None = None
        self.step: int | None = None
        self.blocks = 0
        self.steps_started = 0

    def _fail(self, msg: str) -> None:
        if self.first is None:
            self.first = msg
            self.stop()

    def _rec(self, index: int, stream: str) -> Any:
        key = (index, stream)
        if key not in self._data:
            rec = self.recorded.get(index)
            self._data[key] = self.reader.stream(index, stream) if rec is not None and stream in rec.rows else None
        return self._data[key]

    def where(self, index: int | None) -> str:
        rec = self.recorded.get(index) if index is not None else None
        return f"step {index} ({rec.name})" if rec is not None else f"step {index}"

    def __call__(self, ev: Event) -> None:
        if isinstance(ev, RunStart):
            planned = [(p.index, p.name) for p in ev.steps]
            stored = [(s.index, s.name) for s in self.recorded.values()]
            if planned != stored:
                self._fail(f"the protocol plans steps {[n for _, n in planned]} but the session holds {[n for _, n in stored]}")
        elif isinstance(ev, StepStart):
            self.step = ev.index
            self.steps_started += 1
        elif isinstance(ev, Block):
            self.blocks += 1
            self._block(ev)

    def _block(self, ev: Block) -> None:
        where = f"{self.where(ev.index)}, stream {ev.stream}"
        rec = self._rec(ev.index, ev.stream)
        if rec is None:
            return self._fail(f"{where}: the session holds no such stream")
        n, off = len(ev), self.offset.get((ev.index, ev.stream), 0)
        self.offset[(ev.index, ev.stream)] = off + n
        if ev.stream not in EXACT_STREAMS:  # force: polling-time dependent, compared loosely
            f = np.asarray(ev.data.get("force_N", []))
            ref = rec.get("force_N")
            if ref is not None and len(ref) and len(f):
                lo, hi = float(np.min(ref)) - FORCE_SLACK_N, float(np.max(ref)) + FORCE_SLACK_N
                bad = f[(f < lo) | (f > hi)]
                if bad.size:
                    self._fail(f"{where}: force {bad[0]:.3f} N outside the recorded {lo + FORCE_SLACK_N:.3f}..{hi - FORCE_SLACK_N:.3f} N (± {FORCE_SLACK_N} N)")
            return
        if off + n > rec.rows:
            return self._fail(f"{where}: rows {off}..{off + n} replayed but the session holds {rec.rows}")
        for col, arr in ev.data.items():
            want = rec[col][off : off + n]
            diff = np.flatnonzero(~((arr == want) | (np.isnan(arr) & np.isnan(want))))
            if diff.size:
                k = int(diff[0])
                return self._fail(f"{where}: {col}[{off + k}] = {arr[k]!r} replayed, {want[k]!r} recorded")

    def unmatched_rows(self) -> str | None:
        for s in self.recorded.values():
            for name, rows in s.rows.items():
                got = self.offset.get((s.index, name), 0)
                if name in EXACT_STREAMS and got != rows:
                    return f"{self.where(s.index)}, stream {name}: {got} rows replayed, {rows} recorded"
        return None


def check(path: str | Path) -> CheckResult:
    """Re-run the session's protocol against its recorded traffic; PASS or the first divergence."""
    from labrig.runner import Runner
    from protocols import registry

    with SessionReader(path) as reader:
        protocol = registry.from_dict(reader.config, f"{path} (protocol as run)")
        try:
            rr = replay_rig(reader)
        except ReplayMismatch as exc:  # a transcript's reference to rows that were changed since
            return CheckResult(False, f"FAIL: {exc}")
        runner = Runner(rr.rig, protocol, uid=reader.uid)
        cmp = _Comparer(reader, runner.request_stop)
        runner.subscribers.append(cmp)
        recorded_status = reader.exit_status
        last_started = max((s.index for s in reader.steps() if math.isfinite(s.t_start)), default=-1)
        if recorded_status == "abort":  # the operator stopped it: stop the replay where the recording ends
            runner.subscribers.append(lambda ev: runner.request_stop() if isinstance(ev, StepStart) and ev.index >= last_started else None)
        try:
            result = runner.run()
        finally:
            rr.close()
        ok = cmp.first is None
        msg = cmp.first or ""
        if ok and result.exit_status == "fail":
            ok, msg = False, f"{cmp.where(cmp.step)}: {result.reason}"
        if ok and recorded_status and result.exit_status != recorded_status:
            ok, msg = False, f"run ended {result.exit_status} ({result.reason}) but the recording ended {recorded_status}"
        if ok and (miss := cmp.unmatched_rows()):
            ok, msg = False, miss
        if ok:
            left = [dev for dev, rep in rr.replayers.items() if not rep.exhausted]
            if left:
                ok, msg = False, f"the recording holds more traffic for {', '.join(left)} than the protocol sent"
        notes = [f"force compared loosely (recorded range ± {FORCE_SLACK_N} N): it depends on when the load cell was polled"]
        if ok:
            msg = f"PASS: {cmp.steps_started} steps, {cmp.blocks} blocks, every command and every daq/eis sample as recorded"
        else:
            msg = f"FAIL: {msg}"
        return CheckResult(ok, msg, cmp.steps_started, cmp.blocks, notes)


def check_exit_code(path: str | Path) -> tuple[int, str]:
    """(exit code, report line): 0 pass, 1 divergence; ``BadInput`` (exit 2) for a bad file."""
    p = Path(path)
    if not p.exists():
        raise BadInput(f"{path}: no such file")
    res = check(p)
    return (0 if res.ok else 1), res.message


def replay_live(path: str | Path, speed: float = 1.0, screenshot: str | Path | None = None) -> int:
    """Play the session's events into the live window; returns the number of events played."""
    from labrig.live.app import new_window, run_in_window
    from labrig.live.model import LiveModel
    from labrig.live.player import play, session_events

    events = session_events(str(path))
    model = LiveModel()
    stop = threading.Event()
    win = new_window(model, stop.set, f"labrig replay: {Path(path).name} ({'max' if speed == 0 else f'{speed:g}x'} speed)")
    return run_in_window(win, lambda: play(events, model, speed, stop), screenshot=screenshot)
