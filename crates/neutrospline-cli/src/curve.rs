//! The curves the command works with, of any kind and dimension.

use neutrospline::{Bezier, BezierDerivative, EvalError, Range};

/// A curve read from a file: planar or spatial. Later kinds (B-spline, NURBS) add variants.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyCurve {
    /// A curve in the plane (x, y).
    Planar(Bezier<2>),
    /// A curve in space (x, y, z).
    Spatial(Bezier<3>),
}

/// Column names of the position, by dimension.
const AXES: [&str; 3] = ["x", "y", "z"];
/// Column names of the degrees.
const DEGREES: [&str; 3] = ["truth", "indeterminacy", "falsity"];

impl AnyCurve {
    /// 2 or 3.
    pub fn dimension(&self) -> usize {
        match self {
            AnyCurve::Planar(_) => 2,
            AnyCurve::Spatial(_) => 3,
        }
    }

    /// The polynomial degree n.
    pub fn degree(&self) -> usize {
        match self {
            AnyCurve::Planar(c) => c.degree(),
            AnyCurve::Spatial(c) => c.degree(),
        }
    }

    /// Number of control points.
    pub fn len(&self) -> usize {
        match self {
            AnyCurve::Planar(c) => c.len(),
            AnyCurve::Spatial(c) => c.len(),
        }
    }

    /// Range (min, max) of truth, indeterminacy and falsity over the control points.
    pub fn degree_ranges(&self) -> [Range; 3] {
        match self {
            AnyCurve::Planar(c) => {
                let b = c.control_bounding_box();
                [b.truth, b.indeterminacy, b.falsity]
            }
            AnyCurve::Spatial(c) => {
                let b = c.control_bounding_box();
                [b.truth, b.indeterminacy, b.falsity]
            }
        }
    }

    /// Column names of a table of samples: `t,x,y[,z],truth,indeterminacy,falsity` and, with
    /// `derivative`, `dx,dy[,dz],dtruth,dindeterminacy,dfalsity`.
    pub fn columns(&self, derivative: bool) -> Vec<String> {
        let names: Vec<&str> = AXES[..self.dimension()]
            .iter()
            .chain(DEGREES.iter())
            .copied()
            .collect();
        let mut columns = vec!["t".to_owned()];
        columns.extend(names.iter().map(|n| (*n).to_owned()));
        if derivative {
            columns.extend(names.iter().map(|n| format!("d{n}")));
        }
        columns
    }

    /// A sampler producing one row per parameter, in the order of [`AnyCurve::columns`].
    pub fn sampler(&self, derivative: bool) -> Sampler<'_> {
        match self {
            AnyCurve::Planar(c) => Sampler::Planar(CurveSampler::new(c, derivative)),
            AnyCurve::Spatial(c) => Sampler::Spatial(CurveSampler::new(c, derivative)),
        }
    }
}

/// Evaluates a curve (and its derivative) row by row.
pub enum Sampler<'a> {
    /// For a planar curve.
    Planar(CurveSampler<'a, 2>),
    /// For a spatial curve.
    Spatial(CurveSampler<'a, 3>),
}

impl Sampler<'_> {
    /// The row at `t`: `t`, the position, the degrees and, if asked, their derivatives.
    ///
    /// # Errors
    /// The core's [`EvalError`] (parameter outside \[0, 1\], overflow).
    pub fn row(&self, t: f64) -> Result<Vec<f64>, EvalError> {
        match self {
            Sampler::Planar(s) => s.row(t),
            Sampler::Spatial(s) => s.row(t),
        }
    }
}

/// A Bézier curve with its hodograph computed once.
pub struct CurveSampler<'a, const D: usize> {
    curve: &'a Bezier<D>,
    derivative: Option<BezierDerivative<D>>,
}

impl<'a, const D: usize> CurveSampler<'a, D> {
    fn new(curve: &'a Bezier<D>, derivative: bool) -> Self {
        CurveSampler {
            curve,
            derivative: derivative.then(|| curve.derivative()),
        }
    }

    fn row(&self, t: f64) -> Result<Vec<f64>, EvalError> {
        let p = self.curve.evaluate(t)?;
        let mut row = Vec::with_capacity(1 + 2 * (D + 3));
        row.push(t);
        row.extend(p.position);
        row.extend(p.degrees.to_array());
        if let Some(derivative) = &self.derivative {
            let d = derivative.evaluate(t)?;
            row.extend(d.position);
            row.extend([d.truth, d.indeterminacy, d.falsity]);
        }
        Ok(row)
    }
}
