"""The development's clause on a basic design whose every trial stopped on its own
synthesis error (issue 71, round 23: the face-hobbed 19x57 by Method 3, rc0 100 mm, was
told to change the path angle and the ellipse length, which its six designs had varied)."""

from __future__ import annotations

from contact.optimize.development_basic_error import levers_tried_text
from geometry.core.errors import InputError

ERROR = InputError("synthesis: the pinion convex flank could not be given the required "
                   "curvature at the mean point (residual 0.000534 1/mm); change the path "
                   "angle, the TE level or the ellipse length")
SAID = f"InputError: {ERROR}"
#: the first designs of round 23's log (path angle [deg], ellipse length [1])
VALUES = [{"path_angle": -45.0, "ellipse_length": 0.4, "tip_relief": 14.9},
          {"path_angle": -58.8, "ellipse_length": 0.4, "tip_relief": 14.9},
          {"path_angle": -45.0, "ellipse_length": 0.55, "tip_relief": 14.9}]


def test_every_design_on_the_same_error_says_the_basic_data_changes_it():
    """Three designs, each on the error: the clause counts them and names the two variables
    that varied (tip_relief did not: not named), then the basic-data fields (exact text)."""
    assert levers_tried_text(ERROR, [SAID] * 3, VALUES) == (
        "; the development's 3 designs, varying ellipse_length, path_angle, each stopped on "
        "this same error: the basic data changes it (design.rc0, design.beta_m; design.z0 "
        "for face hobbing)")


def test_no_clause_where_a_design_ran_or_stopped_otherwise():
    """A design analysed ("" reason), another error, one design only, or nothing varied:
    the clause would not be true, so it is not said."""
    assert levers_tried_text(ERROR, [SAID, "", SAID], VALUES) == ""
    assert levers_tried_text(ERROR, [SAID, "InputError: relief: other", SAID], VALUES) == ""
    assert levers_tried_text(ERROR, [SAID], VALUES[:1]) == ""
    assert levers_tried_text(ERROR, [SAID] * 2, [VALUES[0], dict(VALUES[0])]) == ""


def test_a_tapered_depth_is_named_among_the_basic_data():
    """Round 36 (branch unseen98): the FM spiral bevel 14x19 at Σ 60° by Method 0 with
    θ_a2 1°, θ_f2 4° stopped on "the gear flank is not generated along the working depth at
    the mean cone distance" with every gear process; rc0 50.8 or 76.2 mm, the fields the
    clause named, stopped the same, θ_f2 0 synthesised (its log). With ``tapered`` the
    clause names the depth taper and its uniform-depth value (exact text); without, as
    before."""
    err = InputError("synthesis: the gear flank is not generated along the working depth "
                     "at the mean cone distance")
    said = f"InputError: {err}"
    assert levers_tried_text(err, [said] * 3, VALUES, tapered=True) == (
        "; the development's 3 designs, varying ellipse_length, path_angle, each stopped on "
        "this same error: the basic data changes it (design.rc0, design.beta_m, "
        "design.theta_a2 and design.theta_f2 (0 and 0: uniform depth); design.z0 for face "
        "hobbing)")
    assert "theta" not in levers_tried_text(err, [said] * 3, VALUES)
