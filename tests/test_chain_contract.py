"""Misuse of the chain's extension point refused in one sentence naming the step (issue 72
item 4, contact/chain_contract.py): a callable that cannot take the state is refused when
it is given, what a step leaves is checked after it runs, and a user step's exception is
wrapped with the step's name and chained.

Each misuse is run on the default case at one torque with the contact-only chain whose
ease-off and LTCA are stand-ins of the user's (empty groups, an ``/ltca`` with only its
torque): the refusals come from the contract, not from the numbers, and the tests take
milliseconds; one well-behaved user step wrapping the built-in LTCA is run for real.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from contact import AnalysisChain, LTCAOptions, run_analysis
from contact.chain import ChainState, ltca_qp
from geometry.core.errors import InputError, PluginError

TORQUE = 250.0
SMALL = LTCAOptions(rolls_per_cycle=4, segments=8)


def _utca(state):
    state.groups["/easeoff"] = xr.Dataset()
    state.groups["/utca"] = xr.Dataset()


def _ltca(state):
    state.groups["/ltca"] = xr.Dataset(coords={"torque": [TORQUE]})


def _run(**steps):
    chain = AnalysisChain.contact_only().with_steps(**{"utca": _utca, "ltca": _ltca, **steps})
    return run_analysis(None, [TORQUE], options=SMALL, steps=chain)


def _one_sentence(exc: BaseException) -> str:
    text = str(exc)
    assert "\n" not in text
    return text


@pytest.mark.parametrize("bad, said", [
    (lambda: None, r"the callable .*<lambda>\(\) cannot be called as f\(state\)"),
    (lambda state, extra: None,
     r"the callable .*<lambda>\(state, extra\) cannot be called as f\(state\)"),
    (ChainState, r"ChainState is a class"),
])
def test_a_callable_that_cannot_take_the_state_is_refused_when_given(bad, said):
    with pytest.raises(InputError, match=r"^steps\.efficiency: " + said) as info:
        AnalysisChain(efficiency=bad)
    _one_sentence(info.value)
    # through run_analysis's mapping too, before any work
    with pytest.raises(InputError, match=r"^steps\.efficiency: "):
        run_analysis(None, [TORQUE], options=SMALL, steps={"efficiency": bad})


def test_callables_with_defaults_or_varargs_are_accepted():
    AnalysisChain(efficiency=lambda state, extra=1: None)
    AnalysisChain(efficiency=lambda *args: None)


def test_a_step_that_never_makes_ltca_is_named():
    with pytest.raises(PluginError, match=r"^steps\.ltca: the callable .*nothing.* left no "
                                          r"/ltca group \(it should make it"):
        def nothing(state):
            pass
        _run(ltca=nothing)


def test_a_step_that_deletes_ltca_is_named_not_a_key_error():
    def drop(state):
        del state.groups["/ltca"]

    with pytest.raises(PluginError, match=r"^steps\.efficiency: the callable .*drop left no "
                                          r"/ltca group \(the ltca step made it"):
        _run(efficiency=drop)


def test_a_step_that_writes_a_list_as_a_group_is_named():
    def as_list(state):
        state.groups["/friction"] = [1.0, 2.0]

    with pytest.raises(PluginError, match=r"^steps\.efficiency: .*as_list wrote "
                                          r"state\.groups\['/friction'\] as list; a group "
                                          r"must be an xarray\.Dataset"):
        _run(efficiency=as_list)


def test_a_step_that_returns_its_dataset_is_refused():
    def returns(state):
        return xr.Dataset()

    with pytest.raises(PluginError, match=r"^steps\.efficiency: .*returns returned Dataset; "
                                          r"a step adds its groups to state\.groups"):
        _run(efficiency=returns)


def test_a_group_key_that_is_no_path_is_refused():
    def no_path(state):
        state.groups["friction"] = xr.Dataset()

    with pytest.raises(PluginError, match=r"state\.groups\['friction'\]: a group's key is "
                                          r"its path"):
        _run(efficiency=no_path)


def test_an_ltca_without_torque_is_refused():
    def flat(state):
        state.groups["/ltca"] = xr.Dataset({"x": ("roll", np.zeros(3))})

    with pytest.raises(PluginError, match=r"^steps\.ltca: .*flat left a /ltca group without "
                                          r"the dimension 'torque'"):
        _run(ltca=flat)


def _friction(efficiency_mean, dims=("torque",)):
    """A user's efficiency step writing ``/friction`` with this ``efficiency_mean``."""
    def mine(state):
        state.groups["/friction"] = xr.Dataset(
            {"efficiency_mean": (dims, np.asarray(efficiency_mean, float))},
            coords={"torque": [TORQUE]})
    return mine


@pytest.mark.parametrize("efficiency_mean, dims, said", [
    # issue 71 (plugin83): before, ``efficiency nan %`` in the summary and a verdict
    # without a word on it
    ([np.nan], ("torque",), r"efficiency_mean nan at 1 of 1 torque\(s\); "
                            r"accepted a finite 0 < efficiency_mean <= 1 \[1\] \(a fraction, "
                            r"not %\)$"),
    ([np.inf], ("torque",), r"efficiency_mean inf at 1 of 1"),
    # before: ``efficiency 9741.92 %``
    ([97.42], ("torque",), r"efficiency_mean 97\.42 at 1 of 1 torque\(s\); accepted"),
    ([0.0], ("torque",), r"efficiency_mean 0 at 1 of 1"),
    ([-0.2], ("torque",), r"efficiency_mean -0\.2 at 1 of 1"),
    # before: NumPy's "only 0-dimensional arrays can be converted to Python scalars" from
    # contact/pipeline.py; over roll without torque, the first roll's value
    ([[0.97, 0.98]], ("torque", "roll"),
     r"efficiency_mean over \('torque', 'roll'\) \(shape \(1, 2\)\); it must be over "
     r"\('torque',\) with the /ltca group's 1 torque\(s\)$"),
    ([0.97, 0.98], ("roll",), r"efficiency_mean over \('roll',\) \(shape \(2,\)\)"),
])
def test_an_efficiency_step_leaving_an_unprintable_efficiency_is_named(efficiency_mean, dims,
                                                                       said):
    with pytest.raises(PluginError, match=r"^steps\.efficiency: the callable .*mine left "
                                          r"/friction with " + said) \
            as info:
        _run(efficiency=_friction(efficiency_mean, dims))
    _one_sentence(info.value)


def test_an_efficiency_step_without_efficiency_mean_is_named():
    def other(state):
        state.groups["/friction"] = xr.Dataset({"power_loss_mean": ("torque", [300.0])})

    with pytest.raises(PluginError, match=r"^steps\.efficiency: the callable .*other left "
                                          r"/friction without efficiency_mean"):
        _run(efficiency=other)


def test_the_efficiency_bounds_take_a_fraction_of_one():
    """0 < η <= 1 inclusive of 1 (no loss): the check refuses what the report could not
    print as a fraction, nothing more."""
    from contact.chain_contract import check_efficiency

    for good in ([1.0], [0.5], [0.9742]):
        check_efficiency("steps.efficiency", xr.Dataset({"efficiency_mean": ("torque", good)}),
                         1)
    with pytest.raises(PluginError, match=r"over \('torque',\) \(shape \(1,\)\); it must "
                                          r"be over \('torque',\) with the /ltca group's 2"):
        check_efficiency("steps.efficiency",
                         xr.Dataset({"efficiency_mean": ("torque", [0.97])}), 2)


def test_a_nan_efficiency_is_accepted_only_where_the_loaded_contact_failed():
    """A failed analysis (a torque with an uncertified roll, ``found`` 0) has no forces and
    the built-in step writes NaN with its reason (tests/test_failed_analysis.py): the
    contract accepts NaN there and only there — at the certified torque it is refused."""
    from contact.chain_contract import check_efficiency, uncertified_torques

    ltca = xr.Dataset({"found": (("torque", "roll"), [[1, 1, 1], [1, 0, 1]])},
                      coords={"torque": [50.0, 250.0]})
    unc = uncertified_torques(ltca)
    assert unc.tolist() == [False, True]
    fr = xr.Dataset({"efficiency_mean": ("torque", [0.97, float("nan")])})
    check_efficiency("steps.efficiency", fr, 2, unc)
    with pytest.raises(PluginError, match=r"efficiency_mean nan at 1 of 2 torque"):
        check_efficiency("steps.efficiency",
                         xr.Dataset({"efficiency_mean": ("torque", [float("nan"), 0.97])}), 2,
                         unc)
    # a percentage is refused at the uncertified torque too: only NaN is the failed mark
    with pytest.raises(PluginError, match=r"efficiency_mean 97 at 1 of 2"):
        check_efficiency("steps.efficiency",
                         xr.Dataset({"efficiency_mean": ("torque", [0.97, 97.0])}), 2, unc)
    assert uncertified_torques(xr.Dataset(coords={"torque": [1.0]})).tolist() == [False]


def test_the_built_in_efficiency_passes_the_check():
    """The built-in step's /friction on the default case passes (97.42 % at 250 N·m, the
    value ``ltca run`` prints with these settings) and a user step wrapping it too."""
    from contact.chain import efficiency_local_friction

    def wrapped(state):
        efficiency_local_friction(state)

    chain = AnalysisChain.contact_only().with_steps(efficiency=wrapped)
    tree = run_analysis(None, [TORQUE], options=SMALL, steps=chain)
    # 97.42 % is what `ltca run --rolls-per-cycle 4 --segments 8 --torque 250` prints;
    # 0.005 % is its last printed digit
    assert float(tree["friction"]["efficiency_mean"][0]) == pytest.approx(0.9742, abs=5e-5)


# ------------------------------------------------- what the load-capacity step reads

#: a stand-in /ltca of 1 torque, 2 rolls, 1 pair, 3 segments: the last segment unloaded
_FORCE = np.array([[[[10.0, 20.0, np.nan]], [[15.0, 5.0, 0.0]]]])
_DIMS4 = ("torque", "roll", "pair", "segment")


def _ltca_force(state):
    state.groups["/ltca"] = xr.Dataset({"force": (_DIMS4, _FORCE)},
                                       coords={"torque": [TORQUE]})


def _full_friction(**change):
    """A user's efficiency step writing a /friction the load-capacity step can read (the
    built-in's variables: μ 0.05, speeds 1-2 m/s, film 0.2 um on the loaded segments, NaN
    on the unloaded ones as the built-in's), ``change`` replacing variables or attributes
    (``None`` drops one)."""
    loaded = np.isfinite(_FORCE) & (_FORCE > 0)

    def on(v):
        return np.where(loaded, v, np.nan)

    data = {"efficiency_mean": (("torque",), np.array([0.97])),
            "friction_coefficient": (_DIMS4, on(0.05)),
            "sliding_velocity": (_DIMS4, on(1.0)), "rolling_velocity": (_DIMS4, on(2.0)),
            "slide_to_roll_total": (_DIMS4, on(0.5)), "film_thickness": (_DIMS4, on(0.2)),
            "surface_speed": (("member", *_DIMS4), np.stack([on(1.5), on(2.5)]))}
    attrs = {"lubricant": "75W90", "inlet_temperature_degC": 90.0, "roughness_rq_um": 0.8}
    for k, v in change.items():
        target = attrs if k in attrs else data
        if v is None:
            target.pop(k)
        else:
            target[k] = v

    def mine(state):
        state.groups["/friction"] = xr.Dataset(data, coords={"torque": [TORQUE]},
                                               attrs=attrs)
    return mine


def _run_rated(efficiency, load_capacity="scuffing_micropitting"):
    """The stand-in chain with the load-capacity step after the user's efficiency step;
    ``load_capacity`` None: without it."""
    chain = AnalysisChain.contact_only().with_steps(
        utca=_utca, ltca=_ltca_force, efficiency=efficiency, load_capacity=load_capacity)
    return run_analysis(None, [TORQUE], options=SMALL, steps=chain)


def _bad(name, value):
    """``name`` of the full stand-in with ``value`` on the first loaded segment."""
    base = {"friction_coefficient": 0.05, "sliding_velocity": 1.0, "rolling_velocity": 2.0,
            "slide_to_roll_total": 0.5, "film_thickness": 0.2}[name]
    loaded = np.isfinite(_FORCE) & (_FORCE > 0)
    arr = np.where(loaded, base, np.nan)
    arr[0, 0, 0, 0] = value
    return (_DIMS4, arr)


@pytest.mark.parametrize("name, value, said", [
    # issue 71 (notchecked83): μ above the models' bound MU_MAX = 1 (friction/coefficient.py)
    ("friction_coefficient", 5.0, r"friction_coefficient 5 \[1\] at 1 of 4 loaded value\(s\); "
                                  r"the load-capacity step reads it: accepted a finite "
                                  r"0 <= friction_coefficient <= 1$"),
    ("friction_coefficient", -0.02, r"friction_coefficient -0\.02 \[1\] at 1 of 4"),
    ("friction_coefficient", np.nan, r"friction_coefficient nan \[1\] at 1 of 4"),
    ("sliding_velocity", -1.0, r"sliding_velocity -1 \[m/s\] at 1 of 4 loaded value\(s\); "
                               r"the load-capacity step reads it: accepted sliding_velocity "
                               r">= 0, finite \(a magnitude\)$"),
    ("rolling_velocity", np.inf, r"rolling_velocity inf \[m/s\] at 1 of 4"),
    ("film_thickness", np.nan, r"film_thickness nan \[um\] at 1 of 4"),
    ("slide_to_roll_total", -0.5, r"slide_to_roll_total -0\.5 \[1\] at 1 of 4 loaded "
                                  r"value\(s\); the load-capacity step reads it: accepted "
                                  r"slide_to_roll_total >= 0 \(a magnitude\)$"),
])
def test_a_friction_the_load_capacity_step_cannot_read_is_named(name, value, said):
    with pytest.raises(PluginError, match=r"^steps\.efficiency: the callable .*mine left "
                                          r"/friction with " + said) as info:
        _run_rated(_full_friction(**{name: _bad(name, value)}))
    _one_sentence(info.value)


def test_a_friction_without_what_the_load_capacity_step_reads_is_named():
    with pytest.raises(PluginError, match=r"mine left /friction without surface_speed \[m/s\] "
                                          r"\(the load-capacity step reads it"):
        _run_rated(_full_friction(surface_speed=None))
    with pytest.raises(PluginError, match=r"mine left /friction without the attribute "
                                          r"roughness_rq_um \(the load-capacity step"):
        _run_rated(_full_friction(roughness_rq_um=None))
    with pytest.raises(PluginError, match=r"roughness_rq_um 0; the load-capacity step reads "
                                          r"it: a finite temperature \[degC\] and a finite "
                                          r"Rq > 0 \[um\]$"):
        _run_rated(_full_friction(roughness_rq_um=0.0))


def test_a_friction_over_other_dims_than_the_load_capacity_step_reads_is_named():
    # μ per torque only (a user's mean): the step broadcasts it onto the segments wrongly
    with pytest.raises(PluginError, match=r"mine left /friction with friction_coefficient over "
                                          r"\('torque',\) \(shape \(1,\)\); the load-capacity "
                                          r"step reads it over \('torque', 'roll', 'pair', "
                                          r"'segment'\) of shape \(1, 2, 1, 3\), the /ltca "
                                          r"force's$"):
        _run_rated(_full_friction(friction_coefficient=(("torque",), np.array([0.05]))))
    # the speeds without their member dimension
    with pytest.raises(PluginError, match=r"surface_speed over \('torque', 'roll', 'pair', "
                                          r"'segment'\) \(shape \(1, 2, 1, 3\)\)"):
        _run_rated(_full_friction(surface_speed=(_DIMS4, np.ones_like(_FORCE))))


def test_the_load_capacity_inputs_are_checked_only_where_that_step_runs():
    """Without the load-capacity step nothing reads μ or the speeds: a /friction of
    efficiency_mean alone (plugin83's minimum) passes; the full stand-in passes both ways;
    μ = 1 (MU_MAX, inclusive) and unloaded segments' NaN pass, an infinite slide-to-roll
    (pure sliding) too."""
    from types import SimpleNamespace

    from contact.chain_contract import check_load_capacity_inputs, check_step_output

    state = SimpleNamespace(groups={})
    _utca(state)
    _ltca_force(state)
    mine = _friction([0.97])
    mine(state)
    check_step_output("efficiency", mine, state, None, ("utca", "ltca", "efficiency"))
    with pytest.raises(PluginError, match=r"mine left /friction without friction_coefficient"):
        check_step_output("efficiency", mine, state, None,
                          ("utca", "ltca", "efficiency", "load_capacity"))
    for change in ({}, {"friction_coefficient": _bad("friction_coefficient", 1.0)},
                   {"slide_to_roll_total": _bad("slide_to_roll_total", np.inf)}):
        state = SimpleNamespace(groups={})
        _ltca_force(state)
        _full_friction(**change)(state)
        check_load_capacity_inputs("steps.efficiency", state.groups["/friction"],
                                   state.groups["/ltca"])


def test_the_built_in_friction_passes_the_load_capacity_check():
    """The built-in efficiency step's /friction of the default case passes with the
    load-capacity step after it (its μ 0.034-0.095, speeds 0.14-4.1 m/s at 50 and
    250 N·m, measured with these settings): the check refuses no real analysis."""
    from contact.chain import efficiency_local_friction

    def wrapped(state):
        efficiency_local_friction(state)

    chain = AnalysisChain.contact_only().with_steps(efficiency=wrapped,
                                                     load_capacity="scuffing_micropitting")
    tree = run_analysis(None, [TORQUE], options=SMALL, steps=chain)
    assert "scuffing_micropitting" in tree.children


def test_a_user_step_that_raises_is_wrapped_with_its_name_and_cause():
    def broken(state):
        return 1 / 0

    with pytest.raises(PluginError, match=r"^steps\.efficiency: the callable .*broken raised "
                                          r"ZeroDivisionError: division by zero$") as info:
        _run(efficiency=broken)
    assert isinstance(info.value.__cause__, ZeroDivisionError)


def test_a_user_step_wrapping_a_built_in_one_still_works():
    """The checks pass a well-behaved user step through: the ``ltca`` step wrapped gives
    the built-in one's /ltca."""
    calls = []

    def mine(state):
        calls.append(1)
        ltca_qp(state)

    tree = run_analysis(None, [TORQUE], options=SMALL,
                        steps=AnalysisChain.contact_only().with_steps(ltca=mine))
    assert calls == [1] and "ltca" in tree.children


# --------------------------------------------------------------------------- named chains

def test_named_configurations():
    """``analysis()`` is the defaults (``ltca run``'s chain); ``contact_only()`` skips
    every optional step; the ``with_…`` methods turn one back on or off; an FEOptions
    turns the root stress on with that model."""
    from contact.chain import OPTIONAL_STEPS
    from contact.compliance.fe import FEOptions

    assert AnalysisChain.analysis() == AnalysisChain()
    lean = AnalysisChain.contact_only()
    assert all(getattr(lean, s) is None for s in OPTIONAL_STEPS)
    assert lean.with_root_stress().root_stress == "fe"
    assert lean.with_root_stress(False) == lean
    fe = FEOptions()
    assert lean.with_root_stress(fe).fe_options is fe
    assert lean.with_mesh_interface().mesh_interface == "linearised"
    assert AnalysisChain.analysis().without("efficiency", "geometry").describe()[
        "efficiency"] == "skipped"
    assert lean.with_load_capacity("scuffing_micropitting").load_capacity == (
        "scuffing_micropitting")
    with pytest.raises(InputError, match=r"^steps: unknown step 'friction'; the steps are"):
        lean.without("friction")
    with pytest.raises(InputError, match=r"^root_stress: must be True, False or a "
                                          r"contact\.compliance\.fe\.FEOptions, got str 'yes'"):
        lean.with_root_stress("yes")
    with pytest.raises(InputError, match=r"^fe_options: must be a contact\.compliance\.fe\."
                                          r"FEOptions or None, got int"):
        AnalysisChain(fe_options=3)


@pytest.mark.parametrize("switch, said", [
    ({"geometry": False}, r"run_analysis\(geometry=\.\.\.\) is deprecated: give the chain as "
                          r"steps=AnalysisChain\.analysis\(\)\.with_geometry"),
    ({"root_stress": False}, r"run_analysis\(root_stress=\.\.\.\) is deprecated"),
    ({"mesh_interface": False}, r"run_analysis\(mesh_interface=\.\.\.\) is deprecated"),
    ({"operating": False}, r"run_analysis\(operating=False\) is deprecated: give the chain "
                           r"as steps=AnalysisChain\.analysis\(\)\.without\('efficiency'\)"),
])
def test_the_on_off_keywords_are_deprecated(switch, said):
    """The booleans still work (the stand-in steps run) and warn, naming the named
    configuration that replaces them."""
    def stop(state):
        raise RuntimeError("stop here")

    with pytest.warns(DeprecationWarning, match=said), pytest.raises(PluginError,
                                                                     match="stop here"):
        run_analysis(None, [TORQUE], options=SMALL, **switch, steps=AnalysisChain.contact_only()
                     .with_steps(utca=_utca, ltca=stop))


@pytest.mark.parametrize("given, name", [(AnalysisChain, "AnalysisChain"),
                                         (AnalysisChain.contact_only,
                                          "AnalysisChain.contact_only")])
def test_a_chain_not_called_is_refused_naming_the_call(given, name):
    """``steps=AnalysisChain.contact_only`` (the parentheses forgotten) or the class."""
    with pytest.raises(InputError, match=rf"^steps: got {name} itself; call it: {name}\(\)"):
        run_analysis(None, [TORQUE], options=SMALL, steps=given)
