"""Step records whose displacement lost its mean before it was stored (issue 12).

An export or an analysis script that "cleans" the laser's drift detrends each record: the least-squares line through
the record's samples (or only its mean: AC coupling in software) taken off the displacement. A sine of whole cycles
loses little. A step record, the strip bent for its first part and relaxing in the rest, loses an offset and a tilt:
its plateau and its rest move off zero, by about half the step. No cause of the catalogue does that to the strip. A
memory or a relaxation fitted to the step's moved plateau is fitted to the script, not the strip: fresh35's detrended
records (seen) were named `hysteresis` and `back_relaxation`.

The strip cannot give a step record of zero mean: it bends one way while driven and relaxes towards rest after, and
even a relaxation that overshoots rest leaves the driven part's area. Read here: per step record, the mean of its
displacement over the RMS of the displacement: 0.93 on the tuning set's clean sessions, 0.35 at the least over the 208
other cached sessions of the seen sets (tuning, fresh31-35: the tuning set's strongest back relaxation). The session
is flagged where every step record reads under ``MEAN_SHARE`` (at least ``MIN_RECORDS`` of them). A detrended record
reads about 1e-13 (fresh35's two), or the quantum of a logger's decimals over the step. The verdict is the
recording's (``engine._recording_decides``), as for a clipped channel. ``MEAN_SHARE`` = 1e-3 is a convention: any
share from 1e-12 to 0.3 splits them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.estimate.session_data import SessionData
from labrig.records import RecordKind

MEAN_SHARE = 1e-3
MIN_RECORDS = 2


def mean_share(d: np.ndarray) -> float:
    """|mean(d)| / RMS(d): what a step record keeps of its own level (0 for a record with its mean taken off)."""
    d = np.asarray(d, float)
    d = d[np.isfinite(d)]
    rms = float(np.sqrt(np.mean(d * d))) if d.size else 0.0
    return abs(float(np.mean(d))) / rms if rms > 0 else float("nan")


def detrended(sd: SessionData) -> dict[str, Any]:
    """Per step record the displacement's mean share; flagged where every one is under ``MEAN_SHARE``."""
    shares = [mean_share(r.d) for r in sd.all_records() if r.kind == RecordKind.STEP and r.d.size >= 16]
    shares = [s for s in shares if np.isfinite(s)]
    largest = max(shares, default=float("nan"))
    return {"records": len(shares), "largest_mean_share": largest, "mean_share": MEAN_SHARE,
            "flagged": len(shares) >= MIN_RECORDS and largest < MEAN_SHARE}
