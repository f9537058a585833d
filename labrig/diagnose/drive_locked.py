"""Foreign lines on the drive's lattice: a channel's reading of the drive transformed on its way to the record.

A line no catalogued cause makes (artefacts.py, *foreign lines*) is either the channel's own, a fan's, a pump's or a
transmitter's, at a frequency of its own whatever the drive, or one made from the drive's signal by something between
the strip and the record that is neither linear nor the strip's: a quantiser re-coding the drive after its monitor (a
comb of the drive's harmonics far above those a catalogued cause makes), a sensor's peak hold or sample-and-hold on a
clock of its own (the drive's harmonics, and their sidebands about that clock's lines). Lines of the second kind sit
on a lattice F + k f0 of the record's drive frequency f0. In a segment of C whole cycles the periodogram's bins are
f0 / C apart, and a line's bin modulo C is its place on the lattice; lines of the first kind fall on the C places
as chance has them.

Per sine record and channel, the fullest place holds m of the record's n foreign lines. The chance of m or more there
by chance is at most C P(Binomial(n, 1/C) >= m), the union over the places. A record counts where that is below
``LOCK_P``, a tail of the chance law and not a level set on sessions; the session is flagged in ``MIN_RECORDS``
records or more (artefacts.py). What a catalogued form takes from such a channel's features (a late fall read as a
lag, the comb's low orders on the mains' lines or as a branch of the current) is not the strip's, so the recording
takes the verdict (``engine._recording_decides``; docs/diagnosis.md, "Lines on the drive's lattice").
"""

from __future__ import annotations

import math

import numpy as np
from scipy.stats import binom

LOCK_P = 1e-6  # per record and channel: with 64 sine records and two channels, 1.3e-4 a session before the two-record rule
LOCK_MIN = 3  # lines on one place at least: two lines share a place too often to mean anything


def lattice_chance(freqs: list[float], f0: float, df: float) -> float:
    """The chance that the fullest place of the lattice f0 / df bins wide holds as many of the lines ``freqs`` (Hz, on
    a periodogram's bins df apart) as it does, were they placed at random: 1.0 where it cannot be read (fewer than two
    cycles, fewer than ``LOCK_MIN`` lines)."""
    cycles = int(round(f0 / df))
    if cycles < 2 or len(freqs) < LOCK_MIN:
        return 1.0
    places = np.round(np.asarray(freqs, float) / df).astype(np.int64) % cycles
    m = int(np.bincount(places, minlength=cycles).max())
    if m < LOCK_MIN:
        return 1.0
    return float(min(1.0, cycles * binom.sf(m - 1, len(freqs), 1.0 / cycles)))


def locked(per: list[dict], channels: tuple[str, ...], min_records: int) -> dict:
    """The session's records whose foreign lines sit on the drive's lattice (``lattice_chance`` below ``LOCK_P``), per
    channel, and whether they are ``min_records`` or more."""
    hits = [(a, ch) for a in per for ch in channels if a[ch]["lattice_p"] < LOCK_P]
    records = len({id(a) for a, _ in hits})
    worst = min((a[ch]["lattice_p"] for a, ch in hits), default=1.0)
    return {"records": records, "channels": sorted({ch for _, ch in hits}),
            "frequencies_Hz": sorted({a["frequency_Hz"] for a, _ in hits}),
            "worst_log10_p": float(math.log10(max(worst, 1e-300))), "lock_p": LOCK_P, "flagged": records >= min_records}
