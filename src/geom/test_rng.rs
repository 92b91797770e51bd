//! A small deterministic generator (xorshift64) for the geometry unit tests, so that their
//! random cases are the same on every run. (The benchmarks keep their own copy: they are
//! built outside the tests, and `bench/geom/compare.py` mirrors theirs.)

use glam::DVec3;

pub(crate) struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// Uniform in [0, 1).
    pub fn f(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A point with coordinates uniform in [0, s).
    pub fn pt(&mut self, s: f64) -> DVec3 {
        DVec3::new(self.f() * s, self.f() * s, self.f() * s)
    }
}
