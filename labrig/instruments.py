"""The bench's instruments, one entry each (``labrig.instrument_kind``): the one place an instrument is registered.

Each entry declares its rig-file table (``[instruments.<name>]``), how to open its driver, how ``labrig check``
identifies it and reads one harmless value, and how replay answers for it from the session's recorded traffic.
The tables, as ``labrig sim --rig-out`` writes them::

    [instruments.daq]       address (gRPC host:port, or "local"), device, drive/voltage/current/displacement
                            channels, current_gain_A_per_V, displacement_m_per_V, watchdog_s (rig seconds
                            without a reset from the host before the DAQ puts 0 V on the drive by itself)
    [instruments.impedance] address (VISA resource name), model ("IM3590", "E4990A" or "SIM-WIDE", the analyser of
                            labrig's older simulator; required: drivers/analyser_models.py)
    [instruments.keyence]   address (pyserial URL or device path), dialect
    [instruments.loadcell]  address
    [instruments.clamp]     mode = "motor" (address) or "operator"

Its driver lives in ``drivers/``; its simulator in ``mock_devices/`` registers its own stand-in there
(``mock_devices.stand_ins``). Adding an instrument: its driver, its simulator, and one entry in ``KINDS`` below.
The order of ``KINDS`` is the order instruments are opened, checked, made safe and closed: the drive first.
"""

from __future__ import annotations

import threading
from contextlib import closing
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field, StringConstraints, ValidationInfo, field_validator

from drivers import analyser_models
from drivers.analysers import open_analyser
from drivers.clamp import MotorClamp, OperatorClamp
from drivers.daq import Daq
from drivers.daq_watchdog import DEFAULT_TIMEOUT_S as DEFAULT_WATCHDOG_S
from drivers.keyence import open_keyence
from drivers.loadcell import LoadCell
from drivers.stream_replay import StreamReplay
from drivers.transcript import ReplayMessages, ReplaySerial
from labrig.instrument_kind import SERIAL_REPLY_RIG_S, InstrumentKind, Opening, Replaying
from labrig.validation import StrictModel, matching

CHECK_TIMEOUT_S = 3.0  # `labrig check`: one harmless exchange answers within this, or the instrument faults
STALE_RIG_S = 2.0  # a load cell with no valid frame for this many rig seconds is a fault...
STALE_WALL_S = 0.05  # ... never fewer wall seconds (the host's scheduling: 50 rig s on a 1000x bench)...
STALE_GRACE_WALL_S = 1.0  # ... and a stream that looks stale gets this long to show a frame (a stalled process:
# 0.2 s faulted a seed001 run in 1 of 4 on this 2-core machine with the suite beside it, after a 0.25 s stall)

Address = Annotated[str, StringConstraints(min_length=1, max_length=512), matching(r"[^\x00-\x20\x7f]+", "contains a space or a control character")]
# what pyvisa opens: TCPIP0::host::5025::SOCKET, TCPIP::host::inst0::INSTR, GPIB0::17::INSTR, USB0::...::INSTR, ASRL/dev/ttyUSB0::INSTR
VisaResource = Annotated[str, StringConstraints(max_length=512), matching(
    r"(?i:TCPIP|GPIB|USB|ASRL|VXI|PXI)[^\x00-\x20:]*::[^\x00-\x20\x7f]+", "not a VISA resource name (e.g. TCPIP::192.168.0.5::5025::SOCKET)")]
Channel = Annotated[str, matching(r"[A-Za-z0-9_./-]{1,64}", "not a device or channel name (letters, digits, _ . / -)")]


class ModelMismatch(Exception):
    """The instrument is not the model the rig file names."""


# ------------------------------------------------------------------ the DAQ: drive and the three AI channels
class DaqCfg(StrictModel):
    address: Address = "local"
    device: Channel = "Dev1"
    drive_channel: Channel = "ao0"
    voltage_channel: Channel = "ai0"
    current_channel: Channel = "ai1"
    displacement_channel: Channel = "ai2"
    current_gain_A_per_V: float = Field(1e-3, gt=0, le=100.0)  # a current amplifier or shunt: 1 pA/V .. 100 A/V
    displacement_m_per_V: float = Field(1e-3, gt=0, le=1.0)  # the laser's analog output: mm per volt
    watchdog_s: float = Field(DEFAULT_WATCHDOG_S, gt=0, allow_inf_nan=False, strict=True)

    def channels(self) -> dict[str, Any]:
        """The driver's device, channel and scaling settings (live, checked or replayed alike)."""
        return {k: getattr(self, k) for k in ("device", "drive_channel", "voltage_channel", "current_channel",
                                              "displacement_channel", "current_gain_A_per_V", "displacement_m_per_V")}

    @property
    def grpc_target(self) -> str | None:
        return None if self.address == "local" else self.address


def _open_daq(d: DaqCfg, o: Opening) -> Daq:
    return Daq(grpc_target=d.grpc_target, transcript=o.transcript, watchdog_s=d.watchdog_s,
                  time_scale=o.clock.time_scale, **d.channels())


def _check_daq(d: DaqCfg, rig: Any) -> tuple[str, str]:
    with Daq(grpc_target=d.grpc_target, **d.channels()) as daq:
        out = daq.run_finite(np.zeros(20), 1000.0, timeout_s=10.0)  # 20 ms at 0 V: reads every AI channel
    where = "this computer" if d.address == "local" else f"gRPC {d.address}"
    return (f"NI-DAQmx {d.device} on {where}",
            f"AI at 0 V drive: {np.mean(out['v_V']):+.4f} V, {np.mean(out['i_A']) * 1e3:+.4f} mA, "
            f"{np.mean(out['disp_m']) * 1e3:+.4f} mm")


def _replay_daq(d: DaqCfg, r: Replaying) -> Daq:
    # the recorded call arguments hold the NI device name, so the replaying driver gets both it and its own name
    daq = Daq(name="daq", replay=r.transcript("daq").replay_calls("daq"), **d.channels())
    r.replayers["daq"] = daq._replay
    return daq


# ------------------------------------------------------------------ the impedance analyser (by model: drivers.analysers)
class ImpedanceCfg(StrictModel):
    address: VisaResource
    # required: the model sets the range a plan is checked against before anything moves (an E4990A stops at 20 Hz)
    model: Literal[tuple(analyser_models.MODELS)]  # type: ignore[valid-type]


def _open_impedance(c: ImpedanceCfg, o: Opening) -> Any:
    return open_analyser(c.address, c.model, transcript=o.transcript, timeout_s=o.timeout(),
                         sweep_timeout_s=o.timeout(600.0))


def _check_impedance(c: ImpedanceCfg, rig: Any) -> tuple[str, str]:
    with closing(open_analyser(c.address, c.model, timeout_s=CHECK_TIMEOUT_S)) as an:
        idn = an.identify()
        if c.model != analyser_models.LEGACY_MODEL and c.model not in idn.upper():
            raise ModelMismatch(f"the rig file names a {c.model} but the instrument answers *IDN? {idn!r}")
        return idn, f"AC level {an.ac_V:g} V; {analyser_models.get(c.model).range_text()}"


def _replay_impedance(c: ImpedanceCfg, r: Replaying) -> Any:
    rep = r.replayers["impedance"] = ReplayMessages(r.transcript("impedance").for_device("impedance"), "impedance")
    return open_analyser(rep, c.model, sweep_timeout_s=600.0)


# ------------------------------------------------------------------ the Keyence laser (dialects: drivers.keyence_dialect)
class KeyenceCfg(StrictModel):
    address: Address
    dialect: Literal["LK-G", "LK-2000"] = "LK-G"


def _open_keyence(k: KeyenceCfg, o: Opening) -> Any:
    return open_keyence(k.address, dialect=k.dialect, transcript=o.transcript, timeout_s=o.timeout(SERIAL_REPLY_RIG_S))


def _check_keyence(k: KeyenceCfg, rig: Any) -> tuple[str, str]:
    with open_keyence(k.address, dialect=k.dialect, timeout_s=CHECK_TIMEOUT_S) as laser:
        program = laser.program()
        d = laser.read_displacement(1)
    return f"Keyence {k.dialect} controller, program {program}", f"OUT1 {d * 1e3:+.4f} mm"


def _replay_keyence(k: KeyenceCfg, r: Replaying) -> Any:
    rep = r.replayers["keyence"] = ReplaySerial(r.transcript("keyence").for_device("keyence"), "keyence")
    return open_keyence(rep, dialect=k.dialect)


# ------------------------------------------------------------------ the load cell's indicator (a frame stream)
class LoadCellCfg(StrictModel):
    address: Address


def _open_loadcell(c: LoadCellCfg, o: Opening) -> LoadCell:
    return LoadCell(c.address, transcript=o.transcript, clock=o.clock, grace_wall_s=STALE_GRACE_WALL_S,
                    stale_s=max(STALE_RIG_S, STALE_WALL_S * o.clock.time_scale))


def _check_loadcell(c: LoadCellCfg, rig: Any) -> tuple[str, str]:
    with LoadCell(c.address, stale_s=CHECK_TIMEOUT_S) as lc:
        frame = lc.latest()
    return f"indicator frame {frame.raw.strip().decode('ascii', 'replace')!r}", f"{frame.force_N:.3f} N ({'stable' if frame.stable else 'unstable'})"


class _ReplayLoadCell(LoadCell):
    """The load cell parsing in the caller's thread (no reader thread racing the replay clock); the runner
    and its force logger both read it, so parsing is serialised."""

    def __init__(self, port: Any, stale_s: float):
        super().__init__(port, stale_s=stale_s, background=False)
        self._pump_lock = threading.Lock()

    def pump(self) -> None:
        with self._pump_lock:
            super().pump()


def _replay_loadcell(c: LoadCellCfg, r: Replaying) -> LoadCell:
    # frames come at the recorded pace on the replay clock (rig s = recorded wall s x the recorded time scale),
    # paced against every other device's replayer (a live view: those opened after this one count too)
    port = StreamReplay(r.transcript("loadcell").for_device("loadcell"), r.replayers, clock=r.clock,
                        scale=r.rig.clock.time_scale)
    return _ReplayLoadCell(port, stale_s=60.0)  # its stream is not used up by a replay: no replayer registered


# ------------------------------------------------------------------ the clamp: a motor controller, or the operator
class ClampCfg(StrictModel):
    mode: Literal["motor", "operator"] = "operator"
    address: Address | None = Field(None, validate_default=True)

    @field_validator("address")
    @classmethod
    def _motor_has_address(cls, address: str | None, info: ValidationInfo) -> str | None:
        if info.data.get("mode") == "motor" and not address:
            raise ValueError("required when mode = 'motor'")
        return address


def _open_clamp(c: ClampCfg, o: Opening) -> Any:
    if c.mode != "motor":
        return OperatorClamp()
    return MotorClamp(c.address, transcript=o.transcript, timeout_s=o.timeout(SERIAL_REPLY_RIG_S),
                      max_force_N=o.rig.safety.max_force_N)


def _check_clamp(c: ClampCfg, rig: Any) -> tuple[str, str]:
    if c.mode == "operator":
        return "operator-set clamp", "nothing to connect (the load cell confirms the force)"
    with MotorClamp(c.address, timeout_s=CHECK_TIMEOUT_S, max_force_N=rig.safety.max_force_N) as clamp:
        return "motor clamp controller", f"target {clamp.target_N():.2f} N"


def _replay_clamp(c: ClampCfg, r: Replaying) -> Any:
    if c.mode != "motor":
        return OperatorClamp(ask=lambda msg: None)  # the operator already did it: the load cell replay says so
    rep = r.replayers["clamp"] = ReplaySerial(r.transcript("clamp").for_device("clamp"), "clamp")
    return MotorClamp(rep, max_force_N=r.rig.safety.max_force_N)


KINDS: dict[str, InstrumentKind] = {k.name: k for k in (
    InstrumentKind("daq", DaqCfg, _open_daq, _check_daq,
                   "the NI device name and, for a remote DAQ, the gRPC server at the address", _replay_daq),
    InstrumentKind("impedance", ImpedanceCfg, _open_impedance, _check_impedance,
                   "the analyser's LAN settings (IP, port), that it is on, and [instruments.impedance] model", _replay_impedance,
                   # sessions recorded before rig files named the analyser ran on labrig's older simulated analyser
                   as_recorded=lambda t: {"model": analyser_models.LEGACY_MODEL, **t}),
    InstrumentKind("keyence", KeyenceCfg, _open_keyence, _check_keyence,
                   "the RS-232C cable, port and baud rate, the controller's power and its mode (R0 = general)", _replay_keyence),
    InstrumentKind("loadcell", LoadCellCfg, _open_loadcell, _check_loadcell,
                   "the indicator's power, cable and port, and that its stream output is on", _replay_loadcell),
    InstrumentKind("clamp", ClampCfg, _open_clamp, _check_clamp, "the clamp controller's cable, port and power",
                   _replay_clamp, default=ClampCfg()),
)}
