"""Run the command line: ``python -m assur``."""

import sys

from assur.cli import main

sys.exit(main())
