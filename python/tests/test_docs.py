"""The examples of docs/python.md, of the README's Python section and of the module's
docstrings are run (doctest): what they show is what the module returns."""

import doctest
import re

import pytest

import collide
from conftest import ROOT


def python_blocks(path):
    text = (ROOT / path).read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, f"{path} has no Python example"
    return "\n".join(blocks)


def run_examples(text, name):
    test = doctest.DocTestParser().get_doctest(text, {"collide": collide, **vars(collide)}, name, name, 0)
    assert test.examples, f"{name}: no examples"
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{name}: {result.failed} of {result.attempted} examples failed"


@pytest.mark.parametrize("path", ["docs/python.md", "README.md"])
def test_document_examples(path):
    run_examples(python_blocks(path), path)


@pytest.mark.parametrize("name", ["collide", "solve", "solve_many", "frames", "plot", "track", "pi", "sweep"])
def test_docstring_examples(name):
    obj = collide if name == "collide" else getattr(collide, name)
    run_examples(obj.__doc__, name)


def test_stub_examples():
    """The type stubs (collide.pyi) repeat the docstrings for editors: their examples run too."""
    import ast

    tree = ast.parse((ROOT / "python" / "collide.pyi").read_text())
    nodes = [tree] + [n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.ClassDef))]
    texts = [ast.get_docstring(n) or "" for n in nodes]
    run_examples("\n\n".join(t for t in texts if ">>>" in t), "collide.pyi")


def test_stubs_name_what_the_module_has():
    """Every public function and class of the module has its stub, and every stub a thing."""
    import ast

    tree = ast.parse((ROOT / "python" / "collide.pyi").read_text())
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {n for n in dir(collide) if not n.startswith("_") and callable(getattr(collide, n))}
    assert stubbed == public, (stubbed ^ public)
    for name in public - {"Section", "Report", "CollideError"}:
        assert getattr(collide, name).__doc__, name
