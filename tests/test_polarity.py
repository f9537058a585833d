"""labrig.fit.polarity: a rig that reads the strip's bend reversed (the laser on the other face) is read with the
model's sign, says so, and fits as the same session read the usual way; a session read the usual way is left alone."""

from __future__ import annotations

import shutil

import h5py
import pytest

from labrig.analysis import load_and_fit
from labrig.estimate.session_data import load_session
from labrig.fit.polarity import displacement_sign, line_agreement, step_agreement

BENCH_FITS = [("none", 2)]  # a clean paper sweep of the shared ones (conftest), fitted only


@pytest.fixture(scope="module")
def sessions(bench_sessions, tmp_path_factory):
    """(a clean paper sweep of the simulated bench, the same file with every displacement negated in place)."""
    path = bench_sessions.get(BENCH_FITS, diagnosed=False)[0].path
    rev = tmp_path_factory.mktemp("polarity") / "reversed.h5"
    shutil.copy(path, rev)
    with h5py.File(rev, "r+") as h:
        for step in h["entry/steps"].values():
            if "daq" in step:
                d = step["daq/disp_m"]
                d[...] = -d[...]
    return path, rev


def test_the_sign_is_read_off_the_frf_and_off_the_steps_without_it(sessions):
    path, rev = sessions
    for p, sign in ((path, 1), (rev, -1)):
        sd = load_session(p)
        assert displacement_sign(sd)[0] == sign
        assert line_agreement(sd) == pytest.approx(sign, abs=0.05)
        assert step_agreement(sd) == sign
        for d in sd.pressures:  # no FRF: the steps alone decide
            d.sines, d.bla = [], None
        assert line_agreement(sd) is None and displacement_sign(sd)[0] == sign


def test_a_reversed_session_fits_as_the_same_session_read_the_usual_way(sessions):
    path, rev = sessions
    sd0, fit0 = load_and_fit(path)
    sd1, fit1 = load_and_fit(rev)
    assert sd0.displacement_sign == 1 and sd1.displacement_sign == -1
    assert not any("runs against the drive" in n for n in fit0.notes)
    assert any("runs against the drive" in n and "opposite sign" in n for n in fit1.notes)
    for a, b in zip(fit0.per_pressure, fit1.per_pressure, strict=True):
        assert b["Kt_bar"] == pytest.approx(a["Kt_bar"], rel=1e-9)
        assert b["peak_disp_m"] == pytest.approx(a["peak_disp_m"], rel=1e-9)
    # read as recorded, the reversed session is not a strip the model can make
    raw = load_session(rev)
    assert raw.displacement_sign == 1 and displacement_sign(raw)[1] < -0.9
