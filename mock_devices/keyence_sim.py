"""Simulated Keyence LK controller with an LK-031 head: the real RS-232C bytes, readings from the bench.

The head measures ±5 mm around its 30 mm reference distance; the controller reports the
displacement from the reference in mm with 0.1 µm resolution (``+01.2345``), ``±FFFFFFF`` beyond
the range. Both outputs show the one head. The command set is the table of ``drivers.keyence_dialect``
(the LK-G communication chapter): ``M0``/``M1``/``M2`` measure, ``V<out>``/``W<out>`` auto-zero on/off,
``VR,<out>`` reset, ``KL,<0|1>`` key lock, ``PW,<n>``/``PR`` program, ``Q0``/``R0`` communication/general
mode, ``SW``/``SR`` setting writes and reads (offset ``OF`` in 0.1 um counts, which the measured value
subtracts; function ``HB``). Refusals are ``ER,<header>,<code>`` with the manual's codes: 00 unknown
command, 01 wrong mode (a mode change to the mode already in use is refused too), 21 parameter count,
22 parameter range.

Faults (``inject``): ``disconnect``, ``timeout``, ``garbage``, ``error`` (``ER,<cmd>,99``, "other error"),
``overrange`` (``+FFFFFFF``), ``invalid`` (``XXXXXXXX``).

Regenerate the recorded traffic the tests replay::

    python -m mock_devices.keyence_sim --record tests/data/transcripts/keyence_basic.jsonl
"""

from __future__ import annotations

from typing import Callable

from drivers.keyence_dialect import COMMUNICATION, GENERAL, LKG_SETTINGS, find, format_reading, header_of
from mock_devices.world_api import WorldView
from mock_devices.serial_server import COMMON_FAULTS, FixedBench, SimSerialDevice, serve, serve_stand_in, sim_main
from mock_devices.stand_ins import Served, SimOptions, stands_in


class _Refused(Exception):
    def __init__(self, code: int):
        self.code = code


class KeyenceSim(SimSerialDevice):
    """Protocol layer of the LK controller over ``bench.displacement_now()`` (m, + towards the head)."""

    FAULTS = COMMON_FAULTS | {"error", "overrange", "invalid"}

    def __init__(self, bench: WorldView, *, range_mm: float = 5.0, resolution_mm: float = 1e-4, seed: int = 0):
        super().__init__(seed)
        self.bench = bench
        self.range_mm = range_mm
        self.resolution_mm = resolution_mm
        self.zero_mm = {1: 0.0, 2: 0.0}  # auto-zero offsets per output
        self.mode = GENERAL
        self.keys_locked, self.program = False, 0
        self.settings: dict[tuple[str, int], int] = {(sid, out): 0 for sid in LKG_SETTINGS for out in (1, 2)}
        self._handlers: dict[str, Callable[[str, tuple[str, ...]], str]] = {
            "M": self._measure, "V": self._zero, "W": self._zero, "VR": self._reset, "KL": self._key_lock,
            "PW": self._program_write, "PR": lambda h, g: f"PR,{self.program}", "Q0": self._mode,
            "R0": self._mode, "SW": self._setting_write, "SR": self._setting_read,
        }

    def _raw_mm(self) -> float:
        return self.bench.displacement_now() * 1e3

    def value_field(self, out: int) -> str:
        """The 8-character measured-value field of output ``out`` as the controller prints it."""
        if self.fault == "invalid":
            return "XXXXXXXX"
        raw = self._raw_mm()
        if self.fault == "overrange" or abs(raw) > self.range_mm:
            return ("-" if raw < 0 else "+") + "FFFFFFF"
        offset_mm = self.settings[("OF", out)] * 1e-4  # OF is in 0.1 um counts
        counts = round((raw - self.zero_mm[out] - offset_mm) / self.resolution_mm)
        sign = "-" if counts < 0 else "+"
        return f"{sign}{abs(counts) * self.resolution_mm:07.4f}"

    def respond(self, line: bytes) -> bytes:
        request = line.decode("ascii", errors="replace").strip().upper()
        header = header_of(request)[:8]
        if self.fault == "error":
            return f"ER,{header},99\r".encode()
        found = find(request)
        if found is None:
            return f"ER,{header},{self._unknown_code(request)}\r".encode()
        cmd, m = found
        if self.mode not in cmd.modes:
            return f"ER,{header},01\r".encode()
        try:
            return (self._handlers[cmd.header](request, m.groups()) + "\r").encode()
        except _Refused as e:
            return f"ER,{header},{e.code:02d}\r".encode()

    @staticmethod
    def _unknown_code(request: str) -> str:
        """A known header with the wrong parameters is 21 (count) / 22 (range); anything else 00."""
        head, *params = request.split(",")
        known = {"VR": 1, "KL": 1, "PW": 1, "SW": 3, "SR": 2}
        if head in known:
            return "21" if len(params) != known[head] else "22"
        if len(head) == 2 and head[0] in "MVW" and head[1].isdigit():
            return "22"  # M3, V9: output out of range
        return "00"

    def _measure(self, request: str, groups: tuple[str, ...]) -> str:
        out = int(groups[0])
        fields = [self.value_field(1), self.value_field(2)] if out == 0 else [self.value_field(out)]
        return f"{request},{','.join(fields)}"

    def _zero(self, request: str, groups: tuple[str, ...]) -> str:
        outs = (1, 2) if groups[0] == "0" else (int(groups[0]),)
        raw = self._raw_mm()
        for out in outs:
            self.zero_mm[out] = raw if request[0] == "V" else 0.0
        return request

    def _reset(self, request: str, groups: tuple[str, ...]) -> str:
        return "VR"  # no hold function runs on the simulated controller: nothing held to clear

    def _key_lock(self, request: str, groups: tuple[str, ...]) -> str:
        self.keys_locked = groups[0] == "1"
        return "KL"

    def _program_write(self, request: str, groups: tuple[str, ...]) -> str:
        self.program = int(groups[0])
        return "PW"

    def _mode(self, request: str, groups: tuple[str, ...]) -> str:
        self.mode = COMMUNICATION if request == "Q0" else GENERAL
        return request

    def _setting_args(self, groups: tuple[str, ...], count: int) -> tuple[str, int, list[str]]:
        sid, rest = groups
        params = rest.split(",") if rest else []
        if sid not in LKG_SETTINGS:
            raise _Refused(0)
        if len(params) != count:
            raise _Refused(21)
        if params[0] not in ("1", "2"):
            raise _Refused(22)
        return sid, int(params[0]), params[1:]

    def _setting_write(self, request: str, groups: tuple[str, ...]) -> str:
        sid, out, (text,) = self._setting_args(groups, 2)
        spec = LKG_SETTINGS[sid]
        try:
            value = int(text)
        except ValueError:
            raise _Refused(22) from None
        if not spec.lo <= value <= spec.hi:
            raise _Refused(22)
        self.settings[(sid, out)] = value
        return f"SW,{sid}"

    def _setting_read(self, request: str, groups: tuple[str, ...]) -> str:
        sid, out, _ = self._setting_args(groups, 1)
        return f"SR,{sid},{out},{format_reading(LKG_SETTINGS[sid], self.settings[(sid, out)])}"


def record_demo(path: str) -> int:
    """Run the driver against the simulator with a recording transcript; save it to ``path``.

    The bench is a ``FixedBench`` set by hand, so the bytes (and the tests' expected values) are the
    same on every run. Returns the number of exchanges saved.
    """
    from drivers.errors import InstrumentError  # lazy: only the recorder needs the driver
    from drivers.keyence import Keyence
    from drivers.transcript import Transcript

    bench = FixedBench(displacement_m=1.2345e-3)
    sim = KeyenceSim(bench, seed=1)
    tr = Transcript()
    with serve(sim, "tcp") as server, Keyence(server.address, transcript=tr, timeout_s=1.0) as k:
        k.read_displacement(1)  # +01.2345
        bench.displacement_m = -0.5e-3
        k.read_displacement(2)  # -00.5000
        k.read_displacements()
        k.auto_zero(True, 1)
        bench.displacement_m = -0.4e-3
        k.read_displacement(1)  # +00.1000 after the zero
        k.auto_zero(False, 1)
        for fault in ("error", "overrange", "invalid", "garbage"):
            sim.inject(fault)
            try:
                k.read_displacement(1)
            except InstrumentError:
                pass
            sim.clear_fault()
        bench.displacement_m = 6e-3  # beyond the LK-031's ±5 mm
        try:
            k.read_displacement(1)
        except InstrumentError:
            pass
    tr.save(path)
    return len(tr)


@stands_in("keyence")
def _stand_in(world: WorldView, opts: SimOptions) -> Served:
    return serve_stand_in(KeyenceSim(world, range_mm=20.0, seed=opts.seed), opts, dialect="LK-G")


def main(argv: list[str] | None = None) -> int:
    return sim_main(
        argv,
        prog="python -m mock_devices.keyence_sim",
        doc=__doc__ or "",
        record=record_demo,
        make_device=lambda value: KeyenceSim(FixedBench(displacement_m=value * 1e-3)),
        value_flag="--displacement-mm",
        default_value=1.0,
    )


if __name__ == "__main__":
    raise SystemExit(main())
