"""Every simulated instrument, on loopback, over one simulated bench: what ``labrig sim`` serves and what
``labrig run --sim`` starts in-process. Returns the instruments' addresses in the rig-file layout."""

from __future__ import annotations

from typing import Any

from mock_devices.clamp_sim import ClampSim
from mock_devices.daq_grpc import SimDaq
from drivers import analyser_models
from mock_devices.im3590_sim import Im3590Sim
from mock_devices.impedance_sim import ImpedanceAnalyzerSim
from mock_devices.keyence_sim import KeyenceSim
from mock_devices.loadcell_sim import LoadCellSim
from mock_devices.serial_server import serve
from mock_devices.world import Bench

# The bench's analog scaling: 10 mA/V current amplifier, laser analog 2 mm/V (+-20 mm on +-10 V).
CURRENT_GAIN_A_PER_V = 1e-2
DISPLACEMENT_M_PER_V = 2e-3


class SimulatedInstruments:
    """Start/stop the simulated laser, load cell, clamp motor, impedance analyser and DAQ on 127.0.0.1."""

    def __init__(self, bench: Bench, serial_transport: str = "tcp", seed: int = 0,
                 impedance_model: str = analyser_models.DEFAULT_MODEL):
        self.bench = bench
        self.transport = serial_transport
        self.keyence = KeyenceSim(bench, range_mm=20.0, seed=seed)
        self.loadcell = LoadCellSim(bench, seed=seed + 1)
        self.clamp = ClampSim(bench, seed=seed + 2)
        self.impedance_model = analyser_models.get(impedance_model).name
        self.impedance = Im3590Sim(bench) if impedance_model == "IM3590" else ImpedanceAnalyzerSim(bench, model=impedance_model)
        self.daq = SimDaq(bench, current_gain_A_per_V=CURRENT_GAIN_A_PER_V, displacement_m_per_V=DISPLACEMENT_M_PER_V, seed=seed + 3)
        self._servers: list[Any] = []

    def start(self) -> "SimulatedInstruments":
        for dev in (self.keyence, self.loadcell, self.clamp):
            self._servers.append(serve(dev, self.transport))
        self.impedance.start()
        self.daq.start()
        return self

    def stop(self) -> None:
        for srv in self._servers:
            srv.stop()
        self._servers.clear()
        self.impedance.stop()
        self.daq.stop()

    def __enter__(self) -> "SimulatedInstruments":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def rig_tables(self) -> dict[str, Any]:
        """The ``[instruments.*]`` tables of a rig file pointing at these simulators."""
        keyence, loadcell, clamp = (s.address for s in self._servers)
        return {
            "keyence": {"address": keyence, "dialect": "LK-G"},
            "loadcell": {"address": loadcell},
            "clamp": {"mode": "motor", "address": clamp},
            "impedance": {"address": self.impedance.resource_name, "model": self.impedance_model},
            "daq": {
                "address": self.daq.address,
                "device": self.daq.device.name,
                "drive_channel": "ao0",
                "voltage_channel": "ai0",
                "current_channel": "ai1",
                "displacement_channel": "ai2",
                "current_gain_A_per_V": CURRENT_GAIN_A_PER_V,
                "displacement_m_per_V": DISPLACEMENT_M_PER_V,
            },
        }
