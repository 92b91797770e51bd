//! PDF output: the SVG this crate writes, converted by svg2pdf into one vector page at true
//! scale (the page is the SVG's physical size: the drawing's extents plus the margin).
//!
//! svg2pdf writes the whole tree as one content stream and has no optional content groups, so
//! layers are not switchable in a PDF viewer; each layer is still drawn in its own colour.

use super::OutputError;

/// usvg measures physical sizes in CSS pixels, 96 to the inch; telling svg2pdf the same makes
/// one millimetre of the SVG one millimetre on the page.
const CSS_DPI: f32 = 96.0;

/// The PDF of an SVG document (sizes in physical units).
pub fn svg_to_pdf(svg: &str) -> Result<Vec<u8>, OutputError> {
    let tree = super::svg::usvg_tree(svg)?;
    let page = svg2pdf::PageOptions { dpi: CSS_DPI };
    svg2pdf::to_pdf(&tree, svg2pdf::ConversionOptions::default(), page)
        .map_err(|e| OutputError::Convert(e.to_string()))
}
