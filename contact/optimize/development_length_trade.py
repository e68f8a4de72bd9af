"""The light-load pattern's length on a low face contact ratio: what the LTE needs, and the
length a development gave up for it, said (issue 71: the spiral bevel 27x34 at β_m 30°
met every drive target but its pattern length, 0.65 against 0.5 ± 0.1).

A localised bearing carries the load over the part of the face its pattern covers, so the
face overlap it keeps is about the light-load pattern's length (fraction of the face width)
times the face contact ratio ε_vβ (ISO 10300-1:2014, Annex A). Measured (``benchmarks/
development_levers.py --check [--tolerance] --at``, ``ltca run``'s sampling and
``lte_range`` torques, 2026-11-27; docs/synthesis.md, "The pattern length on a low face
contact ratio"), the least light-load pattern length at which the LTE p-p keeps the
development's 40 µrad at the light and design torque and 60 µrad between them:

======================================  =======  ================  ==============
design                                   ε_vβ     least length       length × ε_vβ
======================================  =======  ================  ==============
hypoid 13x41 at β_m1 30°                  0.83     0.80 (40.5 µrad)    0.66
spiral bevel 11x41 (bundled, β_m 40.5°)   1.13     0.60                0.68
spiral bevel 27x34 at β_m 30°             1.17     0.60 (61 between)   0.70–0.76
                                                   – 0.65 (tolerant)
spiral bevel 27x34 at β_m 35°             1.42     ≤ 0.50              ≤ 0.71
spiral bevel 20x40 at β_m 25°             0.87     > 0.85 (43 / 49)    > 0.74
======================================  =======  ================  ==============

with the edges clear: a loaded edge shares the load too (the 20x40 with its profile
crowning 22 → 10 µm reaches 20 / 39 µrad at 0.58, the gear tip carrying 3.4 % of the
torque against the 2 % target),

so the LTE needs a pattern of about :data:`FACE_OVERLAP_LENGTH` / ε_vβ
(:func:`overlap_length`): within the target's 0.5 ± 0.1 down to ε_vβ ≈ 1.17, 0.56 at
AGMA 2005-D03's least ε_vβ 1.25. The target is **not** made to follow ε_vβ: a band moved
to 0.7 / ε_vβ leaves the 27x34 where it is (0.6 at ε_vβ 1.17: its measured 61 µrad between
the torques at 0.60 is the law's margin, not a longer need), asks 0.75–0.85 of the face
below ε_vβ 1, where the pattern is no sign-off lever (the 13x41 reaches 40 µrad only at
0.80, its centre v missed, 0.07 from the heel; the 20x40 at no length up to 0.85), and
would change the development of every normal-β design below ε_vβ 1.17 (four of
tests/data/designs and the bundled 11x41 at β_m 40.5°, ε_vβ 1.13, among them).
No other lever reaches 0.6 with the LTE kept on the 27x34 (42 variants: profile crowning,
path angle, TE level, mean point, blade angle, relief starts and depths; the nearest
0.60 long, 31 / 38 µrad, tolerant, 61 µrad between). What is left to the user is the face
contact ratio: :func:`length_trade_text` says the trade in ``ltca synthesize``'s
contact-ratio note, with the length the LTE needs now and at the ratio's remedy.

Below ε_vβ ≈ 0.76 the law's length no longer fits between the toe and heel clearance the
targets keep (1 − 2 × ``clearance``, 0.92 of the face by default; :func:`fits_the_face`),
and a longer pattern is no lever at all (measured 2026-11-27, branch contact82, the
written drive bearing's ellipse lengthened at ``ltca run``'s sampling; docs/synthesis.md,
"A longer pattern below a face contact ratio of 0.76"):

======================================  =======  ==========================================
design                                   ε_vβ     light-load length → LTE p-p light / design
======================================  =======  ==========================================
FM spiral bevel 21x21 (558.5 N m)         0.64     0.55: 90 / 90; 0.65: 80 / 95; 0.73: 69 /
                                                   110; 0.82: 41 / 118 (heel reached, plastic)
FH spiral bevel 16x20 at Σ 75° (422.4)    0.71     0.53: 55 / 84; 0.57: 49 / 83; 0.60: 46 / 84
======================================  =======  ==========================================

the light torque's LTE falls with the length, the design torque's stays or rises (the
teeth's deflection sets it there); the development developed to a target of 0.7 instead of
0.5 wrote 141 / 149 (21x21) and 116 / 126 µrad (16x20). :func:`no_length_text` says so in
``ltca synthesize``'s contact-ratio note; the target stays.

Public names
------------
FACE_OVERLAP_LENGTH, overlap_length, traded_length, length_trade_text, fits_the_face,
no_length_text
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from geometry.core.errors import InputError

__all__ = ["FACE_OVERLAP_LENGTH", "fits_the_face", "length_trade_text", "no_length_text",
           "overlap_length", "traded_length"]

#: the light-load pattern length × face contact ratio ε_vβ at which the LTE p-p kept the
#: development's 40 µrad at both torques and 60 µrad between them [1] (measured: 0.66 on
#: the hypoid 13x41 at β_m1 30°, 0.68 on the bundled 11x41, 0.70–0.76 on the spiral bevel
#: 27x34 at β_m 30°; module docstring)
FACE_OVERLAP_LENGTH = 0.7

#: the section of docs/synthesis.md that holds the measurement
_DOCS = "docs/synthesis.md, 'The pattern length on a low face contact ratio'"

#: the section of docs/synthesis.md that holds the measurement below ε_vβ 0.76
_DOCS_NO_LENGTH = "docs/synthesis.md, 'A longer pattern below a face contact ratio of 0.76'"


def overlap_length(eps_vb: float) -> float:
    """The light-load pattern length the LTE needs on a face contact ratio [1 of the face].

    Parameters
    ----------
    eps_vb : float — [1]
        Face contact ratio ε_vβ (ISO 10300-1:2014, Annex A), > 0.

    Returns
    -------
    float
        :data:`FACE_OVERLAP_LENGTH` / ε_vβ [1 of the face width]; above 1 where no pattern
        on the face is long enough.

    Raises
    ------
    InputError
        ``eps_vb`` not a finite number above 0.

    Notes
    -----
    Source: the measurement of the module docstring (three designs at ε_vβ 0.83–1.17,
    ``ltca run``'s sampling; docs/synthesis.md, "The pattern length on a low face contact
    ratio").
    """
    if isinstance(eps_vb, bool) or not isinstance(eps_vb, (int, float)) or not (
            math.isfinite(eps_vb) and eps_vb > 0.0):
        raise InputError(f"eps_vb: must be a finite number above 0 [1], got {eps_vb!r}")
    return FACE_OVERLAP_LENGTH / float(eps_vb)


def traded_length(metrics: Mapping[str, object], missed: Mapping[str, float],
                  pattern_length: float, tolerance: float) -> float | None:
    """The light-load pattern length of a design that misses its length alone, longer than
    the target's band, else None.

    Parameters
    ----------
    metrics : mapping
        The design's metrics (``pattern_toe_u``, ``pattern_heel_u`` [1], light torque
        first).
    missed : mapping of str to float
        Each target's shortfall [1] (:func:`~contact.optimize.development_targets.
        development_score`'s second item: > 0 where missed).
    pattern_length, tolerance : float — [1]
        The target ``pattern_length`` ± ``pattern_length_tolerance``.

    Returns
    -------
    float or None
        ``pattern_heel_u − pattern_toe_u`` at the light torque [1] where ``length`` is the
        only target missed and the pattern is longer than ``pattern_length + tolerance``;
        None otherwise (a short pattern, another target missed, or none).

    Raises
    ------
    Nothing.
    """
    if [k for k, v in missed.items() if v > 0.0] != ["length"]:
        return None
    length = float(metrics["pattern_heel_u"][0]) - float(metrics["pattern_toe_u"][0])
    return length if length > pattern_length + tolerance + 1e-9 else None


def length_trade_text(development, eps_vb: float, eps_target: float, *,
                      remedy: bool = False) -> str:
    """The sentence of ``ltca synthesize``'s contact-ratio note on a drive design that
    misses its pattern length alone, too long: the length, the length the LTE needs at the
    design's face contact ratio (:func:`overlap_length`) and at the ratio's remedy, and
    that the target stays.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
        Its ``best`` (``full``, ``metrics``) and ``targets`` (``pattern_length``,
        ``pattern_length_tolerance`` [1]).
    eps_vb : float — [1]
        The design's face contact ratio.
    eps_target : float — [1]
        The face contact ratio the note's remedy reaches
        (:data:`~contact.load_capacity.iso10300.face_contact.FACE_CONTACT_RATIO_MIN`).
    remedy : bool, optional
        Whether a contact-ratio change passed its check (the note offers it and ``ltca
        synthesize --apply-remedy`` develops it): the sentence then names the flag.
        Default False.

    Returns
    -------
    str
        E.g. "the drive pattern is 0.65 of the face width long, above the target 0.5 +/-
        0.1, its one target missed: the development gave the length up for the LTE, which
        at eps_vb 1.17 needs a light-load pattern of about 0.60 of the face (length x eps_vb
        about 0.7, ...); the target stays: at eps_vb 1.25 the LTE needs 0.56, within it"
        (and "; ltca synthesize --apply-remedy develops the checked change" with
        ``remedy``: on the 27x34 it developed β_m 31.7°, ε_vβ 1.25, every drive target met
        with the pattern 0.60 long);
        empty where the drive design meets its length, misses another target, or its
        ε_vβ is at or above ``eps_target``.

    Raises
    ------
    InputError
        ``eps_vb`` or ``eps_target`` not a finite number above 0.

    Notes
    -----
    Source: the measurement of the module docstring (the law and why the target does not
    follow ε_vβ); AGMA 2005-D03's least face contact ratio 1.25 (``eps_target``).
    """
    need, at_target = overlap_length(eps_vb), overlap_length(eps_target)
    best, t = development.best, development.targets
    if eps_vb >= eps_target or best.full is None or best.metrics is None:
        return ""
    length = traded_length(best.metrics, best.full[1], float(t.pattern_length),
                           float(t.pattern_length_tolerance))
    if length is None:
        return ""
    band = f"{t.pattern_length:g} +/- {t.pattern_length_tolerance:g}"
    return (f"the drive pattern is {length:.2f} of the face width long, above the target "
            f"{band}, its one target missed: the development gave the length up for the "
            f"LTE, which at eps_vb {eps_vb:.2f} needs a light-load pattern of about "
            f"{need:.2f} of the face (length x eps_vb about {FACE_OVERLAP_LENGTH:g}, "
            f"measured; {_DOCS}); the target stays: at eps_vb {eps_target:g} the LTE needs "
            f"{at_target:.2f}, within it"
            + ("; ltca synthesize --apply-remedy develops the checked change" if remedy
               else ""))


def fits_the_face(eps_vb: float, clearance: float) -> bool:
    """Whether the light-load pattern the LTE needs (:func:`overlap_length`) fits between
    the toe and heel clearance the development's targets keep.

    Parameters
    ----------
    eps_vb : float — [1]
        Face contact ratio ε_vβ (ISO 10300-1:2014, Annex A), > 0.
    clearance : float — [1]
        The targets' least distance of the pattern's ends from the toe and the heel
        (:class:`~contact.optimize.development_targets.DevelopmentTargets` ``clearance``,
        0.04 by default), in [0, 0.5).

    Returns
    -------
    bool
        ``overlap_length(eps_vb) <= 1 − 2 clearance`` (with the default clearance: ε_vβ ≥
        0.7 / 0.92 ≈ 0.76).

    Raises
    ------
    InputError
        ``eps_vb`` not a finite number above 0, or ``clearance`` not a finite number in
        [0, 0.5).

    Notes
    -----
    Source: the law of :func:`overlap_length` and the measurement of the module docstring
    (the 21x21 at ε_vβ 0.64 and the 16x20 at 0.71: no length lowers the design torque's
    LTE; the 13x41 at 0.83 and the 20x40 at 0.87 reach 40–60 µrad at 0.75–0.85 of the face).
    """
    if isinstance(clearance, bool) or not isinstance(clearance, (int, float)) or not (
            math.isfinite(clearance) and 0.0 <= clearance < 0.5):
        raise InputError(f"clearance: must be a finite number in [0, 0.5) [1 of the face "
                         f"width], got {clearance!r}")
    return overlap_length(eps_vb) <= 1.0 - 2.0 * float(clearance) + 1e-12


def no_length_text(development, eps_vb: float, lte_limit: float) -> str:
    """The sentence of ``ltca synthesize``'s contact-ratio note on a drive design above the
    verdict's LTE limit whose face contact ratio is too low for any light-load pattern the
    targets allow (:func:`fits_the_face`): a longer pattern is no lever there.

    Parameters
    ----------
    development : contact.optimize.development.DevelopmentResult
        Its ``best.metrics`` (``lte_peak_to_peak`` [µrad], light torque first) and
        ``targets`` (``clearance`` [1]).
    eps_vb : float — [1]
        The design's face contact ratio, > 0.
    lte_limit : float — [µrad]
        The verdict's LTE limit (:data:`contact.study.verdicts.LTE_LIMIT`, 60).

    Returns
    -------
    str
        E.g. "a longer light-load pattern is no lever here: at eps_vb 0.64 the LTE would
        need one about 1.09 of the face long (length x eps_vb about 0.7), more than the
        0.92 the toe and heel clearance leave; measured, a longer pattern lowers the light
        torque's LTE and leaves or raises the design torque's, which the teeth's deflection
        sets (...); the length target stays"; empty where the drive LTE is within
        ``lte_limit`` at both torques or the needed pattern fits.

    Raises
    ------
    InputError
        ``eps_vb`` not a finite number above 0 (:func:`overlap_length`).

    Notes
    -----
    Source: the measurement of the module docstring (branch contact82, 2026-11-27).
    """
    clearance = float(development.targets.clearance)
    if fits_the_face(eps_vb, clearance):
        return ""
    lte = development.best.metrics["lte_peak_to_peak"]
    if not max(float(lte[0]), float(lte[-1])) > lte_limit:
        return ""
    return (f"a longer light-load pattern is no lever here: at eps_vb {eps_vb:.2f} the LTE "
            f"would need one about {overlap_length(eps_vb):.2f} of the face long (length x "
            f"eps_vb about {FACE_OVERLAP_LENGTH:g}), more than the "
            f"{1.0 - 2.0 * clearance:.2f} the toe and heel clearance leave; measured, a "
            f"longer pattern lowers the light torque's LTE and leaves or raises the design "
            f"torque's, which the teeth's deflection sets ({_DOCS_NO_LENGTH}); the length "
            f"target stays")
