"""Records written in pieces, joined again.

A logger that rotates its file every few minutes (so that a crash loses at most one file), an edge-triggered logger
that closes its file at a trigger, a DAQ task restarted by its watchdog mid-record: one record of the protocol reaches
the manifest as consecutive records of the same kind, clamp setting, frequency and amplitude, each piece's first
sample one sample after the last piece's last. Read as records of their own they are not what they were: a sine cut
mid-cycle, its settling cycles in the first piece only; a step that starts on its plateau. ``join_pieces`` puts them
back in one record wherever the stamps say that they are one (the next piece's start within ``JOIN_SAMPLES`` sample
spacings of the previous piece's end on the rig clock). Two records of labrig's own runs are never that close: the
runner rests between records.
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import numpy as np

from labrig.estimate import sample_spacing

if TYPE_CHECKING:
    from labrig.estimate.session_data import TimeRecord

JOIN_SAMPLES = 2.5  # the next piece starts within this many sample spacings after the previous one's last sample
SAME = ("frequency_Hz", "amplitude_V", "pressure_kPa")  # what a piece of one record shares with the others
LAYOUT = ("cycles", "on_s")  # the layout a piece's metadata cannot keep for the whole (the count, the step's span)


def continues(prev: "TimeRecord", rec: "TimeRecord") -> bool:
    """Whether ``rec`` is the next piece of ``prev``: the same kind and settings, and its first sample one sample after
    ``prev``'s last on the rig clock."""
    if rec.kind != prev.kind or any(prev.meta.get(k) != rec.meta.get(k) for k in SAME):
        return False
    if not (np.isfinite(prev.t_start) and np.isfinite(rec.t_start)) or prev.t.size < 2 or rec.t.size < 2:
        return False
    gap = rec.t_start - (prev.t_start + float(prev.t[-1] - prev.t[0]))  # each record's t_start is its first sample's
    return 0.0 < gap <= JOIN_SAMPLES * sample_spacing(prev.t)


def joined(prev: "TimeRecord", rec: "TimeRecord") -> "TimeRecord":
    """``prev`` and its next piece ``rec`` as one record on ``prev``'s time axis (the force readings too)."""
    shift = rec.t_start - prev.t_start
    both = lambda a, b: np.concatenate([np.asarray(a, float), np.asarray(b, float)])  # noqa: E731
    meta = {k: v for k, v in prev.meta.items() if k not in LAYOUT}
    return dataclasses.replace(prev, meta=meta, t=both(prev.t, prev.t[0] + shift + (rec.t - rec.t[0])), v=both(prev.v, rec.v),
                               i=both(prev.i, rec.i), d=both(prev.d, rec.d), force_N=both(prev.force_N, rec.force_N),
                               force_t=both(prev.force_times, rec.force_times + shift), filled=np.zeros(0, bool))


def join_pieces(records: list["TimeRecord"], notes: list[str]) -> list["TimeRecord"]:
    """The records (in the session's order) with every run of pieces of one record joined (module docstring)."""
    out: list[TimeRecord] = []
    pieces = 0
    for rec in records:
        if out and continues(out[-1], rec):
            out[-1] = joined(out[-1], rec)
            pieces += 1
        else:
            out.append(rec)
    if pieces:
        notes.append(f"{pieces} records continue the record before them (the same kind and settings, the next sample on the "
                     "rig clock): a file rotated or a task restarted mid-record, joined into one")
    return out
