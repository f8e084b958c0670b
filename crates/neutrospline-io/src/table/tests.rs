use super::*;

fn output(format: &str, digits: Option<usize>) -> TableOutput {
    let mut output = TableOutput::default();
    output
        .set("format", OptionValue::Word(format.into()))
        .unwrap();
    if let Some(n) = digits {
        output
            .set("digits", OptionValue::Integer(n as i64))
            .unwrap();
    }
    output.validate().unwrap();
    output
}

fn write<C: TableCell>(output: &TableOutput, columns: &[&str], rows: Vec<Vec<C>>) -> String {
    let columns: Vec<String> = columns.iter().map(|c| (*c).to_owned()).collect();
    let mut out = Vec::new();
    write_table(
        &mut out,
        output,
        &columns,
        rows.into_iter().map(Ok::<_, io::Error>),
    )
    .unwrap();
    String::from_utf8(out).unwrap()
}

fn numbers(rows: &[&[f64]]) -> Vec<Vec<Option<f64>>> {
    rows.iter()
        .map(|r| r.iter().copied().map(Some).collect())
        .collect()
}

#[test]
fn csv_and_json_keep_every_digit() {
    let rows = numbers(&[&[0.0, 1.0 - 0.3 - 0.6], &[1.0, 1e-20]]);
    assert_eq!(
        write(&output("csv", None), &["t", "indeterminacy"], rows.clone()),
        "t,indeterminacy\n0,0.09999999999999998\n1,0.00000000000000000001\n"
    );
    assert_eq!(
        write(&output("json", None), &["t", "indeterminacy"], rows),
        "[\n  {\"t\": 0, \"indeterminacy\": 0.09999999999999998},\n  \
         {\"t\": 1, \"indeterminacy\": 0.00000000000000000001}\n]\n"
    );
    assert_eq!(
        write::<Option<f64>>(&output("json", None), &["t"], vec![]),
        "[]\n"
    );
}

#[test]
fn missing_values_and_words() {
    let rows = vec![vec![Cell::Number(0.5), Cell::Missing, Cell::Word("cross")]];
    let columns = ["t_a", "curvature", "contact"];
    assert_eq!(
        write(&output("csv", None), &columns, rows.clone()),
        "t_a,curvature,contact\n0.5,,cross\n"
    );
    assert_eq!(
        write(&output("json", None), &columns, rows.clone()),
        "[\n  {\"t_a\": 0.5, \"curvature\": null, \"contact\": \"cross\"}\n]\n"
    );
    assert_eq!(
        write(&output("latex", None), &columns, rows.clone()),
        "\\begin{tabular}{rrl}\n\\toprule\n$t_a$ & $\\kappa$ & contact \\\\\n\\midrule\n\
         0.5 &  & cross \\\\\n\\bottomrule\n\\end{tabular}\n"
    );
    assert_eq!(
        write(&output("markdown", None), &columns, rows),
        "| t_a | curvature | contact |\n| ---: | ---: | :--- |\n| 0.5 |  | cross |\n"
    );
}

/// Example 1 of the paper at t = 0 and 0.5 under the intuitionistic rule, the indeterminacy
/// derived as 1 - T - F: the rounded formats print what the inputs said.
#[test]
fn latex_and_markdown_round_to_what_the_inputs_justify() {
    let rows = numbers(&[
        &[0.0, 1.0, 3.0, 0.3, 1.0 - 0.3 - 0.6, 0.6],
        &[0.5, 4.625, 4.625, 0.6125, 1.0 - 0.6125 - 0.25, 0.25],
        &[1.0, 9.0, 5.0, 0.7, 1.0 - 0.7 - 0.3, 0.3],
    ]);
    // The derived indeterminacies carry floating-point noise.
    assert_eq!(1.0 - 0.3 - 0.6, 0.09999999999999998);
    assert_eq!(1.0 - 0.7 - 0.3, 5.551115123125783e-17);
    let columns = ["t", "x", "y", "truth", "indeterminacy", "falsity"];
    assert_eq!(
        write(&output("latex", None), &columns, rows.clone()),
        "\\begin{tabular}{rrrrrr}\n\\toprule\n$t$ & $x$ & $y$ & $T$ & $I$ & $F$ \\\\\n\
         \\midrule\n0 & 1 & 3 & 0.3 & 0.1 & 0.6 \\\\\n0.5 & 4.625 & 4.625 & 0.6125 & 0.1375 & \
         0.25 \\\\\n1 & 9 & 5 & 0.7 & 0 & 0.3 \\\\\n\\bottomrule\n\\end{tabular}\n"
    );
    assert_eq!(
        write(&output("markdown", None), &columns, rows.clone()),
        "| t | x | y | truth | indeterminacy | falsity |\n\
         | ---: | ---: | ---: | ---: | ---: | ---: |\n\
         | 0 | 1 | 3 | 0.3 | 0.1 | 0.6 |\n\
         | 0.5 | 4.625 | 4.625 | 0.6125 | 0.1375 | 0.25 |\n\
         | 1 | 9 | 5 | 0.7 | 0 | 0.3 |\n"
    );
    // With --digits, an exact tie (4.625) rounds to even, as Rust's and C's formatting do.
    assert_eq!(
        write(&output("latex", Some(3)), &columns, rows),
        "\\begin{tabular}{rrrrrr}\n\\toprule\n$t$ & $x$ & $y$ & $T$ & $I$ & $F$ \\\\\n\
         \\midrule\n0.00 & 1.00 & 3.00 & 0.300 & 0.100 & 0.600 \\\\\n0.500 & 4.62 & 4.62 & \
         0.613 & 0.138 & 0.250 \\\\\n1.00 & 9.00 & 5.00 & 0.700 & 0.00 & 0.300 \\\\\n\
         \\bottomrule\n\\end{tabular}\n"
    );
}

#[test]
fn negative_numbers_are_minus_signs_in_latex() {
    let rows = numbers(&[&[-0.5, -1e-17, -1e-17, 2.0 / 3.0]]);
    let columns = ["dx", "dtruth", "indeterminacy", "d2y"];
    assert_eq!(
        write(&output("latex", Some(2)), &columns, rows.clone()),
        "\\begin{tabular}{rrrr}\n\\toprule\n$x'$ & $T'$ & $I$ & $y''$ \\\\\n\\midrule\n\
         $-0.50$ & $-0.000000000000000010$ & 0.0 & 0.67 \\\\\n\\bottomrule\n\\end{tabular}\n"
    );
    // The column's magnitude sets what is noise: -1e-17 is noise next to a degree's 1 but not
    // in a column of derivatives that small.
    assert_eq!(
        write(&output("markdown", None), &columns, rows),
        "| dx | dtruth | indeterminacy | d2y |\n| ---: | ---: | ---: | ---: |\n\
         | -0.5 | -0.00000000000000001 | 0 | 0.666666666666667 |\n"
    );
}

#[test]
fn headings_are_typeset() {
    let cases = [
        ("t", "$t$"),
        ("u", "$u$"),
        ("z", "$z$"),
        ("truth", "$T$"),
        ("indeterminacy", "$I$"),
        ("falsity", "$F$"),
        ("score", "score"),
        ("dx", "$x'$"),
        ("d2falsity", "$F''$"),
        ("d3z", "$z'''$"),
        ("dx_du", "$x_{u}$"),
        ("dtruth_duv", "$T_{uv}$"),
        ("nz", "$n_z$"),
        ("arc_length", "arc length"),
        ("curvature", "$\\kappa$"),
        ("x_lo", "$x_{\\mathrm{lo}}$"),
        ("y_centroid", "$y_{\\mathrm{centroid}}$"),
        ("t_a", "$t_a$"),
        ("falsity_b", "$F_b$"),
        ("distance", "distance"),
        ("a&b_c%", "a\\&b c\\%"),
    ];
    for (name, want) in cases {
        assert_eq!(latex_heading(name), want, "{name}");
    }
}

#[test]
fn options_are_checked() {
    let mut output = TableOutput::default();
    assert_eq!(
        output
            .set("digits", OptionValue::Integer(0))
            .unwrap_err()
            .to_string(),
        "digits = 0: significant digits must be 1 to 17 (17 tell every 64-bit float apart)"
    );
    assert_eq!(
        output
            .set("format", OptionValue::Text("xlsx".into()))
            .unwrap_err()
            .to_string(),
        "format = \"xlsx\": expected one of csv, json, latex, markdown"
    );
    output.set("digits", OptionValue::Integer(4)).unwrap();
    assert_eq!(
        output.validate().unwrap_err().to_string(),
        "format and digits exclude each other (csv and json keep every digit of every number; \
         digits rounds the numbers of --format latex or markdown)"
    );
    assert_eq!(output.value_text("digits").unwrap().as_deref(), Some("4"));
    assert_eq!(
        TableOutput::default()
            .value_text("format")
            .unwrap()
            .as_deref(),
        Some("csv")
    );
}
