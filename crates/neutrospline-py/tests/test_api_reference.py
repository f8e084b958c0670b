"""The Python API reference (pdoc, as scripts/python-tests builds it into target/python-docs)
documents every public name with its docstring."""

import inspect

import pdoc

import neutrospline


def test_pdoc_documents_every_public_name(tmp_path):
    pdoc.pdoc("neutrospline", output_directory=tmp_path)
    page = (tmp_path / "neutrospline.html").read_text()
    for name in neutrospline.__all__:
        if name == "__version__":
            continue
        assert f'id="{name}"' in page, name
    # Docstrings come through, with their examples: the module's own first line and fit's.
    assert "neutrosophic Bézier, B-spline and NURBS curves and surfaces" in page
    first_line = inspect.getdoc(neutrospline.fit).splitlines()[0]
    assert first_line.split("`")[0][:40] in page
