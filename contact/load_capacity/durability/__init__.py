"""Durability of the flanks and the roots: S–N curves, Miner's rule, damage and life.

Modules
-------
sn_curve   S–N curves of ISO 6336-2/-3 from the material table, Miner's rule variants
damage     cumulative damage over a spectrum's bins, peak fillet stress, life
static_strength  the static contact strength every flank and edge pressure check reads
"""

from contact.load_capacity.durability.damage import (
    cumulative_damage,
    life_at_first_failure,
    member_cycles,
    peak_fillet_stress,
    pressure_envelopes,
)
from contact.load_capacity.durability.sn_curve import GRADES, MINER_RULES, SNCurve, sn_curves
from contact.load_capacity.durability.static_strength import (
    StaticContactStrength,
    static_contact_strength,
    weaker_static_strength,
)

__all__ = ["GRADES", "MINER_RULES", "SNCurve", "StaticContactStrength", "cumulative_damage",
           "life_at_first_failure", "member_cycles", "peak_fillet_stress", "pressure_envelopes",
           "sn_curves", "static_contact_strength", "weaker_static_strength"]
