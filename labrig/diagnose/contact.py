"""A dry contact on the tip whose hold depends on where the tip is: memory in the displacement path.

The tip rubs on something (a cuvette's floor or wall, a guide's slot, a hanger) with Coulomb friction: it sticks while
the strip's pull stays within r of where it is, r the friction over the strip's stiffness. Where the contact's
normal load follows the bend, r follows the tip's position y:

    r(y) = r0 max(1 - (y/y_off)^2, 0) + c |y|

r0 a preload at rest that the bend relieves (the tip drawn up off a floor: the arc's draw-up ~ 2 d^2/3L, gone past
the lift-off y_off); c a load that the bend builds (edges pressed on a slot's walls by the twist that comes with the
bend, a wall the tip leans on harder). c = 0 and y_off past the bends is the plain play (``catalogue._play``); r0 = 0
gives lens loops pinched at rest, loading at d/(1 + c), a constant loss factor. The reading is the tip's position,
read through the gain g (the baseline's alpha took in the contact's mean loss):

    y_k = clip(y_(k-1), d_k - r(y_k), d_k + r(y_k)),  reading g y

Pushed up the tip sits where y + r(y) = d, pushed down where y - r(y) = d: each push is the running extreme of d
mapped through that curve's inverse (tabulated on a grid of y), one vectorised pass per push as in ``catalogue._play``.
The curves must rise (r' > -1): the preload is kept below y_off/2. The sines by their periodic state (fundamental
and 3rd harmonic), the step's prediction read through it as it stands.
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, _drive, baseline
from labrig.diagnose.flag import largest_bend

_N = 64  # points per cycle of the sines' periodic state
_CYCLES = 2  # the first cycle settles the contact from rest, the second is read
_GRID = 2001  # points of the push curves' tables
_FLOOR = 1e-5  # the least hold, of the largest bend


def radius(y: np.ndarray, r0: float, y_off: float, c: float) -> np.ndarray:
    """The contact's stick radius (m) with the tip at ``y`` (m)."""
    y = np.asarray(y, float)
    return r0 * np.clip(1 - (y / y_off) ** 2, 0.0, None) + c * np.abs(y)


def contact_play(d: np.ndarray, r0: float, y_off: float, c: float) -> np.ndarray:
    """The tip's position through the contact, driven by the free bend ``d`` (m), from rest at 0."""
    d = np.asarray(d, float).ravel()
    span = float(np.max(np.abs(d), initial=0.0)) * 1.001 + 1e-12
    grid = np.linspace(-span, span, _GRID)
    eps = _FLOOR * span  # a hold below any reading: a free tip's prediction wiggling at rounding level is no push
    r = radius(grid, r0, y_off, c) + eps
    up, down = np.maximum.accumulate(grid + r), np.maximum.accumulate(grid - r)  # d where a push leaves y: rising
    y = np.empty_like(d)
    k, state = 0, 0.0
    while k < d.size:
        rs = float(radius(state, r0, y_off, c)) + eps
        out = np.flatnonzero(np.abs(d[k:] - state) > rs)  # the first sample that pushes the tip
        if out.size == 0:
            y[k:] = state
            break
        j = k + out[0]
        y[k:j] = state
        if d[j] > state:
            push = np.interp(np.maximum.accumulate(d[j:]), up, grid)
            back = np.flatnonzero(d[j:] < np.interp(push, grid, down))  # turned back through the hold
        else:
            push = np.interp(np.minimum.accumulate(d[j:]), down, grid)
            back = np.flatnonzero(d[j:] > np.interp(push, grid, up))
        end = j + (back[0] if back.size else d.size - j)
        y[j:end] = push[: end - j]
        state, k = float(y[end - 1]), end
    return y


def contact_df(a: np.ndarray, r0: float, y_off: float, c: float) -> tuple[np.ndarray, np.ndarray]:
    """Describing function of the contact at sine amplitudes ``a`` (m): fundamental and 3rd harmonic of the tip's
    position over the amplitude (complex, cosine phase), in the periodic state."""
    th = 2 * np.pi * np.arange(_CYCLES * _N) / _N
    n1, n3 = np.zeros(np.size(a), complex), np.zeros(np.size(a), complex)
    for k, ak in enumerate(np.atleast_1d(a)):
        if ak <= 0:
            continue
        y = contact_play(ak * np.cos(th), r0, y_off, c)[-_N:]
        f = np.fft.rfft(y) / _N * 2
        n1[k], n3[k] = f[1] / ak, f[3] / ak
    return n1, n3


def contact_output(th, ctx: Context):
    """``contact_play`` on the displacement: preload r0 (um), lift-off y_off (um, r0 kept below y_off/2), the load's
    slope c and the gain g."""
    r0_um, y_off_um, c, gain = th
    y_off = y_off_um * 1e-6
    r0 = min(r0_um * 1e-6, 0.45 * y_off)
    p = baseline(ctx)
    if ctx.sines:
        y = p.Hd * np.array([_drive(s) for s in ctx.sines])
        a = np.abs(y)
        n1, n3 = contact_df(a, r0, y_off, c)
        g1 = np.where(np.abs(n1) > 1e-6, n1, 1e-6)  # a sine that never moves the tip reads nothing but its noise
        p.hd[:, 1] = p.hd[:, 1] + n3 / g1 * (y / np.where(a > 0, a, 1.0)) ** 2
        p.Hd = p.Hd * g1 * gain
    for k, d in enumerate(p.step_d):
        p.step_d[k] = gain * contact_play(d, r0, y_off, c)
    return p


def contact_start(ctx: Context) -> np.ndarray:
    """A start read off the data: a preload of 0.03 of the largest bend the steps or sines read, lifted off at half
    of it, a light load with the bend."""
    big = largest_bend(ctx)
    return np.array([0.03 * big * 1e6, 0.5 * big * 1e6, 0.02, 1.0])
