"""The papers' bearings as named presets.

Values are written as a user writes them in a sweep definition (numbers with units), so a
preset goes through the same validation as the user's own values and any field can be
overridden. Each preset says where its numbers come from and which were not stated.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Preset:
    name: str
    model: str  # the first model it is for; ``also`` names others with the same inputs
    values: dict
    source: str
    notes: str = ""
    also: tuple = ()

    @property
    def models(self) -> tuple:
        return (self.model,) + self.also


_PAPER003_LOADING = {"roller_count": 16, "effective_length": "21.5 mm",
                     "roller_mean_diameter": "13.71 mm", "outer_contact_angle": "28 deg",
                     "radial_load": "40 kN", "axial_load": "27 kN"}

_PRESETS = (
    Preset(
        name="paper000-A",
        model="crb_radial",
        values={"roller_count": 13, "pitch_diameter": "39 mm", "roller_diameter": "7.5 mm",
                "effective_length": "8.6 mm", "clearance": "0.04 mm", "crown": "0 mm"},
        source="Paper 000, Table 1 (bearing A, compared with Lim's model in Fig. 6)",
        notes="Roller length 9 mm and width 15 mm are not model inputs. Straight rollers: the "
              "comparison of section 2.1 has no crown and no speed.",
    ),
    Preset(
        name="paper000-B",
        model="crb_radial",
        values={"roller_count": 14, "pitch_diameter": "170 mm", "roller_diameter": "34.8 mm",
                "effective_length": "25 mm", "clearance": "0.05 mm", "crown": "0.0045 mm"},
        source="Paper 000, Table 2 (bearing B, compared with reference [5] in Fig. 7)",
        notes="Table 2 is inconsistent: 14 rollers of 34.8 mm cannot sit on its 39 mm pitch "
              "circle (bearing A's value). The pitch diameter is set to 170 mm so that they fit; "
              "it enters only the centrifugal force, which is zero in Fig. 7 (no speed). The "
              "effective length is not stated; the paper tries 25 and 28 mm and 25 mm is the "
              "default here.",
    ),
    Preset(
        name="paper000-C",
        model="crb_radial",
        values={"roller_count": 22, "pitch_diameter": "102 mm", "roller_diameter": "10 mm",
                "effective_length": "9 mm", "clearance": "0 mm", "crown": "0 mm"},
        source="Paper 000, Table 3 (bearing C, compared with the numerical method in Fig. 8)",
        notes="Pitch diameter = (outer diameter 122 + bore 82) / 2. The clearance is not stated "
              "and is taken as zero; straight rollers as in section 2.3 (k_j = 1, c = 0).",
    ),
    Preset(
        name="paper000-D",
        model="crb_radial",
        values={"roller_count": 14, "pitch_diameter": "65 mm", "roller_diameter": "10 mm",
                "effective_length": "9.6 mm", "dynamic_load_rating": "48.4 kN"},
        source="Paper 000, Table 4 (bearing D, the parametric study of Figs. 9-14)",
        notes="Pitch diameter = (outer diameter 75 + bore 55) / 2. Roller length 10 mm is not a "
              "model input. Clearance, crown, speed and load are the study's axes. The paper "
              "states no dynamic load rating: an assumption, Cr = 48.4 kN from the geometry by "
              "ISO 281:2007, 7.1, Cr = bm fc (i Lwe cos a)^(7/9) Z^(3/4) Dwe^(29/27) = "
              "1.1 x 88.3 x 9.6^(7/9) x 14^(3/4) x 10^(29/27) (N, mm), with bm = 1.1 "
              "(Table 1, cylindrical roller bearings) and fc = 88.3 interpolated in Table 7 at "
              "Dwe cos a / Dpw = 10/65 = 0.154.",
    ),
    Preset(
        name="paper001-71807AC",
        model="ball_5dof",
        values={"ball_count": 25, "ball_diameter": "3.14 mm", "pitch_diameter": "41 mm",
                "contact_angle": "25 deg", "inner_curvature_ratio": 0.52,
                "outer_curvature_ratio": 0.53, "clearance": "0 mm", "youngs_modulus": "207 GPa",
                "poisson_ratio": 0.3, "contact_constant": "1.0649e10 N/m^1.5",
                "dynamic_load_rating": "4.15 kN", "skf_rolling_constant_1": 5.03e-7,
                "skf_rolling_constant_2": 1.97, "skf_rolling_constant_3": 1.90e-12,
                "skf_sliding_constant_1": 1.30e-2, "skf_sliding_constant_2": 0.68,
                "skf_sliding_constant_3": 1.91e-12},
        source="Paper 001, Table 1 (71807AC angular contact ball bearing)",
        notes="Pitch diameter = (35 + 47) / 2 from the table's inner and outer ring diameters. "
              "The groove curvature ratios are not stated: 0.52 (inner) and 0.53 (outer) are "
              "usual for angular contact bearings. They set the contact angle's change under "
              "load; the contact constant is the paper's, where Hertz theory gives "
              "5.45e9 N/m^1.5 for these ratios (remove contact_constant to use it). Zero "
              "clearance: the axial preload of 1000 N is a load of the study. The paper "
              "states no dynamic load rating: an assumption, Cr = 4.15 kN from the table's "
              "geometry by ISO 281:2007, 5.1 (Dw <= 25.4 mm), "
              "Cr = bm fc (i cos a)^0.7 Z^(2/3) Dw^1.8 = 1.3 x 51.0 x cos(25 deg)^0.7 x "
              "25^(2/3) x 3.14^1.8 (N, mm), with bm = 1.3 (Table 1, angular contact groove "
              "ball bearings) and fc = 51.0 interpolated in Table 2 at Dw cos a / Dpw = "
              "0.0694. SKF's friction constants R1-R3, S1-S3 are those its table of "
              "geometric constants gives single-row angular contact ball bearings as a type "
              "(it has no row for the thin-section series 718).",
    ),
    Preset(
        name="paper003-table1",
        model="trb_load",
        values={**_PAPER003_LOADING, "pitch_diameter": "79.537 mm",
                "dynamic_load_rating": "127.6 kN"},
        source="Paper 003, Table 1 (single-row tapered roller bearing of a vehicle reducer)",
        notes="Roller length 21.5 mm is taken as the effective length l of eq. 14; the "
              "contact constant is eq. 14's default. The pitch diameter (for the contact "
              "pressure and the life) is not stated: 79.537 mm is the one trb_rib derives from "
              "the rib diameter of paper003-table1-rib. The paper states no dynamic load "
              "rating: an assumption, Cr = 127.6 kN from the geometry by ISO 281:2007, 7.1, "
              "Cr = bm fc (i Lwe cos a)^(7/9) Z^(3/4) Dwe^(29/27) = 1.1 x 88.3 x "
              "(21.5 cos 28 deg)^(7/9) x 16^(3/4) x 13.71^(29/27) (N, mm), with bm = 1.1 "
              "(Table 1, tapered roller bearings), the cup angle for a, the mean roller "
              "diameter for Dwe and fc = 88.3 interpolated in Table 7 at Dwe cos a / Dpw = "
              "0.152.",
    ),
    Preset(
        name="paper003-table1-rib",
        model="trb_rib",
        values={**_PAPER003_LOADING, "roller_large_diameter": "15.21 mm",
                "roller_half_angle": "4 deg", "roller_end_radius": "103 mm",
                "oil_groove_size": "1 mm", "rib_diameter": "74.007 mm",
                "youngs_modulus": "206 GPa", "poisson_ratio": 0.3},
        source="Paper 003, Table 1",
        notes="The rib diameter di is not stated. 74.007 mm makes the rib's radius of curvature "
              "R12 at the design method's rib angle 88 deg 53' (contact at the middle of the "
              "rib) equal to Table 1's arc-rib radius rho = 109 mm. The rib angle is the "
              "study's axis.",
    ),
    Preset(
        name="paper002-test",
        model="cage_slip",
        values={"roller_count": 13, "inner_raceway_diameter": "44 mm", "roller_diameter": "10 mm",
                "roller_length": "11 mm", "effective_length": "7.2 mm", "clearance": "0.02 mm",
                "cage_inner_diameter": "48.5 mm", "cage_outer_diameter": "59 mm",
                "cage_width": "13 mm", "pocket_clearance": "0.1 mm", "roller_density":
                "7820 kg/m^3", "youngs_modulus": "207 GPa", "poisson_ratio": 0.28,
                "end_film_thickness": "0.015 mm"},
        source="Paper 002, Tables 2-3 (the test bearing of Fig. 17)",
        also=("cage_dynamics", "cage_dynamics_6dof"),
        notes="Table 2 is inconsistent: 44 + 2 x 10 + 0.02 = 64.02 mm, not its 63.82 mm outer "
              "raceway (which would be 0.18 mm of interference). The inner raceway, roller and "
              "clearance are kept; the outer raceway follows from them. The cage width is not "
              "stated: 13 mm assumed, the 11 mm roller and a 1 mm side ring each side (it "
              "sets the cage's windage and, in the transients, its mass and inertia). The end "
              "film is the rib axial play, 0.015 mm. Oil, traction and drag are the model's "
              "documented defaults: the paper gives none of them.",
    ),
    Preset(
        name="paper002-NU2330EM1",
        model="cage_slip",
        values={"roller_count": 14, "inner_raceway_diameter": "165 mm",
                "roller_diameter": "45 mm", "roller_length": "74.6 mm",
                "effective_length": "70 mm", "clearance": "0.08 mm",
                "cage_inner_diameter": "196 mm", "cage_outer_diameter": "224 mm",
                "cage_width": "90 mm", "pocket_clearance": "0.36 mm",
                "end_film_thickness": "0.015 mm", "radial_load": "50 kN", "speed": "1000 rpm"},
        source="Paper 002, Table 1 (NU2330EM1, compared with ref. [20] in Fig. 13)",
        also=("cage_dynamics",),
        notes="Table 1's 165 mm 'bore' is taken as the inner raceway diameter (an NU2330 has a "
              "150 mm bore; 14 rollers of 45 mm fit on a 165 mm raceway). Not stated and "
              "assumed: effective length 70 mm (74.6 mm roller less its end chamfers), cage "
              "196/224 mm and 90 mm wide (it only sets windage), the clearance 0.08 mm taken "
              "as diametral. Oil, traction and drag: the model's defaults.",
    ),
    *(Preset(
        name=f"paper004-NU208-{number}",
        model="crb_runout",
        values={"inner_raceway_diameter": f"{inner} mm", "outer_raceway_diameter": f"{outer} mm",
                "roller_diameter": f"{roller} mm", "roller_count": 14},
        source=f"Paper 004, Table 1 (NU208 number {number}; computed runout {computed} um, "
               f"measured {measured} um in Table 2)",
        notes=f"The roller diameter is the middle of the stated range {spread}; the rollers' "
              "own deviations are roller_diameter_error. The measured roundness harmonics "
              "behind Table 2 are not printed: the preset has round parts.",
    ) for number, inner, outer, roller, spread, computed, measured in (
        (1, 49.481, 71.555, 10.9985, "10.998-10.999 mm", 5.2, 5),
        (2, 49.492, 71.540, 10.998, "10.997-10.999 mm", 3.5, 4),
        (3, 49.499, 71.545, 10.9985, "10.997-11 mm", 5.5, 6))),
)

PRESETS = {preset.name: preset for preset in _PRESETS}
