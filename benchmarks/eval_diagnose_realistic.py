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
HOLDOUT50 was run once for the fifty-second round's measurement (16 of 30 right) and is part of ALL since.
HOLDOUT51 was run once for the fifty-third round's measurement (14 of 30 right) and is part of ALL since.
HOLDOUT52 was run once for the fifty-fourth round's measurement (3 of 30 right) and is part of ALL since.
HOLDOUT53 was run once for the fifty-fifth round's measurement (17 of 30 right) and is part of ALL since.
HOLDOUT54 was run once for the fifty-sixth round's measurement (15 of 30 right) and is part of ALL since.
HOLDOUT55 was run once for the fifty-seventh round's measurement (16 of 30 right) and is part of ALL since.
HOLDOUT56 was run once for the fifty-eighth round's measurement (19 of 30 right) and is part of ALL since.
HOLDOUT57 was run once for the fifty-ninth round's measurement (15 of 30 right) and is part of ALL since.
HOLDOUT58 was run once for the sixtieth round's measurement (19 of 30 right) and is part of ALL since.
HOLDOUT59 was run once for the sixty-first round's measurement (20 of 30 right) and is part of ALL since.

Run: python benchmarks/eval_diagnose_realistic.py [--set tuning|holdout|holdout2|...|holdout59|all] [--seeds 3]
     [--cases NAME ...] [--json OUT] [--csv OUT] [--compare SAVED] [--perturb SHARE] [--jobs 2]
     python benchmarks/eval_diagnose_realistic.py --summary OUT     (the figures of a saved run, again)
     python benchmarks/eval_diagnose_realistic.py --summary NEW --compare SAVED   (run by run against another)

``--csv`` writes each run as one line (the format of ``benchmarks/results/diagnose_realistic.csv``,
every committed set's runs as measured: see ``benchmarks/results/README.md``); ``--summary`` and
``--compare`` read either format. ``--compare`` lists the runs whose answer (named effects or
verdict) differs from the saved file's, and how many went from right to wrong and back: a
change to a decision is weighed run by run against the committed runs without running them
again.

After the figures it prints where the wrong runs are: how many named the right effects with the
wrong verdict, missed an expected effect, named another beside the expected ones, or named
another instead (effects compared by family), with the families most often missed and named
beside or instead, and how many of each kind are right up to a reported near tie.
"""

import argparse
import csv
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


def perturbed(y, noise_std, share, name, seed):
    """`y` plus Gaussian noise of `share` times the record's true noise, drawn from a generator
    seeded by the case's name and seed (the same perturbation on every run and machine).

    Examples
    --------
    >>> import numpy as np
    >>> a = perturbed(np.zeros(4), 2.0, 1e-4, "c", 0)
    >>> bool(np.all(a == perturbed(np.zeros(4), 2.0, 1e-4, "c", 0))), bool(np.abs(a).max() < 1e-3)
    (True, True)
    """
    import zlib

    import numpy as np

    rng = np.random.default_rng([zlib.crc32(name.encode()), seed, 1])
    return y + share * noise_std * rng.standard_normal(len(y))


def run_one(name, seed, perturb=0.0):
    """Diagnose one record; return a dict of what was expected and what came out.  With
    `perturb` > 0 the output is first moved by noise of `perturb` times the true noise
    (:func:`perturbed`): how far the answer rests on the data's last digits."""
    from hystcomp.diagnose import diagnose

    rec = KNOWN[name](seed)
    y = rec.y if not perturb else perturbed(rec.y, rec.noise_std, perturb, name, seed)
    t0 = time.perf_counter()
    try:
        # one thread a record: --jobs runs records side by side in processes
        res = diagnose(rec.t, rec.v, y, progress=False, workers=1)
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


#: the columns of a results file (``--csv``), in order
CSV_COLUMNS = ("set", "case", "seed", "expected", "expect_verdict", "effects", "verdict", "right", "right_or_tie",
               "ambiguous", "explained_over_limit", "clean", "combined", "rms_heldout", "rms_base", "noise_floor",
               "true_noise", "seconds", "error", "measured_on", "steps")


def set_of(case):
    """The --set name of a case (the first set that holds it)."""
    return next((n for n, cases in SETS.items() if case in cases), "?")


def _names(cell):
    return [x for x in cell.split(";") if x]


def _number(cell):
    return None if cell == "" else float(cell)


def write_csv(rows, path, measured_on=""):
    """Write `rows` (as :func:`run_one` returns them) to a results file at `path`, one run a line.

    Names are joined by ";", a near tie as ``effect:alternative|alternative`` pairs, each
    step as ``effect/kind/gain/loss_without/flags`` (flags: d dropped, t tentative, c core
    shape) joined by " ; "; numbers to 6 significant digits (seconds to 0.01 s).
    `measured_on`: the commit the runs were measured on, for rows that do not say."""
    def g(x):
        return "" if x is None else f"{x:.6g}"

    with open(path, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(CSV_COLUMNS)
        for r in rows:
            steps = " ; ".join(
                f"{st['effect']}/{st.get('kind') or ''}/{g(st.get('gain'))}/{g(st.get('loss_without'))}/"
                + "".join(f for f, key in (("d", "dropped"), ("t", "tentative"), ("c", "core_shape"))
                          if st.get(key)) for st in r.get("steps") or [])
            amb = ";".join(f"{e}:{'|'.join(a)}" for e, a in sorted((r.get("ambiguous") or {}).items()))
            w.writerow([r.get("set") or set_of(r["case"]), r["case"], r["seed"], ";".join(r["expected"]),
                        r["expect_verdict"], ";".join(r["effects"]), r["verdict"], int(r["right"]),
                        int(r["right_or_tie"]), amb, int(r["explained_over_limit"]), int(r["clean"]),
                        int(r["combined"]), g(r.get("rms_heldout")), g(r.get("rms_base")), g(r.get("noise_floor")),
                        g(r.get("true_noise")), f"{r.get('seconds') or 0:.2f}", r.get("error") or "",
                        r.get("measured_on") or measured_on, steps])


def read_csv(path):
    """The rows of a results file written by :func:`write_csv` (each a dict as :func:`run_one`
    returns, its steps reduced to ``effect``, ``kind``, ``gain``, ``loss_without`` and the flags)."""
    rows = []
    with open(path, newline="") as fh:
        reader = csv.DictReader(fh)
        if tuple(reader.fieldnames or ()) != CSV_COLUMNS:
            raise ValueError(f"{path}: columns {reader.fieldnames} but a results file has {list(CSV_COLUMNS)}")
        for c in reader:
            steps = []
            for cell in filter(None, c["steps"].split(" ; ")):
                effect, kind, gain, loss, flags = cell.split("/")
                steps.append({"effect": effect, "kind": kind or None, "gain": _number(gain),
                              "loss_without": _number(loss), "dropped": "d" in flags, "tentative": "t" in flags,
                              "core_shape": "c" in flags})
            rows.append({
                "set": c["set"], "case": c["case"], "seed": int(c["seed"]), "expected": _names(c["expected"]),
                "expect_verdict": c["expect_verdict"], "effects": _names(c["effects"]), "verdict": c["verdict"],
                "right": c["right"] == "1", "right_or_tie": c["right_or_tie"] == "1",
                "ambiguous": {e: a.split("|") for e, a in (x.split(":") for x in _names(c["ambiguous"]))},
                "explained_over_limit": c["explained_over_limit"] == "1", "clean": c["clean"] == "1",
                "combined": c["combined"] == "1", "rms_heldout": _number(c["rms_heldout"]),
                "rms_base": _number(c["rms_base"]), "noise_floor": _number(c["noise_floor"]),
                "true_noise": _number(c["true_noise"]), "seconds": float(c["seconds"]), "error": c["error"] or None,
                "measured_on": c["measured_on"], "steps": steps})
    return rows


def load_rows(path):
    """The rows and the wall time (None if not saved) of a --json or --csv file."""
    if path.endswith(".csv"):
        return read_csv(path), None
    with open(path) as fh:
        saved = json.load(fh)
    return saved["rows"], saved.get("seconds")


def compare(rows, saved, out=print):
    """Run by run: the runs of `rows` whose answer (named effects, verdict) differs from the
    same case and seed in `saved`. Prints one line a changed run and a count; returns a dict
    ``changed``, ``to_right``, ``to_wrong``, ``tie_to_right``... (counts) and ``missing`` (runs
    of `rows` not in `saved`).

    Examples
    --------
    >>> old = [dict(case="a", seed=0, effects=["creep"], verdict="explained", right=True, right_or_tie=True),
    ...        dict(case="b", seed=0, effects=[], verdict="unexplained", right=False, right_or_tie=False)]
    >>> new = [dict(old[0]), dict(old[1], effects=["drift"], right=True, right_or_tie=True)]
    >>> compare(new, old, out=lambda s: None)["to_right"]
    1
    """
    by = {(r["case"], r["seed"]): r for r in saved}
    c = Counter()
    missing = 0
    for r in rows:
        o = by.get((r["case"], r["seed"]))
        if o is None:
            missing += 1
            continue
        if (list(r["effects"]), r["verdict"]) == (list(o["effects"]), o["verdict"]):
            continue
        c["changed"] += 1
        c["to_right"] += r["right"] and not o["right"]
        c["to_wrong"] += o["right"] and not r["right"]
        c["tie_to_right"] += r["right_or_tie"] and not o["right_or_tie"]
        c["tie_to_wrong"] += o["right_or_tie"] and not r["right_or_tie"]
        mark = "+" if r["right"] and not o["right"] else "-" if o["right"] and not r["right"] else " "
        out(f"{mark} {r['case'][:60]:60s} {r['seed']}  {','.join(o['effects']) or '-'} {o['verdict']} -> "
            f"{','.join(r['effects']) or '-'} {r['verdict']}")
    res = {k: c[k] for k in ("changed", "to_right", "to_wrong", "tie_to_right", "tie_to_wrong")}
    res["missing"] = missing
    out(f"changed answers: {res['changed']} of {len(rows) - missing} runs; right: +{res['to_right']} "
        f"-{res['to_wrong']} (net {res['to_right'] - res['to_wrong']:+d}); right up to a near tie: "
        f"+{res['tie_to_right']} -{res['tie_to_wrong']}" + (f"; {missing} runs not in the saved file" if missing
                                                            else ""))
    return res


def _finish(a, rows, seconds, saved):
    """The figures of `rows`, their comparison with the `saved` rows (if any) and the --csv file."""
    summarise(rows, seconds)
    if saved is not None:
        print()
        compare(rows, saved)
    if a.csv:
        write_csv(rows, a.csv, a.measured_on)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--set", choices=[*SETS, "all"], default="tuning")
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--cases", nargs="*", default=None)
    p.add_argument("--json", default=None)
    p.add_argument("--csv", default=None, help="write the runs to a results file (one run a line)")
    p.add_argument("--perturb", type=float, default=0.0, metavar="SHARE",
                   help="move each record's output by noise of SHARE times its true noise first (with "
                        "--compare: how many answers rest on the data's last digits)")
    p.add_argument("--measured-on", metavar="COMMIT", default="",
                   help="the commit the runs were made on, written in --csv's measured_on column")
    p.add_argument("--compare", metavar="SAVED", default=None,
                   help="list the runs whose answer differs from a saved --json or --csv file's")
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--summary", metavar="JSON", default=None,
                   help="print the figures and the breakdown of wrong runs of an earlier run's --json file, "
                        "without running")
    a = p.parse_args(argv)
    if a.perturb < 0:
        p.error(f"--perturb {a.perturb}: should be 0 or more (a share of the true noise)")
    saved = None
    if a.compare:
        try:
            saved, _ = load_rows(a.compare)
        except (OSError, ValueError, KeyError, TypeError) as exc:
            p.error(f"--compare {a.compare!r}: not a --json or --csv file of this script ({exc})")
    if a.summary:
        try:
            rows, seconds = load_rows(a.summary)
        except (OSError, ValueError, KeyError, TypeError) as exc:
            p.error(f"--summary {a.summary!r}: not a --json or --csv file of this script ({exc})")
        _finish(a, rows, seconds, saved)
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
            rows = list(ex.map(run_one, *zip(*jobs), [a.perturb] * len(jobs)))
    else:
        one_blas_thread()
        rows = [run_one(n, s, a.perturb) for n, s in jobs]
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
    _finish(a, rows, total, saved)
    if a.json:
        with open(a.json, "w") as fh:
            json.dump({"rows": rows, "right": sum(r["right"] for r in rows), "n": len(rows), "seconds": total},
                      fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
