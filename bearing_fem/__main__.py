"""``python -m bearing_fem``: the command line (same as ``bearing-fem``; see ``docs/cli.md``)."""
from __future__ import annotations

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
