"""The Python examples of the README, python/PACKAGE.md (the package's page on the index),
docs/install.md and docs/python.md, run as written (in a scratch directory). The FreeCAD
ones run in freecadcmd (integration/tests/freecad.rs)."""

import os
import re

import pytest

import rmfsurf

DOCS = os.path.join(os.environ.get("RMFSURF_REPOSITORY",
                                   os.path.join(os.path.dirname(__file__), "..", "..")), "docs")


def blocks(name, heading=None):
    """The ```python blocks of docs/<name>, only those of the section `heading` if given."""
    with open(os.path.join(DOCS, name)) as f:
        text = f.read()
    if heading is not None:
        start = text.index(heading)
        end = text.find("\n## ", start + len(heading))
        text = text[start:end if end >= 0 else len(text)]
    return re.findall(r"```python\n(.*?)```", text, re.S)


def run(code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "<docs example>", "exec"), {"__name__": "__main__"})


def test_readme_python_example(tmp_path, monkeypatch):
    with open(os.path.join(DOCS, "..", "README.md")) as f:
        text = f.read().split("<!-- python-example -->")[1].split("\n## ")[0]
    (code,) = re.findall(r"```python\n(.*?)```", text, re.S)
    run(code, tmp_path, monkeypatch)
    assert (tmp_path / "pipe.step").stat().st_size > 0


def test_package_page_example(tmp_path, monkeypatch):
    with open(os.path.join(DOCS, "..", "python", "PACKAGE.md")) as f:
        (code,) = re.findall(r"```python\n(.*?)```", f.read(), re.S)
    run(code, tmp_path, monkeypatch)
    assert (tmp_path / "pipe.step").stat().st_size > 0


def test_install_python_example(tmp_path, monkeypatch):
    (code,) = blocks("install.md", "## Python")
    run(code, tmp_path, monkeypatch)


def test_python_md_examples(tmp_path, monkeypatch):
    found = blocks("python.md")
    assert found
    for code in found:
        run(code, tmp_path, monkeypatch)


@pytest.mark.skipif(not rmfsurf.shapes._has_wire_sweep(),
                    reason="this librmfsurf has no rmf_wire_sweep yet (the wire sweep C API)")
def test_install_build123d_example(tmp_path, monkeypatch):
    (code,) = blocks("install.md", "## build123d")
    run(code, tmp_path, monkeypatch)
    assert (tmp_path / "pipe.step").exists()
