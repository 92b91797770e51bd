//! cargo-fuzz target: arbitrary bytes through the DXF reader, strict and `--recover`, must
//! never panic; a drawing that reads must write and read back. Run with
//! `cargo +nightly fuzz run dxf_read fuzz/corpus/dxf_read` (seed the corpus with
//! scripts/temple-outline.dxf and the files of tests/validate/dxf_samples.py).
#![no_main]

use lispcad::output::{read_dxf, render, Format, OutputOptions};

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    for recover in [false, true] {
        if let Ok(d) = read_dxf(data, recover) {
            if let Ok(bytes) = render(&d, Format::Dxf, &OutputOptions::default()) {
                read_dxf(&bytes, recover).expect("a written drawing reads back");
            }
        }
    }
});
