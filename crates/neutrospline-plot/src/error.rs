//! The errors of this crate.

/// Why a figure could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    /// A view that would misdraw the degrees of the model's membership family.
    #[error("the view `{view}` does not draw {family} models: {reason}")]
    FamilyView {
        /// The view's name.
        view: String,
        /// The family.
        family: String,
        /// Why, and which views do.
        reason: String,
    },
    /// A view name that [`View`](crate::View) does not know.
    #[error("unknown view \"{name}\" (expected one of: controls, truth, indeterminacy, falsity, all, plane, score, derived, data, band)")]
    UnknownView {
        /// The name given.
        name: String,
    },
    /// A figure file whose extension names no figure format.
    #[error("{path}: unsupported figure extension (accepted: .svg, .png, .pdf)")]
    FigureExtension {
        /// The file.
        path: String,
    },
    /// A print size whose canvas (in points) is outside the supported range.
    #[error("figure size {size} is not supported (each side must be between {min} and {max} points, 2.26 cm to 5.78 m)")]
    InvalidPrintSize {
        /// The size as given.
        size: String,
        /// Smallest side, in points.
        min: u32,
        /// Largest side, in points.
        max: u32,
    },
    /// A print size whose PNG at the resolution would have too many or too few pixels.
    #[error("a PNG of {size} at {dpi} dpi would be {width}x{height} pixels (each side must be between {min} and {max}; change --dpi or give the size in pixels)")]
    InvalidRaster {
        /// The size as given.
        size: String,
        /// The resolution.
        dpi: f64,
        /// The PNG's width.
        width: u32,
        /// The PNG's height.
        height: u32,
        /// Smallest side, in pixels.
        min: u32,
        /// Largest side, in pixels.
        max: u32,
    },
    /// A resolution outside the supported range.
    #[error("dpi = {dpi} is not supported (must be between {min} and {max})")]
    InvalidDpi {
        /// The resolution given.
        dpi: f64,
        /// Smallest accepted.
        min: f64,
        /// Largest accepted.
        max: f64,
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
    /// A position, degree or parameter that is NaN or infinite.
    #[error("{what} {index}: {channel} = {value} is not a finite number")]
    NotFinite {
        /// `"control point"`, `"curve sample"`, `"surface sample"`, `"data point"` or
        /// `"curve point of data point"` (the curve where a data point's whisker ends).
        what: &'static str,
        /// Index of the point (0-based).
        index: usize,
        /// `x`, `y`, `z`, `truth`, `indeterminacy`, `falsity`, or `t` (a data point's
        /// parameter).
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
    /// The `data` view was asked for a model without data points.
    #[error("the data view needs data points (neutrospline plot MODEL --data DATA.csv, or neutrospline fit --plot)")]
    NoData,
    /// The `band` view asked for of a surface.
    #[error("the band view draws curves (spreads are given per control point of a curve); surfaces have no band")]
    BandOnSurface,
    /// An alpha level of the band view outside [0, 1].
    #[error("alpha level {alpha} is outside [0, 1] (the band view draws alpha-cuts at levels in [0, 1])")]
    InvalidAlpha {
        /// The level given.
        alpha: f64,
    },
    /// The fuzzy position of the curve cannot be cut (the core's message).
    #[error("{0}")]
    Fuzzy(String),
    /// Parameters of the other kind of model: curve parameters `t` for a surface, or
    /// surface parameters `(u, v)` for a curve.
    #[error("the data points' {given} do not fit a {model}")]
    ParameterKind {
        /// What was given.
        given: &'static str,
        /// `"curve"` or `"surface"`.
        model: &'static str,
    },
    /// A data point's surface parameter outside the surface's domain.
    #[error(
        "data point {index}: parameter {channel} = {value} is outside the surface's domain \
         [{start}, {end}] in {channel}"
    )]
    SurfaceParameterOutsideDomain {
        /// Index of the data point (0-based).
        index: usize,
        /// `"u"` or `"v"`.
        channel: &'static str,
        /// The parameter given.
        value: f64,
        /// Start of the domain in that direction.
        start: f64,
        /// End of the domain in that direction.
        end: f64,
    },
    /// A data overlay without any point.
    #[error("the data overlay has no data points (give at least one)")]
    EmptyData,
    /// The degrees or parameters of a data overlay are not one per point.
    #[error("{count} {what} given for {points} data points")]
    DataCount {
        /// `"degree triples"` or `"parameters"`.
        what: &'static str,
        /// How many were given.
        count: usize,
        /// Number of data points.
        points: usize,
    },
    /// A degree of a data point outside \[0, 1\].
    #[error("data point {index}: {channel} = {value} is outside [0, 1]")]
    DataDegreeRange {
        /// Index of the data point (0-based).
        index: usize,
        /// `truth`, `indeterminacy` or `falsity`.
        channel: &'static str,
        /// The offending value.
        value: f64,
    },
    /// A data point's parameter outside the curve's parameter domain.
    #[error(
        "data point {index}: parameter t = {value} is outside the curve's domain [{start}, {end}]"
    )]
    ParameterOutsideDomain {
        /// Index of the data point (0-based).
        index: usize,
        /// The parameter given.
        value: f64,
        /// Start of the domain.
        start: f64,
        /// End of the domain.
        end: f64,
    },
    /// The curve could not be evaluated.
    #[error("cannot sample the curve: {0}")]
    Evaluate(#[from] neutrospline::EvalError),
    /// The nearest point of the curve to a data point could not be found (values overflow).
    #[error("data point {index}: cannot find the nearest point of the curve: {source}")]
    Nearest {
        /// The data point's index.
        index: usize,
        /// Why.
        source: neutrospline::NearestError,
    },
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
