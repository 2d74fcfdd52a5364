"""The contact region {Phi < delta0} of a polynomial punch, found and traced (the geometry behind (3.3)).

Private to :mod:`thinlayer.asymptotics.contour`: the polynomial in a fast numeric form, a box that holds
the region, its critical points, and the closed level line that bounds it, traced by contourpy and
checked for holes, several components and unboundedness.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import sympy as sp

from .. import symbols as S
from .._checks import ComputationError, InputError, InputTypeError, WorkLimitError
from ..parse import as_expr, check_cost, expression_cost, parse_expression
from ..punch import MAX_DEGREE


def as_polynomial(Phi) -> tuple[sp.Expr, list[tuple[int, int, float]]]:
    """Phi -> (sympy expression in the canonical x1, x2, [(i, j, c_ij)])."""
    expr = getattr(Phi, "expr", Phi)  # a thinlayer Punch carries its expression in .expr
    if isinstance(expr, str):
        expr = parse_expression(expr, what="Phi")
    try:
        expr = as_expr(expr, "Phi")
    except (TypeError, ValueError) as exc:
        raise InputTypeError(f"Phi must be a sympy expression in x1, x2, got {Phi!r} ({type(Phi).__name__})") from exc
    if not isinstance(expr, sp.Expr):
        raise InputTypeError(f"Phi must be a sympy expression in x1, x2, got {expr!r} ({type(expr).__name__})")
    # symbols that carry the canonical names but other assumptions are the coordinates too
    ren = {q: {S.x1.name: S.x1, S.x2.name: S.x2}[q.name] for q in expr.free_symbols
           if q.name in (S.x1.name, S.x2.name)}
    expr = expr.xreplace(ren)
    cost = expression_cost(expr)  # a sympy expression given directly: bounded like a string, before any work
    check_cost(expr, "Phi", cost=cost)
    if cost.degree > MAX_DEGREE:
        raise WorkLimitError(f"Phi has degree up to {cost.degree}, above the limit {MAX_DEGREE} of a punch: the "
                             "contour's polynomial arithmetic grows with it; give a polynomial of lower degree")
    other = sorted(expr.free_symbols - {S.x1, S.x2}, key=lambda q: q.name)
    if other:
        names = ", ".join(q.name for q in other)
        hint = ""
        if any(q.name in ("x1", "x2") for q in other):
            hint = " (the coordinates are thinlayer.symbols.x1, x2, named x_1, x_2)"
        raise InputError(
            f"Phi = {expr} has free symbol(s) {names} besides the coordinates x_1, x_2{hint}; "
            "substitute numeric values for the punch parameters first"
        )
    if expr.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise InputError(f"Phi = {expr} is not finite")
    if not expr.is_polynomial(S.x1, S.x2):
        raise InputError(
            f"Phi = {expr} is not a polynomial in x_1, x_2; the contour needs "
            "Phi = sum c_ij x_1^i x_2^j with numeric coefficients"
        )
    poly = sp.Poly(expr, S.x1, S.x2)
    terms = []
    for (i, j), c in poly.terms():
        cv = complex(sp.N(c))
        if cv.imag != 0 or not math.isfinite(cv.real):
            raise InputError(f"Phi = {expr} has the non-real coefficient {c} of x_1^{i} x_2^{j}")
        if cv.real != 0.0:
            terms.append((int(i), int(j), cv.real))
    return expr, terms


# ---------------------------------------------------------------------------------------------
# fast numeric polynomial with derivatives
# ---------------------------------------------------------------------------------------------
class Poly2:
    """Phi(x, y) = sum c_ij x^i y^j with its gradient and Hessian, vectorised (numpy)."""

    def __init__(self, terms: list[tuple[int, int, float]]):
        self.terms = list(terms)
        self.deg = max((i + j for i, j, _ in terms), default=0)
        self.ix = np.array([t[0] for t in terms], dtype=int)
        self.iy = np.array([t[1] for t in terms], dtype=int)
        self.c = np.array([t[2] for t in terms], dtype=float)

    def _powers(self, x):
        p = [np.ones_like(x)]
        for _ in range(self.deg):
            p.append(p[-1] * x)
        return p

    def value(self, x, y):
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        px, py = self._powers(x), self._powers(y)
        out = np.zeros(np.broadcast(x, y).shape)
        for i, j, c in self.terms:
            out = out + c * px[i] * py[j]
        return out

    def all(self, x, y):
        """(Phi, Phi_x, Phi_y, Phi_xx, Phi_xy, Phi_yy)."""
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        px, py = self._powers(x), self._powers(y)
        shape = np.broadcast(x, y).shape
        f, fx, fy, fxx, fxy, fyy = (np.zeros(shape) for _ in range(6))
        for i, j, c in self.terms:
            f = f + c * px[i] * py[j]
            if i:
                fx = fx + c * i * px[i - 1] * py[j]
            if j:
                fy = fy + c * j * px[i] * py[j - 1]
            if i > 1:
                fxx = fxx + c * i * (i - 1) * px[i - 2] * py[j]
            if i and j:
                fxy = fxy + c * i * j * px[i - 1] * py[j - 1]
            if j > 1:
                fyy = fyy + c * j * (j - 1) * px[i] * py[j - 2]
        return f, fx, fy, fxx, fxy, fyy

    def grad(self, x, y):
        return self.all(x, y)[1:3]

    def homogeneous(self, k: int, theta):
        """The degree-k homogeneous part on the unit circle."""
        ct, st = np.cos(theta), np.sin(theta)
        out = np.zeros_like(theta)
        for i, j, c in self.terms:
            if i + j == k:
                out = out + c * ct**i * st**j
        return out

    def abs_sum(self, k: int) -> float:
        return float(sum(abs(c) for i, j, c in self.terms if i + j == k))

    def constant(self) -> float:
        return float(sum(c for i, j, c in self.terms if i == 0 and j == 0))


# ---------------------------------------------------------------------------------------------
# locating the region
# ---------------------------------------------------------------------------------------------
def short(v: float) -> str:
    return f"{v:.6g}"


def _bounding_radius(P: Poly2, delta0: float, expr, fr: Frame) -> tuple[float, bool]:
    """A radius R with Phi > delta0 for |x| > R (rigorous: True), or a first guess (False).

    Raises ValueError when {Phi < delta0} is unbounded for a structural reason.
    """
    d = P.deg
    c0 = P.constant()
    if d == 0:
        if c0 >= delta0:
            raise InputError(
                f"no contact: Phi = {expr} is constant, min Phi = {fr.val(c0)} >= delta0 = {fr.val(delta0)}; "
                "delta0 must exceed the minimum of Phi"
            )
        raise InputError(f"Phi = {expr} is constant below delta0 = {fr.val(delta0)}: the contact area "
                         "{delta0 - Phi > 0} is the whole plane (unbounded)")
    theta = np.linspace(0.0, 2 * np.pi, 2048, endpoint=False)
    lead = P.homogeneous(d, theta)
    big = float(np.max(np.abs(lead)))
    m = float(np.min(lead))
    if m < -1e-12 * big:
        th = fr.angle(float(theta[int(np.argmin(lead))]))
        raise InputError(
            f"the contact area {{delta0 - Phi > 0}} is unbounded: Phi = {expr} tends to -infinity along "
            f"the direction (cos t, sin t), t = {short(th)}; the punch must rise in every direction "
            "(e.g. a positive definite leading part)"
        )
    if m > 1e-9 * big and d >= 2:
        m *= 1.0 - 1e-3  # the circle is sampled: keep the bound on the safe side
        coeffs = [m] + [-P.abs_sum(k) for k in range(d - 1, 0, -1)] + [-(delta0 - c0)]
        roots = np.roots(coeffs)
        pos = [r.real for r in roots if abs(r.imag) <= 1e-9 * max(1.0, abs(r)) and r.real > 0]
        if pos:
            return max(pos), True
    # semidefinite leading part (or no positive root): a guess, to be checked by growth
    scales = [((abs(delta0 - c0) + delta0) / P.abs_sum(k)) ** (1.0 / k) for k in range(1, d + 1)
              if P.abs_sum(k) > 0]
    # the smallest length first (the box grows until its edge is clear); the largest is checked too
    return (min(scales) if scales else 1.0), False


# ---------------------------------------------------------------------------------------------
# the natural frame: the region search runs in x = A u, Phi / delta0 (scale-free)
# ---------------------------------------------------------------------------------------------
#: up to this aspect ratio (longest / shortest principal axis of omega_0) Gamma_0 is represented directly by
#: its arc-length Fourier series in x (an ellipse of aspect ratio r needs about 18 r^2 nodes: 256 for r = 3);
#: more elongated contours are represented in the round frame x = W w (:func:`round_frame`), at a cost that
#: does not grow with r
ASPECT_DIRECT = 3.0
#: the largest supported aspect ratio: beyond it the tip curvature (about r^2 / length) and the powers of the
#: frame lengths in the transformed polynomial approach the double range (1e308)
ASPECT_MAX = 1e100


def _sym_eig2(q11: float, q12: float, q22: float):
    """Eigenvalues (lo, hi) and the unit eigenvector of ``hi`` of a symmetric 2x2 matrix (lo via det/hi)."""
    m = 0.5 * (q11 + q22)
    r = math.hypot(0.5 * (q11 - q22), q12)
    hi = m + r
    if hi <= 0:
        return m - r, hi, (1.0, 0.0)
    # the determinant exactly (a rotated, elongated form cancels in q11 q22 - q12^2)
    lo = float(Fraction(q11) * Fraction(q22) - Fraction(q12) ** 2) / hi
    if q12 == 0.0:
        v = (1.0, 0.0) if q11 >= q22 else (0.0, 1.0)
    elif q11 >= q22:
        v = (0.5 * (q11 - q22) + r, q12)
    else:
        v = (q12, 0.5 * (q22 - q11) + r)
    nv = math.hypot(*v)
    return lo, hi, (v[0] / nv, v[1] / nv)


class Frame:
    """``x = A u`` and ``Phi = delta0 Phi~``: the coordinates the region is searched in (messages in x)."""

    def __init__(self, A: np.ndarray, ell: float, vscale: float):
        self.A = np.asarray(A, dtype=float)  # x = A u, A = ell * B
        self.ell = float(ell)
        self.vscale = float(vscale)

    def to_x(self, u1, u2):
        u1 = np.asarray(u1, dtype=float)
        u2 = np.asarray(u2, dtype=float)
        return self.A[0, 0] * u1 + self.A[0, 1] * u2, self.A[1, 0] * u1 + self.A[1, 1] * u2

    def pt(self, u1, u2, bare: bool = False) -> str:
        x, y = self.to_x(u1, u2)
        p = f"({short(float(x))}, {short(float(y))})"
        return p if bare else f"(x1, x2) = {p}"

    def val(self, v: float) -> str:
        return short(float(v) * self.vscale)

    def length(self, r: float) -> str:
        return short(float(r) * float(np.linalg.norm(self.A, 2)))

    def angle(self, th: float) -> float:
        x, y = self.to_x(math.cos(th), math.sin(th))
        return math.atan2(float(y), float(x)) % (2 * math.pi)


def _term_lengths(P: Poly2, delta0: float) -> dict[int, float]:
    """``l_k``: the radius where the degree-k terms alone reach ``|delta0 - c0| + delta0`` (in logs)."""
    c0 = P.constant()
    top = math.log(abs(delta0 - c0) + delta0)
    out = {}
    for k in range(1, P.deg + 1):
        a = P.abs_sum(k)
        if a > 0:
            out[k] = math.exp((top - math.log(a)) / k)
    return out


def natural_frame(P: Poly2, delta0: float) -> Frame:
    """The natural lengths of Phi at delta0: ``x = A u`` with the region of size about 1 in ``u``.

    A positive definite quadratic part ``x^T Q x / 2`` gives the principal lengths
    ``l_j = sqrt(2 delta0 / lambda_j)`` along its eigenvectors (each capped by the lengths of the
    other degrees, which bound the region when they are larger); otherwise one isotropic length,
    the smallest ``l_k``.
    """
    lens = _term_lengths(P, delta0)
    if not lens:
        return Frame(np.eye(2), 1.0, delta0)
    c = {(i, j): cc for i, j, cc in P.terms if i + j == 2}
    lo, hi, v = _sym_eig2(2 * c.get((2, 0), 0.0), c.get((1, 1), 0.0), 2 * c.get((0, 2), 0.0))
    cap = min((lk for k, lk in lens.items() if k != 2), default=math.inf)
    if lo > 0 and hi > 0 and math.isfinite(lo) and math.isfinite(hi):
        l_short = min(math.sqrt(2 * delta0 / hi), cap)  # along v
        l_long = min(math.sqrt(2 * delta0 / lo), cap)  # along v rotated by 90 degrees
        ell = math.sqrt(l_short) * math.sqrt(l_long)
        B = np.array([[v[0] * l_short / ell, -v[1] * l_long / ell],
                      [v[1] * l_short / ell, v[0] * l_long / ell]])
    else:
        # no definite quadratic part: per-axis lengths from the pure powers x1^i, x2^j when both exist
        top = math.log(abs(delta0 - P.constant()) + delta0)
        l1 = min((math.exp((top - math.log(abs(cc))) / i) for i, j, cc in P.terms if j == 0 and i > 0),
                 default=None)
        l2 = min((math.exp((top - math.log(abs(cc))) / j) for i, j, cc in P.terms if i == 0 and j > 0),
                 default=None)
        if l1 is not None and l2 is not None:
            ell = math.sqrt(l1) * math.sqrt(l2)
            B = np.diag([l1 / ell, l2 / ell])
        else:
            ell = min(lens.values())
            B = np.eye(2)
    return Frame(ell * B, ell, delta0)


def _linear_power(p: Fraction, q: Fraction, n: int) -> dict[tuple[int, int], Fraction]:
    """``(p u + q v)^n`` as {(a, b): coefficient of u^a v^b}."""
    return {(k, n - k): math.comb(n, k) * p**k * q ** (n - k) for k in range(n + 1)}


def transformed(P: Poly2, fr: Frame) -> Poly2:
    """``Phi(A u) / delta0`` as a :class:`Poly2` in ``u``, each coefficient correctly rounded.

    The expansion runs in exact rational arithmetic on the float coefficients of Phi, the entries of
    ``A`` and delta0 (each a :class:`fractions.Fraction`, exact): no overflow of the powers of the
    frame lengths, and no loss to the cancellation of a rotated, elongated quadratic form, whose terms
    ``c_20 x1^2 + c_11 x1 x2 + c_02 x2^2`` are each about ``r^2`` times their sum on the region.
    """
    A = [[Fraction(float(v)) for v in row] for row in fr.A]
    inv = 1 / Fraction(float(fr.vscale))
    out: dict[tuple[int, int], Fraction] = {}
    for i, j, c in P.terms:
        cs = Fraction(c) * inv
        px = _linear_power(A[0][0], A[0][1], i)
        py = _linear_power(A[1][0], A[1][1], j)
        for (a1, b1), v1 in px.items():
            for (a2, b2), v2 in py.items():
                key = (a1 + a2, b1 + b2)
                out[key] = out.get(key, 0) + cs * v1 * v2
    vals = {}
    for (i, j), v in sorted(out.items()):
        try:
            vals[(i, j)] = float(v)
        except OverflowError:
            raise InputError(f"Phi overflows on its natural lengths: the coefficient of u_1^{i} u_2^{j} in "
                             f"Phi(A u)/delta0 exceeds the double range (|A| = {np.abs(fr.A).max():g})") from None
    big = max((abs(v) for v in vals.values()), default=0.0)
    return Poly2([(i, j, v) for (i, j), v in vals.items() if abs(v) > 1e-300 * big and v != 0.0])


def _moments(curve_u: np.ndarray) -> tuple[float, float, np.ndarray]:
    """Centroid and central second-moment matrix of the polygon (exact for the polygon, Green's theorem)."""
    x, y = curve_u[:, 0], curve_u[:, 1]
    xn, yn = np.roll(x, -1), np.roll(y, -1)
    a = x * yn - xn * y
    A = 0.5 * a.sum()
    cx = ((x + xn) * a).sum() / (6 * A)
    cy = ((y + yn) * a).sum() / (6 * A)
    mxx = ((x * x + x * xn + xn * xn) * a).sum() / (12 * A) - cx * cx
    myy = ((y * y + y * yn + yn * yn) * a).sum() / (12 * A) - cy * cy
    mxy = ((x * yn + 2 * x * y + 2 * xn * yn + xn * y) * a).sum() / (24 * A) - cx * cy
    return float(cx), float(cy), np.array([[mxx, mxy], [mxy, myy]])


def _aspect(curve_u: np.ndarray, fr: Frame) -> float:
    """sqrt(largest / smallest principal second moment) of the polygon, mapped to x (ellipse: a/b)."""
    B = fr.A / fr.ell
    with np.errstate(over="ignore", invalid="ignore"):
        M = B @ _moments(curve_u)[2] @ B.T
        if not np.all(np.isfinite(M)):
            return math.inf
        lo, hi, _ = _sym_eig2(M[0, 0], M[0, 1], M[1, 1])
        return math.sqrt(hi / lo) if lo > 0 and math.isfinite(hi) else math.inf


def round_frame(curve_u: np.ndarray, fr: Frame) -> tuple[Frame, np.ndarray, float]:
    """The frame ``x = W w`` in which omega_0 is round: ``W = A S``, ``S = (4 M)^(1/2)``.

    ``M`` is the central second-moment matrix of the region polygon in the natural coordinates
    ``u`` (``x = A u``), so the region becomes about the unit disk in ``w = S^-1 u`` (its second
    moments are those of the unit disk, ``I/4``).  The product is formed in ``u``, never by
    inverting ``W`` in ``x``, so an aspect ratio of 1e30 loses nothing.  Returns the frame (with
    ``ell`` and ``vscale`` of ``fr``), the polygon in ``w`` and ``det W`` (from the factors).
    """
    _, _, M = _moments(curve_u)
    lam, V = np.linalg.eigh(4.0 * M)
    if not (lam.min() > 0 and np.all(np.isfinite(lam))):
        raise ComputationError("degenerate region polygon (no area in one direction)")
    S = (V * np.sqrt(lam)) @ V.T
    Sinv = (V / np.sqrt(lam)) @ V.T
    A = fr.A
    # det A = (v1^2 + v2^2) l_short l_long for the natural frames: both products have one sign, no cancellation
    det = float(A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]) * float(np.prod(np.sqrt(lam)))
    return Frame(A @ S, fr.ell, fr.vscale), curve_u @ Sinv.T, det


def _box_edge(x0, x1, y0, y1, n=256):
    t = np.linspace(0.0, 1.0, n)
    xs = np.concatenate([x0 + (x1 - x0) * t, np.full(n, x1), x1 - (x1 - x0) * t, np.full(n, x0)])
    ys = np.concatenate([np.full(n, y0), y0 + (y1 - y0) * t, np.full(n, y1), y1 - (y1 - y0) * t])
    return xs, ys


def _edge_min(P: Poly2, fixed: float, lo: float, hi: float, axis: int) -> float:
    """The minimum of Phi on the segment x_axis = fixed, the other coordinate in [lo, hi] (exact 1-D polynomial)."""
    coef = np.zeros(P.deg + 1)
    for i, j, c in P.terms:
        k, m = (j, i) if axis == 0 else (i, j)  # m: power of the fixed coordinate, k: of the free one
        coef[k] += c * fixed**m
    p = np.polynomial.Polynomial(coef)
    cand = [lo, hi]
    if P.deg >= 2 and np.any(coef[1:] != 0):
        for r in p.deriv().roots():
            if abs(r.imag) <= 1e-9 * max(1.0, abs(r)) and lo <= r.real <= hi:
                cand.append(r.real)
    return float(np.min(p(np.array(cand))))


def _edge_clear(P: Poly2, delta0: float, box) -> bool:
    xs, ys = _box_edge(*box)
    if not np.all(P.value(xs, ys) > delta0):
        return False
    x0, x1, y0, y1 = box
    with np.errstate(all="ignore"):
        mins = [_edge_min(P, x0, y0, y1, 0), _edge_min(P, x1, y0, y1, 0),
                _edge_min(P, y0, x0, x1, 1), _edge_min(P, y1, x0, x1, 1)]
    return bool(all(m > delta0 or not math.isfinite(m) for m in mins))


def _outer_box(P: Poly2, delta0: float, expr, fr: Frame):
    R, rigorous = _bounding_radius(P, delta0, expr, fr)
    if rigorous:
        R = 1.25 * R + 1e-300
        return (-R, R, -R, R)
    # heuristic: grow until the box edge lies in {Phi > delta0}, then confirm on larger boxes and at the
    # largest natural length (where the weakest terms alone reach delta0)
    far = max(_term_lengths(P, delta0).values(), default=R)
    for _ in range(60):
        fs = (1.0, 2.0, 4.0, 16.0, 256.0) + ((2 * far / R,) if 2 * far > 256 * R else ())
        if all(_edge_clear(P, delta0, (-R * f, R * f, -R * f, R * f)) for f in fs):
            return (-2 * R, 2 * R, -2 * R, 2 * R)
        R *= 2.0
    raise InputError(
        f"the contact area {{delta0 - Phi > 0}} is unbounded for Phi = {expr}, delta0 = {fr.val(delta0)}: "
        "the set {Phi < delta0} reaches the edge of every box up to "
        f"|x| = {fr.length(R)}; the punch must rise above delta0 in every direction"
    )


def _grid(P: Poly2, box, nx: int, ny: int):
    xs = np.linspace(box[0], box[1], nx)
    ys = np.linspace(box[2], box[3], ny)
    X, Y = np.meshgrid(xs, ys)
    return xs, ys, X, Y, P.all(X, Y)


def _critical_points(P: Poly2, X, Y, D, box) -> list[tuple[float, float]]:
    """Critical points of Phi: Newton on grad Phi = 0 from the grid minima of |grad Phi|^2."""
    _, fx, fy, *_ = D
    g2 = fx**2 + fy**2
    core = g2[1:-1, 1:-1]
    ismin = np.ones_like(core, dtype=bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                ismin &= core <= g2[1 + di:g2.shape[0] - 1 + di, 1 + dj:g2.shape[1] - 1 + dj]
    idx = np.argwhere(ismin)
    if len(idx) == 0:
        return []
    vals = core[ismin]
    order = np.argsort(vals)[:400]
    idx = idx[order]
    x = X[idx[:, 0] + 1, idx[:, 1] + 1].copy()
    y = Y[idx[:, 0] + 1, idx[:, 1] + 1].copy()
    size = max(box[1] - box[0], box[3] - box[2])
    for _ in range(80):
        _, gx, gy, hxx, hxy, hyy = P.all(x, y)
        # regularised Newton step for the 2x2 system H dx = -g (H may be singular)
        hn = hxx**2 + 2 * hxy**2 + hyy**2
        mu = 1e-14 * hn + 1e-300
        a11 = hxx * hxx + hxy * hxy + mu
        a12 = hxx * hxy + hxy * hyy
        a22 = hxy * hxy + hyy * hyy + mu
        r1 = -(hxx * gx + hxy * gy)
        r2 = -(hxy * gx + hyy * gy)
        det = a11 * a22 - a12 * a12
        det = np.where(det == 0, 1e-300, det)
        dx = (a22 * r1 - a12 * r2) / det
        dy = (a11 * r2 - a12 * r1) / det
        step = np.hypot(dx, dy)
        lim = 0.25 * size
        scale = np.where(step > lim, lim / np.maximum(step, 1e-300), 1.0)
        x = x + scale * dx
        y = y + scale * dy
        if np.all(step <= 1e-15 * size):
            break
    _, gx, gy, hxx, hxy, hyy = P.all(x, y)
    gscale = np.sqrt(np.max(g2)) + 1e-300
    ok = np.isfinite(x) & np.isfinite(y) & (np.hypot(gx, gy) <= 1e-9 * gscale)
    ok &= (x >= box[0] - 0.01 * size) & (x <= box[1] + 0.01 * size)
    ok &= (y >= box[2] - 0.01 * size) & (y <= box[3] + 0.01 * size)
    pts: list[tuple[float, float]] = []
    for xi, yi in zip(x[ok], y[ok]):
        if all(math.hypot(xi - p, yi - q) > 1e-6 * size for p, q in pts):
            pts.append((float(xi), float(yi)))
    return pts


def _inside(poly: np.ndarray, x, y) -> np.ndarray:
    """Even-odd point-in-polygon test, vectorised over the points (x, y)."""
    x = np.atleast_1d(np.asarray(x, dtype=float))
    y = np.atleast_1d(np.asarray(y, dtype=float))
    px, py = poly[:, 0], poly[:, 1]
    qx, qy = np.roll(px, -1), np.roll(py, -1)
    X = x[:, None]
    Y = y[:, None]
    cond = (py[None, :] > Y) != (qy[None, :] > Y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xint = px[None, :] + (Y - py[None, :]) * (qx - px)[None, :] / (qy - py)[None, :]
    cross = cond & (X < xint)
    return (np.count_nonzero(cross, axis=1) % 2) == 1


def _closed_lines(xs, ys, Z, level, expr, delta0, fr: Frame, outer: tuple):
    """The closed level lines on one grid; an open one is unboundedness only on the outer box."""
    import contourpy

    gen = contourpy.contour_generator(xs, ys, Z, line_type=contourpy.LineType.Separate)
    out = []
    for ln in gen.lines(level):
        ln = np.asarray(ln, dtype=float)
        if len(ln) < 4:
            continue
        if not np.allclose(ln[0], ln[-1], rtol=0, atol=1e-12 * (abs(ln).max() + 1e-300)):
            if (xs[0], xs[-1], ys[0], ys[-1]) != tuple(outer):
                raise ComputationError(
                    f"could not resolve the level set Phi = {fr.val(delta0)} of Phi = {expr}: it leaves every zoom "
                    "box of the search grid (features much thinner than the region, e.g. long narrow arms)"
                )
            raise InputError(
                f"the contact area {{delta0 - Phi > 0}} is unbounded for Phi = {expr}, delta0 = {fr.val(delta0)}: "
                "a level line Phi = delta0 leaves the search box"
            )
        out.append(ln[:-1])
    return out


def signed_area(poly: np.ndarray) -> float:
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def _expand(box, frac, outer):
    w, h = box[1] - box[0], box[3] - box[2]
    b = (box[0] - frac * w, box[1] + frac * w, box[2] - frac * h, box[3] + frac * h)
    return (max(b[0], outer[0]), min(b[1], outer[1]), max(b[2], outer[2]), min(b[3], outer[3]))


def _lowest_point(P: Poly2, F: np.ndarray, X: np.ndarray, Y: np.ndarray, crit: list, delta0: float,
                  expr, fr: Frame) -> tuple[float, float, float]:
    """The global minimum of Phi (grid and critical points); no contact when it is not below delta0."""
    k = int(np.argmin(F))
    best = (float(F.flat[k]), float(X.flat[k]), float(Y.flat[k]))
    for cx, cy in crit:
        v = float(P.value(cx, cy))
        if v < best[0]:
            best = (v, cx, cy)
    scale = max(delta0, abs(best[0]))
    if best[0] >= delta0 - 1e-12 * scale:
        raise InputError(
            f"no contact: delta0 = {fr.val(delta0)} does not exceed the minimum of Phi = {expr}, "
            f"min Phi = {fr.val(best[0])} at {fr.pt(best[1], best[2])}; "
            "delta0 must be larger than min Phi for the set {delta0 - Phi > 0} to be non-empty"
        )
    return best


def _zoom_boxes(P: Poly2, F, X, Y, crit, delta0: float, cell: tuple, G: int) -> tuple[list, list]:
    """Boxes around the grid points below delta0 and around each local minimum below it (with its radius)."""
    neg = F < delta0
    boxes = []
    if np.any(neg):
        boxes.append((X[neg].min() - 1.5 * cell[0], X[neg].max() + 1.5 * cell[0],
                      Y[neg].min() - 1.5 * cell[1], Y[neg].max() + 1.5 * cell[1]))
    mins = []
    for cx, cy in crit:
        v, _, _, hxx, hxy, hyy = (float(t) for t in P.all(cx, cy))
        lam = 0.5 * (hxx + hyy) - math.hypot(0.5 * (hxx - hyy), hxy)
        if v < delta0 and lam >= 0:
            r = math.sqrt(2 * (delta0 - v) / lam) if lam > 0 else max(cell)
            r = min(max(r, 1e-12 * max(cell)), max(cell) * G)
            mins.append((cx, cy, r))
            boxes.append((cx - r, cx + r, cy - r, cy + r))
    return boxes, mins


def _fit(P: Poly2, delta0: float, b: tuple, outer: tuple) -> tuple:
    """Grow a box until the level set stays clear of its edges (or it is the outer box)."""
    for _ in range(40):
        if _edge_clear(P, delta0, b) or b == outer:
            break
        b = _expand(b, 0.25, outer)
    return b


def _trace(P: Poly2, delta0: float, expr, box: tuple, outer: tuple, crit: list, fr: Frame) -> tuple[list, list]:
    """The closed level lines on a fine grid, zooming in while they fill less than a fifth of the box."""
    Gf = 129
    curves: list = []
    for _ in range(12):
        xs, ys, X, Y, D = _grid(P, box, Gf, Gf)
        crit = crit + [c for c in _critical_points(P, X, Y, D, box)
                       if all(math.hypot(c[0] - p, c[1] - q) > 1e-6 * (box[1] - box[0]) for p, q in crit)]
        curves = _closed_lines(xs, ys, D[0], delta0, expr, delta0, fr, outer)
        if curves:
            pts = np.vstack(curves)
            cb = (pts[:, 0].min(), pts[:, 0].max(), pts[:, 1].min(), pts[:, 1].max())
            if (cb[1] - cb[0]) < 0.2 * (box[1] - box[0]) or (cb[3] - cb[2]) < 0.2 * (box[3] - box[2]):
                nb = _fit(P, delta0, _expand(cb, 0.15, outer), outer)
                if nb != box:
                    box = nb
                    continue
        break
    return curves, crit


def _check_smooth(P: Poly2, crit: list, delta0: float, expr, fr: Frame) -> None:
    """A critical point on the level set: Gamma_0 is not smooth there."""
    for cx, cy in crit:
        v = float(P.value(cx, cy))
        if abs(v - delta0) <= 1e-8 * max(delta0, abs(v)):
            raise InputError(
                f"the contour Phi = delta0 = {fr.val(delta0)} of Phi = {expr} is not smooth: it passes through "
                f"the critical point {fr.pt(cx, cy)} where grad Phi = 0; "
                "choose a delta0 different from the critical values of Phi"
            )


def _small_components(P: Poly2, curves: list, mins: list, delta0: float, expr, outer: tuple,
                      fr: Frame) -> list:
    """Minima below delta0 that no curve encloses: zoom around each (unresolved small components)."""
    curves = list(curves)
    for cx, cy, r in mins:
        if any(_inside(c, cx, cy)[0] for c in curves):
            continue
        lb = _fit(P, delta0, _expand((cx - r, cx + r, cy - r, cy + r), 0.5, outer), outer)
        lxs, lys, _, _, LD = _grid(P, lb, 97, 97)
        for c in _closed_lines(lxs, lys, LD[0], delta0, expr, delta0, fr, outer):
            if _inside(c, cx, cy)[0]:
                curves.append(c)
                break
    return curves


def _check_one_region(P: Poly2, curves: list, crit: list, delta0: float, expr, fr: Frame) -> np.ndarray:
    """The one closed curve of a simply connected region; holes and extra components are errors."""
    if not curves:
        raise ComputationError(f"could not resolve the level set Phi = {fr.val(delta0)} of Phi = {expr} on a grid")
    if len(curves) > 1:
        nested = any(_inside(b, *a[0])[0] for a in curves for b in curves if a is not b)
        cents = "; ".join(fr.pt(c[:, 0].mean(), c[:, 1].mean(), bare=True) for c in curves)
        if nested:
            raise InputError(
                f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {fr.val(delta0)} is not simply "
                f"connected: its boundary has {len(curves)} nested closed curves (a region with a hole, e.g. an "
                f"annulus) around {cents}; the boundary-layer analysis needs one simply connected region"
            )
        raise InputError(
            f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {fr.val(delta0)} has {len(curves)} "
            f"components (near {cents}); the boundary-layer analysis needs one simply connected region"
        )
    curve = curves[0]
    for cx, cy in crit:
        v = float(P.value(cx, cy))
        ins = _inside(curve, cx, cy)[0]
        if ins and v > delta0:
            raise InputError(
                f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {fr.val(delta0)} is not simply "
                f"connected: it has a hole around {fr.pt(cx, cy)} where Phi = {fr.val(v)} > "
                "delta0; the boundary-layer analysis needs one simply connected region"
            )
        if not ins and v < delta0:
            raise InputError(
                f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {fr.val(delta0)} has more than "
                f"one component: Phi = {fr.val(v)} < delta0 at {fr.pt(cx, cy)} outside the "
                "main one; the boundary-layer analysis needs one simply connected region"
            )
    return curve


def region(P: Poly2, delta0: float, expr):
    """The polygon (M, 2) of the single closed level line, after all structural checks (3.3).

    The search is scale-free: it runs on ``Phi(A u) / delta0 = 1`` in the natural frame ``x = A u``
    (:func:`natural_frame`) and maps back.  Returns the curve, the critical points of Phi found on
    the way, the lowest point ``(Phi, x1, x2)`` (all in x), the aspect ratio of the region
    (longest/shortest principal axis, from its second moments; ``a/b`` for an ellipse), the natural
    frame and the curve in its coordinates ``u`` (``x = A u``).
    """
    fr = natural_frame(P, delta0)
    Q = transformed(P, fr)
    d1 = 1.0
    outer = _outer_box(Q, d1, expr, fr)
    G = 97
    _, _, X, Y, D = _grid(Q, outer, G, G)
    crit = _critical_points(Q, X, Y, D, outer)
    best = _lowest_point(Q, D[0], X, Y, crit, d1, expr, fr)
    cell = ((outer[1] - outer[0]) / (G - 1), (outer[3] - outer[2]) / (G - 1))
    boxes, mins = _zoom_boxes(Q, D[0], X, Y, crit, d1, cell, G)
    bb = (min(b[0] for b in boxes), max(b[1] for b in boxes), min(b[2] for b in boxes), max(b[3] for b in boxes))
    curves, crit = _trace(Q, d1, expr, _fit(Q, d1, _expand(bb, 0.1, outer), outer), outer, crit, fr)
    _check_smooth(Q, crit, d1, expr, fr)
    curves = _small_components(Q, curves, mins, d1, expr, outer, fr)
    curve = _check_one_region(Q, curves, crit, d1, expr, fr)
    cx, cy = fr.to_x(curve[:, 0], curve[:, 1])
    crit_x = [tuple(float(t) for t in fr.to_x(a, b)) for a, b in crit]
    bx, by = fr.to_x(best[1], best[2])
    return (np.column_stack([cx, cy]), crit_x, (best[0] * delta0, float(bx), float(by)), _aspect(curve, fr),
            fr, curve)


def region_curve(P: Poly2, delta0: float, expr):
    """The first three results of :func:`region`: ``(curve, critical points, lowest point)`` in x."""
    return region(P, delta0, expr)[:3]


def too_elongated(expr, delta0: float, ratio: float) -> InputError:
    """The one-line error for a contour whose aspect ratio leaves the double range."""
    return InputError(
        f"the contact contour of Phi = {expr} at delta0 = {short(delta0)} is too elongated for double precision: "
        f"its aspect ratio (longest/shortest principal axis) is {ratio:.3g}, above the supported limit "
        f"{ASPECT_MAX:g} (the tip curvature, about ratio^2/length, and the powers of the frame lengths "
        "approach the double range)"
    )
