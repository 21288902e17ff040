"""Bearings as mounted on a shaft: each rolling-element support's fits and temperatures, and
the operating clearance they leave it (:mod:`models.operating_clearance`, Lame's press fits,
thermal expansion and the inner ring's centrifugal growth), as its own model forms it.

The shaft gives what it knows: its bore where the bearing sits (the section there), its
Young's modulus and Poisson's ratio, and its speed. The support gives the rest of
:data:`models.operating_clearance.OPERATING_INPUTS`: the fits, the rings' and seats'
dimensions, the temperatures and the housing. A ring whose fit is lost at temperature or
speed (it may creep) marks the point out of validity, as the bearing's own model does.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from .operating_clearance import OPERATING_INPUTS, mounted_clearance
from .registry import Constraint

#: How far [relative] a ring's bore may differ from its seat's diameter: a written value's
#: rounding, not a fit (a fit is its own input).
SEAT_TOLERANCE = 1e-9
#: The operating inputs the shaft gives rather than the support.
FROM_SHAFT = ("shaft_bore", "shaft_youngs_modulus", "shaft_poisson_ratio")
#: The operating inputs of a rolling-element support.
SUPPORT_OPERATING_INPUTS = tuple(spec for spec in OPERATING_INPUTS
                                 if spec.name not in FROM_SHAFT)
#: Per kind of bearing: its rolling element's diameter, and the contact angle that puts a
#: tapered roller's raceways at its middle (``d_m -+ D cos(alpha)``).
ELEMENTS = {"ball_5dof": ("ball_diameter", None), "crb_radial": ("roller_diameter", None),
            "trb_load": ("roller_mean_diameter", "outer_contact_angle")}


def section_bore(sections: np.ndarray, position) -> np.ndarray:
    """The shaft's bore [m] at each axial ``position`` [m] (a section's own at its right end;
    beyond the shaft, its last section's)."""
    ends = np.cumsum(sections[:, 0])
    index = np.minimum(np.searchsorted(ends, np.asarray(position, dtype=float)),
                       len(sections) - 1)
    return sections[index, 2]


def support_constraints(sections: np.ndarray, name: str, model, inputs) -> tuple:
    """The conditions of support ``name``'s own ``model`` between the ``inputs`` it takes on
    the shaft (its rolling elements fit on the pitch circle, a fit needs its ring, shaft,
    rings and housing nest, ...), on its prefixed inputs, the shaft's bore taken from the
    section at its position."""
    taken = {spec.name for spec in inputs} | {"shaft_bore"}

    def prefixed(constraint):
        inputs = tuple(f"supports_{name}_{'position' if n == 'shaft_bore' else n}"
                       for n in constraint.inputs)

        def check(**given):
            own = {n: given[m] for n, m in zip(constraint.inputs, inputs)}
            if "shaft_bore" in own:
                own["shaft_bore"] = section_bore(sections, own["shaft_bore"])
            return constraint.check(**own)

        return replace(constraint, inputs=inputs, check=check,
                       message=f"support {name}: {constraint.message}")

    ends = np.cumsum(sections[:, 0])

    def on_its_seat(**given):
        bore, position = given[f"supports_{name}_bore"], given[f"supports_{name}_position"]
        index = np.minimum(np.searchsorted(ends, position), len(sections) - 1)
        seat = sections[index, 1]
        return np.isnan(bore) | (np.abs(bore - seat) <= SEAT_TOLERANCE * seat)

    seated = Constraint((f"supports_{name}_bore", f"supports_{name}_position"), on_its_seat,
                        f"support {name}: its bore differs from the shaft's diameter at its "
                        "position; the inner ring sits on its seat (give the section there "
                        "the bore's diameter, the fit as shaft_fit)", unset=True)
    return tuple(prefixed(c) for c in model.constraints if set(c.inputs) <= taken) + (seated,)


def mounted(sections: np.ndarray, name: str, kind: str, given, shaft_modulus,
            shaft_poisson, speed) -> dict:
    """The operating clearance of support ``name`` and its parts
    (:func:`models.operating_clearance.mounted_clearance`, arrays over the cases), with
    ``fit_lost``. ``given(input)``: the support's input's values in the cases (SI)."""
    element, angle = ELEMENTS[kind]
    diameter = given(element)
    offset = diameter * (np.cos(given(angle)) if angle else 1.0)
    pitch = given("pitch_diameter")
    shaft = {"shaft_bore": section_bore(sections, given("position")),
             "shaft_youngs_modulus": shaft_modulus, "shaft_poisson_ratio": shaft_poisson}
    operating = [shaft[spec.name] if spec.name in shaft else given(spec.name)
                 for spec in OPERATING_INPUTS]
    clearance = np.asarray(given("clearance"), dtype=float) + np.zeros(np.shape(pitch))
    return mounted_clearance(clearance, pitch - offset, pitch + offset, diameter, speed,
                             given("youngs_modulus"), given("poisson_ratio"), *operating)
