"""The result contract of a load-capacity rating method (after xarray's ``BackendEntrypoint``).

Every method of the registry (:mod:`contact.load_capacity.methods`) returns, beside its own
variables, the common safeties its readers — the verdict, the report, ``ltca run``'s
rating lines — read, under names of no standard:

==========================  =====================  ==========================================
variable                    dims                   meaning
==========================  =====================  ==========================================
``pitting_safety``          (torque, member)       safety against pitting (ISO 10300: S_H)
``pitting_safety_min``      () or (member,)        its least permissible value (S_H,min)
``bending_safety``          (torque, member)       safety against tooth breakage (S_F)
``bending_safety_min``      () or (member,)        its least permissible value (S_F,min)
==========================  =====================  ==========================================

all finite and > 0, ``torque`` the rated pinion torques (as many as asked for),
``member`` the pinion and the gear. Optional, judged where present:

* ``contact_stress``, ``root_stress`` (torque, member) [MPa]: the standard's stresses the
  safeties are computed from (ISO 10300: σ_H, σ_F; AGMA 2003: s_c, s_t), printed beside
  the LTCA's peaks;
* ``permissible_cycles_pitting``, ``permissible_cycles_bending`` (torque, member) [1]:
  pinion load cycles at which the safety reaches its minimum (inf: long life, 0: beyond
  the static strength), with ``design_torque`` () [N·m], ``load_cycles`` (member) [1]
  (NaN: long life) and ``pinion_speed`` () [rpm]: a torque above the design torque with a
  finite life is an overload of finite life (attention), not a failure.

Each safety's attributes ``symbol`` (the standard's symbol, ``"S_H"``) and, for the
pitting and bending values, ``life_factor`` (``"Z_NT"``) say how the findings name it. The
registry (:func:`contact.load_capacity.methods.rate`) stamps the dataset's attributes
``rating_method``, ``rating_standard`` and ``rating_worked_example`` from the method's
entry, and refuses a result that breaks the contract (:func:`check_result`) in one sentence
naming the method and the variable.

Public functions
----------------
check_result      refuse a method's result that breaks the contract
contract_variables  the contract's variables from a method's own ones (a helper)
safeties          the contract's view of a ``/rating`` dataset, or why there is none
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import xarray as xr

from geometry.core.conventions import assigned
from geometry.core.errors import PluginError

__all__ = ["MODES", "OPTIONAL", "REQUIRED", "check_result", "contract_variables", "safeties"]

#: the failure modes every method rates: mode → (value, minimum)
MODES: Mapping[str, tuple[str, str]] = {
    "pitting": ("pitting_safety", "pitting_safety_min"),
    "bending": ("bending_safety", "bending_safety_min"),
}

#: the contract's required variables and their dims (a minimum: () or (member,))
REQUIRED: Mapping[str, tuple[tuple[str, ...], ...]] = {
    "pitting_safety": (("torque", "member"),),
    "pitting_safety_min": ((), ("member",)),
    "bending_safety": (("torque", "member"),),
    "bending_safety_min": ((), ("member",)),
}

#: the optional variables and their dims, checked where present
OPTIONAL: Mapping[str, tuple[tuple[str, ...], ...]] = {
    "contact_stress": (("torque", "member"),),
    "root_stress": (("torque", "member"),),
    "permissible_cycles_pitting": (("torque", "member"),),
    "permissible_cycles_bending": (("torque", "member"),),
    "design_torque": ((),),
    "load_cycles": (("member",),),
    "pinion_speed": ((),),
}

#: where the contract is written down, for the messages
WHERE = "docs/extending.md, 'A load-capacity rating method'"


def check_result(method: str, ds: object, torque: np.ndarray | None = None) -> xr.Dataset:
    """Refuse a rating method's result that breaks the contract (module docstring).

    Parameters
    ----------
    method : str
        The method's registry name (named in the message).
    ds : object
        What the method returned.
    torque : numpy.ndarray, shape (n,) — [N·m], optional
        The torques it was asked for: the result's ``torque`` dimension must have as many.

    Returns
    -------
    xarray.Dataset
        ``ds`` unchanged.

    Raises
    ------
    PluginError
        One sentence naming the method and what is wrong: not a Dataset, a required
        variable missing, a variable with other dims, a safety or minimum that is not
        finite and > 0, an optional variable with other dims or NaN (inf allowed in the
        permissible cycles), a ``member`` dimension other than 2 long, a ``torque``
        dimension of another length than asked for.
    """
    def refuse(what: str) -> PluginError:
        return PluginError(f"load-capacity method {method!r} breaks the result contract: "
                           f"{what} ({WHERE})")

    if not isinstance(ds, xr.Dataset):
        raise refuse(f"it returned {type(ds).__name__}, not an xarray.Dataset")
    for name in REQUIRED:
        if name not in ds.data_vars:
            raise refuse(f"the variable {name} is missing (the contract: "
                         f"{', '.join(REQUIRED)})")
    for table in (REQUIRED, OPTIONAL):
        for name, allowed in table.items():
            if name not in ds.data_vars:
                continue
            var = ds.variables[name]  # (the variable: a DataArray filters the coordinates)
            if "torque" in var.dims:
                var = var.transpose("torque", ...)
            if not any(set(var.dims) == set(d) and len(var.dims) == len(d) for d in allowed):
                want = " or ".join(f"({', '.join(d)})" for d in allowed)
                raise refuse(f"{name} has dims ({', '.join(var.dims)}), not {want}")
            values = np.asarray(var.values)
            if values.dtype.kind not in "fiu":
                raise refuse(f"{name} is not numeric ({values.dtype})")
            values = values.astype(float)
            if table is REQUIRED:
                ok = np.isfinite(values) & (values > 0)
                if "torque" in var.dims and "torque" in ds.coords:
                    # an infinite safety where nothing is transmitted (zero torque)
                    idle = np.asarray(ds.variables["torque"].values, float) == 0.0
                    ok |= np.isposinf(values) & idle.reshape((-1,) + (1,) * (values.ndim - 1))
                bad = ~ok
                if bad.any():
                    raise refuse(f"{name} holds {float(values[bad].ravel()[0])!r} (every "
                                 "value finite and > 0; inf only at zero torque)")
            elif name.startswith("permissible_cycles") and np.any(np.isnan(values) |
                                                                  (values < 0)):
                raise refuse(f"{name} holds NaN or a negative value (cycles ≥ 0, inf: "
                             "long life)")
            elif name in ("contact_stress", "root_stress") and not np.all(
                    np.isfinite(values)):
                raise refuse(f"{name} holds a value that is not finite")
    if ds.sizes.get("member") != 2:
        raise refuse(f"the member dimension has {ds.sizes.get('member')} entries, not 2 "
                     "(pinion, gear)")
    if torque is not None and ds.sizes.get("torque") != np.size(torque):
        raise refuse(f"the torque dimension has {ds.sizes.get('torque')} entries for the "
                     f"{np.size(torque)} torques asked for")
    return ds


def contract_variables(ds: xr.Dataset, *, pitting: tuple[str, str, str, str],
                       bending: tuple[str, str, str, str],
                       stresses: tuple[str, str] | None = None,
                       life: tuple[str, str] | None = None) -> xr.Dataset:
    """``ds`` with the contract's variables made from its own (a helper for a method).

    Parameters
    ----------
    ds : xarray.Dataset
        A method's dataset, ``torque`` and ``member`` dimensions.
    pitting, bending : (value, minimum, symbol, minimum's symbol)
        Names of ``ds``'s safety (torque, member) and minimum variables and the symbols the
        findings print (``("S_H", "S_Hmin", "S_H", "S_H,min")``).
    stresses : (contact, root), optional
        Names of ``ds``'s contact (torque, or torque and member) and root (torque,
        member) stresses [MPa].
    life : (pitting, bending), optional
        The symbols of the life factors (``("Z_NT", "Y_NT")``), the findings' words.

    Returns
    -------
    xarray.Dataset
        With ``pitting_safety``, ``pitting_safety_min``, ``bending_safety``,
        ``bending_safety_min`` (and ``contact_stress``, ``root_stress``), each with
        ``units``, ``long_name``, ``symbol`` and ``source`` (the variable it copies).
    """
    # the dataset's own variables (not DataArrays: assigning those merges every one's
    # coordinates with the dataset's, which cost 3/4 of this on a rating of ~100
    # variables; the dataset is the same)
    out: dict[str, xr.Variable] = {}

    def copied(name: str, dims: tuple[str, ...], **attrs: str) -> xr.Variable:
        x = ds.variables[name]
        if "member" in dims and "member" not in x.dims:
            x = x.set_dims({**dict(zip(x.dims, x.shape, strict=True)),
                            "member": ds.sizes["member"]})
        x = (x.transpose(*dims) if dims else x).copy()
        x.attrs.update(attrs)
        return x

    for mode, (value, least, symbol, least_symbol) in (("pitting", pitting),
                                                       ("bending", bending)):
        v, m = MODES[mode]
        out[v] = copied(value, ("torque", "member"), units="1",
                        long_name=f"safety against {mode} ({symbol})", symbol=symbol,
                        source=f"{value} (the method's own)")
        if life is not None:
            out[v].attrs["life_factor"] = life[0 if mode == "pitting" else 1]
        out[m] = copied(least, (), units="1",
                        long_name=f"least permissible safety against {mode} ({least_symbol})",
                        symbol=least_symbol, source=f"{least} (the method's own)")
    if stresses is not None:
        for key, name in zip(("contact_stress", "root_stress"), stresses, strict=True):
            out[key] = copied(name, ("torque", "member"), units="MPa",
                              long_name=f"the standard's {key.replace('_', ' ')} ({name})",
                              symbol=name, source=f"{name} (the method's own)")
    return assigned(ds, out)  # ds.assign(out), without its merge (issue 75)


def safeties(ds: xr.Dataset | None) -> tuple[xr.Dataset | None, str]:
    """The contract's view of a ``/rating`` dataset: (the dataset, ``""``) where it holds
    the contract, else (None, why) — a rating without it is not checked, never passed.

    Parameters
    ----------
    ds : xarray.Dataset or None
        A ``/rating`` dataset (a method's, or read back from a file).

    Returns
    -------
    (xarray.Dataset or None, str)
        A file written before the contract by ISO 10300 (``S_H``, ``S_F``, ``S_Hmin``,
        ``S_Fmin``) is read as the contract (the same quantities); otherwise the dataset
        itself, or None and one clause saying what it lacks.
    """
    if ds is None:
        return None, "no /rating group"
    if "pitting_safety" not in ds and ds.attrs.get("rating_method", "iso10300") == "iso10300" \
            and {"S_H", "S_F", "S_Hmin", "S_Fmin"} <= set(ds.data_vars):
        # a file of ISO 10300 written before the contract existed: the same quantities
        ds = contract_variables(ds, pitting=("S_H", "S_Hmin", "S_H", "S_Hmin"),
                                bending=("S_F", "S_Fmin", "S_F", "S_Fmin"),
                                life=("Z_NT", "Y_NT"), stresses=(("sigma_H", "sigma_F")
                                          if {"sigma_H", "sigma_F"} <= set(ds) else None))
        ds.attrs.setdefault("rating_standard", "ISO 10300")
    missing = [v for v in REQUIRED if v not in ds.data_vars]
    if missing:
        return None, (f"/rating of {ds.attrs.get('rating_method', 'an unnamed method')} "
                      f"lacks the result contract ({', '.join(missing)})")
    return ds, ""
