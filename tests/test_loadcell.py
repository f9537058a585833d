"""Load-cell indicator driver against its simulated stream on a real pty and on socket://, plus replay."""

from __future__ import annotations

import math
import time
from pathlib import Path

import pytest

from drivers import errors
from drivers.loadcell import LoadCell, parse_frame
from drivers.transcript import Exchange, ReplaySerial, Transcript
from labrig.clock import ScaledClock
from labrig.instruments import STALE_GRACE_WALL_S
from mock_devices.loadcell_sim import LoadCellSim
from mock_devices.serial_server import FixedBench, serve

TRANSCRIPT = Path(__file__).parent / "data" / "transcripts" / "loadcell_basic.jsonl"
G_N = 9.80665  # standard gravity, N per kgf (independent of the driver's constant)
HALF_COUNT_N = 0.005 * G_N + 1e-9  # frames carry 0.01 kgf


class World:
    """Stand-in bench: clamp force ``force(t)`` of simulated time t on a 1000x clock."""

    def __init__(self, force_N: float = 0.0):
        self.clock = ScaledClock(1000.0)
        self.force = lambda t: force_N

    def clamp_force_now(self) -> float:
        return self.force(self.clock.now())


def _fresh(lc: LoadCell, expect_N: float | None = None, wall_s: float = 1.0):
    """Reading after three more frames (one may be in flight, one unstable after a change) or, given
    ``expect_N``, once a stable frame within half a count of it arrived (a loaded CI box may delay the
    reader thread; a wrong value still fails after ``wall_s``)."""
    seq = lc._seq
    deadline = time.monotonic() + wall_s
    while time.monotonic() < deadline:
        if lc._seq >= seq + 3:
            r = lc.force()
            if expect_N is None or (r.stable and abs(r.force_N - expect_N) <= HALF_COUNT_N):
                return r
        time.sleep(0.002)
    return lc.force()


@pytest.fixture(params=["pty", "tcp"])
def rig(request):
    bench = World(4.9)
    sim = LoadCellSim(bench)
    # the grace labrig opens it with: a loaded host that stalls the reader thread gets to catch up before a stream
    # reads as stale (without it a disconnect read as StaleStream when the sweeps ran beside this test)
    with serve(sim, request.param) as server, LoadCell(server.address, stale_s=0.15, grace_wall_s=STALE_GRACE_WALL_S) as lc:
        yield bench, sim, lc, server


@pytest.mark.parametrize("f_N", [4.9, 12.3456, 0.0, -0.7, 97.9])
def test_force_matches_bench_within_resolution(rig, f_N):
    bench, _, lc, _ = rig
    bench.force = lambda t: f_N
    reading = _fresh(lc, f_N)
    assert reading.force_N == pytest.approx(f_N, abs=HALF_COUNT_N)
    assert reading.stable


def test_newton_frames():
    bench = World(12.3456)
    with serve(LoadCellSim(bench, unit="N"), "tcp") as server, LoadCell(server.address, stale_s=0.15) as lc:
        assert lc.latest().raw == b"ST,GS,+0012.35N\r\n" or lc.latest().raw.endswith(b"N\r\n")
        assert _fresh(lc, 12.3456).force_N == pytest.approx(12.3456, abs=0.005 + 1e-9)


def test_wall_frame_rate_is_capped_at_1000x(rig):
    _, sim, lc, _ = rig
    assert sim.stream_interval_s >= 1 / 200
    # counted where the frames are made (the reader may catch up on a backlog a loaded machine left it)
    sent0, t0 = sim._count, time.monotonic()
    time.sleep(0.2)
    sent, took = sim._count - sent0, time.monotonic() - t0
    assert 0 < sent <= 200 * took + 1


def test_wait_stable_waits_out_the_ramp(rig):
    bench, _, lc, _ = rig
    clock = bench.clock
    t_end = clock.now() + 60.0  # 60 simulated seconds of ramp = 60 ms wall
    bench.force = lambda t: 9.8 * min(1.0, max(0.0, 1 - (t_end - t) / 60.0))
    reading = lc.wait_stable(9.8, 0.1, hold_s=10.0, timeout_s=400.0, clock=clock)
    assert clock.now() >= t_end + 10.0 - 1e-6  # not before the ramp ended and the hold passed
    assert reading.stable and reading.force_N == pytest.approx(9.8, abs=0.1)


def test_wait_stable_times_out_off_target(rig):
    bench, _, lc, _ = rig
    with pytest.raises(errors.InstrumentTimeout, match="did not hold"):
        lc.wait_stable(20.0, 0.1, hold_s=1.0, timeout_s=50.0, clock=bench.clock)


def test_wait_stable_rejects_an_unsteady_force_on_target(rig):
    bench, _, lc, _ = rig
    bench.force = lambda t: 9.8 + 0.05 * math.sin(0.7 * t)  # within tolerance, never steady
    with pytest.raises(errors.InstrumentTimeout, match="unstable|stable"):
        lc.wait_stable(9.8, 0.2, hold_s=30.0, timeout_s=200.0, clock=bench.clock)


def test_tare_and_zero(rig):
    bench, _, lc, _ = rig
    lc.tare()
    r = _fresh(lc, 0.0)
    assert r.force_N == pytest.approx(0.0, abs=HALF_COUNT_N) and lc.latest().kind == "NT"
    lc.zero()  # 4.9 N is inside the zero range
    assert lc.latest().kind == "GS"
    bench.force = lambda t: 4.9 + 2.0
    assert _fresh(lc, 2.0).force_N == pytest.approx(2.0, abs=HALF_COUNT_N)


def test_zero_refused_under_load_is_reported(rig):
    bench, _, lc, _ = rig
    bench.force = lambda t: 50.0
    _fresh(lc)
    with pytest.raises(errors.InstrumentTimeout, match="zero"):
        lc.zero(confirm_s=0.1)


@pytest.mark.parametrize("fault,exc", [
    ("overrange", errors.Overload),
    ("timeout", errors.StaleStream),
    ("garbage", errors.MalformedReply),
    ("disconnect", errors.Disconnected),
])
def test_each_fault_gives_its_exception(rig, fault, exc):
    _, sim, lc, _ = rig
    assert _fresh(lc, 4.9).force_N == pytest.approx(4.9, abs=HALF_COUNT_N)
    sim.inject(fault)
    t0 = time.monotonic()
    with pytest.raises(exc):
        while time.monotonic() - t0 < 2.5:  # stale_s plus a frame (room for a loaded machine), never a hang
            lc.force()
            time.sleep(0.005)
    assert time.monotonic() - t0 < 3.0  # stale_s (0.15 s) and the grace (1 s), with room for a loaded machine
    if fault != "disconnect":
        sim.clear_fault()
        assert _fresh(lc, 4.9).force_N == pytest.approx(4.9, abs=HALF_COUNT_N)  # recovers


def test_real_overload_above_98N(rig):
    bench, _, lc, _ = rig
    bench.force = lambda t: 120.0
    with pytest.raises(errors.Overload):
        _fresh(lc)


def test_noise_between_frames_is_skipped(rig):
    bench, sim, lc, _ = rig
    sim.inject("noise")
    for f_N in (3.0, 7.5):
        bench.force = lambda t, f=f_N: f
        assert _fresh(lc, f_N).force_N == pytest.approx(f_N, abs=HALF_COUNT_N)
    assert lc.bytes_skipped > 0


@pytest.mark.parametrize("fault,exc", [("garbage", errors.MalformedReply), ("timeout", errors.StaleStream)])
def test_dead_from_the_start(fault, exc):
    sim = LoadCellSim(World(1.0))
    sim.inject(fault)
    with serve(sim, "pty") as server, LoadCell(server.address, stale_s=0.1) as lc:
        t0 = time.monotonic()
        with pytest.raises(exc):
            lc.force()
        assert time.monotonic() - t0 < 2.0  # stale_s (0.1 s) with room for a loaded machine; a hang never ends


# -- parsing ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("line,status,kind,force", [
    (b"ST,GS,+0012.34Kg\r\n", "ST", "GS", 12.34 * G_N),
    (b"US,NT,-0000.05Kg\r\n", "US", "NT", -0.05 * G_N),
    (b"ST,GS,+0012.34 N\r\n", "ST", "GS", 12.34),
    (b"ST,GS,+   1.50kg\r\n", "ST", "GS", 1.5 * G_N),
])
def test_parse_frame(line, status, kind, force):
    f = parse_frame(line)
    assert (f.status, f.kind) == (status, kind) and f.force_N == pytest.approx(force)


@pytest.mark.parametrize("line", [b"ST,GS,+0012.34Kg", b"XX,GS,+0012.34Kg\r\n", b"ST,GS,+12.34Kg\r\n",
                                  b"\x90ST,GS,+0012.34Kg\r\n", b"ST,GS,+00.2.34Kg\r\n", b"ST,GS,+0012.34oz\r\n",
                                  b"ST,GS,+00 2.34kg\r\n", b"ST,GS,     .  kg\r\n"])
def test_parse_frame_rejects(line):
    assert parse_frame(line) is None


def test_overload_frame_with_no_number():
    f = parse_frame(b"OL,GS,+   .   Kg\r\n")
    assert f is not None and f.status == "OL" and math.isnan(f.force_N)


def _stream(data: bytes, **kw) -> LoadCell:
    return LoadCell(ReplaySerial([Exchange(0, "loadcell", "read", data)]), background=False, **kw)


def test_resync_after_garbage_and_overlong_lines():
    junk = b"\x90\x91\x92" * 40  # no LF: longer than a line, dropped
    lc = _stream(b"ST,GS,+00" + junk + b"\r\nST,GS,+0001.00Kg\r\n\xa0\xa1ST,GS,+0009.99Kg\r\nST,GS,+0002.00Kg\r\n")
    assert lc.force() == (pytest.approx(2.0 * G_N), True)
    assert lc.bytes_skipped > len(junk)


def test_only_garbage_is_malformed_not_a_hang():
    with pytest.raises(errors.MalformedReply):
        _stream(b"\x90\x91\x92\r\n" * 20).force()
    with pytest.raises(errors.StaleStream):
        _stream(b"").force()


# -- recorded traffic --------------------------------------------------------------------------------


def test_recording_captures_the_stream_and_commands(rig):
    _, _, first, server = rig
    first.close()  # a serial line has one client
    tr = Transcript()
    with LoadCell(server.address, transcript=tr, stale_s=0.5) as lc:
        lc.force()
        lc.tare()
    data = b"".join(e.payload for e in tr if e.op == "read")
    assert [e.payload for e in tr if e.op == "write"] == [b"T\r\n"]
    assert b"ST,GS,+0000.50kg\r\n" in data and b"ST,NT,+0000.00kg\r\n" in data


def test_replay_of_recorded_session():
    lc = LoadCell(ReplaySerial(Transcript.load(TRANSCRIPT).for_device("loadcell")), background=False)
    assert lc.force() == (pytest.approx(0.5 * G_N), True)
    lc.zero()
    assert lc.force() == (pytest.approx(1.0 * G_N), True)  # last frame before the tare: load added
    lc.tare()
    assert lc.force() == (pytest.approx(0.0), True) and lc.latest().kind == "NT"
    assert lc.port.exhausted


def test_replay_names_an_unrecorded_command():
    lc = LoadCell(ReplaySerial(Transcript.load(TRANSCRIPT).for_device("loadcell")), background=False)
    with pytest.raises(errors.ReplayMismatch, match=r"T\\r\\n"):
        lc.tare()  # the recording zeroes first


# -- the frames of real indicators (facts from each manual's data-format section, written anew) ------

LB_N = 0.45359237 * G_N


@pytest.mark.parametrize("line, status, kind, force", [
    # A&D AD-4329 "format 1" / AD-4404 "A&D data format": 8-figure data with polarity, 2- or 3-figure unit
    (b"ST,GS,+0012.34kg\r\n", "ST", "GS", 12.34 * G_N),
    (b"US,NT,-0000.05kg\r\n", "US", "NT", -0.05 * G_N),
    (b"ST,G ,+0001.50 kg\r\n", "ST", "GS", 1.5 * G_N),  # "G " header, 3-figure unit
    (b"ST,N ,+0123.40 g\r\n", "ST", "NT", 0.1234 * G_N),  # " g"
    (b"ST,GS,+00.0125 t\r\n", "ST", "GS", 12.5 * G_N),  # " t"
    (b"ST,GS,+0010.00lb\r\n", "ST", "GS", 10 * LB_N),
    (b"ST,GS,+0009.81 N\r\n", "ST", "GS", 9.81),
    # Tiger TI-02-P auto weight string: a space for the plus sign, a comma before the unit
    (b"ST,GS, 0012.34,kg\r\n", "ST", "GS", 12.34 * G_N),
    (b"US,NT,-0000.25,lb\r\n", "US", "NT", -0.25 * LB_N),
    (b"ST,GS,   12.34, g\r\n", "ST", "GS", 0.01234 * G_N),
    # CAS 22-byte format: device ID and lamp byte, 8-byte data without sign, a blank before the unit
    (b"ST,GS,1\xc4,000013.5 kg\r\n", "ST", "GS", 13.5 * G_N),
    (b"US,NT,1\x86,-00013.5 kg\r\n", "US", "NT", -13.5 * G_N),
    # CAS "18 bytes for AND" (also Dacell's A&D-compatible stream)
    (b"ST,GS,000013.5kg\r\n", "ST", "GS", 13.5 * G_N),
])
def test_frames_of_real_indicators(line, status, kind, force):
    f = parse_frame(line)
    assert f is not None and (f.status, f.kind) == (status, kind)
    assert f.force_N == pytest.approx(force, rel=1e-9)


@pytest.mark.parametrize("line", [b"ST,TR,+0001.00kg\r\n", b"ST,T ,+0001.00kg\r\n", b"ST,PT,+0001.00kg\r\n"])
def test_tare_frames_are_not_the_load(line):
    f = parse_frame(line)
    assert f is not None and f.kind in ("TR", "PT")
    lc = _stream(b"ST,GS,+0002.00kg\r\n" + line)
    assert lc.force().force_N == pytest.approx(2.0 * G_N)  # the gross frame, not the tare after it


def test_ad_out_of_range_frame_is_an_overload_not_a_stale_stream():
    lc = _stream(b"ST,GS,+0009.00kg\r\nOL,GS,     .  kg\r\n")
    with pytest.raises(errors.Overload, match="overload"):
        lc.force()


def test_simulator_speaks_ad_format_with_lower_case_kg():
    sim = LoadCellSim(FixedBench(force_N=0.5 * G_N))
    assert sim.frame() == b"US,GS,+0000.50kg\r\n"
    assert sim.frame() == b"ST,GS,+0000.50kg\r\n"
    sim.inject("overrange")
    assert sim.frame() == b"OL,GS,     .  kg\r\n"
    assert LoadCellSim(FixedBench(force_N=9.81), unit="N").frame() == b"US,GS,+0009.81 N\r\n"


def test_an_overload_during_a_run_drives_to_zero_and_exits_3():
    from labrig.events import StepStart
    from labrig.runner import Runner
    from labrig.simulate import simulated_rig
    from protocols import registry

    with simulated_rig() as (rig, sims):
        runner = Runner(rig, registry.load("step"), [])
        steps = runner.plan()
        runner.subscribers.append(lambda ev: isinstance(ev, StepStart) and steps[ev.index].kind == "step"
                                  and sims.loadcell.inject("overrange"))
        res = runner.run()
        assert sims.daq.ao_output_V() == 0.0
    assert res.exit_code == 3 and "loadcell" in res.reason and "overload" in res.reason.lower()


@pytest.mark.parametrize("transport", ["pty", "tcp"])
def test_project_sperm_scales_client_reads_the_simulator(transport):
    """woxuankai/project_sperm's scales module (an A&D-format reader): open the port, flush input, read a line to
    drop a partial one, read the next, weight = float(line[6:14] without spaces). Written anew as facts; the
    18-byte A&D frame ("18 bytes for AND" in the CAS manuals) is what it slices."""
    import serial

    bench = World(1.2345 * G_N)
    with serve(LoadCellSim(bench), transport) as server:
        port = serial.serial_for_url(server.address, timeout=1.0)
        try:
            port.reset_input_buffer()
            port.readline()
            line = port.readline()
        finally:
            port.close()
    assert len(line) == 18 and line.endswith(b"\r\n") and line[:6] in (b"ST,GS,", b"US,GS,")
    assert float(line[6:14].decode().replace(" ", "")) == pytest.approx(1.23, abs=0.005)
    assert line[14:16] == b"kg"


def test_cr_only_terminator_and_a_cr_lf_split_across_reads():
    """A&D lets a frame end in CR alone; a CR LF may arrive in two reads (the LF must not become a blank line)."""
    lc = _stream(b"ST,GS,+0001.00kg\rST,GS,+0002.00kg\r")
    assert lc.force().force_N == pytest.approx(2.0 * G_N) and lc.bytes_skipped == 0
    lc._feed(b"ST,GS,+0003.00kg\r")
    lc._feed(b"\nST,GS,+0004.00kg\r\n")
    assert [round(f.force_N / G_N, 2) for f in lc._frames_after(0)][-2:] == [3.0, 4.0] and lc.bytes_skipped == 0
