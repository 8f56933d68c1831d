"""Long display equations of the note's HTML set in rows (assur.explain._breaks).

MathML breaks no line, so the note breaks its long chains itself: at ``=`` first,
at the ``+`` and ``-`` between terms where a step is still too wide. Nothing is
lost or added, and each row fits :data:`WIDEST` characters when it can.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

import assur
from assur.explain import explain
from assur.explain._blocks import Display
from assur.explain._breaks import (
    WIDEST,
    broken,
    clauses,
    pieces,
    rows,
    shown_width,
    terms,
)
from assur.explain._html import display
from assur.explain._latex import _aligned
from assur.explain._mathml import mathml

EXAMPLES = Path(__file__).parent.parent / "examples"
DATA = Path(__file__).parent / "data"


def width(tex: str) -> float:
    return shown_width(mathml(tex))


def _lines(stem: str) -> list[str]:
    found = EXAMPLES / f"{stem}.toml"
    mech = assur.load(found if found.exists() else DATA / "explain" / f"{stem}.toml")
    angle = [40.0, 100.0] if len(mech.drivers) > 1 else 45.0
    if mech.joint(mech.drivers[0].joint).kind == "prismatic":
        angle = 0.05  # m
    note = explain(mech, angle)
    return [line for b in note.blocks if isinstance(b, Display) for line in b.lines]


def _bare(tex: str) -> str:
    """``tex`` without its spaces and the quads a break may drop."""
    return re.sub(r"\\q?quad|\\[ ,;]|\s", "", tex)


@pytest.mark.parametrize(
    "stem",
    [
        "class3",
        "six_bar_lecture",
        "five_bar_two_cranks",
        "slider_crank_friction",
        "whitworth",  # a Coriolis line of words: broken at its commas
        "slider_driven",  # -[a + b + ...]: broken inside its brackets
    ],
)
def test_rows_hold_the_whole_equation_and_fit_where_they_can(stem: str) -> None:
    broken = 0
    for tex in _lines(stem):
        assert "".join(pieces(tex)) == tex
        assert "".join(terms(tex)) == tex
        got = rows(tex, width)
        assert _bare("".join(got)) == _bare(tex)
        if width(tex) <= WIDEST:
            assert got == [tex]  # a line that fits is left as it is
            continue
        broken += len(got) > 1
        for row in got:
            # wider only when nothing is left to break it at
            assert width(row) <= WIDEST or [row] == clauses(row) == terms(row, 1), row
        for row in got[1:]:
            # a row goes on from the one before: a step, a term or a statement
            assert row.startswith(("=", "+", "-")) or not row.startswith("\\quad")
    assert broken > 0


def test_a_chain_is_broken_at_its_equals_signs_first() -> None:
    tex = (
        r"\vec a_{\mathrm{C}} = \vec a_{\mathrm{B}} + \varepsilon\,\vec k \times "
        r"\vec r_{\mathrm{BC}} - \omega^2 \vec r_{\mathrm{BC}} = (1.25,\ -2.5) + "
        r"17.95 \cdot \vec k \times (0.1016,\ -0.02894) - 1.5^2 \cdot "
        r"(0.1016,\ -0.02894) = (-2.828,\ -2.828)\ \mathrm{m/s^2},\quad a_C = 4"
    )
    got = rows(tex, width)
    assert got[0].startswith(r"\vec a_{\mathrm{C}} = \vec a_{\mathrm{B}} +")
    assert got[0].rstrip().endswith(r"\vec r_{\mathrm{BC}}")
    assert [row[:9] for row in got[1:]] == ["= (1.25,\\", "= (-2.828"]
    # a statement after \quad stays on the row it fits on
    assert got[-1].endswith(r"\quad a_C = 4")


def test_a_broken_equation_is_one_block_of_rows_named_by_its_whole_tex() -> None:
    tex = " = ".join(["x"] + [f"{k}.125 + {k}.5" for k in range(1, 12)])
    element = ET.fromstring(display(tex))
    assert element.get("display") == "block"
    assert element.get("alttext") == tex
    (table,) = list(element)
    assert table.tag == "mtable"
    cells = [row[0] for row in table]
    assert len(cells) > 1
    # the rows after the first set in from the left, their "=" leading
    assert all(cell[0].tag == "mspace" for cell in cells[1:])
    assert cells[0][0].tag != "mspace"
    assert ET.fromstring(display("x = 1")).find("mtable") is None


def test_a_statement_after_a_quad_starts_its_own_row_without_the_quad() -> None:
    first = " + ".join(f"{k}.125" for k in range(1, 10))
    tex = rf"x = {first},\quad y = {first}"
    got = rows(tex, width)
    assert got == [f"x = {first},", f"y = {first}"]


def test_the_latex_note_breaks_the_same_rows() -> None:
    # multline* with no line break ran a long chain past the margin (17 overfull
    # boxes in this note), stretched a short one across the page, and zigzagged
    # the rows of a long one (first left, middle centred, last right)
    note = explain(assur.load(EXAMPLES / "class3.toml"), 45.0)
    shown = re.findall(
        r"\\begin\{equation\*\}(.*?)\\end\{equation\*\}", note.to_latex(), re.S
    )
    lines = [line for b in note.blocks if isinstance(b, Display) for line in b.lines]
    assert len(shown) == len(lines)
    split = 0
    for tex, body in zip(lines, shown, strict=True):
        if not body.startswith("\\begin{split}"):
            assert body == tex
            continue
        split += 1
        aligned = body.removeprefix("\\begin{split}").removesuffix("\\end{split}")
        parts = aligned.split(" \\\\\n")
        # one alignment point a row: the first row's "=", the "=" a row starts
        # with, or a quad before a row of terms (its sign a binary one: {}+)
        assert all(part.count("&") == 1 for part in parts)
        assert all(p.startswith(("&=", "&\\quad ")) for p in parts[1:])
        got = [re.sub(r"^&(\\quad (\{\})?)?", "", p).replace("&", "") for p in parts]
        assert got == rows(tex, width)
        for part in parts:  # each row's braces closed within it
            assert part.count("{") == part.count("}")
    assert split > 10


@pytest.mark.parametrize(
    "tex",
    [
        r"= (0.1016,\ -0.02894)",  # a vector's second component and its sign
        r"a \approx -b",  # a sign after a relation
        r"a \le -b",
        r"x^-1",  # a row may not end with "^"
    ],
)
def test_a_sign_is_not_taken_for_a_difference(tex: str) -> None:
    # "(0.1016,\ -0.02894)" was split between its two components (the control
    # space was taken for a term), "a \approx" ended a row, and so did "x^", whose
    # MathML could not be made
    assert terms(tex, inside=1) == [tex]


def test_a_row_never_ends_with_a_script_or_a_relation_before_a_sign() -> None:
    long = " + ".join(f"{k}.125" for k in range(1, 9))
    for tex in (f"x^-1 - {long} - {long}", rf"a \approx -{long} \approx -{long}"):
        for row in rows(tex, width):
            mathml(row)  # each row is whole TeX: "x^" raised ValueError
            assert not row.rstrip().endswith(("^", "\\approx"))


@pytest.mark.parametrize("stem", ["class3", "whitworth", "six_bar_lecture"])
def test_no_row_is_a_left_side_alone_and_a_split_equation_goes_on(stem: str) -> None:
    # "a_G_left_rocker" stood alone on its row before "= a_F + ..."; the Coriolis
    # line "a^k = 2|omega| v_r" and its "= 2 * 5.954 * 0.144 = ..." took two rows
    # where one held both
    for tex in _lines(stem):
        got = rows(tex, width)
        assert not (len(got) > 1 and len(pieces(got[0])) == 1 and got[1][0] == "="), got
        if "counter-clockwise" in tex:
            (coriolis,) = [row for row in got if row.startswith("a^k")]
            assert "= 2 \\cdot" in coriolis  # its value on its row


def test_the_rows_of_a_line_set_in_go_on_further_in_than_it() -> None:
    # a Coriolis term's note ("\qquad 2 omega k x v_r: ... turned 90 deg") broke
    # into rows set a quad from the alignment point, a quad left of its first row
    (coriolis,) = [
        tex
        for tex in _lines("whitworth")
        if tex.startswith("\\qquad") and "turns" in tex
    ]
    first, *rest = _aligned(broken(coriolis))
    assert first.startswith("&\\qquad ")
    assert rest
    assert all(row.startswith("&\\qquad \\quad ") for row in rest)


def test_an_equals_sign_in_brackets_is_no_step_and_an_empty_row_no_sign() -> None:
    # "v = (x_0 = 0.1, ...)" was broken before the "=" inside its parentheses,
    # which LaTeX then aligned under the "=" of v
    inner = ", ".join(f"x_{k} = {k}.1234" for k in range(10))
    assert pieces(f"v = ({inner})") == ["v ", f"= ({inner})"]
    # a row of nothing but spaces takes no sign's braces
    assert _aligned(["a = 1", ""]) == ["a &= 1", "&\\quad "]


def test_a_sign_after_words_keeps_its_number_and_rows_align_at_the_equals() -> None:
    # a minus after \text{...} began a row as a subtraction, where the MathML
    # sets it as the number's sign
    words = r"x = 1,\ \text{read at the point where the long link meets the ground } "
    got = broken(words + r"-0.01\ \mathrm{m} \text{ and then more words}")
    assert not any(row.startswith("-") for row in got)
    # a first row whose "=" comes after a statement's words aligns at that "="
    first = r"\text{at } B \quad a = 1 + 2"
    assert _aligned([first, "= 3"]) == [r"\text{at } B \quad a &= 1 + 2", "&= 3"]


def test_a_bracket_in_words_does_not_hold_a_row_together() -> None:
    # "\text{(its table, read at } 250 ... \text{)}": the "(" in the words was
    # counted open for the rest of the row, which then could not be broken
    note = explain(assur.load(DATA / "explain" / "load_tables.toml"), 250.0)
    lines = [line for b in note.blocks if isinstance(b, Display) for line in b.lines]
    tables = [line for line in lines if "its table" in line]
    assert tables
    for tex in tables:
        assert all(width(row) <= WIDEST for row in rows(tex, width)), tex


def test_a_fence_of_left_and_right_closes_as_it_opens() -> None:
    # the ")" of \right) was taken for a bracket closing none: no term after it
    # could start a row
    assert terms(r"x = \left(a - b\right) + c - d") == [
        r"x = \left(a - b\right) ",
        "+ c ",
        "- d",
    ]
    # an "=" in words or in brackets is no step; one after them is
    assert pieces(r"\text{(at } s = 1\text{)} = 2") == [
        r"\text{(at } s ",
        r"= 1\text{)} ",
        "= 2",
    ]
