"""Notebooks are tests: every notebook in ``notebooks/`` runs top to bottom in a Jupyter kernel.

Each notebook reads ``THINLAYER_NB_SMALL``: ``"1"`` picks small sizes (fewer Poisson ratios, thicknesses and
grid points; the same story and the same assertions), which is what the default test run uses.  The
full-size run is marked ``slow`` and runs only with ``THINLAYER_SLOW=1`` (see ``conftest.py``).

Notebooks are executed with nbclient and an ipykernel ``python3`` kernel, with matplotlib's Agg backend, in
``notebooks/`` as working directory; they write only to temporary directories.  The committed notebooks
must carry no outputs: ``jupyter nbconvert --clear-output --inplace notebooks/*.ipynb`` strips them.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

NB_DIR = Path(__file__).resolve().parents[1] / "notebooks"
NOTEBOOKS = sorted(NB_DIR.glob("*.ipynb"))
SWITCH = "THINLAYER_NB_SMALL"
#: per-cell limit; the slowest cell of the small run takes a few seconds
CELL_TIMEOUT = {"small": 240, "full": 900}


def _cells(path: Path) -> list[dict]:
    return json.loads(path.read_text(encoding="utf-8"))["cells"]


def _source(cell: dict) -> str:
    src = cell["source"]
    return src if isinstance(src, str) else "".join(src)


def _need_jupyter():
    """nbformat, nbclient and ipykernel: the ``test`` extra installs them."""
    for mod in ("nbformat", "nbclient", "ipykernel"):
        pytest.importorskip(mod, reason=f"{mod} is needed to execute notebooks: pip install -e '.[test]'")
    import nbclient
    import nbformat

    return nbformat, nbclient


def _execute(nb, monkeypatch, size: str, timeout: int):
    _, nbclient = _need_jupyter()
    monkeypatch.setenv(SWITCH, "1" if size == "small" else "0")
    monkeypatch.setenv("MPLBACKEND", "Agg")  # inherited by the kernel process
    client = nbclient.NotebookClient(nb, timeout=timeout, startup_timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(NB_DIR)}})
    client.execute()
    return nb


def test_there_are_notebooks():
    assert len(NOTEBOOKS) >= 6, f"expected the six story notebooks in {NB_DIR}, found {[p.name for p in NOTEBOOKS]}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_committed_notebook_is_stripped(path):
    dirty = [i for i, c in enumerate(_cells(path)) if c["cell_type"] == "code"
             and (c.get("outputs") or c.get("execution_count") is not None)]
    assert not dirty, (f"{path.name}: code cells {dirty} carry outputs or execution counts; strip them with "
                       f"jupyter nbconvert --clear-output --inplace notebooks/{path.name}")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_reads_the_small_switch_and_tells_a_story(path):
    cells = _cells(path)
    code = "\n".join(_source(c) for c in cells if c["cell_type"] == "code")
    assert re.search(rf"os\.environ\.get\(\s*[\"']{SWITCH}[\"']\s*\)", code), f"{path.name} ignores {SWITCH}"
    first = cells[0]
    assert first["cell_type"] == "markdown" and _source(first).startswith("# "), \
        f"{path.name} must open with a markdown cell whose first line is its title"
    prose = sum(c["cell_type"] == "markdown" for c in cells)
    assert prose >= 3, f"{path.name}: {prose} markdown cells; a story needs prose between the code"


@pytest.mark.parametrize("size", ["small", pytest.param("full", marks=pytest.mark.slow)])
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs(path, size, monkeypatch):
    nbformat, _ = _need_jupyter()
    nb = _execute(nbformat.read(path, as_version=4), monkeypatch, size, CELL_TIMEOUT[size])
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    errors = [o for o in outputs if o.get("output_type") == "error"]
    assert not errors, f"{path.name}: {errors[0].get('ename')}: {errors[0].get('evalue')}"
    # the kernel really ran every code cell, in order
    counts = [c.execution_count for c in nb.cells if c.cell_type == "code" and _source(c).strip()]
    assert counts == list(range(1, len(counts) + 1)), f"{path.name}: execution counts {counts}"


def test_results_render_as_latex_in_jupyter(monkeypatch):
    """Rich display reaches Jupyter: a result object's output has text/latex (our block) and text/plain."""
    nbformat, _ = _need_jupyter()
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("import thinlayer as tl\n"
                                          "tl.kernel_coefficients(tl.BondedLayer('3/10'), 1)"),
                nbformat.v4.new_code_cell("print(tl.Punch.paraboloid(R=1))")]
    _execute(nb, monkeypatch, "small", 120)
    data = nb.cells[0].outputs[0]["data"]
    assert data["text/latex"].startswith("$$\\begin{gather*}\\mathcal{A} = \\frac{20}{49} \\tag{2.4}")
    assert "m_{1} = \\frac{1}{14} \\tag{2.20}" in data["text/latex"]
    # text/plain is the readable text (_repr_pretty_), not the dataclass's field-by-field repr (issue 17)
    assert data["text/plain"].startswith("KernelCoefficients of BondedLayer(nu=3/10), n <= 1")
    assert "layer=BondedLayer" not in data["text/plain"]
    text = nb.cells[1].outputs[0]["text"]
    assert text.startswith("Punch (paraboloid of revolution): Phi(x_1, x_2) = x_1**2/2 + x_2**2/2   (1.1)")

