"""A series element in the drive line, read off the data, and the strip's baseline refitted behind it.

A resistance or a capacitor between the DAQ's recorded drive and the strip (a current-sense resistor, a DC-blocking
capacitor, a relay's contact) makes both channels follow v_eff = v - R i - q/C instead of v. The analyser, wired at
the strip, does not see it. The baseline's seed-000 fit reads the DAQ's current with the spectra, so it takes the
element partly into the strip's electrical values (fresh16's DC-blocking supercapacitor: the baseline matched the DAQ's
current at the spectra's cost, 3x their accuracy at 0.1 Hz), and a series element applied on that baseline counts it
twice: on that case it halved the steps' misfit and raised the sines' current from 1.6x to 9x its accuracy.

The data hold the element without the model: the DAQ's impedance at each stepped sine, 1/Y_daq, less the analyser's
at the same frequency and pressure (a cubic spline of its real and imaginary parts in log f) is Z_s = R + 1/(j w C)
(``series_reading``; linear least squares, each point weighted by 1/|Z|^2: its error is relative to the strip's |Z|).
On clean sessions that reads 1/C of 0.1-0.25 F^-1 (C of 4-10 F, no element); on the supercapacitor of 0.227 F, 0.216 F.
The session is then recorded anew with the strip's own drive (``behind_series``), the seed-000 fit run on it, and the
rival's series form (rivals.SERIES_ELEMENT) fitted on that baseline from the reading: it predicts the recorded
channels, as the DAQ read them, from the strip behind the element (``series_contexts``).
"""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy.integrate import cumulative_trapezoid
from scipy.interpolate import CubicSpline

from labrig.diagnose.features import Features
from labrig.diagnose.wet_strip import WetSession, paired_sines, recorded_anew, refitted_contexts
from labrig.estimate.session_data import SessionData, step_onset
from labrig.records import SINE_KINDS, RecordKind

PERIODIC = (*SINE_KINDS, RecordKind.MULTISINE)  # records driven from their first sample, periodic: the mean is the offset


def series_reading(feats: Features, pressures: set) -> tuple[float, float] | None:
    """(R in ohm, elastance 1/C in F^-1) of Z_s = 1/Y_daq - Z_analyser over the stepped sines of ``pressures`` inside
    their spectrum's band, each at least 0; None without such sines (module docstring)."""
    zs, w, mag = [], [], []
    for spec, ss in paired_sines(feats, pressures):
        o = np.argsort(spec.f)
        lf, at = np.log(spec.f[o]), np.log([s.f for s in ss])
        z = CubicSpline(lf, spec.Z[o].real)(at) + 1j * CubicSpline(lf, spec.Z[o].imag)(at)
        zs.append(1 / np.array([s.Hi for s in ss]) - z)
        w.append(2 * np.pi * np.array([s.f for s in ss]))
        mag.append(np.abs(z))
    if not zs:
        return None
    zs, w, mag = np.concatenate(zs), np.concatenate(w), np.concatenate(mag)
    wt = 1 / mag**2
    r = float(np.sum(wt * zs.real) / np.sum(wt))
    el = float(np.sum(wt * -zs.imag / w) / np.sum(wt / w**2))  # Im Z_s = -S / w
    return max(r, 0.0), max(el, 0.0)


def _offset(rec) -> float:
    """The current's offset, which the amplifier's zero sets, not the strip: a periodic record's mean over the record;
    another record's level at rest before its drive switches on (``step_onset``; 0 if it never rests)."""
    i = np.asarray(rec.i, float)
    if rec.kind in PERIODIC:
        return float(np.mean(i))
    rest = rec.t < step_onset(rec)
    return float(np.median(i[rest])) if rest.any() else 0.0


def behind_series(sd: SessionData, r: float, el: float) -> SessionData:
    """The session with each record's drive the strip's own, v - R i - q/C (i less its offset, q its charge since the
    record's start), the sines' estimates made again."""

    def record(rec):
        i = np.asarray(rec.i, float) - _offset(rec)
        return dataclasses.replace(rec, v=rec.v - r * i - el * cumulative_trapezoid(i, rec.t, initial=0.0))

    return recorded_anew(sd, record)


def series_contexts(ws: WetSession, feats: Features, r: float, el: float, build):
    """The fitted and held-out contexts (``build``: ``engine.build_context``) of the recorded features on the seed-000
    fit of the session behind the element (``behind_series``). None if that fit gives no strip."""
    return refitted_contexts(ws, behind_series(ws.sd, r, el), feats, build)
