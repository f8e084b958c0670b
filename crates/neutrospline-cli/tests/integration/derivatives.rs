//! End-to-end tests of `eval --derivative N` (N = 1, 2, 3): exact column names for curves and
//! surfaces, values against closed forms (Example 1: C'' = 6 (P_2 - 2 P_1 + P_0),
//! C''' = 6 (P_3 - 3 P_2 + 3 P_1 - P_0); the unit circle: |C''| = |C'|^2 at t = 0) and the
//! sympy reference of `scripts/reference/make_higher_derivative_reference.py`, the first
//! derivative unchanged, and the usage errors.

use crate::util::examples_dir;

/// Runs the binary in the examples directory.
fn run(args: &[&str]) -> (i32, String, String) {
    crate::util::run(&examples_dir(), args)
}

/// Runs the binary in the examples directory and expects exit 0 with nothing on stderr.
fn ok(args: &[&str]) -> String {
    crate::util::ok(&examples_dir(), args)
}

/// The value of `column` in data row `row` of a CSV table.
fn cell(table: &str, row: usize, column: &str) -> f64 {
    let mut lines = table.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|c| *c == column).expect(column);
    let line = lines.nth(row).unwrap();
    line.split(',').nth(k).unwrap().parse().unwrap()
}

#[test]
fn eval_derivative_orders_add_their_columns_for_curves() {
    let first = "t,x,y,truth,indeterminacy,falsity,dx,dy,dtruth,dindeterminacy,dfalsity";
    let second = ",d2x,d2y,d2truth,d2indeterminacy,d2falsity";
    let third = ",d3x,d3y,d3truth,d3indeterminacy,d3falsity";
    let alone = ok(&["eval", "example1.toml", "--at", "0,0.5,1", "--derivative"]);
    assert_eq!(alone.lines().next().unwrap(), first);
    // `--derivative 1` is `--derivative`, byte for byte.
    assert_eq!(
        ok(&[
            "eval",
            "example1.toml",
            "--at",
            "0,0.5,1",
            "--derivative",
            "1"
        ]),
        alone
    );
    assert_eq!(
        ok(&["eval", "example1.toml", "--at", "0,0.5,1", "--derivative=1"]),
        alone
    );
    let two = ok(&[
        "eval",
        "example1.toml",
        "--at",
        "0,0.5,1",
        "--derivative",
        "2",
    ]);
    assert_eq!(two.lines().next().unwrap(), format!("{first}{second}"));
    let three = ok(&[
        "eval",
        "example1.toml",
        "--at",
        "0,0.5,1",
        "--derivative",
        "3",
    ]);
    assert_eq!(
        three.lines().next().unwrap(),
        format!("{first}{second}{third}")
    );
    // The lower orders' columns are the same numbers in every table.
    for (a, b) in alone.lines().zip(three.lines()).skip(1) {
        assert!(b.starts_with(a), "{a} / {b}");
    }
    // Example 1: C'' = 6 (P_2 - 2 P_1 + P_0) at t = 0, 6 (P_3 - 2 P_2 + P_1) at t = 1;
    // C''' = 6 (P_3 - 3 P_2 + 3 P_1 - P_0) = (-6, 84) everywhere.
    assert_eq!(
        (cell(&three, 0, "d2x"), cell(&three, 0, "d2y")),
        (6.0, -42.0)
    );
    assert_eq!(
        (cell(&three, 2, "d2x"), cell(&three, 2, "d2y")),
        (0.0, 42.0)
    );
    for row in 0..3 {
        assert_eq!(
            (cell(&three, row, "d3x"), cell(&three, row, "d3y")),
            (-6.0, 84.0)
        );
    }
    // truth'' at t = 0: 6 (0.7 - 1.6 + 0.3) = -3.6.
    assert!((cell(&three, 0, "d2truth") + 3.6).abs() < 1e-14);
    // A 3-D curve has a z column in every order.
    let helix = ok(&["eval", "helix3d.toml", "--at", "0.5", "--derivative", "2"]);
    assert!(helix.lines().next().unwrap().ends_with(
        ",dx,dy,dz,dtruth,dindeterminacy,dfalsity,d2x,d2y,d2z,d2truth,d2indeterminacy,d2falsity"
    ));
}

#[test]
fn eval_derivative_of_the_nurbs_circle_and_the_bspline() {
    let t = ok(&[
        "eval",
        "nurbs-circle.toml",
        "--at",
        "0,0.1",
        "--derivative",
        "3",
    ]);
    // At t = 0 the speed is 8 w (w = sqrt(2) / 2) and the acceleration points at the centre
    // with magnitude speed^2 / radius = 32.
    let w = std::f64::consts::FRAC_1_SQRT_2;
    assert!((cell(&t, 0, "dy") - 8.0 * w).abs() < 1e-14);
    assert!((cell(&t, 0, "d2x") + 32.0).abs() < 1e-13);
    // The sympy reference (tests/data/higher_derivatives.json of the core) at t = 0.1.
    for (column, want) in [
        ("d2x", -37.34550753536714),
        ("d2y", -22.256055277883547),
        ("d3x", 189.19591777349703),
        ("d3y", -386.9298801740179),
        ("d3truth", 76.5321715721012),
    ] {
        let got = cell(&t, 1, column);
        assert!(
            (got - want).abs() < 1e-11 * 400.0,
            "{column}: {got} vs {want}"
        );
    }
    // A cubic B-spline's third derivative is constant on each span: the same at 0.3 and 0.45.
    let b = ok(&[
        "eval",
        "bspline.toml",
        "--at",
        "0.3,0.45",
        "--derivative",
        "3",
    ]);
    assert_eq!(cell(&b, 0, "d3x"), cell(&b, 1, "d3x"));
}

#[test]
fn eval_derivative_orders_add_mixed_partials_for_surfaces() {
    let channels = ["x", "y", "z", "truth", "indeterminacy", "falsity"];
    let names = |suffixes: &[&str]| -> String {
        suffixes
            .iter()
            .flat_map(|s| channels.iter().map(move |c| format!(",d{c}_{s}")))
            .collect()
    };
    let base = "u,v,x,y,z,truth,indeterminacy,falsity";
    let one = ok(&[
        "eval",
        "nurbs-surface.json",
        "--at",
        "0.3:0.2",
        "--derivative",
    ]);
    assert_eq!(
        one.lines().next().unwrap(),
        format!("{base}{}", names(&["du", "dv"]))
    );
    let three = ok(&[
        "eval",
        "nurbs-surface.json",
        "--at",
        "0.3:0.2",
        "--derivative",
        "3",
    ]);
    assert_eq!(
        three.lines().next().unwrap(),
        format!(
            "{base}{}",
            names(&["du", "dv", "duu", "duv", "dvv", "duuu", "duuv", "duvv", "dvvv"])
        )
    );
    assert!(three
        .lines()
        .nth(1)
        .unwrap()
        .starts_with(one.lines().nth(1).unwrap()));
    // The quarter cylinder: straight along v (every partial with v twice vanishes), and the
    // sympy reference for the u partials.
    for (column, want) in [
        ("dx_duu", -2.5236878762942196),
        ("dy_duu", -0.7608488877219748),
        ("dindeterminacy_duu", 0.35256779771444896),
        ("dx_duuu", 0.8289754914623805),
        ("dy_duuu", -6.409423629921164),
    ] {
        let got = cell(&three, 0, column);
        assert!(
            (got - want).abs() < 1e-12 * 10.0,
            "{column}: {got} vs {want}"
        );
    }
    for column in ["dz_dvv", "dx_duvv", "dz_dvvv", "dx_duv"] {
        assert!(cell(&three, 0, column).abs() < 1e-13, "{column}");
    }
}

#[test]
fn eval_derivative_order_errors() {
    for bad in ["0", "4", "two"] {
        let (code, stdout, stderr) = run(&["eval", "example1.toml", "--derivative", bad]);
        assert_eq!((code, stdout.as_str()), (2, ""));
        assert_eq!(
            stderr.lines().next().unwrap(),
            format!(
                "error: invalid value '{bad}' for '--derivative [<N>]': `{bad}` is not a \
                 derivative order 1, 2 or 3 (--derivative alone means 1; a file named right \
                 after it is read as the order: put the file first)"
            )
        );
    }
}
