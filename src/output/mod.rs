//! The drawing model and its writers (SVG, DXF in two profiles), with atomic saving.

pub mod aci;
pub mod atomic;
pub mod biarc;
pub mod cam;
pub mod document;
pub mod drawing;
pub mod dxf;
pub mod dxf_opened;
pub mod dxf_writer;
pub mod dxfin;
pub mod entity;
pub mod record;
pub mod svg;

use std::path::Path;

use glam::DVec3;

pub use drawing::{Drawing, DrawingError, Entity, EntityKind, Layer};
pub use dxfin::{open_drawing, read_dxf, DxfReadError};

/// Which DXF flavour `save` writes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DxfProfile {
    /// AutoCAD R2000 (AC1015) with full tables, blocks and objects.
    #[default]
    Cad,
    /// AutoCAD R12 (AC1009) for laser/CNC: lines, arcs, circles and bulged polylines only.
    Cam,
}

impl std::str::FromStr for DxfProfile {
    type Err = OutputError;
    fn from_str(s: &str) -> Result<Self, OutputError> {
        match s.to_ascii_uppercase().as_str() {
            "CAD" => Ok(DxfProfile::Cad),
            "CAM" => Ok(DxfProfile::Cam),
            _ => Err(OutputError::BadProfile(s.to_string())),
        }
    }
}

/// Options of the writers (the system variables DXFPROFILE, VIEWDIR and the `--cam-tol` flag).
#[derive(Clone, Debug, PartialEq)]
pub struct OutputOptions {
    pub dxf_profile: DxfProfile,
    /// CAM profile: the largest distance (drawing units, mm) between a spline and its arcs.
    pub cam_tol: f64,
    /// SVG: the direction the viewer looks from (towards the origin); (0,0,1) is plan view.
    pub view_dir: DVec3,
    /// SVG: stroke width in millimetres.
    pub stroke_width_mm: f64,
    /// SVG: blank border around the extents, in drawing units.
    pub margin: f64,
}

impl Default for OutputOptions {
    fn default() -> Self {
        OutputOptions {
            dxf_profile: DxfProfile::Cad,
            cam_tol: 0.01,
            view_dir: DVec3::Z,
            stroke_width_mm: 0.25,
            margin: 5.0,
        }
    }
}

/// Why a drawing could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    #[error("cannot write {path}: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("unknown output format {0:?}: the file name must end in .svg or .dxf")]
    UnknownFormat(String),
    #[error("unknown DXF profile {0:?}: expected \"CAD\" or \"CAM\"")]
    BadProfile(String),
    #[error("cam_tol must be positive and finite, got {0}")]
    BadTolerance(f64),
    #[error("view direction must be a finite non-zero vector")]
    BadViewDir,
    #[error("entity {handle:X}: {source}")]
    BadEntity {
        handle: u64,
        #[source]
        source: DrawingError,
    },
}

impl OutputOptions {
    pub fn validate(&self) -> Result<(), OutputError> {
        if !(self.cam_tol.is_finite() && self.cam_tol > 0.0) {
            return Err(OutputError::BadTolerance(self.cam_tol));
        }
        if !self.view_dir.is_finite() || self.view_dir.length() < 1e-12 {
            return Err(OutputError::BadViewDir);
        }
        Ok(())
    }
}

/// Output formats `save` knows, from the file extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Svg,
    Dxf,
}

impl Format {
    /// The format named by `path`'s extension (case-insensitive).
    pub fn from_path(path: &Path) -> Result<Format, OutputError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_ascii_lowercase();
        match ext.as_str() {
            "svg" => Ok(Format::Svg),
            "dxf" => Ok(Format::Dxf),
            _ => Err(OutputError::UnknownFormat(path.display().to_string())),
        }
    }
}

/// Re-check every entity (fields are public, so an edited entity may have gone bad).
pub(crate) fn check_drawing(d: &Drawing) -> Result<(), OutputError> {
    for e in d.entities() {
        e.kind.validate().map_err(|source| OutputError::BadEntity {
            handle: e.handle,
            source,
        })?;
    }
    Ok(())
}

/// The file contents for `format`.
pub fn render(d: &Drawing, format: Format, opts: &OutputOptions) -> Result<Vec<u8>, OutputError> {
    opts.validate()?;
    check_drawing(d)?;
    Ok(match format {
        Format::Svg => svg::write_svg(d, opts).into_bytes(),
        Format::Dxf => match (opts.dxf_profile, d.document()) {
            // An opened drawing is written back in its own version and code page.
            (DxfProfile::Cad, Some(doc)) => dxf_opened::write_opened(d, doc),
            (DxfProfile::Cad, None) => dxf::encode_cp1252(dxf::write_cad(d)),
            (DxfProfile::Cam, _) => dxf::encode_cp1252(cam::write_cam(d, opts.cam_tol)),
        },
    })
}

/// Write the drawing to `path` atomically, in the format of its extension (.svg or .dxf).
pub fn save(d: &Drawing, path: &Path, opts: &OutputOptions) -> Result<(), OutputError> {
    let format = Format::from_path(path)?;
    let bytes = render(d, format, opts)?;
    atomic::write_atomic(path, &bytes).map_err(|source| OutputError::Io {
        path: path.display().to_string(),
        source,
    })
}
