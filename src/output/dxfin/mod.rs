//! The DXF reader, in ezdxf's two stages: `tags` turns bytes into (group code, value,
//! position) whatever the version, code page or binary form; `load` groups them into
//! sections and records, builds the entities lispcad models (`factory`) and keeps every other
//! record as its group list so that saving writes it back unchanged.

pub mod factory;
pub mod load;
pub mod tags;

use std::path::Path;

pub use load::read_dxf;
pub use tags::Pos;

use super::Drawing;

/// Why a DXF file could not be read: the message, where (line or byte offset), and the file.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub struct DxfReadError {
    pub path: Option<String>,
    pub pos: Option<Pos>,
    pub message: String,
}

impl DxfReadError {
    pub fn at(pos: Option<Pos>, message: impl Into<String>) -> DxfReadError {
        DxfReadError {
            path: None,
            pos,
            message: message.into(),
        }
    }

    pub fn with_path(mut self, path: &Path) -> DxfReadError {
        self.path = Some(path.display().to_string());
        self
    }
}

impl std::fmt::Display for DxfReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if let Some(p) = &self.path {
            write!(f, "{p}: ")?;
        }
        if let Some(pos) = &self.pos {
            write!(f, "{pos}: ")?;
        }
        f.write_str(&self.message)
    }
}

/// Open a DXF file as a drawing (`--open`, `dxf-open`, `convert`, `batch --open`).
/// With `recover`, damaged groups are skipped instead of refused; the drawing's document
/// counts them (`Drawing::document().recovered`).
pub fn open_drawing(path: &Path, recover: bool) -> Result<Drawing, DxfReadError> {
    let data = std::fs::read(path).map_err(|e| {
        DxfReadError::at(None, format!("cannot read the drawing: {e}")).with_path(path)
    })?;
    read_dxf(&data, recover).map_err(|e| e.with_path(path))
}

/// The note to print after opening with `--recover` when it was needed, if it was.
pub fn recover_note(path: &Path, d: &Drawing) -> Option<String> {
    let n = d.document()?.recovered;
    (n > 0).then(|| {
        format!(
            "warning: {}: damaged DXF read with --recover ({n} bad group{} skipped or repaired)",
            path.display(),
            if n == 1 { "" } else { "s" }
        )
    })
}
