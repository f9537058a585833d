"""A channel held at the end of its range (labrig/diagnose/clipping.py): the test on synthetic readings of every shape
it must tell apart, and end to end, a drive monitor that clips on the 1 V records of the suite's clean sweep
(exported, clipped, imported and diagnosed from the command line): no cause is named, and the verdict points at the
clipped channel."""

import json

import numpy as np
import pytest

from bench import inject
from labrig.cli import main
from labrig.diagnose.clipping import CLIP_RUN, channel_clip

BENCH_CASES = [("none", 1)]  # shared with test_fit, the coverage and the injected probe (conftest)
CODE = 2.0 / 65536  # a 16-bit converter on +-1 V


def _read(x: np.ndarray, noise: float, rng: np.random.Generator, top: float = np.inf) -> np.ndarray:
    """What a 16-bit converter returns for x plus white noise, held at +-top."""
    return np.round(np.clip(x + noise * rng.standard_normal(x.size), -top, top) / CODE) * CODE


@pytest.fixture
def rng():
    return np.random.default_rng(7)


def test_a_clipped_sine_and_a_clipped_plateau_are_found(rng):
    t = np.arange(6000) / 60.0  # a 0.1 Hz sine at 60 samples a second, ten cycles
    sine = _read(1.04 * np.sin(2 * np.pi * 0.1 * t), 2e-4, rng, top=1.0)
    c = channel_clip(sine)
    assert c["clipped"] and c["run"] >= CLIP_RUN and c["level"] == pytest.approx(1.0, abs=CODE)
    step = _read(np.where(np.arange(30000) >= 15000, 1.03, 0.0), 2e-4, rng, top=1.0)
    assert channel_clip(step)["clipped"]


def test_smooth_tops_noise_and_setpoints_are_not_clipping(rng):
    t = np.arange(60000) / 1000.0  # a slow sine sampled fast: its top holds one code for tens of readings
    assert not channel_clip(np.round(np.sin(2 * np.pi * 0.1 * t) / CODE) * CODE)["clipped"]  # noise-free: a smooth top
    assert not channel_clip(_read(np.sin(2 * np.pi * 0.1 * t), 2e-4, rng))["clipped"]  # measured, not clipped
    # a commanded step stored as the drive (no noise): its plateau is flat, but nothing else moves either
    assert not channel_clip(np.where(np.arange(30000) >= 15000, 1.0, 0.0))["clipped"]
    # a noisy plateau below the range's end
    assert not channel_clip(_read(np.where(np.arange(30000) >= 15000, 1.0, 0.0), 2e-4, rng, top=1.05))["clipped"]


def clip_monitor(s: inject.Session) -> None:
    """The drive amplifier 4 % high into the strip, its output monitored on a DAQ range ending at 1.01 V: the strip's
    signals are 1.04 of the commanded drive's, and the recorded drive is right except where it passes the range's end
    (the 1 V records' plateaus and tops)."""
    for r in s.series():
        r.cols["i_A"], r.cols["disp_m"] = 1.04 * r.cols["i_A"], 1.04 * r.cols["disp_m"]
        r.cols["v_V"] = np.round(np.clip(1.04 * r.cols["v_V"], -1.01, 1.01) / CODE) * CODE


def test_a_clipped_drive_monitor_names_no_cause_and_says_where(bench_sessions, tmp_path, capsys):
    assert main(["export", bench_sessions.get(BENCH_CASES)[0].path, "--out", str(tmp_path / "clean")]) == 0
    s = inject.read_export(tmp_path / "clean", "paper")
    clip_monitor(s)
    h5 = tmp_path / "clipped.h5"
    assert main(["import", str(inject.write_import(s, tmp_path / "clipped")), "--out", str(h5)]) == 0
    capsys.readouterr()
    assert main(["diagnose", str(h5), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    out = out[0] if isinstance(out, list) else out
    assert (out["verdict"], out["cause"], out["effects"]) == ("unexplained", None, [])
    clipped = out["recording"]["clipped"]
    assert clipped["flagged"] and clipped["channels"] == ["drive"]
    assert all("1V" in name for name in clipped["records"]["drive"])  # the 1 V records only: the 0.5 V ones stay inside
    top = out["residual"]["where"][0]
    assert top["block"] == "recording" and "drive reading held at -1.01 V, 1.01 V" in top["detail"]
