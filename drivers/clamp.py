"""The clamp: a motorised clamp controller over serial, or an operator asked to turn the screw.

Both expose ``request(force_N)``; the load cell (not the clamp) confirms the force is on target and
steady. The motor controller speaks a small ASCII protocol (CR-terminated), documented in
docs/instruments_serial.md: ``F<newtons>`` -> ``OK``; ``F?`` -> ``F,+0029.40``; ``S`` (stop) -> ``OK``;
``ER,<cmd>,<code>`` on error.
"""

from __future__ import annotations

import sys
from typing import Any, Callable, Protocol

from drivers.errors import InstrumentErrorReply, InstrumentTimeout, MalformedReply
from drivers.instrument import Instrument
from drivers.serial_port import Command, SerialInstrument, SerialLike, io_errors
from drivers.transcript import Transcript

CR = b"\r"


class ClampController(Protocol):
    def request(self, force_N: float) -> None: ...

    def close(self) -> None: ...


class MotorClamp(SerialInstrument):
    """Motorised clamp controller: set the target force, read it back, stop."""

    default_name = "clamp"
    set_force = Command("F{force:.2f}", "Drive the clamp towards <force> newtons.", confirmed=False)
    get_force = Command("F?", "Target force, N.", confirmed=False)
    stop = Command("S", "Stop the motor where it is.", confirmed=False)

    def __init__(self, port: str | SerialLike, *, name: str | None = None, transcript: Transcript | None = None, timeout_s: float = 0.5, max_force_N: float = 98.0):
        super().__init__(port, name=name, transcript=transcript, timeout_s=timeout_s, baudrate=9600)
        self.max_force_N = max_force_N

    def _query(self, cmd: Command, **kw: Any) -> str:
        with io_errors(self.name):
            self.port.reset_input_buffer()
        self._write(cmd.request(**kw) + CR)
        raw = self._read_until(CR, 64)
        if not raw.endswith(CR):
            raise InstrumentTimeout(self.name, f"no reply to {cmd.request(**kw).decode()} within {self.timeout_s} s")
        text = raw[:-1].decode("ascii", errors="replace")
        if text.startswith("ER,"):
            raise InstrumentErrorReply(self.name, f"error reply {text!r}", code=text.split(",")[-1])
        return text

    def request(self, force_N: float) -> None:
        if not 0 <= force_N <= self.max_force_N:
            raise ValueError(f"{self.name}: target {force_N} N outside 0..{self.max_force_N} N")
        reply = self._query(self.set_force, force=force_N)
        if reply != "OK":
            raise MalformedReply(self.name, f"reply {reply!r} to F{force_N:.2f}")

    def target_N(self) -> float:
        reply = self._query(self.get_force)
        try:
            head, value = reply.split(",")
            assert head == "F"
            return float(value)
        except (ValueError, AssertionError):
            raise MalformedReply(self.name, f"reply {reply!r} to F?") from None

    def safe(self) -> bool:
        self._query(self.stop)  # a moving clamp stops where it is; it never releases the strip
        return True


class OperatorClamp(Instrument):
    """A manual clamp: the operator is asked to set the force (the load cell then confirms it)."""

    name = "clamp"

    def __init__(self, ask: Callable[[str], None] | None = None):
        self._ask = ask or (lambda msg: input(msg))

    def request(self, force_N: float) -> None:
        print(f"\a", end="", file=sys.stderr)
        self._ask(f"Set the clamp to {force_N:.2f} N on the load cell, then press Enter: ")

    def close(self) -> None:
        pass
