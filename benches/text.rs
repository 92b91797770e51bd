//! Speed of the text functions the interpreter calls in loops: printing reals, rtos, distof,
//! and wcmatch (including the pattern that makes naive backtracking exponential).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use lispcad::builtins::text::{distof, format_real, rtos, wcmatch, WcPattern};

fn printing(c: &mut Criterion) {
    c.bench_function("format_real 3.14159265", |b| {
        b.iter(|| format_real(black_box(std::f64::consts::PI)))
    });
    c.bench_function("rtos 17.5 mode 2 prec 4", |b| {
        b.iter(|| rtos(black_box(17.5), 2, 4, 0, 0))
    });
    c.bench_function("rtos 17.5 mode 4 prec 4", |b| {
        b.iter(|| rtos(black_box(17.5), 4, 4, 0, 0))
    });
    c.bench_function("distof 1'-5 1/2\"", |b| {
        b.iter(|| distof(black_box("1'-5 1/2\""), Some(4)))
    });
}

fn matching(c: &mut Criterion) {
    c.bench_function("wcmatch layer name", |b| {
        b.iter(|| wcmatch(black_box("A-WALL-EXTR-NEW"), black_box("A-WALL-*,~*-OLD")))
    });
    let layers = WcPattern::new("A-WALL-*,~*-OLD");
    c.bench_function("WcPattern::matches layer name", |b| {
        b.iter(|| layers.matches(black_box("A-WALL-EXTR-NEW")))
    });
    let text = "a".repeat(1000);
    c.bench_function("wcmatch *a*a*a*a*a*b on 1000 chars", |b| {
        b.iter(|| wcmatch(black_box(&text), black_box("*a*a*a*a*a*b")))
    });
}

criterion_group!(benches, printing, matching);
criterion_main!(benches);
