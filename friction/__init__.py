"""Mechanical power loss and efficiency: lubricant, film thickness, friction, losses (seed ch. 5)."""
