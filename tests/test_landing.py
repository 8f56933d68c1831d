"""Files of one command land together (assur._landing): all new, or all old."""

from __future__ import annotations

import os
import signal
from pathlib import Path

import pytest

from assur import _output
from assur._landing import _held, together
from assur._output import output_path
from assur.cli import main

EXAMPLES = Path(__file__).parent.parent / "examples"


def test_files_land_only_when_the_last_is_written(tmp_path: Path) -> None:
    first, second = tmp_path / "a.txt", tmp_path / "b.txt"
    first.write_text("old a", encoding="utf-8")
    with together():
        with output_path(first) as temporary:
            temporary.write_text("new a", encoding="utf-8")
        assert first.read_text(encoding="utf-8") == "old a"  # held back for its set
        with output_path(second) as temporary:
            temporary.write_text("new b", encoding="utf-8")
        assert not second.exists()
    assert first.read_text(encoding="utf-8") == "new a"
    assert second.read_text(encoding="utf-8") == "new b"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "b.txt"]


def test_a_failure_in_the_set_lands_none(tmp_path: Path) -> None:
    first, second = tmp_path / "a.txt", tmp_path / "b.txt"
    first.write_text("old a", encoding="utf-8")

    def written() -> None:
        with together():
            with output_path(first) as temporary:
                temporary.write_text("new a", encoding="utf-8")
            with output_path(second) as temporary:
                temporary.write_text("half of b", encoding="utf-8")
                raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        written()
    assert first.read_text(encoding="utf-8") == "old a"
    assert [p.name for p in tmp_path.iterdir()] == ["a.txt"]  # no temporary left


def test_signals_wait_till_the_files_have_landed() -> None:
    landed = []

    def landing() -> None:
        with _held():
            os.kill(os.getpid(), signal.SIGINT)  # to the process, as Ctrl-C is
            landed.append(True)  # the interrupt came, and waits

    with pytest.raises(KeyboardInterrupt):
        landing()
    assert landed
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_an_interrupt_as_the_csv_is_synced_lands_no_parquet(
    tmp_path: Path, monkeypatch, capsys
) -> None:
    pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed")
    # the Parquet file had replaced its old one while the CSV was still being
    # flushed to the disk: Ctrl-C there left a new Parquet beside an old CSV
    csv, parquet = tmp_path / "t.csv", tmp_path / "t.parquet"
    csv.write_text("old csv", encoding="utf-8")
    parquet.write_bytes(b"old parquet")
    synced = _output._sync

    def interrupted(path: Path) -> None:
        if path.suffix == ".csv":
            raise KeyboardInterrupt
        synced(path)

    monkeypatch.setattr(_output, "_sync", interrupted)
    path = EXAMPLES / "slider_crank_exercise.toml"
    argv = ["forces", str(path), "--csv", str(csv), "--parquet", str(parquet)]
    assert main(argv) == 130
    assert capsys.readouterr().err == "assur: interrupted\n"
    assert csv.read_text(encoding="utf-8") == "old csv"
    assert parquet.read_bytes() == b"old parquet"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.csv", "t.parquet"]
