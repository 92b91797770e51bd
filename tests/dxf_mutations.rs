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
