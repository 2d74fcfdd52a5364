"""The local analysis of section "4 A boundary layer": equations (3.2), (3.4)-(3.14).

(3.1), (3.3), (3.4), (3.13), (3.14) for general contours are in test_contour.py; (3.15)-(3.25) in
test_boundary_layer.py and test_wiener_hopf.py; the edge position (3.5)-(3.6) against the direct
solver in test_direct.py (edge shift) and test_solution.py (contact area).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy import integrate, special

from thinlayer import BondedLayer

th, psi, sig, v, vp, eps = sp.symbols("theta psi sigma v v' epsilon", real=True)
R1s, R2s, d0s, Hs, vt = sp.symbols("R_1^* R_2^* delta_0^* H_* vartheta", positive=True)


def test_313_from_the_right_hand_side_of_32():
    # (3.2) with (2.10): eps^2 phi*(xi) = pi^2 vartheta/(Lambda^2 H_*) (delta0* - Phi*(xi)), Phi* of (2.13).
    # On the contour xi = f*(s) + n n0 (3.4) with n = eps v (3.7) it must equal eps^2 times
    # q*(xi) = pi^2 vartheta H_* [eps v b1* + eps^2 v^2 b2*] (3.13), with b1*, b2* of (3.14).
    a = sp.sqrt(2 * d0s * R1s) / Hs  # semi-axes in xi (3.1) with R1* (erratum 3.1)
    b = sp.sqrt(2 * d0s * R2s) / Hs
    f = sp.Matrix([a * sp.cos(th), b * sp.sin(th)])  # counterclockwise; any parametrisation
    df = f.diff(th)
    t = df / sp.sqrt(df.dot(df))
    n0 = sp.Matrix([-t[1], t[0]])  # inward normal (3.3)
    Phi = lambda x: Hs**2 * (x[0] ** 2 / (2 * R1s) + x[1] ** 2 / (2 * R2s))  # (2.13)
    xi = f + eps * v * n0  # (3.4), (3.7)
    phi_star = sp.pi**2 * vt * (d0s - Phi(xi)) / Hs
    b1 = -f[0] * n0[0] / R1s - f[1] * n0[1] / R2s  # (3.14)
    b2 = (-n0[0] ** 2 / R1s - n0[1] ** 2 / R2s) / 2
    q313 = sp.pi**2 * vt * Hs * (eps * v * b1 + eps**2 * v**2 * b2)
    # phi* = pi^2 vartheta (delta0* - Phi*)/H_* (the rhs of (2.10) is eps^2 phi*) equals q* (3.13)
    diff = sp.simplify(sp.expand(phi_star - q313))
    assert diff == 0
    # numeric spot check at a few points (mpmath-free: plain floats suffice for an exact identity)
    fn = sp.lambdify((th, v, eps, R1s, R2s, d0s, Hs, vt), phi_star - q313)
    for p in [(0.3, 1.2, 0.1, 3.0, 1.0, 0.2, 1.5, 2.0), (2.0, -0.7, 0.05, 1.0, 4.0, 0.5, 0.8, 1.0)]:
        assert abs(fn(*p)) < 1e-12


def test_38_to_312_rotation():
    # (3.8) with (3.9): sigma f*' + (v - v') n0 is (sigma, v - v') rotated by psi, so |.| is unchanged
    tvec = sp.Matrix([sp.cos(psi), sp.sin(psi)])
    n0 = sp.Matrix([-sp.sin(psi), sp.cos(psi)])  # (3.9), consistent with (3.3)
    assert sp.simplify(n0 - sp.Matrix([-tvec[1], tvec[0]])) == sp.zeros(2, 1)
    w = sig * tvec + (v - vp) * n0
    assert sp.simplify(w.dot(w) - (sig**2 + (vp - v) ** 2)) == 0
    # (3.11): the substitution s = rotation(t) has unit Jacobian and keeps |s|
    t1, t2 = sp.symbols("t_1 t_2", real=True)
    s1 = t1 * sp.cos(psi) - t2 * sp.sin(psi)
    s2 = t1 * sp.sin(psi) + t2 * sp.cos(psi)
    J = sp.Matrix([[s1.diff(t1), s1.diff(t2)], [s2.diff(t1), s2.diff(t2)]]).det()
    assert sp.simplify(J) == 1 and sp.simplify(s1**2 + s2**2 - t1**2 - t2**2) == 0


def _k_smooth(layer, x1, x2, smax=30.0):
    """(2.12) for the exponentially decaying part (L - 1)/s of the kernel: the quarter-plane cosine integral.

    (The part 1/s gives (1/4) iint e^{i s.xi}/|s| ds = pi/(2|xi|), radial by itself.)  The quarter plane in polar
    coordinates (s, theta), where the Jacobian s cancels the 1/s: composite Gauss-Legendre in s (30 panels of 24
    nodes up to smax, where L - 1 < 1e-20) times Gauss-Legendre in theta (256 nodes); L is evaluated once per node.
    """
    xs, ws = np.polynomial.legendre.leggauss(24)
    edges = np.linspace(0.0, smax, 31)
    h = np.diff(edges)[:, None]
    s = (h * (xs + 1) / 2 + edges[:-1, None]).ravel()
    w = (h * ws / 2).ravel()
    g = np.asarray(layer.L_numeric(s, backend="numpy"), dtype=float) - 1.0
    tx, tw = np.polynomial.legendre.leggauss(256)
    theta = (tx + 1) * math.pi / 4
    f = np.cos(np.outer(s, np.cos(theta)) * x1) * np.cos(np.outer(s, np.sin(theta)) * x2)
    return float((w * g) @ f @ (tw * math.pi / 4))


@pytest.mark.parametrize("r", [0.7, 1.5])
def test_312_kernel_is_radial(r):
    # k(xi) of (2.12)/(3.10) depends on |xi| only, which (3.12) uses: compare two directions and the
    # Hankel form k(r) = pi/(2r) + (pi/2) int_0^oo (L(s) - 1) J0(s r) ds (polar coordinates in (3.10))
    layer = BondedLayer(0.3)
    a = _k_smooth(layer, r, 0.0)
    b = _k_smooth(layer, r * math.cos(0.6), r * math.sin(0.6))
    hank, _ = integrate.quad(lambda s: (float(layer.L_numeric(s, backend="numpy")) - 1.0) * special.j0(s * r),
                             0, 40, limit=400)
    assert a == pytest.approx(b, abs=1e-10)
    assert a == pytest.approx(math.pi / 2 * hank, abs=1e-9)
