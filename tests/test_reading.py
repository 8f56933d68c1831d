"""Reading never crashes nor hangs: every odd file is one ModelError line.

Deep nesting, integers too long for Python, endless or huge files, folders, files
that cannot be opened, names with control characters, odd values in every entry;
and the model's own refusals (a revolute joint's axis, a crank of zero length).
"""

from __future__ import annotations

import contextlib
import csv
import dataclasses
import io
import json
import math
import os
import tomllib
from pathlib import Path

import pytest

import assur
from assur import AssurError, Driver, Joint, Link, Mechanism, ModelError
from assur.cli import main
from assur.io import MAX_FILE_BYTES

from .conftest import EXAMPLES
from .test_model import BASE

FOUR_BAR = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")


def write(tmp_path: Path, name: str, text: str | bytes) -> Path:
    path = tmp_path / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text, encoding="utf-8")
    return path


def message(path: Path) -> str:
    """The error of reading ``path``, after the file's name (checked once)."""
    with pytest.raises(ModelError) as info:
        assur.load(path)
    text = str(info.value)
    assert "\n" not in text
    assert text.startswith(f"{path}: ")
    return text[len(f"{path}: ") :]


def cli_line(capsys, path: Path) -> str:
    assert main(["structure", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1, err
    assert "Traceback" not in err
    return err.rstrip("\n")


# --- nesting and long integers -----------------------------------------------------


@pytest.mark.parametrize(
    ("name", "text", "expected"),
    [
        (
            "deep.toml",
            "a = " + "[" * 1000 + "]" * 1000,
            "not valid TOML: nested too deeply (more than the parser can follow); "
            "expected the few levels of a mechanism file",
        ),
        (
            "deep.json",
            "[" * 100_000 + "]" * 100_000,
            "not valid JSON: nested too deeply (more than the parser can follow); "
            "expected the few levels of a mechanism file",
        ),
        (
            "center.json",
            '{"links": {"a": {"center": ' + "[" * 500 + "]" * 500 + "}}}",
            "links.a.center" + "[0]" * 14 + ": nested too deeply (more than 16 "
            "levels); expected the few levels of a mechanism file",
        ),
    ],
)
def test_deep_nesting(name, text, expected, tmp_path, capsys):
    path = write(tmp_path, name, text)
    assert message(path) == expected
    assert cli_line(capsys, path) == f"assur: error: {path}: {expected}"


def test_an_integer_too_long_for_python_names_its_entry(tmp_path, capsys):
    digits = "1" * 5000
    toml = write(
        tmp_path, "long.toml", BASE.replace("omega = 200.0", f"omega = {digits}")
    )
    line = BASE[: BASE.index("omega = 200.0")].count("\n") + 1
    expected = (
        f"drivers[0].omega (line {line}): an integer of 5000 digits; expected a "
        "number of at most 4300 digits"
    )
    assert message(toml) == expected
    assert cli_line(capsys, toml) == f"assur: error: {toml}: {expected}"
    under = write(
        tmp_path, "under.toml", BASE.replace("omega = 200.0", f"omega = 1_{digits}")
    )
    assert message(under).startswith(
        f"drivers[0].omega (line {line}): an integer of 5001"
    )
    data = tomllib.loads(BASE)
    data["drivers"][0]["omega"] = 0
    text = json.dumps(data, indent=1).replace('"omega": 0', f'"omega": {digits}')
    path = write(tmp_path, "long.json", text)
    line = text[: text.index(digits)].count("\n") + 1
    assert message(path) == (
        f"omega (line {line}): an integer of 5000 digits; expected a number of at "
        "most 4300 digits"
    )


def test_a_long_integer_inside_an_inline_table_names_the_line(tmp_path):
    text = BASE + f'\n[[loads]]\nlink = "rod"\nat = "B"\nforce = [{"2" * 4400}, 0]\n'
    path = write(tmp_path, "inline.toml", text)
    line = text.count("\n")
    assert message(path) == (
        f"loads[0].force (line {line}): an integer of 4400 digits; expected a number "
        "of at most 4300 digits"
    )
    text = BASE + f'\n[[loads]]\nlink = "rod"\nat = [{"2" * 4400}, 0]\nforce = [1, 0]'
    path = write(tmp_path, "inline2.toml", text)
    assert message(path).startswith(f"loads[0].at (line {text.count(chr(10))}): ")


def test_an_integer_too_large_for_a_float(tmp_path):
    path = write(
        tmp_path, "big.toml", BASE.replace("mass = 0.5", "mass = 1" + "0" * 400)
    )
    assert message(path) == (
        "links.rod.mass: the number is too large (an integer of 401 digits); "
        "expected a number of magnitude at most 1e+15"
    )


# --- files that cannot be read ----------------------------------------------------


def test_an_endless_device_is_bounded(capsys):
    path = Path("/dev/zero")
    if not path.exists():
        pytest.skip("no /dev/zero")
    assert message(path) == (
        "larger than 16 MiB; expected a mechanism file (a few kilobytes of TOML or "
        "JSON)"
    )
    assert cli_line(capsys, path).startswith("assur: error: /dev/zero: larger than")


def test_a_huge_file_is_refused(tmp_path):
    path = tmp_path / "huge.toml"
    with open(path, "wb") as stream:
        stream.truncate(MAX_FILE_BYTES + 1)  # sparse: costs no disk
    assert message(path).startswith("larger than 16 MiB; ")
    assert MAX_FILE_BYTES == 16 * 2**20


def test_a_file_just_under_the_cap_is_read(tmp_path):
    text = BASE + "# " + "x" * (MAX_FILE_BYTES - len(BASE) - 3) + "\n"
    path = write(tmp_path, "large.toml", text)
    assert path.stat().st_size == MAX_FILE_BYTES
    assert assur.load(path).name == "Slider-crank"


def test_a_folder(tmp_path, capsys):
    assert message(tmp_path) == (
        "cannot read the file (it is a folder); expected a TOML or JSON file"
    )
    assert cli_line(capsys, tmp_path).endswith(
        "(it is a folder); expected a TOML or JSON file"
    )


def test_permission_denied(monkeypatch, tmp_path, capsys):
    path = write(tmp_path, "secret.toml", BASE)

    def denied(*args, **kwargs):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr(assur.io, "open", denied, raising=False)
    assert message(path) == "cannot read the file (Permission denied)"
    assert cli_line(capsys, path) == (
        f"assur: error: {path}: cannot read the file (Permission denied)"
    )


@pytest.mark.skipif(
    not hasattr(os, "geteuid") or os.geteuid() == 0, reason="root reads any file"
)
def test_permission_denied_for_real(tmp_path):
    path = write(tmp_path, "secret.toml", BASE)
    path.chmod(0)
    assert message(path) == "cannot read the file (Permission denied)"


def test_a_name_with_a_control_character_as_the_file(tmp_path):
    path = tmp_path / "a\nb.toml"
    with pytest.raises(ModelError) as info:
        assur.load(path)
    assert str(info.value) == (
        f"{tmp_path}/a\\nb.toml: cannot read the file (No such file or directory)"
    )


# --- values echoed briefly ----------------------------------------------------------


@pytest.mark.parametrize(
    ("old", "new", "expected"),
    [
        (
            "at = [0.052326, 0.052326]",
            f"at = {list(range(10_000))}",
            "joints.B.at: expected two numbers [x, y], got [0, 1, 2, 3, ... (10000 "
            "items)]",
        ),
        (
            "mass = 0.5",
            "mass = 2020-01-01",
            "links.rod.mass: expected a number, got the date 2020-01-01",
        ),
        (
            "mass = 0.5",
            "mass = 07:32:00",
            "links.rod.mass: expected a number, got the time 07:32:00",
        ),
        (
            "mass = 0.5",
            "mass = { value = 1, unit = 'kg' }",
            "links.rod.mass: expected a number, got a table {value, unit}",
        ),
        (
            "mass = 0.5",
            """mass = { "line\\nbreak" = 1, "two words" = 2, kg = 3 }""",
            "links.rod.mass: expected a number, got a table "
            "{'line\\nbreak', two words, kg}",
        ),
        (
            'joint = "A"',
            f'joint = "{"A" * 1000}"',
            f"drivers[0].joint: unknown joint '{'A' * 55}...' (known: A, B, C, guide)",
        ),
        (
            'name = "Slider-crank"',
            'name = "Slider-crank"\ndescription = true',
            # a description is text, not a name
            "description: expected text in quotes, got true",
        ),
        (
            'kind = "revolute"',
            "kind = 1979-05-27T07:32:00Z",
            "joints.A.kind: expected a name in quotes, got the date and time "
            "1979-05-27T07:32:00+00:00",
        ),
    ],
)
def test_values_are_echoed_briefly(old, new, expected, tmp_path):
    text = BASE.replace(old, new, 1)
    assert text != BASE
    got = message(write(tmp_path, "m.toml", text))
    assert got == expected
    assert len(got) < 200


# --- names ----------------------------------------------------------------------


@pytest.mark.parametrize("char", ["\n", "\t", "\r", "\x00", "\x7f", "\x85", "\u2028"])
@pytest.mark.parametrize("kind", ["links", "joints", "points"])
def test_names_with_control_characters_are_refused(kind, char, tmp_path):
    escaped = json.dumps(f"x{char}y", ensure_ascii=True)
    old, new = {
        "links": ("[links.slider]", f"[links.{escaped}]"),
        "joints": ("[joints.guide]", f"[joints.{escaped}]"),
        "points": ("", f"\n[points]\n{escaped} = {{ link = 'rod', at = 'B' }}\n"),
    }[kind]
    text = BASE.replace(old, new, 1) if old else BASE + new
    if kind == "links":
        text = text.replace('"slider"', escaped)
    shown = repr(f"x{char}y")
    assert message(write(tmp_path, "m.toml", text)) == (
        f"{kind}.{shown}: the name {shown} holds the control character "
        f"{char!a}; expected printable characters only"
    )


@pytest.mark.parametrize("char", ["\n", "\x1b", "\u2028"])
def test_a_mechanism_s_name_with_control_characters_is_refused(char, tmp_path):
    # the name heads the summary and the dynamics' title on a terminal: a line
    # break split them, an escape sequence recoloured the terminal
    escaped = json.dumps(f"x{char}[31m", ensure_ascii=True)
    text = BASE.replace('name = "Slider-crank"', f"name = {escaped}", 1)
    shown = repr(f"x{char}[31m")
    assert message(write(tmp_path, "m.toml", text)) == (
        f"name: the name {shown} holds the control character {char!a}; expected "
        "one line of printable characters"
    )


def test_names_with_control_characters_are_refused_in_code():
    with pytest.raises(ModelError, match=r"^links\.'a\\nb': the name 'a\\nb' holds"):
        Mechanism(
            (Link("a\nb"),),
            (Joint("A", "revolute", ("ground", "a\nb"), (0.0, 0.0)),),
            (Driver("A", 1.0),),
        )


def test_names_with_quotes_keep_the_csv_header_whole():
    mech = assur.loads(
        BASE.replace('"rod"', '"\\"rod"').replace("[links.rod]", '[links."\\"rod"]')
    )
    table = assur.kinematics(mech, [0.0, 10.0])
    rows = list(csv.reader(io.StringIO(table.to_csv())))
    assert rows[0] == list(table.columns)
    assert '"rod.angle' in rows[0]
    assert len(rows) == 3


def test_a_very_long_name_is_cut_in_entries(tmp_path):
    name = "L" * 500
    text = BASE.replace("[links.slider]", f"[links.{name}]").replace(
        '"slider"', f'"{name}"'
    )
    text = text.replace("mass = 0.4", "mass = -0.4")
    got = message(write(tmp_path, "m.toml", text))
    assert got.startswith("links.'LLLL")
    assert got.endswith(": expected a number >= 0, got -0.4")
    assert len(got) < 120


def test_long_names_are_cut_where_the_known_ones_are_listed(tmp_path):
    # joints.guide names a link that does not exist; the links that do are listed
    text = BASE.replace('links = ["ground", "slider"]', 'links = ["ground", "piston"]')
    for i, link in enumerate(("crank", "rod", "slider")):
        long = f"{link}{i}" * 40
        text = text.replace(f"[links.{link}]", f"[links.{long}]")
        text = text.replace(f'"{link}"', f'"{long}"')
    got = message(write(tmp_path, "m.toml", text))
    assert "unknown link 'piston' (known: crank0crank0" in got
    assert "crank0crank0crank0crank0cra..., ground, rod1" in got
    assert len(got) < 300
    # a close match is cut as well
    assert len(assur._text.suggest("crank0" * 39, ["crank0" * 40])) < 80


# --- the model's refusals -------------------------------------------------------


def test_a_revolute_joint_takes_no_axis(tmp_path, capsys):
    text = BASE.replace("at = [0.0, 0.0]", "at = [0.0, 0.0]\naxis = [0, 0]", 1)
    path = write(tmp_path, "m.toml", text)
    expected = (
        "joints.A.axis: a revolute joint has no slide line, got [0.0, 0.0]; expected "
        "'axis' only on prismatic and slot joints"
    )
    assert message(path) == expected
    assert cli_line(capsys, path) == f"assur: error: {path}: {expected}"
    mech = assur.loads(BASE)
    joints = tuple(
        dataclasses.replace(j, axis=(1.0, 0.0)) if j.name == "B" else j
        for j in mech.joints
    )
    with pytest.raises(ModelError, match=r"^joints\.B\.axis: a revolute joint has no"):
        dataclasses.replace(mech, joints=joints)


def zero_crank() -> str:
    """The four-bar with its crank pin A moved onto the crank's pivot O2."""
    text = FOUR_BAR.replace(
        "at = [0.020000000000000004, 0.034641016151377546]", "at = [0.0, 0.0]"
    )
    text = text.replace('axis = ["O2", "A"]\n', "")
    return text.replace(
        'center = { from = "O2", toward = "A", distance = 0.02 }',
        "center = [0.01, 0.0]",
    )


def test_a_crank_of_zero_length_is_refused(tmp_path, capsys):
    path = write(tmp_path, "m.toml", zero_crank())
    expected = (
        "drivers[0].joint: the input link 'crank' has its joint 'A' at the pivot of "
        "'O2' (a crank of zero length), so the driver moves nothing; expected a joint "
        "of the input link away from its pivot"
    )
    assert message(path) == expected
    assert cli_line(capsys, path) == f"assur: error: {path}: {expected}"


def test_a_crank_of_zero_length_with_many_joints_names_four_and_counts_them():
    # the joints at the pivot past four are counted, not dropped without a word
    text = zero_crank() + "".join(
        f'\n[links.c{i}]\n\n[joints.A{i}]\nkind = "revolute"\n'
        f'links = ["crank", "c{i}"]\nat = [0.0, 0.0]\n'
        for i in range(1, 5)
    )
    with pytest.raises(assur.ModelError) as caught:
        assur.loads(text)
    assert "has its joints 'A', 'A1', 'A2', 'A3', ... (5 in all) at the pivot" in str(
        caught.value
    )


def test_a_crank_with_a_slide_through_its_pivot_drives():
    # a slide line through the pivot still turns with the crank
    text = (EXAMPLES / "scotch_yoke.toml").read_text(encoding="utf-8")
    assert assur.kinematics(assur.loads(text), [0.0, 30.0])


# --- every entry, every odd value -------------------------------------------------

ODD = [
    None,
    True,
    "x",
    "",
    math.nan,
    math.inf,
    -math.inf,
    1e308,
    -1e308,
    1e16,
    10**30,
    [],
    {},
    [1.0],
    [[0.0, 0.0]],
    {"from": "A"},
    [None, None],
    ["A", 1.0],
]


def leaves(data, path=()):
    """Every path to a value of the file's data (tables and lists included)."""
    yield path
    if isinstance(data, dict):
        for key, value in data.items():
            yield from leaves(value, (*path, key))
    elif isinstance(data, list):
        for index, value in enumerate(data):
            yield from leaves(value, (*path, index))


def replaced(data, path, value):
    data = json.loads(json.dumps(data))
    if not path:
        return value
    target = data
    for key in path[:-1]:
        target = target[key]
    target[path[-1]] = value
    return data


def test_no_odd_value_anywhere_crashes():
    text = (
        BASE + '\n[[loads]]\nlink = "rod"\nat = "B"\nforce = [1.0, 0.0]\ntorque = 1.0\n'
    )
    text += "\n[gravity]\ng = [0.0, -9.81]\n\n[points]\n"
    text += 'P = { link = "rod", at = [0.1, 0.0] }\n'
    data = tomllib.loads(text)
    tried = 0
    for path in leaves(data):
        for value in ODD:
            tried += 1
            body = json.dumps(replaced(data, path, value))
            try:
                mech = assur.loads(body, json_format=True)
            except ModelError as err:
                line = str(err)
                assert "\n" not in line
                assert len(line) < 400, line
                continue
            with contextlib.suppress(AssurError):  # decomposes, or says why
                assur.structure(mech)
    assert tried > 500
