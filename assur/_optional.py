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
    except ModuleNotFoundError as err:
        if not _missing(err, module):
            raise _broken(needed_for, package, err) from err
        # the extra quoted, as the docs write it: zsh (macOS's shell) reads a bare
        # assur[study] as a pattern and refuses it ("no matches found")
        msg = (
            f"{needed_for} needs {package}, which is not installed; expected "
            f"'pip install {package}' (or 'pip install \"assur[{extra}]\"')"
        )
        raise ImportError(msg) from err
    except Exception as err:  # any fault of a broken install (an ImportError too)
        raise _broken(needed_for, package, err) from err


def _missing(err: ModuleNotFoundError, module: str) -> bool:
    """Whether ``err`` says ``module`` itself (or a package above it) is not there.

    A module it needs that is not there (pandas without its pytz) is a broken
    install, not a missing one.
    """
    name = err.name or ""
    return module == name or module.startswith(f"{name}.")


def _broken(needed_for: str, package: str, err: BaseException) -> ImportError:
    """Return the error that says ``package`` is installed but fails to import.

    Its traceback would hide the one line that says what to do: what it raised
    is named instead (its first line).
    """
    said = str(err).strip().splitlines()
    what = f"{type(err).__name__}: {said[0]}" if said else type(err).__name__
    msg = (
        f"{needed_for} needs {package}, which is installed but fails to import "
        f"({what}); expected a working install, 'pip install --force-reinstall "
        f"{package}'"
    )
    return ImportError(msg)
