"""Shared plumbing of the serial drivers: open a port (URL, device path or port object), record it,
turn pyserial's failures into the errors of ``drivers.errors``, and declare commands at class level.
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Any, Iterator

import serial

try:  # tcflush on a hung-up pty raises termios.error, which is not an OSError
    from termios import error as _TermiosError
except ImportError:  # pragma: no cover - Windows
    _TermiosError = OSError

from drivers.errors import Disconnected, InstrumentError, InstrumentTimeout
from drivers.instrument import Instrument
from drivers.transcript import RecordingSerial, Transcript

SerialLike = Any  # pyserial Serial, RecordingSerial, ReplaySerial: write/read/read_until/in_waiting/close


def open_serial(
    port: str | SerialLike,
    *,
    device: str,
    timeout_s: float,
    transcript: Transcript | None = None,
    **settings: Any,
) -> SerialLike:
    """Open ``port`` (a pyserial URL such as ``socket://127.0.0.1:5000`` or a path such as ``/dev/pts/5``)
    or adopt an already-open port object; wrap it in ``RecordingSerial`` when a transcript is given."""
    if isinstance(port, str):
        try:
            raw = serial.serial_for_url(port, timeout=timeout_s, write_timeout=timeout_s, **settings)
        except (serial.SerialException, OSError, ValueError) as e:
            raise Disconnected(device, f"cannot open {port}: {e}") from e
    else:
        raw = port
    return RecordingSerial(raw, transcript, device) if transcript is not None else raw


@contextmanager
def io_errors(device: str) -> Iterator[None]:
    """Map pyserial/OS failures to ``InstrumentTimeout`` (write timeout) or ``Disconnected``."""
    try:
        yield
    except InstrumentError:
        raise
    except serial.SerialTimeoutException as e:  # subclass of SerialException: test it first
        raise InstrumentTimeout(device, f"write timed out: {e}") from e
    except (serial.SerialException, OSError, _TermiosError) as e:
        raise Disconnected(device, f"port gone: {e}") from e


class Command:
    """Class-level declaration of one instrument command, in the spirit of PyMeasure's ``Instrument.control``.

    ``template`` is formatted with the call's keyword arguments after checking them against
    ``allowed``; ``request()`` returns the request bytes (without terminator) and the driver decides
    how to send it and read the answer. ``confirmed=False`` marks a command not verified against the vendor manual.
    """

    def __init__(self, template: str, doc: str, *, confirmed: bool = True, **allowed: tuple):
        self.template, self.doc, self.confirmed, self.allowed = template, doc, confirmed, allowed
        self.name = ""
        self.__doc__ = doc

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    def request(self, **kwargs: Any) -> bytes:
        for key, value in kwargs.items():
            if key in self.allowed and value not in self.allowed[key]:
                raise ValueError(f"{self.name}: {key}={value!r} not in {self.allowed[key]}")
        return self.template.format(**kwargs).encode("ascii")


class SerialInstrument(Instrument):
    """Base of the serial drivers: owns the port, maps errors, closes safely, context manager."""

    default_name = "serial"
    default_baudrate = 9600

    def __init__(
        self,
        port: str | SerialLike,
        *,
        name: str | None = None,
        transcript: Transcript | None = None,
        timeout_s: float = 0.5,
        baudrate: int | None = None,
        **settings: Any,
    ):
        """``port``: pyserial URL, device path or open port; ``settings``: more pyserial options (8N1 default)."""
        self.name = name or self.default_name
        self.timeout_s = timeout_s
        baud = baudrate or self.default_baudrate
        self.port = open_serial(port, device=self.name, timeout_s=timeout_s, transcript=transcript, baudrate=baud, **settings)
        self.closed = False

    def _write(self, data: bytes) -> None:
        if self.closed:
            raise Disconnected(self.name, "driver is closed")
        with io_errors(self.name):
            self.port.write(data)

    def _read_until(self, terminator: bytes, size: int | None = None) -> bytes:
        if self.closed:
            raise Disconnected(self.name, "driver is closed")
        with io_errors(self.name):
            return bytes(self.port.read_until(terminator, size))

    def safe(self) -> bool:
        """Put the instrument in its safe state (before the port closes; override)."""
        return True

    def close(self) -> None:
        """Leave the instrument safe and close the port; idempotent, never raises for a dead port."""
        if self.closed:
            return
        try:
            self.safe()
        except InstrumentError:
            pass  # a dead line cannot be made safer; closing must still happen
        finally:
            self.closed = True
            try:
                self.port.close()
            except (serial.SerialException, OSError, _TermiosError):
                pass
