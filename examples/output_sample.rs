#[path = "../tests/output_support/mod.rs"]
mod support;
fn main() {
    let d = support::mixed_drawing();
    let dir = std::env::args().nth(1).unwrap();
    let mut o = lispcad::output::OutputOptions::default();
    lispcad::output::save(&d, &std::path::Path::new(&dir).join("mixed.dxf"), &o).unwrap();
    lispcad::output::save(&d, &std::path::Path::new(&dir).join("mixed.svg"), &o).unwrap();
    o.dxf_profile = lispcad::output::DxfProfile::Cam;
    lispcad::output::save(&d, &std::path::Path::new(&dir).join("mixed_cam.dxf"), &o).unwrap();
}
