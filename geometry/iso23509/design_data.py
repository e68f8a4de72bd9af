"""The basic design data of a bevel or hypoid pair, ISO 23509:2016 input data types I and II.

:class:`BevelGearDesign` holds what the standard's data sheet gives for a face-milled or
face-hobbed spiral bevel or hypoid pair — shaft angle, offset, numbers of teeth, the
gear's outer pitch diameter or mean pitch diameter (type I or II), face width, spiral
angle, design pressure angles of the drive and coast sides, cutter radius and blade
groups, depth factors, backlash — validated on construction: a field out of its range
raises :class:`~geometry.core.errors.InputError` naming it. :mod:`geometry.iso23509.pitch_cone`
(clause 5) and :mod:`geometry.iso23509.blank` (clause 6) compute from it.

Public names
------------
BevelGearDesign     the design data, validated
HANDS, BACKLASH_KINDS, INPUT_DATA_TYPES, DEPTH_FIELDS   the accepted choices
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import MISSING, dataclass, fields
from typing import Any

from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.validation import integer, one_of, real

__all__ = [
    "BACKLASH_KINDS",
    "DEPTH_FIELDS",
    "HANDS",
    "INPUT_DATA_TYPES",
    "BevelGearDesign",
]

_DEG = math.pi / 180.0


#: hand of spiral of the pinion (the gear has the opposite hand)
HANDS = ("left", "right")


#: how the backlash is specified: outer normal j_en, outer transverse j_et2, mean normal j_mn
BACKLASH_KINDS = ("j_en", "j_et2", "j_mn")


#: ISO 23509 input data types of the tooth depth and thickness (ISO 23509 cl. 6, Tables 3-4)
INPUT_DATA_TYPES = ("I", "II")


#: the depth and thickness fields of each input data type
DEPTH_FIELDS: Mapping[str, tuple[str, ...]] = {
    "I": ("x_hm1", "k_hap", "k_hfp", "x_smn"),
    "II": ("c_ham", "k_d", "k_c", "k_t"),
}


# --------------------------------------------------------------------------- input data
@dataclass(frozen=True, kw_only=True)
class BevelGearDesign:
    """Basic design data of a bevel/hypoid gear pair (ISO 23509 initial data).

    Angles are in radians and lengths in millimetres; :meth:`from_degrees` builds the
    object from angles in degrees (as in case files). Fields are keyword-only. Every field is
    validated on construction; a bad, missing or superfluous value raises
    :class:`~geometry.core.errors.InputError` naming the field and its accepted range.

    Parameters
    ----------
    method : int
        ISO 23509 pitch-cone method, a key of :data:`PITCH_CONE_METHODS`: 0 (spiral bevel,
        zero offset), 1 (hypoid, Gleason), 2 (hypoid, Oerlikon; face hobbing only) or
        3 (hypoid, Klingelnberg; face hobbing only).
    Sigma : float
        Shaft angle Σ [rad], 0 < Σ < π, with cos Σ > −z1/z2 for a spiral bevel (a = 0:
        gear pitch angle below 90°); a hypoid's bound is its pitch cone's, which closes only
        with δ2 below 90° (:func:`~geometry.iso23509.pitch_cone.pitch_cone` names ``Sigma``
        where it does not past that bound).
    a : float
        Hypoid offset a [mm], 0 ≤ a < d/2 (d = d_e2, or d_m2 for Method 2); must be 0 for
        Method 0. Only the offset that makes the pinion spiral angle larger than the gear's
        (the usual hypoid) is modelled.
    z1, z2 : int
        Numbers of teeth of pinion and gear [1], 5 ≤ z1 ≤ z2 ≤ 500.
    de2 : float
        Outer pitch diameter of the gear d_e2 [mm], > 0: required for Methods 0, 1 and 3,
        left out (``None``) for Method 2.
    dm2 : float
        Mean pitch diameter of the gear d_m2 [mm], > 0: required for Method 2, left out
        (``None``) otherwise.
    b2 : float
        Face width of the gear b_2 [mm], 0 < b2 < d/2 (checked against R_e2 later).
    beta_m : float
        Mean spiral angle [rad], 0 ≤ β ≤ 70°: the gear's β_m2 for Methods 0 (where
        β_m1 = β_m2), 2 and 3; the desired pinion β_m1 for Method 1.
    rc0 : float
        Nominal cutter radius r_c0 [mm], 0 < r_c0 ≤ 10 d: for face milling the radius of the
        tooth trace in the pitch plane, for face hobbing the distance from the cutter centre
        to the blade at the mean point.
    z0 : int
        Number of blade groups of the cutter z0 [1]: 0 (default) for face milling, ≥ 1 for
        face hobbing (required by Methods 2 and 3).
    alpha_dD, alpha_dC : float
        Design pressure angles of the drive and coast flanks α_dD, α_dC [rad], (0°, 45°).
    f_alim : float
        Influence factor of the limit pressure angle f_αlim [1], [0, 1].
    input_data_type : str
        How tooth depth and thickness are given, one of :data:`INPUT_DATA_TYPES`: ``"II"``
        (default; ``c_ham``, ``k_d``, ``k_c``, ``k_t``) or ``"I"`` (``x_hm1``, ``k_hap``,
        ``k_hfp``, ``x_smn``). The fields of the type chosen are required, the other type's
        must be left out (:data:`DEPTH_FIELDS`).
    c_ham : float
        Type II: mean addendum factor of the gear c_ham [1], [0, 0.5].
    k_d : float
        Type II: depth factor k_d [1], (0, 4]: mean working depth h_mw = k_d m_mn.
    k_c : float
        Type II: clearance factor k_c [1], [0, 0.5]: clearance c = k_c h_mw.
    k_t : float
        Type II: thickness factor k_t [1], [−0.5, 0.5].
    k_hap : float
        Type I: basic crown gear addendum factor k_hap [1], (0, 2]: h_mw = 2 k_hap m_mn
        (k_hap = k_d/2).
    x_hm1 : float
        Type I: profile shift coefficient of the pinion x_hm1 [1], [0, k_hap]:
        h_am1 = (k_hap + x_hm1) m_mn, h_am2 = (k_hap − x_hm1) m_mn (x_hm1 = k_d (0.5 − c_ham)).
    k_hfp : float
        Type I: basic crown gear dedendum factor k_hfp [1], [k_hap, 2 k_hap]: clearance
        c = (k_hfp − k_hap) m_mn (k_hfp = k_d (k_c + 0.5)).
    x_smn : float
        Type I: thickness modification coefficient x_smn [1], [−0.25, 0.25] (x_smn = k_t/2).
    backlash : str
        How the backlash is given, one of :data:`BACKLASH_KINDS`: ``"j_en"`` outer normal
        backlash (measured perpendicular to the flanks), ``"j_et2"`` outer transverse
        backlash of the gear (default: the kind ISO 23509's Annex F samples specify),
        ``"j_mn"`` mean normal backlash.
    backlash_value : float
        The backlash [mm], [0, 2].
    theta_a2, theta_f2 : float
        Addendum and dedendum angles of the gear θ_a2, θ_f2 [rad], [0°, 20°] (the pinion
        angles follow from the gear's); both 0 for uniform depth (ISO 23509 Annex C), the
        usual taper of face-hobbed teeth.
    hand : str
        Hand of spiral of the pinion, ``"left"`` or ``"right"`` (does not change the blank).
    delta2 : float
        Optional, Method 2 with an offset only: the gear pitch angle δ2 [rad], (0°, 90°), at
        which the pitch cone is taken instead of the exact closing condition (the pinion apex
        on the line from the gear apex through the cutter centre). The standard reaches that
        condition by an iteration that stops at a tolerance; its Annex F sample 3 (and
        ISO/TR 10300-30 sample 3, rated on it) stops 0.3 % short of it, at δ2 = 63.212°
        against 63.145° exact. Giving the published δ2 reproduces the published pitch cone
        (the offset and ratio conditions still hold exactly); leave it out for a design.

    Raises
    ------
    InputError
        A bad, missing or superfluous value (named, with its accepted range).

    Notes
    -----
    Source: ISO 23509:2016 cl. 5.1 (initial data) and cl. 6.1 (input data types I and II);
    field names are the standard's symbols. The ranges of the type I factors are those of
    the type II factors carried over by the standard's conversion (k_hap = k_d/2,
    x_hm1 = k_d (0.5 − c_ham), k_hfp = k_d (k_c + 0.5), x_smn = k_t/2), so that both types
    describe the same set of designs.
    """

    method: int
    Sigma: float
    a: float
    z1: int
    z2: int
    de2: float | None = None
    dm2: float | None = None
    b2: float
    beta_m: float
    rc0: float
    z0: int = 0
    alpha_dD: float
    alpha_dC: float
    f_alim: float
    input_data_type: str = "II"
    c_ham: float | None = None
    k_d: float | None = None
    k_c: float | None = None
    k_t: float | None = None
    x_hm1: float | None = None
    k_hap: float | None = None
    k_hfp: float | None = None
    x_smn: float | None = None
    backlash: str = "j_et2"
    backlash_value: float
    theta_a2: float
    theta_f2: float
    hand: str = "left"
    delta2: float | None = None

    def __post_init__(self) -> None:
        # the methods' registry lives with the methods (which import this module)
        from geometry.iso23509.pitch_cone import PITCH_CONE_METHODS

        set_ = object.__setattr__
        method = integer("method", self.method, 0, 9, allow_float=True)
        if method not in PITCH_CONE_METHODS:
            raise ModelUnavailableError(
                f"method = {method} is not available: implemented ISO 23509 pitch-cone methods "
                f"are {sorted(PITCH_CONE_METHODS)}"
            )
        set_(self, "method", method)
        z0 = integer("z0", self.z0, 0, None, allow_float=True)
        set_(self, "z0", z0)
        if z0 == 0 and method in (2, 3):
            raise ModelUnavailableError(self._face_milled_refusal(method))
        z1 = integer("z1", self.z1, 5, 500, allow_float=True)
        z2 = integer("z2", self.z2, z1, 500, allow_float=True)
        set_(self, "z1", z1)
        set_(self, "z2", z2)
        sigma = real("Sigma", self.Sigma, unit="deg", low=0.0, high=math.pi,
                     low_open=True, high_open=True, scale=_DEG)
        set_(self, "Sigma", sigma)
        given, absent = ("dm2", "de2") if method == 2 else ("de2", "dm2")
        if getattr(self, absent) is not None:
            raise InputError(
                f"{absent}: must be left out for method {method}, which takes {given} [mm], got "
                f"{getattr(self, absent)!r}"
            )
        d = _required(given, getattr(self, given), f"for method {method}")
        d = real(given, d, unit="mm", low=0.0, high=1e5, low_open=True)
        set_(self, given, d)
        set_(self, "b2", real("b2", self.b2, unit="mm", low=0.0, high=d / 2,
                              low_open=True, high_open=True))
        if isinstance(self.a, (int, float)) and not isinstance(self.a, bool) and self.a < 0:
            # ISO 23509's sign convention: a < 0 makes the pinion spiral angle the smaller
            # one (a left-hand pinion above centre), a pair the pitch cones do not model
            raise InputError(
                f"a: must be in [0, {d / 2:.4g}) [mm], got {self.a:g}: a negative offset (the "
                "pinion spiral angle smaller than the gear's, ISO 23509) is not modelled; the "
                "usual hypoid has a >= 0 (a left-hand pinion below centre, `hand` = "
                "\"left\"; its mirror image, a right-hand pinion above centre, `hand` = "
                "\"right\")"
            )
        a = real("a", self.a, unit="mm", low=0.0, high=d / 2, high_open=True)
        if method == 0 and a != 0.0:
            raise InputError(f"a: must be 0 for method 0 (use method 1, 2 or 3 for hypoid gears) "
                             f"[mm], got {a:g}")
        if a == 0.0 and math.cos(sigma) <= -z1 / z2:
            # the bound in the field's own unit: a user typing Σ reads the degrees, not the
            # cosine (issue 71, round 23: 9x41 typed at Σ 105° where 102.68° is the limit).
            # Exact for a spiral bevel only (tan δ2 = sin Σ / (z1/z2 + cos Σ)); a hypoid's
            # gear pitch angle is its pitch cone's, smaller (issue 71, round 39: the FH
            # 12x41 at a = 31.5 mm, refused at Σ 110° here, has δ2 80.2°): its bound is
            # said where its pitch cone does not close (pitch_cone.pitch_cone)
            raise InputError(
                f"Sigma: must be below {math.degrees(math.acos(-z1 / z2)):.2f} for "
                f"{z1}x{z2} (cos Σ > −z1/z2 = {-z1 / z2:.4f}: gear pitch angle below 90°; "
                f"internal bevel gears are not modelled) [deg], got {sigma / _DEG:g}"
            )
        set_(self, "a", a)
        set_(self, "beta_m", real("beta_m", self.beta_m, unit="deg", low=0.0,
                                  high=70 * _DEG, scale=_DEG))
        set_(self, "rc0", real("rc0", self.rc0, unit="mm", low=0.0, high=10 * d,
                               low_open=True))
        for name in ("alpha_dD", "alpha_dC"):
            set_(self, name, real(name, getattr(self, name), unit="deg", low=0.0,
                                  high=45 * _DEG, low_open=True, high_open=True, scale=_DEG))
        set_(self, "f_alim", real("f_alim", self.f_alim, unit="1", low=0.0, high=1.0))
        self._check_depth_data()
        one_of("backlash", self.backlash, BACKLASH_KINDS)
        set_(self, "backlash_value", real("backlash_value", self.backlash_value, unit="mm",
                                          low=0.0, high=2.0))
        for name in ("theta_a2", "theta_f2"):
            set_(self, name, real(name, getattr(self, name), unit="deg", low=0.0,
                                  high=20 * _DEG, scale=_DEG))
        one_of("hand", self.hand, HANDS)
        if self.delta2 is not None:
            if method != 2 or a == 0.0:
                raise InputError(
                    "delta2: may be given only for method 2 with an offset a > 0 (it fixes "
                    f"the hypoid pitch cone of that method) [deg], got "
                    f"{real('delta2', self.delta2, unit='deg') / _DEG:g}")
            set_(self, "delta2", real("delta2", self.delta2, unit="deg", low=0.0,
                                      high=0.5 * math.pi, low_open=True, high_open=True,
                                      scale=_DEG))

    def _face_milled_refusal(self, method: int) -> str:
        """Why Method 2 or 3 is refused for face milling, with the Method 1 inputs of the
        typed pitch cone in its face-milling limit where the other fields are valid and
        it has one (:func:`~geometry.iso23509.face_milled_inputs.method_1_inputs`; issue
        71, round 28)."""
        from dataclasses import replace

        from geometry.iso23509.face_milled_inputs import method_1_inputs

        text = (f"method = {method} is implemented for face hobbing only (z0 ≥ 1 blade "
                f"groups); for face milling (z0 = 0) use method 0 or 1")
        try:
            # the other fields validated as a face-hobbed twin's, then its cutter
            # taken to the face-milling limit z0 = 0 (validation does not read z0 further)
            twin = replace(self, z0=1)
        except InputError:
            return text
        object.__setattr__(twin, "z0", 0)
        inputs = method_1_inputs(twin)
        if inputs is not None:
            # a spiral bevel (a = 0) reads the same two inputs by method 0, its own method
            which = "method 0 (or 1)" if self.a == 0 else "method 1"
            text += (f": this pair by {which} is de2 = {inputs[0]:.1f} [mm] and beta_m = "
                     f"{inputs[1]:.2f} [deg] (the pinion's mean spiral angle), the outer "
                     f"pitch diameter and β_m1 of method {method}'s pitch cone face milled "
                     f"(z0 → 0)")
        return text

    def _check_depth_data(self) -> None:
        """Validate the tooth depth/thickness fields of the input data type chosen."""
        set_ = object.__setattr__
        kind = one_of("input_data_type", self.input_data_type, INPUT_DATA_TYPES)
        other = "I" if kind == "II" else "II"
        for name in DEPTH_FIELDS[other]:
            if getattr(self, name) is not None:
                raise InputError(
                    f"{name}: must be left out for input_data_type {kind!r} (give "
                    f"{', '.join(DEPTH_FIELDS[kind])}) [1], got {getattr(self, name)!r}"
                )
        where = f"for input_data_type {kind!r}"
        if kind == "II":
            set_(self, "c_ham", real("c_ham", _required("c_ham", self.c_ham, where), unit="1",
                                     low=0.0, high=0.5))
            set_(self, "k_d", real("k_d", _required("k_d", self.k_d, where), unit="1",
                                   low=0.0, high=4.0, low_open=True))
            set_(self, "k_c", real("k_c", _required("k_c", self.k_c, where), unit="1",
                                   low=0.0, high=0.5))
            set_(self, "k_t", real("k_t", _required("k_t", self.k_t, where), unit="1",
                                   low=-0.5, high=0.5))
            return
        k_hap = real("k_hap", _required("k_hap", self.k_hap, where), unit="1", low=0.0,
                     high=2.0, low_open=True)
        set_(self, "k_hap", k_hap)
        set_(self, "x_hm1", real("x_hm1", _required("x_hm1", self.x_hm1, where), unit="1",
                                 low=0.0, high=k_hap))
        set_(self, "k_hfp", real("k_hfp", _required("k_hfp", self.k_hfp, where), unit="1",
                                 low=k_hap, high=2.0 * k_hap))
        set_(self, "x_smn", real("x_smn", _required("x_smn", self.x_smn, where), unit="1",
                                 low=-0.25, high=0.25))

    @property
    def u(self) -> float:
        """Gear ratio u = z2/z1 [1] (ISO 23509 cl. 5)."""
        return self.z2 / self.z1

    @property
    def process(self) -> str:
        """``"face milling"`` (z0 = 0) or ``"face hobbing"`` (z0 ≥ 1)."""
        return "face hobbing" if self.z0 >= 1 else "face milling"

    def to_degrees(self) -> dict[str, Any]:
        """The fields given (``None`` left out), angles in degrees: the ``[design]`` table
        of a case or basic file; inverse of :meth:`from_degrees`.

        Returns
        -------
        dict
            Field → value, ``Sigma``, ``beta_m``, ``alpha_dD``, ``alpha_dC``, ``theta_a2``,
            ``theta_f2`` in [deg], the rest in the units of the class.
        """
        out: dict[str, Any] = {}
        for f in fields(self):
            value = getattr(self, f.name)
            if value is not None:
                out[f.name] = value / _DEG if f.name in _ANGLE_INPUTS else value
        return out

    @classmethod
    def from_degrees(cls, **values: Any) -> BevelGearDesign:
        """Build the design from the same fields with angles in degrees.

        Parameters
        ----------
        **values
            The fields of :class:`BevelGearDesign`; ``Sigma``, ``beta_m``, ``alpha_dD``,
            ``alpha_dC``, ``theta_a2``, ``theta_f2`` in [deg], the rest as documented there.

        Returns
        -------
        BevelGearDesign

        Raises
        ------
        InputError
            On an unknown or missing field or a value out of range.
        ModelUnavailableError
            For a method that is not implemented (or not for the process given by z0).
        """
        names = {f.name for f in fields(cls)}
        unknown = sorted(set(values) - names)
        if unknown:
            # "<field>: unknown field; accepted: …", the caller's "design." before it, as
            # every other table's unknown field reads (design.beta_mm, not "design.unknown
            # design field(s) ['beta_mm']")
            raise InputError(f"{', '.join(unknown)}: unknown field"
                             f"{'s' if len(unknown) > 1 else ''}; accepted: "
                             f"{', '.join(sorted(names))}")
        converted: dict[str, Any] = dict(values)
        for name in _ANGLE_INPUTS & set(values):
            converted[name] = real(name, values[name], unit="deg") * _DEG
        missing = [f.name for f in fields(cls) if f.name not in converted
                   and f.default is MISSING and f.default_factory is MISSING]
        if missing:
            raise InputError(f"{', '.join(missing)}: missing; ISO 23509 design data need "
                             + ", ".join(f"{n} ({_FIELD_MEANING.get(n, n)})" for n in missing))
        return cls(**converted)


#: what each field of the design is, for the message of a missing one
_FIELD_MEANING = {
    "method": "pitch-cone method 0-3", "Sigma": "shaft angle [deg]", "a": "hypoid offset [mm]",
    "z1": "number of pinion teeth", "z2": "number of gear teeth",
    "b2": "gear face width [mm]", "beta_m": "mean spiral angle [deg]",
    "rc0": "cutter radius [mm]", "alpha_dD": "design pressure angle, drive [deg]",
    "alpha_dC": "design pressure angle, coast [deg]",
    "f_alim": "influence factor of the limit pressure angle [1]",
    "backlash_value": "backlash [mm]", "theta_a2": "gear addendum angle [deg]",
    "theta_f2": "gear dedendum angle [deg]", "delta2": "gear pitch angle [deg]",
}


def _required(name: str, value: Any, where: str) -> Any:
    """``value`` unless it is None (a required field left out)."""
    if value is None:
        raise InputError(f"{name}: must be given {where}, got None")
    return value


_ANGLE_INPUTS = frozenset({"Sigma", "beta_m", "alpha_dD", "alpha_dC", "theta_a2", "theta_f2",
                           "delta2"})
