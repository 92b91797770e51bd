//! One fuzz input through the file and batch input parsers: the first byte picks CSV table,
//! grid spec, STL, OBJ or DXF; the rest is the file. Anything but a clean `Ok`/`Err` — a panic,
//! an abort, a huge allocation — is a bug. Shared by the cargo-fuzz target `inputs` and the
//! stable driver `examples/fuzz_inputs.rs`.

use lispcad::cli::batch::{csv, sink, source};
use lispcad::geom::mesh::{parse_obj, parse_stl};
use lispcad::output::{read_dxf, render, Format, OutputOptions};

pub fn run(data: &[u8]) {
    let Some((&kind, rest)) = data.split_first() else {
        return;
    };
    match kind % 5 {
        0 => {
            let text = String::from_utf8_lossy(rest);
            if let Ok((_, rows)) = csv::table(&text) {
                for r in rows.iter().take(8) {
                    let _ = sink::expand_pattern("out/{row}-{a}.dxf", r);
                }
            }
        }
        1 => {
            let text = String::from_utf8_lossy(rest);
            if let Ok(src) = source::grid_source(&text) {
                // Rows are made on demand: a few, from both ends, never the whole product.
                let n = src.len();
                let _ = src.rows().take(4).count();
                if let source::Source::Grid(g) = &src {
                    if n > 0 {
                        let last = g.row(n - 1);
                        assert_eq!(last.number, n);
                    }
                }
            }
        }
        2 => {
            let _ = parse_stl(rest, 0.0, "fuzz.stl");
            let _ = parse_stl(rest, 1e-6, "fuzz.stl");
        }
        3 => {
            let _ = parse_obj(&String::from_utf8_lossy(rest), "fuzz.obj");
        }
        _ => {
            // Strict and --recover; whatever reads must write and read back (as dxf_read).
            for recover in [false, true] {
                if let Ok(d) = read_dxf(rest, recover) {
                    if let Ok(bytes) = render(&d, Format::Dxf, &OutputOptions::default()) {
                        read_dxf(&bytes, recover).expect("a written drawing reads back");
                    }
                }
            }
        }
    }
}
