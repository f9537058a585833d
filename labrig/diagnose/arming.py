"""A transient at each record's arming: the rest before a step's edge is not at rest for its first moment.

A relay or a solenoid switched as a record is armed rings the laser's stand, an amplifier enabled for the record
settles, a converter's first readings after its range is set glitch: something happens at the start of every record,
before the strip is driven. The model predicts rest there, and the step's noise is read from the same readings, so no
feature block sees it: the sines' demodulation skips their first cycles, a step's blocks count the pre-edge readings
as its noise floor. Read here instead: per step record and channel, the sample-to-sample scatter (the RMS of first
differences: a slow settling of the strip from the record before hardly moves it, a ring does) over the first
``WINDOW_S`` of the pre-edge rest against the median of the rest's later windows. For white noise the ratio of two
RMS of n differences scatters by about 1/sqrt(2 n), so the ratio is read as z = (ratio - 1) sqrt(2 n), a record
carrying a transient where z > ``ARMING_Z``, the session when ``MIN_RECORDS`` do (a knock on the table happens once).

``ARMING_Z`` = 6, the bursts' convention (artefacts.BURST_Z). Tuning set's ten clean sessions: the largest record
3.4, the second largest of a session at most 1.3. The clean sessions and effects of fresh12-15 (102 sessions, every
data shape, never used to set it): ratios at most 1.23 on the session's second record. Fresh15's relay at arming
(seen when this was written): 3.9 and 7.4. A rest with rows filled in (``TimeRecord.filled``: a logger that kept only
the rows it needed, a buffer's lost packets) is not read: its interpolated samples have no scatter to compare with.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.estimate.session_data import SessionData, TimeRecord, step_onset

WINDOW_S = 0.1  # the transient's moment: a relay's ring, an amplifier's settling
ARMING_Z = 6.0
MIN_WINDOWS = 4  # windows of rest the first one is compared with, at least
MIN_SAMPLES = 5  # differences per window, at least
EDGE_GUARD_S = 0.02  # the rest ends this long before the edge (the drive's own rise)
CHANNELS = {"displacement": "d", "current": "i"}


def record_arming(r: TimeRecord) -> dict[str, float] | None:
    """Per channel: z of the first window's scatter over the rest's (None: not a step, or too little rest)."""
    if r.kind != "step" or r.t.size < 16:
        return None
    rest = r.t < step_onset(r) - EDGE_GUARD_S
    if r.filled.size and np.any(r.filled[rest]):
        return None  # a rest partly interpolated (a logger that thinned it): its scatter is not the readings'
    n = max(int(round(WINDOW_S * r.fs)), MIN_SAMPLES)
    out = {}
    for ch, attr in CHANNELS.items():
        d = np.diff(getattr(r, attr)[rest])
        k = d.size // n
        if k < MIN_WINDOWS + 1:
            return None
        w = np.sqrt(np.mean(d[: k * n].reshape(k, n) ** 2, axis=1))
        ref = float(np.median(w[1:]))
        out[ch] = float((w[0] / ref - 1.0) * np.sqrt(2 * n)) if ref > 0 else 0.0
    return out


def arming(sd: SessionData, min_records: int) -> dict[str, Any]:
    """The session's records with a transient at their arming, by channel, and whether it is flagged."""
    per = [(r.name, z) for r in sd.all_records() for z in [record_arming(r)] if z is not None]
    hit = [(name, z) for name, z in per if max(z.values()) > ARMING_Z]
    worst = sorted((max(z.values()) for _, z in per), reverse=True)
    return {"records": [name for name, _ in hit], "records_read": len(per),
            "channels": sorted({ch for _, z in hit for ch, v in z.items() if v > ARMING_Z}),
            "second_z": float(worst[1]) if len(worst) > 1 else 0.0, "z_limit": ARMING_Z, "window_s": WINDOW_S,
            "flagged": len(hit) >= min_records}
