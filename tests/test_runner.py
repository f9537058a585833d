"""The runner on the simulated bench: events, safety, faults (drive at 0 V first), bad protocol files."""

import time

import numpy as np
import pytest

from labrig.errors import BadInput
from labrig.events import Block, RunStart, RunStop, StepEnd, StepStart
from labrig.runner import Runner
from labrig.simulate import simulated_rig
from protocols import registry


class Recorder:
    def __init__(self, on_step_start=None):
        self.events = []
        self.on_step_start = on_step_start

    def __call__(self, ev):
        self.events.append(ev)
        if isinstance(ev, StepStart) and self.on_step_start:
            self.on_step_start(ev)

    def of(self, kind):
        return [e for e in self.events if isinstance(e, kind)]


def _proto(tmp_path, text, name="p.toml"):
    path = tmp_path / name
    path.write_text(text)
    return registry.load(str(path))


def test_step_protocol_emits_a_complete_event_stream():
    rec = Recorder()
    with simulated_rig() as (rig, sims):
        res = Runner(rig, registry.load("step"), [rec]).run()
        assert sims.daq.ao_output_V() == 0.0
    assert res.exit_code == 0 and res.exit_status == "success"
    start = rec.of(RunStart)[0]
    assert [s.kind for s in start.steps] == ["clamp", "settle", "step"]
    assert all(e.status == "done" for e in rec.of(StepEnd))
    daq = [b for b in rec.of(Block) if b.stream == "daq"]
    rows = sum(len(b) for b in daq)
    assert rows == start.steps[2].streams[1].expected_rows
    disp = np.concatenate([b.data["disp_m"] for b in daq])
    assert disp.max() > 1e-3  # a 1 V step bends the strip by millimetres
    force = np.concatenate([b.data["force_N"] for b in rec.of(Block) if b.stream == "force"])
    assert force.size > 3 and abs(np.median(force) - 3062e3 * 16e-6) < 0.5
    assert rec.of(RunStop)[0].exit_status == "success"


@pytest.mark.parametrize("device, fault", [("daq", "error"), ("daq", "disconnect"), ("keyence", "disconnect"), ("keyence", "error")])
def test_instrument_fault_puts_drive_to_zero_and_exits_3(device, fault):
    rec = Recorder()
    with simulated_rig() as (rig, sims):
        runner = Runner(rig, registry.load("step"), [rec])
        steps = runner.plan()

        def inject(ev):
            if steps[ev.index].kind == "step":
                getattr(sims, device).inject(fault)

        rec.on_step_start = inject
        res = runner.run()
        if device == "daq" and fault == "disconnect":
            sims.daq.clear_fault()
        assert sims.daq.ao_output_V() == 0.0
    assert res.exit_code == 3 and "instrument fault" in res.reason and device in res.reason
    ends = rec.of(StepEnd)
    assert [e.status for e in ends] == ["done", "done", "failed"]
    assert rec.of(RunStop)[0].exit_status == "fail"


def test_current_trip_keeps_the_data_and_exits_3():
    rec = Recorder()
    with simulated_rig(safety={"max_current_A": 0.005}) as (rig, sims):
        res = Runner(rig, registry.load("step"), [rec]).run()
        assert sims.daq.ao_output_V() == 0.0
    assert res.exit_code == 3 and "safety trip" in res.reason and res.drive.startswith("drive read back at")
    rows = sum(len(b) for b in rec.of(Block) if b.stream == "daq")
    failed = [e for e in rec.of(StepEnd) if e.status == "failed"]
    assert len(failed) == 1 and failed[0].summary["rows_kept"]["daq"] == rows  # measured before the trip: kept
    planned = rec.of(RunStart)[0].steps[failed[0].index].streams[1].expected_rows
    assert 0 < rows < planned / 4  # tripped in the block of the 1 V edge, not after the record


def test_stop_request_ends_at_the_next_safe_point():
    rec = Recorder()
    with simulated_rig() as (rig, sims):
        runner = Runner(rig, registry.load("step"), [rec])
        rec.on_step_start = lambda ev: runner.request_stop() if ev.index == 0 else None
        res = runner.run()
        assert sims.daq.ao_output_V() == 0.0
    assert res.exit_status == "abort" and res.exit_code == 1
    assert [e.index for e in rec.of(StepEnd)] == [0]


def test_plan_beyond_safety_limits_is_refused_before_anything_moves(tmp_path):
    p = _proto(tmp_path, 'protocol = "step"\n[step]\namplitude_V = 5.0\n')
    with simulated_rig() as (rig, sims):
        before = sims.clamp.target_N
        with pytest.raises(BadInput, match=r"p.toml: step step_5V: drive 5 V exceeds .*max_drive_V"):
            Runner(rig, p, []).plan()
        assert sims.clamp.target_N == before  # the clamp was never asked to move


@pytest.mark.parametrize(
    "text, message",
    [
        ('protocol = "step"\n[step]\namplitdue_V = 1\n', "step.amplitdue_V: unknown field"),
        ('protocol = "nope"\n', "protocol: 'nope' is not one of"),
        ('[step]\namplitude_V = 1\n', "protocol: missing"),
        ('protocol = "paper-sweep"\n[clamp]\npressures_kPa = [612, -5]\n', "clamp: pressures_kPa must be positive"),
        ('protocol = "step"\n[step\n', "not valid TOML"),
        ('protocol = "eis"\n[eis]\nf_start_Hz = 100\nf_stop_Hz = 1\n', "eis: f_stop_Hz must be above f_start_Hz"),
    ],
)
def test_bad_protocol_files_name_file_field_and_problem(tmp_path, text, message):
    with pytest.raises(BadInput) as exc:
        _proto(tmp_path, text)
    line = str(exc.value)
    assert line.startswith(str(tmp_path / "p.toml")) and message in line and "\n" not in line


def test_every_bundled_protocol_plans_within_default_limits():
    for name in registry.PROTOCOLS:
        steps = registry.load(name).plan(16e-6)
        assert steps and len({s.name for s in steps}) == len(steps)


# ---------------------------------------------------------------------------------------------- limits as data arrives
from drivers.errors import InvalidReading, MalformedReply, StaleStream  # noqa: E402
from labrig.errors import SafetyTrip  # noqa: E402
from labrig.limits import check_daq_block, check_force, check_stream  # noqa: E402
from labrig.rig import SafeState, SafetyCfg  # noqa: E402


def _block(i_A, v_V=0.5):
    n = len(i_A)
    return {"t_s": np.arange(n) / 100.0, "v_V": np.full(n, v_V), "i_A": np.asarray(i_A, float), "disp_m": np.zeros(n)}


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_a_non_finite_reading_is_a_fault_not_a_pass(bad):
    lim = SafetyCfg(max_current_A=0.005)
    with pytest.raises(InvalidReading, match="non-finite current"):
        check_daq_block(_block([0.001, bad, 0.001]), lim)  # NaN > limit is False: it must never get that far
    with pytest.raises(InvalidReading, match="non-finite force"):
        check_force(bad, lim)


def test_block_limits_name_the_limit_and_when():
    lim = SafetyCfg(max_current_A=0.005, max_drive_V=1.0)
    check_daq_block(_block([0.001, -0.004]), lim)  # within both: no trip
    with pytest.raises(SafetyTrip, match=r"current 0.006 A exceeded safety.max_current_A = 0.005 A \(from t = 0.010 s"):
        check_daq_block(_block([0.001, -0.006]), lim)
    with pytest.raises(SafetyTrip, match="drive 1.2 V exceeded safety.max_drive_V = 1 V"):
        check_daq_block(_block([0.001], v_V=1.2), lim)
    with pytest.raises(SafetyTrip, match="clamp force 95 N"):
        check_force(95.0, SafetyCfg())


def test_a_garbled_stream_is_a_fault_even_with_some_frames():
    check_stream(frames=20, skipped_bytes=30, frame_bytes=18)  # a stray line: fine
    with pytest.raises(MalformedReply, match="garbled stream: 400 unparseable bytes against 10 valid frames"):
        check_stream(frames=10, skipped_bytes=400, frame_bytes=18)


def test_safe_state_says_0_V_only_when_read_back():
    assert SafeState(0.0004).verified and SafeState(0.0004).line() == "drive read back at +0.000 V"
    unknown = SafeState(None, ("daq: gone",))
    assert not unknown.verified and "UNKNOWN" in unknown.line() and "switch off the amplifier" in unknown.line()
    live = SafeState(0.998)
    assert not live.verified and "NOT 0 V" in live.line()


def test_load_cell_staleness_is_counted_in_rig_seconds():
    """50 rig s on a 1000x bench is 50 ms of wall time: a silent indicator is a fault within a fraction of a second."""
    from drivers.loadcell import LoadCell
    from labrig.clock import ScaledClock
    from mock_devices.loadcell_sim import LoadCellSim
    from mock_devices.serial_server import FixedBench, serve

    bench = FixedBench(force_N=9.8)
    bench.clock = ScaledClock(1000.0)
    sim = LoadCellSim(bench)
    with serve(sim, "tcp") as server, LoadCell(server.address, clock=bench.clock, stale_s=50.0, grace_wall_s=0.05) as lc:
        assert lc.force().force_N == pytest.approx(9.8, abs=0.1)
        sim.inject("timeout")  # the stream stops
        t0 = time.monotonic()
        with pytest.raises(StaleStream, match=r"limit 50.0 s"):
            while time.monotonic() - t0 < 5.0:
                lc.force()
                time.sleep(0.005)
        assert time.monotonic() - t0 < 5.0  # 50 ms wall (room for a loaded machine), not 50 wall seconds

