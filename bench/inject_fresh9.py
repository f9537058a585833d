"""A tenth held-out set for the diagnosis (issue 12), written without sight of the diagnosis (its code, its doc,
its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh8.py and the simulated
bench (mock_devices/effects.py), most of them present in only part of the session, changing with the clamp pressure
or with time, acting on one channel, or carrying a memory; four structures outside the catalogue (truth
"unexplained": a slow drift of the drive amplifier's output offset that the recorded command does not show, a
draught or a circulator's jet buffeting the strip in spells, a pneumatic isolation table sinking and re-levelling
under a leaning hand, a handheld radio's transmissions rectified in the current amplifier); clean sessions. All on
three bases of new seeds (97-99: the paper strip, the seed-001 strip on its own sweep, the paper strip 42 mm free) and
on the earlier sets' protocol / data-shape variants plus one new here: the load cell logged by its own indicator and
merged onto the DAQ's rows on time stamps (each row carrying the latest indicator reading stamped at or before it, as
a merge-as-of join writes it, the merged file's columns in the join's order: the import contract reads columns by
their header names and asks only t_s strictly increasing).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh8 are reused (importing inject_fresh8 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import. Strengths are drawn from
the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case, measured in
memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the column's
sample-to-sample noise at rest, from the samples before the step records' edges: 0.56 um and 15 uA on paper_97,
0.59 um and 15 uA on p42_99, 0.56 um and 4.4 uA on s001_98).

Run: python bench/inject_fresh9.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal

import inject
from inject import Case, Rec, Session, lti, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _drive_side, _spec, _through
from inject_fresh3 import _cat, _resist, _sign
from inject_fresh4 import _clamp_law, _preset
from inject_fresh6 import _blocks, _bursts, _reading
from inject_fresh7 import KGF, _ramp_env, _superpose
from inject_fresh8 import _late

# the paper's strip 42 mm free (earlier sets used 20, 25, 28, 30, 32, 35, 38, 40 and 45 mm; its 1 V step peaks at
# 16.8 mm, inside the laser's +-20 mm): registered in every process that imports this module
inject.register_free_length("paper_42", 0.042)

inject.BASES.update({
    "paper_97": ("paper-sweep", "paper", 97),
    "s001_98": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 98),
    "p42_99": ("paper-sweep", "paper_42", 99),
})

G_N = 9.81  # m/s^2


# ------------------------------------------------------------------------------------------------ tools


def _gaps(s: Session, step: float):
    """The session's records in time order, each with the rest before it cut into sub-steps of at most ``step`` seconds:
    yields (record, [(dt, fraction of the way from the last record's end to this record's start)])."""
    t_end = None
    for r in _chrono(s):
        t0 = float(r.cols["t_s"][0])
        sub = []
        if t_end is not None and t0 > t_end:
            n = max(int(math.ceil((t0 - t_end) / step)), 1)
            sub = [((t0 - t_end) / n, (k + 0.5) / n) for k in range(n)]
        yield r, sub
        t_end = float(r.cols["t_s"][-1])


def _session_grid(s: Session, dt: float, lead: float = 0.0) -> np.ndarray:
    return np.arange(s.t0 - lead, s.t1 + dt, dt)


def _ou(s: Session, tg: np.ndarray, tau: float) -> np.ndarray:
    """A unit-variance Ornstein-Uhlenbeck process (correlation time tau) on the grid tg, from its stationary state."""
    x = np.empty(tg.size)
    x[0] = s.rng.normal()
    a = np.exp(-np.diff(tg) / tau)
    w = s.rng.normal(size=tg.size - 1) * np.sqrt(1 - a**2)
    for k in range(1, tg.size):
        x[k] = a[k - 1] * x[k - 1] + w[k - 1]
    return x


def _heavy_strip(L: float, EI: float, q: float, kappa: np.ndarray) -> np.ndarray:
    """The tip's height of a strip clamped horizontal at s = 0 under a uniform actuation curvature kappa (an
    eigen-moment) and its own net weight q per length (N/m, downwards), exact (large rotations): theta' = kappa + M/EI,
    M' = q (L - s) cos(theta) (the weight of the part beyond s on its horizontal lever arms), M(L) = 0, theta(0) = 0.
    Shooting on M(0) (secant, vectorised over kappa), RK4 on 600 steps. Returns Y(L) = int sin(theta)."""
    kappa = np.asarray(kappa, float)
    n, h = 600, L / 600

    def shoot(m0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        th, m, y = np.zeros_like(kappa), m0.copy(), np.zeros_like(kappa)

        def f(sv: float, th: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            return kappa + m / EI, q * (L - sv) * np.cos(th), np.sin(th)

        for k in range(n):
            sv = k * h
            a1 = f(sv, th, m)
            a2 = f(sv + h / 2, th + h / 2 * a1[0], m + h / 2 * a1[1])
            a3 = f(sv + h / 2, th + h / 2 * a2[0], m + h / 2 * a2[1])
            a4 = f(sv + h, th + h * a3[0], m + h * a3[1])
            th = th + h / 6 * (a1[0] + 2 * a2[0] + 2 * a3[0] + a4[0])
            m = m + h / 6 * (a1[1] + 2 * a2[1] + 2 * a3[1] + a4[1])
            y = y + h / 6 * (a1[2] + 2 * a2[2] + 2 * a3[2] + a4[2])
        return m, y

    m0 = np.full_like(kappa, -q * L**2 / 2)
    m1 = m0 * 1.01 - 1e-6 * EI / L
    r0, r1 = shoot(m0)[0], shoot(m1)[0]
    for _ in range(40):
        den = r1 - r0
        m2 = np.where(den != 0, m1 - r1 * (m1 - m0) / np.where(den != 0, den, 1.0), m1)
        m0, r0, m1 = m1, r1, m2
        r1 = shoot(m1)[0]
        if np.max(np.abs(r1)) < 1e-11 * (np.max(np.abs(m1)) + EI / L):
            break
    return shoot(m1)[1]


def _dry_by(s: Session, disp_loss: Callable[[np.ndarray], np.ndarray],
            cond_loss: Callable[[np.ndarray], np.ndarray]) -> None:
    """inject._dry with separate laws (session time -> loss) for the gain and the conductance: the displacement x (1 -
    disp_loss), the current x (1 - cond_loss), a spectrum taken at the start of the time series recorded after it, its
    impedance / (1 - cond_loss) there."""
    for k, r in enumerate(s.recs):
        if r.series:
            t = r.cols["t_s"]
            r.cols["disp_m"] = r.cols["disp_m"] * (1 - disp_loss(t))
            r.cols["i_A"] = r.cols["i_A"] * (1 - cond_loss(t))
            continue
        after = next((q for q in s.recs[k + 1:] if q.series), None)
        x = float(cond_loss(np.array([after.cols["t_s"][0] if after else s.t1]))[0])
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = r.cols["z_re_ohm"] / (1 - x), r.cols["z_im_ohm"] / (1 - x)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_capillary_entry(s: Session) -> None:
    """The back-flow leaves the cathode's side through the plated electrode's hydrophobic pores, and water enters a pore
    only above its capillary entry pressure (Laplace, 2 gamma cos(theta)/r): a Bingham-like flow. The water pushed
    towards the cathode (in units of the fast bend d) builds a pressure with the part not yet returned, d - w, and flows
    back at (abs(d - w) - p_e)+ sign(d - w)/tau (tau 3-12 s, log; p_e 0.04-0.12 of the displacement scale), beside a
    slow leak through the polymer bulk, (d - w)/tau_l (tau_l 4-12 tau); the reading is d - K2 w, K2 0.9-1.3. Small or
    fast motions stay inside the entry pressure and give nothing back, and water trapped below it after a large bend is
    released only by the slow leak (a remanent reversed bend that fades over minutes). Sample by sample through the
    session in time order (the rests included, the fast part linear across them). Measured (paper_97): displacement RMS
    -63 % (residual 90 % of its RMS), the 1 V steps' peaks -81 % (2.9 mm at 7.6 s instead of 8.8 mm), 20 Hz record
    residual 19-202 % (the slow leak's remnant)."""
    k2, tau, pe, tl = s.rng.uniform(0.9, 1.3), lu(s.rng, 3.0, 12.0), s.rng.uniform(0.04, 0.12), s.rng.uniform(4.0, 12.0)
    th, tl = pe * ref_disp(s), tl * tau
    w, d_end = 0.0, 0.0

    def rate(x: float, w: float) -> float:
        e = x - w
        return (math.copysign(abs(e) - th, e) if abs(e) > th else 0.0) / tau + e / tl

    for r, gap in _gaps(s, 0.1):
        d = r.cols["disp_m"]
        for dt, u in gap:
            w += dt * rate(d_end + u * (float(d[0]) - d_end), w)
        out, dt = np.empty(d.size), 1.0 / r.fs
        for k, x in enumerate(d.tolist()):
            w += dt * rate(x, w)
            out[k] = w
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


def br_bath_topup(s: Session) -> None:
    """An open bath of tap or saline water, topped up with deionised water by the operator at one re-clamping after the
    first (20-60 s before that block's first record) to make up for what had evaporated: the bath's ionic strength
    falls, the membrane swells more (Donnan) and its clusters hold more free water, so the back-flow grows and quickens:
    K2 from 0.5-0.8 to 1.0-1.3, tau from 6-15 s (log) to 0.4-0.7 of it, along the membrane's re-equilibration 1 -
    exp(-t/tau_eq) (tau_eq 60-300 s, log) after the top-up, nothing before it. A lag with a time-varying K2 and time
    constant, sample by sample through the session in time order (the state carried over the rests), reading d - K2 x.
    Measured (p42_99, topped up before the 3062 kPa block): the 1 V steps peak at 6.6 mm (-60 %) on their plateau's end
    before it, at 4.7 mm after 6.4 s and 3.1 mm after 2.8 s (then reversing) after it; displacement RMS -62 % (residual
    89 %)."""
    k2a, k2b = s.rng.uniform(0.5, 0.8), s.rng.uniform(1.0, 1.3)
    ta = lu(s.rng, 6.0, 15.0)
    tb, teq = ta * s.rng.uniform(0.4, 0.7), lu(s.rng, 60.0, 300.0)
    starts = sorted(a for a, _ in _blocks(s).values())
    at = starts[int(s.rng.integers(1, len(starts)))] if len(starts) > 1 else starts[0]
    t_up = at - s.rng.uniform(20.0, 60.0)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x = np.where(t > t_up, -np.expm1(-np.clip(t - t_up, 0, None) / teq), 0.0)
        return k2a + (k2b - k2a) * x, ta * (tb / ta) ** x

    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 1.0):
        t, d = r.cols["t_s"], r.cols["disp_m"]
        for dt, u in gap:
            tau = float(state(np.array([float(t[0]) - (1 - u) * dt * len(gap)]))[1][0])
            x += -math.expm1(-dt / tau) * (d_end + u * (float(d[0]) - d_end) - x)
        K2, tau = state(t)
        out = np.empty(d.size)
        for k, (dk, ak) in enumerate(zip(d.tolist(), np.exp(-1.0 / (r.fs * tau)).tolist())):
            x = dk + (x - dk) * ak
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - K2 * out


# ------------------------------------------------------------------------------------------------ faradaic current


def far_clamp_crevice(s: Session) -> None:
    """Electrolysis in the clamp's crevice: where the jaw's contact meets the strip's electrode the water the pads leave
    (the strip's own, or wicked from the bath) carries a Butler-Volmer current, 2 i0 sinh(u/2v_t) (v_t 0.1-0.2 V) at the
    interface's share u of the terminal voltage, in series with the ohmic path through the thin wet film (u = v - R i, R
    i 0.1-0.3 V at 1 V, per unit of wetted area). The pads squeeze the film: its wetted area falls as (p_min/p)^m (m
    0.5-1.2), so the current, 0.1-0.4 mA at 1 V on the lowest pressure (log), keeps its wave's shape (exponential onset,
    then ohmic) and falls block by block. Implicit in i, solved by bisection on u per sample. Current only. Measured
    (s001_98): current RMS +1.9 %, residual 4.1 % of its RMS (27x its noise); on the 1 V steps' plateaus 0.33, 0.24,
    0.20, 0.17 mA block by block."""
    i1, vt, drop, m = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.5, 1.2)
    pmin = min(s.pressures())
    R1, i0 = drop / i1, i1 / (2 * math.sinh((1 - drop) / (2 * vt)))
    for r in s.series():
        v = r.cols["v_V"]
        lo, hi = np.minimum(v, 0.0), np.maximum(v, 0.0)
        for _ in range(60):  # u + R1 2 i0 sinh(u/2v_t) = v (per unit of wetted area), increasing in u
            u = 0.5 * (lo + hi)
            big = u + 2 * i0 * R1 * np.sinh(u / (2 * vt)) > v
            hi, lo = np.where(big, u, hi), np.where(big, lo, u)
        area = (pmin / float(r.entry["pressure_kPa"])) ** m
        r.cols["i_A"] = r.cols["i_A"] + area * (v - 0.5 * (lo + hi)) / R1


def far_reaeration(s: Session) -> None:
    """An oxygen shuttle limited by the bath's dissolved oxygen, in a bath filled with degassed water (freshly deionised
    or boiled water, or a nitrogen-purged bath, 300-1500 s before the session's first record): O2 reduced on the
    cathodic face and regenerated on the anodic one, kinetics sinh(v/v_s) (v_s 0.1-0.2 V, the kinetic current at 1 V
    2-5x the transport limit) in series with the O2 transport to the face (Koutecky-Levich, i = i_k/(1 +
    abs(i_k)/i_lim)), the limit following the bath's re-aeration through its open surface: i_lim = i_sat (1 - (1 - c0)
    exp(-t/tau_a)), c0 0.1-0.3 of saturation at filling, tau_a 1000-4000 s (log), i_sat 0.1-0.4 mA (log). A saturating
    wave at 1 V that grows through the session; nearly nothing on the 0.5 V sines. Current only. Measured (paper_97):
    current RMS +0.7 %, residual 2.4 % (5.1x its noise); on the 1 V steps' plateaus 0.14, 0.18, 0.19, 0.19 mA block by
    block."""
    c0, ta, isat = s.rng.uniform(0.1, 0.3), lu(s.rng, 1000.0, 4000.0), lu(s.rng, 1e-4, 4e-4)
    kin, vs, fill = s.rng.uniform(2.0, 5.0), s.rng.uniform(0.1, 0.2), s.rng.uniform(300.0, 1500.0)
    for r in s.series():
        v = r.cols["v_V"]
        lim = isat * (1 - (1 - c0) * np.exp(-(r.cols["t_s"] - s.t0 + fill) / ta))
        ik = kin * isat * np.sinh(v / vs) / math.sinh(1 / vs)
        r.cols["i_A"] = r.cols["i_A"] + ik / (1 + np.abs(ik) / lim)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_eyring_slip(s: Session) -> None:
    """Dry friction with thermally activated creep (Eyring; the platelets of a cracked electrode or pinned cluster
    domains): a play of radius r (0.1-0.3 V) on the drive that slips at once when the drive leaves its band, and while
    held inside it creeps towards the drive at (r/tau_c) sinh((v - z)/sigma)/sinh(r/sigma) (sigma 0.15-0.3 r, tau_c
    20-200 s, log): fast just after a reversal, slowing as it goes (the logarithmic creep of friction). A share h
    0.15-0.3 of the drive goes through it, Gamma = (1 - h) v + h z; the loop stays at 0.1 Hz and narrows on the slowest
    drives, and a held bend creeps after each reversal. Its state through the session in time order (the rests
    included); Gamma - v reaches the displacement through the strip's measured step response
    (inject_fresh2._drive_side); current untouched. Measured (paper_97): displacement residual 7.2 % of its RMS (430x
    its noise), the 1 V steps' peaks -2.0 to -4.3 %; the 20 Hz records (5 um of signal) drift by 0.1 mm as the play held
    since the record before is released."""
    h, r0 = s.rng.uniform(0.15, 0.3), s.rng.uniform(0.1, 0.3)
    sig, tc = r0 * s.rng.uniform(0.15, 0.3), lu(s.rng, 20.0, 200.0)
    c = r0 / tc / math.sinh(r0 / sig)

    def step(z: float, v: float, dt: float) -> float:
        e = min(max(v - z, -r0), r0)
        zc = z + dt * c * math.sinh(e / sig)
        z = zc if (v - zc) * e > 0 else v  # the creep never overshoots the drive
        return min(max(z, v - r0), v + r0)  # and the band slips with the drive

    z, v_end, parts = 0.0, 0.0, []
    for r, gap in _gaps(s, 0.25):
        v = r.cols["v_V"]
        for dt, u in gap:
            z = step(z, v_end + u * (float(v[0]) - v_end), dt)
        out, dt = np.empty(v.size), 1.0 / r.fs
        for k, x in enumerate(v.tolist()):
            z = step(z, x, dt)
            out[k] = z
        v_end = float(v[-1])
        parts.append((1 - h) * v + h * out)
    gam = np.concatenate(parts)
    _drive_side(s, lambda v: gam)


def hy_aging_relays(s: Session) -> None:
    """Preisach relays on the drive that age: domains of the strip's actuation (pinned cluster regions) switch up above
    c + w and down below c - w, and a domain left long in its state sinks deeper into its pinning (contact aging,
    accommodation): its half-width grows as w (1 + g ln(1 + t_w/theta)) with the time t_w since it last switched (g
    0.1-0.3, theta 0.5-5 s, log). 48 relays, centres c ~ N(0, 0.1-0.25 V), half-widths w log-normal about 0.08-0.2 V
    (spread x e^0.6); a share h 0.1-0.2 of the drive, Gamma = (1 - h) v + h V_max mean(state). After each rest the first
    excursion needs more drive (a wider first loop), on fast sines the loop narrows (the relays switch before they can
    age). Their states through the session in time order; through the strip's measured step response
    (inject_fresh2._drive_side); current untouched. Measured (s001_98): displacement RMS +13 % (residual 21 %), the 1 V
    steps' peaks -1.1 % in the first block and +8.7 % in the later ones (each starting from the remanence the block
    before left), 20 Hz records' residuals 380-500 %."""
    n = 48
    h, g, theta = s.rng.uniform(0.1, 0.2), s.rng.uniform(0.1, 0.3), lu(s.rng, 0.5, 5.0)
    c = s.rng.normal(0.0, s.rng.uniform(0.1, 0.25), n)
    w = s.rng.uniform(0.08, 0.2) * np.exp(0.6 * s.rng.normal(size=n))
    recs = _chrono(s)
    vmax = max(float(np.max(np.abs(r.cols["v_V"]))) for r in recs) or 1.0
    state, last = -np.sign(c), np.full(n, recs[0].cols["t_s"][0] - 60.0)
    parts = []
    for r in recs:
        t, v = r.cols["t_s"], r.cols["v_V"]
        out = np.empty(v.size)
        m = float(np.mean(state))
        for k, (tk, x) in enumerate(zip(t.tolist(), v.tolist())):
            wid = w * (1 + g * np.log1p((tk - last) / theta))
            up, down = (state < 0) & (x > c + wid), (state > 0) & (x < c - wid)
            if up.any() or down.any():
                flip = up | down
                state = np.where(flip, -state, state)
                last = np.where(flip, tk, last)
                m = float(np.mean(state))
            out[k] = m
        parts.append((1 - h) * v + h * vmax * out)
    gam = np.concatenate(parts)
    _drive_side(s, lambda v: gam)


# ------------------------------------------------------------------------------------------------ time delay


def td_averaging_switched(s: Session) -> None:
    """The laser's averaging changed by the operator at a re-clamping after the first (the early blocks looked noisy):
    from that block on the controller's recursive (exponential) average, y += (x - y)/N at its internal rate (a
    first-order lag of tau = N/f_int, 4-25 ms, log) smooths and delays the reading; before it, nothing. A delay present
    in part of the session only, with the noise lower where it is. Through the lag with the session's history
    (inject_fresh2._through) on the records after the change; displacement only. Measured (p42_99, switched before the
    4287 kPa block): the 17 records of that block changed, 23 um RMS there (39x its noise; residual 0.18 % over all),
    its 20 Hz record's residual 36 %."""
    tau = lu(s.rng, 4e-3, 25e-3)
    starts = sorted(a for a, _ in _blocks(s).values())
    t_sw = starts[int(s.rng.integers(1, len(starts)))] - 1.0 if len(starts) > 1 else s.t0 - 1.0
    new = _through(s, lambda r: lambda z: 1 / (1 + tau * z), 2.0)
    map_disp(s, lambda r, d: new[id(r)] if r.cols["t_s"][0] > t_sw else d)


def td_usb_contention(s: Session) -> None:
    """The laser's readings reach the host over USB and are stamped on arrival; the operator films the strip now and
    then with a webcam on the same USB controller (2-5 spells of 60-300 s, log, each starting inside a recorded series),
    and while the camera streams its isochronous frames take the bus first: the laser's packets wait, their delay rising
    from the bus's 1-3 ms to 8-30 ms (log) with a ripple at the camera's frame rate (25 or 30 frames a second, +-20-50 %
    of the extra delay: a packet waits for the frame transfer in progress), 0.5 s edges: a delay that jumps up in spells
    over the bus's own small one. Through inject_fresh8._late; displacement only. Measured (s001_98): 19-23 ms of delay
    on the six records inside the spells (the 900 kPa block's 0.3-1 Hz sines, the 1700 kPa harmonic), about 1 ms
    elsewhere (20 Hz records' residuals 14 %); displacement residual 0.13 % (4.3x its noise)."""
    base, extra, rip = lu(s.rng, 1e-3, 3e-3), lu(s.rng, 8e-3, 3e-2), s.rng.uniform(0.2, 0.5)
    fps, ph = (25.0 if s.rng.random() < 0.5 else 30.0), s.rng.uniform(0, 1)
    spells = _bursts(s, int(s.rng.integers(2, 6)), (60.0, 300.0))

    def delay(r: Rec, t: np.ndarray) -> np.ndarray:
        saw = ((t - s.t0) * fps + ph) % 1.0 - 0.5
        return base + _ramp_env(t, spells, 0.5) * extra * (1 + 2 * rip * saw)

    _late(s, delay)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_bumped_stand(s: Session) -> None:
    """Someone knocks the laser's stand once, at a moment inside a recorded series in the middle 20-80 % of the session:
    the head turns on its clamp, its spot jumps inboard along the strip from the tip to x_m 0.75-0.92 L and its zero
    moves by 10-60 um (either sign), the stand ringing at its own mode (15-40 Hz, damping 0.03-0.1, 20-80 um, log) for a
    moment. Before the knock the tip, after it w(x_m) through inject_fresh6._reading (gain down, zeros moved, poles
    kept) for the rest of the session. Displacement only. Measured (paper_97, knocked at 46 % of the session, in the
    1837 kPa block's 6.4 Hz record): the later 1 V steps' peaks -32 %, displacement RMS -15 % (residual 23 %), the later
    20 Hz records' residuals 1100-1400 % (mostly the zero's shift)."""
    xm, off = s.rng.uniform(0.75, 0.92), s.rng.uniform(1e-5, 6e-5) * _sign(s)
    fr, zr, ar = s.rng.uniform(15.0, 40.0), s.rng.uniform(0.03, 0.1), lu(s.rng, 2e-5, 8e-5)
    recs = _chrono(s)
    mid = [r for r in recs if 0.2 <= (r.cols["t_s"][0] - s.t0) / (s.t1 - s.t0) <= 0.8] or recs[: max(len(recs) - 1, 1)]
    r0 = mid[int(s.rng.integers(0, len(mid)))]
    tb = s.rng.uniform(r0.cols["t_s"][0], r0.cols["t_s"][-1])
    new = _reading(s, lambda sp: [(1.0, xm * sp.geometry.length, 0)])
    wr = 2 * np.pi * fr
    for r in s.series():
        t = r.cols["t_s"]
        after = t >= tb
        if not after.any():
            continue
        u = t[after] - tb
        d = r.cols["disp_m"].copy()
        d[after] = new[id(r)][after] + off + ar * np.exp(-zr * wr * u) * np.sin(wr * math.sqrt(1 - zr**2) * u)
        r.cols["disp_m"] = d


def so_tracker_swap(s: Session) -> None:
    """Video tracking of a marker at the tip by template matching, with a look-alike feature inboard at x_2 0.65-0.88 L
    (a scratch, the edge of a plating defect): when the tip moves fast the marker smears over the exposure and the match
    jumps to the feature, which the tracker then follows (its search window now around it) until the operator re-selects
    the tip before the next record; the reported height is the feature's, w(x_2), from that moment on. The swap comes
    where the tip's speed (the reading smoothed over the 5-20 ms exposure, log) first exceeds the blur limit, 0.3-0.8 of
    the session's fastest (the strip in water is slow: a few mm/s at the 1 V steps' edges and on the sines near f1):
    those records from that moment on, the others read at the tip; a reading at another station in part of the records
    only. Through inject_fresh6._reading; displacement only. Measured (p42_99): 11 records swapped (the four steps,
    seven sines at 1.4 and 2.1 Hz), the steps' peaks -40 %, displacement RMS -39 % (residual 40 %)."""
    x2, q, te = s.rng.uniform(0.65, 0.88), s.rng.uniform(0.3, 0.8), lu(s.rng, 5e-3, 2e-2)
    speed = {}
    for r in s.series():  # the exposure's smoothing, recursive (no padding at the record's end)
        a = math.exp(-1.0 / (r.fs * te))
        y = signal.lfilter([1 - a], [1.0, -a], r.cols["disp_m"] - r.cols["disp_m"][0])
        speed[id(r)] = np.abs(np.gradient(y, r.cols["t_s"]))
    vth = q * max(float(np.max(x)) for x in speed.values())
    new = _reading(s, lambda sp: [(1.0, x2 * sp.geometry.length, 0)])
    for r in s.series():
        fast = speed[id(r)] > vth
        if fast.any():
            k = int(np.argmax(fast))
            d = r.cols["disp_m"].copy()
            d[k:] = new[id(r)][k:]
            r.cols["disp_m"] = d


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_hvac_tts(s: Session) -> None:
    """The pads relax under a held gap by a linear viscoelastic law (a stretched exponential, 1 - r (1 -
    exp(-(xi/tau)^beta)), r 6-15 %, tau 200-800 s, log, beta 0.4-0.7) whose clock runs with the room's temperature
    (time-temperature superposition: reduced time xi = int exp(E_a/R (1/T0 - 1/T)) dt, E_a 100-250 kJ/mol), and the
    room's air conditioning cycles T by +-0.5-1.5 K (a triangle, period 600-1800 s): the relaxation advances in spurts
    in the warm half-cycles, and the frame's expansion (0.5-1.5 % of the force per K, the gap opening when warm) adds
    the cycle itself on the load cell. From each block's start, through the preset's clamp law (the strip follows its
    force: inject_fresh4._clamp_law). Measured (s001_98): load cell down to 0.89-0.90 of its setting in each block,
    current residual 0.44 % of its RMS (2.8x its noise), displacement residual 0.03 % (0.9x)."""
    r0, tau, beta = s.rng.uniform(0.06, 0.15), lu(s.rng, 200.0, 800.0), s.rng.uniform(0.4, 0.7)
    ea, dT = s.rng.uniform(1e5, 2.5e5), s.rng.uniform(0.5, 1.5)
    period, ph = s.rng.uniform(600.0, 1800.0), s.rng.uniform(0, 1)
    kT = s.rng.uniform(0.005, 0.015)
    tg = _session_grid(s, 1.0, 600.0)
    T = dT * (4 * np.abs(((tg - s.t0) / period + ph) % 1.0 - 0.5) - 1)
    rate = np.exp(ea / 8.314 * (1 / 298.15 - 1 / (298.15 + T)))
    xi = np.r_[0.0, np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(tg))]

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        dxi = np.clip(np.interp(t, tg, xi) - float(np.interp(t_set, tg, xi)), 0, None)
        warm = np.interp(t, tg, T) - float(np.interp(t_set, tg, T))
        return (1 - r0 * -np.expm1(-((dxi / tau) ** beta))) * (1 - kT * warm)

    _clamp_law(s, rel)


def cr_perzyna_overstress(s: Session) -> None:
    """Viscoplastic pads (Perzyna): under a held gap the pad flows only while its stress exceeds its yield stress
    sigma_y plus a back stress X from kinematic hardening, at the plastic rate (1/tau_v) ((sigma - sigma_y -
    X)/sigma_y)^n (n 1-2.5, tau_v 100-600 s, log), the stress falling by E times the plastic strain and X rising by h
    (2-5) times the stress lost. Below the yield (drawn at 0.15-0.5 of the way from the lowest to the highest pressure
    of the session) nothing relaxes; above it each block's force falls towards a floor, and the back stress carried from
    the blocks before lowers the next block's overstress (a memory of the clamp's history). Closed form per block, from
    its start; through the preset's clamp law (inject_fresh4._clamp_law). Measured (paper_97): the 612 kPa block
    untouched (below the yield), the load cell down to 0.96, 0.90 and 0.91 of its setting in the later blocks;
    displacement residual 0.10 % (6x its noise), the 4287 kPa block's 20 Hz record residual 24 %; current residual 0.5 %
    (1.1x)."""
    ps = s.pressures()
    sy = ps[0] + (ps[-1] - ps[0]) * s.rng.uniform(0.15, 0.5)
    hh, n, tv = s.rng.uniform(2.0, 5.0), s.rng.uniform(1.0, 2.5), lu(s.rng, 100.0, 600.0)
    law, X = {}, 0.0
    for p, (a, b) in sorted(_blocks(s).items(), key=lambda kv: kv[1][0]):
        f0 = p - sy - X
        if f0 <= 0:
            law[p] = (0.0, X)
            continue
        law[p] = (f0, X)
        t = b - a
        f = f0 * math.exp(-(1 + hh) * t / tv) if abs(n - 1) < 1e-9 else \
            sy * ((f0 / sy) ** (1 - n) + (n - 1) * (1 + hh) * t / tv) ** (1 / (1 - n))
        X += hh * (f0 - f) / (1 + hh)

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        f0 = law[p][0]
        if f0 <= 0:
            return np.ones(t.size)
        u = np.clip(t - t_set, 0, None)
        f = f0 * np.exp(-(1 + hh) * u / tv) if abs(n - 1) < 1e-9 else \
            sy * ((f0 / sy) ** (1 - n) + (n - 1) * (1 + hh) * u / tv) ** (1 / (1 - n))
        return 1 - (f0 - f) / (1 + hh) / p

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_falling_waterline(s: Session) -> None:
    """A strip hanging from a clamp held just above an open bath, its root 0-5 % of the free length out of the water at
    the start; the bath's level falls steadily (evaporation from a warm bath, or a slow leak at the cuvette's seal),
    exposing 6-20 % more by the session's end, and each exposed element dries in the air (it loses 60-90 % of its mobile
    water over tau_d 60-300 s, log). The dry part is at the root, where the strip's curvature counts most for the tip:
    the displacement keeps 1 - 2 int loss(x) (1 - x) dx of its gain (x from the root, in units of L), the conductance 1
    - c int loss(x) dx (c 0.5-1, the wet line's share), the spectra following (each taken at the start of the time
    series after it). The water left on the strip and the dry part's stiffening neglected. Measured (p42_99):
    displacement RMS -13 % (residual 15 %), the 1 V steps' peaks -5.6, -11, -16 and -21 % block by block, current -5.3 %
    (12x its noise), impedance at 0.1 Hz 1.02-1.08x."""
    e0 = s.rng.uniform(0.0, 0.05)
    e1, a = e0 + s.rng.uniform(0.06, 0.2), s.rng.uniform(0.6, 0.9)
    td, c = lu(s.rng, 60.0, 300.0), s.rng.uniform(0.5, 1.0)
    x = (np.arange(200) + 0.5) / 200
    tx = np.where(x < e0, s.t0 - 10 * td, s.t0 + (x - e0) / (e1 - e0) * (s.t1 - s.t0))
    tg = _session_grid(s, (s.t1 - s.t0) / 4000)
    loss = a * -np.expm1(-np.clip(tg[:, None] - tx[None, :], 0, None) / td)
    ld = 2 * np.mean(loss * (1 - x)[None, :], axis=1)
    lc = c * np.mean(loss, axis=1)
    _dry_by(s, lambda t: np.interp(t, tg, ld), lambda t: np.interp(t, tg, lc))


def dh_cathode_sweating(s: Session) -> None:
    """A strip in air sweats at large drives: the water pushed to the cathode's side (in proportion to the fast bend) is
    pressed out through the cracked electrode once its pressure passes the cracks' entry (abs(d)/d_max above 0.4-0.7)
    and evaporates from the surface, at a rate growing with the excess; beside it a slow evaporation from both faces
    (10-30 % of the loss). Total loss 10-30 % by the session's end, in steps at the large drives (the 1 V steps'
    plateaus, within them), flat through the small sines. Gain x (1 - loss), conductance x (1 - c loss), c 0.3-1, the
    spectra following (inject_fresh9._dry_by). Measured (s001_98): displacement RMS -6.1 % (residual 7.2 %), the 1 V
    steps' peaks -2.1, -5.3, -8.6 and -12 %, current -4.4 % (32x its noise), impedance at 0.1 Hz 1.02-1.06x."""
    total, qth = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.4, 0.7)
    bg, c = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.3, 1.0)
    recs, d, _ = _cat(s, "disp_m")
    t = np.concatenate([r.cols["t_s"] for r in recs])
    dt = np.concatenate([np.full(r.cols["t_s"].size, 1.0 / r.fs) for r in recs])
    ex = np.clip(np.abs(d) / max(float(np.max(np.abs(d))), 1e-12) - qth, 0, None)
    cum = np.cumsum(ex * dt)
    sw = cum / max(float(cum[-1]), 1e-30)
    L = total * ((1 - bg) * sw + bg * (t - s.t0) / (s.t1 - s.t0))
    tt, LL = np.r_[s.t0 - 1.0, t], np.r_[0.0, L]
    _dry_by(s, lambda x: np.interp(x, tt, LL), lambda x: c * np.interp(x, tt, LL))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_rocking_contact(s: Session) -> None:
    """The jaw's gold contact on the strip's electrode: the clamped part of the strip is actuated too and rocks in the
    compliant pads as it bends, and the face bent away from its jaw lifts off the jaw's edge, its contact spot shrinking
    (constriction resistance ~ 1/a, a ~ sqrt(1 - e/e_l)): dR/R = (1 - e/e_l)^(-1/2) - 1, clipped at 0.9 e_l (the spot
    never fully opens). The lift-off bend e_l (1.5-3 displacement scales at the lowest pressure) grows with the clamp
    pressure as (p/p_min)^m (m 0.5-1.2): a firm clamp rocks less, so the effect is strongest in the first block. One
    face (drawn) fully, the other at 0.3-1 of it. Gains fall by 0.015-0.04 (displacement), 0.04-0.1 (current) per unit
    of dR/R (inject_fresh3._resist). Measured (paper_97): displacement RMS -1.3 % (residual 2.0 %), the 1 V steps' peaks
    -4.1, -1.6, -0.6 and -0.4 % block by block, current residual 1.5 % (3x its noise)."""
    m, el, wb, side = s.rng.uniform(0.5, 1.2), s.rng.uniform(1.5, 3.0), s.rng.uniform(0.3, 1.0), _sign(s)
    pmin = min(s.pressures())

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        lim = el * (float(r.entry["pressure_kPa"]) / pmin) ** m
        g = lambda y: (1 - np.clip(y, 0, 0.9 * lim) / lim) ** -0.5 - 1  # noqa: E731
        return g(side * e) + wb * g(-side * e)

    _resist(s, shape, (0.015, 0.04), (0.04, 0.1))


def sr_stress_corrosion(s: Session) -> None:
    """Stress-corrosion cracking of the tensioned electrode in water (subcritical crack growth, Charles' law: the cracks
    grow at a rate ~ K^n while the stress intensity exceeds its threshold K_scc): the strain sensitivity grows with the
    time spent above the threshold (abs bend above 0.4-0.7 of the session's largest on that side), weighted by
    (e/e_max)^n (n 4-10), not with the cycles: the held 1 V steps' plateaus grow the cracks, the sines hardly. dR/R =
    (c0 + (1 - c0) A(t)/A_end) (e+ + o e-), c0 0.1-0.4 (the cracks already there), o 0.1-0.3 (the other face), one side
    (drawn) in tension. Gains fall by 0.02-0.06 (displacement), 0.05-0.15 (current) per unit (inject_fresh3._resist).
    Measured (p42_99): displacement RMS -2.7 % (residual 3.1 %), the 1 V steps' peaks -1.0, -3.7, -3.7 and -6.5 % block
    by block, current residual 2.2 % (4.9x its noise)."""
    side, c0, n = _sign(s), s.rng.uniform(0.1, 0.4), s.rng.uniform(4.0, 10.0)
    eth, o = s.rng.uniform(0.4, 0.7), s.rng.uniform(0.1, 0.3)
    recs, e, cuts = _cat(s, "disp_m")
    dt = np.concatenate([np.full(r.cols["t_s"].size, 1.0 / r.fs) for r in recs])
    ep = np.clip(side * e, 0, None) / max(float(np.max(side * e)), 1e-12)
    A = np.cumsum(np.where(ep > eth, ep**n, 0.0) * dt)
    fac = dict(zip([id(r) for r in recs], np.split(c0 + (1 - c0) * A / max(float(A[-1]), 1e-30), cuts)))
    _resist(s, lambda r, x: fac[id(r)] * (np.clip(side * x, 0, None) + o * np.clip(-side * x, 0, None)),
            (0.02, 0.06), (0.05, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_self_weight(s: Session) -> None:
    """The strip held horizontal, bending up and down under a laser looking down at it (in water through the bath's
    surface): its own weight less the buoyancy of its medium (a plated Nafion strip of 2000-2600 kg/m^3; q L^3/EI
    0.2-0.35 at 30 mm in water, 0.15-0.2 at 20 mm in air) sags it at rest, and as it bends the weight's horizontal lever
    arms shorten and its share across the rotated strip falls: the exact heavy strip (inject_fresh9._heavy_strip), the
    height of its tip's material point relative to the rest sag, at the actuation curvature 2d/L^2 of the linear reading
    (the weight's sag being the same at every curvature for the linear strip). The arc's odd compression and an even
    part (both bend directions lift the tip against the sag). Fixed by geometry but for the density. Displacement only.
    Measured (paper_97): displacement RMS -0.8 % (residual 0.9 %, 54x its noise), the 1 V steps' peaks -1.6 % (-0.14
    mm), the 1 V harmonic's peaks -0.06 % on one side, -0.7 % on the other."""
    rho = s.rng.uniform(2000.0, 2600.0)
    sp = _preset(s).specimen()
    L, b, h = float(s.specimen["length_m"]), float(s.specimen["width_m"]), float(s.specimen["thickness_m"])
    EI, q = sp.mechanics.E * b * h**3 / 12, (rho - sp.fluid.density) * b * h * G_N
    top = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) * 1.05 + 1e-9
    kap = np.linspace(-2 * top / L**2, 2 * top / L**2, 801)
    Y = _heavy_strip(L, EI, q, np.r_[0.0, kap])
    map_disp(s, lambda r, d: np.interp(d, kap * L**2 / 2, Y[1:] - Y[0]))


def ld_synclastic(s: Session) -> None:
    """The strip's actuation is an isotropic swelling of one face against the other, so it curls across its width as
    much as along its length (a bowl, kappa_y = kappa_x = kappa_a); a bowl stretches its mid-plane (the fibres off the
    centre line lie on a longer arc), and as the curvature grows the plate's membrane energy, E h b^5 (kappa_x
    kappa_y)^2/1440 per length against its bending energy D b/2 ((kappa_x - kappa_a)^2 + (kappa_y - kappa_a)^2 + 2 nu
    (...)(...)), holds both curvatures below the actuation's (the large-deformation plate of a mismatch-strained film:
    Masters & Salamon; Finot & Suresh), in proportion to b^4/h^2 (nu 0.3-0.45): the longitudinal curvature
    kappa_x(kappa_a) (Ritz, uniform curvatures, minimised by Newton), then read on the exact arc, (1 - cos(kappa_x
    L))/kappa_x. The gain falls at large amplitude well beyond the arc's own compression. Fixed by geometry but for nu.
    Displacement only. Measured (s001_98): displacement RMS -5.0 % (residual 5.5 %, 180x its noise), the 1 V steps'
    peaks -8.5 % (the arc alone: -1.8 %), the 1 V harmonic's -2.2 %."""
    nu = s.rng.uniform(0.3, 0.45)
    L, b, h = float(s.specimen["length_m"]), float(s.specimen["width_m"]), float(s.specimen["thickness_m"])
    c = (1 - nu**2) * b**4 / (60 * h**2)
    top = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) * 1.05 + 1e-9
    ka = np.linspace(0.0, 2 * top / L**2, 401)
    kx, ky = ka.copy(), ka.copy()
    for _ in range(60):  # the stationary point of the energy (divided by D b/2)
        gx = 2 * (kx - ka) + 2 * nu * (ky - ka) + 2 * c * kx * ky**2
        gy = 2 * (ky - ka) + 2 * nu * (kx - ka) + 2 * c * ky * kx**2
        hxx, hyy, hxy = 2 + 2 * c * ky**2, 2 + 2 * c * kx**2, 2 * nu + 4 * c * kx * ky
        det = hxx * hyy - hxy**2
        kx, ky = kx - (hyy * gx - hxy * gy) / det, ky - (hxx * gy - hxy * gx) / det
    ks = np.where(kx < 1e-9, 1e-9, kx)
    Y = np.where(kx < 1e-9, kx * L**2 / 2, (1 - np.cos(ks * L)) / ks)
    map_disp(s, lambda r, d: np.sign(d) * np.interp(np.abs(d), ka * L**2 / 2, Y))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_burst_fire(s: Session) -> None:
    """A heater on the next bench under a burst-fire (integral-cycle, zero-cross) controller: whole mains cycles (50 or
    60 Hz +- 0.05) switched in packets, on for the first D N of every N cycles (a control period of 0.5-2 s), the duty D
    wandering between 0.2 and 0.8 with the controller's demand (a slow random, 60-300 s); the heater's current radiates
    into the laser's and the current amplifier's cables: a sine (3rd -0.02 to -0.05, the grid's flat top) in packets,
    starting and stopping at its zero crossings, 1.5-6 um and 3-12 uA (log); phase locked to the session clock. Measured
    (s001_98): on the 55 % of the samples inside packets 1.9 um RMS on the displacement (3.4x its noise) and 7.1 uA on
    the current (1.6x), peaks 2.8 um and 10.5 uA, 20 Hz record residual 5-7 %."""
    ad, ai, h3 = lu(s.rng, 1.5e-6, 6e-6), lu(s.rng, 3e-6, 1.2e-5), -s.rng.uniform(0.02, 0.05)
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    N, pd = int(round(s.rng.uniform(0.5, 2.0) * f)), s.rng.uniform(0, 1)
    tg = _session_grid(s, 5.0, 10.0)
    duty = np.clip(0.5 + 0.3 * _ou(s, tg, lu(s.rng, 60.0, 300.0)) / 1.5, 0.2, 0.8)
    pi_ = s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        t = r.cols["t_s"]
        ph = f * t + pd  # cycles
        k = np.floor(ph)
        on = (k % N) < np.round(np.interp(t, tg, duty) * N)
        w = 2 * np.pi * ph
        r.cols["disp_m"] = r.cols["disp_m"] + ad * on * (np.sin(w) + h3 * np.sin(3 * w))
        r.cols["i_A"] = r.cols["i_A"] + ai * on * (np.sin(w + pi_) + h3 * np.sin(3 * (w + pi_)))


def mp_flicker_tilt(s: Session) -> None:
    """The room's LED lighting flickers at twice the line (100 or 120 Hz +- 0.1: a rectified line whose top the driver
    regulates flat, min(abs(sin), c)/c, c 0.3-0.7; 2-6 um peak to peak at rest, log), and the ambient light reaching the
    laser's receiver biases the spot's centroid by its share of the received light; the laser's return from the diffuse
    plated surface falls as the tip tilts (cos^k of the tip's angle, k 2-6, the angle 2d/L on the arc), so the flicker's
    error grows with the bend: several times the rest level at the steps' peaks. Displacement only; phase locked to the
    session clock. Measured (p42_99): residual 3.0 um RMS (5.1x its noise), 3.6 um peak to peak at rest, 30 um on the 1
    V steps' plateaus, 20 Hz record residual 31-32 %."""
    a0, c, k = lu(s.rng, 2e-6, 6e-6), s.rng.uniform(0.3, 0.7), s.rng.uniform(2.0, 6.0)
    fl, p = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05), s.rng.uniform(0, 2 * np.pi)
    u = np.linspace(0, np.pi, 2001)
    mean = float(np.mean(np.minimum(np.abs(np.sin(u)), c))) / c
    L = float(s.specimen["length_m"])
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        wave = np.minimum(np.abs(np.sin(2 * np.pi * fl * t + p)), c) / c - mean
        r.cols["disp_m"] = d + a0 * wave / np.cos(np.clip(2 * d / L, -1.2, 1.2)) ** k


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_drive_offset_drift(s: Session) -> None:
    """The drive amplifier's output offset drifts with its temperature (a power op-amp's input offset times its gain, a
    DAC's zero): a slow random wander of 1-5 mV RMS (log, correlation time 100-600 s, log) that the strip feels, while
    the DAQ records the command (v_V knows nothing of it). The strip answers it as it answers any drive: its change
    within each record reaches the displacement and the current through the strip's measured step responses
    (inject_fresh7._superpose): slow drifts of the bend (8-9 um per mV on the paper strip) and a current below its
    noise. Measured (paper_97): displacement residual 2.7 um RMS (4.8x its noise), peaks 10 um, 20 Hz record residual
    3-10 %, current 0.5 uA (0.03x its noise); (s001_98): 2.7 um (4.8x), peaks 11 um, current 1.6 uA (0.4x)."""
    sig, tc = lu(s.rng, 1e-3, 5e-3), lu(s.rng, 100.0, 600.0)
    tg = _session_grid(s, 1.0, 10.0)
    e = sig * _ou(s, tg, tc)
    _superpose(s, {id(r): np.interp(r.cols["t_s"], tg, e) for r in s.series()})


def out_flow_buffeting(s: Session) -> None:
    """A flow buffets the strip in spells: an air-conditioning draught or a fume hood's when the strip is in air, a bath
    circulator's jet when it is in water (2-5 spells of 60-600 s, log, each starting inside a recorded series, 2 s
    edges): a random force of flat spectrum (turbulence well above f1) through the strip's own first mode (f1 and its
    damping from labrig.physics.transfer.modal_set at the record's pressure, static gain 1): a narrow-band random
    vibration about f1 in air, a broader one in water, 1.5-6 um RMS (log). Displacement only (the force bends the strip,
    not its electrodes). Measured (s001_98): 4.5 um RMS on the 10 % of the samples inside the spells (8x its noise),
    peaks 19 um; (p42_99): 5.1 um on 13 % (8.7x), peaks 23 um."""
    from labrig.physics import transfer

    rms = lu(s.rng, 1.5e-6, 6e-6)
    spells = _bursts(s, int(s.rng.integers(2, 6)), (60.0, 600.0))
    modes: dict[float, tuple[float, float]] = {}
    for r in s.series():
        t = r.cols["t_s"]
        env = _ramp_env(t, spells, 2.0)
        if not env.any():
            continue
        p = float(r.entry["pressure_kPa"])
        if p not in modes:
            ms = transfer.modal_set(_spec(s, r))
            modes[p] = float(ms.omega[0]), float(np.atleast_1d(ms.xi)[0])
        w1, z1 = modes[p]
        H = lambda z: 1 / (1 + 2 * z1 * z / w1 + (z / w1) ** 2)  # noqa: E731
        pre = int(5 / (z1 * w1) * r.fs) + 1
        imp = np.zeros(2 * pre + t.size)
        imp[0] = 1.0
        scale = 1 / math.sqrt(float(np.sum(lti(imp, r.fs, H) ** 2)))
        x = lti(s.rng.normal(size=2 * pre + t.size), r.fs, H)[pre:pre + t.size]  # the flow before and after the record
        r.cols["disp_m"] = r.cols["disp_m"] + rms * scale * env * x


def out_table_lean(s: Session) -> None:
    """The strip's clamp stands on a pneumatic isolation table and the laser's stand on the floor beside it: each time
    someone leans on the table or sets something on it (3-8 events, each starting inside a recorded series, held 5-60 s,
    log) the table sinks by 20-150 um (log) through its suspension's bounce (1-2 Hz, damping 0.08-0.25) and its
    levelling valves bring it back to height over 2-15 s (log, critically damped); when the load comes off, the mirror
    image. The laser sees the strip move with the table: sink-and-relevel transients on the displacement, in either
    direction by the laser's side. Displacement only. Measured (p42_99): 32 um RMS on the 6 % of the samples touched
    (54x its noise), peaks 0.14 mm; (paper_97): 40 um on 1 % (71x), peaks 0.10 mm."""
    fs_, zs, tv, side = s.rng.uniform(1.0, 2.0), s.rng.uniform(0.08, 0.25), lu(s.rng, 2.0, 15.0), _sign(s)
    events = _bursts(s, int(s.rng.integers(3, 9)), (5.0, 60.0))
    amps = [lu(s.rng, 2e-5, 1.5e-4) for _ in events]
    ws, wd = 2 * np.pi * fs_, 2 * np.pi * fs_ * math.sqrt(1 - zs**2)

    def resp(u: np.ndarray) -> np.ndarray:
        u = np.clip(u, 0, None)
        sus = 1 - np.exp(-zs * ws * u) * (np.cos(wd * u) + zs / math.sqrt(1 - zs**2) * np.sin(wd * u))
        lev = 1 - (1 + u / tv) * np.exp(-u / tv)
        return np.where(u > 0, sus - lev, 0.0)

    for r in s.series():
        t, x = r.cols["t_s"], np.zeros(r.cols["t_s"].size)
        for (a, b), am in zip(events, amps):
            x += am * (resp(t - a) - resp(t - b))
        r.cols["disp_m"] = r.cols["disp_m"] - side * x


def out_rf_rectification(s: Session) -> None:
    """A handheld radio (a PMR446 walkie-talkie, 0.5 W at 446 MHz) used near the bench: its carrier, picked up by the
    current amplifier's input leads, is rectified by the input stage's junctions into a DC offset while it transmits
    (FM: a constant envelope, so a plain shift). 2-3 conversations (each starting inside a recorded series) of 2-5
    transmissions of 2-15 s (log) with 1-10 s pauses; each transmission shifts the current by 8-60 uA (log, one sign for
    the session, +-30 % between transmissions as the speaker turns), 20-100 ms edges (the keying and the amplifier's
    filter). Current only. Measured (paper_97): 57 uA RMS on the 1 % of the samples inside transmissions (3.7x its
    noise), peaks 70 uA; (s001_98): 15 uA on 4 % (3.5x), peaks 17 uA."""
    lvl, side, edge = lu(s.rng, 8e-6, 6e-5), _sign(s), lu(s.rng, 0.02, 0.1)
    tx = []
    for a, _ in _bursts(s, int(s.rng.integers(2, 4)), (1.0, 1.0)):
        t = a
        for _ in range(int(s.rng.integers(2, 6))):
            dur = lu(s.rng, 2.0, 15.0)
            tx.append((t, t + dur, lvl * s.rng.uniform(0.7, 1.3)))
            t += dur + s.rng.uniform(1.0, 10.0)
    for r in s.series():
        t, x = r.cols["t_s"], np.zeros(r.cols["t_s"].size)
        for a, b, am in tx:
            x += am * _ramp_env(t, [(a, b)], edge)
        r.cols["i_A"] = r.cols["i_A"] + side * x


FRESH9_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"capillary_entry": br_capillary_entry, "bath_topup": br_bath_topup},
    "faradaic_current": {"clamp_crevice": far_clamp_crevice, "reaeration": far_reaeration},
    "hysteresis": {"eyring_slip": hy_eyring_slip, "aging_relays": hy_aging_relays},
    "time_delay": {"averaging_switched": td_averaging_switched, "usb_contention": td_usb_contention},
    "sensor_offset": {"bumped_stand": so_bumped_stand, "tracker_swap": so_tracker_swap},
    "clamp_relaxation": {"hvac_tts": cr_hvac_tts, "perzyna_overstress": cr_perzyna_overstress},
    "dehydration": {"falling_waterline": dh_falling_waterline, "cathode_sweating": dh_cathode_sweating},
    "strain_resistance": {"rocking_contact": sr_rocking_contact, "stress_corrosion": sr_stress_corrosion},
    "large_deflection": {"self_weight": ld_self_weight, "synclastic": ld_synclastic},
    "mains_pickup": {"burst_fire": mp_burst_fire, "flicker_tilt": mp_flicker_tilt},
    "unexplained": {"drive_offset_drift": out_drive_offset_drift, "flow_buffeting": out_flow_buffeting,
                    "table_lean": out_table_lean, "rf_rectification": out_rf_rectification},
}
inject.register_forms(FRESH9_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_merged_loadcell(s: Session) -> None:
    """The load cell logged by its own indicator (read over RS-232 by a logging script at 2-10 readings a second, log,
    each stamped on arrival, 20-60 ms after it was taken, and at the indicator's 0.01 kgf) and merged onto the DAQ's
    rows on time stamps as a merge-as-of join does: each row carries the latest reading stamped at or before it (a
    staircase instead of the bench's interpolated stream), the merged file's columns in the join's order (t_s, force_N,
    then the DAQ's v_V, i_A, disp_m). The import contract reads the columns by their header names; the other columns,
    the rows and the spectra untouched."""
    rate, lat, ph = lu(s.rng, 2.0, 10.0), s.rng.uniform(0.02, 0.06), s.rng.uniform(0, 1)
    T = 1.0 / rate
    for r in s.series():
        if "force_N" not in r.cols:
            continue
        t, F = r.cols["t_s"], r.cols["force_N"]
        k = np.arange(math.floor((t[0] - lat) / T - ph) - 1, math.ceil((t[-1] - lat) / T - ph) + 2)
        tk = (k + ph) * T
        Fk = np.round(np.interp(tk, t, F) / KGF) * KGF
        idx = np.clip(np.searchsorted(tk + lat, t, side="right") - 1, 0, None)
        r.cols = {"t_s": t, "force_N": Fk[idx], **{c: x for c, x in r.cols.items() if c not in ("t_s", "force_N")}}


inject.VARIANTS.update({"merged_loadcell": v_merged_loadcell})

# ------------------------------------------------------------------------------------------------ the cases

P97, S98, T99 = "paper_97", "s001_98", "p42_99"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 97 / 98 / 99
    "back_relaxation": [("capillary_entry", 97, P97, "asrun"), ("bath_topup", 99, T99, "merged_loadcell")],
    "faradaic_current": [("clamp_crevice", 98, S98, "asrun"), ("reaeration", 97, P97, "eis_descending")],
    "hysteresis": [("eyring_slip", 97, P97, "merged_loadcell"), ("aging_relays", 98, S98, "rate07")],
    "time_delay": [("averaging_switched", 99, T99, "asrun"), ("usb_contention", 98, S98, "trigger_clock")],
    "sensor_offset": [("bumped_stand", 97, P97, "two_pressures"), ("tracker_swap", 99, T99, "host_timed")],
    "clamp_relaxation": [("hvac_tts", 98, S98, "asrun"), ("perzyna_overstress", 97, P97, "merged_loadcell")],
    "dehydration": [("falling_waterline", 99, T99, "asrun"), ("cathode_sweating", 98, S98, "no_spectra")],
    "strain_resistance": [("rocking_contact", 97, P97, "dropped_packets"), ("stress_corrosion", 99, T99, "decimated3")],
    "large_deflection": [("self_weight", 97, P97, "float32_time"), ("synclastic", 98, S98, "merged_loadcell")],
    "mains_pickup": [("burst_fire", 98, S98, "asrun"), ("flicker_tilt", 99, T99, "resampled")],
    "unexplained": [("drive_offset_drift", 97, P97, "asrun"), ("drive_offset_drift", 98, S98, "own_clock"),
                    ("flow_buffeting", 98, S98, "asrun"), ("flow_buffeting", 99, T99, "shortened_shuffled"),
                    ("table_lean", 99, T99, "asrun"), ("table_lean", 97, P97, "steps_sines"),
                    ("rf_rectification", 97, P97, "merged_loadcell"), ("rf_rectification", 98, S98, "host_timed")],
}
CLEAN = [(97, P97, "asrun"), (97, P97, "merged_loadcell"), (98, S98, "asrun"), (98, S98, "host_timed"),
         (99, T99, "asrun"), (99, T99, "merged_loadcell")]


def fresh9_cases(only: str | None = None) -> list[Case]:
    """The tenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds 97-99)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh9_cases, "inject_fresh9", "fresh9")
