"""A nineteenth held-out set for the diagnosis (issue 12), fresh18, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh17.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a PEDOT:PSS coating over the electrodes
switching its doping with the charge-trapping hysteresis of conducting polymers, a strip moving through a yield-stress
gel phantom, a through-crack isolating the strip's outer part behind its opening resistance, an OSEM-type shadow vane
in a Gaussian beam, a wide-angle camera's equidistant projection, the drive amplifier's transformer radiating more with
its load), some on the history (calcium carbonate scale growing in the pores of whichever face passed cathodic current,
a detergent film on the platinum stripped above a potential and re-adsorbing at rest, a water film running off the
tilting tip before a strip in air starts drying, electrolysis gas clouding the laser's view under its automatic
exposure), some on time or on the clamp pressure (a strip thinner towards its tip relaxing with a spread of lags, a
bath's on/off thermostat warming the electrolysis, a laser on a 3D-printed bracket sagging by power-law creep, a
Belleville stack whose flat top hides the pads' creep, a vacuum clamp losing its vacuum through a laminar leak, a
silica-gel sachet drying the air of a closed box and saturating, a direct-assembly electrode whose ionomer binder swells
towards its percolation threshold, the building's voltage distortion changing through the working day) and some from
the lab's wiring or settings (a programmable elliptic anti-alias filter on the laser's line, two heads inboard whose
readings the lab's script extrapolates to the tip). Four structures outside the catalogue (truth "unexplained": the
current read by a clamp-on Hall probe whose core keeps a remanence until it is degaussed, the impedance analyser's DC
bias left on so that the strip discharges at each block's first record, a drive output updated on a clock of its own
slower than the logged command, a drive amplifier's soft start at every record's arming); clean sessions. All on three
bases of new seeds (124-126: the paper strip, the seed-001 strip on its own sweep, the paper strip 23 mm free) and on
the earlier sets' protocol / data-shape variants plus one new here: a frequency-response logger that stores each
stepped sine as its synchronously averaged period (``cycle_averaged``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh17 are reused (importing inject_fresh17 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh18.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal, special

import inject
import inject_fresh17  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, play, ref_disp
from inject_fresh2 import _chrono, _drive_side, _spec, _through
from inject_fresh3 import _resist, _sign, _step_responses
from inject_fresh4 import _clamp_law, _lag_state
from inject_fresh5 import _arc
from inject_fresh7 import _block_of, _superpose
from inject_fresh8 import _hum, _late, _leaky
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f
from inject_fresh14 import _lagged, _largest, _thermostat
from inject_fresh15 import _edges
from inject_fresh17 import _first_steps

# the paper's strip 23 mm free (earlier sets used 20, 25-40, 42 and 45 mm; its 1 V step peaks near 5.2 mm, 8.8 mm x
# (23/30)^2, inside the laser's +-20 mm). The preset is "paper_23mm" (not "paper_23", which is a base of
# bench/inject.py), its base "p23_126": registered in every process importing this module
inject.register_free_length("paper_23mm", 0.023)

inject.BASES.update({
    "paper_124": ("paper-sweep", "paper", 124),
    "s001_125": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 125),
    "p23_126": ("paper-sweep", "paper_23mm", 126),
})

R_GAS = 8.314  # J/(mol K)
T_ROOM = 298.15  # K
P_ATM = 101.3  # kPa


# ------------------------------------------------------------------------------------------------ tools


def _ratio_grid(h: Callable[[np.ndarray], np.ndarray], fmax: float, dc: complex) -> Callable[[np.ndarray], np.ndarray]:
    """A smooth transfer function h(s) evaluated on 1500 log-spaced frequencies up to fmax and interpolated (real and
    imaginary parts) onto any s = 2 pi j f: the beam's ratios change slowly with f, and an FFT grid of a long record
    holds 10^5 points. Below the grid's first frequency its first value (``dc`` if that is not finite)."""
    fg = np.logspace(-4, math.log10(max(fmax, 1e-3)), 1500)
    with np.errstate(divide="ignore", invalid="ignore"):
        hg = h(2j * np.pi * fg)
    dc = complex(hg[0]) if np.isfinite(hg[0]) else dc
    hg = np.where(np.isfinite(hg), hg, dc)

    def out(z: np.ndarray) -> np.ndarray:
        f = np.abs(np.asarray(z)) / (2 * np.pi)
        re = np.interp(f, np.r_[0.0, fg], np.r_[np.real(dc), hg.real])
        im = np.interp(f, np.r_[0.0, fg], np.r_[np.imag(dc), hg.imag])
        return re + 1j * im

    return out


def _stations(s: Session, xs: np.ndarray, memory_s: float = 2.0) -> dict[int, np.ndarray]:
    """The strip read at the stations xs (fractions of L) in place of its tip, each record through the ratios of the
    beam's transfer functions (displacement_tf with sensor_x over the tip's) with the session's history before it
    (inject_fresh2._through's padding: memory_s of the session before, its own last value held after): id(record) ->
    array (len(xs), n). The ratios interpolated from a log grid (_ratio_grid)."""
    from labrig.physics import transfer

    recs = _chrono(s)
    T = np.concatenate([r.cols["t_s"] for r in recs])
    D = np.concatenate([r.cols["disp_m"] for r in recs])
    out = {}
    for r in recs:
        d, n, k = r.cols["disp_m"], r.cols["disp_m"].size, int(memory_s * r.fs)
        past = np.interp(r.cols["t_s"][0] - np.arange(k, 0, -1) / r.fs, T, D, left=0.0)
        x = np.r_[past, d, np.full(n, d[-1])]
        m = 1 << int(math.ceil(math.log2(2 * x.size)))
        X = np.fft.rfft(x, m)
        z = 2j * np.pi * np.fft.rfftfreq(m, 1.0 / r.fs)
        sp = _spec(s, r)
        rows = []
        for xi in np.asarray(xs, float).tolist():
            si = sp.with_(sensor_x=xi * sp.geometry.length)
            h = _ratio_grid(lambda q, si=si: transfer.displacement_tf(q, si) / transfer.displacement_tf(q, sp),
                            r.fs / 2, complex(xi**2))
            rows.append(np.fft.irfft(X * h(z), m)[k : k + n])
        out[id(r)] = np.array(rows)
    return out


def _plateau_current(s: Session) -> dict[float, float]:
    """Each pressure's leak current at 1 V: the median abs(current) over the last 3 s of its first step's plateau,
    per volt of that step."""
    out = {}
    for p, r in _first_steps(s).items():
        v, i = r.cols["v_V"], r.cols["i_A"]
        on, off = (int(e) for e in _edges(v)[:2])
        hold = slice(max(off - int(3 * r.fs), on + 1), off)
        out[p] = float(np.median(np.abs(i[hold]))) / max(float(np.median(np.abs(v[hold]))), 1e-3)
    return out


def _bv(v: np.ndarray, i1: float, vt: float) -> np.ndarray:
    """A symmetric Butler-Volmer branch 2 i0 sinh(v/2 v_t) scaled to i1 at 1 V."""
    return i1 * np.sinh(np.asarray(v) / (2 * vt)) / math.sinh(1 / (2 * vt))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_tapered_thickness(s: Session) -> None:
    """A hand-polished strip (or one cut from the thin edge of a cast membrane) thinner towards its tip, h = h_0 (1 - a
    xi) (a 0.15-0.4 at the tip, xi = x/L): the back-flow crosses the membrane's thickness, so its time goes as h^2/D,
    tau(xi) = tau_0 (1 - a xi)^2 (tau_0 4-12 s at the root, log), and each station relaxes with its own lag. The tip
    reads them weighted by their share of its bend, the curvature 1/h (the moment h^2, the stiffness h^3) times the
    lever (1 - xi): a continuous spread of lags from tau_0 (1 - a)^2 to tau_0, 1 - K2 sum_j w_j/(1 + tau_j s) over 24
    stations (K2 0.8-1.2), not any sum of a few exponentials. Through inject_fresh2._through with 60 s of the session's
    history; displacement only. Measured (s001_125): K2 0.95, tau_0 11.9 s, a 0.22 (the tip's lag 7.3 s): displacement
    RMS -63 % (residual 85 %, 2590x its noise); the 1 V steps peak at 1.60 mm (4.69 mm clean) and hold 1.13 mm by their
    plateaus' ends, -0.02 to -0.04 mm 2 s after their falls; the 1 V harmonics' gain 0.969 with 8.8 deg of lead, the 0.5
    V sines' at 0.1 Hz 0.984 with 8.3 deg."""
    k2, tau0, a = s.rng.uniform(0.8, 1.2), lu(s.rng, 4.0, 12.0), s.rng.uniform(0.15, 0.4)
    xi = (np.arange(24) + 0.5) / 24
    w = (1 - xi) / (1 - a * xi)
    w, taus = w / w.sum(), tau0 * (1 - a * xi) ** 2

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda z: 1 - k2 * np.sum(w[:, None] / (1 + taus[:, None] * np.asarray(z)[None, :]), axis=0)

    new = _through(s, H, 60.0)
    map_disp(s, lambda r, d: new[id(r)])


def br_cathodic_scale(s: Session) -> None:
    """A tap-water bath (its Ca2+ and HCO3-): wherever a face is the cathode and the drive is beyond water reduction's
    onset v_on (0.6-0.8 V: the 1 V steps' plateaus, the crests of the 1 V harmonics), the hydroxide it makes raises the
    pH in that face's electrode pores and calcium carbonate precipitates there. The back-flow leaves and re-enters the
    membrane through the face it was pushed to, and the scale narrows that face's pores: the back-flow's lag is tau_0
    (1 + Q_f/q_s) (tau_0 2-6 s, log; q_s 20-80 mC, log), Q_f the electrolysis charge the face has passed as cathode
    (the current beyond onset, i_1 (abs(v) - v_on)/(1 - v_on), i_1 each pressure's leak at 1 V), the face the one
    holding the pushed water (the lag's sign). The positive 1 V steps scale one face far more than the other: the
    back-flow on that side slows block by block, the other side hardly. Sample by sample through the session in time
    order (the state carried over the rests, the displacement linear across them), read d - K2 x (K2 0.8-1.2);
    displacement only. Measured (paper_124): K2 1.01, tau_0 4.9 s, v_on 0.70 V, q_s 34 mC: the positive side's lag 4.9,
    7.9, 10.9, 13.7 s at the blocks' starts (22, 42, 63 mC passed), 16.6 s by the end, the other side's grown only by
    the harmonics' negative crests: displacement RMS -63 % (residual 90 %, 5410x its noise); the 1 V steps peak at 2.12,
    2.67, 3.08, 3.42 mm block by block (8.82 mm clean), 1.04 to 2.72 mm by their plateaus' ends, -1.06, -0.61, -0.12,
    +0.37 mm 2 s after their falls; the 1 V harmonics' lead 12.0, 8.8, 7.0, 5.7 deg."""
    k2, tau0 = s.rng.uniform(0.8, 1.2), lu(s.rng, 2.0, 6.0)
    v_on, q_s = s.rng.uniform(0.6, 0.8), lu(s.rng, 0.02, 0.08)
    g1 = _plateau_current(s)
    g0 = float(np.median(list(g1.values()))) if g1 else 5e-4
    x, qa, qb, d_end = 0.0, 0.0, 0.0, 0.0
    for r, gap in _gaps(s, 1.0):
        d, v = r.cols["disp_m"], r.cols["v_V"]
        for dt, u in gap:
            tau = tau0 * (1 + (qb if x > 0 else qa) / q_s)
            x += -math.expm1(-dt / tau) * (d_end + u * (float(d[0]) - d_end) - x)
        dt = 1.0 / r.fs
        g = g1.get(float(r.entry["pressure_kPa"]), g0)
        ia = (g * np.clip((np.abs(v) - v_on) / (1 - v_on), 0, None) * dt).tolist()
        out = np.empty(d.size)
        for k, (dk, vk, qk) in enumerate(zip(d.tolist(), v.tolist(), ia)):
            if vk > 0:
                qb += qk
            else:
                qa += qk
            tau = tau0 * (1 + (qb if x > 0 else qa) / q_s)
            x += (dk - x) * -math.expm1(-dt / tau)
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


# ------------------------------------------------------------------------------------------------ faradaic current


def far_detergent_film(s: Session) -> None:
    """A detergent film on the platinum (the cuvette washed with a surfactant and not rinsed enough, or the strip
    handled with gloves): the adsorbed molecules block a share phi (0.6-0.9) of the sites where water is electrolysed
    (symmetric Butler-Volmer on the bare surface, 0.1-0.4 mA at 1 V, log, v_t 0.1-0.2 V). The film desorbs (oxidative
    or reductive desorption) when the drive's magnitude passes E_d (0.6-0.85 V), at the rate exp((abs(v) - E_d)/b)/tau_d
    (b 0.08-0.15 V, tau_d 2-10 s, log), and re-adsorbs from the bath at (1 - theta)/tau_a (tau_a 30-300 s, log): the
    covered share theta falls during the large records and comes back over the rests. The leak current is (1 - phi
    theta) of the bare surface's: small at the first moments of each 1 V record, growing as the film strips, and larger
    for the records that follow a large one. Sample by sample through the session (inject_fresh11._walk, the film whole
    at the first record); the analyser's 10 mV sees the branch's slope at 0 V (under 0.1 mS, blocked), the spectra
    untouched: the current only. Measured (paper_124): 0.10 mA at 1 V bare, v_t 0.12 V, phi 0.66, E_d 0.72 V, b 0.14
    V, tau_d 4.5 s, tau_a 65 s: current residual 1.4 % of its RMS (1.0x its noise); on each 1 V step +44 uA 0.1 s after
    the rise, +71 uA at 0.5 s, +100 uA from 5 s on (the plateaus' current +16 to +17 %); the 1 V harmonics' current +1.1
    % with 0.6 deg of lag; the 0.5 V sines' at most +9 uA."""
    i1, vt = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2)
    phi, e_d, b = s.rng.uniform(0.6, 0.9), s.rng.uniform(0.6, 0.85), s.rng.uniform(0.08, 0.15)
    tau_d, tau_a = lu(s.rng, 2.0, 10.0), lu(s.rng, 30.0, 300.0)

    def step(th: float, v: float, dt: float) -> float:
        kd = math.exp((abs(v) - e_d) / b) / tau_d
        k = kd + 1.0 / tau_a
        th_inf = (1.0 / tau_a) / k
        return th_inf + (th - th_inf) * math.exp(-k * dt)

    th = _walk(s, step, "v_V", 1.0, lambda x, sec: 1 - (1 - x) * math.exp(-sec / tau_a))
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + (1 - phi * th[id(r)]) * _bv(r.cols["v_V"], i1, vt)


def far_thermostat_bath(s: Session) -> None:
    """An aquarium heater on its bimetal thermostat in the cuvette, a few centimetres from the strip: the water there
    saws by +-dT (0.8-2.5 K) about its set point, rising over the heating share (0.25-0.5) of each cycle (300-900 s)
    and falling over the rest (inject_fresh14._thermostat). Water's electrolysis on platinum is thermally activated
    (E_a 40-60 kJ/mol for the hydrogen and oxygen evolutions), so its exchange current follows the saw: a symmetric
    Butler-Volmer branch (0.08-0.3 mA at 1 V at the set point, log, v_t 0.12-0.2 V) times exp(E_a/R (1/T_0 - 1/T)), a
    leak that breathes by +-10-30 % with the thermostat's cycle, its phase unrelated to the records. The strip's own
    linear response taken as unchanged (the form adds the faradaic branch only); the current only. Measured (p23_126):
    0.28 mA at 1 V at the set point, v_t 0.20 V, E_a 43 kJ/mol, +-2.2 K over 892 s (heating 41 % of it): the leak
    +-13 % with the saw; current residual 4.3 % of its RMS (3.1x its noise); the 1 V steps' plateaus +0.27, +0.31,
    +0.27, +0.27 mA block by block (0.45-0.49 mA clean); the 1 V harmonics' current +4.0 to +4.6 % with 2.3-2.6 deg of
    lag."""
    i1, vt, ea = lu(s.rng, 8e-5, 3e-4), s.rng.uniform(0.12, 0.2), s.rng.uniform(4e4, 6e4)
    dT, duty = s.rng.uniform(0.8, 2.5), s.rng.uniform(0.25, 0.5)
    per, ph = s.rng.uniform(300.0, 900.0), s.rng.uniform(0.0, 1.0)
    for r in s.series():
        T = T_ROOM + dT * _thermostat(r.cols["t_s"], per, duty, ph)
        r.cols["i_A"] = r.cols["i_A"] + np.exp(ea / R_GAS * (1 / T_ROOM - 1 / T)) * _bv(r.cols["v_V"], i1, vt)


# ------------------------------------------------------------------------------------------------ hysteresis


def _logistic(x: np.ndarray) -> np.ndarray:
    return 0.5 * (1 + np.tanh(0.5 * np.asarray(x)))


def hy_pedot_coating(s: Session) -> None:
    """Both electrodes coated with PEDOT:PSS (to lower their surface resistance, a common IPMC recipe): each coating's
    doping switches with its face's potential, and conducting polymers keep a charge-trapping hysteresis between their
    oxidation and reduction waves that does not close at slow scans: the doped share y of a face follows its anodic wave
    S((u - E_0 - r)/w) while its potential u rises, its cathodic one S((u - E_0 + r)/w) while it falls, and stays put
    between them: y = S((play_r(u) - E_0)/w) (S the logistic; E_0 0.1-0.4 V of drive, r 0.08-0.2 V, w 0.04-0.1 V), the
    face on +v and the other on -v. Doping swells or shrinks the coating with the same sense as the strip's own
    actuation, a share h (0.05-0.15 V of drive) between a face fully doped and undoped: Gamma = v + h (y_A - y_B), a
    loop that sits where abs(v) crosses E_0 +- r and nothing below. Rate-independent; the play carried through the
    session in time order, the change reaching the displacement through the strip's measured step response
    (inject_fresh2._drive_side); current untouched. Measured (s001_125): h 0.070 V, E_0 0.29 V, r 0.14 V, w 0.096 V:
    displacement RMS +7.6 % (residual 7.9 %, 241x its noise); the 1 V steps' peaks +6.9 % in the first block, +8.1 % in
    the later ones; the 1 V harmonics' gain 1.083 with 0.7 deg of lag; the 0.5 V, 20 Hz sines' 1.10 (residuals 60-79 %,
    the loop's harmonics on a few um)."""
    h, e0 = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.1, 0.4)
    rr, w = s.rng.uniform(0.08, 0.2), s.rng.uniform(0.04, 0.1)

    def gamma(v: np.ndarray) -> np.ndarray:
        pl = play(v, rr)
        return v + h * (_logistic((pl - e0) / w) - _logistic((-pl - e0) / w))

    _drive_side(s, gamma)


def hy_gel_phantom(s: Session) -> None:
    """A strip tested in a tissue phantom instead of water (a Carbopol gel, as labs do for medical actuators): the gel
    is a Herschel-Bulkley medium with a yield stress, so the tip stays where it is until the strip's elastic pull, k (d
    - y) (d where the strip would be, y where it is), exceeds the gel's yield force, r in the tip's units (0.02-0.06 of
    the displacement scale), and then moves at the speed the overstress drives through a shear-thinning gel, v_c ((abs(d
    - y) - r)/r)^(1/n) (n 0.35-0.6, the flow index; v_c 0.5-3 displacement scales a second, log). A loop of width 2 r
    that stays as the drive slows, a lag that grows on fast motion. Sample by sample through the session in time order
    (the tip held by the gel over the rests, the free bend linear across them); displacement only. Measured (p23_126):
    the yield 48 um (0.037 of the 1.30 mm scale), n 0.59, v_c 1.7 scales a second: displacement RMS -0.3 % (residual 2.7
    %, 99x its noise); the 1 V steps' peaks -1.0 %, +0.06 mm left 2 s after their falls; the 1 V harmonics' gain 0.993
    with 3.8 deg of lag; the 20 Hz sines' few um held by the gel (nothing of them read)."""
    ref = ref_disp(s)
    ry, n, vc = s.rng.uniform(0.02, 0.06) * ref, s.rng.uniform(0.35, 0.6), lu(s.rng, 0.5, 3.0) * ref

    def move(y: float, x: float, dt: float) -> float:
        over = abs(x - y) - ry
        if over <= 0:
            return y
        return y + math.copysign(min(vc * (over / ry) ** (1 / n) * dt, over), x - y)

    y, d_end = None, 0.0
    for r, gap in _gaps(s, 0.2):
        d = r.cols["disp_m"]
        if y is None:
            y = float(d[0])
        for dt, u in gap:
            y = move(y, d_end + u * (float(d[0]) - d_end), dt)
        dt, out = 1.0 / r.fs, np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            y = move(y, dk, dt)
            out[k] = y
        d_end = float(d[-1])
        r.cols["disp_m"] = out


# ------------------------------------------------------------------------------------------------ time delay


def td_elliptic_antialias(s: Session) -> None:
    """The laser's analogue line through a programmable anti-alias filter (a Krohn-Hite or Precision-Filters type
    instrument, or a DAQ's conditioning module) that the lab left on its "elliptic" setting for the sharpest cut: a
    4th, 6th or 8th order elliptic low-pass (Cauer; pass-band ripple 0.1-0.5 dB, stop band 50-80 dB down) at f_c
    40-120 Hz (log), its DC gain set to 1 (the instrument's calibration). Far below f_c its phase is a lag of nearly
    fixed delay, larger than a Butterworth's of the same order, with its ripple's wobble of group delay towards the
    corner; the 20 Hz records late and slightly off in gain. Through inject_fresh2._through (0.5 s of the session's
    history); displacement only. Measured (paper_124): 8th order, 0.38 dB of ripple, 55 dB of stop band, f_c 41.9 Hz:
    displacement residual 0.35 % of its RMS (21x its noise); the 1 V harmonics late by 15 ms (0.53 deg), the 4.4 Hz
    sines' gain 1.014 at -24 deg (15 ms), the 20 Hz ones' 1.007 at -124 deg (17 ms); the steps within 0.01 mm."""
    order = int(s.rng.choice([4, 6, 8]))
    rp, rs, fc = s.rng.uniform(0.1, 0.5), s.rng.uniform(50.0, 80.0), lu(s.rng, 40.0, 120.0)
    z, p, k = signal.ellip(order, rp, rs, 2 * np.pi * fc, analog=True, output="zpk")

    def h(q: np.ndarray) -> np.ndarray:
        q = np.asarray(q)[None, :]
        return k * np.prod(q - z[:, None], axis=0) / np.prod(q - p[:, None], axis=0)

    g0 = float(np.real(h(np.array([0.0]))[0]))
    new = _through(s, lambda r: (lambda q: h(q) / g0), 0.5)
    map_disp(s, lambda r, d: new[id(r)])


def td_bubble_exposure(s: Session) -> None:
    """A triangulation laser looking into the bath beside the strip's tip, its exposure on automatic: the gas that the
    large drives' electrolysis makes (above v_g 0.6-0.85 V, in proportion to abs(v) - v_g: the 1 V steps' plateaus, the
    crests of the 1 V harmonics) rises as a cloud of small bubbles through the beam, clearing over tau_b 5-30 s (log),
    and scatters the light: the received light falls as exp(-a G) (G the cloud, a leaky store of the gas,
    inject_fresh8._leaky; a up to 1.5-3 at the session's densest cloud), and the controller lengthens its exposure in
    proportion, t_e = t_e0 exp(a G) (t_e0 2-8 ms, log, capped at 30-60 ms), each reading centred in its exposure: a
    delay t_e/2 that rises during and after every large record and falls back over the following ones. Through
    inject_fresh8._late; displacement only. Measured (p23_126): v_g 0.72 V, tau_b 5.9 s, t_e0 3.6 ms, a 2.5, the cap 57
    ms: the delay 1.8 ms at rest, up to 22 ms by the end of each 1 V step's plateau (its fall read 22 ms late), up to
    4.9 ms on the 1 V harmonics' crests; displacement residual 0.13 % of its RMS (4.7x its noise); the 0.5 V sines at
    4.4 Hz -2.8 deg, at 20 Hz -12.9 deg (1.8 ms)."""
    v_g, tau_b = s.rng.uniform(0.6, 0.85), lu(s.rng, 5.0, 30.0)
    te0, a, cap = lu(s.rng, 2e-3, 8e-3), s.rng.uniform(1.5, 3.0), s.rng.uniform(0.03, 0.06)
    rate = {id(r): np.clip((np.abs(r.cols["v_V"]) - v_g) / (1 - v_g), 0, None) for r in s.series()}
    gas = _leaky(s, rate, tau_b)
    top = max(float(np.max(g)) for g in gas.values()) or 1.0
    _late(s, lambda r, t: 0.5 * np.minimum(te0 * np.exp(a * gas[id(r)] / top), cap), 0.3)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_quadratic_heads(s: Session) -> None:
    """No head on the tip (its end ragged from cutting, or too narrow a strip for the spot to stay on it): two laser
    heads on the strip at x_1 (0.3-0.5 L) and x_2 (0.6-0.85 L), and the lab's script taking the deflection as the
    root's rotation plus a uniform curvature, w = a x + b x^2, through both readings, evaluated at L: w(L) = c_1 w(x_1)
    + c_2 w(x_2) (c_1 negative, c_2 above 1: the extrapolation's weights). Right for the strip's quasi-static bend (a
    uniform curvature), but its dynamic shape (the first mode's, the back-flow's share along the strip) is not that
    quadratic, and the extrapolation multiplies the difference: the slow records read the tip, the fast ones' gain and
    phase off. The two stations through the beam's transfer functions with the session's history (_stations);
    displacement only. Measured (s001_125): the heads at 0.31 L and 0.65 L (c_1 -3.23, c_2 3.05): displacement residual
    0.38 % of its RMS (12x its noise); the 1 V steps' peaks +0.3 %, the 1 V harmonics' gain 1.008 with 0.5 deg of lead,
    the 20 Hz sines' 1.085-1.095 with 0.6-0.7 deg (residuals 11-13 %)."""
    x1, x2 = s.rng.uniform(0.3, 0.5), s.rng.uniform(0.6, 0.85)
    c = np.linalg.solve(np.array([[x1, x2], [x1**2, x2**2]]), np.array([1.0, 1.0]))
    at = _stations(s, np.array([x1, x2]))
    map_disp(s, lambda r, d: c[0] * at[id(r)][0] + c[1] * at[id(r)][1])


def so_printed_bracket(s: Session) -> None:
    """The laser head held on a 3D-printed PLA bracket beside a strip mounted upright (the clamp below, the tip up),
    its beam level and aimed a margin m (0.2-0.5 mm) below the tip's end when it was mounted (60-1200 s before the first
    record): PLA creeps at room temperature under the head's weight (Findley's power law, delta ~ t^n, n 0.15-0.35),
    so the head sinks and its spot walks down the strip, inboard, by 3-10 % of L by the session's end: fast at first,
    slower later. The strip read at the moving station (inject_fresh10._station); displacement only. Measured
    (paper_124): the aim 0.47 mm inside the tip, mounted 739 s before the first record, n 0.22, the sag 1.76 mm by the
    end: the station from 0.946 L at the first record to 0.926 L at the last; displacement RMS -12 % (residual 12 %,
    750x its noise); the 1 V steps' peaks -10.5, -12.1, -13.1, -13.7 % block by block, the 1 V harmonics' gain 0.895 to
    0.865, the 20 Hz sines' 0.72 to 0.66."""
    L = float(s.specimen["length_m"])
    m, t_m = s.rng.uniform(2e-4, 5e-4), s.rng.uniform(60.0, 1200.0)
    n, end = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.03, 0.1) * L
    t_mount, span = s.t0 - t_m, s.t1 - (s.t0 - t_m)

    def frac(r: Rec) -> np.ndarray:
        return 1 - (m + end * (np.clip(r.cols["t_s"] - t_mount, 0, None) / span) ** n) / L

    _station(s, frac, 1 - (m + end) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_belleville_stack(s: Session) -> None:
    """A screw clamp preloaded through a stack of Belleville (disc) springs, so that the force stays put as the pads
    settle: a disc's force follows the Almen-Laszlo curve, F ~ x ((eta - x)(eta - x/2) + 1) in units of its thickness
    (eta = h_0/t 1.2-1.4, monotonic with a nearly flat stretch about x = eta), and the operator sets each pressure by
    the screw, the top one at 0.8-1.0 eta, on the flat. The pads under the jaw creep under the held force (their
    thinning ~ F log(1 + u/tau), tau 10-60 s, log, from the setting 10-40 s before the block), and the stack extends by
    the same amount: the force falls by the stack's local slope times the creep, most at the lightest setting, on the
    curve's steep start (3-10 % there after 10 min, drawn), and hardly at the top, on its flat. Through the preset's
    clamp law (inject_fresh4._clamp_law). Measured (paper_124): eta 1.35, the top setting at 0.85 eta, tau 23 s, set 37
    s before each block, the lightest losing 6.1 % in 600 s: the load cell from 0.98 to 0.93 of its setting through the
    612 kPa block, 0.987 to 0.95 at 1837 kPa, 0.992 to 0.968 at 3062, 0.999 to 0.996 at 4287; displacement residual
    0.009 % of its RMS (0.55x its noise), current 0.21 % (0.16x); the 1837 kPa block's 20 Hz sines +1.5 %."""
    eta = s.rng.uniform(1.2, 1.4)
    x_top, lead = s.rng.uniform(0.8, 1.0) * eta, s.rng.uniform(10.0, 40.0)
    tau, drop_low = lu(s.rng, 10.0, 60.0), s.rng.uniform(0.03, 0.10)

    def F(x: np.ndarray) -> np.ndarray:
        return x * ((eta - x) * (eta - x / 2) + 1)

    xs = np.linspace(0.0, x_top, 4001)
    Fs = F(xs)
    p_top, p_low = max(s.pressures()), min(s.pressures())
    set_x = {p: float(np.interp(Fs[-1] * p / p_top, Fs, xs)) for p in s.pressures()}
    xl = set_x[p_low]
    beta = (xl - float(np.interp(float(F(xl)) * (1 - drop_low), Fs, xs))) / (float(F(xl)) * math.log1p(600.0 / tau))

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        x0 = set_x[min(set_x, key=lambda q: abs(q - p))]
        dx = beta * float(F(x0)) * np.log1p(np.clip(t - (t_set - lead), 0, None) / tau)
        return F(np.clip(x0 - dx, 0, None)) / float(F(x0))

    _clamp_law(s, rel)


def cr_vacuum_diaphragm(s: Session) -> None:
    """A vacuum clamp: the jaw pulled by a rubber diaphragm (through a lever) whose chamber the operator pumps down by
    hand at each setting (5-30 s before the block's first record), to a depth in proportion to the pressure wanted (the
    top setting at 60-90 % of the atmosphere), then closes its valve. The chamber leaks back through a fine laminar leak
    (a porous seat, a capillary), whose gas flow goes as p_atm^2 - p^2, so the chamber's pressure follows p = p_atm
    tanh(k p_atm u + atanh(p_0/p_atm)) from its pump-down p_0: the force, p_atm - p, falls by 3-10 % of the top
    setting's in 10 min (drawn), and relatively faster at the light settings (their chamber nearer the atmosphere: the
    loss rate k (p_atm + p)), beside the pads' own creep (1 - c log(1 + u/tau_p), c 0.2-0.6 %, tau_p 20-100 s, log).
    Through the preset's clamp law (inject_fresh4._clamp_law). Measured (p23_126): the top setting at 85 % of the
    atmosphere, losing 8.8 % of it in 10 min, pumped 18 s before each block, c 0.49 %, tau_p 91 s: the load cell from
    0.99 to 0.81 of its setting through the 612 kPa block, 0.997 to 0.83 at 1837 kPa, 0.996 to 0.85 at 3062, 0.997 to
    0.87 at 4287; displacement residual 0.15 % of its RMS (5.6x its noise), current 1.0 % (0.74x); the 4287 kPa block's
    sines near f1 -13 % at 4.4 Hz (+7 deg), -34 deg at 20 Hz."""
    dp_top, loss_top = s.rng.uniform(0.6, 0.9) * P_ATM, s.rng.uniform(0.03, 0.1)
    lead, c, tau_p = s.rng.uniform(5.0, 30.0), s.rng.uniform(0.002, 0.006), lu(s.rng, 20.0, 100.0)
    p_top = max(s.pressures())
    p0_top = P_ATM - dp_top
    k = (math.atanh((P_ATM - dp_top * (1 - loss_top)) / P_ATM) - math.atanh(p0_top / P_ATM)) / (P_ATM * 600.0)

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        p0 = P_ATM - dp_top * p / p_top
        u = np.clip(t - (t_set - lead), 0, None)
        pin = P_ATM * np.tanh(k * P_ATM * u + math.atanh(p0 / P_ATM))
        return (P_ATM - pin) / (P_ATM - p0) * (1 - c * np.log1p(u / tau_p))

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def _tilts(s: Session, frac: float) -> list[float]:
    """The session times where the bend's magnitude rises through frac of the session's largest (the tip's slope, 2
    d/L on the uniform arc, past the same share of its largest): one per excursion, the next counted only once the bend
    has come back below 0.7 of that level."""
    level, armed, out = frac * _largest(s), True, []
    for r in _chrono(s):
        for tk, dk in zip(r.cols["t_s"].tolist(), np.abs(r.cols["disp_m"]).tolist()):
            if armed and dk > level:
                out.append(tk)
                armed = False
            elif dk < 0.7 * level:
                armed = True
    return out


def dh_film_shedding(s: Session) -> None:
    """A strip in air wetted (dipped, or a drop from a pipette) 0-300 s before the first record: a film of surface water
    keeps the membrane saturated while it lasts. The film evaporates at the wet surface's steady rate (alone it would
    last 0.3-0.8 of the session) and runs off the tip whenever the tip tilts past the film's roll-off angle (water on
    the rough plating slides at 20-40 deg; here 0.3-0.6 of the session's largest tip slope): at each excursion beyond it
    (the 1 V steps, the 1 V harmonics' crests) a share (20-50 %) of what is left drains and drips off. Once the film is
    gone the membrane dries towards its loss in the room's air (l_inf 10-25 %, 1 - exp(-u/tau), tau 300-1200 s, log):
    nothing for the first records, then a drying that starts the earlier the more large excursions there were. The gain
    as the water, the conductance as its 1.5-2.5th power, the spectra at the next series' start (inject_fresh9._dry_by).
    Measured (s001_125): wetted 12 s before, the film alone lasting 0.40 session, 29 % of it running off at each
    excursion past 0.47 of the largest bend (the 1 V step and the 1 V harmonic of each block), l_inf 11 %, tau 800 s,
    the conductance's power 1.93: the film gone 850 s in (0.21 session; 1600 s without the excursions); displacement RMS
    -5.8 % (residual 7.4 %, 230x its noise), current -12 % (41x); the 1 V steps' peaks as they were in the first block,
    -3.2, -9.4, -10.9 % in the next three, their plateaus' current -6.1, -17, -20 %; the spectra's |Z| +0, +5.9, +21,
    +25 %."""
    lead, life = s.rng.uniform(0.0, 300.0), s.rng.uniform(0.3, 0.8) * (s.t1 - s.t0)
    shed, frac = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.3, 0.6)
    l_inf, tau, gc = s.rng.uniform(0.1, 0.25), lu(s.rng, 300.0, 1200.0), s.rng.uniform(1.5, 2.5)
    film, t_dry, t_prev = 1.0, s.t1 + 1e6, s.t0 - lead
    for tj in _tilts(s, frac) + [s.t1 + 1e6]:
        end = t_prev + film * life  # when the film would be gone by evaporation alone
        if end <= tj:
            t_dry = end
            break
        film = (film - (tj - t_prev) / life) * (1 - shed)
        t_prev = tj

    def loss(t: np.ndarray) -> np.ndarray:
        return l_inf * -np.expm1(-np.clip(np.asarray(t, float) - t_dry, 0, None) / tau)

    _dry_by(s, loss, lambda t: 1 - (1 - loss(t)) ** gc)


def dh_silica_gel(s: Session) -> None:
    """A strip in air in a closed box (a draught shield, a cuvette's lid) in which a silica-gel sachet was left (from
    the laser's or the strip's packaging), partly used (its water in equilibrium with 25-35 % RH): closed 0-600 s before
    the first record, the box's air leaks to the room (35-50 % RH) at 1-4 changes an hour while the gel takes water from
    it far faster (5-20 an hour), so the box's humidity falls within minutes to near the gel's and comes back only as
    the gel fills (its capacity such that it takes 0.5-2 sessions). The strip's water follows Nafion's isotherm
    (inject_fresh10._lambda) through its sorption lag (100-400 s, log, re-wetting 1.5-3x slower,
    inject_fresh14._lagged): a loss that deepens over the first blocks and is given back slowly. The gain as the water,
    the conductance as its 1.5-2.5th power, the spectra at the next series' start (inject_fresh9._dry_by). Measured
    (s001_125): the room at 37 % RH, the gel at 30 %, 3.6 air changes an hour and the gel's 8.4, the gel full in 1.8
    sessions, the box closed 323 s before; the sorption lag 121 s (re-wetting 2.9x slower), the conductance's power
    2.49: the box's humidity down to 32.9 % 630 s in, 34.2 % by the end, the strip's water down 4.3 % at 790 s and 3.1 %
    by the end; displacement RMS -3.5 % (residual 3.6 %, 110x its noise), current -9.0 % (24x); the 1 V steps' peaks
    -2.6, -4.3, -3.8, -3.4 % block by block, their plateaus' current -6.4, -10.3, -9.3, -8.1 %; the spectra's |Z| +6.3,
    +11.5, +10.2, +8.9 %."""
    rh_room, q = s.rng.uniform(0.35, 0.5), s.rng.uniform(0.25, 0.35)
    n_air, g_gel = s.rng.uniform(1.0, 4.0) / 3600.0, s.rng.uniform(5.0, 20.0) / 3600.0
    fill, lead = s.rng.uniform(0.5, 2.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)
    tau_s, slow, gc = lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 3.0), s.rng.uniform(1.5, 2.5)
    cap = fill * n_air * g_gel / (n_air + g_gel)  # the gel's capacity over the box air's, per unit of RH
    tg = _session_grid(s, 1.0, lead)
    rh, x = np.empty(tg.size), rh_room
    for k in range(tg.size):
        x, q = x + n_air * (rh_room - x) - g_gel * (x - q), q + g_gel / cap * (x - q)
        rh[k] = x
    water = _lagged(tg, _lambda(rh), tau_s, tau_s * slow) / float(_lambda(np.array([rh_room]))[0])
    _dry_by(s, lambda t: 1 - np.interp(t, tg, water), lambda t: 1 - np.interp(t, tg, water) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_binder_swelling(s: Session) -> None:
    """Electrodes made by direct assembly (platinum black in a Nafion ionomer ink painted on and hot-pressed): they
    conduct through the particles' contacts, a network near its percolation threshold, and stretching a face towards the
    threshold e_c raises its resistance as (1 - e/e_c)^(-1.3) (the 2-D percolation exponent). In the bath the binder
    keeps swelling after the mounting (from 0-600 s before the first record, 1 - exp(-u/tau), tau 0.3-1 session),
    spreading the particles, so the threshold comes down, e_c = e_c0 (1 - delta (1 - exp(-u/tau))) (e_c0 1.8-3 times the
    session's largest bend, delta 0.2-0.4): the same bend opens more of the network later in the session. Both faces
    alike (either face in tension), the excess over the rest only; gains fall by 0.02-0.06 (displacement) and 0.05-0.15
    (current) per unit of dR/R (inject_fresh3._resist). Measured (paper_124): e_c0 10.6 scales (2.5 times the largest
    bend's 4.24), delta 0.39, tau 0.83 session from 550 s before the first record, 0.056 and 0.148 per unit:
    displacement RMS -4.5 % (residual 5.0 %, 305x its noise), current residual 3.3 % (2.5x); the 1 V steps' peaks -5.9,
    -7.2, -8.7, -10.0 % block by block, their plateaus' current -15, -18, -22, -25 %; the 1 V harmonics -1.6 to -2.2 %,
    the 0.5 V sines within 0.01 %."""
    ec0, delta = s.rng.uniform(1.8, 3.0) * _largest(s) / ref_disp(s), s.rng.uniform(0.2, 0.4)
    tau, lead = s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        ec = ec0 * (1 - delta * -np.expm1(-(r.cols["t_s"] - s.t0 + lead) / tau))
        return (1 - np.clip(np.abs(e) / ec, 0, 0.9)) ** -1.3 - 1

    _resist(s, shape, (0.02, 0.06), (0.05, 0.15))


def sr_through_crack(s: Session) -> None:
    """A crack right across one face's electrode at x_c (0.2-0.5 L; the strip bent hard there once), the face the
    positive drive stretches or the other (drawn): closed, it conducts like the film; opened by the face's tension
    beyond e_0 (0.2-0.5 of the displacement scale) its bridges part and the outer (1 - x_c) of that face is fed only
    through them, a resistance growing as exp((e - e_0)/w) - 1 (w 0.1-0.3 scales): the outer part charges through it
    with the time constant tau_1 (exp((e - e_0)/w) - 1) (tau_1 0.02-0.1 s, capped at 1-4 s). The outer part's own
    voltage u lags the drive while the crack is open and catches up at once when it closes: the bend loses the outer
    part's share (1 - x_c)^2 of v - u (its curvature's lever), the current its share (1 - x_c) (its area), both through
    the strip's measured step responses; a one-sided, dynamic loss on the large bends that way only. Sample by sample
    through the session in time order; displacement and current. Measured (p23_126): the crack at 0.39 L in the face
    the positive drive stretches, e_0 0.49, w 0.26, tau_1 0.083 s capped at 1.65 s: displacement residual 3.5 % of its
    RMS (125x its noise), current 9.3 % (6.8x); the 1 V harmonics' gain 0.99 with 5.8 deg of lag, their current's 0.99
    with 8.7 deg; the 1 V steps' peaks as they were (the outer part catches up within seconds), +0.28 mm left 2 s after
    their falls (it discharges through the open crack); the 0.5 V sines within 0.2 %."""
    sg, xc = _sign(s), s.rng.uniform(0.2, 0.5)
    e0, wd = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.1, 0.3)
    tau1, tau_max = s.rng.uniform(0.02, 0.1), s.rng.uniform(1.0, 4.0)
    ref, u, e = ref_disp(s), 0.0, {}
    for r in _chrono(s):
        v = r.cols["v_V"].tolist()
        ten = (sg * r.cols["disp_m"] / ref).tolist()
        dt, out = 1.0 / r.fs, np.empty(len(v))
        for k, (vk, ek) in enumerate(zip(v, ten)):
            if ek <= e0:
                u = vk
            else:
                tau = min(tau1 * math.expm1((ek - e0) / wd), tau_max)
                u = vk + (u - vk) * math.exp(-dt / tau) if tau > 0 else vk
            out[k] = u - vk
        e[id(r)] = out
    _superpose(s, e, {"disp_m": (1 - xc) ** 2, "i_A": 1 - xc})


# ------------------------------------------------------------------------------------------------ large deflection


def ld_shadow_vane(s: Session) -> None:
    """No laser: an OSEM-type shadow sensor (a LED's collimated beam onto a photodiode, half cut by a thin vane of
    black shim glued at the tip, the vane's edge across the beam): the light passed goes as the Gaussian beam's share
    beyond the edge, (1/2) erfc(sqrt(2) (Y - y_0)/w), w the beam's 1/e^2 radius sized so that the session's largest
    bend spans 0.25-0.45 of it, the edge centred at rest within +-0.1 w (y_0, drawn), the vane's height Y on the exact
    arc of the tip. Calibrated by its slope at rest: linear in the middle, compressed as erf towards the beam's edges, a
    little asymmetric with the centring. Displacement only. Measured (paper_124): the beam's radius 23.7 mm (the
    largest bend 0.37 of it), the edge 1.7 mm off its centre at rest: displacement RMS -9.3 % (residual 10 %, 610x its
    noise); the 1 V steps' peaks -15.0 %, -9.9 % 2 s after their falls, the 1 V harmonics' gain 0.96, the 0.5 V sines
    within 0.01 %."""
    L, big = float(s.specimen["length_m"]), _largest(s)
    w = big / s.rng.uniform(0.25, 0.45)
    y0 = s.rng.uniform(-0.1, 0.1) * w
    slope = 2 / math.sqrt(math.pi) * math.sqrt(2) / w * math.exp(-2 * (y0 / w) ** 2)
    f0 = math.erf(-math.sqrt(2) * y0 / w)
    map_disp(s, lambda r, d: (special.erf(math.sqrt(2) * (_arc(d, L)[0] - y0) / w) - f0) / slope)


def ld_fisheye_camera(s: Session) -> None:
    """Video tracking with a wide-angle camera (an action camera, a phone's ultra-wide lens) close to the strip: its
    lens maps the angle off its axis to the image equidistantly, r = f theta, so a point at lateral offset rho and
    depth D images at f atan(rho/D); the camera D (2-5 times the session's largest bend) from the tip, its axis off the
    tip's rest by y_c (0-0.3 of the largest bend, either side), calibrated by a small move at rest. The tip on the exact
    arc moves sideways by Y and draws back by B, seen at atan(sqrt(B^2 + (Y - y_c)^2)/D) along its direction: a reading
    compressed as atan, more on the side away from the axis. Displacement only. Measured (p23_126): the camera 10.6 mm
    from the tip (2.0 largest bends), its axis 1.18 mm off the tip's rest towards the negative side: displacement RMS
    -8.0 % (residual 8.6 %, 310x its noise); the 1 V steps' peaks -12.6 %, -8.3 % 2 s after their falls; the 1 V
    harmonics' gain 0.964; the 0.5 V sines within 0.02 %."""
    L, big = float(s.specimen["length_m"]), _largest(s)
    D, yc = s.rng.uniform(2.0, 5.0) * big, _sign(s) * s.rng.uniform(0.0, 0.3) * big
    slope = (1 / D) / (1 + (yc / D) ** 2)
    img0 = math.atan(-yc / D)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        Y, B = _arc(d, L)
        dy = Y - yc
        rho = np.hypot(B, dy)
        img = np.where(rho > 0, np.arctan(rho / D) * dy / np.where(rho > 0, rho, 1.0), 0.0)
        return (img - img0) / slope

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_transformer_load(s: Session) -> None:
    """The drive amplifier's mains transformer on the bench beside the laser's and the current amplifier's cables: its
    stray field has a magnetising part, always there and distorted by the core's saturation (3rd 0.3-0.6 of it, 5th
    0.1-0.3), and a load part that follows the current its secondary delivers, the amplifier's output current abs(i)
    smoothed by its reservoir capacitors' recharge (20-100 ms, log) and drawn in the rectifier's pulses (3rd 0.5-0.8,
    5th 0.2-0.5): at the session's heaviest load 3-8 times the magnetising part. 50 or 60 Hz, phase locked to the
    session clock; 0.3-1.5 um and 1.5-6 uA of magnetising pickup (log): a hum that swells at the steps' edges and
    plateaus and on the fast sines' currents. Displacement and current. Measured (p23_126): 50.01 Hz, the magnetising
    part's 1.5 um and 2.5 uA with its 3rd 0.50 and 5th 0.11, the load's part 7.1 times it at the heaviest load (3rd
    0.72, 5th 0.44), its envelope over 29 ms: the hum 4.6 um peak to peak at rest, 6.8 um on the steps' plateaus, 41 um
    at their edges, 34 um on the 20 Hz sines; displacement residual 0.16 % of its RMS (5.8x its noise), current 0.17 %
    (0.13x)."""
    f0, ph, phl = _line_f(s), s.rng.uniform(0, 2 * np.pi), s.rng.uniform(-0.5, 0.5)
    a3, a5, b3, b5 = (s.rng.uniform(0.3, 0.6), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.5, 0.8),
                      s.rng.uniform(0.2, 0.5))
    ad, ai = lu(s.rng, 3e-7, 1.5e-6), lu(s.rng, 1.5e-6, 6e-6)
    load, tau_l = s.rng.uniform(3.0, 8.0), lu(s.rng, 0.02, 0.1)
    env = {id(r): _lag_state(np.abs(r.cols["i_A"]), r.fs, tau_l, abs(float(r.cols["i_A"][0]))) for r in s.series()}
    top = max(float(np.max(x)) for x in env.values()) or 1.0
    for r in s.series():
        t = r.cols["t_s"]
        hum = _hum(t, f0, {3: a3, 5: a5}, ph) + load * env[id(r)] / top * _hum(t, f0, {3: b3, 5: b5}, ph + phl)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * hum
        r.cols["i_A"] = r.cols["i_A"] + ai * hum


def mp_office_harmonics(s: Session) -> None:
    """Pickup from the building's wiring behind the bench, capacitive (so it follows the supply's voltage waveform,
    each harmonic weighted by its order), whose distortion follows the building's load: as the offices' computers and
    LED lights come on in the morning (or go off in the evening, drawn) their rectifiers flatten the voltage's top,
    and its 3rd, 5th and 7th harmonics grow (in the pickup from 0.05-0.15, 0.05-0.15, 0.02-0.08 of the line to 0.2-0.5,
    0.25-0.6, 0.1-0.3) along a logistic in the session's time (its middle 20-80 % in, its width 5-20 % of the session),
    the line itself steady. 50 or 60 Hz, phase locked to the session clock; 1-4 um and 2-8 uA at the line (log), the
    harmonics' phases their own. Displacement and current. Measured (s001_125): 49.98 Hz, 1.2 um and 6.9 uA at the
    line, an evening: the 3rd from 0.32 to 0.13, the 5th from 0.36 to 0.06, the 7th from 0.21 to 0.03, 62 % into the
    session over 7 % of it; displacement residual 0.05 % of its RMS (1.6x its noise), current 0.19 % (0.50x)."""
    f0, ph = _line_f(s), s.rng.uniform(0, 2 * np.pi, 2)
    lo = np.array([s.rng.uniform(0.05, 0.15), s.rng.uniform(0.05, 0.15), s.rng.uniform(0.02, 0.08)])
    hi = np.array([s.rng.uniform(0.2, 0.5), s.rng.uniform(0.25, 0.6), s.rng.uniform(0.1, 0.3)])
    pn = s.rng.uniform(0, 2 * np.pi, 3)
    mid, width, rising = s.rng.uniform(0.2, 0.8), s.rng.uniform(0.05, 0.2), bool(s.rng.random() < 0.5)
    ad, ai = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 2e-6, 8e-6)
    for r in s.series():
        t = r.cols["t_s"]
        g = _logistic(((t - s.t0) / (s.t1 - s.t0) - mid) / width)
        g = g if rising else 1 - g
        for col, amp, p in (("disp_m", ad, ph[0]), ("i_A", ai, ph[1])):
            wave = np.cos(2 * np.pi * f0 * t + p)
            for (n, a, b), q in zip(((3, lo[0], hi[0]), (5, lo[1], hi[1]), (7, lo[2], hi[2])), pn):
                wave += (a + (b - a) * g) * np.cos(n * (2 * np.pi * f0 * t + p) + q)
            r.cols[col] = r.cols[col] + amp * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_probe_remanence(s: Session) -> None:
    """The current read by a clamp-on Hall-effect current probe (no shunt in the drive line) instead of the current
    amplifier: the probe's magnetic core keeps a remanence after large currents, an offset that follows the current's
    excursions as a play of radius r (0.1-0.3 of the session's largest current: the core's coercivity) times k_r
    (1-4 %): beyond the play's band the reading's gain rises by k_r, and each large excursion leaves an offset up to
    k_r r of its sign (the steps' charging spikes, up and then down). The operator degausses the probe at each
    re-clamping: the core at rest at each block's first record. Sample by sample through the session in time order;
    the current only (the spectra from the analyser's own sense). Measured: (paper_124) r 7.7 mA (0.27 of the steps'
    28 mA charging spikes), k_r 2.6 %: +0.21 mA on the 1 V steps' plateaus (0.58-0.62 mA clean), -0.20 mA at the start
    of the harmonic after each step, shrinking to -0.08 mA with its swings; current residual 4.6 % of its RMS (3.5x its
    noise); (p23_126) r 6.5 mA, k_r 1.6 %: +0.11 mA on the plateaus, -0.11 to -0.04 mA after them; 2.6 % (1.9x)."""
    ri, kr = s.rng.uniform(0.1, 0.3) * _largest(s, "i_A"), s.rng.uniform(0.01, 0.04)
    block, state, at = _block_of(s), 0.0, None
    for r in _chrono(s):
        b = float(block(r.cols["t_s"][:1])[0])
        if b != at:
            state, at = 0.0, b
        i = r.cols["i_A"]
        out = np.empty(i.size)
        for k, x in enumerate(i.tolist()):
            state = min(max(state, x - ri), x + ri)
            out[k] = state
        r.cols["i_A"] = i + kr * out


def out_eis_bias_left(s: Session) -> None:
    """The impedance analyser's DC bias left at V_b (0.1-0.3 V, either sign) from another experiment: through each
    spectrum's sweep (minutes) the strip sits charged at V_b, and when the relay hands it back to the DAQ at the start
    of the next time series (each block's first record, its step) the drive's 0 V discharges it: a bend V_b (S_d(end) -
    S_d(t)) relaxing from the bias' and a current -V_b S_i(t) from the record's first sample, S the strip's measured
    unit-step responses at that pressure (inject_fresh3._step_responses of the pressure's first step, held at their
    last values), nothing in the recorded drive. The spectra as they were (the strip's small-signal impedance taken
    the same at V_b). Displacement and current. Measured: (paper_124) V_b +0.23 V: each block's step record starting
    2.0 mm up (1.7 mm at its rise, 1 s in), its current -6.4 mA in the first sample, -1.0 mA at 0.5 s; displacement
    residual 9.8 % of its RMS (595x its noise), current 3.8 % (2.9x); (s001_125) -0.28 V: -1.3 mm, +5.0 mA; 12 %
    (366x), 6.5 % (17x)."""
    vb = _sign(s) * s.rng.uniform(0.1, 0.3)
    steps = {}
    for r in reversed(_chrono(s)):
        if r.kind == "step":
            si, sd, _, _ = _step_responses(r)
            steps[float(r.entry["pressure_kPa"])] = (np.arange(si.size) / r.fs, si, sd)
    for k, r in enumerate(s.recs):
        if r.series:
            continue
        nxt = next((q for q in s.recs[k + 1:] if q.series), None)
        if nxt is None or float(nxt.entry["pressure_kPa"]) not in steps:
            continue
        ts, si, sd = steps[float(nxt.entry["pressure_kPa"])]
        tt = np.arange(nxt.cols["t_s"].size) / nxt.fs
        nxt.cols["disp_m"] = nxt.cols["disp_m"] + vb * (sd[-1] - np.interp(tt, ts, sd))
        nxt.cols["i_A"] = nxt.cols["i_A"] - vb * np.interp(tt, ts, si)


def out_ao_staircase(s: Session) -> None:
    """The drive's output task on a timing engine of its own at a fixed update rate f_ao (200, 250, 400 or 500 Hz,
    drawn), whatever the record's input rate, while the logger stores the command on the input's clock as v_V: the strip
    feels the command held from each update to the next (a staircase, the updates' phase drawn per record), late by
    half an update on average and jumping at every update. Its difference from the logged command reaches the current
    and the displacement through the strip's measured step responses (inject_fresh7._superpose): a comb of charging
    spikes at the update rate in the current on the fast sines, a step edge late by up to one update. Displacement and
    current. Measured: (paper_124) 500 Hz: the 20 Hz sines' (1 kHz) current 7-10 deg late with a comb at 500 Hz, their
    displacement 3-11 deg; current residual 10 % of its RMS (7.8x its noise), displacement 0.03 % (1.6x); (s001_125)
    200 Hz: the 20 Hz sines 18-21 deg late; 21 % (56x), 0.11 % (3.3x)."""
    f_ao = float(s.rng.choice([200.0, 250.0, 400.0, 500.0]))
    e = {}
    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        up = t[0] + (s.rng.uniform(0.0, 1.0) + np.arange(int((t[-1] - t[0]) * f_ao) + 2)) / f_ao
        idx = np.searchsorted(up, t, side="right") - 1
        held = np.where(idx >= 0, np.interp(up[np.clip(idx, 0, None)], t, v), v[0])
        e[id(r)] = held - v
    _superpose(s, e)


def out_soft_start(s: Session) -> None:
    """The drive amplifier (a small audio power chip used DC-coupled) unmuted by the logger at each record's arming,
    0-50 ms after its first sample, through its soft-start: its gain ramps up as 1 - exp(-u/tau_s) (tau_s 0.2-1.5 s,
    log), while the logged v_V is the command. The strip feels v g(u): each record's first second or so driven short,
    the steps' edges (about a second in) at a fraction of their height and creeping up, the sines' first cycles small.
    The difference reaches the current and the displacement through the strip's measured step responses
    (inject_fresh7._superpose). Displacement and current. Measured: (s001_125) tau_s 1.09 s, 43 ms: current residual 30
    % of its RMS (81x its noise), displacement 2.9 % (90x); the 1 V steps' peaks -0.7 %, the 20 Hz sines' gain 0.92
    (current 0.93); (p23_126) 0.60 s, 22 ms: 24 % (17x), 1.4 % (49x), the 20 Hz sines' gain 0.83-0.85."""
    tau_s, lag = lu(s.rng, 0.2, 1.5), s.rng.uniform(0.0, 0.05)
    e = {}
    for r in s.series():
        u = r.cols["t_s"] - r.cols["t_s"][0]
        e[id(r)] = -r.cols["v_V"] * np.exp(-np.clip(u - lag, 0, None) / tau_s)
    _superpose(s, e)


FRESH18_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"tapered_thickness": br_tapered_thickness, "cathodic_scale": br_cathodic_scale},
    "faradaic_current": {"detergent_film": far_detergent_film, "thermostat_bath": far_thermostat_bath},
    "hysteresis": {"pedot_coating": hy_pedot_coating, "gel_phantom": hy_gel_phantom},
    "time_delay": {"elliptic_antialias": td_elliptic_antialias, "bubble_exposure": td_bubble_exposure},
    "sensor_offset": {"quadratic_heads": so_quadratic_heads, "printed_bracket": so_printed_bracket},
    "clamp_relaxation": {"belleville_stack": cr_belleville_stack, "vacuum_diaphragm": cr_vacuum_diaphragm},
    "dehydration": {"film_shedding": dh_film_shedding, "silica_gel": dh_silica_gel},
    "strain_resistance": {"binder_swelling": sr_binder_swelling, "through_crack": sr_through_crack},
    "large_deflection": {"shadow_vane": ld_shadow_vane, "fisheye_camera": ld_fisheye_camera},
    "mains_pickup": {"transformer_load": mp_transformer_load, "office_harmonics": mp_office_harmonics},
    "unexplained": {"probe_remanence": out_probe_remanence, "eis_bias_left": out_eis_bias_left,
                    "ao_staircase": out_ao_staircase, "soft_start": out_soft_start},
}
inject.register_forms(FRESH18_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_cycle_averaged(s: Session) -> None:
    """A frequency-response logger (a signal analyser's time-synchronous averaging, or the lab's FRA-style script)
    that stores each stepped sine as its averaged period: the measured cycles (after the record's settle_cycles, its
    ``cycles`` of them) cut at the drive's period from the record's own samples (round(fs/f) samples each, every cycle
    started at the nearest sample) and averaged sample by sample, stamped with the first measured cycle's times; the
    manifest then says settle_cycles 0 and cycles 1. What is not locked to the drive (noise, hum, a drift within the
    record) averages down; the harmonics, the steps, the spectra and the rest of the manifest as they were.
    ``labrig import`` takes it (each record a period of rows, t_s increasing, the session clock kept)."""
    for r in s.series():
        f = r.entry.get("frequency_Hz")
        if r.kind != "stepped_sine" or not f:
            continue
        t = r.cols["t_s"]
        P = r.fs / float(f)
        whole = math.floor((float(t[-1]) - float(t[0])) * float(f) + 0.01)
        settle = float(r.entry.get("settle_cycles", round(whole / 3)))
        cycles = int(r.entry.get("cycles") or max(whole - settle, 1))
        n = int(round(P))
        starts = [a for a in (int(round((settle + j) * P)) for j in range(cycles)) if a + n <= t.size]
        if not starts:
            continue
        a0 = starts[0]
        r.cols = {k: (x[a0 : a0 + n].copy() if k == "t_s" else np.mean([x[a : a + n] for a in starts], axis=0))
                  for k, x in r.cols.items()}
        r.entry = {**r.entry, "settle_cycles": 0.0, "cycles": 1.0}


inject.VARIANTS.update({"cycle_averaged": v_cycle_averaged})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_124", "s001_125", "p23_126"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 124-126
    "back_relaxation": [("tapered_thickness", 125, S, "cycle_averaged"), ("cathodic_scale", 124, P, "log_steps")],
    "faradaic_current": [("detergent_film", 124, P, "rate07"), ("thermostat_bath", 126, T, "float32_time")],
    "hysteresis": [("pedot_coating", 125, S, "settled_sines"), ("gel_phantom", 126, T, "tared_records")],
    "time_delay": [("elliptic_antialias", 124, P, "dropped_packets"), ("bubble_exposure", 126, T, "asrun")],
    "sensor_offset": [("quadratic_heads", 125, S, "coherent_sines"), ("printed_bracket", 124, P, "shortened_shuffled")],
    "clamp_relaxation": [("belleville_stack", 124, P, "merged_loadcell"),
                         ("vacuum_diaphragm", 126, T, "trigger_clock")],
    "dehydration": [("film_shedding", 125, S, "host_timed"), ("silica_gel", 125, S, "cycle_averaged")],
    "strain_resistance": [("binder_swelling", 124, P, "steps_sines"), ("through_crack", 126, T, "two_pressures")],
    "large_deflection": [("shadow_vane", 124, P, "resampled"), ("fisheye_camera", 126, T, "short_pretrigger")],
    "mains_pickup": [("office_harmonics", 125, S, "eis_descending"), ("transformer_load", 126, T, "own_clock")],
    "unexplained": [("probe_remanence", 124, P, "decimated3"), ("probe_remanence", 126, T, "no_loadcell"),
                    ("eis_bias_left", 124, P, "asrun"), ("eis_bias_left", 125, S, "swinging_door"),
                    ("ao_staircase", 124, P, "fir_decimated"), ("ao_staircase", 125, S, "cycle_averaged"),
                    ("soft_start", 125, S, "asrun"), ("soft_start", 126, T, "cycle_averaged")],
}
CLEAN = [(124, P, "asrun"), (124, P, "cycle_averaged"), (125, S, "asrun"), (125, S, "no_spectra"),
         (126, T, "asrun"), (126, T, "cycle_averaged")]


def fresh18_cases(only: str | None = None) -> list[Case]:
    """The nineteenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    124-126)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh18_cases, "inject_fresh18", "fresh18")
