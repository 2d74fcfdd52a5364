"""Notebooks are tests: every notebook in ``notebooks/`` runs top to bottom in a Jupyter kernel.

The notebooks are plain user notebooks at full size: no environment variable, no switch for the tests.
The default test run executes each one at small sizes (fewer Poisson ratios, thicknesses and grid points;
the same story and the same assertions) by substituting the constants listed in :data:`SMALL` in the code
text before execution; each substitution must match exactly one line, so a renamed constant fails the test
instead of silently running the full size.  The full-size run is marked ``slow`` and runs only with
``THINLAYER_SLOW=1`` (see ``conftest.py``).

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
#: the small run: (line start at full size, its small-size replacement) per notebook
SMALL = {
    "00_solve": [("nus = [0.3, 0.45, 0.49, 0.499, 0.5]", "nus = [0.3, 0.49, 0.5]"),
                 ("ratios = [0.005, 0.02, 0.05, 0.2, 0.5]", "ratios = [0.005, 0.05]")],
    "01_layer_kernel": [("u = np.linspace(1e-6, 4, 800)", "u = np.linspace(1e-6, 4, 200)"),
                        ("ORDER = 60", "ORDER = 24"), ("TOL = 0.005", "TOL = 0.05"),
                        ("nu_scan = np.linspace(-0.95, 0.48, 40)", "nu_scan = np.linspace(-0.95, 0.48, 12)")],
    "02_moment_expansion": [("LAMS = [4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128]", "LAMS = [8, 16, 32, 64]")],
    "03_inner_expansion": [("GRID = 400", "GRID = 120")],
    "04_boundary_layer": [("t = np.linspace(0.02, 6, 400)", "t = np.linspace(0.02, 6, 120)"),
                          ("nus = np.linspace(-0.95, 0.48, 40)", "nus = np.linspace(-0.95, 0.48, 10)"),
                          ("n = 300", "n = 100")],
    "05_validation": [("RATIOS = [10, 20, 30, 60, 120]", "RATIOS = [10, 20, 40]"),
                      ("grids = [256, 384]", "grids = [256]")],
    "06_exporting": [("n_points = 5000", "n_points = 200")],
    "07_flat_punch": [("NUS = (0.0, 0.3, 0.45, 0.5)", "NUS = (0.3, 0.5)"), ("N_EXACT = 25", "N_EXACT = 7")],
    "08_fitting": [("THICKNESS = [20.0, 10.0, 4.0, 2.0, 1.0]", "THICKNESS = [10.0, 1.5]"),
                   ("N_POINTS = 30", "N_POINTS = 5"),
                   ("chis = np.geomspace(0.05, 10.0, 14)", "chis = np.geomspace(0.05, 3.0, 5)")],
    "09_afm_tips": [("RATIOS = [0.1, 0.2, 0.5, 1.0, 2.0, 5.0]", "RATIOS = [0.2, 5.0]"),
                    ("N_GRID = 160   # cells per side of the square [-1.25, 1.25]^2",
                     "N_GRID = 64   # cells per side of the square [-1.25, 1.25]^2")],
}
#: what a user's notebook never holds
PLUMBING = re.compile(r"os\.environ|getenv|THINLAYER_|pytest|\bSMALL\b")
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


def small_sizes(sources: list[str], name: str) -> list[str]:
    """The code cells' sources with the constants of :data:`SMALL` replaced; each must match exactly one line."""
    out = list(sources)
    for full, small in SMALL.get(name, []):
        pattern = re.compile(rf"^([ \t]*){re.escape(full)}(?![\w.])", re.M)
        hits = [(k, m) for k, src in enumerate(out) for m in pattern.finditer(src)]
        assert len(hits) == 1, f"{name}: the small run expects one line starting {full!r}, found {len(hits)}"
        k, m = hits[0]
        out[k] = out[k][:m.start()] + m.group(1) + small + out[k][m.end():]
    return out


def _shrink(nb, name: str):
    code = [c for c in nb.cells if c.cell_type == "code"]
    for cell, src in zip(code, small_sizes([c.source for c in code], name)):
        cell.source = src
    return nb


def _execute(nb, monkeypatch, size: str, timeout: int, name: str = "", kernel=None):
    """Run ``nb`` in a new kernel, or in ``kernel`` (a running ``(manager, client)``) after a fresh start of its
    namespace (:data:`FRESH`)."""
    _, nbclient = _need_jupyter()
    if size == "small":
        _shrink(nb, name)
    if kernel is None:
        monkeypatch.setenv("MPLBACKEND", "Agg")  # inherited by the kernel process
        client = nbclient.NotebookClient(nb, timeout=timeout, startup_timeout=120, kernel_name="python3",
                                         resources={"metadata": {"path": str(NB_DIR)}})
        client.execute()
        return nb
    km, kc = kernel
    msg = kc.execute(FRESH.format(path=str(NB_DIR)), store_history=False)
    reply = kc.get_shell_msg(timeout=60)
    while reply["parent_header"].get("msg_id") != msg:
        reply = kc.get_shell_msg(timeout=60)
    assert reply["content"]["status"] == "ok", f"resetting the shared kernel failed: {reply['content']}"
    client = nbclient.NotebookClient(nb, km=km, timeout=timeout, kernel_name="python3",
                                     resources={"metadata": {"path": str(NB_DIR)}})
    client.kc = kc
    client.execute()
    return nb


#: run in the shared kernel before each notebook: an empty namespace (``%reset -f`` drops every name, imports
#: included, so a notebook that forgets an import still fails), figures closed, matplotlib's settings restored and
#: the working directory back in ``notebooks/``.  Modules stay imported: a notebook then runs as in a new kernel,
#: minus the seconds of starting one and importing numpy, sympy, matplotlib and thinlayer again.
FRESH = """%reset -f
import os as _os, sys as _sys
if "matplotlib.pyplot" in _sys.modules:
    _sys.modules["matplotlib.pyplot"].close("all")
    _sys.modules["matplotlib"].rcdefaults()
_os.chdir({path!r})
del _os, _sys
"""


@pytest.fixture(scope="module")
def shared_kernel():
    """One ipykernel for the small runs of this module (they share this fixture, hence one xdist worker).

    The full-size runs (``THINLAYER_SLOW=1``) each start their own kernel, as a user opening the notebook would.
    """
    _need_jupyter()
    import os

    from jupyter_client.manager import KernelManager

    km = KernelManager(kernel_name="python3")
    km.start_kernel(env=dict(os.environ, MPLBACKEND="Agg"), cwd=str(NB_DIR))
    kc = km.client()
    kc.start_channels()
    try:
        kc.wait_for_ready(timeout=120)
        yield km, kc
    finally:
        kc.stop_channels()
        km.shutdown_kernel(now=True)


def test_there_are_notebooks():
    assert len(NOTEBOOKS) >= 6, f"expected the six story notebooks in {NB_DIR}, found {[p.name for p in NOTEBOOKS]}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_committed_notebook_is_stripped(path):
    dirty = [i for i, c in enumerate(_cells(path)) if c["cell_type"] == "code"
             and (c.get("outputs") or c.get("execution_count") is not None)]
    assert not dirty, (f"{path.name}: code cells {dirty} carry outputs or execution counts; strip them with "
                       f"jupyter nbconvert --clear-output --inplace notebooks/{path.name}")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_is_free_of_test_plumbing(path):
    # issue 17 item 5: the small-size switch lives here, not in the notebooks
    bad = [(i, m.group(0)) for i, c in enumerate(_cells(path)) for m in [PLUMBING.search(_source(c))] if m]
    assert not bad, f"{path.name}: cells {bad} hold test plumbing; the tests' sizes belong in tests/test_notebooks.py"


def test_plumbing_check_can_fail():
    assert PLUMBING.search('SMALL = os.environ.get("THINLAYER_NB_SMALL") == "1"')
    assert PLUMBING.search("import pytest") and not PLUMBING.search("SMALLER = 2  # a test function")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_small_sizes_match_the_notebook(path):
    code = [_source(c) for c in _cells(path) if c["cell_type"] == "code"]
    small = small_sizes(code, path.stem)
    assert len(small) == len(code) and (small != code) == bool(SMALL.get(path.stem))
    with pytest.raises(AssertionError, match="expects one line"):
        small_sizes(["ORDER = 600\nx = 1\n"], "01_layer_kernel")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_tells_a_story(path):
    cells = _cells(path)
    first = cells[0]
    assert first["cell_type"] == "markdown" and _source(first).startswith("# "), \
        f"{path.name} must open with a markdown cell whose first line is its title"
    prose = sum(c["cell_type"] == "markdown" for c in cells)
    assert prose >= 3, f"{path.name}: {prose} markdown cells; a story needs prose between the code"


@pytest.mark.parametrize("size", ["small", pytest.param("full", marks=pytest.mark.slow)])
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs(path, size, monkeypatch, shared_kernel):
    nbformat, _ = _need_jupyter()
    kernel = shared_kernel if size == "small" else None
    nb = _execute(nbformat.read(path, as_version=4), monkeypatch, size, CELL_TIMEOUT[size], path.stem, kernel)
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    errors = [o for o in outputs if o.get("output_type") == "error"]
    assert not errors, f"{path.name}: {errors[0].get('ename')}: {errors[0].get('evalue')}"
    # the kernel really ran every code cell, in order (a shared kernel goes on counting from its last notebook)
    counts = [c.execution_count for c in nb.cells if c.cell_type == "code" and _source(c).strip()]
    first = counts[0] if counts and kernel is not None else 1
    assert counts == list(range(first, first + len(counts))), f"{path.name}: execution counts {counts}"


def test_results_render_as_latex_in_jupyter(monkeypatch, shared_kernel):
    """Rich display reaches Jupyter: a result object's output has text/latex (our block) and text/plain."""
    nbformat, _ = _need_jupyter()
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("import thinlayer as tl\n"
                                          "tl.kernel_coefficients(tl.BondedLayer('3/10'), 1)"),
                nbformat.v4.new_code_cell("print(tl.Punch.paraboloid(R=1))")]
    _execute(nb, monkeypatch, "small", 120, kernel=shared_kernel)
    data = nb.cells[0].outputs[0]["data"]
    assert data["text/latex"].startswith("$$\\begin{gather*}\\mathcal{A} = \\frac{20}{49} \\tag{2.4}")
    assert "m_{1} = \\frac{1}{14} \\tag{2.20}" in data["text/latex"]
    # text/plain is the readable text (_repr_pretty_), not the dataclass's field-by-field repr (issue 17)
    assert data["text/plain"].startswith("KernelCoefficients of BondedLayer(nu=3/10), n <= 1")
    assert "layer=BondedLayer" not in data["text/plain"]
    text = nb.cells[1].outputs[0]["text"]
    assert text.startswith("Punch (paraboloid of revolution): Φ(x₁, x₂) = x₁²/2 + x₂²/2   (1.1)")

