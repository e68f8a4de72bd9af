"""Mechanical power loss and efficiency (seed chapter 5).

Lubricant properties, film thickness and lambda ratio, friction coefficient models
(a registry: the bundled ``kolivand2009``, ``xu2007``, ``benedict_kelley``, ``constant``
and any registered with :func:`register_friction_model`), the mixed-EHL line-contact
solvers, rolling loss, power loss and efficiency. (Flash temperature, scuffing, specific film
thickness and micropitting are load capacity: :mod:`contact.load_capacity`, which reads the
efficiency stage's ``/friction`` dataset; nothing here reads its outputs.)

The names below are the package's public, stable surface (issue 54): import them from
``friction``, never from a submodule::

    from friction import efficiency_analysis, load_lubricant, register_friction_model
"""

from geometry.core.lazy import lazy_exports

__all__ = [
    "DEFAULT_FRICTION_MODEL",
    "GroundSurface",
    "LineContactCondition",
    "Lubricant",
    "OperatingConditions",
    "available_friction_models",
    "available_lubricants",
    "efficiency_analysis",
    "friction_coefficient",
    "load_kolivand2009_fit",
    "load_lubricant",
    "pressure_viscosity_coefficient",
    "register_friction_model",
    "solve_line_contact",
    "solve_stochastic_line_contact",
    "stochastic_summary",
    "unregister_friction_model",
    "viscosity",
]

#: the public names and the module each comes from, imported when first used (PEP 562)
_LAZY = {
    **dict.fromkeys(("DEFAULT_FRICTION_MODEL", "available_friction_models",
                     "friction_coefficient", "register_friction_model",
                     "unregister_friction_model"),
                    "friction.coefficient"),
    **dict.fromkeys(("Lubricant", "available_lubricants", "load_lubricant",
                     "pressure_viscosity_coefficient", "viscosity"), "friction.lubricant"),
    "OperatingConditions": "friction.operating",
    "efficiency_analysis": "friction.efficiency",
    # (the model function is friction_coefficient("kolivand2009", ...): a name kolivand2009
    # here would be hidden by the module of that name once it is imported)
    "load_kolivand2009_fit": "friction.kolivand2009",
    **dict.fromkeys(("LineContactCondition", "solve_line_contact"),
                    "friction.ehl.line_contact"),
    **dict.fromkeys(("solve_stochastic_line_contact", "stochastic_summary"),
                    "friction.ehl.stochastic"),
    "GroundSurface": "friction.ehl.roughness",
}
__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
