"""A reading that moves before its cause: processing that is not causal (issue 12).

The strip answers its drive; it cannot bend, nor draw current, before the drive's edge. An export script that smooths
a record forward and backward (scipy.signal.filtfilt, a centred moving average, a Savitzky-Golay or spline smoother,
an FFT brick-wall filter) spreads every edge of the response to both sides: the reading leaves its rest level before
the drive moves. No cause of the catalogue does that, and what the forms fit on such a record (a gain that falls with
frequency without a lag, rounded edges) is the script's: fresh36's zero-phase Butterworth on the displacement (outside,
seen) was named `hysteresis` (`play_output` 0.07).

The test, per step record and channel (displacement, current), at each edge of the drive: a line fitted to the
reading over ``BASE_S`` ending ``PRE_S`` before the edge (its rest level and drift) is extrapolated to the edge; the
reading's mean departure from it over the last third of that window, up to ``GUARD`` samples before the edge (an
interpolating resampler or a decimator's short filter spreads an edge by a sample or two), is the precursor. It
counts where it is ``Z`` times its white noise (from the sample-to-sample differences of the base window) and
``SHARE`` of the response's own mean departure over the ``AFTER_S`` after the edge. A record counts where every edge
read does. One record flags the session; ``MIN_RECORDS`` take the verdict from any cause (``decides``,
``engine._recording_decides``) but a time delay: a reading late against its drive record (the drive's monitor late,
a reading aligned on the drive) also leads it, and the family names it (``engine._leads_explain``).

Read on the tuning set's 40 sessions: the displacement departs by 2 noise units at most (by up to 3.7 % of the
response, where the drying strips' trends bend), the current by 5-7 units and 0.2-0.7 % (the simulated converter's own
edge). On the seen sets: fresh36's zero-phase smoothing 230-950 units and 2.4-9 %; fresh32's FFT brick-wall filter on
the current (outside, already `unexplained`) 30-39 units and 5-8 %; the time delays that lead (fresh36's alignment
script) 220-240 units and 60 %. ``Z`` (20) and ``SHARE`` (1 %) are conventions: 3 times the tuning set's largest
noise units (about) and a share above its current's, both required. What the seen sets read is in docs/diagnosis.md ("A
reading that moves before its cause").
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.diagnose.arming import CHANNELS
from labrig.diagnose.clipping import record_tally
from labrig.estimate.session_data import SessionData

PRE_S = 0.04  # the window before the edge read for a precursor
BASE_S = 0.5  # the rest level's window before that
AFTER_S = 0.1  # the response read over this long after the edge, for its direction and size
GUARD = 2  # samples next to the edge not read
Z = 20.0
SHARE = 0.01
MIN_RECORDS = 2


def edge_precursors(v: np.ndarray, x: np.ndarray, fs: float) -> list[tuple[float, float]]:
    """Per edge of the drive ``v`` (a change of half its range from one sample to the next): the reading ``x``'s
    departure from its extrapolated rest just before the edge, as (noise units, share of the response after it),
    signed towards the response. Edges too near the record's ends to read are left out."""
    v, x = np.asarray(v, float), np.asarray(x, float)
    span = float(np.ptp(v)) if v.size else 0.0
    npre, nbase, nafter = int(PRE_S * fs), int(BASE_S * fs), int(AFTER_S * fs)
    if not span > 0 or x.size != v.size or npre < GUARD + 3 or not np.all(np.isfinite(x)):
        return []
    out = []
    for k in np.flatnonzero(np.abs(np.diff(v)) > 0.5 * span) + 1:
        a = k - npre - nbase
        if a < 0 or k + nafter > x.size:
            continue
        base = np.arange(a, k - npre)
        line = np.polyfit(base - k, x[base], 1)
        pre = np.arange(k - npre, k - GUARD)
        m = max(3, pre.size // 3)
        early = x[pre[-m:]] - np.polyval(line, pre[-m:] - k)
        after = x[k:k + nafter] - np.polyval(line, np.arange(nafter, dtype=float))
        size = float(np.mean(after))
        noise = float(np.std(np.diff(x[base]))) / np.sqrt(2.0)
        lead = float(np.mean(early)) * (1.0 if size >= 0 else -1.0)
        out.append((lead / (noise / np.sqrt(m)) if noise > 0 else (np.inf if lead else 0.0),
                    lead / abs(size) if size else 0.0))
    return out


def moves_early(edges: list[tuple[float, float]]) -> bool:
    """Whether every edge read departs before the drive, by ``Z`` noise units and ``SHARE`` of its response, either way
    (a smoother mirrors the response's first part, whichever way that goes)."""
    return bool(edges) and all(abs(z) >= Z and abs(s) >= SHARE for z, s in edges)


def precursor(sd: SessionData) -> dict[str, Any]:
    """Per channel, the step records whose reading leaves its rest before the drive's edges; flagged in one, deciding
    the verdict in ``MIN_RECORDS``."""
    per: dict[str, list[str]] = {}
    largest = 0.0
    for r in sd.all_records():
        if r.kind != "step" or r.t.size < 4:
            continue
        for ch, attr in CHANNELS.items():
            edges = edge_precursors(r.v, getattr(r, attr), r.fs)
            if edges:
                largest = max(largest, min(min(abs(z) / Z, abs(s) / SHARE) for z, s in edges))
            if moves_early(edges):
                per.setdefault(ch, []).append(r.name)
    return {**record_tally(per, MIN_RECORDS), "largest": float(largest), "z": Z, "share": SHARE}
