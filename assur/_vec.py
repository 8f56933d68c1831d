"""Private numerical helpers shared by the core: arrays, angles and batched leaves.

The kernels work on vectors as ``(x, y)`` pairs of arrays (see ``groups._motion``).
A quantity that does not change over a batch stays a float (a "leaf"); the states of
a sweep are nested tuples and dicts of such leaves, filled chunk by chunk.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Iterator
from typing import Any

import numpy as np
from numpy.typing import ArrayLike as ArrayLike  # the public signatures' inputs
from numpy.typing import NDArray

from assur._quiet import quiet

Array = NDArray[np.float64]
Mask = NDArray[np.bool_]
Index = NDArray[np.integer[Any]]


def wrap(phi: Array) -> Array:
    """Wrap angles to (-pi, pi]."""
    return np.pi - np.mod(np.pi - phi, 2.0 * np.pi)


Leaf = Any
"""A quantity over a batch: an array (n,), or a number (or None) where it does not
change over the batch."""


def is_flag(value: Any) -> bool:
    """Return whether ``value`` is a yes or no: True, False, numpy's, 0 or 1."""
    if isinstance(value, bool | np.bool_):
        return True
    return type(value) is int and value in (0, 1)


def real(value: Any) -> float | None:
    """Return an argument given as a number as a float; None if it is not one.

    True is no number and "0.04" a typing slip: both None, as anything ``float``
    refuses or cannot hold (an integer of 400 digits). NaN and inf stay floats.
    """
    if isinstance(value, bool | str):
        return None
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):
        return None


def integer(value: Any) -> int | None:
    """Return an argument given as a whole number (a count, an index) as an int.

    None for anything else: True, 1.0, "1".
    """
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        return None
    return int(value)


def opposed(a: float, b: float) -> bool:
    """Return whether ``a`` and ``b`` have opposite signs (a zero opposes nothing).

    The signs compared, not the product: 1e-170 * -1e-170 is -0.0, which is not
    below zero.

    Examples
    --------
    >>> opposed(1e-170, -1e-170), opposed(-2.0, -3.0), opposed(0.0, -1.0)
    (True, False, False)
    """
    return (a < 0.0 < b) or (b < 0.0 < a)


def is_array(value: Leaf) -> bool:
    """Whether a leaf varies over the batch (an array) rather than being constant."""
    return isinstance(value, np.ndarray) and value.ndim > 0


def full(value: Leaf, n: int) -> Array:
    """Return a leaf as a read-only array of ``n`` values (a constant is repeated).

    A constant is one value seen through a stride of zero: nothing is written per
    position, whatever ``n``.
    """
    if isinstance(value, np.ndarray) and value.ndim > 0:  # is_array, called often
        return value
    number = np.nan if value is None else float(value)
    # -0.0 == 0.0 (one key): the sign goes into the key, or the first made would
    # serve both, and which one came first would change the results (atan2, 1/x)
    return _constant(number, n, math.copysign(1.0, number))


@functools.lru_cache(maxsize=1024)
def _constant(value: float, n: int, sign: float) -> Array:
    """Return ``value`` repeated ``n`` times, read-only; kept for reuse.

    A table has tens of constant columns (the frame's, a crank's speed), mostly the
    same few numbers: made once, each costs a lookup. Being read-only, one array can
    serve every table. ``sign`` is that of ``value`` (+1.0 or -1.0), which tells a
    zero's sign apart. (NaN is not equal to itself: each NaN makes a new entry, up to
    the cache's bound.)
    """
    one = np.array((value,))
    # the base read-only too: a view's flag could else be set back, and one table's
    # write would reach every other through this cache
    one.flags.writeable = False
    out: Array = np.ndarray((n,), np.float64, one, 0, (0,))
    out.flags.writeable = False
    return out


SQUARE_RANGE = (1e-280, 1e280)
"""Squares within this range keep full precision; outside it :func:`norm` falls
back to ``np.hypot`` (a square underflows below about 1e-308, overflows above 1e308)."""


def diameters(points: Array) -> Array:
    """Return the largest distance between two of the points (k, P, 2) of each row.

    Every pair compared: for the few points of a group or a link (m, as given).
    """
    gap = points[:, :, None, :] - points[:, None, :, :]
    return np.sqrt((gap * gap).sum(axis=-1)).max(axis=(1, 2))  # type: ignore[no-any-return]


def norm(x: Array, y: Array, out: Array | None = None) -> Array:
    """Return ``sqrt(x**2 + y**2)`` per element, as ``np.hypot`` does.

    ``np.hypot`` calls the C library per element; the sum of squares runs about ten
    times faster, and is as exact (within an ulp) while the squares stay in
    :data:`SQUARE_RANGE`. Elements outside it, tiny or huge, are computed by
    ``np.hypot``; a NaN in either component gives NaN.

    Parameters
    ----------
    x, y : ndarray or float
        The components, of shapes that broadcast (any unit).
    out : ndarray, optional
        Where to write the result; it may not be ``x`` or ``y``.

    Returns
    -------
    ndarray
        The lengths, in the unit of the components.
    """
    if np.ndim(x) == 0 and np.ndim(y) == 0:
        return np.hypot(x, y)  # type: ignore[no-any-return]
    with quiet():  # a huge square is redone by np.hypot below
        s = np.multiply(x, x, out=out)
        s += y * y
    # two reductions find the rare odd square without a mask over every element
    low, high = SQUARE_RANGE
    # the ufuncs' reductions called directly: s.min() reaches them through Python
    fine = not s.size or (
        low <= np.minimum.reduce(s, axis=None)
        and np.maximum.reduce(s, axis=None) <= high
    )
    if fine:
        return np.sqrt(s, out=s)
    with quiet():
        odd = (s < SQUARE_RANGE[0]) | (s > SQUARE_RANGE[1])
    odd &= (x != 0.0) | (y != 0.0)
    np.sqrt(s, out=s)
    if odd.any():
        wide_x, wide_y = np.broadcast_to(x, s.shape), np.broadcast_to(y, s.shape)
        s[odd] = np.hypot(wide_x[odd], wide_y[odd])
    return s


def leaves(tree: Any) -> list[Any]:
    """Return the leaves of nested tuples, lists and dicts, in a fixed order."""
    out: list[Any] = []
    stack = [tree]
    while stack:
        item = stack.pop()
        kind = item.__class__
        if kind is tuple or kind is list:
            stack.extend(reversed(item))
        elif kind is dict:
            stack.extend(reversed(list(item.values())))
        else:
            out.append(item)
    return out


def rebuild(tree: Any, values: Iterator[Any]) -> Any:
    """Return ``tree`` with its leaves replaced, in order, by ``values``."""
    if isinstance(tree, dict):
        return {key: rebuild(tree[key], values) for key in tree}
    if isinstance(tree, tuple | list):
        return type(tree)(rebuild(item, values) for item in tree)
    return next(values)


def allocate_like(tree: Any, n: int) -> Any:
    """Return a tree shaped as ``tree`` with an empty array (n,) for every array leaf.

    Constant leaves (quantities that do not change over a batch) stay as they are.
    The float arrays are the rows of one block (see :func:`rows_of`).
    """
    values = leaves(tree)
    floats = [is_array(x) and x.dtype == np.float64 for x in values]
    block = iter(rows_of(sum(floats), n))
    out = [
        next(block) if real else np.empty(n, x.dtype) if is_array(x) else x
        for x, real in zip(values, floats, strict=True)
    ]
    return rebuild(tree, iter(out))


def rows_of(count: int, n: int) -> list[Array]:
    """Return ``count`` empty arrays (n,), the rows of one block.

    The system hands one large block out in huge pages (numpy asks for them), so
    writing it first costs a fraction of what as many separate arrays of a long sweep
    cost; the block lives as long as any of its rows.
    """
    return list(np.empty((count, n)))


def write_rows(target: Any, piece: Any, rows: slice) -> None:
    """Write the leaves of ``piece`` into rows ``rows`` of ``target``'s arrays."""
    for whole, part in zip(leaves(target), leaves(piece), strict=True):
        if is_array(whole):
            whole[rows] = part


set_writeable: Any = np.ndarray.setflags
"""``set_writeable(a, False)`` makes the array ``a`` read-only: numpy's ``setflags``
given its argument by position, a fifth of the cost of ``a.flags.writeable = False``
(which calls it by name); a table sets about two hundred such flags."""


def freeze(tree: Any) -> Any:
    """Make every array leaf of ``tree`` read-only; return ``tree``.

    Only the containers go through the stack, in no particular order: a table's
    states hold about a hundred leaves, each looked at once.
    """
    stack: list[Iterable[Any]] = [(tree,)]
    while stack:
        for x in stack.pop():
            kind = x.__class__
            if kind is np.ndarray:
                set_writeable(x, False)
            elif kind is tuple or kind is list:
                stack.append(x)
            elif kind is dict:
                stack.append(x.values())
    return tree


def take_rows(tree: Any, rows: Any) -> Any:
    """Return ``tree`` with every array leaf indexed by ``rows`` (constants stay)."""
    return rebuild(tree, iter([x[rows] if is_array(x) else x for x in leaves(tree)]))


def gather(n: int, pieces: Iterable[tuple[slice, Any]]) -> Any:
    """Return the tree of a whole batch of ``n`` rows from the trees of its slices.

    A single slice covering every row is returned as it is (nothing is copied);
    otherwise every array leaf is allocated once and filled slice by slice.
    """
    whole: Any = None
    for rows, piece in pieces:
        if whole is None:
            if rows.start == 0 and rows.stop >= n:
                return piece
            whole = allocate_like(piece, n)
        write_rows(whole, piece, rows)
    return whole


def add(a: Leaf, b: Leaf) -> Leaf:
    """Return ``a + b``, skipping a term that is the float zero (no array is made)."""
    if b.__class__ is float and not b:
        return a
    if a.__class__ is float and not a:
        return b
    return a + b


def dot(weights: Iterable[Leaf], values: Iterable[Leaf]) -> Leaf:
    """Return the sum of the products ``w * v`` with as few array operations as may be.

    Terms with a float zero are skipped and a float one is not multiplied by: over
    small batches each array operation saved counts.
    """
    total: Leaf = 0.0
    for w, v in zip(weights, values, strict=True):
        if (w.__class__ is float and not w) or (v.__class__ is float and not v):
            continue
        if w.__class__ is float and w == 1.0:
            term = v
        elif v.__class__ is float and v == 1.0:
            term = w
        else:
            term = w * v
        total = term if (total.__class__ is float and not total) else total + term
    return total


def sub(a: Leaf, b: Leaf) -> Leaf:
    """Return ``a - b``, skipping a term that is the float zero."""
    if b.__class__ is float and not b:
        return a
    if a.__class__ is float and not a:
        return -b
    return a - b


def mul(a: Leaf, b: Leaf) -> Leaf:
    """Return ``a * b``; a float zero or one factor makes no array."""
    if a.__class__ is float:
        if not a:
            return 0.0
        if a == 1.0:
            return b
    if b.__class__ is float:
        if not b:
            return 0.0
        if b == 1.0:
            return a
    return a * b


def cross(ax: Leaf, ay: Leaf, bx: Leaf, by: Leaf) -> Leaf:
    """Return the z component of ``a x b``: ``ax by - ay bx``, skipping zero terms."""
    return sub(mul(ax, by), mul(ay, bx))
