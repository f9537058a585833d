"""Pause and suspension (issue 14 item 3): the drive at 0 V while held, the interrupted step run again from
its start, every hold recorded in the session; from a pause file, SIGUSR1 and a [safety.suspend] watch."""

import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

from labrig.events import Pause, StepStart
from labrig.runner import Runner
from labrig.simulate import simulated_rig
from labrig.store import SessionReader, SessionWriter
from labrig.suspenders import PauseControl
from protocols import registry

STEP_TOML = Path(__file__).parent / "data" / "sessions" / "step.toml"


class Hooks:
    """Subscriber calling ``on(kind)(event)`` for the events a test cares about."""

    def __init__(self, **on):
        self.on, self.events = on, []

    def __call__(self, ev):
        self.events.append(ev)
        fn = self.on.get(type(ev).__name__)
        if fn:
            fn(ev)


def test_a_pause_file_holds_the_run_at_0V_and_the_step_starts_over(tmp_path):
    pause = tmp_path / "PAUSE"
    out = tmp_path / "s.h5"
    held_V = []
    with simulated_rig(time_scale=1000.0) as (rig, sims):
        def step_start(ev):
            if ev.index == 1 and not held_V:  # the settle after the clamp
                pause.write_text("refill the water")

        def paused(ev):
            if not ev.resumed:
                held_V.append(sims.daq.ao_output_V())
                threading.Timer(0.3, pause.unlink).start()  # 300 rig s later the operator is done

        hooks = Hooks(StepStart=step_start, Pause=paused)
        runner = Runner(rig, registry.load(str(STEP_TOML)), [SessionWriter(out), hooks], pauses=PauseControl(pause))
        res = runner.run()
    assert res.exit_code == 0, res.reason
    assert held_V == [0.0]
    holds = [e for e in hooks.events if isinstance(e, Pause)]
    assert [(e.kind, e.index, e.resumed) for e in holds] == [("pause", 1, False), ("pause", 1, True)]
    assert str(pause) in holds[0].reason
    starts = [e.index for e in hooks.events if isinstance(e, StepStart)]
    assert starts == [0, 1, 1, 2]  # the interrupted settle ran again from its start
    with SessionReader(out) as r:
        assert [(p["event"], p["kind"], p["step"]) for p in r.pauses] == [("hold", "pause", 1), ("resume", "pause", 1)]
        assert r.pauses[1]["t"] - r.pauses[0]["t"] > 100  # held for ~300 rig seconds
        steps = r.steps()
        assert all(s.status == "done" for s in steps)
        assert steps[1].t_start >= r.pauses[1]["t"]  # the settle's times are those of its second run
        assert steps[1].rows["force"] > 0 and not r.incomplete()


def test_a_suspender_holds_while_the_clamp_force_is_out_of_tolerance(tmp_path):
    out = tmp_path / "s.h5"
    suspend = {"clamp_force_tol_N": 2.0, "resume_after_s": 5.0, "poll_s": 1.0}
    with simulated_rig(time_scale=1000.0, safety={"suspend": suspend}) as (rig, sims):
        target = []

        def step_start(ev):
            if ev.index == 1 and not target:  # the clamp slips during the settle
                target.append(sims.bench._force_target)
                sims.bench.set_clamp_force(target[0] - 10.0)
                deadline = time.monotonic() + 5.0  # until the load cell shows it (a loaded machine lags)
                while rig.loadcell.force().force_N > target[0] - 5.0 and time.monotonic() < deadline:
                    time.sleep(0.001)

        def paused(ev):
            if not ev.resumed:
                target.append(sims.daq.ao_output_V())
                threading.Timer(0.2, sims.bench.set_clamp_force, (target[0],)).start()  # re-tightened

        hooks = Hooks(StepStart=step_start, Pause=paused)
        res = Runner(rig, registry.load(str(STEP_TOML)), [SessionWriter(out), hooks]).run()
    assert res.exit_code == 0, res.reason
    holds = [e for e in hooks.events if isinstance(e, Pause)]
    assert [(e.kind, e.resumed) for e in holds] == [("suspend", False), ("suspend", True)], [(type(e).__name__, getattr(e, "index", None)) for e in hooks.events if type(e).__name__ != "Block"]
    assert "clamp force" in holds[0].reason and "± 2 N" in holds[0].reason
    assert target[1] == 0.0  # drive at 0 V while suspended
    with SessionReader(out) as r:
        assert [p["kind"] for p in r.pauses] == ["suspend", "suspend"]
        assert all(s.status == "done" for s in r.steps())


def _steps_done(path):
    try:
        with SessionReader(path) as r:
            return sum(s.status == "done" for s in r.steps()), len(r.pauses)
    except Exception:
        return 0, 0


def test_sigusr1_pauses_and_resumes_a_headless_run(tmp_path):
    # A settle of 60 rig s (1.5 wall s at 40x) after the clamp: the signal, sent once the clamp is on
    # disk, lands inside it however slowly the file is polled on a loaded machine; the settle has safe
    # points every rig second, so the hold cannot miss it and the run cannot finish first.
    toml = tmp_path / "step.toml"
    toml.write_text(STEP_TOML.read_text().replace("settle_s = 5.0", "settle_s = 60.0"))
    out = tmp_path / "s.h5"
    proc = subprocess.Popen([sys.executable, "-m", "labrig", "run", str(toml), "--sim", "--quiet", "--time-scale", "40",
                             "--out", str(out)], stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.time() + 60
        while _steps_done(out)[0] < 1 and time.time() < deadline:
            time.sleep(0.05)
        proc.send_signal(signal.SIGUSR1)
        while _steps_done(out)[1] < 1 and time.time() < deadline:
            time.sleep(0.05)
        done_at_hold = _steps_done(out)[0]
        assert done_at_hold == 1  # held inside the settle
        time.sleep(2.0)  # 80 rig seconds: the 60 s settle would be over if it ran
        assert _steps_done(out) == (done_at_hold, 1) and proc.poll() is None
        proc.send_signal(signal.SIGUSR1)
        assert proc.wait(60) == 0, proc.stderr.read()
    finally:
        if proc.poll() is None:
            proc.kill()
    with SessionReader(out) as r:
        assert [(p["event"], p["reason"]) for p in r.pauses] == [("hold", "SIGUSR1"), ("resume", "SIGUSR1")]
        assert r.exit_status == "success" and all(s.status == "done" for s in r.steps())


def test_ctrl_c_at_a_terminal_asks_and_abort_stops_with_the_drive_at_0V(tmp_path):
    """What _Interrupts does on Ctrl-C at a terminal: a hold with the question; the answer 'abort' ends the run."""
    asked = []
    out = tmp_path / "s.h5"
    with simulated_rig(time_scale=1000.0) as (rig, sims):
        pauses = PauseControl(ask=lambda where: asked.append((where, sims.daq.ao_output_V())) or "abort")
        hooks = Hooks(StepStart=lambda ev: pauses.request("Ctrl-C") if ev.index == 1 else None)
        res = Runner(rig, registry.load(str(STEP_TOML)), [SessionWriter(out), hooks], pauses=pauses).run()
    assert res.exit_code == 1 and res.exit_status == "abort" and "while paused" in res.reason
    assert asked == [("paused at step 2 (Ctrl-C)", 0.0)]  # asked with the drive already at 0 V
    with SessionReader(out) as r:
        assert [(p["event"], p["reason"]) for p in r.pauses] == [("hold", "Ctrl-C")]
        assert [s.status for s in r.steps()] == ["done", "aborted", "planned"]
