//! The errors of this crate.

/// Why a figure could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    /// A view name that [`View`](crate::View) does not know.
    #[error("unknown view \"{name}\" (expected one of: controls, truth, indeterminacy, falsity, all, plane)")]
    UnknownView {
        /// The name given.
        name: String,
    },
    /// Image width or height outside the supported range.
    #[error("image size {width}x{height} is not supported (each side must be between {min} and {max} pixels)")]
    InvalidSize {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// Smallest supported side.
        min: u32,
        /// Largest supported side.
        max: u32,
    },
    /// Number of curve samples outside the supported range.
    #[error("samples = {samples} is not supported (must be between {min} and {max})")]
    InvalidSamples {
        /// Requested number of samples.
        samples: usize,
        /// Smallest supported number.
        min: usize,
        /// Largest supported number.
        max: usize,
    },
    /// A camera angle that is not finite, or an elevation outside [-90, 90] degrees.
    #[error("camera {angle} = {value} degrees is not supported ({rule})")]
    InvalidCamera {
        /// `"azimuth"` or `"elevation"`.
        angle: &'static str,
        /// The value given.
        value: f64,
        /// What the value must satisfy.
        rule: &'static str,
    },
    /// A model whose points are neither 2-D nor 3-D.
    #[error("{dimension}-D points cannot be plotted (only 2-D and 3-D)")]
    UnsupportedDimension {
        /// The dimension of the points.
        dimension: usize,
    },
    /// A model without any control point.
    #[error("the model has no control points")]
    NoControlPoints,
    /// A model given curve samples but none.
    #[error("the model has no curve samples")]
    NoCurvePoints,
    /// A position or degree that is NaN or infinite.
    #[error("{what} {index}: {channel} = {value} is not a finite number")]
    NotFinite {
        /// `"control point"`, `"curve sample"` or `"surface sample"`.
        what: &'static str,
        /// Index of the point (0-based).
        index: usize,
        /// `x`, `y`, `z`, `truth`, `indeterminacy` or `falsity`.
        channel: &'static str,
        /// The offending value.
        value: f64,
    },
    /// The point names do not match the control points one to one.
    #[error("{names} names given for {points} control points")]
    NamesMismatch {
        /// Number of names.
        names: usize,
        /// Number of control points.
        points: usize,
    },
    /// The coordinates span a range too large to draw (it overflows a 64-bit float).
    #[error("the {axis} coordinates span a range too large to draw")]
    RangeTooLarge {
        /// `x`, `y` or `z`.
        axis: &'static str,
    },
    /// The curve could not be evaluated.
    #[error("cannot sample the curve: {0}")]
    Evaluate(#[from] neutrospline::EvalError),
    /// The SVG text could not be read by the rasterizer.
    #[error("cannot read the SVG: {message}")]
    Svg {
        /// The rasterizer's message.
        message: String,
    },
    /// The PNG could not be encoded.
    #[error("cannot encode the PNG: {message}")]
    Png {
        /// The encoder's message.
        message: String,
    },
}
