"""The diagnosis' validation set (issue 12): effects written into exported CSVs in forms of their own, not the
simulator's, then imported and diagnosed as a user would (``labrig export`` -> inject -> ``labrig import`` ->
``labrig diagnose``). No threshold of the diagnosis was set on these cases.

Each catalogue effect has at least two forms here that the simulated bench (``mock_devices/effects.py``, the
tuning set) does not use, and four structures outside the catalogue must come out ``unexplained``. The clean
sessions and every case also vary the protocol and the data's shape (spectra left out, harmonic records left out,
two pressures, the time series decimated to another sampling rate, records shortened, the manifest's order
shuffled) and the strip (the seed-001 preset on a sweep of its own pressures).

Forms act on the measured signals of each record (``t_s`` on the session clock, ``v_V``, ``i_A``, ``disp_m``,
``force_N``): linear ones through their transfer function applied to the record (FFT with zero padding: causal from
the record's start), memory operators sample by sample, drifts through the session clock. Strengths are drawn from
the case's seed in the ranges of docs/effects.md.

Run: python bench/inject.py [--cache .cache/validation] [--jobs 2] [--only NAME] [--fresh] [--make-only]  (bench/diagnose.py runs it too)
"""

from __future__ import annotations

import argparse
import importlib
import math
import shutil
import subprocess
import sys
import time
import tomllib
import zlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
import tomli_w

REPO = Path(__file__).resolve().parents[1]
BASES = {  # clean sessions the validation set is written into: (protocol, preset, seed)
    "paper_21": ("paper-sweep", "paper", 21),
    "paper_22": ("paper-sweep", "paper", 22),
    "paper_23": ("paper-sweep", "paper", 23),
    "long_21": ("paper-sweep", "paper_long", 21),  # another strip: the paper's, 40 mm free instead of 30
    # the fresh held-out part (written before the diagnosis' changes of the second pass; seeds never run before)
    "paper_31": ("paper-sweep", "paper", 31),
    "s001_32": (str(REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 32),  # the seed-001 strip: 20 mm free in air, its own clamp pressures
    "short_33": ("paper-sweep", "paper_short", 33),  # the paper's strip cut to 25 mm free
}


def register_forms(forms: dict[str, dict[str, Callable[[Session], None]]]) -> None:
    """A held-out set's forms, added beside the forms of the earlier sets in ``REGISTRY`` (none replaced)."""
    for truth, by_name in forms.items():
        REGISTRY.setdefault(truth, {}).update(by_name)


def register_free_length(name: str, length_m: float) -> None:
    """The paper's strip with another free length, as preset ``name``. Registered in every process that runs or
    reads it (the simulated bench and the sensor-offset forms look presets up by name)."""
    from dataclasses import replace

    from labrig.physics import presets

    def strip() -> presets.Preset:
        p = presets.get("paper")
        base = replace(p.base, geometry=replace(p.base.geometry, length=length_m))
        return replace(p, name=name, base=base, description=f"the paper's strip, {length_m * 1e3:g} mm free")

    presets._PRESETS.setdefault(name, strip)


def register_presets() -> None:
    """``paper_long``: 40 mm free (its first resonance 0.56x lower); ``paper_short``: 25 mm free."""
    register_free_length("paper_long", 0.040)
    register_free_length("paper_short", 0.025)


register_presets()


@dataclass
class Rec:
    """One record of an exported session: its manifest entry and its columns."""

    entry: dict
    cols: dict[str, np.ndarray]

    @property
    def kind(self) -> str:
        return self.entry["kind"]

    @property
    def series(self) -> bool:
        return self.kind != "eis"

    @property
    def fs(self) -> float:
        return 1.0 / float(np.median(np.diff(self.cols["t_s"])))


@dataclass
class Session:
    specimen: dict
    recs: list[Rec]
    preset: str
    t0: float = 0.0  # the first sample of the session (s, session clock)
    t1: float = 1.0  # its last
    rng: np.random.Generator = field(default_factory=lambda: np.random.default_rng(0))

    def series(self) -> list[Rec]:
        return [r for r in self.recs if r.series]

    def pressures(self) -> list[float]:
        return sorted({float(r.entry["pressure_kPa"]) for r in self.recs})


def read_export(folder: Path, preset: str) -> Session:
    man = tomllib.loads((folder / "manifest.toml").read_text())
    recs = []
    for e in man["record"]:
        path = folder / e["file"]
        head = path.open().readline().strip().split(",")
        data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        recs.append(Rec(dict(e), {h: data[:, k].copy() for k, h in enumerate(head)}))
    ts = [r.cols["t_s"] for r in recs if r.series]
    return Session(man["specimen"], recs, preset, min(float(t[0]) for t in ts), max(float(t[-1]) for t in ts))


def write_import(s: Session, folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for r in s.recs:
        keys = list(r.cols)
        np.savetxt(folder / r.entry["file"], np.column_stack([r.cols[k] for k in keys]), delimiter=",", header=",".join(keys),
                   comments="", fmt="%.10g")
    (folder / "manifest.toml").write_text(tomli_w.dumps({"specimen": s.specimen, "record": [r.entry for r in s.recs]}))
    return folder / "manifest.toml"


# ------------------------------------------------------------------------------------------------ tools


def lti(x: np.ndarray, fs: float, H: Callable[[np.ndarray], np.ndarray], dc_at_first_line: bool = False) -> np.ndarray:
    """x through H(s) from rest at the record's start (zero padding to twice its length: causal to that length). The
    zero-frequency bin is H at 1e-9 rad/s, or with ``dc_at_first_line`` H at the grid's first line: the strip's
    displacement per volt grows without bound towards zero frequency (its double layer's constant-phase element keeps
    taking charge), so a signal's mean is then answered as what its length can build, not as DC."""
    n = x.size
    m = 1 << int(math.ceil(math.log2(2 * n)))
    s = 2j * np.pi * np.fft.rfftfreq(m, 1.0 / fs)
    with np.errstate(divide="ignore", invalid="ignore"):  # H at s = 0, replaced below
        h = H(s)
    h[0] = H(s[1:2] if dc_at_first_line else np.array([1e-9 + 0j]))[0].real
    return np.fft.irfft(np.fft.rfft(x, m) * h, m)[:n]


def lu(rng: np.random.Generator, lo: float, hi: float) -> float:
    return float(np.exp(rng.uniform(math.log(lo), math.log(hi))))


def play(x: np.ndarray, r: float) -> np.ndarray:
    """Play (backlash) operator, sample by sample (written anew here, not the diagnosis' phase-wise one)."""
    y = np.empty_like(x)
    prev = 0.0
    for k, xk in enumerate(x):
        prev = min(max(prev, xk - r), xk + r)
        y[k] = prev
    return y


def ref_disp(s: Session) -> float:
    """A session's displacement scale: the RMS of the first 1 V harmonic or step record."""
    for kind in ("harmonic", "step"):
        for r in s.series():
            if r.kind == kind:
                return float(np.std(r.cols["disp_m"])) * math.sqrt(2)
    return 1e-3


def map_disp(s: Session, f: Callable[[Rec, np.ndarray], np.ndarray]) -> None:
    for r in s.series():
        r.cols["disp_m"] = f(r, r.cols["disp_m"])


# ------------------------------------------------------------------------------------------------ forms


def br_cole_cole(s: Session) -> None:
    k2, tau, beta = s.rng.uniform(0.8, 1.3), lu(s.rng, 3.0, 15.0), s.rng.uniform(0.5, 0.8)
    map_disp(s, lambda r, d: lti(d, r.fs, lambda z: 1 - k2 / (1 + (tau * z) ** beta)))


def br_two_exp(s: Session) -> None:
    k2, t1, t2, w = s.rng.uniform(0.8, 1.3), lu(s.rng, 1.0, 4.0), lu(s.rng, 10.0, 40.0), s.rng.uniform(0.3, 0.7)
    map_disp(s, lambda r, d: lti(d, r.fs, lambda z: 1 - k2 * (w / (t1 * z + 1) + (1 - w) / (t2 * z + 1))))


def br_stretched(s: Session) -> None:
    """Opposing flux whose step response is a stretched exponential 1 - exp(-(t/tau)^beta) (time-domain kernel)."""
    k2, tau, beta = s.rng.uniform(0.8, 1.3), lu(s.rng, 3.0, 12.0), s.rng.uniform(0.4, 0.7)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        t = np.arange(d.size) / r.fs
        step = 1 - np.exp(-((t / tau) ** beta))
        kern = np.diff(np.r_[0.0, step])  # impulse response per sample
        m = 1 << int(math.ceil(math.log2(2 * d.size)))
        return d - k2 * np.fft.irfft(np.fft.rfft(d, m) * np.fft.rfft(kern, m), m)[: d.size]

    map_disp(s, f)


def _faradaic(s: Session, branch: Callable[[np.ndarray], np.ndarray]) -> None:
    i1 = lu(s.rng, 1e-4, 6e-4)  # A at 1 V, the seed's range
    scale = i1 / branch(np.array([1.0]))[0]
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + scale * branch(r.cols["v_V"])


def far_tafel(s: Session) -> None:
    vt = s.rng.uniform(0.12, 0.3)  # electrolysis growing exponentially with voltage, one-sided
    _faradaic(s, lambda v: np.exp(v / vt) - 1)


def far_asym_bv(s: Session) -> None:
    a, vt = (s.rng.uniform(0.25, 0.4) if s.rng.random() < 0.5 else s.rng.uniform(0.6, 0.75)), s.rng.uniform(0.08, 0.15)
    _faradaic(s, lambda v: np.exp(a * v / vt) - np.exp(-(1 - a) * v / vt))


def far_threshold(s: Session) -> None:
    v_on = s.rng.uniform(0.2, 0.4)  # a diode-like onset (water splitting above a threshold), both signs
    _faradaic(s, lambda v: np.sign(v) * np.clip(np.abs(v) - v_on, 0, None) ** 1.5)


def hy_play_output(s: Session) -> None:
    """Rate-independent memory in the displacement path (the laser's mount, the strip's tip), not the drive."""
    w, rr = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.1, 0.3) * ref_disp(s)
    map_disp(s, lambda r, d: (1 - w) * d + w * play(d, rr))


def hy_bouc_wen_output(s: Session) -> None:
    a, zmax = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.1, 0.3) * ref_disp(s)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        z = np.empty_like(d)
        prev, dd = 0.0, np.diff(np.r_[d[0], d])
        for k, step in enumerate(dd):  # Bouc-Wen, n = 1, beta = gamma: z' = d' (1 - (sgn(d' z) + 1)/2 |z| / zmax)
            prev += step * (1 - (np.sign(step * prev) + 1) / 2 * abs(prev) / zmax)
            z[k] = prev
        return (1 - a) * d + a * (d - z + zmax * np.tanh(z / zmax))

    map_disp(s, f)


def hy_multi_play_output(s: Session) -> None:
    """Prandtl-Ishlinskii with three radii on the displacement."""
    ref, w = ref_disp(s), s.rng.uniform(0.3, 0.6)
    radii = np.array([0.05, 0.15, 0.3]) * ref * s.rng.uniform(0.7, 1.3)
    map_disp(s, lambda r, d: (1 - w) * d + w * np.mean([play(d, x) for x in radii], axis=0))


def td_shift(s: Session) -> None:
    tau = lu(s.rng, 5e-3, 40e-3)
    map_disp(s, lambda r, d: np.interp(r.cols["t_s"] - tau, r.cols["t_s"], d, left=d[0]))


def td_bessel2(s: Session) -> None:
    tau = lu(s.rng, 4e-3, 12e-3)  # the laser controller's output filter: group delay tau, gain flat in band
    map_disp(s, lambda r, d: lti(d, r.fs, lambda z: 1 / (1 + z * tau + (z * tau) ** 2 / 3)))


def td_skew(s: Session) -> None:
    """The DAQ samples the displacement channel late by a fraction of a sample period plus a fixed skew."""
    tau = lu(s.rng, 8e-3, 30e-3)
    map_disp(s, lambda r, d: lti(d, r.fs, lambda z: np.exp(-z * tau)))


def _beam_ratio(s: Session, ratio: Callable) -> None:
    from labrig.physics import presets

    pre = presets.get(s.preset)
    for r in s.series():
        sp = pre.specimen(float(r.entry["pressure_kPa"]))
        r.cols["disp_m"] = lti(r.cols["disp_m"], r.fs, lambda z: ratio(z, sp))


def so_beam(s: Session) -> None:
    from labrig.physics import transfer

    xi = s.rng.uniform(0.55, 0.9)
    _beam_ratio(s, lambda z, sp: transfer.displacement_tf(z, sp.with_(sensor_x=xi * sp.geometry.length)) / transfer.displacement_tf(z, sp))


def so_two_mode(s: Session) -> None:
    """An Euler-Bernoulli two-mode reading of the spot's position, written here: mode shapes of a clamped-free beam
    under a tip moment, the first resonance from the preset's FRF peak, the second at (4.694/1.875)^2 of it."""
    from labrig.physics import transfer

    xi = s.rng.uniform(0.55, 0.9)

    def phi(b: float, x: float) -> float:
        c = (math.cosh(b) + math.cos(b)) / (math.sinh(b) + math.sin(b))
        return math.cosh(b * x) - math.cos(b * x) - c * (math.sinh(b * x) - math.sin(b * x))

    betas = (1.8751, 4.6941)
    slope = lambda b: (phi(b, 1.0) - phi(b, 1.0 - 1e-6)) / 1e-6  # noqa: E731  phi'(1): a moment spread along the strip

    def ratio(z, sp):
        f = np.logspace(0, 3, 3000)
        f1 = f[int(np.argmax(np.abs(transfer.frf(f, sp))))]
        num, den = 0, 0
        for b in betas:
            wn = 2 * np.pi * f1 * (b / betas[0]) ** 2
            q = slope(b) / (wn**2 + 0.1 * wn * z + z**2)
            num, den = num + q * phi(b, xi), den + q * phi(b, 1.0)
        return num / den

    _beam_ratio(s, ratio)


def _clamp(s: Session, creep: Callable[[np.ndarray], np.ndarray]) -> None:
    b = s.rng.uniform(0.5, 1.5)  # the gain follows the force
    first = {}
    for r in s.series():
        p = r.entry["pressure_kPa"]
        first[p] = min(first.get(p, np.inf), float(r.cols["t_s"][0]))
    for r in s.series():
        rel = creep(r.cols["t_s"] - first[r.entry["pressure_kPa"]])
        if "force_N" in r.cols:
            r.cols["force_N"] = np.round(r.cols["force_N"] * rel / 0.0980665) * 0.0980665  # the indicator's 0.01 kgf
        r.cols["disp_m"] = r.cols["disp_m"] * rel**b


def cr_log(s: Session) -> None:
    c, tau = s.rng.uniform(0.015, 0.04), lu(s.rng, 5.0, 50.0)
    _clamp(s, lambda t: 1 - c * np.log1p(np.clip(t, 0, None) / tau))


def cr_power(s: Session) -> None:
    c, n, tau = s.rng.uniform(0.02, 0.06), s.rng.uniform(0.3, 0.5), 600.0
    _clamp(s, lambda t: 1 - c * (np.clip(t, 0, None) / tau) ** n)


def _dry(s: Session, loss: Callable[[np.ndarray], np.ndarray]) -> None:
    """Gain and conductance lost with the session's time; a spectrum (no clock of its own in the CSV) is taken at
    the start of the time series recorded after it, its impedance up as the conductance is down."""
    share = s.rng.uniform(0.3, 1.0)  # the conductance dries more slowly than the gain
    u = lambda t: (t - s.t0) / (s.t1 - s.t0)  # noqa: E731
    for k, r in enumerate(s.recs):
        if r.series:
            x = loss(u(r.cols["t_s"]))
            r.cols["disp_m"] = r.cols["disp_m"] * (1 - x)
            r.cols["i_A"] = r.cols["i_A"] * (1 - share * x)
            continue
        after = next((q for q in s.recs[k + 1 :] if q.series), None)
        x = loss(u(np.array([after.cols["t_s"][0] if after else s.t1])))[0]
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = r.cols["z_re_ohm"] / (1 - share * x), r.cols["z_im_ohm"] / (1 - share * x)


def dh_linear(s: Session) -> None:
    total = s.rng.uniform(0.15, 0.4)
    _dry(s, lambda u: total * u)


def dh_sigmoid(s: Session) -> None:
    total, mid, w = s.rng.uniform(0.15, 0.4), s.rng.uniform(0.35, 0.65), s.rng.uniform(0.08, 0.15)
    _dry(s, lambda u: total / (1 + np.exp(-(u - mid) / w)))


def _strain(s: Session, shape: Callable[[np.ndarray], np.ndarray]) -> None:
    ref = ref_disp(s)
    kd, ki = s.rng.uniform(0.02, 0.06), s.rng.uniform(0.05, 0.15)  # the current feels the resistance more
    for r in s.series():
        e = shape(r.cols["disp_m"] / ref)
        r.cols["disp_m"] = r.cols["disp_m"] * (1 - kd * e)
        r.cols["i_A"] = r.cols["i_A"] * (1 - ki * e)


def sr_abs(s: Session) -> None:
    _strain(s, np.abs)  # both electrodes crack alike: resistance up with either sign of curvature


def sr_one_sided(s: Session) -> None:
    _strain(s, lambda e: np.clip(e, 0, None) ** 1.3)  # one electrode cracks, on tension only


def ld_arc(s: Session) -> None:
    L = float(s.specimen["length_m"]) * s.rng.uniform(0.8, 1.1)  # uniform curvature: the tip on a circular arc

    def f(r, d):
        k = 2 * d / L**2
        out = d.copy()
        big = np.abs(k) > 1e-9
        out[big] = (1 - np.cos(k[big] * L)) / k[big]
        return out

    map_disp(s, f)


def ld_tanh(s: Session) -> None:
    D = float(s.specimen["length_m"]) * s.rng.uniform(0.5, 0.8)
    map_disp(s, lambda r, d: D * np.tanh(d / D))


def _mains(s: Session, wave: Callable[[np.ndarray, float], np.ndarray]) -> None:
    ad, ai = lu(s.rng, 1e-6, 5e-6), lu(s.rng, 2e-6, 1e-5)
    pd, pi = s.rng.uniform(0, 2 * np.pi, 2)
    for r in s.series():
        t = r.cols["t_s"]
        r.cols["disp_m"] = r.cols["disp_m"] + ad * wave(t, pd)
        r.cols["i_A"] = r.cols["i_A"] + ai * wave(t, pi)


def mp_50_third(s: Session) -> None:
    f, h3 = 50.0, s.rng.uniform(0.2, 0.5)
    _mains(s, lambda t, p: np.cos(2 * np.pi * f * t + p) + h3 * np.cos(6 * np.pi * f * t + 2 * p))


def mp_60_am(s: Session) -> None:
    m, fm = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.2, 1.0)
    _mains(s, lambda t, p: (1 + m * np.sin(2 * np.pi * fm * t)) * np.cos(2 * np.pi * 60.0 * t + p))


def mp_50_wander(s: Session) -> None:
    df = s.rng.uniform(-0.3, 0.3)  # the grid off nominal, its phase wandering slowly
    _mains(s, lambda t, p: np.cos(2 * np.pi * (50.0 + df) * t + p + 0.5 * np.sin(2 * np.pi * t / 7.0)))


# ------------------------------------------------------------------------------------ outside the catalogue


def out_fixture_resonance(s: Session) -> None:
    """The clamp fixture resonates: a second-order peak in the displacement path at a few Hz."""
    fr, a, z = lu(s.rng, 3.0, 8.0), s.rng.uniform(0.08, 0.2), s.rng.uniform(0.05, 0.15)
    wr = 2 * np.pi * fr
    map_disp(s, lambda r, d: lti(d, r.fs, lambda q: 1 + a * (q / wr) ** 2 / ((q / wr) ** 2 + 2 * z * q / wr + 1)))


def out_current_bandwidth(s: Session) -> None:
    """The current amplifier's bandwidth: a second-order low-pass at tens of Hz on the current channel only."""
    fc = lu(s.rng, 25.0, 60.0)
    wc = 2 * np.pi * fc
    for r in s.series():
        r.cols["i_A"] = lti(r.cols["i_A"], r.fs, lambda q: 1 / (1 + 1.41 * q / wc + (q / wc) ** 2))


def out_gain_wander(s: Session) -> None:
    """The displacement gain breathes with the room's temperature cycle: up and down, not monotonic."""
    a, periods, ph = s.rng.uniform(0.06, 0.12), s.rng.uniform(1.5, 3.0), s.rng.uniform(0, 2 * np.pi)
    map_disp(s, lambda r, d: d * (1 + a * np.sin(2 * np.pi * periods * (r.cols["t_s"] - s.t0) / (s.t1 - s.t0) + ph)))


def out_laser_drift(s: Session) -> None:
    """The laser's zero drifts within each record (warm-up after each re-aim): a ramp on the displacement."""
    rate = lu(s.rng, 2e-6, 8e-6) * ref_disp(s) / 1e-3  # m/s for a 1 mm scale

    map_disp(s, lambda r, d: d + rate * (r.cols["t_s"] - r.cols["t_s"][0]) * (1 if s.rng.random() < 0.5 else -1))


FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"cole_cole": br_cole_cole, "stretched": br_stretched},
    "faradaic_current": {"tafel": far_tafel, "asym_bv": far_asym_bv},
    "hysteresis": {"play_output": hy_play_output, "bouc_wen_output": hy_bouc_wen_output},
    "time_delay": {"shift": td_shift, "bessel2": td_bessel2},
    "sensor_offset": {"beam": so_beam, "two_mode": so_two_mode},
    "clamp_relaxation": {"log_creep": cr_log, "power_creep": cr_power},
    "dehydration": {"linear": dh_linear, "sigmoid": dh_sigmoid},
    "strain_resistance": {"abs": sr_abs, "one_sided": sr_one_sided},
    "large_deflection": {"arc": ld_arc, "tanh": ld_tanh},
    "mains_pickup": {"50_third": mp_50_third, "60_am": mp_60_am},
    "unexplained": {"fixture_resonance": out_fixture_resonance, "current_bandwidth": out_current_bandwidth,
                    "gain_wander": out_gain_wander, "laser_drift": out_laser_drift},
    "none": {"clean": lambda s: None},
}
# further forms, run with --extra (the default set keeps the run within ~40 min on a shared 2-core machine)
EXTRA_FORMS = {"back_relaxation": {"two_exp": br_two_exp}, "faradaic_current": {"threshold": far_threshold},
               "hysteresis": {"multi_play_output": hy_multi_play_output}, "time_delay": {"skew": td_skew},
               "mains_pickup": {"50_wander": mp_50_wander}}


# ------------------------------------------------------------------ the fresh held-out part (second pass, issue 12)
# One further form per catalogue effect and a further structure outside the catalogue, each from the physics of
# its cause (not from the diagnosis' families), written before the diagnosis was changed for the second pass and
# run on seeds (31-33) and strips (seed-001, 25 mm) never run before. Reported apart as the unseen set.


def br_diffusion(s: Session) -> None:
    """Water diffusing back across a layer of finite thickness (the electrode's pores): the opposing flux follows
    the bending through the finite-length diffusion kernel tanh(sqrt(tau s))/sqrt(tau s) (a Warburg element with
    a reflecting wall), not through any sum of a few exponentials."""
    k2, tau = s.rng.uniform(0.8, 1.3), lu(s.rng, 5.0, 40.0)

    def kernel(z):
        q = np.sqrt(tau * z + 0j)
        small = np.abs(q) < 1e-6
        return np.where(small, 1.0 + 0j, np.tanh(q) / np.where(small, 1.0, q))

    map_disp(s, lambda r, d: lti(d, r.fs, lambda z: 1 - k2 * kernel(z)))


def far_mass_limited(s: Session) -> None:
    """Electrolysis limited by transport of water to the electrode (Koutecky-Levich): the kinetic Butler-Volmer
    current i_k in series with a diffusion-limited one, 1/i = 1/i_k + 1/i_lim, on each sign."""
    vt, lim = s.rng.uniform(0.1, 0.2), s.rng.uniform(1.5, 4.0)  # i_lim in units of the kinetic current at 1 V

    def branch(v):
        ik = 2 * np.sinh(v / vt) / (2 * np.sinh(1.0 / vt))
        return ik / (1 + np.abs(ik) / lim)

    _faradaic(s, branch)


def hy_duhem_output(s: Session) -> None:
    """A smooth rate-independent loop in the displacement path (Coleman-Hodgdon / Duhem): the sensed value z
    approaches the tip's position at a rate set by how far the tip has moved, dz = |dd| (d - z)/c."""
    w, c = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.1, 0.3) * ref_disp(s)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        z = np.empty_like(d)
        prev = d[0]
        for k, step in enumerate(np.abs(np.diff(np.r_[d[0], d]))):
            prev += (d[k] - prev) * -math.expm1(-step / c)  # exact for a path of constant d over the step
            z[k] = prev
        return (1 - w) * d + w * z

    map_disp(s, f)


def td_boxcar(s: Session) -> None:
    """The laser controller averages over its own sampling window T before the DAQ reads it: a moving average,
    (1 - exp(-sT))/(sT), group delay T/2, gain sinc(f T) (flat far below 1/T)."""
    T = lu(s.rng, 10e-3, 60e-3)
    map_disp(s, lambda r, d: lti(d, r.fs, lambda z: np.where(np.abs(z) < 1e-9, 1.0 + 0j, -np.expm1(-z * T) / np.where(np.abs(z) < 1e-9, 1.0, z * T))))


def so_reaimed(s: Session) -> None:
    """The laser is re-aimed after each re-clamping: the spot sits at a different x_m < L at each pressure
    (x_m/L 0.6-0.9, drawn per pressure), the beam read there through the strip's own transfer function."""
    from labrig.physics import presets, transfer

    pre = presets.get(s.preset)
    xs = {p: s.rng.uniform(0.6, 0.9) for p in s.pressures()}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        sp = pre.specimen(p)
        r.cols["disp_m"] = lti(r.cols["disp_m"], r.fs,
                               lambda z: transfer.displacement_tf(z, sp.with_(sensor_x=xs[p] * sp.geometry.length)) / transfer.displacement_tf(z, sp))


def cr_two_arm(s: Session) -> None:
    """Stress relaxation of the polymer under the clamp as a generalised Maxwell solid with two arms (a fast and a
    slow one), F/F0 = 1 - c1 (1 - exp(-t/tau1)) - c2 (1 - exp(-t/tau2))."""
    c1, c2, t1, t2 = s.rng.uniform(0.01, 0.03), s.rng.uniform(0.02, 0.06), lu(s.rng, 5.0, 30.0), lu(s.rng, 200.0, 1500.0)
    _clamp(s, lambda t: 1 - c1 * -np.expm1(-np.clip(t, 0, None) / t1) - c2 * -np.expm1(-np.clip(t, 0, None) / t2))


def dh_sqrt(s: Session) -> None:
    """Fickian desorption from a thin film: the early water loss grows as sqrt(t) (M_t/M_inf = 4 sqrt(D t/pi)/h)."""
    total = s.rng.uniform(0.15, 0.4)
    _dry(s, lambda u: total * np.sqrt(np.clip(u, 0, None)))


def sr_quadratic(s: Session) -> None:
    _strain(s, np.square)  # a thin film's resistance dR/R = G2 e^2 (crack opening, even in the strain)


def ld_rigid_tip(s: Session) -> None:
    """The spot on a tip that rotates as the strip bends: the reading of a point a lever D from the bend's hinge,
    D sin(atan(d/D)) = d / sqrt(1 + (d/D)^2)."""
    D = float(s.specimen["length_m"]) * s.rng.uniform(0.5, 0.8)
    map_disp(s, lambda r, d: d / np.sqrt(1 + (d / D) ** 2))


def mp_60_rectifier(s: Session) -> None:
    """A nearby supply's full-wave rectifier: the 60 Hz line with its 120 and 180 Hz ripple."""
    h2, h3 = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.1, 0.3)
    _mains(s, lambda t, p: np.cos(2 * np.pi * 60 * t + p) + h2 * np.cos(4 * np.pi * 60 * t + 2 * p) + h3 * np.cos(6 * np.pi * 60 * t + 3 * p))


def out_crosstalk(s: Session) -> None:
    """A shared ground return: the drive current's drop across it appears on the laser's analogue input, so the
    displacement channel carries a copy of the current (k ohm-equivalent of 2-6 % of the displacement scale)."""
    i_scale = max(float(np.std(r.cols["i_A"])) for r in s.series() if r.kind in ("harmonic", "stepped_sine", "step"))
    k = s.rng.uniform(0.02, 0.06) * ref_disp(s) / max(i_scale, 1e-12)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + k * r.cols["i_A"]


FRESH_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"diffusion": br_diffusion}, "faradaic_current": {"mass_limited": far_mass_limited},
    "hysteresis": {"duhem_output": hy_duhem_output}, "time_delay": {"boxcar": td_boxcar},
    "sensor_offset": {"reaimed": so_reaimed}, "clamp_relaxation": {"two_arm": cr_two_arm}, "dehydration": {"sqrt": dh_sqrt},
    "strain_resistance": {"quadratic": sr_quadratic}, "large_deflection": {"rigid_tip": ld_rigid_tip},
    "mains_pickup": {"60_rectifier": mp_60_rectifier}, "unexplained": {"crosstalk": out_crosstalk},
}
FRESH_PLAN = [("paper_31", "asrun"), ("s001_32", "asrun"), ("short_33", "no_spectra")]  # seed k of a fresh form
FRESH_CLEAN = [("paper_31", "asrun"), ("paper_31", "steps_sines"), ("s001_32", "asrun"), ("s001_32", "two_pressures"),
               ("short_33", "asrun"), ("short_33", "no_spectra")]


def fresh_cases() -> list[Case]:
    """The fresh held-out part: every fresh form (and the earlier outside structures) on the new seeds and strips,
    and the clean sessions of those bases."""
    out = [Case(t, f, 30 + k, b, v) for t, forms in FRESH_FORMS.items() for f in forms for k, (b, v) in enumerate(FRESH_PLAN)]
    out += [Case("unexplained", f, 30 + k, *FRESH_PLAN[k]) for k, f in enumerate(("fixture_resonance", "current_bandwidth", "laser_drift"))]
    out += [Case("none", "clean", 30 + k, b, v) for k, (b, v) in enumerate(FRESH_CLEAN)]
    return sorted(out, key=lambda c: c.seed)


REGISTRY: dict[str, dict[str, Callable[[Session], None]]] = {}  # forms of further sets (bench/inject_fresh2.py adds its own)


def form_of(case: Case) -> Callable[[Session], None]:
    return {**FORMS[case.truth], **EXTRA_FORMS.get(case.truth, {}), **FRESH_FORMS.get(case.truth, {}), **REGISTRY.get(case.truth, {})}[case.form]


# ------------------------------------------------------------------------------------ protocol and data shape


def v_asrun(s: Session) -> None:
    pass


def v_no_spectra(s: Session) -> None:
    s.recs = [r for r in s.recs if r.kind != "eis"]


def v_steps_sines(s: Session) -> None:
    s.recs = [r for r in s.recs if r.kind in ("step", "stepped_sine", "eis")]


def v_two_pressures(s: Session) -> None:
    keep = set(s.pressures()[::2])
    s.recs = [r for r in s.recs if float(r.entry["pressure_kPa"]) in keep]


def v_resampled(s: Session) -> None:
    """Another DAQ: every series at half the rate (block means of two samples, as an averaging ADC does)."""
    for r in s.series():
        n = r.cols["t_s"].size // 2 * 2
        r.cols = {k: (x[:n].reshape(-1, 2).mean(axis=1) if k != "t_s" else x[:n:2]) for k, x in r.cols.items()}


def v_shortened_shuffled(s: Session) -> None:
    """Records cut to 80 % of their length (the sine records keep 3 of their 4 measured cycles or so) and listed
    in a shuffled order in the manifest (their clock still places them)."""
    for r in s.series():
        if r.kind != "step":
            n = int(0.8 * r.cols["t_s"].size)
            r.cols = {k: x[:n] for k, x in r.cols.items()}
    order = s.rng.permutation(len(s.recs))
    s.recs = [s.recs[k] for k in order]


VARIANTS = {"asrun": v_asrun, "no_spectra": v_no_spectra, "steps_sines": v_steps_sines, "two_pressures": v_two_pressures,
            "resampled": v_resampled, "shortened_shuffled": v_shortened_shuffled}
EFFECT_PLAN = [("paper_21", "asrun"), ("paper_22", "steps_sines"), ("paper_23", "resampled")]  # seed k of a form
LONG_PLAN = [("long_21", "asrun")]  # a fourth seed of each effect's first form and of the first outside structure
CLEAN_PLAN = [(b, v) for b in ("paper_21", "paper_22", "paper_23") for v in VARIANTS] + [("long_21", "asrun"), ("long_21", "two_pressures")]


@dataclass(frozen=True)
class Case:
    truth: str  # the catalogue effect, "unexplained" (outside the catalogue) or "none"
    form: str
    seed: int
    base: str
    variant: str

    @property
    def name(self) -> str:
        return f"{self.truth}-{self.form}-{self.seed}-{self.base}-{self.variant}"


QUICK_CLEAN = [(b, v) for b in ("paper_21", "paper_22", "paper_23") for v in ("asrun", "no_spectra", "two_pressures")] + [("long_21", "asrun")]


def cases(only: str | None = None, extra: bool = False, full: bool = False) -> list[Case]:
    """The validation cases. ``full``: every form on every seed of EFFECT_PLAN (+ the 40 mm strip for the first
    form), every clean variant. Default (what a shared 2-core machine runs in ~45 min): three seeds per effect with
    its forms in turn (each form at least once), every outside structure on two seeds, ten clean sessions."""
    out = []
    for truth, forms in FORMS.items():
        if only and truth != only:
            continue
        forms = list({**forms, **(EXTRA_FORMS.get(truth, {}) if extra else {})})
        if truth == "none":
            out += [Case("none", "clean", k, b, v) for k, (b, v) in enumerate(CLEAN_PLAN if full else QUICK_CLEAN)]
        elif full:
            for j, form in enumerate(forms):
                plan = EFFECT_PLAN + (LONG_PLAN if j == 0 else [])
                out += [Case(truth, form, k, b, v) for k, (b, v) in enumerate(plan)]
        elif truth == "unexplained":
            out += [Case(truth, form, k, *EFFECT_PLAN[k]) for form in forms for k in (0, 2)]
        else:
            out += [Case(truth, forms[k % len(forms)], k, b, v) for k, (b, v) in enumerate(EFFECT_PLAN)]
    return sorted(out, key=lambda c: c.seed % 3)  # every kind of case early: a run cut short still covers them all


def base_export(cache: Path, base: str) -> Path:
    """The clean session ``base`` run on the simulated bench and exported once (cached)."""
    protocol, preset, seed = BASES[base]
    h5, out = cache / "base" / f"{base}.h5", cache / "export" / base
    if (out / "manifest.toml").exists():
        return out
    h5.parent.mkdir(parents=True, exist_ok=True)
    if not h5.exists():  # `labrig run PROTOCOL --sim --preset PRESET --seed N`, in this process (paper_long is registered here)
        from labrig.session_run import RunRequest, execute

        tmp = h5.with_suffix(".part.h5")
        res = execute(RunRequest(protocol, tmp, seed=seed, preset=preset))
        if res.exit_code != 0:
            raise RuntimeError(f"{base}: the run failed ({res.exit_code})")
        tmp.rename(h5)
    subprocess.run([sys.executable, "-m", "labrig", "export", str(h5), "--out", str(out), "--force"], check=True, capture_output=True)
    return out


def make_case(cache: Path, case: Case) -> Path:
    """The case's session file: the base's export with the form and the variant written in, imported."""
    h5 = cache / "cases" / f"{case.name}.h5"
    if h5.exists():
        return h5
    s = read_export(base_export(cache, case.base), BASES[case.base][1])
    s.rng = np.random.default_rng(zlib.crc32(f"{case.truth}/{case.form}/{case.seed}".encode()))
    form_of(case)(s)
    VARIANTS[case.variant](s)
    folder = cache / "csv" / case.name
    shutil.rmtree(folder, ignore_errors=True)
    manifest = write_import(s, folder)
    tmp = h5.with_suffix(".part.h5")
    h5.parent.mkdir(parents=True, exist_ok=True)
    from labrig.cli import main as labrig  # `labrig import`, in this process

    if labrig(["import", str(manifest), "--out", str(tmp)]) != 0:
        raise RuntimeError(f"{case.name}: labrig import failed")
    shutil.rmtree(folder, ignore_errors=True)
    tmp.rename(h5)
    return h5


def run_case(args: tuple[str, Case]):
    """Make (or reuse) the case's session and diagnose it as ``labrig diagnose --json`` does."""
    from labrig.analysis import load_and_fit, run_diagnosis
    from bench.coverage import CaseResult

    cache, case, reuse = Path(args[0]), args[1], args[2]
    path = make_case(cache, case)
    t0 = time.perf_counter()
    try:
        out = stored(path) if reuse else None
        if out is None:
            fitted = load_and_fit(path, "diagnose")
            out = run_diagnosis(path, fitted)
    except Exception as exc:  # a case the fit or diagnosis cannot take is a wrong answer, said so
        out = {"verdict": f"error: {type(exc).__name__}: {exc}"[:80], "cause": None, "effects": [], "gain": {"heldout_nrmse_ratio": float("nan"), "delta_bic": float("nan")}}
    return CaseResult(case.truth, case.seed, out["verdict"], out["cause"], list(out["effects"]), float(out["gain"]["heldout_nrmse_ratio"]),
                      float(out["gain"]["delta_bic"]), time.perf_counter() - t0, out, str(path)), case


def stored(path: Path) -> dict | None:
    """The diagnosis a run of this code left in the case's file (one with ``baseline.accuracy``), if any."""
    import json

    from labrig.store import SessionFile

    try:
        out = json.loads(SessionFile(path).read_analysis("diagnosis")["result_json"])
    except Exception:  # nothing stored
        return None
    return out if "accuracy" in out.get("baseline", {}) and "form" in out.get("extended", {}) else None


def _in_worker(job: tuple[str, str | None, tuple]):
    """(function name, module, its args) in a spawned worker: the module registers its set's forms, bases and
    variants here first (workers import modules by name, not the parent's state)."""
    name, registers, args = job
    if registers:
        importlib.import_module(registers)
    return {"run": run_case, "make": lambda a: make_case(Path(a[0]), a[1])}[name](args)


def _pool_map(name: str, cache: Path, todo: list[Case], jobs: int, registers: str | None, extra: tuple = ()):
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    for b in dict.fromkeys(c.base for c in todo):  # the bases first, one at a time (each is a simulated run)
        base_export(cache, b)
    with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
        yield from pool.map(_in_worker, [(name, registers, (str(cache), c, *extra)) for c in todo])


def run_all(cache: Path, todo: list[Case], jobs: int = 2, reuse: bool = False, registers: str | None = None) -> list:
    """Make (or reuse) and diagnose every case, ``jobs`` at a time; ``registers``: the module of a further set."""
    return list(_pool_map("run", cache, todo, jobs, registers, (reuse,)))


def plan_cases(plan: dict, clean: list, only: str | None = None) -> list[Case]:
    """A held-out set's cases from its plan (truth: [(form, seed, base, variant)]) and clean (seed, base, variant)."""
    out = [Case(t, f, k, b, v) for t, rows in plan.items() for f, k, b, v in rows]
    out += [Case("none", "clean", k, b, v) for k, b, v in clean]
    return sorted([c for c in out if not only or c.truth == only], key=lambda c: c.seed)


def make_set_main(cases: Callable[[str | None], list[Case]], registers: str, set_name: str) -> None:
    """The command line of a held-out set's module: make its case files (never diagnose them)."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--cache", default=str(REPO / ".cache" / "validation"))
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--only", default=None, help="one truth (effect name, unexplained or none)")
    ap.add_argument("--limit", type=int, default=0, help="make only the first N cases (0: all)")
    ap.add_argument("--make-only", action="store_true", help="make the case files (this script never diagnoses)")
    a = ap.parse_args()
    if not a.make_only:
        ap.error(f"this script only makes the cases (--make-only); diagnose them with bench/diagnose.py --set {set_name}")
    cache, todo = Path(a.cache), cases(a.only)
    todo = todo[: a.limit] if a.limit else todo
    t0 = time.perf_counter()
    for path in _pool_map("make", cache, todo, a.jobs, registers):
        print(f"  {time.perf_counter() - t0:6.0f} s  {path.name}", flush=True)
    print(f"{len(todo)} cases made in {time.perf_counter() - t0:.0f} s")


def report(results: list) -> dict[str, float]:
    """Print the validation set's confusion matrix and per-form answers; return the issue's figures."""
    from bench.coverage import confusion

    from labrig.diagnose.catalogue import CATALOGUE

    rs = [r for r, _ in results]
    print(confusion(rs, sorted(CATALOGUE) + ["none"]))
    by = {}
    for r, c in results:
        by.setdefault((c.truth, c.form), []).append(r.answer)
    for (truth, form), answers in by.items():
        print(f"  {truth:18s} {form:20s} {' '.join(a[:16] for a in answers)}")
    share = lambda xs: sum(r.right for r in xs) / max(len(xs), 1)  # noqa: E731
    eff = [r for r in rs if r.scenario not in ("none", "unexplained")]
    figs = {"effects_right": share(eff), "unexplained_right": share([r for r in rs if r.scenario == "unexplained"]),
            "none_right": share([r for r in rs if r.scenario == "none"])}
    print(f"validation set: effects right {100 * figs['effects_right']:.0f} % ({len(eff)}), outside the catalogue -> unexplained "
          f"{100 * figs['unexplained_right']:.0f} %, clean -> none {100 * figs['none_right']:.0f} %")
    ratios = {}
    for r in rs:
        if r.right and r.scenario not in ("none", "unexplained"):
            ratios.setdefault(r.scenario, []).append(r.heldout_ratio)
    print("held-out error ratio of the named extension (right answers): " + ", ".join(f"{k} {max(v):.2f}" for k, v in sorted(ratios.items())))
    return figs


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--cache", default=str(REPO / ".cache" / "validation"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default=None, help="one truth (effect name, unexplained or none)")
    ap.add_argument("--make-only", action="store_true", help="make the case files, do not diagnose")
    ap.add_argument("--extra", action="store_true", help="the further forms too (EXTRA_FORMS)")
    ap.add_argument("--full", action="store_true", help="every form on every seed, every clean variant")
    ap.add_argument("--reuse", action="store_true", help="take a diagnosis this code stored in a case's file")
    ap.add_argument("--fresh", action="store_true", help="the fresh held-out part (fresh_cases) instead")
    a = ap.parse_args()
    cache = Path(a.cache)
    todo = fresh_cases() if a.fresh else cases(a.only, a.extra, a.full)
    t0 = time.perf_counter()
    if a.make_only:
        for b in dict.fromkeys(c.base for c in todo):
            base_export(cache, b)
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(a.jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
            list(pool.map(make_case, [cache] * len(todo), todo))
        print(f"{len(todo)} cases made in {time.perf_counter() - t0:.0f} s")
        return
    results = run_all(cache, todo, a.jobs, a.reuse)
    print(f"{len(todo)} validation cases, {a.jobs} at a time: {time.perf_counter() - t0:.0f} s")
    report(results)


if __name__ == "__main__":
    main()
