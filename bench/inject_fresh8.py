"""A ninth held-out set for the diagnosis (issue 12), written without sight of the diagnosis (its code, its doc,
its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh7.py and the simulated
bench (mock_devices/effects.py); four structures outside the catalogue (truth "unexplained": the open bath's surface
sloshing in the laser's path, speckle noise that grows with the tip's speed, an electrode delaminating at one moment
of the session, a neighbouring rig's square drive coupled into the current input); clean sessions. All on three
bases of new seeds (94-96: the paper strip, the seed-001 strip on its own sweep, the paper strip 32 mm free) and on the
earlier sets' protocol / data-shape variants plus one new here: every time series sampled by a host-timed loop
(software timing: each sample taken late by the operating system's latency and stamped when it was taken, so the
stamps are right but unevenly spaced; the import contract asks t_s strictly increasing, not evenly spaced).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh7 are reused (importing inject_fresh7 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import. Strengths are drawn from
the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case, measured in
memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the column's
sample-to-sample noise at rest, from the samples before the step records' edges: 0.57 um and 15 uA on the paper bases,
0.58 um and 4.2 uA on the seed-001 one).

Run: python bench/inject_fresh8.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable

import numpy as np
from scipy import signal

import inject
from inject import Case, Rec, Session, _dry, lti, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _map_through, _step_response
from inject_fresh3 import _past, _resist, _sign
from inject_fresh4 import _preset, _ratio_both
from inject_fresh6 import _blocks, _bursts, _reading
from inject_fresh7 import KGF, _block_of, _ramp_env

# the paper's strip 32 mm free (earlier sets used 20, 25, 28, 30, 35, 38, 40 and 45 mm; its 1 V step peaks at ~10 mm,
# inside the laser's +-20 mm): registered in every process that imports this module
inject.register_free_length("paper_32", 0.032)

inject.BASES.update({
    "paper_94": ("paper-sweep", "paper", 94),
    "s001_95": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 95),
    "p32_96": ("paper-sweep", "paper_32", 96),
})


# ------------------------------------------------------------------------------------------------ tools


def _leaky(s: Session, rate: dict[int, np.ndarray], tau: float) -> dict[int, np.ndarray]:
    """A leaky store through the session in time order: dc/dt = rate - c/tau (rate: id(record) -> array), exact for
    the rate held over each sample, decaying over the rests between records. Returns c per record."""
    out, c, t_end = {}, 0.0, None
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None:
            c *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau)
        a = math.exp(-1.0 / (r.fs * tau))
        y, _ = signal.lfilter([tau * (1 - a)], [1.0, -a], rate[id(r)], zi=[a * c])
        out[id(r)], c, t_end = y, float(y[-1]), float(t[-1])
    return out


def _late(s: Session, delay: Callable[[Rec, np.ndarray], np.ndarray], seconds: float = 0.3) -> None:
    """The displacement read late by delay(r, t) (seconds, any shape), the session's history before each record
    (inject_fresh3._past) supplying the samples before its start."""
    new = {}
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        past = _past(s, r, "disp_m", seconds, r.fs)
        T = np.r_[t[0] - np.arange(past.size, 0, -1) / r.fs, t]
        new[id(r)] = np.interp(t - delay(r, t), T, np.r_[past, d])
    map_disp(s, lambda r, d: new[id(r)])


def _hum(t: np.ndarray, f: float, harm: dict[int, float], phase: float) -> np.ndarray:
    """A line at f with harmonics {n: relative amplitude}, phase locked to the session clock."""
    w = 2 * np.pi * f * t + phase
    return np.cos(w) + sum(a * np.cos(n * w) for n, a in harm.items())


def _drive_share(s: Session, y: dict[int, np.ndarray], share: float) -> None:
    """A share of the strip bending from y (id(record) -> array) instead of the recorded drive: (1 - share) d +
    share (d_0 + S * dy), the record's own displacement for the rest and, for the share, the drive y's changes
    within the record through the strip's measured unit-step response at that pressure (inject_fresh2._step_response
    of the pressure's first step record, held at its last value beyond), from the rest d_0 the record starts in.
    Where y stays put (a locked zone on a fast sine) the share simply stops moving, with no kernel error on fast
    records."""
    steps = {float(r.entry["pressure_kPa"]): _step_response(r) for r in reversed(_chrono(s)) if r.kind == "step"}
    for r in s.series():
        p, d = float(r.entry["pressure_kPa"]), r.cols["disp_m"]
        if p not in steps:
            continue
        ts, S = steps[p]
        n = d.size
        m = 1 << int(math.ceil(math.log2(2 * n)))
        dy = np.diff(y[id(r)] - y[id(r)][0], prepend=0.0)
        resp = np.fft.irfft(np.fft.rfft(dy, m) * np.fft.rfft(np.interp(np.arange(n) / r.fs, ts, S), m), m)[:n]
        r.cols["disp_m"] = (1 - share) * d + share * (d[0] + resp)


def _arc(d: np.ndarray, L: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The exact uniform arc whose linear tip reading is d: curvature, tip height and tip abscissa."""
    k = 2 * d / L**2
    ks = np.where(np.abs(k) < 1e-9, 1e-9, k)
    return k, (1 - np.cos(ks * L)) / ks, np.sin(ks * L) / ks


# ------------------------------------------------------------------------------------------------ back relaxation


def br_salt_polarisation(s: Session) -> None:
    """Concentration polarisation: the ionic current drives the cations to the cathode faster than the membrane's
    salt can follow, leaving a salt gradient across it that relaxes over tau_c 30-120 s (log); the osmotic back-flow
    grows with that gradient. A lag 1 - K2/(tau s + 1) per record (tau 3-10 s, log) whose K2 runs from 0.3-0.6 (no
    gradient) to 1.0-1.3 (the session's strongest) with the gradient left by the drive at that record: a leaky store
    of abs(i) (time order, decaying over the rests), its mean over the record. With the session's history. Measured
    (paper_94): displacement RMS -73 % (residual 82 % of its RMS), the 1 V steps' peaks -77 to -78 %, 20 Hz record
    residual 22-25 %."""
    k0, k1, tau, tc = s.rng.uniform(0.3, 0.6), s.rng.uniform(1.0, 1.3), lu(s.rng, 3.0, 10.0), lu(s.rng, 30.0, 120.0)
    c = _leaky(s, {id(r): np.abs(r.cols["i_A"]) for r in s.series()}, tc)
    x = {k: float(np.mean(v)) for k, v in c.items()}
    top = max(x.values()) or 1.0
    _map_through(s, lambda r: (lambda k2: lambda z: 1 - k2 / (tau * z + 1))(k0 + (k1 - k0) * x[id(r)] / top), 120.0)


def br_joule_heating(s: Session) -> None:
    """The strip's own dissipation v i warms it (a thermal lag of 5-20 s, log; 3-10 K at the session's hottest) and
    water's diffusivity in Nafion follows Arrhenius (E_a 15-30 kJ/mol): the back-flow's lag runs faster while the
    strip is hot, tau = tau_0 exp(E_a/R (1/T - 1/T_0)), tau_0 3-12 s (log), K2 0.9-1.3. A lag with a time-varying
    time constant, sample by sample through the session in time order (the state carried over the rests), reading d
    - K2 x. Measured (p32_96): displacement RMS -76 % (residual 100 %), the 1 V steps' peaks -79 %, 20 Hz record
    residual 19-36 %."""
    k2, tau0, ea = s.rng.uniform(0.9, 1.3), lu(s.rng, 3.0, 12.0), s.rng.uniform(15e3, 30e3)
    dT, tth = s.rng.uniform(3.0, 10.0), lu(s.rng, 5.0, 20.0)
    heat = _leaky(s, {id(r): np.abs(r.cols["v_V"] * r.cols["i_A"]) for r in s.series()}, tth)
    top = max(float(np.max(h)) for h in heat.values()) or 1.0
    x, d_end, t_end = 0.0, 0.0, None
    for r in _chrono(s):
        t, d = r.cols["t_s"], r.cols["disp_m"]
        tau = tau0 * np.exp(ea / 8.314 * (1 / (293.15 + dT * heat[id(r)] / top) - 1 / 293.15))
        if t_end is not None:
            x += -math.expm1(-(float(t[0]) - t_end) / tau0) * (0.5 * (d_end + float(d[0])) - x)
        out = np.empty(d.size)
        for k, (dk, ak) in enumerate(zip(d.tolist(), np.exp(-1 / (r.fs * tau)).tolist())):
            x = dk + (x - dk) * ak
            out[k] = x
        d_end, t_end = float(d[-1]), float(t[-1])
        r.cols["disp_m"] = d - k2 * out


# ------------------------------------------------------------------------------------------------ faradaic current


def far_peroxide_buildup(s: Session) -> None:
    """Oxygen reduction on the cathodic platinum runs partly by the two-electron path and leaves hydrogen peroxide
    in the bath by the strip; it builds up with the charge passed above the reduction's onset (abs(v) > 0.2-0.4 V)
    and is lost by decomposition and diffusion over tau_p 300-1500 s (log). The peroxide is oxidised on the anodic
    face and reduced on the cathodic one at low overpotential: a saturating wave sign(v) (1 - exp(-abs(v)/b)), b
    0.1-0.25 V, times the peroxide present, 0.05-0.3 mA at the session's highest (log): a faradaic current that
    grows through the session with the drive's history. Current only. Measured (paper_94): current RMS +1.5 %,
    residual 2.1 % of its RMS (4.4x its noise), 0.14 mA at its largest, the steps' current peaks +0.3 % from the
    second block on."""
    imax, b, vo, tp = lu(s.rng, 5e-5, 3e-4), s.rng.uniform(0.1, 0.25), s.rng.uniform(0.2, 0.4), lu(s.rng, 300.0, 1500.0)
    c = _leaky(s, {id(r): np.abs(r.cols["i_A"]) * (np.abs(r.cols["v_V"]) > vo) for r in s.series()}, tp)
    top = max(float(np.max(x)) for x in c.values()) or 1.0
    for r in s.series():
        v = r.cols["v_V"]
        r.cols["i_A"] = r.cols["i_A"] + imax * c[id(r)] / top * np.sign(v) * -np.expm1(-np.abs(v) / b)


def far_crack_area(s: Session) -> None:
    """Electrolysis runs where platinum, membrane and water meet, and a cracked electrode offers that line along its
    crack walls: as the tensioned face (side drawn) stretches its cracks open and the reacting area grows, a share
    a0 0.2-0.5 there at rest, rising as tanh of the tension (in units of the session's displacement scale; the face
    limits the current). Butler-Volmer at the terminal voltage, 2 sinh(v/2v_t), v_t 0.12-0.25 V, 0.2-0.6 mA at 1 V
    on the unit tension (log). The current follows the bend, so it lags the drive: a loop in i-v. Current only.
    Measured (s001_95): current RMS +0.3 %, residual 0.8 % (5.5x its noise), peaks 0.17 mA."""
    i1, vt, a0, side = lu(s.rng, 2e-4, 6e-4), s.rng.uniform(0.12, 0.25), s.rng.uniform(0.2, 0.5), _sign(s)
    ref = ref_disp(s)
    for r in s.series():
        e = np.clip(side * r.cols["disp_m"] / ref, 0, None)
        area = a0 + (1 - a0) * np.tanh(e) / math.tanh(1.0)
        r.cols["i_A"] = r.cols["i_A"] + i1 * np.sinh(r.cols["v_V"] / (2 * vt)) / math.sinh(1 / (2 * vt)) * area


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_snap_fold(s: Session) -> None:
    """A strip with a residual curl across its width (the plating's stress) is a tape spring: bent against the
    curl's sense it holds its section until a critical moment, then snaps into a localised fold, and unfolds only at
    a lower moment (the fold's hysteresis, Seffen & Pellegrino). One side (drawn) folds at m_c 0.4-0.75 of the
    session's largest bend on that side and unfolds below m_r = (0.3-0.7) m_c; while folded the fold is a hinge that
    adds g 4-12 % of the bend beyond the unfolding point: a single big hysteron, a jump at the snap,
    rate-independent, its state through the session. Displacement only. Measured (p32_96): displacement residual
    0.33 % of its RMS (23x its noise), 1 % of the samples folded (104 um RMS there, 190x), the 1 V steps untouched
    (the fold on the other side)."""
    side, mc, g = _sign(s), s.rng.uniform(0.4, 0.75), s.rng.uniform(0.04, 0.12)
    mr = mc * s.rng.uniform(0.3, 0.7)
    recs = _chrono(s)
    d = np.concatenate([r.cols["disp_m"] for r in recs])
    top = max(float(np.max(side * d)), 1e-12)
    on, state = np.empty(d.size, bool), False
    for k, m in enumerate((side * d / top).tolist()):
        state = m > mc or (state and m > mr)
        on[k] = state
    out = d + np.where(on, side * g * np.clip(side * d - mr * top, 0, None), 0.0)
    for r, x in zip(recs, np.split(out, np.cumsum([r.cols["disp_m"].size for r in recs])[:-1])):
        r.cols["disp_m"] = x


def hy_root_friction(s: Session) -> None:
    """Friction at the jaw's edge: the strip's first millimetres beside the clamp swell under the pad's falling
    pressure, and Coulomb friction holds that zone's actuation until the drive has moved it by a threshold: a play
    on the drive whose radius grows with the clamp pressure, r = r_0 (p/p_min)^k (r_0 0.05-0.15 V, k 0.5-1), the
    zone's share of the tip's bend 0.15-0.35; each re-clamping sets the zone at rest (the play's state from 0 at
    each new pressure). At the highest pressures the zone locks for the 0.5 V sines. Through the strip's measured
    step response (_drive_share: the locked zone's share stops moving, the rest of the strip as measured); current
    untouched. Measured (paper_94): displacement RMS -5.3 % (residual 10 %), the 1 V steps' peaks -1.8 % (612 kPa)
    to -10 % (4287 kPa); on the 20 Hz records (5 um of signal) the zone's remanent state from the record before is
    released: drifts of 40-110 um."""
    share, r0, k = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.05, 0.15), s.rng.uniform(0.5, 1.0)
    recs = _chrono(s)
    p = np.concatenate([np.full(r.cols["v_V"].size, float(r.entry["pressure_kPa"])) for r in recs])
    rad = r0 * (p / p.min()) ** k

    v = np.concatenate([r.cols["v_V"] for r in recs])
    y, prev, pp = np.empty_like(v), 0.0, None
    for j, (x, rr, pj) in enumerate(zip(v.tolist(), rad.tolist(), p.tolist())):
        if pj != pp:
            prev, pp = 0.0, pj
        prev = min(max(prev, x - rr), x + rr)
        y[j] = prev
    parts = np.split(y, np.cumsum([r.cols["v_V"].size for r in recs])[:-1])
    _drive_share(s, dict(zip([id(r) for r in recs], parts)), share)


# ------------------------------------------------------------------------------------------------ time delay


def td_ntp_slew(s: Session) -> None:
    """The laser streamed over Ethernet and stamped by a host whose clock NTP disciplines: the host's crystal runs
    50-150 ppm off (log), so between polls (every 64-256 s, log) its offset from the DAQ's clock grows, and at each
    poll NTP slews it back at its 500 ppm limit: a sawtooth of delay (rising for the poll interval, falling 3-10x
    faster) on top of the stream's fixed latency of 5-20 ms (log), free-running on the session clock. Displacement
    only. Measured (s001_95): delay 9.5-21 ms (95 ppm, polls every 124 s), displacement residual 0.53 % of its RMS
    (17x its noise), 20 Hz records' residuals 117-185 %."""
    base, drift, poll, ph = lu(s.rng, 5e-3, 2e-2), lu(s.rng, 5e-5, 1.5e-4), lu(s.rng, 64.0, 256.0), s.rng.uniform(0, 1)
    up, back = drift * poll, drift * poll / (5e-4 - drift)

    def delay(r: Rec, t: np.ndarray) -> np.ndarray:
        u = ((t - s.t0) / (poll + back) + ph) % 1.0 * (poll + back)
        return base + np.where(u < poll, drift * u, up - (5e-4 - drift) * (u - poll))

    _late(s, delay)


def td_block_alignment(s: Session) -> None:
    """The laser logged by its own controller's software, restarted at each re-clamping, and aligned to the DAQ's
    records by the step's edge: the alignment is good to one of the laser's samples (its logging period T_L 2-10 ms,
    log), so each pressure block carries its own delay, the controller's fixed filter delay 5-20 ms (log) plus an
    error uniform within +-T_L/2. Constant within a block, jumping between blocks. Displacement only. Measured
    (p32_96): delays 3.4-10.5 ms by block, displacement residual 0.22 % (10x its noise), 20 Hz records' residuals
    37-112 %."""
    filt, tl = lu(s.rng, 5e-3, 2e-2), lu(s.rng, 2e-3, 1e-2)
    dl = {p: filt + s.rng.uniform(-0.5, 0.5) * tl for p in sorted(_blocks(s))}
    _late(s, lambda r, t: np.full(t.size, dl[float(r.entry["pressure_kPa"])]))


# ------------------------------------------------------------------------------------------------ sensor offset


def so_shadow_edge(s: Session) -> None:
    """No triangulation: a thru-beam laser micrometer (a light sheet across the strip near its tip, a line camera
    behind it) reports the edge of the strip's shadow, the extreme of the strip's height over the band the sheet
    covers, [x_c - w_b/2, x_c + w_b/2] L (x_c 0.85-0.95, the sheet 0.03-0.08 L thick): on the upper edge the band's
    outer end while the strip bends up, its inner end while it bends down (w grows along the strip), so the two
    sides of the bend are read at two stations, max(w(x_hi), w(x_lo)) (the edge drawn). Through
    inject_fresh6._reading at both stations: gain down, zeros move, an even part. Measured (paper_94): displacement
    RMS -20 % (residual 20 %), the 1 V steps' peaks -20 %, 20 Hz record residual 28-35 %."""
    xc, wb, side = s.rng.uniform(0.85, 0.95), s.rng.uniform(0.03, 0.08), _sign(s)
    hi = _reading(s, lambda sp: [(1.0, min(xc + wb / 2, 1.0) * sp.geometry.length, 0)])
    lo = _reading(s, lambda sp: [(1.0, (xc - wb / 2) * sp.geometry.length, 0)])
    map_disp(s, lambda r, d: side * np.maximum(side * hi[id(r)], side * lo[id(r)]))


def so_two_marker(s: Session) -> None:
    """Video tracking of two markers painted on the strip at a and b of its length (a 0.3-0.55, b 0.7-0.9; the tip
    itself is hard to track against the bath), the tip's deflection extrapolated along the straight line through
    them: w(b) + (1 - b)/(b - a) (w(b) - w(a)). A chord extrapolation reads a curved strip short (it misses the
    curvature beyond b) and weights the stations with opposite signs above f1. Through inject_fresh6._reading.
    Measured (p32_96): displacement RMS -7.3 % (residual 7.3 %), the 1 V steps' peaks -7.2 %, 20 Hz record residual
    16-19 %."""
    a, b = s.rng.uniform(0.3, 0.55), s.rng.uniform(0.7, 0.9)
    k = (1 - b) / (b - a)
    new = _reading(s, lambda sp: [(1 + k, b * sp.geometry.length, 0), (-k, a * sp.geometry.length, 0)])
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ clamp relaxation


def _per_block(s: Session, rel: Callable[[np.ndarray], np.ndarray]) -> dict[int, np.ndarray]:
    """The law rel(time since the block's first sample) on each series' samples; the load cell follows it (the
    indicator's 0.01 kgf). Returns rel per record."""
    block, out = _block_of(s), {}
    for r in s.series():
        x = rel(np.clip(r.cols["t_s"] - block(r.cols["t_s"]), 0, None))
        if "force_N" in r.cols:
            r.cols["force_N"] = np.round(r.cols["force_N"] * x / KGF) * KGF
        out[id(r)] = x
    return out


def cr_swelling_pressure(s: Session) -> None:
    """A fixed jaw gap on a strip whose clamped part was squeezed and partly drained by the last setting: it takes
    water back from the bath and swells against the pads, so the force first rises by a 3-8 % (Fickian uptake, 1 -
    exp(-t/tau_s), tau_s 30-150 s, log), then the polymer relaxes under the raised stress by r 2-6 % over tau_r
    300-1500 s (log), from each block's start. The strip follows its clamp at the force it feels (the preset's clamp
    law at p F/F_set, per record at its mean) with its clamped layer as wet as the uptake says, 1 - exp(-t/tau_s):
    its CPE Q0c x (1 + q w), R_c and the leak R_pc x (1 - q w/2), q 0.1-0.3 (Table 1's rows read the other way), and
    the swollen layer softer, gripping less (K_t bar x (1 - k w), k 0.05-0.15), through the strip's transfer
    functions (inject_fresh4._ratio_both). Measured (paper_94): load cell up to 1.02 of its setting by the blocks'
    ends (+1.7 N at most), current RMS +3.8 % (residual 4.0 %, 8x its noise), displacement residual 0.13 % (8x), 20
    Hz record residuals 8-10 % (displacement) and 4-5 % (current)."""
    a, ts = s.rng.uniform(0.03, 0.08), lu(s.rng, 30.0, 150.0)
    r0, tr = s.rng.uniform(0.02, 0.06), lu(s.rng, 300.0, 1500.0)
    q, kt = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.15)
    rel = _per_block(s, lambda t: (1 + a * -np.expm1(-t / ts)) * (1 - r0 * -np.expm1(-t / tr)))
    block, pre = _block_of(s), _preset(s)

    def new(r: Rec):
        w = float(np.mean(-np.expm1(-np.clip(r.cols["t_s"] - block(r.cols["t_s"]), 0, None) / ts)))
        sp = pre.specimen(float(r.entry["pressure_kPa"]) * float(np.mean(rel[id(r)])))
        cl = sp.clamp
        cl = replace(cl, Q0c=cl.Q0c * (1 + q * w), R_c=cl.R_c * (1 - q * w / 2), R_pc=cl.R_pc * (1 - q * w / 2))
        return sp.with_(clamp=cl, Kt_bar=sp.Kt_bar * (1 - kt * w))

    _ratio_both(s, new)


def cr_gasket_extrusion(s: Session) -> None:
    """Soft pads (a silicone or rubber gasket) under a fixed jaw gap flow out sideways: Stefan's squeeze flow of a
    thin layer, the held force falling as 1 - r (1 - (1 + t/t_s)^(-1/2)) (r 5-15 %, t_s 20-200 s, log, from each
    block's start), and the bulge the pads push out beyond the jaw's edge grips the strip's first millimetres: the
    clamping line moves out and the free length shortens by up to 1-3 % of it along the same law. Per record at its
    mean: the preset's clamp at that force and a specimen that much shorter (the laser's spot stays on the tip),
    through the strip's transfer functions (inject_fresh4._ratio_both): gain down, f1 up, within each block.
    Measured (s001_95): load cell at 0.89-0.97 of its setting by the blocks' ends, displacement RMS -0.8 % (residual
    0.9 %, 28x its noise), 20 Hz record residual 16-23 %, current residual 0.3 % (2.3x)."""
    r0, tsq, dl = s.rng.uniform(0.05, 0.15), lu(s.rng, 20.0, 200.0), s.rng.uniform(0.01, 0.03)
    u = {k: x for k, x in _per_block(s, lambda t: 1 - r0 * (1 - (1 + t / tsq) ** -0.5)).items()}
    pre = _preset(s)

    def new(r: Rec):
        x = float(np.mean(1 - u[id(r)])) / r0
        sp = pre.specimen(float(r.entry["pressure_kPa"]) * (1 - r0 * x))
        return sp.with_(geometry=replace(sp.geometry, length=sp.geometry.length * (1 - dl * x)))

    _ratio_both(s, new)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_handling_dips(s: Session) -> None:
    """A strip in water lifted or handled in air each time the clamp is re-set (20-60 s before the block's first
    record): it loses 5-15 % of its mobile water each time, and the bath gives back a share rho 0.6-0.9 of it over
    tau 60-300 s (log) while the block runs, the rest lost for good (a surface skin that does not re-wet): a loss
    stepping up at every re-clamping and recovering within the block. Through inject._dry (conductance and spectra
    follow; each spectrum, taken first in its block, at its deepest). Measured (p32_96): displacement RMS -11 %
    (residual 12 %), the 1 V steps' peaks -7, -10, -13 and -15 % block by block, current -3.9 %, impedance at 0.1 Hz
    1.06-1.11x."""
    dip, rho = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.6, 0.9)
    tr, lead = lu(s.rng, 60.0, 300.0), s.rng.uniform(20.0, 60.0)
    starts = np.sort([a for a, _ in _blocks(s).values()])

    def loss(u: np.ndarray) -> np.ndarray:
        t = s.t0 + np.asarray(u) * (s.t1 - s.t0)
        k = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, None)
        return dip * ((1 - rho) * (k + 1) + rho * np.exp(-(np.clip(t - starts[k], 0, None) + lead) / tr))

    _dry(s, loss)


def dh_lamp_cycling(s: Session) -> None:
    """A strip in air beside a lamp or an enclosure heater on a thermostat: while the heater is on (its cycle
    300-900 s, on 30-60 %) the air at the strip is warmer and drier and the strip loses water several times faster
    than while it rests (the resting rate 0.1-0.3 of it): a loss that grows in a staircase of steep and shallow
    stretches, total 0.15-0.35 by the session's end. Through inject._dry. Measured (s001_95): displacement RMS -8.1
    % (residual 10 %), the 1 V steps' peaks -0, -5, -11 and -16 %, current -3.7 % (29x its noise), impedance at 0.1
    Hz up to 1.06x."""
    total, base = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.1, 0.3)
    period, duty, ph = s.rng.uniform(300.0, 900.0), s.rng.uniform(0.3, 0.6), s.rng.uniform(0, 1)
    tg = np.linspace(s.t0, s.t1, 20001)
    rate = base + (1 - base) * (((tg - s.t0) / period + ph) % 1.0 < duty)
    cum = np.r_[0.0, np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(tg))]
    _dry(s, lambda u: total * np.interp(s.t0 + np.asarray(u) * (s.t1 - s.t0), tg, cum / cum[-1]))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_gold_overlayer(s: Session) -> None:
    """Electrodes of platinum with a thin gold overlayer (plated on to lower the surface resistance): the gold
    carries 1 - g_Pt of the face's conductance (g_Pt 0.2-0.5) until its own cracks percolate, its share falling as
    1/(1 + (e/e_c)^m) of the tension e (e_c 0.3-0.8 of the displacement scale, m 2-4), leaving the cracked platinum:
    dR/R = 1/(g_Pt + (1 - g_Pt)/(1 + (e/e_c)^m)) - 1, a threshold then a plateau, on the tensioned face (side drawn)
    and on the other face at 1.5-3x its e_c. Gains fall by 0.015-0.04 (displacement), 0.04-0.1 (current) per unit
    (inject_fresh3._resist). Measured (paper_94): displacement RMS -2.1 % (the 1 V steps' peaks -2.4 %), current
    residual 1.9 % (3.9x its noise)."""
    side, gpt, ec, m = _sign(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.3, 0.8), s.rng.uniform(2.0, 4.0)
    eo = ec * s.rng.uniform(1.5, 3.0)
    face = lambda e, c: 1 / (gpt + (1 - gpt) / (1 + (np.clip(e, 0, None) / c) ** m)) - 1  # noqa: E731
    _resist(s, lambda r, e: face(side * e, ec) + face(-side * e, eo), (0.015, 0.04), (0.04, 0.1))


def sr_crack_flicker(s: Session) -> None:
    """A cracked electrode near its percolation threshold: the bridges across its cracks make and break while the
    face is stretched (the resistance fluctuations of a strained cracked film), a random telegraph of +-a (a
    0.1-0.3) on its strain gauge, switching at 2-20 per second (log); the tensioned face (side drawn) and the other
    at 0.1-0.4 of it. The current feels each switch at once, the bend through the strip's charging (a lag of 0.2-1
    s, log). Gains fall by 0.015-0.04 (displacement), 0.04-0.1 (current) per unit of dR/R. Measured (s001_95):
    displacement RMS -4.1 % (the 1 V steps' peaks -5 to -7 %), current residual 1.3 % (8.8x its noise)."""
    side, a, rate = _sign(s), s.rng.uniform(0.1, 0.3), lu(s.rng, 2.0, 20.0)
    tb, other = lu(s.rng, 0.2, 1.0), s.rng.uniform(0.1, 0.4)
    kd, ki, ref = s.rng.uniform(0.015, 0.04), s.rng.uniform(0.04, 0.1), ref_disp(s)
    for r in s.series():
        flips = np.cumsum(s.rng.random(r.cols["t_s"].size) < -math.expm1(-rate / r.fs))
        tel = np.where(flips % 2 == 0, 1.0, -1.0) * _sign(s)
        e = r.cols["disp_m"] / ref
        g = np.clip(side * e, 0, None) + other * np.clip(-side * e, 0, None)
        r.cols["disp_m"] = r.cols["disp_m"] * (1 - kd * g * (1 + a * lti(tel, r.fs, lambda z: 1 / (1 + tb * z))))
        r.cols["i_A"] = r.cols["i_A"] * (1 - ki * g * (1 + a * tel))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_ldv_integrated(s: Session) -> None:
    """A laser Doppler vibrometer aimed at x_s = 0.9-0.98 L (just inboard, so the beam stays on the strip) with its
    displacement decoder: it integrates the velocity component along the beam of whatever material point is under
    the beam at each moment. On the exact uniform arc the point under the beam slides as the strip draws back, and
    the decoder misses the slope x slide term: the reading is R(k) = int_0^k dY/dk(s*(k'), k') dk' (s* the material
    point at the beam's abscissa), neither the material point's height nor the fixed station's; scaled to the tip as
    a uniform arc gives it, (L/x_s)^2. Measured (p32_96): displacement RMS +0.5 % (residual 0.6 %, 41x its noise),
    the 1 V steps' peaks +1.0 % (the decoder reads more than the material point's height)."""
    L = float(s.specimen["length_m"])
    xs = L * s.rng.uniform(0.9, 0.98)
    top = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) * 1.05 + 1e-12
    k = np.linspace(0.0, 2 * top / L**2, 801)
    ks = np.where(k < 1e-9, 1e-9, k)
    sst = np.arcsin(np.clip(ks * xs, 0, 0.999)) / ks
    dy = np.where(k < 1e-9, sst**2 / 2, sst * np.sin(ks * sst) / ks - (1 - np.cos(ks * sst)) / ks**2)
    R = np.r_[0.0, np.cumsum(0.5 * (dy[1:] + dy[:-1]) * np.diff(k))] * (L / xs) ** 2
    dg = k * L**2 / 2
    map_disp(s, lambda r, d: np.sign(d) * np.interp(np.abs(d), dg, R))


def ld_tilt_characteristic(s: Session) -> None:
    """A triangulation laser on the exact uniform arc's material point, and its tilt characteristic: a target tilted
    by theta returns a spot whose intensity profile is skewed, and the receiver's centroid shifts by an even amount,
    b theta^2 (the data sheet's "angle characteristic"), 10-60 um at 30 deg (log, its sign by the head's
    orientation), theta the tip's angle. Odd compression from the arc, an even part from the head. Measured
    (s001_95): displacement RMS -0.7 % (residual 0.9 %, 25x its noise), the 1 V steps' peaks -1.3 %."""
    L, b = float(s.specimen["length_m"]), lu(s.rng, 1e-5, 6e-5) * _sign(s) / (np.pi / 6) ** 2

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        k, y, _ = _arc(d, L)
        return y + b * (k * L) ** 2

    map_disp(s, f)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_clamp_motor(s: Session) -> None:
    """The motorised clamp's stepper driver: its supply transformer and the energised windings radiate the line (50
    or 60 Hz +- 0.05, with 3rd 0.2-0.4 and 5th 0.05-0.2) into the laser's and the current amplifier's cables while
    the motor holds at full current, from the setting (20-40 s before the block's first record) for 60-180 s, and at
    the driver's standby current (0.1-0.3 of it) for the rest of the block: a pickup stepping with the pressure
    blocks. 1.5-5 um and 3-10 uA (log) at full; phase locked to the session clock. Measured (paper_94): residual 1.1
    um RMS on the displacement (1.9x its noise) and 4.2 uA on the current (0.3x its white noise, a narrow line),
    peaks 3.6 um and 14 uA, 20 Hz record residual 8-9 %."""
    ad, ai, h3, h5 = lu(s.rng, 1.5e-6, 5e-6), lu(s.rng, 3e-6, 1e-5), s.rng.uniform(0.2, 0.4), s.rng.uniform(0.05, 0.2)
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    pd, pi, standby = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0.1, 0.3)
    spans = []
    for a, _ in sorted(_blocks(s).values()):
        lead = s.rng.uniform(20.0, 40.0)
        spans.append((a - lead, a - lead + s.rng.uniform(60.0, 180.0)))
    for r in s.series():
        t = r.cols["t_s"]
        env = standby + (1 - standby) * _ramp_env(t, spans, 0.5)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * env * _hum(t, f, {3: h3, 5: h5}, pd)
        r.cols["i_A"] = r.cols["i_A"] + ai * env * _hum(t, f, {3: h3, 5: h5}, pi)


def mp_bath_heater_leak(s: Session) -> None:
    """An immersion heater in the water bath with a small leakage to the water: while its thermostat has it on (a
    cycle of 120-600 s, on 30-60 %, a contactor's 0.2 s edges) the bath sits at a fraction of the line voltage, a
    common-mode potential on both faces that the faces' unequal interfaces turn into a differential current: the
    line (50 or 60 Hz +- 0.05) with the grid's flat-topped distortion (3rd -0.02 to -0.05, 5th 0.02-0.04), 2-10 uA
    (log), on the current only (the laser is optical), nothing while the heater rests. Measured (p32_96): current
    residual 5.1 uA RMS on the 42 % of the samples touched (0.3x the current's white noise, a narrow line), peaks
    7.3 uA."""
    ai, h3, h5 = lu(s.rng, 2e-6, 1e-5), -s.rng.uniform(0.02, 0.05), s.rng.uniform(0.02, 0.04)
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    period, duty = s.rng.uniform(120.0, 600.0), s.rng.uniform(0.3, 0.6)
    ph, p = s.rng.uniform(0, 1), s.rng.uniform(0, 2 * np.pi)
    k = np.arange(math.floor((s.t0 - period) / period) - 1, math.ceil(s.t1 / period) + 1)
    on = [((j + ph) * period, (j + ph + duty) * period) for j in k]
    for r in s.series():
        t = r.cols["t_s"]
        r.cols["i_A"] = r.cols["i_A"] + ai * _ramp_env(t, on, 0.2) * _hum(t, f, {3: h3, 5: h5}, p)


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_bath_slosh(s: Session) -> None:
    """The laser looks down into the open bath through its free surface: every touch of the rig (each re-clamping,
    5-20 s before the block's first record, and 4-8 knocks at random inside recorded series) sets the water in the
    cuvette sloshing at its first mode (3-6 Hz for a 30-60 mm cuvette, damping ratio 0.001-0.004, log: a ring of
    10-50 s), and the tilting surface refracts the beam, moving the spot: a decaying sine of 5-20 um (log, each
    event 0.5-1.5x) added to the displacement, from rest at each event. Displacement only. Measured (paper_94):
    residual 4.3 um RMS on the 60 % of the samples touched (7.6x its noise), peaks 28 um; (p32_96): 1.2 um (2.2x),
    peaks 9.3 um."""
    fsl, zeta, a = s.rng.uniform(3.0, 6.0), lu(s.rng, 0.001, 0.004), lu(s.rng, 5e-6, 2e-5)
    events = [b - s.rng.uniform(5.0, 20.0) for b, _ in sorted(_blocks(s).values())]
    events += [b for b, _ in _bursts(s, int(s.rng.integers(4, 9)), (1.0, 1.0))]
    amps = [a * s.rng.uniform(0.5, 1.5) for _ in events]
    w = 2 * np.pi * fsl
    ring = 20 / (zeta * w)
    for r in s.series():
        t, x = r.cols["t_s"], np.zeros(r.cols["t_s"].size)
        for te, am in zip(events, amps):
            m = (t >= te) & (t < te + ring)
            u = t[m] - te
            x[m] += am * np.exp(-zeta * w * u) * np.sin(w * math.sqrt(1 - zeta**2) * u)
        r.cols["disp_m"] = r.cols["disp_m"] + x


def out_speckle_noise(s: Session) -> None:
    """Speckle decorrelation on a rough (plated) surface: while the strip moves and tilts under the spot, the
    speckle pattern on the triangulation receiver changes and its centroid jitters, a noise whose level follows the
    tip's speed (the reading smoothed over 20 ms, differentiated), 3-10 um RMS (log) at the session's
    99th-percentile speed, capped at 3x that, white at the samples; nothing at rest. Displacement only. Measured
    (s001_95): residual 1.3 um RMS over all (2.3x its noise), peaks 18 um, 20 Hz record residual 15 %; (paper_94):
    1.7 um (3.0x), peaks 40 um."""
    level = lu(s.rng, 3e-6, 1e-5)
    speed = {id(r): np.abs(np.gradient(lti(r.cols["disp_m"] - r.cols["disp_m"][0], r.fs, lambda z: 1 / (1 + 0.02 * z)),
                                       r.cols["t_s"])) for r in s.series()}
    v99 = float(np.percentile(np.concatenate(list(speed.values())), 99)) or 1.0
    for r in s.series():
        x = speed[id(r)]
        r.cols["disp_m"] = r.cols["disp_m"] + level * np.minimum(x / v99, 3.0) * s.rng.normal(size=x.size)


def out_delamination_event(s: Session) -> None:
    """One moment of damage: part of an electrode peels off the membrane (a blister that has grown under the plating
    lets go) at a time drawn inside a recorded series in the middle 20-80 % of the session, over 0.05-0.5 s (log):
    from then on the strip bends g 8-20 % less and its charging area, so its current, is c 3-10 % less, and the
    spectra measured after it show the impedance up by 1/(1 - c). A single step, neither a drying trend nor a
    clamp's block-wise change. Measured (p32_96): displacement RMS -6.4 % (residual 7.5 %), the 1 V steps' peaks
    -8.6 % after the event, current -4.8 % (12x its noise), impedance 1.07x after; (s001_95): steps -12.8 %, current
    -5.2 % after it."""
    g, c, tr = s.rng.uniform(0.08, 0.2), s.rng.uniform(0.03, 0.1), lu(s.rng, 0.05, 0.5)
    mid = [r for r in _chrono(s) if 0.2 <= (r.cols["t_s"][0] - s.t0) / (s.t1 - s.t0) <= 0.8] or _chrono(s)
    r0 = mid[int(s.rng.integers(0, len(mid)))]
    td = s.rng.uniform(r0.cols["t_s"][0], r0.cols["t_s"][-1])
    for k, r in enumerate(s.recs):
        if r.series:
            x = np.clip((r.cols["t_s"] - td) / tr, 0, 1)
            r.cols["disp_m"], r.cols["i_A"] = r.cols["disp_m"] * (1 - g * x), r.cols["i_A"] * (1 - c * x)
            continue
        after = next((q for q in s.recs[k + 1:] if q.series), None)
        if after is not None and after.cols["t_s"][0] > td:
            r.cols["z_re_ohm"], r.cols["z_im_ohm"] = r.cols["z_re_ohm"] / (1 - c), r.cols["z_im_ohm"] / (1 - c)


def out_neighbour_rig(s: Session) -> None:
    """A neighbouring experiment on the same bench and mains earth drives its own device with a +-5 V square wave
    (0.2-2 Hz, log) in spells of 2-10 min (2-4 of them, starting inside recorded series); its drive couples into the
    current amplifier's input, capacitively (a spike at each edge, A 30-100 uA, log, decaying in 1-5 ms, log, caught
    by whichever sample falls after it) and through a leakage (a square of 0.2-0.5 A). The strip's own drive, the
    voltage and the displacement know nothing of it. Current only. Measured (s001_95): 36 uA RMS on the 10 % of the
    samples inside the spells (8.6x its noise), peaks 0.13 mA; (paper_94): 16 uA RMS there (1.0x its white noise),
    peaks 62 uA."""
    a, tau, f, lk = lu(s.rng, 3e-5, 1e-4), lu(s.rng, 1e-3, 5e-3), lu(s.rng, 0.2, 2.0), s.rng.uniform(0.2, 0.5)
    spells = _bursts(s, int(s.rng.integers(2, 5)), (120.0, 600.0))
    for r in s.series():
        t, x = r.cols["t_s"], np.zeros(r.cols["t_s"].size)
        for b0, b1 in spells:
            m = (t >= b0) & (t < b1)
            u = (t[m] - b0) * 2 * f  # half periods since the spell began
            sg = np.where(np.floor(u) % 2 == 0, 1.0, -1.0)
            x[m] += a * sg * (np.exp(-(u - np.floor(u)) / (2 * f * tau)) + lk)
        r.cols["i_A"] = r.cols["i_A"] + x


FRESH8_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"salt_polarisation": br_salt_polarisation, "joule_heating": br_joule_heating},
    "faradaic_current": {"peroxide_buildup": far_peroxide_buildup, "crack_area": far_crack_area},
    "hysteresis": {"snap_fold": hy_snap_fold, "root_friction": hy_root_friction},
    "time_delay": {"ntp_slew": td_ntp_slew, "block_alignment": td_block_alignment},
    "sensor_offset": {"shadow_edge": so_shadow_edge, "two_marker": so_two_marker},
    "clamp_relaxation": {"swelling_pressure": cr_swelling_pressure, "gasket_extrusion": cr_gasket_extrusion},
    "dehydration": {"handling_dips": dh_handling_dips, "lamp_cycling": dh_lamp_cycling},
    "strain_resistance": {"gold_overlayer": sr_gold_overlayer, "crack_flicker": sr_crack_flicker},
    "large_deflection": {"ldv_integrated": ld_ldv_integrated, "tilt_characteristic": ld_tilt_characteristic},
    "mains_pickup": {"clamp_motor": mp_clamp_motor, "bath_heater_leak": mp_bath_heater_leak},
    "unexplained": {"bath_slosh": out_bath_slosh, "speckle_noise": out_speckle_noise,
                    "delamination_event": out_delamination_event, "neighbour_rig": out_neighbour_rig},
}
inject.register_forms(FRESH8_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_host_timed(s: Session) -> None:
    """A host-timed (software-timed) acquisition: a loop on the PC reads the instruments once per period T and
    stamps each reading with the host's clock when it was taken; the operating system makes each read late by an
    exponential latency (mean 3-10 % of T, drawn per session, at most 0.6 T), so the stamps are true but unevenly
    spaced (t_k = k T + latency_k) and each value is the signal at its stamp (linear interpolation of the series;
    samples whose stamp falls past the record's end dropped). The import contract asks t_s strictly increasing, not
    evenly spaced; the spectra untouched."""
    mean = s.rng.uniform(0.03, 0.1)
    for r in s.series():
        t, T = r.cols["t_s"], 1.0 / r.fs
        tn = t + np.minimum(s.rng.exponential(mean * T, t.size), 0.6 * T)
        keep = tn <= t[-1]
        r.cols = {k: (tn[keep] if k == "t_s" else np.interp(tn[keep], t, x)) for k, x in r.cols.items()}


inject.VARIANTS.update({"host_timed": v_host_timed})

# ------------------------------------------------------------------------------------------------ the cases

P94, S95, T96 = "paper_94", "s001_95", "p32_96"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 94 / 95 / 96
    "back_relaxation": [("salt_polarisation", 94, P94, "asrun"), ("joule_heating", 96, T96, "host_timed")],
    "faradaic_current": [("peroxide_buildup", 94, P94, "two_pressures"), ("crack_area", 95, S95, "no_spectra")],
    "hysteresis": [("snap_fold", 96, T96, "asrun"), ("root_friction", 94, P94, "rate07")],
    "time_delay": [("ntp_slew", 95, S95, "dropped_packets"), ("block_alignment", 96, T96, "decimated3")],
    "sensor_offset": [("shadow_edge", 94, P94, "host_timed"), ("two_marker", 96, T96, "eis_descending")],
    "clamp_relaxation": [("swelling_pressure", 94, P94, "float32_time"), ("gasket_extrusion", 95, S95, "asrun")],
    "dehydration": [("lamp_cycling", 95, S95, "host_timed"), ("handling_dips", 96, T96, "asrun")],
    "strain_resistance": [("gold_overlayer", 94, P94, "asrun"), ("crack_flicker", 95, S95, "shortened_shuffled")],
    "large_deflection": [("ldv_integrated", 96, T96, "own_clock"), ("tilt_characteristic", 95, S95, "resampled")],
    "mains_pickup": [("clamp_motor", 94, P94, "trigger_clock"), ("bath_heater_leak", 96, T96, "steps_sines")],
    "unexplained": [("bath_slosh", 94, P94, "asrun"), ("bath_slosh", 96, T96, "host_timed"),
                    ("speckle_noise", 95, S95, "asrun"), ("speckle_noise", 94, P94, "decimated3"),
                    ("delamination_event", 96, T96, "asrun"), ("delamination_event", 95, S95, "two_pressures"),
                    ("neighbour_rig", 94, P94, "eis_descending"), ("neighbour_rig", 95, S95, "host_timed")],
}
CLEAN = [(94, P94, "asrun"), (94, P94, "host_timed"), (95, S95, "asrun"), (95, S95, "own_clock"),
         (96, T96, "asrun"), (96, T96, "host_timed")]


def fresh8_cases(only: str | None = None) -> list[Case]:
    """The ninth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds 94-96)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh8_cases, "inject_fresh8", "fresh8")
