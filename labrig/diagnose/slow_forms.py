"""The slow effects' forms: drying over the session (dehydration) and the clamp's force creeping (clamp relaxation).

Each is a shape in time, the session's clock or the charge passed for drying, the time since a pressure's first
record for the clamp (or the shaking its records gave it); ``families.FAMILIES`` registers them as forms of their effect.
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, baseline, creep_since_first_record, follow_force


# ------------------------------------------------------------------------------------------ drying


def drying(loss):
    """Water loss over the session, ``loss(t, sh, ctx)`` in 0..1 at rig time t: the displacement's gain falls by
    k_d x and the conductance by k_i x (one loss of water: the mobile ions' share dries with it, more slowly or
    faster), each from a level of its own. The level is free because the baseline's alpha and electrical values
    were fitted on data already drying: they hold the session's average, not the wet strip."""

    def apply(th, ctx: Context):
        lev_d, k_d, lev_i, k_i, *sh = th
        p = baseline(ctx)
        for k, s in enumerate(ctx.sines):
            x = loss(np.array(s.t_start), sh, ctx)
            p.Hd[k] *= lev_d * (1 - k_d * x)
            p.Hi[k] *= lev_i * (1 - k_i * x)
        for k, st in enumerate(ctx.steps):
            x = loss(st.t_start + (st.t - st.t[0]), sh, ctx)  # the loss runs on during a long step record
            p.step_d[k] = p.step_d[k] * lev_d * (1 - k_d * x)
            p.step_i[k] = p.step_i[k] * lev_i * (1 - k_i * x)
        return p

    apply.loss = loss  # the loss's shape, for the wet strip's refit (wet_strip.py)
    return apply


def session_time(shape):
    """A loss that follows the clock: shape(u) of u, the session's time over its span."""
    return drying(lambda t, sh, ctx: shape(ctx.feats.time_share(t), sh))


def by_charge(t, sh, ctx: Context):
    """Electro-osmotic drying: the hydrated cations drag water to the cathode, where it leaves the polymer, so the
    strip dries while it is driven, with the charge passed (Q = int |i| dt over the session's records, in the
    order they ran), beside the clock's evaporation: x = (1 - a) u + a Q(t)/Q_end."""
    (a,) = sh
    return (1 - a) * ctx.feats.time_share(t) + a * ctx.feats.charge_share(t)


def linear(u, sh):
    """Zero order: evaporation at a constant vapour-pressure deficit removes water at a constant rate."""
    return u


def saturating(u, sh):
    """First order towards the room's equilibrium water content, time constant tau (in session spans)."""
    (tau,) = sh
    return -np.expm1(-u / tau) / -np.expm1(-1.0 / tau)


def power(u, sh):
    """Diffusion-limited loss: water leaving through a skin that thickens as it dries goes as a power of time,
    u^n (Fick: n = 1/2 while the strip's core is still wet; n = 1: zero order, n > 1: a loss that speeds up)."""
    (n,) = sh
    return u**n


def two_stage(u, sh):
    """Two-stage sorption (Berens and Hopfenberg's diffusion-relaxation model, the water a Nafion film takes up or gives
    off): a fast share w by diffusion through the film, the rest at the polymer network's own relaxation, k times
    slower, each first order: w (1 - exp(-u/tau)) + (1 - w)(1 - exp(-u/(k tau))) (u, tau in session spans). A loss
    that runs fast and keeps creeping (the network relaxing, a film or fouling layer growing in two stages, a pore
    filling whose driving force is spent); w = 1 is the saturating form. Normalised to 1 at the session's end."""
    tau, k, w = sh
    f = lambda x: w * -np.expm1(-x / tau) + (1 - w) * -np.expm1(-x / (k * tau))  # noqa: E731
    return f(np.asarray(u, float)) / f(np.array(1.0))


def falling_rate(u, sh):
    """The classic drying curve: a constant-rate period (surface water leaving at a fixed rate) up to the critical
    moisture at u_c, then a falling-rate period in which the rate is proportional to the water still removable,
    approaching it exponentially with the rate continuous at u_c; m is the removable water left at u_c over the
    water lost by then. Normalised to 1 at the session's end."""
    uc, m = sh
    f = lambda x: np.where(x < uc, x / uc, 1.0 + m * -np.expm1(-(x - uc) / (uc * m)))  # noqa: E731
    return f(u) / f(np.array(1.0))


def from_onset(u, sh):
    """Drying that starts at a moment inside the session, u0 (a humidifier's tank runs dry, a purge stops, a door is
    left open): nothing before it, then first order towards the new equilibrium with tau (in session spans)."""
    u0, tau = sh
    x = np.maximum(np.asarray(u, float) - u0, 0.0)
    return -np.expm1(-x / tau) / -np.expm1(-max(1.0 - u0, 1e-6) / tau)


def per_setting(t, sh, ctx: Context):
    """Water set anew at each clamp setting (the operator opens a shield or a lid to re-clamp, squeezes the pads that
    feed the strip, lets the bath's air in) and followed through the block with the sorption lag tau (s), beside the
    clock's trend: x = (1 - w) u + w exp(-t_b/tau), t_b the time since the block's first record. w > 0: a loss at
    each setting made up through the block; w < 0: a loss that builds through each block and is made up (or steps
    down) at the next setting."""
    w, tau = sh
    return (1 - w) * ctx.feats.time_share(t) + w * np.exp(-ctx.feats.since_setting(t) / tau)


# ------------------------------------------------------------------------------------------ clamp creep


def creep(shape):
    """The clamp's force relaxes as the polymer under it creeps, F/F0 = 1 - r c(t / tau), t from the pressure's
    first record; K_t bar and the gain follow the force the load cell reads (as ``catalogue._clamp_relaxation``)."""

    def apply(th, ctx: Context):
        loss, tau, b_kt, b_gain, *sh = th
        p = baseline(ctx)
        p.force_rel[:] = -loss * shape(creep_since_first_record(ctx) / tau, sh)
        follow_force(p, ctx, b_kt, b_gain)
        return p

    return apply


def log_creep(x, sh):
    """A flat spectrum of relaxation times (a glassy polymer): the force falls with log time, ln(1 + t/tau)."""
    return np.log1p(x)


def power_creep(x, sh):
    """Nutting's law (t/tau)^n, 0 < n < 1: a power-law spectrum of relaxation times (scale-free creep)."""
    (n,) = sh
    return x**n


def two_arm_creep(x, sh):
    """A generalised Maxwell clamp with two arms: a fast share w relaxing with tau and the rest ``ratio`` times
    slower (a polymer's two relaxation processes: chain slip, then the bulk's viscous flow)."""
    ratio, w = sh
    return w * -np.expm1(-x) + (1.0 - w) * -np.expm1(-x / ratio)


def shaking_dose(ctx: Context, threshold: float) -> np.ndarray:
    """Per sine: the shaking its clamp took since its pressure's first record, to the record's middle, as a share of the
    session's. A record shakes the jaw by the strip's tip acceleration, (2 pi f)^2 |d| from its measured displacement,
    and a thread slips past ``threshold`` of the session's largest (Junker's transverse loosening): each cycle above
    it doses (a/a_max - threshold), a record its cycles' worth."""
    acc = np.array([(2 * np.pi * s.f) ** 2 * abs(s.est.displacement[0]) if s.est.displacement.size else 0.0 for s in ctx.sines])
    top = float(np.max(acc)) if acc.size and np.max(acc) > 0 else 1.0
    cycles = np.array([max(s.est.noise_dof / 2 + 1, 1.0) for s in ctx.sines])
    dose = np.clip(acc / top - threshold, 0.0, None) * cycles
    out, run = np.zeros(len(ctx.sines)), {}
    for k in sorted(range(len(ctx.sines)), key=lambda j: ctx.sines[j].t_start):
        q = ctx.sines[k].pressure_kPa
        out[k] = run.get(q, 0.0) + 0.5 * dose[k]
        run[q] = run.get(q, 0.0) + dose[k]
    total = float(np.sum(dose))
    return out / total if total > 0 else out


def shaken_loose(th, ctx: Context):
    """A screw clamp loosened by the records that shake it (a bolted joint's self-loosening under transverse vibration):
    the force falls with the shaking dose since each setting (``shaking_dose``), F = F0 (1 - r (1 - e^-D/D0)), and holds
    through quiet records and rests, beside the pads' own creep with log time, r_c ln(1 + t/tau_c) (the loosening's
    steps sit on it); K_t bar and the gain follow it."""
    loss, d0, threshold, r_c, tau_c, b_kt, b_gain = th
    p = baseline(ctx)
    p.force_rel[:] = -loss * -np.expm1(-shaking_dose(ctx, threshold) / d0) - r_c * np.log1p(creep_since_first_record(ctx) / tau_c)
    follow_force(p, ctx, b_kt, b_gain)
    return p


def room_cycle(th, ctx: Context):
    """A clamp breathing with the room's temperature: an air conditioner or a heating cycles the room (periods of
    minutes to an hour), the screw's and the frame's metals expand by different amounts and the preload follows, F/F0
    = 1 - [a (sin w t - sin w t_s) + b (cos w t - cos w t_s)] - r_c ln(1 + (t - t_s)/tau_c), t the record's time on
    the session's clock and t_s its block's setting (its first record of any kind: the operator set the force then),
    beside the pads' creep. The cycle is the room's, one phase for every block: the held-out blocks sit elsewhere on
    it. a and b enter linearly (one start per period, ``engine._starts``); K_t bar and the gain follow the force."""
    a, b, period, r_c, tau_c, b_kt, b_gain = th
    p = baseline(ctx)
    w = 2 * np.pi / period
    t_rig = np.array([s.t_start for s in ctx.sines], float)
    since = ctx.feats.since_setting(t_rig)  # from the block's first record of any kind
    t = t_rig - ctx.feats.t0
    ts = t - since
    cycle = a * (np.sin(w * t) - np.sin(w * ts)) + b * (np.cos(w * t) - np.cos(w * ts))
    p.force_rel[:] = -cycle - r_c * np.log1p(since / tau_c)
    follow_force(p, ctx, b_kt, b_gain)
    return p


def norton(th, ctx: Context):
    """Power-law (Norton) creep of the polymer under the pads at a fixed jaw gap: the creep rate goes as the stress to
    the n, d sigma/dt = -E A sigma^n, so sigma/sigma0 = (1 + (n - 1) t/tau_p)^(-1/(n - 1)) with tau_p = tau (p/p_top)^(1 - n):
    the top pressure relaxes with tau, lower ones (p/p_top)^(n - 1) times slower (n -> 1: the exponential, alike at
    every pressure). A share r of the force relaxes this way (the rest is carried elastically)."""
    loss, tau, b_kt, b_gain, n = th
    p = baseline(ctx)
    ps = ctx.feats.pressures()
    top = max(ps) if ps else 1.0
    rel_p = np.array([(s.pressure_kPa or top) / top for s in ctx.sines], float)
    p.force_rel[:] = -loss * (1.0 - norton_relaxed(creep_since_first_record(ctx) / tau, rel_p, n))
    follow_force(p, ctx, b_kt, b_gain)
    return p


def norton_relaxed(x: np.ndarray, rel_p: np.ndarray, n: float) -> np.ndarray:
    """sigma/sigma0 of Norton creep at a fixed strain after time x (in tau at the top pressure) for a pressure rel_p
    of the top: (1 + (n - 1) x rel_p^(n - 1))^(-1/(n - 1))."""
    m = max(n - 1.0, 1e-6)
    return np.exp(-np.log1p(m * x * rel_p**m) / m)
