//! Writes the benchmark pair: icosphere A (8 subdivisions, 1,310,720 triangles) and
//! B = A rotated 0.3 rad about (1, 2, 3) and moved by (0.5, 0.3, 0.2), as binary STL.
//!
//! Usage: gen_icospheres OUT_DIR

use lispcad::geom::mesh::{icosphere, write_stl_binary};
use lispcad::geom::{DMat4, DVec3};

fn main() {
    let dir = std::env::args().nth(1).unwrap_or_else(|| ".".into());
    let a = icosphere(DVec3::ZERO, 1.0, 8);
    let m = DMat4::from_translation(DVec3::new(0.5, 0.3, 0.2))
        * DMat4::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.3);
    let b = a
        .map_vertices(|p| m.transform_point3(p))
        .expect("transform");
    write_stl_binary(&a, format!("{dir}/ico_a.stl")).expect("write A");
    write_stl_binary(&b, format!("{dir}/ico_b.stl")).expect("write B");
    println!("wrote {} triangles each", a.len());
}
