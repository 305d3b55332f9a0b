"""Layer 0, base: the one exception type of :mod:`trains`."""


class TrainError(ValueError):
    """An impossible train or request: under- or over-determined, unknown member, bad ratio.

    The message names the offending members or relations and what would make the request valid.
    """
