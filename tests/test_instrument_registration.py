"""Adding an instrument takes its driver, its simulator and one entry (docs/architecture.md): a thermometer that
labrig has never heard of, registered once in ``labrig.instruments.KINDS`` (its simulator registering its own
stand-in beside it), is served by the simulated bench, opened by the rig, recorded, checked by ``labrig check``
and stood in by replay, with no other line of labrig changed."""

from __future__ import annotations

import time
from pathlib import Path

import pytest
import tomli_w

from drivers.errors import InstrumentTimeout
from drivers.serial_port import SerialInstrument
from drivers.transcript import ReplaySerial, Transcript
from labrig.cli import main
from labrig.clock import ScaledClock
from labrig.errors import BadInput
from labrig.instrument_kind import SERIAL_REPLY_RIG_S, InstrumentKind, Opening, Replaying
from labrig.instruments import KINDS, Address
from labrig.replay import check, replay_rig
from labrig.simulate import rig_file_data
from labrig.store.reader import SessionReader
from labrig.validation import StrictModel
from mock_devices.serial_server import SimSerialDevice, serve
from mock_devices.simbench import SimulatedInstruments
from mock_devices.stand_ins import STAND_INS, Served, SimOptions
from mock_devices.world import World

STEP = Path(__file__).parent / "data" / "sessions" / "step.toml"  # the short recorded-session protocol


# ---- the driver (would be drivers/thermometer.py)
class Thermometer(SerialInstrument):
    default_name = "thermo"

    def read_C(self) -> float:
        self._write(b"T?\r")
        reply = self._read_until(b"\r", 32)
        if not reply.endswith(b"\r"):
            raise InstrumentTimeout(self.name, "no reply to T?")
        return float(reply[:-1].decode("ascii").split(",")[1])


# ---- the simulator with its own stand-in (would be mock_devices/thermometer_sim.py)
class ThermometerSim(SimSerialDevice):
    def respond(self, line: bytes) -> bytes:
        return b"T,+21.50\r" if line.strip() == b"T?" else b"ER\r"


def thermometer_stand_in(world, opts: SimOptions) -> Served:  # registered with @stands_in("thermo") in its module
    sim = ThermometerSim(opts.seed + 7)
    srv = serve(sim, opts.transport)
    return Served(sim, {"address": srv.address}, srv.stop)


# ---- the one registration (would be an entry of labrig.instruments.KINDS)
class ThermoCfg(StrictModel):
    address: Address


def _open(c: ThermoCfg, o: Opening) -> Thermometer:
    t = Thermometer(c.address, transcript=o.transcript, timeout_s=o.timeout(SERIAL_REPLY_RIG_S))
    t.start_C = t.read_C()  # the room temperature the session starts at: traffic the recording holds
    return t


def _check(c: ThermoCfg, rig) -> tuple[str, str]:
    with Thermometer(c.address, timeout_s=3.0) as t:
        return "bench thermometer", f"{t.read_C():+.2f} C"


def _replay(c: ThermoCfg, r: Replaying) -> Thermometer:
    rep = r.replayers["thermo"] = ReplaySerial(r.transcript("thermo").for_device("thermo"), "thermo")
    t = Thermometer(rep)
    t.start_C = t.read_C()
    return t


THERMO = InstrumentKind("thermo", ThermoCfg, _open, _check, "the thermometer's cable and port", _replay)


@pytest.fixture
def thermometer(monkeypatch):
    monkeypatch.setitem(STAND_INS, "thermo", thermometer_stand_in)
    monkeypatch.setitem(KINDS, "thermo", THERMO)


def test_a_registered_instrument_is_simulated_opened_recorded_and_replayed(thermometer, tmp_path, capsys):
    out = tmp_path / "s.h5"
    assert main(["run", str(STEP), "--sim", "--out", str(out), "-q"]) == 0
    with SessionReader(out) as r:
        assert r.rig["instruments"]["thermo"]["address"].startswith("socket://")  # served by the simulated bench
        recorded = [(e.op, e.payload) for e in Transcript.loads(r.transcript("thermo")).exchanges]
        assert recorded == [("write", b"T?\r"), ("read", b"T,+21.50\r")]  # opened by the rig, its traffic recorded

        rr = replay_rig(r)  # stood in by replay: answers from the recording, which it used up
        assert isinstance(rr.rig.instruments["thermo"], Thermometer) and rr.rig.instruments["thermo"].start_C == 21.5
        assert rr.replayers["thermo"].exhausted
        rr.close()
    assert check(out).ok, check(out).message  # the whole session replays with it
    KINDS.pop("thermo")  # unregistered, the recorded rig file no longer parses: the entry is what made it known
    with pytest.raises(BadInput, match="instruments.thermo: unknown field"):
        check(out)


def test_labrig_check_checks_a_registered_instrument(thermometer, tmp_path, capsys):
    clock = ScaledClock(1000.0, time.time())
    with SimulatedInstruments(World(clock, seed=5), seed=5) as sims:
        rig = tmp_path / "rig.toml"
        rig.write_text(tomli_w.dumps(rig_file_data(sims, clock, "paper")))
        assert main(["check", "--rig", str(rig)]) == 0
        lines = capsys.readouterr().out.splitlines()
        assert lines[-1].split()[:2] == ["ok", "thermo"] and "+21.50 C" in lines[-1]
        sims.served["thermo"].stop()
        assert main(["check", "--rig", str(rig)]) == 3
        assert "look at: the thermometer's cable and port" in capsys.readouterr().out
