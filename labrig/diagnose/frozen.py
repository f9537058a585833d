"""A reading frozen while the others go on: one channel repeating one value, the rest of the record read (issue 12).

A sensor's controller that holds its output (a 'hold' or 'timing' input wired to a trigger, a reboot after a brown-out,
a serial sensor whose logger repeats the last frame it parsed) returns the same value sample after sample while the
strip moves and the other channels go on with their noise. No cause of the catalogue does that: the strip's bend and
its current are read with their noise at every sample, and a memory that holds the strip still leaves the sensor's
noise on it. What a form fits on the frozen stretch (a plateau read at the rest level, a bend that jumps at the
release) is the sensor's, not the strip's: fresh36's laser held through every step's plateau (outside, seen) was named
`large_deflection` at 0.48 and 0.49.

The test, per record (every kind) and channel (displacement, current): the longest run of identical readings during
which the other channel changes from one sample to the next in ``OTHER_MOVING`` of its samples or more, and which ends
with a jump (the release: the reading goes to where the strip went meanwhile, by ``RELEASE`` times the reading's 99th
percentile move between samples or more). A packet the logger lost and the import filled is not read, and ends a run.
A play written into a reading without its noise also holds it to the bit at each turn of the motion, but leaves the
hold as the strip moves on, without a jump: a memory's holds, not a frozen sensor (on the suite's clean sweep with a
pure play written into it: 24-28 records held for 545-575 samples, none released with a jump). A record counts where
the run is ``FROZEN_RUN`` samples or longer. One such record flags the session (no knock on the table freezes a reading
to the bit: the rule of two records for the other artefacts, artefacts.py, is not needed here), so a verdict of `none`
becomes `unexplained`; in ``MIN_RECORDS`` records or more the recording takes the verdict from any cause
(``decides``, ``engine._recording_decides``), as for a clipped channel, but a memory that predicts the held-out half as
a strip's holds do (``engine._held_by_memory``). A channel held at the end of its range is the clipping test's
(clipping.py).

Read on 251 seen sessions (tuning, fresh2, fresh32-36): every session but fresh36's held laser reads 5 samples at most
(runs released with a jump); the held laser 5002 and 15002. ``FROZEN_RUN`` (100) and ``RELEASE`` (3) are conventions
that split them with room on both sides. Fresh36's controller rebooting at brown-outs (outside) holds 193-261 samples
but leaves them without a jump (it re-zeroes near where the reading was) and is not read.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.diagnose.clipping import record_tally, run_bounds
from labrig.estimate.session_data import SessionData

FROZEN_RUN = 100  # samples
OTHER_MOVING = 0.5  # share of the other channel's samples that differ from the one before, over the run
MIN_RECORDS = 2
PAIRS = {"displacement": ("d", "i"), "current": ("i", "d")}
RELEASE = 3.0  # the jump at a run's end over the reading's 99th-percentile move between samples


def frozen_run(x: np.ndarray, other: np.ndarray, filled: np.ndarray | None = None) -> int:
    """The longest run of identical readings of ``x`` over which ``other`` (the same samples) keeps changing in
    ``OTHER_MOVING`` of its samples (0 where the channels are too short, not finite or of other lengths); samples
    ``filled`` in a gap of the time stamps (``TimeRecord.filled``: not read) end a run."""
    x, other = np.asarray(x, float), np.asarray(other, float)
    if x.size < 2 or x.size != other.size or not (np.all(np.isfinite(x)) and np.all(np.isfinite(other))):
        return 0
    dx = np.diff(x)
    same = dx == 0
    if filled is not None and np.size(filled) == x.size:
        same &= ~(filled[1:] | filled[:-1])
    moving = np.diff(other) != 0
    step = np.abs(dx[~same])
    largest = float(np.quantile(step, 0.99)) if step.size else 0.0  # the reading's largest moves from sample to sample
    best = 0
    for a, b in zip(*run_bounds(same)):
        # a run of readings x[a..b]; released with a jump to where the strip went meanwhile (a hold, a reboot), not
        # the continuous exit of a memory's hold at a turn of the motion
        released = b < dx.size and abs(dx[b]) > RELEASE * largest
        if b - a + 1 > best and released and np.mean(moving[a:b]) >= OTHER_MOVING:
            best = int(b - a + 1)
    return best


def frozen(sd: SessionData) -> dict[str, Any]:
    """Per channel, the records with a frozen run of ``FROZEN_RUN`` samples or more; flagged in one, deciding the verdict
    in ``MIN_RECORDS``."""
    per: dict[str, list[str]] = {}
    longest = 0
    for r in sd.all_records():
        for ch, (own, other) in PAIRS.items():
            run = frozen_run(getattr(r, own), getattr(r, other), r.filled)
            longest = max(longest, run)
            if run >= FROZEN_RUN:
                per.setdefault(ch, []).append(r.name)
    return {**record_tally(per, MIN_RECORDS), "longest_run": longest, "frozen_run": FROZEN_RUN}
