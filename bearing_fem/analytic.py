"""Closed-form oracles (PHYSICS.md section 5), used by the tests and the studies.

Every oracle here is evaluated from its closed form; nothing is tabulated.
SI units unless a docstring says otherwise.
"""
from __future__ import annotations

import numpy as np

# ----------------------------------------------------------------------------------------
# Section A: Kapitsa (point/line, rigid), Martin (rigid cylinder), Hertz dry limits.
# ----------------------------------------------------------------------------------------

# ----------------------------------------------------------------------------------------
# Section B: Korovchinsky half-plane thermal contact (PHYSICS.md 5.4), Jaeger/Blok.
# ----------------------------------------------------------------------------------------
