"""Layer 8, command line.

Sub-commands of the ``geartrain`` CLI, one module each (see :mod:`trains.cli`)."""
