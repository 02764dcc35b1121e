"""Acceptance of issue 10: the diagnosis on realistic records it was not built from.

Every case of the tuning, held-out and HOLDOUT2-5 sets of ``tests/realistic`` (one seed each
here, the benchmark ``benchmarks/eval_diagnose_realistic.py`` runs three) is diagnosed once, on two processes, and judged against the issue's criteria:

- the right verdict (named effect families equal the expected ones, verdict as expected) in
  at least 90 % of runs;
- no effect named on a clean record;
- every "explained" verdict within 1.5x the TRUE sensor noise (known to the generator);
- both effects named in every combined case.
"""

import os
import sys
from concurrent.futures import ProcessPoolExecutor

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "benchmarks"))

from eval_diagnose_realistic import EXPLAINED_LIMIT, run_one  # noqa: E402
from realistic import ALL, family  # noqa: E402

pytestmark = pytest.mark.realistic
SEED = 0


@pytest.fixture(scope="module")
def rows():
    jobs = sorted(ALL)
    with ProcessPoolExecutor(2) as ex:
        return list(ex.map(run_one, jobs, [SEED] * len(jobs)))


def _table(rows):
    return "\n".join(f"{r['case']}: expected {r['expected']} {r['expect_verdict']}, got "
                     f"{r['effects']} {r['verdict']}" + (f" [{r['error']}]" if r["error"] else "")
                     for r in rows)


def test_no_crash(rows):
    bad = [r for r in rows if r["error"]]
    assert not bad, _table(bad)


# Not met yet over every set (issue 10 stays open): measured with three seeds, 197/225 (88 %)
# over the six sets as committed; on each fresh set when it was fresh 21/36 (held-out), 17/30
# (HOLDOUT2), 19/30 (HOLDOUT3), 28/30 (HOLDOUT4) and 20/33 (HOLDOUT5); 64/75 here at seed 0;
# combined cases 31/33 (docs/diagnose.md). Strict: the suite says so when the criterion starts
# to hold.
@pytest.mark.xfail(strict=True, reason="issue 10 open: 88 % right over the six sets (target 90 %)")
def test_right_verdict_in_90_percent_of_runs(rows):
    right = sum(r["right"] for r in rows)
    assert right >= 0.9 * len(rows), f"{right}/{len(rows)} right\n" + _table([r for r in rows if not r["right"]])


def test_no_effect_named_on_clean_records(rows):
    clean = [r for r in rows if r["clean"]]
    assert len(clean) >= 5
    named = [r for r in clean if r["effects"] or r["verdict"] != "explained"]
    assert not named, _table(named)


def test_explained_means_within_the_noise(rows):
    over = [r for r in rows if r["explained_over_limit"]]
    assert not over, "\n".join(f"{r['case']}: {r['rms_heldout'] / r['true_noise']:.2f}x > "
                               f"{EXPLAINED_LIMIT}x the true noise" for r in over)


@pytest.mark.xfail(strict=True, reason="issue 10 open: both effects named in 31/33 runs of the combined "
                                        "cases of the six sets")
def test_both_effects_named_in_combined_cases(rows):
    comb = [r for r in rows if r["combined"]]
    assert len(comb) >= 4
    missed = [r for r in comb if not family(r["expected"]) <= family(r["effects"])]
    assert not missed, _table(missed)
