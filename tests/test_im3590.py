"""Hioki IM3590 driver against its simulator over TCP VISA (pyvisa-py), and a published client's sequence."""

from __future__ import annotations

import numpy as np
import pytest

from drivers import analyser_models
from drivers.analysers import open_analyser
from drivers.errors import InstrumentErrorReply, InstrumentTimeout, MalformedReply, OverRange
from drivers.hioki_im3590 import HiokiIM3590
from labrig.clock import ScaledClock
from mock_devices.im3590_sim import Im3590Sim


class RCBench:
    """Series R + C on a 1000x clock: a 1 mHz point takes 3 s of wall time, 0.1 Hz 30 ms."""

    def __init__(self, r_ohm: float = 80.0, c_F: float = 2e-3):
        self.r_ohm, self.c_F, self.clock = r_ohm, c_F, ScaledClock(1000.0)
        self.calls: list[tuple[float, float]] = []

    def z(self, f):
        return self.r_ohm + 1 / (2j * np.pi * np.asarray(f, float) * self.c_F)

    def impedance(self, freqs_Hz, ac_V, bias_V):
        self.calls.append((ac_V, bias_V))
        return self.z(freqs_Hz)


@pytest.fixture
def bench():
    return RCBench()


@pytest.fixture
def sim(bench):
    with Im3590Sim(bench) as s:
        yield s


@pytest.fixture
def an(sim, rm):
    driver = HiokiIM3590(sim.resource_name, resource_manager=rm, timeout_s=1.0)
    yield driver
    driver.close()


def test_identify_and_setup(an, sim):
    assert an.identify().startswith("HIOKI,IM3590,")
    assert (sim.mode, sim.trigger, sim.header, sim.parameters) == ("LCR", "EXTERNAL", False, {1: "Z", 2: "PHASE", 3: "OFF", 4: "OFF"})


def test_spectrum_down_to_a_tenth_of_a_hertz_equals_the_bench(an, bench):
    f, z = an.spectrum(0.1, 1e4, 9, ac_V=0.01)
    np.testing.assert_allclose(f, np.geomspace(0.1, 1e4, 9))
    np.testing.assert_allclose(z, bench.z(f), rtol=2e-5)  # six significant digits on the wire


def test_level_and_bias_reach_the_instrument_and_safe_undoes_them(an, sim, bench):
    an.configure_list([1.0, 10.0], ac_V=0.05, bias_V=0.2)
    an.measure()
    assert bench.calls[-1] == (0.05, 0.2) and sim.bias_on
    an.safe()
    assert (sim.bias_on, sim.bias_V, sim.ac_V) == (False, 0.0, 0.005)


def test_frequency_outside_the_range_is_refused_by_driver_and_instrument(an, rm, sim):
    with pytest.raises(ValueError, match="IM3590 measures 1 mHz to 200 kHz"):
        an.configure_list([1e-4, 1.0], ac_V=0.01)
    res = rm.open_resource(sim.resource_name, read_termination="\n", write_termination="\n", timeout=1000)
    try:
        res.write(":FREQuency 300000")
        assert res.query("*ESR?").strip() == "16"  # execution error, as the manual's status model says
        assert sim.f_Hz == 1e3
    finally:
        res.close()


def test_an_instrument_error_is_raised_with_its_meaning(an, sim):
    sim.inject("error", code=-222, message="Data out of range")
    with pytest.raises(InstrumentErrorReply, match="Execution error") as info:
        an.check_errors()
    assert info.value.code == -200


@pytest.mark.timeout(10)
def test_a_millihertz_point_waits_and_a_dropped_link_shows_at_once(an, sim):
    from _exchanges import assert_dropped_link_shows_at_once

    assert_dropped_link_shows_at_once(an, sim, 0.3)


@pytest.mark.parametrize("fault, exc", [("timeout", InstrumentTimeout), ("garbage", MalformedReply), ("overrange", OverRange)])
def test_faults(an, sim, fault, exc):
    an.configure_list([10.0], ac_V=0.01)
    sim.inject(fault)
    with pytest.raises(exc):
        an.measure()
    sim.clear_fault()


def test_open_rig_picks_the_driver_by_model(sim):
    an = open_analyser(sim.resource_name, "IM3590", timeout_s=1.0)
    try:
        assert isinstance(an, HiokiIM3590) and an.model.freq_range_Hz == (1e-3, 2e5)
    finally:
        an.close()


def test_lab_instruments_im3590_client_sequence(sim, bench, rm):
    """taka998/lab-instruments' IM3590SCPI over its LAN interface: every setting goes out as the command, then
    ``*OPC`` and a ``*ESR?`` poll (its CommonSCPI.s_send / s_query). Written anew as facts. (That client tests
    bit 1 of the ESR for completion; the instrument sets bit 0, value 1, which is what is asserted here.)"""
    from _exchanges import Exchanges, visa_asker

    z = bench.z(1000.0)

    def safe(command: str, reply=None):
        return [(command, reply), ("*OPC", None), ("*ESR?", "1")]

    res = rm.open_resource(sim.resource_name, read_termination="\n", write_termination="\n", timeout=2000)
    try:
        Exchanges([
            ("*IDN?", analyser_models.get("IM3590").idn),
            *safe(":MODE LCR"), *safe(":MODE?", ":MODE LCR"),
            *safe(":PARameter1 Z"), *safe(":PARameter2 PHASE"), *safe(":PARameter3 OFF"),
            *safe(":PARameter1?", ":PARAMETER1 Z"),
            *safe(":SPEEd MEDium"), *safe(":SPEEd?", ":SPEED MEDIUM"),
            *safe(":RANGe?", ":RANGE 1"),
            *safe(":FREQuency 1000"), *safe(":FREQuency?", ":FREQUENCY 1.00000E+03"),
            *safe(":HEADer OFF"),
            *safe(":MEASure?", f"{abs(z):.5E},{np.degrees(np.angle(z)):.5E}"),
            ("*OPT?", "0"), ("*TST?", "0"), ("*STB?", "0"),
        ]).check(visa_asker(res))
    finally:
        res.close()
    assert sim.server.undefined == []


def test_a_rig_file_must_name_its_analyser_model():
    """The model sets the range every plan is checked against: a real bench's rig file without it would let a
    protocol ask an E4990A for 0.1 Hz. Refused with one line naming the field (recorded sessions replay as SIM-WIDE)."""
    from labrig.errors import BadInput
    from labrig.rig import parse_rig

    data = {"instruments": {"keyence": {"address": "socket://127.0.0.1:1"}, "loadcell": {"address": "x"},
                            "impedance": {"address": "TCPIP::127.0.0.1::1::SOCKET"}, "daq": {}}}
    with pytest.raises(BadInput, match="instruments.impedance.model"):
        parse_rig(data, "rig.toml")
    data["instruments"]["impedance"]["model"] = "E4990A"
    assert parse_rig(data, "rig.toml").instruments.impedance.model == "E4990A"
