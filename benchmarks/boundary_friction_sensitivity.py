"""How much the default model's efficiency depends on the oil's boundary friction μ_b.

Prints, for the default case (``kolivand2009_fm_11x41_reference`` at 50 / 250 / 500 N·m)
and Table 5.4's face-hobbed A and B (500 N·m), at 1500 rpm, 75W90 at 90 °C, Rq 0.8 µm,
run-in flanks (the default ``ltca run``'s operating conditions), the mean mesh efficiency
and the flank load-weighted μ of the default friction model ``mixed_ehl`` with the
bundled oil's ``boundary_friction`` replaced by each of 0.08, 0.10 and 0.13 — the range
the oil file states for steel with additive-containing oils (0.10 is the bundled value) —
and the asperities' load-weighted share of the flanks' load, which μ_b multiplies.

Usage::

    python benchmarks/boundary_friction_sensitivity.py [--ltca-cache DIR] [--mu-b 0.08 0.1 0.13]

The LTCAs are those of ``benchmarks/friction_anchors.py``, computed once and cached in
``--ltca-cache`` (default ``~/.cache/hypoid-ltca/benchmarks``); each μ_b then costs only
the efficiency stage (~0.1 s per case).
"""

from __future__ import annotations

import argparse
import re
import tempfile
import warnings
from importlib import resources
from pathlib import Path

from friction_anchors import CASES, _flank_weighted, _ltca
from tabulate import tabulate

from friction.coefficient import FrictionModelRangeWarning
from friction.efficiency import efficiency_analysis
from friction.operating import OperatingConditions

#: the range of μ_b the bundled oil file states (steel, additive oils), and its value
MU_B = (0.08, 0.10, 0.13)


def oil_with(mu_b: float, folder: Path) -> Path:
    """The bundled 75W90 oil file with ``boundary_friction`` set to ``mu_b`` [1]."""
    text = resources.files("friction").joinpath("data", "75W90.toml").read_text("utf-8")
    # the number, not the [units] table's boundary_friction = "1"
    text, n = re.subn(r"(?m)^boundary_friction = [0-9.eE+-]+$",
                      f"boundary_friction = {mu_b!r}", text)
    if n != 1:
        raise SystemExit("the bundled 75W90.toml has no single 'boundary_friction =' line")
    path = folder / f"75W90_mu_b_{mu_b:g}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def rows(args: argparse.Namespace) -> list[list]:
    """One row per case and torque: efficiency [%] and flank μ at each μ_b, the
    efficiency's change per 0.01 of μ_b [point], the flanks' load-weighted asperity share
    [1] (μ_b's lever on the flank μ)."""
    out = []
    with tempfile.TemporaryDirectory() as tmp:
        oils = [oil_with(m, Path(tmp)) for m in args.mu_b]
        for label, case, torques, rolls in CASES:
            lt = _ltca(case, torques, rolls, args.ltca_cache)
            eff, mu = [], []
            for oil in oils:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", FrictionModelRangeWarning)
                    fr = efficiency_analysis(lt, OperatingConditions(lubricant=str(oil)))
                eff.append(fr["efficiency_mean"].values * 100.0)
                mu.append(_flank_weighted(lt, fr, "friction_coefficient"))
            span = args.mu_b[-1] - args.mu_b[0]
            # μ = μ_film + μ_b/γ₂ and neither μ_film nor 1/γ₂ depends on μ_b: the flanks'
            # load-weighted asperity share is the change of their μ over the change of μ_b
            share = (mu[-1] - mu[0]) / span
            for i, t in enumerate(torques):
                slope = (eff[-1][i] - eff[0][i]) / span * 0.01
                out.append([label, t, *(e[i] for e in eff), slope, *(m[i] for m in mu),
                            share[i]])
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ltca-cache", type=Path,
                    default=Path.home() / ".cache" / "hypoid-ltca" / "benchmarks")
    ap.add_argument("--mu-b", type=float, nargs="+", default=list(MU_B),
                    help="boundary friction values [1] (default %(default)s)")
    args = ap.parse_args(argv)
    print("mixed_ehl, 1500 rpm, 75W90 at 90 °C, Rq 0.8 µm, run-in flanks; boundary_friction "
          f"{', '.join(f'{m:g}' for m in args.mu_b)}")
    head = ["case", "T [N·m]", *(f"η [%] μ_b {m:g}" for m in args.mu_b),
            "Δη per 0.01 μ_b [point]", *(f"flank μ, μ_b {m:g}" for m in args.mu_b),
            "flank asperity share"]
    print(tabulate(rows(args), headers=head, floatfmt=".4g"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
