"""A fourteenth held-out set for the diagnosis (issue 12), fresh13, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh12.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (channels the pore pressure dilates, the
strip stirring its own diffusion layer, a plated film yielding with a Bauschinger back stress, a visco-plastic drag on
the cations, an anti-aliasing capacitor losing capacitance with its DC bias, a substrate relaxing under the cracked
film, a round water-filled vial as a lens), some on the history (a fresh strip conditioned by its largest bend so far,
a metal impurity shuttled between the faces, crack bridges welded by the current's spikes, a video tracker's template
drifting along the strip's edge, the room's humidity cycling through a hysteretic isotherm), some on time or on the
clamp pressure (an electromagnet clamp's coil warming, a magnet clamp closing its gap as the pads creep, blotting pads
drawing the water out of the root, a jaw that tilts the root as it is tightened), some from the lab's wiring or
settings (a laser head re-aimed inboard for the steps, a mains notch on the laser channel, hum from a lamp's cord the
strip's tip swings towards, a DAQ whose output reference carries the mains ripple). Four structures outside the
catalogue (truth "unexplained": a jaw protruding past the other, the voltage monitor's range clipping the 1 V records,
the load cell's zero warming up, two blocks' pressures swapped in the manifest); clean sessions. All on three bases of
new seeds (109-111: the paper strip, the seed-001 strip on its own sweep, the paper strip 37 mm free) and on the earlier
sets' protocol / data-shape variants plus one new here: a frequency-response logger clocked from its generator, so
every sine record is sampled at a fixed number of points per drive period by an integrating converter
(``coherent_sines``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh12 are reused (importing inject_fresh12 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, std(diff)/sqrt(2) over the 200 samples before each step record's edge, the
median over the steps; the values for the three bases are in docs/effects.md).

Run: python bench/inject_fresh13.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal

import inject
import inject_fresh12  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lti, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _drive_side, _spec
from inject_fresh3 import _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _blocks
from inject_fresh7 import KGF, _block_of
from inject_fresh8 import _arc, _hum, _leaky
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f, _per_record

# the paper's strip 37 mm free (earlier sets used 20, 25, 27, 28, 30, 32, 33, 34, 35, 36, 38, 40, 42 and 45 mm; its 1 V
# step peaks near 13.2 mm, 8.8 mm x (37/30)^2, inside the laser's +-20 mm): registered in every process importing this
inject.register_free_length("paper_37", 0.037)

inject.BASES.update({
    "paper_109": ("paper-sweep", "paper", 109),
    "s001_110": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 110),
    "p37_111": ("paper-sweep", "paper_37", 111),
})


# ------------------------------------------------------------------------------------------------ tools


def _series_t(s: Session) -> tuple[list[Rec], np.ndarray, np.ndarray]:
    """The series in time order, their concatenated times and the seconds each sample stands for (1/fs of its record).
    """
    recs = _chrono(s)
    t = np.concatenate([r.cols["t_s"] for r in recs])
    dt = np.concatenate([np.full(r.cols["t_s"].size, 1.0 / r.fs) for r in recs])
    return recs, t, dt


def _smooth(r: Rec, col: str, fc: float) -> np.ndarray:
    """One column of a record through a causal second-order (critically damped) low-pass at fc (Hz, at most a fifth of
    the record's rate), from its first value (the record starts at rest)."""
    x = r.cols[col]
    wc = 2 * np.pi * min(fc, 0.2 * r.fs)
    return x[0] + lti(x - x[0], r.fs, lambda z: 1 / (1 + z / wc) ** 2)


def _tip_steps(s: Session) -> float:
    """The session's largest displacement (abs) on its step records (on any series if it has none)."""
    recs = [r for r in s.series() if r.kind == "step"] or s.series()
    return max(float(np.max(np.abs(r.cols["disp_m"]))) for r in recs)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_compliant_channels(s: Session) -> None:
    """The back-flow runs through channels that its own pore pressure dilates: a compliant channel's width grows with
    the pressure across it (w = w0 (1 + dp/p_c)) and a slit's hydraulic conductance as the cube of its width (the cubic
    law), so the store x of water flowing back follows the bend d at the rate (1 + abs(d - x)/g_c)^3 / tau0: slow (tau0
    8-25 s, log) for the small pressures of the 0.5 V sines and the tails, 5-60x faster at the start of a 1 V step's
    give-back (g_c 1.5-4 of the displacement scale, log); read d - K2 x, K2 0.9-1.3. Sample by sample through the
    session in time order (the store carried over the rests, the displacement linear across them); displacement only.
    Measured (paper_109): displacement RMS -75 % (residual 105 %); the 1 V steps peak at 1.70 mm 2.3 s after the edge
    (8.8 mm clean) and are back to +0.03 mm by the plateau's end, -1.9 mm 2 s after the fall; the 1 V harmonic's
    residual 94 %, the 0.5 V sine's at 0.1 Hz 37 % (a linear lag takes the same share of both)."""
    k2, tau0, gc = s.rng.uniform(0.9, 1.3), lu(s.rng, 8.0, 25.0), lu(s.rng, 1.5, 4.0) * ref_disp(s)
    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 0.5):
        d = r.cols["disp_m"]
        for dt, u in gap:
            target = d_end + u * (float(d[0]) - d_end)
            x += -math.expm1(-dt * (1 + abs(target - x) / gc) ** 3 / tau0) * (target - x)
        h = 1.0 / (r.fs * tau0)
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            g = dk - x
            x += -math.expm1(-h * (1 + abs(g) / gc) ** 3) * g
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


def br_conditioning(s: Session) -> None:
    """A fresh strip conditioned by its largest bend: the first time the swelling passes a threshold the ionic clusters
    coalesce into channels for good (the first-cycle effect of a strip that was dried and re-soaked before mounting),
    and the back-flow through them grows and speeds up with the largest bend so far, not with time or use: K2 from
    0.2-0.5 to 1.0-1.3 and tau from tau_a 8-20 s (log) down 2-4x as the running maximum of abs(d) goes from u0 0.2-0.5
    of the session's largest bend to the largest, a state that never goes back. Through inject_fresh10._lag_varying (the
    lag sample by sample through the session in time order, the state read off the running maximum on the session
    clock); displacement only. Measured (p37_111): displacement RMS -60 % (residual 115 %); the first 1 V step (the
    session's first large bend) peaks at 6.24 mm 9.9 s after its edge and ends its plateau at -0.85 mm, the later ones
    peak at 3.07 mm 3.9 s after it and end at -1.43 mm (13.2 mm clean)."""
    ka, kb = s.rng.uniform(0.2, 0.5), s.rng.uniform(1.0, 1.3)
    ta, a, u0 = lu(s.rng, 8.0, 20.0), s.rng.uniform(2.0, 4.0), s.rng.uniform(0.2, 0.5)
    recs, t, _ = _series_t(s)
    m = np.maximum.accumulate(np.abs(np.concatenate([r.cols["disp_m"] for r in recs])))
    share = np.clip((m / max(float(m[-1]), 1e-30) - u0) / (1 - u0), 0, 1)

    def state(tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        p = np.interp(tt, t, share, left=0.0, right=float(share[-1]))
        return ka + (kb - ka) * p, ta / (1 + (a - 1) * p)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_metal_shuttle(s: Session) -> None:
    """A metal impurity (copper from tap water or a brass fitting, a few nmol) plated on the two faces and shuttled
    between them: while v > 0 the metal on face A dissolves and re-deposits on face B, while v < 0 the other way, at the
    rate k(v) = exp((abs(v) - 1)/b)/tau1 (Butler-Volmer past both faces' equilibrium, b 0.06-0.12 V, tau1 0.5-4 s at 1
    V, log) times the metal still on the giving face: a finite inventory Q 0.3-1.5 mC (log), split 0.3-0.7 at the
    mounting, that a held step moves in a decaying pulse and the next step of the same sign finds spent; nothing on the
    0.5 V sines (k 65-4000x lower), the inventory held over the rests. Charge-conserving sample by sample through the
    session in time order; current only. Measured (paper_109): current residual 2.4 % of its RMS (1.2x its noise); a
    pulse of 0.69 mA decaying within a second on the first 1 V step (0.36 mC moved), 1.29 mA on the later ones (0.68 mC:
    each 1 V harmonic before them moved the metal back), nothing at rest and on the 0.5 V sines (residual 0.04 %); the 1
    V harmonic's current +0.65 / -0.73 mA at most (residual 7.1 %)."""
    b, tau1, q = s.rng.uniform(0.06, 0.12), lu(s.rng, 0.5, 4.0), lu(s.rng, 3e-4, 1.5e-3)
    qa = q * s.rng.uniform(0.3, 0.7)
    qb = q - qa
    for r in _chrono(s):
        v, dt = r.cols["v_V"].tolist(), 1.0 / r.fs
        add = np.empty(len(v))
        for k, u in enumerate(v):
            moved = 0.0
            if u != 0.0:
                frac = -math.expm1(-dt * math.exp((abs(u) - 1.0) / b) / tau1)
                if u > 0:
                    moved = qa * frac
                    qa, qb = qa - moved, qb + moved
                else:
                    moved = -qb * frac
                    qa, qb = qa - moved, qb + moved
            add[k] = moved / dt
        r.cols["i_A"] = r.cols["i_A"] + add


def far_motion_stirring(s: Session) -> None:
    """A dissolved species' reduction (the bath's oxygen) on the cathodic face, a wave of onset E0 0.3-0.6 V and width w
    0.04-0.08 V whose limiting current is set by the diffusion layer, and the strip stirs its own layer: natural
    convection alone holds it when the strip is still or creeps, forced convection by the strip's own motion thins it
    when the tip moves fast (a plate's boundary layer, Sherwood ~ sqrt(U)), the two combined as Churchill's mixed
    convection, I_L = I_0 (1 + (U/U_c)^(3/2))^(1/3), U_c 0.3-1 mm/s (log: the still bath's own convection; U the tip's
    speed, from the displacement low-passed at 40 Hz), the layer re-forming over tau_r 0.5-3 s (log) once the motion
    stops (the speed through that lag, inject_fresh8._leaky, carried over the rests). 0.1-0.3 mA at 1 V held still
    (log): the step's faradaic current is largest just after its edge, where the tip moves fastest, and falls back
    within seconds; current only. Measured (p37_111): current residual 2.7 % of its RMS (1.4x its noise); on the 1 V
    steps +0.215 mA 1-3 s after the edge and +0.144 mA by the plateau's end (the layer re-formed); the 1 V harmonic's
    current +-0.26 mA at most (residual 5.3 %)."""
    e0, w, tau_r = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.04, 0.08), lu(s.rng, 0.5, 3.0)
    i1, uc = lu(s.rng, 1e-4, 3e-4), lu(s.rng, 3e-4, 1e-3)
    speed = {id(r): np.abs(np.gradient(_smooth(r, "disp_m", 40.0))) * r.fs for r in s.series()}
    lag = _leaky(s, speed, tau_r)
    sig = lambda x: 1 / (1 + np.exp(-x))  # noqa: E731
    g0 = float(sig(-e0 / w))

    def wave(v: np.ndarray) -> np.ndarray:
        return np.sign(v) * (sig((np.abs(v) - e0) / w) - g0) / (1 - g0)

    scale = i1 / float(wave(np.array([1.0]))[0])
    for r in s.series():
        boost = np.cbrt(1 + (np.clip(lag[id(r)] / tau_r, 0, None) / uc) ** 1.5)
        r.cols["i_A"] = r.cols["i_A"] + scale * boost * wave(r.cols["v_V"])


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_bauschinger_film(s: Session) -> None:
    """The plated metal film yields: a platinum or gold layer strained past its yield (0.1-0.5 % at the surface of a 1 V
    bend) flows plastically and, on the way back, yields early (the Bauschinger effect), which Armstrong-Frederick
    kinematic hardening describes: the film's stress in displacement units s = d - p (p its plastic part) stays within r
    of a back stress a that follows the plastic flow, da = H dp - (H/a_s) a abs(dp), saturating at +-a_s; the film takes
    a share w of the bending, so the strip reads d - w (d - p). Yield r 0.02-0.06, a_s 0.1-0.3 of the displacement
    scale, H 0.5-2, w 0.15-0.3: the small sines stay elastic (their gain 1 - w about a plastic set), the large records
    yield and leave a remanent bend, and one-sided steps ratchet. Return mapping sample by sample through the session in
    time order (inject_fresh11._walk, the state held over the rests); displacement only. Measured (s001_110):
    displacement residual 3.5 % of its RMS (108x its noise); the 0.5 V sine's swing at 0.1 Hz -11 %, the 1 V harmonic's
    -7.5 %, the 1 V steps' peaks -1.9 % with +91 um left at the records' ends; the 20 Hz records' residuals 27-29 %."""
    ref = ref_disp(s)
    r0, a_s = s.rng.uniform(0.02, 0.06) * ref, s.rng.uniform(0.1, 0.3) * ref
    hh, w = s.rng.uniform(0.5, 2.0), s.rng.uniform(0.15, 0.3)
    st = {"p": 0.0, "a": 0.0}

    def step(_: float, d: float, dt: float) -> float:
        p, a = st["p"], st["a"]
        z = d - p - a
        f = abs(z) - r0
        if f > 0:
            sg = 1.0 if z > 0 else -1.0
            dp = f / (1 + hh - hh * a * sg / a_s)
            p, a = p + sg * dp, a + hh * sg * dp - hh * a * dp / a_s
            st["p"], st["a"] = p, a
        return p

    ps = _walk(s, step, "disp_m")
    map_disp(s, lambda r, d: d - w * (d - ps[id(r)]))


def hy_bingham_drive(s: Session) -> None:
    """The pinned cations as a Bingham (visco-plastic) medium on the drive: a part h 0.2-0.4 of the drive moves them
    only past a yield r 0.1-0.3 V and then at a rate set by the overstress, dx/dt = sign(v - x) max(abs(v - x) - r,
    0)/tau_v (tau_v 0.2-2 s, log; exact for the drive held over each sample, the overstress relaxing over the rests): a
    play of radius r on slow drives, a lag that grows with the rate and a gain that falls on fast ones. Gamma = (1 - h)
    v + h x through the strip's measured step response (inject_fresh2._drive_side); current untouched. Measured
    (paper_109): displacement residual 8.0 % of its RMS (490x its noise); the 1 V steps' peaks -4.7 % with +0.41 mm left
    at the records' ends, the 1 V harmonic's residual 13 %, the 0.5 V sines' 50 % at 0.1 Hz (swing -16 %), 59 % at 0.45
    Hz and 54-68 % at 20 Hz."""
    h, rr, tau = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.1, 0.3), lu(s.rng, 0.2, 2.0)
    recs = _chrono(s)
    x, out, t_end = 0.0, [], None
    for r in recs:
        if t_end is not None and abs(x) > rr:  # the rest at 0 V: the overstress relaxes
            x = math.copysign(rr + (abs(x) - rr) * math.exp(-(float(r.cols["t_s"][0]) - t_end) / tau), x)
        a = math.exp(-1.0 / (r.fs * tau))
        y = np.empty(r.cols["v_V"].size)
        for k, u in enumerate(r.cols["v_V"].tolist()):
            e = u - x
            if abs(e) > rr:
                x = u - math.copysign(rr + (abs(e) - rr) * a, e)
            y[k] = x
        out.append(y)
        t_end = float(r.cols["t_s"][-1])
    v = np.concatenate([r.cols["v_V"] for r in recs])
    gam = (1 - h) * v + h * np.concatenate(out)
    _drive_side(s, lambda _v: gam)


# ------------------------------------------------------------------------------------------------ time delay


def td_x7r_filter(s: Session) -> None:
    """The laser's analogue output reaches the DAQ through a home-made anti-aliasing RC whose capacitor is a class-2
    ceramic (X7R): its capacitance falls with the DC bias across it, C(u) = C0/(1 + (u/u_c)^2), so the filter's time
    constant R C(u) is 4-15 ms (log) at rest and 0.3-0.6 of that at the session's largest reading: a lag that shrinks
    with the reading's size (the charge q(u) = C0 u_c atan(u/u_c) follows (x - u)/R). Sample by sample in each record
    from its first value (the line settled over the rest before it, inject_fresh12._per_record); displacement only.
    Measured (p37_111): displacement residual 0.11 % of its RMS (9.9x its noise); a lag of 5.9 ms on the 0.1 Hz sines (a
    small reading), 4.1 ms just after the steps' falls (from 12.5 mm), 5.0 ms at the 1 V harmonic's crests; gain 0.70
    and -42 deg on the 20 Hz records (residuals 27 %)."""
    tau0, cmin = lu(s.rng, 4e-3, 1.5e-2), s.rng.uniform(0.3, 0.6)
    uc = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) / math.sqrt(1 / cmin - 1)

    def step(y: float, x: float, dt: float) -> float:
        tau = tau0 / (1 + (y / uc) ** 2)
        return x + (y - x) * math.exp(-dt / tau)

    ys = _per_record(s, "disp_m", step)
    map_disp(s, lambda r, d: ys[id(r)])


def td_mains_notch(s: Session) -> None:
    """The lab's logging software puts a digital mains notch on the laser's channel (against hum on its long analogue
    cable), set wide to take the hum's neighbourhood too: a second-order IIR notch at the line frequency (50 or 60 Hz)
    of quality Q 0.7-2 (log), designed at each record's own rate (scipy.signal.iirnotch, so its shape warps with the
    rate) and run causally from the record's first value. Below the notch its phase is a lag of about 1/(Q w0) on the
    fast records and more on the 200 Hz ones, a delay of 1.6-10 ms, and its gain droops towards the notch (the 20 Hz
    records lose 3-20 %): a delay that comes with its own gain and depends on the record's rate. Displacement only.
    Measured (s001_110): displacement residual 0.12 % of its RMS (3.7x its noise); 3.8 ms of lag on the 0.1 Hz sines
    (200 Hz records), gain 0.93 and 3.0 ms on the 20 Hz ones (1 kHz), their residuals 37 %."""
    f0, q = (50.0 if s.rng.random() < 0.5 else 60.0), lu(s.rng, 0.7, 2.0)

    def notch(r: Rec, d: np.ndarray) -> np.ndarray:
        if r.fs <= 2.2 * f0:
            return d
        b, a = signal.iirnotch(f0, q, r.fs)
        return signal.lfilter(b, a, d, zi=signal.lfilter_zi(b, a) * d[0])[0]

    map_disp(s, notch)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_range_reaim(s: Session) -> None:
    """The lab's laser head has a short measuring range (+-6 to +-10 mm: a high-resolution head), too short for the 1 V
    step at the tip, so for the step records the operator moves the head inboard to where the step's peak reads 0.8-
    0.95 of the range (x_m/L = sqrt(that over the tip's peak), the quasi-static (x/L)^2, at least 0.55), and back to the
    tip for the sines (which fit): the steps read at a station of their own, the sines at the tip. Through
    inject_fresh10._station (the beam's own transfer functions at the station); a strip whose step fits the range is
    read at the tip throughout. Displacement only. Measured (p37_111): the steps read at 0.81 L (a +-9.6 mm head): their
    peaks -34.5 %, -47 to -56 % 50 ms after the edge; displacement RMS -32 % (residual 34 %); the sines untouched."""
    rng_m, fill = s.rng.uniform(6e-3, 10e-3), s.rng.uniform(0.8, 0.95)
    f = float(np.clip(math.sqrt(min(fill * rng_m / _tip_steps(s), 1.0)), 0.55, 1.0))
    if f >= 0.999:
        return
    _station(s, lambda r: np.full(r.cols["t_s"].size, f if r.kind == "step" else 1.0), f)


def so_template_drift(s: Session) -> None:
    """Video tracking with template update (each frame's match becomes the next template): the tip's image is an edge
    along the strip, and along an edge a match is unconstrained (the aperture problem), so the tracked point walks along
    the strip at random, more the more the image changes: a station x_s/L that the operator's click puts on the tip at
    each record's first frame and that then random-walks with a variance sigma^2 per unit of the strip's motion (sigma
    0.02-0.05 of L per displacement scale travelled, log; updates every 0.1 s, on 0.1 s means of the displacement), held
    off the tip's end by the corner there (reflected at 1) and kept above 0.6. Through inject_fresh10._station;
    displacement only. Measured (paper_109): displacement RMS -4.9 % (residual 6.3 %, 380x its noise); the 1 V steps'
    plateaus' ends -4.4, -7.0, -1.5, -4.3 % block by block, the 1 V harmonics' troughs -4.9 to -39 %, the 0.5 V sines'
    residuals at 0.1 Hz 7-15 %."""
    sig, ref, lo = lu(s.rng, 0.02, 0.05), ref_disp(s), 0.6

    def frac(r: Rec) -> np.ndarray:
        t, d = r.cols["t_s"], r.cols["disp_m"]
        edges = np.arange(float(t[0]), float(t[-1]) + 0.1, 0.1)
        k = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, edges.size - 1)
        sums = np.bincount(k, d, minlength=edges.size)
        cnt = np.bincount(k, minlength=edges.size)
        m = sums[cnt > 0] / cnt[cnt > 0]
        path = np.abs(np.diff(m, prepend=m[0])) / ref
        x = 1 - np.abs(np.cumsum(sig * np.sqrt(path) * s.rng.normal(size=m.size)))
        x = np.where(x < lo, lo + (lo - x) % (1 - lo), x)  # folded back into [lo, 1]
        tm = edges[cnt > 0] + 0.05
        return np.clip(np.interp(t, tm, x), lo, 1.0)

    stations = {id(r): frac(r) for r in _chrono(s)}
    _station(s, lambda r: stations[id(r)], lo)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_solenoid_heating(s: Session) -> None:
    """An electromagnet clamp (a solenoid pulling the jaw) on a constant-voltage supply: the operator sets the voltage
    for each pressure's force, then the coil warms by its own power and its copper resistance rises (0.39 %/K), so the
    current and the force, F ~ I^2, fall: F/F_set = ((1 + a T(t_set))/(1 + a T(t)))^2. The coil's temperature rise T
    follows its power through a thermal lag (300-1200 s, log) from its energising 0-200 s before the first record, the
    power (and the steady rise, 20-50 K at the top pressure's force) growing with the force set: the lowest block's
    small force barely warms the coil, each tightening raises the power and the coil heats on from where it was, so
    every later block loses a few percent however warm it starts. Through the preset's clamp law
    (inject_fresh4._clamp_law). Measured (paper_109): the load cell at 0.97, 0.94, 0.94, 0.95 of its setting by the
    blocks' ends (-0.3, -1.8, -2.8, -3.6 N); displacement residual 0.07 % (4.1x its noise), current 0.35 % (0.2x), the 3
    Hz records' up to 18 % in the top block (its f1 moved)."""
    t_top, tau, lead = s.rng.uniform(20.0, 50.0), lu(s.rng, 300.0, 1200.0), s.rng.uniform(0.0, 200.0)
    alpha = 0.0039
    tg = _session_grid(s, 1.0, lead)
    block = _block_of(s)
    press = {a: p for p, (a, _) in _blocks(s).items()}
    p_of = np.array([press[float(b)] for b in block(tg)])
    p_top = max(press.values())
    temp, x = np.empty(tg.size), 0.0
    for k, p in enumerate(p_of.tolist()):
        x += -math.expm1(-1.0 / tau) * (t_top * p / p_top / (1 + alpha * x) - x)
        temp[k] = x

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        at = lambda u: 1 + alpha * np.interp(u, tg, temp)  # noqa: E731
        return (at(np.array([t_set]))[0] / at(t)) ** 2

    _clamp_law(s, rel)


def cr_magnet_clamp(s: Session) -> None:
    """A permanent-magnet clamp whose force is set by shims (the gap g between the magnet and the steel jaw, the strip
    and its pads in it): the pads creep under the force (logarithmically, time constant 20-200 s, log), which closes the
    gap, and the magnet's pull grows as 1/g^2, which makes them creep faster: F/F_set = 1/(1 - e)^2 with the gap's
    relative closure e = e_lin(t) (F/F_set), e_lin = e0 (p/p_top) log(1 + t/tau)/log(1 + 1500 s/tau), e0 0.01-0.04 at
    the top pressure: a force that rises through each block, the more the tighter. Through the preset's clamp law
    (inject_fresh4._clamp_law). Measured (s001_110): the load cell at 1.016, 1.033, 1.045, 1.053 of its setting by the
    blocks' ends (+0.4 to +4.5 N); displacement residual 0.01 % (0.2x its noise), current 0.15 % (0.3x), the 20 Hz
    records' up to 1.5 %."""
    e0, tau = s.rng.uniform(0.01, 0.04), lu(s.rng, 20.0, 200.0)
    p_top = max(s.pressures())

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        lin = e0 * p / p_top * np.log1p(np.clip(t - t_set, 0, None) / tau) / math.log1p(1500.0 / tau)
        e = lin.copy()
        for _ in range(30):  # the fixed point e = lin / (1 - e)^2 (small e: converges)
            e = lin / (1 - e) ** 2
        return 1 / (1 - e) ** 2

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_sorption_hysteresis(s: Session) -> None:
    """A strip in air in a room whose air conditioning cycles the humidity (+-4-8 % RH, a period of 900-2400 s) about a
    falling trend (from 0.4-0.55 down by 0.1-0.2 through the session), and Nafion's sorption is hysteretic (its
    desorption branch above its absorption branch: pores that empty only below their filling pressure): the water
    follows the isotherm (inject_fresh10._lambda) at an effective humidity that moves only once the room's has turned by
    more than 2 r (a play of radius r 0.02-0.05 on the humidity, Everett's independent domains at their simplest),
    through a sorption lag of 100-400 s (log): after each turn the strip holds its water for a while, then follows, so
    the cycles ratchet it drier. The gain as lambda/lambda_0, the conductance as (lambda/lambda_0)^1.5-2.5
    (inject_fresh9._dry_by). Measured (s001_110): displacement RMS -2.8 % (residual 5.4 %), the 1 V steps' peaks +3.4,
    -1.6, -4.3, -9.0 % block by block (the room first wetter, then drier cycle by cycle); current -6.9 % (residual 17 %,
    31x its noise), -20 % in the last block."""
    a0, drop = s.rng.uniform(0.4, 0.55), s.rng.uniform(0.1, 0.2)
    amp, per, ph = s.rng.uniform(0.04, 0.08), s.rng.uniform(900.0, 2400.0), s.rng.uniform(0, 2 * np.pi)
    rr, tau_s, gc = s.rng.uniform(0.02, 0.05), lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, 600.0)
    u = np.clip((tg - s.t0) / (s.t1 - s.t0), 0, 1)
    rh = a0 - drop * u + amp * (np.sin(2 * np.pi * (tg - tg[0]) / per + ph) - math.sin(ph))
    eff, y = np.empty(tg.size), float(rh[0])
    for k, a in enumerate(rh.tolist()):
        y = min(max(y, a - rr), a + rr)
        eff[k] = y
    lam = _lambda(eff)
    x, lag = float(lam[0]), np.empty(tg.size)
    for k, target in enumerate(lam.tolist()):
        x += -math.expm1(-1.0 / tau_s) * (target - x)
        lag[k] = x
    rel = lag / float(lam[0])
    _dry_by(s, lambda t: 1 - np.interp(t, tg, rel), lambda t: 1 - np.interp(t, tg, rel) ** gc)


def dh_pad_suction(s: Session) -> None:
    """A strip in air clamped between blotting-paper pads (laid under the jaws' contacts to spread the pressure): the
    dry paper draws the strip's water out through the clamped root by capillary suction, at a rate that grows with the
    clamp pressure (the paper's contact with the strip, (p/p_min)^m, m 0.5-1) and falls as the paper fills (capacity
    0.05-0.12 of the strip's water; the same pads kept through the session): dL/dt = k (p/p_min)^m (1 - L/L_cap), k such
    that the first block draws 0.2-0.6 of the capacity. The water leaves from the root, where the bend is made, so the
    gain loses 1.5-2.5x the conductance's share (at most 0.5); a loss that steps faster at each tightening and stops as
    the pads saturate (inject_fresh9._dry_by). Measured (s001_110): displacement RMS -13 % (residual 16 %), the 1 V
    steps' peaks -0.2, -11, -20, -24 % block by block (each block's step at its start); current -6.6 % (14x its noise),
    -4.2, -7.9, -9.5 % on the later blocks' steps."""
    cap, m, g = s.rng.uniform(0.05, 0.12), s.rng.uniform(0.5, 1.0), s.rng.uniform(1.5, 2.5)
    blocks = _blocks(s)
    p_min = min(blocks)
    first = min(blocks.values())
    k = -math.log(1 - s.rng.uniform(0.2, 0.6)) / max(first[1] - first[0], 1.0)
    tg = _session_grid(s, 1.0, 0.0)
    block = _block_of(s)
    press = {a: p for p, (a, _) in blocks.items()}
    rate = k * (np.array([press[float(b)] for b in block(tg)]) / p_min) ** m
    loss = cap * -np.expm1(-np.cumsum(rate * (tg > s.t0)))
    _dry_by(s, lambda t: np.minimum(g * np.interp(t, tg, loss), 0.5), lambda t: np.interp(t, tg, loss))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_fritting(s: Session) -> None:
    """The cracks of the tensioned face are bridged by thin oxide-covered contacts whose films break down (fritting)
    when the current through them is high: each current spike above i_c (0.3-0.6 of the session's largest current) welds
    a share of the bridges (the gauge's sensitivity falls to 1 - b F, b 0.5-0.9), and the welds re-oxidise in the water
    over tau_o 20-100 s (log): the strain sensitivity is low just after the steps' edges and recovers through their
    plateaus and the rests (F through the session in time order, inject_fresh11._walk). The tensioned face (side drawn)
    with the other at 0.1-0.3 of its gauge; gains fall by 0.03-0.08 (displacement) and 0.08-0.2 (current) per unit of
    the displacement scale (inject_fresh3._resist). Measured (s001_110): displacement RMS -4.7 % (residual 4.9 %, 150x
    its noise), the 1 V steps -6.6 % by the plateau's end, the gauge at 0.46 of its size just after each edge and each
    fall and back to 0.85 by the plateau's end; current residual 2.6 % (5x its noise), -12.7 % by the plateaus' ends."""
    side, b, o, tau_o = _sign(s), s.rng.uniform(0.5, 0.9), s.rng.uniform(0.1, 0.3), lu(s.rng, 20.0, 100.0)
    ic = s.rng.uniform(0.3, 0.6) * max(float(np.max(np.abs(r.cols["i_A"]))) for r in s.series())
    rate = 200.0  # /s per unit of overcurrent: the welding is fast against a sample

    def step(x: float, i: float, dt: float) -> float:
        x *= math.exp(-dt / tau_o)
        over = abs(i) / ic - 1
        return x + (1 - x) * -math.expm1(-rate * over * dt) if over > 0 else x

    fr = _walk(s, step, "i_A", 0.0, lambda x, sec: x * math.exp(-sec / tau_o))

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        return (1 - b * fr[id(r)]) * np.clip(side * e, 0, None) + o * np.clip(-side * e, 0, None)

    _resist(s, shape, (0.03, 0.08), (0.08, 0.2))


def sr_substrate_relaxation(s: Session) -> None:
    """The cracks' opening follows the film's stress, not its strain: the soft polymer under the cracked platinum
    relaxes its shear over tau 1-10 s (log), so a held bend's film stress (and the cracks' opening and resistance) falls
    to 1 - c of its first value (c 0.4-0.8): the gauge sees e - c LP_tau(e), its full size on the fast records and the
    steps' edges, much less on the held plateaus and the slowest sines (the opposite of a crack that opens by creep).
    The tensioned face (side drawn) with the other at 0.1-0.3 of its gauge; the lag with the session's history
    (inject_fresh3._through_x); gains fall by 0.04-0.1 (displacement) and 0.1-0.25 (current) per unit of the session's
    largest bend (inject_fresh3._resist). Measured (p37_111): displacement RMS -3.2 % (residual 3.3 %, 290x its noise);
    the 1 V steps -1.4 % 1 s after the edge and -4.5 % by the plateau's end (c 0.55: the unrelaxed gauge would take
    about -10 % there), the 1 V harmonic's crests -2.6 %, its troughs -0.15 %; current residual 1.2 % (0.6x its noise),
    -5.9 % by the steps' plateaus' ends."""
    side, c, tau, o = _sign(s), s.rng.uniform(0.4, 0.8), lu(s.rng, 1.0, 10.0), s.rng.uniform(0.1, 0.3)
    big = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series())
    e = {id(r): r.cols["disp_m"] / big for r in s.series()}
    lp = _through_x(s, e, lambda r: lambda z: 1 / (tau * z + 1), min(5 * tau, 60.0))
    eff = {k: e[k] - c * lp[k] for k in e}

    def shape(r: Rec, _: np.ndarray) -> np.ndarray:
        x = eff[id(r)]
        return np.clip(side * x, 0, None) + o * np.clip(-side * x, 0, None)

    _resist(s, shape, (0.04, 0.1), (0.1, 0.25))


# ------------------------------------------------------------------------------------------------ large deflection


def _vial_map(radius: float, n: float = 1.333) -> tuple[np.ndarray, np.ndarray]:
    """A water-filled round vial seen from far off through its side: a point on the axis' plane at lateral y appears at
    h, y = h - sqrt(R^2 - h^2) tan(alpha - beta), sin(alpha) = h/R, sin(beta) = h/(n R) (Snell at the wall, the glass
    thin). Returns (y, h) on a grid (y increasing)."""
    h = np.linspace(-0.995, 0.995, 4001) * radius
    al = np.arcsin(h / radius)
    be = np.arcsin(h / (n * radius))
    return h - np.sqrt(radius**2 - h**2) * np.tan(al - be), h


def ld_round_vial(s: Session) -> None:
    """Video tracking through a round glass vial (a beaker or a test tube as the bath, a common bench set-up): the strip
    hangs along the vial's axis and bends across it, the camera looks through its side from far off, and the
    water-filled cylinder is a lens: a point at lateral y appears at h(y) (Snell at the wall, _vial_map), magnified
    n-fold near the axis and more towards the wall. The lab calibrates the image's scale by a small known move at rest,
    so the reading is (h(y0 + Y) - h(y0))/h'(y0): the tip's material point on the exact arc (Y, inject_fresh8._arc) read
    through the vial's distortion, the vial's radius 2-4 times the session's largest bend (log), the strip's rest off
    the axis by 0-0.3 of the radius (either side): odd and even terms that grow with the bend. Displacement only.
    Measured (paper_109): the 1 V steps' peaks -7.1 % (the arc alone -2.9 %), the 1 V harmonic's crests -1.7 % and
    troughs +0.04 %; displacement RMS -3.9 % (residual 4.3 %, 260x its noise)."""
    rad = lu(s.rng, 2.0, 4.0) * _tip_steps(s)
    y0 = _sign(s) * s.rng.uniform(0.0, 0.3) * rad
    ys, hs = _vial_map(rad)
    h = lambda y: np.interp(y, ys, hs)  # noqa: E731
    slope = float((h(np.array([y0 + 1e-6])) - h(np.array([y0 - 1e-6])))[0] / 2e-6)
    h0 = float(h(np.array([y0]))[0])

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        _, Y, _ = _arc(d, float(s.specimen["length_m"]))
        return (h(y0 + Y) - h0) / slope

    map_disp(s, read)


def ld_jaw_tilt(s: Session) -> None:
    """Jaws whose faces are not parallel (a worn or mis-machined pair): tightening squeezes one edge more and turns the
    strip's root by beta, growing with the pressure, beta = beta_top (p - p_min)/(p_max - p_min), beta_top 3-8 deg
    (either way), the operator re-zeroing the camera after each re-clamping. The camera tracks the tip's material point
    on the exact arc (inject_fresh8._arc) in the lab's frame, where the arc is turned by beta: Y cos(beta) - (L - X)
    sin(beta): the arc's odd compression in every block and an even part, its draw-back times the tilt, that grows block
    by block with the pressure. Displacement only. Measured (p37_111): the 1 V steps' peaks -4.2, -3.3, -2.5, -2.0 %
    block by block (the arc alone in the first), the 1 V harmonics' crests and troughs -1.0 / 0.0 % in the first block,
    -0.34 / -0.91 % in the last; displacement residual 1.9 % (160x its noise)."""
    top, side = math.radians(s.rng.uniform(3.0, 8.0)), _sign(s)
    lo, hi = min(s.pressures()), max(s.pressures())
    L = float(s.specimen["length_m"])

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        beta = side * top * (float(r.entry["pressure_kPa"]) - lo) / max(hi - lo, 1e-9)
        _, Y, X = _arc(d, L)
        return Y * math.cos(beta) - (L - X) * math.sin(beta)

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_cord_field(s: Session) -> None:
    """A desk lamp's mains cord lying beside a strip in air: its electric field couples to the strip's exposed
    electrodes through a capacitance that grows as the tip swings towards the cord (a plate facing a wire, C ~ g0/(g0 -
    d), the cord g0 = 2-5 times the session's largest bend away, on either side), so the hum the current amplifier sees
    (the line at 50 or 60 Hz with its 3rd, 0.1-0.3; 5-20 uA at rest, log) is modulated by the bend: more on the steps'
    plateaus towards the cord, less away, sidebands about the line at the drive's frequencies; the laser's cable picks
    up a steady 1-3 um (log) of the same line. Measured (s001_110): the current's hum 9.2 uA RMS at rest before the
    steps, 11.0 uA on their plateaus (0.7x the current's noise over all); the displacement's 1.2 um RMS (2.0x its
    noise), the 20 Hz records' residuals 5-6 %."""
    f0, side, g0 = _line_f(s), _sign(s), lu(s.rng, 2.0, 5.0) * _tip_steps(s)
    h3, ai, ad = s.rng.uniform(0.1, 0.3), lu(s.rng, 5e-6, 2e-5), lu(s.rng, 1e-6, 3e-6)
    pi_, pd = s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        r.cols["i_A"] = r.cols["i_A"] + ai * g0 / (g0 - side * d) * _hum(t, f0, {3: h3}, pi_)
        r.cols["disp_m"] = d + ad * _hum(t, f0, {3: h3}, pd)


def mp_reference_ripple(s: Session) -> None:
    """A USB-powered DAQ whose analogue output takes its reference from the bus's 5 V, which a ground loop through the
    computer fills with mains ripple (the line at 50 or 60 Hz with its 3rd, 0.2-0.5): the output is ratiometric, so the
    strip is driven with v (1 + eps hum(t)), eps 0.2-1 % (log), while the DAQ logs the command it wrote: a hum that
    exists only while the drive is on and is proportional to it, reaching the current through the strip's admittance at
    the line and its 3rd (labrig.physics.transfer, at the record's pressure; v changes slowly against the line, so each
    record's hum is v(t) |Y| cos(...+ arg Y)) and the displacement through its (small) response there. Measured
    (paper_109): the current's hum 63 uA RMS on the 1 V steps' plateaus, nothing at rest; current residual 1.0 % of its
    RMS (0.5x its noise over all), +-0.11 mA on the 1 V harmonic's crests; displacement below 0.01 %."""
    from labrig.physics import transfer

    f0, eps, h3 = _line_f(s), lu(s.rng, 2e-3, 1e-2), s.rng.uniform(0.2, 0.5)
    ph = s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        sp = _spec(s, r)
        t, v = r.cols["t_s"], r.cols["v_V"]
        for n, a in ((1, 1.0), (3, h3)):
            z = np.array([2j * np.pi * n * f0])
            w = 2 * np.pi * n * f0 * t + n * ph
            for col, tf in (("i_A", transfer.admittance_tf), ("disp_m", transfer.displacement_tf)):
                g = complex(tf(z, sp)[0])
                r.cols[col] = r.cols[col] + eps * a * v * abs(g) * np.cos(w + np.angle(g))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_protruding_jaw(s: Session) -> None:
    """One jaw protrudes past the other by l_j 0.8-2.5 mm (log; a jaw mis-set or a pad cut long): bent towards it, the
    strip lies against its underside there and bends only over the rest of its length, so that side reads (1 - l_j/L)^2
    of the free bend (the quasi-static uniform curvature), the other side all of it: a gain that changes with the bend's
    sign and nothing else (no memory, no amplitude dependence beyond the sign), even harmonics on every sine.
    Displacement only. Measured (paper_109): the jaw on the side the steps do not bend to: the 0.5 V sines' troughs -5.4
    %, their crests and the steps untouched, displacement residual 0.36 % (22x its noise); (p37_111) on the steps' side:
    their peaks -4.7 %, residual 4.7 %."""
    side, lj = _sign(s), lu(s.rng, 8e-4, 2.5e-3)
    k = (1 - lj / float(s.specimen["length_m"])) ** 2
    map_disp(s, lambda r, d: np.where(side * d > 0, k * d, d))


def out_monitor_clip(s: Session) -> None:
    """The drive amplifier's gain is 3-6 % high and its output is monitored (v_V) on the DAQ's +-1 V range, whose top
    code sits at 1.000-1.01 V: every record's strip signals are (1 + g) of the commanded drive's and the monitor reads
    them right, but on the 1 V records the monitor clips at the range's end (the steps' plateaus, the harmonic's tops):
    the recorded drive is short of what the strip got by 2-6 % there and only there (v_V re-read at the range's 16-bit
    step). v_V, current and displacement. Measured (s001_110): v_V 1.004 V on the 1 V plateaus where the strip got 1.035
    V (3.0 % short), current and displacement +3.5 % throughout; (p37_111): 1.010 V for 1.054 V (4.2 % short), +5.4 %.
    """
    g, top, q = s.rng.uniform(0.03, 0.06), s.rng.uniform(1.0, 1.01), 2.0 / 65536
    for r in s.series():
        for col in ("i_A", "disp_m"):
            r.cols[col] = r.cols[col] * (1 + g)
        r.cols["v_V"] = np.round(np.clip(r.cols["v_V"] * (1 + g), -top, top) / q) * q


def out_loadcell_drift(s: Session) -> None:
    """The load cell's zero warms up: a strain-gauge cell beside the clamp's motor (or under a lamp) warms by 10-25 K
    from its switch-on 0-300 s before the first record (time constant 600-2000 s, log) and its bridge's zero moves by
    0.03-0.05 % of its 98 N span per K (either way): the force it reports drifts by 0.3-1.2 N through the session while
    the clamp and the strip do not change at all (re-read at the indicator's 0.01 kgf). The force column only. Measured
    (paper_109): +0.49, +0.78, +0.78, +0.81 N by the blocks' ends (1.050 of the lowest block's force, 1.012 of the top
    one's); (s001_110): -0.49 to -0.59 N (0.980 of the lowest block's)."""
    dT, lead, tau = s.rng.uniform(10.0, 25.0), s.rng.uniform(0.0, 300.0), lu(s.rng, 600.0, 2000.0)
    z = _sign(s) * dT * s.rng.uniform(3e-4, 5e-4) * 98.0
    for r in s.series():
        if "force_N" in r.cols:
            drift = z * -np.expm1(-(r.cols["t_s"] - s.t0 + lead) / tau)
            r.cols["force_N"] = np.round((r.cols["force_N"] + drift) / KGF) * KGF


def out_swapped_labels(s: Session) -> None:
    """A bookkeeping fault: two adjacent pressure blocks' pressures swapped when the manifest was written (by hand, from
    the lab book), every record of each block labelled with the other's pressure (pressure_kPa, and the label's prefix):
    the data are the strip's at its true pressures, the load cell still reads each block's true force, the manifest says
    otherwise. The blocks drawn among the session's adjacent pairs in time. The manifest only; no column changes.
    Measured (s001_110): the 1300 and 1700 kPa blocks swapped; (p37_111): the 612 and 1837 kPa blocks."""
    order = sorted(_blocks(s).items(), key=lambda kv: kv[1][0])
    j = int(s.rng.integers(0, len(order) - 1))
    a, b = order[j][0], order[j + 1][0]
    swap = {a: b, b: a}
    for r in s.recs:
        p = float(r.entry["pressure_kPa"])
        if p in swap:
            q = swap[p]
            r.entry = dict(r.entry, pressure_kPa=q)
            lab = r.entry.get("label")
            if isinstance(lab, str) and lab.startswith(f"p{p:g}/"):
                r.entry["label"] = f"p{q:g}/" + lab[len(f"p{p:g}/"):]


FRESH13_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"compliant_channels": br_compliant_channels, "conditioning": br_conditioning},
    "faradaic_current": {"metal_shuttle": far_metal_shuttle, "motion_stirring": far_motion_stirring},
    "hysteresis": {"bauschinger_film": hy_bauschinger_film, "bingham_drive": hy_bingham_drive},
    "time_delay": {"x7r_filter": td_x7r_filter, "mains_notch": td_mains_notch},
    "sensor_offset": {"range_reaim": so_range_reaim, "template_drift": so_template_drift},
    "clamp_relaxation": {"solenoid_heating": cr_solenoid_heating, "magnet_clamp": cr_magnet_clamp},
    "dehydration": {"sorption_hysteresis": dh_sorption_hysteresis, "pad_suction": dh_pad_suction},
    "strain_resistance": {"fritting": sr_fritting, "substrate_relaxation": sr_substrate_relaxation},
    "large_deflection": {"round_vial": ld_round_vial, "jaw_tilt": ld_jaw_tilt},
    "mains_pickup": {"cord_field": mp_cord_field, "reference_ripple": mp_reference_ripple},
    "unexplained": {"protruding_jaw": out_protruding_jaw, "monitor_clip": out_monitor_clip,
                    "loadcell_drift": out_loadcell_drift, "swapped_labels": out_swapped_labels},
}
inject.register_forms(FRESH13_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_coherent_sines(s: Session) -> None:
    """A frequency-response logger clocked from its own generator (a frequency-response analyser's or a DAQ's 'coherent
    sampling': the sample clock a multiple of the drive's frequency, so no sine leaks): every sine record (the harmonic
    and the stepped sines) sampled at N points per drive period (N 32 or 40 for the session, at most the record's own
    rate) by an integrating converter, each value the mean of the signal over its sample period centred on its stamp
    (from the record's own samples, linear between them; the record's ends averaged over the part inside it), the first
    stamp at the record's first sample; the steps, the spectra and the manifest as they were, the session clock kept.
    ``labrig import`` takes it (t_s strictly increasing, the rate read off the data)."""
    n = 32 if s.rng.random() < 0.5 else 40
    for r in s.series():
        f = r.entry.get("frequency_Hz")
        if r.kind not in ("harmonic", "stepped_sine") or not f or n * float(f) > r.fs * 1.0001:
            continue
        t = r.cols["t_s"]
        T = 1.0 / (n * float(f))
        tn = t[0] + T * np.arange(int(math.floor((t[-1] - t[0]) / T + 1e-9)) + 1)
        lo, hi = np.clip(tn - T / 2, t[0], t[-1]), np.clip(tn + T / 2, t[0], t[-1])
        out = {"t_s": tn}
        for k, x in r.cols.items():
            if k == "t_s":
                continue
            cum = np.r_[0.0, np.cumsum(0.5 * (x[1:] + x[:-1]) * np.diff(t))]

            def area(u: np.ndarray) -> np.ndarray:  # the integral of the piecewise-linear x from t[0] to u
                j = np.clip(np.searchsorted(t, u, side="right") - 1, 0, t.size - 2)
                du = u - t[j]
                slope = (x[j + 1] - x[j]) / (t[j + 1] - t[j])
                return cum[j] + x[j] * du + 0.5 * slope * du**2

            out[k] = (area(hi) - area(lo)) / (hi - lo)
        r.cols = out


inject.VARIANTS.update({"coherent_sines": v_coherent_sines})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_109", "s001_110", "p37_111"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 109-111
    "back_relaxation": [("compliant_channels", 109, P, "asrun"), ("conditioning", 111, T, "dropped_packets")],
    "faradaic_current": [("metal_shuttle", 109, P, "eis_descending"), ("motion_stirring", 111, T, "short_pretrigger")],
    "hysteresis": [("bauschinger_film", 110, S, "settled_sines"), ("bingham_drive", 109, P, "coherent_sines")],
    "time_delay": [("x7r_filter", 111, T, "asrun"), ("mains_notch", 110, S, "rate07")],
    "sensor_offset": [("range_reaim", 111, T, "two_pressures"), ("template_drift", 109, P, "asrun")],
    "clamp_relaxation": [("solenoid_heating", 109, P, "merged_loadcell"), ("magnet_clamp", 110, S, "asrun")],
    "dehydration": [("sorption_hysteresis", 110, S, "asrun"), ("pad_suction", 110, S, "host_timed")],
    "strain_resistance": [("fritting", 110, S, "coherent_sines"), ("substrate_relaxation", 111, T, "steps_sines")],
    "large_deflection": [("round_vial", 109, P, "float32_time"), ("jaw_tilt", 111, T, "shortened_shuffled")],
    "mains_pickup": [("cord_field", 110, S, "own_clock"), ("reference_ripple", 109, P, "no_spectra")],
    "unexplained": [("protruding_jaw", 109, P, "asrun"), ("protruding_jaw", 111, T, "coherent_sines"),
                    ("monitor_clip", 110, S, "resampled"), ("monitor_clip", 111, T, "asrun"),
                    ("loadcell_drift", 109, P, "trigger_clock"), ("loadcell_drift", 110, S, "asrun"),
                    ("swapped_labels", 110, S, "asrun"), ("swapped_labels", 111, T, "decimated3")],
}
CLEAN = [(109, P, "asrun"), (109, P, "coherent_sines"), (110, S, "asrun"), (110, S, "no_loadcell"),
         (111, T, "asrun"), (111, T, "coherent_sines")]


def fresh13_cases(only: str | None = None) -> list[Case]:
    """The fourteenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds 109-111).
    """
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh13_cases, "inject_fresh13", "fresh13")
