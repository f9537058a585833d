"""Electrical model of seed 000: distributed RC line with CPE branches and a lumped clamp area.

Pure functions of the Laplace variable ``s`` (complex array, rad/s) and the parameters. Equation
numbers are seed 000's. Along the free strip x runs from 0 (clamp edge) to L (tip).
"""

from __future__ import annotations

import numpy as np

from labrig.physics.params import ClampElectrical, Geometry, LineElectrical, Specimen


def cpe_admittance(s: np.ndarray, Q0: float, n: float) -> np.ndarray:
    """Eq. 1 inverted: Y_CPE = Q0 s^n (principal branch, so Re s > 0 maps into the right half plane)."""
    return Q0 * np.power(np.asarray(s, complex), n)


def theta(s: np.ndarray, line: LineElectrical) -> np.ndarray:
    """Eq. 9: admittance per length of the R + CPE branch, Theta = Q0 s^n / (1 + R Q0 s^n)."""
    y = cpe_admittance(s, line.Q0, line.n)
    return y / (1.0 + line.R * y)


def shunt_admittance(s: np.ndarray, line: LineElectrical) -> np.ndarray:
    """M(s) = Theta(s) + 1/R_p (eq. 10): all the current per length leaving the electrode at x."""
    return theta(s, line) + 1.0 / line.R_p


def propagation(s: np.ndarray, line: LineElectrical) -> np.ndarray:
    """sqrt(N(s)) with N = 2 R_s M (eq. 10), principal root (Re > 0)."""
    return np.sqrt(2.0 * line.R_s * shunt_admittance(s, line))


def contact_resistance(clamp: ClampElectrical, geometry: Geometry) -> float:
    """R_cont (ohm) of one electrode/clamp interface: specific resistance over the clamp area."""
    return clamp.r_cont / geometry.clamp_area


def z1(clamp: ClampElectrical, geometry: Geometry) -> float:
    """Eq. 5: Z1 = 2 (R_cont + R_sc), R_sc lumped over the clamp length."""
    return 2.0 * (contact_resistance(clamp, geometry) + clamp.R_sc * geometry.clamp_length)


def z2(s: np.ndarray, clamp: ClampElectrical, geometry: Geometry) -> np.ndarray:
    """Eq. 5: the clamp-area shunt, Z2 = R_Pc (1 + R_c Q s^n) / (1 + (R_Pc + R_c) Q s^n), lumped."""
    lc = geometry.clamp_length
    R_pc, R_c, y = clamp.R_pc / lc, clamp.R_c / lc, cpe_admittance(s, clamp.Q0c * lc, clamp.n_c)
    return R_pc * (1.0 + R_c * y) / (1.0 + (R_pc + R_c) * y)


def line_admittance(s: np.ndarray, line: LineElectrical, length: float) -> np.ndarray:
    """Input admittance of the open-ended line (i(L) = 0): (M / sqrt N) tanh(sqrt N L), the term of eq. 12."""
    a = propagation(s, line)
    return shunt_admittance(s, line) / a * np.tanh(a * length)


def impedance(s: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 12 (exact): Z = Z1 + (1/Z2 + (M/sqrt N) tanh(sqrt N L))^-1."""
    s = np.asarray(s, complex)
    g = sp.geometry
    return z1(sp.clamp, g) + 1.0 / (1.0 / z2(s, sp.clamp, g) + line_admittance(s, sp.line, g.length))


def impedance_lowfreq(s: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 13: Z ~ Z1 + sqrt N / (M tanh(sqrt N L)), i.e. eq. 12 with the clamp shunt Z2 -> infinity."""
    s = np.asarray(s, complex)
    return z1(sp.clamp, sp.geometry) + 1.0 / line_admittance(s, sp.line, sp.geometry.length)


def line_entry_voltage(s: np.ndarray, sp: Specimen) -> np.ndarray:
    """v(0, s) / V0(s): the fraction of the drive left at the clamp edge after Z1 and the Z2 shunt (eq. 6)."""
    s = np.asarray(s, complex)
    g = sp.geometry
    zp = 1.0 / (1.0 / z2(s, sp.clamp, g) + line_admittance(s, sp.line, g.length))
    return zp / (z1(sp.clamp, g) + zp)


def voltage_shape(s: np.ndarray, x: np.ndarray, line: LineElectrical, length: float) -> np.ndarray:
    """g(x, s) of eq. 17, v(x)/v(0) = cosh(a(L-x))/cosh(aL), in an overflow-free form.

    Returns shape (len(s), len(x)). Written with decaying exponentials only (Re a > 0).
    """
    a = propagation(np.atleast_1d(np.asarray(s, complex)), line)[:, None]
    x = np.atleast_1d(np.asarray(x, float))
    near = np.exp(-a * x[None, :])
    if np.allclose(x + x[::-1], length, rtol=0, atol=1e-12 * length):
        # nodes symmetric about L/2 (Gauss-Legendre): exp(-a(2L - x_k)) = exp(-aL) exp(-a x_(n-1-k))
        far = np.exp(-a * length) * near[:, ::-1]
    else:
        far = np.exp(-a * (2.0 * length - x[None, :]))
    return (near + far) / (1.0 + np.exp(-2.0 * a * length))


def voltage_along(s: np.ndarray, x: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 14: v(x, s) / V0(s) along the strip (shape (len(s), len(x)))."""
    v0 = line_entry_voltage(np.atleast_1d(s), sp)[:, None]
    return v0 * voltage_shape(s, x, sp.line, sp.geometry.length)


def current_along(s: np.ndarray, x: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 14 (second line): surface current i(x, s) / V0(s) = -v'(x)/(2 R_s)."""
    s1 = np.atleast_1d(np.asarray(s, complex))
    a = propagation(s1, sp.line)[:, None]
    L = sp.geometry.length
    x = np.atleast_1d(np.asarray(x, float))[None, :]
    # -d/dx of cosh(a(L-x))/cosh(aL) = a sinh(a(L-x))/cosh(aL), overflow-free
    dg = a * (np.exp(-a * x) - np.exp(-a * (2.0 * L - x))) / (1.0 + np.exp(-2.0 * a * L))
    return line_entry_voltage(s1, sp)[:, None] * dg / (2.0 * sp.line.R_s)


def charging_admittance(s: np.ndarray, sp: Specimen) -> np.ndarray:
    """Admittance per length whose current stays in the polymer as charge (docs/model.md 4.2).

    ``capacitive`` (default): only the CPE branch, Theta(s); the leak through R_p crosses the membrane
    and is not stored. ``total``: M(s) = Theta + 1/R_p as eq. 17 prints (a DC drive would then bend
    the strip without bound).
    """
    return theta(s, sp.line) if sp.charge == "capacitive" else shunt_admittance(s, sp.line)


def charge_density(s: np.ndarray, x: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 16-17: rho(x, s)/V0(s) in C/m^3 = (charging current per length) / (s W h)."""
    s1 = np.atleast_1d(np.asarray(s, complex))
    g = sp.geometry
    y = charging_admittance(s1, sp)[:, None]
    return y * voltage_along(s1, x, sp) / (s1[:, None] * g.width * g.thickness)


def actuation_moment(s: np.ndarray, x: np.ndarray, sp: Specimen) -> np.ndarray:
    """Eq. 25: M_app(x, s)/V0(s) = alpha h W h rho = alpha h q(x, s) (N*m per volt).

    With rho = q/(W h), eq. 25's 2 W int_0^h alpha rho z dz = alpha W h^2 rho = alpha h q.
    """
    g = sp.geometry
    return sp.mechanics.alpha * g.thickness * g.width * g.thickness * charge_density(s, x, sp)
