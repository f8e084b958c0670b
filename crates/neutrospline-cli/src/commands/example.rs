//! `neutrospline example`: the paper's Example 1 from built-in data.

use neutrospline::{example1, EXAMPLE1_NAMES};

use crate::output::{self, number, rounded, Align};

/// Arguments of `example`. (A later step adds `--out DIR` for the paper's figures.)
#[derive(Debug, clap::Args)]
pub struct ExampleArgs {}

/// Number of intervals of the curve table: t = k / STEPS.
const STEPS: u32 = 10;
/// Decimals shown in the curve table.
const DECIMALS: usize = 6;

/// The note printed under the tables (SPEC section 5).
pub const ERRATUM: &str =
    "Note: the paper's Table 3 gives C3 an indeterminacy of 0.1, but Table 1, \
which defines the example, gives 0.4; this output follows Table 1.";

/// Prints the control points and the curve at t = 0, 0.1, ..., 1.
///
/// # Errors
/// A write error, or an evaluation error (none for the built-in data).
pub fn run(_args: &ExampleArgs) -> anyhow::Result<()> {
    let curve = example1();
    let header = ["t", "x", "y", "truth", "indeterminacy", "falsity"];
    let right = [Align::Right; 6];

    let mut points = Vec::new();
    for (i, p) in curve.control_points().iter().enumerate() {
        let mut row = vec![EXAMPLE1_NAMES
            .get(i)
            .map_or_else(|| format!("C{i}"), |n| (*n).to_owned())];
        row.extend(
            p.position
                .iter()
                .chain(&p.degrees.to_array())
                .map(|&v| number(v)),
        );
        points.push(row);
    }
    let mut samples = Vec::new();
    for k in 0..=STEPS {
        let t = f64::from(k) / f64::from(STEPS);
        let p = curve.evaluate(t)?;
        let mut row = vec![number(t)];
        row.extend(
            p.position
                .iter()
                .chain(&p.degrees.to_array())
                .map(|&v| rounded(v, DECIMALS)),
        );
        samples.push(row);
    }

    output::emit(None, |w| {
        writeln!(
            w,
            "Example 1 of \"A Neutrosophic Bezier Curve Model using Control Points\": \
             a cubic (degree {}) neutrosophic Bezier curve in the plane.",
            curve.degree()
        )?;
        writeln!(w)?;
        writeln!(w, "Control points")?;
        let mut point_header = header;
        point_header[0] = "point";
        let mut point_align = right;
        point_align[0] = Align::Left;
        output::write_text_table(w, &point_header, &point_align, &points)?;
        writeln!(w)?;
        writeln!(
            w,
            "Curve at t = k/{STEPS}, k = 0..{STEPS} (values rounded to {DECIMALS} decimals)"
        )?;
        output::write_text_table(w, &header, &right, &samples)?;
        writeln!(w)?;
        writeln!(w, "{ERRATUM}")?;
        Ok(())
    })
}
