"""Plans (assur.plotting.plans, ``assur plans``): exact images, lever, Kennedy, "
"files."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.explain._lever import lever_parts, lever_rates
from assur.explain._position import cross, perp
from assur.explain._solve import position, table_at
from assur.plotting import lever, plans, polygons

from .test_plan_labels import _overlap

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"
STEMS = ["slider_crank_exercise", "six_bar_lecture", "whitworth", "class3", "tenbar"]


@pytest.mark.parametrize("angle", [0.0, 0.5, 2.0, -2.9])
def test_perp_turns_a_vector_a_quarter_turn_counter_clockwise(angle: float) -> None:
    # the plans, the lever and the note draw k x r with this one function
    v = 0.3 * np.array([np.cos(angle), np.sin(angle)])
    turned = 0.3 * np.array([np.cos(angle + np.pi / 2), np.sin(angle + np.pi / 2)])
    np.testing.assert_allclose(perp(v), turned, rtol=0.0, atol=1e-15)
    assert cross(v, perp(v)) == pytest.approx(0.09, rel=1e-14)  # CCW, |v|^2


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


@pytest.mark.parametrize("level", [1, 2])
def test_a_triad_s_plan_draws_its_links_relative_motions(level: int) -> None:
    # the class III plans drew the images alone: no triangle to check
    import matplotlib.pyplot as plt

    from assur.plotting.plans import _rigid_parts

    mech = assur.load(EXAMPLES / "class3.toml")
    table = assur.kinematics(mech, [40.0])
    pos = position(mech, 40.0)
    (triad,) = [s for s in table.plan.solvers if len(s.bodies) == 4]
    mu = 0.001
    parts = _rigid_parts(pos, triad.bodies, level, mu)
    ends = {tuple(np.round(v / mu, 9)) for v in plans.images(pos, level).values()}
    step = 1 if level == 1 else 2
    # rod 1, plate 2, each rocker 1 relative motion: from a known pin's image
    assert len(parts) == 5 * step
    for i in range(0, len(parts), step):
        chain = parts[i : i + step]
        assert tuple(np.round(chain[0][0], 9)) in ends  # from a pin's image
        assert tuple(np.round(chain[-1][1], 9)) in ends  # to another's
        if level == 2:
            normal, tangential = chain
            assert np.array_equal(normal[1], tangential[0])
            assert (normal[2], tangential[2]) == ("n", "t")
            # -w^2 r along the link, eps x r across it: square to each other (a
            # normal part of the wrong sign leaves the rest oblique)
            n, t = (part[1] - part[0] for part in chain)
            assert abs(n @ t) <= 1e-9 * np.hypot(*n) * np.hypot(*t)
    ax = plans.acceleration_plan(table) if level == 2 else plans.velocity_plan(table)
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    plt.close(ax.figure)
    assert ("normal" in legend) if level == 2 else ("relative (rotation)" in legend)


@pytest.mark.parametrize(
    "stem",
    [
        "slider_crank_exercise",
        "six_bar_lecture",
        "whitworth",
        # friction's power counts on the lever (its sign went unseen)
        "slider_crank_friction",
        "four_bar_bearings",
    ],
)
@pytest.mark.parametrize("angle", [45.0, 190.0])
def test_lever_gives_the_balancing_torque(stem: str, angle: float) -> None:
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    torque = assur.forces(mech, [angle])["driver.torque"][0]
    assert lever.lever_balance(table_at(mech, angle)) == pytest.approx(torque, rel=1e-9)


def test_lever_of_the_lecture_exercise() -> None:
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    assert lever.lever_balance(table_at(mech, 45.0)) == pytest.approx(84.625, abs=5e-4)


@pytest.mark.parametrize(
    ("stem", "angle"),
    [
        ("six_bar_lecture", 45.0),
        ("tenbar", 45.0),
        ("whitworth", 45.0),
        ("whitworth", 90.0),
    ],
)
def test_relative_centres_obey_kennedy(stem: str, angle: float) -> None:
    # whitworth at 90 deg: the rod and the ram both translate, and the centre of pin F
    # was solved from round-off, far off the pin
    pos = position(assur.load(EXAMPLES / f"{stem}.toml"), angle)
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
    """The points with an image on the plan (their markers carry the names)."""
    return {
        x.get_gid()[6:] for x in ax.lines if (x.get_gid() or "").startswith("image-")
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
        ax = lever.zhukovsky_lever(table_at(mech, 45.0))
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


FRICTION = [
    (EXAMPLES / "slider_crank_friction.toml", 45.0),
    (EXAMPLES / "four_bar_bearings.toml", 30.0),
    (EXAMPLES / "slider_crank_locking.toml", 250.0),
    (Path(__file__).parent / "data" / "friction" / "jammed_guide.toml", 76.0),
]


@pytest.mark.parametrize(
    ("path", "angle"), FRICTION, ids=lambda x: getattr(x, "stem", x)
)
def test_the_lever_counts_friction(path: Path, angle: float) -> None:
    # it gave the frictionless load (84.6 N m for 100.8 on the slider-crank)
    mech = assur.load(path)
    table = assur.forces(mech, [angle])
    want = float(table["driver.torque"][0])
    scale = max(
        abs(want),
        float(np.max([table[c][0] for c in table.columns if c.endswith(".F")])) * 1e-3,
    )
    assert lever.lever_balance(table) == pytest.approx(want, abs=1e-9 * scale)


@pytest.mark.parametrize(
    ("path", "angle"), FRICTION, ids=lambda x: getattr(x, "stem", x)
)
def test_force_polygons_close_with_friction(path: Path, angle: float) -> None:
    import matplotlib.pyplot as plt

    # a sliding pair's friction force was left out: open by exactly that force
    fig = polygons.force_polygons(assur.forces(assur.load(path), [angle]))
    try:
        for ax in fig.axes:
            # open by more than round-off, the title gives the gap in mm
            assert ax.get_title().endswith(": the polygon closes"), ax.get_title()
    finally:
        plt.close(fig)


def test_the_lever_of_a_driver_at_rest_is_per_unit_speed(tmp_path: Path) -> None:
    # omega = 0: the lever divided by the driver's speed (ZeroDivisionError)
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    text = text.replace("omega = 200.0", "omega = 0.0")
    assert "omega = 0.0" in text
    mech = assur.loads(text)
    table = assur.forces(mech, [45.0])
    assert lever.lever_balance(table) == pytest.approx(
        float(table["driver.torque"][0]), rel=1e-9
    )


def test_each_driver_has_its_lever() -> None:
    import matplotlib.pyplot as plt

    table = assur.forces(assur.load(EXAMPLES / "five_bar_two_cranks.toml"), [[60, 60]])
    for i, name in enumerate(("A", "E")):
        want = float(table[f"{name}.torque"][0])
        assert lever.lever_balance(table, driver=i) == pytest.approx(want, rel=1e-9)
        ax = lever.zhukovsky_lever(table, driver=i)
        assert f"driver {name}" in ax.get_title()
        plt.close(ax.figure)
    with pytest.raises(
        assur.UsageError, match="lever_balance: no driver 2; expected 0 to 1"
    ):
        lever.lever_balance(table, driver=2)


def test_the_lever_needs_a_forces_table() -> None:
    table = assur.kinematics(
        assur.load(EXAMPLES / "slider_crank_exercise.toml"), [30.0]
    )
    for draw in (lever.lever_balance, lever.zhukovsky_lever):
        with pytest.raises(assur.UsageError, match="needs a forces table"):
            draw(table)


@pytest.mark.pictures
def test_command_writes_a_lever_per_driver(tmp_path: Path, capsys) -> None:
    from assur.cli import main

    out = tmp_path / "five"
    five = EXAMPLES / "five_bar_two_cranks.toml"
    assert main(["plans", str(five), "--angle", "45,90", "-o", str(out), "-q"]) == 0
    stems = {p.stem for p in out.iterdir()}
    assert {"zhukovsky_lever_1", "zhukovsky_lever_2", "force_polygons"} <= stems
    kin = tmp_path / "kin"
    assert main(["plans", str(EXAMPLES / "lever_var9.toml"), "-o", str(kin)]) == 0
    err = capsys.readouterr().err
    assert err == (
        f"assur: note: {EXAMPLES / 'lever_var9.toml'}: no force polygons and no lever: "
        "no link has a mass and no load is applied\n"
    )


def test_a_name_is_drawn_whole_in_the_force_polygons(tmp_path: Path) -> None:
    import matplotlib.pyplot as plt

    # the note's TeX of "a^b" (\hat{}) drew a hat over nothing: the "^" was lost
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    odd = "c^o{u}p_l%e&r \\ $x"
    text = text.replace("[links.coupler]", f"[links.{_toml_key(odd)}]")
    text = text.replace('"coupler"', _toml_key(odd))
    path = tmp_path / "odd.toml"
    path.write_text(text, encoding="utf-8")
    table = assur.forces(assur.load(path), [30.0])
    fig = polygons.force_polygons(table)
    try:
        labels = [t.get_text() for ax in fig.axes for t in ax.texts]
        fig.canvas.draw()  # every label can be set
    finally:
        plt.close(fig)
    # what mathtext draws of the name: every character, a backslash as set-minus
    drawn = "\\text{c^o\\{u\\}p_l%e&r \N{SET MINUS} \\$x}"
    named = [label for label in labels if drawn in label]
    assert len(named) >= 2  # the coupler's loads and reactions
    assert all(label[0] == label[-1] == "$" for label in named)


def _toml_key(text: str) -> str:
    return '"' + text.replace("\\", "\\\\") + '"'


ROTOR = """format = 1
name = "Rotor"
[links.crank]
mass = 1.0
center = [0.05, 0.0]
inertia = 0.001
[joints.A]
kind = "revolute"
links = ["ground", "crank"]
at = [0.0, 0.0]
[[drivers]]
joint = "A"
omega = 10.0
epsilon = 2.0
"""


def test_a_crank_alone_has_plans_and_a_lever_but_no_polygon(
    tmp_path: Path, capsys
) -> None:
    from assur.cli import main

    # no Assur group: the command blamed its output folder (a matplotlib error)
    path = tmp_path / "rotor.toml"
    path.write_text(ROTOR, encoding="utf-8")
    out = tmp_path / "plans"
    assert main(["plans", str(path), "--angle", "30", "-o", str(out), "-q"]) == 0
    assert capsys.readouterr().err == ""
    stems = {p.stem for p in out.iterdir()}
    assert stems == {
        "velocity_plan", "acceleration_plan", "zhukovsky_lever", "instant_centres"
    }  # fmt: skip
    table = assur.forces(assur.load(path), [30.0])
    # the crank's own inertia torque: J epsilon about its pivot, m e^2 included
    assert float(table["driver.torque"][0]) == pytest.approx((0.001 + 0.05**2) * 2.0)
    assert lever.lever_balance(table) == pytest.approx(table["driver.torque"][0])
    with pytest.raises(assur.ModelError, match="no Assur group, so no polygon"):
        polygons.force_polygons(table)
    status = main(["plot", str(path), "--group", "1", "-o", str(tmp_path / "g.png")])
    assert status == 2
    assert "expected no --group: only its input link moves" in capsys.readouterr().err


def test_a_folder_written_again_holds_one_mechanism_s_plans(tmp_path: Path) -> None:
    from assur.cli import main

    # the five-bar's levers stayed beside the lever of the next mechanism
    out = tmp_path / "plans"
    out.mkdir()
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    five = str(EXAMPLES / "five_bar_two_cranks.toml")
    assert main(["plans", five, "--angle", "30,60", "-o", str(out), "-q"]) == 0
    assert (out / "zhukovsky_lever_2.svg").exists()
    lever = str(EXAMPLES / "lever_var9.toml")  # no masses: no polygons, no lever
    assert main(["plans", lever, "-o", str(out), "-q"]) == 0
    assert {p.name for p in out.iterdir()} == {
        "notes.txt",
        *(f"{stem}.{suffix}" for stem in ("velocity_plan", "acceleration_plan",
          "instant_centres") for suffix in ("png", "svg")),
    }  # fmt: skip


def _inside(ax, points: np.ndarray) -> bool:
    """Whether every point lies within the limits of ``ax``."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    x, y = np.transpose(points)
    return bool(np.all((x0 <= x) & (x <= x1) & (y0 <= y) & (y <= y1)))


@pytest.mark.parametrize("stem", STEMS)
def test_the_instant_centres_drawn_are_within_the_limits(stem: str) -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import draw

    # the centres were plotted after draw() had framed the mechanism alone: the
    # rod's centre of the lecture exercise, at (0.245, 0.245) m, stood above y = 0.078
    table = table_at(assur.load(EXAMPLES / f"{stem}.toml"), 45.0)
    ax = plans.instant_centres(table)
    centres = [ln.get_xydata()[0] for ln in ax.lines if ln.get_zorder() == 9]
    assert centres
    assert _inside(ax, np.array(centres))
    # the mechanism stays in view: the limits are those of draw() or wider
    alone = draw(table)
    corners = np.array([alone.get_xlim(), alone.get_ylim()]).T
    assert _inside(ax, corners)
    plt.close(alone.figure)
    plt.close(ax.figure)


def _with_torque(tmp_path: Path) -> Path:
    """The crank-rocker four-bar with a torque of -4 N m resisting its rocker."""
    path = tmp_path / "four_bar_torque.toml"
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    path.write_text(text + '\n[[loads]]\nlink = "rocker"\ntorque = -4.0\n', "utf-8")
    return path


CYLINDER = """format = 1
name = "Oscillating cylinder"
[links.crank]
[links.piston]
[links.cylinder]
mass = 1.2
center = "O4"
inertia = 1.5e-3
[joints.O2]
kind = "revolute"
links = ["ground", "crank"]
at = [0.0, 0.0]
[joints.B]
kind = "revolute"
links = ["crank", "piston"]
at = [0.025, 0.0433013]
[joints.bore]
kind = "prismatic"
links = ["cylinder", "piston"]
at = [0.025, 0.0433013]
axis = [-0.155, 0.0433013]
[joints.O4]
kind = "revolute"
links = ["ground", "cylinder"]
at = [0.18, 0.0]
[[drivers]]
joint = "O2"
omega = 15.0
"""
"""An oscillating cylinder whose only load is its own inertia couple: a link whose
two joints apart are a pivot and a prismatic joint (the bore)."""


def _lever_file(stem: str, tmp_path: Path) -> Path:
    """The mechanism file of one of ``LEVERS``."""
    if stem == "torque":
        return _with_torque(tmp_path)
    if stem == "cylinder":
        path = tmp_path / "cylinder.toml"
        path.write_text(CYLINDER, "utf-8")
        return path
    return EXAMPLES / f"{stem}.toml"


LEVERS = [
    "slider_crank_exercise",
    "six_bar_lecture",
    "four_bar",
    "whitworth",
    "four_bar_bearings",
    "torque",
    "cylinder",
]
"""Levers whose couples must be counted: inertia couples on every link but the
slider-crank's crank, a couple on a block with no two joints apart (Whitworth), an
external torque with friction (bearings) and without (``torque``), a couple carried
by a pivot and a prismatic joint (``cylinder``)."""


@pytest.mark.parametrize("stem", LEVERS)
@pytest.mark.parametrize("angle", [45.0, 160.0, 290.0])
def test_the_lever_s_terms_add_up_to_the_balancing_load(
    stem: str, angle: float, tmp_path: Path
) -> None:
    path = _lever_file(stem, tmp_path)
    mech = assur.load(path)
    torque = float(assur.forces(mech, [angle])["driver.torque"][0])
    terms = lever.lever_moments(table_at(mech, angle))
    couples = [t for t, _ in terms if t.startswith(("M_{i,", "T_{"))]
    assert couples, "every one of these levers carries a couple"
    total = sum(share for _, share in terms)
    assert total == pytest.approx(torque, rel=1e-9, abs=1e-12 * abs(torque))


def test_the_exercise_s_lever_counts_the_rod_s_inertia_couple() -> None:
    # without the couple the drawn forces give 89.53 N m, not the 84.625 N m printed
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    terms = dict(lever.lever_moments(table_at(mech, 45.0)))
    rod = "M_{i,\\mathrm{rod}}"
    # -M omega_rod / omega = -(-18.083)(-54.21) / 200
    assert terms[rod] == pytest.approx(-4.9018, abs=5e-5)
    forces = sum(v for k, v in terms.items() if k != rod)
    assert forces == pytest.approx(89.527, abs=5e-4)
    assert sum(terms.values()) == pytest.approx(84.625, abs=5e-4)


def _listed(ax) -> tuple[dict[str, float], str]:
    """The terms written beside a lever (label: value) and the sum as written."""
    (text,) = [t.get_text() for t in ax.texts if "balancing load" in t.get_text()]
    *rows, last = [line for line in text.splitlines() if ":  " in line or "sum" in line]
    terms = {}
    for row in rows:
        label, value = row.rsplit(":  ", 1)
        terms[label] = float(value)
    return terms, last.split(": ")[1].split()[0]


@pytest.mark.parametrize("stem", LEVERS)
def test_the_terms_written_on_the_lever_add_up_by_hand(
    stem: str, tmp_path: Path
) -> None:
    import matplotlib.pyplot as plt

    path = _lever_file(stem, tmp_path)
    table = table_at(assur.load(path), 45.0)
    ax = lever.zhukovsky_lever(table)
    terms, written = _listed(ax)
    plt.close(ax.figure)
    # each term one decimal finer than the sum: the rounding of a handful of terms
    # stays below the sum's last digit
    places = len(written.partition(".")[2])
    assert abs(sum(terms.values()) - float(written)) <= 10.0 ** (-places)
    assert float(written) == pytest.approx(lever.lever_balance(table), rel=1e-4)
    # every couple is written, by its symbol as mathtext
    couples = [t for t, _ in lever.lever_moments(table) if t.startswith(("M_", "T_"))]
    assert sum(label.startswith(("$M_{i,", "$T_{")) for label in terms) == len(couples)


@pytest.mark.parametrize("angle", [0.0, 180.0])
def test_a_sum_that_rounds_to_nothing_is_written_0(angle: float) -> None:
    # the slider-crank at a dead centre: the sum was "-0.00000000 N·m"
    import matplotlib.pyplot as plt

    table = table_at(assur.load(EXAMPLES / "slider_crank_exercise.toml"), angle)
    ax = lever.zhukovsky_lever(table)
    _, written = _listed(ax)
    plt.close(ax.figure)
    assert float(written) == 0.0
    assert not written.startswith("-")


@pytest.mark.parametrize("stem", LEVERS)
def test_the_forces_drawn_on_the_lever_give_its_load(stem: str, tmp_path: Path) -> None:
    # the moments about the pole of the arrows drawn (a couple as its pair of forces
    # at two joints' images), over the speed, are the balancing load less friction's
    # share and the couples only listed (a block whose joints coincide)
    path = _lever_file(stem, tmp_path)
    table = table_at(assur.load(path), 45.0)
    pos = position(assur.load(path), 45.0)
    bodies, speed, _ = lever_rates(pos, 0)
    turned = dataclasses.replace(pos, bodies=bodies)
    terms = lever_parts(pos, bodies)
    apart = lever._apart(turned, terms)
    arrows = lever._lever_arrows(turned, terms, apart)
    drawn = sum(a[0] * f[1] - a[1] * f[0] for a, f, _, _ in arrows) / speed
    listed_only = sum(
        -t.power / speed for t in terms if t.couple and apart[t.body] is None
    )
    shares = dict(lever.lever_moments(table))
    want = sum(shares.values()) - shares.get("friction", 0.0) - listed_only
    assert drawn == pytest.approx(want, rel=1e-9, abs=1e-12)
    pairs = [a for a in arrows if a[3]]
    assert len(pairs) == 2 * sum(t.couple and apart[t.body] is not None for t in terms)


@pytest.mark.parametrize("stem", LEVERS)
def test_the_note_s_lever_lists_the_terms_the_picture_lists(
    stem: str, tmp_path: Path
) -> None:
    from assur.explain import explain

    path = _lever_file(stem, tmp_path)
    mech = assur.load(path)
    note = str(explain(mech, 45.0)).split("## 6. Check by Zhukovsky's lever")[1]
    # the table of powers: | $load$ | force or couple | velocity | $power$ |
    rows = [line.split(" | ") for line in note.splitlines() if line.startswith("| $")]
    shown = [(cells[0][3:-1], cells[-1].strip(" |$")) for cells in rows]
    speed = lever_rates(position(mech, 45.0), 0)[1]
    terms = lever.lever_moments(table_at(mech, 45.0))
    want = [(t, -share * speed) for t, share in terms if t != "friction"]
    assert [t for t, _ in shown] == [t for t, _ in want]
    for (_, got), (_, power) in zip(shown, want, strict=True):
        # to half a unit of the last digit printed
        half = 0.5 * 10.0 ** -len(got.partition(".")[2])
        assert abs(float(got) - power) <= half * (1 + 1e-9)


def test_the_documented_couple_numbers_are_the_note_s() -> None:
    # docs/explain.rst quotes the rod's couple on the exercise's lever at 45 degrees
    from assur.explain import explain

    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    note = str(explain(mech, 45.0))
    row = r"| $M_{i,\mathrm{rod}}$ | $-18.08$ | $\omega = -54.21$ |  | $980.36$ |"
    assert row in note
    terms = dict(lever.lever_moments(table_at(mech, 45.0)))
    assert round(terms[r"M_{i,\mathrm{rod}}"], 2) == pytest.approx(-4.90)
    # the crank's inertia force is square to its centre's velocity: its term is
    # zero but for round-off, of either sign by the machine's arithmetic (-0.00
    # on one, 0.00 on another), and the note shows it as 0
    shown = [
        f"{round(v, 2) + 0.0:.2f}" for k, v in terms.items() if k.startswith(r"\vec F")
    ]
    assert shown == ["0.00", "32.73", "56.79"]


@pytest.mark.parametrize(
    ("draw", "angle"), [("velocity_plan", 91.0), ("acceleration_plan", 95.0)]
)
def test_a_short_arrow_of_a_plan_has_a_head_shorter_than_itself(
    draw: str, angle: float
) -> None:
    # the plans drew every head 11 pt long: a short vector's hid its direction (the
    # Whitworth block hardly slides near 90 deg)
    from .test_plotting import _arrow_lengths

    table = table_at(assur.load(EXAMPLES / "whitworth.toml"), angle)
    ax = getattr(plans, draw)(table)
    import matplotlib.pyplot as plt

    lengths = _arrow_lengths(ax)
    plt.close(ax.figure)
    assert lengths
    # some are under 11 pt: the fixed head (4.4 pt) was over 0.4 of their length
    assert min(length for length, _ in lengths) < 11.0
    for length, head in lengths:
        assert head <= 0.4 * length * (1 + 1e-9)
        assert head <= 0.4 * 11


LABELLED = Path(__file__).parent / "data" / "plans"
"""The mechanisms whose plans a review found labels overlapping on."""


def _boxes(fig, texts) -> np.ndarray:
    """Return the display boxes (x0, y0, x1, y1) of ``texts`` as drawn."""
    renderer = fig.canvas.get_renderer()
    return np.array([t.get_window_extent(renderer).extents for t in texts])


def _overlaps(boxes: np.ndarray) -> list[tuple[int, int]]:
    """Return the pairs of boxes that overlap (more than half a pixel each way)."""
    return [
        (i, j)
        for i in range(len(boxes))
        for j in range(i + 1, len(boxes))
        if _overlap(boxes[i], boxes[j])
    ]


@pytest.mark.parametrize(("stem", "angle"), [("fourbar", 60.0), ("inverted", 230.0)])
def test_the_force_polygons_names_do_not_overlap(stem: str, angle: float) -> None:
    import matplotlib.pyplot as plt

    # F_crank,coupler was written over m_rocker g; F_ground,guide over F_crank,block
    table = assur.forces(assur.load(LABELLED / f"{stem}.toml"), [angle])
    fig = polygons.force_polygons(table)
    try:
        fig.canvas.draw()
        for ax in fig.axes:
            texts = [t for t in ax.texts if t.get_text()]
            assert len(texts) >= 5
            boxes = _boxes(fig, texts)
            pairs = _overlaps(boxes)
            assert not pairs, [
                (texts[i].get_text(), texts[j].get_text()) for i, j in pairs
            ]
            frame = ax.bbox.extents
            assert (boxes[:, :2] >= frame[:2] - 1).all()
            assert (boxes[:, 2:] <= frame[2:] + 1).all()
    finally:
        plt.close(fig)


def test_the_lever_s_names_stay_inside_it_off_the_list_of_terms() -> None:
    import matplotlib.pyplot as plt

    # b = slot = g(block) ran out of the lever over the list's m_lever g line
    table = assur.forces(assur.load(LABELLED / "shaper.toml"), [200.0])
    ax = lever.zhukovsky_lever(table)
    fig = ax.figure
    try:
        fig.canvas.draw()
        # every text drawn but the ticks' (those past the limits are not drawn)
        texts = [*ax.texts, ax.title, ax.xaxis.label, *ax.get_legend().get_texts()]
        boxes = _boxes(fig, texts)
        page = fig.bbox.extents
        assert (boxes[:, :2] >= page[:2] - 1).all()
        assert (boxes[:, 2:] <= page[2:] + 1).all()
        (terms,) = [t for t in ax.texts if "sum = balancing load" in t.get_text()]
        labels = [t for t in ax.texts if t is not terms]
        assert any(" = g(block)" in t.get_text() for t in labels)
        inside = _boxes(fig, labels)
        frame = ax.bbox.extents
        assert (inside[:, :2] >= frame[:2] - 1).all()
        assert (inside[:, 2:] <= frame[2:] + 1).all()
        pairs = _overlaps(np.vstack([_boxes(fig, [terms]), inside]))
        assert not [labels[j - 1].get_text() for i, j in pairs if i == 0]
    finally:
        plt.close(fig)


@pytest.mark.parametrize("level", [1, 2])
def test_the_guide_s_point_under_the_block_is_named(level: int) -> None:
    import matplotlib.pyplot as plt

    # the tip of v_SQ (a_SQ's parts) on the RPR group's plans had no name
    table = assur.forces(assur.load(LABELLED / "inverted.toml"), [230.0])
    pos = plans._pos(table, 230.0)
    pair = pos.plan.pairs["S"]
    guide = pos.coincident(pair.first, pos.pair_point(pair), level)
    mu = plans._scale(list(plans.images(pos, level).values()))
    draw = plans.velocity_plan if level == 1 else plans.acceleration_plan
    ax = draw(table, 230.0)
    try:
        named = [
            t.get_text() for t in ax.texts if np.allclose(t.xy, guide / mu, atol=1e-9)
        ]
    finally:
        plt.close(ax.figure)
    assert named == ["$\\text{s}_{\\text{guide}}$"]


@pytest.mark.parametrize(("stem", "angle"), [("shaper", 200.0), ("inverted", 230.0)])
def test_the_plans_names_do_not_overlap(stem: str, angle: float) -> None:
    import matplotlib.pyplot as plt

    # slot_lever, the guide's point, was written over b = slot = g(block)
    table = assur.forces(assur.load(LABELLED / f"{stem}.toml"), [angle])
    for draw in (plans.velocity_plan, plans.acceleration_plan):
        ax = draw(table, angle)
        try:
            ax.figure.canvas.draw()
            texts = [t for t in ax.texts if t.get_text()]
            pairs = _overlaps(_boxes(ax.figure, texts))
        finally:
            plt.close(ax.figure)
        assert not [(texts[i].get_text(), texts[j].get_text()) for i, j in pairs]


def test_a_cylinder_s_couple_acts_at_its_pivot_and_its_bore(tmp_path: Path) -> None:
    import matplotlib.pyplot as plt

    table = table_at(assur.load(_lever_file("cylinder", tmp_path)), 70.0)
    ax = lever.zhukovsky_lever(table)
    texts = [t.get_text() for t in ax.texts]
    plt.close(ax.figure)
    assert not any("listed only" in t for t in texts)
    # the pair's forces, and the image of the cylinder's point at the bore
    assert sum("/l_{" in t for t in texts) == 2
    assert r"$\text{bore}_{\text{cylinder}}$" in texts


def test_an_accelerating_crank_s_pin_is_drawn_in_two_parts(monkeypatch) -> None:
    # its acceleration was one grey arrow from the pole, epsilon's part unseen
    mech = assur.load(EXAMPLES / "four_bar.toml")
    table = assur.kinematics(mech, [70.0])
    w, eps = table["crank.omega"][0], table["crank.alpha"][0]
    assert eps != 0
    drawn = []

    def record(ax, start, end, color, **kw):
        drawn.append((np.asarray(start), np.asarray(end), color))
        return True

    monkeypatch.setattr(plans, "_arrow", record)
    plans.acceleration_plan(table_at(mech, 70.0))
    mu = plans._scale(list(plans.images(position(mech, 70.0), 2).values()))
    pivot = mech.joint(mech.drivers[0].joint).at
    r = np.array([table["A.x"][0] - pivot[0], table["A.y"][0] - pivot[1]])
    normal = -w * w * r / mu
    tip = np.array([table["A.ax"][0], table["A.ay"][0]]) / mu
    n = [c for s, e, c in drawn if np.allclose(s, 0) and np.allclose(e, normal)]
    t = [c for s, e, c in drawn if np.allclose(s, normal) and np.allclose(e, tip)]
    assert len(n) == len(t) == 1
    assert n != t  # two colours: normal and tangential


def test_the_instant_centres_legend_says_what_squares_dots_and_lines_are():
    import matplotlib.pyplot as plt

    from assur.plotting import instant_centres

    table = table_at(assur.load(EXAMPLES / "four_bar.toml"), 60.0)
    ax = instant_centres(table)
    try:
        said = [t.get_text() for t in ax.get_legend().get_texts()]
    finally:
        plt.close(ax.figure)
    assert "absolute centre: a link about the frame" in said
    assert "relative centre of two links" in said
    assert "Kennedy: three centres on a line" in said
    assert said[0].startswith("I, driver")  # the groups' entries are kept


def _segments(ax) -> list[np.ndarray]:
    """Return the ends (2, 2) of every straight arrow on ``ax``, data coordinates."""
    from matplotlib.patches import FancyArrowPatch

    found = []
    for p in ax.patches:
        if isinstance(p, FancyArrowPatch) and p._posA_posB is not None:
            found.append(np.asarray(p._posA_posB, dtype=float))
    return found


def _on_each_other(a: np.ndarray, b: np.ndarray, near: float) -> bool:
    """Whether segments ``a`` and ``b`` lie on one line and share more than ``near``."""
    u = (a[1] - a[0]) / np.hypot(*(a[1] - a[0]))
    off = [abs(u[0] * (q - a[0])[1] - u[1] * (q - a[0])[0]) for q in b]
    low, high = sorted(float(np.dot(u, q - a[0])) for q in b)
    return max(off) <= near and min(high, np.hypot(*(a[1] - a[0]))) - max(low, 0) > near


@pytest.mark.parametrize("angle", [0.0, 180.0])
def test_a_dead_centre_s_polygon_draws_its_sides_apart(angle: float) -> None:
    import matplotlib.pyplot as plt

    # at a dead centre every side lies on the rod's line: the reaction was drawn
    # over both inertia forces, and could be neither seen nor told apart
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [angle])
    fig = polygons.force_polygons(table)
    try:
        (ax,) = fig.axes
        sides = _segments(ax)
        assert len(sides) == 3
        assert all(abs(s[1, 1] - s[0, 1]) < 1e-9 for s in sides)  # on one line
        for i, a in enumerate(sides):
            for b in sides[i + 1 :]:
                assert not _on_each_other(a, b, 0.2), (a, b)
        # the side moved aside is joined to the chain's corners by dotted lines
        dotted = [ln.get_xydata() for ln in ax.lines if ln.get_linestyle() == ":"]
        moved = [s for s in sides if abs(s[0, 1]) > 1e-9]
        assert len(moved) == 1
        assert len(dotted) == 2
        tips = np.cumsum([[0.0, 0.0]] + [s[1] - s[0] for s in sides], axis=0)
        ends = {tuple(np.round(d[0], 9)) for d in dotted}
        assert ends <= {tuple(np.round(t, 9)) for t in tips}
        np.testing.assert_allclose(tips[-1], 0.0, atol=1e-9)  # the polygon closes
    finally:
        plt.close(fig)


@pytest.mark.parametrize("drawing", ["velocity", "acceleration", "polygons"])
def test_a_plan_s_scale_is_written_once_in_its_key(drawing: str) -> None:
    import matplotlib.pyplot as plt

    # the force polygon wrote μF in its title and again in its legend
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_friction.toml"), [45.0])
    if drawing == "polygons":
        axes = polygons.force_polygons(table).axes
    else:
        axes = [getattr(plans, f"{drawing}_plan")(table)]
    try:
        for ax in axes:
            key = [t.get_text() for t in ax.get_legend().get_texts()]
            texts = [ax.get_title(), *key, *(t.get_text() for t in ax.texts)]
            assert sum(t.count("μ") for t in texts) == 1, texts
            assert any(t.startswith("scale: μ") for t in key), key
    finally:
        plt.close(axes[0].figure)


def _key_clear(ax) -> tuple[bool, bool]:
    """Whether ``ax``'s key covers a drawn line, and whether it is inside the axes."""
    from assur.plotting._bars import settled_renderer
    from assur.plotting._key import covers

    renderer = settled_renderer(ax)
    box = ax.get_legend().get_window_extent(renderer)
    return covers(ax, renderer), box.x0 < ax.bbox.x1


@pytest.mark.parametrize("moved", [True, False])
def test_a_key_over_a_polygon_s_sides_is_moved_beside_it(monkeypatch, moved) -> None:
    # the class III example's triad at 30 deg fills its axes to every corner:
    # loc="best" put the key over two of its sides (moved=False: as before)
    import matplotlib.pyplot as plt

    from assur.plotting._bars import settle_without

    if not moved:
        monkeypatch.setattr(
            polygons,
            "keys_clear",
            lambda axes, texts, widen: settle_without(axes[0], texts),
        )
    table = table_at(assur.load(EXAMPLES / "class3.toml"), 30.0)
    fig = polygons.force_polygons(table, 30.0)
    try:
        (ax,) = fig.axes
        assert _key_clear(ax) == ((False, False) if moved else (True, True))
        assert bool(fig.get_size_inches()[0] > 5.5 + 1.0) is moved  # grown by the key
    finally:
        plt.close(fig)


@pytest.mark.parametrize("level", [1, 2])
def test_a_plan_s_key_in_a_free_corner_stays_there(level: int) -> None:
    import matplotlib.pyplot as plt

    table = table_at(assur.load(EXAMPLES / "class3.toml"), 30.0)
    draw = plans.acceleration_plan if level == 2 else plans.velocity_plan
    ax = draw(table)
    try:
        assert _key_clear(ax) == (False, True)
        assert tuple(ax.figure.get_size_inches()) == (7.5, 6.5)
    finally:
        plt.close(ax.figure)


def test_a_plan_on_the_caller_s_axes_keeps_the_figure_s_size() -> None:
    import matplotlib.pyplot as plt

    table = table_at(assur.load(EXAMPLES / "class3.toml"), 30.0)
    fig, ax = plt.subplots(figsize=(3.0, 3.0), layout="constrained")
    try:
        plans.acceleration_plan(table, ax=ax)
        assert tuple(fig.get_size_inches()) == (3.0, 3.0)
    finally:
        plt.close(fig)
