"""Shared fixtures of the rmfx module's tests: where the sources and the rmfx command are.

ctest runs them with PYTHONPATH=build/python, RMFX_BINARY=build/rmfx and RMFX_SOURCE_DIR set
(python/CMakeLists.txt); run by hand, the defaults find the default preset's build."""
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("RMFX_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
RMFX_BINARY = pathlib.Path(os.environ.get("RMFX_BINARY", SOURCE_DIR / "build" / "rmfx"))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def rmfx_binary():
    if not RMFX_BINARY.exists():
        pytest.fail(f"{RMFX_BINARY} is missing: build the rmfx target (or set RMFX_BINARY)")
    return RMFX_BINARY
