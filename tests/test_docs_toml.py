"""Every TOML block of the documentation parses as TOML 1.0 (``tomllib``).

The blocks are the ``.. code-block:: toml`` directives of ``docs/*.rst`` and the
```` ```toml ```` fences of README.md. A reader copies them into a file, so each one
is whole TOML: none is a fragment (an inline table continued over several lines,
which TOML 1.0 forbids, once stood in the page of the file format).
"""

from __future__ import annotations

import re
import textwrap
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).parent.parent
DIRECTIVE = re.compile(r"^( *)\.\. code-block:: toml\n((?:\1 +:.*\n)*)\n", re.M)
FENCE = re.compile(r"^```toml\n(.*?)^```", re.M | re.S)


def rst_blocks(path: Path) -> list[tuple[str, str]]:
    """The ``toml`` code blocks of an reST page, each with its line number."""
    text = path.read_text("utf-8")
    found = []
    for match in DIRECTIVE.finditer(text):
        body = []
        for line in text[match.end() :].splitlines():
            if line.strip() and len(line) - len(line.lstrip()) <= len(match[1]):
                break
            body.append(line)
        where = f"{path.name}:{text.count(chr(10), 0, match.start()) + 1}"
        found.append((where, textwrap.dedent("\n".join(body))))
    return found


def blocks() -> list[tuple[str, str]]:
    found = [
        b for page in sorted((ROOT / "docs").glob("*.rst")) for b in rst_blocks(page)
    ]
    readme = (ROOT / "README.md").read_text("utf-8")
    for match in FENCE.finditer(readme):
        where = f"README.md:{readme.count(chr(10), 0, match.start()) + 1}"
        found.append((where, match[1]))
    return found


BLOCKS = blocks()


def test_the_pages_have_toml_blocks():
    assert len(BLOCKS) >= 7


def test_the_whole_format_on_one_page_is_a_whole_mechanism():
    # the page's first block, copied into a file, is a mechanism to analyse (its
    # joints once named links it never declared)
    import numpy as np

    import assur

    where, text = rst_blocks(ROOT / "docs" / "file_format.rst")[0]
    assert text.startswith("format = 1"), where
    mech = assur.io.loads(text)
    table = assur.forces(mech, [45.0])
    assert {link.name for link in mech.links} == {"crank", "rod", "slider"}
    assert np.isfinite(table["driver.torque"]).all()
    np.testing.assert_allclose(
        table["driver.torque"], table["driver.torque_check"], rtol=1e-9
    )


@pytest.mark.parametrize(("where", "text"), BLOCKS, ids=[w for w, _ in BLOCKS])
def test_each_block_is_toml(where, text):
    assert text.strip(), where
    try:
        tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        pytest.fail(f"{where}: {err}")
