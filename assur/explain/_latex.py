r"""The note as a LaTeX report that compiles with pdflatex (amsmath, longtable).

Headings become sections, equations ``\[ ... \]`` (broken over lines by breqn-free
means: each equation on its own), tables ``tabular``; text is escaped.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from assur._warn import warn
from assur.explain._blocks import Display, Grid, Heading, Items, Para, segments
from assur.explain._breaks import LEADING, broken, first_equals
from assur.explain._latex_chars import unset

if TYPE_CHECKING:
    from assur.explain._blocks import Block
    from assur.explain._note import Note

__all__ = ["latex_document"]

PREAMBLE = r"""\documentclass[a4paper,10pt]{article}
\usepackage[T1]{fontenc}
\usepackage[utf8]{inputenc}
\usepackage[margin=2cm]{geometry}
\usepackage{amsmath,amssymb}
\usepackage{textcomp}
\newcommand{\degreesign}{\textdegree}
\DeclareUnicodeCharacter{00B0}{\textdegree}
\DeclareUnicodeCharacter{2192}{$\rightarrow$}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5em}
"""
SECTIONS = {1: "section*", 2: "section*", 3: "subsection*", 4: "subsubsection*"}
TEXT_SPECIAL = {
    "\\": r"\textbackslash{}",
    "&": r"\&",
    "%": r"\%",
    "$": r"\$",
    "#": r"\#",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "~": r"\textasciitilde{}",
    "^": r"\textasciicircum{}",
}


def _text(text: str) -> str:
    """Return text with its inline mathematics kept and the rest escaped."""
    return "".join(
        f"${part}$" if is_math else "".join(TEXT_SPECIAL.get(c, c) for c in part)
        for is_math, part in segments(text)
    )


def _display(tex: str) -> str:
    """Return a display equation as LaTeX, centred; several rows aligned.

    The rows of a long one (:func:`assur.explain._breaks.broken`) are set in a
    ``split``, their ``=`` under the first row's, a row of terms or words set in
    from them: a multline zigzagged (first row left, middle centred, last right),
    and one of a single row stretched its spaces across the page.
    """
    parts = broken(tex)
    if len(parts) > 1:
        tex = "\\begin{split}" + " \\\\\n".join(_aligned(parts)) + "\\end{split}"
    return f"{{\\small\\begin{{equation*}}{tex}\\end{{equation*}}}}"


def _aligned(parts: list[str]) -> list[str]:
    r"""Return the rows of an equation with their alignment points (``&``).

    The first row aligns at its first ``=`` (at its start if it has none); a row
    that starts with ``=`` at that ``=``; any other a quad in from it, a leading
    sign as a binary one (``{}+``), and as far in as the first row's own spaces
    (``\qquad``) where that row has no ``=``.
    """
    first = parts[0]
    indent = "\\quad "
    at = first_equals(first)
    if at >= 0:
        # its first "=" outside braces and brackets, a later statement's too
        head = f"{first[:at]}&{first[at:]}"
    else:
        # a line set in (the "\qquad" of a Coriolis term's note) keeps its rows in
        # further than its first: they went on a quad to the left of it
        lead = LEADING.match(first)
        indent = (lead.group() if lead else "") + indent
        head = f"&{first}"
    rows = [head]
    for row in parts[1:]:
        if row.startswith("="):
            rows.append(f"&{row}")
        else:
            rows.append(f"&{indent}{'{}' if row[:1] in ('+', '-') else ''}{row}")
    return rows


def _block(block: Block) -> str:
    """Return one block as LaTeX."""
    if isinstance(block, Heading):
        return f"\\{SECTIONS.get(block.level, 'paragraph*')}{{{_text(block.text)}}}"
    if isinstance(block, Para):
        return _text(block.text)
    if isinstance(block, Display):
        # a long chain in rows, as in HTML (assur.explain._breaks): multline sets
        # the first to the left, the last to the right
        return "\n".join(_display(line) for line in block.lines)
    if isinstance(block, Grid):
        columns = "l" * len(block.head)
        head = " & ".join(_text(c) for c in block.head)
        rows = "\n".join(" & ".join(_text(c) for c in r) + r" \\" for r in block.rows)
        return (
            f"\\begin{{tabular}}{{{columns}}}\n\\hline\n{head} \\\\\n\\hline\n"
            f"{rows}\n\\hline\n\\end{{tabular}}"
        )
    assert isinstance(block, Items)
    items = "\n".join(f"\\item {_text(x)}" for x in block.items)
    return f"\\begin{{itemize}}\n{items}\n\\end{{itemize}}"


def latex_document(note: Note) -> str:
    """Return the note as a whole LaTeX document.

    A name in a script the preamble's fonts lack (Cyrillic, Greek, CJK) is said in
    the document's first line and in a warning: pdflatex stops at it.
    """
    body = "\n\n".join(_block(b) for b in note.blocks)
    text = (
        f"{PREAMBLE}\\title{{{_text(note.title)}}}\n\\date{{}}\n"
        f"\\begin{{document}}\n\\maketitle\n\n{body}\n\n\\end{{document}}\n"
    )
    missing = unset(text)
    if not missing:
        return text
    more = ", ..." if len(missing) > 6 else ""
    points = ", ".join(f"U+{ord(c):04X}" for c in missing[:6]) + more
    shown = ", ".join(f"{c} (U+{ord(c):04X})" for c in missing[:6]) + more
    warn(
        f"the LaTeX note holds characters pdflatex cannot set with the note's T1 "
        f"fonts ({shown}), at which it stops; expected the note as HTML or "
        "Markdown, or names in Latin letters"
    )
    return f"% pdflatex cannot set these characters: {points}\n{text}"
