//! Pairs per second for curve/curve intersection (issue 3 targets: ≥ 20M pairs/s for the
//! analytic pairs, ≥ 20k pairs/s for cubic spline/spline with every root found).
//! Each benchmark intersects a fixed set of varied pairs so branch prediction cannot learn
//! one answer; throughput is reported per pair.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use lispcad::geom::bspline::BSpline;
use lispcad::geom::intersect::{intersect_into, Hit};
use lispcad::geom::{Curve, DVec3};

const N: usize = 256;

/// A tiny deterministic generator (xorshift) so runs are comparable.
struct Rng(u64);
impl Rng {
    fn f(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn pt(&mut self, s: f64) -> DVec3 {
        DVec3::new(self.f() * s, self.f() * s, self.f() * s)
    }
    fn pt2(&mut self, s: f64) -> DVec3 {
        DVec3::new(self.f() * s, self.f() * s, 0.0)
    }
}

fn pairs(kind: &str) -> Vec<(Curve, Curve)> {
    let mut r = Rng(0x9E3779B97F4A7C15);
    let mut out = Vec::new();
    while out.len() < N {
        let pair = match kind {
            "line/line" => {
                // Coplanar crossing segments in a random plane.
                let (p, d1, d2) = (r.pt(10.0), r.pt(1.0) - 0.5, r.pt(1.0) - 0.5);
                (
                    Curve::line(p - d1, p + d1),
                    Curve::line(p - d2, p + d2 * 2.0),
                )
            }
            "line/circle" => {
                let c = r.pt2(10.0);
                let a = r.pt2(10.0);
                (
                    Curve::line(a, c + (c - a) * 0.3),
                    Curve::circle(c, 1.0 + r.f() * 3.0, None),
                )
            }
            "circle/circle" => {
                let c = r.pt2(10.0);
                (
                    Curve::circle(c, 2.0 + r.f(), None),
                    Curve::circle(c + r.pt2(3.0), 1.0 + r.f() * 2.0, None),
                )
            }
            "arc/arc 3D" => {
                // Arcs of two circles in different planes through a common chord a–b.
                let (a, b) = (r.pt(10.0), r.pt(10.0));
                let ab = b - a;
                let m = (a + b) * 0.5;
                let perp = |n: DVec3| (n - ab * (n.dot(ab) / ab.length_squared())).normalize();
                let (n1, n2) = (perp(r.pt(1.0) - 0.5), perp(r.pt(1.0) - 0.5));
                let c1 = m + n1.cross(ab).normalize() * (r.f() * 4.0 - 2.0);
                let c2 = m + n2.cross(ab).normalize() * (r.f() * 4.0 - 2.0);
                (
                    Curve::arc(c1, (a - c1).length(), r.f() * 6.0, r.f() * 6.0, Some(n1)),
                    Curve::arc(c2, (a - c2).length(), r.f() * 6.0, r.f() * 6.0, Some(n2)),
                )
            }
            "spline/line" => {
                // Cubic B-spline (7 control points, 4 spans) against a crossing line.
                let ctrl: Vec<DVec3> = (0..7)
                    .map(|i| DVec3::new(i as f64, (r.f() - 0.5) * 4.0, 0.0))
                    .collect();
                let y = (r.f() - 0.5) * 2.0;
                (
                    Curve::bspline(ctrl, 3, None, None),
                    Curve::line(
                        DVec3::new(-1.0, y, 0.0),
                        DVec3::new(7.0, y + r.f() - 0.5, 0.0),
                    ),
                )
            }
            "cubic spline/spline (9 roots)" => nine_root_pair(&mut r),
            _ => unreachable!(),
        };
        if let (Ok(a), Ok(b)) = pair {
            out.push((a, b));
        }
    }
    out
}

/// The two cubics y = P(x), x = Q(y) of the hard-case suite, jittered: 9 crossings each.
fn nine_root_pair(
    r: &mut Rng,
) -> (
    lispcad::geom::error::Result<Curve>,
    lispcad::geom::error::Result<Curve>,
) {
    let bp = [-0.229, 3.011, -2.449, 1.391];
    let bq = [-1.18432, 5.153146666666666, -3.49272, 1.87808];
    let j = (r.f() - 0.5) * 1e-3;
    let pa: Vec<DVec3> = (0..4)
        .map(|i| DVec3::new(i as f64 / 3.0, bp[i] + j, 0.0))
        .collect();
    let pb: Vec<DVec3> = (0..4)
        .map(|i| DVec3::new(bq[i] - j, i as f64 / 3.0, 0.0))
        .collect();
    (
        BSpline::new(3, pa, None, None)
            .map(Curve::BSpline)
            .map_err(Into::into),
        BSpline::new(3, pb, None, None)
            .map(Curve::BSpline)
            .map_err(Into::into),
    )
}

/// CPU time of this thread in ns from /proc/self/schedstat (Linux): on a shared machine
/// wall-clock throughput understates the code's speed by the load factor.
fn cpu_ns() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    s.split_whitespace().next()?.parse().ok()
}

/// Pairs per CPU-second over at least ~0.3 s of CPU time. The clock is read every 64
/// passes: reading /proc costs microseconds, as much as a pass over the analytic pairs.
fn cpu_rate(ps: &[(Curve, Curve)], out: &mut Vec<Hit>) -> Option<f64> {
    let start = cpu_ns()?;
    let mut pairs = 0u64;
    loop {
        for _ in 0..64 {
            for (a, b) in ps {
                intersect_into(black_box(a), black_box(b), 1e-9, out);
                black_box(&*out);
            }
        }
        pairs += 64 * ps.len() as u64;
        let used = cpu_ns()? - start;
        if used > 300_000_000 {
            return Some(pairs as f64 / (used as f64 * 1e-9));
        }
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("intersect");
    for kind in [
        "line/line",
        "line/circle",
        "circle/circle",
        "arc/arc 3D",
        "spline/line",
        "cubic spline/spline (9 roots)",
    ] {
        // GEOM_BENCH_KIND=line/line restricts the run to one kind (for profiling).
        if std::env::var("GEOM_BENCH_KIND").is_ok_and(|k| k != kind) {
            continue;
        }
        let ps = pairs(kind);
        let mut out: Vec<Hit> = Vec::with_capacity(16);
        let total: usize = ps
            .iter()
            .map(|(a, b)| {
                intersect_into(a, b, 1e-9, &mut out);
                out.len()
            })
            .sum();
        if kind.contains("9 roots") {
            assert_eq!(total, 9 * N, "every root found");
        }
        let rate = cpu_rate(&ps, &mut out).unwrap_or(f64::NAN);
        eprintln!("{kind}: {total} hits over {N} pairs; {rate:.4e} pairs per CPU-second");
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function(kind, |bch| {
            bch.iter(|| {
                for (a, b) in &ps {
                    intersect_into(black_box(a), black_box(b), 1e-9, &mut out);
                    black_box(&out);
                }
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = bench
}
criterion_main!(benches);
