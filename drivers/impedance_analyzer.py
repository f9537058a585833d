"""Impedance analyser / potentiostat over VISA, using a Keysight E4990A SCPI subset.

The driver is given a VISA resource name (``TCPIP::host::5025::SOCKET``, ``TCPIP::host::inst0::INSTR``,
...) or an already-open message-based resource (e.g. ``drivers.transcript.ReplayMessages``) and cannot
tell a real instrument from the simulated one. Every failure is one of ``drivers.errors``. The command
subset and what is assumed about the E4990A are in ``docs/instruments_impedance.md``.
"""

from __future__ import annotations

import logging
import select
import socket
import time
from contextlib import contextmanager
from typing import Any, Iterator, Sequence

import numpy as np
import pyvisa
from pyvisa import constants

from drivers.errors import Disconnected, InstrumentError, InstrumentTimeout, MalformedReply
from drivers.scpi import control, fmt, measurement, on_off, parse_error, parse_floats, raise_for_errors
from drivers.transcript import RecordingMessages, Transcript

log = logging.getLogger(__name__)

MAX_LIST_POINTS = 201  # E4990A segment table: at most 201 segments (one frequency each here)
_LOST = {constants.StatusCode.error_connection_lost, constants.StatusCode.error_io,
         constants.StatusCode.error_invalid_object, constants.StatusCode.error_closing_failed}


def estimate_sweep_s(freqs_Hz: np.ndarray, cycles: float = 5.0, min_point_s: float = 0.1) -> float:
    """Generous real-time duration of a sweep: a few cycles per point, never less than ``min_point_s``."""
    f = np.asarray(freqs_Hz, dtype=float)
    return float(np.sum(np.maximum(cycles / f, min_point_s))) if f.size else 0.0


class ImpedanceAnalyzer:
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
                 resource_manager: pyvisa.ResourceManager | None = None):
        self.device = device
        self.timeout_s = float(timeout_s)
        self.sweep_timeout_s = sweep_timeout_s
        self._rm: pyvisa.ResourceManager | None = None
        self._closed = False
        self._freqs: np.ndarray | None = None  # what the last configure asked for
        if isinstance(resource, str):
            self._raw = self._open(resource, resource_manager)
        else:
            self._raw = resource  # already open: a pyvisa resource or a ReplayMessages
        self._res = RecordingMessages(self._raw, transcript, device) if transcript is not None else self._raw
        self._set_timeout(self.timeout_s)
        try:
            self._setup(reset)
        except BaseException:
            self._release()  # a refused connection must not leak the socket or our resource manager
            raise

    # ---- connection -------------------------------------------------------------------------

    def _open(self, name: str, rm: pyvisa.ResourceManager | None) -> Any:
        if rm is None:
            rm = self._rm = pyvisa.ResourceManager("@py")
        kw: dict[str, Any] = {"write_termination": "\n", "open_timeout": int(self.timeout_s * 1000)}
        if name.upper().endswith("::SOCKET"):
            kw["read_termination"] = "\n"  # raw sockets have no END signal
        try:
            return rm.open_resource(name, **kw)
        except (ValueError, TypeError):
            raise  # a malformed resource name is the caller's error, not the instrument's
        except Exception as e:  # pyvisa-py raises a bare Exception when connect() fails
            raise Disconnected(self.device, f"cannot open {name}: {e}") from e

    def _setup(self, reset: bool) -> None:
        """Known state: ASCII data, trace 1 = impedance Z, bus trigger, channel 1 held until armed."""
        if reset:
            self._send("*RST")
        for cmd in ("*CLS", ":FORM:DATA ASC", ":CALC1:PAR1:DEF Z", ":TRIG:SOUR BUS", ":INIT1:CONT OFF"):
            self._send(cmd)
        self.check_errors()

    def _set_timeout(self, seconds: float) -> None:
        self._raw.timeout = int(max(seconds, 0.001) * 1000)  # pyvisa wants ms

    def _socket(self) -> socket.socket | None:
        """The TCP socket under a pyvisa-py SOCKET resource, if that is what we have."""
        try:
            sock = self._raw.visalib.sessions[self._raw.session].interface
        except Exception:
            return None
        return sock if isinstance(sock, socket.socket) else None

    def _peer_closed(self) -> bool:
        """pyvisa-py reports a socket closed by the instrument as a timeout; look at the socket."""
        sock = self._socket()
        if sock is None:
            return False
        try:
            readable, _, _ = select.select([sock], [], [], 0)
            return bool(readable) and sock.recv(1, socket.MSG_PEEK) == b""
        except (OSError, ValueError):
            return True

    @contextmanager
    def _io(self, what: str, timeout_s: float | None = None) -> Iterator[None]:
        """Turn transport failures into ``drivers.errors``."""
        try:
            yield
        except InstrumentError:
            raise
        except pyvisa.errors.VisaIOError as e:
            if e.error_code == constants.StatusCode.error_timeout:
                if self._peer_closed():
                    raise Disconnected(self.device, f"connection closed by the instrument during {what}") from e
                wait = self.timeout_s if timeout_s is None else timeout_s
                raise InstrumentTimeout(self.device, f"no reply to {what} within {wait:g} s") from e
            if e.error_code in _LOST:
                raise Disconnected(self.device, f"{what}: {e.description}") from e
            raise InstrumentError(self.device, f"{what}: {e}") from e
        except pyvisa.errors.InvalidSession as e:
            raise Disconnected(self.device, f"{what}: session is closed") from e
        except OSError as e:  # refused, reset, broken pipe
            raise Disconnected(self.device, f"{what}: {e}") from e
        except UnicodeDecodeError as e:
            raise MalformedReply(self.device, f"{what}: reply is not ASCII") from e

    def _send(self, cmd: str) -> None:
        if self._closed:
            raise Disconnected(self.device, "driver is closed")
        with self._io(cmd):
            self._res.write(cmd)

    def _read(self, what: str, timeout_s: float | None = None) -> str:
        with self._io(what, timeout_s):
            if timeout_s is not None:
                self._set_timeout(timeout_s)
            try:
                return self._res.read().strip()
            finally:
                if timeout_s is not None:
                    self._set_timeout(self.timeout_s)

    def _ask(self, cmd: str) -> str:
        self._send(cmd)
        return self._read(cmd)

    # ---- public -----------------------------------------------------------------------------

    def identify(self) -> str:
        """``*IDN?``: manufacturer,model,serial,firmware."""
        idn = self._ask("*IDN?")
        if idn.count(",") != 3:
            raise MalformedReply(self.device, f"*IDN? answered {idn[:60]!r}, not 4 comma-separated fields")
        return idn

    def errors(self) -> list[tuple[int, str]]:
        """Drain the error queue: ``[(code, message), ...]``, empty when ``+0,"No error"``."""
        found: list[tuple[int, str]] = []
        for _ in range(64):  # an instrument that never says "No error" must not hang us
            code, msg = parse_error(self.device, self._ask("SYST:ERR?"))
            if code == 0:
                return found
            found.append((code, msg))
        raise MalformedReply(self.device, "SYST:ERR? never answered +0 (error queue does not drain)")

    def check_errors(self) -> None:
        """Raise ``InstrumentErrorReply`` if the instrument queued any error."""
        raise_for_errors(self.device, self.errors())

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
        done = self._wait_opc(wait)
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

    def _wait_opc(self, wait_s: float) -> str:
        """``*OPC?`` with a long wait, read in short slices on a socket so a dropped link shows at once."""
        self._send("*OPC?")
        if self._socket() is None:
            return self._read("*OPC? (sweep)", timeout_s=wait_s)
        deadline = time.monotonic() + wait_s
        while True:
            try:
                return self._read("*OPC? (sweep)", timeout_s=min(0.5, max(deadline - time.monotonic(), 0.001)))
            except InstrumentTimeout:  # a slice ran out; _io already turned a closed socket into Disconnected
                if time.monotonic() >= deadline:
                    raise InstrumentTimeout(self.device, f"sweep not complete within {wait_s:g} s (*OPC?)") from None

    def spectrum(self, f_start_Hz: float, f_stop_Hz: float, points: int, ac_V: float,
                 bias_V: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """Configure a log sweep and measure it."""
        self.configure_log_sweep(f_start_Hz, f_stop_Hz, points, ac_V, bias_V)
        return self.measure()

    def safe(self) -> None:
        """Bias off and to 0 V, AC amplitude to the instrument's minimum."""
        self._send(":SOUR:BIAS:STAT OFF")
        self._send(":SOUR1:BIAS:VOLT 0")
        self._send(":SOUR1:VOLT MIN")
        self.check_errors()

    def close(self) -> None:
        """Leave the source safe (best effort: the instrument may be gone) and release the resource."""
        if self._closed:
            return
        try:
            self.safe()
        except InstrumentError as e:
            log.warning("%s: could not make the source safe on close: %s", self.device, e)
        self._release()

    def _release(self) -> None:
        self._closed = True
        try:
            self._raw.close()
        except Exception as e:  # closing a dead socket can fail; nothing left to protect
            log.debug("%s: close: %s", self.device, e)
        if self._rm is not None:
            self._rm.close()
            self._rm = None

    def __enter__(self) -> "ImpedanceAnalyzer":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
