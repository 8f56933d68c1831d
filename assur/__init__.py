"""assur: kinetostatic analysis of planar linkages, built on Assur groups.

Describe a mechanism (links, revolute and prismatic joints, masses, loads, the driving
crank), then get its structure, its kinematics over a sweep of driver positions, and its
inertia loads, joint reactions and balancing torque.

>>> import assur
>>> mech = assur.catalog.slider_crank()
>>> print(assur.structure(mech).formula)
I(ground, crank) -> II(rod, slider)
"""

# Ctrl-C while the command line's modules load (numpy, the analysis) ends it
# quietly, when this import starts it (python -m assur, the assur script)
from assur import _start

_start.guard()

import typing as _typing

from assur._lazy import names as _names
from assur.errors import (
    AssemblyError,
    AssurError,
    AssurWarning,
    ConvergenceError,
    DecompositionError,
    ModelError,
    OutputError,
    SelfLockingError,
    SingularConfigurationError,
    UnknownNameError,
    UsageError,
)

# ``explain`` is imported here, not at its first use: the package of that name would
# otherwise stand in its place once anything imported it (``assur.explain._note``).
# The package itself is light; it loads the analysis at the first note.
from assur.explain import explain

# the names below, for type checkers; loaded at their first use (_WHERE)
if _typing.TYPE_CHECKING:
    from assur import catalog
    from assur._structure import Group, Structure, graph, mobility, structure
    from assur.analysis import Table, forces, kinematics
    from assur.dynamics_flywheel import FlywheelSizing, flywheel, flywheel_sizing
    from assur.dynamics_model import Dynamics, dynamics
    from assur.dynamics_startup import Startup, startup
    from assur.explain import Note
    from assur.io import dumps, load, loads, save
    from assur.model import (
        Driver,
        Joint,
        Link,
        Load,
        LoadTable,
        Mechanism,
        Motor,
        Point,
        Toward,
    )
    from assur.study import Study, sweep

_NAMES = {
    "assur.catalog": "catalog",
    "assur._structure": "Group Structure graph mobility structure",
    "assur.analysis": "Table forces kinematics",
    "assur.dynamics_flywheel": "FlywheelSizing flywheel flywheel_sizing",
    "assur.dynamics_model": "Dynamics dynamics",
    "assur.dynamics_startup": "Startup startup",
    "assur.explain": "Note",
    "assur.io": "dumps load loads save",
    "assur.model": "Driver Joint Link Load LoadTable Mechanism Motor Point Toward",
    "assur.study": "Study sweep",
}
"""The public names loaded at their first use, by the module that defines them."""
_WHERE = {name: module for module, names in _NAMES.items() for name in names.split()}

__getattr__, __dir__ = _names(__name__, _WHERE, globals())

__version__ = "0.1.0"

__all__ = [
    "AssemblyError",
    "AssurError",
    "AssurWarning",
    "ConvergenceError",
    "DecompositionError",
    "Driver",
    "Dynamics",
    "FlywheelSizing",
    "Group",
    "Joint",
    "Link",
    "Load",
    "LoadTable",
    "Mechanism",
    "ModelError",
    "Motor",
    "Note",
    "OutputError",
    "Point",
    "SelfLockingError",
    "SingularConfigurationError",
    "Startup",
    "Structure",
    "Study",
    "Table",
    "Toward",
    "UnknownNameError",
    "UsageError",
    "__version__",
    "catalog",
    "dumps",
    "dynamics",
    "explain",
    "flywheel",
    "flywheel_sizing",
    "forces",
    "graph",
    "kinematics",
    "load",
    "loads",
    "mobility",
    "save",
    "startup",
    "structure",
    "sweep",
]
