"""The Keyence LK-G RS-232C command set as data, shared by the driver (``drivers.keyence``) and the simulated
controller (``mock_devices.keyence_sim``), so the two cannot drift apart.

Facts from the LK-G communication chapter ("RS-232C command list", "error response"): one ASCII command,
CR-terminated; the reply echoes the command's header (``M1,+01.2345``, ``VR``, ``SW,OF``); a refused
command answers ``ER,<header>,<code>`` (three fields). The controller is in *general mode* after power-up
(measured values, auto-zero, reset, key lock, program change); ``Q0`` switches to *communication mode*
(setting reads and writes ``SR`` / ``SW``), ``R0`` back. A command sent in the wrong mode is error 01.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

GENERAL, COMMUNICATION = "general", "communication"
BOTH = frozenset({GENERAL, COMMUNICATION})

# error codes of the LK-G manual's error response (ER,<command>,<code>)
ERROR_CODES = {
    0: "command error",  # unknown command
    1: "status error",  # command not allowed in the present mode
    20: "command length error",
    21: "parameter count error",
    22: "parameter range error",
    88: "timeout error",
    99: "other error",
}


@dataclass(frozen=True)
class LkCommand:
    """One command: its header (what replies and errors echo), its request pattern and the modes it runs in."""

    header: str
    pattern: re.Pattern[str]
    modes: frozenset[str]
    doc: str


def _cmd(header: str, pattern: str, modes: frozenset[str], doc: str) -> LkCommand:
    return LkCommand(header, re.compile(pattern), modes, doc)


# the commands published LK-G clients send (EPICS LK-G IOC, LabVIEW/C++ LK-G5000 clients)
LKG_COMMANDS: tuple[LkCommand, ...] = (
    _cmd("M", r"M([0-2])", frozenset({GENERAL}), "measured value: M1/M2 one output, M0 both"),
    _cmd("V", r"V([0-2])", frozenset({GENERAL}), "auto-zero ON for OUT<n> (0 = all)"),
    _cmd("W", r"W([0-2])", frozenset({GENERAL}), "auto-zero OFF for OUT<n> (0 = all)"),
    _cmd("VR", r"VR,([0-2])", frozenset({GENERAL}), "reset: clear the held value of OUT<n> (0 = all)"),
    _cmd("KL", r"KL,([01])", frozenset({GENERAL}), "key lock ON (1) / OFF (0)"),
    _cmd("PW", r"PW,([0-7])", frozenset({GENERAL}), "switch to program 0..7"),
    _cmd("PR", r"PR", frozenset({GENERAL}), "which program is in use"),
    _cmd("Q0", r"Q0", frozenset({GENERAL}), "go to communication mode"),
    _cmd("R0", r"R0", frozenset({COMMUNICATION}), "back to general mode"),
    _cmd("SW", r"SW,([A-Z]{2}),(.*)", frozenset({COMMUNICATION}), "write a setting: SW,<id>,<out>,<value>"),
    _cmd("SR", r"SR,([A-Z]{2}),(.*)", frozenset({COMMUNICATION}), "read a setting: SR,<id>,<out>"),
)


@dataclass(frozen=True)
class LkSetting:
    """A setting reachable with SW/SR: ``SW,<id>,<out>,<value>`` / ``SR,<id>,<out>`` -> ``SR,<id>,<out>,<value>``.

    The written value is an integer (``width`` > 0: signed, zero-padded to that many digits, ``+0001000``);
    the read value is that integer times ``read_scale`` printed with ``read_decimals`` (the offset is written
    in 0.1 um counts and read back in mm, ``+00.1000``, as the EPICS LK-G IOC expects)."""

    id: str
    doc: str
    lo: int
    hi: int
    width: int = 0
    read_scale: float = 1.0
    read_decimals: int = 0


LKG_SETTINGS: dict[str, LkSetting] = {
    "OF": LkSetting("OF", "offset of OUT<out>: written in 0.1 um counts, read in mm", -999999, 999999, 7, 1e-4, 4),
    "HB": LkSetting("HB", "measurement mode (function) of OUT<out>, 0..9", 0, 9),
}


def format_setting(setting: LkSetting, value: int) -> str:
    """The value field of ``SW``."""
    return f"{value:+0{setting.width + 1}d}" if setting.width else str(value)


def format_reading(setting: LkSetting, value: int) -> str:
    """The value field of the reply to ``SR``."""
    if not setting.read_decimals:
        return str(value)
    return f"{value * setting.read_scale:+0{setting.read_decimals + 4}.{setting.read_decimals}f}"


def find(request: str, commands: tuple[LkCommand, ...] = LKG_COMMANDS) -> tuple[LkCommand, re.Match[str]] | None:
    """The command a request line is, with its match, or None."""
    for cmd in commands:
        if m := cmd.pattern.fullmatch(request):
            return cmd, m
    return None


def header_of(request: str) -> str:
    """What the reply to ``request`` echoes: ``M1`` for M1, ``VR`` for ``VR,1``, ``SW`` for ``SW,OF,1,...``."""
    return request.split(",", 1)[0]
