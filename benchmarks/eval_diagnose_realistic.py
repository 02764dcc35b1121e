"""Judge ``hystcomp.diagnose`` on realistic records it was not built from.

The records come from ``tests/realistic`` (mechanisms written from their physics, not from
hystcomp's model parts). For every case and seed this runs ``diagnose(t, v, y)`` with its
defaults and prints: the expected effects and verdict, what was named, the held-out RMS
against the diagnosed noise floor and against the TRUE sensor noise, and whether the answer
is right (named effect families equal the expected ones, and the verdict matches unless the
case accepts either). Any "explained" verdict whose held-out RMS exceeds 1.5x the true noise
is flagged.

HOLDOUT6 was run once for the sixth round's final measurement and is part of ALL since.
HOLDOUT7 was run once for the seventh round's final measurement and is part of ALL since.
HOLDOUT8 was run once for the eighth round's final measurement and is part of ALL since.
HOLDOUT9 was run once for the ninth round's final measurement and is part of ALL since.
HOLDOUT10 was run once for the tenth round's final measurement and is part of ALL since.
HOLDOUT11 was run once for the eleventh round's measurement and is part of ALL since.
HOLDOUT12 was run once for the twelfth round's measurement and is part of ALL since.
HOLDOUT13 was run once for the thirteenth round's measurement and is part of ALL since.
HOLDOUT14 was run once for the fifteenth round's measurement (26 of 30 right) and is part of ALL since.
HOLDOUT15 was run once for the seventeenth round's measurement (20 of 30 right) and is part of ALL since.
HOLDOUT16 was run once for the eighteenth round's measurement (23 of 30 right) and is part of ALL since.
HOLDOUT17 was run once for the nineteenth round's measurement (24 of 30 right) and is part of ALL since.
HOLDOUT18 was run once for the twentieth round's measurement (22 of 30 right) and is part of ALL since.
HOLDOUT19 was run once for the twenty-first round's measurement (24 of 30 right) and is part of ALL since.
HOLDOUT20 was run once for the twenty-second round's measurement (25 of 30 right) and is part of ALL since.
HOLDOUT21 was run once for the twenty-fourth round's measurement (23 of 30 right) and is part of ALL since.
HOLDOUT22 was run once for the twenty-fifth round's measurement (20 of 30 right) and is part of ALL since.
HOLDOUT23 was run once for the twenty-sixth round's measurement (26 of 30 right) and is part of ALL since.
HOLDOUT24 was run once for the twenty-sixth round's second measurement (24 of 30 right) and is part of ALL since.
HOLDOUT25 was run once for the twenty-seventh round's measurement (21 of 30 right) and is part of ALL since.
HOLDOUT26 was run once for the twenty-eighth round's measurement (24 of 30 right) and is part of ALL since.
HOLDOUT27 was run once for the twenty-ninth round's measurement (22 of 30 right) and is part of ALL since.
HOLDOUT28 was run once for the thirtieth round's measurement (27 of 30 right) and is part of ALL since.
HOLDOUT29 was run once for the thirty-first round's measurement (28 of 30 right) and is part of ALL since.
HOLDOUT30 was run once for the thirty-second round's measurement (23 of 30 right) and is part of ALL since.
HOLDOUT31 was run once for the thirty-third round's measurement (21 of 30 right) and is part of ALL since.
HOLDOUT32 was run once for the thirty-fourth round's measurement (15 of 30 right) and is part of ALL since.
HOLDOUT33 was run once for the thirty-fifth round's measurement (3 of 30 right) and is part of ALL since.
HOLDOUT34 was run once for the thirty-sixth round's measurement (7 of 30 right) and is part of ALL since.
HOLDOUT35 was run once for the thirty-seventh round's measurement (9 of 30 right) and is part of ALL since.
HOLDOUT36 was run once for the thirty-eighth round's measurement (19 of 30 right) and is part of ALL since.
HOLDOUT37 was run once for the thirty-ninth round's measurement (12 of 30 right) and is part of ALL since.
HOLDOUT38 was run once for the fortieth round's measurement (20 of 30 right) and is part of ALL since.
HOLDOUT39 was run once for the forty-first round's measurement (13 of 30 right) and is part of ALL since.
HOLDOUT40 was run once for the forty-second round's measurement (16 of 30 right) and is part of ALL since.
HOLDOUT41 was run once for the forty-third round's measurement (26 of 30 right) and is part of ALL since.
HOLDOUT42 was run once for the forty-fourth round's measurement (6 of 30 right) and is part of ALL since.
HOLDOUT43 was run once for the forty-fifth round's measurement (17 of 30 right) and is part of ALL since.
HOLDOUT44 was run once for the forty-sixth round's measurement (20 of 30 right) and is part of ALL since.
HOLDOUT45 was run once for the forty-seventh round's measurement (8 of 30 right) and is part of ALL since.
HOLDOUT46 was run once for the forty-eighth round's measurement (22 of 30 right) and is part of ALL since.
HOLDOUT47 was run once for the forty-ninth round's measurement (19 of 30 right) and is part of ALL since.
HOLDOUT48 was run once for the fiftieth round's measurement (24 of 30 right) and is part of ALL since.
HOLDOUT49 was run once for the fifty-first round's measurement (22 of 30 right) and is part of ALL since.

Run: python benchmarks/eval_diagnose_realistic.py [--set tuning|holdout|holdout2|...|holdout49|all] [--seeds 3]
     [--cases NAME ...] [--json OUT] [--jobs 2]
     python benchmarks/eval_diagnose_realistic.py --summary OUT     (the figures of a saved run, again)

After the figures it prints where the wrong runs are: how many named the right effects with the
wrong verdict, missed an expected effect, named another beside the expected ones, or named
another instead (effects compared by family), with the families most often missed and named
beside or instead, and how many of each kind are right up to a reported near tie.
"""

import argparse
import itertools
import json
import os
import sys
import time
from collections import Counter
from concurrent.futures import ProcessPoolExecutor


HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests"))

import realistic  # noqa: E402
from realistic import ALL, family  # noqa: E402

#: every set by its --set name: the tuning set and each HOLDOUT* the package exports (a new
#: set needs no edit here)
SETS = {"tuning": realistic.TUNING,
        **{n.lower(): getattr(realistic, n) for n in realistic.__all__ if n.startswith("HOLDOUT")}}

#: every case by name: ALL and every set exported (a set written but not yet measured, not in
#: ALL, is run by its --set name)
KNOWN = {**ALL, **{name: case for cases in SETS.values() for name, case in cases.items()}}

EXPLAINED_LIMIT = 1.5    # the bound on an "explained" residual, in true noise std


def one_blas_thread():
    """Limit BLAS to one thread in this process (a pool's initializer): the figures in
    docs/diagnose.md were measured so, and a decision that sits on a threshold can move with the
    order of a multi-threaded sum. A no-op without threadpoolctl (installed with scikit-learn,
    a test dependency)."""
    global _LIMITS
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:
        return
    _LIMITS = threadpool_limits(limits=1, user_api="blas")


_LIMITS = None


def run_one(name, seed):
    """Diagnose one record; return a dict of what was expected and what came out."""
    from hystcomp.diagnose import diagnose

    rec = KNOWN[name](seed)
    t0 = time.perf_counter()
    try:
        # one thread a record: --jobs runs records side by side in processes
        res = diagnose(rec.t, rec.v, rec.y, progress=False, workers=1)
        error = None
    except Exception as exc:  # a crash is a wrong answer, reported as such
        res, error = None, f"{type(exc).__name__}: {exc}"
    elapsed = time.perf_counter() - t0
    effects = list(getattr(res, "effects", []) or [])
    verdict = getattr(res, "verdict", "n/a") if res is not None else "crash"
    rms = getattr(res, "rms_heldout", None)
    if rms is None and res is not None:
        rms = getattr(res, "rms_after", None)
    floor = getattr(res, "noise_floor", None)
    right = error is None and rec.judge(effects, verdict)
    # right up to a reported near tie: some choice among each named effect and
    # its near ties (``ambiguous``) gives the expected families
    amb = dict(getattr(res, "ambiguous", {}) or {})
    options = [[e] + list(amb.get(e, [])) for e in effects]
    right_or_tie = error is None and any(rec.judge(list(c), verdict) for c in itertools.product(*options))
    over = (verdict == "explained" and rms is not None
            and rms > EXPLAINED_LIMIT * rec.noise_std)
    return {
        "case": name, "seed": seed, "expected": sorted(rec.expect_effects),
        "expect_verdict": rec.expect_verdict, "effects": effects, "verdict": verdict,
        "rms_heldout": None if rms is None else float(rms),
        "rms_base": None if res is None else float(res.rms_before),
        "noise_floor": None if floor is None else float(floor),
        "true_noise": float(rec.noise_std), "right": bool(right), "right_or_tie": bool(right_or_tie),
        "ambiguous": amb, "explained_over_limit": bool(over),
        "clean": not rec.expect_effects and rec.expect_verdict == "explained",
        "combined": len(family(rec.expect_effects)) >= 2,
        "stopped": getattr(res, "stopped", None), "error": error, "seconds": elapsed,
        "preisach_core": getattr(res, "preisach_core", None),
        "steps": [] if res is None else [
            {"effect": st["effect"], "kind": st["evidence"]["extension"].get("kind"),
             "dropped": bool(st.get("dropped", False)), "tentative": bool(st.get("tentative", False)),
             "core_shape": bool(st.get("core_shape", False)),
             "acceptable": st["evidence"].get("acceptable", {}),
             "revised_by": (st["evidence"].get("revised") or {}).get("by"),
             "loss_without": st["evidence"].get("held_out_loss_without_it_noise_variances"),
             "gain": st["evidence"].get("held_out_gain_noise_variances"),
             "alternatives": st.get("alternatives", [])} for st in res.steps],
    }


def _fmt(x, d=2):
    return "   -  " if x is None else f"{x:6.{d}f}"


#: the kinds of wrong run :func:`breakdown` counts, in its order
WRONG_KINDS = {
    "verdict": "the right effects named, the wrong verdict",
    "missed": "an expected effect missed, nothing else named",
    "extra": "every expected effect named, and another beside them",
    "confused": "an expected effect missed and another named instead",
    "crash": "the diagnosis raised an error",
}


def wrong_kind(row):
    """The kind of a wrong run (a key of :data:`WRONG_KINDS`), compared by effect families;
    None for a right run."""
    if row["right"]:
        return None
    if row["error"] is not None:
        return "crash"
    expected, named = family(row["expected"]), family(row["effects"])
    if expected == named:
        return "verdict"
    if named < expected:
        return "missed"
    if expected < named:
        return "extra"
    return "confused"


def breakdown(rows, most=8):
    """Where the wrong runs of an evaluation are.

    Returns a dict: ``n`` (runs), ``wrong`` (wrong runs), ``kinds`` (for each key of
    :data:`WRONG_KINDS` with any run: its ``count``, how many of them are right up to a
    reported near tie, ``tie``, and how many the diagnosis called ``unexplained``: it said
    that something is left that it did not name), ``missed`` and ``extra`` (the effect families most often
    missed / named beside or instead of the expected ones, over the wrong runs: a list of
    ``(family, runs)``, at most `most`), and ``confusions`` (the commonest ``(missed,
    named instead)`` pairs of the ``confused`` runs, families joined by "+").

    Examples
    --------
    >>> rows = [dict(right=True, error=None, expected=["creep"], effects=["creep"], right_or_tie=True,
    ...              verdict="explained"),
    ...         dict(right=False, error=None, expected=["delay"], effects=["rate_dependence"],
    ...              right_or_tie=True, verdict="explained"),
    ...         dict(right=False, error=None, expected=["drift"], effects=[], right_or_tie=False,
    ...              verdict="unexplained")]
    >>> b = breakdown(rows)
    >>> b["wrong"], b["kinds"]["confused"], b["kinds"]["missed"]["unexplained"]
    (2, {'count': 1, 'tie': 1, 'unexplained': 0}, 1)
    >>> b["confusions"]
    [(('delay', 'rate_dependence'), 1)]
    """
    wrong = [r for r in rows if not r["right"]]
    kinds, missed, extra, confusions = {}, Counter(), Counter(), Counter()
    for r in wrong:
        k = wrong_kind(r)
        entry = kinds.setdefault(k, {"count": 0, "tie": 0, "unexplained": 0})
        entry["count"] += 1
        entry["tie"] += bool(r.get("right_or_tie"))
        entry["unexplained"] += r.get("verdict") == "unexplained"
        if k == "crash":
            continue
        expected, named = family(r["expected"]), family(r["effects"])
        missed.update(expected - named)
        extra.update(named - expected)
        if k == "confused":
            confusions["+".join(sorted(expected - named)), "+".join(sorted(named - expected))] += 1
    order = {k: kinds[k] for k in WRONG_KINDS if k in kinds}
    return {"n": len(rows), "wrong": len(wrong), "kinds": order, "missed": missed.most_common(most),
            "extra": extra.most_common(most), "confusions": confusions.most_common(most)}


def print_breakdown(b):
    """Print :func:`breakdown`'s dict `b` as a few lines of text."""
    if not b["wrong"]:
        print("\nwrong runs: none")
        return
    print(f"\nwrong runs: {b['wrong']}/{b['n']}, by kind (effects compared by family; 'tie': right up to a "
          "reported near tie; 'unexplained': the verdict says something is left):")
    for k, x in b["kinds"].items():
        print(f"  {x['count']:5d}  {WRONG_KINDS[k]} ({x['tie']} tie, {x['unexplained']} unexplained)")
    fmt = lambda pairs: ", ".join(f"{f} {c}" for f, c in pairs) or "none"  # noqa: E731
    print(f"  missed most often: {fmt(b['missed'])}")
    print(f"  named beside or instead most often: {fmt(b['extra'])}")
    print("  confused most often (missed -> named instead): "
          + (", ".join(f"{m} -> {n} {c}" for (m, n), c in b["confusions"]) or "none"))


def summarise(rows, total=None):
    """Print the run's figures against the issue's targets, then where the wrong runs are
    (:func:`breakdown`). `total`: the run's wall time in seconds (None: not printed)."""
    n = len(rows)
    right = sum(r["right"] for r in rows)
    clean = [r for r in rows if r["clean"]]
    false_alarms = sum(bool(r["effects"]) for r in clean)
    comb = [r for r in rows if r["combined"]]
    comb_both = sum(family(r["expected"]) <= family(r["effects"]) for r in comb)
    over = sum(r["explained_over_limit"] for r in rows)
    crashes = sum(r["error"] is not None for r in rows)
    print(f"\nright verdict: {right}/{n} ({100 * right / max(n, 1):.0f} %; target >= 90 %)")
    tie = sum(r["right_or_tie"] for r in rows)
    amb = sum(bool(r["ambiguous"]) for r in rows)
    print(f"right up to a reported near tie: {tie}/{n} ({100 * tie / max(n, 1):.0f} %); runs with a near tie "
          f"reported: {amb}, of them right as named: {sum(bool(r['ambiguous']) and r['right'] for r in rows)}")
    print(f"effects named on clean records: {false_alarms}/{len(clean)} runs (target 0)")
    print(f"combined cases with both effects named: {comb_both}/{len(comb)} (target all)")
    print(f"'explained' verdicts above {EXPLAINED_LIMIT}x the true noise: {over} (target 0)")
    timing = "" if total is None else f"; total {total:.0f} s, {total / max(n, 1):.1f} s per record"
    print(f"crashes: {crashes}{timing}")
    print_breakdown(breakdown(rows))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--set", choices=[*SETS, "all"], default="tuning")
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--cases", nargs="*", default=None)
    p.add_argument("--json", default=None)
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--summary", metavar="JSON", default=None,
                   help="print the figures and the breakdown of wrong runs of an earlier run's --json file, "
                        "without running")
    a = p.parse_args(argv)
    if a.summary:
        try:
            with open(a.summary) as fh:
                saved = json.load(fh)
            rows = saved["rows"]
        except (OSError, ValueError, KeyError, TypeError) as exc:
            p.error(f"--summary {a.summary!r}: not a --json file of this script ({exc})")
        summarise(rows, saved.get("seconds"))
        return 0
    pool = {**SETS, "all": ALL}[a.set]
    names = a.cases or list(pool)
    known = KNOWN
    for n in names:
        if n not in known:
            p.error(f"unknown case {n!r}; known: {', '.join(known)}")
    jobs = [(n, s) for n in names for s in range(a.seeds)]
    t0 = time.perf_counter()
    if a.jobs > 1:
        with ProcessPoolExecutor(a.jobs, initializer=one_blas_thread) as ex:
            rows = list(ex.map(run_one, *zip(*jobs)))
    else:
        one_blas_thread()
        rows = [run_one(n, s) for n, s in jobs]
    total = time.perf_counter() - t0
    print(f"{'case':38s} sd {'expected':28s} {'named':32s} {'verdict':11s} "
          f"{'rms/floor':>9s} {'rms/true':>8s} ok   time")
    for r in rows:
        ratio_floor = (r["rms_heldout"] / r["noise_floor"]
                       if r["rms_heldout"] is not None and r["noise_floor"] else None)
        ratio_true = r["rms_heldout"] / r["true_noise"] if r["rms_heldout"] is not None else None
        exp = ",".join(r["expected"]) or "-"
        exp += "" if r["expect_verdict"] == "explained" else f" ({r['expect_verdict'][:5]})"
        flag = "yes" if r["right"] else "NO "
        if r["explained_over_limit"]:
            flag += "!"
        print(f"{r['case'][:38]:38s} {r['seed']:2d} {exp[:28]:28s} {','.join(r['effects'])[:32] or '-':32s} "
              f"{r['verdict'][:11]:11s} {_fmt(ratio_floor):>9s} {_fmt(ratio_true):>8s} {flag:4s} "
              f"{r['seconds']:5.1f}s" + (f"  {r['error']}" if r["error"] else ""))
    summarise(rows, total)
    if a.json:
        with open(a.json, "w") as fh:
            json.dump({"rows": rows, "right": sum(r["right"] for r in rows), "n": len(rows), "seconds": total},
                      fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
