"""A fifteenth held-out set for the diagnosis (issue 12), fresh14, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh13.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (a back-flow through a cluster network
that percolates only while swollen, a pre-cracked face whose cracks close under compression, a plate's anticlastic
curl flattening at large bends, a storage crease acting as a hinge, a triangulation head searching a tracking window
that narrows at rest), some on the history (protons from the strip's own electrolysis exchanging into it, platelets
of the cracked electrode multiplying with use), some on time or on the clamp pressure (a warm bath cooling, a laser
window fogging over a warm bath, the clamped root shrinking as it dries, pads swelling with a bath's thermostat, a
humidifier running dry, the lamp lit for each record, a wet surface brightening as it dries, crack lips pinched by the
pad, dendrites pressed together in the clamped root, a floating clamp frame coupling hum through its pads), some from
the lab's wiring or settings (a splashed connector in the drive line, an LDV blended with the triangulation head above
a crossover, a heater on its half-wave setting). Four structures outside the catalogue (truth "unexplained": a
specular glint saturating the laser's receiver at one tip angle, squeeze-film damping by a cuvette wall near the
tip, the laser's UDP packets logged out of order, the drive monitor's divider mis-compensated); clean sessions. All on
three bases of new seeds (112-114: the paper strip, the seed-001 strip on its own sweep, the paper strip 39 mm free)
and on the earlier sets' protocol / data-shape variants plus one new here: a logger that zeroes the laser at each
record's arming (``tared_records``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh13 are reused (importing inject_fresh13 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, std(diff)/sqrt(2) over the 200 samples before each step record's edge, the
median over the steps; the values for the three bases are in docs/effects.md).

Run: python bench/inject_fresh14.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal

import inject
import inject_fresh13  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _drive_side, _spec, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh8 import _hum
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f, _per_record

# the paper's strip 39 mm free (earlier sets used 20, 25, 27, 28, 30, 32, 33, 34, 35, 36, 37, 38, 40, 42 and 45 mm;
# its 1 V step peaks near 14.9 mm, 8.8 mm x (39/30)^2, 14.6 mm measured, inside the laser's +-20 mm): registered in
# every process importing this module
inject.register_free_length("paper_39", 0.039)

inject.BASES.update({
    "paper_112": ("paper-sweep", "paper", 112),
    "s001_113": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 113),
    "p39_114": ("paper-sweep", "paper_39", 114),
})

DISP_LSB = 0.04 / 65536  # the laser's analogue output on the DAQ: +-20 mm over 16 bits
VOLT_LSB = 20.0 / 65536  # the DAQ's +-10 V input range over 16 bits (the drive monitor)


# ------------------------------------------------------------------------------------------------ tools


def _series_cat(s: Session, col: str) -> tuple[np.ndarray, np.ndarray]:
    """The session's times and one column over all series, concatenated in time order."""
    recs = _chrono(s)
    return np.concatenate([r.cols["t_s"] for r in recs]), np.concatenate([r.cols[col] for r in recs])


def _largest(s: Session, col: str = "disp_m") -> float:
    """The session's largest absolute value of a column over all series."""
    return max(float(np.max(np.abs(r.cols[col]))) for r in s.series())


def _lagged(tg: np.ndarray, target: np.ndarray, tau_down: float, tau_up: float | None = None) -> np.ndarray:
    """A first-order lag of ``target`` on the grid ``tg`` (even steps) from its first value; ``tau_up`` (if given) for
    rises, ``tau_down`` for falls (a sorption that dries and re-wets at different speeds)."""
    dt = float(tg[1] - tg[0]) if tg.size > 1 else 1.0
    out, x = np.empty(tg.size), float(target[0])
    for k, y in enumerate(target.tolist()):
        tau = tau_up if (tau_up is not None and y > x) else tau_down
        x += -math.expm1(-dt / tau) * (y - x)
        out[k] = x
    return out


# ------------------------------------------------------------------------------------------------ back relaxation


def br_percolating_clusters(s: Session) -> None:
    """The back-flow runs through the ionic cluster network of the swollen side, which percolates only while that side
    is swollen past a threshold: the water clusters connect into channels once their volume fraction passes the
    percolation point, and the network's conductance then grows as (phi/phi_c - 1)^t (t 1.5-2, the 3-D exponent), with a
    weak background path b 0.02-0.08 (log) below it. The swelling imbalance is the bend the strip shows, y = d - K2 x
    (K2 0.9-1.3), so the store x of water flowing back follows the bend d at the rate (b + A max(abs(y)/y_c - 1, 0)^t) /
    tau0 (tau0 2-8 s, log, at the session's largest bend; y_c 0.3-0.6 of it): a step's bend is pulled back towards the
    threshold and stalls there, the give-back after its fall stops once the reversed bend is below it, and the 0.5 V
    sines (below it) see only the background. Sample by sample through the session in time order (the store carried over
    the rests, the displacement linear across them); displacement only. Measured (paper_112): displacement RMS -38 %
    (residual 73 %, 4400x its noise); the 1 V steps peak at 4.81 mm (8.82 mm clean) and stall at 4.44 mm by the
    plateau's end (y_c 2.9 mm), give back to 2.1 mm 2 s after the fall (6.6 mm clean) and end their records at -1.6 mm
    (+3.1 mm clean): the store trapped below the threshold drains over minutes, an offset the later records start on
    (the 0.5 V sines' swings within 5 %, their residuals dominated by that offset's drift)."""
    k2, tau0, uc = s.rng.uniform(0.9, 1.3), lu(s.rng, 2.0, 8.0), s.rng.uniform(0.3, 0.6)
    tx, b = s.rng.uniform(1.5, 2.0), lu(s.rng, 0.02, 0.08)
    yc = uc * _largest(s)
    amp = 1.0 / (1.0 / uc - 1.0) ** tx  # the percolating part is 1 at the session's largest bend

    def rate(y: float) -> float:
        return (b + amp * max(abs(y) / yc - 1.0, 0.0) ** tx) / tau0

    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 0.5):
        d = r.cols["disp_m"]
        for dt, u in gap:
            target = d_end + u * (float(d[0]) - d_end)
            x += -math.expm1(-dt * rate(target - k2 * x)) * (target - x)
        h = 1.0 / r.fs
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            x += -math.expm1(-h * rate(dk - k2 * x)) * (dk - x)
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


def br_proton_uptake(s: Session) -> None:
    """Protons from the strip's own electrolysis exchange into it: the bath is a sodium (or lithium) salt solution and
    the strip is in that form, but at the large drives the anodic face oxidises water (2 H2O -> O2 + 4 H+ + 4 e-) and
    the protons made in its unstirred layer take sulfonate sites from the sodium; the dilute bath's sodium takes them
    back slowly. The proton share X follows dX/dt = g exp((abs(v) - 1)/b) (1 - X) - X/tau_x (g 0.01-0.03 /s at 1 V, b
    0.08-0.15 V: the 0.5 V sines make next to none; tau_x 2000-6000 s, log), through the session in time order
    (inject_fresh11._walk, decaying over the rests). Protons (Grotthuss, a smaller hydration shell) give a back-flow
    stronger and faster than sodium's: K2 from 0.3-0.5 to 1.0-1.3 and tau from tau_a 10-25 s (log) down 2-4x as X goes
    from 0 to 1 (inject_fresh10._lag_varying). Displacement only. Measured (p39_114): displacement RMS -53 % (residual
    81 %, 8400x its noise); K2 0.49 -> 0.89 through the first 1 V step, 0.99-1.04 from the second block on; the 1 V
    steps' peaks -48.0, -56.8, -58.9, -59.1 % block by block (14.6 mm clean), their plateaus' ends 6.1, 4.3, 3.9, 3.8
    mm, their records' ends -0.9 to -1.8 mm (+5.3 mm clean)."""
    ka, kb = s.rng.uniform(0.3, 0.5), s.rng.uniform(1.0, 1.3)
    ta, m = lu(s.rng, 10.0, 25.0), s.rng.uniform(2.0, 4.0)
    g, bf, taux = s.rng.uniform(0.01, 0.03), s.rng.uniform(0.08, 0.15), lu(s.rng, 2000.0, 6000.0)

    def step(x: float, v: float, dt: float) -> float:
        k = g * math.exp((abs(v) - 1.0) / bf)
        lam = k + 1.0 / taux
        xi = k / lam
        return xi + (x - xi) * math.exp(-lam * dt)

    share = _walk(s, step, "v_V", 0.0, lambda x, sec: x * math.exp(-sec / taux))
    recs = _chrono(s)
    t = np.concatenate([r.cols["t_s"] for r in recs])
    xs = np.concatenate([share[id(r)] for r in recs])

    def state(tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        p = np.interp(tt, t, xs, left=0.0, right=float(xs[-1]))
        return ka + (kb - ka) * p, ta / (1 + (m - 1) * p)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_crushed_root(s: Session) -> None:
    """Platinum dendrites (grown into the membrane in plating, a known IPMC fault) in the clamped root, pressed towards
    each other by the jaws: where their tips come within nanometres electrons tunnel across the polymer (Simmons' law at
    intermediate voltage, i = G (v + v^3/v_s^2), v_s 0.4-0.8 V), and the gaps close as the pads compress the root, the
    tunnelling's exponential in the gap making the conductance G = G_top exp(-a (1 - (p/p_top)^n)) (a 2-4, n 0.6-0.8:
    the compression's Hertz-like law), 0.1-0.4 mA at 1 V at the top pressure (log) and a tenth or less of that in the
    lowest block. In parallel with the strip, memoryless: the current, and the spectra (the analyser at 0 V bias sees
    the parallel conductance G of the record's block). Measured (paper_112): 0.040, 0.073, 0.117, 0.176 mA added on the
    1 V steps' plateaus block by block, 0.047 mA at the top block's 0.5 V peaks (3.8x less than at 1 V), nothing at
    rest; current residual 1.7 % of its RMS (0.86x its noise), 3.6 % on the top block's 1 V harmonic; the spectra's |Z|
    at 0.1 Hz -0.25 % to -1.15 % block by block."""
    i_top, vs = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.4, 0.8)
    a, n = s.rng.uniform(2.0, 4.0), s.rng.uniform(0.6, 0.8)
    p_top = max(s.pressures())
    g_top = i_top / (1 + 1 / vs**2)  # so that the current at 1 V is i_top at the top pressure

    def cond(p: float) -> float:
        return g_top * math.exp(-a * (1 - (p / p_top) ** n))

    for r in s.recs:
        g = cond(float(r.entry["pressure_kPa"]))
        if r.series:
            v = r.cols["v_V"]
            r.cols["i_A"] = r.cols["i_A"] + g * (v + v**3 / vs**2)
        else:
            z = 1 / (1 / (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) + g)
            r.cols["z_re_ohm"], r.cols["z_im_ohm"] = z.real.copy(), z.imag.copy()


def _bv_series(v: np.ndarray, i0: np.ndarray, vt: float, rf: np.ndarray) -> np.ndarray:
    """The current of a symmetric Butler-Volmer interface (exchange current i0, 2 i0 sinh(u/2v_t)) in series with a
    resistance rf, at the voltage v: the root of i = 2 i0 sinh((v - i rf)/(2 v_t)), by bisection (|i| < |v|/rf)."""
    lo, hi = np.minimum(0.0, v / rf), np.maximum(0.0, v / rf)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        f = mid - 2 * i0 * np.sinh((v - mid * rf) / (2 * vt))
        lo, hi = np.where(f < 0, mid, lo), np.where(f < 0, hi, mid)
    return 0.5 * (lo + hi)


def far_wet_connector(s: Session) -> None:
    """A connector in the drive line splashed when the strip was wetted (a banana pair or a terminal block at the bench,
    between the current amplifier and the strip): a film of tap water bridges its brass pins, and the pins carry an
    electrolysis current, brass being quick (symmetric Butler-Volmer, v_t 0.04-0.08 V, exchange current 1-10 uA, log) in
    series with the film's own ionic resistance (2-8 kOhm, log): a current that grows faster than the voltage up to a
    few hundred millivolts and then ohmically, measured with the strip's. The film dries: its wetted area falls as
    exp(-t/tau_d) (tau_d 0.5-2 sessions, log, from the session's first record), the exchange current with the area and
    the resistance as area^-1.5. The analyser clips onto the clamp's own terminals (the spectra untouched). Current
    only. Measured (s001_113): 0.143 mA added at 1 V on the first block's step, 0.088, 0.054, 0.034 mA on the later ones
    (the film drying), 0.054 mA at the first block's 0.5 V peaks (2.6x less than at 1 V); current residual 1.5 % of its
    RMS (2.8x its noise), 4.8 % on the first step."""
    vt, i0, rf0 = s.rng.uniform(0.04, 0.08), lu(s.rng, 1e-6, 1e-5), lu(s.rng, 2e3, 8e3)
    tau_d = lu(s.rng, 0.5, 2.0) * (s.t1 - s.t0)
    for r in s.series():
        area = np.exp(-np.clip(r.cols["t_s"] - s.t0, 0, None) / tau_d)
        r.cols["i_A"] = r.cols["i_A"] + _bv_series(r.cols["v_V"], i0 * area, vt, rf0 / area**1.5)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_crack_friction(s: Session) -> None:
    """The cracked electrode's platelets multiply with use: each bend extends the mud cracks of the plated film
    (fatigue), and every new platelet is a slider that sticks to its neighbours until its shear passes a threshold (the
    Iwan / Maxwell-slip picture of a cracked electrode's dry friction). Five elasto-slide elements in the bending (radii
    0.02-0.3 of the displacement scale, log-spread, times 0.7-1.3), the reading d - w mean(d - x_i) with each slider x_i
    within r_i of the bend (a play), their share w growing with the path bent so far P (the running sum of abs(dd)
    through the session), w = w0 + (w_max - w0)(1 - exp(-P/P_c)) (w0 0-0.05, w_max 0.2-0.4, P_c 0.1-0.3 of the session's
    whole path): loops that widen through the session and a remanence after each large step. Sample by sample through
    the session in time order (the sliders held over the rests); displacement only. Measured (p39_114): displacement
    residual 1.1 % of its RMS (117x its noise); the 0.5 V sine's swing at 0.1 Hz -2.8, -5.0, -6.0, -6.3 % block by
    block, at 1.4 Hz -8.3 to -12.8 %, at 20 Hz -14 to -21 %; the 1 V steps' peaks -0.2 to -0.7 % with +31, +74, +92,
    +100 um left at their records' ends."""
    ref = ref_disp(s)
    radii = np.geomspace(0.02, 0.3, 5) * ref * s.rng.uniform(0.7, 1.3)
    w0, wmax, share = s.rng.uniform(0.0, 0.05), s.rng.uniform(0.2, 0.4), s.rng.uniform(0.1, 0.3)
    recs = _chrono(s)
    whole = sum(float(np.sum(np.abs(np.diff(r.cols["disp_m"])))) for r in recs)
    pc = max(share * whole, 1e-12)
    rad = radii.tolist()
    sl, path, last, nsl = [0.0] * len(rad), 0.0, None, len(rad)
    for r in recs:
        d = r.cols["disp_m"]
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            if last is not None:
                path += abs(dk - last)
            last = dk
            acc = 0.0
            for i in range(nsl):
                x = min(max(sl[i], dk - rad[i]), dk + rad[i])
                sl[i] = x
                acc += x
            w = w0 + (wmax - w0) * -math.expm1(-path / pc)
            out[k] = dk - w * (dk - acc / nsl)
        r.cols["disp_m"] = out


def hy_cooling_friction(s: Session) -> None:
    """A warm bath cooling through the session (filled from a warm tap or a heated reservoir at 35-45 C, 0-300 s before
    the first record, cooling towards the room's 21-24 C with tau 1200-3600 s, log), and the pinned cations' friction is
    thermally activated: the play of the coupling (a share h 0.2-0.4 of the drive moving only once the drive has turned
    by r) has the radius r(T) = r_room exp(E/R (1/T - 1/T_room)) (r_room 0.15-0.3 V, E 20-40 kJ/mol): half as wide or
    less at the start, at its full width by the session's end. Gamma = (1 - h) v + h play_r(t)(v) through the strip's
    measured step response (inject_fresh2._drive_side), the play from rest at each record's start (the pinned ions
    redistribute over the rest at 0 V before it); current untouched. Measured (paper_112): displacement RMS -3.1 %
    (residual 6.9 %, 420x its noise); the bath from 44.3 C (tau 3060 s): the 1 V steps' peaks -4.8, -6.1, -7.0, -7.7 %
    block by block, the 0.5 V sine's swing at 0.1 Hz -7.9, -10.8, -13.0, -14.7 %, at 1.4 Hz -9.7 to -15.7 %; the 1 V
    harmonics' residuals 6-9 %."""
    t_hot, t_room = s.rng.uniform(35.0, 45.0), s.rng.uniform(21.0, 24.0)
    tau_c, lead = lu(s.rng, 1200.0, 3600.0), s.rng.uniform(0.0, 300.0)
    ea, r_room, h = s.rng.uniform(20e3, 40e3), s.rng.uniform(0.15, 0.3), s.rng.uniform(0.2, 0.4)
    t, _ = _series_cat(s, "v_V")
    temp = t_room + (t_hot - t_room) * np.exp(-np.clip(t - s.t0 + lead, 0, None) / tau_c)
    radius = r_room * np.exp(ea / 8.314 * (1 / (temp + 273.15) - 1 / (t_room + 273.15)))
    starts = set(np.cumsum([0] + [r.cols["v_V"].size for r in _chrono(s)])[:-1].tolist())

    def gamma(v: np.ndarray) -> np.ndarray:
        y, prev = np.empty(v.size), 0.0
        for k, (u, rr) in enumerate(zip(v.tolist(), radius.tolist())):
            if k in starts:
                prev = 0.0  # the pinned ions redistribute over the rest at 0 V before each record
            prev = min(max(prev, u - rr), u + rr)
            y[k] = prev
        return (1 - h) * v + h * y

    _drive_side(s, gamma)


# ------------------------------------------------------------------------------------------------ time delay


def td_window_search(s: Session) -> None:
    """A triangulation head that tracks its spot on the receiver's line inside a search window around the last peak (to
    reject stray reflections from the bath): it narrows the window while the spot is still (halving it over tau_m 0.5-3
    s, log, down to a width the spot leaves at 1.5-4 mm/s of tip speed, log) and opens it to the whole line when the
    spot escapes, after a full-line search that takes n_s 4-12 frames with its output held. Frames every T_f 0.5-1 ms
    (log) with a processing latency of 2-4 frames, the analogue output held between frames. A delay of a few ms
    throughout, and a hold of several more at every motion that starts after a rest (a step's edge and fall, the first
    cycle of a fast sine), so the lag at the motion's onset depends on how long the strip was still. Frame by frame from
    each record's start (the window narrow after the rest before it), the record's displacement linear between its
    samples; displacement only. Measured (p39_114): displacement residual 0.042 % of its RMS (4.4x its noise); frames of
    0.63 ms, a latency of 3 frames, searches of 5 frames, the narrowest window left at 1.6 mm/s: a lag of 2.2 ms on
    every sine (the 20 Hz records' residuals 18-19 %, their gain within 0.4 %), holds at the steps' edges and falls
    (errors of 16-18 um where the tip speeds up past the window)."""
    tf, nl, ns = lu(s.rng, 5e-4, 1e-3), int(s.rng.integers(2, 5)), int(s.rng.integers(4, 13))
    w_min, tau_m = lu(s.rng, 1.5e-3, 4e-3) * tf, lu(s.rng, 0.5, 3.0)  # the narrowest window: a speed times a frame
    w_max = 1e-2  # the whole line
    shrink = math.exp(-math.log(2) * tf / tau_m)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        tfr = t[0] + tf * np.arange(int((t[-1] - t[0]) / tf) + 1)
        dfr = np.interp(tfr, t, d).tolist()
        out = np.empty(len(dfr))
        found, w, hold = dfr[0], w_min, 0
        for k, x in enumerate(dfr):
            if hold > 0:
                hold -= 1
                if hold == 0:
                    found, w = x, w_max
            elif abs(x - found) > w:
                hold = ns
            else:
                if abs(x - found) < 0.5 * w:
                    w = max(w * shrink, w_min)
                found = x
            out[k] = found
        shifted = np.r_[np.full(nl, out[0]), out[: out.size - nl]] if out.size > nl else np.full(out.size, out[0])
        k = np.clip(np.searchsorted(tfr, t, side="right") - 1, 0, tfr.size - 1)
        return shifted[k]

    map_disp(s, read)


def td_drying_exposure(s: Session) -> None:
    """A strip in air read by a triangulation head in automatic exposure: the wet plated surface looks dark (the water
    film fills its roughness and scatters little back) and brightens as the film dries off, so the head shortens its
    exposure through the session: t_e from 3-10 ms (log) at the first record to a 1.5-3rd of that by the last, the
    brightening following 1 - exp(-t/tau) (tau 0.3-1 of the session). Each reading is the mean of the spot's position
    over its exposure, output a processing time of 0.5-2 ms (log) after it: a moving average of length t_e(t) ending t_p
    before the stamp, a delay of t_p + t_e/2 with the sinc's droop, shrinking through the session. Per record from its
    first value (held before it); displacement only. Measured (s001_113): displacement residual 0.082 % of its RMS (2.7x
    its noise); exposure 4.9 ms at the start, 2.1x shorter by the end, 0.52 ms processing: the 20 Hz records lag 2.21,
    1.85, 1.70, 1.65 ms block by block (gain 0.990-0.994, residuals 28, 23, 21, 21 %), the steps' edges 11, 8, 7, 7 um
    behind."""
    te0, fall, tp = lu(s.rng, 3e-3, 1e-2), s.rng.uniform(1.5, 3.0), lu(s.rng, 5e-4, 2e-3)
    tau = s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0)
    norm = -math.expm1(-(s.t1 - s.t0) / tau)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        bright = 1 + (fall - 1) * -np.expm1(-np.clip(t - s.t0, 0, None) / tau) / norm
        te = te0 / bright
        cum = np.r_[0.0, np.cumsum(0.5 * (d[1:] + d[:-1]) * np.diff(t))]

        def area(u: np.ndarray) -> np.ndarray:  # the integral of d from t[0], d held at d[0] before the record
            return np.where(u < t[0], d[0] * (u - t[0]), np.interp(u, t, cum))

        return (area(t - tp) - area(t - tp - te)) / te

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_blended_ldv(s: Session) -> None:
    """Two sensors blended by the lab's script: a triangulation head on the tip for the slow part and a laser Doppler
    vibrometer for the fast part (its displacement decoder drifts at low frequency, the triangulation head is noisy at
    high frequency), joined by a complementary second-order crossover at f_c 1-5 Hz (log; LP = 1/(1 + 2 zeta s/w_c +
    (s/w_c)^2), zeta 0.7, and HP = 1 - LP). The vibrometer is aimed inboard at x_v 0.8-0.9 L so that its beam stays on
    the strip as the tip draws back: the reading is LP d + HP w(x_v), w(x_v) through the beam's own transfer functions
    (displacement_tf with sensor_x over the tip's): the slow records read the tip, the fast ones the station, the steps'
    edges a mixture. Through inject_fresh2._through (the session's history before each record); displacement only.
    Measured (p39_114): the vibrometer at 0.84 L, the crossover at 1.2 Hz: displacement residual 0.81 % of its RMS (84x
    its noise); the 0.1 Hz sines' gain 1.00 (phase +1.9 deg), 0.75 at 1.4 Hz (+9.8 deg), 0.89 at 4.4 Hz, 0.28 at 20 Hz
    (residuals 27-41 %); the 1 V steps' peaks -0.1 %."""
    from labrig.physics import transfer

    fa, fc = s.rng.uniform(0.8, 0.9), lu(s.rng, 1.0, 5.0)
    wc, zeta = 2 * np.pi * fc, 0.7

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        sa = sp.with_(sensor_x=fa * sp.geometry.length)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                ratio = transfer.displacement_tf(z, sa) / transfer.displacement_tf(z, sp)
            ratio = np.where(np.isfinite(ratio), ratio, fa**2)
            lp = 1 / (1 + 2 * zeta * z / wc + (z / wc) ** 2)
            return lp + (1 - lp) * ratio

        return h

    out = _through(s, H, min(10.0 / fc, 10.0))
    map_disp(s, lambda r, d: out[id(r)])


def _half_disc_station(r_spot: np.ndarray, centre: float) -> np.ndarray:
    """The quasi-static station of a round spot of radius r_spot centred ``centre`` (in L) inboard of the tip, its part
    beyond the tip lost: sqrt of the chord-weighted mean of (x/L)^2 over the part on the strip (x in L)."""
    u = np.linspace(-1.0, 1.0, 401)
    out = np.empty(r_spot.size)
    for k, rad in enumerate(r_spot.tolist()):
        x = 1.0 - centre + rad * u
        w = np.sqrt(np.clip(1 - u**2, 0, None)) * (x <= 1.0)
        out[k] = math.sqrt(float(np.sum(w * x**2) / np.sum(w)))
    return out


def so_fogging_window(s: Session) -> None:
    """A laser head looking down into a warm open bath (the bath held at 30-40 C): the humid air above it condenses on
    the head's colder window, and the fog scatters the beam into a halo that grows through the session, the spot's
    radius from 0.1-0.3 mm (log) to 1.5-3 mm (log) as 1 - exp(-t/tau) (tau 0.3-1 of the session, the bath filled 0-600 s
    before the first record). The operator aimed the clean spot just inside the tip (its centre r0 inboard), so the
    growing halo falls off the tip's end and what the receiver sees of it lies on the strip, its centroid moving
    inboard: the reading is the strip read at the chord-weighted station of the on-strip part of the disc
    (quasi-statically, the mean of (x/L)^2 over it), through inject_fresh10._station. Displacement only. Measured
    (paper_112): the spot from 0.10 to 2.9 mm (tau 0.34 of the session): displacement RMS -5.3 % (residual 5.8 %, 350x
    its noise); the 1 V steps' peaks -1.5, -5.4, -6.8, -7.6 % block by block, the 0.1 Hz sines' gain 0.974 in the first
    block, 0.926 in the last, the 20 Hz records' 0.90 and 0.82."""
    L = float(s.specimen["length_m"])
    r0, r1 = lu(s.rng, 1e-4, 3e-4), lu(s.rng, 1.5e-3, 3e-3)
    tau, lead = s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)
    tg = _session_grid(s, 5.0)
    rad = r0 + (r1 - r0) * -np.expm1(-(tg - s.t0 + lead) / tau)
    frac = _half_disc_station(rad / L, r0 / L)
    fa = float(frac.min())
    _station(s, lambda r: np.clip(np.interp(r.cols["t_s"], tg, frac), fa, 1.0), fa)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_root_shrinkage(s: Session) -> None:
    """A strip in air clamped under a held jaw gap: the clamped part of the strip dries through the jaws' open edges and
    shrinks in thickness (Nafion loses several % of its thickness as it dries), Fickian from the edges, u(t) = sqrt(1 -
    exp(-t/tau_c)) of its final loss (tau_c 1000-3000 s, log, from the mounting 0-300 s before the first record). The
    pads-and-strip stack was compressed by delta(p) ~ p^n (n 0.7-1) at each setting, and the operator re-sets the force
    at each block (the shrinkage so far taken up): F/F_set = 1 - q (u(t) - u(t_set)) (p_top/p)^n, q 0.02-0.05 the final
    shrinkage over the top setting's compression. The same shrinkage is a larger share of a light setting's compression,
    and the drying slows: a loss that is largest in the first (lightest) block and fades block by block. Through the
    preset's clamp law (inject_fresh4._clamp_law). Measured (s001_113): the load cell at 0.953, 0.991, 0.997, 0.999 of
    its setting by the blocks' ends (-1.18, -0.39, -0.20, -0.10 N); displacement residual 0.0035 % (0.12x its noise),
    current 0.075 % (0.14x), the first block's fast records' up to 0.45 %."""
    tau_c, lead = lu(s.rng, 1000.0, 3000.0), s.rng.uniform(0.0, 300.0)
    q, n = s.rng.uniform(0.02, 0.05), s.rng.uniform(0.7, 1.0)
    p_top = max(s.pressures())

    def u(t: np.ndarray) -> np.ndarray:
        return np.sqrt(-np.expm1(-np.clip(t - s.t0 + lead, 0, None) / tau_c))

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        return 1 - q * (u(t) - u(np.array([t_set]))[0]) * (p_top / p) ** n

    _clamp_law(s, rel)


def _thermostat(t: np.ndarray, period: float, duty: float, phase: float) -> np.ndarray:
    """An on/off thermostat's temperature swing in units of its half-swing: rising from -1 to +1 over the heating share
    ``duty`` of each period, falling back over the rest (a triangle, phase in periods)."""
    u = (t / period + phase) % 1.0
    return np.where(u < duty, -1 + 2 * u / duty, 1 - 2 * (u - duty) / (1 - duty))


def cr_thermostat_pads(s: Session) -> None:
    """Silicone pads under the jaws in a thermostatted bath: the heater's on/off thermostat saws the water's temperature
    by a degree or so (a period of 300-900 s, heating over 30-50 % of it), and silicone expands some 3e-4 per K, so
    under the held jaw gap the pads push harder as the bath warms and less as it cools. The expansion is the same at
    every setting but a larger share of a light setting's compression: the force swings by +-A_low (1.5-4 %, half its
    peak-to-peak) at the lowest pressure and by +-A_low (p_min/p)^n (n 0.6-1) above it, beside the pads' own slow
    relaxation (1 - c log(1 + t/tau), c 0.3-0.8 %, tau 20-100 s, log): F/F_set = (1 - c log(1 + t/tau)) (1 + A(p) (T(t)
    - T(t_set))), T the thermostat's saw in units of its half-swing (from -1 to 1 and back), a force that oscillates
    about a slow fall, the more the lighter the setting. Through the preset's clamp law (inject_fresh4._clamp_law).
    Measured (paper_112): the load cell between 0.97 and 1.05 of its setting in the lowest block (its 9.8 N read at the
    indicator's 0.1 N), falling to 0.96 in the second and swinging 0.975-1.0 and 0.984-1.0 in the upper two;
    displacement residual 0.016 % (1.0x its noise), current 0.15 % (0.08x), the top block's 3-20 Hz records' 3-5 %."""
    per, duty, ph = s.rng.uniform(300.0, 900.0), s.rng.uniform(0.3, 0.5), s.rng.uniform(0.0, 1.0)
    a_low, n = s.rng.uniform(0.015, 0.04), s.rng.uniform(0.6, 1.0)
    c, tau = s.rng.uniform(0.003, 0.008), lu(s.rng, 20.0, 100.0)
    p_min = min(s.pressures())

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        swing = _thermostat(t, per, duty, ph) - _thermostat(np.array([t_set]), per, duty, ph)[0]
        return (1 - c * np.log1p(np.clip(t - t_set, 0, None) / tau)) * (1 + a_low * (p_min / p) ** n * swing)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_humidifier_empty(s: Session) -> None:
    """A strip in air kept wet by an ultrasonic humidifier blowing into its enclosure (70-80 % RH): the humidifier's
    tank runs dry at a moment 25-60 % into the session, after which the enclosure's humidity falls by 3-7 % RH towards
    the room's as its air is exchanged (tau_a 200-800 s, log), and the strip's water follows the isotherm
    (inject_fresh10._lambda) through its sorption lag (tau_s 200-600 s, log). Nothing before that moment, a loss that
    starts inside the session and levels off. The gain as lambda/lambda_0, the conductance as
    (lambda/lambda_0)^(1.5-2.5) (inject_fresh9._dry_by). Measured (s001_113): the tank dry 35 % into the session (in the
    second block): displacement RMS -6.0 % (residual 8.9 %, 300x its noise), current -14 % (35x); the 1 V steps' peaks
    0, 0, -10.6, -14.3 % block by block, the current at their plateaus' ends -21 and -28 % in the last two; the later
    spectra's resistance up 25 and 38 %."""
    a_hi, drop = s.rng.uniform(0.7, 0.8), s.rng.uniform(0.03, 0.07)
    t_e = s.t0 + s.rng.uniform(0.25, 0.6) * (s.t1 - s.t0)
    tau_a, tau_s, gc = lu(s.rng, 200.0, 800.0), lu(s.rng, 200.0, 600.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0)
    rh = a_hi - drop * -np.expm1(-np.clip(tg - t_e, 0, None) / tau_a)
    lam = _lagged(tg, _lambda(rh), tau_s)
    rel = lam / float(lam[0])
    _dry_by(s, lambda t: 1 - np.interp(t, tg, rel), lambda t: 1 - np.interp(t, tg, rel) ** gc)


def dh_record_lamp(s: Session) -> None:
    """A strip in air filmed at every record under a halogen lamp that the logger switches on for the record and off
    after it: the lamp's radiant heat warms the strip's surface by 4-10 K, and the saturation pressure of water rises
    some 6 % per K, so the strip's local humidity falls from the room's 45-60 % to exp(-0.06 dT) of it while lit. The
    strip's water follows the isotherm (inject_fresh10._lambda) towards the lit value while the lamp is on (tau 150-500
    s, log) and back towards the room's in the dark 1.5-3 times more slowly (Nafion dries faster than it takes water
    up): a loss that grows through each long record and partly recovers over the rests, ratcheting down through the
    session. The gain as lambda/lambda_0, the conductance as (lambda/lambda_0)^(1.5-2.5) (inject_fresh9._dry_by).
    Measured (s001_113): a room at 48 % RH, the lamp 8.5 K: displacement RMS -6.2 % (residual 6.6 %, 220x its noise),
    current -22 % (42x); the 1 V steps' peaks -3.2, -7.1, -7.3, -7.8 % block by block (each its block's first record,
    after the dark rest), the 1 V harmonics after them -14, -19, -20, -20 %, the current at the steps' plateaus' ends
    -7, -15, -16, -17 %."""
    a_room, dt_k = s.rng.uniform(0.45, 0.6), s.rng.uniform(4.0, 10.0)
    tau_d, slow, gc = lu(s.rng, 150.0, 500.0), s.rng.uniform(1.5, 3.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 0.5, 600.0)  # from a rest in the dark before the first record
    lit = np.zeros(tg.size, bool)
    for r in s.series():
        lit |= (tg >= r.cols["t_s"][0]) & (tg <= r.cols["t_s"][-1])
    lam0 = float(_lambda(np.array([a_room]))[0])
    lam_lit = float(_lambda(np.array([a_room * math.exp(-0.06 * dt_k)]))[0])
    lam = _lagged(tg, np.where(lit, lam_lit, lam0), tau_d, tau_d * slow)
    rel = lam / lam0
    _dry_by(s, lambda t: 1 - np.interp(t, tg, rel), lambda t: 1 - np.interp(t, tg, rel) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_precracked_face(s: Session) -> None:
    """One face's electrode was cracked before the session (the strip stored dry, or bent hard while it was handled),
    its cracks partly open at rest: stretched, they open further (its resistance up with the tension), compressed, they
    close (down, at a gauge 0.3-0.7 of the tensile one, until they are shut at a compressive bend of 0.3-0.6 of the
    displacement scale); the other face intact, cracking in tension only at 0.1-0.3 of the first's gauge. The strain's
    resistance change is signed: bent to one side the strip's electrodes conduct worse, bent a little to the other side
    better (the closing cracks) and worse again beyond (the intact face's cracks). The face drawn; gains fall by
    0.03-0.08 (displacement) and 0.08-0.2 (current) per unit of the displacement scale (inject_fresh3._resist). Measured
    (s001_113): the pre-cracked face in tension on the troughs' side: displacement residual 1.7 % of its RMS (57x its
    noise), current 1.0 % (1.9x); the 1 V steps' peaks -2.6 % (the intact face's tension beyond the closed cracks), the
    0.5 V sine at 0.1 Hz +0.5 % at its crests (the closing cracks) and -1.9 % at its troughs."""
    side, gcl, ecl, o = _sign(s), s.rng.uniform(0.3, 0.7), s.rng.uniform(0.3, 0.6), s.rng.uniform(0.1, 0.3)

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        x = side * e
        comp = np.clip(-x, 0, None)
        return np.clip(x, 0, None) - gcl * np.minimum(comp, ecl) + o * comp

    _resist(s, shape, (0.03, 0.08), (0.08, 0.2))


def sr_jaw_pinch(s: Session) -> None:
    """The cracks that matter most open in the tensioned film at the jaw's edge, where the bending moment is largest,
    and the pad pressing on the film right up to that edge holds their lips by friction: the harder the clamp, the
    longer the stretch of each crack held shut, and the smaller the resistance the same bend adds. The gauge falls with
    the block's pressure, g(p) = 1 - r ((p - p_min)/(p_max - p_min))^m (r 0.4-0.7, m 0.7-1.3): full at the lightest
    setting, 0.3-0.6 of it at the top. The tensioned face (side drawn) with the other at 0.1-0.3 of its gauge; gains
    fall by 0.04-0.1 (displacement) and 0.1-0.25 (current) per unit of the displacement scale (inject_fresh3._resist).
    Measured (p39_114): displacement RMS -2.0 % (residual 2.2 %, 230x its noise), current residual 1.9 % (1.0x); the 1 V
    steps' peaks -4.4, -3.1, -2.2, -1.5 % block by block, the 1 V harmonics' crests -2.0 to -0.7 %, the current on them
    -2.8 to -1.0 %."""
    side, o, rr, m = _sign(s), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.4, 0.7), s.rng.uniform(0.7, 1.3)
    lo, hi = min(s.pressures()), max(s.pressures())

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        g = 1 - rr * ((float(r.entry["pressure_kPa"]) - lo) / max(hi - lo, 1e-9)) ** m
        x = side * e
        return g * (np.clip(x, 0, None) + o * np.clip(-x, 0, None))

    _resist(s, shape, (0.04, 0.1), (0.1, 0.25))


# ------------------------------------------------------------------------------------------------ large deflection


def _anticlastic_phi(lam: np.ndarray) -> np.ndarray:
    """Ashwell's transition of a bent strip from a beam (lam -> 0: the section free to curl anticlastically) to a plate
    (lam -> inf: the curl suppressed): 1 - (2/lam)(cosh lam - cos lam)/(sinh lam + sin lam), ~ lam^4/180 when small."""
    lam = np.abs(lam)
    small = lam < 0.05
    ls = np.where(small, 1.0, lam)
    full = 1 - (2 / ls) * (np.cosh(ls) - np.cos(ls)) / (np.sinh(ls) + np.sin(ls))
    return np.where(small, lam**4 / 180, full)


def ld_anticlastic(s: Session) -> None:
    """A strip wide against its thickness is a plate: bent along its length it curls anticlastically across its width
    (Poisson's ratio nu 0.35-0.49, wet Nafion near incompressible), but the curl needs the section to warp, and as the
    curvature grows (Searle's parameter b^2 kappa/h) the membrane stresses flatten the section, the strip stiffening
    from EI towards EI/(1 - nu^2) along Ashwell's transition phi(lam), lam = (3 (1 - nu^2))^(1/4) b sqrt(kappa/h): the
    curvature kappa solves kappa (1 + nu^2/(1 - nu^2) phi(lam(kappa))) = 2 d/L^2 (d the linear reading), the reading the
    tip's height on the exact arc of that curvature. A loss that grows as the bend squared at first, on top of the
    arc's, odd in the bend. The width and thickness the manifest's; displacement only. Measured (s001_113): nu 0.37; the
    1 V steps' peaks -3.3 % (the arc alone -1.8 %), the 1 V harmonics' crests -0.8 %, the 0.5 V sines' -0.05 %;
    displacement RMS -1.9 % (residual 2.1 %, 70x its noise)."""
    nu = s.rng.uniform(0.35, 0.49)
    b, h, L = (float(s.specimen[k]) for k in ("width_m", "thickness_m", "length_m"))
    c, beta = nu**2 / (1 - nu**2), (3 * (1 - nu**2)) ** 0.25

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        klin = 2 * d / L**2
        k = klin.copy()
        for _ in range(30):  # kappa = kappa_lin / (1 + c phi): c phi small, a contraction
            k = klin / (1 + c * _anticlastic_phi(beta * b * np.sqrt(np.abs(k) / h)))
        small = np.abs(k * L) < 1e-6
        ks = np.where(small, 1.0, k)
        return np.where(small, k * L**2 / 2, (1 - np.cos(ks * L)) / ks)

    map_disp(s, read)


def ld_crease_hinge(s: Session) -> None:
    """A strip with a crease across its outer half (picked up by its free end with tweezers, or folded there in storage)
    at x_h 0.55-0.8 L: the crease is a soft hinge that takes a share sigma 0.2-0.35 of the tip's linear deflection as a
    rotation there, the rest of the strip bending uniformly, so its outer part turns as a whole by phi_h on top of its
    own curvature. Exactly: the tangent angle theta(s) = kappa s + phi_h H(s - x_h), kappa = (1 - sigma) 2 d/L^2, phi_h
    = sigma d/(L - x_h) (so the linear reading is d), the tip's height the integral of sin(theta): the outer part's
    larger angles compress the large bends more than the uniform arc does. Displacement only. Measured (p39_114): the
    crease at 0.71 L taking 0.21: the 1 V steps' peaks -6.5 % (the arc alone -4.6 %), the 1 V harmonics' crests -1.4 %,
    the 0.5 V sines' -0.07 %; displacement RMS -3.6 % (residual 4.0 %, 420x its noise)."""
    L = float(s.specimen["length_m"])
    xh, sig = s.rng.uniform(0.55, 0.8) * L, s.rng.uniform(0.2, 0.35)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        k = (1 - sig) * 2 * d / L**2
        ph = sig * d / (L - xh)
        small = np.abs(k * L) < 1e-9
        ks = np.where(small, 1.0, k)
        inner = np.where(small, k * xh**2 / 2, (1 - np.cos(ks * xh)) / ks)
        outer = np.where(small, (L - xh) * np.sin(ph) + k * (L**2 - xh**2) / 2 * np.cos(ph),
                         (np.cos(ks * xh + ph) - np.cos(ks * L + ph)) / ks)
        return inner + outer

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_floating_frame(s: Session) -> None:
    """The clamp's metal frame left floating (its earth strap off, or a frame on rubber feet): stray capacitance to the
    bench's mains wiring holds it at a fraction of the line voltage, and it couples to the strip's electrode through the
    pad under its jaw, a capacitor whose dielectric thins as the pad is compressed (by 20-40 % at the top pressure, as
    (p/p_top)^n, n 0.6-1): a hum current into the current amplifier's input that grows block by block with the clamp
    pressure. The line at 50 or 60 Hz with the building's flat-topped voltage (3rd 0.03-0.08, 5th 0.01-0.04), each
    harmonic weighted by its order (the current of a capacitor); 6-20 uA at the lowest pressure (log). The laser is on
    its own ground: the current only. Measured (paper_112): the current's hum 8.9, 9.7, 10.4, 11.5 uA RMS block by block
    (on the 20 Hz records 12 uA at the line, 2.0 uA at its 3rd, 1.4 uA at its 5th); current residual 0.32 % of its RMS
    (0.16x its noise over all)."""
    f0, a0, eps, n = _line_f(s), lu(s.rng, 6e-6, 2e-5), s.rng.uniform(0.2, 0.4), s.rng.uniform(0.6, 1.0)
    h3, h5, ph = s.rng.uniform(0.03, 0.08), s.rng.uniform(0.01, 0.04), s.rng.uniform(0, 2 * np.pi)
    p_min, p_top = min(s.pressures()), max(s.pressures())
    thick = lambda p: 1 - eps * (p / p_top) ** n  # noqa: E731
    for r in s.series():
        amp = a0 * thick(p_min) / thick(float(r.entry["pressure_kPa"]))
        r.cols["i_A"] = r.cols["i_A"] + amp * _hum(r.cols["t_s"], f0, {3: 3 * h3, 5: 5 * h5}, ph)


def _half_wave_dt(t: np.ndarray, f0: float, phase: float, terms: int = 4) -> np.ndarray:
    """The time derivative of a half-wave rectified sine (1/pi + sin(w t)/2 - (2/pi) sum cos(2k w t)/(4k^2 - 1)), over
    w/2: the line with its even harmonics weighted by their order (2nd 0.85, 4th 0.34, 6th 0.22 of the line)."""
    w = 2 * np.pi * f0 * t + phase
    out = np.cos(w)
    for k in range(1, terms + 1):
        out = out + (8 / np.pi) * k * np.sin(2 * k * w) / (4 * k * k - 1)
    return out


def mp_half_wave_heater(s: Session) -> None:
    """A heater on the next bench on its "low" setting, a diode in series halving its power (a soldering station, a hot
    plate, a heating mantle's two-step switch): its load current is a half-wave rectified sine, the line with its even
    harmonics, and its magnetic field couples into the laser's cable and the current amplifier's leads as the current's
    rate of change, so the pickup carries the line (50 or 60 Hz) and its 2nd, 4th and 6th harmonics at 0.85, 0.34 and
    0.22 of it, none of the odd ones a saturated transformer or a rectifier makes. Present while the heater's thermostat
    has it on (a relay: on 40-70 % of a 60-300 s cycle, phase drawn): 1.5-5 um on the displacement and 4-15 uA on the
    current (log, at the line). Measured (p39_114): the heater on 66 % of the time (a 294 s cycle): while on, the
    current's lines 7.2, 6.1, 2.4, 1.6 uA at the line and its 2nd, 4th and 6th harmonics, nothing at the 3rd, the
    displacement's 1.5, 1.3, 0.5, 0.3 um; current residual 0.17 % of its RMS (0.09x its noise), displacement 0.021 %
    (2.2x)."""
    f0, ad, ai = _line_f(s), lu(s.rng, 1.5e-6, 5e-6), lu(s.rng, 4e-6, 1.5e-5)
    per, duty, t_ph = s.rng.uniform(60.0, 300.0), s.rng.uniform(0.4, 0.7), s.rng.uniform(0.0, 1.0)
    pd, pi_ = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        t = r.cols["t_s"]
        on = (((t - s.t0) / per + t_ph) % 1.0) < duty
        r.cols["disp_m"] = r.cols["disp_m"] + on * ad * _half_wave_dt(t, f0, pd)
        r.cols["i_A"] = r.cols["i_A"] + on * ai * _half_wave_dt(t, f0, pi_)


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_specular_glint(s: Session) -> None:
    """A specular glint saturating the laser's receiver: the wet plated strip is glossy, and when its tip's surface
    turns to the angle that sends the beam's mirror reflection into the receiver (half the head's triangulation angle,
    on one side, here 0.4-0.8 of the session's largest tip angle 2 d_max/L) the return floods the receiver's line, its
    saturated peak's centroid biased towards the specular lobe: a bump of 20-60 um (log, either sign) in the reading as
    a Gaussian of the tip's angle (width 2-6 % of the largest angle), nothing elsewhere. A reading error set by where
    the tip is, passed through on the way up and on the way down of every record that bends far enough; displacement
    only. Measured (paper_112): a bump of -21 um at 4.03 mm (0.46 of the largest angle), passed by the 1 V steps on
    their rise and dwelt on through their slow give-back after the fall, and by the 1 V harmonics: displacement residual
    0.17 % of its RMS (10x its noise); (p39_114): +28 um at 7.66 mm, 0.12 % (13x)."""
    L = float(s.specimen["length_m"])
    th_max = 2 * _largest(s) / L
    side, sg = _sign(s), _sign(s)
    thg, wg, amp = s.rng.uniform(0.4, 0.8) * th_max, s.rng.uniform(0.02, 0.06) * th_max, lu(s.rng, 2e-5, 6e-5)
    map_disp(s, lambda r, d: d + sg * amp * np.exp(-0.5 * ((side * 2 * d / L - thg) / wg) ** 2))


def out_wall_squeeze(s: Session) -> None:
    """The cuvette's wall close beside the tip on one side (the strip put in off-centre, the wall at 1.08-1.25 times the
    session's largest bend): when the tip comes near it the water between the strip's face and the wall must be squeezed
    out of the narrowing gap (Reynolds' squeeze film, a damping as the gap's -3rd power), so the tip follows its free
    motion through a lag tau(g) = tau0 (g0/g)^3 (tau0 0.02-0.1 ms at rest, log: nothing away from the wall; tens to
    hundreds of ms at the closest): it creeps into its last approach and is held as it starts away. A one-sided lag set
    by where the tip is; each record from its first value (inject_fresh12._per_record); displacement only. Measured
    (paper_112): the wall at 1.06 of the largest bend: the 1 V steps' creep slowed, their peaks -0.46 %, and the tip
    held back 0.48 mm 0.19 s after each fall; displacement residual 0.41 % of its RMS (25x its noise); (p39_114) at
    1.09: peaks -0.2 %, 0.40-0.44 mm held back 0.2 s after the falls, 0.21 % (22x)."""
    side, g0, tau0 = _sign(s), s.rng.uniform(1.05, 1.15) * _largest(s), lu(s.rng, 3e-5, 1.5e-4)

    def step(x: float, d: float, dt: float) -> float:
        gap = max(g0 - side * x, 1e-3 * g0)
        return d + (x - d) * math.exp(-dt / (tau0 * (g0 / gap) ** 3))

    ys = _per_record(s, "disp_m", step)
    map_disp(s, lambda r, d: ys[id(r)])


def out_reordered_packets(s: Session) -> None:
    """The laser's readings streamed over UDP (a controller's Ethernet output) in packets of N samples (16, 32 or 64 for
    the session), and the logger writes the packets in the order they arrive, without their sequence numbers: now and
    then the network delivers a packet after the next one (0.3-1.5 % of the packets, log), and the two are written
    swapped, onto the DAQ's rows as they stand. Invisible at rest, a zig-zag of two packets' worth of motion wherever
    the tip moves (never the first two packets of a record); displacement only. Measured (s001_113): packets of 16, 0.45
    % swapped: 42 records touched, errors up to 65 um on the sines; displacement residual 0.13 % of its RMS (4.4x its
    noise); (p39_114): packets of 32, 0.57 %: up to 0.83 mm on the 2 Hz sine (200 Hz, so a packet is 0.16 s), 0.23 %
    (24x)."""
    n, p = int(s.rng.choice([16, 32, 64])), lu(s.rng, 3e-3, 1.5e-2)
    for r in s.series():
        d = r.cols["disp_m"]
        m = d.size // n
        order, k = list(range(m)), 2
        while k < m - 1:
            if s.rng.random() < p:
                order[k], order[k + 1] = order[k + 1], order[k]
                k += 2
            else:
                k += 1
        idx = np.concatenate([np.arange(j * n, (j + 1) * n) for j in order] + [np.arange(m * n, d.size)])
        r.cols["disp_m"] = d[idx]


def out_divider_compensation(s: Session) -> None:
    """The drive is monitored at the strip's terminals through a 10:1 divider (to keep the amplifier's rails off the
    DAQ's input) whose compensating trimmer across its top resistor is mis-set: the divider passes the fast part of the
    drive with a gain 10-30 % off its DC gain (either way), v_mon = v (1 + a tau s/(1 + tau s)) (tau 0.5-5 ms, log):
    each step's edge in v_V overshoots (or undershoots) and settles over tau, the fast sines read 1 + a |HP| of their
    amplitude, while the strip gets the drive as it is (the current and the displacement untouched). The high-pass exact
    for the output's held samples, each record from rest; v_V re-read at the DAQ's 16-bit step (+-10 V). v_V only.
    Measured (paper_112): a = -0.27, tau 0.59 ms: the 1 V steps' edges read 0.731 V, 0.991 V a sample later; v_V
    residual 0.96 % of its RMS, the 20 Hz records' amplitude -0.1 %; (s001_113): a = -0.29, tau 3.8 ms: the edges 0.71,
    0.83, 0.90, 0.94 V over four samples, the 20 Hz records' amplitude -5.1 %, residual 2.7 %."""
    a, tau = _sign(s) * s.rng.uniform(0.1, 0.3), lu(s.rng, 5e-4, 5e-3)
    for r in s.series():
        v = r.cols["v_V"]
        hp = signal.lfilter([1.0, -1.0], [1.0, -math.exp(-1.0 / (r.fs * tau))], v - v[0])  # exact for the held drive
        r.cols["v_V"] = np.round((v + a * hp) / VOLT_LSB) * VOLT_LSB


FRESH14_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"percolating_clusters": br_percolating_clusters, "proton_uptake": br_proton_uptake},
    "faradaic_current": {"crushed_root": far_crushed_root, "wet_connector": far_wet_connector},
    "hysteresis": {"crack_friction": hy_crack_friction, "cooling_friction": hy_cooling_friction},
    "time_delay": {"window_search": td_window_search, "drying_exposure": td_drying_exposure},
    "sensor_offset": {"blended_ldv": so_blended_ldv, "fogging_window": so_fogging_window},
    "clamp_relaxation": {"root_shrinkage": cr_root_shrinkage, "thermostat_pads": cr_thermostat_pads},
    "dehydration": {"humidifier_empty": dh_humidifier_empty, "record_lamp": dh_record_lamp},
    "strain_resistance": {"precracked_face": sr_precracked_face, "jaw_pinch": sr_jaw_pinch},
    "large_deflection": {"anticlastic": ld_anticlastic, "crease_hinge": ld_crease_hinge},
    "mains_pickup": {"floating_frame": mp_floating_frame, "half_wave_heater": mp_half_wave_heater},
    "unexplained": {"specular_glint": out_specular_glint, "wall_squeeze": out_wall_squeeze,
                    "reordered_packets": out_reordered_packets, "divider_compensation": out_divider_compensation},
}
inject.register_forms(FRESH14_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_tared_records(s: Session) -> None:
    """A logger that zeroes the laser at each record's arming (the controller's zero-set input pulsed before the drive
    starts, as many labs do to keep the reading inside the head's range): every time series' displacement less its value
    at arming, the mean over the samples before the drive first moves (at most 0.5 s, at least the first sample), taken
    to the DAQ's step (the laser's +-20 mm on 16 bits, so the values stay on the converter's grid); the current, the
    drive, the load cell, the spectra and the manifest as they were. A record that starts on a strip still bent from the
    one before starts at zero. ``labrig import`` takes it (the values finite, the columns and the clock as they were).
    """
    for r in s.series():
        v, d = r.cols["v_V"], r.cols["disp_m"]
        moved = np.flatnonzero(np.abs(v - v[0]) > 1e-3)
        n = int(moved[0]) if moved.size else v.size
        n = max(1, min(n, int(0.5 * r.fs)))
        r.cols["disp_m"] = d - round(float(np.mean(d[:n])) / DISP_LSB) * DISP_LSB


inject.VARIANTS.update({"tared_records": v_tared_records})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_112", "s001_113", "p39_114"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 6 / 7 / 7 effect cases on seeds 112-114
    "back_relaxation": [("percolating_clusters", 112, P, "asrun"), ("proton_uptake", 114, T, "dropped_packets")],
    "faradaic_current": [("crushed_root", 112, P, "eis_descending"), ("wet_connector", 113, S, "short_pretrigger")],
    "hysteresis": [("crack_friction", 114, T, "tared_records"), ("cooling_friction", 112, P, "settled_sines")],
    "time_delay": [("window_search", 114, T, "rate07"), ("drying_exposure", 113, S, "float32_time")],
    "sensor_offset": [("blended_ldv", 114, T, "coherent_sines"), ("fogging_window", 112, P, "resampled")],
    "clamp_relaxation": [("root_shrinkage", 113, S, "merged_loadcell"), ("thermostat_pads", 112, P, "asrun")],
    "dehydration": [("humidifier_empty", 113, S, "asrun"), ("record_lamp", 113, S, "host_timed")],
    "strain_resistance": [("precracked_face", 113, S, "steps_sines"), ("jaw_pinch", 114, T, "two_pressures")],
    "large_deflection": [("anticlastic", 113, S, "tared_records"), ("crease_hinge", 114, T, "shortened_shuffled")],
    "mains_pickup": [("floating_frame", 112, P, "no_spectra"), ("half_wave_heater", 114, T, "asrun")],
    "unexplained": [("specular_glint", 112, P, "tared_records"), ("specular_glint", 114, T, "asrun"),
                    ("wall_squeeze", 112, P, "decimated3"), ("wall_squeeze", 114, T, "asrun"),
                    ("reordered_packets", 113, S, "asrun"), ("reordered_packets", 114, T, "trigger_clock"),
                    ("divider_compensation", 112, P, "own_clock"), ("divider_compensation", 113, S, "asrun")],
}
CLEAN = [(112, P, "asrun"), (112, P, "tared_records"), (113, S, "asrun"), (113, S, "no_loadcell"),
         (114, T, "asrun"), (114, T, "tared_records")]


def fresh14_cases(only: str | None = None) -> list[Case]:
    """The fifteenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds 112-114).
    """
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh14_cases, "inject_fresh14", "fresh14")
