//! cargo-fuzz target: CSV tables, grid specs, STL and OBJ files (first byte picks which) must
//! never panic or abort. `cargo +nightly fuzz run inputs fuzz/corpus/inputs`.
#![no_main]

#[path = "../inputs.rs"]
mod inputs;

libfuzzer_sys::fuzz_target!(|data: &[u8]| inputs::run(data));
