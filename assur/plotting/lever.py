"""Zhukovsky's lever: the velocity plan turned by 90 degrees, with every load on it.

The moment about the pole of each load at its image, divided by the driver's speed,
is that load's share of the balancing load (the principle of virtual power drawn):
:func:`lever_balance` sums them, :func:`lever_moments` lists them and
:func:`zhukovsky_lever` draws the lever with the list beside it.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._digits import settled
from assur._text import describe
from assur._vec import integer
from assur.errors import UsageError
from assur.explain._friction_text import power_rows
from assur.explain._lever import LeverTerm, lever_load, lever_parts, lever_rates
from assur.explain._position import Position, perp
from assur.explain._tex import name as tex_name
from assur.plotting._apart import slid
from assur.plotting._drawing import (
    ALONG,
    BESIDE,
    _arrow,
    _axes,
    _images_plot,
    _joined,
    _legend,
)
from assur.plotting._mathtext import _symbol
from assur.plotting._numbers import PLAIN_RANGE, quantity
from assur.plotting._placing import Name, place_names
from assur.plotting._style import INERTIA_COLOR, LOAD_COLOR, literal, load_colour
from assur.plotting.plans import (
    _pos,
    _scale,
    _title,
    images,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from assur.groups._motion import Motion
    from assur.table import Table

__all__ = ["lever_balance", "lever_moments", "zhukovsky_lever"]


def lever_balance(table: Table, angle: Any = None, driver: int = 0) -> float:
    """Return the balancing load read off Zhukovsky's lever, N m or N.

    The sum of the moments about the pole of every load at its image point (the
    velocity plan turned by +90 degrees), of the couples' terms and of friction's
    power, divided by the driver's speed: the balancing load of driver ``driver``
    (its index in the file's order). With several drivers, or a driver standing
    still, the velocities are those per unit speed of that driver, the others held
    (as the explanatory note's lever).

    Raises
    ------
    UsageError
        For a kinematics table, or a driver index out of range.
    """
    pos = _lever_position(table, angle, driver, "lever_balance")
    return lever_load(pos, driver)


def _lever_position(table: Table, angle: Any, driver: int, what: str) -> Position:
    """Return the solved position of a lever, its table and driver checked."""
    from assur.plotting._context import _need_forces

    _need_forces(table, what)
    count = len(table.plan.drivers)
    index = integer(driver)
    if index is None or not 0 <= index < count:
        msg = f"{what}: no driver {describe(driver)}; expected 0 to {count - 1}"
        raise UsageError(msg)
    return _pos(table, angle)


def lever_moments(
    table: Table, angle: Any = None, driver: int = 0
) -> list[tuple[str, float]]:
    r"""Return the terms Zhukovsky's lever lists, N m or N: they add up to its load.

    One term per load, in the note's order, as (its TeX symbol, its moment about
    the pole of the lever divided by the driver's speed): ``-F . v / omega`` for a
    force, ``-M omega_L / omega`` for a couple on link L (the moment of the pair of
    forces :math:`\pm M / l` that replaces it at two joints of L); with friction,
    one last term ``"friction"`` (its power over the speed). Their sum is
    :func:`lever_balance`. With several drivers, or a driver standing still, the
    speeds are per unit speed of the driver.

    Raises
    ------
    UsageError
        As :func:`lever_balance`.
    """
    pos = _lever_position(table, angle, driver, "lever_moments")
    rates = lever_rates(pos, driver)[:2]
    return [(t, share) for t, share, _ in _shares(pos, rates)]


def _shares(
    pos: Position, rates: tuple[list[Motion], float]
) -> list[tuple[str, float, LeverTerm | None]]:
    """Return each load's share of the balancing load, friction's last (if any)."""
    bodies, speed = rates
    out: list[tuple[str, float, LeverTerm | None]] = [
        (t.load.tex, -t.power / speed, t) for t in lever_parts(pos, bodies)
    ]
    if pos.result is not None and pos.result.friction:
        lost = power_rows(pos, bodies, bodies is pos.bodies)[1]
        out.append(("friction", -lost / speed, None))
    return out


def zhukovsky_lever(
    table: Table, angle: Any = None, ax: Axes | None = None, driver: int = 0
) -> Axes:
    """Draw Zhukovsky's lever: the velocity plan turned by 90 degrees, the loads on it.

    Every force acts at its point's image; a couple M on a link acts as the pair of
    forces ``M / l`` and ``-M / l`` across the link's two joints farthest apart, at
    their images (a link without two joints apart has its couple listed only),
    drawn to the forces' scale: arrow times arm is each share. An arrow shorter
    than :data:`MARK` at that scale is drawn that long, its name starred, the legend
    saying so; one that lies on another is slid along its own line (its moment
    stays), a dotted line back to its point.
    Beside the lever every load's moment about the pole divided by the driver's
    speed is listed (``assur.plotting.lever.lever_moments``): the terms add up to
    the balancing load of driver ``driver`` written below them (friction's power
    in; see ``lever_balance``). With several drivers, or a driver standing still,
    the plan is that of the velocities per unit speed of the driver.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    UsageError
        As ``lever_balance``.
    """
    pos = _lever_position(table, angle, driver, "zhukovsky_lever")
    bodies, speed, _ = lever_rates(pos, driver)
    unit_speed = bodies is not pos.bodies
    lever = dataclasses.replace(pos, bodies=bodies)
    found = {n: perp(v) for n, v in images(lever, 1).items()}
    mu = _scale(list(found.values()))
    d = pos.plan.drivers[driver]
    whose = f" of driver {d.pair.name}" if len(pos.plan.drivers) > 1 else ""
    ax = _axes(ax, _title(pos, f"Zhukovsky's lever{literal(whose)}"), (11.0, 6.5))
    # the images' names too are kept inside the lever's frame, off the list beside
    # it, and clear of the loads' names
    images_named = _images_plot(ax, found, mu, "#777777")
    names = [Name(t, np.asarray(t.xy), np.asarray(t.xy)) for t in images_named]
    shares = _shares(pos, (bodies, speed))
    terms = [t for _, _, t in shares if t is not None]
    apart = _apart(lever, terms)
    arrows = _lever_arrows(lever, terms, apart)
    names += _name_pair_points(ax, lever, apart, found, mu)
    # one scale for forces and couples' pairs: on a lever arrow length times arm
    # is the moment, so a couple's pair drawn to a scale of its own would show a
    # share of 0.1 % as the biggest arrow; every arrow sets it (a resisting
    # torque's pair, larger than the forces, ran 125 mm off a 40 mm lever)
    fmu = _scale([f for _, f, *_ in arrows]) * 2.0
    # each force in its colour of the other pictures (inertia, gravity or load)
    colours = {_symbol(t.load.tex): load_colour(t.load.tex) for t in terms}
    marked = False
    used: dict[str, None] = {}
    # at a dead centre the loads lie on each other: each is slid along its own
    # line (its moment about the pole stays), a dotted line back to its point
    drawn: list[tuple[np.ndarray, np.ndarray]] = []
    largest = max((float(np.hypot(*f)) for _, f, *_ in arrows), default=0.0)
    for at, force, label, couple in arrows:
        if not float(np.hypot(*force)) > ROUND_OFF * largest:
            continue  # round-off (a dead centre's): not drawn 3 mm long either way
        tip, mark = _tip(at / mu, force / fmu)
        # a load of nothing (a crank's inertia force at its centre) gets no arrow
        # and no name: its share, nothing, is listed
        color = COUPLE if couple else colours.get(label, LOAD_COLOR)
        ends = slid(drawn, at / mu, tip, BESIDE, ALONG)
        if _arrow(ax, *ends, color):
            _joined(ax, at / mu, tip, ends)
            drawn.append(ends)
            # a load drawn longer than its scale is starred, its arrow solid (a
            # dotted one read as the dotted line to a slid load's point)
            shown = f"{label}*" if mark else label
            text = ax.annotate(shown, tuple(ends[1]), fontsize=7, color=color)
            names.append(Name(text, *ends))
            used[color] = None
            marked |= mark
    # the shares add up to the balancing load: their sum is the one written
    balancing = math.fsum(share for _, share, _ in shares)
    _list_terms(ax, apart, d.kind, shares, (speed, balancing), unit_speed)
    per = " per unit speed of the driver" if unit_speed else ""
    mu_unit = "(m/s)/mm" if not unit_speed else "m/mm" if d.kind == "R" else "1/mm"
    kinds = {INERTIA_COLOR: "inertia force", LOAD_COLOR: "gravity, external load"}
    entries = [(text, c) for c, text in kinds.items() if c in used]
    if COUPLE in used:
        entries.append(("couple M as ±M/l at two joints, same scale", COUPLE))
    below = f"*: below the scale, drawn {MARK:g} mm long\n" if marked else ""
    note = (
        f"forces: 1 mm = {quantity(fmu, 'N', 6)}\n{below}"
        f"lever: μv = {quantity(mu, mu_unit, 6)}{per},\nturned 90°"
    )
    _legend(ax, entries, note, beside=True)
    # room round the lever for the names; each beside its arrow or image, clear
    # of the other names, arrows and the images' rays from the pole
    ax.margins(0.08)
    rays = [np.array([np.zeros(2), v / mu]) for v in found.values()]
    place_names(ax, names, np.array(rays) if rays else None)
    return ax


COUPLE = "#9467bd"
"""The colour of a couple's pair of forces on the lever."""
ROUND_OFF = 1e-9
"""Shares all below this times the largest a load could have are round-off."""
MARK = 3.0
"""Length, mm, a force shorter than this at the force scale is drawn (dotted)."""
PAIR_GAP = 1e-6
"""Two joints of a link closer than this times the mechanism's size carry no pair."""


Ends = tuple[tuple[str, np.ndarray], tuple[str, np.ndarray]]
"""Two joints of a link: each its name and its place (m)."""


def _tip(start: np.ndarray, arrow: np.ndarray) -> tuple[Any, bool]:
    """Return an arrow's tip, mm, and whether it is marked below the scale.

    A force (or a couple's) shorter than :data:`MARK` at the force scale is drawn
    that long, in its direction, so that a small load is seen yet stays small: a
    slider's inertia force of 0.3 mm was a name beside nothing.
    """
    length = float(np.hypot(*arrow))
    if length >= MARK or length == 0.0:
        return start + arrow, False
    return start + arrow * (MARK / length), True


def _apart(lever: Position, terms: list[LeverTerm]) -> dict[int, Ends | None]:
    """Return the two joints farthest apart of each link with a couple in ``terms``.

    None for a link without two joints apart.
    """
    return {t.body: _joints_apart(lever, t.body) for t in terms if t.couple}


def _lever_arrows(
    lever: Position, terms: list[LeverTerm], apart: dict[int, Ends | None]
) -> list[tuple[np.ndarray, np.ndarray, str, bool]]:
    """Return the lever's arrows: (image, m/s; force, N; label; whether a couple's).

    ``apart`` holds the joints of each link with a couple (:func:`_apart`).

    A force at its point's image; a couple ``M`` as ``M perp(d) / |d|^2`` at the
    image of joint P and its opposite at joint Q's (``d = P - Q``): the pair's
    moment is ``M`` and its power ``M omega``, as the couple's.
    """
    out = []
    for t in terms:
        if not t.couple:
            image = perp(t.velocity)
            out.append((image, t.load.force, _symbol(t.load.tex), False))
            continue
        ends = apart[t.body]
        if ends is None:
            continue
        (p, at_p), (q, at_q) = ends
        d = at_p - at_q
        force = t.load.couple * perp(d) / float(np.dot(d, d))
        label = f"{t.load.tex}/l_{{{tex_name(p)}{tex_name(q)}}}"
        for point, sign, text in ((at_p, 1.0, label), (at_q, -1.0, f"-{label}")):
            image = perp(lever.coincident(t.body, point, 1))
            out.append((image, sign * force, _symbol(text), True))
    return out


def _name_pair_points(
    ax: Any,
    lever: Position,
    apart: dict[int, Ends | None],
    found: dict[str, np.ndarray],
    mu: float,
) -> list[Name]:
    """Mark and name the images a couple's pair acts at that are no named image.

    Return the names, to place.

    A link's point at a prismatic joint (a cylinder's at its bore) moves unlike
    the joint's point on the other link: its image is ``bore_cylinder``, as on
    the velocity plan.
    """
    size = max((float(np.hypot(*v)) for v in found.values()), default=0.0)
    names = []
    for body, ends in apart.items():
        for name, at in ends or ():
            image = perp(lever.coincident(body, at, 1))
            if any(np.hypot(*(image - v)) <= 1e-9 * size for v in found.values()):
                continue
            tip = image / mu
            ax.plot(*tip, "o", ms=3.5, color="#333333")
            link = tex_name(lever.link(body))
            label = _symbol(f"{tex_name(name.lower())}_{{{link}}}")
            text = ax.annotate(
                label, tip, xytext=(4, 4), textcoords="offset points", fontsize=8
            )
            names.append(Name(text, tip, tip))
    return names


def _joints_apart(pos: Position, body: int) -> Ends | None:
    """Return the two joints of ``body`` farthest apart, or None.

    A prismatic joint counts at its point: any two points of a link carry its
    couple as a pair of forces (an oscillating cylinder's pivot and its bore).
    """
    pins = [
        (p.name, pos.pair_point(p))
        for p in pos.plan.pairs.values()
        if body in (p.first, p.second) and "~" not in p.name
    ]
    best, far = None, PAIR_GAP * pos.size()
    for i, (a, at_a) in enumerate(pins):
        for b, at_b in pins[i + 1 :]:
            gap = float(np.hypot(*(at_a - at_b)))
            if gap > far:
                best, far = ((a, at_a), (b, at_b)), gap
    return best


def _list_terms(
    ax: Any,
    apart: dict[int, Ends | None],
    kind: str,
    shares: list[tuple[str, float, LeverTerm | None]],
    rates: tuple[float, float],
    unit_speed: bool,
) -> None:
    """Write every load's share of the balancing load beside the lever, and the sum.

    ``apart`` holds the joints of each link with a couple (:func:`_apart`);
    ``rates`` are the driver's speed and the balancing load; ``unit_speed`` says the
    speeds are per unit speed of the driver. The shares carry one decimal more than
    the sum: they add up by hand to the sum written.
    """
    speed, balancing = rates
    unit, rate, speed_unit = ("N·m", "ω", "rad/s") if kind == "R" else ("N", "v", "m/s")
    given = "per unit speed" if unit_speed else f"{rate} = {speed:g} {speed_unit}"
    big = max([abs(balancing)] + [abs(x) for _, x, _ in shares])
    # what a share could be, its load along its point's velocity: at a dead centre
    # every share is round-off of it (1e-13 N m), written to the decimals of the
    # loads, not to eight
    reach = max([abs(x) for _, x, t in shares if t is None] + [
        (abs(t.load.couple) * abs(t.omega) if t.couple
         else math.hypot(*t.load.force) * math.hypot(*t.velocity)) / abs(speed)
        for _, _, t in shares if t is not None
    ])  # fmt: skip
    size = big if big > ROUND_OFF * reach else reach
    # a watch's 1e-13 N m, a crane's 1e16: one power of ten, so no share reads 0
    plain = size == 0 or PLAIN_RANGE[0] <= size < PLAIN_RANGE[1]
    power = 0 if plain else 3 * math.floor(math.log10(size) / 3)
    size /= 10.0**power
    places = 4 if size == 0 else min(8, max(0, 4 - math.floor(math.log10(size))))
    shown = f"$10^{{{power}}}$ {unit}" if power else unit
    lines = [
        f"each load's moment about the pole / {rate}",
        f"({given}; a couple: -M·$\\omega_L$/{rate}), {shown}:",
    ]
    for tex, share, t in shares:
        head = "friction" if t is None else _symbol(tex)
        if t is not None and t.couple:
            ratio = t.omega / speed
            # a link at rest in its turning (a rocker at its dead centre) has a
            # speed of round-off: 2.7e-16 of the driver's is 0
            ratio = 0.0 if abs(ratio) < 1e-12 else settled(ratio)
            couple = quantity(t.load.couple, "N·m", 6)
            head += f" ({couple}, $\\omega_L$/{rate} = {ratio:.6g}"
            head += ")" if apart[t.body] else "; listed only)"
        # a share that rounds to nothing is written 0 (a dead centre's round-off),
        # not +0.000 or -0.000; a decimal tie (0.009375 N m) rounds alike on
        # every machine, read first to 12 digits
        rounded = round(settled(share / 10.0**power), places + 1) + 0.0
        lines.append(f"{head}:  {f'{rounded:+.{places + 1}f}' if rounded else '0'}")
    total = round(settled(balancing / 10.0**power), places) + 0.0
    times = "× " if power else ""
    said = f"{total:.{places}f} {times}{shown}" if total else "0 " + unit
    lines.append(f"sum = balancing load: {said}")
    ax.text(1.03, 1.0, "\n".join(lines), transform=ax.transAxes, fontsize=8,
            va="top", ha="left", linespacing=1.7)  # fmt: skip
