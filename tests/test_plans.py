"""Plans (assur.plotting.plans, ``assur plans``): exact images, lever, Kennedy, "
"files."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.explain._solve import position, table_at
from assur.plotting import plans

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"
STEMS = ["slider_crank_exercise", "six_bar_lecture", "whitworth", "class3", "tenbar"]


@pytest.mark.parametrize("stem", STEMS)
def test_plan_images_are_the_table_s_velocities_and_accelerations(stem: str) -> None:
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    table = assur.kinematics(mech, [45.0])
    pos = position(mech, 45.0)
    for k, (x, y) in ((1, ("vx", "vy")), (2, ("ax", "ay"))):
        found = plans.images(pos, k)
        assert sorted(found) == sorted(p for p in table.plan.points if "~" not in p)
        for name, v in found.items():
            want = [table[f"{name}.{x}"][0], table[f"{name}.{y}"][0]]
            np.testing.assert_allclose(v, want, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize(
    "stem", ["slider_crank_exercise", "six_bar_lecture", "whitworth"]
)
@pytest.mark.parametrize("angle", [45.0, 190.0])
def test_lever_gives_the_balancing_torque(stem: str, angle: float) -> None:
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    torque = assur.forces(mech, [angle])["driver.torque"][0]
    assert plans.lever_balance(table_at(mech, angle)) == pytest.approx(torque, rel=1e-9)


def test_lever_of_the_lecture_exercise() -> None:
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    assert plans.lever_balance(table_at(mech, 45.0)) == pytest.approx(84.625, abs=5e-4)


@pytest.mark.parametrize("stem", ["six_bar_lecture", "tenbar", "whitworth"])
def test_relative_centres_obey_kennedy(stem: str) -> None:
    pos = position(assur.load(EXAMPLES / f"{stem}.toml"), 45.0)
    centres = plans.relative_centres(pos)
    size = pos.size()
    checked = 0
    for (i, j), p in centres.items():
        a, b = centres.get((0, i)) if i else None, centres.get((0, j))
        if not i or p is None or a is None or b is None:
            continue
        d = b - a
        # the relative centre lies on the line of the two absolute ones
        gap = abs(d[0] * (p - a)[1] - d[1] * (p - a)[0]) / max(np.hypot(*d), 1e-300)
        assert gap <= 1e-9 * max(size, float(np.abs(p).max())), (i, j)
        checked += 1
    assert checked
    # a pin is the relative centre of the two links it joins
    for pair in pos.plan.pairs.values():
        if pair.kind == "R" and not pair.virtual and pair.first:
            key = (min(pair.first, pair.second), max(pair.first, pair.second))
            np.testing.assert_allclose(
                centres[key], pos.pair_point(pair), atol=1e-9 * size
            )


def _labels(ax) -> set[str]:
    return {
        t.get_gid()[6:] for t in ax.texts if (t.get_gid() or "").startswith("image-")
    }


@pytest.mark.parametrize("stem", ["slider_crank_exercise", "lever_var9", "class3"])
def test_every_point_is_on_each_plan(stem: str) -> None:
    import matplotlib.pyplot as plt

    mech = assur.load(EXAMPLES / f"{stem}.toml")
    points = {p for p in assur.kinematics(mech, [45.0]).plan.points if "~" not in p}
    for draw in (plans.velocity_plan, plans.acceleration_plan):
        ax = draw(table_at(mech, 45.0))
        assert _labels(ax) == points
        plt.close(ax.figure)
    if mech.links[0].mass or stem == "slider_crank_exercise":
        ax = plans.zhukovsky_lever(table_at(mech, 45.0))
        assert _labels(ax) == points
        plt.close(ax.figure)


@pytest.mark.pictures
def test_command_writes_the_plans(tmp_path: Path, capsys) -> None:
    from assur.cli import main

    out = tmp_path / "plans"
    source = EXAMPLES / "slider_crank_exercise.toml"
    assert main(["plans", str(source), "--angle", "45", "-o", str(out)]) == 0
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(f"{n}.{s}" for n in plans_names() for s in ("png", "svg"))
    for p in out.iterdir():
        assert p.stat().st_size > 10_000, p.name
        if p.suffix == ".png":
            assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        else:
            assert "<svg" in p.read_text(encoding="utf-8")[:2000]
    # kinematics only: no force polygons, no lever
    kin = tmp_path / "kin"
    assert main(["plans", str(EXAMPLES / "lever_var9.toml"), "-o", str(kin), "-q"]) == 0
    assert sorted(p.stem for p in kin.iterdir()) == sorted(
        2 * ["acceleration_plan", "instant_centres", "velocity_plan"]
    )
    assert (
        main(["plans", str(source), "--angle", "0:90:45", "-o", str(tmp_path / "x")])
        == 2
    )
    assert not (tmp_path / "x").exists()


def plans_names() -> list[str]:
    from assur.pictures_cli import PLANS

    return list(PLANS)
