//! Properties of surface fitting (SPEC section 4): interpolation, reproduction, bounds,
//! the two solvers' agreement, refusals.

use super::*;
use crate::surface::EvaluateSurface;

fn pseudo(k: usize) -> f64 {
    ((k as f64 * 0.7548776662466927 + 0.1).fract() - 0.5) * 2.0
}

/// A `rows x cols` grid over `[0, 3] x [0, 2]` of `z = f(x, y)` with smooth degrees.
fn grid_data(rows: usize, cols: usize, f: impl Fn(f64, f64) -> f64) -> SurfaceFitData {
    let (mut positions, mut degrees) = (Vec::new(), Vec::new());
    for k in 0..rows {
        for l in 0..cols {
            let x = 3.0 * k as f64 / (rows - 1) as f64 + 0.05 * (0.2 * l as f64).sin();
            let y = 2.0 * l as f64 / (cols - 1) as f64;
            positions.push([x, y, f(x, y)]);
            degrees.push(Degrees::new(0.2 + 0.2 * x, 0.1 + 0.1 * y, 0.3).unwrap());
        }
    }
    SurfaceFitData::grid(rows, cols, positions, degrees).unwrap()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn interpolation_passes_through_every_grid_point() {
    let data = grid_data(7, 5, |x, y| (x * 1.3).sin() * (y * 0.7).cos() + 0.2 * x * y);
    for parametrization in [
        Parametrization::Uniform,
        Parametrization::ChordLength,
        Parametrization::Centripetal,
    ] {
        for (p, q) in [(3, 2), (1, 1), (4, 4)] {
            let options = SurfaceFitOptions::default()
                .with_degrees(p, q)
                .with_parametrization(parametrization)
                .with_target(SurfaceTarget::Interpolate);
            let fitted = fit_surface(&data, &options).unwrap();
            assert!(fitted.report.two_pass);
            assert_eq!(fitted.report.control_points, [7, 5]);
            for (k, uv) in fitted.parameters.iter().enumerate() {
                let s = fitted.surface.evaluate(uv[0], uv[1]).unwrap();
                for a in 0..3 {
                    assert!(
                        close(s.position[a], data.positions()[k][a], 1e-12 * 3.0),
                        "{parametrization:?} ({p}, {q}) point {k}"
                    );
                }
                let want = data.degrees()[k].to_array();
                let got = s.degrees.to_array();
                for c in 0..3 {
                    assert!(close(got[c], want[c], 1e-12), "{k} {c}");
                }
            }
            assert!(fitted.report.worst_distance < 1e-12 * 3.0);
        }
    }
}

#[test]
fn a_bicubic_polynomial_is_reproduced_by_both_solvers() {
    // Degree (3, 2) polynomials lie in every spline space of those degrees.
    let f = |x: f64, y: f64| 0.3 * x * x * x - x * y * y + 0.5 * y - 1.0;
    let data = grid_data(12, 9, f);
    let options = SurfaceFitOptions::default()
        .with_degrees(3, 2)
        .with_target(SurfaceTarget::ControlPoints([6, 5]));
    let grid = fit_surface(&data, &options).unwrap();
    assert!(grid.report.two_pass);
    // The x of the data is not a polynomial of (u, v), but z along the data is reproduced
    // only if x and y are: check z via a scattered fit with (u, v) = (x, y) instead.
    let scattered =
        SurfaceFitData::scattered(data.positions().to_vec(), data.degrees().to_vec()).unwrap();
    let options = options.with_projection(Projection::Xy);
    let fitted = fit_surface(&scattered, &options).unwrap();
    assert!(!fitted.report.two_pass);
    // The degrees are linear in x and y: reproduced too. z is cubic in x, quadratic in y.
    assert!(
        fitted.report.max("z").unwrap() < 1e-11,
        "{:?}",
        fitted.report
    );
    assert!(fitted.report.max("truth").unwrap() < 1e-12);
    assert!(grid.report.condition_estimate >= 1.0);
}

#[test]
fn the_two_pass_solver_matches_the_whole_system() {
    let data = grid_data(10, 8, |x, y| {
        (x + 0.3 * y).sin() + 0.01 * pseudo((x * 100.0) as usize)
    });
    let options = SurfaceFitOptions::default()
        .with_degrees(3, 3)
        .with_target(SurfaceTarget::ControlPoints([6, 5]));
    let two = fit_surface(&data, &options).unwrap();
    assert!(two.report.two_pass);
    // Equal weights of 2 give the same least-squares solution through the whole system.
    let weighted = data.clone().with_weights(vec![2.0; data.len()]).unwrap();
    let whole = fit_surface(&weighted, &options.clone().with_weights(DataWeights::Given)).unwrap();
    assert!(!whole.report.two_pass);
    for (a, b) in two
        .surface
        .control_points()
        .iter()
        .zip(whole.surface.control_points())
    {
        for i in 0..3 {
            assert!(close(a.position[i], b.position[i], 1e-11), "{a:?} {b:?}");
        }
        for (x, y) in a.degrees.to_array().iter().zip(b.degrees.to_array()) {
            assert!(close(*x, y, 1e-11));
        }
    }
    let ratio = two.report.condition_estimate / whole.report.condition_estimate;
    assert!(ratio > 0.1 && ratio < 10.0, "{ratio}");
}

#[test]
fn degrees_stay_valid_under_every_rule_for_jumping_data() {
    // Degrees jumping 0 -> 1 -> 0 along u (and the rule's complement), which an
    // unconstrained fit overshoots.
    for membership in [Family::Neutrosophic, Family::Intuitionistic, Family::Fuzzy] {
        let (rows, cols) = (16, 9);
        let (mut positions, mut degrees) = (Vec::new(), Vec::new());
        for k in 0..rows {
            for l in 0..cols {
                positions.push([k as f64, l as f64, 0.1 * (k * l) as f64]);
                let on = if (5..10).contains(&k) { 1.0 } else { 0.0 };
                let d = match membership {
                    Family::Neutrosophic => Degrees::new(on, 1.0 - on, on),
                    Family::Intuitionistic => Degrees::intuitionistic(on, 1.0 - on),
                    family => Degrees::with_membership(family, on, None, None),
                };
                degrees.push(d.unwrap());
            }
        }
        let grid = SurfaceFitData::grid(rows, cols, positions.clone(), degrees.clone()).unwrap();
        let scattered = SurfaceFitData::scattered(positions, degrees).unwrap();
        for data in [grid, scattered] {
            let options = SurfaceFitOptions::default()
                .with_membership(membership)
                .with_projection(Projection::Xy)
                .with_target(SurfaceTarget::ControlPoints([10, 5]));
            let fitted = fit_surface(&data, &options).unwrap();
            assert!(!fitted.report.at_bound.is_empty(), "{membership:?}");
            for cp in fitted.surface.control_points() {
                cp.degrees.check_membership(membership).unwrap();
            }
            let [du, dv] = fitted.surface.domain();
            for a in 0..=20 {
                for b in 0..=10 {
                    let u = du.start + (du.end - du.start) * a as f64 / 20.0;
                    let v = dv.start + (dv.end - dv.start) * b as f64 / 10.0;
                    // Convex combinations of valid control values, to rounding.
                    let [t, i, f] = fitted.surface.evaluate(u, v).unwrap().degrees.to_array();
                    let e = 1e-14;
                    assert!([t, i, f].iter().all(|x| (-e..=1.0 + e).contains(x)));
                    if membership == Family::Intuitionistic {
                        assert!(t + f <= 1.0 + e);
                    }
                }
            }
        }
    }
}

/// Scattered points over `[0, 1]^2` with a hole `[0.3, 0.7]^2`.
fn holed() -> SurfaceFitData {
    let (mut positions, mut degrees) = (Vec::new(), Vec::new());
    for k in 0..2000 {
        let (x, y) = (
            0.5 + 0.5 * pseudo(k),
            (k as f64 * 0.414_213_562_373_095_1).fract(),
        );
        if (0.3..0.7).contains(&x) && (0.3..0.7).contains(&y) {
            continue;
        }
        positions.push([x, y, x * x - y]);
        degrees.push(Degrees::new(0.5, 0.25, 0.25).unwrap());
    }
    SurfaceFitData::scattered(positions, degrees).unwrap()
}

#[test]
fn an_empty_cell_is_named_unless_smoothing_fills_it() {
    let data = holed();
    let options = SurfaceFitOptions::default()
        .with_degrees(1, 1)
        .with_projection(Projection::Xy)
        .with_target(SurfaceTarget::ControlPoints([12, 12]));
    let error = fit_surface(&data, &options).unwrap_err();
    let FitError::EmptyCell { row, col, u, v } = error else {
        panic!("{error}")
    };
    assert!(
        u[0] >= 0.29 && u[1] <= 0.71 && v[0] >= 0.29 && v[1] <= 0.71,
        "{u:?} {v:?}"
    );
    assert!((row, col) > (0, 0));
    let smoothed = options.clone().with_smoothing(1e-6);
    let fitted = fit_surface(&data, &smoothed).unwrap();
    assert!(!fitted.report.data_in_every_support);
    // The hole is bridged by the quadratic's own surface (within the smoothing's pull).
    let s = fitted.surface.evaluate(0.5, 0.5).unwrap();
    assert!(close(s.position[2], -0.25, 0.05), "{}", s.position[2]);
}

#[test]
fn the_tolerance_is_met_or_said_not_to_be() {
    let data = grid_data(30, 25, |x, y| (1.5 * x).sin() * y.cos());
    let options = SurfaceFitOptions::default().with_target(SurfaceTarget::Tolerance(1e-3));
    let fitted = fit_surface(&data, &options).unwrap();
    assert_eq!(
        fitted.report.tolerance_met,
        Some(true),
        "{:?}",
        fitted.report
    );
    assert!(fitted.report.worst_distance <= 1e-3);
    assert!(fitted.report.control_points[0] < 30);
    // Noisy scattered data cannot be met to 1e-9 without interpolating every point.
    let noisy = holed();
    let positions: Vec<[f64; 3]> = noisy
        .positions()
        .iter()
        .enumerate()
        .map(|(k, p)| [p[0], p[1], p[2] + 0.01 * pseudo(3 * k + 1)])
        .collect();
    let noisy = SurfaceFitData::scattered(positions, noisy.degrees().to_vec()).unwrap();
    let options = SurfaceFitOptions::default()
        .with_projection(Projection::Xy)
        .with_smoothing(1e-8)
        .with_target(SurfaceTarget::Tolerance(1e-9));
    let fitted = fit_surface(&noisy, &options).unwrap();
    assert_eq!(fitted.report.tolerance_met, Some(false));
    assert!(fitted.report.worst_distance > 1e-9);
}

#[test]
fn bad_input_is_refused_with_its_place() {
    let d = Degrees::new(0.5, 0.5, 0.5).unwrap();
    let grid = SurfaceFitData::grid(3, 4, vec![[0.0; 3]; 11], vec![d; 11]).unwrap_err();
    assert_eq!(
        grid.to_string(),
        "a grid of 3 x 4 points does not hold 11 points (rows x cols must be the number of \
         points, each at least 1)"
    );
    let nan = SurfaceFitData::scattered(vec![[0.0, f64::NAN, 0.0]], vec![d]).unwrap_err();
    assert_eq!(nan.to_string(), "point 0: y = NaN is not a finite number");
    let few = grid_data(3, 3, |x, _| x);
    let interpolate = SurfaceFitOptions::default().with_target(SurfaceTarget::Interpolate);
    assert_eq!(
        fit_surface(&few, &interpolate).unwrap_err().to_string(),
        "9 points are too few: interpolation with degree 3 needs at least 4 rows (3 here)"
    );
    let scattered =
        SurfaceFitData::scattered(few.positions().to_vec(), few.degrees().to_vec()).unwrap();
    assert!(fit_surface(&scattered, &interpolate)
        .unwrap_err()
        .to_string()
        .starts_with("interpolation needs gridded data"));
    // Repeated rows with chord-length parameters cannot be interpolated.
    let mut positions = few.positions().to_vec();
    for l in 0..3 {
        positions[3 + l] = positions[l];
    }
    let repeated = SurfaceFitData::grid(3, 3, positions, few.degrees().to_vec()).unwrap();
    let options = interpolate.with_degrees(2, 2);
    assert_eq!(
        fit_surface(&repeated, &options).unwrap_err().to_string(),
        "grid rows 0 and 1 have one parameter (0): interpolation needs distinct ones (the rows \
         coincide; remove one, or give parameters)"
    );
}
