//! One-dimensional minimisation by golden-section search (Kiefer 1953): shrinks a bracket
//! [lo, hi] around a minimum of a unimodal function by the golden ratio each step.

/// The midpoint of the final bracket after shrinking [lo, hi] until it is no wider than `tol`
/// or `max_iter` steps have run.
pub(crate) fn golden_section_min(
    f: impl Fn(f64) -> f64,
    mut lo: f64,
    mut hi: f64,
    max_iter: usize,
    tol: f64,
) -> f64 {
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    let (mut x1, mut x2) = (hi - phi * (hi - lo), lo + phi * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..max_iter {
        if f1 < f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - phi * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + phi * (hi - lo);
            f2 = f(x2);
        }
        if hi - lo <= tol {
            break;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    #[test]
    fn finds_the_minimum_of_a_parabola() {
        let t = super::golden_section_min(|x| (x - 0.3) * (x - 0.3), 0.0, 1.0, 100, 1e-12);
        assert!((t - 0.3).abs() < 1e-6);
    }
}
