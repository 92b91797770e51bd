//! The drawing model and its writers (SVG, DXF in two profiles, PDF and PNG through the SVG),
//! with atomic saving.

pub mod aci;
pub mod atomic;
pub mod biarc;
pub mod blocks;
pub mod cam;
mod cam_overlap;
pub mod cam_tidy;
pub mod document;
pub mod drawing;
pub mod drawing_adopt;
pub mod drawing_import;
pub mod dxf;
mod dxf_entities;
pub mod dxf_merge;
pub mod dxf_opened;
pub mod dxf_relocate;
pub mod dxf_spline;
pub mod dxf_upgrade;
pub mod dxf_writer;
pub mod dxfin;
pub mod entity;
pub mod objects;
pub mod pdf;
pub mod png;
pub mod props;
pub mod record;
pub mod sheet;
pub mod svg;

use std::collections::HashMap;
use std::path::Path;

use glam::DVec3;

use crate::geom::bspline::BSpline;

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
    /// SVG, PDF, PNG: blank border around the extents, in millimetres on paper.
    pub margin: f64,
    /// The drawing unit (`INSUNITS`: 4 mm, 1 inch, ...): the DXF header and the physical size
    /// of SVG, PDF and PNG.
    pub insunits: i32,
    /// PNG: pixels per inch.
    pub dpi: f64,
    /// CAM profile: the shortest segment written (drawing units) unless the geometry itself is
    /// shorter.
    pub cam_min_seg: f64,
}

impl Default for OutputOptions {
    fn default() -> Self {
        OutputOptions {
            dxf_profile: DxfProfile::Cad,
            cam_tol: 0.01,
            view_dir: DVec3::Z,
            stroke_width_mm: 0.25,
            margin: 5.0,
            insunits: 4,
            dpi: 300.0,
            cam_min_seg: 0.05,
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
    #[error("unknown output format {0:?}: the file name must end in .svg, .dxf, .pdf or .png")]
    UnknownFormat(String),
    #[error("unknown DXF profile {0:?}: expected \"CAD\" or \"CAM\"")]
    BadProfile(String),
    #[error("cam_tol must be positive and finite, got {0}")]
    BadTolerance(f64),
    #[error("view direction must be a finite non-zero vector")]
    BadViewDir,
    #[error("INSUNITS must be a DXF unit code 0..=24, got {0}")]
    BadUnits(i32),
    #[error("dpi must be between 1 and 10000, got {0}")]
    BadDpi(f64),
    #[error("cam_min_seg must be zero or positive and finite, got {0}")]
    BadMinSeg(f64),
    #[error("the drawing at {dpi} dpi would be {w}x{h} pixels, more than a PNG should hold")]
    TooLarge { dpi: f64, w: f64, h: f64 },
    #[error("cannot convert the SVG: {0}")]
    Convert(String),
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
        if !(0..=24).contains(&self.insunits) {
            return Err(OutputError::BadUnits(self.insunits));
        }
        if !(self.dpi.is_finite() && (1.0..=10000.0).contains(&self.dpi)) {
            return Err(OutputError::BadDpi(self.dpi));
        }
        if !(self.cam_min_seg.is_finite() && self.cam_min_seg >= 0.0) {
            return Err(OutputError::BadMinSeg(self.cam_min_seg));
        }
        Ok(())
    }

    /// Millimetres per drawing unit.
    pub fn unit_mm(&self) -> f64 {
        unit_mm(self.insunits)
    }
}

/// Millimetres per drawing unit for a DXF `$INSUNITS` code; unitless (0) and the codes without
/// a fixed length (astronomical, parsecs) draw as millimetres.
pub fn unit_mm(insunits: i32) -> f64 {
    match insunits {
        1 => 25.4,
        2 => 304.8,
        3 => 1_609_344.0,
        5 => 10.0,
        6 => 1000.0,
        7 => 1e6,
        8 => 25.4e-6,
        9 => 0.0254,
        10 => 914.4,
        11 => 1e-7,
        12 => 1e-6,
        13 => 1e-3,
        14 => 100.0,
        15 => 1e4,
        16 => 1e5,
        17 => 1e12,
        21 => 1200.0 / 3937.0 * 1000.0,
        22 => 1200.0 / 3937.0 * 1000.0 / 12.0,
        23 => 1200.0 / 3937.0 * 1000.0 * 3.0,
        24 => 1200.0 / 3937.0 * 1000.0 * 5280.0,
        _ => 1.0,
    }
}

/// `$MEASUREMENT` for a unit: 0 imperial (inches, feet, miles, mils, yards, US survey), 1
/// metric.
pub fn measurement(insunits: i32) -> i32 {
    match insunits {
        1 | 2 | 3 | 8 | 9 | 10 | 21..=24 => 0,
        _ => 1,
    }
}

/// Output formats `save` knows, from the file extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Svg,
    Dxf,
    Pdf,
    Png,
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
            "pdf" => Ok(Format::Pdf),
            "png" => Ok(Format::Png),
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

/// A drawing about to be written, with what several formats need worked out once: a run
/// with `-o a.dxf -o a.svg` (every batch row) used to compute the extents, which means
/// decomposing every spline, once for each file.
pub struct Prepared<'a> {
    pub drawing: &'a Drawing,
    extents: std::cell::OnceCell<Option<(DVec3, DVec3)>>,
    /// Each spline's Bézier pieces, by the curve's address (the drawing is borrowed, so its
    /// entities stay put): the extents and the SVG path both need them.
    beziers: std::cell::RefCell<HashMap<usize, entity::BezierPieces>>,
}

impl<'a> Prepared<'a> {
    pub fn new(drawing: &'a Drawing) -> Self {
        Prepared {
            drawing,
            extents: std::cell::OnceCell::new(),
            beziers: Default::default(),
        }
    }

    /// `Drawing::extents`, computed on first use.
    pub fn extents(&self) -> Option<(DVec3, DVec3)> {
        *self
            .extents
            .get_or_init(|| self.drawing.extents_with(&|c| self.beziers(c)))
    }

    /// `curve.to_beziers()`, worked out once per curve. Only for curves of `drawing`'s
    /// entities: the key is the address, which a temporary could share with another.
    pub(crate) fn beziers(&self, curve: &BSpline) -> entity::BezierPieces {
        let key = std::ptr::from_ref(curve) as usize;
        let mut cache = self.beziers.borrow_mut();
        cache
            .entry(key)
            .or_insert_with(|| entity::fresh_beziers(curve))
            .clone()
    }
}

/// The file contents for `format`.
pub fn render(d: &Drawing, format: Format, opts: &OutputOptions) -> Result<Vec<u8>, OutputError> {
    render_prepared(&Prepared::new(d), format, opts)
}

/// `render` of a prepared drawing (shared by the formats of one save).
pub fn render_prepared(
    p: &Prepared,
    format: Format,
    opts: &OutputOptions,
) -> Result<Vec<u8>, OutputError> {
    let d = p.drawing;
    opts.validate()?;
    check_drawing(d)?;
    Ok(match format {
        Format::Svg => svg::svg_layers_prepared(p, opts).to_svg().into_bytes(),
        Format::Dxf => match (opts.dxf_profile, d.document()) {
            // An opened drawing is written back in its own version and code page.
            (DxfProfile::Cad, Some(doc)) => dxf_opened::write_opened(d, doc),
            (DxfProfile::Cad, None) => {
                dxf::encode_cp1252(dxf::write_cad_prepared(p, opts.insunits))
            }
            (DxfProfile::Cam, _) => {
                let out = cam::write_cam_with(d, opts);
                for w in &out.warnings {
                    eprintln!("warning: CAM: {w}");
                }
                dxf::encode_cp1252(out.dxf)
            }
        },
        Format::Pdf => pdf::layers_to_pdf(&svg::svg_layers_prepared(p, opts))?,
        Format::Png => png::svg_to_png(&svg::svg_layers_prepared(p, opts).to_svg(), opts.dpi)?,
    })
}

/// Write the drawing to `path` atomically, in the format of its extension (.svg, .dxf, .pdf,
/// .png).
pub fn save(d: &Drawing, path: &Path, opts: &OutputOptions) -> Result<(), OutputError> {
    save_prepared(&Prepared::new(d), path, opts)
}

/// `save_prepared` of the file `name` in the open directory `dir` (`shown`: the path for
/// messages), replaced atomically relative to the handle.
pub fn save_prepared_at(
    p: &Prepared,
    dir: &cap_std::fs::Dir,
    name: &std::ffi::OsStr,
    shown: &Path,
    opts: &OutputOptions,
) -> Result<(), OutputError> {
    write_rendered(p, shown, opts, |bytes| {
        atomic::write_atomic_at(dir, name, bytes)
    })
}

/// `save` of a prepared drawing (shared by the files of one run).
pub fn save_prepared(p: &Prepared, path: &Path, opts: &OutputOptions) -> Result<(), OutputError> {
    write_rendered(p, path, opts, |bytes| atomic::write_atomic(path, bytes))
}

/// Renders `p` in the format of `shown`'s extension and hands the bytes to `write`.
fn write_rendered(
    p: &Prepared,
    shown: &Path,
    opts: &OutputOptions,
    write: impl FnOnce(&[u8]) -> std::io::Result<()>,
) -> Result<(), OutputError> {
    let format = Format::from_path(shown)?;
    let bytes = render_prepared(p, format, opts)?;
    write(&bytes).map_err(|source| OutputError::Io {
        path: shown.display().to_string(),
        source,
    })
}
