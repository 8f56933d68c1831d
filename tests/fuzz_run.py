"""Run a mechanism text through assur and judge how it ends.

:func:`run_case` reads the text (``assur.loads``), checks that ``assur.dumps`` writes it
back to the same mechanism, finds its structure and runs ``assur.forces`` (or
``assur.kinematics`` when nothing has a mass or a load) at a few driver positions: the
reference pose, +-30 deg and a full turn in 45 deg steps (small slides, in fractions of
the mechanism's size, for a prismatic driver). When a group fails at one of them, the
same positions run again with ``skip_unassembled`` and that table is checked too.
A complete table goes on as a user's would: its summary (a force table), the
explanatory note at its first position and, for one force table in
:data:`DYNAMICS_EVERY`, the dynamic model (:func:`assur.dynamics`), each ending in its
answer or an AssurError with a one-line message.

The :class:`Outcome` is a table (every column finite except the documented NaN,
``driver.torque`` agreeing with ``driver.torque_check``), an AssurError with a
one-line message, or a failure with a signature that names what went wrong and
where: a raw exception and its last assur frame, a case that ran past its time limit,
a NaN or an inf that no AssurWarning explains, a bad message, a warning of another
kind.
"""

from __future__ import annotations

import contextlib
import json
import math
import re
import signal
import threading
import time
import traceback
import warnings
import zlib
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from types import TracebackType
from typing import Any

import numpy as np

import assur
from assur.model import resolve_point
from assur.plan import plan_of

PACKAGE = Path(assur.__file__).resolve().parent
TIME_LIMIT = 30.0
"""Seconds of CPU time a case may take before it counts as a hang.

CPU time, not the clock's: on a machine busy with other work a case takes the
same CPU time but several times the wall time (the slowest fixed case takes about
6 s of CPU here, and took 13 s of wall time at a load of 6 on 2 cores)."""
WAIT_FACTOR = 10.0
"""A case that waits (a lock, a read, a sleep) spends no CPU time: it counts as a
hang after this many times :data:`TIME_LIMIT` of the clock's time."""
MAX_MESSAGE = 400
"""Longest acceptable error message, characters."""
DYNAMICS_ANGLES = tuple(range(0, 360, 30))
"""Crank angles (deg) of the rows of the dynamic model run on a mutant."""
DYNAMICS_EVERY = 8
"""One mutant in this many (chosen by a checksum of its text) runs the dynamic model,
which samples a whole turn on a grid of a thousand positions or more."""
REVOLUTE_STEPS = (0.0, 30.0, -30.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0)
"""Positions of a revolute driver, deg from the reference pose."""
PRISMATIC_STEPS = (0.0, 0.01, -0.01, 0.02, -0.02, 0.05, -0.05, 0.1, -0.1, 0.002)
"""Positions of a prismatic driver, in fractions of the mechanism's size."""
FOREIGN = re.compile(
    r"datetime\.(date|time|datetime)\(|<[\w.]+ object at 0x|\bat 0x[0-9a-f]{6,}"
    r"|np\.float\d*\(|numpy\.|array\(|mappingproxy\(|<class '|Decimal\("
)
"""Python reprs of foreign objects that a message must not show."""
TORQUE_RTOL = 1e-4
TORQUE_ATOL = 1e-6
TORQUE_FLOOR = 1e-290
"""Tolerance of driver.torque against driver.torque_check: relative, relative to the
largest moment in the row (forces times the mechanism's size, couples), and a floor
for loads that are zero but for round-off below the normal floats."""
DIGITS = 8
"""Significant digits of the reference pose below which a disagreement of the
balancing load with its check is put down to the pose (a group of its own)."""


class Hang(BaseException):
    """A case ran past its time limit (not an Exception: assur must not catch it)."""


@dataclass(frozen=True)
class Outcome:
    """How a case ended.

    ``label`` is ``"table"``, the name of an AssurError's class or ``"failure"``;
    a failure has a ``signature`` (what went wrong and where, without line numbers,
    so that failures of one cause group together) and a ``detail`` (the message, the
    traceback's key line).
    """

    label: str
    signature: str = ""
    detail: str = ""
    warned: tuple[str, ...] = field(default=(), compare=False)

    @property
    def failed(self) -> bool:
        """Whether the case is a failure."""
        return self.label == "failure"


def run_case(text: str, time_limit: float | None = TIME_LIMIT) -> Outcome:
    """Run the text through assur; return how it ended (never raises an Exception)."""
    stage = ["loads"]
    try:
        with _time_limit(time_limit), warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                outcome = _pipeline(text, stage, caught)
            except assur.AssurError as err:
                outcome = _assur_error(err)
            except Exception as err:  # what the fuzzer looks for
                where, line = _location(err.__traceback__)
                outcome = Outcome(
                    "failure",
                    f"raw {type(err).__name__} at {where}",
                    f"{line} | {type(err).__name__}: {_cut(str(err))}",
                )
    except Hang as err:
        where, line = _location(err.__traceback__)
        # where the timer struck is chance: the stage names the hang, the frame is
        # the detail
        return Outcome("failure", f"hang in {stage[0]}", f"at {where}: {line}")
    return _judge_warnings(outcome, caught)


@contextlib.contextmanager
def _time_limit(seconds: float | None) -> Iterator[None]:
    """Raise :class:`Hang` after ``seconds`` of CPU time, or :data:`WAIT_FACTOR`
    times as long by the clock (main thread only, else no limit)."""
    if seconds is None or threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum: int, frame: Any) -> None:
        raise Hang

    # CPU time for work that spins; the clock, far longer, for work that waits
    timers = (
        (signal.SIGPROF, signal.ITIMER_PROF, seconds),
        (signal.SIGALRM, signal.ITIMER_REAL, WAIT_FACTOR * seconds),
    )
    saved = [signal.signal(number, handler) for number, _, _ in timers]
    for _, timer, limit in timers:
        signal.setitimer(timer, limit)
    try:
        yield
    finally:
        for (number, timer, _), old in zip(timers, saved, strict=True):
            signal.setitimer(timer, 0)
            signal.signal(number, old)


def _pipeline(text: str, stage: list[str], caught: list[Any]) -> Outcome:
    mech = assur.loads(text)
    stage[0] = "dumps"
    written = assur.dumps(mech)
    if assur.loads(written) != mech:
        return Outcome("failure", "dumps: the written file reads to another mechanism")
    stage[0] = "structure"
    found = assur.structure(mech)
    str(found)
    json.dumps(found.to_dict())
    stage[0] = "positions"
    angles = positions(mech)
    analyse = assur.forces if _has_loads(mech) else assur.kinematics
    stage[0] = analyse.__name__
    try:
        table = analyse(mech, angles)
        first = None
    except (assur.AssemblyError, assur.SingularConfigurationError) as err:
        first = err
        stage[0] = f"{analyse.__name__} (skip_unassembled)"
        table = analyse(mech, angles, skip_unassembled=True)
    stage[0] = "columns"
    problem = check_table(table, _assur_warnings(caught))
    if problem is not None:
        return problem
    if first is not None:
        return _assur_error(first)
    return _further(written, mech, table, stage) or Outcome("table")


def _further(
    written: str, mech: assur.Mechanism, table: assur.Table, stage: list[str]
) -> Any:
    """Run what users run next on a table; return the failure, or None.

    Its summary, the explanatory note at its first position and the dynamic model
    (when a checksum of ``written``, the mechanism as ``assur.dumps`` writes it,
    picks it: comments and layout do not change the choice). A refusal (an
    AssurError) is an answer when its message is one short line.
    """
    steps: list[tuple[str, Any]] = []
    if table.force_state is not None:
        steps.append(("summary", table.summary))
    first = table.given[0].tolist()
    steps.append(("explain", lambda: str(assur.explain(mech, first))))
    if (
        table.force_state is not None
        and zlib.crc32(written.encode()) % DYNAMICS_EVERY == 0
    ):
        steps.append(("dynamics", lambda: assur.dynamics(mech, DYNAMICS_ANGLES)))
    for name, step in steps:
        stage[0] = name
        try:
            step()
        except assur.AssurError as err:
            outcome = _assur_error(err)
            if outcome.failed:
                return Outcome(
                    outcome.label, f"{outcome.signature} in {name}", outcome.detail
                )
    return None


def positions(mech: assur.Mechanism) -> Any:
    """The driver positions of a case: (n,) for one driver, (n, d) for several."""
    plan = plan_of(mech)
    columns = []
    for d in plan.drivers:
        if d.kind == "R":
            columns.append(math.degrees(d.reference) + np.array(REVOLUTE_STEPS))
        else:
            columns.append(d.reference + plan.scale * np.array(PRISMATIC_STEPS))
    if not columns:
        return np.zeros(1)
    out = np.stack(columns, axis=-1)
    return out[:, 0] if out.shape[1] == 1 else out


def _has_loads(mech: assur.Mechanism) -> bool:
    return bool(mech.loads) or any(link.mass for link in mech.links)


def _assur_error(err: assur.AssurError) -> Outcome:
    """An AssurError's outcome: its class, or a failure when its message is bad."""
    name = type(err).__name__
    problem = message_problem(str(err))
    if problem is None:
        return Outcome(name, detail=str(err))
    where, line = _location(err.__traceback__)
    return Outcome(
        "failure", f"message {problem}: {name} at {where}", f"{line} | {_cut(str(err))}"
    )


def message_problem(message: str) -> str | None:
    """What is wrong with an error's (or a warning's) message, or None."""
    if not message.strip():
        return "empty"
    if "\n" in message or "\r" in message:
        return "not one line"
    if len(message) > MAX_MESSAGE:
        return "too long"
    if FOREIGN.search(message):
        return "shows a Python repr"
    return None


def _judge_warnings(outcome: Outcome, caught: list[Any]) -> Outcome:
    """A failure for a warning that is not an AssurWarning or has a bad message."""
    warned = tuple(str(w.message) for w in caught)
    if outcome.failed:
        return Outcome(outcome.label, outcome.signature, outcome.detail, warned)
    for w in caught:
        where = _frame_text(w.filename, None)
        if not issubclass(w.category, assur.AssurWarning):
            return Outcome(
                "failure",
                f"stray {w.category.__name__} at {where}: {_cut(str(w.message), 60)}",
                f"{where}:{w.lineno} | {_cut(str(w.message))}",
                warned,
            )
        problem = message_problem(str(w.message))
        if problem is not None:
            return Outcome(
                "failure",
                f"warning message {problem} at {where}",
                _cut(str(w.message)),
                warned,
            )
    return Outcome(outcome.label, outcome.signature, outcome.detail, warned)


def _assur_warnings(caught: list[Any]) -> list[str]:
    return [
        str(w.message) for w in caught if issubclass(w.category, assur.AssurWarning)
    ]


def _location(tb: TracebackType | None) -> tuple[str, str]:
    """The last assur frame of a traceback: ``module:function`` and its line."""
    frames = [f for f in traceback.extract_tb(tb) if _inside(f.filename)]
    if not frames:
        return "outside assur", ""
    f = frames[-1]
    where = _frame_text(f.filename, f.name)
    return where, f"{_frame_text(f.filename, None)}:{f.lineno}: {f.line}"


def _inside(filename: str) -> bool:
    return Path(filename).resolve().is_relative_to(PACKAGE)


def _frame_text(filename: str, function: str | None) -> str:
    path = Path(filename).resolve()
    name = (
        "assur/" + path.relative_to(PACKAGE).as_posix()
        if path.is_relative_to(PACKAGE)
        else path.name
    )
    return name if function is None else f"{name}:{function}"


def _cut(text: str, limit: int = 300) -> str:
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


# --- the checks of a table --------------------------------------------------------


def check_table(table: assur.Table, explained: list[str]) -> Outcome | None:
    """A failure for a non-finite value or a balancing load off its check, or None."""
    if len(table) == 0:
        return None
    values = {c: np.asarray(table[c], dtype=float) for c in table.columns}
    scale = float(table.plan.scale)
    speed = _row_max(values, table, ("vx", "vy"))
    force = _row_max(values, table, ("Fx", "Fy", "Fi.x", "Fi.y", "F"))
    for name in table.columns:
        bad = ~np.isfinite(values[name])
        if not bad.any():
            continue
        column = table.column(name)
        bad &= ~_documented(column, values, scale, speed, force, table.mechanism)
        if bad.any() and not _told(column, table, explained):
            row = int(np.flatnonzero(bad)[0])
            return Outcome(
                "failure",
                f"NaN or inf in {column.family} columns",
                f"{name} = {values[name][row]} at driver position "
                f"{table.given[row].tolist()}",
            )
    return _check_balance(table, values, scale, force)


def _row_max(values: dict[str, Any], table: assur.Table, parts: tuple[str, ...]) -> Any:
    """The largest finite magnitude, row by row, of the columns of ``parts``."""
    out = np.zeros(len(table))
    for c in table.schema:
        if c.quantity in parts:
            v = np.abs(values[c.name])
            out = np.fmax(out, np.where(np.isfinite(v), v, 0.0))
    return out


def _documented(
    column: Any,
    values: dict[str, Any],
    scale: float,
    speed: Any,
    force: Any,
    mech: assur.Mechanism,
) -> Any:
    """Where a non-finite value of ``column`` is a documented NaN."""
    v = values[column.name]
    if column.family == "ic":
        # the instant centre of a link that translates (omega = 0) is at infinity
        omega = values[f"{column.owner}.omega"]
        still = np.abs(omega) * scale <= 1e-6 * speed
        return np.isnan(v) & np.isfinite(omega) & (still | (omega == 0.0))
    if column.family == "offset":
        # a prismatic pair's offset is M / N: NaN where the normal force N is zero,
        # or so small beside the couple M that the pair carries a pure couple
        # N is the reaction's component normal to the slide line: with a friction
        # coefficient mu the reaction is at most sqrt(1 + mu^2) times N
        f = values[f"{column.owner}.F"]
        mu = {j.name: j.friction for j in mech.joints}[column.owner]
        normal = f / math.sqrt(1.0 + mu * mu)
        m = np.abs(values[f"{column.owner}.M"])
        none = normal <= np.fmax(1e-9, 1e-6 * force)
        couple = np.isfinite(m) & (m > 1e11 * scale * normal)
        return np.isnan(v) & np.isfinite(f) & (none | couple)
    return np.zeros(v.shape, dtype=bool)


def _told(column: Any, table: assur.Table, explained: list[str]) -> bool:
    """Whether an AssurWarning names the owner of ``column``, or what it is built on.

    A point (a joint, a centre of mass) moves with the link that carries it: a
    warning naming that link names it too. A warning whose list of owners ends in
    "..." names more than it shows.
    """
    if _named(column.owner, explained):
        return True
    if column.family == "point":
        body, _ = table.plan.point_of(column.owner)
        if _named(table.plan.bodies[body], explained):
            return True
    # "values of link rod, ..., joint guide, ... (8 in all) are not finite ..."
    return any(", ... (" in m and " are not finite" in m for m in explained)


def _named(owner: str, explained: list[str]) -> bool:
    """Whether an AssurWarning names ``owner`` (a link, a joint, ``driver``)."""
    word = re.compile(rf"(?<![\w.~-]){re.escape(owner)}(?![\w~-])(?! position)")
    return any(word.search(m) for m in explained)


def _check_balance(
    table: assur.Table, values: dict[str, Any], scale: float, force: Any
) -> Outcome | None:
    moment = _row_max(values, table, ("Mi", "M", "torque", "torque_check"))
    for column in table.schema:
        if column.family != "balancing":
            continue
        t, k = values[column.name], values[f"{column.name}_check"]
        size = (
            force * scale + moment
            if column.quantity == "torque"
            else (force + moment / scale)
        )
        both = np.isfinite(t) & np.isfinite(k)
        off = np.abs(t - k) > np.fmax(
            TORQUE_RTOL * np.fmax(np.abs(t), np.abs(k)) + TORQUE_ATOL * size,
            TORQUE_FLOOR,
        )
        if (both & off).any():
            row = int(np.flatnonzero(both & off)[0])
            digits = digits_kept(table.plan)
            where = ""
            if digits < DIGITS:
                where = f" where the pose keeps fewer than {DIGITS} digits"
            elif _subnormal(table.plan):
                where = " where the velocities are subnormal"
            return Outcome(
                "failure",
                f"{column.name} disagrees with its check{where}",
                f"{column.name} = {t[row]:.17g}, check {k[row]:.17g} at driver "
                f"position {table.given[row].tolist()}; the pose keeps {digits:.1f} "
                "digits",
            )
    return None


def _subnormal(plan: Any) -> bool:
    """Whether a driver's speed makes the velocities subnormal (fewer bits)."""
    normal = np.finfo(float).tiny / np.finfo(float).eps
    return any(
        abs(d.omega) * (plan.scale if d.kind == "R" else 1.0) < normal
        for d in plan.drivers
    )


def digits_kept(plan: Any) -> float:
    """Significant digits of the reference pose left to its shortest link.

    The joints' coordinates, in the file and about the first driver's pivot (where
    the core puts its origin), are known to a relative 2.2e-16; the shortest link
    (largest distance between two of its joints) keeps what remains of them.
    """
    mech = plan.mechanism
    at = {j.name: np.array(resolve_point(mech, j.at), dtype=float) for j in mech.joints}
    shift = np.array(plan.shift, dtype=float)
    size = max(
        max(float(np.hypot(*p)), float(np.hypot(*(p - shift)))) for p in at.values()
    )
    lengths = []
    for link in mech.links:
        points = [at[j.name] for j in mech.joints if link.name in j.links]
        length = max(
            (float(np.hypot(*(a - b))) for a in points for b in points), default=0.0
        )
        if length > 0.0:
            lengths.append(length)
    if not lengths or size == 0.0:
        return math.inf
    return math.log10(min(lengths) / (size * np.finfo(float).eps))


# --- reducing a failing case ------------------------------------------------------


def reduce(text: str, signature: str, budget: float = 60.0) -> str:
    """Return a shorter text that fails with the same signature.

    Deletes chunks of tables (a header and its keys), then of lines, halving their
    size down to one, and keeps each deletion after which the case fails the same
    way; stops after ``budget`` seconds.
    """
    deadline = time.monotonic() + budget

    def same(candidate: str) -> bool:
        if time.monotonic() > deadline:
            return False
        outcome = run_case(candidate, time_limit=TIME_LIMIT)
        return outcome.signature == signature

    blocks = _shrink(_blocks(text), same, join="")
    lines = _shrink("".join(blocks).split("\n"), same)
    return "\n".join(lines).strip("\n") + "\n"


def _blocks(text: str) -> list[str]:
    """The text cut before every table header: ``[links.rod]`` and its keys."""
    parts = re.split(r"(?m)^(?=\s*\[)", text)
    return [p for p in parts if p]


def _shrink(items: list[str], same: Any, join: str = "\n") -> list[str]:
    """Delete chunks of ``items`` while ``same`` holds (a simple ddmin)."""
    chunk = max(len(items) // 2, 1)
    while True:
        i = 0
        while i < len(items):
            trial = items[:i] + items[i + chunk :]
            if trial and same(join.join(trial)):
                items = trial
            else:
                i += chunk
        if chunk == 1:
            return items
        chunk //= 2
