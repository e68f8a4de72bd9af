"""The declared analysis chain (issue 63 item 1, contact/chain.py): ``contact.run_analysis``
and ``ltca run`` write the same file; steps are chosen by name, replaced by a callable or
skipped, and a skipped step leaves its group out and the verdict says so.

Every analysis here is the default case at one torque, 250 N·m, with the smallest
discretisation the options accept (4 rolls per cycle, 8 segments per curve: the same steps
at a tenth of the time). The root stress reads the default design's FE coefficients from
the session's cache (tests/conftest.py), built once by the suite.

The reference of "the same file" is the file itself: both paths run the same steps in one
process on the same inputs, so every variable must agree to round-off. The tolerance is
1e-12 relative (and 1e-12 absolute for values near 0): the arithmetic is the same, only a
different order of floating-point sums could move a value, by a few ulp of the largest
term.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from contact import AnalysisChain, LTCAOptions, available_steps, run_analysis, verdict
from contact.chain import OPTIONAL_STEPS, STEP_ORDER, ChainState, ltca_qp, resolve_chain
from contact.cli import main as ltca
from geometry.core.errors import InputError
from geometry.core.io import read_netcdf, write_netcdf

TORQUE = 250.0
SMALL = LTCAOptions(rolls_per_cycle=4, segments=8)
#: attributes that differ between two writes of the same analysis: the wall times and the
#: file's creation stamp
VOLATILE = ("time_", "date_", "history")
#: relative and absolute tolerance of one variable between the two files (module docstring)
RTOL = ATOL = 1e-12
#: the lean chain of a study's hot loop: the contact only
CONTACT_ONLY = dict(geometry=False, root_stress=False, mesh_interface=False, operating=False,
                    steps={"load_capacity": None})


def _stable(attrs) -> dict:
    """The attributes but the volatile ones, as comparable text (arrays as lists, NaN as
    'nan', which equals no NaN)."""
    return {k: repr(np.asarray(v).tolist()) for k, v in attrs.items()
            if not any(k.startswith(p) for p in VOLATILE)}


def _wall_time(var: xr.Variable) -> bool:
    """A variable that holds wall times [s] (``solve_time``, ``compliance_time``)."""
    return var.attrs.get("units") == "s" and str(var.attrs.get("long_name", "")).find(
        "time") >= 0


def assert_same_data(a: xr.Dataset, b: xr.Dataset, rtol: float = 0.0, atol: float = 0.0,
                     where: str = "") -> None:
    """The same variables, dims, attributes and values (to ``rtol``/``atol``) but the
    wall times."""
    assert sorted(a.variables) == sorted(b.variables), where
    assert _stable(a.attrs) == _stable(b.attrs), where
    for name, var in a.variables.items():
        other = b.variables[name]
        assert var.dims == other.dims, f"{where}/{name}"
        assert _stable(var.attrs) == _stable(other.attrs), f"{where}/{name}"
        if _wall_time(var):
            continue
        if np.issubdtype(var.dtype, np.number):
            np.testing.assert_allclose(var.values, other.values, rtol=rtol, atol=atol,
                                       err_msg=f"{where}/{name}")
        else:
            np.testing.assert_array_equal(var.values, other.values, err_msg=f"{where}/{name}")


@pytest.fixture(scope="module")
def both_files(tmp_path_factory):
    """The default case at 250 N·m written by the API (``run_analysis`` +
    ``write_netcdf``) and by the CLI (``ltca run``), with the same discretisation."""
    d = tmp_path_factory.mktemp("chain")
    tree = run_analysis(None, [TORQUE], options=SMALL)
    api = write_netcdf(tree, d / "api.nc", inputs=tree.attrs["inputs"])
    cli = d / "cli.nc"
    code = ltca(["run", "--no-progress", "--torque", f"{TORQUE:g}",
                             "--rolls-per-cycle", "4", "--segments", "8", "-o", str(cli)])
    assert code == 0
    return read_netcdf(api, tree=True), read_netcdf(cli, tree=True)


def test_api_and_cli_write_the_same_groups_and_variables(both_files):
    """The file of ``contact.run_analysis(...)`` and that of ``ltca run`` hold the same
    groups, rating and root stress among them, the same variables with the same dims and
    attributes, and the same values (module docstring: 1e-12)."""
    api, cli = both_files
    assert sorted(api.groups) == sorted(cli.groups)
    # what the CLI alone wrote before the chain (issue 63) is now the API's too
    assert {"/rating", "/rating/flash_temperature", "/friction", "/mesh_interface"} <= set(
        api.groups)
    assert {"root_stress", "root_stress_max"} <= set(api["ltca"].data_vars)
    assert _stable(api.attrs) == _stable(cli.attrs)
    for path in api.groups:
        assert_same_data(api[path].to_dataset(inherit=False),
                         cli[path].to_dataset(inherit=False), RTOL, ATOL, path)


def test_verdict_of_the_api_run_checks_the_rating(both_files):
    """``contact.verdict`` on the API's analysis makes the rating check (before the chain
    it silently had no ``/rating`` to read)."""
    api, _ = both_files
    v = verdict(api)
    assert "rating" in v.checks
    assert all(check != "rating" for check, _ in v.unchecked)


def test_the_steps_and_their_names():
    """Every step of :data:`STEP_ORDER` has its implementations by name, the first the
    default; ``AnalysisChain()``'s defaults are those names; a chain of the defaults given
    by name is the default chain."""
    steps = available_steps()
    assert tuple(steps) == STEP_ORDER
    chain = AnalysisChain()
    assert all(getattr(chain, s) == names[0] for s, names in steps.items())
    assert AnalysisChain(**{s: names[0] for s, names in steps.items()}) == chain
    assert resolve_chain({"root_stress": "fe"}) == chain
    assert resolve_chain(None, root_stress=False).root_stress is None
    # True turns a step the mapping skips back on, with its default implementation
    assert resolve_chain({"root_stress": None}, root_stress=True).root_stress == "fe"
    assert chain.describe()["load_capacity"] == "iso10300"


def test_unknown_step_names_list_the_available_ones():
    """An unknown implementation or step name, a value of the wrong type and skipping a
    step the analysis needs are refused in one sentence naming the step and what is
    accepted."""
    with pytest.raises(InputError, match=r"^steps\.load_capacity: unknown step 'agma9999'; "
                                         r"available: iso10300, scuffing_micropitting, "
                                         r"agma2003 \(or a "
                                         r"callable f\(state\), "
                                         r"or None to skip it\)$"):
        AnalysisChain(load_capacity="agma9999")
    with pytest.raises(InputError, match=r"^steps: unknown step 'friction'; the steps are "
                                         r"geometry, utca, ltca, root_stress, mesh_interface, "
                                         r"efficiency, load_capacity, lte_range$"):
        run_analysis(None, [TORQUE], options=SMALL, steps={"friction": None})
    with pytest.raises(InputError, match=r"^steps\.ltca: the analysis cannot skip it"):
        run_analysis(None, [TORQUE], options=SMALL, steps={"ltca": None})
    with pytest.raises(InputError, match=r"^steps\.utca: must be one of easeoff, ute, a callable"):
        AnalysisChain(utca=42)
    assert set(OPTIONAL_STEPS) == set(STEP_ORDER) - {"utca", "ltca"}


def test_a_step_by_name_and_a_step_replaced_by_a_callable():
    """The ``ltca`` step chosen by name gives the default's LTCA; a callable in place of the
    ``efficiency`` step runs after the LTCA and the root stress (it sees ``/ltca`` with
    ``root_stress_max``), before the load capacity, and its group is the file's
    ``/friction``; a callable wrapping the built-in ``ltca`` step gives the same LTCA bit
    for bit (the same function on the same state)."""
    seen: dict = {}

    def my_efficiency(state: ChainState) -> None:
        lt = state.groups["/ltca"]
        seen["root_stress"] = "root_stress_max" in lt
        seen["rating_before"] = "/rating" in state.groups
        # a constant-efficiency model of the user's: 98 % at every torque
        state.groups["/friction"] = xr.Dataset(
            {"efficiency_mean": ("torque", np.full(lt.sizes["torque"], 0.98),
                                 {"units": "1", "long_name": "mean mechanical efficiency"})},
            coords={"torque": lt["torque"]}, attrs={"friction_model": "user constant"})

    def my_ltca(state: ChainState) -> None:
        seen["ltca_calls"] = seen.get("ltca_calls", 0) + 1
        ltca_qp(state)

    base = dict(geometry=False, mesh_interface=False, steps=None)
    by_name = run_analysis(None, [TORQUE], options=SMALL, **{
        **base, "steps": {"ltca": "qp", "efficiency": my_efficiency,
                          "load_capacity": None}})
    assert seen == {"root_stress": True, "rating_before": False}
    fr = by_name["friction"].to_dataset()
    assert fr.attrs["friction_model"] == "user constant"
    np.testing.assert_array_equal(fr["efficiency_mean"].values, [0.98])
    assert "efficiency_not_run" not in by_name.attrs
    wrapped = run_analysis(None, [TORQUE], options=SMALL, **{
        **base, "steps": {"ltca": my_ltca, "efficiency": my_efficiency,
                          "load_capacity": None}})
    assert seen["ltca_calls"] == 1
    assert_same_data(wrapped["ltca"].to_dataset(), by_name["ltca"].to_dataset(), where="ltca")


def test_a_skipped_step_leaves_its_group_out_and_the_verdict_says_not_checked():
    """Without the efficiency and load-capacity steps there is no ``/friction`` and no
    ``/rating``; the root attributes say why, and the verdict lists the checks it could
    not make — the rating and the friction checks — instead of passing them."""
    tree = run_analysis(None, [TORQUE], options=SMALL, **CONTACT_ONLY)
    assert {"friction", "rating", "mesh_interface", "geometry"}.isdisjoint(tree.children)
    assert "root_stress_max" not in tree["ltca"]
    for step in ("geometry", "root_stress", "mesh_interface", "efficiency", "load_capacity"):
        assert tree.attrs[f"{step}_not_run"] == "not requested (steps)"
    v = verdict(tree)
    unchecked = dict(v.unchecked)
    assert {"rating", "friction_extrapolated", "scuffing", "micropitting"} <= set(unchecked)
    assert "no /rating group" in unchecked["rating"]
    assert "rating" not in v.checks
    assert any(line.startswith("  not checked: ") and "rating" in line for line in v.lines())


def test_a_case_that_cannot_be_rated_says_why():
    """The load-capacity step of a case whose ``[operating]`` speed is 0 (no efficiency
    step either) writes no ``/rating``; ``load_capacity_not_run`` holds the rating's own
    reason, which ``ltca run`` prints."""
    tree = run_analysis(None, [TORQUE], options=SMALL, geometry=False, root_stress=False,
                        mesh_interface=False, operating=False)
    assert "rating" not in tree.children
    assert "no pinion speed" in tree.attrs["load_capacity_not_run"]
    assert tree.attrs["efficiency_not_run"] == "not requested (steps)"
    # the verdict gives the rating's own reason
    assert dict(verdict(tree).unchecked)["rating"] == (
        "no /rating group: " + tree.attrs["load_capacity_not_run"])


def test_a_bad_rating_table_is_refused_before_the_ltca():
    """A ``[rating]`` table the rating refuses stops the analysis before any step runs (the
    ``ltca`` step, replaced by a callable that records its calls, is never called)."""
    import dataclasses

    from contact.catalogue import resolve_case

    case = resolve_case(None)
    bad = dataclasses.replace(case, extra={**case.extra, "rating": {
        **case.extra["rating"], "bogus_factor": 1.0}})
    calls = []
    with pytest.raises(InputError, match=r"^rating\.bogus_factor: unknown field"):
        run_analysis(bad, [TORQUE], options=SMALL, geometry=False, root_stress=False,
                     mesh_interface=False, steps={"ltca": lambda state: calls.append(state)})
    assert calls == []


def test_a_repeated_analysis_rates_the_nominal_geometry_once():
    """A method that rates the nominal geometry (ISO 10300) is rated once per case object
    as run, torques, speed and flank (issue 75): the analysis of the same case object
    repeated gets the same ``/rating``, value for value and attribute for attribute, as a
    fresh process's (the memo emptied), and each tree its own attributes (annotating one
    leaves the other and the kept rating alone); another torque is rated anew."""
    from contact.catalogue import resolve_case
    from geometry.core.caches import cache_sizes, clear_caches

    case = resolve_case(None)

    def run(torque=TORQUE):
        return run_analysis(case, [torque], options=SMALL, geometry=False,
                            root_stress=False, mesh_interface=False)

    clear_caches()
    fresh = run()["/rating"].to_dataset()
    key = "contact.chain._memo_nominal_rating"
    assert cache_sizes()[key] == 1
    first = run()
    first["/rating"].attrs["side"] = "changed"
    second = run()["/rating"].to_dataset()
    assert cache_sizes()[key] == 1
    assert second.identical(fresh) and second.attrs["side"] != "changed"
    other = run(1.2 * TORQUE)["/rating"].to_dataset()
    assert cache_sizes()[key] == 2
    assert not np.array_equal(other["pitting_safety"].values, fresh["pitting_safety"].values)
