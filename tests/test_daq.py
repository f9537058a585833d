"""The DAQ driver through the real nidaqmx package, over gRPC, to the simulated NI gRPC Device Server."""

from __future__ import annotations

import threading
import time

import numpy as np
import pytest
from scipy.signal import lfilter

from drivers.daq import Daq
from drivers.errors import BufferOverflow, Disconnected, InstrumentError, InstrumentErrorReply, InstrumentTimeout, ReplayMismatch
from drivers.transcript import Transcript
from labrig.clock import ScaledClock
from mock_devices.daq_grpc import SimDaq, StandInBench

GAIN_A_PER_V, M_PER_V = 2e-3, 5e-4  # not the driver defaults, so the scaling is really exercised
BUFFER_S = 10_000.0  # continuous input buffer: 100 wall s at 1000x, which a loaded machine cannot overrun


@pytest.fixture
def bench() -> StandInBench:
    return StandInBench(ScaledClock(1000.0), R_ohm=100.0, tau_s=0.05, k_m_per_V=1e-3)


@pytest.fixture
def sim(bench: StandInBench):
    with SimDaq(bench, current_gain_A_per_V=GAIN_A_PER_V, displacement_m_per_V=M_PER_V, noise_V=1e-4) as s:
        yield s


@pytest.fixture
def rig(sim: SimDaq):
    r = Daq("SimDev1", grpc_target=sim.address, current_gain_A_per_V=GAIN_A_PER_V, displacement_m_per_V=M_PER_V)
    yield r
    r.safe()


def _sine(n: int, fs: float, f: float = 5.0, amp: float = 0.8) -> np.ndarray:
    return amp * np.sin(2 * np.pi * f * np.arange(n) / fs)


def test_finite_record_matches_bench(rig: Daq, bench: StandInBench) -> None:
    fs, n = 1000.0, 3000
    drive = _sine(n, fs)
    out = rig.run_finite(drive, fs, timeout_s=5.0)
    assert set(out) == {"t_s", "v_V", "i_A", "disp_m"}
    np.testing.assert_allclose(out["t_s"], np.arange(n) / fs)
    # sample k of every input belongs to drive sample k (AO started by AI's start trigger)
    np.testing.assert_allclose(out["v_V"], drive, atol=1e-3)
    np.testing.assert_allclose(out["i_A"], drive / 100.0, atol=1e-3 * GAIN_A_PER_V)
    a = np.exp(-1.0 / (fs * 0.05))
    disp = lfilter([1 - a], [1, -a], 1e-3 * drive)
    np.testing.assert_allclose(out["disp_m"], disp, atol=1e-3 * M_PER_V)
    assert sum(r[2] for r in bench.records) == n  # the bench saw exactly the record, contiguous
    starts = [r[0] for r in bench.records]
    assert np.allclose(np.diff(starts), [r[2] / fs for r in bench.records[:-1]])


def test_wrong_calibration_scales_linearly(sim: SimDaq) -> None:
    fs, drive = 1000.0, np.r_[_sine(500, 1000.0), np.zeros(500)]  # ends at rest: the bench lag decays
    with Daq(grpc_target=sim.address, current_gain_A_per_V=GAIN_A_PER_V, displacement_m_per_V=M_PER_V) as good:
        ref = good.run_finite(drive, fs)
    off_cal = {"current_gain_A_per_V": 2 * GAIN_A_PER_V, "displacement_m_per_V": 3 * M_PER_V}
    with Daq(grpc_target=sim.address, **off_cal) as off:
        got = off.run_finite(drive, fs)
    np.testing.assert_allclose(got["i_A"], 2 * ref["i_A"], atol=5e-3 * GAIN_A_PER_V)
    np.testing.assert_allclose(got["disp_m"], 3 * ref["disp_m"], atol=5e-3 * M_PER_V)


def test_continuous_blocks_are_contiguous(rig: Daq, sim: SimDaq) -> None:
    fs, period = 100.0, 50
    block = _sine(period, fs, f=fs / period) + 0.1  # no sample at exactly 0 V: the live check below reads one
    rig.start_continuous(fs, drive_block=block, buffer_s=BUFFER_S)
    blocks = [rig.read_block(200) for _ in range(6)]
    assert sim.ao_output_V() != 0.0 or np.allclose(block, 0)
    rig.stop()
    t = np.concatenate([b["t_s"] for b in blocks])
    v = np.concatenate([b["v_V"] for b in blocks])
    np.testing.assert_allclose(t, np.arange(1200) / fs)
    np.testing.assert_allclose(v, np.tile(block, 1200 // period), atol=1e-3)  # AO regenerates, no gap
    assert sim.ao_output_V() == 0.0


def test_continuous_without_drive_reads_zero_volts(rig: Daq) -> None:
    rig.start_continuous(100.0, buffer_s=BUFFER_S)
    a, b = rig.read_block(100), rig.read_block(100)
    rig.stop()
    assert b["t_s"][0] == pytest.approx(a["t_s"][-1] + 0.01)
    assert np.max(np.abs(np.concatenate([a["v_V"], b["v_V"]]))) < 1e-3


def test_ao_returns_to_zero_after_close(sim: SimDaq) -> None:
    rig = Daq(grpc_target=sim.address)
    rig.run_finite(np.full(200, 1.5), 1000.0)
    assert sim.ao_output_V() == pytest.approx(1.5)  # the output holds the last drive sample, as hardware does
    rig.close()
    assert sim.ao_output_V() == 0.0


@pytest.mark.parametrize("fault, exc, when", [
    ("timeout", InstrumentTimeout, "before"),  # the read never completes while AO drives 2 V
    ("overflow", BufferOverflow, "before"),  # the first read fails after AO has started
    ("error", InstrumentErrorReply, "during"),  # a DAQmx error on the call after the read
])
def test_ao_returns_to_zero_after_error_mid_record(sim: SimDaq, fault: str, exc: type, when: str) -> None:
    rig = Daq(grpc_target=sim.address)
    drive = np.full(100_000, 2.0)  # 1000 s simulated = 1 s wall: a watcher a loaded machine delays still lands mid-record
    seen: list[float] = []

    def watch() -> None:
        deadline = time.monotonic() + 2.0
        while time.monotonic() < deadline and not any(
                t.kind == "ao" and t.state == "running" for t in list(sim.device.tasks.values())):
            time.sleep(0.001)
        seen.append(sim.ao_output_V())
        if when == "during":
            sim.inject(fault)

    if when == "before":
        sim.inject(fault)
    th = threading.Thread(target=watch)
    th.start()
    with pytest.raises(exc):
        rig.run_finite(drive, 100.0, timeout_s=0.5)
    th.join()
    sim.clear_fault()
    if fault != "overflow":
        assert seen == [pytest.approx(2.0)]  # the drive was live mid-record
    assert sim.ao_output_V() == 0.0
    rig.close()
    assert sim.ao_output_V() == 0.0


@pytest.mark.parametrize("fault, exc", [
    ("timeout", InstrumentTimeout),
    ("overflow", BufferOverflow),
    ("error", InstrumentErrorReply),
    ("disconnect", Disconnected),
])
def test_each_fault_maps_to_its_exception(rig: Daq, sim: SimDaq, fault: str, exc: type) -> None:
    rig.start_continuous(100.0, buffer_s=BUFFER_S)
    rig.read_block(10)
    sim.inject(fault)
    with pytest.raises(exc) as info:
        rig.read_block(10, timeout_s=0.3)
    assert info.value.device == "daq"
    if fault == "error":
        assert info.value.code == -50103
    sim.clear_fault()


def test_injected_error_code_is_reported(rig: Daq, sim: SimDaq) -> None:
    sim.inject("error", code=-200077)
    with pytest.raises(InstrumentErrorReply) as info:
        rig.run_finite(np.zeros(10), 1000.0)
    assert info.value.code == -200077 and "-200077" in str(info.value)


def test_real_overflow_when_the_reader_falls_behind(rig: Daq) -> None:
    rig.start_continuous(1000.0, buffer_s=1.0)  # 1000-sample buffer = 1 ms of wall time at 1000x
    time.sleep(0.05)
    with pytest.raises(BufferOverflow):
        rig.read_block(10)


def test_disconnect_then_server_back(sim: SimDaq) -> None:
    rig = Daq(grpc_target=sim.address)
    sim.inject("disconnect")
    with pytest.raises(Disconnected):
        rig.run_finite(np.zeros(100), 1000.0)
    assert rig.safe() is False  # cannot confirm 0 V on a dead link, and says so
    sim.clear_fault()
    with Daq(grpc_target=sim.address) as again:
        assert len(again.run_finite(np.zeros(100), 1000.0)["t_s"]) == 100


def test_replay_answers_from_the_recording(sim: SimDaq) -> None:
    tr = Transcript()
    drive, fs = _sine(400, 1000.0), 1000.0
    with Daq(grpc_target=sim.address, transcript=tr) as rig:
        live = rig.run_finite(drive, fs)
    calls = [e.meta["method"] for e in tr.for_device("daq")]
    assert calls == ["run_finite", "zero_output"]
    payload = tr.for_device("daq")[0].payload
    assert len(payload) == 4 * 400 * 8  # four float64 arrays

    saved = Transcript.loads(tr.dumps())
    with Daq.from_replay(saved, "daq") as replay:
        again = replay.run_finite(drive, fs)
    for k in live:
        np.testing.assert_array_equal(again[k], live[k])


def test_replay_mismatch_names_the_call(sim: SimDaq) -> None:
    tr = Transcript()
    drive = _sine(300, 1000.0)
    with Daq(grpc_target=sim.address, transcript=tr) as rig:
        rig.run_finite(drive, 1000.0)
    with pytest.raises(ReplayMismatch, match="run_finite"):
        Daq.from_replay(tr, "daq").run_finite(drive * 1.01, 1000.0)
    with pytest.raises(ReplayMismatch, match="run_finite"):
        Daq.from_replay(tr, "daq").run_finite(drive, 2000.0)
    with pytest.raises(ReplayMismatch, match="current_gain_A_per_V"):
        Daq.from_replay(tr, "daq", current_gain_A_per_V=5e-3).run_finite(drive, 1000.0)


def test_replay_of_a_continuous_run(sim: SimDaq) -> None:
    tr = Transcript()
    with Daq(grpc_target=sim.address, transcript=tr) as rig:
        rig.start_continuous(100.0, buffer_s=BUFFER_S)
        live = [rig.read_block(50), rig.read_block(50)]
        rig.stop()
    with Daq.from_replay(tr, "daq") as rig:
        rig.start_continuous(100.0, buffer_s=BUFFER_S)
        again = [rig.read_block(50), rig.read_block(50)]
        with pytest.raises(ReplayMismatch, match="read_block"):
            rig.read_block(60)
    for a, b in zip(live, again):
        np.testing.assert_array_equal(a["v_V"], b["v_V"])
        np.testing.assert_array_equal(a["t_s"], b["t_s"])


def test_local_path_without_ni_daqmx_is_a_clear_error() -> None:
    rig = Daq("Dev1")  # plain nidaqmx.Task(): needs the NI-DAQmx driver on this machine
    with pytest.raises((Disconnected, InstrumentErrorReply)):
        rig.run_finite(np.zeros(10), 1000.0)
    assert rig.safe() is False


def test_start_trigger_order_matters_as_on_hardware(sim: SimDaq) -> None:
    """Plain nidaqmx (high-level Task.write / Task.read): AO armed on ai/StartTrigger must be started first."""
    import grpc
    import nidaqmx
    from nidaqmx.constants import AcquisitionType

    channel = grpc.insecure_channel(sim.address)

    def task(name: str) -> nidaqmx.Task:
        return nidaqmx.Task(name, grpc_options=nidaqmx.GrpcSessionOptions(grpc_channel=channel, session_name=name))

    for ao_first in (False, True):  # the pin holds what a finished AO left: AI-first case goes first
        ao, ai = task(f"ao{ao_first}"), task(f"ai{ao_first}")
        ao.ao_channels.add_ao_voltage_chan("SimDev1/ao0")
        ai.ai_channels.add_ai_voltage_chan("SimDev1/ai0")
        for t in (ao, ai):
            t.timing.cfg_samp_clk_timing(1000.0, sample_mode=AcquisitionType.FINITE, samps_per_chan=100)
        ao.triggers.start_trigger.cfg_dig_edge_start_trig("/SimDev1/ai/StartTrigger")
        ao.write(np.full(100, 1.0), auto_start=False)
        (ao.start(), ai.start()) if ao_first else (ai.start(), ao.start())
        v = np.asarray(ai.read(100, timeout=2.0))
        assert np.allclose(v, 1.0 if ao_first else 0.0, atol=1e-3)  # late AO missed the edge: no drive
        ao.close()
        ai.close()
    channel.close()


def test_with_the_simulated_world() -> None:
    """The real world bench behind the DAQ: a finite record and a few continuous blocks."""
    from mock_devices.world import World

    world = World(ScaledClock(1000.0))
    with SimDaq(world) as sim, Daq(grpc_target=sim.address) as rig:
        fs = 1000.0
        drive = 0.5 * np.sin(2 * np.pi * np.arange(5000) / fs)
        out = rig.run_finite(drive, fs)
        np.testing.assert_allclose(out["v_V"], drive, atol=5e-3)
        assert np.all(np.isfinite(out["disp_m"])) and np.ptp(out["disp_m"]) > 0
        rig.start_continuous(fs, drive_block=drive[:1000], buffer_s=BUFFER_S)  # 30 s was 30 wall ms: overrun beside the test workers
        blocks = [rig.read_block(1000) for _ in range(3)]
        rig.stop()
        assert blocks[2]["t_s"][0] == pytest.approx(2.0)
        assert sim.ao_output_V() == 0.0


def test_an_emergency_stop_from_another_thread_stops_a_record_cleanly() -> None:
    """The force logger makes the rig safe from its own thread while the run's thread may be setting up or reading
    a record. Each record then completes or stops with an instrument error (never a half-released task); every
    0 V write succeeds and is read back, so the driver never gives the drive up to the card's watchdog."""
    from labrig.simulate import simulated_rig

    with simulated_rig() as (rig, sims):
        stop, states, outcomes = threading.Event(), [], []

        def emergency_stops() -> None:
            while not stop.is_set():
                states.append(rig.safe())
                time.sleep(0.003)

        th = threading.Thread(target=emergency_stops, daemon=True)
        th.start()
        try:
            for _ in range(30):
                try:
                    rig.daq.run_finite(np.full(300, 0.1), 1000.0)
                    outcomes.append("done")
                except InstrumentError:
                    outcomes.append("stopped")
        finally:
            stop.set()
            th.join()
        assert len(states) > 10 and "stopped" in outcomes  # the two threads did meet
        assert [s.line() for s in states if s.problems or not s.verified] == []
        assert rig.daq.watchdog.failed_resets == 0 and not rig.daq.watchdog.expired()
        out = rig.daq.run_finite(np.full(300, 0.1), 1000.0)  # and the driver records as before
        assert np.allclose(out["v_V"], 0.1, atol=5e-3)
