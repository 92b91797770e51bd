//! lispcad's side of bench/dxf: open a DXF (`read_dxf`) and save it again (`render` + write),
//! printing the two times in seconds. `cargo run --release --example dxf_open_save IN OUT`.

use std::time::Instant;

use lispcad::output::{read_dxf, render, Format, OutputOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (input, output) = (&args[1], &args[2]);
    let t0 = Instant::now();
    let data = std::fs::read(input).expect("read the input");
    let d = read_dxf(&data, false).unwrap_or_else(|e| panic!("{input}: {e}"));
    drop(data);
    let t1 = Instant::now();
    let bytes = render(&d, Format::Dxf, &OutputOptions::default()).expect("render");
    std::fs::write(output, bytes).expect("write the output");
    let t2 = Instant::now();
    println!("open_s {:.4}", (t1 - t0).as_secs_f64());
    println!("save_s {:.4}", (t2 - t1).as_secs_f64());
    println!("entities {}", d.len());
}
