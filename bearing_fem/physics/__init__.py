"""Physics of the film and the bodies: viscosity and density laws, the Reynolds flux,
elastic compliance, traction (shear-stress) models and heat conduction.

These modules import numpy, scipy and scikit-fem (and the package's own low-level
``units`` and ``analytic``) only: no I/O, no plotting, no contact driver.
"""
