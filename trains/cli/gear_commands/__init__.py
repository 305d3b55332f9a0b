"""Layer 9, command line: the gear commands (``pair``, ``profile``, ``mesh``, ``bevel``, ``rate``,
``search``, ``worm``), one module each; see :mod:`trains.cli.app`."""
