"""Simulated Hioki IM3590 chemical impedance analyser (1 mHz..200 kHz) on a loopback TCP socket (the LAN
interface's raw command port), in LCR mode.

``*TRG`` (with ``:TRIGger EXTernal``) measures Z at the present frequency from ``bench.impedance``; the
measurement occupies ``max(cycles / f, min_point_s)`` simulated seconds and ``:MEASure?`` answers when it
is done with the values of ``:PARameter1..4`` in order (``OFF`` ones left out), bare numbers with
``:HEADer OFF``, each prefixed by its parameter name with ``:HEADer ON``. With ``:TRIGger INTernal``
``:MEASure?`` measures at once. A refused command sets the event status register (``*ESR?``): -1xx the
command-error bit, -2xx (e.g. a frequency outside 1 mHz..200 kHz) the execution-error bit.

Implemented: ``:MODE``, ``:FREQuency``, ``:LEVel``, ``:LEVel:VOLTage``, ``:DCBias``, ``:DCBias:LEVel``,
``:PARameter1..4``, ``:HEADer``, ``:SPEEd``, ``:AVERaging``, ``:RANGe``, ``:RANGe:AUTO``, ``:TRIGger``,
``:TRIGger:DELay``, ``:MEASure?`` and the IEEE 488.2 common commands. What is not is listed in
docs/instruments_impedance.md. Faults: see ``mock_devices.analyser_sim``.
"""

from __future__ import annotations

import argparse
from typing import Callable

import numpy as np

from drivers import analyser_models
from mock_devices.analyser_sim import ScpiAnalyserSim, one_arg, word
from mock_devices.world_api import WorldView
from mock_devices.scpi_server import Request, ScpiError, parse_bool, parse_number

MODES = {"LCR": "LCR", "ANAL": "ANALYZER", "ANALYZER": "ANALYZER", "CONT": "CONTINUOUS", "CONTINUOUS": "CONTINUOUS"}
LEVEL_MODES = {"V": "V", "CV": "CV", "CC": "CC"}
SPEEDS = {"FAST": "FAST", "MED": "MEDIUM", "MEDIUM": "MEDIUM", "SLOW": "SLOW", "SLOW2": "SLOW2"}
TRIGGERS = {"INT": "INTERNAL", "INTERNAL": "INTERNAL", "EXT": "EXTERNAL", "EXTERNAL": "EXTERNAL"}
TWO_PI = 2 * np.pi
# what each :PARameter computes from Z at f (PHASE in degrees, as the instrument shows it)
QUANTITIES: dict[str, Callable[[complex, float], float]] = {
    "Z": lambda z, f: abs(z), "Y": lambda z, f: abs(1 / z), "PHASE": lambda z, f: float(np.degrees(np.angle(z))),
    "RS": lambda z, f: z.real, "X": lambda z, f: z.imag, "G": lambda z, f: (1 / z).real, "B": lambda z, f: (1 / z).imag,
    "RP": lambda z, f: 1 / (1 / z).real, "CS": lambda z, f: -1 / (TWO_PI * f * z.imag),
    "CP": lambda z, f: (1 / z).imag / (TWO_PI * f), "LS": lambda z, f: z.imag / (TWO_PI * f),
    "LP": lambda z, f: -1 / (TWO_PI * f * (1 / z).imag), "D": lambda z, f: z.real / abs(z.imag),
    "Q": lambda z, f: abs(z.imag) / z.real,
}
PARAMETERS = {**{k: k for k in QUANTITIES}, "OFF": "OFF"}


def hioki_number(x: float) -> str:
    """Six significant digits in exponent form, as the IM3590 answers with :HEADer OFF."""
    return f"{x:.5E}"


class Im3590Sim(ScpiAnalyserSim):
    """The IM3590 on 127.0.0.1; ``resource_name`` is the pyvisa-py SOCKET resource the driver opens."""

    def __init__(self, bench: WorldView, *, port: int = 0, cycles: float = 3.0, min_point_s: float = 0.05):
        m = analyser_models.get("IM3590")
        self.freq_range_Hz, self.ac_range_V, self.bias_range_V = m.freq_range_Hz, m.ac_range_V, m.bias_range_V
        self.measurements: list[dict[str, float]] = []  # what each measurement applied, for tests
        super().__init__(bench, port=port, name="im3590-sim", idn=m.idn, cycles=cycles, min_point_s=min_point_s)

    def reset(self) -> None:
        """``*RST`` state (initial settings of the manual, as far as labrig uses them)."""
        self.mode, self.f_Hz, self.level_mode, self.ac_V = "LCR", 1e3, "V", 1.0
        self.bias_on, self.bias_V, self.header = False, 0.0, True
        self.speed, self.averaging, self.range_no, self.auto_range = "MEDIUM", 1, 1, True
        self.trigger, self.trigger_delay_s = "INTERNAL", 0.0
        self.parameters = {1: "Z", 2: "OFF", 3: "PHASE", 4: "OFF"}
        self.busy_until = float("-inf")
        self.data: tuple[float, complex] | None = None

    def setting(self, header, parse, attr, show, guard=None) -> None:  # type: ignore[override]
        """As the base, but a query answer carries its header (``:FREQUENCY 1.00000E+03``) while ``:HEADer ON``."""
        name = ":" + header.replace("#", "").upper()
        super().setting(header, parse, attr, lambda v: f"{name} {show(v)}" if self.header else show(v), guard)

    def measured_reply(self, request: Request) -> int:
        return len([p for p in self.parameters.values() if p != "OFF"]) if "MEAS" in request.header.upper() else 0

    def _register(self) -> None:
        add, setting = self.server.add, self.setting
        f_lo, f_hi = self.freq_range_Hz
        on_off = lambda v: "ON" if v else "OFF"  # noqa: E731 - the IM3590 answers ON/OFF
        setting("MODE", lambda a: word(a, MODES), "mode", str)
        setting("FREQuency", lambda a: parse_number(a, f_lo, f_hi), "f_Hz", hioki_number)
        setting("LEVel", lambda a: word(a, LEVEL_MODES), "level_mode", str)
        setting("LEVel:VOLTage", lambda a: parse_number(a, *self.ac_range_V), "ac_V", hioki_number)
        setting("DCBias", parse_bool, "bias_on", on_off)
        setting("DCBias:LEVel", lambda a: parse_number(a, *self.bias_range_V), "bias_V", hioki_number)
        setting("HEADer", parse_bool, "header", on_off)
        setting("SPEEd", lambda a: word(a, SPEEDS), "speed", str)
        setting("AVERaging", lambda a: 1 if a.strip().upper() == "OFF" else int(parse_number(a, 1, 256)),
                "averaging", lambda v: "OFF" if v == 1 else str(v))
        setting("RANGe", lambda a: int(parse_number(a, 1, 12)), "range_no", str)
        setting("RANGe:AUTO", parse_bool, "auto_range", on_off)
        setting("TRIGger", lambda a: word(a, TRIGGERS), "trigger", str)
        setting("TRIGger:DELay", lambda a: parse_number(a, 0.0, 9.0), "trigger_delay_s", hioki_number)
        add("PARameter#", self._set_parameter)
        add("PARameter#?", lambda r: (f":PARAMETER{self._slot(r)} " if self.header else "") + self.parameters[self._slot(r)])
        add("*TRG", self._trg)
        add("*OPC?", lambda r: (self.wait_idle(), "1")[1])
        add("*WAI", lambda r: self.wait_idle())
        add("MEASure?", self._measure)

    @staticmethod
    def _slot(r: Request) -> int:
        if not 1 <= r.suffixes[0] <= 4:
            raise ScpiError(-114, "Header suffix out of range")
        return r.suffixes[0]

    def _set_parameter(self, r: Request) -> None:
        self.parameters[self._slot(r)] = word(one_arg(r), PARAMETERS)

    def _start_measurement(self) -> None:
        if self.mode != "LCR":
            raise ScpiError(-221, "Settings conflict")  # labrig simulates LCR mode only
        f = self.f_Hz
        bias = self.bias_V if self.bias_on else 0.0
        t0 = self.bench.clock.now()  # the measurement starts now; computing Z is part of its duration
        z = complex(np.asarray(self.bench.impedance(np.array([f]), self.ac_V, bias), dtype=complex).ravel()[0])
        self.data = (f, z)
        self.busy_until = t0 + self.trigger_delay_s + self.averaging * self.measuring_time_s([f])
        self.measurements.append({"f_Hz": f, "ac_V": self.ac_V, "bias_V": bias})

    def _trg(self, r: Request) -> None:
        if self.trigger != "EXTERNAL":
            raise ScpiError(-211, "Trigger ignored")
        self._start_measurement()

    def _measure(self, r: Request) -> str:
        if self.trigger == "INTERNAL":
            self._start_measurement()  # free-running: the next complete measurement
        self.wait_idle()
        if self.data is None:
            raise ScpiError(-230, "Data corrupt or stale")
        f, z = self.data
        out = []
        for p in (self.parameters[i] for i in (1, 2, 3, 4)):
            if p != "OFF":
                value = hioki_number(QUANTITIES[p](z, f))
                out.append(f"{p} {value}" if self.header else value)
        return ",".join(out)


def main(argv: list[str] | None = None) -> int:
    from mock_devices.impedance_sim import DemoBench

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.parse_args(argv)
    Im3590Sim(DemoBench()).serve_forever()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
