"""Contact analysis of hypoid and spiral bevel gears: UTCA, compliance, the loaded-contact QP, LTCA."""
