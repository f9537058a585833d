"""Simulated Keyence LK controller with an LK-031 head: the real RS-232C bytes, readings from the bench.

The head measures ±5 mm around its 30 mm reference distance; the controller reports the
displacement from the reference in mm with 0.1 µm resolution (``+01.2345``), ``±FFFFFFF`` beyond
the range. Both outputs show the one head. Commands: ``M0``/``M1``/``M2`` measure, ``V<out>``
auto-zero on, ``W<out>`` auto-zero off; anything else is ``ER,<cmd>,00``.

Faults (``inject``): ``disconnect``, ``timeout``, ``garbage``, ``error`` (``ER,<cmd>,02``),
``overrange`` (``+FFFFFFF``), ``invalid`` (``XXXXXXXX``).

Regenerate the recorded traffic the tests replay::

    python -m mock_devices.keyence_sim --record tests/data/transcripts/keyence_basic.jsonl
"""

from __future__ import annotations

import re

from mock_devices.bench_api import BenchView
from mock_devices.serial_server import COMMON_FAULTS, FixedBench, SimDevice, serve, sim_main

_MEASURE = re.compile(r"M([0-2])")
_ZERO = re.compile(r"([VW])([0-2])")


class KeyenceSim(SimDevice):
    """Protocol layer of the LK controller over ``bench.displacement_now()`` (m, + towards the head)."""

    FAULTS = COMMON_FAULTS | {"error", "overrange", "invalid"}

    def __init__(self, bench: BenchView, *, range_mm: float = 5.0, resolution_mm: float = 1e-4, seed: int = 0):
        super().__init__(seed)
        self.bench = bench
        self.range_mm = range_mm
        self.resolution_mm = resolution_mm
        self.zero_mm = {1: 0.0, 2: 0.0}  # auto-zero offsets per output

    def _raw_mm(self) -> float:
        return self.bench.displacement_now() * 1e3

    def value_field(self, out: int) -> str:
        """The 8-character measured-value field of output ``out`` as the controller prints it."""
        if self.fault == "invalid":
            return "XXXXXXXX"
        raw = self._raw_mm()
        if self.fault == "overrange" or abs(raw) > self.range_mm:
            return ("-" if raw < 0 else "+") + "FFFFFFF"
        counts = round((raw - self.zero_mm[out]) / self.resolution_mm)
        sign = "-" if counts < 0 else "+"
        return f"{sign}{abs(counts) * self.resolution_mm:07.4f}"

    def respond(self, line: bytes) -> bytes:
        cmd = line.decode("ascii", errors="replace").strip().upper()
        if self.fault == "error":
            return f"ER,{cmd},02\r".encode()
        if m := _MEASURE.fullmatch(cmd):
            out = int(m.group(1))
            fields = [self.value_field(1), self.value_field(2)] if out == 0 else [self.value_field(out)]
            return f"{cmd},{','.join(fields)}\r".encode()
        if m := _ZERO.fullmatch(cmd):
            outs = (1, 2) if m.group(2) == "0" else (int(m.group(2)),)
            raw = self._raw_mm()
            for out in outs:
                self.zero_mm[out] = raw if m.group(1) == "V" else 0.0
            return f"{cmd}\r".encode()
        return f"ER,{cmd[:8]},00\r".encode()


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
