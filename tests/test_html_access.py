"""The report for readers who do not see its colours: screen readers, grey paper.

Every picture of the page is named for a screen reader.
"""

from __future__ import annotations

import re
from pathlib import Path

import assur
from assur.html import render_report

EXAMPLES = Path(__file__).parent.parent / "examples"


def test_every_picture_of_the_page_is_named() -> None:
    # the free-body diagrams (matplotlib's SVG, its words drawn as outlines) had
    # neither a role nor a name: a screen reader met a picture it could not name
    page = render_report(
        assur.load(EXAMPLES / "six_bar_lecture.toml"), [30.0, 120.0, 210.0]
    )
    body = page.split('<script type="application/json"')[0]
    roots = re.findall(r"<svg\b[^>]*>", body)
    assert len(roots) == 3  # the drawing and two groups' free bodies
    for root in roots:
        assert 'role="img"' in root
        label = re.search(r'aria-label="([^"]+)"', root)
        assert label is not None
    named = re.findall(r'<svg[^>]*aria-label="Free-body diagram of ([^"]+)"', body)
    assert named == ["Group 1: RRR (3, 4)", "Group 2: RRR (5, 6)"]
