"""An eighteenth held-out set for the diagnosis (issue 12), fresh17, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh16.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (pits in a stainless contact that open
above their pitting potential and close below their repassivation potential, double-layer area gained on the walls of
opening cracks, a lateral-effect position-sensitive detector's edge non-linearity, a magnetoresistive angle sensor
reading a tip magnet, a defocused spot cut by the tip's end, a video tracker's alpha-beta filter, a ferrite flux
concentrator's hysteresis behind a Hall sensor), some on the history (a reversed electrolytic capacitor across the
strip whose oxide the reverse charge thins, the leak current's continued electro-osmotic drag), some on time or on the
clamp pressure (ethanol leaving the membrane through its plated skin, calcium from a tap-water bath bridging the
clusters, a hand-pumped bellows clamp whose fresh air cools, an open-loop piezo stack creeping after each step, a draft
shield opened at each re-clamping, an oil film draining off a strip in air, silver ligaments corroding in the cracks,
motion-sensor lights switching the lab's LED drivers on and off) and some from the lab's wiring or settings (a line
laser set to report its "peak", a USB oscilloscope logging the laser a screen per record, an impedance analyser in
its fast mode next to unshielded sense leads). Four structures outside the catalogue (truth "unexplained": the
laser's reading through an int16 register that wraps, the USB ground's drop under the drive amplifier's supply current
on every single-ended input, a gas bubble growing on the strip and letting go, a plating dendrite shorting the strip
until it fuses); clean sessions. All on three bases of new seeds (121-123: the paper strip, the seed-001 strip on its
own sweep, the paper strip 26 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: a
process historian's swinging-door compression of every time series (``swinging_door``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh16 are reused (importing inject_fresh16 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh17.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh16  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lti, lu, map_disp, play, ref_disp
from inject_fresh2 import _chrono, _drive_side, _spec, _through
from inject_fresh3 import _past, _resist, _sign
from inject_fresh4 import _clamp_law, _lag_state
from inject_fresh6 import _blocks
from inject_fresh8 import _hum, _leaky
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f
from inject_fresh14 import _half_disc_station, _lagged, _largest
from inject_fresh15 import _edges, _store, rest_noise
from inject_fresh16 import CURRENT_A_PER_V, LASER_M_PER_V, _eibeam, _held_area

# the paper's strip 26 mm free (earlier sets used 20, 25, 27-40, 42 and 45 mm; its 1 V step peaks near 6.6 mm, 8.8 mm x
# (26/30)^2, 6.69 mm measured, inside the laser's +-20 mm): registered in every process importing this module
inject.register_free_length("paper_26", 0.026)

inject.BASES.update({
    "paper_121": ("paper-sweep", "paper", 121),
    "s001_122": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 122),
    "p26_123": ("paper-sweep", "paper_26", 123),
})

G_N = 9.81  # m/s^2
RHO_WATER = 997.0  # kg/m^3 at 25 C
# viscosity of ethanol-water mixtures at 25 C against the ethanol mass fraction (mPa s): the maximum near 45-50 %
W_ETHANOL = np.linspace(0.0, 1.0, 11)
ETA_ETHANOL = np.array([0.890, 1.323, 1.815, 2.180, 2.350, 2.400, 2.240, 2.010, 1.710, 1.400, 1.074])


# ------------------------------------------------------------------------------------------------ tools


def _eta(w: np.ndarray | float) -> np.ndarray:
    """The viscosity of an ethanol-water mixture of ethanol mass fraction w over pure water's."""
    return np.interp(w, W_ETHANOL, ETA_ETHANOL) / ETA_ETHANOL[0]


def _first_steps(s: Session) -> dict[float, Rec]:
    """Each pressure's first step record with a rise and a fall."""
    out: dict[float, Rec] = {}
    for r in _chrono(s):
        p = float(r.entry["pressure_kPa"])
        if r.kind == "step" and p not in out and _edges(r.cols["v_V"]).size >= 2:
            out[p] = r
    return out


def _episodes(t: np.ndarray, spans: list[tuple[float, float]], ramp: float) -> np.ndarray:
    """1 inside any span, linear ramps of ``ramp`` seconds at the starts, 0 elsewhere (the last span's end cuts)."""
    env = np.zeros(t.size)
    for a, b in spans:
        env = np.maximum(env, np.clip((t - a) / ramp, 0, 1) * (t < b))
    return env


def _spectrum_times(s: Session) -> dict[int, float]:
    """A spectrum (no clock of its own in the CSV) placed at the start of the first time series listed after it (the
    session's end if none): id(record) -> time."""
    out = {}
    for k, r in enumerate(s.recs):
        if not r.series:
            after = next((q for q in s.recs[k + 1:] if q.series), None)
            out[id(r)] = float(after.cols["t_s"][0]) if after else s.t1
    return out


def _sdt_keep(t: np.ndarray, cols: list[np.ndarray], devs: list[float]) -> np.ndarray:
    """Swinging-door compression of rows (t, cols): the indices kept so that the straight line between two kept rows
    passes within dev of every column's value at every row skipped between them (a chord from the last kept row is
    extended while its slope stays inside every column's door, the narrowing range of slopes that clears the rows
    passed so far; the row before the first one that closes a door is kept and becomes the next anchor). The first and
    the last rows are always kept."""
    n = t.size
    if n <= 2:
        return np.arange(n)
    tl = t.tolist()
    xs = [c.tolist() for c in cols]
    m = len(xs)
    keep, a = [0], 0
    lo, hi = [-math.inf] * m, [math.inf] * m
    j = 1
    while j < n:
        dt = tl[j] - tl[a]
        ok = True
        for c in range(m):
            sl = (xs[c][j] - xs[c][a]) / dt
            if sl < lo[c] or sl > hi[c]:
                ok = False
                break
        if ok:
            for c in range(m):
                lo[c] = max(lo[c], (xs[c][j] - devs[c] - xs[c][a]) / dt)
                hi[c] = min(hi[c], (xs[c][j] + devs[c] - xs[c][a]) / dt)
            j += 1
        else:
            a = j - 1
            keep.append(a)
            lo, hi = [-math.inf] * m, [math.inf] * m
    if keep[-1] != n - 1:
        keep.append(n - 1)
    return np.array(keep)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_ethanol_exchange(s: Session) -> None:
    """A strip last rinsed and stored in aqueous ethanol (the lab's 70 % disinfectant, or a cleaning step: an ethanol
    mass fraction w0 0.5-0.75 in its pores) mounted in the water bath 0-600 s before the first record: the alcohol
    leaves through the plated skins, which limit the exchange to a first-order one (w0 exp(-u/tau_x), tau_x 0.15-0.5
    session). The back-flow is the pore liquid's Darcy flow: its lag follows the liquid's viscosity, which in
    ethanol-water passes through a maximum near 45-50 % (2.7 times water's at 25 C), tau = tau_w eta(w)/eta_water (tau_w
    3-8 s, log), so the lag first lengthens, then falls to water's; and ethanol swells Nafion more, so the share that
    flows back is K_w (1 + s_w w) (K_w 0.8-1.1, s_w 0.2-0.5). Through inject_fresh10._lag_varying (the reading d - K2 x,
    x the lag of d, sample by sample through the session, carried over the rests); displacement only. Measured
    (paper_121): w0 0.74, tau_x 1210 s (0.26 session), tau_w 6.5 s, K_w 1.00, s_w 0.44: the lag 17.4 s at the first
    record (w 0.52; its maximum, 17.6 s, 44 s in), 12.1, 8.4, 7.3 s at the later blocks' starts, K2 from 1.23 to 1.01:
    displacement RMS -62 % (residual 94 %, 5350x its noise); the 1 V steps peak at 3.33, 3.04, 2.65, 2.50 mm block by
    block (8.82 mm clean), 1.88, 1.67, 1.21, 1.08 mm by their plateaus' ends, -0.57 to -1.05 mm 2 s after the falls; the
    1 V harmonics' gain 0.919 with 4.3 deg of lead in the first block, 0.819 with 9.6 deg in the last."""
    w0, lead = s.rng.uniform(0.5, 0.75), s.rng.uniform(0.0, 600.0)
    tau_x = s.rng.uniform(0.15, 0.5) * (s.t1 - s.t0)
    tau_w, k_w, s_w = lu(s.rng, 3.0, 8.0), s.rng.uniform(0.8, 1.1), s.rng.uniform(0.2, 0.5)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        w = w0 * np.exp(-np.clip(np.asarray(t, float) - (s.t0 - lead), 0, None) / tau_x)
        return k_w * (1 + s_w * w), tau_w * _eta(w)

    _lag_varying(s, state)


def br_leak_drag(s: Session) -> None:
    """The leak (faradaic) current a held drive keeps passing carries hydrated cations across the membrane too: most of
    their water leaves at the electrodes, but a share n_rel (0.06-0.2 of what the charging current's cations leave, per
    coulomb) stays in the cathode side and diffuses back over tau_d 15-60 s (log). So the back relaxation (a lag of the
    bend, tau 3-10 s, log, share K2 0.8-1.1) runs against a forward creep that follows the leak current: a held step
    stops relaxing part of the way, and the falls overshoot less. The leak current G v_i (G each pressure's conductance
    at the end of its first step's plateau, v_i the drive through the interface's lag of 0.3-1.5 s) feeds a store
    (inject_fresh8._leaky, decaying over the rests); the bend per coulomb b_q is each pressure's first step's (its
    plateau's bend over its charging charge, the leak's part taken off). The reading d - K2 x + n_rel b_q Q;
    displacement only. Measured (p26_123): K2 0.99, tau 3.7 s, n_rel 0.20, tau_d 18 s (G 0.51-0.55 mS, b_q 0.43-0.47
    mm/mC): displacement RMS -75 % (residual 86 %, 4060x its noise); the 1 V steps peak at 1.50 mm 3 s after the rise
    (6.69 mm clean) and hold 1.13 mm from 20 s to the fall (0.47 mm with the back-flow alone), -0.27 mm 2 s after the
    falls (-0.91 mm alone); the 1 V harmonics' gain 0.66 with 19 deg of lead."""
    k2, tau = s.rng.uniform(0.8, 1.1), lu(s.rng, 3.0, 10.0)
    n_rel, tau_i, tau_d = s.rng.uniform(0.06, 0.2), s.rng.uniform(0.3, 1.5), lu(s.rng, 15.0, 60.0)
    G, bq = {}, {}
    for p, r in _first_steps(s).items():
        v, i, d = r.cols["v_V"], r.cols["i_A"], r.cols["disp_m"]
        on, off = (int(e) for e in _edges(v)[:2])
        hold = slice(max(off - int(3 * r.fs), on + 1), off)
        G[p] = float(np.median(i[hold] / np.where(np.abs(v[hold]) > 0.1, v[hold], np.nan)))
        q = float(np.sum(i[on:off] - G[p] * v[on:off])) / r.fs
        bq[p] = float(d[off - 1] - d[max(on - 1, 0)]) / q if q != 0 else 0.0
    g0, b0 = float(np.nanmedian(list(G.values()))), float(np.median(list(bq.values())))
    rate = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        rate[id(r)] = G.get(p, g0) * _lag_state(r.cols["v_V"], r.fs, tau_i, float(r.cols["v_V"][0]))
    charge, lag = _leaky(s, rate, tau_d), _store(s, tau)
    for r in s.series():
        b = bq.get(float(r.entry["pressure_kPa"]), b0)
        r.cols["disp_m"] = r.cols["disp_m"] - k2 * lag[id(r)] + n_rel * b * charge[id(r)]


# ------------------------------------------------------------------------------------------------ faradaic current


def far_pitting_contact(s: Session) -> None:
    """A stainless-steel (316) contact plate in the clamp touching the wet electrode on one side of the drive, in a
    tap-water bath (its chloride): passive until the contact is made anodic beyond its pitting potential E_pit
    (0.55-0.85 V of drive), where pits open (the active share A of the pit sites growing towards 1 with tau_n 1-8 s,
    log) and pass i_1 A (v - E_rp)/(1 V - E_rp) (the pits' solution ohmic, i_1 0.1-0.5 mA at A = 1 and 1 V, log); an
    open pit keeps dissolving on the way down until the drive falls below the repassivation potential E_rp (0.15-0.35
    V), where it closes within tau_rp 0.1-0.5 s (log). Nothing on the other polarity (the contact cathodic), nothing on
    the 0.5 V records, a loop in i-v on the 1 V harmonics, a current growing through the 1 V steps. Sample by sample
    through the session in time order (inject_fresh11._walk, the pits closing over the rests at 0 V); the analyser's 10
    mV sees no pit (spectra untouched): the current only. Measured (p26_123): the contact anodic on the positive drive,
    E_pit 0.61 V, E_rp 0.30 V, tau_n 5.6 s, i_1 0.17 mA: current residual 1.9 % of its RMS (1.4x its noise); +0.015 mA
    0.5 s into each 1 V step, +0.17 mA by its plateau's end (0.50-0.54 mA clean); on the 1 V harmonics up to +0.047 mA
    near their crests, +0.019 mA at 0.5 V on the way down and nothing at 0.5 V on the way up (their fundamental -0.04 %
    with 0.2 deg of lag); the 0.5 V records and the negative half-waves untouched."""
    sg = _sign(s)
    e_pit, e_rp = s.rng.uniform(0.55, 0.85), s.rng.uniform(0.15, 0.35)
    tau_n, tau_rp, i1 = lu(s.rng, 1.0, 8.0), lu(s.rng, 0.1, 0.5), lu(s.rng, 1e-4, 5e-4)

    def step(a: float, v: float, dt: float) -> float:
        u = sg * v
        if u > e_pit:
            return a + (1 - a) * -math.expm1(-dt / tau_n)
        if u < e_rp:
            return a * math.exp(-dt / tau_rp)
        return a

    active = _walk(s, step, "v_V", 0.0, lambda a, sec: a * math.exp(-sec / tau_rp))
    for r in s.series():
        u = sg * r.cols["v_V"]
        r.cols["i_A"] = r.cols["i_A"] + sg * i1 * active[id(r)] * np.clip((u - e_rp) / (1 - e_rp), 0, None)


def far_reversed_electrolytic(s: Session) -> None:
    """An aluminium electrolytic capacitor (2.2-10 uF, log) across the strip's terminals in the drive box, after the
    current sense, fitted to tame the amplifier's ringing and wired the wrong way round for one polarity of the bipolar
    drive: beside its charging current C dv/dt, it conducts when reverse-biased, through its oxide acting as a
    rectifier, i_r1 (exp(u/v_0) - 1)/(exp(1/v_0) - 1) (u the reverse bias, v_0 0.15-0.3 V; i_r1 20-150 uA at 1 V, log),
    and the reverse charge thins its oxide: the leakage grows by (1 + D), D rising by the reverse charge over q_d (0.3-3
    mC, log) towards D_max 1-3 (the oxide thinned to its limit) and healing with tau_h 100-600 s (log) when the bias is
    forward or nil (reforming). A one-sided, exponential current that grows through each reverse-biased swing. Sample by
    sample through the session (inject_fresh11._walk); the analyser, switched in at the strip by its own relay, does not
    see it (spectra untouched): the current only. Measured (s001_122): 2.4 uF, reverse-biased by the negative drive,
    i_r1 47 uA, v_0 0.29 V, q_d 1.2 mC, D_max 2.6, tau_h 180 s: current residual 1.1 % of its RMS (2.9x its noise); -44
    uA at the first negative crest of each 1 V harmonic, -52 uA at its last (the oxide thinning), healed by the next
    block's; -8 uA on the 0.5 V sines' negative halves; the capacitor's own 1.2 mA in the sample of each step's edge and
    0.11 mA RMS on the 20 Hz sines (their current +0.4 % with 1.0 deg of lead); the positive half-waves and the plateaus
    untouched."""
    sg = _sign(s)
    cap, i_r1, v0 = lu(s.rng, 2.2e-6, 1e-5), lu(s.rng, 2e-5, 1.5e-4), s.rng.uniform(0.15, 0.3)
    q_d, d_max, tau_h = lu(s.rng, 3e-4, 3e-3), s.rng.uniform(1.0, 3.0), lu(s.rng, 100.0, 600.0)
    scale = i_r1 / math.expm1(1 / v0)

    def step(dmg: float, v: float, dt: float) -> float:
        u = -sg * v
        if u > 0:
            return dmg + scale * (1 + dmg) * math.expm1(u / v0) * dt / q_d * max(1 - dmg / d_max, 0.0)
        return dmg * math.exp(-dt / tau_h)

    dmg = _walk(s, step, "v_V", 0.0, lambda x, sec: x * math.exp(-sec / tau_h))
    for r in s.series():
        v = r.cols["v_V"]
        u = np.clip(-sg * v, 0, None)
        leak = -sg * scale * (1 + dmg[id(r)]) * np.expm1(u / v0)
        r.cols["i_A"] = r.cols["i_A"] + cap * np.diff(v, prepend=v[0]) * r.fs + leak


# ------------------------------------------------------------------------------------------------ hysteresis


def _relay_mean(h: np.ndarray, alpha: np.ndarray, beta: np.ndarray) -> np.ndarray:
    """The mean state (-1 or +1, starting at -1) of Preisach relays switching up where h >= alpha and down where h <=
    beta, along the path h: each relay's state is set by the later of its last up- and last down-crossing."""
    idx = np.arange(h.size)
    acc = np.zeros(h.size)
    for a, b in zip(alpha.tolist(), beta.tolist()):
        up = np.maximum.accumulate(np.where(h >= a, idx, -1))
        dn = np.maximum.accumulate(np.where(h <= b, idx, -1))
        acc += np.where(up > dn, 1.0, -1.0)
    return acc / max(alpha.size, 1)


def hy_hall_ferrite(s: Session) -> None:
    """No laser: a small magnet glued at the tip and a Hall sensor behind a ferrite flux concentrator facing it along
    the bend (the gap at rest g 1.8-3 times the session's largest bend), the lab's table made on one slow ascending
    sweep of the tip (a micrometer from -Y to +Y, Y 1.05 times the largest bend, after going up to +Y and down to -Y
    first): the field at the sensor is the dipole's, H = (g/(g - y))^3 - 1, and the concentrator adds its magnetisation,
    whose irreversible part is a Preisach population of domains (150 relays: coercive fields log-normal, median 1-4 % of
    the field's change over Y at rest, spread 0.3-0.6; interaction fields normal, 0.5-1.5 of that change; weight chi
    0.3-0.8 of it). The table inverts the ascending branch, so the ascending branch reads right, the descending one off,
    with minor loops inside. Rate-independent; the domains' state through the session in time order (the table's sweep
    first, then the tip at rest); displacement only. Measured (s001_122): the gap 2.9 times the largest bend, the
    coercive fields' median 1.2 % (spread 0.46), interactions 0.61, chi 0.55: displacement residual 1.6 % of its RMS
    (52x its noise); the ascending branches read to 1 um, the descending ones 32 um high mid-swing on the 1 V harmonics
    (2.2 mm of swing: their gain +0.8 % with 0.9 deg of lag) and 44 um on the 0.5 V, 0.1 Hz sines (1.1 mm of swing); +32
    um left 29 s after each step's fall."""
    big = _largest(s)
    yc = 1.05 * big
    g = s.rng.uniform(1.8, 3.0) * yc
    unit = 3 * yc / g  # the field's change over yc at rest
    n = 150
    hc = unit * lu(s.rng, 0.01, 0.04) * np.exp(s.rng.uniform(0.3, 0.6) * s.rng.standard_normal(n))
    hi = unit * s.rng.uniform(0.5, 1.5) * s.rng.standard_normal(n)
    chi = s.rng.uniform(0.3, 0.8) * unit
    field = lambda y: (g / (g - y)) ** 3 - 1  # noqa: E731
    yg = np.linspace(-yc, yc, 801)
    cal = _relay_mean(np.r_[field(yc), field(-yc), field(yg)], hi + hc, hi - hc)[2:]
    b_cal = field(yg) + chi * cal
    recs = _chrono(s)
    d = np.concatenate([r.cols["disp_m"] for r in recs])
    pre = np.array([field(yc), field(-yc), field(yc), 0.0])
    m = _relay_mean(np.r_[pre, field(d)], hi + hc, hi - hc)[pre.size:]
    read = np.interp(field(d) + chi * m, b_cal, yg)
    for r, x in zip(recs, np.split(read, np.cumsum([r.cols["t_s"].size for r in recs])[:-1])):
        r.cols["disp_m"] = x


def hy_calcium_bridges(s: Session) -> None:
    """A bath of tap water (or a strip stored in it): its calcium exchanges into the membrane through the session (1 -
    exp(-u/tau_x), tau_x 0.3-1 session, from the filling 0-600 s before the first record), and each Ca2+ bridges two
    sulfonates of neighbouring clusters, pinning their cations: a bridged cluster's share of the actuation moves only
    once the drive has turned by the bridges' depinning threshold r (0.1-0.3 V) and then slides with it (Coulomb-like
    pinning, rate-independent), so the coupling is Gamma = (1 - h c(t)) v + h c(t) play_r(v), h 0.25-0.45 the share
    bridged by the session's end. The loops open through the session: the first records nearly linear, the last ones'
    small sines pinned. Through the strip's measured step response (inject_fresh2._drive_side, the play carried through
    the session in time order); current untouched. Measured (paper_121): h 0.36, r 0.20 V, tau_x 1530 s (0.33 session),
    filled 300 s before: displacement RMS +3.2 % (residual 11 %, 620x its noise); the 0.5 V sines' gain 0.96, 0.94, 0.93
    at 0.1, 4.4 and 20 Hz in the first block, 0.90, 0.88, 0.98 in the last, with 2-8 deg of lag; the first step's peak
    -1.3 %, the later ones' as they were, but 0.23-0.32 mm left 2 s after their falls and 0.8-1.1 mm by their records'
    ends; the 1 V harmonics offset by -0.1 to -0.55 mm mid-swing (the pinned share's remanence)."""
    h_end, rad = s.rng.uniform(0.25, 0.45), s.rng.uniform(0.1, 0.3)
    tau_x, lead = s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)
    tt = np.concatenate([r.cols["t_s"] for r in _chrono(s)])
    share = h_end * -np.expm1(-(tt - s.t0 + lead) / tau_x)
    _drive_side(s, lambda v: v + share * (play(v, rad) - v))


# ------------------------------------------------------------------------------------------------ time delay


def td_alpha_beta_tracker(s: Session) -> None:
    """Video tracking of the tip with a camera at F 100-250 frames/s (log, free running), each frame's position the
    tip's mean over its exposure (0.3-0.7 of the frame), and the tracking software smoothing the positions with a
    constant-velocity alpha-beta filter (alpha 0.25-0.5, beta = alpha^2/(2 - alpha), the critically damped pair) whose
    estimate is delivered one frame later and interpolated onto the DAQ's rows. No lag of its own on a steady ramp (a
    frame's latency and half an exposure), a lag and a gain peaking that grow towards the filter's band (a few Hz to
    tens of Hz): the fast sines late, the step's edges overshooting a little. Each record with the session's history
    before it (inject_fresh3._past); displacement only. Measured (paper_121): 113 frames/s, alpha 0.30, exposure 0.65 of
    the frame: displacement residual 0.51 % of its RMS (29x its noise); the 1 V harmonics late by 7.5 ms (0.27 deg), the
    4.4 Hz sines' gain 1.16 at -49 deg, 9.4 Hz 0.61-0.68 at -93 to -96 deg, 20 Hz 0.27 at -137 deg; the steps within
    0.03 mm."""
    F, alpha = lu(s.rng, 100.0, 250.0), s.rng.uniform(0.25, 0.5)
    beta, expo = alpha**2 / (2 - alpha), s.rng.uniform(0.3, 0.7) / F
    out = {}
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        pre = _past(s, r, "disp_m", 2.0, r.fs)
        T, D = np.r_[t[0] - np.arange(pre.size, 0, -1) / r.fs, t], np.r_[pre, d]
        area = _held_area(T, D)
        tf = np.arange(T[0] + expo + s.rng.uniform(0.0, 1.0 / F), t[-1] + 2.0 / F, 1.0 / F)
        pos = ((area(tf) - area(tf - expo)) / expo).tolist()
        x, v, est = pos[0], 0.0, np.empty(len(pos))
        for k, z in enumerate(pos):
            xp = x + v / F
            res = z - xp
            x, v = xp + alpha * res, v + beta * F * res
            est[k] = x
        out[id(r)] = np.interp(t, tf + 1.0 / F, est)
    map_disp(s, lambda r, d: out[id(r)])


def _screen(dur: float) -> float:
    """A scope's screen (10 divisions) on the 1-2-5 timebase that holds ``dur`` seconds."""
    for e in range(-4, 4):
        for m in (1.0, 2.0, 5.0):
            if 10 * m * 10.0**e >= dur:
                return 10 * m * 10.0**e
    return 10 * dur


def td_scope_capture(s: Session) -> None:
    """The DAQ's inputs all taken, the laser's analogue output is logged on a USB oscilloscope: one screen per record
    (the 1-2-5 timebase that holds the record, 10 divisions, N points a screen: 1000, 2000 or 5000, drawn), triggered on
    the drive, the lab's script laying the scope's points onto the DAQ's rows from the record's first row by linear
    interpolation. The scope sets its trigger on its own sample grid and a fixed pipeline later: every point is stamped
    k (0.3-1.5 samples, drawn for the session) plus a fraction of a sample (uniform, per record) after it was taken. A
    delay and a smoothing in proportion to each record's screen (no anti-alias filter: the scope samples, the noise
    aliases). Each record with the session's history before it; displacement only. Measured (s001_122): 5000 points a
    screen, k 1.44 samples: displacement residual 0.41 % of its RMS (13x its noise); the 61 s steps (a 100 s screen, 20
    ms a point) late by 30-50 ms (-0.02 to -0.04 mm 0.5 s after the rise, +0.01 to +0.02 mm after the fall), the 1 V
    harmonics (a 50 s screen) by 11-14 ms, the 4.4 Hz sines (a 5 s screen, 1 ms a point) by 1.7-2.1 ms (-2.7 to -3.4
    deg), the 20 Hz ones by 1.6-2.1 ms (-12 to -15 deg)."""
    npts, k0 = int(s.rng.choice([1000, 2000, 5000])), s.rng.uniform(0.3, 1.5)
    out = {}
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        dur = float(t[-1] - t[0])
        dts = _screen(dur) / npts
        lag = (k0 + s.rng.uniform(0.0, 1.0)) * dts
        pre = _past(s, r, "disp_m", lag + 2 * dts + 2.0 / r.fs, r.fs)
        T, D = np.r_[t[0] - np.arange(pre.size, 0, -1) / r.fs, t], np.r_[pre, d]
        ts = t[0] + np.arange(0.0, dur + 2 * dts, dts)
        out[id(r)] = np.interp(t, ts, np.interp(ts - lag, T, D))
    map_disp(s, lambda r, d: out[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_defocus_edge(s: Session) -> None:
    """A triangulation head with a short depth of focus, focused on the strip at rest and aimed with its spot's centre a
    margin m (0.1-0.6 mm) inside the tip's end: the spot's radius grows with the distance from focus, r0 + (r1 - r0)
    abs(d)/d_max (r0 0.1-0.25 mm at rest, r1 1-2.5 mm at the session's largest bend, log), and what lies beyond the
    tip's end returns nothing, so the receiver sees the on-strip part of a growing disc, its centroid moving inboard as
    the strip bends either way. The strip read at the chord-weighted station of that part
    (inject_fresh14._half_disc_station, tabulated), sample by sample, through the beam's transfer functions
    (inject_fresh10._station); displacement only. Measured (p26_123): the aim 0.33 mm inside the tip, the spot's radius
    0.14 mm at rest and 1.8 mm at the largest bend: displacement RMS -5.3 % (residual 5.4 %, 255x its noise); the 1 V
    steps' peaks -6.7 %, the 1 V harmonics' gain 0.961, the 0.5 V sines' 0.976 at 0.1 Hz, 0.984 at 4.4 Hz, 0.93 at 20
    Hz."""
    L = float(s.specimen["length_m"])
    margin, r0, r1 = s.rng.uniform(1e-4, 6e-4), lu(s.rng, 1e-4, 2.5e-4), lu(s.rng, 1e-3, 2.5e-3)
    big = _largest(s)
    rg = np.linspace(r0, 1.05 * r1, 160)
    st = _half_disc_station(rg / L, margin / L)
    _station(s, lambda r: np.interp(r0 + (r1 - r0) * np.abs(r.cols["disp_m"]) / big, rg, st), float(st.min()))


def so_peak_line_mode(s: Session) -> None:
    """A line-beam triangulation head (its line 1-3 mm long along the strip, ending at the tip's end, so that the spot
    stays on the strip) whose controller is set to report the line's "peak" (the point nearest the head) instead of its
    average: bending towards the head it reads the tip, away from it the line's inner end, (1 - l/L)^2 of the bend
    quasi-statically. The head on one side (drawn); the inner end read through the beam's transfer functions
    (displacement_tf with sensor_x over the tip's, with the session's history, inject_fresh2._through), the reading the
    larger of the two towards the head, sample by sample; displacement only. Measured (s001_122): a 1.6 mm line, the
    head on the negative side (the positive bends read at 0.92 L): displacement RMS -15 % (residual 15 %, 490x its
    noise); the 1 V steps' peaks -15.2 % ((1 - l/L)^2 = 0.846), the 1 V harmonics' gain 0.848 (their swing mostly
    positive), the 0.5 V sines' 0.917 at 0.1 Hz (half of each cycle read short), 0.918 at 4.4 Hz, 0.94 at 20 Hz."""
    from labrig.physics import transfer

    lb, sg = s.rng.uniform(1e-3, 3e-3), _sign(s)
    L = float(s.specimen["length_m"])

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        si = sp.with_(sensor_x=sp.geometry.length - lb)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                q = transfer.displacement_tf(z, si) / transfer.displacement_tf(z, sp)
            return np.where(np.isfinite(q), q, (1 - lb / L) ** 2)

        return h

    inner = _through(s, H, 2.0)
    map_disp(s, lambda r, d: sg * np.maximum(sg * d, sg * inner[id(r)]))


# ------------------------------------------------------------------------------------------------ clamp relaxation


def _block_order(s: Session) -> list[tuple[float, float]]:
    """The pressure blocks in time order: (first sample, pressure)."""
    return sorted((a, p) for p, (a, _) in _blocks(s).items())


def cr_pumped_bellows(s: Session) -> None:
    """A pneumatic clamp: a small bellows (effective area A_b 2-6 cm^2, log) pushing the jaw, pumped up by hand through
    a check valve at each setting and then closed. A hand pump's air comes out hot (its compression nearly adiabatic:
    dT_a 20-60 K above the room), so right after a setting the added gas, a share 1 - P_prev/P of the bellows' absolute
    pressure P, holds the gauge force high by dT_a (1 - P_prev/P)/T P/(P - P_atm); the operator sets the force on the
    load cell then, and it falls to its cold value with the bellows' thermal time tau_th 15-90 s (log), beside the pads'
    creep (1 - c ln(1 + u/tau_p), c 0.3-1 %, tau_p 20-100 s, log): the first records of each block start 5-30 s after
    its setting. The drop is the largest at the lightest setting (the added share of a small gauge pressure over the
    atmosphere's). Through the preset's clamp law (inject_fresh4._clamp_law: the load cell at the indicator's 0.01 kgf,
    the strip at each record's mean pressure). Measured (paper_121): A_b 3.1 cm^2, dT_a 49 K, tau_th 68 s, the records
    from 14 s after each setting: the load cell from 0.97 to 0.84 of its setting over the 612 kPa block's first records
    (-1.3 N), 0.98 to 0.88, 0.99 to 0.91, 0.99 to 0.93 in the later blocks; displacement residual 0.09 % of its RMS
    (5.1x its noise), current 0.68 % (0.51x); the 4287 kPa block's sines near f1 +31 % at 4.4 Hz, -20 % at 20 Hz, the
    1837 kPa block's -5 % at 4.4 Hz."""
    area_b, dt_a, tau_th = lu(s.rng, 2e-4, 6e-4), s.rng.uniform(20.0, 60.0), lu(s.rng, 15.0, 90.0)
    lead, c, tau_p = s.rng.uniform(5.0, 30.0), s.rng.uniform(0.003, 0.01), lu(s.rng, 20.0, 100.0)
    area, p_atm, t_room = float(s.specimen["clamp_area_m2"]), 101325.0, 295.0
    rise, prev = {}, p_atm
    for _, p in _block_order(s):
        pa = p_atm + p * 1e3 * area / area_b
        rise[p] = dt_a * max(1 - prev / pa, 0.0) / t_room * pa / (pa - p_atm)
        prev = pa

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        u = np.clip(t - t_set + lead, 0, None)
        x = rise.get(p, 0.0)
        return (1 + x * np.exp(-u / tau_th)) / (1 + x) * (1 - c * np.log1p(u / tau_p))

    _clamp_law(s, rel)


def cr_piezo_stack(s: Session) -> None:
    """A piezo-stack clamp (a stack actuator behind a stiff jaw, for fine force steps), run open loop: each setting is a
    voltage step, and a piezo stack creeps on after a step by gamma (1-2.5 %, PZT's usual) of the step's stroke per
    decade of time, log10(1 + u/0.1 s); the operator sets the force on the load cell 5-20 s before the block's first
    record, so the creep of that step and of every earlier one (each in proportion to its force increment) goes on
    pushing the force up through the block, beside the pads' own creep the other way (1 - c ln(1 + u/tau_p), c 0.2-0.6
    %, tau_p 20-100 s, log). A rise that is fastest just after each setting and largest in the first block (its step the
    whole force), small in the later ones. Through the preset's clamp law (inject_fresh4._clamp_law). Measured
    (p26_123): gamma 2.1 % a decade, the settings 17 s before each block, c 0.45 %: the load cell at 1.04 to 1.06 of its
    setting through the 612 kPa block, 1.03 to 1.04 at 1837 kPa, 1.015 to 1.019 at 3062, 1.011 to 1.009 at 4287;
    displacement residual 0.024 % of its RMS (1.2x its noise), current 0.21 % (0.16x); the 4287 kPa block's sines near
    f1 -2.2 % at 4.4 Hz (-4.0 deg), +3.3 % at 20 Hz."""
    gam, lead = s.rng.uniform(0.01, 0.025), s.rng.uniform(5.0, 20.0)
    c, tau_p = s.rng.uniform(0.002, 0.006), lu(s.rng, 20.0, 100.0)
    steps, prev = [], 0.0
    for a, p in _block_order(s):
        steps.append((a - lead, p - prev))
        prev = p

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        tk = t_set - lead
        creep = np.zeros(t.size)
        for tj, dp in steps:
            if tj <= tk + 1e-9:
                creep += dp / p * gam * (np.log10(1 + np.clip(t - tj, 0, None) / 0.1) - math.log10(1 + (tk - tj) / 0.1))
        return (1 + creep) * (1 - c * np.log1p(np.clip(t - tk, 0, None) / tau_p))

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_draft_shield(s: Session) -> None:
    """A strip in air inside a small draft shield (a clear box with a dish of water, its air at 55-70 % RH once closed)
    that the operator opens at each re-clamping (for 15-45 s, ending 20-60 s before the block's first record): while
    open, the room's air (35-50 % RH) replaces the box's within seconds; closed, the box's humidity returns towards its
    own with tau_box 100-400 s (log). The strip's water follows Nafion's isotherm (inject_fresh10._lambda) through its
    sorption lag, 100-400 s (log) drying, 1.5-3x slower re-wetting (inject_fresh14._lagged): a dip at each block's
    start, made up through the block. The gain as the water, the conductance as its 1.5-2.5th power, the spectra at the
    next series' start (inject_fresh9._dry_by). Measured (s001_122): the room at 43 %, the box at 62 % (tau_box 150 s),
    open 24 s ending 34 s before each block, the sorption lag 250 s (re-wetting 2.8x slower), the conductance's power
    1.56: displacement RMS -8.7 % (residual 8.8 %, 280x its noise), current -11 % (32x); the 1 V steps' peaks -7.0,
    -9.3, -9.4, -9.5 % block by block, their plateaus' current -11 to -14 %; in each block the 1 V harmonic (after the
    step) -10 to -12 %, the last, 20 Hz sine -5 to -6 % (made up through the block); the spectra's |Z| +8.5, +13, +14,
    +14 %."""
    rh_room, rh_box, tau_box = s.rng.uniform(0.35, 0.5), s.rng.uniform(0.55, 0.7), lu(s.rng, 100.0, 400.0)
    open_s, lead = s.rng.uniform(15.0, 45.0), s.rng.uniform(20.0, 60.0)
    tau_d, slow, gc = lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 3.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, 900.0)
    opened = np.zeros(tg.size, bool)
    for a, _ in _block_order(s):
        opened |= (tg >= a - lead - open_s) & (tg < a - lead)
    rh, x = np.empty(tg.size), rh_box
    for k, o in enumerate(opened.tolist()):
        target, tau = (rh_room, 5.0) if o else (rh_box, tau_box)
        x += (target - x) * -math.expm1(-1.0 / tau)
        rh[k] = x
    water = _lagged(tg, _lambda(rh), tau_d, tau_d * slow) / float(_lambda(np.array([rh_box]))[0])
    _dry_by(s, lambda t: 1 - np.interp(t, tg, water), lambda t: 1 - np.interp(t, tg, water) ** gc)


def dh_oil_film(s: Session) -> None:
    """A strip in air brushed with a film of silicone oil 0-600 s before the first record, to keep it from drying: the
    oil drains off the hanging strip under gravity, its thickness falling as (1 + u/t_d)^(-1/2) (Jeffreys' draining
    film; t_d 300-1500 s, log), and the water's way out is the film's resistance in series with the air's boundary
    layer, rho (h/h0) + 1 times the bare strip's (rho 5-20 at the start, log): the strip dries towards its loss at the
    room's humidity (l_inf 10-25 %) with tau_0 (1 + rho h/h0) (tau_0 300-900 s, log, the bare strip's), slowly at first
    and faster as the oil thins: a loss that accelerates through the session. The gain as the water, the conductance as
    its 1.5-2.5th power, the spectra at the next series' start (inject_fresh9._dry_by). Measured (s001_122): coated 217
    s before, t_d 870 s, rho 6.6, tau_0 680 s, l_inf 0.23, the conductance's power 1.62: displacement RMS -8.9 %
    (residual 11 %, 340x its noise), current -17 % (51x); the 1 V steps' peaks -1.1, -6.9, -12.0, -15.9 % block by
    block, their plateaus' current -1.8, -11, -19, -25 %; the spectra's |Z| +1.6, +12, +23, +32 %."""
    lead, t_d, rho = s.rng.uniform(0.0, 600.0), lu(s.rng, 300.0, 1500.0), lu(s.rng, 5.0, 20.0)
    tau0, l_inf, gc = lu(s.rng, 300.0, 900.0), s.rng.uniform(0.1, 0.25), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, lead)
    loss, x = np.empty(tg.size), 0.0
    for k, u in enumerate((tg - tg[0]).tolist()):
        x += (l_inf - x) * -math.expm1(-1.0 / (tau0 * (1 + rho / math.sqrt(1 + u / t_d))))
        loss[k] = x
    _dry_by(s, lambda t: np.interp(t, tg, loss), lambda t: 1 - (1 - np.interp(t, tg, loss)) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_crack_wall_capacitance(s: Session) -> None:
    """Cracks of the face the positive drive stretches (the face whose plating the 1 V steps cracked) that open beyond
    e_0 (0.2-0.5 of the displacement scale) expose their walls, the platinum's edges and the membrane beneath, to the
    bath: the face's double layer gains area, dC/C = c_max ((e - e_0)/(e_max - e_0))^m (c_max 3-10 % at the session's
    largest tension, m 1-1.5), so the strip takes more charge per volt while it is bent that way: the current's gain
    rises by a_i 0.6-1 and the bend's by a_d 0.3-0.7 times dC/C (the cracks' walls lie where the actuation is weakest).
    The other way, and below e_0, nothing; the analyser at rest sees closed cracks (spectra untouched). A one-sided,
    amplitude-dependent gain that rises: even harmonics in the 1 V records. Displacement and current. Measured
    (paper_121): e_0 0.42 of the scale, m 1.29, c_max 4.8 %, a_d 0.44, a_i 0.62: displacement RMS +1.3 % (residual 1.5
    %, 82x its noise), current residual 0.48 % (0.36x); the 1 V steps' peaks +2.1 %, their plateaus' current +3.0 %; the
    1 V harmonics' fundamental +0.55 % (current +0.25 %), their troughs as they were; the 0.5 V sines within 0.01 %."""
    ref = ref_disp(s)
    e0, m, cmax = s.rng.uniform(0.2, 0.5), s.rng.uniform(1.0, 1.5), s.rng.uniform(0.03, 0.1)
    ad, ai = s.rng.uniform(0.3, 0.7), s.rng.uniform(0.6, 1.0)
    emax = max(float(np.max(r.cols["disp_m"])) for r in s.series()) / ref
    for r in s.series():
        e = r.cols["disp_m"] / ref
        g = cmax * (np.clip(e - e0, 0, None) / max(emax - e0, 1e-9)) ** m
        r.cols["disp_m"] = r.cols["disp_m"] * (1 + ad * g)
        r.cols["i_A"] = r.cols["i_A"] * (1 + ai * g)


def sr_ligament_corrosion(s: Session) -> None:
    """Electrodes plated the cheaper way, platinum over an electroless silver seed: where the tensioned face's film is
    cracked (the face the positive drive stretches, cracked by the 1 V steps), silver ligaments bridge the cracks and
    carry the current across them, and in the bath (its chloride and dissolved oxygen) they corrode from the bath's
    filling (0-600 s before the first record) on, 1 - exp(-u/tau_c) (tau_c 0.3-1 session): the face's resistance rises
    with its tension as (1 + g_1 c(t))/(1 + g_1) e+ (g_1 1-3: the gauge 2-4 times the fresh one's by the corrosion's
    end). Gains fall by 0.02-0.06 (displacement) and 0.05-0.15 (current) per unit of dR/R (inject_fresh3._resist): the
    one-sided strain gauge grows with time, whatever the strip does. Measured (p26_123): g_1 2.3, tau_c 3720 s (0.86
    session), filled 345 s before, 0.038 and 0.055 per unit: displacement RMS -6.4 % (residual 7.0 %, 330x its noise),
    current residual 2.4 % (1.8x); the 1 V steps' peaks -5.7, -8.5, -10.4, -11.9 % block by block, their plateaus'
    current -8.4, -12, -15, -17 %; the 1 V harmonics -2.6 % in the first block, -5.3 % in the last; the 0.5 V sines at
    0.1 Hz -0.4 to -0.7 %."""
    g1 = s.rng.uniform(1.0, 3.0)
    tau_c, lead = s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        c = -np.expm1(-(r.cols["t_s"] - s.t0 + lead) / tau_c)
        return (1 + g1 * c) / (1 + g1) * np.clip(e, 0, None)

    _resist(s, shape, (0.02, 0.06), (0.05, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_psd_edge(s: Session) -> None:
    """No laser: a lens images a small marker at the tip (a retro-reflective dot lit along the lens' axis) onto a 1-D
    lateral-effect position-sensitive detector, the magnification chosen so that the session's largest bend fills
    0.8-0.95 of the detector's half-length X, the rest at its centre. A lateral-effect PSD is linear in its middle, but
    near its ends (the spot's light spreading to the electrodes, the layer's resistance non-uniform at its edges) it
    reads short: x (1 - k_e abs(x/X)^3), k_e 3-8 % at the ends, calibrated by its slope at the centre. Symmetric, odd,
    the compression steep towards the ends: the 1 V steps' tops, hardly the harmonics. Displacement only. Measured
    (paper_121): the largest bend at 0.82 of the half-length, k_e 5.7 %: displacement RMS -1.4 % (residual 1.7 %, 96x
    its noise); the 1 V steps' peaks -3.1 %, -1.8 % at 7.4 mm (20 s in), -1.4 % 2 s after their falls; the 1 V harmonics
    -0.23 %, the 0.5 V sines within 0.01 %."""
    fill, k_e = s.rng.uniform(0.8, 0.95), s.rng.uniform(0.03, 0.08)
    half = _largest(s) / fill
    map_disp(s, lambda r, d: d * (1 - k_e * np.abs(d / half) ** 3))


def ld_amr_angle(s: Session) -> None:
    """No laser: a magnet (a 0.5 mm sphere, magnetised along the strip) glued at the tip and a magnetoresistive angle
    sensor (AMR, saturated: its output sin 2 theta_B of the field's direction) on the strip's axis D beyond the tip (D
    5-10 times the session's largest bend), calibrated by its slope at rest. Bending moves the magnet sideways and along
    the arc (the exact uniform-curvature arc, curvature 2 d/L^2) and turns it with the tip: the dipole's field at the
    sensor turns by theta_B = theta_m + f(psi - theta_m) (f the dipole's field angle at the polar angle psi from its
    axis, atan2(3 cos psi sin psi, 3 cos^2 psi - 1)), and the output's sine bends over: a symmetric compression, odd,
    steepening with the bend. Displacement only. Measured (p26_123): D 8.1 times the largest bend (54 mm): displacement
    RMS -4.6 % (residual 5.3 %, 250x its noise); the 1 V steps' peaks -8.9 %, -5.9 % at 5.6 mm (20 s in), -4.6 % 2 s
    after their falls; the 1 V harmonics -1.4 %, the 0.5 V sines -0.08 %."""
    L = float(s.specimen["length_m"])
    big = _largest(s)
    dist = s.rng.uniform(5.0, 10.0) * big
    y = np.linspace(-1.05, 1.05, 2101) * big
    k = 2 * y / L**2
    small = np.abs(k) < 1e-9
    ks = np.where(small, 1.0, k)
    X = np.where(small, L, np.sin(ks * L) / ks)
    Y = np.where(small, y, (1 - np.cos(ks * L)) / ks)
    th_m = k * L
    psi = np.arctan2(-Y, L + dist - X) - th_m
    th_b = th_m + np.arctan2(3 * np.cos(psi) * np.sin(psi), 3 * np.cos(psi) ** 2 - 1)
    out = np.sin(2 * th_b)
    slope = float(np.polyfit(y[1045:1056], out[1045:1056], 1)[0])
    read = out / slope
    map_disp(s, lambda r, d: np.interp(d, y, read))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_eis_line_leak(s: Session) -> None:
    """The impedance analyser in its fast mode (its detector integrating N = 1 or 2 cycles of each test frequency) with
    unshielded sense leads beside the bench's mains wiring: the hum on the sense leads (a_h 0.1-0.5 mV at the line, log;
    50 or 60 Hz, its 3rd 0.2-0.5 and 5th 0.05-0.2) passes the detector as a tone at n f_line passes an N-cycle window at
    f: sinc(N (n f_line - f)/f), with a phase of its own at every point (the sweep is not locked to the line). Against
    the 10 mV test signal each point's impedance is off by (a_h/10 mV) sum_n a_n sinc(...) e^(j phi): a few % near the
    line and its harmonics (the points from 30 to 500 Hz), a small scatter elsewhere (the window's sidelobes). The
    spectra only: the DAQ's time series are clean. Measured (paper_121): 60 Hz, a_h 0.29 mV, N 2, the 3rd 0.32, the 5th
    0.17: the 68.1 Hz points off by 2.6 %, the 46.4 Hz ones by 1.5-1.6 %, those from 100 to 464 Hz by 0.5-1.4 %, the
    median point by 0.05-0.07 %."""
    f0, ah, ncyc = _line_f(s), lu(s.rng, 1e-4, 5e-4), int(s.rng.choice([1, 2]))
    harm = ((1, 1.0), (3, s.rng.uniform(0.2, 0.5)), (5, s.rng.uniform(0.05, 0.2)))
    for r in s.recs:
        if r.series:
            continue
        f = r.cols["f_Hz"]
        err = np.zeros(f.size, complex)
        for n, a in harm:
            err += a * np.sinc(ncyc * (n * f0 - f) / f) * np.exp(1j * s.rng.uniform(0, 2 * np.pi, f.size))
        z = (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) * (1 + ah / 0.01 * err)
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = z.real.copy(), z.imag.copy()


def mp_occupancy_lights(s: Session) -> None:
    """The lab's ceiling lights on a motion sensor: each person passing (Poisson, 1-4 an hour; the first 0-60 % into the
    session) switches them on for t_on 3-10 min (a new pass restarts it), their LED drivers' capacitor-input rectifiers
    drawing the line's current in peaks (3rd 0.6-0.85 of the fundamental, 5th 0.3-0.6, 7th 0.15-0.35), and the cable run
    above the bench couples it magnetically into the laser's and the current amplifier's leads (an induced voltage, each
    harmonic weighted by its order): 0.5-2 um and 2-8 uA at the line (log), 50 or 60 Hz, phase locked to the session
    clock, on while the lights are (a 0.5 s soft start), off otherwise. Displacement and current. Measured (p26_123): 50
    Hz, 2.1 passes an hour, t_on 8.4 min: the lights on 57 % of the recorded samples (from 45 to 550 s, 1600 to 3060 s
    and 3250 to 3800 s into the session); while on 0.99 um and 2.5 uA at 50 Hz, 1.8 um / 4.5 uA at 150 Hz, 2.8 um / 7.1
    uA at 250 Hz, 2.0 um / 5.1 uA at 350 Hz; displacement residual 0.083 % of its RMS (3.9x its noise), current 0.17 %
    (0.13x)."""
    f0, ph = _line_f(s), s.rng.uniform(0, 2 * np.pi)
    a3, a5, a7 = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.3, 0.6), s.rng.uniform(0.15, 0.35)
    ad, ai = lu(s.rng, 5e-7, 2e-6), lu(s.rng, 2e-6, 8e-6)
    rate, t_on = s.rng.uniform(1.0, 4.0) / 3600.0, s.rng.uniform(180.0, 600.0)
    trig, t = [s.t0 + s.rng.uniform(0.0, 0.6) * (s.t1 - s.t0)], s.t0 - t_on
    while t < s.t1:
        t += s.rng.exponential(1 / rate)
        trig.append(t)
    spans: list[list[float]] = []
    for a in sorted(trig):
        if spans and a <= spans[-1][1]:
            spans[-1][1] = a + t_on
        else:
            spans.append([a, a + t_on])
    spans_t = [(a, b) for a, b in spans]
    for r in s.series():
        tt = r.cols["t_s"]
        hum = _episodes(tt, spans_t, 0.5) * _hum(tt, f0, {3: 3 * a3, 5: 5 * a5, 7: 7 * a7}, ph)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * hum
        r.cols["i_A"] = r.cols["i_A"] + ai * hum


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_register_wrap(s: Session) -> None:
    """The laser's reading taken from its controller's register over a fieldbus (Modbus) as a signed 16-bit count of
    0.05 or 0.1 um (drawn: the head's resolution), the strip's rest 2 mm at most from the head's reference distance
    (drawn), the logger taring the count at rest: a count beyond +-32767 wraps to the other end, so every excursion
    beyond +-1.64 or +-3.28 mm from the reference jumps by 3.28 or 6.55 mm (the 1 V steps, the 1 V harmonics' crests),
    the small records as they were (to the count's step). Displacement only. Measured: (paper_121) 0.05 um counts, the
    rest 1.79 mm below the reference: every 1 V step wraps above 3.43 mm (47 % of its samples; its top read between -1.2
    and 5.1 mm), 16.7 % of the samples, displacement residual 79 % of its RMS; (s001_122) 0.05 um, 0.50 mm above: the
    steps wrap above 1.14 mm (96 % of their samples) and the 1 V harmonics (half their samples, their fundamental turned
    by -169 deg), 38 % of the samples, residual 122 %."""
    unit, off = float(s.rng.choice([5e-8, 1e-7])), s.rng.uniform(-2e-3, 2e-3)

    def counts(x: np.ndarray) -> np.ndarray:
        return (np.round((x + off) / unit) + 32768) % 65536 - 32768

    c0 = float(counts(np.array([0.0]))[0])
    map_disp(s, lambda r, d: (counts(d) - c0) * unit)


def out_usb_ground_drop(s: Session) -> None:
    """A bus-powered rig: the small drive amplifier takes its supply from the same USB port as the DAQ, through a DC-DC
    converter making its +-12 V rails (its input current 2.5-3.5 times its load's abs(i), smoothed by its decoupling
    over tau_s 0.5-5 ms, log), while the DAQ's single-ended inputs are referred to the DAQ's ground: that supply current
    returns through the USB cable's ground (0.15-0.5 Ohm, log, with its connectors), and every input reads the ground's
    drop on top of its signal, the drive's monitor (v_V), the current amplifier's output (10 mA/V) and the laser's (2
    mm/V) alike, with one sign (drawn), its quiescent part zeroed by the logger at rest. A rectified ghost of the
    current in all three channels, a few mV on the drive's record. Voltage, current and displacement. Measured:
    (paper_121) 0.15 Ohm, the converter 3.3x, tau_s 1.3 ms, negative: the drive's record -11 mV at the steps' edges,
    -3.5 mV on average over the 20 Hz sines, -1.4 mV over the 1 V harmonics; the current's +-0.11 mA and the
    displacement's 23 um at the edges; displacement residual 0.09 % of its RMS (5.3x its noise), current 0.49 % (0.37x);
    (p26_123) 0.21 Ohm, 3.0x, positive: +13 mV at the edges, +4.5 mV over the 20 Hz sines; 0.15 % (7.1x), 0.62 %
    (0.46x)."""
    rg, boost, tau_s, sg = lu(s.rng, 0.15, 0.5), s.rng.uniform(2.5, 3.5), lu(s.rng, 5e-4, 5e-3), _sign(s)
    for r in s.series():
        a = np.abs(r.cols["i_A"])
        g = sg * rg * boost * _lag_state(a, r.fs, tau_s, float(a[0]))
        r.cols["v_V"] = r.cols["v_V"] + g
        r.cols["i_A"] = r.cols["i_A"] + g * CURRENT_A_PER_V
        r.cols["disp_m"] = r.cols["disp_m"] + g * LASER_M_PER_V


def out_buoyant_bubble(s: Session) -> None:
    """A strip held with its faces horizontal in a bath filled with cold tap water that warms (so supersaturated with
    air): a gas bubble nucleates under the strip at x_b (0.6-0.95 L), grows by diffusion (its radius as the square root
    of time, to its detaching radius R_d 0.5-1 mm in t_grow 120-600 s, log) and pushes the strip by its buoyancy rho g
    V, bending it by rho g V x_b^2 (3 L - x_b)/(6 EI) at the tip (EI from the preset's modulus); it lets go at R_d, or
    earlier when the tip moves faster than 0.2-0.5 of the session's largest bend per second (its motion over 0.2 s: the
    step's edges, the large harmonics' swings, not the fast small sines), and the next one starts 10-120 s later (log).
    A slow creep of the reading's zero, up to about 0.1 mm, that drops back at the steps' edges. Sample by sample
    through the session in time order (the bubble growing and letting go over the rests too); displacement only.
    Measured: (paper_121) the bubble at 0.87 L (the strip pushed towards the negative side), R_d 0.87 mm, t_grow 300 s:
    up to -0.18 mm, creeping through the sines, dropping at the steps' edges and in the 1 V harmonics (10 times inside
    records), displacement residual 1.9 % of its RMS (110x its noise); (p26_123) 0.81 L, positive, R_d 0.70 mm, t_grow
    400 s: up to +0.053 mm, 0.64 % (30x)."""
    EI, _, L = _eibeam(s)
    xb, sg = s.rng.uniform(0.6, 0.95) * L, _sign(s)
    comp = xb**2 * (3 * L - xb) / (6 * EI) * RHO_WATER * G_N * 4 / 3 * math.pi
    rd, t_grow = s.rng.uniform(5e-4, 1e-3), lu(s.rng, 120.0, 600.0)
    v_j = s.rng.uniform(0.2, 0.5) * _largest(s)
    waits = iter([lu(s.rng, 10.0, 120.0) for _ in range(2000)])
    t_n = s.t0 - s.rng.uniform(0.0, t_grow)
    for r in _chrono(s):
        t = r.cols["t_s"]
        while t_n + t_grow <= float(t[0]):  # let go over the rest before this record
            t_n = t_n + t_grow + next(waits)
        slow = lti(r.cols["disp_m"], r.fs, lambda z: 1 / (1 + 0.2 * z))
        speed = (np.abs(np.diff(slow, prepend=slow[0])) * r.fs).tolist()
        out = np.empty(t.size)
        for k, tk in enumerate(t.tolist()):
            rad = rd * math.sqrt((tk - t_n) / t_grow) if tk > t_n else 0.0
            if rad >= rd or (rad > 0 and speed[k] > v_j):
                t_n, rad = tk + next(waits), 0.0
            out[k] = rad**3
        r.cols["disp_m"] = r.cols["disp_m"] + sg * comp * out


def out_dendrite_fuse(s: Session) -> None:
    """A platinum dendrite grown through the membrane in the plating (a known IPMC fault) shorts the two electrodes
    through R_d 0.5-3 kOhm (log): an ohmic path beside the strip that the drive's current passes without bending it, and
    the analyser sees too, until it fuses. The dendrite's neck wears by electromigration, its life at a voltage v going
    as abs(v)^-n (Black's law, n 2-4), the damage summed sample by sample through the session in time order, and it
    fuses where the damage reaches its life, set at 30-80 % of the whole session's: an extra conductance in the current
    and the spectra (those taken before it fuses) that vanishes at one instant, during a large-drive record. Current and
    spectra. Measured: (s001_122) R_d 1.06 kOhm, n 2.3, fused 57 % into the session (in the 1300 kPa block's 1 V
    harmonic): +0.94 mA on the steps' plateaus before it (0.55-0.65 mA clean), the current's RMS +6.7 % (residual 15 %,
    39x its noise); the spectra before it |Z| -14 % at 0.1 Hz, -4.5 % at 10 kHz; (p26_123) 0.84 kOhm, n 3.9, fused 55 %
    in (during the 3062 kPa block's step): +1.2 mA, residual 16 % (12x), |Z| -19 % at 0.1 Hz."""
    rd, n = lu(s.rng, 500.0, 3000.0), s.rng.uniform(2.0, 4.0)
    recs = _chrono(s)
    dose = [np.cumsum(np.abs(r.cols["v_V"]) ** n) / r.fs for r in recs]
    total = float(sum(x[-1] for x in dose))
    life, acc, t_f = s.rng.uniform(0.3, 0.8) * total, 0.0, s.t1 + 1.0
    for r, x in zip(recs, dose):
        if acc + x[-1] >= life:
            t_f = float(r.cols["t_s"][int(np.searchsorted(x, life - acc))])
            break
        acc += float(x[-1])
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + r.cols["v_V"] / rd * (r.cols["t_s"] < t_f)
    at = _spectrum_times(s)
    for r in s.recs:
        if not r.series and at[id(r)] < t_f:
            z = 1 / (1 / (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) + 1 / rd)
            r.cols["z_re_ohm"], r.cols["z_im_ohm"] = z.real.copy(), z.imag.copy()


FRESH17_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"ethanol_exchange": br_ethanol_exchange, "leak_drag": br_leak_drag},
    "faradaic_current": {"pitting_contact": far_pitting_contact, "reversed_electrolytic": far_reversed_electrolytic},
    "hysteresis": {"hall_ferrite": hy_hall_ferrite, "calcium_bridges": hy_calcium_bridges},
    "time_delay": {"alpha_beta_tracker": td_alpha_beta_tracker, "scope_capture": td_scope_capture},
    "sensor_offset": {"defocus_edge": so_defocus_edge, "peak_line_mode": so_peak_line_mode},
    "clamp_relaxation": {"pumped_bellows": cr_pumped_bellows, "piezo_stack": cr_piezo_stack},
    "dehydration": {"draft_shield": dh_draft_shield, "oil_film": dh_oil_film},
    "strain_resistance": {"crack_wall_capacitance": sr_crack_wall_capacitance,
                          "ligament_corrosion": sr_ligament_corrosion},
    "large_deflection": {"psd_edge": ld_psd_edge, "amr_angle": ld_amr_angle},
    "mains_pickup": {"eis_line_leak": mp_eis_line_leak, "occupancy_lights": mp_occupancy_lights},
    "unexplained": {"register_wrap": out_register_wrap, "usb_ground_drop": out_usb_ground_drop,
                    "buoyant_bubble": out_buoyant_bubble, "dendrite_fuse": out_dendrite_fuse},
}
inject.register_forms(FRESH17_FORMS)


# ------------------------------------------------------------------------------------------------ variants

SDT_FLOOR = {"v_V": 1e-4, "i_A": 1e-6, "disp_m": 1e-7, "force_N": 0.02}  # the historian's smallest deviations


def sdt_deviations(s: Session, k: float) -> dict[str, float]:
    """``swinging_door``'s deviation per column: k times the column's noise at rest (inject_fresh15.rest_noise; the
    median over the series of std(diff)/sqrt(2) where the session has no step edge), at least SDT_FLOOR; the load
    cell's 0.02 N."""
    out = {}
    for col in ("v_V", "i_A", "disp_m"):
        nz = rest_noise(s, col)
        if not np.isfinite(nz):
            nz = float(np.median([np.std(np.diff(r.cols[col])) / math.sqrt(2) for r in s.series()]))
        out[col] = max(k * nz, SDT_FLOOR[col])
    out["force_N"] = SDT_FLOOR["force_N"]
    return out


def v_swinging_door(s: Session) -> None:
    """A process historian (the kind a plant-style lab logs its instruments into) that stores every time series with its
    swinging-door compression and exports the stored rows: a row is kept only when the straight line from the last kept
    row can no longer pass within each column's deviation of every row skipped since (every column of a record shares
    its rows here, so a row is kept when any column needs it), the first and last rows always. The deviations are set
    near each channel's noise, k (1.5-3, drawn for the session) times its noise at rest for the drive's monitor, the
    current and the displacement, 0.02 N for the load cell: the rests and the plateaus shrink to a quarter of their
    rows, the fast records keep nearly all of theirs, and every kept row holds its own raw value and stamp. The spectra
    and the manifest as they were. ``labrig import`` takes it (t_s strictly increasing, unevenly spaced)."""
    dev = sdt_deviations(s, s.rng.uniform(1.5, 3.0))
    for r in s.series():
        keys = [c for c in r.cols if c != "t_s"]
        keep = _sdt_keep(r.cols["t_s"], [r.cols[c] for c in keys], [dev.get(c, 0.0) for c in keys])
        r.cols = {c: x[keep] for c, x in r.cols.items()}


inject.VARIANTS.update({"swinging_door": v_swinging_door})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_121", "s001_122", "p26_123"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 121-123
    "back_relaxation": [("ethanol_exchange", 121, P, "swinging_door"), ("leak_drag", 123, T, "log_steps")],
    "faradaic_current": [("pitting_contact", 123, T, "rate07"), ("reversed_electrolytic", 122, S, "float32_time")],
    "hysteresis": [("hall_ferrite", 122, S, "tared_records"), ("calcium_bridges", 121, P, "settled_sines")],
    "time_delay": [("alpha_beta_tracker", 121, P, "dropped_packets"), ("scope_capture", 122, S, "asrun")],
    "sensor_offset": [("defocus_edge", 123, T, "coherent_sines"), ("peak_line_mode", 122, S, "shortened_shuffled")],
    "clamp_relaxation": [("pumped_bellows", 121, P, "merged_loadcell"), ("piezo_stack", 123, T, "asrun")],
    "dehydration": [("draft_shield", 122, S, "swinging_door"), ("oil_film", 122, S, "host_timed")],
    "strain_resistance": [("crack_wall_capacitance", 121, P, "steps_sines"),
                          ("ligament_corrosion", 123, T, "two_pressures")],
    "large_deflection": [("psd_edge", 121, P, "resampled"), ("amr_angle", 123, T, "short_pretrigger")],
    "mains_pickup": [("eis_line_leak", 121, P, "eis_descending"), ("occupancy_lights", 123, T, "trigger_clock")],
    "unexplained": [("register_wrap", 121, P, "own_clock"), ("register_wrap", 122, S, "asrun"),
                    ("usb_ground_drop", 121, P, "decimated3"), ("usb_ground_drop", 123, T, "no_loadcell"),
                    ("buoyant_bubble", 121, P, "swinging_door"), ("buoyant_bubble", 123, T, "asrun"),
                    ("dendrite_fuse", 122, S, "fir_decimated"), ("dendrite_fuse", 123, T, "asrun")],
}
CLEAN = [(121, P, "asrun"), (121, P, "swinging_door"), (122, S, "asrun"), (122, S, "no_spectra"),
         (123, T, "asrun"), (123, T, "swinging_door")]


def fresh17_cases(only: str | None = None) -> list[Case]:
    """The eighteenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    121-123)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh17_cases, "inject_fresh17", "fresh17")
