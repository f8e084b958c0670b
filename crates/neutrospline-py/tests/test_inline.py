"""The figure a notebook shows (`_repr_svg_`, `_repr_png_`) and the module setting `inline()`
that chooses it: a notebook size, a responsive SVG root, a PNG beside it, surfaces' SVG under
200 KB."""

import re
import struct

import pytest

import neutrospline as ns


@pytest.fixture(autouse=True)
def default_inline():
    ns.inline(reset=True)
    yield
    ns.inline(reset=True)


def root_of(svg):
    return re.search(r"<svg [^>]*>", svg).group(0)


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_the_default_is_a_responsive_svg_and_a_png_at_a_notebook_size():
    curve = ns.example1()
    root = root_of(curve._repr_svg_())
    assert 'width="100%"' in root
    assert 'style="max-width: 800px; height: auto"' in root
    assert 'viewBox="0 0 800 600"' in root
    assert "height=" not in root.replace('height: auto', "")
    assert png_size(curve._repr_png_()) == (800, 600)
    # The inline SVG is to_svg's figure at that size, only the root differs.
    plain = curve.to_svg(width=800, height=600)
    assert curve._repr_svg_().replace(root, "") == plain.replace(root_of(plain), "")


def test_the_setting_chooses_view_format_and_size():
    setting = ns.inline(view="truth", format="svg", width=640, height=480)
    assert (setting["view"], setting["format"], setting["width"]) == ("truth", "svg", "640")
    curve = ns.example1()
    assert curve._repr_png_() is None
    svg = curve._repr_svg_()
    assert "curve: truth</title>" in svg
    assert 'viewBox="0 0 640 480"' in root_of(svg)
    ns.inline(format="png")
    assert curve._repr_svg_() is None
    assert png_size(curve._repr_png_()) == (640, 480)


def test_refusals_are_the_figure_options_messages():
    with pytest.raises(ns.ModelError, match="format"):
        ns.inline(format="gif")
    with pytest.raises(ns.ModelError, match="view"):
        ns.inline(view="sideways")
    # A refused setting changes nothing.
    assert ns.inline()["view"] is None


def test_a_surface_inline_svg_is_under_200_kb(root):
    surface = ns.load(root / "examples/surface.toml")
    svg = surface._repr_svg_()
    assert len(svg.encode()) < 200_000, len(svg.encode())
    # The full figure (40 samples a direction) is several times larger.
    assert len(surface.to_svg().encode()) > 2 * len(svg.encode())
    assert ns.inline(samples=30)["samples"] == "30"
    assert len(surface._repr_svg_().encode()) > len(svg.encode())
