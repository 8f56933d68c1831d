"""The words of messages: values echoed as the user wrote them, lists as a sentence.

A numpy scalar or a foreign object given to the library is echoed as its number or
its type, never as a Python repr ("np.float64(nan)", "<object object at 0x...>");
names are listed as a sentence ("a, b or c"), counts agree with their noun.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

import assur
from assur import catalog
from assur._text import describe
from assur.plotting.decomposition import draw_decomposition, draw_free_body

FOREIGN = re.compile(r"np\.\w+\(|object at 0x|<\w+ ")
"""A Python repr in a message."""


@pytest.fixture(scope="module")
def four_bar_forces():
    return assur.forces(catalog.four_bar(), [0.0, 90.0])


@pytest.mark.parametrize(
    ("value", "shown"),
    [(np.float64("nan"), "got nan"), (np.float64(-1.0), "got -1.0")],
)
def test_a_catalog_length_echoes_a_numpy_number_as_a_number(value, shown):
    with pytest.raises(assur.ModelError) as caught:
        catalog.four_bar(crank=value)
    assert str(caught.value).endswith(shown)
    assert not FOREIGN.search(str(caught.value))


@pytest.mark.parametrize("dtype", [np.float32, np.float16])
@pytest.mark.parametrize("written", ["-0.1", "-0.3", "-1e-05", "-1.5"])
def test_a_narrow_float_is_echoed_as_given_not_widened(dtype, written):
    # np.float32(-0.1) read -0.10000000149011612, the float64 nearest to it
    value = dtype(written)
    with pytest.raises(assur.ModelError) as caught:
        catalog.four_bar(crank=value)
    shown = str(caught.value).rpartition("got ")[2]
    assert dtype(shown) == value  # the same number in its own precision...
    # ...in no more digits than that precision needs
    assert len(shown) <= len(np.format_float_positional(value, unique=True))
    assert not FOREIGN.search(str(caught.value))


@pytest.mark.parametrize("dtype", [np.float32, np.float16])
def test_describe_writes_a_narrow_float_in_its_own_precision(dtype):
    value = dtype(0.1)
    assert float(value) != 0.1  # widened, it is another number's text
    assert describe(value) == np.format_float_positional(value, unique=True)
    assert describe([value, dtype("nan")]) == f"[{describe(value)}, nan]"


@pytest.mark.parametrize(
    ("angle", "expected"),
    [
        (np.float64("nan"), "angle: expected a finite driver position, got nan"),
        (object(), "angle: expected a driver position (deg, or m), got a value of "),
        ([1.0, 2.0, 3.0], "angle: 3 values for 1 driver; expected one position per"),
    ],
)
def test_a_drawing_angle_is_echoed_without_a_repr(four_bar_forces, angle, expected):
    with pytest.raises(assur.UsageError) as caught:
        draw_decomposition(four_bar_forces, angle=angle)
    assert str(caught.value).startswith(expected)
    assert not FOREIGN.search(str(caught.value))


def test_a_group_index_out_of_range_counts_the_groups_in_words(four_bar_forces):
    with pytest.raises(assur.UsageError) as caught:
        draw_free_body(four_bar_forces, group_index=5)
    assert str(caught.value) == (
        "group_index: 5 is out of range; the mechanism has 1 Assur group; "
        "expected 0 to 0"
    )
    with pytest.raises(assur.UsageError, match=r"got 0\.5$"):
        draw_free_body(four_bar_forces, group_index=np.float64(0.5))


def test_a_reserved_name_lists_the_others_as_a_choice():
    source = assur.dumps(catalog.four_bar()).replace("links.rocker]", "links.angle]")
    with pytest.raises(assur.ModelError) as caught:
        assur.io.loads(source.replace('"rocker"', '"angle"'))
    assert str(caught.value).endswith(
        "is taken by the result tables; expected another name (not angle, driver, "
        "shaking or residual)"
    )


def test_a_table_level_echoes_a_numpy_integer_as_a_number():
    table = assur.kinematics(catalog.four_bar(), [0.0])
    with pytest.raises(assur.UsageError) as caught:
        table.motion(np.int64(7))
    assert str(caught.value) == (
        "level: expected 0, 1, 2 or 3 (positions to jerks), got 7"
    )
