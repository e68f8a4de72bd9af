"""Misusing an extension point gives an InputError naming the field and what is accepted,
never a deep traceback (issue 71, "API = CLI", branch api82).

The registries: solvers (``contact.register_backend``), compliance models
(``contact.register_compliance_model``), load-capacity rating methods
(``contact.register_rating_method``), friction models (``friction.register_friction_model``)
and the analysis chain's steps. For each: a wrong signature, a name that exists, an unknown
name asked for. An unknown name was a ``ModelUnavailableError`` (a LookupError) that a caller
catching ``InputError`` missed; it is now both (``UnknownNameError``). No analysis runs: every
case is refused before any work.
"""

from __future__ import annotations

import numpy as np
import pytest

import contact
import friction
from geometry.core.errors import InputError, ModelUnavailableError, UnknownNameError


def _problem() -> contact.ContactProblem:
    """Two unit springs, one unit moment arm each: a valid contact problem."""
    return contact.ContactProblem(compliance=np.eye(2), separation=np.zeros(2),
                                  moment_arm=np.ones(2), torque=1.0)


def _rate(case, torque, speed, *, flank=None, datasets=None, **options):
    """A rating method of the registry's protocol (never called here)."""
    raise AssertionError("not called")


@pytest.fixture
def cleanup():
    """Names registered by a test, removed after it whatever happened."""
    made: list[tuple] = []
    yield made
    for remove, name in made:
        try:
            remove(name)
        except InputError:
            pass


@pytest.mark.parametrize(("call", "message"), [
    # an unknown name, by each way a user names it
    (lambda: contact.solve_contact(_problem(), "no_such_solver"),
     r"^solver: 'no_such_solver' is not available; available: active_set"),
    (lambda: contact.LTCAOptions(solver="no_such_solver"),
     r"^solver: 'no_such_solver' is not available; available: active_set"),
    (lambda: contact.rate_load_capacity(None, [250.0], method="no_such_method"),
     r"^method: unknown load-capacity rating method 'no_such_method'; available: .*iso10300"),
    (lambda: contact.unregister_rating_method("no_such_method"),
     r"^method: unknown load-capacity rating method 'no_such_method'; available: "),
    (lambda: friction.friction_coefficient("no_such_model"),
     r"^unknown friction model 'no_such_model'; available: .*kolivand2009"),
    (lambda: friction.OperatingConditions(friction_model="no_such_model"),
     r"^friction_model: unknown friction model 'no_such_model'; available: "),
    (lambda: contact.LTCAOptions(compliance="no_such_model"),
     r"^compliance: unknown compliance model 'no_such_model'; available: .*shell"),
    (lambda: contact.AnalysisChain.analysis().with_steps(load_capacity="no_such_method"),
     r"^steps\.load_capacity: unknown step 'no_such_method'; available: iso10300"),
])
def test_an_unknown_name_is_an_input_error_listing_the_available(call, message):
    with pytest.raises(InputError, match=message) as info:
        call()
    # still a ModelUnavailableError where it was one (a LookupError), so old handlers hold
    if not str(info.value).startswith(("compliance:", "steps.")):
        assert isinstance(info.value, UnknownNameError)
        assert isinstance(info.value, ModelUnavailableError)
        assert isinstance(info.value, LookupError)


@pytest.mark.parametrize(("call", "message"), [
    # solver: not the problem first, not callable, a bare object where a solver goes
    (lambda: contact.register_backend("user_a", lambda: None),
     r"^solve: <lambda>\(\) must take 1 positional argument"),
    (lambda: contact.register_backend("user_b", lambda problem, extra: None),
     r"^solve: parameter\(s\) \['extra'\] of <lambda> have no default"),
    (lambda: contact.LTCAOptions(solver=42),
     r"^solver: must be a registered solver's name \(active_set, .*\), a Backend or a solve "
     r"function, got int 42"),
    # compliance model: prepare(case, easeoff, options, …)
    (lambda: contact.register_compliance_model("user_c", lambda case: None),
     r"^prepare: <lambda>\(case\) must take 3 positional argument"),
    # rating method: function(case, torque, speed, *, flank, datasets, **options)
    (lambda: contact.register_rating_method("user_d", lambda: None, title="t", source="s"),
     r"^function: <lambda>\(\) of method 'user_d' cannot be called as function\(case, "
     r"torque, speed, \*, flank=None, datasets=None, \*\*options\)"),
    (lambda: contact.register_rating_method("user_e", lambda case, torque, speed: None,
                                            title="t", source="s"),
     r"^function: .* cannot be called as .*unexpected keyword argument 'flank'"),
    (lambda: contact.register_rating_method("user_f", 42, title="t", source="s"),
     r"^function: must be callable, got 42"),
    # friction model: keyword inputs only
    (lambda: friction.register_friction_model("user_g", lambda *inputs: 0.05),
     r"^function: <lambda> takes \*inputs; its inputs are passed by keyword only"),
    # a step of the chain: f(state)
    (lambda: contact.AnalysisChain.analysis().with_steps(efficiency=lambda: None),
     r"^steps\.efficiency: the callable .* cannot be called as f\(state\)"),
])
def test_a_wrong_signature_is_refused_when_registered(call, message):
    with pytest.raises(InputError, match=message):
        call()


def test_a_name_that_exists_is_refused_naming_it(cleanup):
    """Bundled names are never replaced; a user's is replaced only with ``replace=True``."""
    with pytest.raises(InputError, match=r"^name: 'active_set' is the toolkit's reference"):
        contact.register_backend("active_set", lambda problem, **kw: None)
    with pytest.raises(InputError, match=r"^name: 'shell' is a bundled compliance model"):
        contact.register_compliance_model("shell", lambda case, easeoff, options: None)
    with pytest.raises(InputError, match=r"^name: the load-capacity rating method "
                                         r"'iso10300' is registered already"):
        contact.register_rating_method("iso10300", _rate, title="t", source="s")
    with pytest.raises(InputError, match=r"^name: 'kolivand2009' is a bundled friction model"):
        friction.register_friction_model("kolivand2009", lambda: 0.05)

    contact.register_backend("user_twice", lambda problem, **kw: None)
    cleanup.append((contact.unregister_backend, "user_twice"))
    with pytest.raises(InputError, match=r"^name: a solver 'user_twice' is registered "
                                         r"already; pass replace=True"):
        contact.register_backend("user_twice", lambda problem, **kw: None)
    contact.register_backend("user_twice", lambda problem, **kw: None, replace=True)

    contact.register_rating_method("user_rate", _rate, title="t", source="s")
    cleanup.append((contact.unregister_rating_method, "user_rate"))
    with pytest.raises(InputError, match=r"^name: .*'user_rate' is registered already"):
        contact.register_rating_method("user_rate", _rate, title="t", source="s")


@pytest.mark.parametrize(("call", "message"), [
    (lambda: contact.register_backend("two words", lambda problem, **kw: None),
     r"^name: must be a non-empty name without spaces, got 'two words'"),
    (lambda: contact.register_compliance_model(None, lambda case, easeoff, options: None),
     r"^name: must be a non-empty name without spaces, got None"),
    (lambda: contact.register_rating_method("Upper", _rate, title="t", source="s"),
     r"^name: a method name is lower-case letters, digits and underscores"),
    (lambda: friction.register_friction_model("", lambda: 0.05),
     r"^name: must be a non-empty name without spaces, got ''"),
    (lambda: contact.unregister_backend("never_registered"),
     r"^name: 'never_registered' was not registered with register_backend"),
    (lambda: contact.unregister_compliance_model("never_registered"),
     r"^name: 'never_registered' was not registered with register_compliance_model"),
    (lambda: friction.unregister_friction_model("never_registered"),
     r"^name: 'never_registered' was not registered with register_friction_model"),
])
def test_a_bad_name_is_refused_naming_the_field(call, message):
    with pytest.raises(InputError, match=message):
        call()


def _assembling(change):
    """A compliance model's preparation: the shell's assembler with ``change`` applied to
    what it returns (the list of ``(C, info)`` of the rolls asked for)."""
    from contact.ltca.compliance_models import shell_assembler

    def prepare(case, easeoff, options):
        inner = shell_assembler(case, easeoff, options)
        return lambda segments: change(inner(segments))
    return prepare


@pytest.mark.parametrize(("change", "message"), [
    (lambda out: [("abc", info) for _, info in out],
     r"gave C str 'abc'; it must be numbers \(\[mm/N\] for C and weber"),
    (lambda out: [(c, {**info, "weber": object()}) for c, info in out],
     r"gave weber object '<object object"),
    (lambda out: [(c, {**info, "time": "fast"}) for c, info in out],
     r"gave time str 'fast'; it must be numbers"),
    (lambda out: [(c, {**info, "asymmetry": np.ones(2)}) for c, info in out],
     r"gave info\['asymmetry'\] array\(\[1\., 1\.\]\); it must be one finite number >= 0"),
    (lambda out: list(out)[:-1],
     r"must return one \(C, info\) per roll position \(\d+\), got list of \d+"),
])
def test_a_compliance_model_returning_the_wrong_thing_is_refused_naming_it(change, message):
    """api83: a registered compliance model whose assembler returned a string for C (or
    for ``info["time"]``) failed with NumPy's ``ValueError: could not convert string to
    float`` inside the pool (contact/ltca/pool.py), naming neither the model nor the
    field; now an InputError (``ComplianceModelError``) names the model, the field and
    what it must be, before the contact problem is solved."""
    name = "user_wrong_return"
    contact.register_compliance_model(name, _assembling(change), replace=True)
    try:
        with pytest.raises(InputError, match=rf"^compliance: model '{name}' {message}"):
            contact.run_analysis(None, [250.0], steps=contact.AnalysisChain.contact_only(),
                                 options=contact.LTCAOptions(compliance=name,
                                                             rolls_per_cycle=4, segments=8))
    finally:
        contact.unregister_compliance_model(name)


@pytest.mark.parametrize(("call", "message"), [
    (lambda: contact.AnalysisChain.contact_only().with_root_stress("coarse"),
     r"^root_stress: must be True, False or a contact\.compliance\.fe\.FEOptions, got str "
     r"'coarse'; the named FE level is FEOptions\.at_level\('coarse'\) \(levels: coarse, "
     r"coarse10, default\)$"),
    (lambda: contact.StudyRun(root_stress="coarse10"),
     r"^root_stress: must be None, True, False or a .*; the named FE level is "
     r"FEOptions\.at_level\('coarse10'\)"),
    (lambda: contact.LTCAOptions(compliance="fe", fe="fine"),
     r"^fe: must be a contact\.compliance\.fe\.FEOptions or None, got a str; a named FE "
     r"level is given as FEOptions\.at_level\('NAME'\) \(levels: coarse, coarse10, default\)"),
    (lambda: contact.FEOptions.at_level("fine"),
     r"^level: must be one of \['coarse', 'coarse10', 'default'\], got 'fine'"),
])
def test_an_fe_level_given_by_its_name_where_fe_options_go_says_how(call, message):
    """api83: ``ltca``'s ``--fe-level coarse`` typed into the API (``with_root_stress(
    "coarse")``, ``StudyRun(root_stress=…)``, ``LTCAOptions(fe=…)``) was refused without
    saying how the API names a level; the refusal now says ``FEOptions.at_level(NAME)``
    and lists the levels."""
    with pytest.raises(InputError, match=message):
        call()
