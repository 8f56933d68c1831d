"""Solvers of the Assur groups, one module per dyad kind.

The registry maps a dyad's pair signature to the module that assembles it in closed
form; everything else a dyad needs is shared (``_dyad``). Groups of class III and above
are solved by :mod:`assur.groups.general`. Adding a dyad kind means one module and one
line here.
"""

from __future__ import annotations

from types import ModuleType

from assur.groups import prp, rpp, rpr, rrp, rrr

__all__ = ["DYADS"]

DYADS: dict[str, ModuleType] = {
    "RRR": rrr,
    "RRP": rrp,
    "RPR": rpr,
    "PRP": prp,
    "RPP": rpp,
}
"""Closed-form assembly of each dyad kind, by signature."""
