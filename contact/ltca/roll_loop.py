"""The LTCA roll loop: every (torque, roll) contact problem of an analysis (seed §3.4)."""

from __future__ import annotations

import dataclasses
import logging

import numpy as np
import xarray as xr

from contact.compliance.mesh import ContactSegments, mesh_compliance_many, pair_compliance_model
from contact.compliance.weber import hertz_half_width, weber_compliance
from contact.ltca.dataset import ltca_dataset
from contact.ltca.options import LTCAOptions
from contact.ltca.screening import SCREEN_MARGIN, SCREEN_PAD, SCREEN_ROUNDS, generous_limit
from contact.ltca.segments import keep_segments
from contact.qp import ContactProblem, solve_contact
from contact.qp.problem import RESIDUALS
from contact.utca import EaseOff
from geometry.errors import InputError

__all__ = ["solve_rolls"]

log = logging.getLogger(__name__)



def solve_rolls(case, eo: EaseOff, opts: LTCAOptions, torques: np.ndarray, roll: np.ndarray,
                 seg: dict, m1: float, m2: float, progress: bool,
                 sink: list | None, timing: dict) -> tuple[xr.Dataset, float]:
    """The contact problems of every (torque, roll) of :func:`loaded_tca` on the segments
    ``seg`` (:func:`segment_geometry`); returns the ``/ltca`` dataset and the largest
    R Θ [mm] the edge segments could reach (greatest boundary arm × greatest Θ), which
    must not exceed the ``edge_limit`` the segments were worked out with. The final
    problems are appended to ``sink`` (if given) in order."""
    ute_env = np.nanmin(seg["ute"], axis=1)  # (J,)
    if not np.all(np.isfinite(ute_env)):
        raise InputError("no tooth pair is in contact at some roll position (check the case)")

    # separation s = R (lag − UTE) [mm] of every segment; ``ok``: the segments with the
    # data of a contact problem (finite s and R_eq, a part inside the blanks)
    arm = seg["moment_arm"]
    sep_all = arm * (seg["lag"] - ute_env[:, None, None])
    ok_all = np.isfinite(sep_all) & np.isfinite(seg["r_eq"]) & (seg["length"] > 0)
    J, K, S = seg["shape"]
    fixed = opts.separation_limit
    limit_max = generous_limit(float(torques.max()), eo.ratio)

    def generous(j: int) -> np.ndarray:
        # the first pool, before any rotation is known
        return ok_all[j] & (sep_all[j] <= limit_max)

    def near(j: int, theta: float) -> np.ndarray:
        # the segments a loaded rotation θ [rad] may close: s < R θ with a margin
        return ok_all[j] & (sep_all[j] < SCREEN_MARGIN * arm[j] * max(theta, 0.0)
                            + SCREEN_PAD)

    model = pair_compliance_model(
        case, theory=opts.theory, n_height=opts.n_height, n_face=opts.n_face,
        pinion_material=(opts.youngs_modulus, opts.poisson_ratio),
        gear_material=(opts.youngs_modulus, opts.poisson_ratio),
    )
    E, nu = opts.youngs_modulus, opts.poisson_ratio
    NT = torques.size
    shape4 = (NT, J, K, S)
    out = {k: np.full(shape4, np.nan) for k in ("force", "load_per_length", "pressure_max",
                                                "half_width")}
    contact = np.zeros(shape4, np.int8)
    in_problem = np.zeros(shape4, np.int8)
    rotation = np.full((NT, J), np.nan)
    resid = {r: np.full((NT, J), np.nan) for r in RESIDUALS}
    found = np.zeros((NT, J), np.int8)
    status = np.full((NT, J), "", dtype=object)
    solve_time = np.zeros((NT, J))
    compliance_time = np.zeros(J)
    weber_iters = np.zeros((NT, J), np.int64)
    n_seg = np.zeros(J, np.int64)
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=J, desc="LTCA", unit="roll")
    # the structural compliance (shells and foundations) of a pool of segments per
    # computed roll, all rolls' segments mapped onto the shells in one batch
    # (mesh_compliance_many); a torque's problem takes the sub-matrix of its selection
    pool: dict[int, np.ndarray] = {}  # (K, S) the segments of the assembled compliance
    structural: dict[int, tuple[np.ndarray, np.ndarray]] = {}

    def assemble(jobs: list[tuple[int, np.ndarray]]) -> None:
        batch = []
        for j, mask in jobs:
            wk, ws = np.nonzero(mask)
            batch.append(ContactSegments(
                midpoints=seg["midpoint_pair"][j, wk, ws],
                ends=seg["ends_pair"][j, wk, ws],
                normals=seg["normal_pair"][j, wk, ws],
                length=seg["length"][j, wk, ws],
                r_eq=seg["r_eq"][j, wk, ws],
                pair_index=np.asarray(opts.pairs)[wk],
                # (Weber's part is replaced below; a unit line load keeps it defined)
                load=seg["length"][j, wk, ws],
                pinion_rotation=float(seg["pinion_rotation"][j]),
                gear_rotation=float(seg["gear_rotation"][j]),
            ))
        try:
            mats = mesh_compliance_many(case, batch, model=model)
        except InputError as exc:
            if fixed is None:
                raise
            raise InputError(
                f"separation_limit: {fixed:g} mm takes in segments so far from contact that "
                "their points lie off the mating tooth (far pairs' edges); use a smaller "
                f"limit or the default screening (None): {exc}") from exc
        for (j, mask), (C_full, info) in zip(jobs, mats, strict=True):
            pool[j] = mask
            structural[j] = (C_full - info["weber"], info["weber_depth"])
            compliance_time[j] += info["time"]

    def weber_solve(j: int, T: float, sel: np.ndarray, prior: np.ndarray | None):
        """The contact problem of roll j at torque T on the segments ``sel``, with the
        Weber compliance iterated to the solution's loads; ``prior`` (N,) [N] (NaN where
        unknown) the forces of a neighbouring solution, a warm start for the solver."""
        idx = np.argwhere(sel)  # (N, 2): pair index, segment index
        kk, ss = idx[:, 0], idx[:, 1]
        sub = np.flatnonzero(sel[pool[j]])  # positions of the selection in the pool
        C_pool, depth_pool = structural[j]
        C_struct = C_pool[np.ix_(sub, sub)]
        depth = depth_pool[sub]
        L = seg["length"][j, kk, ss]
        Req = seg["r_eq"][j, kk, ss]
        R = arm[j, kk, ss]
        s = sep_all[j, kk, ss]
        Tn = T * eo.ratio * 1e3  # gear torque [N·mm]
        # Weber's formula holds while the Hertz half-width b is well below the depth h
        # (ln(2h/b) − ν/(2(1−ν)) > 0); loads are capped where b would reach h, i.e.
        # w′ ≤ π E* h²/(4 R_eq) — beyond that a segment is in gross edge contact and
        # the secant compliance is frozen at the cap (logged)
        e_star = E / (2 * (1 - nu**2))
        cap = np.pi * e_star * np.min(depth, axis=1) ** 2 / (4 * Req) * L  # [N]
        # first Weber loads: the torque shared evenly over the roll's curve segments (not
        # the neighbour's loads, nor the selection's: the roll's result then depends on
        # the roll alone, not on the path to it or on which edge segments were worked out)
        on_curve = ok_all[j] & (seg["kind"] == 0)
        share = Tn / max(float(np.sum(arm[j][on_curve if on_curve.any() else ok_all[j]])),
                         1e-12)
        load = np.minimum(np.full(kk.size, share), cap)
        start = None if prior is None else np.nan_to_num(prior)
        lte_prev = step_prev = None
        sol = problem = None
        n_it = time_used = 0
        for w_it in range(1, opts.max_weber_iterations + 1):
            # Newton on Weber's δ(F): δ ≈ c_s F₀ + c_t (F − F₀), c_s the secant and c_t
            # the tangent compliance at the loads F₀, i.e. compliance c_t and separation
            # s + (c_s − c_t) F₀; the secant alone where c_t is not well positive (b near
            # the depth h) or the load is at the cap (frozen there)
            cs, ct = weber_compliance(load, L, depth[:, 0], depth[:, 1], e1=E, nu1=nu, e2=E,
                                      nu2=nu, r_eq=Req, kind=("secant", "tangent"))
            newton = (ct > 0.5 * cs) & (load < cap)
            cw = np.where(newton, ct, cs)
            problem = ContactProblem(C_struct + np.diag(cw),
                                     s + np.where(newton, (cs - ct) * load, 0.0), R, Tn,
                                     name=f"{case.name} roll {j} T {T:g}")
            sol = solve_contact(problem, opts.solver,
                                initial=sol if sol is not None else start)
            time_used += sol.solve_time + sol.build_time
            if not sol.found:
                break
            load = np.minimum(np.maximum(sol.force, 0.0), cap)
            if np.any(sol.force > cap):
                log.info("roll %d: Weber load cap reached on %d segments", j,
                         int(np.sum(sol.force > cap)))
            lte = sol.rotation * 1e6
            n_it = w_it
            if lte_prev is not None:
                step = abs(lte - lte_prev)
                # Newton's steps shrink quadratically once close (the last step below
                # 1000 tolerances) where every loaded segment took it: the next step is
                # then about step²/(last step), asked to be ten times below the tolerance
                quadratic = (step_prev is not None
                             and step_prev < 1000.0 * opts.weber_tolerance
                             and bool(np.all(newton[load > 0])))
                if step < opts.weber_tolerance or (
                        quadratic and step * step < 0.1 * opts.weber_tolerance * step_prev):
                    break
                step_prev = step
            lte_prev = lte
        return sol, problem, kk, ss, n_it, time_used

    problems: dict[tuple[int, int], ContactProblem] = {}
    last_force: list[np.ndarray | None] = [None] * NT  # forces of the last computed roll [N]
    last_theta: list[float | None] = [None] * NT  # its LTE Θ + UTE [rad]
    computed = [j for j in range(J) if int(seg["source"][j]) == j and ok_all[j].any()]
    if fixed is not None:
        assemble([(j, ok_all[j] & (sep_all[j] <= fixed)) for j in computed])
    elif computed:
        assemble([(computed[0], generous(computed[0]))])
    for j in range(J):
        src = int(seg["source"][j])
        if src != j:
            # a roll whole mesh cycles after ``src``: its segments, separations and hence
            # its contact problems are identical (segment_geometry), so are the results
            for arr in (*out.values(), contact, in_problem, *resid.values(), rotation, found,
                        status, weber_iters):
                arr[:, j] = arr[:, src]
            for it in range(NT):
                if sink is not None and (it, src) in problems:
                    sink.append(dataclasses.replace(
                        problems[it, src], name=f"{case.name} roll {j} T {torques[it]:g}"))
            n_seg[j] = n_seg[src]
            if bar is not None:
                bar.update()
            continue
        for it, T in enumerate(torques):
            if j not in pool or not pool[j].any():
                status[it, j] = "no segment within the separation limit"
                continue
            # the segments that may touch: the whole pool, or (screening) those the
            # LTE of the last computed roll at this torque would close here
            if fixed is not None or last_theta[it] is None:
                sel = pool[j]
            else:
                sel = near(j, last_theta[it] - ute_env[j]) & pool[j]
                if not sel.any():
                    sel = pool[j]
            # the last computed roll's forces on the same (pair, segment) start the
            # Weber iteration and (backends that take one) the solver
            prior = None if last_force[it] is None else last_force[it][sel]
            for _round in range(SCREEN_ROUNDS):
                if np.any(sel & ~pool[j]):
                    assemble([(j, pool[j] | sel)])
                sol, problem, kk, ss, n_it, t_used = weber_solve(j, T, sel, prior)
                solve_time[it, j] += t_used
                if not sol.found:
                    break
                # a segment left out keeps its gap open if s + C F − R Θ ≥ 0: checked
                # exactly within the assembled pool, and beyond it by s ≥ R Θ (the
                # compliances are ≥ 0); then the solution is that of all segments
                rest = pool[j] & ~sel
                missed = ok_all[j] & ~sel & ~pool[j] & (sep_all[j] < arm[j] * sol.rotation)
                if rest.any():
                    C_pool = structural[j][0]
                    gap = (sep_all[j][rest] - arm[j][rest] * sol.rotation
                           + C_pool[np.ix_(np.flatnonzero(rest[pool[j]]),
                                           np.flatnonzero(sel[pool[j]]))] @ sol.force)
                    missed[rest] = gap < 0.0
                if not missed.any():
                    break
                if fixed is not None:
                    log.warning("roll %d, torque %g N m: %d segments beyond the separation "
                                "limit %g mm would touch", j, T, int(missed.sum()), fixed)
                    break
                # the missed ones and, within the assembled pool, those nearly missed
                sel = sel | missed | (near(j, sol.rotation) & pool[j])
                full = np.full((K, S), np.nan)
                full[kk, ss] = np.maximum(sol.force, 0.0)
                prior = full[sel]
            else:
                log.warning("roll %d, torque %g N m: the screening of the segments did not "
                            "settle in %d rounds", j, T, SCREEN_ROUNDS)
                sol = dataclasses.replace(sol, found=False,
                                          status="segment screening did not settle")
            weber_iters[it, j] = n_it
            n_seg[j] = max(n_seg[j], kk.size)
            if sink is not None:
                sink.append(problem)
                problems[it, j] = problem
            found[it, j] = int(sol.found)
            status[it, j] = sol.status
            for r in RESIDUALS:
                resid[r][it, j] = sol.residuals[r]
            if not sol.found:
                log.warning("roll %d, torque %g N m: %s", j, T, sol.status)
                continue
            F = sol.force
            rotation[it, j] = sol.rotation
            last_theta[it] = sol.rotation + ute_env[j]
            last_force[it] = np.full((K, S), np.nan)
            last_force[it][kk, ss] = F
            L = seg["length"][j, kk, ss]
            Req = seg["r_eq"][j, kk, ss]
            w = F / L
            b = hertz_half_width(np.maximum(w, 1e-12), Req, E, nu, E, nu)
            pmax = np.where(F > 0, 2 * w / (np.pi * b), 0.0)
            out["force"][it, j, kk, ss] = F
            out["load_per_length"][it, j, kk, ss] = w
            out["half_width"][it, j, kk, ss] = np.where(F > 0, b, 0.0)
            out["pressure_max"][it, j, kk, ss] = pmax
            contact[it, j, kk, ss] = sol.active_set.astype(np.int8)
            in_problem[it, j, kk, ss] = 1
        if fixed is None and computed and j == computed[0]:
            # the pools of the other rolls: the segments this roll's LTE at the largest
            # torque would close there (the LTE varies little over the cycle; a segment
            # missed is added when its roll is solved)
            it_max = int(np.argmax(torques))
            jobs = []
            for i in computed[1:]:
                mask = (near(i, ute_env[j] + rotation[it_max, j] - ute_env[i])
                        if found[it_max, j] else generous(i))
                jobs.append((i, mask if mask.any() else generous(i)))
            if jobs:
                assemble(jobs)
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    # the segment axis keeps the curve segments and the edge segments in some problem
    keep = (seg["kind"] == 0) | np.any(in_problem > 0, axis=(0, 1, 2))
    seg = keep_segments(seg, keep)
    sep_all, contact, in_problem = sep_all[..., keep], contact[..., keep], in_problem[..., keep]
    out = {k: v[..., keep] for k, v in out.items()}
    reach = float(seg["edge_arm_max"]) * float(np.nanmax(rotation, initial=0.0))
    return ltca_dataset(case, eo, opts, torques, roll, seg, sep_all, ute_env, out, contact,
                         in_problem, rotation, resid, found, status, solve_time, weber_iters,
                         compliance_time, n_seg, m1, m2, timing=timing), reach
