//! A libFuzzer-free driver for the reader+evaluator fuzz harness (fuzz/harness.rs), for
//! machines without nightly Rust or cargo-fuzz: mutates a corpus (default: the conformance
//! cases, split at top-level forms) with a xorshift PRNG for a given number of seconds and
//! reports any input that panics. An abort or stack overflow kills the process; the input
//! being run is in `fuzz-current.lsp` for reproduction.
//!
//!   cargo run --release --example fuzz_eval -- SECONDS [SEED] [CORPUS_DIR...]

#[path = "../fuzz/harness.rs"]
mod harness;

use std::time::{Duration, Instant};

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Tokens worth splicing in: the syntax and the functions most likely to reach edge cases.
const TOKENS: &[&str] = &[
    "(",
    ")",
    "'",
    "\"",
    ".",
    ";",
    ";|",
    "|;",
    "\\",
    " nil ",
    " t ",
    " 0 ",
    " -1 ",
    " 1e308 ",
    " -2147483648 ",
    " 2147483647 ",
    " 1. ",
    " .5 ",
    "(defun f (x / y) ",
    "(lambda (x) ",
    "(setq ",
    "(repeat 100 ",
    "(while ",
    "(foreach x ",
    "(mapcar ",
    "(apply ",
    "(eval ",
    "(read ",
    "(vl-catch-all-apply ",
    "(*error* ",
    "(defun *error* (m) ",
    "(cons ",
    "(list ",
    "(append ",
    "(reverse ",
    "(subst ",
    "(assoc ",
    "(nth ",
    "(vl-sort ",
    "(acad_strlsort ",
    "(rtos ",
    "(angtos ",
    "(distof ",
    "(atof ",
    "(atoi ",
    "(itoa ",
    "(substr ",
    "(strcat ",
    "(vl-string-subst ",
    "(vl-prin1-to-string ",
    "(read ",
    "(chr ",
    "(ascii ",
    "(/ ",
    "(rem ",
    "(expt ",
    "(sqrt ",
    "(exp ",
    "(log ",
    "(fix ",
    "(float ",
    "(gcd ",
    "(lsh ",
    "(boole ",
    "(~ ",
    "(logand ",
    "(equal ",
    "(eq ",
    "(member ",
    "(length ",
    "(last ",
    "(type ",
    "(inters ",
    "(polar ",
    "(angle ",
    "(distance ",
    "(trans ",
    "(getvar ",
    "(setvar ",
    "(exit)",
    "(quit)",
    "(princ ",
    "(prin1 ",
    "(print ",
    "(strcase ",
    "(wcmatch ",
];

fn mutate(rng: &mut Rng, corpus: &[Vec<u8>], input: &[u8]) -> Vec<u8> {
    let mut v = input.to_vec();
    for _ in 0..1 + rng.below(4) {
        let pos = rng.below(v.len() + 1);
        match rng.below(8) {
            0 if !v.is_empty() => {
                let end = (pos + 1 + rng.below(16)).min(v.len());
                v.drain(pos.min(end)..end);
            }
            1 => v.insert(pos, rng.next() as u8),
            2 if !v.is_empty() => {
                let p = pos.min(v.len() - 1);
                v[p] ^= 1 << rng.below(8);
            }
            3 | 4 => {
                let t = TOKENS[rng.below(TOKENS.len())].as_bytes();
                v.splice(pos..pos, t.iter().copied());
            }
            5 => {
                // Splice in a piece of another corpus entry.
                let other = &corpus[rng.below(corpus.len())];
                let a = rng.below(other.len());
                let b = (a + rng.below(64)).min(other.len());
                v.splice(pos..pos, other[a..b].iter().copied());
            }
            6 if !v.is_empty() => {
                // Duplicate a slice: nesting and repetition.
                let a = rng.below(v.len());
                let b = (a + rng.below(32)).min(v.len());
                let piece = v[a..b].to_vec();
                v.splice(pos..pos, piece);
            }
            _ => {
                let n = [0, 1, 127, 128, 255, 0x7f, 0xc3, 0xff][rng.below(8)];
                v.insert(pos, n);
            }
        }
    }
    v.truncate(4096);
    v
}

/// Top-level chunks of the conformance files (split before lines starting with `(`).
fn load_corpus(dirs: &[String]) -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    for d in dirs {
        let Ok(rd) = std::fs::read_dir(d) else {
            continue;
        };
        for e in rd.flatten() {
            let Ok(text) = std::fs::read_to_string(e.path()) else {
                continue;
            };
            let mut cur = String::new();
            for line in text.lines() {
                if line.starts_with('(') && !cur.trim().is_empty() {
                    out.push(std::mem::take(&mut cur).into_bytes());
                }
                cur.push_str(line);
                cur.push('\n');
            }
            if !cur.trim().is_empty() {
                out.push(cur.into_bytes());
            }
        }
    }
    if out.is_empty() {
        out.push(b"(defun f (n) (if (< n 2) n (+ (f (- n 1)) (f (- n 2))))) (f 10)".to_vec());
    }
    out
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let secs: u64 = args.first().and_then(|s| s.parse().ok()).unwrap_or(60);
    let seed: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(0x5eed);
    let dirs: Vec<String> = if args.len() > 2 {
        args[2..].to_vec()
    } else {
        vec![concat!(env!("CARGO_MANIFEST_DIR"), "/tests/conformance").to_string()]
    };
    let corpus = load_corpus(&dirs);
    let mut rng = Rng(seed | 1);
    // Panics are reported and counted, not printed by the default hook for every input.
    std::panic::set_hook(Box::new(|_| {}));
    let deadline = Instant::now() + Duration::from_secs(secs);
    let (mut runs, mut panics) = (0u64, 0u64);
    while Instant::now() < deadline {
        let base = &corpus[rng.below(corpus.len())];
        let input = mutate(&mut rng, &corpus, base);
        let _ = std::fs::write("fuzz-current.lsp", &input);
        if std::panic::catch_unwind(|| harness::run(&input)).is_err() {
            panics += 1;
            let name = format!("fuzz-crash-{panics}.lsp");
            let _ = std::fs::write(&name, &input);
            eprintln!("panic: input saved to {name}");
        }
        runs += 1;
    }
    let _ = std::fs::remove_file("fuzz-current.lsp");
    println!(
        "{runs} inputs in {secs} s (seed {seed}), corpus {}, panics: {panics}",
        corpus.len()
    );
    if panics > 0 {
        std::process::exit(1);
    }
}
