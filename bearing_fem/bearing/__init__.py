"""Bearing-level EHL: from a bearing, its speed and its load to film, pressure, friction
torque and heat power at every rolling element (see ``docs/bearing.md``).

    import bearing_fem as bf
    bearing = bf.Bearing.from_toml("6209.toml")      # or bearing_fem.bearing.load_example
    result = bf.solve_bearing(bearing)               # never raises for non-convergence
    result.success, result.status, result.message, result.summary()

Modules: :mod:`~bearing_fem.bearing.description` (the bearing file),
:mod:`~bearing_fem.bearing.geometry`, :mod:`~bearing_fem.bearing.loads` (internal load
distribution), :mod:`~bearing_fem.bearing.kinematics`,
:mod:`~bearing_fem.bearing.contacts` (EHL scenes of every contact),
:mod:`~bearing_fem.bearing.totals`, :mod:`~bearing_fem.bearing.empirical` (Palmgren, SKF,
Nikitin, film formulas) and :mod:`~bearing_fem.bearing.solve`.
"""
from __future__ import annotations

from .description import Bearing, example_names, load_example
from .empirical import (palmgren_friction_torque, palmgren_heat_power, palmgren_torque,
                        skf_friction_torque, nikitin_power_loss, nikitin_split, film_formulas,
                        empirical_models)
from .kinematics import (ElementKinematics, RollerContacts, cylindrical_roller_contacts,
                         element_kinematics, max_line_load)
from .loads import LoadDistribution, distribute_loads
from .solve import BearingResult, solve_bearing

__all__ = ["Bearing", "BearingResult", "solve_bearing", "load_example", "example_names",
           "LoadDistribution", "distribute_loads", "ElementKinematics", "element_kinematics",
           "RollerContacts", "cylindrical_roller_contacts", "max_line_load",
           "palmgren_friction_torque", "palmgren_heat_power", "palmgren_torque",
           "skf_friction_torque", "nikitin_power_loss", "nikitin_split", "film_formulas",
           "empirical_models"]
