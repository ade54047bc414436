"""The engine: the one private layer between the public API and the compiled core."""
