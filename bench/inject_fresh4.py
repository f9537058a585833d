"""A fifth held-out set for the diagnosis (issue 12), written without sight of the diagnosis (its code, its doc, its
tests, its results).

Two forms per catalogue effect, each from the physics of the effect's cause and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py, bench/inject_fresh3.py and the simulated
bench (mock_devices/effects.py); three structures outside the catalogue (truth "unexplained"); clean sessions. All on
three bases of new seeds (61-63: the paper strip, the seed-001 strip on its own sweep, the paper strip 20 mm free) and
on protocol / data-shape variants, one of them new here: a USB DAQ's buffer overruns, whole packets of samples lost
from the time series while the kept rows keep their true time stamps (gaps in t_s).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject,
inject_fresh2 and inject_fresh3 are reused (importing inject_fresh3 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import.

Run: python bench/inject_fresh4.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable

import numpy as np
from scipy import signal

import inject
from inject import Case, Rec, Session, _dry, lti, lu, map_disp, play, ref_disp
from inject_fresh2 import _chrono, _drive_side, _map_through, _spec
from inject_fresh3 import _past, _resist, _sign, _through_x


# the paper's strip 20 mm free (earlier sets used 30, 40, 25 and 35 mm): registered in every process that imports this module
inject.register_free_length("paper_20", 0.02)

inject.BASES.update({
    "paper_61": ("paper-sweep", "paper", 61),
    "s001_62": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 62),
    "p20_63": ("paper-sweep", "paper_20", 63),
})


def _preset(s: Session):
    from labrig.physics import presets

    return presets.get(s.preset)


def _ratio_both(s: Session, new: Callable[[Rec], object], memory_s: float = 2.0) -> None:
    """Each record's displacement and current through the ratio of the strip's own transfer functions (displacement
    and admittance, labrig.physics.transfer) of the changed specimen new(r) over the unchanged one, with the session's
    history (inject_fresh2._through)."""
    from labrig.physics import transfer

    def ratio(tf: Callable) -> Callable[[Rec], Callable[[np.ndarray], np.ndarray]]:
        def per(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
            a, b = _spec(s, r), new(r)

            def h(z: np.ndarray) -> np.ndarray:
                with np.errstate(divide="ignore", invalid="ignore"):  # s = 0 (lti replaces that bin)
                    return tf(z, b) / tf(z, a)

            return h

        return per

    cur = _through_x(s, {id(r): r.cols["i_A"] for r in s.series()}, ratio(transfer.admittance_tf), memory_s)
    _map_through(s, ratio(transfer.displacement_tf), memory_s)
    for r in s.series():
        r.cols["i_A"] = cur[id(r)]


def _lag_state(x: np.ndarray, fs: float, tau: float, y0: float) -> np.ndarray:
    """A first-order lag 1/(tau s + 1) of x, exact for x held over each sample, from the state y0."""
    a = math.exp(-1.0 / (fs * tau))
    return signal.lfilter([1 - a], [1.0, -a], x, zi=[a * y0])[0]


# ------------------------------------------------------------------------------------------------ back relaxation


def br_polarity(s: Session) -> None:
    """The two plated electrodes differ (thickness, porosity), so the water pushed to either side flows back through a
    different layer: each bend direction's opposing flux has its own lag and share, d - K+ LP+(d+) - K- LP-(d-).
    K+ 0.9-1.3, K-/K+ 0.5-0.9, tau+ 3-10 s (log), tau-/tau+ 1.5-3 (the thicker electrode slower)."""
    kp, tp = s.rng.uniform(0.9, 1.3), lu(s.rng, 3.0, 10.0)
    km, tm = kp * s.rng.uniform(0.5, 0.9), tp * s.rng.uniform(1.5, 3.0)
    if s.rng.random() < 0.5:
        kp, km, tp, tm = km, kp, tm, tp
    ups = _through_x(s, {id(r): np.clip(r.cols["disp_m"], 0, None) for r in s.series()}, lambda r: lambda z: kp / (tp * z + 1), 120.0)
    dns = _through_x(s, {id(r): np.clip(r.cols["disp_m"], None, 0) for r in s.series()}, lambda r: lambda z: km / (tm * z + 1), 120.0)
    map_disp(s, lambda r, d: d - ups[id(r)] - dns[id(r)])


def br_cluster_sphere(s: Session) -> None:
    """Water exchanged with the ionic clusters (roughly spherical domains) by radial diffusion: the opposing flux follows
    the bend through the sphere's uptake kernel 3 (q coth q - 1)/q^2, q = sqrt(tau s), tau = a^2/D 10-60 s (log), K2
    0.8-1.2 (a slab's tanh kernel or a single lag are other laws)."""
    k2, tau = s.rng.uniform(0.8, 1.2), lu(s.rng, 10.0, 60.0)

    def kernel(z: np.ndarray) -> np.ndarray:
        q = np.sqrt(tau * z + 0j)
        small = np.abs(q) < 1e-3
        qs = np.where(small, 1.0, q)
        return np.where(small, 1.0 - q**2 / 15, 3 * (qs / np.tanh(qs) - 1) / qs**2)

    _map_through(s, lambda r: lambda z: 1 - k2 * kernel(z), 120.0)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_bubble_blanket(s: Session) -> None:
    """Electrolysis (symmetric Butler-Volmer, v_t 0.1-0.2 V) whose gas bubbles blanket the electrodes: the covered share
    theta follows theta_eq = theta_max x/(1 + x) (x the kinetic current over its 1 V value) through the bubbles' growth
    and detachment time tau_b 2-10 s (log), the current falling to i_k (1 - theta). theta_max 0.3-0.6, i(1 V) 0.15-0.6
    mA (log) before blanketing; coverage carried through the session (it clears over the rests). Current only."""
    i1, vt, thmax, taub = lu(s.rng, 1.5e-4, 6e-4), s.rng.uniform(0.1, 0.2), s.rng.uniform(0.3, 0.6), lu(s.rng, 2.0, 10.0)
    th, t_end = 0.0, None
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None:
            th *= math.exp(-(t[0] - t_end) / taub)
        ik = i1 * np.sinh(r.cols["v_V"] / vt) / math.sinh(1.0 / vt)
        x = np.abs(ik) / i1
        theta = _lag_state(thmax * x / (1 + x), r.fs, taub, th)
        r.cols["i_A"] = r.cols["i_A"] + ik * (1 - theta)
        th, t_end = float(theta[-1]), float(t[-1])


def far_pt_oxide(s: Session) -> None:
    """Platinum oxide grown on whichever electrode is the anode with Elovich (inverse-log, place-exchange) kinetics,
    dq/dt = k(E) exp(-q/q0), k = i0 exp((E - 1 V)/b), and stripped again only once the potential falls below E_red
    0.05-0.25 V (the oxide's irreversibility): a decaying anodic current on each rise to 1 V, a cathodic stripping peak
    on the way back, at the interface's potential (double-layer lag 20-100 ms, log). q0 30-100 uC (log: a monolayer on a
    rough electrode), i0 0.2-0.8 mA (log), b 40-80 mV, stripping time 0.2-1 s (log). Current only."""
    q0, i0, b = lu(s.rng, 3e-5, 1e-4), lu(s.rng, 2e-4, 8e-4), s.rng.uniform(0.04, 0.08)
    ered, taur, taui = s.rng.uniform(0.05, 0.25), lu(s.rng, 0.2, 1.0), lu(s.rng, 0.02, 0.1)
    q, t_end = [0.0, 0.0], None  # the oxide on electrode A (anode for v > 0) and on B
    for r in _chrono(s):
        t, dt = r.cols["t_s"], 1.0 / r.fs
        if t_end is not None:  # the rest at 0 V strips what E_red allows
            q = [x * math.exp(-(t[0] - t_end) * math.exp(min(ered / b, 30.0)) / taur) for x in q]
        v = lti(r.cols["v_V"], r.fs, lambda z: 1 / (1 + taui * z)).tolist()
        out = np.empty(len(v))
        for n, vn in enumerate(v):
            before = q[0] - q[1]
            for e, pot in enumerate((vn, -vn)):
                k = i0 * math.exp(min((pot - 1.0) / b, 30.0))
                qe = q[e] + q0 * math.log1p(k * dt / q0 * math.exp(-q[e] / q0))
                q[e] = qe * math.exp(-dt * math.exp(max(min((ered - pot) / b, 30.0), -50.0)) / taur)
            out[n] = (q[0] - q[1] - before) / dt
        r.cols["i_A"] = r.cols["i_A"] + out
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_charge_play(s: Session) -> None:
    """Memory between the charge moved and the strain it makes (cations pinned at sulfonate sites until the charge has
    moved on by a threshold): the bend follows (1 - h) Q + h mean play_r(Q) of the charge Q = int i dt (each record
    from 0 after its rest, the plays' state through the session), not the voltage; the change reaches the tip through
    the first bending mode. Radii 0.1-0.5 of the 1 V harmonic's charge amplitude (x 0.8-1.25), h 0.3-0.5."""
    from labrig.physics import transfer

    h, scale = s.rng.uniform(0.3, 0.5), s.rng.uniform(0.8, 1.25)
    recs = _chrono(s)
    Q = [np.r_[0.0, np.cumsum(0.5 * (r.cols["i_A"][1:] + r.cols["i_A"][:-1]) * np.diff(r.cols["t_s"]))] for r in recs]
    ref = next((k for kind in ("harmonic", "step") for k, r in enumerate(recs) if r.kind == kind), 0)
    qref = max(0.5 * float(np.ptp(Q[ref])), 1e-12)
    beta = 0.5 * float(np.ptp(recs[ref].cols["disp_m"])) / qref
    allq = np.concatenate(Q)
    hyst = np.mean([play(allq, rad * qref * scale) for rad in (0.1, 0.2, 0.35, 0.5)], axis=0) - allq
    parts = np.split(beta * h * hyst, np.cumsum([q.size for q in Q])[:-1])

    def mode(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        ms = transfer.modal_set(_spec(s, r))
        w, xi = float(ms.omega[0]), float(ms.xi[0])
        return lambda z: 1 / (1 + 2 * xi * z / w + (z / w) ** 2)

    new = _through_x(s, {id(r): p for r, p in zip(recs, parts)}, mode, 2.0)
    map_disp(s, lambda r, d: d + new[id(r)])


def hy_pinning_ja(s: Session) -> None:
    """Pinning-type memory on the drive (Jiles-Atherton's energy-loss law for walls pinned by defects): the irreversible
    part approaches a saturating anhysteretic curve only while the drive moves towards it, dM_irr = (M_an - M_irr)
    |dV|/k; Gamma = (1 - h) V + h (c M_an + (1 - c) M_irr), M_an = tanh law of width a. Through the strip's measured step
    response (inject_fresh2._drive_side); h 0.2-0.4, k 0.05-0.15, a 0.6-1.2 of the session's peak drive, c 0.3-0.6."""
    h, kk, aa, c = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.05, 0.15), s.rng.uniform(0.6, 1.2), s.rng.uniform(0.3, 0.6)

    def gamma(v: np.ndarray) -> np.ndarray:
        vmax = float(np.max(np.abs(v))) or 1.0
        man = vmax * np.tanh(v / (aa * vmax)) / math.tanh(1 / aa)
        k, mi, prev = kk * vmax, 0.0, float(v[0])
        out = np.empty_like(v)
        for n, (vn, mn) in enumerate(zip(v.tolist(), man.tolist())):
            dv, prev = vn - prev, vn
            if (mn - mi) * dv > 0:
                mi += (mn - mi) * -math.expm1(-abs(dv) / k)
            out[n] = c * mn + (1 - c) * mi
        return (1 - h) * v + h * out

    _drive_side(s, gamma)


# ------------------------------------------------------------------------------------------------ time delay


def td_fir_samples(s: Session) -> None:
    """The laser read by a delta-sigma ADC whose linear-phase decimation FIR (windowed sinc, cut-off 0.4 fs) delays it by
    a fixed number of samples, n_d 2-6: the delay in seconds differs with each record's rate (10-30 ms at 200 Hz, 2-6
    ms at 1 kHz), with a steep roll-off near Nyquist."""
    nd = int(s.rng.integers(2, 7))
    k = np.arange(2 * nd + 1) - nd
    fir = np.sinc(0.8 * k) * np.hanning(2 * nd + 3)[1:-1]
    fir /= fir.sum()

    def f(r: Rec) -> np.ndarray:
        past = _past(s, r, "disp_m", (2 * nd + 2) / r.fs, r.fs)
        return np.convolve(np.r_[past, r.cols["disp_m"]], fir)[past.size : past.size + r.cols["disp_m"].size]

    new = {id(r): f(r) for r in s.series()}
    map_disp(s, lambda r, d: new[id(r)])


def td_dac_latency(s: Session) -> None:
    """The recorded voltage is the waveform as programmed, stamped on the input clock, while the output task starts on
    its own software trigger and through its DAC's FIFO tau later: current and displacement both late by tau against
    v_V (the current's charging spike too). tau 3-15 ms (log)."""
    tau = lu(s.rng, 3e-3, 15e-3)
    late = lambda r: lambda z: np.exp(-z * tau)  # noqa: E731
    cur = _through_x(s, {id(r): r.cols["i_A"] for r in s.series()}, late, 1.0)
    _map_through(s, late, 1.0)
    for r in s.series():
        r.cols["i_A"] = cur[id(r)]


# ------------------------------------------------------------------------------------------------ sensor offset


def so_optical_lever(s: Session) -> None:
    """An optical lever: the laser reflected off the strip at x_m = 0.75-0.95 L onto a position-sensitive detector reads
    the slope there, converted to tip displacement as a uniform arc would give it, w' (x_m) L^2/(2 x_m); through the
    beam's transfer functions (the slope's modal shapes differ from the tip height's)."""
    from labrig.physics import transfer

    frac = s.rng.uniform(0.75, 0.95)

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        L = sp.geometry.length
        x, dx = frac * L, 1e-3 * L

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                up, dn = (transfer.displacement_tf(z, sp.with_(sensor_x=x + e)) for e in (dx, -dx))
                return (up - dn) / (2 * dx) * L**2 / (2 * x) / transfer.displacement_tf(z, sp)

        return h

    _map_through(s, ratio, 2.0)


def so_camera_fit(s: Session) -> None:
    """Video tracking of ink markers along the strip, the tip itself lost in the glare: five stations over [a, b] L
    (a 0.3-0.5, b 0.75-0.9), a least-squares uniform-curvature fit w = k x^2/2 extrapolated to the tip, k L^2/2 =
    L^2 sum x_i^2 w(x_i)/sum x_i^4; through the beam's transfer functions at the stations."""
    from labrig.physics import transfer

    a, b = s.rng.uniform(0.3, 0.5), s.rng.uniform(0.75, 0.9)

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        L = sp.geometry.length
        xs = np.linspace(a, b, 5) * L
        c = L**2 * xs**2 / np.sum(xs**4)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                return sum(ci * transfer.displacement_tf(z, sp.with_(sensor_x=x)) for ci, x in zip(c, xs)) / transfer.displacement_tf(z, sp)

        return h

    _map_through(s, ratio, 2.0)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def _clamp_law(s: Session, rel: Callable[[np.ndarray, float, float], np.ndarray]) -> None:
    """The clamp force relative to its setting, rel(t, p, t_set), on the load cell (the indicator's 0.01 kgf) and on
    the strip through the preset's clamp law: each record is the specimen clamped at p rel (its mean over the record),
    the contact resistance and the root's stiffness with it (gain and f1 move), not a gain law."""
    first: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        first[p] = min(first.get(p, np.inf), float(r.cols["t_s"][0]))
    mean = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        x = rel(r.cols["t_s"], p, first[p])
        if "force_N" in r.cols:
            r.cols["force_N"] = np.round(r.cols["force_N"] * x / 0.0980665) * 0.0980665
        mean[id(r)] = p * float(np.mean(x))
    pre = _preset(s)
    _ratio_both(s, lambda r: pre.specimen(mean[id(r)]))


def cr_thermal_preload(s: Session) -> None:
    """The clamp frame (aluminium) and its screw (steel) warm with the room or the amplifiers after the bench is switched
    on: their differential expansion opens the jaw gap and the preload falls with the temperature rise since each
    setting, 1 - L (T(t) - T(t_set)), T = 1 - exp(-(t - t0)/tau_th): the early blocks lose most, the late ones little.
    L 0.08-0.2 (2-4 K at 3-5 %/K), tau_th 600-2000 s (log)."""
    loss, tau = s.rng.uniform(0.08, 0.2), lu(s.rng, 600.0, 2000.0)
    T = lambda t: -np.expm1(-(np.asarray(t) - s.t0) / tau)  # noqa: E731
    _clamp_law(s, lambda t, p, t_set: 1 - loss * (T(t) - T(t_set)))


def cr_boltzmann(s: Session) -> None:
    """The pads as a linear viscoelastic solid under a held gap: each re-setting adds a gap increment, and the force is the
    Boltzmann superposition of every increment's relaxation, F(t) = sum_j du_j G(t - t_j), G = 1 - r (1 - exp(-t/tau)):
    the earlier settings keep relaxing in the later blocks. r 0.1-0.25, tau 300-1500 s (log)."""
    rr, tau = s.rng.uniform(0.1, 0.25), lu(s.rng, 300.0, 1500.0)
    G = lambda t: 1 - rr * -np.expm1(-np.clip(t, 0, None) / tau)  # noqa: E731
    starts: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        starts[p] = min(starts.get(p, np.inf), float(r.cols["t_s"][0]))
    order = sorted(starts, key=starts.get)
    du: list[float] = []
    for j, p in enumerate(order):
        du.append(p - sum(du[i] * float(G(starts[p] - starts[order[i]])) for i in range(j)))

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        j = order.index(p)
        return sum(du[i] * G(t - starts[order[i]]) for i in range(j + 1)) / p

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_stiffening(s: Session) -> None:
    """Drying stiffens the polymer (Nafion's modulus rises steeply as it loses water) while the coupling, capacitance and
    leak fall: per record the specimen with E x (1 + g x), alpha x (1 - x), Q0 x (1 - c x), R_p / (1 - c x) through the
    strip's transfer functions (the gain falls and f1 rises; spectra follow); the loss follows Page's thin-layer drying
    law x = total (1 - exp(-k u^n))/(1 - exp(-k)). total 0.08-0.2, g 1-2.5, c 0.3-0.8, n 0.6-1.4, k 1-3."""
    from labrig.physics import transfer

    total, g, c = s.rng.uniform(0.08, 0.2), s.rng.uniform(1.0, 2.5), s.rng.uniform(0.3, 0.8)
    n, k = s.rng.uniform(0.6, 1.4), s.rng.uniform(1.0, 3.0)
    loss = lambda t: total * -np.expm1(-k * np.clip((t - s.t0) / (s.t1 - s.t0), 0, 1) ** n) / -math.expm1(-k)  # noqa: E731

    def dried(sp, x: float):
        m, ln = sp.mechanics, sp.line
        return sp.with_(mechanics=replace(m, E=m.E * (1 + g * x), alpha=m.alpha * (1 - x)),
                        line=replace(ln, Q0=ln.Q0 * (1 - c * x), R_p=ln.R_p / (1 - c * x)))

    for j, r in enumerate(s.recs):  # a spectrum at the start of the series after it (no clock of its own)
        if r.series:
            continue
        after = next((q for q in s.recs[j + 1 :] if q.series), None)
        sp = _spec(s, r)
        z = 2j * np.pi * r.cols["f_Hz"]
        zz = (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) * transfer.admittance_tf(z, sp) / transfer.admittance_tf(
            z, dried(sp, float(loss(after.cols["t_s"][0] if after else s.t1))))
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = zz.real, zz.imag
    _ratio_both(s, lambda r: dried(_spec(s, r), float(loss(np.mean(r.cols["t_s"])))))


def dh_convective(s: Session) -> None:
    """A strip in air loses water by evaporation through its boundary layer, which the strip's own motion thins (forced
    convection, Sherwood ~ Re^(1/2)): the drying rate is a still-air share plus a term in the square root of the tip's
    speed, so the loss accumulates fastest in the fast, large records. Loss = total W(t)/W_end through inject._dry;
    total 0.15-0.35, still-air share 0.2-0.5."""
    total, still = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.2, 0.5)
    recs = _chrono(s)
    tt = np.concatenate([r.cols["t_s"] for r in recs])
    speed = [np.sqrt(np.abs(np.gradient(np.convolve(r.cols["disp_m"], np.ones(9) / 9, "same"), r.cols["t_s"]))) for r in recs]
    vref = float(np.mean(np.concatenate(speed)))
    rate = np.concatenate([(1 - still) * v / vref for v in speed]) * np.gradient(tt)
    W = np.cumsum(rate) + still * (tt - s.t0)
    W /= max(W[-1], 1e-30)
    _dry(s, lambda u: total * np.interp(s.t0 + u * (s.t1 - s.t0), tt, W))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_crack_creep(s: Session) -> None:
    """The tensioned electrode's cracks are held by the viscoelastic polymer beneath: their opening (and the resistance)
    follows the tension through the substrate's creep, a lag of 0.3-3 s (log), so the slow records see the full gauge
    and the fast ones little; the other electrode at 0.2-0.5 of the first's gauge. Gains as inject._strain
    (displacement 0.02-0.06, current 0.05-0.15 per unit)."""
    side, tau, gb, ref = _sign(s), lu(s.rng, 0.3, 3.0), s.rng.uniform(0.2, 0.5), ref_disp(s)
    x = {id(r): np.clip(side * r.cols["disp_m"] / ref, 0, None) + gb * np.clip(-side * r.cols["disp_m"] / ref, 0, None) for r in s.series()}
    opened = _through_x(s, x, lambda r: lambda z: 1 / (1 + tau * z), max(10 * tau, 5.0))
    _resist(s, lambda r, e: opened[id(r)], (0.02, 0.06), (0.05, 0.15))


def sr_prestress(s: Session) -> None:
    """The plating leaves the electrodes in residual compression, which holds their cracks shut: each electrode's
    resistance rises only once its tension exceeds its own pre-strain (a dead zone, theta 0.2-0.6 of the displacement
    scale), the second electrode at 0.2-0.6 of the first's gauge. Gains 0.03-0.08 (displacement), 0.08-0.2 (current)."""
    side, ta, tb, gb = _sign(s), s.rng.uniform(0.2, 0.6), s.rng.uniform(0.2, 0.6), s.rng.uniform(0.2, 0.6)
    _resist(s, lambda r, e: np.clip(side * e - ta, 0, None) + gb * np.clip(-side * e - tb, 0, None), (0.03, 0.08), (0.08, 0.2))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_tapered_curvature(s: Session) -> None:
    """The drive's voltage falls along the resistive electrodes, so the actuation curvature decays from the root,
    kappa(s) = kappa0 exp(-s/lambda), lambda 0.5-2 L; the laser reads the exact height of the tip's material point,
    int sin(theta) ds, of the strip whose linear reading is int theta ds = d."""
    lam = s.rng.uniform(0.5, 2.0)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        L = float(s.specimen["length_m"])
        sg = np.linspace(0.0, L, 257)
        th1 = lam * L * -np.expm1(-sg / (lam * L))  # theta(s) per unit kappa0
        dlin1 = np.trapezoid(th1, sg)
        top = float(np.max(np.abs(d))) * 1.05 + 1e-12
        grid = np.linspace(-top, top, 801)
        return np.interp(d, grid, np.trapezoid(np.sin(np.outer(grid / dlin1, th1)), sg, axis=1))

    map_disp(s, f)


def ld_camera_distance(s: Session) -> None:
    """Video tracking of the tip, reported as the distance the tip has moved from rest (signed by its side): on the exact
    arc of curvature 2 d/L^2 the tip rises by (1 - cos kL)/k and draws back by L - sin(kL)/k, so the reading is
    sqrt(Y^2 + (L - X)^2) (a weaker compression than the height alone, fixed by geometry)."""

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        L = float(s.specimen["length_m"])
        k = 2 * d / L**2
        small = np.abs(k * L) < 1e-6
        ks = np.where(small, 1.0, k)
        Y = np.where(small, d, (1 - np.cos(k * L)) / ks)
        back = np.where(small, k**2 * L**3 / 6, L - np.sin(k * L) / ks)
        return np.sign(d) * np.hypot(Y, back)

    map_disp(s, f)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_triac_heater(s: Session) -> None:
    """The bath's (or the room's) heater on a triac phase control: its load current is the line's sine chopped at a
    firing angle of 60-130 deg, rich in odd harmonics, coupling magnetically (the pickup grows with di/dt: harmonic n
    weighted n) into both lines; the lab's grid 50 or 60 Hz (+-0.05), phase locked to the session clock. Peak of the
    wave 1-5 um, 2-10 uA (log)."""
    ad, ai = lu(s.rng, 1e-6, 5e-6), lu(s.rng, 2e-6, 1e-5)
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    alpha = math.radians(s.rng.uniform(60.0, 130.0))
    th = np.linspace(0, 2 * np.pi, 4096, endpoint=False)
    coef = np.fft.rfft(np.where(th % np.pi >= alpha, np.sin(th), 0.0)) / 2048
    n = np.arange(1, 16, 2)
    cn = coef[n] * n
    peak = float(np.max(np.real(np.exp(1j * np.outer(th, n)) @ cn)))
    pd, pi = s.rng.uniform(0, 2 * np.pi, 2)
    for r in s.series():
        ph = 2 * np.pi * f * r.cols["t_s"]
        wave = lambda p: np.real(np.exp(1j * np.outer(ph + p, n)) @ cn) / peak  # noqa: E731
        r.cols["disp_m"] = r.cols["disp_m"] + ad * wave(pd)
        r.cols["i_A"] = r.cols["i_A"] + ai * wave(pi)


def mp_ground_loop(s: Session) -> None:
    """A ground loop between the drive amplifier's and the DAQ's grounds puts a 50 Hz (+-0.05, with a 0.1-0.3 third
    harmonic) voltage in series with the strip: it drives the strip itself, so the current carries it through the
    strip's admittance (2-10 uA, log) and the displacement only through the strip's own response at 50 Hz (tiny, far
    above its resonance), while the recorded (commanded) voltage does not show it."""
    from labrig.physics import transfer

    target, h3, f = lu(s.rng, 2e-6, 1e-5), s.rng.uniform(0.1, 0.3), 50.0 + s.rng.uniform(-0.05, 0.05)
    p1, p3 = s.rng.uniform(0, 2 * np.pi, 2)
    z = 2j * np.pi * np.array([f, 3 * f])
    ps = s.pressures()
    eg = target / abs(transfer.admittance_tf(z[:1], _preset(s).specimen(ps[len(ps) // 2]))[0])
    for r in s.series():
        sp, w = _spec(s, r), 2 * np.pi * f * r.cols["t_s"]
        for col, tf in (("i_A", transfer.admittance_tf), ("disp_m", transfer.displacement_tf)):
            g = tf(z, sp)
            r.cols[col] = r.cols[col] + eg * (np.abs(g[0]) * np.cos(w + p1 + np.angle(g[0])) + h3 * np.abs(g[1]) * np.cos(3 * w + p3 + np.angle(g[1])))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_laser_dropout(s: Session) -> None:
    """The laser loses its target for moments (a gas bubble on the strip's face, a glint off the wet surface): its
    controller holds the last valid reading for each dropout. Dropouts at 0.05-0.3 per s (log, Poisson over the
    records' time), each 20-150 ms (log); the displacement only."""
    rate = lu(s.rng, 0.05, 0.3)
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"].copy()
        for t0 in np.sort(s.rng.uniform(t[0], t[-1], s.rng.poisson(rate * (t[-1] - t[0])))):
            lost = np.flatnonzero((t >= t0) & (t < t0 + lu(s.rng, 0.02, 0.15)))
            if lost.size and lost[0] > 0:
                d[lost] = d[lost[0] - 1]
        r.cols["disp_m"] = d


def out_dac_bit(s: Session) -> None:
    """The laser controller's analogue output comes from a 16-bit R-2R DAC with one mismatched bit (offset binary, zero
    at mid-scale): whenever that bit is set the output is off by e, a square wave in the reading's value with a period
    of 2^(k+1) codes (the bit's weight 50-400 um), e 2-6 um (either sign)."""
    d0 = next(r.cols["disp_m"] for r in s.series())
    steps = np.abs(np.diff(d0))
    q = float(np.min(steps[steps > 1e-8])) if np.any(steps > 1e-8) else 6.1e-7  # the reading's code step
    ks = [k for k in range(2, 16) if 5e-5 <= q * 2**k <= 4e-4] or [8]
    k, e = int(s.rng.choice(ks)), s.rng.uniform(2e-6, 6e-6) * _sign(s)
    map_disp(s, lambda r, d: d + e * ((((np.round(d / q).astype(np.int64) + 32768) >> k) & 1) - 0.5))


def out_pwm_alias(s: Session) -> None:
    """A class-D (PWM) drive amplifier's switching residual at 20-45 kHz, sampled without an anti-alias filter: each
    record sees it aliased to |f_sw - m fs|, a narrow line whose frequency changes with the record's rate (not 50/60 Hz
    or their harmonics, redrawn until so), at a phase of its own per record (the switching is not locked to the DAQ).
    Current 3-15 uA, displacement (radiated into the laser's cable) 0.5-2 um (log)."""
    ai, ad = lu(s.rng, 3e-6, 1.5e-5), lu(s.rng, 5e-7, 2e-6)
    rates = sorted({round(r.fs, 3) for r in s.series()})
    alias = lambda fsw, fs: abs(fsw - fs * round(fsw / fs))  # noqa: E731
    for _ in range(200):
        fsw = s.rng.uniform(20e3, 45e3)
        ok = all(2.0 < alias(fsw, fs) < fs / 2 - 2.0 and min(abs(alias(fsw, fs) - m * base) for base in (50.0, 60.0) for m in range(1, 12)) > 2.0
                 for fs in rates)
        if ok:
            break
    for r in s.series():
        fa = alias(fsw, round(r.fs, 3))
        ph = 2 * np.pi * fa * np.arange(r.cols["t_s"].size) / r.fs + s.rng.uniform(0, 2 * np.pi)
        r.cols["i_A"] = r.cols["i_A"] + ai * np.cos(ph)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * np.cos(ph + s.rng.uniform(-0.5, 0.5))


FRESH4_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"polarity": br_polarity, "cluster_sphere": br_cluster_sphere},
    "faradaic_current": {"bubble_blanket": far_bubble_blanket, "pt_oxide": far_pt_oxide},
    "hysteresis": {"charge_play": hy_charge_play, "pinning_ja": hy_pinning_ja},
    "time_delay": {"fir_samples": td_fir_samples, "dac_latency": td_dac_latency},
    "sensor_offset": {"optical_lever": so_optical_lever, "camera_fit": so_camera_fit},
    "clamp_relaxation": {"thermal_preload": cr_thermal_preload, "boltzmann": cr_boltzmann},
    "dehydration": {"stiffening": dh_stiffening, "convective": dh_convective},
    "strain_resistance": {"crack_creep": sr_crack_creep, "prestress": sr_prestress},
    "large_deflection": {"tapered_curvature": ld_tapered_curvature, "camera_distance": ld_camera_distance},
    "mains_pickup": {"triac_heater": mp_triac_heater, "ground_loop": mp_ground_loop},
    "unexplained": {"laser_dropout": out_laser_dropout, "dac_bit": out_dac_bit, "pwm_alias": out_pwm_alias},
}
inject.register_forms(FRESH4_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_dropped_packets(s: Session) -> None:
    """A USB DAQ's buffer overruns: whole packets (32, 64 or 128 samples, drawn per session) lost from the time series
    with a probability of 0.5-2 % per packet (never the first two or the last), the kept rows with their true time
    stamps: gaps in t_s, every column alike."""
    size, p = int(s.rng.choice([32, 64, 128])), s.rng.uniform(0.005, 0.02)
    for r in s.series():
        m = r.cols["t_s"].size // size
        lost = [j for j in np.flatnonzero(s.rng.random(max(m, 1)) < p) if 1 < j < m - 1]
        if not lost:
            continue
        keep = np.ones(r.cols["t_s"].size, bool)
        for j in lost:
            keep[j * size : (j + 1) * size] = False
        r.cols = {k: x[keep] for k, x in r.cols.items()}


inject.VARIANTS.update({"dropped_packets": v_dropped_packets})

# ------------------------------------------------------------------------------------------------ the cases

P61, S62, T63 = "paper_61", "s001_62", "p20_63"
PLAN = {  # effect: three (form, seed, base, variant); forms alternated over the seeds
    "back_relaxation": [("polarity", 61, P61, "dropped_packets"), ("cluster_sphere", 62, S62, "asrun"), ("polarity", 63, T63, "decimated3")],
    "faradaic_current": [("pt_oxide", 61, P61, "asrun"), ("bubble_blanket", 62, S62, "rate07"), ("pt_oxide", 63, T63, "no_spectra")],
    "hysteresis": [("charge_play", 61, P61, "two_pressures"), ("pinning_ja", 62, S62, "asrun"), ("charge_play", 63, T63, "dropped_packets")],
    "time_delay": [("fir_samples", 61, P61, "asrun"), ("dac_latency", 62, S62, "shortened_shuffled"), ("fir_samples", 63, T63, "own_clock")],
    "sensor_offset": [("optical_lever", 61, P61, "resampled"), ("camera_fit", 62, S62, "dropped_packets"), ("optical_lever", 63, T63, "asrun")],
    "clamp_relaxation": [("boltzmann", 61, P61, "asrun"), ("thermal_preload", 62, S62, "no_spectra"), ("boltzmann", 63, T63, "rate07")],
    "dehydration": [("stiffening", 61, P61, "steps_sines"), ("convective", 62, S62, "asrun"), ("stiffening", 63, T63, "dropped_packets")],
    "strain_resistance": [("crack_creep", 61, P61, "asrun"), ("prestress", 62, S62, "decimated3"), ("crack_creep", 63, T63, "two_pressures")],
    "large_deflection": [("tapered_curvature", 61, P61, "own_clock"), ("camera_distance", 62, S62, "asrun"), ("tapered_curvature", 63, T63, "resampled")],
    "mains_pickup": [("triac_heater", 61, P61, "asrun"), ("ground_loop", 62, S62, "steps_sines"), ("triac_heater", 63, T63, "dropped_packets")],
    "unexplained": [("laser_dropout", 61, P61, "asrun"), ("dac_bit", 62, S62, "asrun"), ("pwm_alias", 63, T63, "asrun"),
                    ("dac_bit", 61, P61, "dropped_packets"), ("pwm_alias", 62, S62, "no_spectra"), ("laser_dropout", 63, T63, "rate07"),
                    ("pwm_alias", 61, P61, "two_pressures"), ("laser_dropout", 62, S62, "own_clock"), ("dac_bit", 63, T63, "shortened_shuffled")],
}
CLEAN = [(61, P61, "asrun"), (61, P61, "dropped_packets"), (62, S62, "asrun"), (62, S62, "rate07"), (63, T63, "asrun"),
         (63, T63, "dropped_packets")]


def fresh4_cases(only: str | None = None) -> list[Case]:
    """The fifth held-out set: 30 effect cases, 9 outside the catalogue, 6 clean (seeds 61-63)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh4_cases, "inject_fresh4", "fresh4")
