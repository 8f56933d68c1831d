"""Each Assur group's free-body diagram at the report's first position, inline SVG.

The diagrams are those of ``assur plot --group N``
(:func:`assur.plotting.draw_free_body`), saved as SVG and set into the page. Inline
SVG keeps the report one file that opens offline; matplotlib is imported here, when
a report with forces is rendered, never on ``import assur.html``.
"""

from __future__ import annotations

import io
import re
import warnings
from html import escape

from assur.analysis import Table
from assur.html._data import public
from assur.html._sections import first_position, wide_card

__all__ = ["free_bodies_html", "inline_svg"]

FIGURE_SIZE = (7.5, 5.5)
"""Size of one diagram, inches (matplotlib's figure size)."""


def inline_svg(svg: str, prefix: str) -> str:
    """Return matplotlib's SVG document as an element to set into an HTML page.

    The XML prologue, the metadata, the style element and the namespace
    declarations go (HTML knows SVG without them, and the page names no address);
    every id gets ``prefix``, since several diagrams share one document and
    matplotlib reuses ids (glyphs).
    """
    start = svg.index("<svg")
    svg = svg[start:]
    svg = re.sub(r"<metadata>.*?</metadata>\s*", "", svg, flags=re.S)
    # matplotlib's <style>*{stroke-linejoin: round; ...}</style> would style the
    # whole HTML page; the same defaults as attributes of the root only inherit
    # into this drawing (an element's own style still wins, as under the rule)
    svg = re.sub(r"\s*<style[^>]*>.*?</style>", "", svg, flags=re.S)
    svg = svg.replace("<svg", '<svg stroke-linejoin="round" stroke-linecap="butt"', 1)
    svg = re.sub(r'\s+xmlns(:\w+)?="[^"]*"', "", svg)
    svg = re.sub(r'\bid="([^"]+)"', rf'id="{prefix}\1"', svg)
    svg = re.sub(r"url\(#([^)]+)\)", rf"url(#{prefix}\1)", svg)
    # SVG 2's plain href: HTML's parser has no xlink namespace declared here
    svg = re.sub(r'xlink:href="#([^"]+)"', rf'href="#{prefix}\1"', svg)
    return svg


def _diagram(table: Table, index: int) -> str:
    """Return the free-body diagram of group ``index`` at the table's first row."""
    import matplotlib as mpl
    from matplotlib.figure import Figure

    from assur._fonts import fallback_fonts
    from assur.plotting import draw_free_body

    # a fixed salt: the same report gives the same clip-path ids, run after run;
    # the fonts for names in CJK scripts after the user's own
    settings = {"svg.hashsalt": "assur", "svg.fonttype": "path", **fallback_fonts()}
    with (
        mpl.rc_context(settings),
        warnings.catch_warnings(),
    ):
        # labels of very long names leave the constrained layout no room: the
        # figure is then simply not tightened, nothing the reader must act on
        warnings.filterwarnings("ignore", "constrained_layout not applied", UserWarning)
        fig = Figure(figsize=FIGURE_SIZE, layout="constrained")
        draw_free_body(table, index, ax=fig.add_subplot())
        buffer = io.StringIO()
        fig.savefig(buffer, format="svg", metadata={"Date": None})
    return inline_svg(buffer.getvalue(), f"fb{index + 1}-")


def free_bodies_html(table: Table) -> str:
    """Return the section of every group's free-body diagram (empty without forces)."""
    if table.force_state is None or len(table) == 0 or not table.plan.groups:
        return ""
    figures = []
    for index, group in enumerate(table.plan.groups):
        links = ", ".join(public(x) for x in group.links)
        caption = f"Group {index + 1}: {escape(group.kind)} ({escape(links)})"
        # the picture's words are drawn as outlines: a screen reader finds no text
        # in it, so the picture is one image named by its caption
        svg = _diagram(table, index).replace(
            "<svg", f'<svg role="img" aria-label="Free-body diagram of {caption}"', 1
        )
        figures.append(
            f'<figure id="free-body-{index + 1}"><figcaption>{caption}</figcaption>\n'
            f"{svg}\n</figure>"
        )
    return wide_card(
        "free-bodies",
        f"Free-body diagrams at the first position ({first_position(table)})",
        '<p class="note">Each Assur group cut free from the links it hangs on, in '
        "the order of attachment: its inertia loads, gravity and external loads, "
        "the reactions of those links on it and the reactions inside it, each with "
        "its value (as <code>assur plot --group N</code> draws it).</p>\n"
        '<div class="charts">\n' + "\n".join(figures) + "\n</div>",
    )
