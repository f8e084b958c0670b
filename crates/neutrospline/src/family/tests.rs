use super::*;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-15 * (1.0 + b.abs())
}

#[test]
fn names_parse_and_print_back() {
    for family in Family::EXAMPLES {
        assert_eq!(family.to_string().parse::<Family>().unwrap(), family);
        assert!(family.channel_count() >= 1 && family.channel_count() <= MAX_CHANNELS);
        assert_eq!(family.channels().len(), family.channel_count());
    }
    assert_eq!(
        " Q-RUNG : 7 ".parse::<Family>().unwrap(),
        Family::q_rung(7).unwrap()
    );
    assert_eq!(
        "t-spherical:3".parse::<Family>().unwrap().to_string(),
        "t-spherical:3"
    );
    let forms = "expected one of: neutrosophic, intuitionistic, fuzzy, pythagorean, fermatean, \
q-rung:Q, picture, spherical, t-spherical:N, interval-neutrosophic, interval-intuitionistic, \
interval-type2, bipolar-neutrosophic (Q and N integers >= 1)";
    for (given, reason) in [
        ("crisp", "no such family"),
        (
            "q-rung",
            "the parameter is missing, as in q-rung:4 or t-spherical:3",
        ),
        ("q-rung:0", "the parameter must be an integer >= 1"),
        ("t-spherical:1.5", "the parameter must be an integer >= 1"),
        ("q-rung:-2", "the parameter must be an integer >= 1"),
        ("picture:2", "this family takes no parameter"),
    ] {
        assert_eq!(
            given.parse::<Family>().unwrap_err().to_string(),
            format!("unknown membership family `{given}` ({reason}; {forms})")
        );
    }
    assert!(Family::q_rung(0).is_err() && Family::t_spherical(0).is_err());
}

#[test]
fn degrees_hold_the_families_that_fit_them() {
    // Every family but the interval-valued and bipolar ones fits truth, indeterminacy and
    // falsity, and its channels round-trip through degrees.
    for family in Family::EXAMPLES {
        let wide = matches!(
            family,
            Family::IntervalNeutrosophic
                | Family::IntervalIntuitionistic
                | Family::IntervalType2
                | Family::BipolarNeutrosophic
        );
        assert_eq!(family.fits_degrees(), !wide, "{family}");
        let mut values = vec![0.7; family.channel_count()];
        family.project(&mut values);
        match family.to_degrees(&values) {
            Ok(d) => assert_eq!(&*family.from_degrees(&d).unwrap(), values.as_slice()),
            Err(e) => assert!(wide, "{family}: {e}"),
        }
    }
    // Degrees the family does not carry must be absent or 0.
    let e = Degrees::with_membership(Family::Pythagorean, 0.5, Some(0.2), Some(0.5));
    assert_eq!(
        e.unwrap_err().to_string(),
        "indeterminacy = 0.2 is not allowed (pythagorean rule: only truth and falsity are given; \
         indeterminacy must be absent or 0)"
    );
    assert_eq!(
        Degrees::with_membership(Family::Fuzzy, 0.5, None, Some(0.1))
            .unwrap_err()
            .to_string(),
        "falsity = 0.1 is not allowed (fuzzy rule: only truth is given; falsity must be absent or 0)"
    );
    assert_eq!(
        Degrees::with_membership(Family::Spherical, 0.5, None, Some(0.1))
            .unwrap_err()
            .to_string(),
        "indeterminacy is missing (spherical rule requires it)"
    );
    assert_eq!(
        Family::IntervalType2
            .to_degrees(&[0.1, 0.2])
            .unwrap_err()
            .to_string(),
        "the interval-type2 family has 2 channels (truth_lower, truth_upper); a truth, \
         indeterminacy, falsity triple cannot hold them"
    );
    let d = Degrees::new(0.3, 0.6, 0.1).unwrap();
    let v = Family::Neutrosophic.from_degrees(&d).unwrap();
    assert_eq!(Family::Neutrosophic.to_degrees(&v).unwrap(), d);
    let d = Degrees::fuzzy(0.4).unwrap();
    assert_eq!(&*Family::Fuzzy.from_degrees(&d).unwrap(), &[0.4]);
    assert_eq!(Family::Fuzzy.to_degrees(&[0.4]).unwrap(), d);
    assert!(Family::Intuitionistic.to_degrees(&[0.7, 0.6]).is_err());
    assert_eq!(
        &*Family::Picture.from_degrees(&d).unwrap(),
        &[0.4, 0.0, 0.0]
    );
    assert!(Family::Picture.to_degrees(&[0.1, 0.1, 0.1]).is_ok());
    assert_eq!(
        Family::Picture
            .to_degrees(&[0.5, 0.3, 0.3])
            .unwrap_err()
            .to_string(),
        "truth + indeterminacy + falsity = 1.1 exceeds 1 (picture rule)"
    );
    assert!(Family::IntervalType2.from_degrees(&d).is_none());
    assert!(Family::Neutrosophic.to_degrees(&[0.1, 0.1]).is_err());
}

#[test]
fn refusals_name_the_rule_and_the_value() {
    let q4 = Family::q_rung(4).unwrap();
    let t3 = Family::t_spherical(3).unwrap();
    let cases: [(Family, &[f64], &str); 12] = [
        (
            Family::Pythagorean,
            &[0.8, 0.7],
            "truth^2 + falsity^2 = 1.13 exceeds 1 (pythagorean rule)",
        ),
        (
            Family::Intuitionistic,
            &[0.5, 0.75],
            "truth + falsity = 1.25 exceeds 1 (intuitionistic rule)",
        ),
        (
            Family::Fermatean,
            &[1.0, 0.5],
            "truth^3 + falsity^3 = 1.125 exceeds 1 (fermatean rule)",
        ),
        (
            q4,
            &[1.0, 0.5],
            "truth^4 + falsity^4 = 1.0625 exceeds 1 (q-rung:4 rule)",
        ),
        (
            Family::Picture,
            &[0.5, 0.25, 0.5],
            "truth + indeterminacy + falsity = 1.25 exceeds 1 (picture rule)",
        ),
        (
            t3,
            &[1.0, 0.5, 0.0],
            "truth^3 + indeterminacy^3 + falsity^3 = 1.125 exceeds 1 (t-spherical:3 rule)",
        ),
        (
            Family::Neutrosophic,
            &[0.5, 1.5, 0.0],
            "indeterminacy = 1.5 is outside [0, 1] (neutrosophic rule)",
        ),
        (
            Family::IntervalNeutrosophic,
            &[0.1, 0.2, 0.5, 0.4, 0.0, 0.0],
            "indeterminacy_lower = 0.5 exceeds indeterminacy_upper = 0.4 (interval-neutrosophic rule: lower <= upper)",
        ),
        (
            Family::IntervalIntuitionistic,
            &[0.25, 0.5, 0.25, 0.75],
            "truth_upper + falsity_upper = 1.25 exceeds 1 (interval-intuitionistic rule)",
        ),
        (
            Family::BipolarNeutrosophic,
            &[0.5, 0.5, 0.5, 0.25, 0.0, 0.0],
            "negative_truth = 0.25 is outside [-1, 0] (bipolar-neutrosophic rule)",
        ),
        (
            Family::Fuzzy,
            &[f64::NAN],
            "truth = NaN is not a finite number (fuzzy rule)",
        ),
        (
            Family::IntervalType2,
            &[0.5],
            "1 values given; the interval-type2 family has 2 channels (truth_lower, truth_upper)",
        ),
    ];
    for (family, values, message) in cases {
        assert_eq!(family.check(values).unwrap_err().to_string(), message);
    }
    // On the boundary is valid; a tolerance admits rounding, not more.
    assert!(Family::Pythagorean.check(&[0.6, 0.8]).is_ok());
    assert!(Family::Intuitionistic
        .check_within(&[0.5, 0.5 + 1e-13], RULE_TOLERANCE)
        .is_ok());
    assert!(Family::Intuitionistic
        .check_within(&[0.5, 0.5 + 1e-11], RULE_TOLERANCE)
        .is_err());
}

#[test]
fn derived_degrees_and_scores_have_their_closed_forms() {
    let q5 = Family::q_rung(5).unwrap();
    let t4 = Family::t_spherical(4).unwrap();
    // (family, channels, derived, score, accuracy), by hand.
    type Case<'a> = (Family, &'a [f64], &'a [f64], f64, Option<f64>);
    let cases: [Case; 13] = [
        (Family::Neutrosophic, &[0.7, 0.1, 0.2], &[], 0.8, Some(0.5)),
        (
            Family::Intuitionistic,
            &[0.5, 0.25],
            &[0.25],
            0.25,
            Some(0.75),
        ),
        (Family::Fuzzy, &[0.4], &[], 0.4, None),
        (Family::Pythagorean, &[0.6, 0.0], &[0.8], 0.36, Some(0.36)),
        (
            Family::Fermatean,
            &[0.5, 0.5],
            &[0.75f64.cbrt()],
            0.0,
            Some(0.25),
        ),
        (
            q5,
            &[0.5, 0.25],
            &[(1.0 - 1.0 / 32.0 - 1.0 / 1024.0f64).powf(0.2)],
            1.0 / 32.0 - 1.0 / 1024.0,
            Some(1.0 / 32.0 + 1.0 / 1024.0),
        ),
        (
            Family::Picture,
            &[0.5, 0.125, 0.25],
            &[0.125],
            0.25,
            Some(0.875),
        ),
        (Family::Spherical, &[0.5, 0.5, 0.5], &[0.5], 0.0, Some(0.75)),
        (
            t4,
            &[0.5, 0.5, 0.0],
            &[0.875f64.powf(0.25)],
            0.0625,
            Some(0.125),
        ),
        (
            Family::IntervalNeutrosophic,
            &[0.5, 1.0, 0.0, 0.25, 0.25, 0.5],
            &[],
            4.5 / 6.0,
            None,
        ),
        (
            Family::IntervalIntuitionistic,
            &[0.25, 0.5, 0.125, 0.25],
            &[0.25, 0.625],
            0.1875,
            Some(0.5625),
        ),
        (Family::IntervalType2, &[0.25, 0.75], &[0.5, 0.5], 0.5, None),
        (
            Family::BipolarNeutrosophic,
            &[0.5, 0.25, 0.25, -0.5, -0.25, -0.5],
            &[],
            3.25 / 6.0,
            None,
        ),
    ];
    for (family, values, derived, score, accuracy) in cases {
        assert!(family.check(values).is_ok(), "{family}");
        let got = family.derived(values);
        assert_eq!(got.len(), derived.len(), "{family}");
        assert_eq!(family.derived_names().len(), derived.len(), "{family}");
        for (g, d) in got.iter().zip(derived) {
            assert!(close(*g, *d), "{family}: derived {g} vs {d}");
        }
        assert!(
            close(family.score(values), score),
            "{family}: score {}",
            family.score(values)
        );
        match (family.accuracy(values), accuracy) {
            (Some(a), Some(b)) => assert!(close(a, b), "{family}: accuracy {a} vs {b}"),
            (a, b) => assert_eq!(a, b, "{family}"),
        }
    }
}

#[test]
fn linear_constraints_describe_each_rule() {
    // Counts: boxes without the implied ends, orders and the sum.
    let counts = [6, 3, 2, 2, 2, 2, 4, 3, 3, 9, 5, 3, 12];
    for (family, count) in Family::EXAMPLES.into_iter().zip(counts) {
        let constraints = family.linear_constraints();
        assert_eq!(constraints.len(), count, "{family}");
        assert_eq!(family.is_linear(), family.power_rule().is_none());
        // The corners of the channel boxes that pass the check satisfy every constraint, and
        // a failing corner breaks one of them or the power rule.
        let k = family.channel_count();
        for corner in 0..1u32 << k {
            let x: Vec<f64> = (0..k)
                .map(|c| {
                    let (low, high) = family.channel_range(c);
                    if corner >> c & 1 == 1 {
                        high
                    } else {
                        low
                    }
                })
                .collect();
            let linear_ok = constraints.iter().all(|c| c.slack(&x) >= 0.0);
            let round_ok = family
                .power_rule()
                .is_none_or(|r| rule::power_sum(&x, r.channels, r.power) <= 1.0);
            assert_eq!(
                family.check(&x).is_ok(),
                linear_ok && round_ok,
                "{family} {x:?}"
            );
        }
    }
    assert_eq!(
        Family::Spherical.power_rule(),
        Some(PowerRule {
            power: 2,
            channels: &[0, 1, 2]
        })
    );
    assert_eq!(Family::q_rung(1).unwrap().power_rule(), None);
}

#[test]
fn lanes_split_and_join_every_family() {
    // Values from a box larger than each rule's, projected onto it: split gives lanes whose
    // slots are in [0, 1], and join gives the values back to the bit.
    let seeds = [-0.9, 0.0, 0.15, 0.5, 0.7, 1.0, 1.3];
    for family in Family::EXAMPLES {
        for (k, _) in seeds.iter().enumerate() {
            let mut values: Vec<f64> = (0..family.channel_count())
                .map(|c| seeds[(k + 3 * c) % seeds.len()])
                .collect();
            family.project(&mut values);
            let (lanes, count) = family.split(&values).unwrap();
            assert_eq!(count, family.lane_count(), "{family}");
            for lane in &lanes[..count] {
                assert!(lane.to_array().iter().all(|v| (0.0..=1.0).contains(v)));
            }
            assert_eq!(
                &*family.join(&lanes[..count]),
                values.as_slice(),
                "{family}"
            );
        }
    }
    // The lanes of the interval-intuitionistic family leave the indeterminacy slot at 0, and
    // the bipolar negative lane holds the negated degrees.
    let (lanes, _) = Family::IntervalIntuitionistic
        .split(&[0.1, 0.4, 0.2, 0.5])
        .unwrap();
    assert_eq!(lanes[0].to_array(), [0.1, 0.0, 0.2]);
    assert_eq!(lanes[1].to_array(), [0.4, 0.0, 0.5]);
    let (lanes, _) = Family::BipolarNeutrosophic
        .split(&[0.9, 0.0, 0.1, -1.0, -0.25, -0.0])
        .unwrap();
    assert_eq!(lanes[1].to_array(), [1.0, 0.25, 0.0]);
    assert!(lanes[1].falsity().is_sign_positive());
    // Rates map like values: a lane's slot rates join to the channels' rates.
    assert_eq!(
        &*Family::BipolarNeutrosophic.join_slots(&[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]),
        &[1.0, 2.0, 3.0, -4.0, -5.0, -6.0]
    );
    assert_eq!(
        &*Family::Pythagorean.join_slots(&[[0.5, 9.0, 0.25]]),
        &[0.5, 0.25]
    );
}

#[test]
fn lanes_refuse_values_that_break_the_rule() {
    let message = |family: Family, values: &[f64]| family.split(values).unwrap_err().to_string();
    assert_eq!(
        message(
            Family::IntervalNeutrosophic,
            &[0.6, 0.4, 0.0, 0.1, 0.0, 0.1]
        ),
        "truth_lower = 0.6 exceeds truth_upper = 0.4 (interval-neutrosophic rule: lower <= upper)"
    );
    assert_eq!(
        message(Family::IntervalIntuitionistic, &[0.1, 0.7, 0.1, 0.4]),
        "truth_upper + falsity_upper = 1.1 exceeds 1 (interval-intuitionistic rule)"
    );
    assert_eq!(
        message(
            Family::BipolarNeutrosophic,
            &[0.5, 0.5, 0.5, 0.2, -0.1, -0.1]
        ),
        "negative_truth = 0.2 is outside [-1, 0] (bipolar-neutrosophic rule)"
    );
    assert_eq!(
        message(Family::IntervalType2, &[0.2]),
        "1 values given; the interval-type2 family has 2 channels (truth_lower, truth_upper)"
    );
}

/// The one-line rule of every family, each text checked by hand against SPEC section 10 (the
/// boxes, `L <= U`, the sums, the derived degrees).
#[test]
fn rule_text_of_every_family() {
    let expected = [
        "neutrosophic: truth, indeterminacy, falsity each in [0, 1]",
        "intuitionistic: truth, falsity each in [0, 1]; truth + falsity <= 1; derived: hesitation",
        "fuzzy: truth in [0, 1]",
        "pythagorean: truth, falsity each in [0, 1]; truth^2 + falsity^2 <= 1; derived: hesitation",
        "fermatean: truth, falsity each in [0, 1]; truth^3 + falsity^3 <= 1; derived: hesitation",
        "q-rung:4: truth, falsity each in [0, 1]; truth^4 + falsity^4 <= 1; derived: hesitation",
        "picture: truth, indeterminacy, falsity each in [0, 1]; truth + indeterminacy + falsity \
         <= 1; derived: refusal",
        "spherical: truth, indeterminacy, falsity each in [0, 1]; truth^2 + indeterminacy^2 + \
         falsity^2 <= 1; derived: hesitation",
        "t-spherical:3: truth, indeterminacy, falsity each in [0, 1]; truth^3 + indeterminacy^3 \
         + falsity^3 <= 1; derived: hesitation",
        "interval-neutrosophic: truth_lower, truth_upper, indeterminacy_lower, \
         indeterminacy_upper, falsity_lower, falsity_upper each in [0, 1]; truth_lower <= \
         truth_upper, indeterminacy_lower <= indeterminacy_upper, falsity_lower <= falsity_upper",
        "interval-intuitionistic: truth_lower, truth_upper, falsity_lower, falsity_upper each in \
         [0, 1]; truth_lower <= truth_upper, falsity_lower <= falsity_upper; truth_upper + \
         falsity_upper <= 1; derived: hesitation_lower, hesitation_upper",
        "interval-type2: truth_lower, truth_upper each in [0, 1]; truth_lower <= truth_upper; \
         derived: type_reduced, footprint",
        "bipolar-neutrosophic: truth, indeterminacy, falsity each in [0, 1]; negative_truth, \
         negative_indeterminacy, negative_falsity each in [-1, 0]",
    ];
    for (family, text) in Family::EXAMPLES.iter().zip(expected) {
        assert_eq!(family.rule_text(), text, "{family}");
    }
    // The first rung and sphere: a plain sum, as the intuitionistic and picture rules.
    assert_eq!(
        Family::q_rung(1).unwrap().rule_text(),
        "q-rung:1: truth, falsity each in [0, 1]; truth + falsity <= 1; derived: hesitation"
    );
    assert_eq!(
        Family::t_spherical(17).unwrap().rule_text(),
        "t-spherical:17: truth, indeterminacy, falsity each in [0, 1]; truth^17 + \
         indeterminacy^17 + falsity^17 <= 1; derived: hesitation"
    );
}

/// What the text of [`Family::rule_text`] says, read back from the text alone: the channels
/// of each box clause `a, b each in [low, high]`, the `lower <= upper` pairs, the sum clause's
/// channels and exponent, and the derived names.
struct ReadRule {
    boxes: Vec<(String, f64, f64)>,
    pairs: Vec<(String, String)>,
    sum: Option<(Vec<String>, u32)>,
    derived: Vec<String>,
}

fn read_rule(family: Family, text: &str) -> ReadRule {
    let prefix = format!("{family}: ");
    let body = text
        .strip_prefix(&prefix)
        .unwrap_or_else(|| panic!("{text} does not start with {prefix}"));
    let mut read = ReadRule {
        boxes: Vec::new(),
        pairs: Vec::new(),
        sum: None,
        derived: Vec::new(),
    };
    for clause in body.split("; ") {
        if let Some(names) = clause.strip_prefix("derived: ") {
            read.derived = names.split(", ").map(str::to_owned).collect();
        } else if let Some((names, range)) = clause.split_once(" in [") {
            let names = names.strip_suffix(" each").unwrap_or(names);
            let (low, high) = range.strip_suffix(']').unwrap().split_once(", ").unwrap();
            let (low, high): (f64, f64) = (low.parse().unwrap(), high.parse().unwrap());
            for name in names.split(", ") {
                read.boxes.push((name.to_owned(), low, high));
            }
        } else if let Some(terms) = clause.strip_suffix(" <= 1") {
            let mut power = None;
            let mut names = Vec::new();
            for term in terms.split(" + ") {
                let (name, p) = match term.split_once('^') {
                    Some((name, p)) => (name, p.parse::<u32>().unwrap()),
                    None => (term, 1),
                };
                assert!(power.is_none_or(|q| q == p), "{clause}: mixed exponents");
                power = Some(p);
                names.push(name.to_owned());
            }
            read.sum = Some((names, power.unwrap()));
        } else {
            for pair in clause.split(", ") {
                let (lower, upper) = pair
                    .split_once(" <= ")
                    .unwrap_or_else(|| panic!("{clause}: not a clause of a rule"));
                read.pairs.push((lower.to_owned(), upper.to_owned()));
            }
        }
    }
    read
}

/// The text names every channel once in a box clause, with the channel's box; its pairs and
/// its sum are the ones [`Family::check`] enforces (a value just past each breaks the check,
/// one just inside passes); its derived names are [`Family::derived_names`].
fn rule_text_states_the_rule(family: Family) {
    let text = family.rule_text();
    let read = read_rule(family, &text);
    let channels = family.channels();
    let named: Vec<&str> = read.boxes.iter().map(|(n, _, _)| n.as_str()).collect();
    let mut sorted_named = named.clone();
    sorted_named.sort_unstable();
    let mut sorted_channels = channels.to_vec();
    sorted_channels.sort_unstable();
    assert_eq!(sorted_named, sorted_channels, "{text}");
    let index = |name: &str| {
        channels
            .iter()
            .position(|c| *c == name)
            .unwrap_or_else(|| panic!("{name} is not a channel of {family}: {text}"))
    };
    for (name, low, high) in &read.boxes {
        assert_eq!(family.channel_range(index(name)), (*low, *high), "{text}");
    }
    // A valid point: every channel at the end of its box nearest 0 (all 0, bipolar too).
    let origin = vec![0.0; channels.len()];
    assert!(family.check(&origin).is_ok(), "{family}");
    for (lower, upper) in &read.pairs {
        let mut values = origin.clone();
        values[index(lower)] = 0.5;
        values[index(upper)] = 0.25;
        assert!(
            matches!(family.check(&values), Err(RuleError::Order { .. })),
            "{text}"
        );
        values[index(upper)] = 0.5;
        assert!(family.check(&values).is_ok(), "{text}");
    }
    match &read.sum {
        Some((names, power)) => {
            // Each summed channel at x with k x^p just past 1, then just below 1.
            let k = names.len() as f64;
            let edge = (1.0 / k).powf(1.0 / f64::from(*power));
            for (scale, passes) in [(1.0 + 1e-9, false), (1.0 - 1e-9, true)] {
                let mut values = origin.clone();
                for name in names {
                    values[index(name)] = edge * scale;
                }
                // An interval's lower bound at its upper one keeps lower <= upper.
                for &(l, u) in family.interval_pairs() {
                    values[l] = values[u];
                }
                assert_eq!(
                    family.check(&values).is_ok(),
                    passes,
                    "{text} at {values:?}"
                );
            }
            assert_eq!(family.power(), Some(*power), "{text}");
        }
        None => assert_eq!(family.power(), None, "{text}"),
    }
    let derived: Vec<&str> = read.derived.iter().map(String::as_str).collect();
    assert_eq!(derived, family.derived_names(), "{text}");
}

#[test]
fn rule_text_names_every_channel_and_states_the_checked_rule() {
    for family in Family::EXAMPLES {
        rule_text_states_the_rule(family);
    }
}

proptest::proptest! {
    /// The parametrised families at any parameter: `q-rung:q` and `t-spherical:n`.
    #[test]
    fn rule_text_of_any_rung_and_sphere(parameter in 1u32..=1000) {
        rule_text_states_the_rule(Family::q_rung(parameter).unwrap());
        rule_text_states_the_rule(Family::t_spherical(parameter).unwrap());
    }
}
