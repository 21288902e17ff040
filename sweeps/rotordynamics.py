"""A bearing's stiffness for a rotor-dynamics model: the coefficients over speed from a result
of ``ball_5dof``, ``crb_radial`` or ``shaft_system`` swept over speed, and ross
``BearingElement`` objects built from them.

ross (the optional extra ``ross``) takes a bearing as linear springs and dampers in the two
lateral directions of its node, as functions of the rotor's speed. Its ``x`` and ``y`` are the
models' ``radial_y`` and ``radial_z``; the four lateral terms come from the result's
``stiffness_matrix`` (dF/dq of the bearing's own equilibrium at each speed). The tilt and
axial terms the matrix also holds have no place in a ross ``BearingElement`` (its rotations
are the shaft elements'), so a rotor built so leaves the bearing's moment stiffness out: it is
then somewhat softer in its conical modes than the bearings make it.

A ``crb_radial`` result holds the stiffness along its load, ``dF/d(delta)``. Across the load
the rollers answer a small sideways displacement as they answer one of the whole
displacement's direction turned: the load stays along the displacement, so the stiffness
across it is the secant ``F / delta`` (the law derives from a potential of ``|delta|``).
"""
from __future__ import annotations

import os
import sys

import numpy as np
import xarray as xr

from .definition.values import convert_written
from .models.registry import out_of_validity
from .stores import open_result

#: The lateral directions of a ross bearing, as the models name them.
_LATERAL = ("radial_y", "radial_z")


def bearing_coefficients(result: str | os.PathLike | xr.Dataset, speed: str = "speed",
                         support: str | None = None) -> dict:
    """The lateral stiffness of a bearing over speed.

    Parameters
    ----------
    result : path or xarray.Dataset
        A result of ``ball_5dof``, ``crb_radial`` or ``shaft_system`` whose only axis with
        more than one value is ``speed`` (select one value of the others first:
        ``result.sel(axial_load=...)``). A ``crb_radial`` bearing's load is along
        ``radial_y``: ``kxx`` is its stiffness along the load, ``kyy`` the secant
        ``F / delta`` across it. A ``shaft_system``'s bearing is its ``support``, with its
        stiffness at the system's equilibrium (``support_stiffness``).
    speed : str
        The speed's dimension.
    support : str, optional
        The support of a ``shaft_system`` result.

    Returns
    -------
    dict of numpy.ndarray
        ``frequency`` [rad/s], the speeds in increasing order; ``kxx``, ``kyy``, ``kxy``,
        ``kyx`` [N/m] at each, ross's ``x`` and ``y`` being the models' ``radial_y`` and
        ``radial_z``.

    Raises
    ------
    ValueError
        A result without a stiffness matrix over speed, another axis of several values, fewer
        than two speeds, or a speed whose point has no stiffness (not converged).
    """
    data = result if isinstance(result, xr.Dataset) else open_result(result)
    if data.attrs.get("model") == "shaft_system":
        data = _support_matrix(data, support)
    elif support is not None:
        raise ValueError("support names a shaft system's support; this result is of "
                         f"{data.attrs.get('model', 'another model')}")
    if data.attrs.get("model") == "crb_radial" and "radial_stiffness" in data:
        data = _roller_matrix(data)
    if "stiffness_matrix" not in data or speed not in data["stiffness_matrix"].dims:
        raise ValueError(f"the result needs a stiffness_matrix along {speed!r} (a ball_5dof, "
                         f"crb_radial or shaft_system result swept over {speed})")
    matrix = data["stiffness_matrix"]
    others = [dim for dim in matrix.dims
              if dim not in (speed, "load_dof", "dof") and matrix.sizes[dim] > 1]
    if others:
        raise ValueError(f"the result varies along {', '.join(others)} too: select one value "
                         "of each first, e.g. result.sel(name=value)")
    matrix = matrix.squeeze([dim for dim in matrix.dims
                             if dim not in (speed, "load_dof", "dof")], drop=True)
    units = data.get("stiffness_matrix_units")
    if units is not None:
        lateral = units.sel(load_dof=list(_LATERAL), dof=list(_LATERAL)).values
        if not np.all(lateral == "N/m"):
            raise ValueError(f"the lateral stiffness is stored in {set(lateral.ravel())}, "
                             "not N/m")
    speeds = convert_written(data[speed].values, data[speed].attrs.get("units", "rad/s"),
                             "rad/s")
    if speeds.size < 2:
        raise ValueError(f"the result has {speeds.size} {speed}: a rotor's bearings need "
                         "their stiffness at two speeds or more")
    order = np.argsort(speeds)
    terms = {f"k{a}{b}": matrix.sel(load_dof=row, dof=column).transpose(speed).values[order]
             for a, row in zip("xy", _LATERAL) for b, column in zip("xy", _LATERAL)}
    missing = ~np.all(np.isfinite(np.stack(list(terms.values()))), axis=0)
    if missing.any():
        raise ValueError(f"no stiffness at {speed} {speeds[order][missing].tolist()} rad/s "
                         "(points not converged)")
    if "status" in data and speed in data["status"].dims:
        status = data["status"].squeeze([d for d in data["status"].dims if d != speed],
                                        drop=True).values[order]
        outside = out_of_validity(status)
        if outside.any():
            raise ValueError(f"the points at {speed} {speeds[order][outside].tolist()} rad/s "
                             "lie outside the model's validity (status out_of_validity): "
                             "select the speeds within it")
    return {"frequency": speeds[order], **terms}


def _support_matrix(data: xr.Dataset, support: str | None) -> xr.Dataset:
    """A ``shaft_system`` result with its ``support``'s stiffness as a ``stiffness_matrix``."""
    names = [str(name) for name in data["support"].values]
    if support not in names:
        raise ValueError(f"support {support!r} is not one of the shaft's: "
                         f"{', '.join(names)} (bearing_coefficients(result, support=...))")
    if "support_stiffness" not in data:
        raise ValueError("the shaft system's result holds no support_stiffness (a result of "
                         "an earlier version: run it again)")
    chosen = data.sel(support=support)
    return chosen.assign(stiffness_matrix=chosen["support_stiffness"],
                         stiffness_matrix_units=chosen["support_stiffness_units"])


def _roller_matrix(data: xr.Dataset) -> xr.Dataset:
    """A ``crb_radial`` result with its lateral stiffness as a ``stiffness_matrix`` [N/m]:
    along the load ``dF/d(delta)``, across it ``F / delta``."""
    def si(name, unit):
        variable = data[name]
        return variable.copy(data=convert_written(variable.values, variable.attrs["units"],
                                                  unit))

    along = si("radial_stiffness", "N/m")
    with np.errstate(divide="ignore", invalid="ignore"):
        across = si("radial_load", "N") / si("radial_displacement", "m")
    across, along = xr.broadcast(across, along)
    zero = xr.zeros_like(along)
    matrix = xr.concat([xr.concat([along, zero], "dof"), xr.concat([zero, across], "dof")],
                       "load_dof").assign_coords(load_dof=list(_LATERAL), dof=list(_LATERAL))
    return data.drop_vars([name for name in ("stiffness_matrix_units",) if name in data]) \
        .assign(stiffness_matrix=matrix)


def bearing_element(result: str | os.PathLike | xr.Dataset, node: int, damping: float = 0.0,
                    speed: str = "speed", support: str | None = None, **options):
    """A ross ``BearingElement`` at ``node`` with the bearing's stiffness over speed.

    Parameters
    ----------
    result, speed, support
        As :func:`bearing_coefficients` takes them.
    node : int
        The rotor's node the bearing sits at.
    damping : float
        ``cxx = cyy`` [N s/m], as the user gives it (the model computes no damping).
    **options
        Passed to ``ross.BearingElement`` (``tag``, ``scale_factor``, ...).
    """
    ross = _ross()
    coefficients = bearing_coefficients(result, speed, support)
    count = coefficients["frequency"].size
    return ross.BearingElement(n=node, kxx=coefficients["kxx"], kyy=coefficients["kyy"],
                               kxy=coefficients["kxy"], kyx=coefficients["kyx"],
                               cxx=np.full(count, float(damping)),
                               cyy=np.full(count, float(damping)),
                               frequency=coefficients["frequency"], **options)


def _ross():
    """ross, imported so that the user's pint application registry stays as it was: ross's
    dependency ccp loads its unit definitions into that registry where one is in use (where
    they clash with pint's own), and makes its registry the application's."""
    if "ross" in sys.modules:
        return sys.modules["ross"]
    import pint

    in_use = pint.get_application_registry().get()
    pint.set_application_registry(pint.registry.LazyRegistry())
    try:
        import ross
    except ImportError as error:
        raise ImportError("a ross BearingElement needs ross: pip install "
                          "'bearing-sweep[ross]'") from error
    finally:
        pint.set_application_registry(in_use)
    return ross
