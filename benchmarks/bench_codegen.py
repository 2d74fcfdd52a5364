"""Benchmarks of code generation (issue 5, item 3): all six languages for one result in < 5 s."""
from __future__ import annotations

from _timing import best, main, once


def run() -> list[tuple[str, float, str]]:
    from thinlayer import BondedLayer, Punch, inner_pressure, kernel_coefficients
    from thinlayer.export.codegen import LANGUAGES, generate, generate_all

    rows = []
    ip = inner_pressure(BondedLayer(), Punch.elliptic_paraboloid())  # symbolic nu, the paper's punch

    def all_languages(result):
        def f():
            codes = generate_all(result)
            assert all(codes[lang].source for lang in LANGUAGES)
        return f

    # first call: sympy's printers and code generators start cold
    rows.append(("codegen, 6 languages: inner pressure (2.26), first call", once(all_languages(ip)), "< 5 s"))
    rows.append(("codegen, 6 languages: inner pressure (2.26), symbolic nu", best(all_languages(ip)),
                 "< 5 s"))
    for lang in LANGUAGES:
        rows.append((f"  of which {lang}", best(lambda lang=lang: generate(ip, lang)), ""))

    big = inner_pressure(BondedLayer(), Punch.general(8))  # degree-8 punch: 5 terms, M_1..M_4 of nu
    rows.append(("codegen, 6 languages: inner pressure, degree-8 punch, sym. nu",
                 best(all_languages(big), 1), "< 5 s"))
    kc = kernel_coefficients(BondedLayer(), 6)
    rows.append(("codegen, 6 languages: A, m_1..m_6, M_1..M_6 of nu", best(all_languages(kc), 1), "< 5 s"))
    return rows


if __name__ == "__main__":  # pragma: no cover
    main(run)
