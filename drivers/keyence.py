"""Keyence LK laser displacement sensor: RS-232C ASCII, one CR-terminated command, one CR-terminated reply.

``M1\\r`` → ``M1,+01.2345\\r`` (mm, sign always present, 7 characters with the decimal point);
``M0\\r`` → ``M0,+01.2345,-00.1234\\r`` (OUT1, OUT2). Errors come back as ``ER,<cmd>,<code>\\r``.
Modes (``Q0`` communication, ``R0`` general), reset ``VR``, key lock ``KL``, program ``PW``/``PR`` and the
setting reads and writes ``SR``/``SW``: the command table is ``drivers.keyence_dialect``, which the
simulator uses too.
Over-range reads ``+FFFFFFF`` / ``-FFFFFFF`` and an invalid reading ``XXXXXXXX``: never numbers.

The dialect table is the set of ``Command`` class attributes: ``KeyenceLKG`` (LK-G, from the LK-G
communication manual) and ``KeyenceLK2000`` (same wire format assumed, unconfirmed; see
docs/instruments_serial.md). Values leave this module in metres.
"""

from __future__ import annotations

import re
from typing import Any

from drivers.errors import InstrumentErrorReply, InstrumentTimeout, InvalidReading, MalformedReply, OverRange
from drivers.keyence_dialect import ERROR_CODES, LKG_SETTINGS, format_setting, header_of
from drivers.serial_port import Command, SerialInstrument, SerialLike, io_errors

CR = b"\r"
MM = 1e-3  # metres per millimetre
MAX_REPLY = 64  # the longest real reply (M0) is 21 bytes

_OVER = re.compile(r"[+-]F{7}")
_INVALID = "XXXXXXXX"


def parse_value_mm(field: str, device: str = "keyence") -> float:
    """One measured-value field in mm; raises ``OverRange``/``InvalidReading``/``MalformedReply``."""
    if _OVER.fullmatch(field):
        raise OverRange(device, f"reading {field} is beyond the measuring range")
    if field == _INVALID:
        raise InvalidReading(device, f"reading {field}: no valid target (too dark, too bright or not settled)")
    body = field[1:]
    if len(field) != 8 or field[0] not in "+-" or body.count(".") > 1 or not body.replace(".", "").isdigit():
        raise MalformedReply(device, f"measured value {field!r} does not parse")
    return float(field)


def analog_to_displacement(volts: Any, m_per_V: float, offset_m: float = 0.0) -> Any:
    """Displacement (m) from the controller's analog output read on the DAQ.

    ``m_per_V`` is the analog scaling (e.g. 1 mm/V → 1e-3) and ``offset_m`` the displacement at
    0 V; works for a float or a numpy array of volts. Over-range is not visible on this route:
    the output sits at its rail, so callers should flag samples at the rail themselves.
    """
    return volts * m_per_V + offset_m


class KeyenceLKG(SerialInstrument):
    """Keyence LK-G controller (LK-G3001 & co.).

    ``KeyenceLKG(port, *, name="keyence", transcript=None, timeout_s=0.5, baudrate=9600)``; ``port`` is
    a pyserial URL, a device path or an open port object (e.g. ``ReplaySerial``).
    """

    dialect = "LK-G"
    default_name = "keyence"
    OUTPUTS = (0, 1, 2)  # 0 = all outputs in one reply

    measure = Command("M{out}", "Measured value of OUT<out>; 0 returns OUT1 and OUT2.", out=OUTPUTS)
    autozero_on = Command("V{out}", "Auto-zero ON: the present value of OUT<out> becomes zero.", out=OUTPUTS)
    autozero_off = Command("W{out}", "Auto-zero OFF: OUT<out> reads absolute again.", out=OUTPUTS)
    reset_cmd = Command("VR,{out}", "Reset: clear the held value of OUT<out> (general mode).", out=OUTPUTS)
    key_lock = Command("KL,{on}", "Key lock ON (1) / OFF (0).", on=(0, 1))
    program_write = Command("PW,{n}", "Switch to program n (0..7).", n=tuple(range(8)))
    program_read = Command("PR", "The program in use.")
    to_communication = Command("Q0", "Communication mode: settings can be read and written, no measuring.")
    to_general = Command("R0", "Back to general mode (measuring).")
    setting_write = Command("SW,{id},{out},{value}", "Write setting <id> of OUT<out> (communication mode).",
                            id=tuple(LKG_SETTINGS), out=(1, 2))
    setting_read = Command("SR,{id},{out}", "Read setting <id> of OUT<out> (communication mode).",
                           id=tuple(LKG_SETTINGS), out=(1, 2))

    def query(self, request: bytes) -> list[str]:
        """Send one command, return the reply's fields after the echoed header."""
        with io_errors(self.name):
            self.port.reset_input_buffer()  # a late reply to an earlier timeout must not answer this one
        self._write(request + CR)
        raw = self._read_until(CR, MAX_REPLY)
        cmd = request.decode("ascii")
        if len(raw) >= MAX_REPLY and not raw.endswith(CR):
            raise MalformedReply(self.name, f"{MAX_REPLY} bytes without CR in reply to {cmd}: {raw[:24]!r}...")
        if not raw.endswith(CR):
            what = "no reply" if not raw else f"incomplete reply {raw!r}"
            raise InstrumentTimeout(self.name, f"{what} to {cmd} within {self.timeout_s} s")
        try:
            fields = raw[:-1].decode("ascii").split(",")
        except UnicodeDecodeError:
            raise MalformedReply(self.name, f"reply {raw!r} to {cmd} is not ASCII") from None
        if fields[0] == "ER":
            code_text = fields[2] if len(fields) == 3 else ""
            code = int(code_text) if code_text.isdigit() else code_text
            meaning = ERROR_CODES.get(code, "unknown code") if isinstance(code, int) else "unreadable code"
            raise InstrumentErrorReply(self.name, f"{cmd} answered {raw[:-1].decode()} ({meaning})", code=code)
        if fields[0].upper() != header_of(cmd).upper():
            raise MalformedReply(self.name, f"reply {raw!r} does not echo {header_of(cmd)}")
        return fields[1:]

    def _command(self, cmd: Command, **kwargs: object) -> list[str]:
        return self.query(cmd.request(**kwargs))

    def _no_data(self, cmd: Command, fields: list[str], expect: list[str] | None = None) -> None:
        if fields != (expect or []):
            raise MalformedReply(self.name, f"unexpected reply fields {fields} to {cmd.name}")

    def read_displacement(self, out: int = 1) -> float:
        """Displacement (m) of output ``out`` (1 or 2)."""
        if out not in (1, 2):
            raise ValueError("out must be 1 or 2; use read_displacements() for both")
        fields = self.query(self.measure.request(out=out))
        if len(fields) != 1:
            raise MalformedReply(self.name, f"M{out} returned {len(fields)} values, expected 1")
        return parse_value_mm(fields[0], self.name) * MM

    def read_displacements(self) -> tuple[float, float]:
        """Displacements (m) of OUT1 and OUT2 from one ``M0`` exchange."""
        fields = self.query(self.measure.request(out=0))
        if len(fields) != 2:
            raise MalformedReply(self.name, f"M0 returned {len(fields)} values, expected 2")
        return parse_value_mm(fields[0], self.name) * MM, parse_value_mm(fields[1], self.name) * MM

    def auto_zero(self, on: bool = True, out: int = 1) -> None:
        """Auto-zero ON (the present reading becomes zero) or OFF for ``out`` (0 = all)."""
        cmd = self.autozero_on if on else self.autozero_off
        fields = self.query(cmd.request(out=out))
        if fields:
            raise MalformedReply(self.name, f"unexpected data {fields} after {cmd.name}")

    def communication_mode(self) -> None:
        """``Q0``: settings can be read and written; measuring answers ER,..,01 until ``general_mode()``."""
        self._no_data(self.to_communication, self._command(self.to_communication))

    def general_mode(self) -> None:
        """``R0``: back to measuring."""
        self._no_data(self.to_general, self._command(self.to_general))

    def reset(self, out: int = 0) -> None:
        """``VR``: clear the held value of ``out`` (0 = all)."""
        self._no_data(self.reset_cmd, self._command(self.reset_cmd, out=out))

    def lock_keys(self, on: bool = True) -> None:
        """``KL``: lock (or unlock) the controller's keys."""
        self._no_data(self.key_lock, self._command(self.key_lock, on=int(on)))

    def set_program(self, n: int) -> None:
        """``PW``: switch to program ``n`` (0..7)."""
        self._no_data(self.program_write, self._command(self.program_write, n=n))

    def program(self) -> int:
        """``PR``: the program in use."""
        fields = self._command(self.program_read)
        if len(fields) != 1 or not fields[0].isdigit():
            raise MalformedReply(self.name, f"PR answered {fields}")
        return int(fields[0])

    def write_setting(self, setting: str, out: int, value: int) -> None:
        """``SW,<setting>,<out>,<value>`` in communication mode (``communication_mode()`` first)."""
        text = format_setting(LKG_SETTINGS[setting], value)
        self._no_data(self.setting_write, self._command(self.setting_write, id=setting, out=out, value=text), [setting])

    def read_setting(self, setting: str, out: int) -> float:
        """``SR,<setting>,<out>`` -> the value as the controller shows it (the offset in mm; communication mode)."""
        fields = self._command(self.setting_read, id=setting, out=out)
        if len(fields) != 3 or fields[:2] != [setting, str(out)]:
            raise MalformedReply(self.name, f"SR,{setting},{out} answered {fields}")
        try:
            return float(fields[2])
        except ValueError:
            raise MalformedReply(self.name, f"SR,{setting},{out} value {fields[2]!r} is not a number") from None

    # A displacement sensor drives nothing: closing the port is its safe state.


class KeyenceLK2000(KeyenceLKG):
    """Keyence LK-2000 series controller (LK-2001/2011, with the paper's LK-031 head).

    Same wire format as LK-G assumed; every command is marked unconfirmed until checked against
    the LK-2000 manual or a real unit (see docs/instruments_serial.md).
    """

    dialect = "LK-2000"
    measure = Command("M{out}", "Measured value of OUT<out> (unconfirmed on LK-2000).", confirmed=False, out=(0, 1, 2))
    autozero_on = Command("V{out}", "Auto-zero ON (unconfirmed on LK-2000).", confirmed=False, out=(0, 1, 2))
    autozero_off = Command("W{out}", "Auto-zero OFF (unconfirmed on LK-2000).", confirmed=False, out=(0, 1, 2))
    # the LK-G communication-chapter commands, same bytes assumed: none checked against an LK-2000 manual
    reset_cmd = Command("VR,{out}", "Reset (unconfirmed on LK-2000).", confirmed=False, out=(0, 1, 2))
    key_lock = Command("KL,{on}", "Key lock (unconfirmed on LK-2000).", confirmed=False, on=(0, 1))
    program_write = Command("PW,{n}", "Program change (unconfirmed on LK-2000).", confirmed=False, n=tuple(range(8)))
    program_read = Command("PR", "Program check (unconfirmed on LK-2000).", confirmed=False)
    to_communication = Command("Q0", "Communication mode (unconfirmed on LK-2000).", confirmed=False)
    to_general = Command("R0", "General mode (unconfirmed on LK-2000).", confirmed=False)


DIALECTS: dict[str, type[KeyenceLKG]] = {"LK-G": KeyenceLKG, "LK-2000": KeyenceLK2000}


def open_keyence(port: str | SerialLike, dialect: str = "LK-G", **kwargs: Any) -> KeyenceLKG:
    """The driver for ``dialect`` (``"LK-G"`` or ``"LK-2000"``) on ``port``."""
    try:
        cls = DIALECTS[dialect]
    except KeyError:
        raise ValueError(f"unknown Keyence dialect {dialect!r}; known: {sorted(DIALECTS)}") from None
    return cls(port, **kwargs)


Keyence = KeyenceLKG  # the default dialect
