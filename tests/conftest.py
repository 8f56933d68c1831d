"""Shared fixtures: the reference mechanisms and every bundled example."""

from __future__ import annotations

from pathlib import Path

import pytest

import assur

DATA = Path(__file__).parent / "data"
EXAMPLES = Path(__file__).parent.parent / "examples"


def example_files() -> list[Path]:
    """Every mechanism file bundled in examples/."""
    return sorted(EXAMPLES.glob("*.toml"))


@pytest.fixture(params=example_files(), ids=lambda p: p.stem)
def example(request: pytest.FixtureRequest) -> assur.Mechanism:
    """Each bundled example mechanism."""
    return assur.load(request.param)


@pytest.fixture
def data_dir() -> Path:
    return DATA
