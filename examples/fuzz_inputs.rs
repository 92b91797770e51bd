//! A libFuzzer-free driver for the input-parser fuzz harness (fuzz/inputs.rs): random and
//! mutated CSV tables, grid specs, STL and OBJ files for a given number of seconds. A panic is
//! reported with its input saved to `fuzz-inputs-crash.bin`.
//!
//!   cargo run --release --example fuzz_inputs -- SECONDS [SEED]

#[path = "../fuzz/inputs.rs"]
mod inputs;

use std::time::{Duration, Instant};

const SEEDS: &[&[u8]] = &[
    b"\x00name,L1,R\n\"big, wide\",140,12\n\"say \"\"hi\"\"\",135.5,10\n",
    b"\x00\xef\xbb\xbfname;L1\r\nbig;140\r\n\"open\n",
    b"\x00a\tb\n1\t2\n3\n",
    b"\x01L1=135:150:5,R=10,15,20",
    b"\x01L1=0:99999:1,R=0:99999:1,T=0.1:0.3:0.1",
    b"\x02solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n",
    b"\x03v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1/1/1 2//2 -1\n",
];

const SPLICE: &[&[u8]] = &[
    b",",
    b";",
    b"\t",
    b"\"",
    b"\"\"",
    b"\r\n",
    b"\n",
    b":",
    b"=",
    b"-1e308",
    b"nan",
    b"1e400",
    b"99999999999999999999",
    b"facet",
    b"vertex",
    b"endloop",
    b"f ",
    b"v ",
    b"/",
    b"\xef\xbb\xbf",
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let secs: u64 = args.first().and_then(|s| s.parse().ok()).unwrap_or(60);
    let mut x: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(0x5eed) | 1;
    let mut rnd = move |n: usize| {
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        (x.wrapping_mul(0x2545_f491_4f6c_dd1d) % n.max(1) as u64) as usize
    };
    let end = Instant::now() + Duration::from_secs(secs);
    let mut runs = 0u64;
    while Instant::now() < end {
        let mut d: Vec<u8> = SEEDS[rnd(SEEDS.len())].to_vec();
        for _ in 0..1 + rnd(8) {
            let i = 1 + rnd(d.len().saturating_sub(1).max(1));
            let i = i.min(d.len());
            match rnd(4) {
                0 => d.insert(i, rnd(256) as u8),
                1 if d.len() > 1 => {
                    d.remove(i.min(d.len() - 1).max(1));
                }
                2 => {
                    let s = SPLICE[rnd(SPLICE.len())];
                    d.splice(i..i, s.iter().copied());
                }
                _ => {
                    let j = rnd(d.len());
                    let k = (j + rnd(16)).min(d.len());
                    let chunk = d[j..k].to_vec();
                    d.splice(i..i, chunk);
                }
            }
        }
        if std::panic::catch_unwind(|| inputs::run(&d)).is_err() {
            std::fs::write("fuzz-inputs-crash.bin", &d).unwrap();
            eprintln!("panic after {runs} inputs; saved to fuzz-inputs-crash.bin");
            std::process::exit(1);
        }
        runs += 1;
    }
    println!("{runs} inputs in {secs} s, no panic");
}
