"""The documentation site (issue 22): it builds from a clean copy of ``docs/`` with warnings
as errors (``sphinx -W``), and what it says is the code's.

* the build: one ``sphinx-build -W --keep-going -b html`` of a copy of ``docs/`` (the
  source tree is left untouched: the generated API pages go to the copy);
* the API reference documents every name of every public package's ``__all__`` (the
  pages are generated from ``__all__``, so this checks the generator and autosummary,
  not a list kept by hand);
* the CLI reference documents every command of the click group;
* every ``rocking.x.y`` name and every ``A.name`` (``rocking.analysis``) the user guide
  mentions exists, and every ``rocking ...`` command line of its code blocks names a real
  command: the guide cannot silently drift from the code;
* the gallery (sphinx-gallery): every script of ``docs/gallery/`` ran during the build
  (an example that raises fails it: ``abort_on_example_error``) and its page shows its
  output and every figure it drew.

Sphinx is a third-party package of the ``docs`` extra: without it the build is skipped.
"""

from __future__ import annotations

import importlib
import pkgutil
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
GUIDE_PAGES = sorted((DOCS / "guide").glob("*.rst")) + [DOCS / "index.rst"]
GALLERY = sorted((DOCS / "gallery").glob("*.py"))


def _public_packages() -> dict[str, str]:
    """``PACKAGES`` of ``docs/conf.py`` (read without running the configuration)."""
    import ast

    tree = ast.parse((DOCS / "conf.py").read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "PACKAGES"
                                                for t in node.targets):
            return ast.literal_eval(node.value)
    raise AssertionError("docs/conf.py has no PACKAGES")


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """Build the site once from a copy of docs/; returns the HTML directory."""
    pytest.importorskip("sphinx", reason="sphinx is not installed (pip install -e '.[docs]')")
    pytest.importorskip("numpydoc", reason="numpydoc is not installed (the docs extra)")
    pytest.importorskip("sphinx_click", reason="sphinx-click is not installed (the docs extra)")
    pytest.importorskip("pydata_sphinx_theme", reason="the docs extra is not installed")
    pytest.importorskip("sphinx_gallery", reason="sphinx-gallery is not installed (the docs "
                        "extra)")
    tmp = tmp_path_factory.mktemp("docs")
    src = tmp / "docs"
    # no output of an earlier local build: sphinx-gallery would skip the examples whose
    # source has not changed since (it keeps their MD5 next to their output)
    shutil.copytree(DOCS, src, ignore=shutil.ignore_patterns(
        "_build", "generated", "__pycache__", "auto_examples", "sg_execution_times.rst"))
    out = tmp / "html"
    proc = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
         str(src), str(out)],
        capture_output=True, text=True, cwd=tmp, timeout=900,
        env={**__import__("os").environ, "MPLBACKEND": "Agg"})
    assert proc.returncode == 0, ("the documentation does not build with -W:\n"
                                  + proc.stderr[-6000:])
    return out


def test_site_builds_with_warnings_as_errors(site):
    for page in ("index", "cli", "changelog", "verification", "api/index",
                 "auto_examples/index",
                 "api/generated/architecture", "api/generated/cluster",
                 *(f"guide/{p.stem}" for p in GUIDE_PAGES if p.parent.name == "guide")):
        assert (site / f"{page}.html").is_file(), page


def test_every_gallery_example_ran_and_shows_its_figures(site):
    """Each script of docs/gallery/ has its page, with its captured output and one image
    per figure it drew (sphinx-gallery numbers them ``sphx_glr_<name>_NNN.png``; the
    thumbnail alone would not do), each image present in the site."""
    assert len(GALLERY) >= 4, [p.name for p in GALLERY]
    index = (site / "auto_examples" / "index.html").read_text(encoding="utf-8")
    for script in GALLERY:
        page = site / "auto_examples" / f"{script.stem}.html"
        assert page.is_file(), f"no page for gallery example {script.name}"
        assert f"{script.stem}.html" in index, f"{script.name} is not in the gallery index"
        html = page.read_text(encoding="utf-8")
        assert "sphx-glr-script-out" in html, f"{script.name}: no captured output"
        images = sorted(set(re.findall(rf"sphx_glr_{re.escape(script.stem)}_\d{{3}}\.png",
                                       html)))
        assert images, f"{script.name} produced no figure"
        for name in images:
            assert (site / "_images" / name).is_file(), f"{script.name}: {name} is missing"
        # the page shows what the script draws: as many figures as it makes
        source = script.read_text(encoding="utf-8")
        drawn = len(re.findall(r"^(?:fig|ax)\b.*=.*(?:subplots|plot\w*)\(", source, re.M))
        assert len(images) >= drawn, (script.name, images, drawn)


def test_api_reference_covers_every_public_name(site):
    text = {p.name: p.read_text(encoding="utf-8")
            for p in (site / "api" / "generated").glob("*.html")}
    for package in _public_packages():
        mod = importlib.import_module(package)
        names = [n for n in getattr(mod, "__all__", ()) if not n.startswith("_")]
        assert names, f"{package} exports nothing"
        page = text[f"{package}.html"]
        for name in names:
            # documented on its own page, or named on the package's page with a link to
            # the page of the package that documents the same object
            assert f"{package}.{name}.html" in text or f'title="{name}' in page \
                or f">{name}<" in page, f"{package}.{name} is not in the API reference"


def test_cli_reference_covers_every_command(site):
    import click

    from rocking.cli import cli

    html = (site / "cli.html").read_text(encoding="utf-8")

    def walk(group: click.Group, prefix: str):
        for name, cmd in group.commands.items():
            if getattr(cmd, "hidden", False):
                continue
            yield f"{prefix} {name}", cmd
            if isinstance(cmd, click.Group):
                yield from walk(cmd, f"{prefix} {name}")

    commands = list(walk(cli, "rocking"))
    assert len(commands) > 10
    for path, _ in commands:
        anchor = "rocking-" + "-".join(path.split()[1:])
        assert f'id="{anchor}"' in html, f"'{path}' is not in the CLI reference"


# ------------------------------------------------------------------ the guide is the code's
_DOTTED = re.compile(r"\brocking(?:\.[A-Za-z_]\w*)+")
_ANALYSIS = re.compile(r"(?<![\w.])A\.([A-Za-z_]\w*)")


@pytest.mark.parametrize("page", GUIDE_PAGES, ids=lambda p: p.stem)
def test_every_name_the_guide_mentions_exists(page):
    import rocking.analysis as A

    text = page.read_text(encoding="utf-8")
    missing = []
    for dotted in sorted(set(_DOTTED.findall(text))):
        if dotted.endswith((".toml", ".csv", ".ply", ".md", ".html")):
            continue
        try:
            pkgutil.resolve_name(dotted)
        except (ImportError, AttributeError, ValueError):
            missing.append(dotted)
    if "import rocking.analysis as A" in text:
        missing += [f"A.{n}" for n in sorted(set(_ANALYSIS.findall(text)))
                    if not hasattr(A, n)]
    assert not missing, f"{page.name} names what does not exist: {missing}"


def _guide_command_lines() -> list[tuple[str, str]]:
    """(page, line) of every ``rocking ...`` line of the guide's bash blocks (joined over
    trailing backslashes)."""
    lines = []
    for page in GUIDE_PAGES:
        text = page.read_text(encoding="utf-8")
        for m in re.finditer(r"\.\. code-block:: bash\n\n((?:   .*\n|\n)+)", text):
            block = re.sub(r"\\\n\s*", " ", m.group(1))
            lines += [(page.name, ln.strip()) for ln in block.splitlines()
                      if ln.strip().startswith("rocking ")]
    return lines


def test_guide_command_lines_name_real_commands_and_options():
    import click

    from rocking.cli import cli

    lines = _guide_command_lines()
    assert len(lines) >= 15
    for name, line in lines:
        words = line.split("#", 1)[0].replace("[", " ").replace("]", " ").split()[1:]
        cmd = cli
        while isinstance(cmd, click.Group) and words and not words[0].startswith("-"):
            if words[0] not in cmd.commands:
                if words[0].isupper() or "." in words[0] or "/" in words[0]:
                    break               # an argument (FILE, a path), not a command
                raise AssertionError(f"{name}: '{line}' names no command '{words[0]}'")
            cmd = cmd.commands[words[0]]
            words = words[1:]
        assert cmd is not cli, f"{name}: '{line}' names no command"
        ctx = click.Context(cmd, info_name=cmd.name)
        flags = {opt for p in cmd.get_params(ctx) for opt in getattr(p, "opts", [])
                 + getattr(p, "secondary_opts", [])}
        unknown = [w.split("=")[0] for w in words
                   if w.startswith("--") and w.split("=")[0] not in flags]
        assert not unknown, f"{name}: '{line}': no option {unknown} of '{cmd.name}'"
