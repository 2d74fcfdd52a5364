"""Timings of the validation study and the speed of the asymptotics at equal accuracy (issue 4).

``run()`` returns rows; nothing runs at import.  The speed rows compare
the asymptotic force (:func:`thinlayer.solve`, and the lambdified force law (1.8) alone) with the
direct solvers run at the cheapest resolution that reaches the asymptotic force's accuracy
(:func:`thinlayer.validation.speed_comparison`, sphere, nu = 0.3).
"""
from __future__ import annotations

from _timing import Row, main, timed


def run() -> list:
    from thinlayer.validation import speed_comparison, validate_elliptic, validate_sphere

    rows: list = []
    validate_sphere(0.3, (0.1,))  # warm the caches (exact boundary-layer table, force law)
    secs, st = timed(lambda: validate_sphere(0.3, (0.2, 0.1, 0.05, 0.025, 0.0125)))
    rows.append((f"validation: sphere nu=0.3, 5 H/a (slope P {st.observed_orders(('force',))[0].observed:.2f})",
                 secs, "< 5 s"))
    secs, st = timed(lambda: validate_elliptic(0.3, (0.1,)))
    rows.append((f"validation: elliptic nu=0.3 H/a=0.1 ({st.rows[0].solver.split(' (')[0]} + coarse)",
                 secs, "< 10 s"))

    for eps in (0.1, 0.05):
        sc = speed_comparison(0.3, eps, repeat=3)
        tag = f"speed H/a={eps:g}:"
        rows.append((f"{tag} solve() (force err {sc.asymptotic_error:.1e})", sc.seconds_solve, "< 0.05 s"))
        rows.append((f"{tag} force law (1.8), one call ({sc.seconds_force_law * 1e6:.2f} us)",
                     sc.seconds_force_law, "< 1e-4 s"))
        # side by side: the direct solvers at the cheapest resolution reaching the asymptotic force's accuracy
        if sc.seconds_fft2d is not None:
            star = " (coarsest: Delta = H/5)" if sc.fft2d_coarsest else ""
            rows.append(Row(f"{tag} solve() vs solve_2d n={sc.fft2d_n}{star}, same acc.", sc.seconds_solve,
                            ">= 10x", f"solve_2d n={sc.fft2d_n}", sc.seconds_fft2d))
        else:
            rows.append(Row(f"{tag} solve() vs solve_2d: no grid <= 1024^2 reaches its accuracy", float("nan"),
                            ">= 10x"))
        if sc.seconds_axisymmetric is not None:
            rows.append(Row(f"{tag} solve() vs solve_axisymmetric ({sc.axisymmetric_modes} modes), same acc.",
                            sc.seconds_solve, "", "solve_axisymmetric", sc.seconds_axisymmetric))  # no target
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
