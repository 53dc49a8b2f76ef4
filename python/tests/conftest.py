"""Shared fixtures: the CLI built beside the module, the source tree, and scratch folders."""

import os
import pathlib
import shutil
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("OBSCURA_SOURCE_DIR", pathlib.Path(__file__).parents[2]))


def cli_path():
    """The obscura CLI of the same build (CTest passes it), else one on PATH."""
    return os.environ.get("OBSCURA_CLI") or shutil.which("obscura")


@pytest.fixture
def cli():
    path = cli_path()
    if not path:
        pytest.skip("the obscura CLI is not available (run through ctest)")

    def run(*args, check=True):
        return subprocess.run([path, *map(str, args)], capture_output=True, text=True,
                              check=check, timeout=300)

    return run


@pytest.fixture
def source_dir():
    return SOURCE_DIR
