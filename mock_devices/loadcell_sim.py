"""Simulated load-cell indicator (Dacell UMMA-K10, 98 N): a continuous stream of frames from the clamp.

Frames in A&D's stream format (AD-4329 format 1), ``ST,GS,+0000.50kg\\r\\n``, computed from
``bench.clamp_force_now()``: status ``US`` while the force moved by more than ``stable_band_N`` since the
previous frame, ``ST`` otherwise; above 98 N the out-of-range frame ``OL,GS,     .  kg`` (the data
field's digits and sign replaced by spaces, the decimal point kept). Rate: ``frames_per_s`` of simulated time, but never more than ``max_wall_fps`` per wall second
(a 1000x bench must not flood the line). Commands (no reply, like many indicators): ``Z`` zero
(within ±10 % of capacity, else ignored), ``T`` tare (switches to net), ``G`` back to gross.

Faults (``inject``): ``disconnect``, ``timeout`` (stream stops), ``garbage`` (only noise),
``overrange`` (``OL`` frames), ``noise`` (valid frames with noise bursts between them).

Regenerate the recorded traffic the tests replay::

    python -m mock_devices.loadcell_sim --record tests/data/transcripts/loadcell_basic.jsonl
"""

from __future__ import annotations


from mock_devices.world_api import WorldView
from mock_devices.serial_server import COMMON_FAULTS, FixedBench, SimSerialDevice, serve, serve_stand_in, sim_main
from mock_devices.stand_ins import Served, SimOptions, stands_in

G_N = 9.80665  # N per kgf


class LoadCellSim(SimSerialDevice):
    """Protocol layer of the indicator over ``bench.clamp_force_now()`` (N)."""

    FAULTS = COMMON_FAULTS | {"overrange", "noise"}
    capacity_N = 98.0
    zero_range_N = 9.8  # ±10 % of capacity

    def __init__(
        self,
        bench: WorldView,
        *,
        frames_per_s: float = 20.0,
        max_wall_fps: float = 200.0,
        unit: str = "kg",
        stable_band_N: float = 0.02,
        seed: int = 0,
    ):
        super().__init__(seed)
        if unit not in ("kg", "N"):
            raise ValueError("unit must be 'kg' or 'N'")
        self.bench, self.unit, self.stable_band_N = bench, unit, stable_band_N
        scale = float(getattr(bench.clock, "time_scale", 1.0))
        self.stream_interval_s = max(1.0 / (frames_per_s * scale), 1.0 / max_wall_fps)
        self.zero_offset_N = 0.0
        self.tare_N: float | None = None  # None = gross display
        self._prev_N: float | None = None
        self._count = 0

    def gross_N(self) -> float:
        return self.bench.clamp_force_now() - self.zero_offset_N

    def frame(self) -> bytes:
        force = self.bench.clamp_force_now()
        stable = self._prev_N is not None and abs(force - self._prev_N) <= self.stable_band_N
        self._prev_N = force
        status = "OL" if self.fault == "overrange" or force > self.capacity_N else ("ST" if stable else "US")
        shown = force - self.zero_offset_N - (self.tare_N or 0.0)
        value = shown / G_N if self.unit == "kg" else shown
        text = "     .  " if status == "OL" else f"{'-' if round(value, 2) < 0 else '+'}{abs(value):07.2f}"
        unit = self.unit if len(self.unit) == 2 else " " + self.unit  # A&D's 2-figure unit field: " N"
        line = f"{status},{'GS' if self.tare_N is None else 'NT'},{text}{unit}\r\n".encode()
        self._count += 1
        if self.fault == "noise" and self._count % 2 == 0:
            line += self.noise(self._rng.randrange(3, 12))  # corrupts the next frame's line only
        return line

    def garbage(self) -> bytes:
        tail = b"\r\n" if self._rng.random() < 0.5 else b""
        return self.noise(self._rng.randrange(4, 24)) + tail

    def respond(self, line: bytes) -> bytes:
        cmd = line.strip().upper()
        if cmd == b"Z" and abs(self.gross_N()) <= self.zero_range_N:
            self.zero_offset_N += self.gross_N()
            self.tare_N = None
        elif cmd == b"T":
            self.tare_N = self.gross_N()
        elif cmd == b"G":
            self.tare_N = None
        return b""  # the indicator does not answer; the stream shows the effect


def record_demo(path: str) -> int:
    """Run the driver against the simulator (fixed bench, 1x) with a recording transcript; save it."""
    from drivers.loadcell import LoadCell  # lazy: only the recorder needs the driver
    from drivers.transcript import Transcript

    bench = FixedBench(force_N=0.5 * G_N)
    sim = LoadCellSim(bench, frames_per_s=40.0, seed=1)
    tr = Transcript()
    with serve(sim, "tcp") as server, LoadCell(server.address, transcript=tr, stale_s=1.0) as lc:
        clock = bench.clock
        lc.wait_stable(0.5 * G_N, 0.05, 0.05, 2.0, clock)
        lc.zero()
        lc.wait_stable(0.0, 0.05, 0.05, 2.0, clock)
        bench.force_N = 1.5 * G_N  # reads 1.00 kgf above the new zero
        lc.wait_stable(1.0 * G_N, 0.05, 0.05, 2.0, clock)
        lc.tare()
        lc.wait_stable(0.0, 0.05, 0.05, 2.0, clock)
    tr.save(path)
    return len(tr)


@stands_in("loadcell")
def _stand_in(world: WorldView, opts: SimOptions) -> Served:
    return serve_stand_in(LoadCellSim(world, seed=opts.seed + 1), opts)


def main(argv: list[str] | None = None) -> int:
    return sim_main(
        argv,
        prog="python -m mock_devices.loadcell_sim",
        doc=__doc__ or "",
        record=record_demo,
        make_device=lambda value: LoadCellSim(FixedBench(force_N=value)),
        value_flag="--force-N",
        default_value=9.8,
    )


if __name__ == "__main__":
    raise SystemExit(main())
