"""Every simulated instrument, on loopback, over one simulated bench: what ``labrig sim`` serves and what
``labrig run --sim`` starts in-process. Returns the instruments' addresses in the rig-file layout.

Which instruments: every stand-in registered by its simulator's own module (``mock_devices.stand_ins``).
"""

from __future__ import annotations

from typing import Any

from drivers import analyser_models
from mock_devices.stand_ins import Served, SimOptions, stand_ins
from mock_devices.world import World


class SimulatedInstruments:
    """Start/stop every simulated instrument (laser, load cell, clamp motor, impedance analyser, DAQ...) on
    127.0.0.1. Once started (and after they stop), each simulator is ``sims.<kind>`` (``sims.daq``, ``sims.clamp``...)."""

    def __init__(self, bench: World, serial_transport: str = "tcp", seed: int = 0,
                 impedance_model: str = analyser_models.DEFAULT_MODEL):
        self.bench = bench
        self.transport = serial_transport
        self.impedance_model = analyser_models.get(impedance_model).name
        self.options = SimOptions(serial_transport, seed, impedance_model)
        self.served: dict[str, Served] = {}  # kept after stop(): tests read the simulators' final state
        self._running: list[Served] = []

    def __getattr__(self, kind: str) -> Any:
        served = self.__dict__.get("served", {})
        if kind in served:
            return served[kind].sim
        raise AttributeError(f"{type(self).__name__} has no attribute {kind!r} (no simulator of that kind is running)")

    def start(self) -> "SimulatedInstruments":
        try:
            for kind, stand_in in stand_ins().items():
                self.served[kind] = stand_in(self.bench, self.options)
                self._running.append(self.served[kind])
        except BaseException:
            self.stop()
            raise
        return self

    def stop(self) -> None:
        while self._running:
            self._running.pop().stop()

    def __enter__(self) -> "SimulatedInstruments":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def rig_tables(self) -> dict[str, Any]:
        """The ``[instruments.*]`` tables of a rig file pointing at these simulators."""
        return {kind: dict(served.table) for kind, served in self.served.items()}
