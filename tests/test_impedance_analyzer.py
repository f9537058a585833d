"""Impedance analyser: the driver against the simulator over real TCP through pyvisa-py, faults, replay."""

from __future__ import annotations

import dataclasses
import logging
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest
import pyvisa

from drivers.errors import (Disconnected, InstrumentErrorReply, InstrumentTimeout, MalformedReply, OverRange,
                            ReplayMismatch)
from drivers.impedance_analyzer import ImpedanceAnalyzer
from drivers.scpi import parse_error, parse_floats
from drivers.transcript import RecordingMessages, ReplayMessages, Transcript
from labrig.clock import ScaledClock
from mock_devices.impedance_sim import SCRIPTS, DemoBench, ImpedanceAnalyzerSim, record, script_error, script_session
from mock_devices.scpi_server import ScpiServer

TRANSCRIPTS = Path(__file__).parent / "data" / "transcripts"


class RCBench:
    """Stand-in bench: series R + C, remembers what the analyser applied."""

    def __init__(self, r_ohm: float = 120.0, c_F: float = 1e-3):
        self.r_ohm, self.c_F = r_ohm, c_F
        self.clock = ScaledClock(1000.0)
        self.calls: list[tuple[np.ndarray, float, float]] = []

    def z(self, f: np.ndarray) -> np.ndarray:
        return self.r_ohm + 1.0 / (2j * np.pi * np.asarray(f) * self.c_F)

    def impedance(self, freqs_Hz: np.ndarray, ac_V: float, bias_V: float) -> np.ndarray:
        self.calls.append((np.array(freqs_Hz), ac_V, bias_V))
        return self.z(freqs_Hz)


@pytest.fixture
def bench() -> RCBench:
    return RCBench()


@pytest.fixture
def sim(bench: RCBench):
    with ImpedanceAnalyzerSim(bench) as s:
        yield s


@pytest.fixture
def an(sim: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager):
    # 2 s for a reply: short enough for the timeout fault, long enough for a busy CI machine (0.5 s once ran out there)
    driver = ImpedanceAnalyzer(sim.resource_name, resource_manager=rm, timeout_s=2.0)
    yield driver
    driver.close()


# ---- the driver against the simulator ---------------------------------------------------------


def test_identify(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    assert an.identify() == sim.idn
    assert sim.resource_name == f"TCPIP::127.0.0.1::{sim.port}::SOCKET"


def test_log_sweep_equals_bench(an: ImpedanceAnalyzer, bench: RCBench) -> None:
    f, z = an.spectrum(0.1, 1e4, 11, 0.01)
    np.testing.assert_allclose(f, np.geomspace(0.1, 1e4, 11), rtol=1e-11)
    np.testing.assert_allclose(z, bench.z(f), rtol=1e-11)
    assert z.dtype == complex and z.imag.max() < 0  # capacitive


def test_list_sweep_bias_and_ac_reach_simulator(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim,
                                                bench: RCBench) -> None:
    freqs = [0.5, 2.0, 31.41592653589, 400.0, 5123.456789]  # digits a sloppy format would lose
    an.configure_list(freqs, ac_V=0.05, bias_V=0.2)
    assert (sim.ac_V, sim.bias_V, sim.bias_on, sim.sweep_type) == (0.05, 0.2, True, "SEGM")
    assert (an.ac_V, an.bias_V, an.bias_on, an.points) == (0.05, 0.2, True, 5)
    f, z = an.measure()
    np.testing.assert_allclose(f, freqs, rtol=1e-12)
    np.testing.assert_allclose(z, bench.z(freqs), rtol=1e-11)
    f_applied, ac, bias = bench.calls[-1]
    assert (ac, bias) == (0.05, 0.2)
    np.testing.assert_allclose(f_applied, freqs)


def test_zero_bias_switches_bias_off(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim, bench: RCBench) -> None:
    an.configure_list([1.0, 10.0], ac_V=0.05, bias_V=0.3)
    an.configure_log_sweep(1.0, 100.0, 3, ac_V=0.02)
    an.measure()
    assert not sim.bias_on and bench.calls[-1][1:] == (0.02, 0.0)


def test_measure_waits_for_the_sweep(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    an.configure_list([0.01, 0.02], ac_V=0.01)  # 300 s + 150 s simulated = 0.45 s at 1000x
    t0 = time.monotonic()
    an.measure()
    assert time.monotonic() - t0 >= sim.sweep_time_s(np.array([0.01, 0.02])) / 1000.0 * 0.9


def test_sweep_timeout_parameter(sim: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager) -> None:
    with ImpedanceAnalyzer(sim.resource_name, resource_manager=rm, timeout_s=0.5, sweep_timeout_s=0.1) as an:
        an.configure_list([0.01], ac_V=0.01)  # 0.3 s of wall time
        with pytest.raises(InstrumentTimeout, match="OPC"):
            an.measure()


def test_instrument_rejects_out_of_range(an: ImpedanceAnalyzer) -> None:
    with pytest.raises(InstrumentErrorReply) as e:
        an.configure_log_sweep(1.0, 1e4, 5, ac_V=5.0)
    assert e.value.code == -222 and "Data out of range" in str(e.value)
    assert an.errors() == []  # drained


def test_undefined_header_is_reported(an: ImpedanceAnalyzer) -> None:
    an._send(":SENS1:FROB 3")
    assert an.errors() == [(-113, "Undefined header")]


def test_trigger_needs_arming(sim: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager) -> None:
    """The simulator is strict like the instrument: a bus trigger on a held channel is ignored."""
    res = rm.open_resource(sim.resource_name, read_termination="\n", write_termination="\n", timeout=500)
    res.write(":TRIG:SOUR BUS")
    res.write(":INIT1:CONT OFF")
    res.write(":TRIG:SING")
    assert res.query("SYST:ERR?") == '-211,"Trigger ignored"'
    res.close()


# ---- faults -----------------------------------------------------------------------------------


def test_fault_timeout(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    sim.inject("timeout")
    with pytest.raises(InstrumentTimeout, match="IDN"):
        an.identify()


def test_fault_disconnect(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager) -> None:
    an.configure_log_sweep(1.0, 100.0, 3, ac_V=0.01)
    sim.inject("disconnect")
    with pytest.raises(Disconnected):
        an.measure()
    with pytest.raises(Disconnected):
        ImpedanceAnalyzer(sim.resource_name, resource_manager=rm, timeout_s=0.5)
    sim.clear_fault()  # the instrument is back on the same port
    with ImpedanceAnalyzer(sim.resource_name, resource_manager=rm, timeout_s=2.0) as again:
        assert again.identify() == sim.idn


@pytest.mark.timeout(10)
def test_disconnect_during_a_long_sweep(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    """The *OPC? wait is minutes long here; a dropped link must show as Disconnected within a second."""
    from _exchanges import assert_dropped_link_shows_at_once

    assert_dropped_link_shows_at_once(an, sim, 0.2)


def test_close_survives_a_dead_instrument(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    sim.inject("disconnect")
    an.close()  # must not raise: there is nothing left to make safe
    with pytest.raises(Disconnected):
        an.identify()


def test_fault_garbage(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    an.configure_log_sweep(1.0, 100.0, 3, ac_V=0.01)
    sim.inject("garbage")
    for call in (an.identify, an.measure, an.errors):
        with pytest.raises(MalformedReply):
            call()
    with pytest.raises(MalformedReply):
        _ = an.ac_V


def test_fault_error(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    sim.inject("error", code=-310, message="System error")
    with pytest.raises(InstrumentErrorReply) as e:
        an.configure_log_sweep(1.0, 100.0, 3, ac_V=0.01)
    assert e.value.code == -310 and "System error" in e.value.detail
    an.configure_list([0.01], ac_V=0.01)  # 0.3 s of wall time
    timer = threading.Timer(0.1, sim.inject, args=("error",))  # queued during the sweep
    timer.start()
    with pytest.raises(InstrumentErrorReply) as e:
        an.measure()  # reports it instead of returning the data
    timer.join()
    assert e.value.code == -200


def test_fault_overrange_is_never_numbers(an: ImpedanceAnalyzer, sim: ImpedanceAnalyzerSim) -> None:
    an.configure_log_sweep(1.0, 1e3, 4, ac_V=0.01)
    sim.inject("overrange", points=[3])  # only the last point: a driver checking the first misses it
    with pytest.raises(OverRange):
        an.measure()
    sim.clear_fault()
    f, z = an.measure()
    assert np.all(np.isfinite(z)) and f.size == 4


def test_inject_rejects_unknown_fault(sim: ImpedanceAnalyzerSim) -> None:
    with pytest.raises(ValueError):
        sim.inject("smoke")


# ---- safe state -------------------------------------------------------------------------------


def test_close_leaves_source_safe(sim: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager) -> None:
    with ImpedanceAnalyzer(sim.resource_name, resource_manager=rm, timeout_s=2.0) as an:
        an.configure_list([1.0, 10.0], ac_V=0.5, bias_V=1.5)
        assert sim.bias_on and sim.ac_V == 0.5
    assert (sim.bias_on, sim.bias_V, sim.ac_V) == (False, 0.0, sim.ac_range_V[0])
    an.close()  # idempotent
    with pytest.raises(Disconnected):
        an.identify()


# ---- recorded traffic -------------------------------------------------------------------------


def _replay(name: str) -> ReplayMessages:
    transcript = Transcript.load(TRANSCRIPTS / f"{name}.jsonl")
    return ReplayMessages(transcript.for_device("impedance"))


def test_replay_session_byte_exact() -> None:
    replay = _replay("impedance_session")
    out = script_session(ImpedanceAnalyzer(replay))
    demo = DemoBench()
    assert out["idn"].startswith("labrig,SIM-IMPEDANCE")
    for key, freqs in (("log", np.geomspace(1.0, 1e4, 5)), ("list", np.array([0.1, 1.0, 10.0]))):
        f, z = out[key]
        np.testing.assert_allclose(f, freqs, rtol=1e-12)
        np.testing.assert_allclose(z, demo.impedance(freqs, 0.0, 0.0), rtol=1e-11)
    assert replay.exhausted


def test_replay_instrument_error() -> None:
    replay = _replay("impedance_error")
    with pytest.raises(InstrumentErrorReply) as e:
        script_error(ImpedanceAnalyzer(replay))
    assert e.value.code == -222 and replay.exhausted


def test_replay_unrecorded_command_names_it() -> None:
    an = ImpedanceAnalyzer(_replay("impedance_session"))
    an.identify()
    with pytest.raises(ReplayMismatch, match=r"':SENS1:FREQ:STAR 2'"):
        an.configure_log_sweep(2.0, 1e4, 5, 0.01)


def _session_with_reply(query: str, edit) -> ReplayMessages:
    """The recorded session with the first reply to ``query`` rewritten by ``edit``."""
    ex = Transcript.load(TRANSCRIPTS / "impedance_session.jsonl").for_device("impedance")
    i = next(k for k, e in enumerate(ex) if e.op == "write" and e.payload == query.encode()) + 1
    ex[i] = dataclasses.replace(ex[i], payload=edit(ex[i].payload.decode()).encode())
    return ReplayMessages(ex)


@pytest.mark.parametrize("query, edit", [
    (":CALC1:DATA:RDAT?", lambda r: r.rsplit(",", 1)[0]),  # odd count: a value lost
    (":CALC1:DATA:RDAT?", lambda r: r.rsplit(",", 2)[0]),  # one point short
    (":SENS1:FREQ:DATA?", lambda r: r.rsplit(",", 1)[0]),  # fewer frequencies than configured points
    (":CALC1:DATA:RDAT?", lambda r: r.replace("+5.0", "+5.O", 1)),  # a letter O for a zero
    ("*OPC?", lambda r: "0"),
])
def test_malformed_replies(query: str, edit) -> None:
    an = ImpedanceAnalyzer(_session_with_reply(query, edit))
    an.identify()
    with pytest.raises(MalformedReply):
        an.spectrum(1.0, 1e4, 5, 0.01)


def test_recordings_are_what_labrig_produces_now(tmp_path: Path) -> None:
    """``python -m mock_devices.impedance_sim --record tests/data/transcripts`` regenerates them."""
    record(tmp_path)
    for name in SCRIPTS:
        fresh = [(e.op, e.payload) for e in Transcript.load(tmp_path / f"{name}.jsonl")]
        stored = [(e.op, e.payload) for e in Transcript.load(TRANSCRIPTS / f"{name}.jsonl")]
        assert fresh == stored, name


# ---- building blocks --------------------------------------------------------------------------


def test_scpi_server_headers_and_error_queue() -> None:
    server = ScpiServer(queue_size=3)
    server.add("SOURce#:VOLTage?", lambda r: str(r.suffixes))
    server.add("CALCulate#[:SELected]:DATA:RDATa?", lambda r: "ok")
    assert server.handle(":SOURCE2:VOLTAGE?") == "(2,)"
    assert server.handle("sour:volt?") == "(1,)"
    assert server.handle(":CALC1:SEL:DATA:RDAT?;:CALC:DATA:RDATA?") == "ok;ok"
    assert server.handle(":SOUR:VOLTS?") is None
    for _ in range(5):
        server.handle("NOPE")
    replies = [server.handle("SYST:ERR?") for _ in range(4)]
    assert replies == ['-113,"Undefined header"'] * 2 + ['-350,"Queue overflow"', '+0,"No error"']


def test_scpi_server_loopback_lifecycle() -> None:
    with pytest.raises(ValueError):
        ScpiServer(host="0.0.0.0")
    server = ScpiServer().start()
    assert server.start() is server and server.port > 0
    with socket.create_connection(("127.0.0.1", server.port), timeout=1) as s:
        s.sendall(b"*CLS\nSYST:ERR?\n")
        assert s.recv(100) == b'+0,"No error"\n'
        server.stop()
        server.stop()  # idempotent
    assert not server.listening and server._threads == []
    with pytest.raises(OSError):
        socket.create_connection(("127.0.0.1", server.port), timeout=1)


def test_reply_parsers() -> None:
    with pytest.raises(MalformedReply):
        parse_floats("x", "Q?", "1.0,abc")
    with pytest.raises(OverRange):
        parse_floats("x", "Q?", "1.0,-9.9E37")
    assert parse_error("x", '-113,"Undefined header"') == (-113, "Undefined header")
    with pytest.raises(MalformedReply):
        parse_error("x", "-113")


def test_driver_never_imports_mock_devices() -> None:
    code = "import sys, drivers.impedance_analyzer; print(any(m.startswith('mock_devices') for m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_recording_wrapper_forwards_timeout(sim: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager) -> None:
    """Setting the timeout through the recorder must reach the real resource (transcript.py fix)."""
    res = rm.open_resource(sim.resource_name, read_termination="\n", write_termination="\n")
    rec = RecordingMessages(res, Transcript(), "impedance")
    rec.timeout = 1234
    assert res.timeout == 1234
    res.close()


# ---- the E4990A as published clients drive it (model "E4990A": its real 20 Hz floor) -----------------


@pytest.fixture
def e4990a(bench: RCBench):
    with ImpedanceAnalyzerSim(bench, model="E4990A") as s:
        yield s


def test_magdynlab_e4990a_client_sequence(e4990a: ImpedanceAnalyzerSim, bench: RCBench, rm: pyvisa.ResourceManager) -> None:
    """The command sequence of magdynlab's KEYSIGHT_E4990A class (D. González Chávez, CBPF) over TCP VISA
    through pyvisa-py: binary REAL data, source and bias modes, a bus-triggered sweep polled on
    STAT:OPER:COND? bit 4, raw data of trace 1. Written anew as facts."""
    from _exchanges import Exchanges, visa_asker

    res = rm.open_resource(e4990a.resource_name, read_termination="\n", write_termination="\n", timeout=3000)
    f = np.linspace(20.0, 1e4, 5)  # the *RST sweep type is linear
    try:
        Exchanges([
            ("*CLS", None), ("FORMat:DATA REAL", None), ("FORMat:BORDer NORM", None), ("INIT1:CONT ON", None),
            ("SENS1:FREQ:STAR 2.00000000000E+01", None), ("SENS1:FREQ:STOP 1.00000000000E+04", None),
            ("SENS1:SWE:POIN 5", None), ("SENS1:FREQ:DATA?", f),
            ("SOUR1:MODE VOLT", None), ("SOUR1:MODE?", "VOLT"), ("SOUR1:VOLT 1.000E-02", None),
            ("SOUR1:BIAS:MODE VOLT", None), ("SOUR1:BIAS:VOLT 0.000E+00", None), ("CALC1:PAR:COUN?", "2"),
            ("TRIG:SOUR BUS", None), ("SENS1:AVER:STAT?", "0"), ("STAT:OPER:COND?", "0"), ("TRIG:IMM", None),
            ("SYST:ERR?", '+0,"No error"'), ("*OPC?", "1"), ("STAT:OPER:COND?", "0"), ("CALC1:PAR1:SEL", None),
            ("CALC1:DATA:RDAT?", np.column_stack([bench.z(f).real, bench.z(f).imag]).ravel()),
        ]).check(visa_asker(res))
    finally:
        res.close()
    assert e4990a.server.undefined == []


def test_e4990a_scpi_rules_and_common_commands(e4990a: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager, caplog) -> None:
    """What the issue found refused: optional nodes of long forms, BIAS:MODE, *TRG, PAR DEF, compound headers that
    keep their path, *OPT?; and a query it does not implement leaves -113 and is named in the log."""
    from _exchanges import Exchanges, visa_asker

    # another library's logging set-up (dask's dictConfig) may have disabled loggers that existed when it ran
    logging.getLogger("mock_devices.scpi_server").disabled = False
    caplog.set_level(logging.WARNING, logger="mock_devices.scpi_server")
    res = rm.open_resource(e4990a.resource_name, read_termination="\n", write_termination="\n", timeout=2000)
    try:
        Exchanges([
            ("*OPT?", "120"), ("*ESE 60", None), ("*ESE?", "60"), ("*SRE 32", None), ("*SRE?", "32"),
            (":SOURce1:VOLTage:LEVel:IMMediate:AMPLitude 0.02", None), (":SOUR1:VOLT?", "+2.000000000000E-02"),
            (":SOUR1:BIAS:MODE CURR", None), (":SOUR1:BIAS:MODE?", "CURR"),
            (":CALC1:PAR2:DEF R", None), (":CALC1:PAR2:DEF?", "R"),
            (":SENS1:FREQ:STAR 100;STOP 10000", None), (":SENS1:FREQ:STAR?;STOP?", "+1.000000000000E+02;+1.000000000000E+04"),
            (":SENS1:AVER ON;AVER:COUN 4;:SENS1:APER 3;BAND 2", None),
            (":SENS1:AVER?;AVER:COUN?;:SENS1:APER?;BAND?", "1;4;3;2"),
            (":TRIG:SOUR BUS;:INIT1", None), ("*TRG", None), ("*WAI", None), ("*ESR?", "0"),
            (":SENS1:FREQ:STAR 1", None),  # below the 20 Hz floor: -222, execution error
            ("*ESR?", "16"), ("SYST:ERR?", '-222,"Data out of range"'),
            (":SENS1:CORR:COLL:METH?", None),  # not simulated: no reply, -113 queued
        ]).check(lambda req, exp: None if req.endswith("METH?") and res.write(req) else visa_asker(res)(req, exp))
        assert res.query("SYST:ERR?").strip() == '-113,"Undefined header"'
        assert res.query("*STB?").strip() == "96"  # ESB (32): the command error is enabled by *ESE 60; MSS (64): *SRE 32
    finally:
        res.close()
    assert e4990a.server.undefined == [":SENS1:CORR:COLL:METH?"]
    assert ":SENS1:CORR:COLL:METH?" in caplog.text


def test_e4990a_keeps_its_20_hz_floor(e4990a: ImpedanceAnalyzerSim, rm: pyvisa.ResourceManager) -> None:
    an = ImpedanceAnalyzer(e4990a.resource_name, resource_manager=rm, timeout_s=2.0, model="E4990A")
    try:
        with pytest.raises(InstrumentErrorReply, match="-222"):
            an.configure_list([0.1, 1.0, 100.0], ac_V=0.01)
        assert an.identify().split(",")[1] == "E4990A"
    finally:
        an.close()
