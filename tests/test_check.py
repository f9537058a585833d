"""`labrig check` on the simulated bench: every instrument ok; a stopped server is named (exit 3); the E4990A
served by `labrig sim --impedance e4990a` passes the check and a paper sweep on it is refused before anything moves."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import tomli_w

from labrig.cli import main
from labrig.clock import ScaledClock
from labrig.simulate import rig_file_data
from mock_devices.simbench import SimulatedInstruments
from mock_devices.world import Bench


@pytest.fixture
def bench_rig(tmp_path):
    clock = ScaledClock(1000.0, time.time())
    with SimulatedInstruments(Bench(clock, seed=3), seed=3) as sims:
        path = tmp_path / "rig.toml"
        path.write_text(tomli_w.dumps(rig_file_data(sims, clock, "paper")))
        yield sims, path


def test_check_passes_on_the_simulated_bench(bench_rig, capsys):
    _, path = bench_rig
    assert main(["check", "--rig", str(path), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["ok"] and [i["instrument"] for i in report["instruments"]] == ["daq", "impedance", "keyence", "loadcell", "clamp"]
    by = {i["instrument"]: i for i in report["instruments"]}
    assert by["impedance"]["identity"].startswith("HIOKI,IM3590")
    assert "kg" in by["loadcell"]["identity"] and " N (" in by["loadcell"]["value"]


@pytest.mark.parametrize("stop", ["impedance", "loadcell"])
def test_check_names_the_instrument_whose_server_is_stopped(bench_rig, capsys, stop):
    sims, path = bench_rig
    if stop == "impedance":
        sims.impedance.stop()
    else:
        sims._servers[1].stop()  # keyence, loadcell, clamp: in that order
    assert main(["check", "--rig", str(path)]) == 3
    out, err = capsys.readouterr()
    lines = {line.split()[1]: line for line in out.splitlines()}
    assert lines[stop].startswith("FAULT") and "look at:" in lines[stop]
    assert all(line.startswith("ok") for name, line in lines.items() if name != stop)
    assert err.strip() == f"labrig check: instrument fault: {stop}"


def _labrig(*args: str) -> list[str]:
    return [sys.executable, "-c", "from labrig.cli import entry; entry()", *args]


def test_e4990a_bench_checks_ok_and_refuses_a_paper_sweep_before_anything_moves(tmp_path):
    rig = tmp_path / "rig.toml"
    sim = subprocess.Popen(_labrig("sim", "--rig-out", str(rig), "--impedance", "e4990a"),
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 30
        while not rig.exists():
            assert sim.poll() is None and time.monotonic() < deadline, sim.stderr.read() if sim.poll() is not None else "no rig file"
            time.sleep(0.1)
        check = subprocess.run(_labrig("check", "--rig", str(rig)), capture_output=True, text=True, timeout=60)
        assert check.returncode == 0, check.stdout + check.stderr
        assert "E4990A" in check.stdout and "20 Hz to 120 MHz" in check.stdout
        run = subprocess.run(_labrig("run", "paper-sweep", "--rig", str(rig), "--out", str(tmp_path / "p.h5"), "-q"),
                             capture_output=True, text=True, timeout=60)
        assert run.returncode == 2
        assert run.stderr.strip().splitlines() == [
            run.stderr.strip()] and "E4990A measures 20 Hz to 120 MHz" in run.stderr and "100 mHz" in run.stderr
        assert not (tmp_path / "p.h5").exists()  # refused before anything moved: no session was even opened
    finally:
        sim.send_signal(signal.SIGINT)
        sim.wait(timeout=20)
