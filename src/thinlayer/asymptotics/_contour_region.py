"""The contact region {Phi < delta0} of a polynomial punch, found and traced (the geometry behind (3.3)).

Private to :mod:`thinlayer.asymptotics.contour`: the polynomial in a fast numeric form, a box that holds
the region, its critical points, and the closed level line that bounds it, traced by contourpy and
checked for holes, several components and unboundedness.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .. import symbols as S
from ..parse import as_expr, parse_expression


def as_polynomial(Phi) -> tuple[sp.Expr, list[tuple[int, int, float]]]:
    """Phi -> (sympy expression in the canonical x1, x2, [(i, j, c_ij)])."""
    expr = getattr(Phi, "expr", Phi)  # a thinlayer Punch carries its expression in .expr
    if isinstance(expr, str):
        expr = parse_expression(expr, what="Phi")
    try:
        expr = as_expr(expr, "Phi")
    except (TypeError, ValueError) as exc:
        raise TypeError(f"Phi must be a sympy expression in x1, x2, got {Phi!r} ({type(Phi).__name__})") from exc
    if not isinstance(expr, sp.Expr):
        raise TypeError(f"Phi must be a sympy expression in x1, x2, got {expr!r} ({type(expr).__name__})")
    # symbols that carry the canonical names but other assumptions are the coordinates too
    ren = {q: {S.x1.name: S.x1, S.x2.name: S.x2}[q.name] for q in expr.free_symbols
           if q.name in (S.x1.name, S.x2.name)}
    expr = expr.xreplace(ren)
    other = sorted(expr.free_symbols - {S.x1, S.x2}, key=lambda q: q.name)
    if other:
        names = ", ".join(q.name for q in other)
        hint = ""
        if any(q.name in ("x1", "x2") for q in other):
            hint = " (the coordinates are thinlayer.symbols.x1, x2, named x_1, x_2)"
        raise ValueError(
            f"Phi = {expr} has free symbol(s) {names} besides the coordinates x_1, x_2{hint}; "
            "substitute numeric values for the punch parameters first"
        )
    if expr.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise ValueError(f"Phi = {expr} is not finite")
    if not expr.is_polynomial(S.x1, S.x2):
        raise ValueError(
            f"Phi = {expr} is not a polynomial in x_1, x_2; the contour needs "
            "Phi = sum c_ij x_1^i x_2^j with numeric coefficients"
        )
    poly = sp.Poly(expr, S.x1, S.x2)
    terms = []
    for (i, j), c in poly.terms():
        cv = complex(sp.N(c))
        if cv.imag != 0 or not math.isfinite(cv.real):
            raise ValueError(f"Phi = {expr} has the non-real coefficient {c} of x_1^{i} x_2^{j}")
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


def _bounding_radius(P: Poly2, delta0: float, expr) -> tuple[float, bool]:
    """A radius R with Phi > delta0 for |x| > R (rigorous: True), or a first guess (False).

    Raises ValueError when {Phi < delta0} is unbounded for a structural reason.
    """
    d = P.deg
    c0 = P.constant()
    if d == 0:
        if c0 >= delta0:
            raise ValueError(
                f"no contact: Phi = {expr} is constant, min Phi = {short(c0)} >= delta0 = {short(delta0)}; "
                "delta0 must exceed the minimum of Phi"
            )
        raise ValueError(f"Phi = {expr} is constant below delta0 = {short(delta0)}: the contact area "
                         "{delta0 - Phi > 0} is the whole plane (unbounded)")
    theta = np.linspace(0.0, 2 * np.pi, 2048, endpoint=False)
    lead = P.homogeneous(d, theta)
    big = float(np.max(np.abs(lead)))
    m = float(np.min(lead))
    if m < -1e-12 * big:
        th = float(theta[int(np.argmin(lead))])
        raise ValueError(
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
    return (max(scales) if scales else 1.0), False


def _box_edge(x0, x1, y0, y1, n=256):
    t = np.linspace(0.0, 1.0, n)
    xs = np.concatenate([x0 + (x1 - x0) * t, np.full(n, x1), x1 - (x1 - x0) * t, np.full(n, x0)])
    ys = np.concatenate([np.full(n, y0), y0 + (y1 - y0) * t, np.full(n, y1), y1 - (y1 - y0) * t])
    return xs, ys


def _edge_clear(P: Poly2, delta0: float, box) -> bool:
    xs, ys = _box_edge(*box)
    return bool(np.all(P.value(xs, ys) > delta0))


def _outer_box(P: Poly2, delta0: float, expr):
    R, rigorous = _bounding_radius(P, delta0, expr)
    if rigorous:
        R = 1.25 * R + 1e-300
        return (-R, R, -R, R)
    # heuristic: grow until the box edge lies in {Phi > delta0}, then confirm on larger boxes
    for _ in range(60):
        if all(_edge_clear(P, delta0, (-R * f, R * f, -R * f, R * f)) for f in (1.0, 2.0, 4.0, 16.0, 256.0)):
            return (-2 * R, 2 * R, -2 * R, 2 * R)
        R *= 2.0
    raise ValueError(
        f"the contact area {{delta0 - Phi > 0}} is unbounded for Phi = {expr}, delta0 = {short(delta0)}: "
        "the set {Phi < delta0} reaches the edge of every box up to "
        f"|x| = {short(R)}; the punch must rise above delta0 in every direction"
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


def _closed_lines(xs, ys, Z, level, expr, delta0):
    import contourpy

    gen = contourpy.contour_generator(xs, ys, Z, line_type=contourpy.LineType.Separate)
    out = []
    for ln in gen.lines(level):
        ln = np.asarray(ln, dtype=float)
        if len(ln) < 4:
            continue
        if not np.allclose(ln[0], ln[-1], rtol=0, atol=1e-12 * (abs(ln).max() + 1e-300)):
            raise ValueError(
                f"the contact area {{delta0 - Phi > 0}} is unbounded for Phi = {expr}, delta0 = {short(delta0)}: "
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
                  expr) -> tuple[float, float, float]:
    """The global minimum of Phi (grid and critical points); no contact when it is not below delta0."""
    k = int(np.argmin(F))
    best = (float(F.flat[k]), float(X.flat[k]), float(Y.flat[k]))
    for cx, cy in crit:
        v = float(P.value(cx, cy))
        if v < best[0]:
            best = (v, cx, cy)
    scale = max(delta0, abs(best[0]))
    if best[0] >= delta0 - 1e-12 * scale:
        raise ValueError(
            f"no contact: delta0 = {short(delta0)} does not exceed the minimum of Phi = {expr}, "
            f"min Phi = {short(best[0])} at (x1, x2) = ({short(best[1])}, {short(best[2])}); "
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


def _trace(P: Poly2, delta0: float, expr, box: tuple, outer: tuple, crit: list) -> tuple[list, list]:
    """The closed level lines on a fine grid, zooming in while they fill less than a fifth of the box."""
    Gf = 129
    curves: list = []
    for _ in range(12):
        xs, ys, X, Y, D = _grid(P, box, Gf, Gf)
        crit = crit + [c for c in _critical_points(P, X, Y, D, box)
                       if all(math.hypot(c[0] - p, c[1] - q) > 1e-6 * (box[1] - box[0]) for p, q in crit)]
        curves = _closed_lines(xs, ys, D[0], delta0, expr, delta0)
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


def _check_smooth(P: Poly2, crit: list, delta0: float, expr) -> None:
    """A critical point on the level set: Gamma_0 is not smooth there."""
    for cx, cy in crit:
        v = float(P.value(cx, cy))
        if abs(v - delta0) <= 1e-8 * max(delta0, abs(v)):
            raise ValueError(
                f"the contour Phi = delta0 = {short(delta0)} of Phi = {expr} is not smooth: it passes through "
                f"the critical point (x1, x2) = ({short(cx)}, {short(cy)}) where grad Phi = 0; "
                "choose a delta0 different from the critical values of Phi"
            )


def _small_components(P: Poly2, curves: list, mins: list, delta0: float, expr, outer: tuple) -> list:
    """Minima below delta0 that no curve encloses: zoom around each (unresolved small components)."""
    curves = list(curves)
    for cx, cy, r in mins:
        if any(_inside(c, cx, cy)[0] for c in curves):
            continue
        lb = _fit(P, delta0, _expand((cx - r, cx + r, cy - r, cy + r), 0.5, outer), outer)
        lxs, lys, _, _, LD = _grid(P, lb, 97, 97)
        for c in _closed_lines(lxs, lys, LD[0], delta0, expr, delta0):
            if _inside(c, cx, cy)[0]:
                curves.append(c)
                break
    return curves


def _check_one_region(P: Poly2, curves: list, crit: list, delta0: float, expr) -> np.ndarray:
    """The one closed curve of a simply connected region; holes and extra components are errors."""
    if not curves:
        raise RuntimeError(f"could not resolve the level set Phi = {short(delta0)} of Phi = {expr} on a grid")
    if len(curves) > 1:
        nested = any(_inside(b, *a[0])[0] for a in curves for b in curves if a is not b)
        cents = "; ".join(f"({short(c[:, 0].mean())}, {short(c[:, 1].mean())})" for c in curves)
        if nested:
            raise ValueError(
                f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {short(delta0)} is not simply "
                f"connected: its boundary has {len(curves)} nested closed curves (a region with a hole, e.g. an "
                f"annulus) around {cents}; the boundary-layer analysis needs one simply connected region"
            )
        raise ValueError(
            f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {short(delta0)} has {len(curves)} "
            f"components (near {cents}); the boundary-layer analysis needs one simply connected region"
        )
    curve = curves[0]
    for cx, cy in crit:
        v = float(P.value(cx, cy))
        ins = _inside(curve, cx, cy)[0]
        if ins and v > delta0:
            raise ValueError(
                f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {short(delta0)} is not simply "
                f"connected: it has a hole around (x1, x2) = ({short(cx)}, {short(cy)}) where Phi = {short(v)} > "
                "delta0; the boundary-layer analysis needs one simply connected region"
            )
        if not ins and v < delta0:
            raise ValueError(
                f"the contact area {{delta0 - Phi > 0}} for Phi = {expr}, delta0 = {short(delta0)} has more than "
                f"one component: Phi = {short(v)} < delta0 at (x1, x2) = ({short(cx)}, {short(cy)}) outside the "
                "main one; the boundary-layer analysis needs one simply connected region"
            )
    return curve


def region_curve(P: Poly2, delta0: float, expr):
    """The polygon (M, 2) of the single closed level line, after all structural checks (3.3).

    Returns the curve, the critical points of Phi found on the way and the lowest point ``(Phi, x1, x2)``.
    """
    outer = _outer_box(P, delta0, expr)
    G = 97
    _, _, X, Y, D = _grid(P, outer, G, G)
    crit = _critical_points(P, X, Y, D, outer)
    best = _lowest_point(P, D[0], X, Y, crit, delta0, expr)
    cell = ((outer[1] - outer[0]) / (G - 1), (outer[3] - outer[2]) / (G - 1))
    boxes, mins = _zoom_boxes(P, D[0], X, Y, crit, delta0, cell, G)
    bb = (min(b[0] for b in boxes), max(b[1] for b in boxes), min(b[2] for b in boxes), max(b[3] for b in boxes))
    curves, crit = _trace(P, delta0, expr, _fit(P, delta0, _expand(bb, 0.1, outer), outer), outer, crit)
    _check_smooth(P, crit, delta0, expr)
    curves = _small_components(P, curves, mins, delta0, expr, outer)
    return _check_one_region(P, curves, crit, delta0, expr), crit, best
