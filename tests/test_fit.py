"""The seed-000 fitter on simulated sessions whose truth is known, on thin data, and on imported data."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from labrig.analysis import run_fit
from labrig.physics import presets, transfer
from labrig.physics.params import TABLE2_KT_BAR
from labrig.session_run import RunRequest, execute
from labrig.store import SessionFile

DATA = Path(__file__).parent / "data"


BENCH_FITS = [("none", 1)]  # the clean paper sweep, shared with the other files that read it (conftest)


@pytest.fixture(scope="module")
def sweep(bench_sessions):
    path = bench_sessions.get(BENCH_FITS, diagnosed=False)[0].path
    return path, run_fit(path)


def test_fit_json_contract(sweep):
    _, out = sweep
    for key in ("per_pressure", "optimum_pressure_kPa", "alpha", "gamma"):
        assert key in out
    for row in out["per_pressure"]:
        for key in ("pressure_kPa", "R_cont_ohm", "f1_Hz", "Kt_bar", "peak_disp_m"):
            assert key in row and row[key] is not None
    json.dumps(out)  # plain JSON


def test_sweep_recovers_table2_and_f1(sweep):
    _, out = sweep
    paper = presets.get("paper")
    for row, kt in zip(out["per_pressure"], TABLE2_KT_BAR):
        truth_f1 = transfer.modal_set(paper.specimen(row["pressure_kPa"])).f_Hz[0]
        assert row["f1_Hz"] == pytest.approx(truth_f1, rel=0.01)
        assert abs(row["Kt_bar"] - kt) < 4 * row["Kt_bar_stderr"] + 0.002 * kt
    assert out["gamma"] == pytest.approx(0.14, rel=0.05)
    assert out["alpha"] == pytest.approx(0.105, rel=0.05)


def test_optimum_is_the_pressure_with_the_largest_measured_step(sweep):
    _, out = sweep
    peaks = {r["pressure_kPa"]: r["peak_disp_m"] for r in out["per_pressure"]}
    assert out["optimum_pressure_kPa"] == max(peaks, key=peaks.get)


def test_results_are_stored_in_the_session(sweep):
    path, out = sweep
    stored = SessionFile(path).read_analysis("fit_seed000")
    assert json.loads(stored["result_json"])["per_pressure"][0]["Kt_bar"] == pytest.approx(out["per_pressure"][0]["Kt_bar"])
    assert np.allclose(stored["pressure_kPa"], [612, 1837, 3062, 4287])


def test_thin_data_gives_nulls_and_notes_not_a_crash(tmp_path):
    path = tmp_path / "step.h5"
    assert execute(RunRequest("step", path)).exit_code == 0
    out = run_fit(path)
    row = out["per_pressure"][0]
    assert row["R_cont_ohm"] is None and row["Kt_bar"] is None and row["f1_Hz"] is None
    assert row["peak_disp_m"] > 1e-3
    assert out["alpha"] is None and out["optimum_pressure_kPa"] is None
    notes = " ".join(out["notes"])
    assert "no impedance spectrum" in notes and "no stepped-sine FRF" in notes and "fewer than two pressures" in notes
    assert out["seed001"] is None  # a single step cannot tell a nonlinearity


def test_imported_data_is_fitted_like_a_session(tmp_path):
    out_h5 = tmp_path / "imported.h5"
    r = subprocess.run([sys.executable, "-m", "labrig", "import", str(DATA / "import_example" / "manifest.toml"), "--out", str(out_h5)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    r = subprocess.run([sys.executable, "-m", "labrig", "fit", str(out_h5), "--json", "--seed001", "on", "--seed001-law", "butler_volmer"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    rows = {row["pressure_kPa"]: row for row in out["per_pressure"]}
    assert set(rows) == {612, 3062}
    assert all(row["peak_disp_m"] > 0 and row["clamp"]["R_c"]["status"] == "fitted" for row in rows.values())
    # a spectrum alone cannot tell R_cont from the CPE resistances (docs/model.md 9): held, null, and said
    assert all(row["R_cont_ohm"] is None and row["R_cont_status"] == "fixed" for row in rows.values())
    assert any("R_cont held" in n for n in out["notes"])
    assert out["optimum_pressure_kPa"] in (612, 3062)
    assert out["alpha"] is None  # one stepped sine cannot make an FRF: said, not guessed
    assert any("FRF" in n for n in out["notes"])
    # seed 001 asked for on imported steps, with the Butler-Volmer law: its parameters, fitted to the steps
    h = out["seed001"]
    assert h["law"] == "butler_volmer" and h["records"] == ["p612/step", "p3062/step"]
    assert {"i0", "v_t"} <= set(h["params"]) and "g3" not in h["params"]
    assert h["nrmse_displacement"] < 0.05  # the linear current -> displacement stage follows the model's steps


def test_amplitude_series_gets_the_hammerstein_fit(tmp_path):
    path = tmp_path / "amp.h5"
    assert execute(RunRequest("amplitude-series", path)).exit_code == 0
    out = run_fit(path)
    h = out["seed001"]
    assert h is not None and h["nrmse_current"] < 0.05
    assert abs(h["params"]["g3"]) < 1e-4  # the simulated strip is linear: no cubic conductance to find
    assert SessionFile(path).read_analysis("fit_seed001")


def test_a_record_with_nans_is_left_out_with_a_note(tmp_path):
    """A stored record whose displacement holds NaNs (a laser dropout) is named in the notes and left out; the FRF
    fit goes on with the other frequencies."""
    import gzip
    import shutil

    import h5py

    path = tmp_path / "stepped-sine.h5"
    with gzip.open(DATA / "sessions" / "stepped-sine.h5.gz") as src, open(path, "wb") as dst:
        shutil.copyfileobj(src, dst)
    with h5py.File(path, "r+") as f:
        steps = f["entry/steps"]
        name = next(n for n in steps if steps[n].attrs["kind"] == "stepped_sine")
        disp = steps[name]["daq/disp_m"]
        disp[10:20] = np.nan
        label = steps[name].attrs["name"]
    out = run_fit(path)
    assert any(label in n and "NaN" in n for n in out["notes"]), out["notes"]
    assert out["alpha"] is not None and np.isfinite(out["alpha"]) and np.isfinite(out["per_pressure"][0]["f1_Hz"])


def test_the_daq_current_chooses_along_the_spectra_valley_but_does_not_overrule_them():
    """The electrical stage joins the DAQ's current admittance to the spectra (it pins their shallow valley). A current
    that agrees (the strip's own, 0.1 % noise) is joined and the spectra stay at their noise; a current read 20 ms late
    (a potentiostat's stream put on the DAQ's rows) or through a 1 ms lag (a shunt amplifier's filter) is a phase the
    electrical values cannot make: joined, it would put the spectra beyond their noise, so the spectra's values are kept
    and the stage says so."""
    from types import SimpleNamespace

    import numpy as np

    from labrig.fit.seed000 import CURRENT_AGREES, fit_electrical, fit_impedance
    from labrig.fit.seed000_problem import Problem
    from labrig.physics import impedance, presets, transfer

    rng = np.random.default_rng(4)
    pressures = (612.0, 1837.0, 3062.0)
    priors = {p: presets.get("paper").specimen(p) for p in pressures}
    truth = priors  # the fit starts there: what moves it is the data's noise and the current's delay
    f_eis, f_cur = np.logspace(-1, 4, 30), np.array([0.1, 0.3, 1.0, 3.0, 10.0, 20.0])

    def data(delay_s: float, lag_s: float = 0.0) -> list:
        out = []
        for p in pressures:
            z = impedance.impedance(2j * np.pi * f_eis, truth[p]) * (1 + 1e-3 * (rng.normal(size=f_eis.size) + 1j * rng.normal(size=f_eis.size)))
            y = transfer.admittance_tf(2j * np.pi * f_cur, truth[p]) * np.exp(-2j * np.pi * f_cur * delay_s) / (1 + 2j * np.pi * f_cur * lag_s)
            y = y * (1 + 1e-4 * rng.normal(size=f_cur.size))
            out.append(SimpleNamespace(pressure_kPa=p, eis=(f_eis, z), current_lines=lambda y=y: (f_cur, y, 1e-4 * np.abs(y))))
        return out

    # the last: the current read through a 1 ms first-order lag (a shunt amplifier's RFI filter)
    for delay, lag, agrees in ((0.0, 0.0, True), (0.02, 0.0, False), (0.0, 0.001, False)):
        d = data(delay, lag)
        res, sigma, said = fit_electrical(d, priors)
        assert said is agrees
        eis_rms = np.sqrt(np.mean(Problem(priors, eis=d, sigma_eis=sigma).residual(res.params) ** 2))
        assert eis_rms < CURRENT_AGREES
        if not agrees:
            alone = fit_impedance(d, priors)[0]
            assert res.params.valuesdict() == alone.params.valuesdict()  # the spectra's own values
            joined = Problem(priors, eis=d, cur=d, sigma_eis=sigma)
            forced = joined.minimize(alone.params)
            assert np.sqrt(np.mean(forced.residual[: joined.offsets[len(d)]] ** 2)) > 5 * CURRENT_AGREES  # the defect


def test_a_branch_the_current_carries_beside_the_spectra_is_joined_and_the_spectras_own_values_kept_beside():
    """A faradaic branch past its onset draws a current at the DAQ's 0.5-1 V that the analyser's small signal barely
    sees: joined, the current moves the electrical values a long way (its RMS falls by more than CURRENT_MOVES) and
    puts the spectra beyond their noise. The join is the stage's result (a drying moves both alike), and the spectra's
    own values are kept beside it (``electrical_stage``'s fourth value), on which the diagnosis judges a branch of the
    current; a clean current leaves none beside."""
    from types import SimpleNamespace

    import numpy as np

    from labrig.fit.seed000 import CURRENT_AGREES, CURRENT_MOVES, current_agreement, electrical_stage, fit_impedance
    from labrig.physics import impedance, presets, transfer

    rng = np.random.default_rng(5)
    pressures = (612.0, 1837.0, 3062.0)
    priors = {p: presets.get("paper").specimen(p) for p in pressures}
    f_eis, f_cur = np.logspace(-1, 4, 30), np.array([0.1, 0.3, 1.0, 3.0, 10.0, 20.0])

    def data(branch_S: float) -> list:
        out = []
        for p in pressures:
            z = impedance.impedance(2j * np.pi * f_eis, priors[p]) * (1 + 1e-3 * (rng.normal(size=f_eis.size) + 1j * rng.normal(size=f_eis.size)))
            y = (transfer.admittance_tf(2j * np.pi * f_cur, priors[p]) + branch_S) * (1 + 1e-4 * rng.normal(size=f_cur.size))
            out.append(SimpleNamespace(pressure_kPa=p, eis=(f_eis, z), current_lines=lambda y=y: (f_cur, y, 1e-4 * np.abs(y))))
        return out

    clean = electrical_stage(data(0.0), priors)
    assert clean[2] is True and clean[3] is None
    d = data(2e-3)  # 2 mS: 1 mA at 0.5 V, beside the strip's 10-30 mS at 0.1 Hz
    res, sigma, agrees, alone = electrical_stage(d, priors)
    _, spectra_rms, fall = current_agreement(d, priors, fit_impedance(d, priors)[0], sigma)
    assert spectra_rms > CURRENT_AGREES and fall > CURRENT_MOVES  # the case: the join disputed, the current moved far
    assert agrees is True and alone is not None
    assert alone.params.valuesdict() == fit_impedance(d, priors)[0].params.valuesdict()
    assert res.params.valuesdict() != alone.params.valuesdict()
