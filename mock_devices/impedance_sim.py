"""Simulated impedance analyser speaking the Keysight E4990A SCPI subset that labrig's driver and published
E4990A clients use (models ``E4990A`` and ``SIM-WIDE`` of ``drivers.analyser_models``).

The instrument keeps its sweep settings; ``:TRIG:SING`` (or ``*TRG`` with the bus trigger) takes Z from
``bench.impedance(f, ac, bias)`` and occupies ``sum(max(cycles / f, min_point_s))`` simulated seconds on
``bench.clock``; ``*OPC?`` and ``*WAI`` wait until the sweep is done. ``model="E4990A"`` keeps the real
instrument's 20 Hz floor (data sheet: 20 Hz to 10/20/30/50/120 MHz); ``SIM-WIDE`` (the default, the
analyser the recorded sessions were made on) reaches 10 uHz.

Implemented headers (short or long forms, optional nodes, numeric suffixes): ``SENSe1:FREQuency:STARt|STOP``,
``SENSe1:SWEep:TYPE|POINts``, ``SENSe1:SEGMent:DATA``, ``SENSe1:FREQuency:DATA?``, ``SENSe1:AVERage[:STATe]|
:COUNt|:CLEar``, ``SENSe1:APERture[:TIME]``, ``SENSe1:BANDwidth[:RESolution]``, ``SOURce1:MODE``,
``SOURce1:VOLTage[:LEVel][:IMMediate][:AMPLitude]``, ``SOURce1:BIAS:MODE|STATe|VOLTage[:LEVel]...``,
``TRIGger[:SEQuence]:SOURce|SINGle``, ``INITiate1[:IMMediate]|CONTinuous``, ``CALCulate1:PARameter#:DEFine|
COUNt``, ``CALCulate1[:SELected]:DATA:RDATa?|FDATa?``, ``FORMat[:DATA]``, ``SYSTem:PRESet``,
``DISPlay:ENABle`` and the common commands (``*OPT?`` answers the frequency option, e.g. ``120``).

Faults on demand (``inject``): see ``mock_devices.analyser_sim``.

Recordings for the replay tests::

    python -m mock_devices.impedance_sim --record tests/data/transcripts
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any, Callable

import numpy as np

from drivers import analyser_models
from mock_devices.analyser_sim import FAULTS, GARBAGE, OVERLOAD, ScpiAnalyserSim, num, one_arg, word
from mock_devices.world_api import WorldView
from mock_devices.im3590_sim import Im3590Sim
from mock_devices.scpi_server import Request, ScpiError, parse_bool, parse_number
from mock_devices.stand_ins import Served, SimOptions, stands_in

__all__ = ["FAULTS", "GARBAGE", "OVERLOAD", "ImpedanceAnalyzerSim", "DemoBench", "VirtualClock"]

SWEEP_TYPES = {"LIN": "LIN", "LINEAR": "LIN", "LOG": "LOG", "LOGARITHMIC": "LOG", "SEGM": "SEGM", "SEGMENT": "SEGM"}
TRIGGER_SOURCES = {"INT": "INT", "INTERNAL": "INT", "EXT": "EXT", "EXTERNAL": "EXT", "BUS": "BUS",
                   "MAN": "MAN", "MANUAL": "MAN"}
DATA_FORMATS = {"ASC": "ASC", "ASCII": "ASC", "REAL": "REAL", "REAL32": "REAL32"}
BYTE_ORDERS = {"NORM": "NORM", "NORMAL": "NORM", "SWAP": "SWAP", "SWAPPED": "SWAP"}
SOURCE_MODES = {"VOLT": "VOLT", "VOLTAGE": "VOLT", "CURR": "CURR", "CURRENT": "CURR"}
# E4990A measurement parameters (CALC:PAR:DEF); the simulator formats the ones it can compute from Z
PARAMETERS = {w: w for w in ("Z", "Y", "R", "X", "G", "B", "LS", "LP", "CS", "CP", "RS", "RP", "Q", "D",
                             "TZ", "TY", "VAC", "IAC", "VDC", "IDC", "IMP", "ADM")}
_FORMATTED: dict[str, Callable[[np.ndarray, np.ndarray], np.ndarray]] = {
    "Z": lambda z, f: np.abs(z), "TZ": lambda z, f: np.degrees(np.angle(z)), "R": lambda z, f: z.real,
    "RS": lambda z, f: z.real, "X": lambda z, f: z.imag, "Y": lambda z, f: np.abs(1 / z),
    "TY": lambda z, f: np.degrees(np.angle(1 / z)), "G": lambda z, f: (1 / z).real, "B": lambda z, f: (1 / z).imag,
    "CS": lambda z, f: -1 / (2 * np.pi * f * z.imag), "D": lambda z, f: z.real / np.abs(z.imag),
    "Q": lambda z, f: np.abs(z.imag) / z.real,
}

class ImpedanceAnalyzerSim(ScpiAnalyserSim):
    """The E4990A (or SIM-WIDE) analyser on a loopback TCP port; ``resource_name`` is what the driver opens."""

    def __init__(self, bench: WorldView, *, port: int = 0, model: str = "SIM-WIDE", idn: str | None = None,
                 freq_range_Hz: tuple[float, float] | None = None, ac_range_V: tuple[float, float] | None = None,
                 bias_range_V: tuple[float, float] | None = None, max_points: int = 1601,
                 max_segments: int = 201, cycles: float = 3.0, min_point_s: float = 0.05):
        m = analyser_models.get(model)
        self.model = m.name
        self.freq_range_Hz = freq_range_Hz or m.freq_range_Hz
        self.ac_range_V = ac_range_V or m.ac_range_V
        self.bias_range_V = bias_range_V or m.bias_range_V
        self.max_points, self.max_segments = max_points, max_segments
        self.sweeps: list[dict[str, Any]] = []  # what each triggered sweep applied, for tests
        option = f"{self.freq_range_Hz[1] / 1e6:g}" if m.name == "E4990A" else "0"
        super().__init__(bench, port=port, idn=idn or m.idn, options=option, cycles=cycles, min_point_s=min_point_s)

    # ---- state ------------------------------------------------------------------------------

    def reset(self) -> None:
        """``*RST`` state (the E4990A's, within this simulator's ranges)."""
        f_lo = max(self.freq_range_Hz[0], 1.0)  # 1 Hz on SIM-WIDE as before, 20 Hz on the E4990A
        self.sweep_type, self.f_start_Hz, self.f_stop_Hz, self.n_points = "LIN", f_lo, 1e5, 201
        self.segments: list[tuple[float, float, int]] = [(f_lo, 1e5, 201)]
        self.ac_V, self.bias_V, self.bias_on = 0.5, 0.0, False
        self.source_mode, self.bias_mode = "VOLT", "VOLT"
        self.trigger_source, self.continuous, self.armed = "INT", True, False
        self.averaging, self.avg_count, self.aperture, self.bandwidth = False, 16, 1, 1
        self.parameters = {1: "Z", 2: "TZ", 3: "R", 4: "X"}
        self.data_format, self.byte_order = "ASC", "NORM"
        self.trace_count = 2
        self.busy_until = float("-inf")
        self.data: tuple[np.ndarray, np.ndarray] | None = None

    def frequencies(self) -> np.ndarray:
        """Stimulus array of the present settings."""
        if self.sweep_type == "LIN":
            return np.linspace(self.f_start_Hz, self.f_stop_Hz, self.n_points)
        if self.sweep_type == "LOG":
            return np.geomspace(self.f_start_Hz, self.f_stop_Hz, self.n_points)
        return np.concatenate([np.linspace(a, b, n) for a, b, n in self.segments])

    def sweep_time_s(self, freqs_Hz: np.ndarray) -> float:
        return self.measuring_time_s(freqs_Hz)

    def measured_reply(self, request: Request) -> int:
        return 2 if "RDAT" in request.header.upper() or "FDAT" in request.header.upper() else 0

    # ---- commands ---------------------------------------------------------------------------

    def _register(self) -> None:
        add = self.server.add
        add("*OPC?", lambda r: (self.wait_idle(), "1")[1])
        add("*WAI", lambda r: self.wait_idle())
        add("*TRG", self._bus_trigger)
        add("SYSTem:PRESet", lambda r: self.reset())
        f_lo, f_hi = self.freq_range_Hz
        ch = self._channel
        self.setting("SENSe#:SWEep:TYPE", lambda a: word(a, SWEEP_TYPES), "sweep_type", str, ch)
        self.setting("SENSe#:FREQuency:STARt", lambda a: parse_number(a, f_lo, f_hi), "f_start_Hz", num, ch)
        self.setting("SENSe#:FREQuency:STOP", lambda a: parse_number(a, f_lo, f_hi), "f_stop_Hz", num, ch)
        self.setting("SENSe#:SWEep:POINts", self._points, "n_points", str, ch)
        self.setting("SENSe#:AVERage[:STATe]", parse_bool, "averaging", lambda v: str(int(v)), ch)
        self.setting("SENSe#:AVERage:COUNt", lambda a: int(parse_number(a, 1, 999)), "avg_count", str, ch)
        self.setting("SENSe#:APERture[:TIME]", lambda a: int(parse_number(a, 1, 5)), "aperture", str, ch)
        self.setting("SENSe#:BANDwidth[:RESolution]", lambda a: int(parse_number(a, 1, 5)), "bandwidth", str, ch)
        self.setting("SOURce#:MODE", lambda a: word(a, SOURCE_MODES), "source_mode", str, ch)
        self.setting("SOURce#:VOLTage[:LEVel][:IMMediate][:AMPLitude]", lambda a: parse_number(a, *self.ac_range_V),
                     "ac_V", num, ch)
        self.setting("SOURce#:BIAS:MODE", lambda a: word(a, SOURCE_MODES), "bias_mode", str, ch)
        self.setting("SOURce#:BIAS:VOLTage[:LEVel][:IMMediate][:AMPLitude]",
                     lambda a: parse_number(a, *self.bias_range_V, 0.0), "bias_V", num, ch)
        self.setting("SOURce#:BIAS:STATe", parse_bool, "bias_on", lambda v: str(int(v)), ch)
        self.setting("TRIGger[:SEQuence]:SOURce", lambda a: word(a, TRIGGER_SOURCES), "trigger_source", str)
        self.setting("INITiate#:CONTinuous", parse_bool, "continuous", lambda v: str(int(v)), ch)
        self.setting("CALCulate#:PARameter:COUNt", lambda a: int(parse_number(a, 1, 4)), "trace_count", str, ch)
        self.setting("FORMat[:DATA]", lambda a: word(a, DATA_FORMATS), "data_format", str)
        self.setting("FORMat:BORDer", lambda a: word(a, BYTE_ORDERS), "byte_order", str)
        add("STATus:OPERation:CONDition?", lambda r: "16" if self.busy_until > self.bench.clock.now() else "0")
        add("TRIGger[:SEQuence][:IMMediate]", self._trigger_now)
        self._fixed("DISPlay:ENABle", "1", {"ON", "OFF", "1", "0"})
        add("CALCulate#:PARameter#:DEFine", self._define)
        add("CALCulate#:PARameter#:DEFine?", lambda r: self.parameters[self._trace(r)])
        add("CALCulate#:PARameter#:SELect", lambda r: self._trace(r) and None)
        add("SENSe#:AVERage:CLEar", ch)
        add("SENSe#:SEGMent:DATA", self._set_segments)
        add("SENSe#:SEGMent:DATA?", self._get_segments)
        add("SENSe#:SWEep:POINts?", lambda r: (ch(r), str(self.frequencies().size))[1])
        add("SENSe#:FREQuency:DATA?", lambda r: (ch(r), self._values(self.frequencies()))[1])
        add("INITiate#[:IMMediate]", lambda r: (ch(r), setattr(self, "armed", True))[1])
        add("TRIGger[:SEQuence]:SINGle", self._trigger)
        add("CALCulate#[:SELected]:DATA:RDATa?", lambda r: (ch(r), self._rdat(r))[1])
        add("CALCulate#[:SELected]:DATA:FDATa?", lambda r: (ch(r), self._fdat(r))[1])

    @staticmethod
    def _channel(r: Request) -> None:
        """Only channel 1 exists (trace suffixes are checked by ``_trace``)."""
        if r.suffixes and r.suffixes[0] != 1:
            raise ScpiError(-114, "Header suffix out of range")

    def _trace(self, r: Request) -> int:
        self._channel(r)
        trace = r.suffixes[1] if len(r.suffixes) > 1 else 1
        if not 1 <= trace <= 4:
            raise ScpiError(-114, "Header suffix out of range")
        return trace

    def _define(self, r: Request) -> None:
        self.parameters[self._trace(r)] = word(one_arg(r), PARAMETERS)

    def _points(self, arg: str) -> int:
        if self.sweep_type == "SEGM":
            raise ScpiError(-221, "Settings conflict")  # segment sweeps take points from the table
        return int(parse_number(arg, 2, self.max_points))

    def _fixed(self, header: str, answer: str, accepted: set[str]) -> None:
        """A setting this simulator supports in one value only."""

        def set_(r: Request) -> None:
            if one_arg(r).upper() not in accepted:
                raise ScpiError(-224, "Illegal parameter value")

        self.server.add(header, set_)
        self.server.add(header + "?", lambda r: answer)

    def _set_segments(self, r: Request) -> None:
        """``7,<stim mode>,<osc>,<bias>,<meas time>,<avg>,<seg time>,<delay>,<N>,<start>,<stop>,<points>,...``"""
        self._channel(r)
        try:
            head = [int(float(a)) for a in r.args[:9]]
            body = [float(a) for a in r.args[9:]]
        except ValueError:
            raise ScpiError(-104, "Data type error") from None
        if len(head) < 9:
            raise ScpiError(-109, "Missing parameter")
        buf, center_span, *flags, n = head
        if buf != 7 or center_span not in (0, 1) or any(flags):
            raise ScpiError(-224, "Illegal parameter value")  # per-segment levels/times: not simulated
        if not 1 <= n <= self.max_segments:
            raise ScpiError(-222, "Data out of range")
        if len(body) < 3 * n:
            raise ScpiError(-109, "Missing parameter")
        if len(body) > 3 * n:
            raise ScpiError(-108, "Parameter not allowed")
        f_lo, f_hi = self.freq_range_Hz
        segments, last_stop = [], 0.0
        for a, b, pts in zip(body[0::3], body[1::3], body[2::3]):
            start, stop = (a - b / 2, a + b / 2) if center_span else (a, b)
            if not (f_lo <= start <= stop <= f_hi and pts >= 1 and pts == int(pts) and start > last_stop):
                raise ScpiError(-222, "Data out of range")
            if pts == 1 and stop != start:
                raise ScpiError(-222, "Data out of range")
            segments.append((start, stop, int(pts)))
            last_stop = stop
        if sum(s[2] for s in segments) > self.max_points:
            raise ScpiError(-222, "Data out of range")
        self.segments = segments

    def _get_segments(self, r: Request) -> str:
        self._channel(r)
        rows = ",".join(f"{num(a)},{num(b)},{n}" for a, b, n in self.segments)
        return f"7,0,0,0,0,0,0,0,{len(self.segments)},{rows}"

    def _trigger(self, r: Request) -> None:
        """One sweep, if the trigger source is BUS and the channel is waiting for a trigger."""
        if self.trigger_source != "BUS" or not (self.continuous or self.armed):
            raise ScpiError(-211, "Trigger ignored")
        self.armed = False
        freqs = self.frequencies()
        if self.sweep_type == "LOG" and not self.f_start_Hz < self.f_stop_Hz:
            raise ScpiError(-221, "Settings conflict")
        bias = self.bias_V if self.bias_on else 0.0
        z = np.asarray(self.bench.impedance(freqs, self.ac_V, bias), dtype=complex)
        if z.shape != freqs.shape:
            raise ScpiError(-240, "Hardware error")
        self.data = (freqs, z)
        self.busy_until = self.bench.clock.now() + self.sweep_time_s(freqs)
        self.sweeps.append({"freqs_Hz": freqs, "ac_V": self.ac_V, "bias_V": bias})

    def _values(self, values: np.ndarray) -> str:
        """Data in the FORMat chosen: ASCII numbers, or an IEEE 488.2 definite-length block of 64-bit
        (REAL) or 32-bit (REAL32) floats, big-endian (NORMal) or little-endian (SWAPped)."""
        if self.data_format == "ASC":
            return ",".join(num(v) for v in values)
        dtype = (">" if self.byte_order == "NORM" else "<") + ("f8" if self.data_format == "REAL" else "f4")
        body = np.asarray(values, dtype=dtype).tobytes()
        size = str(len(body))
        return f"#{len(size)}{size}" + body.decode("latin-1")

    def _trigger_now(self, r: Request) -> None:
        """``:TRIG[:SEQ][:IMM]``: a sweep now, whatever the trigger source, if the channel waits for one."""
        if not (self.continuous or self.armed):
            raise ScpiError(-211, "Trigger ignored")
        source, self.trigger_source = self.trigger_source, "BUS"
        try:
            self._trigger(r)
        finally:
            self.trigger_source = source

    def _bus_trigger(self, r: Request) -> None:
        """``*TRG``: a sweep when the trigger source is BUS (else -211, as the instrument)."""
        self._trigger(r)

    def _fdat(self, r: Request) -> str:
        """Formatted data of the active trace (trace 1): two values per point, the second 0 for scalar formats."""
        if self.data is None:
            raise ScpiError(-230, "Data corrupt or stale")
        f, z = self.data
        fn = _FORMATTED.get(self.parameters[1])
        if fn is None:
            raise ScpiError(-221, "Settings conflict")  # a parameter this simulator does not compute
        return self._values(np.column_stack([fn(z, f), np.zeros(f.size)]).ravel())

    def _rdat(self, r: Request) -> str:
        if self.data is None:
            raise ScpiError(-230, "Data corrupt or stale")
        z = self.data[1]
        return self._values(np.column_stack([z.real, z.imag]).ravel())




# --------------------------------------------------------------------------------------------------
# a deterministic demo bench and the recordings made with it


class VirtualClock:
    """Simulated time that advances only when slept: recordings are instant and repeatable."""

    time_scale = 1e9

    def __init__(self) -> None:
        self._t = 0.0

    def now(self) -> float:
        return self._t

    def sleep(self, seconds: float) -> None:
        self._t += max(seconds, 0.0)


class DemoBench:
    """Series R + C, noise-free: Z = R + 1/(j 2 pi f C)."""

    def __init__(self, r_ohm: float = 50.0, c_F: float = 2e-3):
        self.r_ohm, self.c_F, self.clock = r_ohm, c_F, VirtualClock()

    def impedance(self, freqs_Hz: np.ndarray, ac_V: float, bias_V: float) -> np.ndarray:
        return self.r_ohm + 1.0 / (2j * np.pi * np.asarray(freqs_Hz, dtype=float) * self.c_F)


def script_session(an: Any) -> dict[str, Any]:
    """The recorded session: identify, a log sweep, a biased list sweep, close."""
    out = {"idn": an.identify(), "log": an.spectrum(1.0, 1e4, 5, 0.01)}
    an.configure_list([0.1, 1.0, 10.0], 0.02, bias_V=0.1)
    out["list"] = an.measure()
    an.close()
    return out


def script_error(an: Any) -> None:
    """The recorded error: an AC amplitude the instrument refuses (-222), then close."""
    try:
        an.configure_log_sweep(1.0, 1e4, 5, ac_V=5.0)
    finally:
        an.close()


SCRIPTS: dict[str, Callable[[Any], Any]] = {"impedance_session": script_session, "impedance_error": script_error}


def record(directory: str | Path) -> list[Path]:
    """Run each script through the driver against the simulator and save ``<name>.jsonl``."""
    from drivers.errors import InstrumentErrorReply  # the recorder drives the real driver
    from drivers.impedance_analyzer import ImpedanceAnalyzer
    from drivers.transcript import Transcript

    paths = []
    for name, script in SCRIPTS.items():
        transcript = Transcript()
        with ImpedanceAnalyzerSim(DemoBench()) as sim:
            an = ImpedanceAnalyzer(sim.resource_name, transcript=transcript, timeout_s=2.0)
            try:
                script(an)
            except InstrumentErrorReply:
                pass  # expected by script_error
        path = Path(directory) / f"{name}.jsonl"
        path.parent.mkdir(parents=True, exist_ok=True)
        transcript.save(path)
        paths.append(path)
    return paths


@stands_in("impedance")
def _stand_in(world: WorldView, opts: SimOptions) -> Served:
    """The analyser of ``opts.impedance_model``: the IM3590's own dialect, or the E4990A-style SCPI of the others."""
    model = analyser_models.get(opts.impedance_model).name
    sim = Im3590Sim(world) if model == "IM3590" else ImpedanceAnalyzerSim(world, model=model)
    sim.start()
    return Served(sim, {"address": sim.resource_name, "model": model}, sim.stop)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--record", metavar="DIR", help="write the replay recordings into DIR")
    parser.add_argument("--serve", action="store_true", help="serve the demo bench until Ctrl-C")
    args = parser.parse_args(argv)
    if args.record:
        for p in record(args.record):
            print(p)
    if args.serve:
        ImpedanceAnalyzerSim(DemoBench()).serve_forever()
    if not (args.record or args.serve):
        parser.print_usage()
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
