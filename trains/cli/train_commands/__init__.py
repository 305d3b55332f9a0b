"""Layer 9, command line: the train commands (``train``, ``planetary``, ``synthesize``,
``differential``), one module each; see :mod:`trains.cli.app`."""
