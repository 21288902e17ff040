"""The lubricant film a bearing model reports: the inputs and outputs every model that loads
rolling elements declares alike, and the one function that turns its contacts into them.

A model knows its own contacts: the load of each rolling element on each raceway, the radius
of the two bodies in the rolling direction and, for a point contact, its ellipticity; it forms
each contact's film by Hamrock and Dowson (point contacts) or Pan and Hamrock (line contacts)
in :mod:`models.lubrication`. :func:`bearing_film` keeps the smallest over the loaded
contacts and the film parameter. The oil is the one the rating lives take (Walther's law
through its viscosities at 40 and 100 deg C, at the oil temperature), isothermal and fully
flooded: neither the inlet's shear heating nor starvation thin the film here.
"""
from __future__ import annotations

import numpy as np

from .lubrication import MINERAL_OIL_PRESSURE_VISCOSITY, OIL_DENSITIES, walther_viscosity
from .registry import Input, Output

#: Density of a mineral oil near 70 deg C [kg/m^3]: lubricating mineral oils weigh about
#: 850-900 kg/m^3 at 15 deg C and expand by about 0.07 % per kelvin.
MINERAL_OIL_DENSITY = 860.0

#: Declared after the life inputs, in this order (the function's last parameters).
FILM_INPUTS = (
    Input("oil_density", "kg/m^3", "density of the oil at its operating temperature, for its "
          "dynamic viscosity in the film (mineral oils: about 850-900 at 15 degC, some 4 % "
          "less at 70 degC)", default=MINERAL_OIL_DENSITY, minimum=OIL_DENSITIES[0],
          maximum=OIL_DENSITIES[1], label="oil density"),
    Input("pressure_viscosity", "1/GPa", "pressure-viscosity coefficient alpha of the oil, "
          "for the film (mineral oils about 15-35 near 40 degC, less when warmer)",
          default=MINERAL_OIL_PRESSURE_VISCOSITY * 1e9, minimum=0.0, exclusive_minimum=True,
          maximum=100.0, label="pressure-viscosity coefficient"),
    Input("composite_roughness", "um", "composite rms roughness sigma = (Rq1^2 + Rq2^2)^(1/2) "
          "of rolling elements and raceways, for the film parameter (ground and honed "
          "raceways: about 0.05-0.3); default: no film parameter (NaN)", default=None,
          minimum=0.0, exclusive_minimum=True, label="composite roughness"),
)

FILM_OUTPUT_NAMES = ("central_film_thickness", "minimum_film_thickness", "film_parameter")


def film_outputs(contacts):
    """Output declarations of :func:`bearing_film`'s results.

    Parameters
    ----------
    contacts : str
        Which contacts the model forms films of and by which formula, e.g. "every loaded
        ball's inner and outer contact, Hamrock and Dowson".
    """
    missing = "NaN without oil viscosities"
    return (
        Output("central_film_thickness", "um", f"smallest central EHL film thickness hc over "
               f"{contacts}; isothermal, fully flooded, inner ring turning; zero at rest, "
               f"{missing}", label="central film thickness"),
        Output("minimum_film_thickness", "um", "smallest minimum EHL film thickness hmin over "
               f"the same contacts; {missing}", label="minimum film thickness"),
        Output("film_parameter", "1", "film parameter lambda = hmin / sigma (below about 1 "
               "the asperities touch through the film, above about 3 they are separated); "
               f"{missing} or composite_roughness", label="film parameter lambda"),
    )


def oil_viscosity(oil_temperature, viscosity_40, viscosity_100, oil_density):
    """Dynamic viscosity of the oil at its temperature [Pa s]: Walther's law
    (:func:`models.lubrication.walther_viscosity`) times the density; NaN where a viscosity
    is None."""
    return walther_viscosity(oil_temperature, np.nan if viscosity_40 is None else viscosity_40,
                             np.nan if viscosity_100 is None else viscosity_100) * oil_density


def bearing_film(central, minimum, composite_roughness):
    """The film outputs from every contact's film.

    Parameters
    ----------
    central, minimum : array_like
        ``(N, contacts)`` central and minimum film thickness of each contact [m], NaN where a
        contact carries no load.
    composite_roughness : array_like or None
        ``sigma`` [m]; None: no film parameter.

    Returns
    -------
    dict of numpy.ndarray
        :data:`FILM_OUTPUT_NAMES`: the smallest ``h_c`` and ``h_min`` over the loaded contacts
        [m] (NaN where none is loaded) and ``lambda = h_min / sigma`` [-].
    """
    smallest = np.fmin.reduce(np.asarray(minimum, dtype=float), axis=-1)
    roughness = np.nan if composite_roughness is None else composite_roughness
    return {"central_film_thickness": np.fmin.reduce(np.asarray(central, dtype=float), axis=-1),
            "minimum_film_thickness": smallest,
            "film_parameter": smallest / np.asarray(roughness, dtype=float)}

