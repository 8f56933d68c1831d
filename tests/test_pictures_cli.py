"""The picture commands: ``assur plot|diagrams|animate|report`` (assur.pictures_cli).

Each command is run through ``assur.cli.main`` with files in ``tmp_path``; the tests
check the exit status, the one-line errors, that the files written are valid and
that no figure is left open.
"""

from __future__ import annotations

import sys
import types
import warnings
from pathlib import Path

import matplotlib
import numpy as np
import pytest

from assur.cli import main
from assur.errors import UsageError

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from PIL import Image

EXAMPLES = Path(__file__).parent.parent / "examples"
TENBAR = str(EXAMPLES / "tenbar.toml")
SLIDER = str(EXAMPLES / "slider_crank_exercise.toml")
SLOT = str(EXAMPLES / "slot_mechanism.toml")
FIVE_BAR = str(EXAMPLES / "five_bar_two_cranks.toml")
KINEMATIC = {"motion.png", "paths.png", "decomposition.png"}
KINETIC = {"torque.png", "hodographs.png", "shaking.png"}


@pytest.fixture(autouse=True)
def _no_figure_left_open():
    before = plt.get_fignums()
    yield
    assert plt.get_fignums() == before


def _run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def _error_line(err: str, *parts: str) -> None:
    """One line, in the command line's format, mentioning every part."""
    assert err.count("\n") == 1
    assert err.startswith("assur: error: ")
    for part in parts:
        assert part in err


def _png(path: Path) -> tuple[int, int]:
    with Image.open(path) as im:
        assert im.format == "PNG"
        return im.size


# ------------------------------------------------------------------------ plot


@pytest.mark.pictures
@pytest.mark.parametrize("file", [TENBAR, SLIDER, SLOT, FIVE_BAR])
def test_plot_png(
    file: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "m.png"
    status, stdout, err = _run(capsys, "plot", file, "-o", str(out))
    assert status == 0, err
    assert stdout == f"wrote {out}\n"
    width, height = _png(out)
    assert width > 600
    assert height > 200


@pytest.mark.pictures
def test_a_matplotlibrc_asking_for_latex_is_not_followed(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # text.usetex in a matplotlibrc made every picture command fail with a
    # traceback where no LaTeX is installed (and drew in another style where it is)
    out = tmp_path / "m.png"
    with matplotlib.rc_context({"text.usetex": True}):
        status, _, err = _run(capsys, "plot", SLIDER, "--forces", "-o", str(out))
        assert status == 0, err
        assert err == ""
        assert matplotlib.rcParams["text.usetex"] is True  # the caller's stands
    assert _png(out)[0] > 600


@pytest.mark.pictures
def test_plot_forces_at_an_angle(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "forces.png"
    status, _, err = _run(
        capsys,
        "plot",
        SLIDER,
        "--angle",
        "30",
        "--forces",
        "--scale",
        "1000",
        "-o",
        str(out),
    )
    assert status == 0, err
    _png(out)


@pytest.mark.pictures
@pytest.mark.parametrize(("suffix", "magic"), [(".svg", b"<?xml"), (".pdf", b"%PDF")])
def test_plot_svg_and_pdf(
    suffix: str, magic: bytes, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out, again = tmp_path / f"m{suffix.upper()}", tmp_path / f"again{suffix}"
    for path in (out, again):
        status, _, err = _run(
            capsys, "plot", SLOT, "--angle", "100", "--no-labels", "-o", str(path)
        )
        assert status == 0, err
    assert out.read_bytes().startswith(magic)
    # the same picture, the same bytes: no time of writing, no random clip names
    assert again.read_bytes() == out.read_bytes()


@pytest.mark.pictures
def test_plot_two_drivers_one_angle_each(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "five.png"
    assert (
        _run(capsys, "plot", FIVE_BAR, "--angle", "70,100", "--forces", "-o", str(out))[
            0
        ]
        == 0
    )
    _png(out)
    status, _, err = _run(capsys, "plot", FIVE_BAR, "--angle", "70", "-o", str(out))
    assert status == 2
    _error_line(err, FIVE_BAR, "--angle 70: 1 value for 2 drivers")


@pytest.mark.parametrize(
    ("argv", "parts"),
    [
        (["--forces"], ["tenbar.toml", "no link has a mass"]),
        (["--angle", "0:90:45"], ["--angle 0:90:45: a range; expected one value"]),
        (["--angle", "abc"], ["--angle: cannot read 'abc'; expected a number"]),
        (["--angle", "30,40"], ["--angle 30,40: 2 values for 1 driver"]),
        (["--scale", "-5"], ["--scale -5: expected a positive number"]),
        # nothing is drawn to a force scale without forces: it was silently ignored
        (
            ["--scale", "100"],
            ["--scale 100: a force scale, for --forces or --group; expected one"],
        ),
        (["--dpi", "0"], ["--dpi 0: expected a positive resolution"]),
    ],
)
def test_plot_bad_options(
    argv: list[str],
    parts: list[str],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    out = tmp_path / "m.png"
    status, stdout, err = _run(capsys, "plot", TENBAR, *argv, "-o", str(out))
    assert status == 2
    assert stdout == ""
    _error_line(err, *parts)
    assert not out.exists()


@pytest.mark.parametrize("scale", ["1e-300", "5e-324"])
@pytest.mark.parametrize("what", [["--forces"], ["--group", "1"]])
def test_plot_refuses_a_force_scale_that_draws_the_forces_far_too_long(
    scale: str,
    what: list[str],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    # 1e-300 N per cm printed numpy's "overflow encountered in scalar multiply"
    # (tests turn warnings into errors), 5e-324 a traceback
    out = tmp_path / "m.png"
    status, _, err = _run(
        capsys, "plot", SLIDER, *what, "--scale", scale, "-o", str(out)
    )
    assert status == 2
    _error_line(err, f"--scale {float(scale):g}: draws the largest force", "N per cm")
    assert not out.exists()


def test_plot_unknown_suffix(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status, _, err = _run(capsys, "plot", TENBAR, "-o", str(tmp_path / "m.bmp"))
    assert status == 2
    _error_line(err, "unknown file type '.bmp'; expected .png, .svg or .pdf")


@pytest.mark.parametrize(
    ("command", "what", "wanted"),
    [
        ("plot", "a picture", ".png, .svg or .pdf"),
        ("animate", "an animation", ".gif"),
        ("report", "a report", ".html or .htm"),
    ],
)
def test_a_picture_to_standard_output_is_refused_as_such(
    command: str,
    what: str,
    wanted: str,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # "-o -" said "unknown file type '(none)'"
    monkeypatch.chdir(tmp_path)
    status, out, err = _run(capsys, command, SLIDER, "-o", "-")
    assert (status, out) == (2, "")
    _error_line(
        err,
        f"-o -: standard output cannot take {what}; expected a file name ending in "
        f"{wanted}",
    )
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("command", ["plot", "animate", "report"])
def test_a_picture_into_a_folder_is_refused_as_such(
    command: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # "-o FOLDER" said "unknown file type '(none)'"
    status, _, err = _run(capsys, command, SLIDER, "-o", str(tmp_path))
    assert status == 2
    _error_line(err, f"-o {tmp_path}: is a folder; expected a file name ending in .")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("command", "name", "wanted"),
    [("plot", "picture", ".png, .svg or .pdf"), ("animate", ".gif", ".gif")],
)
def test_a_picture_named_without_a_suffix_is_said_so(
    command: str,
    name: str,
    wanted: str,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    # "unknown file type '(none)'", as if "(none)" were the suffix
    target = tmp_path / name
    status, _, err = _run(capsys, command, SLIDER, "-o", str(target))
    assert status == 2
    _error_line(err, f"-o {target}: no suffix; expected {wanted}")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("command", ["diagrams", "plans"])
def test_a_set_of_pictures_to_standard_output_is_refused(
    command: str,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # a folder named "-" was made
    monkeypatch.chdir(tmp_path)
    status, _, err = _run(capsys, command, SLIDER, "-o", "-")
    assert status == 2
    _error_line(err, "-o -: standard output cannot take a folder of ")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("command", ["diagrams", "plans"])
def test_a_folder_of_pictures_is_made_only_in_one_that_is_there(
    command: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # the whole tree was made, where --csv no/such/t.csv is an error
    target = tmp_path / "no" / "such" / "dir"
    status, _, err = _run(capsys, command, SLIDER, "-o", str(target))
    assert status == 2
    _error_line(
        err,
        f"assur: error: {target}: cannot make the folder (No such file or directory: "
        f"{target.parent}); expected a folder in an existing one",
    )
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("command", "name"), [("plot", "p.png"), ("animate", "a.gif"), ("report", "r.html")]
)
def test_a_file_in_a_missing_folder_is_refused_before_the_analysis(
    command: str,
    name: str,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # found only once the report's analysis was done
    import assur._picture_animate
    import assur.pictures_cli

    def analysed(path: object) -> None:
        msg = "the mechanism was read"
        raise AssertionError(msg)

    for module in (assur.pictures_cli, assur._picture_animate):
        monkeypatch.setattr(module, "load_mechanism", analysed, raising=False)
    target = tmp_path / "no" / name
    status, _, err = _run(capsys, command, SLIDER, "-o", str(target))
    assert status == 2
    assert err == (
        f"assur: error: {target}: cannot write the file (No such file or directory)\n"
    )


def test_plot_missing_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    missing = tmp_path / "nope.toml"
    status, _, err = _run(capsys, "plot", str(missing), "-o", str(tmp_path / "m.png"))
    assert status == 2
    _error_line(err, str(missing), "cannot read the file")


def test_plot_unwritable_output(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "no" / "such" / "folder" / "m.png"
    status, _, err = _run(capsys, "plot", TENBAR, "-o", str(out))
    assert status == 2
    _error_line(err, "cannot write the file")


def test_plot_needs_an_output(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["plot", TENBAR]) == 2
    assert "-o/--output" in capsys.readouterr().err


# -------------------------------------------------------------------- diagrams


@pytest.mark.pictures
def test_diagrams_kinematics_only(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "tenbar"
    status, stdout, err = _run(
        capsys,
        "diagrams",
        TENBAR,
        "--angles",
        "0:360:30",
        "--dpi",
        "40",
        "-o",
        str(out),
    )
    assert status == 0, err
    # the ten-bar's sliders get their slides drawn
    assert {p.name for p in out.iterdir()} == KINEMATIC | {"slides.png"}
    assert stdout.count("wrote ") == 4
    for path in out.iterdir():
        _png(path)


@pytest.mark.pictures
def test_diagrams_with_forces(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "d"
    status, _, err = _run(
        capsys, "diagrams", SLOT, "--angles", "40:400:30", "--dpi", "40", "-o", str(out)
    )
    assert status == 0, err
    # its slot and guide are prismatic: their slides are drawn too
    want = KINEMATIC | KINETIC | {"dynamics.png", "slides.png"}
    assert {p.name for p in out.iterdir()} == want
    for path in out.iterdir():
        _png(path)


@pytest.mark.pictures
def test_diagrams_two_drivers(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status, _, err = _run(
        capsys,
        "diagrams",
        FIVE_BAR,
        "--angles",
        "60:420:30,120:480:30",
        "--dpi",
        "40",
        "-o",
        str(tmp_path),
    )
    assert status == 0, err
    assert {p.name for p in tmp_path.iterdir()} == KINEMATIC | KINETIC


def test_diagrams_into_a_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "taken.png"
    target.write_text("x", encoding="utf-8")
    status, _, err = _run(capsys, "diagrams", TENBAR, "-o", str(target))
    assert status == 2
    _error_line(err, "is a file; expected a folder")


@pytest.mark.parametrize("command", ["diagrams", "plans"])
def test_a_folder_named_like_a_picture_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], command: str
) -> None:
    # -o x.png made a folder named x.png for the pictures
    target = tmp_path / "x.png"
    status, _, err = _run(capsys, command, TENBAR, "-o", str(target))
    assert status == 2
    _error_line(err, f"-o {target}: a .png file's name; expected a folder for the")
    assert not target.exists()


@pytest.mark.pictures
def test_diagrams_over_a_folder_in_a_picture_s_place_replace_none(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # dynamics.png, hodographs.png and motion.png were replaced before paths.png
    # failed, and the message named the folder, not the file
    out = tmp_path / "d"
    argv = ["diagrams", SLIDER, "--angles", "0:360:60", "--dpi", "30", "-o", str(out)]
    status, _, err = _run(capsys, *argv)
    assert status == 0, err
    old = {p.name: p.read_bytes() for p in out.iterdir()}
    (out / "paths.png").unlink()
    (out / "paths.png").mkdir()
    status, _, err = _run(capsys, *argv[:3], "0:360:30", *argv[4:])
    assert status == 2
    assert err == (
        f"assur: error: {out / 'paths.png'}: cannot write the file (it is a folder); "
        "expected a file\n"
    )
    for name, data in old.items():
        if name != "paths.png":
            assert (out / name).read_bytes() == data, name
    assert {p.name for p in tmp_path.iterdir()} == {"d"}


# --------------------------------------------------------------------- animate


@pytest.mark.pictures
def test_animate_gif(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "slot.gif"
    status, stdout, err = _run(
        capsys,
        "animate",
        SLOT,
        "--frames",
        "3",
        "--forces",
        "--fps",
        "5",
        "-o",
        str(out),
    )
    assert status == 0, err
    assert stdout == f"wrote {out} (3 frames)\n"
    with Image.open(out) as gif:
        assert gif.format == "GIF"
        assert gif.n_frames == 3
        assert gif.info["duration"] == pytest.approx(200, abs=10)


@pytest.mark.pictures
def test_animate_frames_spread_over_the_angles(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "five.gif"
    status, stdout, _ = _run(
        capsys, "animate", FIVE_BAR, "--angles", "60:120:30,120:180:30", "-o", str(out)
    )
    assert status == 0
    assert stdout.endswith("(3 frames)\n")
    with Image.open(out) as gif:
        assert gif.n_frames == 3


@pytest.mark.pictures
def test_animate_forces_of_a_prismatic_driver(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # the sweep was checked with driver.torque, which a prismatic driver has not
    out = tmp_path / "ram.gif"
    ram = str(Path(__file__).parent / "data" / "explain" / "ram_only.toml")
    argv = ["animate", ram, "--forces", "--frames", "3", "-o", str(out)]
    status, stdout, err = _run(capsys, *argv)
    assert status == 0, err
    assert stdout == f"wrote {out} (3 frames)\n"
    with Image.open(out) as gif:
        assert gif.n_frames == 3


@pytest.mark.parametrize(
    ("argv", "parts"),
    [
        (["-o", "x.mp4"], ["unknown file type '.mp4'; expected .gif"]),
        (["--frames", "0", "-o", "x.gif"], ["expected at least one frame"]),
        (["--forces", "-o", "x.gif"], ["no link has a mass"]),
    ],
)
def test_animate_bad_input(
    argv: list[str],
    parts: list[str],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.chdir(tmp_path)
    status, _, err = _run(capsys, "animate", TENBAR, *argv)
    assert status == 2
    _error_line(err, *parts)
    assert list(tmp_path.iterdir()) == []


def test_animate_refuses_frames_too_large_for_memory_first(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # every frame is kept until the last is drawn: 360 at 300 dpi take 9 GB, and
    # the system killed the command without a word
    import assur.plotting

    def drawn(*args: object, **kwargs: object) -> int:
        msg = "a film too large for memory was drawn"
        raise AssertionError(msg)

    monkeypatch.setattr(assur.plotting, "animate", drawn)
    out = tmp_path / "a.gif"
    argv = ["animate", SLIDER, "-o", str(out), "--frames", "1000", "--dpi", "300"]
    status, _, err = _run(capsys, *argv)
    assert status == 2
    _error_line(
        err,
        "--frames 1000 --dpi 300: 360 frames of up to 20.5 MB, 7.38 GB in all",
        "expected at most 2 GiB of frames: at most 104 frames at --dpi 300",
    )
    assert not out.exists()


def test_a_film_of_the_most_frames_fits_at_the_default_resolution() -> None:
    from assur._picture_animate import FPS_RANGE, FRAMES_RANGE, _check_film
    from assur.plotting.animation import FILM_BYTES, MOST_FPS

    _check_film(FRAMES_RANGE[1], FRAMES_RANGE[1], 80.0)
    _check_film(104, 104, 300.0)
    with pytest.raises(UsageError, match="at most 104 frames at --dpi 300"):
        _check_film(105, 105, 300.0)
    assert FILM_BYTES == 2 * 1024**3
    assert FPS_RANGE[1] == MOST_FPS


# ---------------------------------------------------------------------- report


@pytest.fixture
def fake_html(monkeypatch: pytest.MonkeyPatch) -> list[tuple]:
    """Stand in for assur.html and record how write_report is called."""
    calls: list[tuple] = []

    def write_report(mechanism, path, angles=None, progress=False, parts=None):
        calls.append((mechanism, path, angles))
        if callable(progress):  # the command's bar, told of the sweep
            progress(1, 1)
        if callable(parts):  # and of the page's parts after it
            parts(1, 1)
        Path(path).write_text("<html></html>", encoding="utf-8")

    module = types.ModuleType("assur.html")
    module.write_report = write_report
    monkeypatch.setitem(sys.modules, "assur.html", module)
    return calls


def test_report_calls_write_report(
    fake_html: list[tuple], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "r.html"
    status, stdout, _ = _run(capsys, "report", SLIDER, "-o", str(out))
    assert status == 0
    assert stdout == f"wrote {out}\n"
    ((mech, path, angles),) = fake_html
    assert mech.name == "Slider-crank exercise"
    assert Path(path) == out
    assert angles is None


def test_report_passes_the_angles(
    fake_html: list[tuple], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert (
        _run(
            capsys,
            "report",
            SLIDER,
            "--angles",
            "0:90:45",
            "-o",
            str(tmp_path / "r.htm"),
        )[0]
        == 0
    )
    np.testing.assert_array_equal(fake_html[0][2], [0.0, 45.0, 90.0])


def test_report_names_the_positions_it_leaves_out(
    fake_html: list[tuple], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # the page left out 123 positions of 360 without a word on the command line
    out = tmp_path / "r.html"
    status, stdout, err = _run(capsys, "report", TRIAD_P, "-o", str(out))
    assert status == 0, err
    (note,) = err.splitlines()
    assert note.startswith(f"assur: note: {TRIAD_P}: left out 123 positions ")
    assert stdout == f"wrote {out}\n"
    status, _, err = _run(capsys, "-q", "report", TRIAD_P, "-o", str(out))
    assert (status, err) == (0, "")


def test_report_bad_suffix(
    fake_html: list[tuple], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status, _, err = _run(capsys, "report", SLIDER, "-o", str(tmp_path / "r.txt"))
    assert status == 2
    _error_line(err, "unknown file type '.txt'; expected .html or .htm")
    assert fake_html == []


def test_report_without_the_html_module(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setitem(sys.modules, "assur.html", None)  # makes the import fail
    status, _, err = _run(capsys, "report", SLIDER, "-o", str(tmp_path / "r.html"))
    assert status == 2
    _error_line(err, "the HTML report (assur.html) is not available")


def test_report_real(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("assur.html")
    out = tmp_path / "slot.html"
    status, _, err = _run(
        capsys, "report", SLOT, "--angles", "30:390:30", "-o", str(out)
    )
    assert status == 0, err
    assert "<html" in out.read_text(encoding="utf-8").lower()


# ------------------------------------------------------------- names as written


@pytest.fixture
def dollar_names(tmp_path: Path) -> Path:
    """The four-bar with names that matplotlib would read as mathtext."""
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    text = text.replace('name = "Crank-rocker four-bar"', 'name = "Four-bar $\\\\foo$"')
    text = text.replace("[links.coupler]", '[links."$^$"]').replace("coupler", "$^$")
    text = text.replace('"B"', '"$B_$"').replace("[joints.B]", '[joints."$B_$"]')
    text = text.replace("P = {", '"$P$" = {')
    path = tmp_path / "dollars.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.pictures
@pytest.mark.parametrize(
    "argv",
    [
        ["plot", "--forces", "-o", "p.png"],
        ["plot", "--group", "1", "-o", "g.png"],
        ["plans", "--angle", "30", "-o", "plans"],
        ["diagrams", "-o", "diagrams"],
        ["animate", "--frames", "2", "-o", "a.gif"],
        ["report", "-o", "r.html"],
    ],
)
def test_names_with_dollars_are_drawn_as_written(
    capsys: pytest.CaptureFixture[str], dollar_names: Path, argv: list[str]
):
    # a name between two $ was parsed as mathtext: "$^$" failed to draw
    command, *options = argv
    out = dollar_names.parent / options[-1]
    options[-1] = str(out)
    status, _, err = _run(capsys, command, str(dollar_names), *options, "-q")
    assert status == 0, err
    assert err == ""
    assert out.exists()


def test_a_name_with_dollars_is_shown_literally():
    from matplotlib import cbook

    from assur.plotting._style import literal

    assert cbook.is_math_text("$^$ and $x$")
    assert not cbook.is_math_text(literal("$^$ and $x$"))
    fig, ax = plt.subplots()
    try:
        ax.text(0, 0, literal("$^$ and $\\foo$"))
        fig.canvas.draw()  # mathtext would fail on both
    finally:
        plt.close(fig)


# ------------------------------------------------- sweeps a crank cannot go round

TRIAD_P = str(Path(__file__).parent / "data" / "edge" / "triadP.toml")


@pytest.mark.pictures
def test_diagrams_skip_positions_a_crank_cannot_reach(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
):
    # the report draws such a sweep; diagrams refused it with no way round
    out = tmp_path / "d"
    status, _, err = _run(capsys, "diagrams", TRIAD_P, "-o", str(out), "-q")
    assert status == 2
    _error_line(err, "cannot be assembled at driver position 115 deg", "of 360")
    status, _, err = _run(
        capsys, "diagrams", TRIAD_P, "-o", str(out), "-q", "--skip-unassembled"
    )
    assert status == 0, err
    assert "note" not in err  # --quiet: no note (the warning of no dynamics stays)
    assert {p.name for p in out.iterdir()} >= KINEMATIC
    # without --quiet the positions left out are named, as `forces` names them
    status, _, err = _run(
        capsys, "diagrams", TRIAD_P, "-o", str(out), "--skip-unassembled"
    )
    assert status == 0, err
    (note,) = (line for line in err.splitlines() if "note" in line)
    assert note.startswith(f"assur: note: {TRIAD_P}: left out 123 positions ")
    # one run of 123 positions, a degree apart
    assert note.endswith(": 115 deg to 237 deg")


@pytest.mark.pictures
def test_animate_counts_the_sweep_and_skips_over_it(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
):
    out = tmp_path / "a.gif"
    argv = ["animate", TRIAD_P, "--frames", "3", "-o", str(out)]
    status, _, err = _run(capsys, *argv)
    assert status == 2
    # the sweep's 360 positions, not the 3 frames picked from it
    _error_line(err, "(123 of 360 positions fail)")
    status, out_text, err = _run(capsys, *argv, "--skip-unassembled")
    assert status == 0, err
    assert "(3 frames)" in out_text
    # the note counts the sweep's positions left out, not the frames'
    (note,) = err.splitlines()
    assert f"{TRIAD_P}: left out 123 positions " in note
    with Image.open(out) as im:
        assert im.n_frames == 3
    status, _, err = _run(capsys, *argv, "--skip-unassembled", "--angles", "200:220:1")
    assert status == 2
    _error_line(err, "every position of the sweep is left out")


def test_a_picture_s_name_ending_with_a_slash_is_refused(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
):
    # a Path dropped the slash: "-o x.svg/" wrote x.svg
    target = f"{tmp_path / 'x.svg'}/"
    status, _, err = _run(capsys, "plot", SLIDER, "-o", target)
    assert status == 2
    assert "the name ends with '/', as a folder's; expected a file" in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.pictures
def test_diagrams_of_one_position_print_no_warning(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
):
    # matplotlib's "No artists with labels found" came out with its source lines
    out = tmp_path / "d"
    argv = ["diagrams", str(EXAMPLES / "four_bar.toml"), "-o", str(out), "-q"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        status, _, err = _run(capsys, *argv, "--angles", "10")
    assert (status, err) == (0, "")
    assert {p.name for p in out.iterdir()} >= KINEMATIC


@pytest.mark.parametrize(
    ("command", "why"),
    [
        ("diagrams", "diagrams draw every position"),
        ("report", "the page holds every position"),
    ],
)
def test_a_sweep_too_long_to_draw_is_refused_first(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, command: str, why: str
):
    # 360 000 positions took 1.9 GB for the report, 9 million ran out of memory
    out = tmp_path / ("r.html" if command == "report" else "d")
    argv = [command, str(EXAMPLES / "four_bar.toml"), "-o", str(out)]
    status, _, err = _run(capsys, *argv, "--angles", "0:360:0.001")
    assert status == 2
    _error_line(err, f"--angles: 360001 positions; expected at most 100000 ({why}")
    assert not out.exists()


@pytest.mark.pictures
def test_diagrams_written_again_hold_one_mechanism_s_set(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
):
    # torque.png of a loaded mechanism stayed beside the diagrams of an unloaded one
    out = tmp_path / "d"
    argv = ["diagrams", "-o", str(out), "-q", "--angles", "0:360:30"]
    status, _, _ = _run(capsys, argv[0], str(EXAMPLES / "four_bar.toml"), *argv[1:])
    assert status == 0
    assert (out / "torque.png").exists()
    status, _, _ = _run(capsys, argv[0], str(EXAMPLES / "tenbar.toml"), *argv[1:])
    assert status == 0
    assert {p.name for p in out.iterdir()} == KINEMATIC | {"slides.png"}


def test_the_slides_diagram_draws_each_prismatic_pair_s_motion() -> None:
    """A slider-crank's stroke is the motion that matters: motion.png (the links'
    angles) left it out."""
    import assur
    from assur import plotting
    from assur._picture_panels import slides_figure

    table = assur.kinematics(assur.catalog.slider_crank(), np.arange(0.0, 360.0, 15.0))
    fig = slides_figure(plotting, plt, table, ["guide"])
    try:
        for ax, part in zip(fig.axes, ("s", "v", "a"), strict=True):
            (line,) = ax.lines
            assert line.get_label() == "guide"
            np.testing.assert_allclose(line.get_ydata(), table[f"guide.{part}"])
            assert ax.get_ylabel().startswith(f"{part} [")
    finally:
        plt.close(fig)


def test_the_stacked_panels_share_one_legend_beside_them() -> None:
    """Each of motion.png's panels had its legend, over the ten-bar's curves."""
    import assur
    from assur import plotting
    from assur._picture_panels import motion_figure

    table = assur.kinematics(assur.load(TENBAR), np.arange(0.0, 360.0, 10.0))
    fig = motion_figure(plotting, plt, table)
    try:
        assert all(ax.get_legend() is None for ax in fig.axes)
        (legend,) = fig.legends
        labels = [t.get_text() for t in legend.get_texts()]
        assert labels == [line.get_label() for line in fig.axes[0].lines]
        fig.canvas.draw()
        box = legend.get_window_extent()
        for ax in fig.axes:
            assert box.x0 >= ax.get_window_extent().x1  # beside, covering nothing
    finally:
        plt.close(fig)


@pytest.mark.pictures
def test_plot_group_leaves_out_the_names_with_no_labels(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # --no-labels was not passed on to the free body: the two pictures were the
    # same, pixel for pixel
    named, bare = tmp_path / "named.png", tmp_path / "bare.png"
    for out, extra in ((named, ()), (bare, ("--no-labels",))):
        argv = ("plot", SLIDER, "--angle", "30", "--group", "1", *extra)
        status, _, err = _run(capsys, *argv, "-o", str(out))
        assert status == 0, err
    with Image.open(named) as a, Image.open(bare) as b:
        assert np.asarray(a).shape == np.asarray(b).shape
        assert (np.asarray(a) != np.asarray(b)).any()
