"""Contact solvers: line and point contacts, Kodnir's dimensionless problem, the
transient squeeze and the thermal coupling, all driven by one shared grid-sequencing
driver (:mod:`~bearing_fem.contacts.driver`)."""
