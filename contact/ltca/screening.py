"""Segment screening: which segments a roll's contact problem must take (seed §3.3).

A segment left out of a roll's problem whose gap C F + s − R Θ stays open (≥ 0) at the
solution changes nothing: the solution on the other segments is that of all of them.

Public functions
----------------
generous_limit   a separation limit that holds every loaded segment, before any rotation
"""

from __future__ import annotations

__all__ = ["generous_limit"]

#: segment screening (LTCAOptions.separation_limit None): a roll's problem takes the
#: segments with s < margin · R Θ̂ + pad, Θ̂ the loaded rotation expected there; after the
#: solve every segment left out must keep its gap open (else it is added and the roll
#: solved again, at most SCREEN_ROUNDS times). [1], [mm]
SCREEN_MARGIN = 1.1
SCREEN_PAD = 1e-3
SCREEN_ROUNDS = 6


def generous_limit(torque: float, ratio: float) -> float:
    """[mm] A separation limit growing with the gear torque (pinion ``torque`` [N·m]
    times ``ratio``) that holds every loaded segment of the seed's cases with room to
    spare: 0.05 mm + 0.15 mm per 1000 N·m of gear torque. It bounds the edge segments
    worked out and the first roll's pool before any rotation is known."""
    return 0.05 + 0.15 * torque * ratio / 1000.0
