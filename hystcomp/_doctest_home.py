"""Doctests of classes shown under another module than the one they are written in.

Several public modules re-home classes written in private ones (``Envelope`` in
``hystcomp.envelopes``, ``FitResult`` in ``hystcomp.identify``, ``Comparison``
in ``hystcomp.loops``, ...) by setting their ``__module__``, so that the API
reference, ``repr`` and pickling name the public module.  :mod:`doctest` then
finds the class's own docstring under the public module, but skips its
methods: a method's globals are the private module's.  A public module names
them in its ``__test__`` with :func:`method_examples`, and their examples run.
"""

__all__ = ["method_examples"]


def method_examples(*classes):
    """``{"Class.method": function}`` for every method, property, class method
    and static method of `classes` (their own, not inherited) whose docstring
    has an example (``>>>``); for a module's ``__test__``.

    Examples
    --------
    >>> class Demo:
    ...     def shown(self):
    ...         '''>>> 1 + 1
    ...         2
    ...         '''
    ...     def quiet(self):
    ...         "no example"
    >>> sorted(method_examples(Demo))
    ['Demo.shown']
    """
    found = {}
    for cls in classes:
        for name, attr in vars(cls).items():
            func = attr.fget if isinstance(attr, property) else getattr(attr, "__func__", attr)
            if callable(func) and ">>>" in (getattr(func, "__doc__", None) or ""):
                found[f"{cls.__name__}.{name}"] = func
    return found
