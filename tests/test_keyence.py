"""Keyence LK driver against its simulated controller on a real pty and on socket://, plus replay."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest

from drivers import errors
from drivers.keyence import (
    Keyence,
    KeyenceLK2000,
    KeyenceLKG,
    analog_to_displacement,
    open_keyence,
    parse_value_mm,
)
from drivers.transcript import Exchange, ReplaySerial, Transcript
from labrig.clock import ScaledClock
from mock_devices.keyence_sim import KeyenceSim, record_demo
from mock_devices.serial_server import serve

TRANSCRIPT = Path(__file__).parent / "data" / "transcripts" / "keyence_basic.jsonl"
RES_M = 0.1e-6  # controller resolution


class World:
    """Stand-in bench: the strip sits where ``displacement_m`` says."""

    def __init__(self, displacement_m: float = 0.0):
        self.clock = ScaledClock(1000.0)
        self.displacement_m = displacement_m

    def displacement_now(self) -> float:
        return self.displacement_m


@pytest.fixture(params=["pty", "tcp"])
def rig(request):
    bench = World()
    sim = KeyenceSim(bench)
    with serve(sim, request.param) as server, Keyence(server.address, timeout_s=0.5) as k:
        yield bench, sim, k, server


@pytest.mark.parametrize("d_m", [1.2345e-3, -0.5e-3, 0.0, 4.99999e-3, -4.9999e-3, 3.21e-8])
def test_reading_matches_bench_within_resolution(rig, d_m):
    bench, _, k, _ = rig
    bench.displacement_m = d_m
    assert k.read_displacement(1) == pytest.approx(d_m, abs=RES_M / 2 + 1e-12)
    assert k.read_displacement(2) == pytest.approx(d_m, abs=RES_M / 2 + 1e-12)


def test_both_outputs_in_one_exchange(rig):
    bench, _, k, _ = rig
    bench.displacement_m = -2.5e-3
    one, two = k.read_displacements()
    assert one == pytest.approx(-2.5e-3, abs=1e-12) and two == pytest.approx(-2.5e-3, abs=1e-12)


def test_auto_zero_on_and_off(rig):
    bench, _, k, _ = rig
    bench.displacement_m = 1.0e-3
    k.auto_zero(True, 1)
    assert k.read_displacement(1) == pytest.approx(0.0, abs=1e-12)
    bench.displacement_m = 1.5e-3
    assert k.read_displacement(1) == pytest.approx(0.5e-3, abs=1e-12)
    assert k.read_displacement(2) == pytest.approx(1.5e-3, abs=1e-12)  # OUT2 not zeroed
    k.auto_zero(False, 1)
    assert k.read_displacement(1) == pytest.approx(1.5e-3, abs=1e-12)


@pytest.mark.parametrize("d_m", [5.5e-3, -7e-3])
def test_beyond_lk031_range_is_overrange_not_a_number(rig, d_m):
    bench, _, k, _ = rig
    bench.displacement_m = d_m
    with pytest.raises(errors.OverRange):
        k.read_displacement(1)
    with pytest.raises(errors.OverRange):
        k.read_displacements()


FAULTS = [
    ("error", errors.InstrumentErrorReply),
    ("overrange", errors.OverRange),
    ("invalid", errors.InvalidReading),
    ("garbage", errors.MalformedReply),
    ("timeout", errors.InstrumentTimeout),
    ("disconnect", errors.Disconnected),
]


@pytest.mark.parametrize("fault,exc", FAULTS)
def test_each_fault_gives_its_exception(rig, fault, exc):
    bench, sim, k, _ = rig
    bench.displacement_m = 1e-3
    assert k.read_displacement(1) == pytest.approx(1e-3, abs=1e-12)
    sim.inject(fault)
    t0 = time.monotonic()
    with pytest.raises(exc) as info:
        k.read_displacement(1)
    assert time.monotonic() - t0 < 3.0  # the timeout is the driver's (0.5 s; room for a loaded machine), not a hang
    assert info.value.device == "keyence"
    if fault == "error":
        assert info.value.code == 99
    sim.clear_fault()
    if fault != "disconnect":
        assert k.read_displacement(1) == pytest.approx(1e-3, abs=1e-12)  # recovers


def test_disconnect_then_reconnect(rig):
    bench, sim, k, server = rig
    bench.displacement_m = 2e-3
    sim.inject("disconnect")
    for _ in range(2):  # stays disconnected, never hangs
        with pytest.raises(errors.Disconnected):
            k.read_displacement(1)
    sim.clear_fault()
    with Keyence(server.address, timeout_s=0.5) as k2:  # a pty comes back under a new path
        assert k2.read_displacement(1) == pytest.approx(2e-3, abs=1e-12)


def test_unknown_command_is_an_error_reply(rig):
    _, _, k, _ = rig
    with pytest.raises(errors.InstrumentErrorReply) as info:
        k.query(b"Q9")
    assert info.value.code == 0


def test_close_is_idempotent_and_closed_driver_refuses(rig):
    _, _, k, _ = rig
    k.close()
    k.close()
    with pytest.raises(errors.Disconnected):
        k.read_displacement(1)


def test_open_nonexistent_port_is_disconnected():
    with pytest.raises(errors.Disconnected):
        Keyence("/dev/pts/does-not-exist")


# -- parsing and helpers ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    "field,value",
    [("+01.2345", 1.2345), ("-00.0120", -0.012), ("+1234.56", 1234.56), ("-00001.2", -1.2), ("+0000000", 0.0)],
)
def test_value_field_formats_of_the_manual(field, value):
    assert parse_value_mm(field) == pytest.approx(value)


@pytest.mark.parametrize("field,exc", [
    ("+FFFFFFF", errors.OverRange), ("-FFFFFFF", errors.OverRange), ("XXXXXXXX", errors.InvalidReading),
    ("+1.2345", errors.MalformedReply), ("01.23456", errors.MalformedReply), ("+01.23.5", errors.MalformedReply),
    ("+0A.2345", errors.MalformedReply), ("+FFFFFF", errors.MalformedReply), ("+.......", errors.MalformedReply),
])
def test_value_field_never_turns_a_flag_into_a_number(field, exc):
    with pytest.raises(exc):
        parse_value_mm(field)


def test_analog_route_helper():
    assert analog_to_displacement(2.0, 1e-3) == pytest.approx(2e-3)
    assert analog_to_displacement(-1.0, 0.5e-3, offset_m=1e-4) == pytest.approx(-4e-4)
    out = analog_to_displacement(np.array([0.0, 1.0, -10.0]), 1e-3, 0.0)
    np.testing.assert_allclose(out, [0.0, 1e-3, -1e-2])


def test_dialect_table():
    assert KeyenceLKG.measure.request(out=1) == b"M1"
    assert KeyenceLKG.autozero_on.request(out=0) == b"V0"
    assert KeyenceLKG.measure.confirmed and not KeyenceLK2000.measure.confirmed
    with pytest.raises(ValueError):
        KeyenceLKG.measure.request(out=3)
    rp = ReplaySerial([Exchange(0, "keyence", "write", b"M1\r"), Exchange(0, "keyence", "read", b"M1,+00.0100\r")])
    k = open_keyence(rp, "LK-2000")
    assert isinstance(k, KeyenceLK2000) and k.read_displacement(1) == pytest.approx(1e-5)
    with pytest.raises(ValueError):
        open_keyence(rp, "LK-9999")


def _replay(*pairs: tuple[bytes, bytes]) -> Keyence:
    ex = []
    for w, r in pairs:
        ex += [Exchange(0, "keyence", "write", w), Exchange(0, "keyence", "read", r)]
    return Keyence(ReplaySerial(ex))


@pytest.mark.parametrize("reply", [b"M2,+01.0000\r", b"M1,+01.0000,+01.0000\r", b"M1\r", b"ER,M1\r"])
def test_wrong_shaped_replies(reply):
    with pytest.raises((errors.MalformedReply, errors.InstrumentErrorReply)):
        _replay((b"M1\r", reply)).read_displacement(1)


def test_incomplete_reply_is_a_timeout():
    with pytest.raises(errors.InstrumentTimeout):
        _replay((b"M1\r", b"M1,+01.23")).read_displacement(1)


def test_endless_reply_is_malformed():
    with pytest.raises(errors.MalformedReply):
        _replay((b"M1\r", b"M1,+01.2345" * 20 + b"\r")).read_displacement(1)


# -- recorded traffic --------------------------------------------------------------------------------


def test_recording_captures_exact_bytes(rig):
    bench, _, _, server = rig
    bench.displacement_m = 1.2345e-3
    tr = Transcript()
    with Keyence(server.address, transcript=tr, name="laser") as k:
        k.read_displacement(1)
    assert [(e.device, e.op, e.payload) for e in tr] == [("laser", "write", b"M1\r"), ("laser", "read", b"M1,+01.2345\r")]


def test_replay_of_recorded_session():
    k = Keyence(ReplaySerial(Transcript.load(TRANSCRIPT).for_device("keyence")))
    assert k.read_displacement(1) == pytest.approx(1.2345e-3, abs=1e-12)
    assert k.read_displacement(2) == pytest.approx(-0.5e-3, abs=1e-12)
    assert k.read_displacements() == pytest.approx((-0.5e-3, -0.5e-3), abs=1e-12)
    k.auto_zero(True, 1)
    assert k.read_displacement(1) == pytest.approx(0.1e-3, abs=1e-12)
    k.auto_zero(False, 1)
    for exc in (errors.InstrumentErrorReply, errors.OverRange, errors.InvalidReading, errors.MalformedReply, errors.OverRange):
        with pytest.raises(exc):
            k.read_displacement(1)
    assert k.port.exhausted


def test_replay_names_an_unrecorded_command():
    k = Keyence(ReplaySerial(Transcript.load(TRANSCRIPT).for_device("keyence")))
    with pytest.raises(errors.ReplayMismatch, match=r"M2\\r"):
        k.read_displacement(2)  # the recording starts with M1


def test_stored_recording_is_what_labrig_produces_today(tmp_path):
    out = tmp_path / "k.jsonl"
    record_demo(str(out))
    fresh = [(e.device, e.op, e.payload) for e in Transcript.load(out)]
    stored = [(e.device, e.op, e.payload) for e in Transcript.load(TRANSCRIPT)]
    assert fresh == stored, "regenerate with: python -m mock_devices.keyence_sim --record " + str(TRANSCRIPT)


# -- a published third-party client, and the manual's command set -----------------------------------


# The EPICS LK-G IOC (ISIS Computing Group's keylkg IOC and its lewis emulator): communication mode, offset
# and function of OUT1 written and read back, general mode, values, reset; error 01 in the wrong mode and
# for a mode change to the mode in use. Written anew as facts, sent the way the IOC sends them (CR, raw).
def test_epics_lkg_client_sequence_over_a_pty():
    from _exchanges import Exchanges, serial_asker

    bench = World(1.2345e-3)
    sim = KeyenceSim(bench)
    with serve(sim, "pty") as server:
        ask, port = serial_asker(server.address)
        try:
            Exchanges([
                ("Q0", "Q0"),
                ("Q0", "ER,Q0,01"),  # already in communication mode
                ("M1", "ER,M1,01"),  # no measuring in communication mode
                ("SW,OF,1,+0001000", "SW,OF"),  # offset 0.1 mm, written in 0.1 um counts
                ("SR,OF,1", "SR,OF,1,+00.1000"),  # read back in mm
                ("SW,HB,1,2", "SW,HB"),
                ("SR,HB,1", "SR,HB,1,2"),
                ("VR,1", "ER,VR,01"),  # reset is a general-mode command
                ("R0", "R0"),
                ("SR,OF,1", "ER,SR,01"),  # settings only in communication mode
                ("M1", "M1,+01.1345"),  # 1.2345 mm less the 0.1 mm offset
                ("M0", "M0,+01.1345,+01.2345"),
                ("VR,0", "VR"),
            ]).check(ask)
        finally:
            port.close()


def test_manual_commands_through_the_driver(rig):
    bench, sim, k, _ = rig
    bench.displacement_m = 2e-3
    k.lock_keys(True)
    assert sim.keys_locked
    k.set_program(3)
    assert k.program() == 3
    k.communication_mode()
    with pytest.raises(errors.InstrumentErrorReply) as info:
        k.read_displacement(1)
    assert info.value.code == 1 and "status error" in str(info.value)
    k.write_setting("OF", 2, -5000)  # -0.5 mm
    assert k.read_setting("OF", 2) == pytest.approx(-0.5)
    k.general_mode()
    assert k.read_displacement(2) == pytest.approx(2.5e-3, abs=1e-12)
    k.reset(0)


@pytest.mark.parametrize("request_,reply", [
    (b"ZZ", b"ER,ZZ,00\r"),  # unknown command
    (b"VR,1,2", b"ER,VR,21\r"),  # parameter count
    (b"PW,9", b"ER,PW,22\r"),  # program out of range
    (b"M3", b"ER,M3,22\r"),
])
def test_error_reply_has_three_fields_and_the_manuals_code(request_, reply):
    sim = KeyenceSim(World())
    assert sim.respond(request_) == reply
    assert sim.respond(b"Q0") == b"Q0\r"
    assert sim.respond(b"SW,OF,1,+9999999") == b"ER,SW,22\r"
    assert sim.respond(b"SW,OF,1") == b"ER,SW,21\r"
