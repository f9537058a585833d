"""Class-level SCPI property declarations and reply parsing, in the spirit of PyMeasure's
``Instrument.control`` / ``Instrument.measurement``.

A host class provides ``device`` (its name for error messages), ``_ask(cmd) -> str``, ``_send(cmd)`` and
``check_errors()``. Then::

    class Analyser:
        ac_V = control(":SOUR1:VOLT?", ":SOUR1:VOLT {}", "AC amplitude (V)")

reads with a query and writes with a command followed by an error-queue check, so a rejected value
raises ``InstrumentErrorReply`` at the assignment that caused it.
"""

from __future__ import annotations

import re
from typing import Any, Callable, Protocol

import numpy as np

from drivers.errors import InstrumentErrorReply, MalformedReply, OverRange

# SCPI's "infinity", which instruments send for an overloaded reading; 9.91E37 is NaN.
OVERLOAD_THRESHOLD = 9.9e37

_ERROR_REPLY = re.compile(r'^\s*([+-]?\d+)\s*,\s*"(.*)"\s*$', re.S)


class ScpiHost(Protocol):
    device: str

    def _ask(self, cmd: str) -> str: ...

    def _send(self, cmd: str) -> None: ...

    def check_errors(self) -> None: ...


def fmt(value: float) -> str:
    """A number as SCPI text: enough digits for a frequency, no locale, no numpy repr."""
    return f"{float(value):.12G}"


def parse_floats(device: str, cmd: str, reply: str) -> np.ndarray:
    """Comma-separated numbers; junk is ``MalformedReply``, an overload value is ``OverRange``."""
    text = reply.strip()
    try:
        values = np.array([float(x) for x in text.split(",")], dtype=float) if text else np.zeros(0)
    except ValueError:
        raise MalformedReply(device, f"{cmd} answered {text[:60]!r}, not numbers") from None
    if not np.all(np.isfinite(values)):
        raise MalformedReply(device, f"{cmd} answered a non-finite number")
    over = np.abs(values) >= OVERLOAD_THRESHOLD
    if over.any():
        raise OverRange(device, f"{cmd}: {int(over.sum())} of {values.size} values flagged overload (9.9E37)")
    return values


def parse_float(device: str, cmd: str, reply: str) -> float:
    """Exactly one number."""
    values = parse_floats(device, cmd, reply)
    if values.size != 1:
        raise MalformedReply(device, f"{cmd} answered {values.size} values, expected 1")
    return float(values[0])


def parse_error(device: str, reply: str) -> tuple[int, str]:
    """``-113,"Undefined header"`` -> (-113, "Undefined header")."""
    m = _ERROR_REPLY.match(reply)
    if m is None:
        raise MalformedReply(device, f"SYST:ERR? answered {reply.strip()[:60]!r}")
    return int(m.group(1)), m.group(2)


def raise_for_errors(device: str, errors: list[tuple[int, str]]) -> None:
    """One ``InstrumentErrorReply`` carrying the first code and every message."""
    if errors:
        text = "; ".join(f'{c:+d},"{m}"' for c, m in errors)
        raise InstrumentErrorReply(device, f"instrument reported {text}", code=errors[0][0])


def on_off(reply: str) -> bool:
    """Boolean reply: 1/0 or ON/OFF."""
    word = reply.strip().upper()
    if word in ("1", "ON", "+1"):
        return True
    if word in ("0", "OFF", "+0"):
        return False
    raise ValueError(word)


class measurement:
    """Read-only SCPI property: ``get_cmd`` parsed with ``cast`` (junk is ``MalformedReply``)."""

    def __init__(self, get_cmd: str, doc: str = "", cast: Callable[[str], Any] | None = None):
        self.get_cmd, self.cast, self.__doc__ = get_cmd, cast, doc
        self.name = ""

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    def __get__(self, obj: ScpiHost | None, owner: type | None = None) -> Any:
        if obj is None:
            return self
        reply = obj._ask(self.get_cmd)
        if self.cast is None:
            return parse_float(obj.device, self.get_cmd, reply)
        try:
            return self.cast(reply.strip())
        except ValueError:
            raise MalformedReply(obj.device, f"{self.get_cmd} answered {reply.strip()[:60]!r}") from None


class control(measurement):
    """Read/write SCPI property: set writes ``set_cmd.format(text)`` then checks the error queue.

    ``values`` maps Python values to their SCPI words (e.g. ``{True: "ON", False: "OFF"}``); numbers
    without a mapping are written with ``fmt``.
    """

    def __init__(self, get_cmd: str, set_cmd: str, doc: str = "", cast: Callable[[str], Any] | None = None,
                 values: dict[Any, str] | None = None):
        super().__init__(get_cmd, doc, cast)
        self.set_cmd, self.values = set_cmd, values

    def __set__(self, obj: ScpiHost, value: Any) -> None:
        if self.values is not None:
            if value not in self.values:
                raise ValueError(f"{self.name}: {value!r} is not one of {sorted(map(str, self.values))}")
            text = self.values[value]
        else:
            text = fmt(value)
        obj._send(self.set_cmd.format(text))
        obj.check_errors()
