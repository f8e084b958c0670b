//! Export to the formats of CAD and 3-D programs: DXF (exact SPLINE entities, or a POLYFACE
//! mesh of a surface), glTF 2.0 (`.glb` and `.gltf`), PLY and OBJ (sampled polylines and
//! triangle meshes), each keeping the degrees where the format can carry them.
//!
//! [`export`] makes the bytes of a file, [`export_file`] writes one atomically. The command-line
//! reference, `docs/cli.md` (`neutrospline export`), says what each format keeps.

mod dxf;
mod dxf_document;
#[cfg(test)]
mod dxf_reader;
mod gltf;
mod obj;
mod ply;
#[cfg(test)]
mod round_trip;
mod samples;
mod step;

use std::fmt;
use std::path::Path;
use std::str::FromStr;

use neutrospline::{Degrees, EvalError};

use neutrospline_io::{write_atomically, Model, UnsupportedFormat};

pub(crate) use samples::Samples;

/// The most points `--samples` may ask for along a curve.
pub const MAX_CURVE_SAMPLES: usize = 10_000_000;
/// The most points `--samples` may ask for along each direction of a surface (the grid has
/// the square of it: at most 16,777,216 points, which 32-bit indices address).
pub const MAX_SURFACE_SAMPLES: usize = 4096;

/// The export formats, chosen by the output file's extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ExportFormat {
    /// AutoCAD DXF R2000 (`.dxf`): curves as exact SPLINE entities, surfaces as a POLYFACE
    /// mesh (with [`ExportOptions::mesh`]).
    Dxf,
    /// Binary glTF 2.0 (`.glb`).
    Glb,
    /// glTF 2.0 JSON with its buffer embedded as a data URI (`.gltf`).
    Gltf,
    /// Stanford PLY (`.ply`), binary little-endian or ASCII ([`ExportOptions::ascii`]).
    Ply,
    /// Wavefront OBJ (`.obj`) with vertex colours.
    Obj,
    /// STEP AP214 (`.step` or `.stp`, ISO 10303-21): the curve or surface as one exact
    /// B-spline entity, the degrees in the names of its control points.
    Step,
}

impl ExportFormat {
    /// Every format.
    pub const ALL: [ExportFormat; 6] = [
        ExportFormat::Dxf,
        ExportFormat::Glb,
        ExportFormat::Gltf,
        ExportFormat::Ply,
        ExportFormat::Obj,
        ExportFormat::Step,
    ];

    /// The extensions [`ExportFormat::from_path`] accepts, for messages.
    pub const ACCEPTED: &'static str = ".dxf, .glb, .gltf, .ply, .obj, .step, .stp";

    /// The extension, without its dot (STEP's is `step`; [`ExportFormat::from_path`] takes
    /// `stp` too).
    pub const fn extension(self) -> &'static str {
        match self {
            ExportFormat::Dxf => "dxf",
            ExportFormat::Glb => "glb",
            ExportFormat::Gltf => "gltf",
            ExportFormat::Ply => "ply",
            ExportFormat::Obj => "obj",
            ExportFormat::Step => "step",
        }
    }

    /// The format of `path` by its extension (case-insensitive).
    ///
    /// # Errors
    /// [`UnsupportedFormat`] for another extension or none (its
    /// [`describe`](UnsupportedFormat::describe) with [`ExportFormat::ACCEPTED`] is the message).
    pub fn from_path(path: impl AsRef<Path>) -> Result<ExportFormat, UnsupportedFormat> {
        let path = path.as_ref();
        let extension = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        ExportFormat::ALL
            .into_iter()
            .find(|f| {
                extension.as_deref() == Some(f.extension())
                    || (*f == ExportFormat::Step && extension.as_deref() == Some("stp"))
            })
            .ok_or_else(|| UnsupportedFormat::new(path))
    }
}

impl fmt::Display for ExportFormat {
    /// `DXF`, `GLB`, `glTF`, `PLY`, `OBJ`, `STEP`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ExportFormat::Dxf => "DXF",
            ExportFormat::Glb => "GLB",
            ExportFormat::Gltf => "glTF",
            ExportFormat::Ply => "PLY",
            ExportFormat::Obj => "OBJ",
            ExportFormat::Step => "STEP",
        })
    }
}

/// Which value of a sample its colour shows (viridis, [`neutrospline::color::viridis`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ColorBy {
    /// The truth degree (the default).
    #[default]
    Truth,
    /// The indeterminacy degree.
    Indeterminacy,
    /// The falsity degree.
    Falsity,
    /// The neutrosophic score `(2 + T - I - F) / 3` in \[0, 1\] (`docs/model.md`, section 7).
    Score,
}

impl ColorBy {
    /// Every choice.
    pub const ALL: [ColorBy; 4] = [
        ColorBy::Truth,
        ColorBy::Indeterminacy,
        ColorBy::Falsity,
        ColorBy::Score,
    ];

    /// `truth`, `indeterminacy`, `falsity` or `score`.
    pub const fn name(self) -> &'static str {
        match self {
            ColorBy::Truth => "truth",
            ColorBy::Indeterminacy => "indeterminacy",
            ColorBy::Falsity => "falsity",
            ColorBy::Score => "score",
        }
    }

    /// The value shown for `degrees`, in \[0, 1\].
    pub fn value(self, degrees: &Degrees) -> f64 {
        let [t, i, f] = degrees.to_array();
        match self {
            ColorBy::Truth => t,
            ColorBy::Indeterminacy => i,
            ColorBy::Falsity => f,
            ColorBy::Score => ((2.0 + t - i - f) / 3.0).clamp(0.0, 1.0),
        }
    }
}

impl fmt::Display for ColorBy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ColorBy {
    type Err = String;

    /// An exact name of [`ColorBy::name`].
    fn from_str(text: &str) -> Result<ColorBy, String> {
        ColorBy::ALL
            .into_iter()
            .find(|c| c.name() == text)
            .ok_or_else(|| {
                format!("unknown colouring `{text}` (known: truth, indeterminacy, falsity, score)")
            })
    }
}

/// How to export.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ExportOptions {
    /// Samples of a curve (N points) or of each direction of a surface (N x N); `None`: as
    /// many as keep the polyline within [`neutrospline::sample::CHORD_TOLERANCE`] of the
    /// bounding-box diagonal ([`neutrospline::sample`]). DXF SPLINE entities are exact and
    /// take no samples.
    pub samples: Option<usize>,
    /// Which value the vertex colours show.
    pub color_by: ColorBy,
    /// DXF: write a surface as a POLYFACE mesh (a SPLINE entity is a curve).
    pub mesh: bool,
    /// PLY: ASCII rather than binary little-endian.
    pub ascii: bool,
}

impl ExportOptions {
    /// The defaults: adaptive sampling, colours by truth, no DXF mesh, binary PLY.
    pub fn new() -> ExportOptions {
        ExportOptions::default()
    }

    /// With [`ExportOptions::samples`].
    pub fn with_samples(mut self, samples: Option<usize>) -> ExportOptions {
        self.samples = samples;
        self
    }

    /// With [`ExportOptions::color_by`].
    pub fn with_color_by(mut self, color_by: ColorBy) -> ExportOptions {
        self.color_by = color_by;
        self
    }

    /// With [`ExportOptions::mesh`].
    pub fn with_mesh(mut self, mesh: bool) -> ExportOptions {
        self.mesh = mesh;
        self
    }

    /// With [`ExportOptions::ascii`].
    pub fn with_ascii(mut self, ascii: bool) -> ExportOptions {
        self.ascii = ascii;
        self
    }
}

/// Why a model could not be exported.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ExportError {
    /// The file name's extension names no export format.
    #[error("{}", .0.describe(ExportFormat::ACCEPTED))]
    Format(UnsupportedFormat),
    /// An option that does not apply to the format or the shape (`--ascii` for OBJ, `--mesh`
    /// for a curve), or a number of samples out of range.
    #[error("{0}")]
    Options(String),
    /// A surface exported to DXF without [`ExportOptions::mesh`].
    #[error(
        "a {kind} cannot be a DXF SPLINE (a SPLINE entity is a curve): export it as a mesh \
         with --mesh (a POLYFACE mesh), or to .glb, .gltf, .ply or .obj"
    )]
    SurfaceNeedsMesh {
        /// The surface's kind (`bezier-surface`, ...).
        kind: String,
    },
    /// The shape could not be sampled (a sample whose value is not finite).
    #[error("cannot sample the shape: {0}")]
    Eval(#[from] EvalError),
    /// More samples than a format's 32-bit indices address.
    #[error("{count} samples are more than a mesh with 32-bit indices can hold (at most {max}); give fewer with --samples")]
    TooManySamples {
        /// Samples needed.
        count: usize,
        /// The most a mesh holds.
        max: usize,
    },
    /// The file could not be written; it was left as it was. Displays as
    /// `PATH: cannot write: ERROR`.
    #[error("{path}: cannot write: {error}")]
    Io {
        /// The path as given.
        path: String,
        /// The cause.
        #[source]
        error: std::io::Error,
    },
}

impl ExportError {
    /// Whether the caller made the mistake (an extension, an option that does not apply).
    pub fn is_usage(&self) -> bool {
        matches!(self, ExportError::Format(_) | ExportError::Options(_))
    }
}

/// Checks that the options fit the format and the model.
fn check(model: &Model, format: ExportFormat, options: &ExportOptions) -> Result<(), ExportError> {
    let surface = model.shape().is_surface();
    if options.ascii && format != ExportFormat::Ply {
        return Err(ExportError::Options(format!(
            "--ascii applies to PLY files only (the output is {format})"
        )));
    }
    if options.mesh && format != ExportFormat::Dxf {
        return Err(ExportError::Options(format!(
            "--mesh applies to DXF files only ({format} holds surfaces as meshes anyway)"
        )));
    }
    if options.mesh && !surface {
        return Err(ExportError::Options(
            "--mesh applies to surfaces only (a curve is written as an exact SPLINE entity)"
                .to_owned(),
        ));
    }
    if format == ExportFormat::Dxf && !options.mesh && options.samples.is_some() {
        return Err(ExportError::Options(
            "--samples does not apply to a DXF SPLINE, which is exact (it applies to --mesh)"
                .to_owned(),
        ));
    }
    if format == ExportFormat::Step && options.samples.is_some() {
        return Err(ExportError::Options(
            "--samples does not apply to STEP, which is exact (a B-spline curve or surface)"
                .to_owned(),
        ));
    }
    if format == ExportFormat::Dxf && surface && !options.mesh {
        return Err(ExportError::SurfaceNeedsMesh {
            kind: model.kind().name().to_owned(),
        });
    }
    if let Some(n) = options.samples {
        let (max, what) = if surface {
            (MAX_SURFACE_SAMPLES, "per direction of a surface")
        } else {
            (MAX_CURVE_SAMPLES, "along a curve")
        };
        if !(2..=max).contains(&n) {
            return Err(ExportError::Options(format!(
                "--samples {n} is out of range (2 to {max} {what})"
            )));
        }
    }
    Ok(())
}

/// The model in `format`, as the bytes of a file.
///
/// Curves and surfaces are sampled ([`ExportOptions::samples`]) for glTF, PLY, OBJ and DXF
/// meshes; a DXF curve is one exact SPLINE entity, a STEP curve or surface one exact B-spline
/// entity.
///
/// # Errors
/// [`ExportError::Options`] for options that do not fit the format or the shape,
/// [`ExportError::SurfaceNeedsMesh`], [`ExportError::Eval`], [`ExportError::TooManySamples`].
pub fn export(
    model: &Model,
    format: ExportFormat,
    options: &ExportOptions,
) -> Result<Vec<u8>, ExportError> {
    check(model, format, options)?;
    if format == ExportFormat::Dxf && !options.mesh {
        return Ok(dxf::spline_document(model)?.into_bytes());
    }
    if format == ExportFormat::Step {
        return Ok(step::document(model)?.into_bytes());
    }
    let samples = Samples::of_model(model, options.samples)?;
    Ok(match format {
        ExportFormat::Dxf => dxf::mesh_document(model, &samples, options.color_by).into_bytes(),
        ExportFormat::Glb => gltf::glb(model, &samples, options.color_by),
        ExportFormat::Gltf => gltf::gltf(model, &samples, options.color_by).into_bytes(),
        ExportFormat::Ply => ply::ply(model, &samples, options.color_by, options.ascii),
        ExportFormat::Obj => obj::obj(model, &samples, options.color_by).into_bytes(),
        ExportFormat::Step => step::document(model)?.into_bytes(),
    })
}

/// Exports the model to `path` in the format of its extension, atomically (a temporary file
/// in the same directory, renamed over `path` when complete; on any error the old file is left
/// as it was).
///
/// # Errors
/// [`ExportError::Format`] for an unsupported extension, as [`export`], and
/// [`ExportError::Io`] naming the file.
pub fn export_file(
    model: &Model,
    path: impl AsRef<Path>,
    options: &ExportOptions,
) -> Result<(), ExportError> {
    let path = path.as_ref();
    let format = ExportFormat::from_path(path).map_err(ExportError::Format)?;
    let bytes = export(model, format, options)?;
    write_atomically(path, &bytes).map_err(|error| ExportError::Io {
        path: path.display().to_string(),
        error,
    })
}

/// Text for one line of a comment in a file: control characters as spaces, and (for headers
/// that must be ASCII) other characters as `\u{...}` escapes.
pub(crate) fn comment_text(text: &str, ascii: bool) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            out.push(' ');
        } else if ascii && !c.is_ascii() {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}

/// `bezier-surface "bicubic hill"`: the kind and the name, for the comments of a file.
pub(crate) fn title(model: &Model) -> String {
    match model.name() {
        Some(name) => format!("{} \"{name}\"", model.kind().name()),
        None => model.kind().name().to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_by_extension() {
        assert_eq!(ExportFormat::from_path("a.DXF"), Ok(ExportFormat::Dxf));
        assert_eq!(ExportFormat::from_path("a.gltf"), Ok(ExportFormat::Gltf));
        assert_eq!(ExportFormat::from_path("a.step"), Ok(ExportFormat::Step));
        assert_eq!(ExportFormat::from_path("a.STP"), Ok(ExportFormat::Step));
        let e = ExportFormat::from_path("a.stl").unwrap_err();
        assert_eq!(
            ExportError::Format(e).to_string(),
            "a.stl: unsupported file extension `.stl` (accepted: .dxf, .glb, .gltf, .ply, .obj, .step, .stp)"
        );
    }

    #[test]
    fn color_by_values() {
        let d = Degrees::new(0.9, 0.3, 0.3).unwrap();
        assert_eq!(ColorBy::Truth.value(&d), 0.9);
        assert_eq!(ColorBy::Indeterminacy.value(&d), 0.3);
        assert_eq!(ColorBy::Falsity.value(&d), 0.3);
        assert!((ColorBy::Score.value(&d) - 2.3 / 3.0).abs() < 1e-15);
        assert_eq!("score".parse::<ColorBy>(), Ok(ColorBy::Score));
        assert!("Truth".parse::<ColorBy>().is_err());
    }

    #[test]
    fn comment_text_escapes() {
        assert_eq!(comment_text("a\nb\u{e9}", false), "a b\u{e9}");
        assert_eq!(comment_text("a\nb\u{e9}", true), "a b\\u{e9}");
    }
}
