"""Independent check of the ease-off's pinion mates: are the envelope roots right?

Issue 71 (branch s70_102, docs/synthesis.md "The criterion and the generation-limit
diagnosis re-calibrated on the ease-off's batch-seed fix"). For one case and flank:

1. at the solved parameters (s, θ, q) of every valid ease-off node, the equation of
   meshing f = n·r_q / L and the place (z, ρ) recomputed from the cutter family alone
   (:func:`geometry.machine.meshing.envelope_family`), and the sign of ∂f/∂q by central
   differences against the flank's regular sign (the pinion flank grid's middle point,
   :func:`geometry.machine.flank.flank_surface`);
2. for a sample of nodes, every root at the node's place: a 25 × 61 × 61 scan of
   (s, θ, q) on every blade section (θ, q over ±0.6 rad about the mate's), least squares
   from the 30 best cells; the roots with the regular sign, their distance from the mate
   and their offset along the mate's outward normal (> 0: outside the mate's point, which
   is then the deeper cut, the material boundary; < 0: the other sheet cuts deeper);
3. the mates' cradle angles against the flank grid's range (``off_sheet_mates``).

Usage::

    python benchmarks/easeoff_root_check.py tests/data/spiral_bevel_16x16_s60_nonconjugate_case.toml
    python benchmarks/easeoff_root_check.py --counts 25 --nodes 8   # the 15x15's 25x25

Measured (2026-11-29, branch s70_102): the 16×16 at Σ 60° and the 15×15's
``--no-development`` case: every mate |f| < 1e-12, place to 1e-7 µm, the regular sign, the
solver's root the innermost regular root at every node searched; the 15×15's 25×25: every
mate on another sheet than the flank grid, the sheets crossing.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy.optimize import least_squares

ROOT = Path(__file__).resolve().parents[1]
BASIC_15X15 = ROOT / "benchmarks" / "data" / "unseen_designs" / "hypoid_15x15_a20.toml"


def _case(args):
    from geometry.case import load_case

    if args.counts:
        from contact.optimize.development_conjugacy import counts_basic
        from geometry.synthesis.basic_design import load_basic
        from geometry.synthesis.case_synthesis import synthesize

        return synthesize(counts_basic(load_basic(BASIC_15X15), args.counts, args.counts))[0]
    return load_case(args.case)


class _Family:
    """The pinion flank's cutter family and its meshing residual at (s, θ, q, section)."""

    def __init__(self, case, flank: str):
        from geometry.machine.cutter import profile_sections

        tool = case.pinion.flank(flank)
        self.blade, self.machine = tool.blade, tool.machine
        self.length = case.pinion.blank.outer_cone_distance
        self.sections = profile_sections(self.blade)

    def family(self, s, t, q, sec):
        from geometry.machine.meshing import envelope_family

        s, t, q = (np.asarray(a, float) for a in (s, t, q))
        secs = np.broadcast_to(np.asarray(sec, np.intp), s.shape)
        return envelope_family(self.blade, self.machine, s, t, q, secs,
                               length_scale=self.length)

    def residual(self, s, t, q, sec, z=0.0, rho=0.0):
        fam = self.family(s, t, q, sec)
        n = np.cross(fam.r_s, fam.r_theta)
        n /= np.linalg.norm(n, axis=-1, keepdims=True)
        f = np.einsum("...k,...k", n, fam.r_q) / self.length
        return f, fam.r[..., 2] - z, np.hypot(fam.r[..., 0], fam.r[..., 1]) - rho

    def dfdq_sign(self, s, t, q, sec, h=1e-6):
        up = self.residual(s, t, np.asarray(q) + h, sec)[0]
        down = self.residual(s, t, np.asarray(q) - h, sec)[0]
        return np.sign((up - down) / (2 * h))

    def roots(self, x0, z, rho):
        """Every root (section, params) of the place (z, ρ) near the parameters x0."""
        found = []
        scale = np.array([1.0, 1.0 / self.length, 1.0 / self.length])
        for j in range(len(self.sections.s_lo)):
            lo = self.sections.s_lo[j]
            grid = np.meshgrid(np.linspace(lo, min(self.sections.s_hi[j], lo + 12.0), 25),
                               np.linspace(x0[1] - 0.6, x0[1] + 0.6, 61),
                               np.linspace(x0[2] - 0.6, x0[2] + 0.6, 61), indexing="ij")
            f, ez, ep = self.residual(*grid, j, z, rho)
            cost = (f / np.nanstd(f)) ** 2 + 1e4 * ((ez / self.length) ** 2
                                                    + (ep / self.length) ** 2)
            cost = np.where(np.isfinite(cost), cost, np.inf).ravel()
            for b in np.argsort(cost)[:30]:
                if not np.isfinite(cost[b]):
                    continue
                start = np.array([g.ravel()[b] for g in grid])
                x = _solve(lambda p, j=j: np.array(
                    [a.item() for a in self.residual(*p, j, z, rho)]) * scale, start)
                inside = (x is not None and lo - 1e-9 <= x[0]
                          <= self.sections.s_hi[j] + 1e-9)
                if inside and not any(k == j and np.allclose(x, y, atol=1e-6)
                                      for k, y in found):
                    found.append((j, x))
        return found


def _solve(fun, start):
    try:
        r = least_squares(fun, start, xtol=1e-14, ftol=1e-14, gtol=1e-14)
    except ValueError:  # the family is not finite at the start
        return None
    ok = np.all(np.isfinite(r.fun)) and np.max(np.abs(r.fun)) < 1e-9
    return r.x if ok else None


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", nargs="?", help="a case file (TOML)")
    parser.add_argument("--counts", type=int, default=0,
                        help="the 15x15 hypoid's basic file at z1 = z2 = COUNTS instead")
    parser.add_argument("--flank", default="drive")
    parser.add_argument("--nodes", type=int, default=8, help="nodes searched for every root")
    args = parser.parse_args(argv)
    if not args.case and not args.counts:
        parser.error("give a case file or --counts")
    from contact.optimize.development_conjugacy import off_sheet_mates
    from contact.utca.easeoff import ease_off
    from geometry.machine.flank import flank_surface

    case = _case(args)
    eo = ease_off(case, flank=args.flank)
    fam = _Family(case, eo.pinion_flank)
    fs = flank_surface(case, "pinion", eo.pinion_flank)
    mid = tuple(np.array(fs.reason.shape) // 2)
    regular = fam.dfdq_sign(fs.s[mid], fs.theta[mid], fs.q[mid], fs.section[mid])
    valid = eo.valid
    par, sec = eo.pinion_parameters[valid], eo.pinion_section[valid]
    z, rho = eo.pinion_axial[valid], eo.pinion_radius[valid]
    f, dz, dr = fam.residual(par[:, 0], par[:, 1], par[:, 2], sec, z, rho)
    sign = fam.dfdq_sign(par[:, 0], par[:, 1], par[:, 2], sec)
    grid_q = fs.q[fs.valid]
    place = 1e3 * max(abs(dz).max(), abs(dr).max())
    print(f"{eo.pinion_flank} pinion flank: {valid.sum()} valid nodes of {valid.size}; "
          f"max |f| {np.abs(f).max():.1e}, place error {place:.1e} "
          f"um, regular sign {100 * np.mean(sign == regular):.1f} %; mates q "
          f"[{par[:, 2].min():.3f}, {par[:, 2].max():.3f}], flank grid q [{grid_q.min():.3f}, "
          f"{grid_q.max():.3f}]: {off_sheet_mates(case, eo)} off its sheet")
    rng = np.random.default_rng(0)
    for k in rng.choice(par.shape[0], size=min(args.nodes, par.shape[0]), replace=False):
        p0 = fam.family(*par[k], sec[k])
        rows = []
        for j, x in fam.roots(par[k], z[k], rho[k]):
            if fam.dfdq_sign(*x, j) != regular:
                continue
            same = j == sec[k] and np.abs(x - par[k]).max() < 1e-6
            offset = float((fam.family(*x, j).r - p0.r) @ p0.normal)
            rows.append("mate" if same else f"sec {j} q {x[2]:+.3f}: {1e3 * offset:+.0f} um")
        print(f"  node {tuple(int(i) for i in np.argwhere(valid)[k])} (mate sec {sec[k]}, "
              f"q {par[k, 2]:+.3f}): regular roots " + "; ".join(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
