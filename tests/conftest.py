"""Fixtures shared by the test modules."""

from __future__ import annotations

import importlib
import os
from importlib import resources
from pathlib import Path

import pytest

import rocking

# the module (``rocking.motions.synthetic`` as an attribute is the function of that name)
synthetic = importlib.import_module("rocking.motions.synthetic")


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: a test that takes more than ~20 s on 2 cores")


@pytest.fixture(scope="session")
def records_dir() -> Path:
    """The folder of the PEER records shipped with the package."""
    with resources.as_file(resources.files("rocking.motions") / "data" / "records") as p:
        yield Path(p)


@pytest.fixture(scope="session", autouse=True)
def paper_cache(tmp_path_factory):
    """A private cache directory for the 30 seed earthquakes, for the whole session (the
    user's is left alone, and every test sees the same cache whatever the order)."""
    d = tmp_path_factory.mktemp("rocking-cache")
    old = os.environ.get("ROCKING_CACHE_DIR")
    os.environ["ROCKING_CACHE_DIR"] = str(d)
    synthetic.clear_cache()
    yield d
    synthetic.clear_cache()
    if old is None:
        del os.environ["ROCKING_CACHE_DIR"]
    else:
        os.environ["ROCKING_CACHE_DIR"] = old


@pytest.fixture(scope="session")
def paper_set(paper_cache):
    """The paper's 30 synthetic earthquakes (generated once per test session)."""
    return rocking.motions.seed_earthquakes()
