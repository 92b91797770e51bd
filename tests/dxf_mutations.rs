//! Damaged drawings never panic the reader: deterministic mutations (truncations, dropped
//! and duplicated lines, flipped bytes, binary garbage) of real files, strict and
//! `--recover`; whatever reads also writes and reads back. The cargo-fuzz target
//! `fuzz/fuzz_targets/dxf_read.rs` does the same with libFuzzer's mutations.

use lispcad::output::{read_dxf, render, Format, OutputOptions};

/// xorshift64*: a fixed sequence, so a failure reproduces.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn mutate(seed: &[u8], rng: &mut Rng) -> Vec<u8> {
    let mut lines: Vec<Vec<u8>> = seed.split(|b| *b == b'\n').map(<[u8]>::to_vec).collect();
    for _ in 0..1 + rng.below(3) {
        let n = lines.len();
        match rng.below(6) {
            0 => lines.truncate(rng.below(n)),
            1 => {
                lines.remove(rng.below(n));
            }
            2 => {
                let i = rng.below(n);
                let l = lines[i].clone();
                lines.insert(i, l);
            }
            3 => {
                let i = rng.below(n);
                if !lines[i].is_empty() {
                    let j = rng.below(lines[i].len());
                    lines[i][j] ^= 1 << rng.below(8);
                }
            }
            4 => {
                let i = rng.below(n);
                lines[i] = b"1e999".to_vec();
            }
            _ => {
                let i = rng.below(n);
                lines[i] = (0..rng.below(12)).map(|_| rng.next() as u8).collect();
            }
        }
    }
    lines.join(&b'\n')
}

fn check(data: &[u8]) {
    for recover in [false, true] {
        if let Ok(d) = read_dxf(data, recover) {
            if let Ok(bytes) = render(&d, Format::Dxf, &OutputOptions::default()) {
                if let Err(e) = read_dxf(&bytes, recover) {
                    panic!("written drawing does not read back: {e}");
                }
            }
        }
    }
}

#[test]
fn mutated_drawings_never_panic() {
    let seed = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scripts/temple-outline.dxf"
    ))
    .unwrap();
    check(&seed);
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for _ in 0..600 {
        check(&mutate(&seed, &mut rng));
    }
}

#[test]
fn binary_garbage_never_panics() {
    let mut rng = Rng(42);
    let mut head = b"AutoCAD Binary DXF\r\n\x1a\0".to_vec();
    head.extend_from_slice(b"\0\0SECTION\0\x02\0HEADER\0");
    for _ in 0..1000 {
        let mut d = head.clone();
        let n = rng.below(200);
        d.extend((0..n).map(|_| rng.next() as u8));
        check(&d);
        check(&d[..rng.below(d.len())]);
    }
}

/// Found by examples/fuzz_inputs: a block name whose 12th byte falls inside a character (here
/// a Windows-1252 quote, three bytes in UTF-8) was sliced there to compare with
/// "*Paper_Space", and panicked.
#[test]
fn a_block_name_with_a_wide_character_at_byte_12_reads() {
    for name in [&b"*Model_Spac\x93e"[..], "*Paper_Spac\u{e9}X".as_bytes()] {
        let mut d = b"  0\nSECTION\n  2\nBLOCKS\n  0\nBLOCK\n  8\n0\n  2\n".to_vec();
        d.extend_from_slice(name);
        d.extend_from_slice(
            b"\n 70\n0\n 10\n0\n 20\n0\n  0\nENDBLK\n  8\n0\n  0\nENDSEC\n  0\nEOF\n",
        );
        check(&d);
        read_dxf(&d, true).expect("reads with --recover");
    }
    // The whole input the fuzzer saved.
    check(include_bytes!("dxf_support/fuzz-block-name.dxf"));
}

/// Found by the release fuzz run (fuzz_inputs, seed 23): the group code ` 40142857` in a SPLINE
/// was kept, written back as -30711 (16 bits), and the copy did not read. A code outside DXF's
/// range is now an error with its line, and `--recover` skips the pair.
#[test]
fn a_group_code_out_of_range_is_an_error_not_a_wrapped_code() {
    let data = include_bytes!("dxf_support/fuzz-group-code.dxf");
    let e = read_dxf(data, false).expect_err("strict read refuses the damaged code");
    let msg = e.to_string();
    assert!(
        msg.contains("group code 40142857 is out of range") && msg.contains("line 739"),
        "{msg}"
    );
    let d = read_dxf(data, true).expect("reads with --recover");
    let bytes = render(&d, Format::Dxf, &OutputOptions::default()).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    assert!(
        !text.lines().any(|l| l.trim() == "-30711"),
        "wrapped code written"
    );
    check(data);
}

/// Found by the release fuzz run (fuzz_inputs, seed 29, after 328,447 inputs): a NUL byte in a
/// layer name past the first 4 KiB was read as text, written back nearer the start, and the
/// copy was then taken for a binary file. A NUL in an ASCII value is now an error with its line;
/// `--recover` cuts the value there, as C readers do.
#[test]
fn a_nul_byte_in_a_value_is_an_error_and_never_written() {
    let data = include_bytes!("dxf_support/fuzz-nul-value.dxf");
    // Past the first 4 KiB, where a NUL no longer marks the whole file as binary.
    let mut clean = format!("999\n{}\n", "x".repeat(5000)).into_bytes();
    clean.extend_from_slice(b"  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n  8\nA");
    clean.extend_from_slice(b"\0B\n 10\n0\n 20\n0\n 11\n1\n 21\n1\n  0\nENDSEC\n  0\nEOF\n");
    let e = read_dxf(&clean, false).expect_err("strict read refuses it");
    let msg = e.to_string();
    assert!(msg.contains("NUL byte") && msg.contains("line 10"), "{msg}");
    for d in [&data[..], &clean[..]] {
        let read = read_dxf(d, true).expect("reads with --recover");
        let bytes = render(&read, Format::Dxf, &OutputOptions::default()).unwrap();
        assert!(!bytes.contains(&0), "a NUL written");
        check(d);
    }
}
