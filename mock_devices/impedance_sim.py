"""Simulated impedance analyser speaking the E4990A SCPI subset of ``drivers.impedance_analyzer``.

The instrument keeps its sweep settings; ``:TRIG:SING`` takes Z from ``bench.impedance(f, ac, bias)``
and occupies ``sum(max(cycles / f, min_point_s))`` simulated seconds on ``bench.clock``; ``*OPC?``
answers ``1`` when the sweep is done. Frequency and level ranges default to the VersaSTAT 3's (the
paper's instrument: 10 uHz..1 MHz), not the E4990A's 20 Hz floor, so IPMC spectra fit.

Faults on demand (``inject``): ``disconnect``, ``timeout``, ``garbage``, ``error``, ``overrange``.

Recordings for the replay tests::

    python -m mock_devices.impedance_sim --record tests/data/transcripts
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any, Callable

import numpy as np

from mock_devices.bench_api import BenchView
from mock_devices.scpi_server import Request, ScpiError, ScpiServer, parse_bool, parse_number

FAULTS = ("disconnect", "timeout", "garbage", "error", "overrange")
OVERLOAD = "+9.9E37"
GARBAGE = "#?!garbage~~"
SWEEP_TYPES = {"LIN": "LIN", "LINEAR": "LIN", "LOG": "LOG", "LOGARITHMIC": "LOG", "SEGM": "SEGM", "SEGMENT": "SEGM"}
TRIGGER_SOURCES = {"INT": "INT", "INTERNAL": "INT", "EXT": "EXT", "EXTERNAL": "EXT", "BUS": "BUS",
                   "MAN": "MAN", "MANUAL": "MAN"}


def _num(x: float) -> str:
    return f"{x:+.12E}"


def _word(arg: str, table: dict[str, str]) -> str:
    try:
        return table[arg.strip().upper()]
    except KeyError:
        raise ScpiError(-224, "Illegal parameter value") from None


class ImpedanceAnalyzerSim:
    """The analyser on a loopback TCP port; ``resource_name`` is what the driver opens."""

    def __init__(self, bench: BenchView, *, port: int = 0, idn: str = "labrig,SIM-IMPEDANCE,0,0.1",
                 freq_range_Hz: tuple[float, float] = (1e-5, 1e6), ac_range_V: tuple[float, float] = (5e-3, 1.0),
                 bias_range_V: tuple[float, float] = (-10.0, 10.0), max_points: int = 1601,
                 max_segments: int = 201, cycles: float = 3.0, min_point_s: float = 0.05):
        self.bench, self.idn = bench, idn
        self.freq_range_Hz, self.ac_range_V, self.bias_range_V = freq_range_Hz, ac_range_V, bias_range_V
        self.max_points, self.max_segments = max_points, max_segments
        self.cycles, self.min_point_s = cycles, min_point_s
        self.server = ScpiServer(port, name="impedance-sim")
        self.server.reply_filter = self._filter
        self.fault: str | None = None
        self._overrange_points: list[int] | None = None
        self.sweeps: list[dict[str, Any]] = []  # what each triggered sweep applied, for tests
        self.reset()
        self._register()

    # ---- state ------------------------------------------------------------------------------

    def reset(self) -> None:
        """``*RST`` state (the E4990A's, within this simulator's ranges)."""
        self.sweep_type, self.f_start_Hz, self.f_stop_Hz, self.n_points = "LIN", 1.0, 1e5, 201
        self.segments: list[tuple[float, float, int]] = [(1.0, 1e5, 201)]
        self.ac_V, self.bias_V, self.bias_on = 0.5, 0.0, False
        self.trigger_source, self.continuous, self.armed = "INT", True, False
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
        return float(np.sum(np.maximum(self.cycles / np.asarray(freqs_Hz), self.min_point_s)))

    # ---- faults -----------------------------------------------------------------------------

    def inject(self, fault: str, *, code: int = -200, message: str = "Execution error",
               points: list[int] | None = None) -> None:
        """Start a fault: see ``FAULTS``. ``error`` queues ``code,"message"`` once; ``overrange`` flags
        ``points`` (indices; default all) of the data as overloaded."""
        if fault not in FAULTS:
            raise ValueError(f"unknown fault {fault!r}; one of {FAULTS}")
        if fault == "error":
            self.server.push_error(code, message)
            return
        self.fault = fault
        if fault == "disconnect":
            self.server.drop()
        elif fault == "timeout":
            self.server.mute_queries = True
        elif fault == "overrange":
            self._overrange_points = points

    def clear_fault(self) -> None:
        """Back to normal; after ``disconnect`` the instrument listens again on the same port."""
        was, self.fault = self.fault, None
        self.server.mute_queries = False
        self._overrange_points = None
        if was == "disconnect" and not self.server.stopping.is_set():
            self.server.start()

    def _filter(self, request: Request, reply: str) -> str:
        if self.fault == "garbage":
            return GARBAGE
        if self.fault == "overrange" and "RDAT" in request.header.upper():
            values = reply.split(",")
            n = len(values) // 2
            for i in range(n) if self._overrange_points is None else self._overrange_points:
                values[2 * i] = values[2 * i + 1] = OVERLOAD
            return ",".join(values)
        return reply

    # ---- transport --------------------------------------------------------------------------

    @property
    def resource_name(self) -> str:
        return self.server.resource_name

    @property
    def port(self) -> int:
        return self.server.port

    def start(self) -> "ImpedanceAnalyzerSim":
        self.server.start()
        return self

    def stop(self) -> None:
        self.server.stop()

    def __enter__(self) -> "ImpedanceAnalyzerSim":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

    # ---- commands ---------------------------------------------------------------------------

    def _register(self) -> None:
        add = self.server.add
        add("*IDN?", lambda r: self.idn)
        add("*RST", lambda r: self.reset())
        add("*OPC?", self._opc)
        f_lo, f_hi = self.freq_range_Hz
        self._setting("SENSe#:SWEep:TYPE", lambda a: _word(a, SWEEP_TYPES), "sweep_type", str)
        self._setting("SENSe#:FREQuency:STARt", lambda a: parse_number(a, f_lo, f_hi), "f_start_Hz", _num)
        self._setting("SENSe#:FREQuency:STOP", lambda a: parse_number(a, f_lo, f_hi), "f_stop_Hz", _num)
        self._setting("SENSe#:SWEep:POINts", lambda a: int(parse_number(a, 2, self.max_points)), "n_points", str)
        self._setting("SOURce#:VOLTage", lambda a: parse_number(a, *self.ac_range_V), "ac_V", _num)
        self._setting("SOURce#:BIAS:VOLTage", lambda a: parse_number(a, *self.bias_range_V, 0.0), "bias_V", _num)
        self._setting("SOURce#:BIAS:STATe", parse_bool, "bias_on", lambda v: str(int(v)))
        self._setting("TRIGger[:SEQuence]:SOURce", lambda a: _word(a, TRIGGER_SOURCES), "trigger_source", str)
        self._setting("INITiate#:CONTinuous", parse_bool, "continuous", lambda v: str(int(v)))
        self._fixed("FORMat[:DATA]", "ASC", {"ASC", "ASCII"})
        self._fixed("CALCulate#:PARameter#:DEFine", "Z", {"Z"})
        add("SENSe#:SEGMent:DATA", self._set_segments)
        add("SENSe#:SEGMent:DATA?", self._get_segments)
        add("SENSe#:SWEep:POINts?", self._channel(lambda r: str(self.frequencies().size)))
        add("SENSe#:FREQuency:DATA?", self._channel(lambda r: ",".join(_num(f) for f in self.frequencies())))
        add("INITiate#[:IMMediate]", self._channel(self._arm))
        add("TRIGger[:SEQuence]:SINGle", self._trigger)
        add("CALCulate#[:SELected]:DATA:RDATa?", self._channel(self._rdat))

    @staticmethod
    def _channel(fn: Callable[[Request], Any]) -> Callable[[Request], Any]:
        """Only channel / trace 1 exists."""

        def checked(r: Request) -> Any:
            if any(s != 1 for s in r.suffixes):
                raise ScpiError(-114, "Header suffix out of range")
            return fn(r)

        return checked

    @staticmethod
    def _one_arg(r: Request) -> str:
        if not r.args or not r.args[0]:
            raise ScpiError(-109, "Missing parameter")
        if len(r.args) > 1:
            raise ScpiError(-108, "Parameter not allowed")
        return r.args[0]

    def _setting(self, header: str, parse: Callable[[str], Any], attr: str, show: Callable[[Any], str]) -> None:
        """A settable value with its query; a query answers in the form ``show`` gives."""

        def set_(r: Request) -> None:
            value = parse(self._one_arg(r))
            if attr == "n_points" and self.sweep_type == "SEGM":
                raise ScpiError(-221, "Settings conflict")  # segment sweeps take points from the table
            setattr(self, attr, value)

        self.server.add(header, self._channel(set_))
        self.server.add(header + "?", self._channel(lambda r: show(getattr(self, attr))))

    def _fixed(self, header: str, answer: str, accepted: set[str]) -> None:
        """A setting this simulator supports in one value only."""

        def set_(r: Request) -> None:
            if self._one_arg(r).upper() not in accepted:
                raise ScpiError(-224, "Illegal parameter value")

        self.server.add(header, self._channel(set_))
        self.server.add(header + "?", self._channel(lambda r: answer))

    def _set_segments(self, r: Request) -> None:
        """``7,<stim mode>,<osc>,<bias>,<meas time>,<avg>,<seg time>,<delay>,<N>,<start>,<stop>,<points>,...``"""
        self._channel(lambda _: None)(r)
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
        self._channel(lambda _: None)(r)
        rows = ",".join(f"{_num(a)},{_num(b)},{n}" for a, b, n in self.segments)
        return f"7,0,0,0,0,0,0,0,{len(self.segments)},{rows}"

    def _arm(self, r: Request) -> None:
        self.armed = True

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

    def _opc(self, r: Request) -> str:
        """Answer once the sweep in progress is over (simulated time); give up if the server stops."""
        clock = self.bench.clock
        chunk = 0.05 * getattr(clock, "time_scale", 1.0)  # ~50 ms of wall time per nap
        while (left := self.busy_until - clock.now()) > 0 and not self.server.stopping.is_set():
            clock.sleep(min(left, chunk))
        return "1"

    def _rdat(self, r: Request) -> str:
        if self.data is None:
            raise ScpiError(-230, "Data corrupt or stale")
        z = self.data[1]
        return ",".join(f"{_num(v.real)},{_num(v.imag)}" for v in z)


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


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--record", metavar="DIR", help="write the replay recordings into DIR")
    parser.add_argument("--serve", action="store_true", help="serve the demo bench until Ctrl-C")
    args = parser.parse_args(argv)
    if args.record:
        for p in record(args.record):
            print(p)
    if args.serve:
        with ImpedanceAnalyzerSim(DemoBench()) as sim:
            print(sim.resource_name, flush=True)
            try:
                sim.server.stopping.wait()
            except KeyboardInterrupt:
                pass
    if not (args.record or args.serve):
        parser.print_usage()
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
