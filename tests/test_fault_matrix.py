"""Faults injected with the drive live: exit 3, the drive at 0 V (read back, or declared unknown with the
link gone and put there by the DAQ's watchdog), the session file opens, finished steps intact, the step in
flight kept and marked. A fast subset of the matrix (``bench/fault_cells.py``); all of it:
``python bench/fault_matrix.py``."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import tomli_w

from drivers.daq_watchdog import WALL_FLOOR_S

from bench import fault_cells as fm
from labrig.clock import ScaledClock
from labrig.simulate import rig_file_data
from labrig.store import SessionReader
from mock_devices.simbench import SimulatedInstruments
from mock_devices.world import World

ROOT = Path(__file__).resolve().parents[1]

# one or two of each instrument's faults, the limit and reading faults, and the analyser mid-sweep
FAST = [
    ("daq", "disconnect", "hold"),
    ("daq", "non-finite", "hold"),
    ("loadcell", "timeout", "hold"),
    ("loadcell", "over-force", "hold"),
    ("keyence", "error", "hold"),
    ("impedance", "timeout", "eis"),
    ("clamp", "disconnect", "hold"),
]


@pytest.mark.parametrize("instrument, fault, phase", FAST, ids=["-".join(c) for c in FAST])
def test_fault_meets_the_contract(tmp_path, instrument, fault, phase):
    cell = fm.run_cell(instrument, fault, phase, tmp_path)
    assert cell.ok, cell.row()
    assert cell.result.exit_code == 3
    if (instrument, fault) == ("daq", "disconnect"):
        assert "UNKNOWN" in cell.result.drive and "switch off the amplifier" in cell.result.drive
        assert cell.ao_V == 0.0 and cell.watchdog_rig_s is not None  # the DAQ's watchdog did it
    else:
        assert cell.result.drive.startswith("drive read back at") and cell.ao_V == 0.0


def test_matrix_covers_every_fault_the_simulators_inject():
    from mock_devices import daq_grpc, impedance_sim
    from mock_devices.keyence_sim import KeyenceSim
    from mock_devices.loadcell_sim import LoadCellSim
    from mock_devices.serial_server import COMMON_FAULTS

    assert set(daq_grpc.FAULTS) <= set(fm.FAULTS["daq"])
    assert set(LoadCellSim.FAULTS) <= set(fm.FAULTS["loadcell"])
    assert set(KeyenceSim.FAULTS) <= set(fm.FAULTS["keyence"])
    assert set(impedance_sim.FAULTS) <= set(fm.FAULTS["impedance"])
    assert set(COMMON_FAULTS) <= set(fm.FAULTS["clamp"])
    assert len(fm.cells()) == sum(len(v) for v in fm.FAULTS.values()) + len(fm.FAULTS["impedance"])


def _long_hold(path: Path, hold_s: float) -> Path:
    path.write_text(f'protocol = "step"\n[clamp]\npressures_kPa = [3062.0]\nsettle_s = 1.0\n'
                    f'[step]\namplitude_V = 1.0\non_s = {hold_s}\noff_s = 1.0\nfs_Hz = 100.0\n')
    return path


def test_kill_9_of_labrig_run_leaves_the_drive_at_zero_within_the_watchdog_time(tmp_path):
    """``labrig run --rig`` against the simulated instruments ``labrig sim`` serves (the same code, here in
    this process so the test can watch the AO itself: a second DAQ client cannot read the drive back while
    the killed client's AI task still holds the card), SIGKILLed mid-hold."""
    scale = 100.0
    clock = ScaledClock(scale, time.time())
    sims = SimulatedInstruments(World(clock, preset="paper", seed=0)).start()
    try:
        rig_path = tmp_path / "rig.toml"
        rig_path.write_text(tomli_w.dumps(rig_file_data(sims, clock, "paper")))
        watch = fm._DriveWatch(sims.daq.device)
        proto = _long_hold(tmp_path / "hold.toml", 600.0)
        run = subprocess.Popen([sys.executable, "-m", "labrig", "run", str(proto), "--rig", str(rig_path),
                                "--out", str(tmp_path / "s.h5"), "-q"], cwd=ROOT, stderr=subprocess.PIPE)
        try:
            assert watch.started.wait(60.0), "the drive never went live"
            clock.sleep(watch.t0 + 100.0 - clock.now())  # 100 s into the 600 s hold: 1 s of wall time at 100x, so that
            # the run has stored blocks by then even on a loaded machine (at 30 s one suite run found none)
            assert sims.daq.ao_output_V() == pytest.approx(1.0, abs=1e-3)  # the drive is live
            t_kill = clock.now()
            os.kill(run.pid, signal.SIGKILL)
            run.wait(10.0)
            # the host may reset the watchdog between reading t_kill and its death (8 ms of wall time on a slow
            # machine is 0.8 rig s at 100x): the bound is one timeout after it is dead
            t_dead = clock.now()
        finally:
            if run.poll() is None:
                run.kill()
        timeout_rig_s = max(5.0, WALL_FLOOR_S * scale)  # watchdog_s = 5 rig s, floored at WALL_FLOOR_S wall s
        seen_rig_s = 1.0 * scale  # how late this process's poller on a loaded machine may see the card's 0 V
        t_zero = fm.wait_for_zero(sims, clock, t_dead + timeout_rig_s + seen_rig_s)
        assert t_zero is not None, "the drive stayed live after the controlling process was killed"
        # the card put 0 V out one timeout after the killed host's last reset (before its death) at the latest
        (wd,) = (t.wd for t in sims.daq.device.tasks.values() if t.wd is not None)
        assert t_kill < wd.expired_at <= t_dead + timeout_rig_s and wd.expired_at <= t_zero <= wd.expired_at + seen_rig_s
        assert run.returncode == -signal.SIGKILL
    finally:
        sims.stop()
    with SessionReader(tmp_path / "s.h5") as rd:  # what was stored before the kill is readable
        hold = next(s for s in rd.steps() if s.kind == "step")
        assert rd.stream(hold.index, "daq").rows > 0
        assert np.all(np.isfinite(rd.stream(hold.index, "daq")["v_V"]))
