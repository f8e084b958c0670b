//! Surface operations, one direction at a time, on random B-spline and NURBS surfaces: each
//! exact operation leaves the surface where it was (its values at a grid of parameters within
//! 1e-12 of the scale, degrees within 1e-12), pieces cover their parts, reversal mirrors the
//! parameter, and a knot inserted r times comes off r times.

use neutrospline::{
    ControlPoint, Degrees, Direction, EvaluateSurface, KnotVector, Surface, SurfaceKind,
};

/// A deterministic random stream (xorshift), so that the cases are the same everywhere.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn knots(rng: &mut Rng, p: usize, n: usize) -> KnotVector {
    let mut interior: Vec<f64> = (0..n - p - 1)
        .map(|_| (0.05 + 0.9 * rng.next() * 1000.0).round() / 1000.0)
        .collect();
    interior.sort_by(f64::total_cmp);
    let mut k = vec![0.0; p + 1];
    k.extend(interior);
    k.extend(vec![1.0; p + 1]);
    KnotVector::new(k, p, n).unwrap()
}

fn surfaces() -> Vec<Surface> {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut out = Vec::new();
    for case in 0..8 {
        let (pu, pv) = (1 + case % 3, 2 + case % 2);
        let (rows, cols) = (pu + 2 + case % 3, pv + 3);
        let net: Vec<ControlPoint<3>> = (0..rows * cols)
            .map(|_| {
                let d = Degrees::new(rng.next(), rng.next(), rng.next()).unwrap();
                ControlPoint::new(
                    [
                        10.0 * rng.next(),
                        10.0 * rng.next(),
                        10.0 * rng.next() - 5.0,
                    ],
                    d,
                )
            })
            .collect();
        let (ku, kv) = (knots(&mut rng, pu, rows), knots(&mut rng, pv, cols));
        out.push(if case % 2 == 0 {
            Surface::bspline(rows, cols, net, ku, kv).unwrap()
        } else {
            let w = (0..rows * cols).map(|_| 0.5 + 2.5 * rng.next()).collect();
            Surface::nurbs(rows, cols, net, w, ku, kv).unwrap()
        });
    }
    let d = Degrees::new(0.7, 0.2, 0.1).unwrap();
    let net = (0..12)
        .map(|k| ControlPoint::new([(k / 4) as f64, (k % 4) as f64, ((k * 7) % 5) as f64], d))
        .collect();
    out.push(Surface::bezier(3, 4, net).unwrap());
    out
}

/// Values of `a` at `(u, v)` and of `b` at `map(u, v)` agree on a 13 x 13 grid of `a`'s
/// domain.
fn assert_same(a: &Surface, b: &Surface, map: impl Fn(f64, f64) -> (f64, f64), what: &str) {
    let [du, dv] = a.domain();
    for i in 0..=12 {
        for j in 0..=12 {
            let at = |r: &std::ops::Range<f64>, k: usize| {
                if k == 12 {
                    r.end
                } else {
                    r.start + (r.end - r.start) * k as f64 / 12.0
                }
            };
            let (u, v) = (at(&du, i), at(&dv, j));
            let (bu, bv) = map(u, v);
            let p = a.evaluate(u, v).unwrap();
            let q = b.evaluate(bu, bv).unwrap();
            for c in 0..3 {
                assert!(
                    (p.position[c] - q.position[c]).abs() <= 1e-12 * 10.0,
                    "{what}: ({u}, {v}) axis {c}"
                );
            }
            for (x, y) in p.degrees.to_array().iter().zip(q.degrees.to_array()) {
                assert!((x - y).abs() <= 1e-12, "{what}: ({u}, {v}) degrees");
            }
        }
    }
}

fn valid_degrees(s: &Surface) -> bool {
    s.control_points()
        .iter()
        .all(|p| p.degrees.to_array().iter().all(|v| (0.0..=1.0).contains(v)))
}

#[test]
fn exact_operations_keep_the_surface() {
    for (n, s) in surfaces().iter().enumerate() {
        for direction in [Direction::U, Direction::V] {
            let what = |op: &str| format!("surface {n} {op} {direction}");
            let id = |u, v| (u, v);
            let inserted = s.insert_knot(direction, 0.37, 2).unwrap();
            assert_same(s, &inserted, id, &what("insert"));
            assert!(valid_degrees(&inserted));
            let refined = s.refine(direction, 2);
            assert_same(s, &refined, id, &what("refine"));
            let elevated = s.elevate(direction);
            assert_same(s, &elevated, id, &what("elevate"));
            let degree = |x: &Surface| match direction {
                Direction::U => x.degree_u(),
                Direction::V => x.degree_v(),
            };
            assert_eq!(degree(&elevated), degree(s) + 1);
            let reversed = s.reversed(direction);
            let mirror = |u: f64, v: f64| match direction {
                Direction::U => (1.0 - u, v),
                Direction::V => (u, 1.0 - v),
            };
            assert_same(s, &reversed, mirror, &what("reverse"));
            let moved = s.reparametrized(direction, 2.0, 6.0).unwrap();
            let onto = |u: f64, v: f64| match direction {
                Direction::U => (2.0 + 4.0 * u, v),
                Direction::V => (u, 2.0 + 4.0 * v),
            };
            assert_same(s, &moved, onto, &what("reparametrize"));
            // Pieces: a Bézier surface's on [0, 1], the others keep the parameters; each
            // piece's point is the original's at the corresponding parameter.
            let unit = s.kind() == SurfaceKind::Bezier;
            let to_original = |lo: f64, hi: f64| {
                move |u: f64, v: f64| {
                    let f = |t: f64| if unit { lo + t * (hi - lo) } else { t };
                    match direction {
                        Direction::U => (f(u), v),
                        Direction::V => (u, f(v)),
                    }
                }
            };
            let (left, right) = s.split(direction, 0.4).unwrap();
            assert_same(&left, s, to_original(0.0, 0.4), &what("split left"));
            assert_same(&right, s, to_original(0.4, 1.0), &what("split right"));
            let piece = s.subsegment(direction, 0.2, 0.7).unwrap();
            assert_same(&piece, s, to_original(0.2, 0.7), &what("subsegment"));
            let [du, dv] = piece.domain();
            let range = match direction {
                Direction::U => du,
                Direction::V => dv,
            };
            assert_eq!(range, if unit { 0.0..1.0 } else { 0.2..0.7 });
            // Removal undoes insertion.
            let back = inserted.remove_knot(direction, 0.37, 5, 1e-9).unwrap();
            assert_eq!(back.removed, 2, "{}", what("remove"));
            assert!(back.error <= 1e-9);
            assert_eq!(back.curve.knots_u(), s.knots_u());
            assert_eq!(back.curve.knots_v(), s.knots_v());
            for (p, q) in back.curve.control_points().iter().zip(s.control_points()) {
                for c in 0..3 {
                    assert!(
                        (p.position[c] - q.position[c]).abs() <= 1e-9,
                        "{}",
                        what("remove")
                    );
                }
            }
        }
        // The Bézier patches cover the surface, each on its own part of the domain.
        let patches = s.to_bezier_patches();
        let spans = |k: &KnotVector| k.interior_breakpoints().len() + 1;
        assert_eq!(
            patches.len(),
            spans(s.knots_u()) * spans(s.knots_v()),
            "surface {n}"
        );
        for patch in &patches {
            assert_eq!(patch.knots_u().interior_breakpoints().len(), 0);
            assert_eq!(patch.knots_v().interior_breakpoints().len(), 0);
            if s.kind() != SurfaceKind::Bezier {
                assert_same(patch, s, |u, v| (u, v), &format!("surface {n} patch"));
            }
        }
    }
}

/// An elevated surface reduces back in either direction, its knots and values the original's.
#[test]
fn degree_reduction_undoes_elevation_on_surfaces() {
    for (n, s) in surfaces().iter().enumerate() {
        for direction in [Direction::U, Direction::V] {
            let up = s.elevate(direction);
            let back = up
                .reduce_degree(direction, 1e-9, neutrospline::Family::Neutrosophic)
                .unwrap();
            assert!(
                back.error <= 1e-9,
                "surface {n} {direction}: {}",
                back.error
            );
            assert_eq!(back.curve.knots_u(), s.knots_u(), "surface {n} {direction}");
            assert_eq!(back.curve.knots_v(), s.knots_v(), "surface {n} {direction}");
            assert_same(
                s,
                &back.curve,
                |u, v| (u, v),
                &format!("surface {n} reduce {direction}"),
            );
        }
    }
}
