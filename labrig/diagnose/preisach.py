"""Memory of the electromechanical coupling as a Preisach operator: relays with a density over coercivity and bias.

The classical model of rate-independent hysteresis (Mayergoyz): a continuum of relays, each switching its output to +1
when the input rises to alpha and to -1 when it falls to beta < alpha, summed with a density mu(alpha, beta). In the
coercivity c = (alpha - beta)/2 and bias b = (alpha + beta)/2 coordinates the density here is a product of two
Gaussians, c about c0 with spread s_c and b about b0 with spread s_b (in units of the session's largest drive V_m):
relays that switch at a coercive voltage (a domain's, a trapped ion population's), loops centred off zero where the bias
does not vanish (the two electrodes unlike, a remanent bend), saturating once the drive passes the relays' thresholds.
It is not the Prandtl-Ishlinskii operator of ``families._pi_drive`` (plays: a loop that never saturates, always centred):
the relay density has no play equivalent unless it is uniform along the bias, and a bias makes even harmonics.

The strip is driven by (1 - w) v + w V_m P[v], P the density-weighted relay sum less its value at rest (the
demagnetised state, relays of negative bias up: ``rest_states``), the gain refitted (as ``catalogue.played_drive``).
The relays sit on a fixed grid of (c, b) for the session, so their states depend on the drive alone and are computed
once (``catalogue.by_records``); a fit only changes the density's weights:

* sines, in their periodic steady state A cos(theta): a relay that the cycle crosses both ways (A >= alpha, -A <= beta)
  is +1 on [0, theta_1) and [theta_2, 2 pi), theta_1 = arccos(beta/A), theta_2 = 2 pi - arccos(alpha/A), so its k-th
  complex Fourier coefficient is 2 (exp(-i k theta_2) - exp(-i k theta_1)) / (i pi k) (``relay_harmonics``; a square
  wave's 4/pi at alpha = beta = 0); a relay the cycle does not cross holds and adds no harmonic. The 2nd and 3rd
  harmonics of the drive pass the strip's response at 2f and 3f;
* steps, relay by relay on the record's block-mean drive from rest (``relay_states``), then through the strip's
  dynamics as the play forms' steps.
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import (Context, Prediction, _drive, at_full_rate, baseline, block_drive, by_records,
                                      frf_by_pressure)
from labrig.diagnose.features import predict_step, specimen_for
from labrig.physics import transfer

COERCIVITY_GRID = np.linspace(0.02, 1.0, 25)  # c / V_m
BIAS_GRID = np.linspace(-0.8, 0.8, 17)  # b / V_m
PARAMS = ("weight", "coercivity", "coercivity_spread", "bias", "bias_spread", "gain", "rest_shift")


def relay_harmonics(amp: np.ndarray, alpha: np.ndarray, beta: np.ndarray) -> np.ndarray:
    """Complex Fourier coefficients k = 1, 2, 3 of each relay (alpha, beta) driven by amp cos(theta) in its periodic
    steady state, shape (3, len(amp), len(alpha)): y = Re sum_k c_k exp(i k theta); 0 where the cycle does not cross
    the relay both ways."""
    a = np.asarray(amp, float)[:, None]
    crossed = (a >= alpha[None, :]) & (-a <= beta[None, :]) & (a > 0)
    safe = np.where(a > 0, a, 1.0)
    th1 = np.arccos(np.clip(beta[None, :] / safe, -1.0, 1.0))
    th2 = 2 * np.pi - np.arccos(np.clip(alpha[None, :] / safe, -1.0, 1.0))
    k = np.arange(1, 4)[:, None, None]
    c = 2 * (np.exp(-1j * k * th2) - np.exp(-1j * k * th1)) / (1j * np.pi * k)
    return np.where(crossed[None], c, 0.0)


def rest_states(bias: np.ndarray) -> np.ndarray:
    """The demagnetised state: relays of negative bias up, of positive bias down (a staircase on the alpha = -beta line)."""
    return np.where(bias < 0, 1.0, -1.0)


def relay_states(v: np.ndarray, alpha: np.ndarray, beta: np.ndarray, start: np.ndarray) -> np.ndarray:
    """Each relay's state at each sample of the drive ``v`` from ``start``, shape (len(v), len(alpha)): the last
    crossing decides, up at v >= alpha, down at v <= beta."""
    idx = np.arange(v.size)[:, None]
    up = np.maximum.accumulate(np.where(v[:, None] >= alpha[None, :], idx, -1), axis=0)
    down = np.maximum.accumulate(np.where(v[:, None] <= beta[None, :], idx, -1), axis=0)
    return np.where(up > down, 1.0, np.where(down > up, -1.0, start[None, :]))


def _relays(ctx: Context) -> dict:
    """The session's relay grid and what the drive makes of it (made once for the records' lists)."""

    def make() -> dict:
        sine_amps = np.array([abs(_drive(s)) for s in ctx.sines])
        vm = max([*sine_amps, *(float(np.max(np.abs(st.v_full))) for st in ctx.steps if st.v_full.size)], default=1.0) or 1.0
        c, b = (g.ravel() * vm for g in np.meshgrid(COERCIVITY_GRID, BIAS_GRID, indexing="ij"))
        alpha, beta = b + c, b - c
        keep = (alpha <= 1.05 * vm) & (beta >= -1.05 * vm)  # the others never switch: the drive never reaches them
        c, b, alpha, beta = c[keep], b[keep], alpha[keep], beta[keep]
        start = rest_states(b)
        harm = relay_harmonics(sine_amps, alpha, beta) if ctx.sines else None
        steps = []
        for st in ctx.steps:
            states = relay_states(block_drive(st), alpha, beta, np.zeros_like(b))  # 0: not switched yet
            steps.append((states, (states != 0).astype(float)))
        straddle = (beta < 0) & (alpha > 0)  # held at 0 V in whatever state the records before left them
        return {"vm": vm, "c": c / vm, "b": b / vm, "harm": harm, "steps": steps, "start": start, "straddle": straddle}

    return by_records("preisach", (ctx.sines, ctx.steps), make)


def density(c: np.ndarray, b: np.ndarray, c0: float, sc: float, b0: float, sb: float) -> np.ndarray:
    """The relays' weights: a Gaussian in coercivity times a Gaussian in bias (units of V_m), summing to 1 over the
    grid's relays the drive can switch."""
    w = np.exp(-0.5 * ((c - c0) / sc) ** 2 - 0.5 * ((b - b0) / sb) ** 2)
    total = w.sum()
    return w / total if total > 0 else w


def _at_double(ctx: Context) -> np.ndarray:
    """The baseline's displacement FRF at twice each sine's frequency (the drive's 2nd harmonic through the strip),
    once per context's specimens."""
    hit = ctx.cache.get("Hd2")
    if hit is None:
        hit = ctx.cache["Hd2"] = frf_by_pressure(ctx.sines, ctx.specimens, tf=lambda f, sp: transfer.frf(2 * np.asarray(f), sp))
    return hit


def preisach_drive(th, ctx: Context) -> Prediction:
    """The strip driven by (1 - w) v + w V_m P[v], P the Preisach operator of the module's docstring, the gain
    refitted: sines by the relays' steady-state harmonics, steps from rest through the strip's dynamics."""
    w, c0, sc, b0, sb, gain, shift = th
    p = baseline(ctx)
    r = _relays(ctx)
    mu = density(r["c"], r["b"], c0, sc, b0, sb)
    vm = r["vm"]
    if ctx.sines:
        drv = np.array([_drive(s) for s in ctx.sines])
        a = np.abs(drv)
        a_safe = np.where(a > 0, a, 1.0)
        c1, c2, c3 = (h @ mu * vm / a_safe for h in r["harm"])
        g1 = (1 - w) + w * c1
        p.Hd = p.Hd * g1 * gain
        ph = drv / a_safe
        p.hd[:, 0] = p.hd[:, 0] + w * c2 * _at_double(ctx) / (g1 * ctx.Hd) * ph
        p.hd[:, 1] = p.hd[:, 1] + w * c3 * ctx.Hd3 / (g1 * ctx.Hd) * ph**2
    start = np.where(r["straddle"], np.clip(r["start"] + shift, -1.0, 1.0), r["start"])
    for k, st in enumerate(ctx.steps):
        states, switched = r["steps"][k]
        # each relay's state less its start: its state where it switched (0 before), less the start there
        relayed = at_full_rate((states @ mu - switched @ (start * mu)) * vm, st)
        sp = specimen_for(ctx.specimens, st.pressure_kPa)
        p.step_d[k] = gain * predict_step(sp, st, (1 - w) * st.v_full + w * relayed)[0]
    return p
