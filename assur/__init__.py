"""assur: kinetostatic analysis of planar linkages, built on Assur groups.

Describe a mechanism (links, revolute and prismatic joints, masses, loads, the driving
crank), then get its structure, its kinematics over a sweep of driver positions, and its
inertia loads, joint reactions and balancing torque.

>>> import assur
>>> mech = assur.catalog.slider_crank()
>>> print(assur.structure(mech).formula)
I(ground, crank) -> II(rod, slider)
"""

# Ctrl-C while the modules below load (numpy, scipy) ends the command line quietly,
# when this import starts it (python -m assur, the assur script)
from assur import _start

_start.guard()

from assur import catalog
from assur._structure import Group, Structure, graph, mobility, structure
from assur.analysis import Table, forces, kinematics
from assur.dynamics_flywheel import FlywheelSizing, flywheel, flywheel_sizing
from assur.dynamics_model import Dynamics, dynamics
from assur.dynamics_startup import Startup, startup
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
from assur.explain import Note, explain
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
