"""Issue 10's acceptance on a sample of the realistic records, in the default suite.

The full acceptance (``tests/test_diagnose_realistic.py``: every case of the sixty sets at
seed 0, about 1,200 CPU-seconds) is marked ``slow`` and runs with ``pytest -m slow``; the
benchmark ``benchmarks/eval_diagnose_realistic.py`` runs three seeds. This sample keeps the
issue's criteria in every run of the suite (and CI) at a fourteenth of the cost: three whole sets,
the three quickest to diagnose (HOLDOUT4, HOLDOUT9 and HOLDOUT14: 82 CPU-seconds at seed 0 in
round 22, each with its clean, out-of-vocabulary and pair case), and the clean record of every
other set (64 clean records in all, HOLDOUT33's and HOLDOUT42's left to the slow test since round 58, see
SLOW_CLEAN; HOLDOUT59's took 11.4 s in round 61's measurement). 91 runs at seed 0; 82 were right in round 61, 81 in
round 60, 80 in rounds 59 and 58, 79 in round 57, 78 in rounds 56 and 55 (77 in round 54, 75 in round 53)
(HOLDOUT9's unipolar generalized plays until round 36's rule on small later steps, HOLDOUT14's eddy-field separation and, since round 32's drift of
events, HOLDOUT14's anhysteretic bias read as a drift, a near tie, were not; HOLDOUT21's
clean record joined in round 24, HOLDOUT22's in round 25, HOLDOUT23's and HOLDOUT24's in round 26,
HOLDOUT25's in round 27, HOLDOUT26's in round 28: a bolted joint's Iwan core, which round 28's finer
core explains with 40 plays; with 20 a drift was named on it when the set was fresh; HOLDOUT27's in round 29,
HOLDOUT28's in round 30, HOLDOUT29's in round 31, HOLDOUT30's in round 32, HOLDOUT31's in round 33,
HOLDOUT32's in round 34: a guide with Dahl friction, not a PI core, left unexplained with nothing named and so
counted wrong against its label, see NOT_PI_CLEAN; HOLDOUT33's in round 35: a Stoner-Wohlfarth armature, not a PI core
either, likewise; HOLDOUT34's in round 36: a stage on stiffening Gent rubber pads, read as a saturation, `explained`,
counted wrong, see SATURATING_CLEAN; HOLDOUT35's in round 37: a push-pull cable with capstan friction, not a PI
core, left unexplained with nothing named at seed 0, see NOT_PI_CLEAN; HOLDOUT36's in round 38: a servo valve
whose iron is a random-field Ising model, read as a saturation at seed 0, `explained`, counted wrong, see
SATURATING_CLEAN; HOLDOUT37's in round 39: a push-pull pair of liquid-nanofoam cells, `explained` with nothing named at
seed 0; HOLDOUT38's in round 40: a rod pushed through friction bushes with free play, `explained` with nothing named at
seed 0; HOLDOUT39's in round 41: a superconducting rod in Kim's critical state, not a PI core, left unexplained with
nothing named at seed 0, see NOT_PI_CLEAN; HOLDOUT40's in round 42: a soft PZT disc whose grains switch, read as a
saturation at seed 0, `explained`, counted wrong, see SATURATING_CLEAN; HOLDOUT41's in round 43: a ferrite ring whose
domain walls are pinned in random landscapes, `explained` with nothing named at seed 0; HOLDOUT42's in round 44: a
shape-memory wire against a bias spring, not a PI core, left unexplained with nothing named at seed 0, see
NOT_PI_CLEAN; HOLDOUT43's in round 45: an electrowetting drop whose contact line is pinned, `explained` with nothing
named at seed 0; HOLDOUT44's in round 46: an antagonistic pair of pneumatic muscles whose braids' contacts slide with
dry friction, `explained` with nothing named at seed 0; HOLDOUT45's in round 47: a prestressed Terfenol-D rod,
`explained` with a saturation held tentative at seed 0; HOLDOUT46's in round 48: a polypyrrole bilayer bender whose
domains switch as Frumkin lattice gases, left unexplained with nothing named at seed 0, see SATURATING_CLEAN;
HOLDOUT47's in round 49: a polarised pair of magnetorheological clutches, `explained` with a saturation held
tentative at seed 0; HOLDOUT48's in round 50: a magnetic shape-memory element, `explained` with a small saturation held
tentative at seed 0; HOLDOUT49's in round 51: a Galfenol rod whose strain is lopsided about its bias, an asymmetry
named at seed 0, `explained`, counted wrong until round 54, see ASYMMETRIC_CLEAN; HOLDOUT50's in round 52: a harmonic drive whose
teeth are wedges with friction in series with their compliance, not a PI core, left unexplained with nothing named at
seed 0, see NOT_PI_CLEAN; HOLDOUT51's in round 53: a PMN-PT relaxor stack whose strain is electrostrictive (even in
the polarisation) about its bias, an asymmetry named at seed 0, `explained`, counted wrong until round 54, see
ASYMMETRIC_CLEAN; since round 54 a first asymmetry on an explained record needs 1.5 noise variances, and these two
gained 1.30 and 0.54; HOLDOUT52's in round 54: a paraffin-in-silica phase-change film whose pores melt along
their walls and freeze through their mouths, an asymmetry named at seed 0 (3.44 noise variances), `explained`, counted
wrong, see ASYMMETRIC_CLEAN; HOLDOUT53's in round 55: a metal-hydride cell whose particles switch between their
absorption and desorption plateaus, `explained` with nothing named at seed 0 (an asymmetry at seeds 1 and 2, see
ASYMMETRIC_CLEAN); HOLDOUT54's in round 56: a spin-crossover strip whose crystallites switch as cooperative
Slichter-Drickamer bodies, a drift of events named at seed 0 (0.79 noise variances), `explained`, counted wrong, see
DRIFTING_CLEAN; HOLDOUT55's in round 57: a P(VDF-TrFE) unimorph whose crystallites are relays of the field,
`explained` with nothing named at seed 0 (an asymmetry at seed 2); HOLDOUT56's in round 58: a VO2 thin-film bimorph
whose grains switch between the insulating and the metallic phase, `explained` with nothing named; HOLDOUT57's in round
59: a Bragg mirror of salted mesoporous silica whose cages fill and empty at two humidities, `unexplained` with nothing
named at seed 0 (2.02 true noise levels), counted wrong, see NOT_PI_CLEAN; HOLDOUT58's in round 60: a chip of 400
pre-buckled silicon beams that snap between their two states, pressed through soft springs, `explained` with nothing
named at seed 0). Since
round 45 HOLDOUT35's and HOLDOUT39's clean cores are `explained` by a
Preisach-type core with nothing named, counted right; since round 47 HOLDOUT36's and HOLDOUT40's small saturations are
tentative, not named, and those records counted right.
"""

import os
import sys
from concurrent.futures import ProcessPoolExecutor

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "benchmarks"))

from eval_diagnose_realistic import one_blas_thread, run_one  # noqa: E402
from realistic import ALL, family  # noqa: E402
from test_diagnose_realistic import NOT_PI_CLEAN, SATURATING_CLEAN, _named_on_clean, _over, _table  # noqa: E402

pytestmark = pytest.mark.realistic
SEED = 0
#: the whole sets in the sample (the three quickest to diagnose at seed 0 in round 22)
SETS = ("holdout4_", "holdout9_", "holdout14_")


#: clean records left to the slow acceptance test: the two slowest of the sample to diagnose (43.6 and
#: 35.2 s at seed 0, 37 % of the sample's time), both cores that are not PI models and stay `unexplained`
#: with nothing named; since round 58, to keep CI within its 20 minutes
SLOW_CLEAN = ("holdout33_clean_sw_armature_footbridge_crowd_sway_1725hz",
              "holdout42_clean_niti_wire_bias_spring_tower_crane_1370hz")


def _in_sample(name):
    # every set names its clean case "clean_..." or "<set>_clean_..." (test_the_sample checks
    # that these are the clean records: no effect, verdict explained)
    return (name.startswith(SETS) or name.startswith("clean_") or "_clean_" in name) and name not in SLOW_CLEAN


@pytest.fixture(scope="module")
def rows():
    jobs = sorted(n for n in ALL if _in_sample(n))
    with ProcessPoolExecutor(2, initializer=one_blas_thread) as ex:
        return list(ex.map(run_one, jobs, [SEED] * len(jobs)))


def test_the_sample(rows):
    assert len(rows) == 91
    assert sum(r["clean"] for r in rows) == 64
    assert sum(r["case"].startswith(SETS) for r in rows) == 30
    # outside the three sets, the sample is every set's clean record and nothing else
    assert all(r["clean"] for r in rows if not r["case"].startswith(SETS))


def test_no_crash(rows):
    bad = [r for r in rows if r["error"]]
    assert not bad, _table(bad)


def test_right_verdict_no_worse_than_measured(rows):
    # 82/91 right in round 61 (HOLDOUT59's clean microgel film right at seed 0); 81/90 in round 60 (HOLDOUT58's
    # clean beam chip right at seed 0); 80/89 in round 59 (HOLDOUT57's clean
    # Bragg mirror wrong at seed 0: unexplained, nothing named); 80/88 in
    # round 58 (HOLDOUT56's clean bimorph right at seed 0; HOLDOUT33's and HOLDOUT42's clean
    # records, wrong, left to the slow test, SLOW_CLEAN); 79/89 in round 57 (HOLDOUT55's clean unimorph right at seed 0); 78/88 in round 56 (HOLDOUT54's clean strip wrong at seed 0: a drift); 78/87 in round 55 (HOLDOUT53's clean cell right at seed 0; 77/86 in round 54, 75/85 in round 53; round 22's 52/54, one fewer since round 32, one more since round 36,
    # and the clean records of HOLDOUT21-51, HOLDOUT32's, HOLDOUT33's, HOLDOUT34's, HOLDOUT42's, HOLDOUT46's and
    # HOLDOUT50's and HOLDOUT52's counted wrong; HOLDOUT49's and HOLDOUT51's right since round 54's rule on first
    # asymmetries;
    # HOLDOUT35's and HOLDOUT39's right since round 45's Preisach-type core, HOLDOUT36's and HOLDOUT40's since
    # round 47's rule on small saturations of explained records); at least 79 (87 %):
    # three runs of margin for decisions that sit on a threshold and may fall
    # the other way on another machine's BLAS
    right = sum(r["right"] for r in rows)
    assert right >= 79, f"{right}/{len(rows)} right\n" + _table([r for r in rows if not r["right"]])


def test_no_effect_named_on_clean_records(rows):
    # beside the known exceptions (NOT_PI_CLEAN, SATURATING_CLEAN, ASYMMETRIC_CLEAN, DRIFTING_CLEAN: see
    # test_diagnose_realistic.py)
    named = _named_on_clean(rows)
    assert not named, _table(named)


@pytest.mark.xfail(strict=False, reason="issue 10 open: a saturation is named on HOLDOUT34's clean stage on "
                                        "stiffening Gent rubber pads at seed 0 (round 36, fresh and as committed; "
                                        "3.50 noise variances) and an asymmetry on HOLDOUT52's phase-change film "
                                        "(round 54, 3.44) and a drift on HOLDOUT54's spin-crossover strip (round 56, 0.79); "
                                        "HOLDOUT36's and HOLDOUT40's small saturations "
                                        "are tentative since round 47, HOLDOUT49's and HOLDOUT51's first asymmetries "
                                        "(1.30 and 0.54) since round 54")
def test_no_effect_named_on_any_clean_record(rows):
    assert len([r for r in rows if r["case"] in SATURATING_CLEAN]) == 5
    named = [r for r in rows if r["clean"] and r["effects"]]
    assert not named, _table(named)


def test_a_clean_core_that_is_not_pi_gets_nothing_named(rows):
    # round 34: a saturation (a cubic output map, 22 % of the base misfit above the noise) was
    # named on it at seed 0 until naming on an unexplained record asked for 40 %
    # (HOLDOUT32's Dahl friction); HOLDOUT33's Stoner-Wohlfarth armature leaves 5.6-8.3 floors with
    # its parts tentative; HOLDOUT35's capstan cable 1.32 floors at seed 0 with nothing paying; HOLDOUT39's
    # critical-state rod 1.33 floors at seed 0 with nothing paying; HOLDOUT42's shape-memory wire 3.60 floors at
    # seed 0 with its asymmetry tentative; HOLDOUT50's harmonic drive 1.41 floors at seed 0 with nothing paying;
    # HOLDOUT57's salted-cage Bragg mirror 2.03 floors at seed 0 with nothing paying (round 59)
    not_pi = [r for r in rows if r["case"] in NOT_PI_CLEAN]
    assert len(not_pi) == len(NOT_PI_CLEAN) - len(SLOW_CLEAN) == 5
    assert all(not r["effects"] for r in not_pi), _table(not_pi)
    # since round 45 a Preisach-type core is taken where it explains a record left unexplained with nothing
    # named: HOLDOUT39's rod (1.10 noise floors) at seed 0, within the explained bound (about 1.45) by a margin no
    # BLAS moves, and HOLDOUT35's cable (1.01) until round 57, since when the blocks split explains the cable with
    # the PI model and nothing named before a Preisach-type core is tried; the other five stay unexplained (the
    # KP core 1.66, 3.88 and 3.42 on HOLDOUT32's, HOLDOUT33's and HOLDOUT42's, the last two in the slow test only,
    # 3.86 on HOLDOUT57's mirror against the PI model's 2.03, and, on HOLDOUT50's harmonic drive, 1.50 against the PI
    # model's 1.41: not taken)
    taken = {r["case"].split("_")[0] for r in not_pi if (r["preisach_core"] or {}).get("taken")}
    assert taken == {"holdout39"}, _table(not_pi)
    explained = taken | {"holdout35"}
    assert all(r["verdict"] == ("explained" if r["case"].split("_")[0] in explained else "unexplained")
               for r in not_pi), _table(not_pi)


def test_explained_means_within_the_noise(rows):
    over = [r for r in rows if r["explained_over_limit"]]
    assert not over, _over(over)
    assert all(r["rms_heldout"] <= 1.5 * r["noise_floor"] for r in rows if r["verdict"] == "explained")


def test_out_of_vocabulary_records_are_unexplained(rows):
    oov = [r for r in rows if "_oov_" in r["case"]]
    assert len(oov) == 3
    wrong = [r for r in oov if r["verdict"] != "unexplained" or r["effects"]]
    assert not wrong, _table(wrong)


def test_both_effects_named_in_combined_cases(rows):
    # the sample's three pairs were named in full in round 22 (the full set's misses are elsewhere)
    comb = [r for r in rows if r["combined"]]
    assert len(comb) == 3
    missed = [r for r in comb if not family(r["expected"]) <= family(r["effects"])]
    assert not missed, _table(missed)
