"""A fresh simulated bench in this process: the world, every simulated instrument on loopback, and a rig
of real drivers connected to them over their real transports (what ``labrig run --sim`` uses)."""

from __future__ import annotations

import time
from contextlib import contextmanager
from typing import Iterator

from drivers.transcript import Transcript
from labrig.clock import ScaledClock
from labrig.rig import Rig, kinds, open_rig, parse_rig
from mock_devices.simbench import SimulatedInstruments
from mock_devices.world import World, Effect

from labrig.clock import SIM_TIME_SCALE as DEFAULT_TIME_SCALE


def rig_file_data(sims: SimulatedInstruments, clock: ScaledClock, preset: str, safety: dict | None = None) -> dict:
    """The rig file of the simulated bench: its clock, its preset and the simulators' tables (in ``kinds()`` order;
    a simulator of a kind labrig does not know keeps its table, which the rig file's check then names)."""
    tables = sims.rig_tables()
    data = {
        "clock": {"time_scale": clock.time_scale, "epoch_wall": clock.epoch_wall},
        "sample": {"preset": preset},
        "instruments": {**{k: tables.pop(k) for k in kinds() if k in tables}, **tables},
    }
    if safety:
        data["safety"] = dict(safety)
    return data


@contextmanager
def simulated_rig(
    preset: str = "paper",
    seed: int = 0,
    effects: list[Effect] | None = None,
    time_scale: float = DEFAULT_TIME_SCALE,
    transcript: Transcript | None = None,
    serial_transport: str = "tcp",
    safety: dict | None = None,
) -> Iterator[tuple[Rig, SimulatedInstruments]]:
    clock = ScaledClock(time_scale, time.time())
    bench = World(clock, preset=preset, seed=seed, effects=effects)
    sims = SimulatedInstruments(bench, serial_transport=serial_transport, seed=seed).start()
    try:
        cfg = parse_rig(rig_file_data(sims, clock, preset, safety), "simulated bench")
        rig = open_rig(cfg, clock, transcript)
        try:
            yield rig, sims
        finally:
            rig.close()
    finally:
        sims.stop()
