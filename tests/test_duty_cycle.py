"""Duty cycles (contact.study.duty_cycle, issue 36): inputs, one bin = one analysis, energy,
damage over the bins, resume, and ``ltca duty-cycle``.

Cheap enough for CI: the analyses use 8 rolls per cycle and 8 segments (about a second
each on the default case) with ``scheduler="synchronous"``, and at most two bins run per
test; the input and arithmetic tests run no analysis at all.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
import xarray as xr

from contact.catalogue import resolve_case
from contact.load_capacity.durability import sn_curves
from contact.ltca import LTCAOptions
from contact.study.duty_cycle import run_duty_cycle
from contact.study.duty_cycle_inputs import (
    DeflectionTable,
    DutyCycle,
    example_duty_cycle,
    read_duty_cycle,
)
from contact.study.run import StudyRun
from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment

OPTIONS = LTCAOptions(rolls_per_cycle=8, segments=8)
RUN = StudyRun(options=OPTIONS, scheduler="synchronous")


@pytest.fixture(scope="module")
def case():
    return resolve_case(None)


def _table(**kw):
    base = {"torque": [0.0, 200.0, 600.0], "delta_E": [0.0, 0.02, 0.05],
            "delta_P": [0.0, -0.01, -0.04], "delta_G": [0.0, 0.01, 0.03],
            "delta_Sigma": [0.0, 0.004, 0.012]}
    base.update(kw)
    return DeflectionTable(**base)


def test_deflection_reproduces_rows_and_is_monotone():
    """PCHIP passes through every row (1e-15) and is monotone between monotone rows."""
    t = _table()
    for i, tq in enumerate(t.torque):
        d = t.at(float(tq))
        assert d["delta_E"] == pytest.approx(t.delta_E[i], abs=1e-15)
        assert d["delta_Sigma"] == pytest.approx(t.delta_Sigma[i], abs=1e-15)
    fine = np.linspace(0, 600, 601)
    for name, sign in (("delta_E", 1), ("delta_P", -1), ("delta_G", 1), ("delta_Sigma", 1)):
        vals = np.array([t.at(float(x))[name] for x in fine])
        assert np.all(sign * np.diff(vals) >= -1e-15), name


def test_deflection_misalignment_adds_assembly_and_converts_degrees():
    t = _table()
    base = Misalignment(delta_E=0.01, delta_Sigma=0.001)
    m = t.misalignment(200.0, base)
    assert m.delta_E == pytest.approx(0.03, abs=1e-15)
    assert m.delta_Sigma == pytest.approx(0.001 + math.radians(0.004), abs=1e-15)


def test_outside_table_refused_naming_the_bin():
    with pytest.raises(InputError, match=r"duty_cycle bin 1.*700"):
        DutyCycle(torque=[100.0, 700.0], pinion_speed=[1000.0, 1000.0], revolutions=[1e5, 1e5],
                  deflection=_table())


@pytest.mark.parametrize(("kw", "field"), [
    ({"torque": [0.0, 200.0, 200.0]}, "deflection.torque"),
    ({"torque": [0.0, 600.0, 200.0]}, "deflection.torque"),
    ({"delta_E": [0.0, 0.1]}, "deflection.delta_E"),
])
def test_bad_deflection_rows_named(kw, field):
    with pytest.raises(InputError, match=field):
        _table(**kw)


def test_bad_bins_named():
    table = {"torque": [100.0, 200.0], "speed": [1000.0, 1000.0], "hours": [10.0, -1.0]}
    with pytest.raises(InputError, match=r"duty_cycle\.hours.*bin 1"):
        read_duty_cycle(table)
    with pytest.raises(InputError, match=r"duty_cycle\.hours"):
        read_duty_cycle({"torque": [1.0], "speed": [1.0]})
    with pytest.raises(InputError, match=r"duty_cycle\.speed"):
        read_duty_cycle({"torque": [1.0, 2.0], "speed": [1.0], "hours": [1.0, 1.0]})
    with pytest.raises(InputError, match="miner_rule"):
        read_duty_cycle({"torque": [1.0], "speed": [1.0], "hours": [1.0],
                         "miner_rule": "palmgren"})
    with pytest.raises(InputError, match="unknown key"):
        read_duty_cycle({"torque": [1.0], "speed": [1.0], "hours": [1.0], "tork": 1})


def test_unknown_grade_refused_before_any_bin(case):
    duty = DutyCycle(torque=[100.0], pinion_speed=[1000.0], revolutions=[1e5], grade="MX")
    with pytest.raises(InputError, match="grade"):
        run_duty_cycle(case, duty, RUN)


def test_hours_and_revolutions_agree():
    d = read_duty_cycle({"torque": [100.0, 200.0], "speed": [1200.0, 600.0],
                         "hours": [2.0, 3.0]})
    assert np.allclose(d.revolutions, [1200 * 60 * 2, 600 * 60 * 3], rtol=1e-15)
    assert np.allclose(d.hours, [2.0, 3.0], rtol=1e-15)


def test_example_is_labelled_and_linear():
    d = example_duty_cycle()
    assert d.illustrative and "illustrative" in d.name
    assert d.n_bins == 7 and d.torque[0] == pytest.approx(50.0) and d.torque[-1] == 500.0
    assert d.hours.sum() == pytest.approx(2000.0, rel=1e-12)
    # linear table: the half-torque deflection is half the full one
    assert d.deflection.at(250.0)["delta_E"] == pytest.approx(
        0.5 * d.deflection.at(500.0)["delta_E"], rel=1e-12)


@pytest.fixture(scope="module")
def one_bin(case):
    """A single bin at the case's own misalignment (no deflection table)."""
    duty = DutyCycle(torque=[250.0], pinion_speed=[1500.0], revolutions=[1e7])
    return duty, run_duty_cycle(case, duty, RUN, root_stress=False)


def test_single_bin_reproduces_run_analysis(case, one_bin):
    """One bin at the case's own misalignment is one run_analysis (1e-12 relative: the same
    arithmetic; the engine only moves it to a worker)."""
    from contact.ltca.summary import edge_load_share, flank_peak
    from contact.pipeline import operating_conditions, run_analysis
    from friction.efficiency import efficiency_analysis

    _, ds = one_bin
    tree = run_analysis(case, [250.0], options=OPTIONS, operating=False, geometry=False,
                        mesh_interface=False, root_stress=False)
    lt = tree["/ltca"].to_dataset()
    fr = efficiency_analysis(lt, operating_conditions(case, pinion_speed=1500.0))
    for name, ref in (("lte_mean", lt["lte_mean"].values[0]),
                      ("lte_peak_to_peak", lt["lte_peak_to_peak"].values[0]),
                      ("pressure_max_flank", lt["pressure_max_flank"].values[0]),
                      # the peak the static check judges: ltca run's verdict's
                      ("flank_peak_pressure", flank_peak(lt).pressure[0]),
                      ("flank_corner_curves", flank_peak(lt).corner_curves[0]),
                      ("edge_load_share", edge_load_share(lt)[0]),
                      ("plastic_load_share", np.max(lt["plastic_load_share"].values[0])),
                      ("efficiency", fr["efficiency_mean"].values[0]),
                      ("power_loss", fr["power_loss_mean"].values[0])):
        assert float(ds[name].values[0]) == pytest.approx(float(ref), rel=1e-12, abs=1e-12), name
    # the line contacts', the corner clips' and the edge envelopes apart; their largest is
    # the analysis's own envelope (the same nearest-node rule and maxima; 1e-12 relative, not
    # to the bit: the shell model's columns kept from an earlier analysis in this process
    # (contact.compliance.shell._half_vectors) join a triangular product of another batch,
    # which rounds differently); the line contacts' peak is the flank peak the static check
    # judges (contact.ltca.summary.flank_peak), the damage's
    every = np.maximum.reduce([ds[f"{k}pressure_envelope"].values[0]
                               for k in ("", "corner_", "edge_")])
    np.testing.assert_allclose(every, lt["pressure_envelope"].values[0], rtol=1e-12, atol=0.0)
    assert ds["pressure_envelope"].values.max() == pytest.approx(
        float(flank_peak(lt).pressure[0]), rel=1e-12)


def test_energy_balance_per_bin(one_bin):
    """Σ(power loss × time) = energy in − energy out per bin, with P_in = T ω computed here
    (1e-12: the efficiency is 1 − loss / P_in at every roll, so their means agree)."""
    duty, ds = one_bin
    seconds = duty.hours * 3600.0
    e_in = 250.0 * 1500.0 * 2 * math.pi / 60.0 * seconds / 3.6e6
    assert float(ds["energy_in"].values[0]) == pytest.approx(e_in[0], rel=1e-14)
    e_out = float(ds["efficiency"].values[0]) * e_in[0]
    assert float(ds["energy_lost"].values[0]) == pytest.approx(e_in[0] - e_out, rel=1e-9)
    assert float(ds["cycle_efficiency"]) == pytest.approx(
        1 - float(ds["energy_lost"].sum()) / float(ds["energy_in"].sum()), rel=1e-15)


def _rated(case, torque: float, speed: float, member: int):
    """The rating's influence factors of one bin, from ISO 10300 at its torque and speed:
    (Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp, Z_L Z_v Z_R, Y_δ Y_R Y_X, Y_R Y_X) of ``member``."""
    from contact.load_capacity.iso10300 import iso10300_rating

    r = iso10300_rating(case, [torque], speed).isel(torque=0, member=member)
    z = float(r["Z_L"] * r["Z_speed"] * r["Z_R"])
    y = float(r["Y_RrelT"] * r["Y_X"])
    return (z * float(r["Z_X"] * r["Z_W"] * r["Z_K"] * r["Z_Hyp"]), z,
            y * float(r["Y_deltarelT"]), y)


def test_damage_of_one_bin_by_hand(case, one_bin):
    """The flank damage is Σ n / N at the envelope's pressures on the rating's allowable of
    the bin (issue 62: σ_Hlim Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp = σ_HP/Z_NT at the knee, Z_L Z_v
    Z_R taken out at the static end 10⁵, ISO 6336-2; hand: Basquin by numpy with the
    exponent of that line), the life the hours over the largest, located at its node;
    bending unavailable, said."""
    duty, ds = one_bin
    c = sn_curves(case.pinion.material, "MQ")["contact"]
    factor, zlvr, _, _ = _rated(case, 250.0, 1500.0, 0)
    assert 0.95 < factor < 1.1 and factor != 1.0  # not the bare σ_Hlim
    allowable = c.allowable * factor
    m = math.log(c.knee_cycles / c.static_cycles) / math.log(c.static_life_factor / zlvr)
    p = ds["pressure_envelope"].values[0]
    n_pin = duty.revolutions[0]
    ratio = np.where(p > 0, allowable / np.where(p > 0, p, 1.0), np.inf)
    hand = np.where(p >= allowable, n_pin / (c.knee_cycles * ratio ** m),
                    n_pin / (c.knee_cycles * ratio ** (2 * m - 1)))
    assert float(ds["contact_safety_factor"].sel(member="pinion")) == pytest.approx(
        allowable / p.max(), rel=1e-12)
    assert "rating's allowables" in ds.attrs["allowables"]
    np.testing.assert_allclose(ds["flank_damage"].sel(member="pinion").values[0], hand,
                               rtol=1e-12, atol=0)
    np.testing.assert_allclose(ds["flank_damage"].sel(member="gear").values[0],
                               hand * case.pinion.blank.teeth / case.gear.blank.teeth,
                               rtol=1e-12, atol=0)
    assert float(ds["life"].sel(member="pinion")) == pytest.approx(
        float(duty.hours[0]) / hand.max(), rel=1e-12)
    iu, iv = np.unravel_index(np.argmax(hand), hand.shape)
    assert float(ds["life_u"][0]) == float(ds["u"][iu])
    assert float(ds["life_v"][0]) == float(ds["v"][iv])
    assert "root_life" not in ds and ds.attrs["bending"].startswith("unavailable")
    for name, var in ds.data_vars.items():
        if name != "reason":
            assert "units" in var.attrs and "long_name" in var.attrs, name


def test_resume_and_twice_the_duration(case, one_bin, tmp_path):
    """A run streamed to disk and started again reads its bins back (no analysis); a
    spectrum of twice the revolutions reuses them and has exactly twice the damage and the
    same life (1e-14: one product per point); another torque is refused (other analyses)."""
    duty, ds = one_bin
    out = tmp_path / "d.nc"
    run = dataclasses.replace(RUN, output=out)
    first = run_duty_cycle(case, duty, run, root_stress=False)
    assert first.attrs["bins_resumed"] == 0
    again = run_duty_cycle(case, duty, run, root_stress=False)
    assert again.attrs["bins_resumed"] == 1
    np.testing.assert_array_equal(again["flank_damage"].values, first["flank_damage"].values)
    twice = dataclasses.replace(duty, revolutions=2 * duty.revolutions)
    ds2 = run_duty_cycle(case, twice, run, root_stress=False)
    assert ds2.attrs["bins_resumed"] == 1  # the durations do not change the analyses
    np.testing.assert_allclose(ds2["flank_damage"].values, 2 * ds["flank_damage"].values,
                               rtol=1e-14, atol=0)
    np.testing.assert_allclose(ds2["life"].values, ds["life"].values, rtol=1e-14)
    with pytest.raises(InputError, match="different"):
        run_duty_cycle(case, dataclasses.replace(duty, torque=np.array([300.0])), run,
                       root_stress=False)


def test_bending_side_consumes_root_stress(case, one_bin):
    """With ``root_stress_peak`` in the bins (here built in the test, two bins: the same
    analysis at two durations) the root damage is Miner's sum by hand per fillet point,
    one cycle per tooth mesh, the life hours / max damage, and S_F = allowable / peak
    stress, the allowable the rating's σ_FE Y_δ,relT Y_R,relT Y_X of the bin (σ_FP/Y_NT)."""
    from contact.study.duty_cycle import DutyInputs, duty_cycle_result

    _, ds = one_bin
    keep = ["lte_mean", "lte_peak_to_peak", "pressure_max_flank", "pressure_max_edge",
            "edge_load_share", "efficiency", "power_loss", "lte_harmonics",
            "pressure_envelope", "edge_pressure_envelope", "status", "reason"]
    bins = xr.concat([ds[keep], ds[keep]], dim="bin")
    root = np.array([[[300.0, 650.0, 0.0], [200.0, 500.0, 900.0]],
                     [[310.0, 700.0, 0.0], [250.0, 400.0, 880.0]]])  # (bin, member, point)
    bins["root_stress_peak"] = xr.DataArray(root, dims=("bin", "member", "fillet_point"),
                                            attrs={"units": "MPa", "long_name": "peak"})
    duty = DutyCycle(torque=[250.0, 250.0], pinion_speed=[1500.0, 1500.0],
                     revolutions=[1e6, 3e6], miner_rule="elementary")
    out = duty_cycle_result(DutyInputs(case, duty, OPTIONS), bins)
    c = sn_curves(case.gear.material, "MQ")["bending"]
    _, _, factor, yrx = _rated(case, 250.0, 1500.0, 1)  # the gear's Y_δ Y_R Y_X, Y_R Y_X
    allowable = 850.0 * factor
    m = math.log(c.knee_cycles / c.static_cycles) / math.log(c.static_life_factor / yrx)
    ratio = case.pinion.blank.teeth / case.gear.blank.teeth
    hand = (1e6 * ratio / (c.knee_cycles * (allowable / 900.0) ** m)
            + 3e6 * ratio / (c.knee_cycles * (allowable / 880.0) ** m))
    got = out["root_damage"].sel(member="gear").sum("bin").values
    assert got[2] == pytest.approx(hand, rel=1e-12)
    assert got[0] > 0 and float(out["root_damage"].sel(member="pinion")[:, 2].sum()) == 0.0
    assert float(out["root_life"].sel(member="gear")) == pytest.approx(
        float(duty.hours.sum()) / got.max(), rel=1e-12)
    assert int(out["root_life_point"].sel(member="gear")) == 2
    assert float(out["bending_safety_factor"].sel(member="gear")) == pytest.approx(
        allowable / 900.0, rel=1e-12)  # the first bin is the peak-torque bin (argmax: first)
    assert out.attrs["bending"] == "available"


def test_a_failed_fe_model_leaves_the_bending_side_out_and_says_why(case, monkeypatch):
    """Issue 71: `ltca duty-cycle` of the 14x35 spiral bevel at Sigma 70 deg stopped with
    rc 2 on its pinion's inverted FE element, where `ltca run` of the same case ran on
    without root stress. The FE build failing (here made to, the way
    contact.compliance.fe.mapped_mesh fails) the duty cycle runs on: the flank side is
    there, the bending side is not, and the dataset's ``bending`` attribute and the
    verdict's bending finding quote the FE model's failure instead of suggesting
    --root-stress."""
    from contact.study.verdicts import verdict
    from geometry.core.errors import LTCAError

    why = "mesh mapping: element 6489 (parameter centre [56.5 9.5 11.5]) is inverted"

    def fails(*args, **kwargs):
        raise LTCAError(why)

    monkeypatch.setattr("contact.ltca.root_stress.prepare_coefficients", fails)
    duty = DutyCycle(torque=[250.0], pinion_speed=[1500.0], revolutions=[1e7])
    ds = run_duty_cycle(case, duty, RUN, root_stress=True)
    assert "damage" in ds and np.all(np.isfinite(ds["damage"].values))
    assert "root_life" not in ds
    assert ds.attrs["bending"].startswith("unavailable: root stress not computed: the FE "
                                          f"model failed ({why})")
    (bending,) = [f for f in verdict(ds).findings if f.check == "bending"]
    assert why in bending.reason and "--no-root-stress" not in bending.reason


def test_edge_note_counts_the_bins_the_verdict_counts():
    """The printed summary's edge sentence counts the bins at or above EDGE_SHARE_MIN, as
    the duty verdict's edge finding does, and says the trace shares apart (a hypoid 9x40 at
    Σ 70° of benchmarks/data/unseen_designs read "edge contact in 3 of 7 bins" above a
    verdict of "1 of 7 bins": two bins at < 0.05 % of the torque)."""
    import xarray as xr

    from contact.study.duty_cycle import edge_note

    ds = xr.Dataset({"edge_load_share": ("bin", [0.0, 0.0, 2e-4, 3e-4, 1e-3]),
                     "pressure_max_edge": ("bin", [0.0, 0.0, 405.0, 1938.0, 2395.0])})
    note = edge_note(ds)
    assert note.startswith("edge contact in 1 of 5 bins (2 more below 0.05 % of the "
                           "torque, no finding) (up to 0.10 % of the torque in bin 4, "
                           "edge peak pressure up to 2395 MPa)")
    ds["edge_load_share"][:] = [0.0, 0.0, 2e-4, 0.0, 0.0]
    assert edge_note(ds).startswith("edge contact below 0.05 % of the torque, no finding, "
                                    "in 1 of 5 bins (up to 0.02 %")
    ds["edge_load_share"][:] = 0.0
    assert edge_note(ds) is None


def test_edge_note_prints_a_trace_share_with_its_digits():
    """Round 34 (issue 71): the FM hypoid 5x48's duty cycle printed "up to 0.00 % of the
    torque in bin 2, edge peak pressure up to 1214 MPa" for an edge share of 2.2e-5 of
    the torque (0.0022 %): a share that rounds to 0.00 % at two decimals is printed with
    two significant digits (exact: the text of 100 x the share), and 0.1 % as before."""
    import xarray as xr

    from contact.study.duty_cycle import edge_note, share_percent

    ds = xr.Dataset({"edge_load_share": ("bin", [0.0, 0.0, 2.204e-5]),
                     "pressure_max_edge": ("bin", [0.0, 0.0, 1214.0])})
    note = edge_note(ds)
    assert "up to 0.0022 % of the torque in bin 2" in note, note
    assert "0.00 %" not in note
    assert share_percent(1e-3) == "0.10"   # two decimals from 0.005 % up, as before
    assert share_percent(5e-5) == "0.01"
    assert share_percent(4.9e-5) == "0.0049"
    assert share_percent(0.0) == "0.00"


def test_a_local_cluster_is_announced_before_the_first_bin():
    """Round 14: `ltca duty-cycle` printed nothing for 53 s between its spectrum line and
    its first bin while the local cluster started; it now says where the bins run, on how
    many processes, for a local cluster only (an address or 'synchronous': no line)."""
    from contact.commands.duty_cycle import where_line

    line = where_line(None, 2, 7)
    assert line.startswith("running the 7 bins on a local Dask cluster of 2 worker processes")
    assert "before the first bin" in line
    assert "1 worker process " in where_line(None, 1, 3)
    assert where_line("synchronous", None, 7) is None
    assert where_line("tcp://host:8786", 4, 7) is None
