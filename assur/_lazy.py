"""A package's names loaded at their first use (PEP 562's module ``__getattr__``).

``import assur`` loads the errors and the function :func:`assur.explain`, not the
modules behind the other names: a script that reads a mechanism file and prints its
structure loads neither the sweeps nor the dynamic model. A name is looked up in its
module when first asked for and kept in the package's namespace, so it costs a
dictionary lookup afterwards, as an imported name does.
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["names"]


def names(
    package: str, where: Mapping[str, str], namespace: dict[str, Any]
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """Return the ``__getattr__`` and ``__dir__`` of ``package``.

    Parameters
    ----------
    package : str
        The package's dotted name.
    where : mapping of str to str
        Each name loaded lazily, to the module that defines it; a submodule of the
        package maps to its own dotted name.
    namespace : dict
        The package's ``globals()``: a name loaded is kept there.

    Notes
    -----
    Any other submodule of the package is loaded when asked for as an attribute
    (``assur.plan``), as when the package loaded everything at its import.
    """

    def getattr_(name: str) -> Any:
        module = where.get(name)
        if module is None:
            # a submodule, as an eager package would have it; dunder probes
            # (``__wrapped__``, ``__path__``) and other names are not modules
            found = not name.startswith("__") and name.isidentifier()
            module = f"{package}.{name}"
            if not found or importlib.util.find_spec(module) is None:
                msg = f"module {package!r} has no attribute {name!r}"
                raise AttributeError(msg)
            value = importlib.import_module(module)
        elif module == f"{package}.{name}":
            value = importlib.import_module(module)
        else:
            value = getattr(importlib.import_module(module), name)
        namespace[name] = value
        return value

    def dir_() -> list[str]:
        return sorted(set(namespace) | set(where))

    return getattr_, dir_
