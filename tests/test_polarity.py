"""labrig.fit.polarity and the loader's spectrum convention: a rig whose channels count the other way (the laser on
the strip's other face, a potentiostat counting the other current positive, an analyser exporting -Z'') is read with
the model's conventions, says so, and fits as the same session read the usual way; a session read the usual way is
left alone."""

from __future__ import annotations

import shutil

import h5py
import numpy as np
import pytest

from labrig.analysis import load_and_fit
from labrig.estimate.session_data import load_session
from labrig.fit.polarity import admittance_agreement, current_sign, displacement_sign, line_agreement, step_agreement

BENCH_FITS = [("none", 2)]  # a clean paper sweep of the shared ones (conftest), fitted only


def _negated(path, out, *datasets: str):
    """A copy of the session at ``path`` with the named datasets of every step (``daq/disp_m``, ...) negated."""
    shutil.copy(path, out)
    with h5py.File(out, "r+") as h:
        for step in h["entry/steps"].values():
            for name in datasets:
                if name in step:
                    step[name][...] = -step[name][...]
    return out


@pytest.fixture(scope="module")
def sessions(bench_sessions, tmp_path_factory):
    """(the shared clean sweep, its seed-000 fit as `labrig fit --json` prints it, the same file with every
    displacement and current negated and its spectra written as -Z'')."""
    case = bench_sessions.get(BENCH_FITS, diagnosed=False)[0]
    out = tmp_path_factory.mktemp("polarity") / "conventions.h5"
    return case.path, case.fit, _negated(case.path, out, "daq/disp_m", "daq/i_A", "eis/z_im_ohm")


def test_each_sign_is_read_off_the_lines_and_off_the_steps_without_them(sessions):
    path, _, flipped = sessions
    for p, sign in ((path, 1), (flipped, -1)):
        sd = load_session(p)
        assert displacement_sign(sd)[0] == sign and current_sign(sd)[0] == sign
        assert line_agreement(sd) == pytest.approx(sign, abs=0.05) and admittance_agreement(sd) == sign
        assert step_agreement(sd) == sign and step_agreement(sd, "i", 0.1) == sign
        for d in sd.pressures:  # no FRF: the steps alone decide
            d.sines, d.bla = [], None
        assert line_agreement(sd) is None and admittance_agreement(sd) is None
        assert displacement_sign(sd)[0] == sign and current_sign(sd)[0] == sign


def test_spectra_written_as_minus_z_are_read_as_z(sessions):
    path, _, flipped = sessions
    orig, raw = load_session(path), load_session(flipped)
    assert any("read as -Z''" in n for n in raw.notes) and not any("-Z''" in n for n in orig.notes)
    for a, b in zip(orig.pressures, raw.pressures, strict=True):
        assert np.array_equal(a.eis[1], b.eis[1])  # conjugated back, bit for bit


def test_a_session_read_the_other_way_fits_as_the_same_session_read_the_usual_way(sessions):
    path, fit0, flipped = sessions
    raw = load_session(flipped)
    assert displacement_sign(raw)[1] < -0.9  # read as recorded, not a strip the model can make
    sd, fit = load_and_fit(flipped)
    assert (sd.displacement_sign, sd.current_sign) == (-1, -1)
    assert any("the displacement runs against the drive" in n and "opposite sign" in n for n in fit.notes)
    assert any("the current runs against the drive" in n for n in fit.notes)
    assert not any("runs against the drive" in n for n in fit0["notes"])
    for a, b in zip(fit0["per_pressure"], fit.to_json()["per_pressure"], strict=True):
        for k in ("Kt_bar", "R_cont_ohm", "peak_disp_m"):
            assert b[k] == pytest.approx(a[k], rel=1e-9), k
