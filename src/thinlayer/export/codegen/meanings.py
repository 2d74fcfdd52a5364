"""What each argument and output of generated code means: its quantity, its units and the paper's equation.

The header of every generated file and the docstring of the generated numpy function list the arguments with
these descriptions (:func:`describe_argument`, :func:`describe_output`).  Units are those of a consistent system
(any: mm, N and MPa, or m, N and Pa); ``1`` marks a dimensionless number.  A name without an entry (a symbol of a
user's punch or expression) is described as what it is: a parameter of the punch shape, or a symbol of the
expression.
"""
from __future__ import annotations

import re
from typing import Any

__all__ = ["ARGUMENTS", "OUTPUTS", "describe_argument", "describe_output"]

#: sympy name -> (meaning, units, equation of the paper)
ARGUMENTS: dict[str, tuple[str, str, str]] = {
    "x_1": ("surface coordinate along the first principal axis of the punch", "length", "1.1"),
    "x_2": ("surface coordinate along the second principal axis of the punch", "length", "1.1"),
    "delta_0": ("indentation depth: the rigid displacement of the punch", "length", "1.2"),
    "H": ("layer thickness", "length", "1.2"),
    "mu": ("shear modulus of the layer", "force/length^2", "1.3"),
    "nu": ("Poisson ratio of the layer, -1 < nu < 1/2", "1", "1.3"),
    "kappa": ("kappa = 3 - 4 nu, the layer parameter of the kernel", "1", "2.3"),
    "vartheta": ("vartheta = mu/(1 - nu)", "force/length^2", "2.1"),
    "R": ("radius of curvature of the punch tip, Phi = (x_1^2 + x_2^2)/(2 R)", "length", "1.1"),
    "R_1": ("principal radius of curvature of the punch along x_1, Phi = x_1^2/(2 R_1) + x_2^2/(2 R_2)", "length",
            "1.1"),
    "R_2": ("principal radius of curvature of the punch along x_2", "length", "1.1"),
    "h^*": ("edge shift h*: the contact edge lies h* H inside the leading contour Gamma_0; a number per layer, "
            "thinlayer.edge_shift_exact(nu)", "1", "3.25"),
    "r_3": ("third Wiener-Hopf constant of the layer, log Phi(p) = -h* p - m_1 p^2/2 + r_3 p^3 + ...", "1", "SO.4"),
    "m_1": ("kernel coefficient m_1 of L(s)/s = A (1 + m_1 s^2 + ...)", "1", "2.20"),
    "A": ("kernel coefficient A = lim L(s)/s", "1", "2.4"),
    "c": ("contact radius", "length", "I.9"),
    "w": ("work of adhesion (JKR)", "force/length", "J.5"),
    "r": ("distance from the punch axis", "length", "I.9"),
    "rho": ("distance from the punch axis at which the pressure is evaluated", "length", "I.9"),
    "a_over_H": ("radius of the flat punch over the layer thickness, a/H", "1", "F.1"),
    "v": ("distance from the leading contour Gamma_0 over H (inward), the edge variable", "1", "3.7"),
    "xi_1": ("scaled coordinate xi_1 = x_1/H_*", "1", "2.8"),
    "xi_2": ("scaled coordinate xi_2 = x_2/H_*", "1", "2.8"),
    "delta_0^*": ("scaled indentation depth, delta_0 = epsilon delta_0^*", "length", "1.2"),
    "H_*": ("scaled layer thickness, H = epsilon H_*", "length", "1.2"),
    "Lambda": ("large parameter Lambda = 1/epsilon", "1", "2.9"),
    "epsilon": ("small parameter of the expansion", "1", "1.2"),
}

#: output name -> (meaning, units, equation); ``m_n``, ``M_n``, ``w_n`` by pattern below
OUTPUTS: dict[str, tuple[str, str, str]] = {
    "p": ("contact pressure", "force/length^2", "2.26"),
    "pressure": ("contact pressure, zero outside the contact", "force/length^2", "I.7"),
    "force": ("force on the punch P", "force", "1.8"),
    "contact_area": ("area of the contact |omega|", "length^2", "3.25"),
    "contact_area_leading": ("leading contact area |omega_0|", "length^2", "3.25"),
    "A": ("kernel coefficient A = lim L(s)/s", "1", "2.4"),
    "kappa": ("stiffness factor kappa(a/H) of the flat punch, P = 4 mu a w_0 kappa/(1 - nu)", "1", "F.1"),
    "error_estimate": ("relative error estimate of kappa", "1", "F.16"),
    "delta0": ("indentation depth delta_0 at contact radius c", "length", "I.11"),
    "semi_axis_a": ("semi-axis of the contact ellipse along x_1", "length", "I.7"),
    "semi_axis_b": ("semi-axis of the contact ellipse along x_2", "length", "I.7"),
}

_PATTERNS = [
    (r"m_(\d+)", "kernel coefficient m_{0} of L(s)/s = A (1 + m_1 s^2 + m_2 s^4 + ...)", "1", "2.20"),
    (r"M_(\d+)", "coefficient M_{0} of s/L(s) = (1 + M_1 s^2 + ...)/A, by the recurrence", "1", "4.2"),
    (r"w_(\d+)", "weight w_{0} of Delta^{0} delta(xi) in the moment expansion of the kernel", "1", "2.22"),
]


def _format(entry: tuple[str, str, str]) -> str:
    meaning, units, eq = entry
    return f"{meaning} [{units}] ({eq})"


def describe_argument(name: str, punch_parameters: Any = ()) -> str:
    """``meaning [units] (equation)`` of an argument named ``name`` (a sympy name).

    >>> describe_argument("H")
    'layer thickness [length] (1.2)'
    >>> describe_argument("b", punch_parameters=["b"])
    'parameter b of the punch shape Phi [units of Phi] (1.1)'
    """
    if name in ARGUMENTS:
        return _format(ARGUMENTS[name])
    if name in {str(getattr(q, "name", q)) for q in punch_parameters}:
        return f"parameter {name} of the punch shape Phi [units of Phi] (1.1)"
    return "a symbol of the expression (no description known)"


#: outputs that are the result's own law: their equation is the result's (a force (1.8), (SO.9), (I.8), ...)
_MAIN = frozenset({"p", "pressure", "force", "delta0", "kappa"})


def describe_output(name: str, equation: str | None = None) -> str:
    """``meaning [units] (equation)`` of an output named ``name``, or an empty string when unknown.

    ``equation``, the result's own equation, replaces the table's for the result's main outputs (the force of
    the second-order law is (SO.9), its area (SO.10)).

    >>> describe_output("force"), describe_output("force", "SO.9")
    ('force on the punch P [force] (1.8)', 'force on the punch P [force] (SO.9)')
    >>> describe_output("m_2")
    'kernel coefficient m_2 of L(s)/s = A (1 + m_1 s^2 + m_2 s^4 + ...) [1] (2.20)'
    """
    if name in OUTPUTS:
        meaning, units, eq = OUTPUTS[name]
        if equation and name in _MAIN:
            eq = equation
        elif equation and equation.startswith("SO.") and name == "contact_area":
            eq = "SO.10"
        return _format((meaning, units, eq))
    for pat, meaning, units, eq in _PATTERNS:
        m = re.fullmatch(pat, name)
        if m:
            return _format((meaning.format(m.group(1)), units, eq))
    return ""
