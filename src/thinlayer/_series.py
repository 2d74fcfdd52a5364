"""Truncated power-series arithmetic over an integral domain.

The coefficients of (2.20) and (4.2) are quotients of power series whose Taylor
coefficients are known in closed form (sinh, cosh, polynomials).  Dividing power
series term by term over the field of rational functions of nu is slow (every step
cancels a gcd), so the quotient is computed *fraction-free*: for

    N(z) / D(z) = sum_n q_n z^n,   q_n = T_n / D_0^(n+1),

the numerators ``T_n`` satisfy ``T_n = N_n D_0^n - sum_{j=1}^n D_j T_{n-j} D_0^(j-1)``
and stay in the ring (polynomials in nu, integers, ...).  Over a field (rationals,
mpmath numbers) the plain recurrence is used.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any


def powers(x: Any, n: int, one: Any) -> list[Any]:
    """``[1, x, x**2, ..., x**n]``."""
    out = [one]
    for _ in range(n):
        out.append(out[-1] * x)
    return out


def quotient_fraction_free(num: Sequence[Any], den: Sequence[Any], n: int, one: Any) -> list[Any]:
    """Numerators ``T_0..T_n`` with ``(num/den)_k = T_k / den[0]**(k+1)`` (ring arithmetic only)."""
    d0p = powers(den[0], n, one)
    T: list[Any] = []
    for k in range(n + 1):
        acc = num[k] * d0p[k]
        for j in range(1, k + 1):
            acc -= den[j] * T[k - j] * d0p[j - 1]
        T.append(acc)
    return T


def quotient_field(num: Sequence[Any], den: Sequence[Any], n: int) -> list[Any]:
    """Coefficients of ``num/den`` to order n over a field (exact rationals or mpmath)."""
    q: list[Any] = []
    for k in range(n + 1):
        acc = num[k]
        for j in range(1, k + 1):
            acc -= den[j] * q[k - j]
        q.append(acc / den[0])
    return q


def reciprocal_recurrence(m: Sequence[Any], n: int, one: Any, zero: Any) -> list[Any]:
    """Reciprocal of ``1 + m_1 z + m_2 z^2 + ...`` by ``M_k = -sum_{j<k} m_{k-j} M_j`` (4.2)."""
    M = [one]
    for k in range(1, n + 1):
        acc = zero
        for j in range(k):
            acc -= m[k - j] * M[j]
        M.append(acc)
    return M


def multiply(a: Sequence[Any], b: Sequence[Any], n: int, zero: Any) -> list[Any]:
    """Cauchy product of two series truncated after order n."""
    out = []
    for k in range(n + 1):
        acc = zero
        for j in range(k + 1):
            acc += a[j] * b[k - j]
        out.append(acc)
    return out


def taylor_sinh(scale: int, n: int, const: Callable[[int, int], Any]) -> list[Any]:
    """Coefficients c_k of ``sinh(scale*s) / s = sum_k c_k s^(2k)``: ``scale^(2k+1)/(2k+1)!``."""
    out, f = [], 1
    for k in range(n + 1):
        if k:
            f *= (2 * k) * (2 * k + 1)
        out.append(const(scale ** (2 * k + 1), f))
    return out


def taylor_cosh(scale: int, n: int, const: Callable[[int, int], Any]) -> list[Any]:
    """Coefficients c_k of ``cosh(scale*s) = sum_k c_k s^(2k)``: ``scale^(2k)/(2k)!``."""
    out, f = [], 1
    for k in range(n + 1):
        if k:
            f *= (2 * k - 1) * (2 * k)
        out.append(const(scale ** (2 * k), f))
    return out


def bonded_series_parts(k: Any, n: int, const: Callable[[int, int], Any]) -> tuple[list[Any], list[Any]]:
    """Taylor coefficients (k <= n) of ``N, D`` in ``L(s)/s = N(s^2)/D(s^2)`` for the kernel (2.3).

    ``N = (2 kappa sinh 2s - 4s)/s``, ``D = 2 kappa cosh 2s + 1 + kappa^2 + 4 s^2``; ``k`` is kappa in
    the arithmetic domain of ``const``.
    """
    sh = taylor_sinh(2, n, const)  # sinh(2s)/s
    ch = taylor_cosh(2, n, const)  # cosh(2s)
    num = [2 * k * c for c in sh]
    num[0] = num[0] - const(4, 1)
    den = [2 * k * c for c in ch]
    den[0] = den[0] + 1 + k * k
    if n >= 1:
        den[1] = den[1] + const(4, 1)
    return num, den
