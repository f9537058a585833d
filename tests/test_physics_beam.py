"""Beam with a torsional-spring root and water loading: Table 2, eq. 27-33, Sader's Gamma."""

import numpy as np
import pytest

from labrig.physics import beam, hydro, presets, transfer
from labrig.physics.params import TABLE2_KT_BAR, WATER_25C

L, W, H, E, MU = 0.030, 0.004, 0.22e-3, 313e6, 0.02
I = W * H**3 / 12


@pytest.mark.parametrize("kt, f1", [(4.17, 3.30), (5.67, 3.54), (8.02, 3.78)])
def test_table2_first_natural_frequency(kt, f1):
    bl = beam.beta_L_roots(kt, 3)[0]
    f = beam.natural_frequency(bl, E, I, MU, L) / (2 * np.pi)
    assert f == pytest.approx(f1, rel=0.005)
    assert beam.kt_bar_from_f1(f, E, I, MU, L) == pytest.approx(kt, rel=1e-9)


def test_inverse_of_measured_frequencies_lands_near_table2():
    for f1, kt in zip((3.30, 3.54, 3.78), TABLE2_KT_BAR[:3]):
        assert beam.kt_bar_from_f1(f1, E, I, MU, L) == pytest.approx(kt, rel=0.02)


def test_stiff_spring_is_the_clamped_cantilever():
    assert beam.beta_L_roots(np.inf, 2)[0] == pytest.approx(1.8751, abs=1e-4)
    assert beam.beta_L_roots(1e7, 2)[0] == pytest.approx(1.8751, abs=1e-4)
    with pytest.raises(ValueError):
        beam.kt_bar_from_beta_L(1.9)  # faster than a clamped root: no spring can do it


def test_roots_are_ordered_and_one_per_mode():
    r = beam.beta_L_roots(5.67, 10)
    assert np.all(np.diff(r) > 2.5)
    # high modes approach the clamped-free spacing pi
    assert r[-1] - r[-2] == pytest.approx(np.pi, rel=0.01)


@pytest.mark.parametrize("kt", [0.5, 4.17, 8.02, 50.0])
def test_mode_shapes_satisfy_boundary_conditions(kt):
    for bl in beam.beta_L_roots(kt, 6):
        d = [beam.mode_shape(np.array([0.0, L]), L, bl, kt, k) for k in range(4)]
        scale = (bl / L) ** 3
        assert abs(d[0][0]) < 1e-9  # w(0) = 0
        assert d[2][0] == pytest.approx(kt / L * d[1][0], rel=1e-7)  # EI w''(0) = k_t w'(0)
        assert abs(d[2][1]) < 1e-8 * scale * L  # w''(L) = 0
        assert abs(d[3][1]) < 1e-8 * scale  # w'''(L) = 0


def _eq29_residuals(kt, bl, sign):
    """Residuals of eq. 27a/27b for eq. 29 with lambda from eq. 31; sign=+1 is the printed first term."""
    b = bl / L
    c, s, ch, sh = np.cos(bl), np.sin(bl), np.cosh(bl), np.sinh(bl)
    lam = (1 + c * ch + s * sh) / (1 + c * ch - s * sh)
    k = sign * kt / (2 * bl) * (1 + lam)
    d1 = lambda x: b * (k * (-np.sin(b * x) - np.sinh(b * x)) + lam * np.cos(b * x) + np.cosh(b * x))
    d2 = lambda x: b**2 * (k * (-np.cos(b * x) - np.cosh(b * x)) - lam * np.sin(b * x) + np.sinh(b * x))
    d3 = lambda x: b**3 * (k * (np.sin(b * x) - np.sinh(b * x)) - lam * np.cos(b * x) + np.cosh(b * x))
    scale = abs(d2(0.0)) + abs(kt / L * d1(0.0))
    return abs(d2(0.0) - kt / L * d1(0.0)) / scale, abs(d2(L)) / b**2 / ch, abs(d3(L)) / b**3 / ch


@pytest.mark.parametrize("kt", [4.17, 8.02])
def test_printed_eq29_has_the_wrong_sign(kt):
    """docs/model.md 4.1: eq. 29 as printed violates eq. 27; with -K_t/(2 beta L) it satisfies all four."""
    for bl in beam.beta_L_roots(kt, 3):
        assert max(_eq29_residuals(kt, bl, +1)) > 1e-3
        assert max(_eq29_residuals(kt, bl, -1)) < 1e-10


def test_rayleigh_quotient_matches_eq33():
    """EI int phi''^2 + k_t phi'(0)^2 = omega^2 mu_v int phi^2 for the computed modes."""
    sp = presets.get("paper").specimen(1837)
    ms = transfer.modal_set(sp)
    EI = sp.mechanics.E * sp.geometry.second_moment
    for i in range(4):
        dphi0 = beam.mode_shape(np.array([0.0]), L, ms.beta_L[i], sp.Kt_bar, 1)[0]
        norm = np.sqrt(ms.weights @ (np.stack([beam.mode_shape(ms.nodes, L, ms.beta_L[i], sp.Kt_bar)])[0] ** 2) / L)
        strain = EI * (ms.weights @ ms.phi2[:, i] ** 2) + sp.Kt_bar * EI / L * (dphi0 / norm) ** 2
        assert strain == pytest.approx(ms.omega[i] ** 2 * ms.modal_mass[i], rel=1e-6)


def test_sader_gamma_at_paper_first_mode():
    g = hydro.gamma_rect(2 * np.pi * 3.78, W, WATER_25C)
    assert g.real == pytest.approx(1.32, rel=0.01)
    assert g.imag == pytest.approx(0.2886, rel=0.01)


def test_sader_limits():
    # inviscid limit: the rectangular correction tends to ~1 and Im Gamma -> 0 as Re grows
    g_hi = hydro.gamma_rect(2 * np.pi * 1e5, W, WATER_25C)
    assert g_hi.imag < 0.01 and 0.95 < g_hi.real < 1.1
    # viscous dissipation grows as Re falls; Im Gamma > 0 is dissipative
    assert hydro.fluid_damping(2 * np.pi * 3.78, W, WATER_25C) > 0
    assert hydro.gamma_rect(2 * np.pi * 0.1, W, WATER_25C).imag > g_hi.imag


def test_fluid_damping_sign_matches_table3():
    """With the dissipative sign, eq. 33 gives xi1 = 0.16 near Table 3's 0.18; as printed it is negative."""
    md = hydro.displaced_mass(W, WATER_25C)
    im = hydro.gamma_rect(2 * np.pi * 3.78, W, WATER_25C).imag
    xi_dissipative = 0.5 * (0.14 + md * im / 0.02)
    xi_printed = 0.5 * (0.14 - md * im / 0.02)
    assert 0.15 < xi_dissipative < 0.19
    assert xi_printed < 0


def test_preset_modes_reproduce_table2_through_the_clamp_law():
    p = presets.get("paper")
    for kpa, f1 in zip((612, 1837, 3062, 4287), (3.30, 3.54, 3.78, 3.30)):
        assert transfer.modal_set(p.specimen(kpa)).f_Hz[0] == pytest.approx(f1, rel=0.005)


def test_sader_mass_option_shifts_f1_a_little():
    p = presets.get("paper")
    sp = p.specimen(612)
    sader = sp.with_(mechanics=sp.mechanics.__class__(**{**sp.mechanics.__dict__, "mu_v": None}))
    f_fixed, f_sader = transfer.modal_set(sp).f_Hz[0], transfer.modal_set(sader).f_Hz[0]
    assert f_sader != f_fixed and abs(f_sader / f_fixed - 1) < 0.02
