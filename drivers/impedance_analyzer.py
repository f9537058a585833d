"""Impedance analyser over VISA, using a Keysight E4990A SCPI subset (models E4990A and SIM-WIDE).

The driver is given a VISA resource name (``TCPIP::host::5025::SOCKET``, ``TCPIP::host::inst0::INSTR``,
...) or an already-open message-based resource (e.g. ``drivers.transcript.ReplayMessages``) and cannot
tell a real instrument from the simulated one. Every failure is one of ``drivers.errors``. The command
subset and what is assumed about the E4990A are in ``docs/instruments_impedance.md``.
"""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np
import pyvisa

from drivers import analyser_models
from drivers.errors import MalformedReply
from drivers.scpi import control, fmt, measurement, on_off, parse_error, parse_floats
from drivers.transcript import Transcript
from drivers.visa_instrument import VisaInstrument

MAX_LIST_POINTS = 201  # E4990A segment table: at most 201 segments (one frequency each here)


def estimate_sweep_s(freqs_Hz: np.ndarray, cycles: float = 5.0, min_point_s: float = 0.1) -> float:
    """Generous real-time duration of a sweep: a few cycles per point, never less than ``min_point_s``."""
    f = np.asarray(freqs_Hz, dtype=float)
    return float(np.sum(np.maximum(cycles / f, min_point_s))) if f.size else 0.0


class ImpedanceAnalyzer(VisaInstrument):
    """Complex impedance spectra from an E4990A-compatible analyser (SI units throughout).

    ``timeout_s`` bounds ordinary replies; the wait for a sweep (``*OPC?``) is ``sweep_timeout_s`` or,
    if None, ``timeout_s`` plus twice ``estimate_sweep_s`` of the configured frequencies, so a 0.1 Hz
    point (tens of seconds on a real instrument) does not time out.
    """

    ac_V = control(":SOUR1:VOLT?", ":SOUR1:VOLT {}", "AC (oscillator) amplitude, V")
    bias_V = control(":SOUR1:BIAS:VOLT?", ":SOUR1:BIAS:VOLT {}", "DC bias level, V")
    bias_on = control(":SOUR:BIAS:STAT?", ":SOUR:BIAS:STAT {}", "DC bias output on", cast=on_off,
                      values={True: "ON", False: "OFF"})
    points = measurement(":SENS1:SWE:POIN?", "points in the configured sweep", cast=lambda s: int(float(s)))

    def __init__(self, resource: str | Any, *, transcript: Transcript | None = None, device: str = "impedance",
                 timeout_s: float = 5.0, sweep_timeout_s: float | None = None, reset: bool = False,
                 resource_manager: pyvisa.ResourceManager | None = None, model: str = "E4990A"):
        self.model = analyser_models.get(model)
        self.sweep_timeout_s = sweep_timeout_s
        self._freqs: np.ndarray | None = None  # what the last configure asked for
        super().__init__(resource, transcript=transcript, device=device, timeout_s=timeout_s, reset=reset,
                         resource_manager=resource_manager)

    def _setup(self, reset: bool) -> None:
        """Known state: ASCII data, trace 1 = impedance Z, bus trigger, channel 1 held until armed."""
        if reset:
            self._send("*RST")
        for cmd in ("*CLS", ":FORM:DATA ASC", ":CALC1:PAR1:DEF Z", ":TRIG:SOUR BUS", ":INIT1:CONT OFF"):
            self._send(cmd)
        self.check_errors()

    def errors(self) -> list[tuple[int, str]]:
        """Drain the error queue: ``[(code, message), ...]``, empty when ``+0,"No error"``."""
        found: list[tuple[int, str]] = []
        for _ in range(64):  # an instrument that never says "No error" must not hang us
            code, msg = parse_error(self.device, self._ask("SYST:ERR?"))
            if code == 0:
                return found
            found.append((code, msg))
        raise MalformedReply(self.device, "SYST:ERR? never answered +0 (error queue does not drain)")

    def _set_source(self, ac_V: float, bias_V: float) -> None:
        if not ac_V > 0:
            raise ValueError(f"ac_V must be positive, got {ac_V}")
        self._send(f":SOUR1:VOLT {fmt(ac_V)}")
        self._send(f":SOUR1:BIAS:VOLT {fmt(bias_V)}")
        self._send(f":SOUR:BIAS:STAT {'ON' if bias_V != 0 else 'OFF'}")

    def configure_log_sweep(self, f_start_Hz: float, f_stop_Hz: float, points: int, ac_V: float,
                            bias_V: float = 0.0) -> None:
        """Logarithmic sweep from ``f_start_Hz`` to ``f_stop_Hz`` (both included) at ``points`` points."""
        if not 0 < f_start_Hz < f_stop_Hz:
            raise ValueError(f"need 0 < f_start_Hz < f_stop_Hz, got {f_start_Hz}, {f_stop_Hz}")
        if int(points) != points or points < 2:
            raise ValueError(f"points must be an integer >= 2, got {points}")
        self._send(":SENS1:SWE:TYPE LOG")
        self._send(f":SENS1:FREQ:STAR {fmt(f_start_Hz)}")
        self._send(f":SENS1:FREQ:STOP {fmt(f_stop_Hz)}")
        self._send(f":SENS1:SWE:POIN {int(points)}")
        self._set_source(ac_V, bias_V)
        self._freqs = None
        self.check_errors()
        self._freqs = np.geomspace(f_start_Hz, f_stop_Hz, int(points))

    def configure_list(self, freqs_Hz: Sequence[float] | np.ndarray, ac_V: float, bias_V: float = 0.0) -> None:
        """Arbitrary frequencies (strictly increasing, at most 201) as a segment sweep, one point per segment."""
        f = np.asarray(freqs_Hz, dtype=float).ravel()
        if f.size < 1 or f.size > MAX_LIST_POINTS:
            raise ValueError(f"need 1..{MAX_LIST_POINTS} frequencies, got {f.size}")
        if not (np.all(f > 0) and np.all(np.diff(f) > 0)):
            raise ValueError("frequencies must be positive and strictly increasing (segments may not overlap)")
        # 7 = buffer format; then start/stop mode, and per-segment OSC, bias, meas time, average,
        # segment time, delay all off: each segment is just start,stop,points.
        table = ",".join(f"{fmt(x)},{fmt(x)},1" for x in f)
        self._send(":SENS1:SWE:TYPE SEGM")
        self._send(f":SENS1:SEGM:DATA 7,0,0,0,0,0,0,0,{f.size},{table}")
        self._set_source(ac_V, bias_V)
        self._freqs = None
        self.check_errors()
        self._freqs = f

    def measure(self) -> tuple[np.ndarray, np.ndarray]:
        """One triggered sweep: (frequencies in Hz, complex impedance in ohm)."""
        self._send(":INIT1")  # arm once; the channel returns to hold after the sweep
        self._send(":TRIG:SING")
        wait = self.sweep_timeout_s
        if wait is None:
            wait = self.timeout_s + 2.0 * estimate_sweep_s(self._freqs if self._freqs is not None else [])
        done = self._ask_long("*OPC?", wait)
        if done not in ("1", "+1"):
            raise MalformedReply(self.device, f"*OPC? answered {done[:60]!r}, expected 1")
        freqs = parse_floats(self.device, ":SENS1:FREQ:DATA?", self._ask(":SENS1:FREQ:DATA?"))
        raw = parse_floats(self.device, ":CALC1:DATA:RDAT?", self._ask(":CALC1:DATA:RDAT?"))
        if self._freqs is not None and freqs.size != self._freqs.size:
            raise MalformedReply(self.device, f"{freqs.size} frequencies for a {self._freqs.size}-point sweep")
        if raw.size != 2 * freqs.size:
            raise MalformedReply(self.device, f"{raw.size} data values for {freqs.size} points (want re,im pairs)")
        self.check_errors()
        return freqs, raw[0::2] + 1j * raw[1::2]

    def spectrum(self, f_start_Hz: float, f_stop_Hz: float, points: int, ac_V: float,
                 bias_V: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """Configure a log sweep and measure it."""
        self.configure_log_sweep(f_start_Hz, f_stop_Hz, points, ac_V, bias_V)
        return self.measure()

    def safe(self) -> bool:
        """Bias off and to 0 V, AC amplitude to the instrument's minimum."""
        self._send(":SOUR:BIAS:STAT OFF")
        self._send(":SOUR1:BIAS:VOLT 0")
        self._send(":SOUR1:VOLT MIN")
        self.check_errors()
        return True

