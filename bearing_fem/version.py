"""The package version (one place; ``bearing_fem.__version__`` is the same string)."""
VERSION = "0.1.0"
