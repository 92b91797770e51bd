//! PNG output: the SVG this crate writes, rasterised by resvg at `dpi` pixels per inch on
//! white, with the resolution recorded in the file (pHYs) so viewers and printers keep the
//! true scale.

use super::OutputError;

/// usvg's unit: CSS pixels, 96 to the inch.
const CSS_DPI: f64 = 96.0;

/// Larger images are refused rather than allocated (a 1 m drawing at 300 dpi is 11811 px).
const MAX_PIXELS: f64 = 400e6;

/// The PNG of an SVG document at `dpi`.
pub fn svg_to_png(svg: &str, dpi: f64) -> Result<Vec<u8>, OutputError> {
    let tree = super::svg::usvg_tree(svg)?;
    let scale = dpi / CSS_DPI;
    let size = tree.size();
    let (w, h) = (
        (size.width() as f64 * scale).ceil(),
        (size.height() as f64 * scale).ceil(),
    );
    if w * h > MAX_PIXELS || w > u32::MAX as f64 || h > u32::MAX as f64 {
        return Err(OutputError::TooLarge { dpi, w, h });
    }
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w.max(1.0) as u32, h.max(1.0) as u32)
        .ok_or(OutputError::TooLarge { dpi, w, h })?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    let t = resvg::tiny_skia::Transform::from_scale(scale as f32, scale as f32);
    resvg::render(&tree, t, &mut pixmap.as_mut());
    encode(&pixmap, dpi).map_err(|e| OutputError::Convert(e.to_string()))
}

/// RGB (the background is opaque) with the pixels per metre of `dpi`.
fn encode(pixmap: &resvg::tiny_skia::Pixmap, dpi: f64) -> Result<Vec<u8>, png::EncodingError> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, pixmap.width(), pixmap.height());
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let ppm = (dpi / 0.0254).round() as u32;
    enc.set_pixel_dims(Some(png::PixelDimensions {
        xppu: ppm,
        yppu: ppm,
        unit: png::Unit::Meter,
    }));
    let rgb: Vec<u8> = pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    let mut w = enc.write_header()?;
    w.write_image_data(&rgb)?;
    w.finish()?;
    Ok(out)
}
