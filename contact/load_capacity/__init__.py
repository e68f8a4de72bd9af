"""Load capacity of the gear pair: rating methods, durability, scuffing and micropitting."""
