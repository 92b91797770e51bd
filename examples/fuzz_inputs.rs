//! A libFuzzer-free driver for the input-parser fuzz harness (fuzz/inputs.rs): random and
//! mutated CSV tables, grid specs, STL, OBJ and DXF files for a given number of seconds. A panic is
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
    b"\x04  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n  8\n0\n 10\n0\n 20\n0\n 11\n1\n 21\n1\n  0\nLWPOLYLINE\n  8\nA\n 90\n2\n 70\n1\n 10\n0\n 20\n0\n 42\n0.5\n 10\n5\n 20\n0\n  0\nCIRCLE\n 10\n1\n 20\n1\n 40\n2\n  0\nENDSEC\n  0\nEOF\n",
];

/// Whole drawings written by the DXF writer and ezdxf (first byte 4: the DXF reader).
const DXF_FILES: &[&[u8]] = &[
    include_bytes!("../tests/golden/basic.dxf"),
    include_bytes!("../tests/golden/splines.dxf"),
    include_bytes!("../tests/golden/mesh.dxf"),
    include_bytes!("../scripts/temple-outline.dxf"),
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
    b"\n  0\n",
    b"\n 10\n",
    b"\n 70\n",
    b"\n 90\n",
    b"SECTION",
    b"ENDSEC",
    b"ENTITIES",
    b"BLOCK",
    b"LWPOLYLINE",
    b"SPLINE",
    b"\n  0\nEOF\n",
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
    let mut per_kind = [0u64; 5];
    while Instant::now() < end {
        let pick = rnd(SEEDS.len() + DXF_FILES.len());
        let mut d: Vec<u8> = match SEEDS.get(pick) {
            Some(s) => s.to_vec(),
            None => [&[4u8][..], DXF_FILES[pick - SEEDS.len()]].concat(),
        };
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
        per_kind[usize::from(d[0] % 5)] += 1;
    }
    let [csv, grid, stl, obj, dxf] = per_kind;
    println!(
        "{runs} inputs in {secs} s, no panic (csv {csv}, grid {grid}, stl {stl}, obj {obj}, dxf {dxf})"
    );
}
