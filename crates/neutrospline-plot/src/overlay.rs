//! The data overlay of a model: measured points with their degrees, drawn by the `data` view
//! next to the curve fitted to them, and its checks.

use std::ops::Range;

use neutrospline::DegreeKind;

use crate::error::PlotError;

/// Measured data points drawn by the `data` view next to the curve fitted to them.
///
/// The [`data`](crate::View::Data) view draws the model's curve (its crisp positions) as a
/// line, each data point as a marker filled with the viridis colour of its
/// [`color_by`](DataOverlay::color_by) degree (with a colour bar titled, for example, "truth
/// of the data"), and a residual whisker from each point to the curve point it was fitted
/// to: the curve at `parameters[k]` when the parameters are given, else the point of the
/// curve nearest to it. Other views ignore the overlay.
///
/// - `positions[k]`: x, y, z of point `k`; z is ignored (taken as 0) for a 2-D model.
/// - `degrees[k]`: its truth, indeterminacy and falsity, each in \[0, 1\].
/// - `parameters`: optionally, the curve parameter each point was fitted at (inside the
///   curve's domain).
/// - `color_by`: the degree that colours the markers (truth unless set).
///
/// Attach it with [`PlotModel::with_data`](crate::PlotModel::with_data), which checks it.
///
/// ```
/// use neutrospline::DegreeKind;
/// use neutrospline_plot::{render_svg, DataOverlay, PlotModel, PlotOptions, View};
///
/// let model = PlotModel::from(&neutrospline::example1());
/// let data = DataOverlay::new(
///     vec![[2.0, 4.0, 0.0], [5.0, 3.5, 0.0], [8.0, 5.5, 0.0]],
///     vec![[0.8, 0.1, 0.1], [0.5, 0.3, 0.2], [0.2, 0.2, 0.7]],
/// )
/// .with_parameters(vec![0.1, 0.5, 0.9])
/// .with_color_by(DegreeKind::Falsity);
/// let model = model.with_data(data)?;
/// assert_eq!(model.data().map(|d| d.positions.len()), Some(3));
/// let svg = render_svg(&model, View::Data, &PlotOptions::default().with_size(800, 600))?;
/// assert_eq!(svg.matches("class=\"data-point\"").count(), 3);
/// assert_eq!(svg.matches("class=\"residual\"").count(), 3);
/// assert!(svg.contains("falsity of the data"));
/// # Ok::<(), neutrospline_plot::PlotError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct DataOverlay {
    /// The points' positions (x, y, z; z is 0 for a 2-D model).
    pub positions: Vec<[f64; 3]>,
    /// The points' degrees (truth, indeterminacy, falsity), one triple per point.
    pub degrees: Vec<[f64; 3]>,
    /// The curve parameter of each point, when known (from the fit).
    pub parameters: Option<Vec<f64>>,
    /// The surface parameters `(u, v)` of each point, when known (from a surface fit).
    pub surface_parameters: Option<Vec<[f64; 2]>>,
    /// The degree that colours the markers.
    pub color_by: DegreeKind,
}

impl DataOverlay {
    /// The data points of a data file ([`neutrospline_io::DataTable`]) for the `data` view,
    /// coloured by `color_by`, with whiskers at the table's `parameter` column (or its `u`,
    /// `v` columns, for a surface) when it has one (else to the nearest point of the curve or
    /// surface): what `neutrospline plot --data` and the
    /// studio draw.
    pub fn from_table(table: &neutrospline_io::DataTable, color_by: DegreeKind) -> DataOverlay {
        let overlay = DataOverlay::new(
            table.positions().to_vec(),
            table.degrees().iter().map(|d| d.to_array()).collect(),
        )
        .with_color_by(color_by);
        let overlay = match table.parameters() {
            Some(parameters) => overlay.with_parameters(parameters.to_vec()),
            None => overlay,
        };
        match table.surface_parameters() {
            Some(uv) => overlay.with_surface_parameters(uv.to_vec()),
            None => overlay,
        }
    }

    /// Points and their degrees (truth, indeterminacy, falsity), coloured by truth, without
    /// parameters (each whisker then goes to the nearest point of the curve).
    pub fn new(positions: Vec<[f64; 3]>, degrees: Vec<[f64; 3]>) -> DataOverlay {
        DataOverlay {
            positions,
            degrees,
            parameters: None,
            surface_parameters: None,
            color_by: DegreeKind::Truth,
        }
    }

    /// The curve parameter each point was fitted at, one per point: each whisker goes to the
    /// curve at its point's parameter.
    pub fn with_parameters(mut self, parameters: Vec<f64>) -> Self {
        self.parameters = Some(parameters);
        self
    }

    /// Sets each point's surface parameters `(u, v)` (for a surface: the whisker of point `k`
    /// goes to the surface at `parameters[k]`).
    pub fn with_surface_parameters(mut self, parameters: Vec<[f64; 2]>) -> Self {
        self.surface_parameters = Some(parameters);
        self
    }

    /// The degree whose value colours the markers.
    pub fn with_color_by(mut self, kind: DegreeKind) -> Self {
        self.color_by = kind;
        self
    }

    /// The overlay checked for a surface over `domain` (`[u range, v range]`): as for a 3-D
    /// curve, and the surface parameters one per point, finite and inside the domain.
    pub(crate) fn checked_on_surface(
        mut self,
        domain: [Range<f64>; 2],
    ) -> Result<DataOverlay, PlotError> {
        if self.parameters.is_some() {
            return Err(PlotError::ParameterKind {
                given: "curve parameters t",
                model: "surface",
            });
        }
        let uv = self.surface_parameters.take();
        let mut checked = self.checked(3, 0.0..1.0)?;
        if let Some(uv) = &uv {
            let points = checked.positions.len();
            if uv.len() != points {
                return Err(PlotError::DataCount {
                    what: "(u, v) parameters",
                    count: uv.len(),
                    points,
                });
            }
            for (index, pair) in uv.iter().enumerate() {
                for (k, (&value, range)) in pair.iter().zip(&domain).enumerate() {
                    let channel = ["u", "v"][k];
                    if !value.is_finite() {
                        return Err(PlotError::NotFinite {
                            what: "data point",
                            index,
                            channel,
                            value,
                        });
                    }
                    if value < range.start || value > range.end {
                        return Err(PlotError::SurfaceParameterOutsideDomain {
                            index,
                            channel,
                            value,
                            start: range.start,
                            end: range.end,
                        });
                    }
                }
            }
        }
        checked.surface_parameters = uv;
        Ok(checked)
    }

    /// The overlay checked for a curve of `dimension` (2 or 3) over `domain`, with z set to
    /// 0 for a 2-D curve.
    pub(crate) fn checked(
        mut self,
        dimension: usize,
        domain: Range<f64>,
    ) -> Result<DataOverlay, PlotError> {
        let points = self.positions.len();
        if points == 0 {
            return Err(PlotError::EmptyData);
        }
        if self.surface_parameters.is_some() {
            return Err(PlotError::ParameterKind {
                given: "surface parameters (u, v)",
                model: "curve",
            });
        }
        if self.degrees.len() != points {
            return Err(PlotError::DataCount {
                what: "degree triples",
                count: self.degrees.len(),
                points,
            });
        }
        if let Some(ts) = &self.parameters {
            if ts.len() != points {
                return Err(PlotError::DataCount {
                    what: "parameters",
                    count: ts.len(),
                    points,
                });
            }
        }
        if dimension == 2 {
            for p in &mut self.positions {
                p[2] = 0.0;
            }
        }
        for (index, (p, d)) in self.positions.iter().zip(&self.degrees).enumerate() {
            for (axis, &value) in p.iter().enumerate() {
                if !value.is_finite() {
                    return Err(PlotError::NotFinite {
                        what: "data point",
                        index,
                        channel: ["x", "y", "z"][axis],
                        value,
                    });
                }
            }
            for kind in DegreeKind::ALL {
                let value = d[kind.index()];
                if !value.is_finite() {
                    return Err(PlotError::NotFinite {
                        what: "data point",
                        index,
                        channel: kind.name(),
                        value,
                    });
                }
                if !(0.0..=1.0).contains(&value) {
                    return Err(PlotError::DataDegreeRange {
                        index,
                        channel: kind.name(),
                        value,
                    });
                }
            }
        }
        if let Some(ts) = &self.parameters {
            for (index, &value) in ts.iter().enumerate() {
                if !value.is_finite() {
                    return Err(PlotError::NotFinite {
                        what: "data point",
                        index,
                        channel: "t",
                        value,
                    });
                }
                if value < domain.start || value > domain.end {
                    return Err(PlotError::ParameterOutsideDomain {
                        index,
                        value,
                        start: domain.start,
                        end: domain.end,
                    });
                }
            }
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two() -> DataOverlay {
        DataOverlay::new(
            vec![[0.0, 1.0, 5.0], [2.0, 3.0, -1.0]],
            vec![[0.5, 0.1, 0.2], [1.0, 0.0, 0.0]],
        )
    }

    #[test]
    fn overlay_defaults_and_builders() {
        let d = two();
        assert_eq!(d.color_by, DegreeKind::Truth);
        assert_eq!(d.parameters, None);
        let d = d
            .with_parameters(vec![0.0, 1.0])
            .with_color_by(DegreeKind::Indeterminacy);
        assert_eq!(d.parameters, Some(vec![0.0, 1.0]));
        assert_eq!(d.color_by, DegreeKind::Indeterminacy);
    }

    #[test]
    fn overlay_2d_ignores_z() {
        let d = two().checked(2, 0.0..1.0).unwrap();
        assert_eq!(d.positions, vec![[0.0, 1.0, 0.0], [2.0, 3.0, 0.0]]);
        let mut nan_z = two();
        nan_z.positions[1][2] = f64::NAN;
        assert!(nan_z.clone().checked(2, 0.0..1.0).is_ok());
        assert_eq!(
            nan_z.checked(3, 0.0..1.0).unwrap_err().to_string(),
            "data point 1: z = NaN is not a finite number"
        );
    }
}
