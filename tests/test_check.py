"""`labrig check` on the simulated bench: every instrument ok; a stopped server is named (exit 3); the E4990A
served by `labrig sim --impedance e4990a` passes the check and a paper sweep on it is refused before anything moves."""

from __future__ import annotations

import json
import time

import pytest
import tomli_w

from labrig.cli import main
from labrig.clock import ScaledClock
from labrig.simulate import rig_file_data
from mock_devices.simbench import SimulatedInstruments
from mock_devices.world import World


@pytest.fixture
def bench_rig(tmp_path):
    clock = ScaledClock(1000.0, time.time())
    with SimulatedInstruments(World(clock, seed=3), seed=3) as sims:
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
        sims.served["loadcell"].stop()
    assert main(["check", "--rig", str(path)]) == 3
    out, err = capsys.readouterr()
    lines = {line.split()[1]: line for line in out.splitlines()}
    assert lines[stop].startswith("FAULT") and "look at:" in lines[stop]
    assert all(line.startswith("ok") for name, line in lines.items() if name != stop)
    assert err.strip() == f"labrig check: instrument fault: {stop}"


def test_e4990a_bench_checks_ok_and_refuses_a_paper_sweep_before_anything_moves(tmp_path, capsys):
    """What `labrig sim --impedance e4990a` serves (SimulatedInstruments(impedance_model="E4990A"))."""
    clock = ScaledClock(1000.0, time.time())
    with SimulatedInstruments(World(clock, seed=4), seed=4, impedance_model="E4990A") as sims:
        rig = tmp_path / "rig.toml"
        rig.write_text(tomli_w.dumps(rig_file_data(sims, clock, "paper")))
        assert main(["check", "--rig", str(rig)]) == 0
        out = capsys.readouterr().out
        assert "E4990A" in out and "20 Hz to 120 MHz" in out
        before = sims.clamp.target_N
        assert main(["run", "paper-sweep", "--rig", str(rig), "--out", str(tmp_path / "p.h5"), "-q"]) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and "E4990A measures 20 Hz to 120 MHz" in err and "100 mHz" in err
        assert sims.clamp.target_N == before  # the clamp was never asked to move
        assert not (tmp_path / "p.h5").exists()  # refused before a session was opened
