"""Exact conversions between mpmath numbers and gmpy2's MPFR numbers (imports nothing of thinlayer).

A hot loop of mpmath arithmetic runs several times faster in MPFR at the same precision: both round every
operation to nearest at a given number of bits, so a sum computed in MPFR at ``mpmath.mp.prec`` has mpmath's bits.
The conversions are exact (a number keeps its mantissa), so they add no rounding of their own.
"""
from __future__ import annotations

import gmpy2
import mpmath


def to_mpfr(x: mpmath.mpf) -> gmpy2.mpfr:
    """A finite mpmath number as an ``mpfr`` of the same value (precision: the mantissa's bits)."""
    sign, man, exp, bc = x._mpf_
    if not man:
        if exp:  # inf or nan
            raise ValueError(f"an exact conversion to MPFR needs a finite number, got {x}")
        return gmpy2.mpfr(0)
    with gmpy2.context(precision=max(int(bc), 2)):  # the mantissa's bits: exact (a negation rounds too)
        return gmpy2.mul_2exp(gmpy2.mpfr(-man if sign else man), int(exp))


def to_mpf(v: gmpy2.mpfr) -> mpmath.mpf:
    """A finite ``mpfr`` as an mpmath number, rounded once to mpmath's working precision (exact if it fits)."""
    man, exp = v.as_mantissa_exp()
    return mpmath.mpf((int(man), int(exp)))


def stieltjes_sums(a0: list, c: list, re: mpmath.mpf, im2: mpmath.mpf) -> tuple[mpmath.mpf, mpmath.mpf]:
    """``sum c_j a_j/(a_j^2 + im2)`` and ``sum c_j/(a_j^2 + im2)`` with ``a_j = a0_j + re``, in MPFR.

    ``a0`` and ``c`` are lists of ``mpfr`` (:func:`to_mpfr`).  Each addition, product and quotient is rounded to
    nearest at ``mpmath.mp.prec`` bits, as the same loop in mpmath arithmetic rounds it: the sums are mpmath's to
    the bit (tests/asymptotics/test_wiener_hopf.py), about ten times faster.
    """
    with gmpy2.context(precision=mpmath.mp.prec):
        r, i2 = to_mpfr(re), to_mpfr(im2)
        sr = si = gmpy2.mpfr(0)
        for x, w in zip(a0, c):
            a = x + r
            d = w / (a * a + i2)
            sr += d * a
            si += d
    return to_mpf(sr), to_mpf(si)
