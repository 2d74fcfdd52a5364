r"""The report's section on the validation against the direct numerics, from ``[validation]``.

A small study (:func:`thinlayer.validation.validation_study`) of the asymptotic results against the direct
numerical solution of (1.5)-(1.8): its table, and its plots when the report has a figure folder.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

from .base import DerivationFileError, polynomial_only, short

__all__ = ["KEY", "SCHEMA", "ORDER", "parse", "applies", "render", "figure_files"]

KEY = "validation"
SCHEMA = {"nu": ((list,), "a list of Poisson ratios"), "H_over_a": ((list,), "a list of H/a values"),
          "shapes": ((list,), "a list of shape names")}
ORDER = 90


def parse(vt: Any, context: Any) -> dict | None:
    """Validate ``[validation]``: a small study against the direct numerics for the report."""
    polynomial_only(KEY, vt, context)
    if vt is None:
        return None
    from ...validation import check_nus, check_ratios, check_shapes

    checks = (("nu", lambda v: list(check_nus(v, "nu")), [0.3]),
              ("H_over_a", lambda v: list(check_ratios(v, "H_over_a")), [0.1, 0.05, 0.025]),
              ("shapes", lambda v: list(check_shapes(v)), ["sphere"]))
    out = {}
    for key, check, default in checks:
        try:
            out[key] = check(vt.get(key, default))
        except (TypeError, ValueError, ArithmeticError) as exc:
            raise DerivationFileError(f"[validation] {key} = {short(vt.get(key))}: {exc}") from exc
    return out


def applies(der: Any) -> bool:
    return der.sections.get(KEY) is not None


def figure_files(der: Any, folder: Path) -> list[Path]:
    """The plot files :func:`render` writes into ``folder`` (checked before anything is written)."""
    from ...validation.plots import figure_files as files

    return list(files(folder, "validation", ("pdf",)))


def render(doc: Any, der: Any, context: Any) -> None:
    from ...validation import validation_study

    v, figure_dir = der.sections[KEY], context.figure_dir
    study = validation_study(v["nu"], v["H_over_a"], v["shapes"], progress=False)
    doc.section("Validation against the direct numerical solution").text(
        r"The asymptotic results (\texttt{thinlayer.solve}) against the direct numerical solution of the full "
        r"contact problem (1.5)--(1.8) (\texttt{thinlayer.numerics}): relative errors, their observed orders in "
        r"$H/a$, and the edge shift measured from the numerical contact radius (Table~\ref{tab:validation}).")
    doc.float_table(r"Validation: errors of the asymptotics against the direct numerics; observed orders "
                    r"against the claimed ones; the edge shift extrapolated to $H/a = 0$. The study is "
                    r"dimensionless, independent of the units of the contact solution: $\mu = 1$, the sphere "
                    r"$R = 1$, the elliptic paraboloid $R_1 = 4$, $R_2 = R = 1$, $\delta_0 = R/2$; "
                    r"$\bar P_{\rm num} = P_{\rm num}/(\mu R^2)$ is the numerical force in units of $\mu R^2$, the "
                    r"errors are relative.",
                    "{\\footnotesize\\setlength{\\tabcolsep}{3pt}\n"
                    + study.latex().replace("contact\\_area", "contact area")
                    .replace("force\\_leading", "force, leading").replace("contact area\\_leading",
                                                                          "contact area, leading")
                    .replace("force\\_second", "force, 2nd order")
                    .replace("contact area\\_second", "contact area, 2nd order") + "\n}",
                    label="tab:validation")
    if figure_dir is None:
        return
    figs, why = _figures(study, Path(figure_dir), context.force)
    if not figs:
        doc.text(rf"(Figures omitted: {why}.)")
    captions = {
        "validation_errors": r"Relative errors of the asymptotic force, contact area and pressure against the "
                             r"direct numerical solution, log--log in $H/a$; dashed: the claimed slope.",
        "validation_pressure": r"Contact pressure along a principal axis: direct numerical solution (solid) and "
                               r"composite asymptotic expansion (dashed); right: near the edge.",
        "validation_contours": r"Contact contour: numerical, and the leading contour $\Gamma_0$ moved in by "
                               r"$h^* H$ with the exact and Alexandrov's $h^*$.",
        "validation_edge_shift": r"Sphere: edge shift $(a_0 - c)/H$ from the numerics against $H/a$, with the "
                                 r"exact and Alexandrov's $h^*$ and the extrapolation to $H/a = 0$.",
    }
    for fig in figs:
        doc.figure(f"{Path(figure_dir).name}/{fig}", captions.get(Path(fig).stem, ""))


def _figures(study: Any, folder: Path, force: bool = False) -> tuple[list[str], str]:
    """The study's plots as PDF files in ``folder``, or ``([], why)`` when matplotlib is missing."""
    try:
        paths = study.plots(folder, formats=("pdf",), force=force)
    except ImportError:
        import logging

        # the install hint goes to the console (the log), never onto the page
        logging.getLogger(__name__).warning("validation figures omitted from the report: matplotlib is not "
                                            "installed; pip install 'thinlayer[plot]'")
        return [], "matplotlib is not installed"
    return [p.name for p in paths if p.suffix == ".pdf"], ""
