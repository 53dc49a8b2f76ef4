"""Every ```python block of docs/python.md and of the README runs as written."""

import re

import pytest

from conftest import SOURCE_DIR

DOC = (SOURCE_DIR / "docs/python.md").read_text()
BLOCKS = re.findall(r"```python\n(.*?)```", DOC, flags=re.S)
README_BLOCKS = re.findall(r"```python\n(.*?)```", (SOURCE_DIR / "README.md").read_text(), flags=re.S)


def test_the_page_has_examples():
    assert len(BLOCKS) >= 4


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_example_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(BLOCKS[index], f"docs/python.md example {index + 1}", "exec"), {})


def test_the_readme_has_an_example():
    assert len(README_BLOCKS) >= 1


@pytest.mark.parametrize("index", range(len(README_BLOCKS)))
def test_readme_example_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(README_BLOCKS[index], f"README.md example {index + 1}", "exec"), {})
