"""Every example in a method of a class shown under another module than the one it is written in runs as a doctest.

A public module that re-homes a class (sets its ``__module__``: ``hystcomp.envelopes.Envelope``,
``hystcomp.identify.FitResult``, ``hystcomp.loops.Comparison``, ...) must name the class's method examples in its
``__test__`` (``hystcomp._doctest_home.method_examples``): doctest skips a method whose globals are another module's,
and until round 39 twelve such examples (FitResult's, HysteresisRegressor's, ModelComparison's and Comparison's) never
ran.
"""

import importlib
import inspect
import pkgutil

import hystcomp
from hystcomp._doctest_home import method_examples


def _modules():
    for info in pkgutil.walk_packages(hystcomp.__path__, "hystcomp."):
        if not info.name.endswith("__main__"):
            yield importlib.import_module(info.name)


def test_every_rehomed_method_example_is_in_its_modules_test_dict():
    missing, seen = [], 0
    for mod in _modules():
        named = {id(f) for f in getattr(mod, "__test__", {}).values()}
        for cname, cls in vars(mod).items():
            if not inspect.isclass(cls) or cls.__module__ != mod.__name__:
                continue
            for key, func in method_examples(cls).items():
                if func.__globals__ is not vars(mod):
                    seen += 1
                    if id(func) not in named:
                        missing.append(f"{mod.__name__}: {key}")
    assert not missing, missing
    # the envelope base class's three, FitResult's four, HysteresisRegressor's five, ModelComparison's one and
    # Comparison's two (round 39): the walk finds the re-homed classes at all
    assert seen >= 15


def test_method_examples_takes_properties_and_static_methods_and_skips_the_rest():
    class Demo:
        @property
        def size(self):
            """>>> 1
            1
            """
            return 1

        @staticmethod
        def make():
            """>>> 2
            2
            """

        def plain(self):
            """No example."""

    found = method_examples(Demo)
    assert sorted(found) == ["Demo.make", "Demo.size"]
    assert found["Demo.size"] is Demo.size.fget
