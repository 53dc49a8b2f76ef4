"""The type stub editors read (obscura/__init__.pyi) names what the module exports, and every
exported function and class carries a docstring."""

import ast

import obscura
from conftest import SOURCE_DIR


def stub_names():
    tree = ast.parse((SOURCE_DIR / "python/obscura/__init__.pyi").read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return names


def test_the_stub_covers_the_module():
    assert set(obscura.__all__) <= stub_names()


def test_everything_has_a_docstring():
    for name in obscura.__all__:
        item = getattr(obscura, name)
        assert item.__doc__ and item.__doc__.strip(), name
        if isinstance(item, type) and item.__module__.startswith("obscura"):
            for member, value in vars(item).items():
                if not member.startswith("_") and callable(value):
                    assert getattr(item, member).__doc__, f"{name}.{member}"
