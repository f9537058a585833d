"""What the fitter and the diagnosis need from a session, read only through the store's reader.

Finished steps only; each record grouped by its clamping pressure. Bad data (NaN, too short) is left out
with a note rather than crashing the fit.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from labrig.errors import BadInput
from labrig.estimate import SineEstimate, sine_estimate


@dataclass
class TimeRecord:
    name: str
    kind: str  # step | harmonic | stepped_sine | multisine | free
    meta: dict[str, Any]
    t: np.ndarray
    v: np.ndarray
    i: np.ndarray
    d: np.ndarray
    force_N: np.ndarray = field(default_factory=lambda: np.zeros(0))
    t_start: float = float("nan")  # rig clock at the step start (s)

    @property
    def fs(self) -> float:
        return float(1.0 / np.median(np.diff(self.t)))


@dataclass
class PressureData:
    pressure_kPa: float
    eis: tuple[np.ndarray, np.ndarray] | None = None  # (f_Hz, Z complex)
    records: list[TimeRecord] = field(default_factory=list)
    sines: list[SineEstimate] = field(default_factory=list)  # stepped-sine estimates, ascending f

    def of_kind(self, kind: str) -> list[TimeRecord]:
        return [r for r in self.records if r.kind == kind]

    def frf(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
        """(f, H_disp, H_cur, sigma_disp) from the stepped sines, or None."""
        if not self.sines:
            return None
        f = np.array([s.frequency_Hz for s in self.sines])
        return f, np.array([s.H_disp for s in self.sines]), np.array([s.H_cur for s in self.sines]), np.array([s.disp_noise for s in self.sines])


@dataclass
class SessionData:
    path: str
    sample: dict[str, Any]
    pressures: list[PressureData]
    notes: list[str] = field(default_factory=list)
    unpressured: list[TimeRecord] = field(default_factory=list)  # records without a pressure

    def all_records(self) -> list[TimeRecord]:
        return [r for p in self.pressures for r in p.records] + self.unpressured


def _finite(*arrays: np.ndarray) -> bool:
    return all(a.size > 0 and np.all(np.isfinite(a)) for a in arrays)


def load_session(path: str | Path) -> SessionData:
    from labrig.store import SessionReader

    p = Path(path)
    if not p.exists():
        raise BadInput(f"{path}: no such session file")
    by_p: dict[float, PressureData] = {}
    notes: list[str] = []
    loose: list[TimeRecord] = []
    with SessionReader(p) as r:
        sample = dict(r.sample)
        for st in r.steps():
            if st.status not in ("done",) or st.kind in ("clamp", "settle"):
                if st.status not in ("done", "skipped") and st.kind not in ("clamp", "settle"):
                    notes.append(f"step {st.name}: {st.status}, not used")
                continue
            pk = st.metadata.get("pressure_kPa")
            bucket = None
            if pk is not None:
                bucket = by_p.setdefault(float(pk), PressureData(float(pk)))
            streams = r.streams(st)
            if st.kind == "eis" and "eis" in streams:
                s = r.stream(st, "eis")
                f, z = s["f_Hz"], s["z_re_ohm"] + 1j * s["z_im_ohm"]
                if not _finite(f, z.real, z.imag) or f.size < 3:
                    notes.append(f"step {st.name}: impedance spectrum has NaN or < 3 points, not used")
                elif bucket is not None:
                    bucket.eis = (f, z)
                continue
            if "daq" not in streams:
                continue
            s = r.stream(st, "daq")
            force = r.stream(st, "force")["force_N"] if "force" in streams else np.zeros(0)
            rec = TimeRecord(st.name, st.kind, dict(st.metadata), s["t_s"], s["v_V"], s["i_A"], s["disp_m"], force, st.t_start)
            if not _finite(rec.t, rec.v, rec.i, rec.d) or rec.t.size < 8:
                notes.append(f"step {st.name}: record has NaN or too few samples, not used")
                continue
            if bucket is None:
                loose.append(rec)
                continue
            bucket.records.append(rec)
            if st.kind == "stepped_sine":
                md = st.metadata
                bucket.sines.append(sine_estimate(rec.t, rec.v, rec.i, rec.d, float(md["frequency_Hz"]), float(md.get("settle_cycles", 0.0)), float(md.get("cycles", 0)) or None))
    for b in by_p.values():
        b.sines.sort(key=lambda s: s.frequency_Hz)
    return SessionData(str(p), sample, [by_p[k] for k in sorted(by_p)], notes, loose)
