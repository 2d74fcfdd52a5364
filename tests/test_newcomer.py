"""What a newcomer hits first (issue 28 item 8): the README's shipped list, the notebooks' numbers, the first
command's output folder, and running the first command twice."""
from __future__ import annotations

import re
import shlex
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()


def _first_command() -> str:
    """The README's first shell line, e.g. ``python3 -m pip install -e . && thinlayer report ...``."""
    block = re.search(r"^```bash\n(.*?)^```", README, flags=re.S | re.M).group(1)
    return block.splitlines()[0]


def test_shipped_list_is_the_derivations_folder():
    text = README.split("Shipped", 1)[1].split("\n\n", 2)
    listed = re.findall(r"^- `([\w-]+\.toml)`", text[1], flags=re.M)
    assert sorted(listed) == sorted(p.name for p in (ROOT / "derivations").glob("*.toml")), listed
    # issue 28 item 8 named seven files; issue 24 added cone.toml and sphere_exact.toml: the list is the folder's
    assert len(listed) == len(set(listed)) == len(list((ROOT / "derivations").glob("*.toml"))) >= 9


def test_notebooks_numbered_without_gaps():
    numbers = sorted(int(p.name[:2]) for p in (ROOT / "notebooks").glob("*.ipynb"))
    assert numbers == list(range(len(numbers))), numbers
    for name in re.findall(r"`(\d\d_\w+)`", README):  # every notebook the README names exists
        assert (ROOT / "notebooks" / f"{name}.ipynb").is_file(), name


def test_first_command_writes_outside_build_and_git_ignores_it():
    argv = shlex.split(_first_command().split("&&")[-1])
    out = argv[argv.index("--out") + 1]
    assert out != "build" and not out.startswith("build/")  # pip wheel's build/ folder
    assert f"{out}/" in (ROOT / ".gitignore").read_text().splitlines()
    assert f"`{out}/elliptic_paraboloid.tex`" in README


@pytest.mark.xdist_group("catalogue-reports")
def test_first_command_runs_twice(tmp_path, monkeypatch, capsys):
    """The first command's thinlayer part, twice in the same folder, as written (it holds --overwrite); without
    --overwrite the second run is refused in one line that names the option."""
    from thinlayer.export.cli import main

    monkeypatch.chdir(tmp_path)
    argv = shlex.split(_first_command().split("&&")[-1])
    assert argv[0] == "thinlayer" and "--overwrite" in argv
    argv = argv[1:]
    if shutil.which("pdflatex") is None:
        argv.remove("--pdf")
    for _ in range(2):
        assert main(argv) == 0, capsys.readouterr().err
        assert "wrote" in capsys.readouterr().out
    assert (tmp_path / "thinlayer-out" / "elliptic_paraboloid.tex").is_file()
    if "--pdf" in argv:
        stamp = (tmp_path / "thinlayer-out" / "elliptic_paraboloid.pdf").stat().st_mtime_ns
        argv.remove("--overwrite")
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert len(err.strip().splitlines()) == 1 and "--overwrite" in err
        assert (tmp_path / "thinlayer-out" / "elliptic_paraboloid.pdf").stat().st_mtime_ns == stamp
