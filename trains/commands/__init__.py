"""Layer 7, command line.

Sub-commands of the ``geartrain`` CLI, one module each (see :mod:`trains.cli`)."""
