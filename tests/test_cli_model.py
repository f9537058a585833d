"""``labrig model`` from the command line, as an engineer would run it."""

import csv
import json
import subprocess
import sys

import numpy as np
import pytest

from labrig.physics import presets, transfer


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "labrig", *args], capture_output=True, text=True, cwd=cwd)


def test_modes_json_reproduces_table2():
    r = run("model", "modes", "--preset", "paper", "--kt", "4.17", "5.67", "8.02", "--json")
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    assert out["Kt_bar"] == [4.17, 5.67, 8.02]
    assert out["f1_Hz"] == pytest.approx([3.30, 3.54, 3.78], rel=0.005)


def test_response_csv_is_importable_and_matches_the_model(tmp_path):
    path = tmp_path / "step.csv"
    r = run("model", "response", "--kind", "harmonic", "--frequency", "0.5", "--duration", "40", "--fs", "200", "--out", str(path))
    assert r.returncode == 0, r.stderr
    rows = list(csv.DictReader(open(path)))
    assert list(rows[0]) == ["t_s", "v_V", "i_A", "disp_m"]
    t = np.array([float(r["t_s"]) for r in rows])
    d = np.array([float(r["disp_m"]) for r in rows])
    tail = t > 30
    amp = 2 * abs(np.mean(d[tail] * np.exp(-2j * np.pi * 0.5 * t[tail])))
    h = abs(transfer.frf(np.array([0.5]), presets.get("paper").specimen())[0])
    assert amp == pytest.approx(h, rel=0.02)


def test_impedance_and_frf_csv(tmp_path):
    assert run("model", "impedance", "--pressure", "612", "--points", "20", "--out", str(tmp_path / "z.csv")).returncode == 0
    assert run("model", "frf", "--points", "20", "--out", str(tmp_path / "f.csv")).returncode == 0
    z = np.loadtxt(tmp_path / "z.csv", delimiter=",", skiprows=1)
    assert z.shape == (20, 3) and np.all(z[:, 2] < 0)


@pytest.mark.parametrize(
    "args, word",
    [
        (("model", "modes", "--kt", "-2"), "--kt"),
        (("model", "modes", "--preset", "nosuch"), "--preset"),
        (("model", "frf", "--fmin", "5", "--fmax", "1", "--out", "x.csv"), "frequency range"),
        (("model", "impedance", "--out", "/nonexistent/dir/z.csv"), "/nonexistent/dir/z.csv"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args, word, tmp_path):
    r = run(*args, cwd=tmp_path)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and word in lines[0] and "Traceback" not in r.stderr
