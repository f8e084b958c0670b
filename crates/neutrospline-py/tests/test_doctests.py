"""Every docstring example of the package runs and prints what it shows."""

import doctest
import inspect

import neutrospline


def public_objects():
    yield "neutrospline", neutrospline
    for name in neutrospline.__all__:
        obj = getattr(neutrospline, name)
        yield name, obj
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if not attr.startswith("__") or attr == "__call__":
                    yield f"{name}.{attr}", member


def test_docstring_examples(in_root):
    finder = doctest.DocTestFinder(recurse=False)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    examples = 0
    for name, obj in public_objects():
        doc = getattr(obj, "__doc__", None)
        if not isinstance(doc, str):
            continue
        for test in finder.find(obj, name, globs={}):
            examples += len(test.examples)
            runner.run(test)
    results = runner.summarize(verbose=False)
    assert results.failed == 0
    # Every class and function documents at least one example; the count guards against a
    # finder that silently finds nothing.
    assert examples >= 30


def test_every_public_name_has_a_docstring():
    for name, obj in public_objects():
        if name.count(".") == 0 and name != "instruction_set":
            assert (obj.__doc__ or "").strip(), name
