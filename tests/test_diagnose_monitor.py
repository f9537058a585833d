"""The drive's record read against the current (labrig/diagnose/monitor.py): a monitor whose two polarities read
with different gains puts an even harmonic on the recorded drive that the strip's current does not carry; a drive
really distorted is followed by the current. Read off the suite's clean paper sweep (the forms are the test's own)."""

import dataclasses

import numpy as np
import pytest

from labrig.diagnose.artefacts import MIN_RECORDS
from labrig.diagnose.features import extract
from labrig.diagnose.monitor import MONITOR_SHARE, detail, drive_monitor, record_monitor
from labrig.estimate.session_data import load_session
from labrig.records import SINE_KINDS

BENCH_CASES = [("none", 1)]  # the clean paper sweep, shared with the other diagnosis tests (conftest)


@pytest.fixture(scope="module")
def clean_case(bench_sessions):
    return bench_sessions.get(BENCH_CASES)[0]


@pytest.fixture(scope="module")
def clean_sines(clean_case):
    return extract(load_session(clean_case.path)).sines


def test_the_clean_sweeps_drive_carries_no_harmonic_of_its_own(clean_case, clean_sines):
    """The DAQ's sine: its harmonics a hundredth of the limit; the diagnosis reports the check, unflagged."""
    m = drive_monitor(clean_sines, MIN_RECORDS)
    assert len(clean_sines) >= 20 and m["records"] == 0 and not m["flagged"], m
    shares = [abs(s.est.drive[k] / s.est.drive[0]) for s in clean_sines for k in (1, 2)]
    assert max(shares) < MONITOR_SHARE / 10
    assert clean_case.output["drive_monitor"]["flagged"] is False


def test_a_monitor_reading_its_polarities_apart_is_flagged_in_the_drive_alone(clean_case, clean_sines):
    """The recorded drive x 1.05 while positive, x 0.95 while negative (an optocoupled isolation amplifier's two
    channels mismatched): its 2nd harmonic is 4 g / (3 pi) = 2.1 % of the fundamental and the current has none. Two
    records are needed, as for every recording artefact."""
    sd = load_session(clean_case.path)
    sine_records = [r for r in sd.all_records() if r.kind in SINE_KINDS]
    for r in sine_records:
        r.v = r.v * np.where(r.v > 0, 1.05, 0.95)
    sines = extract(sd).sines
    m = drive_monitor(sines, MIN_RECORDS)
    assert m["flagged"] and m["records"] >= 0.9 * len(sine_records), m
    w = m["worst"]
    assert w["order"] == 2 and w["drive_share"] == pytest.approx(4 * 0.05 / (3 * np.pi), rel=0.1) and w["current_follows"] < 0.05, w
    assert "2nd harmonic" in detail(m) and "monitor" in detail(m)
    k = next(j for j, x in enumerate(sines) if record_monitor(x) is not None)
    one = drive_monitor(clean_sines[:k] + sines[k : k + 1] + clean_sines[k + 1 :], MIN_RECORDS)  # one record's: a knock
    assert one["records"] == 1 and not one["flagged"], one


def test_a_drive_really_distorted_is_followed_by_the_current(clean_sines):
    """The same 2 % harmonic on the drive, and the current carrying it at 1.5 times the drive's share (the strip's
    admittance rising with frequency): not the monitor's. The current carrying a fifth of it is."""

    def distorted(follow: float):
        out = []
        for s in clean_sines:
            drive, cur = s.est.drive.copy(), s.est.current.copy()
            drive[1], cur[1] = 0.02 * drive[0], 0.02 * follow * cur[0]
            out.append(dataclasses.replace(s, est=dataclasses.replace(s.est, drive=drive, current=cur)))
        return out

    assert not drive_monitor(distorted(1.5), MIN_RECORDS)["flagged"]
    assert drive_monitor(distorted(0.2), MIN_RECORDS)["flagged"]
