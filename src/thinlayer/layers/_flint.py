"""Optional python-flint arithmetic for the coefficient quotients of :mod:`thinlayer.layers.coefficients`.

python-flint (``pip install "thinlayer[fast]"``) is used *explicitly* here: its ``fmpq_poly`` (polynomials
over QQ) for the products of the quotient recurrences, with plain Python integers in and out, so that the
results are the same exact polynomials as those of the default pure-Python arithmetic.

Nothing here depends on sympy's ground types.  Note that sympy itself switches its ground types to python-flint
whenever python-flint is importable and ``SYMPY_GROUND_TYPES`` is unset; that made the rest of thinlayer
1.2-1.8x slower when measured, so set ``SYMPY_GROUND_TYPES=gmpy`` (with gmpy2 installed) to keep sympy on gmpy2
while these quotients still use python-flint.
"""
from __future__ import annotations

from collections.abc import Sequence

try:  # pragma: no cover - depends on the environment
    import flint as _flint_module
except ImportError:  # pragma: no cover
    _flint_module = None


def available() -> bool:
    """Whether python-flint can be imported (and has ``fmpq_poly``)."""
    return _flint_module is not None and hasattr(_flint_module, "fmpq_poly")


def version() -> str | None:
    """The installed python-flint version, or None."""
    return getattr(_flint_module, "__version__", None) if available() else None


class FlintQuotient:
    """Coefficients ``C_k`` of ``P(y)/Q(y)`` with ``Q_0 = 1``, every coefficient a polynomial over QQ.

    ``C_k = P_k - sum_{j=1}^k Q_j C_{k-j}``: ring operations only (no division), computed with
    ``flint.fmpq_poly``.  Inputs and outputs are ``(integer coefficients, lowest first; positive
    denominator)`` pairs; :meth:`extend` is incremental (a longer input continues where the last call stopped).
    """

    name = "flint"

    def __init__(self) -> None:
        if not available():
            raise ImportError("python-flint is not installed: pip install 'thinlayer[fast]' (python-flint>=0.6)")
        self._P: list = []
        self._Q: list = []
        self._C: list = []

    def extend(self, P: Sequence[tuple[list[int], int]], Q: Sequence[tuple[list[int], int]]
               ) -> list[tuple[list[int], int]]:
        """The new ``C_k`` for ``k = (previous length) .. len(P) - 1``, as (coefficients, denominator) pairs."""
        fq = _flint_module.fmpq_poly
        for co, d in P[len(self._P):]:
            self._P.append(fq(co, d))
        for co, d in Q[len(self._Q):]:
            self._Q.append(fq(co, d))
        Pl, Ql, Cl = self._P, self._Q, self._C
        start = len(Cl)
        for k in range(start, len(Pl)):
            acc = Pl[k]
            for j in range(1, k + 1):
                acc = acc - Ql[j] * Cl[k - j]
            Cl.append(acc)
        return [([int(c) for c in p.numer().coeffs()], int(p.denom())) for p in Cl[start:]]
