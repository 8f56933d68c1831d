"""Every command on every bundled example writes a valid, non-empty file.

The picture commands run with a coarse sweep and few frames to stay quick; the
checks are on the files: PNG size, GIF frame count, the HTML's embedded data.
"""

from __future__ import annotations

import json
import re
import warnings

import numpy as np
import pytest

import assur
from assur.cli import main

from .conftest import example_files


def has_forces(path) -> bool:
    from assur._loads import compile_loads
    from assur.plan import compile_plan

    return not compile_loads(compile_plan(assur.load(path))).empty


@pytest.mark.pictures
@pytest.mark.parametrize("path", example_files(), ids=lambda p: p.stem)
def test_every_command_writes_a_valid_file(path, tmp_path, capsys):
    from PIL import Image

    mech = assur.load(path)
    forces = has_forces(path)
    assert main(["structure", str(path), "--json"]) == 0
    structure = json.loads(capsys.readouterr().out)
    assert structure["dof"] == len(mech.drivers)
    csv = tmp_path / "table.csv"
    command = "forces" if forces else "kinematics"
    assert main([command, str(path), "--csv", str(csv)]) == 0
    header = csv.read_text(encoding="utf-8").splitlines()[0].split(",")
    assert header[0] == "angle"
    assert len(csv.read_text(encoding="utf-8").splitlines()) == 361
    png = tmp_path / "pose.png"
    extra = ["--forces"] if forces else []
    assert main(["plot", str(path), "-o", str(png), "--dpi", "60", *extra]) == 0
    with Image.open(png) as image:
        assert min(image.size) > 100
    gif = tmp_path / "turn.gif"
    assert (
        main(["animate", str(path), "-o", str(gif), "--frames", "3", "--dpi", "40"])
        == 0
    )
    with Image.open(gif) as image:
        assert image.n_frames == 3
    html = tmp_path / "report.html"
    assert main(["report", str(path), "-o", str(html)]) == 0
    text = html.read_text(encoding="utf-8")
    data = re.search(
        r'<script type="application/json" id="assur-data">(.*?)</script>', text, re.S
    )
    assert data is not None
    assert json.loads(data.group(1))
    capsys.readouterr()


@pytest.mark.pictures
@pytest.mark.parametrize("path", example_files()[:4], ids=lambda p: p.stem)
def test_diagrams_of_examples(path, tmp_path):
    out = tmp_path / "diagrams"
    assert main(["diagrams", str(path), "-o", str(out), "--dpi", "50"]) == 0
    written = sorted(p.name for p in out.glob("*.png"))
    assert {"motion.png", "paths.png", "decomposition.png"} <= set(written)
    from assur.dynamics_shown import has_dynamics

    assert len(written) == (6 if has_forces(path) else 3) + has_dynamics(
        assur.load(path)
    )


def test_table_to_pandas():
    pd = pytest.importorskip("pandas")
    t = assur.kinematics(assur.catalog.four_bar(), [0.0, 90.0])
    frame = t.to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == list(t.columns)
    np.testing.assert_array_equal(frame["coupler.omega"], t["coupler.omega"])
    # each column's unit, as the schema gives it (the frame carried none)
    units = frame.attrs["units"]
    assert list(units) == list(t.columns)
    assert units["coupler.omega"] == "rad/s"
    assert units["angle"] == "deg"
    assert units["B.ax"] == "m/s^2"
    dynamics = assur.dynamics(assur.catalog.slider_crank(), [0.0, 90.0]).to_pandas()
    assert dynamics.attrs["units"]["driver.omega"] == "rad/s"


def test_near_dead_centre_is_warned_once_with_positions():
    """A rocker just longer than the limit: a transmission angle of 1.7 deg at 0 deg."""
    mech = assur.catalog.four_bar(rocker=0.06005)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        t = assur.kinematics(mech, np.arange(-10.0, 11.0, 1.0))
    near = [w for w in caught if issubclass(w.category, assur.AssurWarning)]
    assert len(near) == 1
    text = str(near[0].message)
    assert "RRR (coupler, rocker): near a dead centre" in text
    assert "at driver positions -1 deg to 1 deg" in text
    assert len(t) == 21
