"""Euler-Bernoulli cantilever with a torsional-spring root (seed 000, eq. 27-33).

Boundary conditions (eq. 27): w(0) = 0, EI w''(0) = k_t w'(0); w''(L) = w'''(L) = 0, with
K_t bar = k_t L / (EI) (eq. 31). Mode shapes are built in the bounded basis
{cos bx, sin bx, exp(-bx), exp(-b(L-x))} rather than eq. 29's cosh/sinh, which loses all precision for
high modes (cosh(30) ~ 5e12) and, as printed, has the wrong sign on its first term (docs/model.md 4.1).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from scipy.optimize import brentq

CLAMPED_BETA1_L = 1.8751040687119611  # first root of 1 + cos cosh = 0 (K_t bar -> infinity)


def characteristic(beta_L: np.ndarray | float, Kt_bar: float) -> np.ndarray:
    """Eq. 30 divided by cosh(beta L) so it stays finite:
    beta L (cos tanh - sin) + K_t bar (sech + cos) = 0. ``Kt_bar = inf`` gives 1 + cos cosh = 0."""
    bl = np.asarray(beta_L, float)
    c, s, t, sech = np.cos(bl), np.sin(bl), np.tanh(bl), 1.0 / np.cosh(bl)
    if np.isinf(Kt_bar):
        return sech + c
    return bl * (c * t - s) + Kt_bar * (sech + c)


@lru_cache(maxsize=256)
def _roots(Kt_bar: float, n: int) -> tuple[float, ...]:
    roots: list[float] = []
    grid = np.linspace(1e-6, (n + 2) * np.pi, 64 * (n + 2))
    f = characteristic(grid, Kt_bar)
    for i in np.nonzero(np.sign(f[:-1]) * np.sign(f[1:]) < 0)[0]:
        roots.append(brentq(characteristic, grid[i], grid[i + 1], args=(Kt_bar,), xtol=1e-14))
        if len(roots) == n:
            break
    if len(roots) < n:
        raise ValueError(f"found only {len(roots)} roots of eq. 30 for K_t bar = {Kt_bar}")
    return tuple(roots)


def beta_L_roots(Kt_bar: float, n: int = 10) -> np.ndarray:
    """First ``n`` positive roots beta_i L of eq. 30 (ascending)."""
    if not Kt_bar > 0:
        raise ValueError("K_t bar must be positive")
    return np.array(_roots(float(Kt_bar), int(n)))


def bc_matrix(beta_L: np.ndarray | float, Kt_bar: float) -> np.ndarray:
    """Rows: eq. 27a (w = 0, EI w'' = k_t w'), eq. 27b (w'' = w''' = 0) on the coefficients of
    (cos bx, sin bx, exp(-bx), exp(-b(L-x))), written per unit beta so the entries stay O(1).
    An array of roots gives a stack of matrices, shape (..., 4, 4)."""
    bl = np.asarray(beta_L, float)
    c, s, e = np.cos(bl), np.sin(bl), np.exp(-bl)
    one, zero = np.ones_like(bl), np.zeros_like(bl)
    # row 2: beta L phi''(0)/beta^2 - Kt phi'(0)/beta, divided by (beta L + Kt) so Kt -> inf is the clamp
    w = zero if np.isinf(Kt_bar) else 1.0 / (bl + Kt_bar)
    k = one if np.isinf(Kt_bar) else Kt_bar * w
    rows = [
        [one, zero, one, e],
        [-bl * w, -k, bl * w + k, (bl * w - k) * e],
        [-c, -s, e, one],  # phi''(L) / beta^2
        [s, -c, -e, one],  # phi'''(L) / beta^3
    ]
    return np.moveaxis(np.array(rows), (0, 1), (-2, -1))


def mode_coefficients(beta_L: np.ndarray | float, Kt_bar: float) -> np.ndarray:
    """Null vector of ``bc_matrix``: the mode's coefficients, sign chosen so phi(L) > 0.
    An array of roots gives one row of coefficients per root (one batched SVD)."""
    bl = np.asarray(beta_L, float)
    _, sv, vt = np.linalg.svd(bc_matrix(bl, Kt_bar))
    coef = vt[..., -1, :]
    bad = sv[..., -1] > 1e-8 * sv[..., 0]
    if np.any(bad):
        raise ValueError(f"beta L = {bl[bad] if bl.ndim else bl} is not an eigenvalue for K_t bar = {Kt_bar}")
    tip = np.einsum("...j,j...->...", coef, _basis(np.array([1.0]), bl, 0)[:, 0])
    return coef * np.where(tip > 0, 1.0, -1.0)[..., None]


def _basis(xi: np.ndarray, beta_L: np.ndarray | float, derivative: int) -> np.ndarray:
    """Basis functions (rows) at xi = x/L, d^k/d(beta x)^k of (cos, sin, exp(-bx), exp(-b(L-x))):
    shape (4, len(xi)) for one root, (4, len(xi), n) for an array of n roots."""
    bl = np.asarray(beta_L, float)
    bx = np.multiply.outer(xi, bl)
    e0, e1 = np.exp(-bx), np.exp(-(bl - bx))
    c, s = np.cos(bx), np.sin(bx)
    k = derivative % 4
    dcos, dsin = (c, -s, -c, s)[k], (s, c, -s, -c)[k]
    return np.array([dcos, dsin, (-1) ** derivative * e0, e1])


def mode_shape(x: np.ndarray, length: float, beta_L: float, Kt_bar: float, derivative: int = 0) -> np.ndarray:
    """phi_i(x) (derivative = 0) or its x-derivatives (1, 2, 3), unnormalised (see ``ModalSet``)."""
    return mode_shapes(x, length, np.array([beta_L]), Kt_bar, derivative)[:, 0]


def mode_shapes(x: np.ndarray, length: float, beta_L: np.ndarray, Kt_bar: float, derivative: int = 0) -> np.ndarray:
    """Every mode of ``beta_L`` at once: phi_i(x) or its x-derivatives, shape (len(x), len(beta_L))."""
    bl = np.asarray(beta_L, float)
    coef = mode_coefficients(bl, Kt_bar)  # (n, 4)
    xi = np.atleast_1d(np.asarray(x, float)) / length
    return np.einsum("nj,jxn->xn", coef, _basis(xi, bl, derivative)) * (bl / length) ** derivative


def natural_frequency(beta_L: np.ndarray | float, E: float, I: float, mu_v: float, length: float) -> np.ndarray:
    """Eq. 33: omega_i = (beta_i L)^2 sqrt(EI / (mu_v L^4)) in rad/s."""
    return np.asarray(beta_L, float) ** 2 * np.sqrt(E * I / (mu_v * length**4))


def kt_bar_from_beta_L(beta_L: float) -> float:
    """Eq. 30 solved for K_t bar at a given first root (0 < beta_1 L < 1.8751)."""
    bl = float(beta_L)
    if not 0 < bl < CLAMPED_BETA1_L:
        raise ValueError(f"beta_1 L = {bl:.4f} is outside (0, {CLAMPED_BETA1_L:.4f}): no torsional spring gives it")
    c, s, ch, sh = np.cos(bl), np.sin(bl), np.cosh(bl), np.sinh(bl)
    return float(-bl * (c * sh - s * ch) / (1.0 + c * ch))


def kt_bar_from_f1(f1_Hz: float, E: float, I: float, mu_v: float, length: float) -> float:
    """The inverse problem f1 -> K_t bar (Table 2): eq. 33 gives beta_1 L, eq. 30 gives K_t bar."""
    bl = np.sqrt(2 * np.pi * f1_Hz / np.sqrt(E * I / (mu_v * length**4)))
    return kt_bar_from_beta_L(bl)
