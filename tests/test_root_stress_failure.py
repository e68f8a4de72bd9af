"""Root stress never sinks an analysis (issue 60, item 3): where the FE model of the teeth
cannot be built (here: the mapping error a fillet of inverted elements raises), ``ltca
run`` writes everything else, says why the root stress is missing on the console and in
the file (root attribute ``root_stress_not_run``), and exits 0; a wrong input is still
refused."""

import pytest

import contact.ltca.root_stress as rs_module
from contact.cli import main
from geometry.core.errors import InputError, LTCAError
from geometry.core.io import read_netcdf

REASON = ("mesh mapping: element 1188 (parameter centre [45.5 0.5 3.5]) is inverted or "
          "collapsed; refine the mesh or check the geometry")
QUICK = ["--torque", "50", "--rolls-per-cycle", "4", "--segments", "10", "--speed", "0",
         "--no-progress"]


def _failing(exc):
    def root_stress(*args, **kwargs):
        raise exc
    return root_stress


def test_a_failed_fe_model_leaves_the_rest_written(monkeypatch, tmp_path, capsys):
    monkeypatch.setattr(rs_module, "root_stress", _failing(LTCAError(REASON)))
    out = tmp_path / "run.nc"
    assert main(["run", *QUICK, "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert f"root stress not computed: the FE model failed ({REASON})" in text
    tree = read_netcdf(out)
    assert "root_stress_max" not in tree["ltca"].variables
    assert "transmission_error" in tree["ltca"].variables  # the LTCA is written
    assert REASON in tree.attrs["root_stress_not_run"]


def test_a_wrong_input_is_still_refused(monkeypatch, tmp_path):
    monkeypatch.setattr(rs_module, "root_stress",
                        _failing(InputError("fe: load_nu must be >= 2, got 1")))
    from contact.pipeline import run_analysis

    with pytest.raises(InputError, match="load_nu"):
        run_analysis(None, [50.0], operating=False, mesh_interface=False,
                     steps={"load_capacity": None})
