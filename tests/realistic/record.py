"""The record a case returns, and how named effects are scored."""

from dataclasses import dataclass, field

import numpy as np

#: effect name -> family; names in one family are interchangeable when scoring
FAMILIES = {
    "drift": "drift", "gain_drift": "drift",
    "saturation": "saturation", "output_saturation": "saturation",
    "rate_dependence": "rate_dependence", "creep": "creep", "asymmetry": "asymmetry",
    "delay": "delay", "initial_state": "initial_state",
}


def family(names):
    """The set of families of effect names (unknown names stay as they are)."""
    return frozenset(FAMILIES.get(n, n) for n in names)


@dataclass
class Record:
    """A realistic record with what a correct diagnosis says about it.

    ``expect_verdict`` is "explained", "unexplained" or, where the mechanism is in the
    vocabulary but its law differs from any hystcomp part (so a fit to the noise floor is
    not guaranteed), "either". ``noise_std`` is the true output sensor noise.
    """

    name: str
    seed: int
    t: np.ndarray | None
    v: np.ndarray
    y: np.ndarray
    expect_effects: frozenset
    expect_verdict: str
    noise_std: float
    note: str = ""
    extra: dict = field(default_factory=dict)

    def judge(self, effects, verdict):
        """True when the named families equal the expected ones and the verdict fits."""
        ok_effects = family(effects) == family(self.expect_effects)
        ok_verdict = self.expect_verdict == "either" or verdict == self.expect_verdict
        return ok_effects and ok_verdict


def finish(name, seed, t, v_drive, y_clean, expect, verdict, note, rng,
           monitor_noise=0.0, output_noise=0.002):
    """Add sensor noise (fractions of the spans) and wrap as a :class:`Record`.

    The recorded input is the drive plus ``monitor_noise`` x its span (an amplifier's
    monitor output); the actuator itself was driven by the clean ``v_drive``.
    """
    v_drive = np.asarray(v_drive, float)
    y_clean = np.asarray(y_clean, float)
    v_rec = v_drive + monitor_noise * np.ptp(v_drive) * rng.standard_normal(len(v_drive))
    sigma = output_noise * np.ptp(y_clean)
    y = y_clean + sigma * rng.standard_normal(len(y_clean))
    return Record(name, seed, t, v_rec, y, frozenset(expect), verdict, sigma, note)


def case_set(prefix, salt_base):
    """One set's registry: ``(cases, case, rng)``.

    ``case`` registers a case function under ``prefix + its name`` in the dict
    ``cases``; ``rng(seed, salt)`` is ``default_rng([seed, salt_base + salt])``, so the
    sets draw from disjoint streams.
    """
    cases = {}

    def case(fn):
        cases[prefix + fn.__name__] = fn
        return fn

    def rng(seed, salt):
        return np.random.default_rng([seed, salt_base + salt])

    return cases, case, rng
