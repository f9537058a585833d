"""The rig: the instruments of one bench (from a rig file), its clock and its safety limits.

Rig file (TOML), as ``labrig sim --rig-out`` writes it::

    [clock]            time_scale = 1000.0, epoch_wall = <unix time>   (simulated benches only)
    [sample]           preset = "paper"                                (the strip's geometry and medium)
    [safety]           max_drive_V, max_current_A, max_force_N
    [instruments.keyence]   address (pyserial URL or device path), dialect
    [instruments.loadcell]  address
    [instruments.clamp]     mode = "motor" (address) or "operator"
    [instruments.impedance] address (VISA resource name)
    [instruments.daq]       address (gRPC host:port, or "local"), device, drive/voltage/current/displacement
                            channels, current_gain_A_per_V, displacement_m_per_V
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, StringConstraints, ValidationError

from drivers.clamp import ClampController, MotorClamp, OperatorClamp
from drivers.daq import DaqRig
from drivers.errors import InstrumentError
from drivers.impedance_analyzer import ImpedanceAnalyzer
from drivers.keyence import open_keyence
from drivers.loadcell import LoadCell
from drivers.transcript import Transcript
from labrig.clock import ScaledClock
from labrig.errors import BadInput, validation_error
from labrig.safe_read import read_text_file
from labrig.validation import StrictModel, Text, matching
from labrig.physics import presets


# the bench's physical limits (docs/input_validation.md says where each comes from)
AO_RANGE_V = 10.0  # the DAQ's analog output range: no safety limit above what the drive can put out
LOADCELL_CAPACITY_N = 98.0  # Dacell UMMA-K10
MAX_RIG_FILE_BYTES = 1 << 20
Address = Annotated[str, StringConstraints(min_length=1, max_length=512), matching(r"[^\x00-\x20\x7f]+", "contains a space or a control character")]
# what pyvisa opens: TCPIP0::host::5025::SOCKET, TCPIP::host::inst0::INSTR, GPIB0::17::INSTR, USB0::...::INSTR, ASRL/dev/ttyUSB0::INSTR
VisaResource = Annotated[str, StringConstraints(max_length=512), matching(
    r"(?i:TCPIP|GPIB|USB|ASRL|VXI|PXI)[^\x00-\x20:]*::[^\x00-\x20\x7f]+", "not a VISA resource name (e.g. TCPIP::192.168.0.5::5025::SOCKET)")]
Channel = Annotated[str, matching(r"[A-Za-z0-9_./-]{1,64}", "not a device or channel name (letters, digits, _ . / -)")]


class _Strict(StrictModel):
    """Every rig model: strict (labrig.validation): unknown keys, booleans as numbers, inf and nan refused."""


class ClockCfg(_Strict):
    # a simulated bench runs 1..1e5 x; below 0.1 x a second of protocol is minutes of waiting (a typo, not a bench)
    time_scale: float = Field(1.0, ge=0.1, le=1e5)
    epoch_wall: float | None = Field(None, ge=0, le=4e9)  # unix time (4e9: year 2096)


class SafetyCfg(_Strict):
    """Defaults safe for an IPMC in water: below electrolysis-heavy drive, well under the load cell's 98 N."""

    max_drive_V: float = Field(2.0, gt=0, le=AO_RANGE_V)
    max_current_A: float = Field(0.2, gt=0, le=10.0)
    max_force_N: float = Field(90.0, gt=0, le=LOADCELL_CAPACITY_N)


class SampleCfg(_Strict):
    preset: Text = "paper"


class KeyenceCfg(_Strict):
    address: Address
    dialect: Literal["LK-G", "LK-2000"] = "LK-G"


class LoadCellCfg(_Strict):
    address: Address


class ClampCfg(_Strict):
    mode: Literal["motor", "operator"] = "operator"
    address: Address | None = None


class ImpedanceCfg(_Strict):
    address: VisaResource


class DaqCfg(_Strict):
    address: Address = "local"
    device: Channel = "Dev1"
    drive_channel: Channel = "ao0"
    voltage_channel: Channel = "ai0"
    current_channel: Channel = "ai1"
    displacement_channel: Channel = "ai2"
    current_gain_A_per_V: float = Field(1e-3, gt=0, le=100.0)  # a current amplifier or shunt: 1 pA/V .. 100 A/V
    displacement_m_per_V: float = Field(1e-3, gt=0, le=1.0)  # the laser's analog output: mm per volt


class Instruments(_Strict):
    keyence: KeyenceCfg
    loadcell: LoadCellCfg
    clamp: ClampCfg = ClampCfg()
    impedance: ImpedanceCfg
    daq: DaqCfg


class RigFile(_Strict):
    clock: ClockCfg = ClockCfg()
    sample: SampleCfg = SampleCfg()
    safety: SafetyCfg = SafetyCfg()
    instruments: Instruments


def parse_rig(data: dict[str, Any], source: str) -> RigFile:
    try:
        cfg = RigFile.model_validate(data)
    except ValidationError as exc:
        raise validation_error(exc, source) from None
    if cfg.sample.preset not in presets.names():
        raise BadInput(f"{source}: sample.preset: unknown preset {cfg.sample.preset!r} (known: {', '.join(presets.names())})")
    if cfg.instruments.clamp.mode == "motor" and not cfg.instruments.clamp.address:
        raise BadInput(f"{source}: instruments.clamp.address: required when mode = 'motor'")
    return cfg


def load_rig(path: str | Path) -> RigFile:
    """A rig file, every value checked (one line naming the file and field, ``BadInput``) before any instrument opens."""
    return parse_rig(read_text_file(path, "rig file", MAX_RIG_FILE_BYTES, toml=True), str(path))


@dataclass
class Rig:
    """Open drivers + clock + limits. ``safe()`` puts the drive at 0 V before anything else."""

    config: RigFile
    clock: ScaledClock
    daq: DaqRig
    laser: Any
    loadcell: LoadCell
    analyzer: ImpedanceAnalyzer
    clamp: ClampController
    transcript: Transcript = field(default_factory=Transcript)

    @property
    def limits(self) -> SafetyCfg:
        return self.config.safety

    @property
    def clamp_area_m2(self) -> float:
        return presets.get(self.config.sample.preset).base.geometry.clamp_area

    def sample_info(self) -> dict[str, Any]:
        g = presets.get(self.config.sample.preset).base
        return {
            "preset": self.config.sample.preset,
            "length_m": g.geometry.length,
            "width_m": g.geometry.width,
            "thickness_m": g.geometry.thickness,
            "clamp_length_m": g.geometry.clamp_length,
            "clamp_area_m2": g.geometry.clamp_area,
            "medium": g.fluid.name,
        }

    def describe(self) -> dict[str, Any]:
        d = self.config.model_dump(mode="json")
        try:
            d["identity"] = {"impedance": self.analyzer.identify(), "daq": self.daq.describe()}
        except InstrumentError as exc:
            d["identity"] = {"error": str(exc)}
        return d

    def safe(self) -> list[str]:
        """Drive to 0 V first, then everything else safe. Never raises; returns what failed."""
        problems = []
        for what, fn in (("daq", self.daq.abort), ("impedance", self.analyzer.safe)):
            try:
                fn()
            except Exception as exc:  # a dead instrument must not stop the others being made safe
                problems.append(f"{what}: {exc}")
        return problems

    def close(self) -> None:
        self.safe()
        for dev in (self.daq, self.analyzer, self.laser, self.loadcell, self.clamp):
            try:
                dev.close()
            except Exception:
                pass


def open_rig(cfg: RigFile, clock: ScaledClock | None = None, transcript: Transcript | None = None) -> Rig:
    """Connect to every instrument of ``cfg`` (drivers record their traffic into ``transcript``)."""
    tr = transcript or Transcript()
    clock = clock or ScaledClock(cfg.clock.time_scale, cfg.clock.epoch_wall)
    ins = cfg.instruments
    opened: list[Any] = []
    try:
        d = ins.daq
        daq = DaqRig(
            device=d.device,
            grpc_target=None if d.address == "local" else d.address,
            drive_channel=d.drive_channel,
            voltage_channel=d.voltage_channel,
            current_channel=d.current_channel,
            displacement_channel=d.displacement_channel,
            current_gain_A_per_V=d.current_gain_A_per_V,
            displacement_m_per_V=d.displacement_m_per_V,
            transcript=tr,
        )
        opened.append(daq)
        analyzer = ImpedanceAnalyzer(ins.impedance.address, transcript=tr, sweep_timeout_s=600.0)
        opened.append(analyzer)
        laser = open_keyence(ins.keyence.address, dialect=ins.keyence.dialect, transcript=tr)
        opened.append(laser)
        loadcell = LoadCell(ins.loadcell.address, transcript=tr, stale_s=2.0)
        opened.append(loadcell)
        clamp = MotorClamp(ins.clamp.address, transcript=tr, max_force_N=cfg.safety.max_force_N) if ins.clamp.mode == "motor" else OperatorClamp()
        return Rig(cfg, clock, daq, laser, loadcell, analyzer, clamp, tr)
    except BaseException:
        for dev in reversed(opened):
            try:
                dev.close()
            except Exception:
                pass
        raise
