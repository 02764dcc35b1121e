"""The committed runs of the realistic evaluation (``benchmarks/results/diagnose_realistic.csv``)
against the sets they come from and the figures docs/diagnose.md gives for them.

The file holds every run of the committed sets (ALL, three seeds) as measured; the docs' sets
table ("as committed" column and the "all" row), its trust table's committed columns and its
table of wrong runs are counted from it here, so a figure in the docs that no run supports, or a
set joined without its runs, fails.  The runs themselves are not made again (that is the slow
acceptance test and the benchmark's work); the file's ``right`` is checked against its own named
effects and verdict by the sets' rule (families equal, verdict fitting)."""

import itertools
import os
import re
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))

from eval_diagnose_realistic import SETS, breakdown, compare, read_csv, set_of  # noqa: E402
from realistic import ALL, family  # noqa: E402

RESULTS = os.path.join(ROOT, "benchmarks", "results", "diagnose_realistic.csv")
DOCS = os.path.join(ROOT, "docs", "diagnose.md")
SEEDS = (0, 1, 2)


@pytest.fixture(scope="module")
def rows():
    return read_csv(RESULTS)


@pytest.fixture(scope="module")
def docs():
    with open(DOCS) as fh:
        return fh.read()


def _judge(row, effects=None):
    effects = row["effects"] if effects is None else effects
    return family(effects) == family(row["expected"]) and (
        row["expect_verdict"] == "either" or row["verdict"] == row["expect_verdict"])


def test_every_committed_run_once(rows):
    """Each case of ALL at seeds 0-2, once, under its set's name, and nothing else."""
    keys = [(r["case"], r["seed"]) for r in rows]
    assert len(keys) == len(set(keys))
    assert set(keys) == {(c, s) for c in ALL for s in SEEDS}
    assert all(r["set"] == set_of(r["case"]) for r in rows)
    # each row says which commit it was measured on (a short hash)
    assert all(re.fullmatch(r"[0-9a-f]{7,40}", r["measured_on"]) for r in rows)


def test_right_follows_from_the_answer(rows):
    """``right`` and ``right_or_tie`` are what the sets' rule makes of the named effects,
    the verdict and the reported near ties; clean and combined what the expectation says."""
    for r in rows:
        assert r["right"] == (r["error"] is None and _judge(r)), r["case"]
        options = [[e] + list(r["ambiguous"].get(e, [])) for e in r["effects"]]
        tie = r["error"] is None and any(_judge(r, list(c)) for c in itertools.product(*options))
        assert r["right_or_tie"] == tie, r["case"]
        assert r["clean"] == (not r["expected"] and r["expect_verdict"] == "explained")
        assert r["combined"] == (len(family(r["expected"])) >= 2)


def _sets_table(docs):
    """{set name in the table: (right, right up to a near tie)} of the sets table's last column,
    and the "all" row's (right, runs, tie, seed-0 right, seed-0 runs)."""
    table = {}
    total = None
    for line in docs.splitlines():
        m = re.match(r"\| (tuning|held-out|HOLDOUT\d+) \| `cases[\w.]*` \| \d+ \| [^|]* \| (\d+)/\d+ \((\d+)\) \|$",
                     line)
        if m:
            table[m.group(1)] = (int(m.group(2)), int(m.group(3)))
        m = re.match(r"\| all [\w-]+ \| \| \d+ \| \| \*\*(\d+)/(\d+), [\d.]+ % \((\d+)\)\*\*; seed 0: (\d+)/(\d+) \|$",
                     line)
        if m:
            total = tuple(int(x) for x in m.groups())
    return table, total


def test_docs_sets_table_counts_the_runs(rows, docs):
    """Every set's "as committed" right (and up to a near tie) in docs/diagnose.md, and the
    "all" row, are the file's counts."""
    table, total = _sets_table(docs)
    names = {"tuning": "tuning", "holdout": "held-out"}
    expected = {}
    for r in rows:
        key = names.get(r["set"], r["set"].upper())
        right, tie = expected.get(key, (0, 0))
        expected[key] = (right + r["right"], tie + r["right_or_tie"])
    assert table == expected
    seed0 = [r for r in rows if r["seed"] == 0]
    assert total == (sum(r["right"] for r in rows), len(rows), sum(r["right_or_tie"] for r in rows),
                     sum(r["right"] for r in seed0), len(seed0))


#: the trust table's rows: one effect family each (drift and gain drift one family, as saturation and output
#: saturation are)
TRUST_FAMILIES = ("saturation", "asymmetry", "creep", "delay", "initial_state", "rate_dependence", "drift")


def test_docs_trust_table_committed_columns(rows, docs):
    """The trust table's "as committed" columns (right when named, found) are the file's."""
    found = {}
    for line in docs.splitlines():
        m = re.match(r"\| `(\w+)` \| \d+ \| [^|]+ \| [^|]+ \| (\d+) of (\d+) \(\d+ %\) \| (\d+) of (\d+) \(\d+ %\) \|$",
                     line)
        if m and m.group(1) in TRUST_FAMILIES:
            found[m.group(1)] = tuple(int(x) for x in m.groups()[1:])
    assert set(found) == set(TRUST_FAMILIES)
    for fam in TRUST_FAMILIES:
        named = [r for r in rows if fam in family(r["effects"])]
        right = sum(fam in family(r["expected"]) for r in named)
        held = sum(fam in family(r["expected"]) for r in rows)
        assert found[fam] == (right, len(named), right, held), fam


def test_docs_wrong_runs_table(rows, docs):
    """The table of wrong runs by kind (runs, right up to a near tie, unexplained) is the file's."""
    b = breakdown(rows)
    text = {"verdict": "the right effects named, the wrong verdict",
            "missed": "an expected effect missed, nothing else named",
            "extra": "every expected effect named, and another beside them",
            "confused": "an expected effect missed and another named instead"}
    for kind, label in text.items():
        m = re.search(r"^\| " + re.escape(label) + r" \| (\d+) \| (\d+) \| (\d+) \|$", docs, re.M)
        assert m, label
        entry = b["kinds"].get(kind, {"count": 0, "tie": 0, "unexplained": 0})
        assert tuple(int(x) for x in m.groups()) == (entry["count"], entry["tie"], entry["unexplained"]), kind


def test_every_set_is_in_the_file(rows):
    """A set joined to ALL brings its runs: every set with a case in ALL has 3 runs a case here."""
    for name, cases in SETS.items():
        joined = [c for c in cases if c in ALL]
        if joined:
            assert sum(r["set"] == name for r in rows) == 3 * len(joined), name


def test_compare_with_itself_changes_nothing(rows):
    """The run-by-run comparison finds no change between the file and itself, and one when an
    answer is changed."""
    lines = []
    assert compare(rows, rows, out=lines.append)["changed"] == 0
    changed = [dict(r) for r in rows]
    changed[0] = dict(changed[0], effects=changed[0]["effects"] + ["creep"], right=False, right_or_tie=False)
    res = compare(changed, rows, out=lines.append)
    assert res["changed"] == 1 and res["to_wrong"] == int(rows[0]["right"])
