//! Contact sheets (`batch --sheet`): every row's drawing in one labelled grid, all at one
//! common scale, so a few hundred variants are reviewed at a glance.
//!
//! Each row's SVG (as `svg::write_svg` made it, at true scale) is nested unchanged as an
//! `<svg>` element in its cell, under a `<g id="row-N">` with a `<text>` label above it. Cells
//! are as large as the largest drawing, so every drawing keeps the same scale: true scale,
//! unless the sheet would exceed 5 m (PDF's page limit is 5.08 m), then everything is scaled
//! down alike and the scale is printed in the title.

use std::fmt::Write as _;

use super::{Format, OutputError};

/// One cell: its label and the row's SVG document.
#[derive(Clone, Debug)]
pub struct SheetRow {
    pub label: String,
    pub svg: String,
}

/// Label band above each drawing, gap between cells, outer border (mm on the sheet).
const LABEL: f64 = 7.0;
const GAP: f64 = 6.0;
const BORDER: f64 = 10.0;
/// The largest sheet side (mm) before everything is scaled down.
const MAX_SIDE: f64 = 5000.0;

/// A row's SVG split into what the sheet needs: physical size in mm, viewBox, inner content.
struct Parsed<'a> {
    w: f64,
    h: f64,
    view_box: &'a str,
    body: &'a str,
}

fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let i = tag.find(&key)? + key.len();
    tag[i..].split('"').next()
}

fn length_mm(v: &str) -> Option<f64> {
    let (num, k) = if let Some(n) = v.strip_suffix("mm") {
        (n, 1.0)
    } else if let Some(n) = v.strip_suffix("in") {
        (n, 25.4)
    } else {
        (v, 25.4 / 96.0)
    };
    num.trim().parse::<f64>().ok().map(|x| x * k)
}

fn parse(svg: &str) -> Option<Parsed<'_>> {
    let start = svg.find("<svg")?;
    let open_end = start + svg[start..].find('>')?;
    let tag = &svg[start..open_end];
    let close = svg.rfind("</svg>")?;
    Some(Parsed {
        w: length_mm(attr(tag, "width")?)?,
        h: length_mm(attr(tag, "height")?)?,
        view_box: attr(tag, "viewBox")?,
        body: &svg[open_end + 1..close],
    })
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The sheet as an SVG document (sizes in mm).
pub fn compose_svg(rows: &[SheetRow]) -> Result<String, OutputError> {
    let parsed: Vec<Parsed> = rows
        .iter()
        .map(|r| {
            parse(&r.svg)
                .ok_or_else(|| OutputError::Convert(format!("row {:?}: not an SVG", r.label)))
        })
        .collect::<Result<_, _>>()?;
    let cw = parsed.iter().map(|p| p.w).fold(40.0, f64::max);
    let ch = parsed.iter().map(|p| p.h).fold(10.0, f64::max) + LABEL;
    let n = parsed.len().max(1);
    // Roughly square: columns ≈ √(n · cell height / cell width).
    let cols = ((n as f64 * (ch + GAP) / (cw + GAP)).sqrt().round() as usize).clamp(1, n);
    let lines = n.div_ceil(cols);
    let full_w = 2.0 * BORDER + cols as f64 * (cw + GAP) - GAP;
    let full_h = 2.0 * BORDER + LABEL + lines as f64 * (ch + GAP) - GAP;
    let scale = (MAX_SIDE / full_w.max(full_h)).min(1.0);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" \
         xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" \
         width=\"{:.3}mm\" height=\"{:.3}mm\" viewBox=\"0 0 {full_w:.3} {full_h:.3}\">",
        full_w * scale,
        full_h * scale
    );
    s.push_str("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
    let title = if scale < 1.0 {
        format!("{} drawings, scale 1:{:.2}", rows.len(), 1.0 / scale)
    } else {
        format!("{} drawings, scale 1:1", rows.len())
    };
    let _ = writeln!(
        s,
        "<text x=\"{BORDER}\" y=\"{:.3}\" font-family=\"sans-serif\" font-size=\"5\">{}</text>",
        BORDER + 4.0,
        escape(&title)
    );
    // Labels longer than the cell is wide (about 2 mm a character at 3.5 mm) are cut short.
    let max_chars = ((cw - 3.0) / 2.0).max(8.0) as usize;
    for (i, (row, p)) in rows.iter().zip(&parsed).enumerate() {
        let label: String = if row.label.chars().count() > max_chars {
            row.label.chars().take(max_chars - 1).chain(['…']).collect()
        } else {
            row.label.clone()
        };
        let (c, l) = (i % cols, i / cols);
        let x = BORDER + c as f64 * (cw + GAP);
        let y = BORDER + LABEL + l as f64 * (ch + GAP);
        let _ = write!(
            s,
            "<g id=\"row-{}\" class=\"sheet-row\">\n<rect x=\"{x:.3}\" y=\"{y:.3}\" \
             width=\"{cw:.3}\" height=\"{ch:.3}\" fill=\"none\" stroke=\"#c0c0c0\" \
             stroke-width=\"0.2\"/>\n<text x=\"{:.3}\" y=\"{:.3}\" font-family=\"sans-serif\" \
             font-size=\"3.5\">{}</text>\n<svg x=\"{x:.3}\" y=\"{:.3}\" width=\"{:.6}\" \
             height=\"{:.6}\" viewBox=\"{}\">{}</svg>\n</g>\n",
            i + 1,
            x + 1.5,
            y + 4.5,
            escape(&label),
            y + LABEL,
            p.w,
            p.h,
            p.view_box,
            p.body
        );
    }
    s.push_str("</svg>\n");
    Ok(s)
}

/// The sheet in `format` (SVG or PDF).
pub fn compose(rows: &[SheetRow], format: Format) -> Result<Vec<u8>, OutputError> {
    let svg = compose_svg(rows)?;
    match format {
        Format::Svg => Ok(svg.into_bytes()),
        Format::Pdf => super::pdf::svg_to_pdf(&svg),
        _ => Err(OutputError::UnknownFormat(
            "a contact sheet is .svg or .pdf".into(),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_labelled_group_per_row_at_a_common_scale() {
        let row = |label: &str, w: f64| {
            SheetRow {
            label: label.into(),
            svg: format!(
                "<svg height=\"20mm\" viewBox=\"0 0 {w} 20\" width=\"{w}mm\"><path d=\"M0 0\"/></svg>"
            ),
        }
        };
        let s = compose_svg(&[row("a<1>", 100.0), row("b", 50.0), row("c", 80.0)]).unwrap();
        assert_eq!(s.matches("class=\"sheet-row\"").count(), 3);
        assert!(s.contains(">a&lt;1&gt;</text>"));
        // Each drawing keeps its own size (mm = user units): common scale 1:1.
        assert!(s.contains("width=\"50.000000\" height=\"20.000000\" viewBox=\"0 0 50 20\""));
        assert!(s.contains("scale 1:1"));
    }
}
