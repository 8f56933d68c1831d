"""The explanatory note (assur.explain): every number it prints against the tables.

The tests read the note as a student would: they parse its Markdown, find every
statement ``symbol = ... = value`` in its mathematics, and compare the value with the
forces table (to half a unit of the last digit printed). The symbols follow the
note's documented notation: ``\\vec v_{\\mathrm{C}}`` is the velocity of point C,
``\\omega_{\\mathrm{rod}}`` the rod's angular velocity, ``\\vec F_{\\mathrm{crank},
\\mathrm{rod}}`` the force of the crank on the rod, and so on.
"""

from __future__ import annotations

import html
import math
import re
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.explain import Note, explain

from .test_html import browser  # noqa: F401 (the headless Chromium fixture)

EXAMPLES = Path(__file__).parent.parent / "examples"
EXERCISE = EXAMPLES / "slider_crank_exercise.toml"

# every example at a few positions (the five-bar takes one position per driver)
CASES = [
    ("slider_crank_exercise", 45.0),
    ("slider_crank_exercise", 200.0),
    ("six_bar_lecture", 30.0),
    ("six_bar_lecture", 250.0),
    ("four_bar", 100.0),
    ("offset_slider_crank", 300.0),
    ("whitworth", 60.0),
    ("whitworth", 210.0),
    ("scotch_yoke", 30.0),
    ("slot_mechanism", 120.0),
    ("lever_var9", 80.0),
    ("tenbar", 36.0),
    ("class3", 20.0),
    ("five_bar_two_cranks", (40.0, 100.0)),
]


def tex(name: str) -> str:
    """A name from the file as the note sets it (upright)."""
    special = {"_": r"\_", "{": r"\{", "}": r"\}", "$": r"\$", "%": r"\%", "&": r"\&"}
    body = "".join(special.get(c, c) for c in name.replace("~block", " block"))
    return f"\\mathrm{{{body.replace(' ', chr(92) + ' ')}}}"


def point_tex(point: str) -> str:
    if point.endswith(".G"):
        return f"G_{{{tex(point[:-2])}}}"
    return tex(point)


MATH = re.compile(r"\$\$(.*?)\$\$|\$(.*?)\$")
NUMBER = r"-?\d+(?:\.\d+)?(?: \\cdot 10\^\{-?\d+\})?"
VECTOR = re.compile(rf"^\(({NUMBER}),\\ ({NUMBER})\)")
SCALAR = re.compile(rf"^({NUMBER})")


def number(text: str) -> tuple[float, float]:
    """A printed number and half a unit of its last digit."""
    m = re.fullmatch(r"(-?\d+)(?:\.(\d+))?(?: \\cdot 10\^\{(-?\d+)\})?", text)
    assert m, text
    whole, decimals, exponent = m.groups()
    places = len(decimals or "")
    scale = 10.0 ** int(exponent or 0)
    value = float(f"{whole}.{decimals or 0}") * scale
    return value, 0.5 * 10.0 ** (-places) * scale


def statements(markdown: str) -> list[tuple[str, str]]:
    """Every ``lhs = ... = last`` of the note's mathematics: (lhs, last)."""
    found = []
    for display, inline in MATH.findall(markdown):
        for part in re.split(r",\\quad |\\quad ", (display or inline).strip()):
            pieces = part.split(" = ")
            if len(pieces) >= 2:
                found.append((pieces[0].strip(), pieces[-1].strip()))
    return found


def expected(table: assur.Table) -> dict[str, tuple[float, ...]]:
    """The table's value of every symbol the note may print, by its TeX."""
    plan = table.plan
    row = {c: float(table[c][0]) for c in table.columns}
    out: dict[str, tuple[float, ...]] = {}
    points = list(plan.points)
    for pair in plan.pairs.values():
        if pair.kind == "R" and not pair.virtual:
            points.append(pair.name)
    for p in dict.fromkeys(points):
        t = point_tex(p)
        out[f"\\vec r_{{{t}}}"] = (row[f"{p}.x"], row[f"{p}.y"])
        for letter, (x, y) in (("v", ("vx", "vy")), ("a", ("ax", "ay"))):
            v = (row[f"{p}.{x}"], row[f"{p}.{y}"])
            out[f"\\vec {letter}_{{{t}}}"] = v
            out[f"{letter}_{{{t}}}"] = (math.hypot(*v),)
    for link in plan.bodies[1:]:
        if "~" in link:
            continue
        t = tex(link)
        out[f"\\omega_{{{t}}}"] = (row[f"{link}.omega"],)
        out[f"\\varepsilon_{{{t}}}"] = (row[f"{link}.alpha"],)
        out[f"\\varphi_{{{t}}}"] = (row[f"{link}.angle"],)
        if f"{link}.Fi.x" in row:
            f = (row[f"{link}.Fi.x"], row[f"{link}.Fi.y"])
            out[f"\\vec F_{{i,{t}}}"] = f
            out[f"F_{{i,{t}}}"] = (math.hypot(*f),)
            out[f"M_{{i,{t}}}"] = (row[f"{link}.Mi"],)
    for name, pair in plan.pairs.items():
        if pair.kind == "P" and not pair.virtual:
            out[f"\\dot s_{{{tex(name)}}}"] = (row[f"{name}.v"],)
            out[f"\\ddot s_{{{tex(name)}}}"] = (row[f"{name}.a"],)
        if "A.Fx" not in row and f"{plan.drivers[0].pair.name}.Fx" not in row:
            continue
        joint = name.split("~")[0]
        f = (row[f"{joint}.Fx"], row[f"{joint}.Fy"])
        a, b = (plan.bodies[x] for x in (pair.first, pair.second))
        for by, on, sign in ((a, b, 1.0), (b, a, -1.0)):
            symbol = f"F_{{{tex(by)},{tex(on)}}}"
            out[f"\\vec {symbol}"] = (sign * f[0], sign * f[1])
            out[symbol] = (math.hypot(*f),)
        if pair.kind == "P" and not pair.virtual:
            out[f"M_{{{tex(name)}}}"] = (row[f"{name}.M"],)
    out.update(_friction_expected(table, row))
    if "driver.torque" in row:
        out["M_{b}"] = out["M_{b}^{\\mathrm{lever}}"] = (row["driver.torque"],)
    if "driver.force" in row:
        out["F_{b}"] = out["F_{b}^{\\mathrm{lever}}"] = (row["driver.force"],)
    for d in plan.drivers:
        what = "torque" if d.kind == "R" else "force"
        letter = "M" if d.kind == "R" else "F"
        key = f"{d.pair.name}.{what}"
        if key in row:
            sym = f"{letter}_{{b,{tex(d.pair.name)}}}"
            out[sym] = out[f"{sym}^{{\\mathrm{{lever}}}}"] = (row[key],)
            if f"{key}_ideal" in row:
                out[f"{sym}^{{\\mathrm{{ideal}}}}"] = (row[f"{key}_ideal"],)
    return out


def _friction_expected(
    table: assur.Table, row: dict[str, float]
) -> dict[str, tuple[float, ...]]:
    """The friction symbols' values: each pair's load, the ideal load, the losses."""
    out: dict[str, tuple[float, ...]] = {}
    for name in table.plan.pairs:
        t = tex(name)
        if f"{name}.Mf" in row:
            out[f"M_{{f,{t}}}"] = (row[f"{name}.Mf"],)
        if f"{name}.Ff" in row:
            out[f"F_{{f,{t}}}"] = (row[f"{name}.Ff"],)
            # the normal force's size: the reaction without its friction
            size = math.sqrt(
                max(row[f"{name}.Fx"] ** 2 + row[f"{name}.Fy"] ** 2
                    - row[f"{name}.Ff"] ** 2, 0.0)
            )  # fmt: skip
            out[f"|N_{{{t}}}|"] = out[f"\\vert N_{{{t}}}\\vert"] = (size,)
    if "driver.torque_ideal" in row:
        out["M_{b}^{\\mathrm{ideal}}"] = (row["driver.torque_ideal"],)
    if "driver.force_ideal" in row:
        out["F_{b}^{\\mathrm{ideal}}"] = (row["driver.force_ideal"],)
    if "friction.power" in row and len(table.plan.drivers) == 1:
        out["\\sum P_{f}"] = (row["friction.power"],)
    return out


def printed(last: str) -> tuple[tuple[float, float], ...] | None:
    """The value(s) a statement ends with, each with its rounding; None if none."""
    last = last.replace("^\\circ", "")
    m = VECTOR.match(last)
    if m:
        return number(m.group(1)), number(m.group(2))
    m = SCALAR.match(last)
    if m and not last[m.end() :].lstrip().startswith(("\\cdot", "+", "-", "(")):
        return (number(m.group(1)),)
    return None


def check(note: Note, table: assur.Table) -> dict[str, int]:
    """Compare every printed value that names a table quantity; count them by kind."""
    values = expected(table)
    counts: dict[str, int] = {}
    for lhs, last in statements(str(note)):
        if lhs not in values:
            continue
        found = printed(last)
        if found is None:
            continue
        want = values[lhs]
        assert len(found) == len(want), (lhs, last)
        for (got, half), ref in zip(found, want, strict=True):
            if lhs.startswith("\\varphi"):
                ref = (ref - got + 180.0) % 360.0 - 180.0 + got
            scale = max(abs(ref), 1.0)
            assert abs(got - ref) <= half + 1e-9 * scale + 1e-12, (lhs, last, ref)
        kind = re.sub(r"_\{.*", "", lhs)
        counts[kind] = counts.get(kind, 0) + 1
    return counts


def _table(stem: str, angle) -> tuple[assur.Mechanism, assur.Table]:
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    at = np.atleast_1d(np.asarray(angle, dtype=float))[None, :]
    at = at if at.shape[1] > 1 else at[:, 0]
    try:
        return mech, assur.forces(mech, at)
    except assur.ModelError:
        return mech, assur.kinematics(mech, at)


@pytest.mark.parametrize(("stem", "angle"), CASES)
def test_every_number_agrees_with_the_table(stem: str, angle) -> None:
    mech, table = _table(stem, angle)
    note = explain(mech, angle)
    counts = check(note, table)
    plan = table.plan
    moving = [b for b in plan.bodies[1:] if "~" not in b]
    # every link's angular velocity and acceleration is printed and checked
    assert counts.get("\\omega", 0) >= len(moving)
    assert counts.get("\\varepsilon", 0) >= len(moving)
    assert counts.get("\\vec v", 0) >= len(plan.groups)
    assert counts.get("\\vec a", 0) >= len(plan.groups)
    if table.force_state is not None:
        # every joint's reaction, and the balancing load by both methods
        joints = [p for p in plan.pairs.values() if not p.virtual]
        assert counts.get("\\vec F", 0) >= len(joints)
        balancing = sum(v for k, v in counts.items() if k in ("M", "F") or "b" in k)
        assert balancing >= 2 * len(plan.drivers)


# a cut from 120 to 240 deg and a torque stepping down at 240 deg (a backslash at a
# line's end joins the lines in the string: TOML's inline tables take one line)
STEPPED = """
[[loads]]
link = "slider"
at = "C"
force = { x = [0.0, 0.0, -1000.0, -1000.0, 0.0], y = [0.0, 0.0, 0.0, 0.0, 0.0], \
over = "driver", table = [0.0, 120.0, 120.0, 240.0, 240.0] }

[[loads]]
link = "crank"
torque = { values = [5.0, 5.0, 2.0, 2.0], over = "driver", table = [0.0, 240.0, \
240.0, 360.0] }
"""


CUT = "(-1000,\\ 0)\\ \\mathrm{N}"
"""The cut as the note writes it."""


@pytest.mark.parametrize(
    ("angle", "said"),
    [
        # 120 and 240 deg come back from radians a unit of the last place low
        (120.0, [CUT, "steps here, from }(0,\\ 0)\\ \\mathrm{N}"]),
        (
            240.0,
            [
                "Q_{\\mathrm{slider},1} = (0,\\ 0)\\ \\mathrm{N}",
                "steps here, from }(-1000,\\ 0)\\ \\mathrm{N}",
                "T_{\\mathrm{crank},1} = 2\\ \\mathrm{N\\,m}",
                "steps here, from }5\\ \\mathrm{N\\,m}",
            ],
        ),
        (480.0, [CUT, "steps here, from }(0,\\ 0)\\ \\mathrm{N}"]),
        (180.0, []),
    ],
)
def test_a_load_at_its_table_s_step_says_which_side(tmp_path, angle, said) -> None:
    # the value after the step holds at its position, the table's as the note's
    path = tmp_path / "stepped.toml"
    path.write_text(EXERCISE.read_text(encoding="utf-8") + STEPPED, encoding="utf-8")
    mech = assur.load(path)
    note = explain(mech, angle)
    check(note, assur.forces(mech, [angle]))
    text = str(note)
    for words in said:
        assert words in text
    assert text.count("(its table steps here, from ") == len(said) // 2


def test_the_lecture_exercise_at_45_degrees() -> None:
    note = str(explain(assur.load(EXERCISE), 45.0))
    for text in (
        r"F_{i,\mathrm{crank}} = m_{\mathrm{crank}} a_{G_{\mathrm{crank}}} = 10 \cdot "
        r"800 = 8000\ \mathrm{N}",
        r"F_{i,\mathrm{rod}} = m_{\mathrm{rod}} a_{G_{\mathrm{rod}}} = 0.5 \cdot "
        r"2565.13 = 1282.57\ \mathrm{N}",
        r"-0.0018 \cdot 10046.13 = -18.08\ \mathrm{N\,m}",
        r"= 0.4 \cdot 2134.73 = 853.89\ \mathrm{N}",
        r"M_{b} = -\sum M_{\mathrm{A}} = 84.63\ \mathrm{N\,m}",
        r"M_{b}^{\mathrm{lever}} = -\frac{\sum P}{\omega} = -\frac{-16925}{200} "
        r"= 84.63",
    ):
        assert text in note, text
    # the RRP group's reactions: the crank's on the rod, the guide's on the slider
    assert r"\vec F_{\mathrm{crank},\mathrm{rod}} = (-1906.66,\ -289.39)" in note
    assert r"\vec F_{\mathrm{ground},\mathrm{slider}} = (0,\ -443.17)" in note
    assert (
        r"= (853.89,\ -443.17)\ \mathrm{N},\quad F_{\mathrm{slider},\mathrm{rod}}"
        in note
    )


# ------------------------------------------------------------- the given answers


ANSWERS = Path(__file__).parent.parent / "docs" / "files"
LECTURE_ANSWERS = ANSWERS / "slider_crank_exercise_answers.toml"


def test_the_lecture_s_slip_is_found() -> None:
    from assur.explain import read_answers

    answers, source = read_answers(LECTURE_ANSWERS)
    note = str(explain(assur.load(EXERCISE), 45.0, answers, source))
    part = note.split("## 7. The given answers")[1]
    assert (
        "| rod.Fi | $1283.45$ | $1282.57$ | $\\mathrm{N}$ | $+0.069$ % | differs |"
        in part
    )
    assert "| rod.G.a | $2565.12$ | $2565.13$ |" in part
    assert "agrees" in part.split("rod.Fi")[0]
    # the lecture's product is off, not its acceleration
    assert r"m a_G = 0.5 \cdot 2565.132 = 1282.566" in part
    assert r"m a_G = 0.5 \cdot 2565.12 = 1282.560" in part
    assert "slip in the given multiplication" in part


def test_an_answer_that_names_nothing_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(assur.ModelError, match=r"answers\.rod\.zz: no such quantity"):
        explain(assur.load(EXERCISE), 45.0, {"rod.zz": 1.0})
    bad = tmp_path / "bad.toml"
    bad.write_text('[answers]\n"rod.Fi" = "many"\n', encoding="utf-8")
    from assur.explain import read_answers

    with pytest.raises(assur.ModelError, match=r"answers\.rod\.Fi: expected a finite"):
        read_answers(bad)


# ------------------------------------------------------------ the command line


def test_command_line_writes_markdown_html_and_latex(tmp_path: Path, capsys) -> None:
    from assur.cli import main

    assert main(["explain", str(EXERCISE), "--angle", "45"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("# Slider-crank exercise")
    assert r"M_{b} = -\sum M_{\mathrm{A}} = 84.63" in out
    for suffix in ("md", "html", "tex"):
        target = tmp_path / f"note.{suffix}"
        assert main(["explain", str(EXERCISE), "--angle", "45", "-o", str(target)]) == 0
        assert target.read_text(encoding="utf-8")
    assert (tmp_path / "note.md").read_text(encoding="utf-8") == out
    assert (
        main(["explain", str(EXERCISE), "--angle", "45", "-o", str(tmp_path / "n.pdf")])
        == 2
    )
    assert "unknown type of note '.pdf'" in capsys.readouterr().err
    assert main(["explain", str(EXERCISE), "--angle", "0:90:45"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "expected one value per driver" in err
    assert not (tmp_path / "n.pdf").exists()


def test_command_line_writes_the_note_to_standard_output_for_a_dash(
    tmp_path: Path, capsys, monkeypatch
) -> None:
    # "-o -" said "unknown type of note '(none)'", though the note goes there anyway
    from assur.cli import main

    monkeypatch.chdir(tmp_path)
    assert main(["explain", str(EXERCISE), "--angle", "45"]) == 0
    alone = capsys.readouterr().out
    assert main(["explain", str(EXERCISE), "--angle", "45", "-o", "-"]) == 0
    out, err = capsys.readouterr()
    assert (out, err) == (alone, "")
    assert list(tmp_path.iterdir()) == []


def test_a_note_to_a_folder_is_refused_as_such(tmp_path: Path, capsys) -> None:
    # "unknown type of note '(none)'", or "cannot write the file" with no more
    from assur.cli import main

    for name in ("notes", "note.md"):
        folder = tmp_path / name
        folder.mkdir()
        assert main(["explain", str(EXERCISE), "-o", str(folder)]) == 2
        err = capsys.readouterr().err
        assert err.endswith(
            f"-o {folder}: is a folder; expected a file name ending in .md, .html or "
            ".tex\n"
        )


def test_command_line_compares_answers(capsys) -> None:
    from assur.cli import main

    args = [
        "explain",
        str(EXERCISE),
        "--angle",
        "45",
        "--answers",
        str(LECTURE_ANSWERS),
    ]
    assert main(args) == 0
    assert "slip in the given multiplication" in capsys.readouterr().out


def test_a_wrong_answer_key_names_the_answers_file(capsys, tmp_path) -> None:
    from assur.cli import main

    answers = tmp_path / "mine.toml"
    answers.write_text('[answers]\n"rod.omegaa" = 5.0\n', encoding="utf-8")
    argv = ["explain", str(EXERCISE), "--angle", "45", "--answers", str(answers)]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err == (
        f"assur: error: {answers}: answers.rod.omegaa: no such quantity (did you "
        "mean 'rod.omega'?); expected a table column, 'P.v' or 'P.a' (a point's "
        "speed, acceleration) or 'L.Fi' (a link's inertia force)\n"
    )
    assert main([*argv[:-1], str(tmp_path / "none.toml")]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"assur: error: {tmp_path / 'none.toml'}: cannot read")
    # an endless file is not read to the end (/dev/zero ran out of memory)
    assert main([*argv[:-1], "/dev/zero"]) == 2
    err = capsys.readouterr().err
    assert err == (
        "assur: error: /dev/zero: larger than 1 MiB; expected a file of given "
        "answers (a few lines of TOML)\n"
    )


# ---------------------------------------------------------------- HTML and LaTeX


def _every_math(page: str) -> list[str]:
    return re.findall(r"<math\b.*?</math>", page, re.S)


def test_every_equation_of_the_html_note_carries_its_tex_as_alternative_text() -> None:
    # a screen reader without MathML met none of the note's 181 equations in words
    import xml.etree.ElementTree as ET

    note = explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 45.0)
    maths = _every_math(note.to_html())
    alts = [ET.fromstring(m).get("alttext") for m in maths]
    pieces = [m.group(1) or m.group(2) for m in MATH.finditer(str(note))]
    assert len(maths) > 50
    assert alts == [" ".join(p.split()) for p in pieces]


def test_an_equation_s_alternative_text_is_its_tex_in_one_line_and_well_quoted():
    # the slider-crank's note above has no quote and no run of spaces in its TeX:
    # the helper itself is held to both
    import xml.etree.ElementTree as ET

    from assur.explain._html import math

    element = math('x_{1}  +\n  \\text{"a" & b} < 2', display=True)
    assert ET.fromstring(element).get("alttext") == 'x_{1} + \\text{"a" & b} < 2'


@pytest.mark.parametrize("stem", ["slider_crank_exercise", "class3", "whitworth"])
def test_html_note_is_offline_and_its_mathml_well_formed(stem: str) -> None:
    import xml.etree.ElementTree as ET

    note = explain(assur.load(EXAMPLES / f"{stem}.toml"), 45.0)
    page = note.to_html()
    assert page.startswith("<!DOCTYPE html>")
    assert page.rstrip().endswith("</html>")
    assert re.search(r"https?://", page) is None
    assert re.search(r"<(script|link|img|iframe)\b|\bsrc\s*=|@import", page) is None
    maths = _every_math(page)
    markdown = str(note)
    # one <math> per piece of mathematics of the Markdown
    assert len(maths) == len(MATH.findall(markdown))
    for m in maths:
        ET.fromstring(m)  # well formed
    assert "$" not in re.sub(r"<math\b.*?</math>", "", page, flags=re.S).replace(
        "\\$", ""
    )


def test_mathml_of_the_constructs() -> None:
    from assur.explain._mathml import mathml

    assert mathml(r"\frac{a}{b}") == (
        "<math><mfrac><mrow><mi>a</mi></mrow><mrow><mi>b</mi></mrow></mfrac></math>"
    )
    assert "<msqrt>" in mathml(r"\sqrt{2}")
    assert '<mover accent="true"><mi>v</mi><mo>→</mo></mover>' in mathml(r"\vec v")
    assert "<mtext>left_crank</mtext>" in mathml(r"\mathrm{left\_crank}")
    # a function's name set apart from its argument: "tan38.79" ran together
    assert '<mi>tan</mi><mspace width="0.17em"/><mn>38.79</mn>' in mathml(r"\tan 38.79")
    with pytest.raises(ValueError, match="knows no"):
        mathml(r"\unknowncommand")
    with pytest.raises(ValueError, match="not closed"):
        mathml(r"\frac{a}{b")


def test_a_minus_sign_hugs_its_number_and_a_subtraction_does_not() -> None:
    # every minus was an infix operator, spaced on both sides: "( - 2960, 0)"
    from assur.explain._mathml import mathml

    sign, minus = '<mo form="prefix">−</mo>', "<mo>−</mo>"
    got = mathml(r"(0,\ 0) - 200^2 \cdot (-0.074,\ -1) = -\frac{-3}{2}")
    assert got.count(minus) == 1
    assert got.count(sign) == 4
    assert "-" not in re.sub(r"<[^>]*>", "", got)  # the minus sign, not a hyphen


def test_the_report_s_display_equations_keep_their_mathematical_layout() -> None:
    # display: block made Chromium lay a block equation out as text, one symbol
    # under another; block math is the display of a block <math>
    from importlib.resources import files

    css = files("assur.html").joinpath("report.css").read_text(encoding="utf-8")
    for rule in re.findall(r"math\[display=\"block\"\]\s*\{([^}]*)\}", css):
        for shown in re.findall(r"(?<![-\w])display:\s*([^;]+);", rule):
            assert shown.strip() == "block math"


NBSP, THIN = "\u00a0", "\u2009"


def test_mathml_text_keeps_its_spaces() -> None:
    # lines the note writes; a browser drops a token's edge spaces, hence NBSP
    from assur.explain._mathml import mathml

    assert mathml(r"\text{the point of ground at } C") == (
        f"<math><mtext>the point of ground at{NBSP}</mtext><mi>C</mi></math>"
    )
    assert "<mtext>(joint C)</mtext>" in mathml(r"F \quad \text{(joint C)}")
    assert mathml(r"\text{from } C \text{ to } B") == (
        f"<math><mtext>from{NBSP}</mtext><mi>C</mi>"
        f"<mtext>{NBSP}to{NBSP}</mtext><mi>B</mi></math>"
    )
    against = mathml(r"\text{at } 45^\circ \text{ (against } \vec a_G\text{)}")
    assert f"<mtext>at{NBSP}</mtext><msup><mn>45</mn><mo>°</mo></msup>" in against
    assert f"<mtext>{NBSP}(against{NBSP}</mtext>" in against
    assert "<mtext>forces on left_rocker along x</mtext>" in mathml(
        r"\text{forces on left\_rocker along x}:\ 1 = 1"
    )


def test_mathml_units_are_spaced_and_raised() -> None:
    from assur.explain._mathml import mathml

    torque = mathml(r"M_{i} = -18.08\ \mathrm{N\,m}")
    assert torque.endswith(
        f'<mn>18.08</mn><mspace width="0.25em"/><mtext>N{THIN}m</mtext></math>'
    )
    for unit in ("m", "rad"):
        assert mathml(rf"\mathrm{{{unit}/s^2}}") == (
            f"<math><mrow><mtext>{unit}/</mtext>"
            "<msup><mtext>s</mtext><mn>2</mn></msup></mrow></math>"
        )
    assert mathml(r"\mathrm{B\ block}") == "<math><mtext>B block</mtext></math>"
    assert mathml(r"\mathrm{a\hat{}b}") == "<math><mtext>a^b</mtext></math>"
    assert mathml(r"x\;y\quad z") == (
        '<math><mi>x</mi><mspace width="0.28em"/><mi>y</mi>'
        '<mspace width="1em"/><mi>z</mi></math>'
    )


TEXT_OR_ROMAN = re.compile(r"\\(?:text|mathrm)\{((?:[^{}]|\\[{}])*)\}")


@pytest.mark.parametrize("stem", ["slider_crank_exercise", "class3", "tenbar"])
def test_html_note_sets_every_text_and_unit(stem: str) -> None:
    # every \text{} and \mathrm{} of the note, read back from its MathML
    note = explain(assur.load(EXAMPLES / f"{stem}.toml"), 45.0)
    page = note.to_html()
    shown = {
        html.unescape(t).replace(NBSP, " ").replace(THIN, r"\,")
        for t in re.findall(r"<mtext>([^<]*)</mtext>", page)
    }
    written = {
        re.sub(r"\\([_{}$%&#])", r"\1", t).replace(r"\ ", " ")
        for t in TEXT_OR_ROMAN.findall(str(note))
        if "^" not in t
    }
    assert written - shown == set()
    # the TeX is the equations' alternative text alone
    assert "s^2" not in re.sub(r' alttext="[^"]*"', "", page)
    assert page.count("<msup><mtext>s</mtext><mn>2</mn></msup>") > 0


@pytest.mark.parametrize(
    ("stem", "angle"),
    [
        ("slider_crank_exercise", 45.0),
        ("class3", 20.0),
        ("five_bar_two_cranks", (40.0, 100.0)),
    ],
)
def test_latex_note_compiles(stem: str, angle, tmp_path: Path) -> None:
    import shutil
    import subprocess

    pdflatex = shutil.which("pdflatex")
    if pdflatex is None:
        pytest.skip("pdflatex not found (apt-get install texlive-latex-recommended)")
    source = tmp_path / "note.tex"
    explain(assur.load(EXAMPLES / f"{stem}.toml"), angle).write(source)
    result = subprocess.run(
        [pdflatex, "-interaction=nonstopmode", "-halt-on-error", source.name],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=180,
    )
    assert result.returncode == 0, result.stdout[-2000:]
    assert (tmp_path / "note.pdf").stat().st_size > 10_000


@pytest.mark.browser
def test_html_note_renders_in_a_browser(browser, tmp_path: Path) -> None:  # noqa: F811
    # headless Chromium lays the MathML out offline (skips without Chromium)
    path = tmp_path / "note.html"
    explain(assur.load(EXERCISE), 45.0).write(path)
    browser.get(path.as_uri())
    count = browser.execute_script("return document.querySelectorAll('math').length")
    assert count == len(_every_math(path.read_text(encoding="utf-8")))
    heights = browser.execute_script(
        "return Array.from(document.querySelectorAll('mfrac'))"
        ".map(e => e.getBoundingClientRect().height)"
    )
    assert heights
    assert min(heights) > 0


def test_html_report_holds_the_note() -> None:
    from assur.html import render_report

    page = render_report(assur.load(EXERCISE), angles=[45.0, 90.0])
    assert '<section class="card wide" id="note">' in page
    section = page.split('id="note"')[1].split("</section>")[0]
    assert "Inertia loads" in section
    assert "group by group" in section
    assert section.count("<math") > 50
    assert f"<mtext>N{THIN}m</mtext>" in section  # the note's units, as on its page
    assert re.search(r"https?://", page) is None


@pytest.mark.pictures
def test_plot_draws_one_group_s_free_body(tmp_path: Path, capsys) -> None:
    from assur.cli import main

    six = EXAMPLES / "six_bar_lecture.toml"
    out = tmp_path / "group.png"
    assert (
        main(["plot", str(six), "--angle", "45", "--group", "2", "-o", str(out)]) == 0
    )
    assert out.stat().st_size > 10_000
    assert main(["plot", str(six), "--group", "3", "-o", str(out)]) == 2
    assert "expected 1 to 2" in capsys.readouterr().err
    # one group: "expected 1 to 1" it said
    slider = EXAMPLES / "slider_crank_exercise.toml"
    assert main(["plot", str(slider), "--group", "0", "-o", str(out)]) == 2
    assert capsys.readouterr().err.endswith(
        ": --group 0: the mechanism has 1 Assur group; expected --group 1\n"
    )


@pytest.mark.parametrize("angle", ["x", [10.0, 20.0], float("nan")])
def test_an_angle_that_is_not_one_position_is_a_usage_error(angle) -> None:
    # the argument is one angle: named so ("angles:" before)
    with pytest.raises(assur.UsageError, match=r"^angle: "):
        assur.explain(assur.catalog.four_bar(), angle)


def test_text_for_an_angle_and_a_path_that_is_no_file_are_told_so() -> None:
    with pytest.raises(assur.UsageError, match=r"^angle: .*got text '30'$"):
        assur.explain(assur.catalog.four_bar(), "30")
    # one position of two drivers: two numbers, not "an array of shape (n, 2)"
    five = assur.load(EXAMPLES / "five_bar_two_cranks.toml")
    with pytest.raises(assur.UsageError, match=r"expected one position, 2 numbers"):
        assur.explain(five, 30.0)
    note = assur.explain(assur.catalog.four_bar(), 30.0)
    for path in (None, 3):
        with pytest.raises(assur.UsageError, match=r"^path: expected a file name"):
            note.write(path)  # type: ignore[arg-type]


def test_given_answers_round_off_nan_and_dotted_keys(tmp_path):
    # a given 0 against the note's round-off (1.4e-17) was "-100 % differs"; NaN was
    # taken; an unquoted dotted key was refused as a table
    from assur.explain import read_answers
    from assur.explain._answers import _verdict

    path = tmp_path / "a.toml"
    path.write_text('[answers]\nB.F = 1928.5\n"rod.G.a" = 2565.13\n', encoding="utf-8")
    assert read_answers(path)[0] == {"B.F": 1928.5, "rod.G.a": 2565.13}
    assert _verdict(0.0, 1.4e-17) == ("", "agrees")
    assert _verdict(1.0, 1.4e-17) == ("", "differs")
    assert _verdict(1.0, float("nan")) == ("", "undefined here")
    assert _verdict(-1.1, -1.0)[0] == "$-10.000$ %"  # below the note's value
    assert _verdict(1e308, 2.0)[0] == "$+5.00e+309$ %"  # not 300 digits, not inf
    assert _verdict(2e4, 1.0)[0] == "$+2.00e+06$ %"
    for bad in ("nan", "inf", "1" + "0" * 400):
        path.write_text(f'[answers]\n"B.x" = {bad}\n', encoding="utf-8")
        with pytest.raises(assur.ModelError, match="expected a finite number"):
            read_answers(path)
    path.write_bytes(b'[answers]\n"B.x" = 1 # \xff\n')
    with pytest.raises(assur.ModelError) as caught:
        read_answers(path)
    # as the mechanism file's fault is told, not in the codec's words
    assert str(caught.value) == (
        f"{path}: not UTF-8 text (byte 0xFF at line 2, column 13 cannot be decoded); "
        "expected a TOML file of given answers saved as UTF-8"
    )
    path.write_bytes('[answers]\n"B.x" = 1\n'.encode("utf-16"))
    with pytest.raises(assur.ModelError, match=r"UTF-16 text \(it starts with"):
        read_answers(path)
    path.write_text("[answers]\n", encoding="utf-8")
    with pytest.raises(assur.ModelError, match=r"\[answers\] is empty; expected"):
        read_answers(path)


def test_answers_from_standard_input_are_refused(capsys) -> None:
    from assur.cli import main

    status = main(["explain", str(EXERCISE), "--angle", "45", "--answers", "-"])
    assert status == 2
    assert capsys.readouterr().err == (
        f"assur: error: {EXERCISE}: --answers -: standard input is not read for "
        "answers; expected a file\n"
    )


def test_the_note_says_whether_the_balancing_torque_drives_or_brakes() -> None:
    # its sign alone does not tell: 84.63 N m drives the crank at +200 rad/s and
    # brakes the same crank turned clockwise (the clockwise one's inertia loads)
    import dataclasses

    mech = assur.load(EXERCISE)
    note = str(explain(mech, 45.0))
    assert "$M_{b} = 84.63\\ \\mathrm{N\\,m}$. It drives the link" in note
    back = dataclasses.replace(
        mech, drivers=(dataclasses.replace(mech.drivers[0], omega=-200.0),)
    )
    torque = float(assur.forces(back, [45.0])["driver.torque"][0])
    said = "It brakes the link" if torque > 0 else "It drives the link"
    assert said in str(explain(back, 45.0))


def test_a_motion_that_is_not_finite_is_refused_by_name(tmp_path, capsys) -> None:
    from assur.cli import main

    # the slider of this file turns at 1e161 rad/s: the note's scale of the
    # motion overflowed (a traceback), and the plans blamed their folder
    path = Path(__file__).parent / "data" / "fuzz" / "tiny_link_overflow.toml"
    with (
        pytest.warns(assur.AssurWarning, match="not finite"),
        pytest.raises(assur.ModelError) as caught,
    ):
        explain(assur.load(path), 45.0)
    assert str(caught.value) == (
        "the motion of rod and slider is not finite at driver position 45 deg: the "
        "inputs are out of the range the arithmetic can follow; expected a position "
        "(or inputs) where it is"
    )
    for argv in (["explain", str(path)], ["plans", str(path), "-o", str(tmp_path)]):
        assert main(argv) == 2
        err = capsys.readouterr().err.splitlines()
        assert err[-1] == f"assur: error: {path}: {caught.value}"
        assert all(line.startswith("assur: ") for line in err)  # no numpy's words


def test_a_small_link_s_inertia_loads_are_its_own_not_round_off():
    # a crank of 5.16e-13 kg m^2 beside links of 1e-3: the note wrote its
    # inertia torque "-0 * 10 = 0", and listed it so among the group's loads
    four_bar = Path(__file__).parent.parent / "examples" / "four_bar.toml"
    text = four_bar.read_text(encoding="utf-8")
    mech = assur.loads(text.replace("inertia = 5.16e-05", "inertia = 5.16e-13"))
    note = str(explain(mech, 0.0))
    assert (
        "M_{i,\\mathrm{crank}} = -J_{G_{\\mathrm{crank}}} "
        "\\varepsilon_{\\mathrm{crank}} = -5.16 \\cdot 10^{-13} \\cdot 10 = "
        "-5.16 \\cdot 10^{-12}\\ \\mathrm{N\\,m}"
    ) in note
    assert "M_{i,\\mathrm{crank}} = -5.16 \\cdot 10^{-12}\\ \\mathrm{N\\,m}" in note
    assert "M_{i,\\mathrm{crank}} = 0\\ " not in note


SCIENTIFIC = re.compile(r"(-?\d+(?:\.\d+)?) \\cdot 10\^\{(-?\d+)\}")
FIGURE = re.compile(r"(?<![\w.^])-?\d+(?:\.\d+)?(?:e-?\d+)?")


def _zeros(note: str) -> list[list[bool]]:
    """Which numbers of each line of a note are written 0."""
    lines = (SCIENTIFIC.sub(r"\1e\2", line) for line in note.splitlines())
    return [[float(x) == 0.0 for x in FIGURE.findall(line)] for line in lines]


@pytest.mark.parametrize("small", [1e-3, 1e-5])
def test_a_small_mechanism_s_note_writes_0_where_a_full_size_one_does(small):
    # a four-bar a thousand times smaller (a watch's): its balancing torque, the
    # sums of moments and the powers of the lever were written 0 (below an absolute
    # 1e-9), where its full-size twin writes 0.02432 N m
    sizes = {"crank": 0.04, "coupler": 0.12, "rocker": 0.08, "frame": 0.10}
    for angle in (30.0, 135.0):
        full = str(explain(assur.catalog.four_bar(), angle))
        less = {name: value * small for name, value in sizes.items()}
        note = str(explain(assur.catalog.four_bar(**less), angle))
        assert _zeros(note) == _zeros(full)
        assert "M_{b} = -\\sum M_{\\mathrm{A}} = 0\\ " not in note


def test_a_small_load_couple_is_written_as_it_is():
    # a torque of -4e-12 N m on a link: its own, not round-off, in the sum of
    # moments and on the lever
    bearings = EXAMPLES / "four_bar_bearings.toml"
    text = bearings.read_text(encoding="utf-8").replace(
        "torque = -4.0", "torque = -4e-12"
    )
    note = str(explain(assur.loads(text), 30.0))
    assert "[(-4 \\cdot 10^{-12})]" in note
    assert "| $-4 \\cdot 10^{-12}$ |" in note


def test_the_note_s_structure_section_refers_to_a_group_explained_before():
    note = str(explain(assur.load(EXAMPLES / "tenbar.toml"), 30.0))
    assert note.count("the same counts as for links 2 and 3 above") == 3


def test_a_slow_small_mechanism_s_kinematics_are_its_own_not_round_off():
    # without masses the note is kinematics alone: a slow crank (1e-4 rad/s) of a
    # four-bar a thousand times smaller has speeds of 1e-9 m/s, told against its own
    import dataclasses

    def bare(mech: assur.Mechanism) -> assur.Mechanism:
        links = tuple(
            dataclasses.replace(link, mass=0.0, center=None, inertia=0.0)
            for link in mech.links
        )
        return dataclasses.replace(mech, links=links)

    sizes = {"crank": 0.04, "coupler": 0.12, "rocker": 0.08, "frame": 0.10}
    small = {name: value * 1e-3 for name, value in sizes.items()}
    full = str(explain(bare(assur.catalog.four_bar(omega=1e-4)), 30.0))
    note = str(explain(bare(assur.catalog.four_bar(omega=1e-4, **small)), 30.0))
    assert "No link has a mass" in note
    assert _zeros(note) == _zeros(full)


def test_a_power_of_ten_is_squared_in_parentheses():
    # "6.536 \cdot 10^{-5}^2" is a double superscript: TeX refuses it, and read
    # as text it is 10^-25
    small = {"crank": 4e-5, "coupler": 1.2e-4, "rocker": 8e-5, "frame": 1e-4}
    note = str(explain(assur.catalog.four_bar(**small), 30.0))
    assert "(6.536 \\cdot 10^{-5})^2" in note
    assert not re.search(r"10\^\{-?\d+\}\^", note)


def test_the_note_says_how_many_drivers_move_the_mechanism():
    one = str(explain(assur.load(EXAMPLES / "tenbar.toml"), 30.0))
    assert "As $W = 1$, one driver moves the mechanism. The input link and" in one
    two = str(explain(assur.load(EXAMPLES / "five_bar_two_cranks.toml"), [30.0, 60.0]))
    assert "As $W = 2$, two drivers move the mechanism. The input links and" in two


def test_a_vector_s_small_components_are_written_in_one_form():
    # "(0.0001894, -1.658 \cdot 10^{-5})": a decimal beside a power of ten
    note = str(explain(assur.load(EXAMPLES / "six_bar_lecture.toml"), 30.0))
    assert "(1.894 \\cdot 10^{-4},\\ -1.658 \\cdot 10^{-5})" in note
