"""The membership families beyond the original three in Python (docs/model.md, "Membership
families"): the family as an argument and a property, degrees given as the family's channels,
values on the rule's boundary blended inside it, the refusals with the rule, files of every
family, and fitting under a round rule."""

import numpy as np
import pytest

import neutrospline as ns


def test_a_pythagorean_curve_from_its_two_channels(tmp_path):
    positions = [[0, 0], [1, 2], [3, 2.5], [4, 0.5]]
    # truth, falsity: P1 and P2 on the boundary truth^2 + falsity^2 = 1.
    degrees = [[0.9, 0.3], [0.8, 0.6], [0.6, 0.8], [0.5, 0.5]]
    curve = ns.Bezier(positions, degrees, membership="pythagorean")
    assert curve.membership == "pythagorean"
    t = np.linspace(0, 1, 10001)
    values = curve(t)
    truth, indeterminacy, falsity = values[:, 2], values[:, 3], values[:, 4]
    s = 1 - t
    bernstein = np.stack([s**3, 3 * s * s * t, 3 * s * t * t, t**3], axis=1)
    np.testing.assert_allclose(truth, bernstein @ [0.9, 0.8, 0.6, 0.5], rtol=0, atol=1e-15)
    np.testing.assert_allclose(falsity, bernstein @ [0.3, 0.6, 0.8, 0.5], rtol=0, atol=1e-15)
    assert np.all(indeterminacy == 0)
    assert np.all(truth**2 + falsity**2 <= 1 + 1e-12)
    saved = tmp_path / "p.toml"
    curve.save(saved)
    assert 'membership = "pythagorean"' in saved.read_text()
    assert ns.load(saved).membership == "pythagorean"


def test_figures_of_the_family_score_and_derived_degrees():
    positions = [[0, 0], [1, 2], [3, 2.5], [4, 0.5]]
    degrees = [[0.9, 0.3], [0.8, 0.6], [0.6, 0.8], [0.5, 0.5]]
    curve = ns.Bezier(positions, degrees, membership="pythagorean")
    score = curve.to_svg(view="score")
    assert ">score T^2\u2212F^2 (pythagorean)</text>" in score
    assert "Control polygon not lifted" in score
    derived = curve.to_svg(view="derived")
    assert ">hesitation = (1\u2212T^2\u2212F^2)^(1/2) (pythagorean)</text>" in derived
    plain = ns.Bezier(positions, [[0.5, 0.2, 0.1]] * 4)
    with pytest.raises(ValueError) as raised:
        plain.to_svg(view="derived")
    assert str(raised.value) == (
        "the view `derived` does not draw neutrosophic models: the derived view draws the degrees "
        "a family derives from its channels (hesitation, refusal, footprint, ...), and "
        "neutrosophic degrees derive none; the views of this model are `controls`, `truth`, "
        "`indeterminacy`, `falsity`, `all`, `plane`, `score`"
    )


def test_the_parametrised_families_keep_their_parameter(tmp_path, root):
    q = ns.load(root / "examples" / "families" / "q-rung.toml")
    assert q.membership == "q-rung:4"
    saved = tmp_path / "q.json"
    q.save(saved)
    assert '"q": 4' in saved.read_text()
    again = ns.load(saved)
    assert again.membership == "q-rung:4"
    t = np.linspace(0, 1, 7)
    np.testing.assert_array_equal(again(t), q(t))
    sphere = ns.Bezier([[0, 0], [1, 1], [2, 0]], [[0.8, 0.5, 0.6], [0.9, 0.4, 0.4], [0.3, 0.7, 0.8]], membership="t-spherical:3")
    assert sphere.membership == "t-spherical:3"


def test_refusals_name_the_rule():
    with pytest.raises(ValueError, match=r"degrees\[1\]: truth\^2 \+ falsity\^2 = 1\.3 exceeds 1 \(pythagorean rule\)"):
        ns.Bezier([[0, 0], [1, 1], [2, 0]], [[0.5, 0.5], [0.9, 0.7], [0.1, 0.1]], membership="pythagorean")
    with pytest.raises(ValueError, match=r"truth \+ indeterminacy \+ falsity = 1\.1 exceeds 1 \(picture rule\)"):
        ns.Bezier([[0, 0], [1, 1]], [[0.5, 0.3, 0.3], [0.1, 0.1, 0.1]], membership="picture")
    with pytest.raises(ValueError, match=r"indeterminacy = 0\.2 is not allowed \(fermatean rule: only truth and falsity are given"):
        ns.Bezier([[0, 0], [1, 1]], [[0.5, 0.2, 0.3], [0.1, 0.0, 0.1]], membership="fermatean")
    with pytest.raises(ValueError, match=r"the parameter is missing, as in q-rung:4"):
        ns.Bezier([[0, 0], [1, 1]], [[0.5, 0.3], [0.1, 0.1]], membership="q-rung")
    with pytest.raises(ValueError, match=r"^degrees\[1\]: truth_lower = 0\.3 exceeds truth_upper = 0\.1 \(interval-type2 rule: lower <= upper\)$"):
        ns.Bezier([[0, 0], [1, 1]], [[0.1, 0.2], [0.3, 0.1]], membership="interval-type2")


def test_fit_under_the_pythagorean_rule():
    k = np.arange(30)
    angle = (k % 6) / 5 * np.pi / 2
    positions = np.stack([k, np.sin(k / 4)], axis=1)
    degrees = np.stack([np.cos(angle), np.sin(angle)], axis=1)
    fitted, report = ns.fit(positions, degrees, membership="pythagorean", control_points=12)
    assert fitted.membership == "pythagorean"
    control = fitted.membership_degrees
    truth, falsity = control[:, 0], control[:, 2]
    assert np.all(truth**2 + falsity**2 <= 1)
    assert np.all(control[:, 1] == 0)
    assert any(entry["channel"] == "truth^2 + falsity^2" for entry in report["at_bound"])


def test_family_rule_states_each_rule_in_one_line():
    # The texts of SPEC section 10, as neutrospline check and the studio show them.
    assert ns.family_rule("pythagorean") == (
        "pythagorean: truth, falsity each in [0, 1]; truth^2 + falsity^2 <= 1; derived: hesitation"
    )
    assert ns.family_rule("t-spherical:5") == (
        "t-spherical:5: truth, indeterminacy, falsity each in [0, 1]; "
        "truth^5 + indeterminacy^5 + falsity^5 <= 1; derived: hesitation"
    )
    assert ns.family_rule(" Fuzzy ") == "fuzzy: truth in [0, 1]"
    assert ns.family_rule("bipolar-neutrosophic") == (
        "bipolar-neutrosophic: truth, indeterminacy, falsity each in [0, 1]; "
        "negative_truth, negative_indeterminacy, negative_falsity each in [-1, 0]"
    )
    assert ns.family_rule("interval-intuitionistic") == (
        "interval-intuitionistic: truth_lower, truth_upper, falsity_lower, falsity_upper each in "
        "[0, 1]; truth_lower <= truth_upper, falsity_lower <= falsity_upper; "
        "truth_upper + falsity_upper <= 1; derived: hesitation_lower, hesitation_upper"
    )
    with pytest.raises(
        ns.ModelError,
        match=r"^membership: unknown membership family `q-rung:0` \(the parameter must be an "
        r"integer >= 1; expected one of: neutrosophic, ",
    ):
        ns.family_rule("q-rung:0")
