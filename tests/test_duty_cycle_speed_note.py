"""The illustrative duty cycle's speeds against the case's own (issue 71, round 29 of
docs/own_gear_set.md): an e-axle case at 12000 rpm ran the bundled spectrum's 3000 ... 600
rpm bins without a word."""
import numpy as np
import pytest

from contact.study.duty_cycle_inputs import (
    DutyCycle,
    example_duty_cycle,
    illustrative_speed_note,
)


def test_a_faster_case_is_told_both_speeds():
    duty = example_duty_cycle(max_torque=170.9)
    note = illustrative_speed_note(duty, 12000.0)
    # the bins' speeds are EXAMPLE_BINS' shares 1.0 ... 0.2 of the default 3000 rpm
    # (exact: products of short decimals, printed with :g)
    assert "3000 ... 600 rpm" in note
    assert "pinion_speed 12000 rpm" in note
    assert "--duty FILE" in note


@pytest.mark.parametrize("speed", [1500.0, 3000.0, 0.0])
def test_no_note_at_or_below_the_spectrum_or_without_a_speed(speed):
    # 3000 rpm is the spectrum's own top speed: nothing the bins miss
    assert illustrative_speed_note(example_duty_cycle(max_torque=100.0), speed) is None


def test_a_users_spectrum_gets_no_note():
    duty = example_duty_cycle(max_torque=100.0)
    mine = DutyCycle(torque=duty.torque, pinion_speed=duty.pinion_speed,
                     revolutions=duty.revolutions, deflection=duty.deflection,
                     grade=duty.grade, miner_rule=duty.miner_rule, name="measured")
    assert not mine.illustrative
    assert illustrative_speed_note(mine, 12000.0) is None
    assert np.isclose(float(np.max(mine.pinion_speed)), 3000.0)
