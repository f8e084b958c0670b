//! The interval-valued and bipolar families in the model files (docs/model.md, "Lanes";
//! docs/formats.md): their channel keys and columns read into two lanes of one geometry, the
//! writers write them back (TOML, JSON and CSV round-trip), and a value that breaks the rule
//! is refused at its line with the rule named.

use neutrospline::Family;
use neutrospline_io::{parse, to_string, Format, Model, ReadOptions};

/// A TOML model of `family`: a planar curve of `kind` whose control points carry `channels`
/// (one vector per point, in the family's channel order), with `extra` keys at the top.
fn toml_model(family: Family, kind: &str, extra: &str, channels: &[Vec<f64>]) -> String {
    let mut out = format!("kind = \"{kind}\"\nmembership = \"{family}\"\n{extra}\n");
    for (i, values) in channels.iter().enumerate() {
        out.push_str("[[control_points]]\n");
        out.push_str(&format!("x = {}\ny = {}\n", i, (i * i) as f64 / 2.0));
        for (name, value) in family.channels().iter().zip(values) {
            out.push_str(&format!("{name} = {value}\n"));
        }
        if kind == "nurbs" {
            out.push_str(&format!("weight = {}\n", 1.0 + i as f64));
        }
    }
    out
}

/// Valid channel values for each wide family, some on the boundary of the rule.
fn cases() -> Vec<(Family, Vec<Vec<f64>>)> {
    vec![
        (
            Family::IntervalNeutrosophic,
            vec![
                vec![0.2, 0.5, 0.1, 0.3, 0.0, 0.4],
                vec![0.6, 0.9, 0.0, 0.2, 0.1, 0.1],
                vec![1.0, 1.0, 0.5, 0.7, 0.2, 0.25],
                vec![0.0, 0.0, 0.0, 1.0, 0.0, 1.0],
            ],
        ),
        (
            Family::IntervalIntuitionistic,
            vec![
                vec![0.1, 0.4, 0.2, 0.6],
                vec![0.3, 0.3, 0.5, 0.7],
                vec![0.0, 0.25, 0.0, 0.75],
                vec![0.5, 0.5, 0.1, 0.2],
            ],
        ),
        (
            Family::IntervalType2,
            vec![
                vec![0.1, 0.4],
                vec![0.5, 0.5],
                vec![0.0, 1.0],
                vec![0.3, 0.9],
            ],
        ),
        (
            Family::BipolarNeutrosophic,
            vec![
                vec![0.7, 0.2, 0.1, -0.3, -0.4, 0.0],
                vec![1.0, 0.0, 0.0, -1.0, -0.0, -0.5],
                vec![0.0, 0.5, 0.9, -0.1, -0.2, -0.3],
                vec![0.4, 0.4, 0.4, -0.4, -0.4, -0.4],
            ],
        ),
    ]
}

fn with_membership(family: Family) -> ReadOptions {
    let mut options = ReadOptions::default();
    options.membership = Some(family);
    options
}

fn read(name: &str, format: Format, text: &str, options: &ReadOptions) -> Result<Model, String> {
    parse(name, format, text.as_bytes(), options).map_err(|e| e.to_string())
}

#[test]
fn wide_families_read_into_two_lanes_and_round_trip() {
    for (family, channels) in cases() {
        for (kind, extra) in [
            ("bezier", ""),
            ("bspline", "degree = 2"),
            ("nurbs", "degree = 3"),
            ("bspline", "degree = 2\nperiodic = true"),
        ] {
            let text = toml_model(family, kind, extra, &channels);
            let model = read("m.toml", Format::Toml, &text, &ReadOptions::default())
                .unwrap_or_else(|e| panic!("{family} {kind}: {e}"));
            assert_eq!(model.membership(), family);
            let lanes = model.lanes();
            assert_eq!(lanes.len(), 2);
            assert!(lanes[0].same_geometry(lanes[1]));
            // The channels come back exactly (periodic curves repeat the first points).
            let read_back: Vec<Vec<f64>> = model
                .control_channels()
                .iter()
                .take(channels.len())
                .map(|v| v.to_vec())
                .collect();
            assert_eq!(read_back, channels, "{family} {kind}");
            for format in [Format::Toml, Format::Json, Format::Csv] {
                let written = to_string(&model, format).unwrap();
                let options = if format == Format::Csv {
                    model.csv_read_options()
                } else {
                    ReadOptions::default()
                };
                let back = read("back", format, &written, &options)
                    .unwrap_or_else(|e| panic!("{family} {kind} {format:?}: {e}\n{written}"));
                assert_eq!(back.control_channels(), model.control_channels());
                assert_eq!(back.lanes(), model.lanes(), "{family} {kind} {format:?}");
            }
        }
    }
}

#[test]
fn the_csv_header_names_the_channels() {
    let (family, channels) = cases().remove(3);
    let text = toml_model(family, "bezier", "", &channels);
    let model = read("m.toml", Format::Toml, &text, &ReadOptions::default()).unwrap();
    let csv = to_string(&model, Format::Csv).unwrap();
    assert_eq!(
        csv.lines().next().unwrap(),
        "x,y,truth,indeterminacy,falsity,negative_truth,negative_indeterminacy,negative_falsity"
    );
    assert_eq!(
        csv.lines().nth(2).unwrap(),
        "1.0,0.5,1.0,0.0,0.0,-1.0,0.0,-0.5"
    );
}

#[test]
fn wide_values_that_break_the_rule_are_refused_where_they_are() {
    let options = ReadOptions::default();
    let mut bad = cases();
    bad[0].1[2][0] = 1.0;
    bad[0].1[2][1] = 0.75; // truth_lower > truth_upper
    let text = toml_model(bad[0].0, "bezier", "", &bad[0].1);
    assert_eq!(
        read("bad.toml", Format::Toml, &text, &options).unwrap_err(),
        "bad.toml:22: control_points[2]: truth_lower = 1 exceeds truth_upper = 0.75 \
         (interval-neutrosophic rule: lower <= upper)"
    );
    let csv = "x,y,truth_lower,truth_upper,falsity_lower,falsity_upper\n\
               0,0,0.1,0.4,0.2,0.5\n\
               1,1,0.2,0.6,0.3,0.5\n";
    let csv_options = with_membership(Family::IntervalIntuitionistic);
    assert_eq!(
        read("bad.csv", Format::Csv, csv, &csv_options).unwrap_err(),
        "bad.csv:3: truth_upper + falsity_upper = 1.1 exceeds 1 (interval-intuitionistic rule)"
    );
    let bipolar =
        "x,y,truth,indeterminacy,falsity,negative_truth,negative_indeterminacy,negative_falsity\n\
                   0,0,0.5,0.5,0.5,0.2,-0.1,-0.1\n";
    let bipolar_options = with_membership(Family::BipolarNeutrosophic);
    assert_eq!(
        read("neg.csv", Format::Csv, bipolar, &bipolar_options).unwrap_err(),
        "neg.csv:2: negative_truth = 0.2 is outside [-1, 0] (bipolar-neutrosophic rule)"
    );
}

#[test]
fn keys_and_columns_must_be_the_familys_channels() {
    let options = ReadOptions::default();
    // A wide family's channel missing, a degree it does not have, a wide channel in a family
    // of one lane: each refused with the channels listed.
    let missing = "kind = \"bezier\"\nmembership = \"interval-type2\"\n[[control_points]]\nx = 0\ny = 0\ntruth_lower = 0.2\n";
    assert_eq!(
        read("t2.toml", Format::Toml, missing, &options).unwrap_err(),
        "t2.toml:3: control_points[0]: missing key `truth_upper` (interval-type2 rule requires it)"
    );
    let stray = "kind = \"bezier\"\nmembership = \"interval-type2\"\n[[control_points]]\nx = 0\ny = 0\ntruth_lower = 0.2\ntruth_upper = 0.3\ntruth = 0.2\n";
    assert_eq!(
        read("t2.toml", Format::Toml, stray, &options).unwrap_err(),
        "t2.toml:8: control_points[0]: key `truth` does not apply to membership interval-type2 \
         (its channels: truth_lower, truth_upper)"
    );
    let narrow = "x,y,truth,falsity,truth_upper\n0,0,0.2,0.3,0.4\n";
    let pythagorean = with_membership(Family::Pythagorean);
    assert_eq!(
        read("p.csv", Format::Csv, narrow, &pythagorean).unwrap_err(),
        "p.csv:1: column `truth_upper` does not apply to membership pythagorean (its channels: \
         truth, falsity); `truth_upper` is a channel of interval-neutrosophic, \
         interval-intuitionistic, interval-type2"
    );
}

#[test]
fn the_wide_examples_read_and_keep_their_rule() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/families/");
    for (file, family) in [
        ("interval-neutrosophic.toml", Family::IntervalNeutrosophic),
        (
            "interval-intuitionistic.toml",
            Family::IntervalIntuitionistic,
        ),
        ("interval-type2.toml", Family::IntervalType2),
        ("bipolar-neutrosophic.toml", Family::BipolarNeutrosophic),
    ] {
        let model = neutrospline_io::load(format!("{root}{file}"), &ReadOptions::default())
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(model.membership(), family);
        assert_eq!(model.lanes().len(), 2);
        for values in model.control_channels() {
            family.check(&values).unwrap();
        }
    }
}

#[test]
fn a_data_table_of_a_wide_family_is_fitted_into_a_model_of_two_lanes() {
    // Interval type-2 memberships that jump between a collapsed interval at 1 and a wide one
    // from 0: the free fit of each lane rings past [0, 1] and the lanes cross.
    let mut csv = String::from("x,y,truth_lower,truth_upper\n");
    for k in 0..20 {
        let (lower, upper) = if (k / 4) % 2 == 0 {
            (1.0, 1.0)
        } else {
            (0.0, 0.5)
        };
        csv.push_str(&format!(
            "{k},{},{lower},{upper}\n",
            (f64::from(k) / 3.0).sin()
        ));
    }
    let table = neutrospline_io::read_data("d.csv", csv.as_bytes(), Family::IntervalType2).unwrap();
    assert_eq!(table.degrees()[4].to_array(), [0.0, 0.0, 0.0]);
    assert_eq!(table.second_lane().unwrap()[4].to_array(), [0.5, 0.0, 0.0]);
    let options = neutrospline::fit::FitOptions::default()
        .with_membership(Family::IntervalType2)
        .with_target(neutrospline::fit::FitTarget::ControlPoints(8));
    let fitted = table.fit(&options).unwrap();
    let model = neutrospline_io::Model::new(fitted.curve)
        .with_family(Family::IntervalType2, fitted.second_lane)
        .unwrap();
    let channels = model.control_channels();
    assert_eq!(channels.len(), 8);
    for (i, values) in channels.iter().enumerate() {
        assert!(
            Family::IntervalType2.check(values).is_ok(),
            "control point {i}: {values:?}"
        );
    }
    // The rule binds somewhere: a collapsed interval or an end of the box.
    assert!(channels
        .iter()
        .any(|v| v[0] == v[1] || v[1] == 1.0 || v[0] == 0.0));
}
