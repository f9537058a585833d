"""A departure from the step response that lasts a fraction of a second.

The step block's level is an RMS over whole records with a relative model floor (``engine.STEP_FLOOR``), so a
residual confined to a moment of the record is diluted by the rest: the tip slowed by the water squeezed out between
it and a nearby wall after each fall, a strip that touches a cable or a guard for a moment, a contact that sticks
and releases. Read here instead: per step record, the largest RMS over ``WINDOW_S`` windows of the baseline's
displacement residual, as a share of the predicted step's peak. The session's level is the second largest record's
(a moment in one record may be a knock on the table: two records, as the recording's artefacts). It is structure
above ``verdict.STRUCTURE_MARGIN`` x ``STEP_WINDOW_ACCURACY``, the level the baseline attains on clean benches.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.diagnose.catalogue import Context, baseline
from labrig.diagnose.features import gap_timing_sigma, specimen_for

WINDOW_S = 0.25
# 1.25 x the largest of the tuning set's ten clean sessions (0.188 % of the step's peak; the clean sessions of
# fresh9-fresh14, never used for it: at most 0.189 %), as ``engine.CLEAN_ACCURACY``. Noise alone is 0.002 %: the
# level is the model's own misfit, which a strip's seed moves between 0.01 and 0.19 %
STEP_WINDOW_ACCURACY = 0.0024


def worst_window(residual: np.ndarray, t: np.ndarray) -> tuple[float, float]:
    """(largest RMS over consecutive ``WINDOW_S`` windows, its start from the record's start); (0, 0) when the record
    holds fewer than four windows. Residuals that are NaN (blocks not read: ``StepFeature.known``) are left out; a
    window with fewer than half its blocks read is not judged."""
    dt = float(np.median(np.diff(t))) if t.size > 1 else 0.0
    w = max(int(round(WINDOW_S / dt)), 1) if dt > 0 else 0
    n = residual.size // w if w else 0
    if n < 4:
        return 0.0, 0.0
    win = residual[: n * w].reshape(n, w)
    read = np.sum(np.isfinite(win), axis=1)
    rms = np.sqrt(np.nansum(win**2, axis=1) / np.maximum(read, 1))
    rms[read < 0.5 * w] = 0.0
    k = int(np.argmax(rms))
    return float(rms[k]), float(t[k * w] - t[0])


def step_windows(contexts: list[Context]) -> dict[str, Any] | None:
    """The session's level (second largest record's worst window over the step's peak, in units of
    ``STEP_WINDOW_ACCURACY``) and the worst record; None with fewer than two step records."""
    per = []
    for ctx in contexts:
        pred = baseline(ctx).step_d
        for st, d in zip(ctx.steps, pred):
            peak = float(np.max(np.abs(d))) if np.size(d) else 0.0
            if peak > 0:
                r = np.asarray(d) - st.d
                if st.known is not None:
                    r = np.where(st.known, r, np.nan)
                if st.edge_gaps:  # where an edge lost in a gap of the stamps moves the prediction more than the level read
                    r = np.where(gap_timing_sigma(specimen_for(ctx.specimens, st.pressure_kPa), st)[0] > STEP_WINDOW_ACCURACY * peak, np.nan, r)
                level, at = worst_window(r, st.t)
                per.append((level / peak, at, st.pressure_kPa))
    if len(per) < 2:
        return None
    per.sort(key=lambda x: -x[0])
    (share, at, p), second = per[0], per[1][0]
    return {"level": second / STEP_WINDOW_ACCURACY, "share": second, "worst_share": share, "worst_time_s": at, "pressure_kPa": p,
            "records": len(per)}


def where_entry(sw: dict[str, Any], margin: float) -> dict[str, Any]:
    """The ``residual.where`` entry of a step window above ``margin`` x its accuracy."""
    p = sw["pressure_kPa"]
    at = f" ({p:g} kPa)" if p is not None else ""
    return {"block": "step_window", "level": sw["level"], "over_accuracy": sw["level"],
            "detail": f"{sw['worst_time_s']:.2f}-{sw['worst_time_s'] + WINDOW_S:.2f} s into the step record{at}: the "
                      f"displacement leaves the model by {sw['worst_share']:.2%} of the step for a moment, in two records "
                      f"or more (the rest of the record follows it): something near the tip, a contact, a sensor's local error",
            "time_s": [sw["worst_time_s"], sw["worst_time_s"] + WINDOW_S], "structure": sw["level"] > margin}
