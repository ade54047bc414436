"""The version, written once: the build reads it (scikit-build-core's regex provider in
pyproject.toml) and ``minkowski2d.__version__`` imports it."""

__version__ = "0.1.0"
