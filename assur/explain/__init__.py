"""The analysis at one driver position written out as a student writes it by hand.

:func:`explain` solves the mechanism at one position and words every step: the
structure, each group's position, velocity and acceleration equations with their
numbers, the inertia loads, each group's equilibrium in the reverse order, the input
link's balancing load and its check by Zhukovsky's lever. With friction in the
pairs, each group also shows its pairs' friction loads and how their sizes were
found, and the balancing load and the lever count the friction. The :class:`Note`
it returns is Markdown (``str()``), HTML with MathML or LaTeX.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from assur._lazy import names as _names

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

    from assur.explain._answers import read_answers
    from assur.explain._note import Note
    from assur.model import Mechanism

__all__ = ["Note", "explain", "read_answers"]

# Loaded at their first use: ``import assur`` loads this package (its function
# ``assur.explain`` has the package's name), not the analysis behind the note.
_LAZY = {"Note": "assur.explain._note", "read_answers": "assur.explain._answers"}


def explain(
    mechanism: Mechanism,
    angle: ArrayLike,
    answers: Mapping[str, float] | None = None,
    source: str = "",
) -> Note:
    """Return the analysis of ``mechanism`` at driver position ``angle``, explained.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism, as :func:`assur.load <assur.io.load>` or
        :mod:`assur.catalog` give it.
    angle : float or sequence of float
        Driver position, deg (m for a prismatic driver); one value per driver.
    answers : mapping of str to float, optional
        Given answers to compare with (a textbook's), by table column or magnitude
        (``"rod.G.a"``, ``"rod.Fi"``, ``"C.v"``): see :func:`read_answers`
        (``from assur.explain import read_answers``; ``assur.explain`` is this
        function).
    source : str
        Where the given answers come from, for the note's words.

    Returns
    -------
    Note
        ``str(note)`` is Markdown; ``note.to_html()`` and ``note.to_latex()`` the same
        note as a self-contained page and as a LaTeX report. Where friction locks a
        group at ``angle``, the note goes as far as that group and shows why it
        locks; its ``values`` are then NaN for the forces not reached (that group's
        reactions and those after it, the balancing loads).

    Warns
    -----
    AssurWarning
        Where friction locks a group at ``angle`` (the note has no balancing load
        and no lever there), naming the group.

    Raises
    ------
    AssemblyError
        When the mechanism cannot be assembled at ``angle``.
    ModelError
        When an answer names no quantity of the mechanism.
    UsageError
        When ``answers`` is not a mapping of names to finite numbers.

    Examples
    --------
    >>> from assur import catalog
    >>> note = explain(catalog.slider_crank(), 45.0)
    >>> str(note).startswith("# ")
    True
    """
    from assur.explain._explain import explained

    return explained(mechanism, angle, answers, source)


__getattr__, __dir__ = _names(__name__, _LAZY, globals())
