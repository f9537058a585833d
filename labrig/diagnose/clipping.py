"""Readings held at the end of their range (a channel that clips) or carried round to its other end (one that wraps).

A converter or a sensor driven past its range returns its last code for as long as the signal stays beyond it: the
drive's monitor on a DAQ range a little smaller than the amplifier's output, a current amplifier that saturates, a
laser whose target leaves its measuring range. The record then sits at its largest (or smallest) value for a run of
samples, the same code each, while everywhere else the reading moves with its noise. The diagnosis' features take the
flattened tops for the signal (a clipped monitor records less drive than the strip got; a clipped sensor less
response), so a cause named from them would be named from the clipping.

The test, per record and channel (drive, current, displacement; every kind of record), at the end of the range where
the readings pile up: the same value ``CLIP_RUN`` times in a row or more, ``PILE`` times as many readings there as at
the next value inward (a histogram's spike at its edge: a smooth top, a sine's arcsine law, puts about twice the next
value's count there), and a channel that moves with its noise elsewhere (``MOVING`` of its readings differ from the one
before: a noise-free setpoint stored as the drive, flat on its plateau, is no clipped measurement). Flagged in
``MIN_RECORDS`` records or more (artefacts.py), on one channel.

A reading carried over a counter's or a register's range comes back at the other end of it (a laser's int16 register
read over Modbus, a 16-bit counter): the record jumps by the whole range in one sample and goes on from there. No
strip's response does that: the displacement and the current move continuously except where the drive switches. The
test, per step record on the current and the displacement: one sample's change, away from the drive's edges (``EDGE``
samples either side of a switch of the recorded drive), of at least ``WRAP_SHARE`` of the record's whole span, the
reading staying at its new level for ``KEEPS`` samples (a dropout to a sentinel comes back at once).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from labrig.estimate.session_data import SessionData, TimeRecord
from labrig.records import RecordKind

# Set on the tuning set: a smooth signal's top, where the code is coarser than the noise, held one value for at most
# 7 readings in a row and 7 times the next value's count on any record of its 40 sessions (the held-out sets fresh12 and
# fresh13: at most 6); a clipped drive monitor held 78-15000 in a row, thousands of times the next value's count
CLIP_RUN = 20  # readings in a row at the record's extreme
PILE = 20.0  # readings at the extreme over readings at the next value inward
MOVING = 0.2  # the share of readings away from the extremes that differ from the one before: a measured, noisy channel
CHANNELS = {"drive": "v", "current": "i", "displacement": "d"}
UNITS = {"drive": "V", "current": "A", "displacement": "m"}
MIN_SAMPLES = 50
# A rail is one level (a converter's last code, a sensor's range end): one record's held level from another's by at most
# a per-record tare (a strip's rest offset, a few percent of a rail); fresh24's tip sticking on a guide held each
# record at its own extremes, 32 records at 49 levels from -0.45 to +0.33 mm, no two rails holding a quarter of them
RAIL_SPREAD = 0.02
RAIL_SHARE = 0.5
# A wrap changes the reading by the whole range in one sample (fresh17's register: 6.55 mm of a record spanning 6.55 mm);
# a strip's response at most by what it moves in a sample after an edge (away from the edges: at most 0.050 of the
# record's span on the tuning set's 40 sessions, 0.058 on every other cached session but a drive on its own clock,
# 0.33; docs/diagnosis.md "A reading carried round its range"). A physical bound, not a tuned one
WRAP_SHARE = 0.5
EDGE = 2  # samples either side of a drive change: the current's spike and a slow record's rise live there
KEEPS = 3  # samples after a wrap that stay at the new level (a dropout to a sentinel comes back at once)


def run_bounds(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The runs of True, in order: their first indices and the indices just past their ends."""
    edges = np.flatnonzero(np.diff(np.r_[0, np.asarray(mask).astype(np.int8), 0]))
    return edges[0::2], edges[1::2]


def record_tally(per: dict[str, list[str]], min_records: int) -> dict:
    """What a per-channel record check found ({channel: the records it named}): the records named on any channel, the
    channels, up to eight names each; flagged at one record, deciding the verdict at ``min_records``."""
    records = len({name for names in per.values() for name in names})
    return {"records": records, "channels": sorted(per), "names": {ch: v[:8] for ch, v in per.items()},
            "flagged": records >= 1, "decides": records >= min_records}


def run_lengths(mask: np.ndarray) -> np.ndarray:
    """The lengths of the runs of True, in order."""
    starts, ends = run_bounds(mask)
    return ends - starts


def longest_run(mask: np.ndarray) -> int:
    """The longest run of True (0 for none)."""
    return int(run_lengths(mask).max(initial=0))


def channel_clip(x: np.ndarray) -> dict[str, Any] | None:
    """At either end of the range: the longest run of the extreme value, the readings there over those at the next
    value inward (``pile``); the share of readings elsewhere that differ from the one before (``moving``); the ends
    that clip (``levels``) and, for the end with the longer run, its run, level and pile; None if the channel is too
    short or constant."""
    x = x[np.isfinite(x)]
    if x.size < MIN_SAMPLES or np.ptp(x) == 0:
        return None
    values, counts = np.unique(x, return_counts=True)
    ends, held = [], np.zeros(x.size, bool)
    for k, inward in ((len(values) - 1, len(values) - 2), (0, 1)):
        at = x == values[k]
        held |= at
        ends.append({"run": longest_run(at), "level": float(values[k]), "pile": float(counts[k] / max(counts[inward], 1))})
    free = ~(held[:-1] | held[1:])
    moving = float(np.mean(np.diff(x)[free] != 0)) if free.sum() >= MIN_SAMPLES else 0.0
    clipped = [e for e in ends if e["run"] >= CLIP_RUN and e["pile"] >= PILE and moving >= MOVING]
    worst = max(ends, key=lambda e: e["run"])
    return {**worst, "levels": [e["level"] for e in clipped], "moving": moving, "clipped": bool(clipped)}


def record_clips(r: TimeRecord) -> dict[str, dict[str, Any]]:
    """The channels of one record that clip (channel -> its ``channel_clip``)."""
    out = {}
    for ch, attr in CHANNELS.items():
        c = channel_clip(np.asarray(getattr(r, attr), float))
        if c is not None and c["clipped"]:
            out[ch] = {**c, "record": r.name}
    return out


def largest_jump(x: np.ndarray, v: np.ndarray) -> tuple[float, int]:
    """(the largest one-sample change of ``x`` away from the drive's edges that the reading keeps for the next
    samples, over the record's span; its index); (0, -1) for a record too short, flat or not finite. The drive's edges:
    its one-sample changes of a tenth of its span or more (a step's switch, not a measured drive's noise). A change
    the reading gives back at once (a dropout to a sentinel) is not a wrap."""
    x, v = np.asarray(x, float), np.asarray(v, float)
    if x.size < MIN_SAMPLES or not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))) or np.ptp(x) == 0:
        return 0.0, -1
    span = float(np.ptp(x))
    dv = np.abs(np.diff(v))
    near = np.zeros(x.size - 1, bool)
    for e in np.flatnonzero(dv >= 0.1 * max(float(np.ptp(v)), 1e-12)) if np.ptp(v) > 0 else []:
        near[max(e - EDGE, 0): e + EDGE + 1] = True
    jump = np.where(near, 0.0, np.abs(np.diff(x)))
    n = x.size - 1
    # kept: for KEEPS samples after it the reading stays at least half the jump away from where it left, and it had
    # been there for KEEPS samples before (a dropout's return leaves a level held for a sample or two)
    stay = np.full(n, np.inf)
    for m in range(1, KEEPS + 1):
        ahead, behind = np.full(n, 0.0), np.full(n, 0.0)
        ahead[: n - m + 1] = np.abs(x[m:] - x[: x.size - m])  # x[k + m] against x[k]
        behind[m - 1:] = np.abs(x[m:] - x[: x.size - m])[: n - m + 1]  # x[k + 1] against x[k + 1 - m]
        stay = np.minimum(stay, np.minimum(ahead, behind))
    jump = np.where(stay >= 0.5 * jump, jump, 0.0)
    k = int(np.argmax(jump))
    return float(jump[k] / span), k


def wrapping(sd: SessionData, min_records: int) -> dict[str, Any]:
    """Per channel (current, displacement), the step records that jump by ``WRAP_SHARE`` of their span in one sample
    away from the drive's edges and stay there; flagged where one channel does in ``min_records`` records or more.
    Step records only: a sine's response moves fast at every sample of a coarsely sampled record."""
    per: dict[str, list[str]] = {}
    worst = 0.0
    for r in sd.all_records():
        if r.kind != RecordKind.STEP:
            continue
        for ch in ("current", "displacement"):
            share, k = largest_jump(getattr(r, CHANNELS[ch]), r.v)
            worst = max(worst, share)
            if share >= WRAP_SHARE:
                per.setdefault(ch, []).append(r.name)
    flagged = sorted(ch for ch, v in per.items() if len(v) >= min_records)
    return {"channels": flagged, "records": per, "largest_share": worst, "wrap_share": WRAP_SHARE, "flagged": bool(flagged)}


def rail_records(clips: list[dict[str, Any]]) -> int:
    """How many of a channel's held records sit at its rails: levels within ``RAIL_SPREAD`` of their size of the next
    (single linkage) are one rail; a channel has two at most, the ends of its range."""
    levels = sorted((x, k) for k, c in enumerate(clips) for x in c["levels"])
    if not levels:
        return 0
    rails: list[set[int]] = [{levels[0][1]}]
    for (x0, _), (x1, k) in zip(levels, levels[1:]):
        if x1 - x0 > RAIL_SPREAD * max(abs(x0), abs(x1)):
            rails.append(set())
        rails[-1].add(k)
    return len(set().union(*sorted(rails, key=len)[-2:]))


def clipping(sd: SessionData, min_records: int) -> dict[str, Any]:
    """Per channel, the records that clip, the level and the longest run; flagged where one channel clips in
    ``min_records`` records or more, most of them (``RAIL_SHARE``) at its rails (``rail_records``): a range's end is
    one level whatever the record, where a strip held by dry friction stops at each record's own extremes."""
    per: dict[str, list[dict[str, Any]]] = {}
    for r in sd.all_records():
        for ch, c in record_clips(r).items():
            per.setdefault(ch, []).append(c)
    flagged = sorted(ch for ch, v in per.items() if len(v) >= min_records and rail_records(v) >= max(min_records, RAIL_SHARE * len(v)))
    return {"channels": flagged, "records": {ch: [c["record"] for c in v] for ch, v in per.items()},
            "levels": {ch: sorted({float(f"{x:.4g}") for c in v for x in c["levels"]}) for ch, v in per.items()},
            "longest_run": max((c["run"] for v in per.values() for c in v), default=0),
            "clip_run": CLIP_RUN, "pile": PILE, "flagged": bool(flagged)}
