"""``labrig run`` / ``labrig sim`` / ``labrig inspect`` from the command line: a crash, a resume, bad input."""

import json
import os
import signal
import subprocess
import sys
import time

import h5py
import pytest

from labrig.store import SessionReader

LABRIG = [sys.executable, "-m", "labrig"]


def run(*args, **kw):
    return subprocess.run([*LABRIG, *args], capture_output=True, text=True, **kw)


def _steps_done(path):
    try:
        with SessionReader(path) as r:
            return sum(s.status == "done" for s in r.steps())
    except Exception:
        return 0


SHORT_SWEEP = """protocol = "paper-sweep"
rest_s = 5.0
[clamp]
pressures_kPa = [612, 3062]
settle_s = 10.0
[eis]
points = 11
[step]
on_s = 10.0
off_s = 10.0
[harmonic]
frequency_Hz = 0.5
[stepped_sine]
f_start_Hz = 0.5
points = 6
"""


def test_kill_9_then_resume_completes_the_session(tmp_path):
    out = tmp_path / "s.h5"
    proto = tmp_path / "short-sweep.toml"
    proto.write_text(SHORT_SWEEP)
    proc = subprocess.Popen([*LABRIG, "run", str(proto), "--sim", "--quiet", "--time-scale", "200", "--out", str(out)])
    try:
        deadline = time.time() + 120
        while _steps_done(out) < 6 and time.time() < deadline:
            time.sleep(0.2)
        assert proc.poll() is None, "the run ended before it could be killed"
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    finally:
        if proc.poll() is None:
            proc.kill()
    with pytest.raises(OSError, match="already open for write"):
        h5py.File(out, "r")  # what the kill leaves: HDF5 tools refuse it ...
    shown = run("inspect", str(out), "--json")
    assert "cleared the 'open for write' flags" in shown.stderr  # ... until the next labrig command, which says so
    h5py.File(out, "r").close()
    with SessionReader(out) as s:  # transcripts are written as the run goes: the kill keeps them
        assert all(s.transcript(dev).strip() for dev in ("daq", "keyence", "loadcell", "impedance"))
    info = json.loads(shown.stdout)
    statuses = [s["status"] for s in info["steps"]]
    done_before = statuses.count("done")
    assert done_before >= 6 and info["exit_status"] in (None, "")
    assert "running" in statuses or "planned" in statuses
    assert info["incomplete"]
    r = run("run", "--resume", str(out), "--sim", "--quiet")
    assert r.returncode == 0, r.stderr
    with SessionReader(out) as s:
        assert s.exit_status == "success"
        steps = s.steps()
        assert all(st.status == "done" for st in steps)
        assert all(st.rows.get("daq", 0) == st.expected_rows.get("daq", 0) for st in steps)
    before = out.read_bytes()
    r = run("run", "--resume", str(out), "--sim", "--quiet")
    assert r.returncode == 0 and "nothing to resume" in r.stderr and "finished with success" in r.stderr
    assert out.read_bytes() == before  # a finished session is left exactly as it was


@pytest.mark.parametrize(
    "args, word",
    [
        (("run", "step", "--out", "x.h5"), "exactly one of --sim or --rig"),
        (("run", "step", "--sim"), "--out FILE.h5 is required"),
        (("run", "nosuch.toml", "--sim", "--out", "x.h5"), "nosuch.toml: no such protocol file"),
        (("run", "step", "--rig", "missing-rig.toml", "--out", "x.h5"), "missing-rig.toml: no such rig file"),
        (("run", "step", "--sim", "--scenario", "gremlins", "--out", "x.h5"), "unknown scenario 'gremlins'"),
        (("inspect", "missing.h5"), "missing.h5"),
    ],
)
def test_bad_run_input_exit_2_one_line(tmp_path, args, word):
    r = run(*args, cwd=tmp_path)
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and word in lines[0], r.stderr


def test_bad_rig_file_names_the_field(tmp_path):
    rig = tmp_path / "rig.toml"
    rig.write_text('[instruments.keyence]\naddress = "socket://127.0.0.1:1"\n[instruments.loadcell]\naddress = "x"\n'
                   '[instruments.impedance]\naddress = "TCPIP::127.0.0.1::1::SOCKET"\nmodel = "IM3590"\n[instruments.daq]\naddres = "z"\n')
    r = run("run", "step", "--rig", str(rig), "--out", str(tmp_path / "s.h5"))
    assert r.returncode == 2 and "instruments.daq.addres: unknown field" in r.stderr


def test_existing_session_is_never_overwritten(tmp_path):
    out = tmp_path / "s.h5"
    out.write_bytes(b"precious")
    r = run("run", "step", "--sim", "--out", str(out))
    assert r.returncode == 2 and "already exists" in r.stderr and out.read_bytes() == b"precious"


def test_labrig_sim_serves_a_rig_that_labrig_run_accepts(tmp_path):
    rig = tmp_path / "rig.toml"
    sim = subprocess.Popen([*LABRIG, "sim", "--rig-out", str(rig), "--time-scale", "1000"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.time() + 30
        while not rig.exists() and time.time() < deadline:
            time.sleep(0.1)
        assert rig.exists()
        text = rig.read_text()
        for table in ("[instruments.keyence]", "[instruments.loadcell]", "[instruments.impedance]", "[instruments.daq]"):
            assert table in text
        assert "127.0.0.1" in text and "0.0.0.0" not in text
        r = run("run", "step", "--rig", str(rig), "--quiet", "--out", str(tmp_path / "s.h5"))
        assert r.returncode == 0, r.stderr
        with SessionReader(tmp_path / "s.h5") as s:
            assert s.exit_status == "success" and s.stream(2, "daq").rows > 1000
    finally:
        sim.send_signal(signal.SIGTERM)
        assert sim.wait(timeout=20) == 0


def test_a_failed_run_exits_3_with_one_line(tmp_path):
    """A safety trip on the simulated bench: exit code 3, the reason on stderr, the session says fail."""
    rig_limits = tmp_path / "tight.toml"
    rig_limits.write_text('protocol = "step"\n[step]\namplitude_V = 1.0\n')
    out = tmp_path / "s.h5"
    r = subprocess.run([*LABRIG, "run", str(rig_limits), "--sim", "--quiet", "--limit", "max_current_A=0.002", "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 3, (r.returncode, r.stderr)
    assert "safety trip" in r.stderr and "drive read back at" in r.stderr  # 0 V said only once read back
    with SessionReader(out) as s:
        assert s.exit_status == "fail" and s.stream(2, "daq").rows > 0


def test_every_command_loads_under_its_name():
    """Commands are imported when they run (labrig.cli._COMMANDS): each entry must resolve to its command."""
    import click

    from labrig.cli import _COMMANDS, app

    ctx = click.Context(app)
    assert app.list_commands(ctx) == sorted(_COMMANDS)
    for name in _COMMANDS:
        assert app.get_command(ctx, name).name == name


SPECIMEN = """[specimen]
name = "strip-B7"
length_m = 0.025
width_m = 0.006
thickness_m = 0.00021
clamp_area_m2 = 1.2e-5
medium = "water"
temperature_C = 22.5
batch = "Nafion 117, lot 11"
notes = "second strip of the batch"

[operator]
name = "A. Researcher"
notes = "refilled the tank at 10:40"
"""


def test_run_with_a_sample_file_stores_the_strip_and_the_operator_and_uses_the_geometry(tmp_path):
    from labrig.fit.seed000 import base_specimen

    spec = tmp_path / "strip.toml"
    spec.write_text(SPECIMEN)
    out = tmp_path / "s.h5"
    proto = os.path.join(os.path.dirname(__file__), "data", "sessions", "step.toml")
    r = run("run", proto, "--sim", "--quiet", "--sample", str(spec), "--out", str(out))
    assert r.returncode == 0, r.stderr
    with h5py.File(out, "r") as f:  # NeXus: NXsample and NXuser
        assert f["entry/sample"].attrs["NX_class"] == "NXsample" and f["entry/user"].attrs["NX_class"] == "NXuser"
        assert f["entry/sample/name"][()] == b"strip-B7" and f["entry/sample/length_m"].attrs["units"] == "m"
        assert f["entry/sample/temperature_C"][()] == 22.5 and f["entry/user/name"][()] == b"A. Researcher"
    with SessionReader(out) as s:
        assert s.sample["batch"] == "Nafion 117, lot 11" and "preset" not in s.sample
        assert s.user == {"name": "A. Researcher", "notes": "refilled the tank at 10:40"}
        clamp = s.steps()[0]
        assert abs(clamp.metadata["force_N"] - 3062e3 * 1.2e-5) < 1e-9  # the clamp force from this strip's area
        geom = base_specimen(s.sample).geometry  # what the fit starts from: this strip, not the preset
        assert (geom.length, geom.width, geom.thickness) == (0.025, 0.006, 0.00021)
    shown = run("inspect", str(out))
    assert "name=strip-B7" in shown.stdout and "operator     name=A. Researcher" in shown.stdout


@pytest.mark.parametrize("edit, word", [
    (lambda t: t.replace('name = "strip-B7"\n', ""), "specimen.name"),
    (lambda t: t.replace("length_m = 0.025", "length_m = true"), "specimen.length_m"),
    (lambda t: t.replace("[operator]", "[operatr]"), "operatr"),
])
def test_a_bad_sample_file_is_one_line_exit_2_before_anything_moves(tmp_path, edit, word):
    spec = tmp_path / "strip.toml"
    spec.write_text(edit(SPECIMEN))
    r = run("run", "step", "--sim", "--quiet", "--sample", str(spec), "--out", str(tmp_path / "s.h5"))
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert str(spec) in r.stderr and word in r.stderr
    assert not (tmp_path / "s.h5").exists()
