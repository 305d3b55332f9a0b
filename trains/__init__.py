"""Gear trains: the Willis formula per carrier, solved generically (see docs/trains.md).

>>> from trains import Train
>>> t = Train()
>>> t.mesh("sun", "planet", teeth=(20, 30), carrier="arm")
>>> t.mesh("planet", "ring", teeth=(30, 80), carrier="arm", internal=True)
>>> t.ratio("sun", "arm", fixed=["ring"])
Fraction(5, 1)
"""

from trains.catalog import (
    bevel_differential,
    biplanetary,
    double_planet,
    ferguson,
    khv,
    simple_planetary,
    stepped_planetary,
    strain_wave,
    wolfrom,
)
from trains.coaxial import coaxial_shifts
from trains.errors import TrainError
from trains.gearbox import Gearbox, Gearboxes, synthesize_gearbox
from trains.inertia import reduced_inertia
from trains.planetary import Assembly, Placement, Planetary
from trains.power import (
    PowerFlow,
    RelationPower,
    parallel_efficiency,
    planetary_efficiency,
    power_flow,
    self_locking_range,
    series_efficiency,
)
from trains.synthesis import Candidate, Candidates, synthesize
from trains.toml_format import read_train
from trains.trajectory import point_path
from trains.willis import IllConditionedTrainWarning, Motion, Relation, Structure, Train

# Kinematics and statics (issue 3). Planetary design and synthesis (issue 4) add their names here.
__all__ = [
    "Assembly",
    "Candidate",
    "Candidates",
    "Gearbox",
    "Gearboxes",
    "IllConditionedTrainWarning",
    "Motion",
    "Placement",
    "Planetary",
    "PowerFlow",
    "Relation",
    "RelationPower",
    "Structure",
    "Train",
    "TrainError",
    "bevel_differential",
    "biplanetary",
    "coaxial_shifts",
    "double_planet",
    "ferguson",
    "khv",
    "parallel_efficiency",
    "planetary_efficiency",
    "point_path",
    "power_flow",
    "read_train",
    "reduced_inertia",
    "self_locking_range",
    "series_efficiency",
    "simple_planetary",
    "stepped_planetary",
    "strain_wave",
    "synthesize",
    "synthesize_gearbox",
    "wolfrom",
]
