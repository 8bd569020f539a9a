"""Shared fixtures: paths given by CTest (python/CMakeLists.txt) with fall-backs for a manual run."""
import os
import pathlib

import pytest

HERE = pathlib.Path(__file__).resolve().parent
SOURCE_DIR = HERE.parent.parent


@pytest.fixture(scope="session")
def shared_data():
    import conforma

    return pathlib.Path(os.environ.get("CONFORMA_SHARED_DATA", conforma.default_shared_data))


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("CONFORMA_CLI")
    if not path or not pathlib.Path(path).exists():
        pytest.fail("CONFORMA_CLI must name the build's conforma executable (set by ctest)")
    return path
