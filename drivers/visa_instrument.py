"""The one base of labrig's VISA instruments: open a resource name (or adopt an open resource), record
the traffic, map pyvisa's failures to ``drivers.errors``, wait long for slow replies, close safely.

A subclass provides ``_setup(reset)`` (known state after connecting), ``errors()`` (the instrument's own
error report) and ``safe()`` (its safe state before the link closes).
"""

from __future__ import annotations

import logging
import select
import socket
import time
from contextlib import contextmanager
from typing import Any, Iterator

import pyvisa
from pyvisa import constants

from drivers.errors import Disconnected, InstrumentError, InstrumentTimeout, MalformedReply
from drivers.instrument import Instrument
from drivers.scpi import raise_for_errors
from drivers.transcript import RecordingMessages, Transcript

log = logging.getLogger(__name__)

_LOST = {constants.StatusCode.error_connection_lost, constants.StatusCode.error_io,
         constants.StatusCode.error_invalid_object, constants.StatusCode.error_closing_failed}


class VisaInstrument(Instrument):
    """Message-based instrument over pyvisa(-py); ``device`` names it in every error."""

    has_output = True  # an analyser's source (AC level and DC bias) drives the strip

    def __init__(self, resource: str | Any, *, transcript: Transcript | None = None, device: str = "impedance",
                 timeout_s: float = 5.0, reset: bool = False, resource_manager: pyvisa.ResourceManager | None = None):
        self.device = device
        self.timeout_s = float(timeout_s)
        self._rm: pyvisa.ResourceManager | None = None
        self._closed = False
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

    def _setup(self, reset: bool) -> None:
        """Bring the instrument to a known state (override)."""

    def errors(self) -> list[tuple[int, str]]:
        """The instrument's pending errors as (code, message) (override)."""
        return []

    def check_errors(self) -> None:
        """Raise ``InstrumentErrorReply`` if the instrument reports any error."""
        raise_for_errors(self.device, self.errors())

    @property
    def name(self) -> str:
        return self.device

    def safe(self) -> bool:
        """Put the source in its safe state (override); raises when the instrument cannot be reached."""
        return True

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

    def identify(self) -> str:
        """``*IDN?``: manufacturer,model,serial,firmware."""
        idn = self._ask("*IDN?")
        if idn.count(",") != 3:
            raise MalformedReply(self.device, f"*IDN? answered {idn[:60]!r}, not 4 comma-separated fields")
        return idn

    def _ask_long(self, cmd: str, wait_s: float) -> str:
        """A query whose reply may take ``wait_s`` (a sweep, a 1 mHz point), read in short slices on a socket
        so a dropped link shows at once."""
        self._send(cmd)
        if self._socket() is None:
            return self._read(f"{cmd} (measuring)", timeout_s=wait_s)
        deadline = time.monotonic() + wait_s
        while True:
            try:
                return self._read(f"{cmd} (measuring)", timeout_s=min(0.5, max(deadline - time.monotonic(), 0.001)))
            except InstrumentTimeout:  # a slice ran out; _io already turned a closed socket into Disconnected
                if time.monotonic() >= deadline:
                    raise InstrumentTimeout(self.device, f"no reply to {cmd} within {wait_s:g} s (measuring)") from None

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
