"""Transfer functions of seed 000: tip displacement per volt by mode superposition (eq. 28-38), and current.

The modal force is the virtual work of the actuation moment on each mode, F_i(s) = int_0^L M_app phi_i'' dx,
evaluated by Gauss-Legendre quadrature on fixed nodes (``modal_force="virtual_work"``, default). Seed 000
instead integrates f_app = d^2 M_app/dx^2 (eq. 26) against phi_i without the end terms (eq. 34-37,
``modal_force="paper"``); docs/model.md 4.3 shows why that misses the moment at the free end.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from labrig.physics import beam, hydro
from labrig.physics.impedance import charging_admittance, impedance, propagation, voltage_along
from labrig.physics.params import ClampElectrical, LineElectrical, Specimen

QUAD_NODES = 48  # exact to 1e-13 for 10 modes up to 1 kHz (checked against 300 nodes)
_LEGENDRE = np.polynomial.legendre.leggauss(QUAD_NODES)  # nodes and weights on [-1, 1], computed once


@dataclass(frozen=True)
class ModalSet:
    """Modes of one specimen: roots, frequencies, damping, modal masses and shapes on quadrature nodes."""

    beta_L: np.ndarray
    omega: np.ndarray  # rad/s, eq. 33 with mu_v(omega_i) self-consistent
    xi: np.ndarray  # eq. 33 with the dissipative fluid sign
    mu_v: np.ndarray  # kg/m, rho A + m_a(omega_i)
    modal_mass: np.ndarray  # eq. 35, kg*m (shapes normalised to int phi^2 dx = L)
    phi_sensor: np.ndarray  # phi_i at the laser spot
    nodes: np.ndarray  # x of the quadrature nodes (m)
    weights: np.ndarray
    phi: np.ndarray  # (nodes, modes)
    phi2: np.ndarray  # (nodes, modes) second derivative

    @property
    def f_Hz(self) -> np.ndarray:
        return self.omega / (2 * np.pi)


def mu_v(omega: np.ndarray | float, sp: Specimen) -> np.ndarray:
    """mu_v(omega) = rho A + m_a(omega) (eq. 24), kg/m; the fixed ``mechanics.mu_v`` when one is given."""
    g = sp.geometry
    if sp.mechanics.mu_v is not None:
        return np.full(np.shape(omega), sp.mechanics.mu_v)
    return sp.mechanics.density * g.cross_section + hydro.added_mass(omega, g.width, sp.fluid)


def damping_ratio(omega: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 33 with Sader's sign: xi_i = (gamma + m_d Im Gamma(omega_i) / mu_v(omega_i)) / 2."""
    g = sp.geometry
    md = hydro.displaced_mass(g.width, sp.fluid)
    return 0.5 * (sp.mechanics.gamma + md * hydro.gamma_rect(omega, g.width, sp.fluid).imag / mu_v(omega, sp))


@lru_cache(maxsize=1024)
def _roots_and_norm(Kt_bar: float, n_modes: int, length: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(beta L roots, quadrature nodes, weights, the raw mode shapes there, each mode's norm: int phi^2 dx = L)."""
    bl = beam.beta_L_roots(Kt_bar, n_modes)
    u, w = _LEGENDRE
    nodes, weights = 0.5 * length * (u + 1.0), 0.5 * length * w
    phi = beam.mode_shapes(nodes, length, bl, Kt_bar)
    return bl, nodes, weights, phi, np.sqrt(weights @ phi**2 / length)


@lru_cache(maxsize=1024)
def _shapes(Kt_bar: float, n_modes: int, length: float, x_sensor: float, lever: float = 0.0) -> tuple[np.ndarray, ...]:
    """Roots and mode shapes on the quadrature nodes: they depend on K_t bar and the geometry only. The sensor's
    shape is phi(x) + lever phi'(x): a rigid flag ``lever`` beyond the spot along the tangent (0: the strip)."""
    L = length
    bl, nodes, weights, phi, norm = _roots_and_norm(Kt_bar, n_modes, L)
    phi2 = beam.mode_shapes(nodes, L, bl, Kt_bar, 2)
    phi_s = beam.mode_shapes(np.array([x_sensor]), L, bl, Kt_bar)[0] / norm
    if lever:
        phi_s = phi_s + lever * beam.mode_shapes(np.array([x_sensor]), L, bl, Kt_bar, 1)[0] / norm
    return bl, nodes, weights, phi / norm, phi2 / norm, phi_s


def modal_set(sp: Specimen) -> ModalSet:
    """The modes of ``sp``. They read only its geometry, fluid, mechanics (not alpha), K_t bar, mode count and
    sensor: the cache is keyed on those, so a fit's step in a contact or line parameter (or alpha) reuses them."""
    return _modal_set(_mechanical(sp))


def _mechanical(sp: Specimen) -> Specimen:
    """``sp`` with every field the modes do not read set to one canonical value (the cache key of ``modal_set``)."""
    return Specimen(sp.geometry, sp.fluid, _NO_LINE, _NO_CLAMP, replace(sp.mechanics, alpha=0.0), float(sp.Kt_bar),
                    None, int(sp.n_modes), float(sp.x_sensor), float(sp.sensor_lever))


_NO_LINE = LineElectrical(1.0, 1.0, 1.0, 1.0, 1.0)
_NO_CLAMP = ClampElectrical(1.0, 1.0, 1.0, 1.0, 1.0, 1.0)


@lru_cache(maxsize=1024)
def _modal_set(sp: Specimen) -> ModalSet:
    g, m = sp.geometry, sp.mechanics
    L = g.length
    bl, nodes, weights, phi, phi2, phi_s = _shapes(float(sp.Kt_bar), int(sp.n_modes), L, float(sp.x_sensor), float(sp.sensor_lever))
    omega = beam.natural_frequency(bl, m.E, g.second_moment, mu_v(1.0, sp), L)
    for _ in range(30):  # fixed point: the added mass depends on the frequency it loads
        new = beam.natural_frequency(bl, m.E, g.second_moment, mu_v(omega, sp), L)
        if np.all(np.abs(new - omega) <= 1e-8 + 1e-12 * np.abs(omega)):  # np.allclose's test, without its overhead
            break
        omega = new
    muv = mu_v(omega, sp)
    return ModalSet(bl, omega, damping_ratio(omega, sp), muv, muv * L, phi_s, nodes, weights, phi, phi2)


def actuation_moment_nodes(s: np.ndarray, sp: Specimen, ms: ModalSet) -> np.ndarray:
    """M_app(x, s)/V0 on the quadrature nodes (eq. 25), shape (len(s), nodes)."""
    g = sp.geometry
    y = charging_admittance(s, sp)[:, None]
    return sp.mechanics.alpha * g.thickness * y * voltage_along(s, ms.nodes, sp) / s[:, None]


def modal_forces(s: np.ndarray, sp: Specimen, ms: ModalSet | None = None) -> np.ndarray:
    """F_i(s)/V0(s), shape (len(s), modes): virtual work int M_app phi_i'' dx, or eq. 34 as printed."""
    ms = ms or modal_set(sp)
    s = np.atleast_1d(np.asarray(s, complex))
    mapp = actuation_moment_nodes(s, sp, ms) * ms.weights[None, :]
    shapes = ms.phi if sp.modal_force == "paper" else ms.phi2
    forces = mapp.real @ shapes + 1j * (mapp.imag @ shapes)  # two real GEMMs beat one mixed-type product
    if sp.modal_force == "paper":
        # f_app = M_app'' = N M_app (g'' = N g), integrated against phi_i with no end terms
        forces *= (propagation(s, sp.line) ** 2)[:, None]
    return forces


def modal_responses(s: np.ndarray, sp: Specimen, ms: ModalSet | None = None) -> np.ndarray:
    """Eq. 38's terms before the sensor's shape: F_i(s) / (M_i (s^2 + 2 xi_i w_i s + w_i^2)), shape (len(s), modes)."""
    ms = ms or modal_set(sp)
    s = np.atleast_1d(np.asarray(s, complex))
    sc = s[:, None]
    den = ms.modal_mass[None, :] * (sc * sc + 2 * ms.xi * ms.omega * sc + ms.omega**2)
    return modal_forces(s, sp, ms) / den


def displacement_tf(s: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 38: H(s) = w(x_m, s)/V0(s) = sum_i phi_i(x_m) F_i(s) / (M_i (s^2 + 2 xi_i w_i s + w_i^2)), m/V."""
    ms = modal_set(sp)  # once: its cache key is a Specimen built per call, a fit's inner loop makes 10^5 of them
    return modal_responses(s, sp, ms) @ ms.phi_sensor


def shapes_at(x: np.ndarray, sp: Specimen) -> np.ndarray:
    """The normalised mode shapes of ``sp`` (as ``_shapes``: int phi^2 dx = L) at stations x (m from the clamp), shape
    (len(x), modes): with ``modal_responses``, the FRF read at any station is (R * shapes_at(x)).sum(1), without a
    modal set per station."""
    L = sp.geometry.length
    bl, _, _, _, norm = _roots_and_norm(float(sp.Kt_bar), int(sp.n_modes), L)
    return beam.mode_shapes(np.atleast_1d(np.asarray(x, float)), L, bl, float(sp.Kt_bar)) / norm


def admittance_tf(s: np.ndarray, sp: Specimen) -> np.ndarray:
    """I0(s)/V0(s) = 1/Z(s) (eq. 12), A/V."""
    return 1.0 / impedance(np.atleast_1d(np.asarray(s, complex)), sp)


def frf(f_Hz: np.ndarray, sp: Specimen) -> np.ndarray:
    """Displacement FRF H(j 2 pi f) in m/V."""
    return displacement_tf(2j * np.pi * np.asarray(f_Hz, float), sp)


def static_deflection(s: np.ndarray, sp: Specimen, x: float | None = None) -> np.ndarray:
    """Quasi-static w(x, s)/V0 of the eigen-moment beam: w'' = M_app/EI, w(0) = w'(0) = 0.

    An internal moment loads no external support, so the root spring is not rotated: this is the
    limit the modal sum must reach at low frequency (tests/test_physics_transfer.py).
    """
    ms = modal_set(sp)
    x = sp.x_sensor if x is None else x
    s = np.atleast_1d(np.asarray(s, complex))
    EI = sp.mechanics.E * sp.geometry.second_moment
    kernel = np.clip(x - ms.nodes, 0.0, None) * ms.weights  # w(x) = int_0^x (x - u) M(u)/EI du
    return actuation_moment_nodes(s, sp, ms) @ kernel / EI
