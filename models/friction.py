"""Friction torque and power loss as a bearing model reports them: the inputs and outputs
every model that loads rolling elements declares alike, and the functions that form them.

Two methods, chosen by the input ``friction_method``:

* ``'skf'`` (default), SKF's model of the frictional moment [1]_: a rolling part
  ``M_rr = phi_ish phi_rs G_rr (nu n)^0.6``, the viscous rolling resistance of the EHL
  contacts reduced for the inlet's shear heating (``phi_ish``) and for the replenishment of
  the raceways' oil (``phi_rs``), and a sliding part ``M_sl = G_sl mu_sl``, whose coefficient
  passes from the boundary value ``mu_bl`` at rest and at thin films to the full-film value
  ``mu_EHL`` as ``nu n`` grows. ``G_rr`` and ``G_sl`` are the bearing type's functions of the
  mean diameter and the loads; their constants ``R1 ...`` and ``S1 ...`` belong to the
  bearing's series and are SKF's (its table of geometric constants). The drag of an oil
  bath is added where its level is given, with SKF's drag loss factor ``V_M`` read off its
  diagram. Seals are not included.
* ``'palmgren'``: Palmgren's load-independent ``M0 = 1e-7 f0 (nu n)^(2/3) dm^3`` (``160e-7
  f0 dm^3`` where ``nu n < 2000``) and load-dependent ``M1 = f1 P1 dm`` [2]_, with the
  factors ``f0`` and ``f1`` the user takes from the catalogue of the bearing's maker, and
  ``P1`` the bearing's static equivalent load (ISO 76) that the model already reports.

Both work in the units their sources print (N mm, N, mm, r/min, mm^2/s); the functions here
take and give SI. The oil's viscosity is the one the rating lives and the film take (Walther's
law at the oil temperature); for grease, that of its base oil.

References
----------
.. [1] SKF, Rolling bearings, catalogue PUB BU/P1 10000/1 EN (2013), "Friction": the SKF
   model for calculating the frictional moment, Table 2a and the geometric constants.
.. [2] A. Palmgren, Ball and Roller Bearing Engineering, 3rd ed., SKF Industries,
   Philadelphia (1959); T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis:
   Essential Concepts of Bearing Technology, 5th ed., CRC Press (2007),
   doi:10.1201/9781420006582, ch. 10.
"""
from __future__ import annotations

import numpy as np

from .registry import Constraint, Input, Output, below

FRICTION_METHODS = ("skf", "palmgren")
LUBRICATION_METHODS = ("oil_bath", "oil_jet", "oil_air", "grease")
#: SKF's replenishment constant K_rs of phi_rs by lubrication (low-level oil bath and oil jet;
#: oil-air and grease) [SKF's units].
_REPLENISHMENT = {"oil_bath": 3e-8, "oil_jet": 3e-8, "oil_air": 6e-8, "grease": 6e-8}

#: Per bearing type: SKF's geometric constant K_Z of phi_rs and the drag, the full-film
#: sliding coefficient mu_EHL (for ball bearings, that of a mineral oil), SKF's constants the
#: type's G_rr and G_sl take (Table 2a), and its roller-type constant K_L of the drag.
_TYPES = {
    "angular_contact_ball": (4.4, 0.05, ("r1", "r2", "r3", "s1", "s2", "s3"), None),
    "cylindrical_roller": (5.1, 0.02, ("r1", "s1", "s2"), 0.65),
    "tapered_roller": (6.0, 0.002, ("r1", "r2", "s1", "s2"), 0.7),
}
#: Bounds above SKF's constants of every series of its table (spherical roller bearings'
#: S2 reach some 9500), by symbol.
_CONSTANT_MAXIMA = {"r1": 1e-4, "r2": 100.0, "r3": 1e-9, "s1": 1.0, "s2": 1e5, "s3": 1e-9}
_CONSTANT_MEANINGS = {
    "r1": "rolling-frictional constant R1", "r2": "rolling-frictional constant R2 (axial "
    "load)", "r3": "rolling-frictional constant R3 (the balls' centrifugal load)",
    "s1": "sliding-frictional constant S1", "s2": "sliding-frictional constant S2 (axial "
    "load)", "s3": "sliding-frictional constant S3 (the balls' centrifugal load)"}
#: Palmgren's nu n below which M0 stops falling with speed [mm^2/s r/min].
_PALMGREN_BRANCH = 2000.0

FRICTION_OUTPUT_NAMES = ("friction_torque", "rolling_friction_torque",
                         "sliding_friction_torque", "drag_friction_torque",
                         "viscous_friction_torque", "load_friction_torque", "power_loss")


def friction_inputs(kind):
    """Input declarations of the friction of a ``kind`` bearing ('angular_contact_ball',
    'cylindrical_roller' or 'tapered_roller'), declared after the static safety's."""
    _, full_film, constants, roller_type = _TYPES[kind]
    series = tuple(
        Input(_constant_name(name), "1",
              f"SKF's {_CONSTANT_MEANINGS[name]} of the bearing's series, in SKF's units (N, "
              f"mm, r/min), for friction_method 'skf'; default: no SKF friction (NaN)",
              default=None, minimum=0.0, maximum=_CONSTANT_MAXIMA[name],
              label=f"SKF constant {name.upper()}")
        for name in constants)
    return (
        Input("friction_method", "", "how the friction torque is formed: 'skf', SKF's model "
              "of the frictional moment (rolling and sliding parts); 'palmgren', Palmgren's "
              "M0 + M1 from the catalogue factors f0 and f1", default="skf", kind="choice",
              choices=FRICTION_METHODS),
        Input("lubrication_method", "", "how the oil reaches the bearing, for SKF's "
              "replenishment factor phi_rs: 'oil_bath' (low level) or 'oil_jet' (K_rs = 3e-8), "
              "'oil_air' or 'grease' (6e-8; the viscosity is then the base oil's)",
              default="oil_bath", kind="choice", choices=LUBRICATION_METHODS),
    ) + series + (
        Input("boundary_friction_coefficient", "1", "SKF's sliding coefficient mu_bl in "
              "boundary lubrication, which the lubricant's additives set (SKF: generally "
              "about 0.15)", default=0.15, minimum=0.0, maximum=1.0,
              label="boundary friction coefficient"),
        Input("full_film_friction_coefficient", "1", "SKF's sliding coefficient mu_EHL in "
              "full-film lubrication (SKF: 0.02 cylindrical and 0.002 tapered roller "
              "bearings; 0.05 others with mineral oil, 0.04 synthetic oil, 0.1 transmission "
              "fluid)", default=full_film, minimum=0.0, maximum=1.0,
              label="full-film friction coefficient"),
        Input("palmgren_speed_factor", "1", "Palmgren's factor f0 of the load-independent "
              "torque M0, from the bearing maker's catalogue for the bearing's type, series and "
              "lubrication (about 1-10), for friction_method 'palmgren'; default: none (NaN)",
              default=None, minimum=0.0, maximum=100.0, label="Palmgren factor f0"),
        Input("palmgren_load_factor", "1", "Palmgren's factor f1 of the load-dependent torque "
              "M1 = f1 P1 dm (P1 = the static equivalent load P0r), from the bearing maker's "
              "catalogue (about 1e-4 to 2e-3), for friction_method 'palmgren'; default: none "
              "(NaN)", default=None, minimum=0.0, maximum=0.1, label="Palmgren factor f1"),
        Input("oil_level", "mm", "level H of an oil bath above the lowest point of the outer "
              "ring's raceway (SKF's H; from 1.2 dm the bearing is submerged), for SKF's drag "
              "loss, with drag_loss_factor, bore and outside_diameter; default: no drag",
              default=None, minimum=0.0, label="oil level"),
        Input("drag_loss_factor", "1", "SKF's drag loss factor V_M, read off its diagram for "
              f"{'roller' if roller_type else 'ball'} bearings at H / dm (at most about "
              f"{1.5e-3 if roller_type else 1.25e-3:g}, submerged), for the drag loss; default: "
              "none", default=None, minimum=0.0, maximum=0.01, label="drag loss factor V_M"),
    ) + ((Input("bearing_width", "mm", "width B of the bearing, for SKF's drag loss of a "
                "roller bearing; default: none", default=None, minimum=0.0,
                exclusive_minimum=True, label="bearing width"),) if roller_type else ())


def friction_constraints(kind):
    """The condition between the friction inputs, checked on a definition before any
    computing (:func:`bearing_friction`'s ``ValueError`` says the same of a direct call): an
    oil level needs what SKF's drag loss takes."""
    needed = ("drag_loss_factor", "bore", "outside_diameter") + (
        ("bearing_width",) if _TYPES[kind][3] else ())

    def given(oil_level, **others):
        arrays = np.broadcast_arrays(oil_level, *(others[name] for name in needed))
        return np.isnan(arrays[0]) | np.all([np.isfinite(a) for a in arrays[1:]], axis=0)

    def bath(oil_level, friction_method, lubrication_method):
        return np.isnan(oil_level) | ((friction_method == "skf")
                                      & (lubrication_method == "oil_bath"))

    return (Constraint(("oil_level",) + needed, given, "oil_level needs "
                       + ", ".join(needed[:-1]) + " and " + needed[-1] + " (SKF's drag loss)",
                       unset=True),
            Constraint(("oil_level", "friction_method", "lubrication_method"), bath,
                       "oil_level is an oil bath's, for SKF's drag loss: it needs "
                       "friction_method 'skf' and lubrication_method 'oil_bath' (Palmgren's "
                       "f0 holds the lubrication's losses)", unset=True))


def _constant_name(symbol):
    """The input name of SKF's constant ``symbol`` ('r1' -> 'skf_rolling_constant_1')."""
    return f"skf_{'rolling' if symbol[0] == 'r' else 'sliding'}_constant_{symbol[1]}"


def friction_outputs():
    """Output declarations of :func:`bearing_friction`'s results."""
    missing = "NaN without the oil's viscosities"
    return (
        Output("friction_torque", "N*m", "friction torque of the bearing turning at the "
               "inner ring's speed: SKF's rolling + sliding moment or Palmgren's M0 + M1, by "
               f"friction_method (with SKF's, an oil bath's drag where oil_level is given; "
               f"seals not included); {missing} or the method's constants",
               label="friction torque"),
        Output("rolling_friction_torque", "N*m", "SKF's rolling frictional moment "
               "phi_ish phi_rs G_rr (nu n)^0.6, the EHL contacts' viscous rolling resistance "
               "(phi_rs = 1 without bore and outside diameter); NaN for Palmgren's",
               label="rolling friction torque"),
        Output("sliding_friction_torque", "N*m", "SKF's sliding frictional moment G_sl "
               "mu_sl, mu_sl passing from mu_bl at rest to mu_EHL as nu n grows; NaN for "
               "Palmgren's", label="sliding friction torque"),
        Output("drag_friction_torque", "N*m", "SKF's drag loss of an oil bath at oil_level, "
               "0.4 V_M K_ball dm^5 n^2 (ball bearings) or 4 V_M K_roll C_w B dm^4 n^2 (roller "
               "bearings) and the bath's viscous part; 0 without oil_level, NaN for "
               "Palmgren's", label="drag friction torque"),
        Output("viscous_friction_torque", "N*m", "Palmgren's load-independent torque M0 = "
               "1e-7 f0 (nu n)^(2/3) dm^3 (160e-7 f0 dm^3 below nu n = 2000; N mm, mm^2/s, "
               "r/min, mm); NaN for SKF's", label="load-independent friction torque M0"),
        Output("load_friction_torque", "N*m", "Palmgren's load-dependent torque M1 = f1 P1 dm "
               "with P1 the static equivalent load P0r; NaN for SKF's",
               label="load-dependent friction torque M1"),
        Output("power_loss", "W", "power the friction turns into heat, friction_torque times "
               "the inner ring's angular speed", label="frictional power loss"),
    )


def bearing_friction(kind, method, lubrication, speed, pitch_diameter, radial_load, axial_load,
                     kinematic_viscosity, constants, boundary_coefficient,
                     full_film_coefficient, speed_factor, load_factor, equivalent_load,
                     bore=np.nan, outside_diameter=np.nan, axial_load_factor=np.nan,
                     oil_level=np.nan, drag_loss_factor=np.nan, bearing_width=np.nan):
    """The friction outputs of a bearing.

    Parameters
    ----------
    kind : {'angular_contact_ball', 'cylindrical_roller', 'tapered_roller'}
        The bearing type, which sets SKF's G_rr and G_sl (Table 2a of [1]_) and K_Z.
    method : {'skf', 'palmgren'}
    lubrication : {'oil_bath', 'oil_jet', 'oil_air', 'grease'}
        For SKF's replenishment constant K_rs.
    speed : array_like
        Inner ring's speed [rad/s].
    pitch_diameter : array_like
        ``d_m`` [m], the mean diameter where bore and outside diameter are not given.
    radial_load, axial_load : array_like
        ``F_r``, ``F_a`` [N] applied to the bearing.
    kinematic_viscosity : array_like
        ``nu`` of the oil (of the grease's base oil) at its temperature [m^2/s].
    constants : dict
        SKF's constants of the series by symbol ('r1', 's2', ...), NaN where not given.
    boundary_coefficient, full_film_coefficient : array_like
        ``mu_bl``, ``mu_EHL`` [-].
    speed_factor, load_factor : array_like
        Palmgren's ``f0``, ``f1`` [-], NaN where not given.
    equivalent_load : array_like
        Palmgren's ``P1`` [N]: the static equivalent load.
    bore, outside_diameter : array_like
        ``d``, ``D`` [m]: SKF's mean diameter ``(d + D) / 2`` and its ``phi_rs``; NaN: the
        pitch diameter and ``phi_rs = 1``.
    axial_load_factor : array_like
        ``Y`` of a tapered roller bearing [-].
    oil_level, drag_loss_factor, bearing_width : array_like
        SKF's ``H`` [m], ``V_M`` [-] and a roller bearing's ``B`` [m] for the drag of an oil
        bath (:func:`skf_drag_moment`); NaN level: no drag.

    Returns
    -------
    dict of numpy.ndarray
        :data:`FRICTION_OUTPUT_NAMES`, torques [N m] and the power loss [W].

    Raises
    ------
    ValueError
        An unknown method, or an oil level without the drag loss factor, the rings (and a
        roller bearing's width).
    """
    if method not in FRICTION_METHODS or lubrication not in LUBRICATION_METHODS:
        raise ValueError(f"friction_method must be one of {FRICTION_METHODS}, "
                         f"lubrication_method one of {LUBRICATION_METHODS}")
    (speed, pitch_diameter, radial_load, axial_load, kinematic_viscosity, equivalent_load,
     bore, outside_diameter, axial_load_factor, oil_level, drag_loss_factor,
     bearing_width) = (np.asarray(np.nan if a is None else a, dtype=float) for a in (
         speed, pitch_diameter, radial_load, axial_load, kinematic_viscosity, equivalent_load,
         bore, outside_diameter, axial_load_factor, oil_level, drag_loss_factor,
         bearing_width))
    rings = np.isfinite(bore) & np.isfinite(outside_diameter)
    mean = 1e3 * np.where(rings, 0.5 * (bore + outside_diameter), pitch_diameter)  # [mm]
    revolutions = np.asarray(speed) * 30.0 / np.pi  # [r/min]
    viscosity = 1e6 * np.asarray(kinematic_viscosity)  # [mm^2/s]
    shape = np.broadcast(mean, viscosity, radial_load, axial_load).shape
    parts = {name: np.full(shape, np.nan) for name in FRICTION_OUTPUT_NAMES[1:6]}
    bath = np.isfinite(oil_level)
    roller = _TYPES[kind][3] is not None
    if np.any(bath & ~(rings & np.isfinite(drag_loss_factor)
                       & (np.isfinite(bearing_width) | (not roller)))):
        raise ValueError(friction_constraints(kind)[0].message)
    if np.any(bath) and (method, lubrication) != ("skf", "oil_bath"):
        raise ValueError(friction_constraints(kind)[1].message)
    if method == "skf":
        with np.errstate(over="ignore", invalid="ignore"):  # IEEE results beyond any bearing
            rolling, sliding = skf_frictional_moments(
                kind, revolutions, mean, radial_load, np.abs(axial_load), viscosity,
                constants, boundary_coefficient, full_film_coefficient,
                _REPLENISHMENT[lubrication], 1e3 * np.where(rings, bore, np.nan),
                1e3 * np.where(rings, outside_diameter, np.nan), axial_load_factor)
            drag = np.where(bath, skf_drag_moment(
                kind, revolutions, mean, viscosity, 1e3 * oil_level, drag_loss_factor,
                1e3 * bore, 1e3 * outside_diameter, 1e3 * bearing_width), 0.0)
        parts.update(rolling_friction_torque=1e-3 * rolling,
                     sliding_friction_torque=1e-3 * sliding, drag_friction_torque=1e-3 * drag)
        total = (parts["rolling_friction_torque"] + parts["sliding_friction_torque"]
                 + parts["drag_friction_torque"])
    else:
        viscous, loaded = palmgren_moments(revolutions, mean, viscosity, speed_factor,
                                           load_factor, equivalent_load)
        parts.update(viscous_friction_torque=1e-3 * viscous, load_friction_torque=1e-3 * loaded)
        total = parts["viscous_friction_torque"] + parts["load_friction_torque"]
    return {"friction_torque": total, **parts, "power_loss": total * np.asarray(speed)}


def skf_frictional_moments(kind, speed, mean_diameter, radial_load, axial_load, viscosity,
                           constants, boundary_coefficient, full_film_coefficient,
                           replenishment_constant, bore=np.nan, outside_diameter=np.nan,
                           axial_load_factor=np.nan):
    """SKF's rolling and sliding frictional moments ``phi_ish phi_rs M_rr`` and ``M_sl``,
    in SKF's units.

    Parameters
    ----------
    kind : str
        Bearing type, as :func:`bearing_friction`'s.
    speed : array_like
        ``n`` [r/min].
    mean_diameter : array_like
        ``d_m`` [mm].
    radial_load, axial_load : array_like
        ``F_r``, ``F_a`` [N].
    viscosity : array_like
        ``nu`` [mm^2/s].
    constants : dict
        ``R1 ...``, ``S1 ...`` by symbol ('r1', ...).
    boundary_coefficient, full_film_coefficient : array_like
        ``mu_bl``, ``mu_EHL`` [-].
    replenishment_constant : float
        ``K_rs`` [-].
    bore, outside_diameter : array_like
        ``d``, ``D`` [mm]; NaN: ``phi_rs = 1``.
    axial_load_factor : array_like
        ``Y`` [-] (tapered roller bearings).

    Returns
    -------
    rolling, sliding : numpy.ndarray
        [N mm].
    """
    n, dm, fr, fa, nu, c = speed, mean_diameter, radial_load, axial_load, viscosity, constants
    key_constant = _TYPES[kind][0]
    if kind == "angular_contact_ball":
        centrifugal = dm ** 4 * n ** 2
        rolling = c["r1"] * dm ** 1.97 * (fr + c["r3"] * centrifugal + c["r2"] * fa) ** 0.54
        sliding = c["s1"] * dm ** 0.26 * ((fr + c["s3"] * centrifugal) ** (4.0 / 3.0)
                                          + c["s2"] * fa ** (4.0 / 3.0))
    elif kind == "cylindrical_roller":
        rolling = c["r1"] * dm ** 2.41 * fr ** 0.31
        sliding = c["s1"] * dm ** 0.9 * fa + c["s2"] * dm * fr
    else:
        rolling = c["r1"] * dm ** 2.38 * (fr + c["r2"] * axial_load_factor * fa) ** 0.31
        sliding = c["s1"] * dm ** 0.82 * (fr + c["s2"] * axial_load_factor * fa)
    inlet_shear = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)
    with np.errstate(invalid="ignore"):
        starvation = np.exp(-replenishment_constant * nu * n * (bore + outside_diameter)
                            * np.sqrt(key_constant / (2.0 * (outside_diameter - bore))))
    starvation = np.where(np.isnan(bore) | np.isnan(outside_diameter), 1.0, starvation)
    boundary_share = np.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    coefficient = (boundary_share * boundary_coefficient
                   + (1.0 - boundary_share) * full_film_coefficient)
    return inlet_shear * starvation * rolling * (nu * n) ** 0.6, sliding * coefficient


def skf_drag_moment(kind, speed, mean_diameter, viscosity, oil_level, drag_loss_factor, bore,
                    outside_diameter, bearing_width=np.nan):
    """SKF's drag loss of a bearing in an oil bath [N mm]: the rolling elements' drag
    ``0.4 V_M K_ball d_m^5 n^2`` (ball bearings) or ``4 V_M K_roll C_w B d_m^4 n^2`` (roller
    bearings) and the bath's viscous loss ``1.093e-7 n^2 d_m^3 (n d_m^2 f_t / nu)^-1.379 R_s``.

    Parameters
    ----------
    kind : str
        Bearing type, as :func:`bearing_friction`'s.
    speed : array_like
        ``n`` [r/min].
    mean_diameter : array_like
        ``d_m`` [mm].
    viscosity : array_like
        ``nu`` [mm^2/s].
    oil_level : array_like
        ``H`` [mm] above the lowest point of the outer ring's raceway; from ``1.2 d_m`` on,
        the bearing is submerged.
    drag_loss_factor : array_like
        ``V_M`` [-], from SKF's diagram at ``H / d_m``.
    bore, outside_diameter : array_like
        ``d``, ``D`` [mm].
    bearing_width : array_like
        ``B`` [mm] of a roller bearing.

    Returns
    -------
    numpy.ndarray
        [N mm].
    """
    key_constant, _, _, roller_type = _TYPES[kind]
    n, dm, nu = speed, mean_diameter, viscosity
    level = np.minimum(oil_level, 1.2 * dm)
    immersion = 2.0 * np.arccos((0.6 * dm - level) / (0.6 * dm))  # t [rad]
    sector = np.where(immersion <= np.pi, np.sin(0.5 * immersion), 1.0)  # f_t
    shape = (outside_diameter + bore) / (outside_diameter - bore)
    wetted = 0.36 * dm ** 2 * (immersion - np.sin(immersion)) * 0.05 * key_constant * shape
    with np.errstate(divide="ignore", invalid="ignore"):
        bath = np.where(wetted * n > 0.0, 1.093e-7 * n ** 2 * dm ** 3 * wetted
                        * (n * dm ** 2 * sector / nu) ** -1.379, 0.0)
    if roller_type is None:
        return 0.4 * drag_loss_factor * key_constant * shape * 1e-12 * dm ** 5 * n ** 2 + bath
    length = 5.0 * roller_type * bearing_width / dm  # l_D
    width_factor = (2.789e-10 * length ** 3 - 2.786e-4 * length ** 2 + 0.0195 * length
                    + 0.6439)  # C_w
    return (4.0 * drag_loss_factor * roller_type * key_constant * shape * 1e-12 * width_factor
            * bearing_width * dm ** 4 * n ** 2 + bath)


def palmgren_moments(speed, mean_diameter, viscosity, speed_factor, load_factor, load):
    """Palmgren's load-independent and load-dependent torques ``M0`` and ``M1`` [N mm] from
    ``n`` [r/min], ``d_m`` [mm], ``nu`` [mm^2/s], ``f0``, ``f1`` [-] and ``P1`` [N]."""
    product = viscosity * speed
    viscous = speed_factor * mean_diameter ** 3 * np.where(
        below(product, _PALMGREN_BRANCH), 160e-7, 1e-7 * np.maximum(product, 0.0) ** (2.0 / 3.0))
    return viscous, load_factor * load * mean_diameter
