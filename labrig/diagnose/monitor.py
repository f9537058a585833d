"""The drive's record read against the current: harmonics on the recorded drive that the strip never felt.

The strip is driven through the DAQ's analogue output or an amplifier, and the drive is recorded through a monitor of
its own (an isolation amplifier, a divider into an input channel). A distortion of the drive itself (an amplifier's
crossover or slew, a supply sagging under the strip's current) reaches the strip, and the current follows it: the
strip's admittance carries the drive's k-th harmonic at |Y(kf)/Y(f)| of the drive's share, 1 or more for a strip that
is resistive and capacitive (its admittance rises with frequency to 1/R). A distortion of the monitor alone (its two
polarities' channels mismatched, a stage of its own saturating) puts the harmonic on the record and not on the
current. No catalogued effect does that: each acts through the strip, its electrodes or the sensor, and a model
driven by such a record predicts harmonics that are not there. A faradaic branch adds harmonics to the current, never
removes the drive's, so it cannot make a real distortion read as the monitor's.

Per sine record and harmonic k = 2, 3: the drive's share h_v = |V_k / V_1| and the current's h_i = |I_k / I_1|. The
record counts where h_v > ``MONITOR_SHARE`` and h_i < ``MONITOR_FOLLOW`` h_v, and the session is flagged in
``artefacts.MIN_RECORDS`` records or more. ``MONITOR_SHARE`` stands far above a clean session's drive (a DAQ's
output: about 1e-4; the largest of 272 held-out sessions 9.9e-4, a record whose sines were re-synthesised);
``MONITOR_FOLLOW`` far below the 1 or more a real distortion gives (docs/diagnosis.md, "The drive's monitor").
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.diagnose.features import SineFeature

MONITOR_SHARE = 0.005  # the drive's harmonic over its fundamental
MONITOR_FOLLOW = 0.25  # the current's share of it, over the drive's, below which the strip did not feel it
ORDERS = (2, 3)


def record_monitor(s: SineFeature) -> tuple[int, float, float] | None:
    """(order, drive share, current share over the drive's) of the record's worst harmonic the current does not
    follow; None where none does or the record cannot tell (no current, one harmonic estimated)."""
    e = s.est
    v1, i1 = complex(e.drive[0]), complex(e.current[0])
    if not (abs(v1) > 0 and abs(i1) > 0 and np.isfinite(abs(i1))):
        return None
    worst = None
    for k in ORDERS:
        if len(e.drive) < k or len(e.current) < k:
            continue
        hv, hi = abs(e.drive[k - 1] / v1), abs(e.current[k - 1] / i1)
        if hv > MONITOR_SHARE and hi < MONITOR_FOLLOW * hv and (worst is None or hv > worst[1]):
            worst = (k, float(hv), float(hi / hv))
    return worst


def drive_monitor(sines: list[SineFeature], min_records: int) -> dict[str, Any]:
    """The sine records whose drive carries a harmonic the current does not, and whether the session is flagged."""
    hits = [(s, m) for s in sines if (m := record_monitor(s)) is not None]
    worst = max(hits, key=lambda h: h[1][1], default=None)
    return {"records": len(hits), "names": [s.name for s, _ in hits][:8], "flagged": len(hits) >= min_records,
            "worst": None if worst is None else {"record": worst[0].name, "order": worst[1][0], "drive_share": worst[1][1],
                                                 "current_follows": worst[1][2]},
            "share_limit": MONITOR_SHARE, "follow_limit": MONITOR_FOLLOW}


def detail(m: dict[str, Any]) -> str:
    """One line for the report and the JSON's ``residual.where``."""
    w = m["worst"]
    return (f"the recorded drive carries a {w['order']}{'nd' if w['order'] == 2 else 'rd'} harmonic of {w['drive_share']:.2%} of its "
            f"fundamental that the current does not follow ({w['current_follows']:.2f} of it; {m['records']} sine records, worst "
            f"{w['record']}): the drive's monitor is distorted, not the drive the strip felt")
