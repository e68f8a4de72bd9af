"""``ltca export-step`` (issue 73, item 4): both members as closed B-rep solids in STEP.

Without the optional extra ``[step]`` (OpenCASCADE's bindings, ``cadquery-ocp-novtk``) the
command refuses in one sentence naming the extra (tested everywhere); the solids' tests
skip where the extra is missing (CI's core install).

The written file of the default case is read back (``STEPControl``/``STEPCAFControl``
readers, not the writer's objects) and checked against what the geometry generates:

* two parts, pinion and gear, each one valid closed solid (``BRepCheck_Analyzer``: a
  shell that is not closed is invalid) with a positive volume;
* its volume against :func:`contact.exchange.step.volume_estimate`, an independent
  quadrature (Pappus for the blank, Green's theorem over each section's slot polygon,
  Simpson along the face) of the same generated points: within 5e-4 relative — the
  polygon is straight between the points, ~1e-4 of the volume by its chord sagittas
  (measured: pinion 4e-5, gear 1.4e-4);
* every flank grid point ``ltca geometry`` writes (41 × 21, both flanks) within 1 µm of
  the part's faces (measured: 1e-10 mm: the faces interpolate them);
* between the grid points (the centres of the grid's cells, from the generated surface
  itself): within 1 µm in the middle of the flank (profile cells 4-15 of 20; measured
  ≤ 0.66 µm), not next to the generated surface's curvature jumps at the blade sections'
  junctions (edge radius → profile at the root, profile → toprem at the pinion's tip),
  where the cubic interpolant rings: measured on the default case, cell centres, at most
  9.9 µm (pinion concave, first cell at the toe), 8.6 µm (gear convex, first profile cell),
  4.6 µm (pinion concave, last cell at the tip); the issue's 1 µm is not met there
  (docs/exchange.md says so) and this test holds them to 12 µm;
* each part's placement is :func:`geometry.pair.assembly.case_transforms` at the case's
  misalignment;
* the file opens in a second reader, gmsh's: two volumes, their volumes by gmsh's
  (OCCT's default, coarser) integration within 5 % (skipped where gmsh is not installed).
"""

from __future__ import annotations

import numpy as np
import pytest

from contact.cli import main
from contact.exchange import step

CASE = "kolivand2009_fm_11x41_reference"


def test_refused_without_the_extra(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(step, "ocp_available", lambda: False)
    target = tmp_path / "pair.step"
    assert main(["export-step", CASE, "-o", str(target)]) == 2
    err = capsys.readouterr().err
    assert "hypoid-ltca[step]" in err
    assert not target.exists()


def test_refuses_a_wrong_suffix(tmp_path, capsys):
    assert main(["export-step", CASE, "-o", str(tmp_path / "pair.stl")]) == 2
    assert ".step or .stp" in capsys.readouterr().err


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    pytest.importorskip("OCP")
    from contact.catalogue import resolve_case

    case = resolve_case(CASE)
    path = tmp_path_factory.mktemp("step") / "pair.step"
    assert main(["export-step", CASE, "-o", str(path)]) == 0
    return case, path, step.read_step(path)


@pytest.mark.slow
def test_two_closed_valid_solids(written):
    from OCP.BRepCheck import BRepCheck_Analyzer

    _, _, parts = written
    assert set(parts) == {"pinion", "gear"}
    for part in parts.values():
        solids = step._solids(part.shape)
        assert len(solids) == 1
        assert BRepCheck_Analyzer(solids[0]).IsValid()
        assert step._volume(solids[0]) > 0.0


@pytest.mark.slow
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_volume_against_quadrature(written, member):
    case, _, parts = written
    volume = step._volume(parts[member].shape)
    expected = step.volume_estimate(case, member)
    assert volume == pytest.approx(expected, rel=5e-4)


@pytest.mark.slow
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_flank_grid_on_the_faces(written, member):
    from geometry.machine.flank import flank_surface

    case, _, parts = written
    for flank in ("concave", "convex"):
        grid = flank_surface(case, member, flank)  # ltca geometry's grid, 41 x 21
        assert grid.valid.all()
        dist = step.face_distance(parts[member].shape, grid.position)
        assert dist.max() <= 1e-3, (flank, dist.max())


@pytest.mark.slow
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_between_grid_points(written, member):
    from geometry.machine.flank import flank_surface

    case, _, parts = written
    for flank in ("concave", "convex"):
        # the centres of the grid's cells (every other one along the face), on the
        # generated surface itself: cell j of the profile is the fine grid's row 2j + 1
        fine = flank_surface(case, member, flank, nu=81, nv=41)
        centres = fine.position[1::4, 1::2]
        dist = step.face_distance(parts[member].shape, centres)
        # the middle of the flank, profile cells 4-15 of 20: within the 1 um
        assert dist[:, 4:16].max() <= 1e-3, (flank, dist[:, 4:16].max())
        # next to the blade sections' junctions (fillet, toprem) the cubic interpolant
        # rings: measured up to 9.9 um (module docstring); the 1 um is not met there
        assert dist.max() <= 12e-3, (flank, dist.max())


@pytest.mark.slow
def test_placements_at_the_misalignment(written):
    from geometry.pair.assembly import case_transforms

    case, _, parts = written
    for member, t in zip(("pinion", "gear"), case_transforms(case), strict=True):
        np.testing.assert_allclose(parts[member].placement, t, atol=1e-9)


@pytest.mark.slow
def test_opens_in_gmsh(written):
    gmsh = pytest.importorskip("gmsh")
    _, path, parts = written
    gmsh.initialize(["-noenv"], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        volumes = gmsh.model.occ.importShapes(str(path))
        gmsh.model.occ.synchronize()
        solids = [tag for dim, tag in volumes if dim == 3]
        assert len(solids) == 2
        measured = sorted(gmsh.model.occ.getMass(3, tag) for tag in solids)
    finally:
        gmsh.finalize()
    ours = sorted(step._volume(p.shape) for p in parts.values())
    # gmsh's getMass is OCCT's volume with its default Gauss rule, not the adaptive one
    # of contact.exchange.step._volume: on these B-spline faces it was 1 % off on the
    # pinion in OCCT itself; gmsh measured 5e-5 (pinion) and 3.3 % (gear) from ours
    np.testing.assert_allclose(measured, ours, rtol=5e-2)
