"""The entry types of the errata registry: :class:`Concern` (which reports carry an entry) and :class:`Erratum`."""
from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from .._checks import InputError
from ..display import latex_escape

__all__ = ["LAYERS", "PUNCHES", "Concern", "Erratum"]

#: the layers an erratum can concern (see :class:`Concern`)
LAYERS = ("compressible", "frictionless", "incompressible", "nearly incompressible")
#: the punches an erratum can concern
PUNCHES = ("smooth", "axisymmetric", "sphere", "elliptic paraboloid", "flat", "cone", "pyramid")


@dataclass(frozen=True)
class Concern:
    """What an erratum concerns: a report carries the entry when it uses one of ``equations`` (displays or
    cites it) for one of ``punches`` on one of ``layers``.

    ``equations`` are equation numbers as the reports print them (the paper's ``"2.21"``, thinlayer's own
    ``"F.1"`` or ``"T.7"``); ``punches`` names of :data:`PUNCHES` or ``"any"``; ``layers`` names of
    :data:`LAYERS` (``"compressible"``: a layer with the paper's expansion, A > 0, bonded or frictionless
    base) or ``"any"``.
    """

    equations: tuple[str, ...]
    punches: tuple[str, ...] = ("any",)
    layers: tuple[str, ...] = ("any",)

    def __post_init__(self) -> None:
        for p in self.punches:
            if p != "any" and p not in PUNCHES:
                raise InputError(f"punch {p!r}: expected 'any' or one of {PUNCHES}")
        for la in self.layers:
            if la != "any" and la not in LAYERS:
                raise InputError(f"layer {la!r}: expected 'any' or one of {LAYERS}")

    def selects(self, equations: Iterable[str], punches: Iterable[str], layers: Iterable[str]) -> bool:
        """Whether a report that uses ``equations`` for ``punches`` on ``layers`` carries the entry."""
        eqs, pun, lay = set(equations), set(punches), set(layers)
        return (bool(eqs & set(self.equations)) and ("any" in self.punches or bool(pun & set(self.punches)))
                and ("any" in self.layers or bool(lay & set(self.layers))))


@dataclass(frozen=True)
class Erratum:
    """One misprint: where it is printed, the printed and derived forms (LaTeX), evidence, and a check.

    ``source`` is the citation key (:mod:`thinlayer.references`) of the publication whose print the entry
    is about, ``where`` the table or equation of that publication the printed value is quoted from
    (``"(2.21)"``, ``"Table 1"``), and ``quoted_from`` a secondary source when the value was not read in the
    publication itself (then ``kind`` is ``"secondary"``, and the entry stays so until checked against the
    original).  ``concerns`` says which reports carry the entry.
    """

    equation: str
    quantity: str
    printed: str
    derived: str
    evidence: str
    check: Callable[[], bool] = field(compare=False, repr=False)
    kind: str = "misprint"  # "misprint", "notation", "ambiguous", "published series", "secondary"
    concerns: Concern = field(default=Concern(("",)), compare=False)
    source: str = "argatov"
    where: str = ""
    quoted_from: str = ""
    cites: tuple[str, ...] = ()

    def verify(self) -> bool:
        """Run the independent check; True when the derived form is confirmed and the print refuted."""
        return bool(self.check())

    def latex(self) -> str:
        return (rf"\textbf{{({self.equation})}} {latex_escape(self.quantity)} [{self.kind}]: printed ${self.printed}$; "
                rf"derived ${self.derived}$. {latex_escape(self.evidence)}")
