"""The fault matrix: every instrument x every fault its simulator can inject, with the drive live.

One cell runs a short two-pressure sweep on a fresh simulated bench into a real session file, injects
one fault while a step is in flight, and judges the outcome against the contract (docs/safety.md):

1. exit code 3;
2. the drive read back at 0 V (``RunResult.drive``), or declared UNKNOWN when the DAQ link is gone, and
   the simulated AO really at 0 V whenever the simulator can still be asked;
3. the session file opens;
4. every finished step intact (its daq and eis rows as planned);
5. the step in flight kept and marked: status ``failed``, its summary saying why and how many rows it
   kept, and the file holding exactly those rows.

Phases: ``hold`` injects ``HOLD_AT_S`` rig seconds into a ``HOLD_S`` s 1 V hold (the drive live); ``eis``
injects as the impedance step starts (the analyser's source live). An instrument that is not talked to
during the hold (laser, clamp motor, analyser) shows its fault when it is next used: the laser at the
end of the record, the clamp and the analyser at the second pressure.

Used by ``tests/test_fault_matrix.py`` (a fast subset) and ``bench/fault_matrix.py`` (all of it).
"""

from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

from labrig.events import StepStart
from labrig.runner import Runner, RunResult
from labrig.simulate import simulated_rig
from labrig.store import SessionReader, SessionWriter
from protocols import registry

HOLD_S = 120.0  # rig seconds of the 1 V hold (120 ms of wall time at 1000x)
WATCHDOG_SLACK_WALL_S = 0.25  # the simulated watchdog's own thread may run this late on a loaded host
HOLD_AT_S = 40.0  # rig seconds into the record when a hold fault is injected

# instrument -> fault kinds: the simulators' own (``inject``), then the limit and reading faults
FAULTS: dict[str, tuple[str, ...]] = {
    "daq": ("disconnect", "timeout", "overflow", "error", "over-current", "non-finite"),
    "loadcell": ("disconnect", "timeout", "garbage", "overrange", "noise", "over-force"),
    "keyence": ("disconnect", "timeout", "garbage", "error", "overrange", "invalid"),
    "impedance": ("disconnect", "timeout", "garbage", "error", "overrange"),
    "clamp": ("disconnect", "timeout", "garbage", "error"),
}


def cells() -> list[tuple[str, str, str]]:
    """(instrument, fault, phase) of the whole matrix: every fault during the hold, the analyser's also mid-EIS."""
    out = [(dev, f, "hold") for dev, kinds in FAULTS.items() for f in kinds]
    return out + [("impedance", f, "eis") for f in FAULTS["impedance"]]


SWEEP = {
    "protocol": "paper-sweep", "rest_s": 0.0,
    "clamp": {"pressures_kPa": [3062.0, 1837.0], "tolerance_N": 0.5, "hold_s": 2.0, "timeout_s": 60.0, "settle_s": 2.0},
    "eis": {"f_start_Hz": 100.0, "f_stop_Hz": 1000.0, "points": 3, "ac_V": 0.01, "bias_V": 0.0},
    "step": {"amplitude_V": 1.0, "on_s": HOLD_S, "off_s": 1.0, "fs_Hz": 200.0},
}
KINDS = ("clamp", "settle", "eis", "step")  # the steps of each pressure the matrix keeps


class _MatrixProtocol(registry.LoadedProtocol):
    """The paper sweep above with only clamp, settle, EIS and the hold at each pressure (six steps: a cell's
    session layout is a third of the full sweep's)."""

    def plan(self, clamp_area_m2: float) -> list[Any]:
        return [s for s in super().plan(clamp_area_m2) if s.kind in KINDS]


def protocol() -> registry.LoadedProtocol:
    """At two pressures: clamp, settle, a 3-point EIS and a ``HOLD_S`` 1 V hold."""
    p = registry.from_dict(SWEEP, "fault matrix")
    return _MatrixProtocol(p.name, p.config, p.source)


@dataclass
class Cell:
    instrument: str
    fault: str
    phase: str
    result: RunResult | None = None
    problems: list[str] = field(default_factory=list)
    ao_V: float | None = None  # the simulated AO after the run (None: not asked)
    watchdog_rig_s: float | None = None  # link lost: rig seconds from the loss to 0 V on the AO (the DAQ's watchdog)
    in_flight: str = ""  # the step that failed, and the rows it kept
    wall_s: float = 0.0

    @property
    def ok(self) -> bool:
        return self.result is not None and not self.problems

    def row(self) -> str:
        r = self.result
        code = "-" if r is None else str(r.exit_code)
        verdict = "ok" if self.ok else "FAIL: " + "; ".join(self.problems)
        return f"{self.instrument:9s} {self.fault:12s} {self.phase:5s} exit {code}  {self.wall_s:4.1f} s  {self.in_flight:38s} {verdict}"


def _injector(sims: Any, rig: Any, instrument: str, fault: str) -> Callable[[], None]:
    """What injecting ``fault`` into ``instrument`` does on this bench."""
    if fault == "over-current":
        return lambda: None  # the cell runs with a current limit the 1 V hold breaks
    if fault == "non-finite":
        return lambda: setattr(rig.daq, "current_gain_A_per_V", math.inf)  # a calibration gone bad mid-record
    if fault == "over-force":
        return lambda: sims.bench.set_clamp_force(80.0)  # the clamp crushes the strip (limit 60 N)
    if instrument == "clamp" and fault == "error":  # the clamp simulator answers ER,.. on it but does not list it
        return lambda: setattr(sims.clamp, "fault", "error")
    return lambda: getattr(sims, instrument).inject(fault)


def wait_for_zero(sims: Any, clock: Any, until_rig_s: float) -> float | None:
    """Rig time at which the simulated AO first reads 0 V, polled until rig time ``until_rig_s`` (None: never)."""
    while True:
        if sims.daq.ao_output_V() == 0.0:
            return clock.now()
        if clock.now() > until_rig_s:
            return None
        time.sleep(0.001)


class _DriveWatch:
    """Notes when the simulated card starts a timed AO task (the drive goes live), from inside the card."""

    def __init__(self, device: Any):
        self.started = threading.Event()
        self.t0 = math.nan
        begin = device._begin

        def watched(task: Any, t0: float) -> None:
            begin(task, t0)
            if task.kind == "ao" and task.rate and not self.started.is_set():
                self.t0 = t0
                self.started.set()

        device._begin = watched

    def wait(self, clock: Any, after_s: float) -> None:
        """Return ``after_s`` rig seconds after the drive went live."""
        if self.started.wait(30.0):
            clock.sleep(self.t0 + after_s - clock.now())


SAFETY = {"over-current": {"max_current_A": 0.005}, "over-force": {"max_force_N": 60.0}}


def run_cell(instrument: str, fault: str, phase: str, out_dir: Path, time_scale: float = 1000.0) -> Cell:
    """Run one cell into ``out_dir`` and judge it against the contract."""
    cell = Cell(instrument, fault, phase)
    path = Path(out_dir) / f"{instrument}-{fault}-{phase}.h5"
    w0 = time.monotonic()
    proto = protocol()
    with simulated_rig(time_scale=time_scale, safety=SAFETY.get(fault)) as (rig, sims):
        injected: dict[str, float] = {}
        do_inject = _injector(sims, rig, instrument, fault)

        def inject() -> None:
            injected["t"] = rig.clock.now()
            do_inject()

        watch = _DriveWatch(sims.daq.device)
        wd = getattr(rig.daq, "watchdog", None)
        wd_timeout = None if wd is None else float(wd.timeout_s)
        writer = SessionWriter(path)
        runner = Runner(rig, proto, [writer])
        steps = runner.plan()
        target = "eis" if phase == "eis" else "step"
        target_i = next(i for i, s in enumerate(steps) if s.kind == target)
        timers: list[threading.Thread] = []

        def on_event(ev: Any) -> None:
            if isinstance(ev, StepStart) and ev.index == target_i:
                if phase == "eis":
                    inject()
                    return
                watch.started.clear()  # HOLD_AT_S rig seconds into this step's drive, from a thread (the runner is recording)
                t = threading.Thread(target=lambda: (watch.wait(rig.clock, HOLD_AT_S), inject()), daemon=True)
                t.start()
                timers.append(t)

        runner.subscribers.append(on_event)
        cell.result = runner.run()
        for t in timers:
            t.join(timeout=5.0)
        if not (instrument == "daq" and fault == "disconnect"):
            cell.ao_V = sims.daq.ao_output_V()
        elif wd_timeout is not None and "t" in injected:  # the link is gone: the DAQ's own watchdog must act
            t_zero = wait_for_zero(sims, rig.clock, injected["t"] + wd_timeout + WATCHDOG_SLACK_WALL_S * time_scale)
            cell.ao_V = sims.daq.ao_output_V()
            cell.watchdog_rig_s = None if t_zero is None else t_zero - injected["t"]
    cell.wall_s = time.monotonic() - w0
    cell.problems = judge(cell, path, steps, target_i)
    return cell


def judge(cell: Cell, path: Path, steps: list[Any], target_i: int) -> list[str]:
    """Every way ``cell`` breaks the contract (empty: it meets it)."""
    r = cell.result
    assert r is not None
    bad: list[str] = []
    if r.exit_code != 3:
        bad.append(f"exit {r.exit_code} ({r.reason[:80]})")
    if cell.instrument == "daq" and cell.fault != "non-finite":  # a faulty card may not be able to read back
        if "UNKNOWN" not in r.drive and not (r.drive.startswith("drive read back at") and "NOT" not in r.drive):
            bad.append(f"drive neither read back at 0 V nor declared unknown: {r.drive!r}")
    elif not r.drive.startswith("drive read back at") or "NOT" in r.drive:
        bad.append(f"drive not read back at 0 V: {r.drive!r}")
    if cell.ao_V is not None and cell.ao_V != 0.0:
        bad.append(f"simulated AO at {cell.ao_V:+.3f} V after the run")
    try:
        with SessionReader(path) as rd:
            recs = rd.steps()
            streams = {s.index: {n: rd.stream(s.index, n).rows for n in rd.streams(s.index)} for s in recs}
    except Exception as exc:  # the contract: the file opens
        return bad + [f"session does not open: {type(exc).__name__}: {exc}"]
    failed = [s for s in recs if s.status not in ("done", "planned")]
    for s in recs:
        if s.status == "done":
            for name in ("daq", "eis"):
                want = s.expected_rows.get(name, 0)
                if want and streams[s.index].get(name, 0) != want:
                    bad.append(f"finished step {s.name}: {name} {streams[s.index].get(name, 0)} of {want} rows")
    if len(failed) != 1 or failed[0].status != "failed":
        return bad + [f"in-flight step not marked failed: {[(s.name, s.status) for s in failed]}"]
    s = failed[0]
    kept = s.summary.get("rows_kept", {})
    cell.in_flight = f"{s.name.split('/')[-1]}: {', '.join(f'{k} {v}' for k, v in kept.items())}"
    if not s.summary.get("reason"):
        bad.append(f"{s.name}: failed without a reason")
    for name, n in kept.items():
        if streams[s.index].get(name, 0) != n:
            bad.append(f"{s.name}: summary says {n} {name} rows kept, the file holds {streams[s.index].get(name, 0)}")
    if s.index == target_i and steps[target_i].kind == "step" and cell.instrument == "loadcell":
        if kept.get("daq", 0) <= 0:  # the DAQ is healthy: the rows up to the fault are stored
            bad.append(f"{s.name}: no daq rows kept from before the fault")
    return bad


def run_matrix(selected: list[tuple[str, str, str]], out_dir: Path, time_scale: float = 1000.0,
               echo: Callable[[str], None] = lambda line: None) -> list[Cell]:
    out = []
    for dev, fault, phase in selected:
        cell = run_cell(dev, fault, phase, out_dir, time_scale)
        echo(cell.row())
        out.append(cell)
    return out


def over_current_latency(time_scale: float, limit_A: float = 0.005) -> float:
    """Rig seconds from the first sample over ``limit_A`` to 0 V on the simulated AO (the step protocol)."""
    with simulated_rig(time_scale=time_scale, safety={"max_current_A": limit_A}) as (rig, sims):
        bench, dev, clock = sims.bench, sims.daq.device, rig.clock
        seen: dict[str, float] = {}
        run_record, write = bench.run_record, dev.write

        def watch_record(t0: float, fs: float, drive: np.ndarray) -> dict[str, np.ndarray]:
            out = run_record(t0, fs, drive)
            over = np.flatnonzero(np.abs(out["i_A"]) > limit_A)
            if over.size and "exceed" not in seen:
                seen["exceed"] = t0 + over[0] / fs
            return out

        def watch_write(name: str, *a: Any) -> int:
            n = write(name, *a)
            if "exceed" in seen and "zero" not in seen and dev.task(name).rate is None and dev.ao_level.get("ao0") == 0.0:
                seen["zero"] = clock.now()
            return n

        bench.run_record, dev.write = watch_record, watch_write
        res = Runner(rig, registry.load("step"), []).run()
    if res.exit_code != 3 or "zero" not in seen:
        raise RuntimeError(f"the over-current trip did not happen: {res.reason}")
    return seen["zero"] - seen["exceed"]
