"""The material numbers of the ISO 10300 rating, from the toolkit's one material table.

:func:`rating_material` gathers, for one member, what the rating takes from
``geometry/core/data/materials.toml``: E and ν (``elastic``), the density (``thermal``),
the allowable stress numbers of an ISO 6336-5 quality grade (``allowable_stress``:
σ_H,lim, and σ_F,lim = σ_FE / Y_ST), the life-factor curves (``sn_contact``,
``sn_bending``) and the material factors of ISO 10300-3 (``rating_factors``: slip-layer
thickness of Y_δrelT, coefficients of Y_R,relT). A ``[rating]`` table may override E, ν,
σ_H,lim and σ_F,lim (:class:`contact.load_capacity.iso10300.inputs.RatingInputs`).
"""

from __future__ import annotations

from dataclasses import dataclass

from contact.load_capacity.durability.sn_curve import SNCurve, sn_curves
from contact.load_capacity.iso10300.bending import STRESS_CORRECTION_TEST_GEAR
from geometry.core.errors import InputError
from geometry.core.materials import material

__all__ = ["RatingMaterial", "rating_material"]


@dataclass(frozen=True)
class RatingMaterial:
    """One member's material numbers for the rating.

    Attributes
    ----------
    key : str
        The material table's name.
    youngs_modulus : float — [MPa]
    poisson_ratio : float — [1]
    density : float — [kg/mm³]
    sigma_Hlim, sigma_Flim : float — [MPa]
        Allowable stress numbers (contact; bending, the nominal number σ_FE / Y_ST).
    contact_curve, bending_curve : SNCurve
        The life-factor curves (knee, static end, static factor).
    slip_layer : float — [mm]
        ρ′ of the relative notch sensitivity factor.
    surface_condition : (float, float, float)
        (a, b, c) of Y_R,relT = a − b (Rz + 1)^c.
    surface_condition_smooth : float
        Y_R,relT below Rz = 1 µm.
    source : str
        Where the numbers come from.
    """

    key: str
    youngs_modulus: float
    poisson_ratio: float
    density: float
    sigma_Hlim: float
    sigma_Flim: float
    contact_curve: SNCurve
    bending_curve: SNCurve
    slip_layer: float
    surface_condition: tuple[float, float, float]
    surface_condition_smooth: float
    source: str


def rating_material(name: str, grade: str = "MQ") -> RatingMaterial:
    """The rating's numbers of a bundled material at an ISO 6336-5 quality grade.

    Parameters
    ----------
    name : str
        A material of the table (:func:`geometry.core.materials.available_materials`).
    grade : {"ML", "MQ", "ME"}

    Returns
    -------
    RatingMaterial

    Raises
    ------
    InputError
        An unknown grade, or a material without the groups the rating needs (named).
    ModelUnavailableError
        An unknown material.

    Notes
    -----
    Source: the material table's groups and their ``source`` texts (ISO 6336-5:2016,
    ISO 6336-2/-3:2019, ISO 10300-3:2014).
    """
    mat = material(name)
    curves = sn_curves(mat, grade)
    groups = mat.groups
    for need in ("thermal", "rating_factors"):
        if need not in groups:
            raise InputError(f"material: {name!r} has no {need} group in its table (needed "
                             "by the ISO 10300 rating)")
    rf = groups["rating_factors"]
    coeffs = tuple(float(x) for x in rf["surface_condition"])
    if len(coeffs) != 3:
        raise InputError(f"{name}.rating_factors.surface_condition: must be [a, b, c], got "
                         f"{list(coeffs)!r}")
    return RatingMaterial(
        key=mat.key, youngs_modulus=mat.youngs_modulus, poisson_ratio=mat.poisson_ratio,
        density=float(groups["thermal"]["density"]) * 1e-9,
        sigma_Hlim=curves["contact"].allowable,
        sigma_Flim=curves["bending"].allowable / STRESS_CORRECTION_TEST_GEAR,
        contact_curve=curves["contact"], bending_curve=curves["bending"],
        slip_layer=float(rf["slip_layer_thickness"]), surface_condition=coeffs,
        surface_condition_smooth=float(rf["surface_condition_smooth"]),
        source=" ".join(mat.sources[g] for g in ("allowable_stress", "sn_contact",
                                                  "sn_bending", "rating_factors")))
