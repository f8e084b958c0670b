//! Projections onto the membership families' rules against a conic solver
//! (`tests/data/family_projections.json`, made by
//! `scripts/reference/make_family_projection_reference.py` with cvxpy and Clarabel): the
//! core's projection is exactly feasible, leaves a valid point unchanged, and its squared
//! distance agrees with the reference optimum within 1e-9 relative (the conic solver's answer
//! polished to 60 digits on its active constraints; see the script).

use neutrospline::Family;
use serde::Deserialize;

#[derive(Deserialize)]
struct File {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    family: String,
    point: Vec<f64>,
    projection: Vec<f64>,
    objective: f64,
    inside: bool,
}

#[test]
fn projections_match_the_conic_solver() {
    let file: File = serde_json::from_str(include_str!("../data/family_projections.json")).unwrap();
    let mut worst = 0.0f64;
    let mut worst_point = 0.0f64;
    let mut outside = 0;
    for case in &file.cases {
        let family: Family = case.family.parse().unwrap();
        let mut z = case.point.clone();
        family.project(&mut z);
        family
            .check(&z)
            .unwrap_or_else(|e| panic!("{}: {:?} -> {z:?}: {e}", case.family, case.point));
        if case.inside {
            assert_eq!(z, case.point, "{}: a valid point moves", case.family);
            continue;
        }
        outside += 1;
        let objective: f64 = z
            .iter()
            .zip(&case.point)
            .map(|(a, b)| (a - b) * (a - b))
            .sum();
        let relative = (objective - case.objective).abs() / case.objective;
        let distance = z
            .iter()
            .zip(&case.projection)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        worst = worst.max(relative);
        worst_point = worst_point.max(distance);
    }
    eprintln!("{outside} outside points: worst relative objective difference {worst:e}, worst point difference {worst_point:e}");
    assert!(outside > 300);
    // Measured: 5.6e-13 and 4.4e-16.
    assert!(worst <= 1e-9, "{worst:e}");
    assert!(worst_point <= 1e-9, "{worst_point:e}");
}
