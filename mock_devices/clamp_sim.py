"""Simulated motorised clamp: the ASCII protocol of drivers/clamp.py, moving the bench's clamp."""

from __future__ import annotations

from mock_devices.world_api import WorldView
from mock_devices.serial_server import SimSerialDevice, serve_stand_in
from mock_devices.stand_ins import Served, SimOptions, stands_in


class ClampSim(SimSerialDevice):
    def __init__(self, bench: WorldView, seed: int = 0, max_force_N: float = 98.0):
        super().__init__(seed)
        self.bench = bench
        self.max_force_N = max_force_N
        self.target_N = bench.clamp_force_now()

    def respond(self, line: bytes) -> bytes:
        text = line.decode("ascii", errors="replace").strip()
        if self.fault == "error":
            return f"ER,{text[:2]},02\r".encode()
        if text == "F?":
            return f"F,{self.target_N:+08.2f}\r".encode()
        if text == "S":
            self.bench.set_clamp_force(self.bench.clamp_force_now())
            return b"OK\r"
        if text.startswith("F"):
            try:
                f = float(text[1:])
            except ValueError:
                return b"ER,F,01\r"
            if not 0 <= f <= self.max_force_N:
                return b"ER,F,03\r"
            self.target_N = f
            self.bench.set_clamp_force(f)
            return b"OK\r"
        return f"ER,{text[:2]},01\r".encode()


@stands_in("clamp")
def _stand_in(world: WorldView, opts: SimOptions) -> Served:
    return serve_stand_in(ClampSim(world, seed=opts.seed + 2), opts, mode="motor")
