"""Sphinx configuration of the assur documentation.

Build (warnings are errors, so the reference stays clean):

    python -m sphinx -W --keep-going -b html docs docs/_build/html

Nothing here touches the network: no intersphinx inventories are fetched and the
gallery scripts only read the mechanism files in ``examples/``.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import os
import shutil
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))
os.environ.setdefault("MPLBACKEND", "Agg")

import assur  # noqa: E402

project = "assur"
author = "The assur developers"
copyright = "The assur developers"
release = assur.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.intersphinx",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
]

# No inventories: the build must work without a network.
intersphinx_mapping: dict[str, tuple[str, str | None]] = {}
# ...so the few names of other projects the pages cite cannot resolve; a nitpicky
# build (-n) would list them as broken references.
nitpick_ignore = [
    ("py:class", "dask.distributed.Client"),
    ("py:func", "scipy.integrate.solve_ivp"),
    ("py:mod", "warnings"),
]

templates_path: list[str] = []
exclude_patterns = ["_build", "**.ipynb_checkpoints", "Thumbs.db", ".DS_Store"]
default_role = "code"
primary_domain = "py"
highlight_language = "python3"

# -- autodoc, autosummary, numpydoc ------------------------------------------------
autosummary_generate = False  # the module pages are written below
autosummary_ignore_module_all = False
autosummary_imported_members = False
autodoc_typehints = "none"
autodoc_member_order = "bysource"
autodoc_default_options = {"inherited-members": False}
add_module_names = False
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_attributes_as_param_list = True
numpydoc_xref_param_type = False

# -- gallery -----------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": [str(ROOT / "examples")],
    "gallery_dirs": ["auto_examples"],
    "filename_pattern": r"/plot_",
    "ignore_pattern": r"__init__\.py|/_",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "plot_gallery": "True",
    "abort_on_example_error": True,
    "show_memory": False,
    "show_signature": False,
    "capture_repr": (),
}

# -- HTML ----------------------------------------------------------------------------
html_title = f"assur {release}"
html_static_path: list[str] = []
html_last_updated_fmt = ""
if importlib.util.find_spec("pydata_sphinx_theme") is not None:
    html_theme = "pydata_sphinx_theme"
    html_theme_options = {
        "navigation_depth": 2,
        "show_toc_level": 2,
        "navbar_align": "left",
        "secondary_sidebar_items": ["page-toc"],
        "footer_start": ["copyright"],
        "footer_end": ["sphinx-version"],
    }
else:  # pragma: no cover - the docs extra installs the theme
    html_theme = "alabaster"


# -- API pages -------------------------------------------------------------------------
# One page per module, listing what its ``__all__`` exports. They are written here
# rather than by autosummary's generator, which would take ``assur.structure`` and
# ``assur.kinematics`` for the functions of those names that ``assur`` re-exports.

API_MODULES = [
    "assur.model",
    "assur._structure",
    "assur._kinematics",
    "assur.kinetostatics",
    "assur.analysis",
    "assur.study",
    "assur.summary",
    "assur.dynamics_reduced",
    "assur.dynamics_steady",
    "assur.dynamics_model",
    "assur.dynamics_flywheel",
    "assur.dynamics_startup",
    "assur.io",
    "assur.catalog",
    "assur.errors",
]
# Modules that may not exist in every checkout get a page once they do.
OPTIONAL_API_MODULES = ["assur.plotting", "assur.html", "assur.explain"]
API_DIR = HERE / "api" / "generated"


def _kind(obj: object) -> str:
    if inspect.isclass(obj):
        return "exception" if issubclass(obj, BaseException) else "class"
    return "function" if callable(obj) else "data"


def _module_page(name: str) -> str:
    """Return the reST of the API page of module ``name``."""
    module = importlib.import_module(name)
    exported = [n for n in getattr(module, "__all__", []) if not n.startswith("_")]
    groups: dict[str, list[str]] = {
        "function": [],
        "class": [],
        "exception": [],
        "data": [],
    }
    for item in exported:
        groups[_kind(getattr(module, item))].append(item)
    lines = [
        name,
        "=" * len(name),
        "",
        f".. automodule:: {name}",
        "   :no-members:",
        "",
        f".. currentmodule:: {name}",
        "",
    ]
    listed = groups["function"] + groups["class"] + groups["exception"]
    if listed:
        lines += [
            ".. rubric:: Contents",
            "",
            ".. autosummary::",
            "   :nosignatures:",
            "",
        ]
        lines += [f"   {item}" for item in listed] + [""]
    sections = (
        ("function", "Functions", "autofunction", ()),
        ("class", "Classes", "autoclass", ("   :members:",)),
        (
            "exception",
            "Exceptions and warnings",
            "autoexception",
            ("   :show-inheritance:",),
        ),
        ("data", "Constants", "autodata", ("   :no-value:",)),
    )
    for kind, title, directive, options in sections:
        if groups[kind]:
            lines += [title, "-" * len(title), ""]
            for item in groups[kind]:
                lines += [f".. {directive}:: {item}", *options, ""]
    return "\n".join(lines)


def _write_api_pages() -> list[str]:
    """Write every module's page afresh; return the module names in order."""
    shutil.rmtree(API_DIR, ignore_errors=True)
    API_DIR.mkdir(parents=True)
    present = [
        m for m in OPTIONAL_API_MODULES if importlib.util.find_spec(m) is not None
    ]
    modules = API_MODULES + present
    for name in modules:
        (API_DIR / f"{name}.rst").write_text(_module_page(name), encoding="utf-8")
    return modules


API_PAGES = _write_api_pages()


def _summary(name: str) -> str:
    doc = inspect.getdoc(importlib.import_module(name)) or ""
    return doc.split("\n\n")[0].replace("\n", " ")


def _api_index(app, docname, source):
    """Put the table and the toctree of the module pages into the API index."""
    if docname != "api/index":
        return
    rows = "".join(
        f"   * - :mod:`{name}`\n     - {_summary(name)}\n" for name in API_PAGES
    )
    table = f".. list-table::\n   :widths: 25 75\n\n{rows}\n"
    entries = "".join(f"   generated/{name}\n" for name in API_PAGES)
    toctree = f".. toctree::\n   :hidden:\n\n{entries}"
    source[0] = source[0].replace(".. api-modules", table + toctree)


def setup(app):
    app.connect("source-read", _api_index)
