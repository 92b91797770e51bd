//! PDF output: the SVG this crate writes, converted by svg2pdf into one vector page at true
//! scale (the page is the SVG's physical size: the drawing's extents plus the margin).
//!
//! A drawing's layers become optional content groups (PDF layers), one per drawing layer and
//! named after it, so a PDF viewer can switch them on and off. svg2pdf converts a whole SVG
//! into one content stream and knows nothing of optional content, so each layer's SVG group
//! is converted on its own into a Form XObject (svg2pdf's chunk API) and the page draws each
//! one inside `/OC /ocN BDC … EMC` (pdf-writer). A layer that is off or frozen is written
//! with its group initially off, rather than left out as in the SVG and PNG.

use std::collections::HashMap;

use pdf_writer::{Content, Finish, Name, Pdf, Rect, Ref, TextStr};

use super::svg::SvgLayers;
use super::OutputError;

/// usvg measures physical sizes in CSS pixels, 96 to the inch; telling svg2pdf the same makes
/// one millimetre of the SVG one millimetre on the page.
const CSS_DPI: f32 = 96.0;

fn convert_err(e: impl std::fmt::Display) -> OutputError {
    OutputError::Convert(e.to_string())
}

/// The PDF of an SVG document (sizes in physical units), as one content stream without
/// layers (the contact sheet).
pub fn svg_to_pdf(svg: &str) -> Result<Vec<u8>, OutputError> {
    let tree = super::svg::usvg_tree(svg)?;
    let page = svg2pdf::PageOptions { dpi: CSS_DPI };
    svg2pdf::to_pdf(&tree, svg2pdf::ConversionOptions::default(), page).map_err(convert_err)
}

/// One layer converted: its Form XObject (already renumbered into the document) and its OCG.
struct LayerObject {
    name: String,
    hidden: bool,
    xobject: Ref,
    ocg: Ref,
}

/// The PDF of a drawing's layered SVG, one optional content group per layer.
pub fn layers_to_pdf(svg: &SvgLayers) -> Result<Vec<u8>, OutputError> {
    if svg.layers.is_empty() {
        return svg_to_pdf(&svg.to_svg());
    }
    let mut alloc = Ref::new(1);
    let catalog_id = alloc.bump();
    let page_tree_id = alloc.bump();
    let page_id = alloc.bump();
    let content_id = alloc.bump();
    let mut pdf = Pdf::new();
    let mut objects = Vec::with_capacity(svg.layers.len());
    // Every layer's SVG has the same size; the page is that size in points.
    let mut size = None;
    for (i, layer) in svg.layers.iter().enumerate() {
        let group = svg.group(i, true);
        let tree = super::svg::usvg_tree(&svg.document([group.as_str()]))?;
        size.get_or_insert(tree.size());
        let (chunk, root) =
            svg2pdf::to_chunk(&tree, svg2pdf::ConversionOptions::default()).map_err(convert_err)?;
        let mut map = HashMap::new();
        let chunk = chunk.renumber(|old| *map.entry(old).or_insert_with(|| alloc.bump()));
        pdf.extend(&chunk);
        objects.push(LayerObject {
            name: layer.name.clone(),
            hidden: layer.hidden,
            xobject: map[&root],
            ocg: alloc.bump(),
        });
    }
    let size = size.expect("at least one layer");
    let k = 72.0 / CSS_DPI;
    let (w, h) = (size.width() * k, size.height() * k);

    let mut catalog = pdf.catalog(catalog_id);
    catalog.pages(page_tree_id);
    write_oc_properties(&mut catalog.insert(Name(b"OCProperties")).dict(), &objects);
    catalog.finish();
    pdf.pages(page_tree_id).count(1).kids([page_id]);
    for o in &objects {
        pdf.indirect(o.ocg)
            .dict()
            .pair(Name(b"Type"), Name(b"OCG"))
            .pair(Name(b"Name"), TextStr(&o.name));
    }

    let names: Vec<(String, String)> = (1..=objects.len())
        .map(|i| (format!("oc{i}"), format!("x{i}")))
        .collect();
    let mut content = Content::new();
    for (oc, x) in &names {
        // Each layer's XObject is one point square (svg2pdf's convention): scale it to the page.
        content
            .begin_marked_content_with_properties(Name(b"OC"))
            .properties_named(Name(oc.as_bytes()));
        content
            .save_state()
            .transform([w, 0.0, 0.0, h, 0.0, 0.0])
            .x_object(Name(x.as_bytes()))
            .restore_state()
            .end_marked_content();
    }
    pdf.stream(content_id, &content.finish());

    let mut page = pdf.page(page_id);
    page.media_box(Rect::new(0.0, 0.0, w, h));
    page.parent(page_tree_id);
    page.contents(content_id);
    let mut resources = page.resources();
    let mut xobjects = resources.x_objects();
    for (o, (_, x)) in objects.iter().zip(&names) {
        xobjects.pair(Name(x.as_bytes()), o.xobject);
    }
    xobjects.finish();
    let mut props = resources.insert(Name(b"Properties")).dict();
    for (o, (oc, _)) in objects.iter().zip(&names) {
        props.pair(Name(oc.as_bytes()), o.ocg);
    }
    props.finish();
    resources.finish();
    page.finish();
    pdf.document_info(alloc.bump())
        .producer(TextStr("lispcad (svg2pdf)"));
    Ok(pdf.finish())
}

/// `/OCProperties`: every group, the viewer's layer list in drawing order, hidden layers off.
fn write_oc_properties(dict: &mut pdf_writer::Dict, objects: &[LayerObject]) {
    dict.insert(Name(b"OCGs"))
        .array()
        .items(objects.iter().map(|o| o.ocg));
    let mut config = dict.insert(Name(b"D")).dict();
    config.pair(Name(b"Name"), TextStr("Layers"));
    config
        .insert(Name(b"Order"))
        .array()
        .items(objects.iter().map(|o| o.ocg));
    config
        .insert(Name(b"OFF"))
        .array()
        .items(objects.iter().filter(|o| o.hidden).map(|o| o.ocg));
}
