"""A fourth held-out set for the diagnosis (issue 12), written without sight of the diagnosis (its code, its doc, its
tests, its results).

Two forms per catalogue effect, each from the physics of the effect's cause and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), of bench/inject_fresh2.py and of the simulated bench
(mock_devices/effects.py); three structures outside the catalogue (truth "unexplained"); clean sessions. All on three
bases of new seeds (51-53: the paper strip, the seed-001 strip on its own sweep, the paper strip 35 mm free) and on
protocol / data-shape variants, one of them new here: every series linearly interpolated onto a grid at 0.7 of its
rate (a DAQ whose rate is not an integer fraction of the bench's).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); its tools and those of
bench/inject_fresh2.py are reused (importing the latter also registers its two variants), and the forms, bases,
preset and variant of this set are registered into inject's lookups at import.

Run: python bench/inject_fresh3.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
from inject import Case, Rec, Session, _dry, lti, lu, map_disp, play, ref_disp
from inject_fresh2 import _chrono, _drive_side, _map_through, _spec


# the paper's strip 35 mm free (a free length no earlier set used: 30, 40, 25 mm): registered in every process that imports this module
inject.register_free_length("paper_35", 0.035)

inject.BASES.update({
    "paper_51": ("paper-sweep", "paper", 51),
    "s001_52": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 52),
    "p35_53": ("paper-sweep", "paper_35", 53),
})


def _sign(s: Session) -> float:
    return 1.0 if s.rng.random() < 0.5 else -1.0


def _cat(s: Session, col: str) -> tuple[list[Rec], np.ndarray, list[int]]:
    """The series in time order, one column of them concatenated, and the record boundaries."""
    recs = _chrono(s)
    return recs, np.concatenate([r.cols[col] for r in recs]), list(np.cumsum([r.cols[col].size for r in recs])[:-1])


def _through_x(s: Session, x: dict[int, np.ndarray], H: Callable[[Rec], Callable[[np.ndarray], np.ndarray]],
               memory_s: float, dc_at_first_line: bool = False) -> dict[int, np.ndarray]:
    """inject_fresh2._through for any per-record signal ``x`` (id(record) -> array): each record's x through H(r),
    preceded by memory_s of the session's x before it (linear across the rests, zero before the session) and
    followed by its own last value held (``dc_at_first_line``: inject.lti's)."""
    recs = _chrono(s)
    T = np.concatenate([r.cols["t_s"] for r in recs])
    X = np.concatenate([x[id(r)] for r in recs])
    out = {}
    for r in recs:
        xr, n, k = x[id(r)], x[id(r)].size, int(memory_s * r.fs)
        past = np.interp(r.cols["t_s"][0] - np.arange(k, 0, -1) / r.fs, T, X, left=0.0)
        out[id(r)] = lti(np.r_[past, xr, np.full(n, xr[-1])], r.fs, H(r), dc_at_first_line)[k : k + n]
    return out


def _past(s: Session, r: Rec, col: str, seconds: float, fs: float) -> np.ndarray:
    """``seconds`` of the session's column before record r at the rate fs (linear across the rests, 0 before)."""
    recs = _chrono(s)
    T = np.concatenate([q.cols["t_s"] for q in recs])
    X = np.concatenate([q.cols[col] for q in recs])
    k = int(seconds * fs)
    return np.interp(r.cols["t_s"][0] - np.arange(k, 0, -1) / fs, T, X, left=0.0)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_wet_diffusivity(s: Session) -> None:
    """Back-diffusion whose speed depends on how far the water has been pushed: the diffusion coefficient of water
    in Nafion rises steeply with the local water content (Zawodzinski; D grows ~5x from lambda 4 to 14), so the
    more the cathode side has swollen (the larger the bend), the faster water flows back. The opposing flux x
    follows the bending d through a lag whose time constant falls with the bend, tau = tau0/(1 + g |d|/d_ref),
    and the strip reads d - K2 x: a large 1 V step relaxes within seconds, the 0.5 V sines see a slow lag.
    K2 0.9-1.3, tau0 8-25 s (log) at rest, g 0.3-1 (tau at the 1 V step's peak 1/2-1/5 of tau0). The lag's
    state runs through the session in time order (across the rests, towards the mean of their ends)."""
    k2, tau0, g = s.rng.uniform(0.9, 1.3), lu(s.rng, 8.0, 25.0), s.rng.uniform(0.3, 1.0)
    ref, x, t_end, d_end = ref_disp(s), 0.0, None, 0.0
    for r in _chrono(s):
        t, d = r.cols["t_s"], r.cols["disp_m"]
        if t_end is not None:  # the rest before the record
            target = 0.5 * (d_end + d[0])
            x = target + (x - target) * math.exp(-(t[0] - t_end) * (1 + g * abs(target) / ref) / tau0)
        rate = -np.expm1(-np.diff(t, prepend=t[0]) * (1 + g * np.abs(d) / ref) / tau0)
        out = np.empty_like(d)
        for k, (dk, ak) in enumerate(zip(d.tolist(), rate.tolist())):
            x += (dk - x) * ak
            out[k] = dk - k2 * x
        t_end, d_end = float(t[-1]), float(d[-1])
        r.cols["disp_m"] = out


def br_clamp_pressure(s: Session) -> None:
    """Back relaxation set by the clamp: the water that flows back is a Darcy flow through the polymer's pores, and
    the clamp's pressure compacts the strip near its root (where the bend matters most for the tip), so the
    permeability falls with the pressure (Kozeny-Carman, k ~ porosity^3) and the flow slows: tau2 grows as
    (p/p_min)^m, m 0.3-0.7; less free water is left to give back, K2 falls as (p/p_min)^-q, q 0-0.15. One lag per
    record at its own pressure, 1 - K2(p)/(tau2(p) s + 1), with the session's history. K2 at the lowest pressure
    1.0-1.3, tau2 there 3-8 s (log): at the paper strip's 4287 kPa tau2 is 1.8-3.9x longer."""
    k20, tau0 = s.rng.uniform(1.0, 1.3), lu(s.rng, 3.0, 8.0)
    m, q = s.rng.uniform(0.3, 0.7), s.rng.uniform(0.0, 0.15)
    p0 = min(s.pressures())

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        x = float(r.entry["pressure_kPa"]) / p0
        k2, tau = k20 * x**-q, tau0 * x**m
        return lambda z: 1 - k2 / (tau * z + 1)

    _map_through(s, H, 120.0)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_orr_diffusion(s: Session) -> None:
    """Oxygen reduction on whichever electrode is the cathode (dissolved O2 in the water film or bath), with Tafel
    kinetics k(v) = exp((v - E_half)/b) at the interface's potential (the terminal voltage through the double
    layer's charging lag, 20-100 ms, log) and the O2 brought by diffusion across a Nernst layer (tau_D = delta^2/D
    1-10 s, log: delta 45-140 um at D = 2e-9 m^2/s). The flux J = k c_s, the surface concentration depleted by the
    flux through the layer (ten diffusion modes, state kept through the session): a Cottrell spike ~ 1/sqrt(t) at
    each edge, a steady wave k/(1 + k) (Koutecky-Levich) after it, and a layer still depleted when the next record
    starts. E_half 0.3-0.6 V, b 50-100 mV, the kinetic rate capped at 50x the transport's; the limiting current
    0.1-0.5 mA (log: nFDC/delta over the strip's faces at 0.25 mM O2 is ~0.5 mA). Current only."""
    ilim, eh, b = lu(s.rng, 1e-4, 5e-4), s.rng.uniform(0.3, 0.6), s.rng.uniform(0.05, 0.1)
    taud, taui = lu(s.rng, 1.0, 10.0), lu(s.rng, 0.02, 0.1)
    lam = ((np.arange(10) + 0.5) * np.pi) ** 2 / taud  # the layer's modes: the flux enters at the electrode, c = c* at its far side
    g = 1.0 / np.sum(1.0 / lam)  # the steady surface deficit equals J (J in units of the limiting flux)
    a, t_end = np.zeros((2, lam.size)), None
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None:
            a *= np.exp(-lam * (t[0] - t_end))  # the rest at 0 V: no reaction, the layer refills
        v = lti(r.cols["v_V"], r.fs, lambda z: 1 / (1 + taui * z))
        k = np.minimum(np.exp((np.stack([v, -v]) - eh) / b), 50.0)  # row 0: the electrode that is the cathode for v > 0
        e = np.exp(-lam / r.fs)
        w = g * (1 - e) / lam
        B = float(w.sum())
        J = np.empty((2, t.size))
        for n in range(t.size):
            a *= e
            kn = k[:, n]
            j = kn * (1 - a.sum(axis=1)) / (1 + kn * B)  # implicit in J: stable for any k
            a += j[:, None] * w
            J[:, n] = j
        r.cols["i_A"] = r.cols["i_A"] + ilim * (J[0] - J[1])
        t_end = float(t[-1])


def far_redox_couple(s: Session) -> None:
    """A dissolved redox couple (e.g. Fe3+/Fe2+ from a steel clamp's corrosion, or a quinone impurity) shuttled
    between the bath and both electrodes: reduced on the cathode, oxidised on the anode, each surface Nernstian, so
    the cell's steady current is a saturating wave i_r tanh(v/(2 w)) (w 50-100 mV: 2RT/F broadened by the
    electrode's distributed resistance), limited by diffusion across the Nernst layers: the current follows the
    wave through the finite diffusion's admittance W = sqrt(tau_D s) coth(sqrt(tau_D s)) (tau_D 1-10 s, log) in
    series with the charge transfer's finite rate (a Randles cell: W (1 + 1/kap)/(1 + W/kap), kap 2-4 the kinetic
    over the transport current), at the interface's potential (double-layer lag 20-100 ms, log). On a sweep: a
    current peak as the drive crosses 0 V (the couple's potential) that decays as the layer depletes; opposite in
    curvature to electrolysis (saturating, not exponential). Plateau i_r 0.03-0.15 mA (log), fast sweeps' peaks up
    to (1 + kap) times that. Current only."""
    ir, w, taud, taui = lu(s.rng, 3e-5, 1.5e-4), s.rng.uniform(0.05, 0.1), lu(s.rng, 1.0, 10.0), lu(s.rng, 0.02, 0.1)
    kap = s.rng.uniform(2.0, 4.0)
    theta = {id(r): np.tanh(lti(r.cols["v_V"], r.fs, lambda z: 1 / (1 + taui * z)) / (2 * w)) for r in s.series()}

    def K(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        def k(z: np.ndarray) -> np.ndarray:
            q = np.sqrt(taud * z + 0j)
            small = np.abs(q) < 1e-6
            W = np.where(small, 1.0 + 0j, q / np.tanh(np.where(small, 1.0, q)))
            return W * (1 + 1 / kap) / (1 + W / kap)

        return k

    new = _through_x(s, theta, K, 60.0)
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + ir * new[id(r)]


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_maxwell_slip(s: Session) -> None:
    """Dry friction inside the bending strip: the plated Pt electrode is a mosaic of platelets (mud cracks) that
    slide over each other once their shear exceeds a threshold. Parallel elasto-slide (Maxwell-slip / Iwan)
    elements in the bending stiffness: the actuation's moment balances EI kappa plus six spring-slider elements,
    so d_lin = x + sum kappa_i clip(x - s_i, +-r_i) (s_i the sliders, moving when an element's extension reaches
    r_i). Small motions see the stuck elements (stiffer: gain 1/(1 + K)); large ones slide them (gain back towards
    1), with loops. Total added stiffness K 0.2-0.6, slip displacements log-spread over 0.03-0.6 of the displacement
    scale (times 0.7-1.3). Displacement only; the sliders' state runs through the session in time order."""
    K, scale = s.rng.uniform(0.2, 0.6), s.rng.uniform(0.7, 1.3)
    rr = (np.geomspace(0.03, 0.6, 6) * scale * ref_disp(s)).tolist()
    kap = [K / 6] * 6
    sl, x = [0.0] * 6, 0.0
    for r in _chrono(s):
        d = r.cols["disp_m"]
        out = np.empty_like(d)
        for n, dk in enumerate(d.tolist()):
            for _ in range(12):  # the piecewise-linear balance, solved on the active set of the last guess
                num, den = dk, 1.0
                for i in range(6):
                    e = x - sl[i]
                    if e > rr[i]:
                        num -= kap[i] * rr[i]
                    elif e < -rr[i]:
                        num += kap[i] * rr[i]
                    else:
                        num += kap[i] * sl[i]
                        den += kap[i]
                xn = num / den
                if abs(xn - x) < 1e-13:
                    break
                x = xn
            x = xn
            for i in range(6):
                sl[i] = x - min(max(x - sl[i], -rr[i]), rr[i])
            out[n] = x
        r.cols["disp_m"] = out


def hy_stop_drive(s: Session) -> None:
    """Hysterons that saturate, on the drive: each cluster domain of the membrane can take only a limited swelling
    (its water uptake capacity, r_i in volts of drive), follows the drive until it is full, then stays full until
    the drive has reversed by twice its capacity (elastic-perfectly-plastic: the stop operator, not the play).
    Gamma[V] = (1 - h) V + h mean_i stop_{r_i}(V), six radii evenly from r_min 0.15-0.3 V to r_max 0.8-1.2 V: the
    gain is the linear one at small drive and falls at large drive (the opposite of a play sum: 1 V gain 0.88-0.96
    of linear), with loops that open at the reversal and a remanent drive after large excursions. h 0.2-0.4.
    Gamma[V] - V reaches the displacement through the strip's own measured step
    response at each pressure (inject_fresh2's machinery, operator state through the session); current untouched."""
    h, r0, r1 = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.15, 0.3), s.rng.uniform(0.8, 1.2)

    def gamma(v: np.ndarray) -> np.ndarray:
        vmax = float(np.max(np.abs(v))) or 1.0
        stops = [v - play(v, rad * vmax) for rad in np.linspace(r0, r1, 6)]
        return (1 - h) * v + h * np.mean(stops, axis=0)

    _drive_side(s, gamma)


# ------------------------------------------------------------------------------------------------ time delay


def td_frame_latency(s: Session) -> None:
    """The laser streams its readings in frames from its own free-running clock; at a record's trigger its stream
    starts with the next frame, so each record's displacement is late by a fixed processing latency plus a
    fraction of a frame period that differs from record to record (no jitter within a record). Latency 3-15 ms
    (log), frame period 10-40 ms (log), the fraction drawn per record: delays 3-55 ms."""
    fix, frame = lu(s.rng, 3e-3, 15e-3), lu(s.rng, 10e-3, 40e-3)
    lat = {id(r): fix + s.rng.uniform(0.0, frame) for r in s.series()}
    _map_through(s, lambda r: (lambda z, tau=lat[id(r)]: np.exp(-z * tau)), 1.0)


def td_running_median(s: Session) -> None:
    """The laser controller's spike rejection: a causal running median over its last T_w of readings (e.g. 15 or
    31 samples at a 0.5-1 ms cycle) before its analogue output. On a monotone stretch the median is the reading
    T_w/2 ago (a pure delay); at the sine's turning points and the step's corner it flattens and rounds, and it
    removes the white noise's spikes. Computed at >= 1 kHz (the record linearly upsampled, with 1 s of the
    session's history) and read back at the record's rate. T_w 8-40 ms (log): delays 4-20 ms."""
    tw = lu(s.rng, 8e-3, 40e-3)
    from numpy.lib.stride_tricks import sliding_window_view

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        up = max(1, math.ceil(1000.0 / r.fs))
        fs = r.fs * up
        past = _past(s, r, "disp_m", 1.0, r.fs)
        x = np.r_[past, d]
        xi = np.interp(np.arange((x.size - 1) * up + 1) / up, np.arange(x.size), x)
        n = max(2, int(round(tw * fs)))
        med = np.median(sliding_window_view(np.r_[np.full(n - 1, xi[0]), xi], n), axis=1)
        return med[past.size * up :: up][: d.size]

    new = {id(r): f(r, r.cols["disp_m"]) for r in s.series()}
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_spot_drift(s: Session) -> None:
    """The laser's spot walks slowly inboard along the strip during the session: the laser on a magnetic base or a
    tripod settles and the bench warms (a few um/K of its 0.2-0.5 m lever), moving the spot a few mm over an hour.
    The reading is w(x_m(t)) with x_m = (f0 - df u) L, u the session's fraction at the record's middle, through
    the beam's own transfer function at x_m: the quasi-static gain falls ~ (x_m/L)^2 over the session and the
    shape above the first resonance changes with it. f0 0.93-1.0, df 0.08-0.2 (ends at 0.73-0.92 L)."""
    from labrig.physics import transfer

    f0, df = s.rng.uniform(0.93, 1.0), s.rng.uniform(0.08, 0.2)

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        u = (float(np.mean(r.cols["t_s"])) - s.t0) / (s.t1 - s.t0)
        x = (f0 - df * u) * sp.geometry.length
        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):  # s = 0 (lti replaces that bin)
                return transfer.displacement_tf(z, sp.with_(sensor_x=x)) / transfer.displacement_tf(z, sp)

        return h

    _map_through(s, ratio, 2.0)


def so_edge_twist(s: Session) -> None:
    """The spot on the strip's edge (0.3-0.45 of the width off the centreline) while the strip twists as it bends:
    an electrode plated unevenly across the width actuates one half more, a twisting moment in step with the
    bending one. The twist follows the actuation quasi-statically (the first torsion mode of a 4-5 mm wide strip is
    at ~100 Hz in water, ~200 Hz in air: drawn 80-200 Hz, log, damping 0.05), without the bending resonance, so the
    edge reads w + y phi = H(s) V + c W_static(s) T(s) V, W_static the beam's quasi-static (charge-driven)
    deflection per volt and T the torsion mode. Written as (1 + c) times the measured reading plus c (W_static T -
    H) V from the recorded voltage (with the session's history): the difference vanishes at low frequency, where
    the modal sum reaches the quasi-static deflection, so neither the CPE's unbounded low-frequency gain nor the
    measured noise is amplified. A gain 1 + c at low frequency and, above the first bending resonance where the bending falls as 1/f^2,
    a twist reading that stays (comparable to the bending by 10-20 Hz). c = 0.03-0.1 (sign: which edge)."""
    from labrig.physics import transfer

    c, ft = s.rng.uniform(0.03, 0.1) * _sign(s), lu(s.rng, 80.0, 200.0)
    wt = 2 * np.pi * ft

    def twist(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                return c * (transfer.static_deflection(z, sp) / (1 + 0.1 * z / wt + (z / wt) ** 2) - transfer.displacement_tf(z, sp))

        return h

    new = _through_x(s, {id(r): r.cols["v_V"] for r in s.series()}, twist, 2.0)
    map_disp(s, lambda r, d: (1 + c) * d + new[id(r)])


# ------------------------------------------------------------------------------------------------ clamp relaxation


def _clamp_p(s: Session, creep: Callable[[np.ndarray, float], np.ndarray]) -> None:
    """inject._clamp with the pressure passed to the law: force x F/F0 (the indicator's 0.01 kgf) and the
    displacement gain following F^b, b 0.5-1.5, from the first sample of each pressure's block."""
    b = s.rng.uniform(0.5, 1.5)
    first: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        first[p] = min(first.get(p, np.inf), float(r.cols["t_s"][0]))
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        rel = creep(r.cols["t_s"] - first[p], p)
        if "force_N" in r.cols:
            r.cols["force_N"] = np.round(r.cols["force_N"] * rel / 0.0980665) * 0.0980665
        r.cols["disp_m"] = r.cols["disp_m"] * rel**b


def cr_norton(s: Session) -> None:
    """Power-law (Norton) creep of the polymer under the pads, the jaw gap fixed: the creep rate goes as sigma^n, so
    under a fixed total strain the stress relaxes as sigma0 (1 + t/t_c)^(-1/(n-1)) with t_c ~ sigma0^(1-n): the
    high pressures relax much more and faster than the low ones (at n = 4 the 612 kPa block barely moves while the
    4287 kPa block loses r_top). n 3-5; r_top 8-20 % lost over the top pressure's block."""
    n, rtop = s.rng.uniform(3.0, 5.0), s.rng.uniform(0.08, 0.2)
    ptop = max(s.pressures())
    ts = [r.cols["t_s"] for r in s.series() if float(r.entry["pressure_kPa"]) == ptop]
    block = max(float(t[-1]) for t in ts) - min(float(t[0]) for t in ts)
    tc_top = block / ((1 - rtop) ** (1 - n) - 1)
    _clamp_p(s, lambda t, p: (1 + np.clip(t, 0, None) / (tc_top * (p / ptop) ** (1 - n))) ** (-1 / (n - 1)))


def cr_consolidation(s: Session) -> None:
    """Consolidation of the wet polymer under the pads (Terzaghi): at the set force part of the load is carried by
    the pore water, which drains sideways out of the clamped layer; the force falls as the pore pressure
    dissipates, F/F0 = 1 - r U(t/t_v), U Terzaghi's degree of consolidation (sqrt(4T/pi) early, 1 - 8/pi^2
    exp(-pi^2 T/4) late): a sqrt(t) start, then exponential, the same share at every pressure. r 5-15 % (the pore
    water's share of the load), t_v = H_dr^2/c_v 100-800 s (log)."""
    r, tv = s.rng.uniform(0.05, 0.15), lu(s.rng, 100.0, 800.0)

    def U(T: np.ndarray) -> np.ndarray:
        T = np.clip(T, 0, None)
        return np.where(T < 0.2827, np.sqrt(4 * T / np.pi), 1 - 8 / np.pi**2 * np.exp(-(np.pi**2) * T / 4))

    _clamp_p(s, lambda t, p: 1 - r * U(t / tv))


# ------------------------------------------------------------------------------------------------ dehydration


def dh_ion_exchange(s: Session) -> None:
    """Loss of mobile cations to the bath's divalent ions (Ca2+/Mg2+ of tap or poorly deionised water): each binds
    two sulfonates and hardly moves, so the strain per charge and the conductance fall as the exchange proceeds.
    Second-order kinetics (rate ~ free sites x ions left in a small bath) give a hyperbolic approach, not an
    exponential: loss = total (1 + k) u/(1 + k u), u the session's fraction. total 0.15-0.4, k 2-8 (the early
    rate 3-9x the mean). Through inject._dry: conductance loses 0.3-1 of the gain's share, spectra follow."""
    total, k = s.rng.uniform(0.15, 0.4), s.rng.uniform(2.0, 8.0)
    _dry(s, lambda u: total * (1 + k) * u / (1 + k * u))


def dh_humidity_steps(s: Session) -> None:
    """A strip in air follows the room's humidity: the air conditioning switches (or a door opens) and the relative
    humidity drops, later comes back. The water content follows each step through Fickian sorption, a lag
    tau_s = h^2/(pi^2 D) 100-600 s (log), so the strip dries, then re-wets: the loss rises to total at the first
    step (u1 0.1-0.35 of the session) and recovers a share 0.6-1 of it after the second (u2 0.55-0.8).
    total 0.2-0.35 (the equilibrium water content's change for a 15-25 % RH drop)."""
    total, u1, u2, rec = s.rng.uniform(0.2, 0.35), s.rng.uniform(0.1, 0.35), s.rng.uniform(0.55, 0.8), s.rng.uniform(0.6, 1.0)
    tau = lu(s.rng, 100.0, 600.0) / (s.t1 - s.t0)

    def step(u: np.ndarray, at: float) -> np.ndarray:
        return np.where(u > at, -np.expm1(-np.clip(u - at, 0, None) / tau), 0.0)

    _dry(s, lambda u: total * (step(u, u1) - rec * step(u, u2)))


# ------------------------------------------------------------------------------------------------ strain resistance


def _resist(s: Session, shape: Callable[[Rec, np.ndarray], np.ndarray], kd: tuple[float, float], ki: tuple[float, float]) -> None:
    """inject._strain with the record passed to the shape and the gains' ranges given: displacement and current
    gains fall by kd and ki times dR/R(e), e the displacement over the session's scale."""
    ref = ref_disp(s)
    a, b = s.rng.uniform(*kd), s.rng.uniform(*ki)
    for r in s.series():
        e = shape(r, r.cols["disp_m"] / ref)
        r.cols["disp_m"] = r.cols["disp_m"] * (1 - a * e)
        r.cols["i_A"] = r.cols["i_A"] * (1 - b * e)


def sr_fatigue(s: Session) -> None:
    """Fatigue cracking of the tensioned electrode: each strain cycle extends its cracks (Coffin-Manson: damage per
    cycle ~ amplitude^m), so the electrode's strain sensitivity grows through the session: dR/R = e+ (c0 + (1 - c0)
    D(t)/D_end), D the accumulated damage, int |de+| e+^(m-1) over the session in time order (through a 1 % play:
    noise does no damage). c0 0.1-0.4 (the fresh electrode's share), m 1.5-2.5; one side (drawn) in tension.
    Displacement gain falls by 0.02-0.06, current gain by 0.05-0.15 per unit of dR/R (inject._strain's ranges)."""
    side, c0, m = _sign(s), s.rng.uniform(0.1, 0.4), s.rng.uniform(1.5, 2.5)
    recs, e, cuts = _cat(s, "disp_m")
    ep = np.clip(play(side * e / ref_disp(s), 0.01), 0, None)
    D = np.cumsum(np.abs(np.diff(ep, prepend=ep[0])) * ep ** (m - 1))
    fac = dict(zip([id(r) for r in recs], np.split(c0 + (1 - c0) * D / max(D[-1], 1e-30), cuts)))
    _resist(s, lambda r, x: fac[id(r)] * np.clip(side * x, 0, None), (0.02, 0.06), (0.05, 0.15))


def sr_percolation(s: Session) -> None:
    """A cracked electrode near its percolation threshold: stretching opens the cracks and thins the conducting
    network, R ~ (1 - eps/eps_c)^(-t) with the 2-D percolation exponent t = 1.3 (eps_c 0.4-1 % strain: films of
    Pt particles lose conduction at about 1 %), while the compressed electrode's cracks close and its resistance
    falls (a negative gauge of k_c 0.3-0.8 of the other's initial one). Strain from the uniform-curvature reading,
    eps = d h/L^2 (0.2 % at the paper strip's 1 V step peak). Normalised to unit slope at rest in units of the
    displacement scale; the tensioned side drawn. Gains fall by 0.015-0.04 (displacement), 0.04-0.1 (current) per
    unit: convex on one side, falling on the other."""
    side, epsc, kc = _sign(s), s.rng.uniform(4e-3, 1e-2), s.rng.uniform(0.3, 0.8)
    L, h, ref = float(s.specimen["length_m"]), float(s.specimen["thickness_m"]), ref_disp(s)
    eref = ref * h / L**2

    def shape(r: Rec, x: np.ndarray) -> np.ndarray:
        eps = side * x * eref
        ep, em = np.clip(eps, 0, None), np.clip(-eps, 0, None)
        up = (np.clip(1 - ep / epsc, 0.1, None) ** -1.3 - 1) * epsc / 1.3
        return (up - kc * em) / eref

    _resist(s, shape, (0.015, 0.04), (0.04, 0.1))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_precurved(s: Session) -> None:
    """A strip that rests curled along its length (plating and hydration leave most IPMC strips with a rest
    curvature; tip angle theta0 10-25 deg, to either side). Bending adds a uniform curvature 2 d/L^2 to the rest
    one, kappa0 = theta0/L, and the laser, square to the clamp, reads the height of the tip's material point on the
    exact arc, zeroed at rest: (1 - cos kL)/k - (1 - cos k0 L)/k0. Around a curled rest the arc's nonlinearity is
    even-order (bending further into the curl reads less, out of it more: -theta0 d/(2L) relative, ~ 2-8 % at the
    1 V step) on top of the flat arc's odd one."""
    th0 = math.radians(s.rng.uniform(10.0, 25.0)) * _sign(s)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        L = float(s.specimen["length_m"])

        def w(k: np.ndarray) -> np.ndarray:
            kl = k * L
            small = np.abs(kl) < 1e-6
            return np.where(small, k * L * L / 2, (1 - np.cos(kl)) / np.where(small, 1.0, k))

        k0 = th0 / L
        return w(k0 + 2 * d / L**2) - w(np.array(k0))

    map_disp(s, f)


def ld_tape_spring(s: Session) -> None:
    """A strip with a residual curl across its width (a tape spring: the plated sheet it was cut from was curled),
    bent along its length. Plate theory with the width's stretching energy (Mansfield, Calladine): per unit width
    U/D = (kx^2 + dky^2 + 2 nu kx dky)/2 + gamma (kx ky)^2, gamma = (1 - nu^2) b^4/(120 h^2), ky = ky0 + dky the
    transverse curvature, relaxing to ky = (ky0 - nu kx)/(1 + 2 gamma kx^2). The moment M(kx) = dU/dkx is
    stiffer than flat by 2 gamma ky0^2/(1 - nu^2) at rest (E0 0.08-0.2: a transverse radius of 20-55 mm) and, as the
    Poisson coupling flattens or deepens the section with the sign of the bend, stiffer one way and softer the other
    at large curvature. The laser reads d kx/kx_lin, kx solving M(kx) = M'(0) kx_lin (kx_lin = 2 d/L^2): an even
    and odd distortion growing with the bend, the small-signal gain unchanged. nu 0.3-0.45, the curl's side drawn."""
    nu, e0, side = s.rng.uniform(0.3, 0.45), s.rng.uniform(0.08, 0.2), _sign(s)
    L, b, h = (float(s.specimen[k]) for k in ("length_m", "width_m", "thickness_m"))
    gam = (1 - nu**2) * b**4 / (120 * h**2)
    ky0 = side * math.sqrt(e0 * (1 - nu**2) / (2 * gam))

    def M(kx: np.ndarray) -> np.ndarray:
        ky = (ky0 - nu * kx) / (1 + 2 * gam * kx**2)
        return kx + nu * (ky - ky0) + 2 * gam * kx * ky**2

    slope = 1 - nu**2 + 2 * gam * ky0**2

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        klin = 2 * d / L**2
        kx, target = klin.copy(), slope * klin
        for _ in range(60):  # Newton, a central difference for the tangent stiffness
            dk = 1e-6 * (1 + np.abs(kx))
            tan = (M(kx + dk) - M(kx - dk)) / (2 * dk)
            kx = kx - (M(kx) - target) / np.maximum(tan, 0.05 * slope)
        return kx * L**2 / 2

    map_disp(s, f)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_compressor(s: Session) -> None:
    """A refrigerator's (or a chiller's) compressor cycling on the lab's mains: while its motor runs, its field and
    its return currents put 50 Hz (grid off nominal by up to 0.05 Hz) with a 3rd harmonic (the motor's iron,
    0.1-0.3) on both lines; when it stops only the background (0.1-0.3 of it) stays; each start adds the motor's
    inrush (3x, decaying in ~1 s). Period 600-1800 s, on 30-60 % of it: some records have the pickup, some almost
    none. Phase locked to the session clock. Displacement 1-5 um, current 2-10 uA (log) while on."""
    ad, ai, off, h3 = lu(s.rng, 1e-6, 5e-6), lu(s.rng, 2e-6, 1e-5), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.1, 0.3)
    period, duty, ph, f = s.rng.uniform(600.0, 1800.0), s.rng.uniform(0.3, 0.6), s.rng.uniform(0, 1), 50.0 + s.rng.uniform(-0.05, 0.05)
    pd, pi = s.rng.uniform(0, 2 * np.pi, 2)
    for r in s.series():
        t = r.cols["t_s"]
        cyc = ((t - s.t0) / period + ph) % 1.0
        on = cyc < duty
        level = off + (1 - off) * on * (1 + 2 * np.exp(-cyc * period / 1.0))
        wave = lambda p: np.cos(2 * np.pi * f * t + p) + h3 * np.cos(3 * (2 * np.pi * f * t + p))  # noqa: E731
        r.cols["disp_m"] = r.cols["disp_m"] + ad * level * wave(pd)
        r.cols["i_A"] = r.cols["i_A"] + ai * level * wave(pi)


def mp_gain_ripple(s: Session) -> None:
    """The laser controller's and the current amplifier's analogue stages run from a half-wave rectified,
    poorly regulated supply: its 50 Hz ripple modulates their reference voltage, so their gains ripple and the
    pickup is proportional to the signal (sidebands at 50 +- f, nothing at rest), beside a small additive 50 Hz
    of the same origin. Gain ripple 0.05-0.25 % on each line (log: 1-5 um on the 1 V sine's 2 mm), additive
    0.3-1 um and 1-3 uA (log); grid off nominal by up to 0.05 Hz."""
    md, mi, f = lu(s.rng, 5e-4, 2.5e-3), lu(s.rng, 5e-4, 2.5e-3), 50.0 + s.rng.uniform(-0.05, 0.05)
    ad, ai = lu(s.rng, 3e-7, 1e-6), lu(s.rng, 1e-6, 3e-6)
    p, pi = s.rng.uniform(0, 2 * np.pi, 2)
    for r in s.series():
        c = np.cos(2 * np.pi * f * r.cols["t_s"] + p)
        ci = np.cos(2 * np.pi * f * r.cols["t_s"] + pi)
        r.cols["disp_m"] = r.cols["disp_m"] * (1 + md * c) + ad * c
        r.cols["i_A"] = r.cols["i_A"] * (1 + mi * ci) + ai * ci


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_cap_coupling(s: Session) -> None:
    """The laser's analogue cable runs beside the drive leads: the drive voltage couples capacitively into the
    laser's high-impedance input, a high-pass copy of V (corner 1/(2 pi R_in C_c), tau 1-5 ms, log) on the
    displacement channel: a spike at every edge of the step, and a lead on the sines that grows with frequency
    (nothing at 0.1 Hz, a third of the bend at 20 Hz). Coupling 20-80 um per volt (log: 10-40 mV/V on the 2 mm/V
    line)."""
    tau, k = lu(s.rng, 1e-3, 5e-3), lu(s.rng, 2e-5, 8e-5)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + k * lti(r.cols["v_V"], r.fs, lambda z: tau * z / (1 + tau * z))


def _step_responses(r: Rec) -> tuple[np.ndarray, np.ndarray, int, float]:
    """A step record's measured unit-step responses of current and displacement, from the drive's rise to its fall
    (the caller holds them at their last values beyond), the rise's sample and the amplitude."""
    v = r.cols["v_V"]
    amp = float(v[np.argmax(np.abs(v))])
    on = int(np.argmax(v / amp > 0.5))
    off = on + int(np.argmax(v[on:] / amp < 0.5))
    off = off - 10 if off > on + 40 else v.size  # the last samples before the fall may already see it
    pre = max(on - 1, 0)
    out = []
    for col in ("i_A", "disp_m"):
        S = (r.cols[col][on:off] - r.cols[col][pre]) / amp
        S[-1] = float(np.mean(S[-20:]))  # the value held beyond: a mean, not one noisy sample
        out.append(S)
    return out[0], out[1], on, amp


def out_current_limit(s: Session) -> None:
    """The drive amplifier's current limit: its output stage (an op-amp booster or a potentiostat's) can source
    and sink at most I_max, below the strip's charging spike at the step's edges (the series resistance's, 18-28
    mA here), though above every sine's peak. At each edge the current is held at +-I_max and the applied voltage
    lags the commanded (recorded) one until the double layer has taken the charge; the strip bends from the applied
    voltage. Solved sample by sample over 1 s after each edge through the strip's own measured step responses at
    that pressure (current and displacement: a linear strip, superposition of the voltage deficit's steps).
    I_max = 0.5-0.8 of the smallest step peak, at least 1.15x the largest sine peak."""
    frac = s.rng.uniform(0.5, 0.8)
    steps = [r for r in s.series() if r.kind == "step"]
    others = [r for r in s.series() if r.kind != "step"]
    imax = max(frac * min(float(np.max(np.abs(r.cols["i_A"]))) for r in steps),
               1.15 * max((float(np.max(np.abs(r.cols["i_A"]))) for r in others), default=0.0))
    for r in steps:
        Si, Sd, on, amp = _step_responses(r)
        v, i = r.cols["v_V"], r.cols["i_A"]
        n = v.size
        edges = [k for k in range(1, n) if abs(v[k] - v[k - 1]) > 0.25 * abs(amp)]
        dE = np.zeros(n)
        win = int(1.0 * r.fs)
        for k0 in edges:
            m = min(win, n - k0)
            extra = np.zeros(m)  # the current the deficit's earlier steps still drive
            E = 0.0
            for k in range(m):
                rest = i[k0 + k] + extra[k]
                want = -E  # the amplifier closes the gap as fast as the limit lets it
                ik = rest + want * Si[0]
                if abs(ik) > imax:
                    want = (math.copysign(imax, ik) - rest) / Si[0]
                dE[k0 + k] = want
                E += want
                extra[k:] += want * Si[: m - k] if m - k <= Si.size else want * np.r_[Si, np.full(m - k - Si.size, Si[-1])]
        if not np.any(dE):
            continue
        M = 1 << int(math.ceil(math.log2(2 * n)))
        for col, S in (("i_A", Si), ("disp_m", Sd)):
            kern = np.r_[S, np.full(max(n - S.size, 0), S[-1])][:n]
            r.cols[col] = r.cols[col] + np.fft.irfft(np.fft.rfft(dE, M) * np.fft.rfft(kern, M), M)[:n]


def out_pump_vibration(s: Session) -> None:
    """A circulation pump or a fume-hood fan on the same bench: a 4-pole induction motor at 1430-1490 rpm (23.8-24.8
    Hz, its slip) shakes the laser's stand against the strip's clamp: its 1x line (imbalance) and 2x line
    (misalignment, 0.2-0.5 of it) on the displacement only, beating slowly with a second machine (amplitude
    modulated 20-40 % at 0.05-0.2 Hz). Not mains (not 50/60 Hz or their harmonics) and not on the current.
    1-4 um (log)."""
    fp, a, h2 = s.rng.uniform(23.8, 24.8), lu(s.rng, 1e-6, 4e-6), s.rng.uniform(0.2, 0.5)
    mod, fm = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.05, 0.2)
    p1, p2, pm = s.rng.uniform(0, 2 * np.pi, 3)
    for r in s.series():
        t = r.cols["t_s"]
        r.cols["disp_m"] = r.cols["disp_m"] + a * (1 + mod * np.sin(2 * np.pi * fm * t + pm)) * (
            np.sin(2 * np.pi * fp * t + p1) + h2 * np.sin(4 * np.pi * fp * t + p2))


FRESH3_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"wet_diffusivity": br_wet_diffusivity, "clamp_pressure": br_clamp_pressure},
    "faradaic_current": {"orr_diffusion": far_orr_diffusion, "redox_couple": far_redox_couple},
    "hysteresis": {"maxwell_slip": hy_maxwell_slip, "stop_drive": hy_stop_drive},
    "time_delay": {"frame_latency": td_frame_latency, "running_median": td_running_median},
    "sensor_offset": {"spot_drift": so_spot_drift, "edge_twist": so_edge_twist},
    "clamp_relaxation": {"norton": cr_norton, "consolidation": cr_consolidation},
    "dehydration": {"ion_exchange": dh_ion_exchange, "humidity_steps": dh_humidity_steps},
    "strain_resistance": {"fatigue": sr_fatigue, "percolation": sr_percolation},
    "large_deflection": {"precurved": ld_precurved, "tape_spring": ld_tape_spring},
    "mains_pickup": {"compressor": mp_compressor, "gain_ripple": mp_gain_ripple},
    "unexplained": {"cap_coupling": out_cap_coupling, "current_limit": out_current_limit, "pump_vibration": out_pump_vibration},
}
inject.register_forms(FRESH3_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_rate07(s: Session) -> None:
    """Another DAQ, at a rate that is not an integer fraction of the bench's: every series linearly interpolated
    onto a grid at 0.7 of its rate from its first sample (no anti-alias filter, as a resampling DAQ driver does)."""
    for r in s.series():
        t = r.cols["t_s"]
        n = int(math.floor((t[-1] - t[0]) * r.fs * 0.7)) + 1
        tn = t[0] + np.arange(n) / (0.7 * r.fs)
        r.cols = {k: (tn if k == "t_s" else np.interp(tn, t, x)) for k, x in r.cols.items()}


inject.VARIANTS.update({"rate07": v_rate07})

# ------------------------------------------------------------------------------------------------ the cases

P51, S52, L53 = "paper_51", "s001_52", "p35_53"
PLAN = {  # effect: three (form, seed, base, variant); forms alternated over the seeds
    "back_relaxation": [("wet_diffusivity", 51, P51, "rate07"), ("clamp_pressure", 52, S52, "asrun"), ("wet_diffusivity", 53, L53, "steps_sines")],
    "faradaic_current": [("redox_couple", 51, P51, "asrun"), ("orr_diffusion", 52, S52, "own_clock"), ("redox_couple", 53, L53, "shortened_shuffled")],
    "hysteresis": [("maxwell_slip", 51, P51, "no_spectra"), ("stop_drive", 52, S52, "rate07"), ("maxwell_slip", 53, L53, "asrun")],
    "time_delay": [("frame_latency", 51, P51, "asrun"), ("running_median", 52, S52, "two_pressures"), ("frame_latency", 53, L53, "resampled")],
    "sensor_offset": [("spot_drift", 51, P51, "steps_sines"), ("edge_twist", 52, S52, "asrun"), ("spot_drift", 53, L53, "own_clock")],
    "clamp_relaxation": [("norton", 51, P51, "asrun"), ("consolidation", 52, S52, "decimated3"), ("norton", 53, L53, "rate07")],
    "dehydration": [("ion_exchange", 51, P51, "resampled"), ("humidity_steps", 52, S52, "asrun"), ("ion_exchange", 53, L53, "no_spectra")],
    "strain_resistance": [("percolation", 51, P51, "asrun"), ("fatigue", 52, S52, "shortened_shuffled"), ("percolation", 53, L53, "rate07")],
    "large_deflection": [("precurved", 51, P51, "two_pressures"), ("tape_spring", 52, S52, "asrun"), ("precurved", 53, L53, "decimated3")],
    "mains_pickup": [("compressor", 51, P51, "asrun"), ("gain_ripple", 52, S52, "no_spectra"), ("compressor", 53, L53, "own_clock")],
    "unexplained": [("cap_coupling", 51, P51, "asrun"), ("current_limit", 52, S52, "asrun"), ("pump_vibration", 53, L53, "asrun"),
                    ("cap_coupling", 53, L53, "rate07"), ("current_limit", 51, P51, "no_spectra")],
}
CLEAN = [(51, P51, "asrun"), (51, P51, "rate07"), (52, S52, "asrun"), (52, S52, "two_pressures"), (53, L53, "asrun"),
         (53, L53, "decimated3")]


def fresh3_cases(only: str | None = None) -> list[Case]:
    """The fourth held-out set: 30 effect cases, 5 outside the catalogue, 6 clean (seeds 51-53)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh3_cases, "inject_fresh3", "fresh3")
