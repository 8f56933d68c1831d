"""A file's entries that are missing or named twice: the message says what is expected.

STYLE.md asks every error line for the file, the entry, what is wrong and what was
expected; "joints.B: missing key 'at'" left a user to find out what 'at' holds.
"""

from __future__ import annotations

import copy
import json
import re
import tomllib

import pytest

import assur
from assur import Link, Mechanism, ModelError, Point
from assur._checks import JOINT_KINDS

from .conftest import EXAMPLES

SLIDER = tomllib.loads(
    (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
)
SLIDER["loads"] = [{"link": "rod", "torque": 5.0}]
SLIDER["points"] = {"P": {"link": "rod", "at": [0.15, 0.08]}}


def _read(data: dict) -> Mechanism:
    """Return the mechanism of a file's ``data``, written as JSON."""
    return assur.loads(json.dumps(data), json_format=True)


def _without(entry: str, key: str) -> dict:
    """Return the slider-crank's data with the ``key`` of ``entry`` left out."""
    data = copy.deepcopy(SLIDER)
    section, _, name = entry.partition(".")
    if "[" in section:
        section, index = section.rstrip("]").split("[")
        del data[section][int(index)][key]
    else:
        del data[section][name][key]
    return data


def test_the_file_read_here_is_valid():
    assert [p.name for p in _read(SLIDER).points] == ["P"]


@pytest.mark.parametrize(
    ("where", "key", "words"),
    [
        ("joints.B", "kind", JOINT_KINDS),
        ("joints.B", "links", ("[first, second]",)),
        ("joints.B", "at", ("[x, y]", "a joint's name", "{from, toward, distance}")),
        ("drivers[0]", "joint", ("joint it drives",)),
        ("drivers[0]", "omega", ("rad/s", "m/s")),
        ("loads[0]", "link", ("moving link",)),
        ("points.P", "link", ("moving link",)),
        ("points.P", "at", ("[x, y]",)),
    ],
)
def test_a_missing_key_says_what_it_holds(where, key, words):
    with pytest.raises(ModelError) as caught:
        _read(_without(where, key))
    message = str(caught.value)
    assert message.startswith(f"{where}: missing key {key!r}; expected "), message
    expected = message.partition("; expected ")[2]
    for word in words:
        assert word in expected, (word, message)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (
            lambda m: Mechanism((*m.links, m.links[0]), m.joints, m.drivers),
            "links.crank: two links with one name; expected a name for each",
        ),
        (
            lambda m: Mechanism(m.links, (*m.joints, m.joints[1]), m.drivers),
            "joints.B: two joints with one name; expected a name for each",
        ),
        (
            lambda m: Mechanism(
                m.links, m.joints, m.drivers, points=(Point("B", "rod", (0.0, 0.0)),)
            ),
            "points.B: a joint or point has the name; expected a name for each",
        ),
        (
            lambda m: Mechanism((*m.links, Link("ground")), m.joints, m.drivers),
            "links.ground: 'ground' is the frame and takes no entry; expected another "
            "name",
        ),
    ],
)
def test_a_name_taken_says_what_is_expected(change, message):
    with pytest.raises(ModelError, match=f"^{re.escape(message)}$"):
        change(_read(SLIDER))


def test_a_force_without_its_point_says_what_a_point_is() -> None:
    # "a force needs its point of application 'at'" named the key, not its forms
    data = copy.deepcopy(SLIDER)
    data["loads"] = [{"link": "rod", "force": [10.0, 0.0]}]
    with pytest.raises(ModelError) as err:
        _read(data)
    assert str(err.value).endswith(
        "loads[0]: a force needs its point of application 'at'; expected [x, y], a "
        "joint's name or {from, toward, distance}"
    )
