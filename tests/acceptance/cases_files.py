"""Acceptance inputs of issue 23, items 2 and 6: links planted where thinlayer writes, runs killed on the way,
units and long strings in reports.

Each input's outcome is decided by an independent check (see :mod:`acceptance`): the bytes of a sentinel
file outside the output folder and the list of files there (``"loss"`` if either changed), the exit code and
the lines on stderr (``"crash"`` unless a one-line refusal with exit 2 or a success), the earlier report's
bytes after a killed run, and for typesetting the LaTeX written out by hand, pdflatex's errors and its
overfull boxes (``"wrong"`` for a double superscript, a failed compile or a line off the page).
"""
from __future__ import annotations

import shutil
import signal
from pathlib import Path

CATEGORIES = ("data loss (symlinks, killed runs)", "typesetting (units, long strings)")
_LOSS, _TYPE = CATEGORIES

#: unit -> its LaTeX and its square, written by hand
UNITS = {
    "m": (r"\mathrm{m}", r"\mathrm{m}^{2}"), "mm": (r"\mathrm{mm}", r"\mathrm{mm}^{2}"),
    "um": (r"\mu\mathrm{m}", r"{\mu\mathrm{m}}^{2}"), "\u00b5m": (r"\mu\mathrm{m}", r"{\mu\mathrm{m}}^{2}"),
    "nm": (r"\mathrm{nm}", r"\mathrm{nm}^{2}"), "N": (r"\mathrm{N}", r"\mathrm{N}^{2}"),
    "mN": (r"\mathrm{mN}", r"\mathrm{mN}^{2}"), "\u00b5N": (r"\mu\mathrm{N}", r"{\mu\mathrm{N}}^{2}"),
    "nN": (r"\mathrm{nN}", r"\mathrm{nN}^{2}"), "Pa": (r"\mathrm{Pa}", r"\mathrm{Pa}^{2}"),
    "kPa": (r"\mathrm{kPa}", r"\mathrm{kPa}^{2}"), "MPa": (r"\mathrm{MPa}", r"\mathrm{MPa}^{2}"),
    "GPa": (r"\mathrm{GPa}", r"\mathrm{GPa}^{2}"), "m^2": (r"\mathrm{m}^{2}", r"\mathrm{m}^{4}"),
    "N/m^2": (r"\mathrm{N}/\mathrm{m}^{2}", r"\mathrm{N}^{2}/\mathrm{m}^{4}"),
    "N/mm^2": (r"\mathrm{N}/\mathrm{mm}^{2}", r"\mathrm{N}^{2}/\mathrm{mm}^{4}"),
    "kg m/s^2": (r"\mathrm{kg}\,\mathrm{m}/\mathrm{s}^{2}", r"\mathrm{kg}^{2}\,\mathrm{m}^{2}/\mathrm{s}^{4}"),
    "kg/(m*s^2)": (r"\mathrm{kg}/(\mathrm{m}\,\mathrm{s}^{2})", r"\mathrm{kg}^{2}/(\mathrm{m}^{2}\,\mathrm{s}^{4})"),
    "N.m^-2": (r"\mathrm{N}/\mathrm{m}^{2}", r"\mathrm{N}^{2}/\mathrm{m}^{4}"),
    "s^-1": (r"\mathrm{s}^{-1}", r"\mathrm{s}^{-2}"),
}
#: [units] tables the schema accepts (one consistent system each)
SYSTEMS = [("mm", "MPa", "N"), ("um", "kPa", "nN"), ("nm", "GPa", "nN"), ("m", "Pa", "N"), ("mm", "N/mm^2", "N"),
           ("m", "kg/(m*s^2)", "kg m/s^2"), ("um", "MPa", "\u00b5N")]
#: [units] entries the schema refuses: (key, value)
REFUSED_UNITS = [("length", "m^2^2"), ("length", "m^2"), ("stress", "N/m/s"), ("force", "\\\\input{x}"),
                 ("length", "mm^10"), ("length", "inch"), ("stress", "Mpa"), ("force", "m/m"), ("length", "2 m"),
                 ("length", "m**2"), ("force", "__import__('os')"), ("length", "(m"), ("length", "m" * 41),
                 ("stress", "N"), ("force", "mm"), ("length", "m\u00b2")]
INCONSISTENT = [("m", "MPa", "N"), ("mm", "Pa", "N"), ("um", "MPa", "mN")]


def run(t, tmp: Path) -> None:
    """Try every input of the two categories and record each outcome in ``t``."""
    import sys

    here = str(Path(__file__).resolve().parents[1])
    if here not in sys.path:
        sys.path.insert(0, here)
    _links(t, tmp / "links")
    _killed(t, tmp / "killed")
    _units(t, tmp / "units")
    _long_strings(t, tmp / "long")


def _guard(t, category: str, what: str, fn) -> None:
    """Run one input; an exception the check did not expect is a crash of the input."""
    try:
        fn()
    except Exception as exc:  # noqa: BLE001 - recorded as the input's outcome
        t.add(category, "crash", f"{what}: {type(exc).__name__}: {str(exc)[:200]}")


#: a refusal takes less than this (wall seconds; the acceptance contract's hang)
HANG = 10.0


def _record_attack(t, what: str, res, refused_expected: bool | None) -> None:
    ok, why = res.safe(refused_expected)
    if res.outside_changed:
        t.add(_LOSS, "loss", f"{what}: {why}")
    elif not ok:
        t.add(_LOSS, "crash", f"{what}: {why}")
    elif refused_expected and res.seconds > HANG:  # a refusal comes before the work
        t.add(_LOSS, "hang", f"{what}: refused after {res.seconds:.1f} s")
    else:
        t.add(_LOSS, "clear")


def _links(t, work: Path) -> None:
    from planting import WRITERS, attack, quick_validation

    with quick_validation():
        k = 0
        for writer in WRITERS:
            for rel in writer.files:  # each location, without --overwrite: refused in one line
                for kind in ("link", "dangling"):
                    k += 1
                    what = f"{writer.name}: {kind} at {rel}"
                    _guard(t, _LOSS, what, lambda w=writer, r=rel, kd=kind, n=k, s=what: _record_attack(
                        t, s, attack(w, [r], kd, False, work / f"a{n}"), True))
            for kind in ("link", "dangling"):  # with --overwrite: every location at once, the links replaced
                k += 1
                what = f"{writer.name}: {kind} at all {len(writer.files)} files, --overwrite"
                _guard(t, _LOSS, what, lambda w=writer, kd=kind, n=k, s=what: _record_attack(
                    t, s, attack(w, list(w.files), kd, True, work / f"a{n}"), False))
            if writer.lock:
                for kind in ("link", "dangling"):
                    for overwrite in (False, True):
                        k += 1
                        what = f"{writer.name}: {kind} at {writer.lock}, overwrite={overwrite}"
                        _guard(t, _LOSS, what, lambda w=writer, kd=kind, o=overwrite, n=k, s=what: _record_attack(
                            t, s, attack(w, [w.lock], kd, o, work / f"a{n}"), True))
            if writer.folder:
                for kind in ("dir", "dangling"):
                    for overwrite in (False, True):
                        k += 1
                        what = f"{writer.name}: {kind} link at {writer.folder}/, overwrite={overwrite}"
                        _guard(t, _LOSS, what, lambda w=writer, kd=kind, o=overwrite, n=k, s=what: _record_attack(
                            t, s, attack(w, [w.folder], kd, o, work / f"a{n}"), True))
        _guard(t, _LOSS, "hard link at the lock", lambda: _hard_link(t, work / "hard"))


def _hard_link(t, work: Path) -> None:
    import os

    from planting import Outside, derivation_file, one_line, run_cli

    outside = Outside(work / "outside")
    out = work / "out"
    out.mkdir(parents=True)
    os.link(outside.sentinel, out / ".inj.lock")
    code, err = run_cli(["report", str(derivation_file(work)), "--out", str(out), "--overwrite"])
    if outside.changed():
        t.add(_LOSS, "loss", f"hard link at the lock: {outside.changed()}")
    else:
        t.add(_LOSS, "clear" if code == 2 and one_line(err) else "crash", f"hard link at the lock: exit {code} {err}")


def _killed(t, work: Path) -> None:
    from planting import killed_run

    for stage in ("compile", "tex"):
        for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGKILL):
            during = "the PDF compiles" if stage == "compile" else "the .tex is written"
            what = f"{signal.Signals(sig).name} while {during}"

            def one(stage=stage, sig=sig, what=what) -> None:
                k = killed_run(work / f"{stage}-{int(sig)}", stage, sig)
                problems = k.problems()
                if k.after != k.before:
                    t.add(_LOSS, "loss", f"{what}: {problems}")
                elif problems:
                    t.add(_LOSS, "crash", f"{what}: {problems}")
                elif k.stop_seconds > HANG:  # the signal ends the run at once
                    t.add(_LOSS, "hang", f"{what}: the run ended {k.stop_seconds:.1f} s after the signal")
                else:
                    t.add(_LOSS, "clear")
            _guard(t, _LOSS, what, one)


def _units(t, work: Path) -> None:
    import re

    from planting import one_line, run_cli

    from thinlayer.export.units import parse_unit

    work.mkdir(parents=True, exist_ok=True)
    base = ("[derivation]\nname='u'\n[layer]\nnu='3/10'\n[punch]\nkind='paraboloid'\n"
            "[contact]\ndelta0=0.1\nH=0.01\nE=2.6\nparameters={R=4}\n")
    # each form the grammar accepts: its LaTeX and its square as written by hand; all of them compiled at once
    compiled = _compile_units(work)
    for text, (first, squared) in UNITS.items():
        def one(text=text, first=first, squared=squared) -> None:
            u = parse_unit(text)
            got = (u.latex(), u.latex(2))
            stacked = any(re.search(r"\^\{-?[0-9]+\}\^", u.latex(n)) for n in (1, 2, 3))
            if got != (first, squared) or stacked:
                t.add(_TYPE, "wrong", f"unit {text!r}: {got}, expected {(first, squared)}")
            elif compiled is not None and compiled != "":
                t.add(_TYPE, "wrong", f"unit {text!r}: the document of every unit did not compile cleanly: {compiled}")
            else:
                t.add(_TYPE, "clear")
        _guard(t, _TYPE, f"unit {text!r}", one)
    # whole [units] tables through the command line: the consistent ones are accepted, the rest refused
    for k, (length, stress, force) in enumerate(SYSTEMS + INCONSISTENT):
        def table(k=k, length=length, stress=stress, force=force) -> None:
            f = work / f"s{k}.toml"
            f.write_text(base + f'[units]\nlength="{length}"\nstress="{stress}"\nforce="{force}"\n')
            code, err = run_cli(["report", str(f), "--out", str(work / f"so{k}"), "--quiet"])
            good = (length, stress, force) in SYSTEMS
            ok = code == 0 if good else (code == 2 and one_line(err) and "inconsistent" in err)
            t.add(_TYPE, "clear" if ok else "crash", f"[units] {length}, {stress}, {force}: exit {code} {err[:200]}")
        _guard(t, _TYPE, f"[units] {length}, {stress}, {force}", table)
    for k, (key, value) in enumerate(REFUSED_UNITS):
        def refused(k=k, key=key, value=value) -> None:
            units = {"length": "mm", "stress": "MPa", "force": "N", key: value}
            f = work / f"r{k}.toml"
            f.write_text(base + "[units]\n" + "".join(f'{a}="{b}"\n' for a, b in units.items()))
            code, err = run_cli(["report", str(f), "--out", str(work / f"ro{k}")])
            ok = code == 2 and one_line(err) and f"[units] {key} = " in err and str(f) in err
            t.add(_TYPE, "clear" if ok else "crash", f"[units] {key} = {value!r}: exit {code} {err[:200]}")
        _guard(t, _TYPE, f"[units] {key} = {value!r}", refused)


def _compile_units(work: Path) -> str | None:
    """Every unit of :data:`UNITS` to the powers 1, 2, 3, -1 in one document: "" if it compiles without an
    error or an overfull box, the reason if not, None without pdflatex."""
    if shutil.which("pdflatex") is None:
        return None
    from thinlayer.export.latex_files import build_pdf, overfull_boxes
    from thinlayer.export.report import Document
    from thinlayer.export.units import parse_unit

    doc = Document("Units")
    doc.section("Units").lines([rf"1.5\,{parse_unit(u).latex()},\quad 2.25\,{parse_unit(u).latex(2)},\quad "
                                rf"3.4\,{parse_unit(u).latex(3)},\quad 0.6\,{parse_unit(u).latex(-1)}" for u in UNITS])
    try:
        _, log = build_pdf(doc.latex(), "units", work)
    except RuntimeError as exc:
        return str(exc)
    return "; ".join(overfull_boxes(log))


TITLES = {"200 x W": "W" * 200, "200 x Omega": "\u03a9" * 200, "200 backslashes": "\\" * 200,
          "specials": "%$#&{}~^_" * 22, "200 x E acute": "\u00c9" * 200, "three 60-letter words": ("M" * 60 + " ") * 3}


def _long_strings(t, work: Path) -> None:
    work.mkdir(parents=True, exist_ok=True)
    have_tex = shutil.which("pdflatex") is not None
    from thinlayer.export.latex_files import build_pdf, overfull_boxes
    from thinlayer.export.report import Document

    for k, (what, title) in enumerate(TITLES.items()):
        def one(k=k, what=what, title=title) -> None:
            doc = Document(title.strip())
            doc.section("Text").text("A paragraph.")
            if not have_tex:
                t.add(_TYPE, "clear" if r"\allowbreak{}" in doc.latex() else "wrong", f"title {what}: no break point")
                return
            try:
                _, log = build_pdf(doc.latex(), f"t{k}", work)
            except RuntimeError as exc:
                t.add(_TYPE, "wrong", f"title {what}: {exc}")
                return
            over = overfull_boxes(log)
            t.add(_TYPE, "wrong" if over else "clear", f"title {what}: {over[:2]}")
        _guard(t, _TYPE, f"title {what}", one)
    _guard(t, _TYPE, "longest names in a report", lambda: _long_report(t, work, have_tex))


def _long_report(t, work: Path, have_tex: bool) -> None:
    from thinlayer.export.derivation import load_derivation, write_report
    from thinlayer.export.latex_files import overfull_boxes

    n1, n2 = "R" + "a" * 63, "S" + "b" * 63
    f = work / "long.toml"
    f.write_text(f'[derivation]\nname = "{"n" * 100}"\ntitle = "{"W" * 200}"\n[layer]\nnu = "3/10"\n'
                 f'[punch]\nexpr = "(x_1**2 + x_2**2)/(2*{n1}) + x_1**4/{n2}"\n'
                 f"[contact]\ndelta0 = 0.1\nH = 0.01\nE = 2.6\nparameters = {{{n1} = 4, {n2} = 100}}\n"
                 '[units]\nlength = "um"\nstress = "kPa"\nforce = "nN"\n')
    tex = write_report(load_derivation(f), work / "out", pdf=have_tex)
    text = tex.read_text()
    if rf"{n2} = 100\,{{\mu\mathrm{{m}}}}^{{3}}" not in text or r"{\mu\mathrm{m}}^{2} \pm" not in text:
        t.add(_TYPE, "wrong", "longest names: the units of S (a length cubed) or of the area are wrong")
        return
    over = overfull_boxes(tex.with_suffix(".log").read_text()) if have_tex else []
    t.add(_TYPE, "wrong" if over else "clear", f"longest names: {over[:2]}")
