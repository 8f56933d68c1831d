"""Shared fixtures: the reference mechanisms and every bundled example."""

from __future__ import annotations

import contextlib
import signal
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

import assur

DATA = Path(__file__).parent / "data"
EXAMPLES = Path(__file__).parent.parent / "examples"

if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    # started in the background by a shell without job control (`cmd &`), the
    # tests inherit Ctrl-C ignored, and so would every command they start: the
    # tests of Ctrl-C need Python's own handler, which a child then gets too
    signal.signal(signal.SIGINT, signal.default_int_handler)


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


def load_example(name: str) -> assur.Mechanism:
    """The bundled example ``examples/<name>.toml``."""
    return assur.load(EXAMPLES / f"{name}.toml")


def run_cli(capsys: pytest.CaptureFixture[str], *args: Any) -> tuple[int, str, str]:
    """Run ``assur ARGS`` (paths and numbers as text); return status, out and err."""
    from assur.cli import main

    status = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


def file_names(folder: Path) -> set[str]:
    """The names of what ``folder`` holds."""
    return {p.name for p in folder.iterdir()}


@pytest.fixture
def double_rocker(tmp_path: Path) -> Path:
    """A four-bar whose input link cannot turn fully, saved in ``tmp_path``.

    It assembles from about 17.3 to 81.1 degrees (the reference pose's circuit) and
    from 278.9 to 342.7 (another circuit, which the mechanism cannot reach from its
    reference pose), with dead centres at the ends of both ranges.
    """
    mech = assur.catalog.four_bar(
        crank=0.1, coupler=0.05, rocker=0.08, frame=0.1, angle=60.0
    )
    path = tmp_path / "double_rocker.toml"
    assur.save(mech, path)
    return path


@contextlib.contextmanager
def local_client(
    workers: int = 1, processes: bool = False, threads: int = 1
) -> Iterator[Any]:
    """A dask.distributed client of a local cluster, closed on leaving.

    The dashboard on a free port: the HTTP server starts even without one, and its
    default port taken (another cluster) was a warning, an error here.
    """
    distributed = pytest.importorskip("distributed")
    with (
        distributed.LocalCluster(
            n_workers=workers,
            processes=processes,
            threads_per_worker=threads,
            dashboard_address=":0",
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        yield client
