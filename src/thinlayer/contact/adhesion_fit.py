r"""Fit Young's modulus and the work of adhesion to an adhesive (JKR) unloading curve (issue 26 item 5).

The model is the JKR superposition (J.1)-(J.5) at any thickness, tabulated once at unit modulus: at a contact
radius ``c`` the smooth-edge depth ``delta_1(c)`` and force ``P_1(c)`` (``P_1`` is proportional to ``mu``), the
flat-punch ``kappa(c/H)`` and ``f(1)`` do not depend on ``E`` or ``w``, so for any ``(E, w)``::

    d(c) = -sqrt(pi c w/vartheta)/f(1),  delta(c) = delta_1(c) + d(c),  P(c) = mu P_1^u(c) + 4 vartheta c kappa d(c)

with ``mu = E/(2(1 + nu))``, ``vartheta = mu/(1 - nu)``.  The table's nodes are interpolated by cubic splines in
``log c`` (``delta_1/c^2``, ``P_1/c^3``, ``kappa``, ``f(1)``: slowly varying); the data should lie inside the
tabulated radii (a depth outside is refused).  The table comes from the sphere's any-thickness JKR law (J.16)
(``model="any-thickness"``, the default for the paraboloid on a layer on a rigid base: 60 nodes in milliseconds)
or from the direct solver (``model="direct"``, about 0.4 s a node; the half-space and other punches).
Each measured depth is
put on the stable branch (``d delta/dc > 0``, displacement control: the unloading curve of an
indentation instrument) and the residual is the force.  ``scipy.optimize.least_squares`` fits ``(E, w)``; the
standard errors are those of the linearised problem, ``s^2 (J^T J)^{-1}`` with ``s^2`` the residual variance.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._checks import InputError, check_choice, positive
from .._lazy import lazy_function, lazy_module
from ..display import RichDisplay
from ..numerics.adhesion import adhesive_state

optimize = lazy_module("scipy.optimize")
any_thickness_jkr = lazy_function("thinlayer.contact.adhesion_sphere", "any_thickness_jkr")
interpolate = lazy_module("scipy.interpolate")

__all__ = ["AdhesiveFit", "fit_adhesive", "fit_free_adhesion"]

#: the most data points and table nodes (each node is one direct solve, about 0.4 s)
MAX_POINTS, MAX_NODES = 100_000, 60


@dataclass(frozen=True)
class AdhesiveFit(RichDisplay):
    """Young's modulus and the work of adhesion fitted to an adhesive unloading curve.

    Attributes
    ----------
    E, work_of_adhesion : float
        float
        The fitted values.
    E_error, work_of_adhesion_error : float
        float
        Their standard errors (linearised least squares).
    nu : float
        The Poisson ratio (given).
    residual_rms : float
        Root-mean-square force residual.
    points : int
        Number of data points.
    radii : tuple
        ``(c_min, c_max)`` of the table.
    model : str
        ``"any-thickness"`` (the law (J.16)) or ``"direct"`` (the direct solver (J.1)-(J.5)).
    """

    E: float
    work_of_adhesion: float
    E_error: float
    work_of_adhesion_error: float
    nu: float
    residual_rms: float
    points: int
    radii: tuple
    model: str = "direct"

    equation = "J.5"

    @property
    def E_se(self) -> float:  # noqa: N802 - fit()'s name for the standard error of E
        """The standard error of E (the name :class:`~thinlayer.contact.fit.FitResult` uses)."""
        return self.E_error

    def as_dict(self) -> dict:
        """The numbers by name (JSON)."""
        return {"model": self.model, "E": self.E, "E_se": self.E_error, "work_of_adhesion": self.work_of_adhesion,
                "work_of_adhesion_se": self.work_of_adhesion_error, "nu": self.nu, "residual_rms": self.residual_rms,
                "n_points": self.points, "radii": list(self.radii)}

    def latex(self) -> str:
        return (rf"E = {self.E:.6g} \pm {self.E_error:.2g},\quad w = {self.work_of_adhesion:.6g} \pm "
                rf"{self.work_of_adhesion_error:.2g} \tag{{J.5}}")

    def text_lines(self) -> list[str]:
        src = "any-thickness JKR law (J.16)" if self.model == "any-thickness" else "direct JKR model (J.1)-(J.5)"
        return [f"AdhesiveFit: {self.points} points, {src}, nu = {self.nu:g}",
                f"  E = {self.E:.8g} +- {self.E_error:.2g}", f"  w = {self.work_of_adhesion:.8g} +- "
                f"{self.work_of_adhesion_error:.2g}", f"  rms force residual {self.residual_rms:.3g}"]


def _array(v: Any, name: str) -> np.ndarray:
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be an array of finite numbers") from None
    if a.ndim != 1 or a.size < 3 or a.size > MAX_POINTS or not np.all(np.isfinite(a)):
        raise InputError(f"{name} must be 3 to {MAX_POINTS} finite numbers (one-dimensional)")
    return a


class _Table:
    """The unit-modulus solutions on the radii (direct, or the any-thickness law), as splines in log c."""

    def __init__(self, layer: Any, punch: Any, radii: np.ndarray, H: float | None, nu: float, n: int | None,
                 model: str = "direct"):
        if model == "any-thickness":
            st = any_thickness_jkr(layer, nu).states(radii, H, punch.sphere_radius, 0.0, 1.0)
            d1, P1, kap, f1 = st.delta_smooth, st.force_smooth, st.kappa, np.sqrt(st.release_factor)
            self.nu = any_thickness_jkr(layer, nu).nu
        else:
            rows = [adhesive_state(layer, punch, float(c), H, 1.0, work_of_adhesion=0.0, nu=nu, n=n,
                                   energy_route=False) for c in radii]
            d1, P1 = np.array([r.delta_smooth for r in rows]), np.array([r.force_smooth for r in rows])
            kap, f1 = np.array([r.kappa for r in rows]), np.array([r.edge_value for r in rows])
            self.nu = rows[0].nu
        x = np.log(radii)
        self.lo, self.hi = float(radii[0]), float(radii[-1])
        cs = interpolate.CubicSpline
        # delta_1/c^2 and P_1/c^3 vary slowly (constants on the half-space and both thickness limits)
        self.delta1 = cs(x, d1 / radii**2)
        self.P1 = cs(x, P1 / radii**3)  # at mu = 1
        self.kappa = cs(x, kap)
        self.f1 = cs(x, f1)
        self.grid = np.geomspace(self.lo, self.hi, 2000)

    def curve(self, E: float, w: float, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        mu = E / (2 * (1 + self.nu))
        vt = mu / (1 - self.nu)
        x = np.log(c)
        d = -np.sqrt(math.pi * c * w / vt) / self.f1(x)
        return c * c * self.delta1(x) + d, mu * c**3 * self.P1(x) + 4 * vt * c * self.kappa(x) * d

    def force_at(self, E: float, w: float, depths: np.ndarray) -> np.ndarray:
        """The force on the stable branch at each depth (NaN outside the table): grid, then Newton on delta(c)."""
        dg, _ = self.curve(E, w, self.grid)
        i = int(np.argmin(dg))  # the stable branch: c beyond the minimum of delta(c)
        dd, cc = dg[i:], self.grid[i:]
        if dd.size < 2 or np.any(np.diff(dd) <= 0):
            return np.full(depths.shape, np.nan)
        c = np.interp(depths, dd, cc, left=np.nan, right=np.nan)
        ok = np.isfinite(c)
        c = np.where(ok, c, cc[-1])
        for _ in range(4):  # Newton on delta(c) = depth (central-difference slope)
            h = 1e-6 * c
            dl, _ = self.curve(E, w, c - h)
            dr, _ = self.curve(E, w, c + h)
            d0, _ = self.curve(E, w, c)
            c = np.clip(c - (d0 - depths) * 2 * h / (dr - dl), cc[0], cc[-1])
        return np.where(ok, self.curve(E, w, c)[1], np.nan)


def fit_adhesive(layer: Any, punch: Any, depths: Any, forces: Any, H: float | None = None, *, nu: float,
                 E0: float, w0: float, radii: Any = None, nodes: int | None = None, n: int | None = None,
                 model: str | None = None) -> AdhesiveFit:
    """Fit ``E`` and ``w`` to an adhesive unloading curve (depths and signed forces, compressive positive).

    Parameters
    ----------
    layer, punch, H, n
        As for :func:`thinlayer.numerics.adhesive_state` (``HalfSpace()`` needs no ``H``).
    depths, forces : array_like
        array_like
        The measured curve (3 to 100000 points); forces are signed (tensile negative).
    nu : float
        Poisson ratio.
    E0, w0 : float
        float
        Starting values (> 0).
    radii : (float, float), optional
        Contact radii the table spans; default from the largest depth: ``(c_max/25, c_max)`` with
        ``c_max = 2 sqrt(2 R max(depth))``.
    nodes : int, optional
        Table nodes, 6 to 60 (default 16 direct solves, 60 nodes of the law).
    model : str, optional
        ``"any-thickness"`` (the law (J.16); default for the paraboloid on a layer on a rigid base) or ``"direct"``.

    Returns
    -------
    AdhesiveFit
    """
    d = _array(depths, "depths")
    P = _array(forces, "forces")
    if d.size != P.size:
        raise InputError(f"depths and forces differ in length: {d.size} and {P.size}")
    E0v, w0v = positive(E0, "E0"), positive(w0, "w0")
    R = getattr(punch, "sphere_radius", None)
    law_ok = R is not None and getattr(layer, "has_thickness", False) and getattr(layer, "on_rigid_base", False)
    if model is None:
        model = "any-thickness" if law_ok else "direct"
    check_choice(model, ("any-thickness", "direct"), "model")
    if model == "any-thickness" and not law_ok:
        raise InputError("model='any-thickness' fits the paraboloid on a layer on a rigid base; use model='direct'")
    if nodes is None:
        nodes = 60 if model == "any-thickness" else 16
    if isinstance(nodes, bool) or not isinstance(nodes, int) or not 6 <= nodes <= MAX_NODES:
        raise InputError(f"nodes must be an integer from 6 to {MAX_NODES}, got {nodes!r}")
    if radii is None:
        if R is None:
            raise InputError("give radii=(c_min, c_max) for a punch that is not a paraboloid of revolution")
        c_hi = 2 * math.sqrt(2 * R * max(float(np.max(d)), 1e-300))
        lo, hi = c_hi / 25, c_hi
    else:
        try:
            lo, hi = (positive(v, "radii") for v in radii)
        except TypeError:
            raise InputError("radii must be a pair (c_min, c_max) of positive numbers") from None
        if not lo < hi:
            raise InputError(f"radii must satisfy c_min < c_max, got {radii!r}")
    table = _Table(layer, punch, np.geomspace(lo, hi, nodes), H, nu, n, model)

    def resid(p: np.ndarray) -> np.ndarray:
        r = table.force_at(p[0] * E0v, p[1] * w0v, d) - P
        return np.where(np.isfinite(r), r, 1e6 * (np.max(np.abs(P)) + 1.0))

    # a start on a log grid of factors 1/4 ... 4 of (E0, w0): the fewest unreached depths, then the least residual
    facs = np.geomspace(0.25, 4.0, 13)
    best = min(((int(np.sum(~np.isfinite(r := table.force_at(fe * E0v, fw * w0v, d) - P))),
                 float(np.nansum(r * r)), fe, fw) for fe in facs for fw in facs))
    res = optimize.least_squares(resid, np.array(best[2:]), bounds=([1e-6, 1e-8], [1e6, 1e6]), x_scale=1.0,
                                  diff_step=1e-7, xtol=1e-14, ftol=1e-14, gtol=1e-14)
    r = table.force_at(res.x[0] * E0v, res.x[1] * w0v, d) - P
    if not np.all(np.isfinite(r)):
        raise InputError(f"the fitted curve does not reach every depth within the tabulated radii "
                         f"[{lo:.4g}, {hi:.4g}]: give radii= wider")
    dof = max(d.size - 2, 1)
    s2 = float(r @ r) / dof
    J = res.jac * np.array([E0v, w0v]) ** -1.0  # d r / d (E, w)
    cov = s2 * np.linalg.inv(J.T @ J)
    return AdhesiveFit(float(res.x[0] * E0v), float(res.x[1] * w0v), float(math.sqrt(cov[0, 0])),
                       float(math.sqrt(cov[1, 1])), float(table.nu), float(math.sqrt(float(r @ r) / d.size)),
                       int(d.size), (lo, hi), model)


def fit_free_adhesion(delta: Any, force: Any, tip: Any, H: Any, nu: float, base: str, *, E0: float | None = None,
                      work_of_adhesion: Any = "free", model: str | None = None, depth_sign: int = 1,
                      extras: tuple = ()) -> AdhesiveFit:
    """``fit(..., work_of_adhesion="free")``: E and w from an adhesive (unloading) curve, via :func:`fit_adhesive`.

    ``tip`` is the paraboloid (``tip.sphere_radius``); ``H`` None or inf is the half-space; ``extras`` names the
    options of :func:`thinlayer.fit` that the adhesive fit does not take (refused in one line).  Starting values:
    ``w0`` from the largest pull, ``-min P/(1.75 pi R)`` (between JKR's 1.5 and the thin layer's 2, (J.12));
    ``E0`` (unless given) from Hertz at the deepest point.
    """
    if not (isinstance(work_of_adhesion, str) and work_of_adhesion == "free"):
        raise InputError(f"work_of_adhesion must be 'free' (fit w with E), got {work_of_adhesion!r}; a known w is not "
                         "fitted in this version")
    if extras:
        raise InputError(f"fit(work_of_adhesion='free') does not take {', '.join(extras)}")
    R = getattr(tip, "sphere_radius", None)
    if R is None:
        raise InputError("fit(work_of_adhesion='free') fits the paraboloid (sphere) only: give punch=R")
    d = _array(delta, "delta") * (1 if depth_sign == 1 else -1)
    P = _array(force, "force")
    if d.size != P.size:
        raise InputError(f"delta and force differ in length: {d.size} and {P.size}")
    from ..layers.kernels import BondedLayer, FrictionlessLayer, HalfSpace, IncompressibleLayer

    if H is None or (isinstance(H, (int, float)) and math.isinf(H)):
        layer, Hv = HalfSpace(), None
    else:
        Hv = positive(H, "H")
        layer = FrictionlessLayer() if base == "frictionless" else IncompressibleLayer() if nu == 0.5 \
            else BondedLayer(nu)
    pull = -float(np.min(P))
    if pull <= 0:
        raise InputError("no tensile (negative) force in the data: an adhesive curve pulls before it comes off "
                         "(give the unloading curve with its negative forces)")
    w0 = pull / (1.75 * math.pi * R)
    if E0 is None:
        i = int(np.argmax(d))
        if d[i] <= 0 or P[i] <= 0:
            raise InputError("give E0= (no point pressed into the layer to start E from)")
        E0 = 3 * P[i] * (1 - nu * nu) / (4 * math.sqrt(R) * d[i] ** 1.5)
    c_hi = 2 * math.sqrt(2 * R * max(float(np.max(d)), 1e-300))
    a_pull = (9 * math.pi * w0 * R * R * (1 - nu * nu) / (4 * float(E0))) ** (1 / 3)
    c_hi = max(c_hi, 2 * a_pull)
    return fit_adhesive(layer, tip, d, P, Hv, nu=nu, E0=E0, w0=w0, radii=(c_hi / 40, c_hi), model=model)
