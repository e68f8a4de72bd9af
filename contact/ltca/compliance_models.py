"""The tooth compliance models of the LTCA: one registry, the bundled models and the user's.

``LTCAOptions.compliance`` names the model that gives the structural compliance (the teeth's
bending and shear, the fillets and the rim or base) of the contact segments; the LTCA adds
Weber's contact term at the loads (:mod:`contact.ltca.weber`). Bundled:

* ``"shell"`` (the default, :data:`DEFAULT_COMPLIANCE`) — both members' tapered shells
  and Sainsot foundations (:func:`contact.compliance.mesh.mesh_compliance_many`); block
  diagonal by tooth pair;
* ``"fe"`` — both members' FE influence coefficients, the tooth mid-surface's displacement
  (bending, shear, fillets, rim down to the support) interpolated to the segments, the
  neighbouring teeth coupled as the FE model has them
  (:func:`contact.compliance.fe.contact_compliance.fe_mesh_compliance_many`; it replaces
  the shells *and* the foundations).

A model is a *preparation* ``prepare(case, easeoff, options)``, called once per analysis,
that returns the *batch assembler* of the analysis: a function of a list of
:class:`contact.compliance.mesh.ContactSegments` (the segments of several roll positions,
pair frame) returning, per roll, ``(C, info)`` — C (P, P) [mm/N] the total compliance of its
P segments *including* Weber's term, and ``info`` with at least ``"weber"`` (P, P) [mm/N]
that term, ``"weber_depth"`` (P, 2) [mm] the (pinion, gear) depths of the load below the
tooth centreline (Weber's), ``"time"`` [s] and ``"asymmetry"`` [1] (the largest relative
asymmetry ‖C − Cᵀ‖/‖C‖ before symmetrising, :data:`contact.errors.ASYMMETRY_LIMIT`). The
pool (:mod:`contact.ltca.pool`) checks what an assembler returns. A user's model
(:func:`register_compliance_model`, or the preparation itself as ``LTCAOptions.compliance``)
usually starts from :func:`shell_assembler`, which gives Weber's term and depths with the
shell's structural part (docs/extending.md).

Public functions
----------------
ComplianceModel              a registered model: name, preparation, description
ComplianceModelError         a model broke its contract
ENTRY_POINT_GROUP            the entry-point group of plug-ins' models
DEFAULT_COMPLIANCE           the default model's name, ``"shell"``
available_compliance_models  the names of every model (bundled, then the user's)
get_compliance_model         the model of a name, a ComplianceModel or a preparation
compliance_model_name        the name a model is recorded by
register_compliance_model    add a user's model under a name
unregister_compliance_model  remove it
shell_assembler, fe_assembler  the bundled models' preparations
"""

from __future__ import annotations

import functools
import logging
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from geometry.core.caches import memoised
from geometry.core.errors import InputError, ModelUnavailableError, PluginError
from geometry.core.registries import (
    callable_name,
    check_model_name,
    entry_point_objects,
    keyword_parameters,
)

if TYPE_CHECKING:
    from contact.compliance.mesh import ContactSegments
    from contact.ltca.options import LTCAOptions
    from contact.utca import EaseOff
    from geometry.case import Case

__all__ = [
    "DEFAULT_COMPLIANCE",
    "ENTRY_POINT_GROUP",
    "Assembler",
    "ComplianceModel",
    "ComplianceModelError",
    "available_compliance_models",
    "compliance_model_name",
    "fe_assembler",
    "get_compliance_model",
    "register_compliance_model",
    "shell_assembler",
    "unregister_compliance_model",
]

log = logging.getLogger(__name__)

#: a batch assembler: the segments of several rolls → one (C with Weber [mm/N], info) each
Assembler = Callable[[list["ContactSegments"]], list[tuple[np.ndarray, dict[str, Any]]]]

#: the default compliance model (the seed's)
DEFAULT_COMPLIANCE = "shell"


class ComplianceModelError(PluginError):
    """A compliance model raised, or returned what its contract (the module docstring) does
    not allow: the wrong number of matrices, shapes, missing ``info`` entries, values not
    finite, a diagonal entry <= 0. The message names the model."""


@dataclass(frozen=True)
class ComplianceModel:
    """A registered tooth compliance model.

    Attributes
    ----------
    name : str
        The registry name (``LTCAOptions.compliance``; recorded in the results' options).
    prepare : callable
        ``prepare(case, easeoff, options) -> assembler``: called once per analysis with
        the case (misalignment included), its :class:`contact.utca.EaseOff` (the working
        flanks; None where an analysis has none) and the :class:`LTCAOptions`; the
        assembler's contract is the module docstring's.
    description : str
        What the model is, for listings.

    Notes
    -----
    A model supplies the members' tooth compliance matrices C_p, C_g of seed Eq. (3.11)
    (each entry the deflection at segment i under a unit load at segment j) that seed
    Eq. (3.12) sums with the Hertzian compliance; the bundled ``"shell"`` model is the seed's
    §3.2.
    """

    name: str
    prepare: Callable[..., Assembler]
    description: str


def _shell_model(case: Case, options: LTCAOptions):
    from contact.compliance.mesh import pair_compliance_model

    material = (options.youngs_modulus, options.poisson_ratio)
    return pair_compliance_model(case, theory=options.theory, n_height=options.n_height,
                                 n_face=options.n_face, pinion_material=material,
                                 gear_material=material)


def shell_assembler(case: Case, easeoff: EaseOff | None, options: LTCAOptions) -> Assembler:
    """The ``"shell"`` model's preparation: both members' tapered shells and Sainsot
    foundations, plus Weber's term (the tooth models memoised per case).

    Parameters
    ----------
    case : geometry.case.Case
    easeoff : contact.utca.EaseOff or None
        Not used (the shells are the case's).
    options : LTCAOptions
        The shell settings ``theory``, ``n_height``, ``n_face`` and the material.

    Returns
    -------
    callable
        The batch assembler (module docstring): ``info`` holds ``"weber"``,
        ``"weber_depth"``, ``"time"``, ``"asymmetry"`` and the shell's own entries
        (:func:`contact.compliance.mesh.mesh_compliance_many`).

    Notes
    -----
    Seed Eq. 3.1–3.11 (the shell), Sainsot et al. (the fillet foundation), Weber (1949).
    """
    from contact.compliance.mesh import mesh_compliance_many

    return functools.partial(mesh_compliance_many, case, model=_shell_model(case, options))


def fe_assembler(case: Case, easeoff: EaseOff | None, options: LTCAOptions) -> Assembler:
    """The ``"fe"`` model's preparation: both members' influence coefficients of the
    analysed flanks (from the disk cache, built the first time), the shell tooth
    measurement for Weber's depths.

    Parameters
    ----------
    case : geometry.case.Case
    easeoff : contact.utca.EaseOff
        The analysis' ease-off: its working flanks choose the coefficients.
    options : LTCAOptions
        ``options.fe_options()`` is the FE model.

    Returns
    -------
    callable
        The batch assembler
        (:func:`contact.compliance.fe.contact_compliance.fe_mesh_compliance_many`).

    Raises
    ------
    InputError
        No ease-off.

    Notes
    -----
    docs/fe.md, "The FE-compliance LTCA".
    """
    from contact.compliance.fe.contact_compliance import fe_mesh_compliance_many, fe_pair_model

    if easeoff is None:
        raise InputError("easeoff: the FE compliance needs the analysis' ease-off (its "
                         "working flanks)")
    model = fe_pair_model(case, {"pinion": easeoff.pinion_flank, "gear": easeoff.gear_flank},
                          options.fe_options(), _shell_model(case, options))
    return functools.partial(fe_mesh_compliance_many, case, model=model)


#: the bundled models
_BUNDLED: Mapping[str, ComplianceModel] = MappingProxyType({
    "shell": ComplianceModel(
        "shell", shell_assembler,
        "tapered-shell Rayleigh–Ritz teeth (seed Eq. 3.1–3.11) on Sainsot's fillet "
        "foundation (contact.compliance.mesh)"),
    "fe": ComplianceModel(
        "fe", fe_assembler,
        "3-D FE models of the generated teeth, fillets and rim: the tooth mid-surface's "
        "displacement from the influence coefficients (contact.compliance.fe)"),
})

#: models registered in this process (not a cache: ``clear_caches`` keeps them)
_USER: dict[str, ComplianceModel] = {}

#: the entry-point group in which an installed distribution advertises compliance models:
#: each entry is a :class:`ComplianceModel` or a preparation function (registered under the
#: entry's name), so that ``ltca run --compliance NAME`` finds it
ENTRY_POINT_GROUP = "hypoid_ltca.compliance_models"


@memoised(maxsize=None)
def _plugins() -> dict[str, ComplianceModel]:
    """The models of the installed plug-ins (:data:`ENTRY_POINT_GROUP`)."""
    out = {}
    for name, obj in entry_point_objects(ENTRY_POINT_GROUP).items():
        if name in _BUNDLED:
            log.warning("entry point %s of group %s shadows a bundled compliance model: "
                        "left out", name, ENTRY_POINT_GROUP)
            continue
        try:
            if not isinstance(obj, ComplianceModel):
                _check_prepare("prepare", obj)
                obj = ComplianceModel(name, obj, f"plug-in model {name}")
            out[name] = obj
        except InputError as exc:
            log.warning("entry point %s of group %s is not a compliance model: %s", name,
                        ENTRY_POINT_GROUP, exc)
    return out


def available_compliance_models() -> tuple[str, ...]:
    """Names of every compliance model: the bundled ones, the plug-ins' and those
    registered in this process.

    Returns
    -------
    tuple of str
        The models' names: the bundled ones, then the plug-ins' and the registered ones.
    """
    return tuple(dict.fromkeys([*_BUNDLED, *_plugins(), *_USER]))


def _check_prepare(field: str, prepare: Any) -> None:
    required, _, _ = keyword_parameters(field, prepare, positional=3)
    if required:
        raise InputError(f"{field}: parameter(s) {list(required)} of "
                         f"{callable_name(prepare)} have no default; a compliance model is "
                         "called as prepare(case, easeoff, options)")


def get_compliance_model(model: str | ComplianceModel | Callable[..., Any]) -> ComplianceModel:
    """The compliance model of a registered name, a :class:`ComplianceModel`, or a
    preparation function (module docstring) used as it is.

    Parameters
    ----------
    model : str, ComplianceModel or callable

    Returns
    -------
    ComplianceModel
        A function is wrapped under its own name (:func:`compliance_model_name`).

    Raises
    ------
    ModelUnavailableError
        An unknown name (the message lists the available ones).
    InputError
        A function that cannot be called as ``prepare(case, easeoff, options)``.
    """
    if isinstance(model, ComplianceModel):
        return model
    if isinstance(model, str):
        found = _BUNDLED.get(model) or _USER.get(model) or _plugins().get(model)
        if found is None:
            raise ModelUnavailableError(
                f"unknown compliance model {model!r}; available: "
                f"{list(available_compliance_models())} (register one with "
                "contact.ltca.compliance_models.register_compliance_model)")
        return found
    _check_prepare("compliance", model)
    return ComplianceModel(callable_name(model), model, f"user model {callable_name(model)}")


def compliance_model_name(model: str | ComplianceModel | Callable[..., Any]) -> str:
    """The name a model is recorded by: the name, the model's name, or the function's."""
    if isinstance(model, str):
        return model
    if isinstance(model, ComplianceModel):
        return model.name
    return callable_name(model)


def register_compliance_model(name: str, prepare: Callable[..., Any], *, description: str = "",
                              replace: bool = False) -> ComplianceModel:
    """Register a user's tooth compliance model under ``name`` for this process.

    After it, ``LTCAOptions(compliance=name)`` runs the LTCA with it (and ``run_analysis``
    and the studies in this process; a Dask cluster's worker processes import the module
    that registers it, or take the preparation itself as ``compliance``).

    Parameters
    ----------
    name : str
        The registry name (no spaces; a bundled name cannot be taken).
    prepare : callable
        ``prepare(case, easeoff, options) -> assembler`` (module docstring).
    description : str
    replace : bool
        Allow replacing a model registered earlier under ``name`` (default False).

    Returns
    -------
    ComplianceModel
        The registered model (name, preparation, description).

    Raises
    ------
    InputError
        A bad name or function, a bundled name, or a name taken without ``replace``.
    """
    check_model_name("name", name)
    if name in _BUNDLED:
        raise InputError(f"name: {name!r} is a bundled compliance model; register under "
                         "another name")
    if (name in _USER or name in _plugins()) and not replace:
        raise InputError(f"name: a compliance model {name!r} is registered already; pass "
                         "replace=True to replace it or choose another name")
    _check_prepare("prepare", prepare)
    model = ComplianceModel(name, prepare, description or f"user model {name}")
    _USER[name] = model
    return model


def unregister_compliance_model(name: str) -> None:
    """Remove a model registered with :func:`register_compliance_model`.

    Parameters
    ----------
    name : str
        The name it was registered under.

    Raises
    ------
    InputError
        ``name`` was not registered with :func:`register_compliance_model`.
    """
    if name not in _USER:
        raise InputError(f"name: {name!r} was not registered with register_compliance_model "
                         f"(registered: {sorted(_USER)})")
    del _USER[name]
