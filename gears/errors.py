"""Layer 0, base: the one exception type of :mod:`gears`."""


class GearError(ValueError):
    """Impossible gear input: the message names the offending value and what would be valid.

    A design that is merely bad (undercut, pointed tip, low contact ratio) never raises: the
    checks return a :class:`gears.report.Report` of failing findings instead.
    """
