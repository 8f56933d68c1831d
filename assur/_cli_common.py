"""What every command of the command line shares: positions, the file, option checks.

:mod:`assur.cli` and :mod:`assur.pictures_cli` both read the mechanism file, turn
``--angles`` into driver positions and check their options here, so that neither
imports the other. Faults of an option raise :class:`~assur.errors.UsageError`.
Their arguments' types (names, numbers, FILE) are :mod:`assur._cli_types`'.
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path
from typing import Any

import numpy as np

from assur._cli_types import plain_number
from assur._decimal_comma import HINT, has_decimal_comma, range_hint
from assur._output import path_text, standard_output
from assur._targets import stdout_is
from assur._text import counted, describe, spoken
from assur.errors import UsageError

__all__ = [
    "MAX_POSITIONS",
    "check_distinct",
    "check_not_input",
    "check_range",
    "check_structure",
    "load_mechanism",
    "parse_angles",
    "positions",
    "terminal",
]

MAX_POSITIONS = 10_000_000
"""Most driver positions one command analyses (the library takes any number)."""


def parse_angles(spec: str, drivers: int = 1, option: str = "--angles") -> np.ndarray:
    """Parse ``START:STOP:STEP`` (STOP included when on the grid) or a single value.

    Several drivers take one range each, separated by commas, with equal counts.
    ``option`` names the option in messages.

    Raises
    ------
    UsageError
        When ``spec`` cannot be read or gives more than :data:`MAX_POSITIONS`.

    Examples
    --------
    >>> parse_angles("0:90:45").tolist()
    [0.0, 45.0, 90.0]
    >>> parse_angles("0:10:5,30:40:5", drivers=2).tolist()
    [[0.0, 30.0], [5.0, 35.0], [10.0, 40.0]]
    """
    parts = spec.split(",")
    if len(parts) != drivers:
        msg = (
            f"{option}: {counted(len(parts), 'range')} given for "
            f"{counted(drivers, 'driver')}; expected one START:STOP:STEP per driver, "
            "separated by commas"
        ) + range_hint(parts)
        raise UsageError(msg)
    ranges = [_one_range(part, option) for part in parts]
    if len({len(r) for r in ranges}) != 1:
        counts = spoken([str(len(r)) for r in ranges])
        # two drivers: "0:90:22,5" splits into a range and a value, never equal
        msg = f"{option}: the ranges have {counts} positions; expected equal counts"
        raise UsageError(msg + range_hint(parts))
    return ranges[0] if drivers == 1 else np.stack(ranges, axis=-1)


def _one_range(text: str, option: str) -> np.ndarray:
    """Return the positions of one ``START:STOP:STEP`` or of a single value."""
    fields = text.split(":")
    try:
        values = [plain_number(f) for f in fields]
    except ValueError:
        values = []
    if len(values) == 1 and math.isfinite(values[0]):
        return np.array(values)
    if len(values) != 3 or not all(map(math.isfinite, values)):
        # "inf" is read, and is no position: said so, not "cannot read"
        fault = (
            f"{describe(text)} holds a number that is not finite"
            if len(values) in (1, 3)
            else f"cannot read {describe(text)}"
        )
        msg = (
            f"{option}: {fault}; expected START:STOP:STEP with a step that leads "
            "from START to STOP, or a single value"
        )
        raise UsageError(msg)
    start, stop, step = values
    if step == 0 or (stop - start) * math.copysign(1.0, step) < 0:
        # read, but going nowhere: "cannot read" it was
        how = "is 0" if step == 0 else "leads away from STOP"
        hint = f" ({-step:g} here)" if step else ""
        msg = (
            f"{option}: in {describe(text)} the step {how}; expected a step that "
            f"leads from START to STOP{hint}"
        )
        raise UsageError(msg)
    # halves first: STOP - START may overflow where their halves do not
    count = (stop / 2 - start / 2) / step * 2
    if not count < MAX_POSITIONS:
        # a count too long to read is given by its size (1e+300, not 301 digits)
        shown = (
            "too many"
            if not math.isfinite(count)
            else f"{math.floor(count) + 1}"
            if count < 1e15
            else f"about {count:.3g}"
        )
        msg = (
            f"{option}: {describe(text)} gives {shown} positions; expected at most "
            f"{MAX_POSITIONS} (a larger step)"
        )
        raise UsageError(msg)
    # in halves too (exact scalings by 2): STEP times a count may overflow where
    # the positions do not
    found = 2.0 * (start / 2 + step / 2 * np.arange(math.floor(count + 1e-9) + 1))
    # compared, not subtracted: neighbours near the largest float overflow
    ahead = found[1:] > found[:-1] if step > 0 else found[1:] < found[:-1]
    if not np.all(ahead):
        msg = (
            f"{option}: in {describe(text)} the step is below the resolution of the "
            "positions (some come out equal); expected a larger step"
        )
        raise UsageError(msg)
    return found


def positions(mech: Any, spec: str | None, option: str = "--angles") -> np.ndarray:
    """Driver positions from ``--angles`` or the default full turn."""
    from assur.analysis import default_positions

    check_structure(mech)
    if spec is None:
        return default_positions(mech)
    return parse_angles(spec, max(1, len(mech.drivers)), option)


def load_mechanism(path: Path) -> Any:
    """Read the mechanism file named on the command line (``-``: standard input).

    Raises
    ------
    UsageError
        When standard output is that very file (``>> m.toml``): whatever the
        command prints, a table or a "wrote" line, would be added to it.
    """
    from assur._stdin import STDIN, from_stdin
    from assur.io import load

    if str(path) == STDIN:
        return from_stdin()
    if stdout_is(path):
        msg = (
            "standard output is the mechanism file being read (a redirection to "
            "it); expected another file for the output"
        )
        raise UsageError(msg)
    return load(path)


def check_range(
    option: str, value: float, low: float, high: float, wanted: str, unit: str
) -> float:
    """Return ``value`` if it lies in [low, high], else raise a UsageError.

    Examples
    --------
    >>> check_range("--dpi", 150.0, 10, 1200, "a resolution", "dots per inch")
    150.0
    """
    if not low <= value <= high:
        msg = f"{option} {value:g}: expected {wanted} from {low:g} to {high:g} {unit}"
        raise UsageError(msg)
    return float(value)


def add_angle_option(parser: Any) -> None:
    """Add ``--angle DEG``, the one position of ``explain``, ``plans`` and ``plot``."""
    parser.add_argument(
        "--angle",
        metavar="DEG",
        help="driver position, deg (m for a prismatic driver; one per driver, "
        "separated by commas); default: the reference pose",
    )


def one_position(mech: Any, spec: str | None) -> Any:
    """Return the one driver position of ``--angle`` (default: the reference pose).

    A value per driver (deg, or m for a prismatic driver), separated by commas; a
    range, or a count that is not the drivers', is a UsageError. A mechanism whose
    structure is wrong (more drivers than degrees of freedom, say) is refused first.

    Examples
    --------
    >>> import assur
    >>> one_position(assur.catalog.four_bar(), "30").tolist()
    [30.0]
    """
    from assur.analysis import reference_position

    check_structure(mech)
    if spec is None:
        # a prismatic driver's default positions start a stroke below the pose
        return reference_position(mech)
    drivers = max(1, len(mech.drivers))
    parts = spec.split(",")
    if ":" in spec:
        msg = (
            f"--angle {describe(spec)[1:-1]}: a range; expected one value per driver "
            "(--angles takes ranges)"
        )
        raise UsageError(msg)
    values = []
    for part in parts:
        try:
            value = plain_number(part)
        except ValueError:
            value = None
        if value is None or not math.isfinite(value):
            # "1e400" and "inf" are read, and are no position: said so
            fault = "cannot read" if value is None else "not a finite number:"
            msg = (
                f"--angle: {fault} {describe(part)}; expected a number, one per "
                "driver separated by commas"
            )
            raise UsageError(msg)
        values.append(value)
    if len(values) != drivers:
        msg = (
            f"--angle {describe(spec)[1:-1]}: {counted(len(values), 'value')} for "
            f"{counted(drivers, 'driver')}; expected one value per driver, separated "
            "by commas"
        ) + (HINT if has_decimal_comma(spec) else "")
        raise UsageError(msg)
    return np.array(values)


def check_structure(mech: Any) -> None:
    """Raise the error of a mechanism whose structure is wrong, if it has one.

    Positions are counted per driver: with more drivers than degrees of freedom a
    message about the count of ``--angles`` would hide the real fault.
    """
    from assur.plan import plan_of

    plan_of(mech)


TABLE_SUFFIXES = {"CSV": (".csv", ".txt"), "Parquet": (".parquet", ".pq")}
"""The names a table file of each format may end in."""
OTHER_SUFFIXES = frozenset(
    {".csv", ".txt", ".parquet", ".pq", ".json", ".toml", ".html", ".htm", ".md"}
    | {".tex", ".png", ".svg", ".pdf", ".gif", ".xlsx", ".xls"}
)
"""Names of files of a known format: a table of another is refused under them (a
name of no known format, or none, is taken as given)."""


def check_table_suffix(option: str, target: Any, kind: str) -> None:
    """Refuse a table file named for another format (``--csv x.parquet``).

    ``kind`` is ``"CSV"`` or ``"Parquet"``; standard output is let through.
    """
    if not target or target == "-" or is_stdout(target):
        return
    suffix = Path(target).suffix.lower()
    allowed = TABLE_SUFFIXES[kind]
    if suffix in OTHER_SUFFIXES and suffix not in allowed:
        msg = (
            f"{option} {path_text(target)}: a {suffix} name for {kind}; expected a "
            f"name ending in {spoken(allowed, 'or')}"
        )
        raise UsageError(msg)
    folder_there(target)


def folder_there(path: Any) -> None:
    """Refuse, before the work, a file whose folder is missing, or that is a folder.

    Raises
    ------
    OutputError
        As the write would, after the analysis: "cannot write the file (No such
        file or directory)", or "(it is a folder)".
    """
    from assur._targets import a_folder, missing_folder
    from assur.errors import OutputError

    if Path(path).is_dir():
        # assur dynamics wrote its tables after the model and the start-up
        raise OutputError(a_folder(path))
    fault = missing_folder(path)
    if fault is not None:
        msg = f"{path_text(path)}: cannot write the file ({fault})"
        raise OutputError(msg)


def check_not_input(
    option: str, output: Any, source: Path, what: str = "the mechanism file"
) -> None:
    """Refuse an output that is a file read (the same file, any name).

    ``what`` names the file read in the message.
    """
    if str(output) == "-":
        return
    if _same_file(output, source):
        msg = (
            f"{option} {path_text(output)}: is {what} being read; "
            "expected another file for the output"
        )
        raise UsageError(msg)


def check_distinct(outputs: list[tuple[str, Any]]) -> None:
    """Refuse two outputs (option, path) that name the same file.

    Each would be written whole in turn, the last replacing the first: a file
    silently lost. Standard output (``-``) and options not given are left out.
    """
    seen: list[tuple[str, Any]] = []
    for option, path in outputs:
        if not path or str(path) == "-":
            continue
        for other, earlier in seen:
            if _same_file(path, earlier):
                msg = (
                    f"{option} {path_text(path)}: is the file of {other} too; "
                    "expected a file of its own for each output"
                )
                raise UsageError(msg)
        seen.append((option, path))


def quiet(args: Any) -> bool:
    """Whether the command was asked to be quiet (``-q``, before or after it)."""
    return bool(getattr(args, "quiet", False))


def is_stdout(path: Any) -> bool:
    """Whether ``path`` names the file standard output writes to (``/dev/stdout``)."""
    return str(path) == "-" or standard_output(path)


def _same_file(a: Any, b: Any) -> bool:
    """Whether paths ``a`` and ``b`` name one file (existing or not)."""
    try:
        return os.path.samefile(a, b)
    except (OSError, ValueError):
        return os.path.realpath(a) == os.path.realpath(b)


def terminal() -> bool:
    """Whether standard error is a terminal (where progress bars go)."""
    try:
        return bool(sys.stderr.isatty())
    except (AttributeError, OSError, ValueError):
        return False


def bar_shown(args: Any, *outputs: Any) -> bool:
    """Whether long work shows a progress bar (on standard error).

    On a terminal, without ``-q``, and not while a table streams to standard output
    on a terminal too (``--csv -`` read on the screen): the bar's redrawn line would
    run into the table's rows. ``outputs`` are the paths the work writes as it goes
    (``True`` for standard output).
    """
    if quiet(args) or not terminal():
        return False
    if any(path is True or (path and is_stdout(path)) for path in outputs):
        try:
            return not sys.stdout.isatty()
        except (AttributeError, OSError, ValueError):
            return True
    return True


def skip_hint(args: Any, err: Exception) -> str:
    """Return a hint of --skip-unassembled after a position a sweep cannot solve.

    Only for a command that has the option and was not given it.
    """
    from assur.errors import AssemblyError, SelfLockingError, SingularConfigurationError

    stops = (AssemblyError, SelfLockingError, SingularConfigurationError)
    if getattr(args, "skip_unassembled", True) or not isinstance(err, stops):
        return ""
    return " (--skip-unassembled leaves such positions out)"
