"""Numerical machinery with no physics in it: finite-element assembly on fixed sparsity
patterns (:mod:`~bearing_fem.numerics.fe`) and damped Newton, continuation and GMRES
(:mod:`~bearing_fem.numerics.newton`)."""
