"""Hioki IM3590 chemical impedance analyser (1 mHz..200 kHz) over LAN (TCP socket, pyvisa-py), no vendor DLL.

The IM3590 speaks a SCPI-like command set (IM3590 communication instruction manual): ``:MODE LCR``,
``:FREQuency``, ``:LEVel V`` with ``:LEVel:VOLTage``, ``:DCBias`` / ``:DCBias:LEVel``,
``:PARameter1..4`` (what ``:MEASure?`` returns, in order), ``:HEADer OFF`` (bare numbers),
``:TRIGger EXTernal`` with ``*TRG``. It reports refused commands through the IEEE 488.2 event status
register (``*ESR?``), not an error queue.

A spectrum is measured the way the published clients do it, point by point in LCR mode: set the
frequency, ``*TRG``, ``:MEASure?`` -> ``|Z|,phase(deg)`` (one program message per point, with ``*ESR?``). The wait for one point is ``timeout_s``
plus twice a few cycles of its frequency, so a 1 mHz point does not time out.
"""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np
import pyvisa

from drivers import analyser_models
from drivers.errors import MalformedReply
from drivers.impedance_analyzer import estimate_sweep_s
from drivers.scpi import control, fmt, on_off, parse_floats, raise_for_errors
from drivers.transcript import Transcript
from drivers.visa_instrument import VisaInstrument

# *ESR? bits (IEEE 488.2 11.5.1) and what the IM3590 manual says sets them
ESR_ERRORS = ((32, -100, "Command error"), (16, -200, "Execution error"),
              (8, -300, "Device-dependent error"), (4, -400, "Query error"))


class HiokiIM3590(VisaInstrument):
    """Complex impedance spectra from a Hioki IM3590 (SI units; phase read in degrees)."""

    ac_V = control(":LEVel:VOLTage?", ":LEVel:VOLTage {}", "measurement signal level (V mode, open-circuit V rms)")
    bias_V = control(":DCBias:LEVel?", ":DCBias:LEVel {}", "DC bias level, V")
    bias_on = control(":DCBias?", ":DCBias {}", "DC bias on", cast=on_off, values={True: "ON", False: "OFF"})
    frequency_Hz = control(":FREQuency?", ":FREQuency {}", "measurement frequency, Hz")

    def __init__(self, resource: str | Any, *, transcript: Transcript | None = None, device: str = "impedance",
                 timeout_s: float = 5.0, sweep_timeout_s: float | None = None, reset: bool = False,
                 resource_manager: pyvisa.ResourceManager | None = None, model: str = "IM3590"):
        self.model = analyser_models.get(model)
        self.sweep_timeout_s = sweep_timeout_s  # the least wait for one point's :MEASure? (a few cycles if longer)
        self._freqs: np.ndarray | None = None
        super().__init__(resource, transcript=transcript, device=device, timeout_s=timeout_s, reset=reset,
                         resource_manager=resource_manager)

    def _setup(self, reset: bool) -> None:
        """Known state: LCR mode, bare numbers, Z and phase only, measurement on *TRG, V-mode level."""
        if reset:
            self._send("*RST")
        for cmd in ("*CLS", ":HEADer OFF", ":MODE LCR", ":TRIGger EXTernal", ":PARameter1 Z",
                    ":PARameter2 PHASE", ":PARameter3 OFF", ":PARameter4 OFF", ":LEVel V"):
            self._send(cmd)
        self.check_errors()

    def errors(self) -> list[tuple[int, str]]:
        """What ``*ESR?`` reports (reading it clears it): one (code, message) per error bit set."""
        return self._esr_errors(self._ask("*ESR?"))

    def _esr_errors(self, reply: str) -> list[tuple[int, str]]:
        try:
            esr = int(float(reply))
        except ValueError:
            raise MalformedReply(self.device, f"*ESR? answered {reply[:60]!r}") from None
        return [(code, msg) for bit, code, msg in ESR_ERRORS if esr & bit]

    def configure_list(self, freqs_Hz: Sequence[float] | np.ndarray, ac_V: float, bias_V: float = 0.0) -> None:
        """Frequencies to measure (any order the caller wants; within the model's range), level and bias."""
        f = np.asarray(freqs_Hz, dtype=float).ravel()
        if f.size < 1:
            raise ValueError("need at least one frequency")
        if problem := analyser_models.out_of_range(self.model.name, f):
            raise ValueError(problem)
        if not ac_V > 0:
            raise ValueError(f"ac_V must be positive, got {ac_V}")
        self._send(f":LEVel:VOLTage {fmt(ac_V)}")
        self._send(f":DCBias:LEVel {fmt(bias_V)}")
        self._send(f":DCBias {'ON' if bias_V != 0 else 'OFF'}")
        self._freqs = None
        self.check_errors()
        self._freqs = f

    def configure_log_sweep(self, f_start_Hz: float, f_stop_Hz: float, points: int, ac_V: float,
                            bias_V: float = 0.0) -> None:
        """Logarithmic sweep, both ends included."""
        if not 0 < f_start_Hz < f_stop_Hz or int(points) != points or points < 2:
            raise ValueError(f"need 0 < f_start_Hz < f_stop_Hz and points >= 2, got {f_start_Hz}, {f_stop_Hz}, {points}")
        self.configure_list(np.geomspace(f_start_Hz, f_stop_Hz, int(points)), ac_V, bias_V)

    def measure_point(self, f_Hz: float) -> complex:
        """One frequency in one program message, ``:FREQuency f;*TRG;:MEASure?;*ESR?`` -> ``|Z|,phase;esr``: one
        round trip (separate small writes would wait on TCP's delayed ACK, ~40 ms each), and the status read
        in the same reply, so a refused frequency never passes the previous point's value off as this one's."""
        cmd = f":FREQuency {fmt(f_Hz)};*TRG;:MEASure?;*ESR?"
        wait = max(self.sweep_timeout_s or 0.0, self.timeout_s + 2.0 * estimate_sweep_s([f_Hz]))
        reply = self._ask_long(cmd, wait)
        measured, sep, esr = reply.rpartition(";")
        if not sep:
            raise MalformedReply(self.device, f"{cmd} answered {reply[:60]!r}, expected |Z|,phase;esr")
        raise_for_errors(self.device, self._esr_errors(esr))
        values = parse_floats(self.device, ":MEASure?", measured)
        if values.size != 2:
            raise MalformedReply(self.device, f":MEASure? answered {values.size} values, expected |Z|,phase")
        mag, phase_deg = values
        return complex(mag * np.exp(1j * np.deg2rad(phase_deg)))

    def measure(self) -> tuple[np.ndarray, np.ndarray]:
        """Every configured frequency: (frequencies in Hz, complex impedance in ohm)."""
        if self._freqs is None:
            raise ValueError("configure_list() or configure_log_sweep() first")
        z = np.array([self.measure_point(f) for f in self._freqs], dtype=complex)
        return self._freqs.copy(), z

    def spectrum(self, f_start_Hz: float, f_stop_Hz: float, points: int, ac_V: float,
                 bias_V: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        self.configure_log_sweep(f_start_Hz, f_stop_Hz, points, ac_V, bias_V)
        return self.measure()

    def safe(self) -> bool:
        """DC bias off and to 0 V, level to the minimum."""
        self._send(":DCBias OFF")
        self._send(":DCBias:LEVel 0")
        self._send(f":LEVel:VOLTage {fmt(self.model.ac_range_V[0])}")
        self.check_errors()
        return True

