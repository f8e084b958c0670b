//! End-to-end tests of `neutrospline transform` on the families of two lanes
//! (interval-neutrosophic, interval-intuitionistic, interval-type2, bipolar-neutrosophic):
//! every exact operation gives a model whose channels are the original's (Bernstein sums
//! computed here, sharing no code with the library), pieces cover their parts, the results are
//! read back under the rule, and degree reduction solves the channels of both lanes jointly
//! (a case where reducing each lane alone breaks `lower <= upper`).

use neutrospline::{on_dimension, Evaluate, Family};
use neutrospline_io::{Model, Shape};

use crate::util::{load_model as load, run_in, succeeds as ok};

/// Channel values of control point `i` that obey `family`'s rule (lower <= upper, T_U + F_U
/// <= 1, negatives in [-1, 0]), varied with `i`.
fn channels(family: Family, i: usize) -> Vec<f64> {
    let x = |k: usize| ((i * 7 + k * 3) % 11) as f64 / 25.0; // in [0, 0.4]
    match family {
        Family::IntervalNeutrosophic => {
            (0..3).flat_map(|d| [x(d), x(d) + x(d + 5) + 0.1]).collect()
        }
        Family::IntervalIntuitionistic => vec![x(0), x(0) + 0.05, x(1), x(1) + x(2)],
        Family::IntervalType2 => vec![x(0), x(0) + x(1) + 0.2],
        Family::BipolarNeutrosophic => vec![x(0), x(1), x(2), -x(3), -x(4) - 0.5, -x(5)],
        other => unreachable!("{other} has one lane"),
    }
}

const WIDE: [Family; 4] = [
    Family::IntervalNeutrosophic,
    Family::IntervalIntuitionistic,
    Family::IntervalType2,
    Family::BipolarNeutrosophic,
];

/// A model file of `family`: `kind` (with `knots` for a B-spline), plane positions, channel
/// values of [`channels`] unless `values` gives them.
fn model_toml(
    family: Family,
    kind: &str,
    knots: Option<&str>,
    positions: &[[f64; 2]],
    values: Option<&[Vec<f64>]>,
) -> String {
    let mut text = format!("kind = \"{kind}\"\nmembership = \"{family}\"\n");
    if let Some(k) = knots {
        text.push_str(&format!("degree = 3\nknots = [{k}]\n"));
    }
    for (i, p) in positions.iter().enumerate() {
        text.push_str(&format!("[[control_points]]\nx = {}\ny = {}\n", p[0], p[1]));
        let v = values.map_or_else(|| channels(family, i), |v| v[i].clone());
        for (name, value) in family.channels().iter().zip(v) {
            text.push_str(&format!("{name} = {value}\n"));
        }
    }
    text
}

/// The channels of `model` at `t` (each lane evaluated and joined) after its position.
fn at(model: &Model, t: f64) -> (Vec<f64>, Vec<f64>) {
    let mut position = Vec::new();
    let lanes: Vec<neutrospline::Degrees> = model
        .lanes()
        .iter()
        .map(|shape| match shape {
            Shape::Curve(c) => on_dimension!(c, c => {
                let p = c.evaluate(t).unwrap();
                position = p.position.to_vec();
                p.degrees
            }),
            Shape::Surface(_) => unreachable!("curves here"),
        })
        .collect();
    (position, model.membership().join(&lanes).to_vec())
}

fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// The Bézier curve of control rows `rows` at `t`: `Σ C(n, i) t^i (1 - t)^(n - i) row_i`.
fn bernstein(rows: &[Vec<f64>], t: f64) -> Vec<f64> {
    let n = rows.len() - 1;
    let mut out = vec![0.0; rows[0].len()];
    for (i, row) in rows.iter().enumerate() {
        let b = binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32);
        for (o, v) in out.iter_mut().zip(row) {
            *o += b * v;
        }
    }
    out
}

fn close(a: &[f64], b: &[f64], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() < 1e-12, "{what}: {a:?} vs {b:?}");
    }
}

const POSITIONS: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.0]];
const TS: [f64; 6] = [0.0, 0.1, 0.37, 0.5, 0.81, 1.0];

/// Elevation, knot insertion, refinement, reversal, a new domain and a subsegment of a cubic
/// Bézier curve of every wide family: the result's channels at several parameters equal the
/// Bernstein sum of the original channels (and positions), and the written model is read back
/// under the family's rule.
#[test]
fn exact_operations_keep_the_channels_of_every_wide_family() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for family in WIDE {
        std::fs::write(
            d.join("m.toml"),
            model_toml(family, "bezier", None, &POSITIONS, None),
        )
        .unwrap();
        let rows: Vec<Vec<f64>> = (0..4)
            .map(|i| {
                let mut row = POSITIONS[i].to_vec();
                row.extend(channels(family, i));
                row
            })
            .collect();
        let expect = |t: f64| bernstein(&rows, t);
        let joined = |(mut p, c): (Vec<f64>, Vec<f64>)| {
            p.extend(c);
            p
        };
        // Same parameter: elevate, insert, refine, reparametrize onto [0, 1].
        for op in [
            &["--elevate", "2"][..],
            &["--insert-knot", "0.3,0.3,0.6"],
            &["--refine", "2"],
        ] {
            let mut args = vec!["transform", "m.toml", "-o", "out.toml"];
            args.extend(op);
            ok(d, &args);
            let out = load(&d.join("out.toml"));
            assert_eq!(out.membership(), family);
            assert_eq!(out.lanes().len(), 2);
            for t in TS {
                close(
                    &joined(at(&out, t)),
                    &expect(t),
                    &format!("{family} {op:?} t={t}"),
                );
            }
        }
        // Reversed: the point at t is the original's at 1 - t.
        ok(d, &["transform", "m.toml", "-o", "out.toml", "--reverse"]);
        let out = load(&d.join("out.toml"));
        for t in TS {
            close(
                &joined(at(&out, t)),
                &expect(1.0 - t),
                &format!("{family} reverse"),
            );
        }
        // A new domain [2, 6]: the point at 2 + 4 t is the original's at t.
        ok(
            d,
            &[
                "transform",
                "m.toml",
                "-o",
                "out.toml",
                "--reparametrize",
                "2:6",
            ],
        );
        let out = load(&d.join("out.toml"));
        for t in TS {
            close(
                &joined(at(&out, 2.0 + 4.0 * t)),
                &expect(t),
                &format!("{family} domain"),
            );
        }
        // Split at 0.3: the first half at s is the original at 0.3 s, the second at 0.3 + 0.7 s.
        ok(
            d,
            &["transform", "m.toml", "-o", "half.toml", "--split", "0.3"],
        );
        let (a, b) = (load(&d.join("half-1.toml")), load(&d.join("half-2.toml")));
        for s in TS {
            close(
                &joined(at(&a, s)),
                &expect(0.3 * s),
                &format!("{family} left half"),
            );
            close(
                &joined(at(&b, s)),
                &expect(0.3 + 0.7 * s),
                &format!("{family} right half"),
            );
        }
        // The piece from 0.8 back to 0.2: at s, the original at 0.8 - 0.6 s.
        ok(
            d,
            &[
                "transform",
                "m.toml",
                "-o",
                "out.toml",
                "--subsegment",
                "0.8:0.2",
            ],
        );
        let out = load(&d.join("out.toml"));
        for s in TS {
            close(
                &joined(at(&out, s)),
                &expect(0.8 - 0.6 * s),
                &format!("{family} piece"),
            );
        }
    }
}

/// A B-spline of every wide family cut into its Bézier pieces: each piece on [0, 1] is the
/// spline on its span; then a knot inserted twice is removed twice (back to the original
/// knots, the channels unchanged), with the removals reported.
#[test]
fn bezier_pieces_and_knot_removal_of_wide_splines() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let positions = [
        [0.0, 0.0],
        [1.0, 2.0],
        [3.0, 3.0],
        [4.0, 1.0],
        [6.0, 0.0],
        [7.0, 2.0],
    ];
    let knots = "0, 0, 0, 0, 0.4, 0.7, 1, 1, 1, 1";
    for family in WIDE {
        std::fs::write(
            d.join("s.toml"),
            model_toml(family, "bspline", Some(knots), &positions, None),
        )
        .unwrap();
        let original = load(&d.join("s.toml"));
        ok(
            d,
            &["transform", "s.toml", "-o", "piece.toml", "--to-bezier"],
        );
        for (k, (a, b)) in [(0.0, 0.4), (0.4, 0.7), (0.7, 1.0)].into_iter().enumerate() {
            let piece = load(&d.join(format!("piece-{}.toml", k + 1)));
            for s in TS {
                let (p, c) = at(&piece, s);
                let (q, e) = at(&original, a + (b - a) * s);
                close(&p, &q, &format!("{family} piece {k} position"));
                close(&c, &e, &format!("{family} piece {k} channels"));
            }
        }
        ok(
            d,
            &[
                "transform",
                "s.toml",
                "-o",
                "more.toml",
                "--insert-knot",
                "0.55,0.55",
            ],
        );
        let out = ok(
            d,
            &[
                "transform",
                "more.toml",
                "-o",
                "back.toml",
                "--remove-knot",
                "0.55",
                "--tolerance",
                "1e-9",
            ],
        );
        assert!(
            out.stderr.contains("removed knot 0.55 2 of 2 times"),
            "{}",
            out.stderr
        );
        let back = load(&d.join("back.toml"));
        assert_eq!(back.shape().curve_knots(), original.shape().curve_knots());
        for (x, y) in back
            .control_channels()
            .iter()
            .zip(original.control_channels())
        {
            close(x, &y, &format!("{family} removal"));
        }
    }
}

/// The adversarial case of degree reduction: an interval-type2 cubic Bézier curve whose lower
/// and upper membership differ only at the first control point (0 <= 0.4). Reducing to degree
/// 2 keeps the ends, and the nearest (L2) middle point is `(-P0 + 3 P1 + 3 P2 - P3) / 4`
/// (the normal equation of the one free point, solved by hand with the Gram values of the
/// Bernstein bases): lower 3 / 4 and upper 0.65, so reducing each lane alone gives lower >
/// upper. Solved jointly under the rule, the objective is `a ((x_L - 0.75)^2 + (x_U -
/// 0.65)^2)` with `x_L <= x_U`, whose minimum is both at the mean 0.7 — which the result must
/// hold, and the file must be read back under the rule.
#[test]
fn degree_reduction_solves_both_lanes_jointly() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The positions of an elevated quadratic, so the reduction keeps them exactly.
    let positions = [
        [0.0, 0.0],
        [2.0 / 3.0, 4.0 / 3.0],
        [4.0 / 3.0, 4.0 / 3.0],
        [2.0, 0.0],
    ];
    let values = [
        vec![0.0, 0.4],
        vec![0.5, 0.5],
        vec![0.5, 0.5],
        vec![0.0, 0.0],
    ];
    std::fs::write(
        d.join("c.toml"),
        model_toml(
            Family::IntervalType2,
            "bezier",
            None,
            &positions,
            Some(&values),
        ),
    )
    .unwrap();
    // Each lane alone (what a one-lane reduction would do) breaks lower <= upper.
    let original = load(&d.join("c.toml"));
    let alone: Vec<f64> = original
        .lanes()
        .iter()
        .map(|shape| match shape {
            Shape::Curve(neutrospline::Dimensional::Planar(c)) => {
                let r = c.reduced(1, 1.0, Family::Neutrosophic).unwrap();
                neutrospline::ControlPolygon::control_points(&r.curve)[1]
                    .degrees
                    .truth()
            }
            _ => unreachable!("a planar curve"),
        })
        .collect();
    assert!(
        (alone[0] - 0.75).abs() < 1e-12 && (alone[1] - 0.65).abs() < 1e-12,
        "{alone:?}"
    );
    let out = ok(
        d,
        &[
            "transform",
            "c.toml",
            "-o",
            "r.toml",
            "--reduce",
            "1",
            "--tolerance",
            "0.2",
        ],
    );
    assert!(out.stderr.contains("degree 3 -> 2"), "{}", out.stderr);
    let reduced = load(&d.join("r.toml"));
    let channels = reduced.control_channels();
    assert_eq!(channels.len(), 3);
    close(&channels[0], &[0.0, 0.4], "first end kept");
    close(&channels[2], &[0.0, 0.0], "last end kept");
    close(&channels[1], &[0.7, 0.7], "the joint minimum");
    for c in &channels {
        assert!(c[0] <= c[1], "lower <= upper exactly: {c:?}");
    }
    let middle = neutrospline::ControlPolygon::control_points(match reduced.shape() {
        Shape::Curve(neutrospline::Dimensional::Planar(c)) => c,
        _ => unreachable!("a planar curve"),
    })[1]
        .position;
    close(&middle, &[1.0, 2.0], "the quadratic's middle point");
}

/// Degree reduction at the boundary of the interval-intuitionistic rule: upper truth and
/// falsity summing to 1 at every control point of an elevated quadratic come back exactly
/// (within 1e-12), every reduced point obeys the rule, and the file is read back; an exact
/// operation on a surface of a wide family acts on each lane alike.
#[test]
fn reduction_at_the_rule_boundary_and_a_surface_lane_by_lane() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let quadratic = [
        vec![0.2, 0.6, 0.1, 0.4],
        vec![0.3, 0.3, 0.7, 0.7],
        vec![0.5, 0.9, 0.0, 0.1],
    ];
    // The quadratic elevated: Q_i = i/3 P_{i-1} + (1 - i/3) P_i.
    let elevate = |i: usize, c: usize| {
        let a = i as f64 / 3.0;
        let before = if i > 0 { quadratic[i - 1][c] } else { 0.0 };
        let this = if i < 3 { quadratic[i][c] } else { 0.0 };
        a * before + (1.0 - a) * this
    };
    let values: Vec<Vec<f64>> = (0..4)
        .map(|i| (0..4).map(|c| elevate(i, c)).collect())
        .collect();
    std::fs::write(
        d.join("b.toml"),
        model_toml(
            Family::IntervalIntuitionistic,
            "bezier",
            None,
            &POSITIONS,
            Some(&values),
        ),
    )
    .unwrap();
    ok(
        d,
        &[
            "transform",
            "b.toml",
            "-o",
            "r.toml",
            "--reduce",
            "1",
            "--tolerance",
            "10",
        ],
    );
    let reduced = load(&d.join("r.toml"));
    for (c, q) in reduced.control_channels().iter().zip(&quadratic) {
        close(c, q, "the quadratic's channels");
        assert!(c[1] + c[3] <= 1.0 && c[0] <= c[1] && c[2] <= c[3], "{c:?}");
    }
    // A surface of a wide family: exact operations work lane by lane.
    let mut surface = String::from(
        "kind = \"bezier-surface\"\nmembership = \"interval-type2\"\nrows = 2\ncols = 2\n",
    );
    for (x, y) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        surface.push_str(&format!(
            "[[control_points]]\nx = {x}\ny = {y}\nz = 0\ntruth_lower = 0.1\ntruth_upper = 0.2\n"
        ));
    }
    std::fs::write(d.join("surf.toml"), surface).unwrap();
    // An exact operation on the surface works lane by lane.
    ok(
        d,
        &[
            "transform",
            "surf.toml",
            "-o",
            "e.toml",
            "--elevate",
            "1",
            "--direction",
            "u",
        ],
    );
    let elevated = load(&d.join("e.toml"));
    assert_eq!(elevated.lanes().len(), 2);
    for c in elevated.control_channels() {
        close(&c, &[0.1, 0.2], "surface channels");
    }
}

/// `export` of a cubic Bézier curve of every wide family: each format writes every channel by
/// its name (DXF extended data, glTF attributes `_TRUTH_LOWER`, ..., PLY properties, OBJ `#deg`
/// lines, STEP point names), and the values are the model's: the curve's first sample is its
/// first control point (t = 0), its last the last. The DXF file imports back to the same
/// model, every channel to the last bit.
#[test]
fn export_writes_every_channel_by_name_and_dxf_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for family in WIDE {
        std::fs::write(
            d.join("m.toml"),
            model_toml(family, "bezier", None, &POSITIONS, None),
        )
        .unwrap();
        let first = channels(family, 0);
        let last = channels(family, 3);
        let names = family.channels();
        // DXF: the extended data, and the import.
        ok(d, &["export", "m.toml", "-o", "m.dxf"]);
        let dxf = std::fs::read_to_string(d.join("m.dxf")).unwrap();
        for name in names {
            assert!(
                dxf.contains(&format!("1000\n{name}\n1071\n4\n")),
                "{family}: {name}"
            );
        }
        ok(d, &["import", "m.dxf", "-o", "back.toml"]);
        let (a, b) = (load(&d.join("m.toml")), load(&d.join("back.toml")));
        assert_eq!(b.membership(), family);
        let bits = |m: &Model| -> Vec<Vec<u64>> {
            m.control_channels()
                .iter()
                .map(|v| v.iter().map(|x| x.to_bits()).collect())
                .collect()
        };
        assert_eq!(bits(&a), bits(&b), "{family}: DXF round trip");
        // PLY (ASCII): a property per channel, the first and last vertex rows.
        ok(
            d,
            &[
                "export",
                "m.toml",
                "-o",
                "m.ply",
                "--ascii",
                "--samples",
                "5",
            ],
        );
        let ply = std::fs::read_to_string(d.join("m.ply")).unwrap();
        let header: Vec<&str> = ply
            .lines()
            .filter(|l| l.starts_with("property double"))
            .collect();
        let expected: Vec<String> = ["x", "y", "z"]
            .iter()
            .chain(names)
            .map(|n| format!("property double {n}"))
            .collect();
        assert_eq!(header, expected, "{family}");
        let body: Vec<Vec<f64>> = ply
            .split("end_header\n")
            .nth(1)
            .unwrap()
            .lines()
            .take(5)
            .map(|l| l.split(' ').map(|v| v.parse().unwrap()).collect())
            .collect();
        // x y z, red green blue, then the channels.
        close(&body[0][6..], &first, &format!("{family} PLY first"));
        close(&body[4][6..], &last, &format!("{family} PLY last"));
        // OBJ: the #deg lines hold the channels.
        ok(d, &["export", "m.toml", "-o", "m.obj", "--samples", "5"]);
        let obj = std::fs::read_to_string(d.join("m.obj")).unwrap();
        assert!(obj.contains(&format!("one per vertex in order: {}\n", names.join(" "))));
        let deg: Vec<Vec<f64>> = obj
            .lines()
            .filter_map(|l| l.strip_prefix("#deg "))
            .map(|l| l.split(' ').map(|v| v.parse().unwrap()).collect())
            .collect();
        assert_eq!(deg.len(), 5);
        close(&deg[0], &first, &format!("{family} OBJ first"));
        close(&deg[4], &last, &format!("{family} OBJ last"));
        // STEP: the control points named by their channels.
        ok(d, &["export", "m.toml", "-o", "m.step"]);
        let step = std::fs::read_to_string(d.join("m.step")).unwrap();
        let label: Vec<String> = names
            .iter()
            .zip(&first)
            .map(|(n, v)| format!("{n}={v}"))
            .collect();
        assert!(
            step.contains(&format!("'P0 {}'", label.join(" "))),
            "{family}: {step}"
        );
        // glTF: an attribute per channel, named `_` and the channel in capitals.
        ok(d, &["export", "m.toml", "-o", "m.gltf", "--samples", "5"]);
        let gltf = std::fs::read_to_string(d.join("m.gltf")).unwrap();
        for name in names {
            assert!(
                gltf.contains(&format!("\"_{}\"", name.to_ascii_uppercase())),
                "{family}: {name}"
            );
        }
        assert!(!gltf.contains("\"_FALSITY\"") || family == Family::BipolarNeutrosophic);
    }
}

/// A rational curve of every wide family (a cubic NURBS curve with weights 1, 2, 0.5, 1 and an
/// interior knot) elevated once and reduced once within 1e-9 comes back: the same knots, and
/// the channels and positions of the original at several parameters (both lanes reduced in
/// homogeneous form as one spline).
#[test]
fn a_rational_wide_curve_elevated_then_reduced_comes_back() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let positions = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 1.0], [6.0, 0.0]];
    let weights = [1.0, 2.0, 0.5, 1.0, 1.5];
    for family in WIDE {
        let text = model_toml(
            family,
            "nurbs",
            Some("0, 0, 0, 0, 0.4, 1, 1, 1, 1"),
            &positions,
            None,
        );
        // A weight for every control point, after its y.
        let mut chunks: Vec<String> = text
            .split("[[control_points]]\n")
            .map(str::to_owned)
            .collect();
        for (chunk, w) in chunks[1..].iter_mut().zip(weights) {
            let end = chunk.find('\n').unwrap() + 1;
            let end = end + chunk[end..].find('\n').unwrap() + 1;
            chunk.insert_str(end, &format!("weight = {w}\n"));
        }
        let text = chunks.join("[[control_points]]\n");
        std::fs::write(d.join("n.toml"), &text).unwrap();
        let original = load(&d.join("n.toml"));
        assert_eq!(
            original.shape().weights().map(<[f64]>::to_vec),
            Some(weights.to_vec()),
            "{text}"
        );
        ok(
            d,
            &["transform", "n.toml", "-o", "up.toml", "--elevate", "1"],
        );
        let out = ok(
            d,
            &[
                "transform",
                "up.toml",
                "-o",
                "back.toml",
                "--reduce",
                "1",
                "--tolerance",
                "1e-9",
            ],
        );
        assert!(out.stderr.contains("degree 4 -> 3"), "{}", out.stderr);
        let back = load(&d.join("back.toml"));
        assert_eq!(back.shape().curve_knots(), original.shape().curve_knots());
        for t in TS {
            let (p, c) = at(&back, t);
            let (q, e) = at(&original, t);
            for (x, y) in p.iter().chain(&c).zip(q.iter().chain(&e)) {
                assert!(
                    (x - y).abs() < 1e-9,
                    "{family} t={t}: {p:?} {c:?} vs {q:?} {e:?}"
                );
            }
        }
    }
}

/// A B-spline surface file of `family` (5 x 4 points, degrees 2 and 3, an interior knot 0.4
/// in u), 3-D positions, channel values of [`channels`].
fn surface_toml(family: Family) -> String {
    let mut text = format!(
        "kind = \"bspline-surface\"\nmembership = \"{family}\"\nrows = 5\ncols = 4\n\
         degree_u = 2\ndegree_v = 3\nknots_u = [0, 0, 0, 0.4, 0.7, 1, 1, 1]\n\
         knots_v = [0, 0, 0, 0, 1, 1, 1, 1]\n"
    );
    for k in 0..20 {
        let (i, j) = ((k / 4) as f64, (k % 4) as f64);
        text.push_str(&format!(
            "[[control_points]]\nx = {i}\ny = {j}\nz = {}\n",
            (i * 0.7 + j * 1.3).sin()
        ));
        for (name, value) in family.channels().iter().zip(channels(family, k)) {
            text.push_str(&format!("{name} = {value}\n"));
        }
    }
    text
}

/// `--reduce` on a surface of every wide family: the surface elevated in v (exact) and reduced
/// once in v within 1e-9 exits 0, says what it did, passes `neutrospline check`, and gives
/// back the original's control channels and positions to 1e-12 (knots included); without
/// `--direction` it is refused with the reason, and a curve refuses one.
#[test]
fn degree_reduction_of_a_surface_of_every_wide_family() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for family in WIDE {
        std::fs::write(d.join("s.toml"), surface_toml(family)).unwrap();
        let original = load(&d.join("s.toml"));
        ok(
            d,
            &[
                "transform",
                "s.toml",
                "-o",
                "up.toml",
                "--elevate",
                "1",
                "--direction",
                "v",
            ],
        );
        let out = ok(
            d,
            &[
                "transform",
                "up.toml",
                "-o",
                "back.toml",
                "--reduce",
                "1",
                "--tolerance",
                "1e-9",
                "--direction",
                "v",
            ],
        );
        assert!(
            out.stderr
                .contains("degree_v 4 -> 3; largest deviation found")
                && out.stderr.contains(&format!(
                    "over both lanes (tolerance 1e-9); the channels solved jointly under the \
                 {family} rule"
                )),
            "{}",
            out.stderr
        );
        ok(d, &["check", "back.toml"]);
        let back = load(&d.join("back.toml"));
        assert_eq!(back.membership(), family);
        assert_eq!(back.lanes().len(), 2);
        let (Shape::Surface(a), Shape::Surface(b)) = (back.shape(), original.shape()) else {
            unreachable!("surfaces")
        };
        assert_eq!(a.knots_v().knots(), b.knots_v().knots(), "{family}");
        assert_eq!(a.knots_u().knots(), b.knots_u().knots(), "{family}");
        for (p, q) in a.control_points().iter().zip(b.control_points()) {
            close(&p.position, &q.position, &format!("{family} positions"));
        }
        for (x, y) in back
            .control_channels()
            .iter()
            .zip(original.control_channels())
        {
            close(x, &y, &format!("{family} channels"));
        }
    }
    let out = run_in(
        d,
        &[
            "transform",
            "s.toml",
            "-o",
            "x.toml",
            "--reduce",
            "1",
            "--tolerance",
            "1",
        ],
        None,
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr
            .ends_with("s.toml: --reduce on a surface needs --direction u or v\n"),
        "{}",
        out.stderr
    );
    assert!(!d.join("x.toml").exists());
    // A curve of a wide family takes no direction.
    std::fs::write(
        d.join("c.toml"),
        model_toml(Family::IntervalType2, "bezier", None, &POSITIONS, None),
    )
    .unwrap();
    let out = run_in(
        d,
        &[
            "transform",
            "c.toml",
            "-o",
            "x.toml",
            "--reduce",
            "1",
            "--tolerance",
            "1",
            "--direction",
            "u",
        ],
        None,
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr
            .ends_with("c.toml: --direction u is for surfaces; this model is a curve\n"),
        "{}",
        out.stderr
    );
}

/// `--remove-knot` on a surface of every wide family: the knot 0.55 inserted twice in u
/// comes off twice within 1e-9, exits 0, says so, passes `neutrospline check`, and gives back
/// the original's knots and control channels to 1e-12; the original knot 0.4 (the data not
/// made for it) stays, and a value that is not a knot is refused with the knots listed.
#[test]
fn knot_removal_of_a_surface_of_every_wide_family() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for family in WIDE {
        std::fs::write(d.join("s.toml"), surface_toml(family)).unwrap();
        let original = load(&d.join("s.toml"));
        ok(
            d,
            &[
                "transform",
                "s.toml",
                "-o",
                "more.toml",
                "--insert-knot",
                "0.55,0.55",
                "--direction",
                "u",
            ],
        );
        let out = ok(
            d,
            &[
                "transform",
                "more.toml",
                "-o",
                "back.toml",
                "--remove-knot",
                "0.55",
                "--tolerance",
                "1e-9",
                "--direction",
                "u",
            ],
        );
        assert!(
            out.stderr.contains("removed knot u = 0.55 2 of 2 times"),
            "{}",
            out.stderr
        );
        ok(d, &["check", "back.toml"]);
        let back = load(&d.join("back.toml"));
        let (Shape::Surface(a), Shape::Surface(b)) = (back.shape(), original.shape()) else {
            unreachable!("surfaces")
        };
        close(
            a.knots_u().knots(),
            b.knots_u().knots(),
            &format!("{family} knots"),
        );
        for (x, y) in back
            .control_channels()
            .iter()
            .zip(original.control_channels())
        {
            close(x, &y, &format!("{family} channels"));
        }
        let out = ok(
            d,
            &[
                "transform",
                "s.toml",
                "-o",
                "same.toml",
                "--remove-knot",
                "0.4",
                "--tolerance",
                "1e-9",
                "--direction",
                "u",
            ],
        );
        assert!(
            out.stderr.contains(
                "knot u = 0.4 not removed: removing it once would move the curve by more than \
                 the tolerance 1e-9"
            ),
            "{}",
            out.stderr
        );
        ok(d, &["check", "same.toml"]);
    }
    let out = run_in(
        d,
        &[
            "transform",
            "s.toml",
            "-o",
            "x.toml",
            "--remove-knot",
            "0.5",
            "--tolerance",
            "1e-9",
            "--direction",
            "v",
        ],
        None,
    );
    assert_eq!(out.code, 1, "{}", out.stderr);
    assert!(
        out.stderr.ends_with(
            "s.toml: knots_v: 0.5 is not an interior knot (the interior knots are none)\n"
        ),
        "{}",
        out.stderr
    );
    assert!(!d.join("x.toml").exists());
}
