"""Issue 12 in the suite: a form the simulator does not make, written into an exported clean sweep by the
validation set's injector (bench/inject.py), imported and diagnosed as a user would. The whole validation set
(every form x three seeds, structures outside the catalogue, protocol variants) is run by bench/diagnose.py, and the
issue's further probes (an exponential electrolysis branch, hum on the drive monitor) by bench/diagnose_probes.py;
here, on the suite's clean seed-1 sweep exported once: the structure outside the catalogue, a moment of the step
records the whole record's RMS dilutes (step_windows.py), a drive monitor that clips and a laser whose register wraps
(clipping.py). A faradaic branch the spectra do not see is tests/test_diagnose_spectra_branch.py (a module of its own:
the suite's two workers share the end-to-end diagnoses)."""

import json

import numpy as np
import pytest
from scipy import signal

from bench import diagnose_probes as probes
from bench import inject
from labrig.cli import main
from labrig.diagnose.verdict import STRUCTURE_MARGIN
from test_diagnose_clipping import _wrapped

BENCH_CASES = [("none", 1)]  # shared with test_fit and the coverage (conftest)


@pytest.fixture(scope="module")
def exported(bench_sessions, tmp_path_factory):
    folder = tmp_path_factory.mktemp("injected")
    assert main(["export", bench_sessions.get(BENCH_CASES)[0].path, "--out", str(folder / "clean")]) == 0
    return folder


def imported_and_diagnosed(s, folder, capsys) -> dict:
    """The injected session written as CSVs, imported and diagnosed from the command line: its JSON."""
    h5 = folder.with_suffix(".h5")
    assert main(["import", str(inject.write_import(s, folder)), "--out", str(h5)]) == 0
    capsys.readouterr()
    assert main(["diagnose", str(h5), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    return out[0] if isinstance(out, list) else out


def test_a_structure_outside_the_catalogue_is_unexplained_and_located(exported):
    """A fixture resonance in the displacement path: no catalogued extension removes it, the verdict says so and
    points at the displacement FRF in a band around the resonance (3-8 Hz drawn)."""
    write, check = probes.PROBES["fixture_resonance"]
    out = probes.diagnosed(exported, "fixture_resonance", write)
    assert check(out) == "", (out["verdict"], out["cause"], out["residual"])


def meniscus_drag(s) -> None:
    """A water meniscus bridging the tip and a nearby wall: after each step's fall it holds the tip back by 3 % of the
    step's peak, let go within 0.1 s (a pull that decays as the bridge thins); nothing on the sines, nothing elsewhere
    in the step records. The whole step records' RMS residual barely moves (the moment is a hundredth of the record)."""
    for r in s.series():
        if r.kind != "step":
            continue
        t, v, d = r.cols["t_s"], r.cols["v_V"], r.cols["disp_m"]
        fall = t[int(np.flatnonzero(v > 0.5)[-1]) + 1]
        peak = float(np.max(np.abs(d)))
        after = np.clip(t - fall, 0.0, None)
        r.cols["disp_m"] = d + np.where(t >= fall, 0.03 * peak * np.exp(-after / 0.1), 0.0)


def two_pressures_dragged(s) -> None:
    inject.v_two_pressures(s)  # two of the four pressures, a step record each: the test needs no more, the fits half the time
    meniscus_drag(s)


def test_a_moment_of_the_step_the_record_dilutes_is_unexplained_and_located(exported):
    out = probes.diagnosed(exported, "meniscus_drag", two_pressures_dragged)
    assert (out["verdict"], out["cause"]) == ("unexplained", None), (out["verdict"], out["cause"], out["residual"])
    top = out["residual"]["where"][0]
    assert top["block"] == "step_window" and top["structure"]
    sw = out["baseline"]["step_window"]
    # the worst window holds the drag's first 0.25 s after the fall (the suite's steps: 1 s before the edge, 30 s on)
    assert 30.7 <= sw["worst_time_s"] <= 31.2, top
    assert 0.005 < sw["share"] < 0.03  # the drag is 3 % at the fall and decays in 0.1 s: the window's RMS holds part of it


def flake_on_the_first_setting(s) -> None:
    """Two of the four pressures; through the lower one's step record (the fitted half's: engine.split) a flake lodged
    against the tip holds it while the bend stays within 2 % of the session's largest bend of where it stuck (dry
    friction, sample by sample, the laser's noise on the reading); the operator fishes it out before the sines (which
    the seed-000 fit reads, so the baseline is not bent by it), and the other setting runs free."""
    inject.v_two_pressures(s)
    low = min(float(r.entry["pressure_kPa"]) for r in s.series())
    half = 0.02 * max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series())
    for r in s.series():
        if float(r.entry["pressure_kPa"]) != low or r.kind != "step":
            continue
        # the laser's own noise (above 0.15 of the rate, far above every drive) stays on the held reading (frozen.py)
        d = signal.sosfiltfilt(signal.butter(2, 0.3, output="sos"), r.cols["disp_m"])
        noise = r.cols["disp_m"] - d
        y = np.empty_like(d)
        y[0] = d[0]
        for k in range(1, d.size):
            y[k] = min(max(y[k - 1], d[k] - half), d[k] + half)
        r.cols["disp_m"] = y + noise


def test_an_episode_on_the_fitted_half_alone_is_not_none(exported):
    """The held-out half at its floor says nothing of a misfit on the fitted half's setting alone: the baseline is the
    same strip on both, so the verdict is ``unexplained`` and says where (engine.FIT_HALF_MARGIN), not ``none``."""
    out = probes.diagnosed(exported, "flake_on_the_first_setting", flake_on_the_first_setting)
    b = out["baseline"]
    held = {k: b["blocks"][k] / b["accuracy"][k] for k in b["blocks"]}
    assert max(held.values()) < STRUCTURE_MARGIN, held  # the held-out half shows no structure of its own
    assert out["verdict"] == "unexplained", (out["verdict"], out["cause"])
    top = out["residual"]["where"][0]
    assert top["block"].startswith("fitted_half.") and str(out["split"]["fit"]) in top["detail"], top
    assert top["over_accuracy"] > 5.0, top


def thinned_steps(s) -> None:
    """A logger that keeps a step record at full rate for 0.2 s after each change of the drive (and before the first)
    and thins the rest to one averaged row per interval growing by a third each time: a record of a few hundred rows
    for a 60 s step, none spanning a change."""
    inject.v_two_pressures(s)  # two of the four pressures: the verdict needs no more, and the fits take half the time
    for r in s.series():
        if r.kind != "step":
            continue
        t, v = r.cols["t_s"], r.cols["v_V"]
        changes = t[1:][np.abs(np.diff(v)) > 0.3]
        rows, k, width = [], 0, 2.0
        while k < t.size:
            since = t[k] - changes[changes <= t[k]].max() if np.any(changes <= t[k]) else -1.0
            if since < 0.2:
                rows.append(slice(k, k + 1))
                k, width = k + 1, 2.0
                continue
            end = min(k + int(width), t.size)
            ahead = np.flatnonzero(np.isin(t[k + 1:end], changes))  # never across a change
            end = k + 1 + int(ahead[0]) if ahead.size else end
            rows.append(slice(k, end))
            k, width = end, width * 4 / 3
        r.cols = {name: np.array([col[sl].mean() for sl in rows]) for name, col in r.cols.items()}


def test_steps_logged_on_a_thinning_time_base_diagnose_as_clean(exported):
    """The samples a thinned step record does not hold are not compared, and its drive holds across each gap: a clean
    sweep so logged reads ``none``, its step blocks within the verdict's margin of their accuracy (before: every
    sample compared, the drive interpolated into a ramp before each fall, the current's step block read 111 x its
    accuracy, the displacement's 5 x: ``unexplained``)."""
    out = probes.diagnosed(exported, "thinned_steps", thinned_steps)
    assert (out["verdict"], out["cause"]) == ("none", None), (out["verdict"], out["residual"]["where"][:2])
    b = out["baseline"]
    # within the verdict's own margin of their accuracy (0.2-0.4 x on most suite sweeps; 1.03 x once, on a clean sweep
    # whose steps the paper model met less well than usual: its own diagnosis none)
    over = {k: b["blocks"][k] / b["accuracy"][k] for k in ("step_i", "step_d")}
    assert all(r < STRUCTURE_MARGIN for r in over.values()), over


CODE = 2.0 / 65536  # a 16-bit converter on +-1 V


def clip_monitor(s: inject.Session) -> None:
    """The drive amplifier 4 % high into the strip, its output monitored on a DAQ range ending at 1.01 V: the strip's
    signals are 1.04 of the commanded drive's, and the recorded drive is right except where it passes the range's end
    (the 1 V records' plateaus and tops)."""
    for r in s.series():
        r.cols["i_A"], r.cols["disp_m"] = 1.04 * r.cols["i_A"], 1.04 * r.cols["disp_m"]
        r.cols["v_V"] = np.round(np.clip(1.04 * r.cols["v_V"], -1.01, 1.01) / CODE) * CODE


def test_a_clipped_drive_monitor_names_no_cause_and_says_where(exported, tmp_path, capsys):
    """labrig/diagnose/clipping.py end to end, from the command line (its test on synthetic readings:
    tests/test_diagnose_clipping.py)."""
    s = inject.read_export(exported / "clean", "paper")
    inject.v_two_pressures(s)  # two of the four pressures: the verdict needs no more, and the fits take half the time
    clip_monitor(s)
    out = imported_and_diagnosed(s, tmp_path / "clipped", capsys)
    assert (out["verdict"], out["cause"], out["effects"]) == ("unexplained", None, [])
    clipped = out["recording"]["clipped"]
    assert clipped["flagged"] and clipped["channels"] == ["drive"]
    assert len(clipped["records"]["drive"]) == 4  # the 1 V step and harmonic at each pressure: the 0.5 V sines stay inside
    assert all("1V" in name for name in clipped["records"]["drive"])
    top = out["residual"]["where"][0]
    assert top["block"] == "recording" and "drive reading held at -1.01 V, 1.01 V" in top["detail"]  # the tops and troughs


def test_a_laser_read_through_a_wrapping_register_names_no_cause_and_says_where(exported, tmp_path, capsys):
    """clipping.wrapping end to end: the laser read over a signed int16 register of 0.05 um, its 8.8 mm steps carried
    round at +-1.64 mm (crossing 8.19 mm on the slow approach to the plateau). Without the test a wrapped step reads as
    a compressed large deflection or a relaxation. (At 0.1 um, +-3.28 mm, each step crosses only within its fast rise
    and fall, next to the drive's edges where a jump is the step's own: one suite sweep in four had a record so read.)"""
    s = inject.read_export(exported / "clean", "paper")
    inject.v_two_pressures(s)
    for r in s.series():
        r.cols["disp_m"] = _wrapped(r.cols["disp_m"], 5e-8)
    out = imported_and_diagnosed(s, tmp_path / "wrapped", capsys)
    assert (out["verdict"], out["cause"], out["effects"]) == ("unexplained", None, []), out["recording"]["wrapped"]
    wrapped = out["recording"]["wrapped"]
    assert wrapped["flagged"] and wrapped["channels"] == ["displacement"] and len(wrapped["records"]["displacement"]) == 2
    assert out["residual"]["where"][0]["block"] == "recording" and "span or more in one sample" in out["residual"]["where"][0]["detail"]


def test_a_capacitor_in_the_drive_line_takes_the_verdict_from_a_relaxation(exported, tmp_path, capsys):
    """rivals.SERIES_ELEMENT and drive_line.py end to end: a 83 mF capacitor between the recorded drive and the strip
    (each record from rest, the strip's own admittance at its pressure), the analyser wired at the strip. The
    capacitor's divider relaxes the steps, which a relaxation takes (0.15); the element read off the DAQ against the
    analyser and refitted behind takes the verdict from it (0.03), its capacitance found. (At 0.2 F the sines'
    current sits near the structure margin, 1.5x its accuracy, from one run of the simulated bench to the next: the
    element's gate needs both channels' linear response missed.)"""
    from labrig.physics import presets, timeresp, transfer

    s = inject.read_export(exported / "clean", "paper")
    inject.v_two_pressures(s)
    strip = presets.get("paper")
    for r in s.series():
        sp = strip.specimen(float(r.entry["pressure_kPa"]))
        divider = lambda z, sp=sp: 1 / (1 + 12.0 / z * transfer.admittance_tf(z, sp))  # noqa: E731  (1/C = 12 F^-1)
        for col in ("i_A", "disp_m"):
            x = r.cols[col]
            r.cols[col] = x[0] + timeresp.simulate(divider, x - x[0], r.fs)
    out = imported_and_diagnosed(s, tmp_path / "capacitor", capsys)
    assert (out["verdict"], out["cause"]) == ("unexplained", None), (out["drive_path"], out["candidates"][:2], out["baseline"]["missed"])
    rival = out["drive_path"]
    assert rival["form"] == "series_element" and rival["heldout_ratio"] < rival["its_ratio"]
    assert rival["params"]["elastance_per_F"] == pytest.approx(12.0, rel=0.1) and rival["params"]["series_ohm"] < 0.5
    assert out["residual"]["where"][0]["block"] == "drive" and "series element" in out["residual"]["where"][0]["detail"]
