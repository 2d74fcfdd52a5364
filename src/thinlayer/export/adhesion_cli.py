"""``thinlayer solve --work-of-adhesion W``: the adhesive (JKR) answer of :func:`thinlayer.solve` as text or JSON.

One line per quantity, each with its estimate; the force as a magnitude with the words "tensile (pulling)" or
"compressive (pushing)"; the branch and the control; the model and why.  ``--pull-off`` adds the pull-off force
and radius under load and displacement control and the jump-in radii (the direct JKR curve: tens of direct
solves).  One value per command (no sweep); bad values exit 2 with one line.
"""
from __future__ import annotations

import argparse
import json
import sys
from typing import Any

__all__ = ["add_adhesion_args", "adhesive_fit_text", "adhesive_lines", "cmd_solve_adhesive"]


def add_adhesion_args(s: argparse.ArgumentParser, number: Any) -> None:
    """The adhesion options of ``thinlayer solve``."""
    s.add_argument("--work-of-adhesion", type=number, default=None, metavar="W",
                   help="work of adhesion w >= 0: JKR adhesion (paraboloid or flat punch; --delta0 and --force may "
                        "then be negative, force compressive positive)")
    s.add_argument("--branch", choices=("stable", "unstable"), default="stable",
                   help="with --work-of-adhesion: the stable (default) or unstable state of the JKR curve")
    s.add_argument("--pull-off", action="store_true",
                   help="with --work-of-adhesion: also the pull-off force under load and displacement control and "
                        "jump-in (the answering model's JKR curve: the any-thickness law, or the direct curve, "
                        "tens of direct solves)")


def _pct(x: float) -> str:
    return f"± {100 * x:.2g} %"


def adhesive_lines(ans: Any, punch_line: str, base: str, given: str, pull_off: bool) -> list[str]:
    """The text of an adhesive answer, one line per quantity."""
    est = ans.error_estimate
    tf = ans.equations[0]
    words = "tensile (pulling) force" if ans.tensile else "compressive (pushing) force"
    lines = [punch_line,
             f"{base} layer, ν = {ans.nu:.6g}, H = {ans.H:.6g}, μ = {ans.mu:.6g} (E = {ans.E:.6g}), "
             f"work of adhesion w = {ans.work_of_adhesion:.6g}",
             f"  depth          δ₀ = {ans.delta0:.8g}   " + ("(given)" if given == "delta0" else _pct(est["depth"]))
             + ("   (punch above the undeformed surface)" if ans.delta0 < 0 else ""),
             f"  force         |P| = {ans.force:.8g}   {words}   " + ("(given)" if given == "force" else
                                                                      f"{_pct(est['force'])}   ({tf})"),
             f"  contact radius  c = {ans.contact_radius:.8g}   {_pct(est['contact_radius'])}",
             f"  branch: {ans.branch} ({ans.control} control)"]
    if pull_off:
        po = ans.pull_off
        lines.append(f"  pull-off force, load control          = {po.load_force:.8g} tensile, at c = "
                     f"{po.load_radius:.8g}")
        lines.append("  pull-off force, displacement control  = " + (
            "none on the sampled radii" if po.displacement_force is None else
            f"{po.displacement_force:.8g} tensile, at c = {po.displacement_radius:.8g}, δ₀ = "
            f"{po.displacement_depth:.8g}"))
        for name, val in (("displacement control (δ₀ = 0)", po.jump_in_displacement_radius),
                          ("load control (P = 0)", po.jump_in_load_radius)):
            lines.append(f"  jump-in radius, {name} = " + ("none" if val is None else f"{val:.8g}"))
    lines.append(f"model: {ans.model} ({ans.reason})")
    return lines


def cmd_solve_adhesive(args: argparse.Namespace, bad: Any, punch_text: Any) -> int:
    """``thinlayer solve`` with ``--work-of-adhesion`` (called by :func:`thinlayer.export.solve_cli.cmd_solve`,
    which passes its error class and its punch printer).
    """
    from ..contact.solve import solve
    from .cli_args import print_text, punch_from_args, punch_params, solve_layer

    fmt = "json" if args.json else args.format
    if fmt == "csv" or args.output is not None or args.latex:
        raise bad("--work-of-adhesion answers one contact as text or --json (no --format csv, --output, --latex)")
    if any(isinstance(getattr(args, k), list) for k in ("delta0", "force", "H")):
        raise bad("--work-of-adhesion answers one value: give one number to --delta0/--force and --H (no sweep)")
    if args.order != 1 or args.boundary_layer != "exact":
        raise bad("--order and --boundary-layer belong to the non-adhesive compressible model: leave them out with "
                  "--work-of-adhesion")
    layer = solve_layer(args.base, args.nu)
    punch, _ = punch_from_args(args, allow_flat=True)
    params = punch_params(args.param)
    kind_params = {} if getattr(punch, "formula_text", None) is not None else params
    given = "delta0" if args.delta0 is not None else "force"
    ans = solve(layer, punch, delta0=args.delta0, force=args.force, H=args.H, mu=args.mu, E=args.E,
                model=args.model, tol=args.tol, parameters=kind_params, work_of_adhesion=args.work_of_adhesion,
                branch=args.branch)
    if fmt in (None, "text"):
        print_text("\n".join(adhesive_lines(ans, punch_text(punch, params), args.base, given, args.pull_off)))
        return 0
    out = {**ans.as_dict(), "reason": ans.reason, "work_of_adhesion": ans.work_of_adhesion, "H": ans.H,
           "mu": ans.mu, "nu": ans.nu, "layer": args.base}
    if args.pull_off:
        po = ans.pull_off
        out["pull_off"] = {k: getattr(po, k) for k in ("load_force", "load_radius", "displacement_force",
                                                       "displacement_radius", "displacement_depth",
                                                       "jump_in_displacement_radius", "jump_in_load_radius",
                                                       "source")}
    sys.stdout.write(json.dumps(out, indent=2, allow_nan=False) + "\n")
    return 0


def adhesive_fit_text(args: argparse.Namespace, punch: Any, delta: Any, force: Any) -> str:
    """``thinlayer fit --work-of-adhesion free``: E and w of an adhesive curve, as text or JSON (``--json``)."""
    from ..contact.fit import fit

    res = fit(delta, force, punch=punch, H=args.H, nu=args.nu, base=args.base, fit_H=args.fit_H,
              fit_offset=args.fit_offset, model=args.model, depth_sign=args.depth_sign,
              work_of_adhesion=args.work_of_adhesion)
    if args.json:
        return json.dumps({"file": str(args.csv), **res.as_dict(), "base": args.base,
                           "H": None if args.H is None or args.H == float("inf") else args.H}, indent=2,
                          allow_nan=False)
    R = getattr(punch, "sphere_radius", punch)
    return "\n".join([f"fit of E and the work of adhesion w by the {res.model} JKR model: the sphere R = {R:.6g} on "
                      f"a {args.base} layer, ν = {res.nu:.6g}; {res.points} points",
                      f"  E = {res.E:.8g} ± {res.E_error:.2g}",
                      f"  w = {res.work_of_adhesion:.8g} ± {res.work_of_adhesion_error:.2g}",
                      f"  rms force residual {res.residual_rms:.3g}"])
