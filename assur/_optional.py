"""The optional dependencies: imported when a feature needs them, named if missing.

``import assur`` stays light: pandas, xarray, dask and pyarrow come with extras
(``pip install "assur[study]"``, ``"assur[parquet]"``) and are imported here, on
first use, with an error that says how to install them.
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = ["optional"]


def optional(module: str, needed_for: str, extra: str) -> Any:
    """Return the module ``module``, imported.

    Parameters
    ----------
    module : str
        The module's name (``"pyarrow.parquet"``, say).
    needed_for : str
        What needs it, to start the message (``"writing Parquet"``).
    extra : str
        The extra of assur that installs it (``"parquet"``).

    Raises
    ------
    ImportError
        When it is not installed, saying how to install it; or when importing it
        fails otherwise (a build for another numpy raises ValueError, say), saying
        what it raised.
    """
    package = module.split(".")[0]
    try:
        return importlib.import_module(module)
    except ImportError as err:
        msg = (
            f"{needed_for} needs {package}, which is not installed; expected "
            f"'pip install {package}' (or 'pip install assur[{extra}]')"
        )
        raise ImportError(msg) from err
    except Exception as err:  # any fault of a broken install
        # the package is there but broken: its traceback would hide the one line
        # that says what to do
        said = str(err).strip().splitlines()
        what = f"{type(err).__name__}: {said[0]}" if said else type(err).__name__
        msg = (
            f"{needed_for} needs {package}, which is installed but fails to import "
            f"({what}); expected a working install, 'pip install --force-reinstall "
            f"{package}'"
        )
        raise ImportError(msg) from err
