"""Names in other scripts than Latin, in the outputs meant for a terminal.

Students name links in their own language: Cyrillic, Greek, CJK, accented Latin
written with combining marks. These tests write the slider-crank exercise so and
check what each output does with such names.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from assur._width import shown_width
from assur.cli import main

from .conftest import EXAMPLES

RENAMED = {
    '"crank"': '"кривошип"',
    "links.crank]": 'links."кривошип"]',
    '"rod"': '"шатун_φ"',
    "links.rod]": 'links."шатун_φ"]',
    '"slider"': '"ползун 滑块"',
    "links.slider]": 'links."ползун 滑块"]',
    "joints.guide]": 'joints."направляющая_e\u0301"]',
}
"""The exercise's names, written in Cyrillic, Greek, CJK and with a combining mark."""


@pytest.fixture
def renamed(tmp_path: Path) -> Path:
    """The slider-crank exercise with non-Latin names, in a folder named so too."""
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    for old, new in RENAMED.items():
        text = text.replace(old, new)
    folder = tmp_path / "Мои файлы τεστ 机构"
    folder.mkdir()
    path = folder / "кривошипно-ползунный.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("command", ["kinematics", "forces"])
def test_a_readable_table_of_wide_names_stays_aligned(renamed, capsys, command):
    # a CJK character is two columns wide and a combining mark none: aligned by
    # len(), every column after such a name was shifted on the terminal
    assert main([command, str(renamed), "--angles", "0:90:45"]) == 0
    lines = capsys.readouterr().out.splitlines()[:5]
    assert "ползун 滑块" in lines[0] or "e\u0301" in lines[0]
    assert len({shown_width(line) for line in lines}) == 1


@pytest.mark.parametrize("guide", ["направляющая_e\u0301", "g_e\u0301"])
def test_a_summary_of_wide_names_stays_aligned(renamed, capsys, guide):
    # the guide's name the longest of the summary, or shorter than others: the
    # padding after it is counted in columns either way
    text = renamed.read_text(encoding="utf-8")
    renamed.write_text(text.replace("направляющая_e\u0301", guide), encoding="utf-8")
    assert main(["forces", str(renamed), "--angles", "0:90:45", "--summary"]) == 0
    rows = [r for r in capsys.readouterr().out.splitlines() if r.startswith("  ")]
    rows = [r for r in rows if not r.startswith("  (")]
    # each value's last digit in one column, whatever the name before it
    ends = {shown_width(r.split("  N")[0]) for r in rows if r.endswith("  N")}
    assert any("e\u0301" in r for r in rows)
    assert len(ends) == 1


@pytest.mark.filterwarnings("default::UserWarning")  # as python runs the command
def test_glyphs_no_font_has_are_one_warning_line(renamed, capsys, recwarn):
    # a CJK name was one matplotlib UserWarning per character and per drawing,
    # each with the package's file and line; its subscripts' boxes went unsaid
    text = renamed.read_text(encoding="utf-8").replace("滑块", "滑块\u0c85")
    renamed.write_text(text, encoding="utf-8")
    out = renamed.parent / "рисунок 图.png"
    assert main(["plot", str(renamed), "-o", str(out), "--forces"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert out.stat().st_size > 0
    assert len(err) == 1, err
    assert err[0].startswith(f"assur: warning: {renamed}: the pictures' fonts ")
    assert "'\u0c85' (U+0C85)" in err[0]  # Kannada: in no font of this machine
    # matplotlib's own warnings on the glyphs are not shown beside the line
    assert [str(w.message) for w in recwarn if "Glyph" in str(w.message)] == []


def test_an_installed_cjk_font_draws_the_pictures_text(renamed, monkeypatch):
    # the pictures take the fallback fonts: matplotlib's text then warns of no
    # CJK glyph (mathtext's subscripts, which take no fallback, still may)
    from assur import _fonts, cli

    if not _fonts.fallback_fonts():
        pytest.skip("no font with CJK glyphs installed")
    heard: list[str] = []

    def gather(messages: list[str]) -> str | None:
        heard.extend(messages)
        return _fonts.missing_glyphs(messages)

    monkeypatch.setattr(cli, "missing_glyphs", gather)
    out = renamed.parent / "p.png"
    assert main(["plot", str(renamed), "-o", str(out), "--forces"]) == 0
    glyphs = [m for m in heard if _fonts.GLYPH_MISSING.fullmatch(m)]
    assert not any("CJK" in m for m in glyphs), glyphs


def test_missing_glyphs_are_told_once_each():
    from assur._fonts import missing_glyphs

    said = missing_glyphs(
        [
            "Glyph 22359 (\\N{CJK UNIFIED IDEOGRAPH-5757}) missing from font(s) "
            "DejaVu Sans.",
            "Font 'rm' does not have a glyph for '\\u5757' [U+5757], substituting "
            "with a dummy symbol.",
            "Font 'rm' does not have a glyph for '\\u6ed1' [U+6ed1], substituting "
            "with a dummy symbol.",
            "constrained_layout not applied",
        ]
    )
    assert said is not None
    assert said.count("U+5757") == 1
    assert "'滑' (U+6ED1)" in said
    assert missing_glyphs(["something else"]) is None


def test_installed_fonts_draw_a_cjk_name():
    # DejaVu Sans has no CJK: a font installed for it follows the user's own
    import matplotlib as mpl
    from matplotlib.figure import Figure

    from assur._fonts import fallback_fonts

    settings = fallback_fonts()
    if not settings:
        pytest.skip("no font with CJK glyphs installed")
    before = mpl.rcParams["font.family"]
    with mpl.rc_context(settings), warnings.catch_warnings():
        warnings.simplefilter("error")  # a glyph missing would raise here
        fig = Figure()
        fig.text(0.5, 0.5, "ползун 滑块")
        fig.canvas.draw()
    assert mpl.rcParams["font.family"] == before


@pytest.mark.parametrize(
    ("old", "new", "told"),
    [
        # the joint named in Cyrillic (А), referred to in Latin (A)
        (
            "[joints.A]",
            '[joints."\u0410"]',
            "U+0410 CYRILLIC CAPITAL LETTER A where this one has U+0041 LATIN",
        ),
        # the link named with é as one character, referred to as e and an accent
        (
            'links."шатун_φ"]',
            'links."шатун_\u00e9"]',
            "U+00E9 LATIN SMALL LETTER E WITH ACUTE where this one has U+0065 LATIN "
            "SMALL LETTER E, U+0301 COMBINING ACUTE ACCENT",
        ),
        # a zero-width space pasted with the name from a web page
        (
            'links."шатун_φ"]',
            'links."шатун_φ\u200b"]',
            "U+200B ZERO WIDTH SPACE where this one has nothing",
        ),
    ],
)
def test_a_name_that_only_looks_like_a_known_one_is_told_apart(
    renamed, capsys, old, new, told
):
    # "unknown joint 'A' (known: А, B, C)", or "did you mean 'шатун_é'?" for an
    # 'шатун_é': no difference the reader could see on the screen
    text = renamed.read_text(encoding="utf-8").replace(old, new)
    if "\u00e9" in new:
        text = text.replace('"шатун_φ"', '"шатун_e\u0301"')
    renamed.write_text(text, encoding="utf-8")
    assert main(["structure", str(renamed)]) == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1
    assert "did you mean" in err
    assert f"(they look alike, but the known name has {told}" in err


def test_a_latex_note_of_cyrillic_names_says_pdflatex_cannot_set_them(renamed):
    # pdflatex stopped at the first Cyrillic letter ("Unicode character к
    # (U+043A) not set up for use with LaTeX"), and nothing had said so
    import assur
    from assur.errors import AssurWarning
    from assur.explain._latex_chars import unset

    note = assur.explain(assur.load(renamed), 45.0)
    with pytest.warns(AssurWarning, match=r"pdflatex cannot set .*\(U\+043A\)"):
        text = note.to_latex()
    first, _, body = text.partition("\n")
    assert first.startswith("% pdflatex cannot set these characters: U+043A, ")
    assert first.isascii()  # code points only, whatever TeX makes of a comment
    # the first six of them, and "..." for the rest
    missing = unset(body)
    assert len(missing) > 6
    listed = ", ".join(f"U+{ord(c):04X}" for c in missing[:6])
    assert first.endswith(f": {listed}, ...")


def test_a_latex_note_of_accented_latin_names_compiles(tmp_path, capsys):
    # Latin letters with accents are in the note's T1 fonts: no warning, and
    # pdflatex sets them (the warning is no false alarm)
    import shutil
    import subprocess

    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    text = text.replace("links.crank]", 'links."manivelle_é"]')
    text = text.replace('"crank"', '"manivelle_é"').replace(
        "Slider-crank exercise", "Système bielle–manivelle"
    )
    path = tmp_path / "bielle.toml"
    path.write_text(text, encoding="utf-8")
    assert (
        main(["explain", str(path), "--angle", "30", "-o", str(tmp_path / "n.tex")])
        == 0
    )
    assert capsys.readouterr().err == ""
    pdflatex = shutil.which("pdflatex")
    if pdflatex is None:
        pytest.skip("pdflatex not found")
    result = subprocess.run(
        [pdflatex, "-interaction=nonstopmode", "-halt-on-error", "n.tex"],
        cwd=tmp_path,
        capture_output=True,
        encoding="utf-8",
        errors="replace",  # TeX's log echoes the file's bytes as it reads them
        timeout=180,
        check=False,
    )
    assert result.returncode == 0, result.stdout[-2000:]


@pytest.mark.parametrize(("encoding", "byte"), [("cp1251", "0xCA"), ("koi8-r", "0xEB")])
def test_a_file_saved_in_a_code_page_is_told_where(tmp_path, capsys, encoding, byte):
    # an editor's "ANSI" (Windows-1251 for Russian): "byte 19 cannot be decoded"
    # left the reader to count bytes to find the first Russian letter
    path = tmp_path / "ansi.toml"
    path.write_bytes('format = 1\nname = "Кривошип"\n'.encode(encoding))
    assert main(["structure", str(path)]) == 2
    assert capsys.readouterr().err.splitlines() == [
        f"assur: error: {path}: not UTF-8 text (byte {byte} at line 2, column 9 "
        "cannot be decoded); expected a TOML or JSON file saved as UTF-8"
    ]


def test_a_bad_byte_after_a_letter_of_two_bytes_is_told_by_its_column(tmp_path, capsys):
    # an editor counts "é" as one column, not as its two bytes in UTF-8
    before = 'format = 1\nname = "é'
    path = tmp_path / "mixed.toml"
    path.write_bytes(before.encode("utf-8") + b'\xff"\n')
    assert main(["structure", str(path)]) == 2
    column = len(before.rpartition("\n")[2]) + 1
    assert f"(byte 0xFF at line 2, column {column} cannot" in capsys.readouterr().err


@pytest.mark.parametrize("mark", ["\u202e", "\u2067"])
def test_a_name_with_a_bidirectional_override_is_refused(renamed, capsys, mark):
    # U+202E in a link's name turned the rest of every header line around it
    # ("rod\u202e.angle" shows as "rodelgna.") and of every message naming it
    text = renamed.read_text(encoding="utf-8").replace("шатун_φ", f"шатун{mark}_φ")
    renamed.write_text(text, encoding="utf-8")
    assert main(["kinematics", str(renamed), "--angles", "0"]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1
    assert f"holds the control character {mark!a}; expected printable" in err[0]


def test_right_to_left_marks_stay_welcome(renamed, capsys):
    # Hebrew and Arabic names need U+200F and U+200E, which reorder nothing beyond
    text = renamed.read_text(encoding="utf-8").replace("шатун_φ", "מוט\u200f_φ")
    renamed.write_text(text, encoding="utf-8")
    assert main(["kinematics", str(renamed), "--angles", "0"]) == 0
    assert "מוט\u200f_φ.omega" in capsys.readouterr().out


@pytest.mark.parametrize("encoding", ["cp1251", "ascii"])
@pytest.mark.parametrize("summary", [[], ["--summary"]])
def test_a_table_stays_aligned_where_standard_output_escapes_names(
    renamed, monkeypatch, encoding, summary
):
    # Windows-1251 writes Cyrillic but not φ or é, ASCII none of them: the names
    # go out as escapes (\u0301), six columns where the table had counted none
    import io
    import sys

    out = io.TextIOWrapper(io.BytesIO(), encoding=encoding)
    monkeypatch.setattr(sys, "stdout", out)
    assert main(["forces", str(renamed), "--angles", "0:90:45", *summary]) == 0
    out.flush()
    lines = out.buffer.getvalue().decode(encoding).splitlines()
    assert any("\\u0301" in line for line in lines)  # the guide's accent
    if summary:
        rows = [r for r in lines if r.endswith("  N")]
        assert len({shown_width(r) for r in rows}) == 1
    else:
        assert len({shown_width(line) for line in lines[:5]}) == 1


@pytest.mark.parametrize(
    ("old", "new"),
    [("mass = 0.5", "mass = 0,5"), ("omega = 200.0", "omega = 200,5")],
)
def test_a_decimal_comma_in_the_file_is_asked_about(tmp_path, capsys, old, new):
    # "0,5" is a half in Russian and most of Europe; TOML said only "Expected
    # newline or end of document after a statement"
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    path = tmp_path / "comma.toml"
    path.write_text(text.replace(old, new), encoding="utf-8")
    assert main(["structure", str(path)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1
    assert err[0].endswith("; a decimal comma? decimals are written with a point "
                           "(0.5, not 0,5)")  # fmt: skip


@pytest.mark.parametrize(
    ("argv", "asked"),
    [
        (["kinematics", "--angles", "0:90:22,5"], True),
        (["explain", "--angle", "22,5"], True),
        (["kinematics", "--angles", "0:90:10,0:90:10"], False),  # two ranges
        (["kinematics", "--angles", "0:90:10,5:90:10"], False),
    ],
)
def test_a_decimal_comma_in_an_angle_is_asked_about(capsys, argv, asked):
    path = str(EXAMPLES / "slider_crank_exercise.toml")
    assert main([argv[0], path, *argv[1:]]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1
    assert ("a decimal comma?" in err[0]) is asked


@pytest.mark.parametrize(
    ("at", "read"), [("[0,0, 0,0]", "[0, 0, 0, 0]"), ("[0,5, 0]", "[0, 5, 0]")]
)
def test_a_point_with_decimal_commas_is_asked_about(tmp_path, capsys, at, read):
    # "at = [0,0, 0,0]": four whole numbers to TOML, two decimals to the
    # writer; "[0,5, 0]" three
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    path = tmp_path / "comma.toml"
    path.write_text(text.replace("at = [0.0, 0.0]", f"at = {at}"), "utf-8")
    assert main(["structure", str(path)]) == 2
    assert capsys.readouterr().err.splitlines() == [
        f"assur: error: {path}: joints.A.at: expected two numbers [x, y], got "
        f"{read}; a decimal comma? decimals are written with a point (0.5, not "
        "0,5)"
    ]


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ('{"mass": 0,5}', True),
        ('{"links": {"crank": {"mass": 0,052, "length": 1}}}', True),
        ('{"mass": 1,}', False),  # a comma too many
        ('{"at": [1, 2}', False),
    ],
)
def test_a_decimal_comma_in_a_json_file_is_asked_about(text, asked):
    # JSON said only "Expecting property name enclosed in double quotes"
    from assur._file_syntax import file_data
    from assur.errors import ModelError

    with pytest.raises(ModelError, match=r"^not valid JSON: ") as err:
        file_data(text, json_format=True)
    assert ("; a decimal comma? decimals are written" in str(err.value)) is asked
