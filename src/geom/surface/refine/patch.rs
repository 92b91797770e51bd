//! A parametric surface as Newton sees it: evaluation, derivatives beside creases, periodic
//! wrapping, and projection of a point from a warm start or the search grid.

use super::super::kinds::Surface;
use super::super::ParamSurface;
use glam::{DVec2, DVec3};

/// The step of the difference quotients, in parameters.
const H: f64 = 1e-6;

/// How near the point a warm start must lie to be taken, as a fraction of the surface's size
/// (farther, the projection starts from the search grid).
const WARM: f64 = 0.05;

/// How far from the point, as a fraction of the surface's size, a projection from a warm
/// start may land before [`Patch::project_warm`] checks it from the search grid: far above
/// any tolerance, so a point on or near the surface pays nothing; small beside the surface,
/// so a slide into another local minimum or to a pole is caught (as [`super::beside`]'s probe
/// step).
const WARM_FAR: f64 = 1e-4;

/// A parametric surface with what Newton needs: periodicity and a seed search grid.
pub(crate) struct Patch<'a> {
    s: &'a Surface,
    periodic: [bool; 2],
    /// Each direction's creases (see [`Surface::creases`]): empty for a smooth surface.
    creases: [Vec<f64>; 2],
    grid: Vec<(DVec2, DVec3)>,
    scale: f64,
}

impl<'a> Patch<'a> {
    pub fn new(s: &'a Surface) -> Patch<'a> {
        const N: usize = 48;
        let mut grid = Vec::with_capacity((N + 1) * (N + 1));
        for j in 0..=N {
            for i in 0..=N {
                let uv = DVec2::new(i as f64 / N as f64, j as f64 / N as f64);
                grid.push((uv, s.eval(uv.x, uv.y)));
            }
        }
        let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
        for (_, p) in &grid {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        let scale = (hi - lo).length().max(1e-300);
        let closes = |f: &dyn Fn(f64) -> (DVec3, DVec3)| {
            (0..=8).all(|k| {
                let (a, b) = f(k as f64 / 8.0);
                a.distance(b) <= 1e-12 * scale
            })
        };
        let periodic = [
            closes(&|t| (s.eval(0.0, t), s.eval(1.0, t))),
            closes(&|t| (s.eval(t, 0.0), s.eval(t, 1.0))),
        ];
        Patch {
            s,
            periodic,
            creases: s.creases(),
            grid,
            scale,
        }
    }

    /// The diagonal of the surface's bounding box (of its search grid).
    pub(crate) fn scale(&self) -> f64 {
        self.scale
    }

    /// Whether each parameter direction closes on itself (a seam, not a boundary).
    pub(crate) fn periodic(&self) -> [bool; 2] {
        self.periodic
    }

    #[inline]
    pub fn eval(&self, uv: DVec2) -> DVec3 {
        self.s.eval(uv.x, uv.y)
    }

    /// Partial derivatives by central differences (one-sided at a domain edge, and beside a
    /// crease: see [`Self::deriv`]).
    pub(crate) fn derivs(&self, uv: DVec2) -> (DVec3, DVec3) {
        (self.deriv(uv, 0), self.deriv(uv, 1))
    }

    /// The derivative along parameter `k`. A central difference straddling a crease (a C0
    /// join inside the patch) blends the derivatives of its two sides, and bends whatever
    /// Newton finds within a step of it: a region's edge on a fold's side by 2e-9, a ring's
    /// inner edge by 1.4e-6. There the second-order one-sided difference is taken from the side
    /// `uv` lies on (the later one when on the crease, as the curves evaluate it). The
    /// creases are the surface's own, known from its curves, so a smooth surface pays nothing.
    /// Always inlined (into `derivs` above all): left to the codegen units, it was inlined in
    /// one build and called twice per `derivs` in the next, +0.7 % on contact_line.
    #[inline(always)]
    fn deriv(&self, uv: DVec2, k: usize) -> DVec3 {
        let (mut a, mut b) = (uv, uv);
        a[k] -= H;
        b[k] += H;
        if !self.periodic[k] {
            a[k] = a[k].max(0.0);
            b[k] = b[k].min(1.0);
        }
        if !self.creases[k].is_empty() {
            if let Some(d) = self.beside_crease(uv, k, (a[k], b[k])) {
                return d;
            }
        }
        (self.eval(b) - self.eval(a)) / (b[k] - a[k])
    }

    /// [`Self::deriv`] where a crease lies strictly inside the stencil `(lo, hi)` along `k`:
    /// the one-sided difference from `uv`'s side (None: no crease there, or too near the
    /// domain's edge on that side, where the straddling quotient stands). Kept out of line,
    /// so the smooth surfaces' path stays as short as it was.
    #[inline(never)]
    fn beside_crease(&self, uv: DVec2, k: usize, (lo, hi): (f64, f64)) -> Option<DVec3> {
        let creases = &self.creases[k];
        let c = *creases.get(creases.partition_point(|c| *c <= lo))?;
        if c >= hi {
            return None;
        }
        let side = if uv[k] < c { -1.0 } else { 1.0 };
        let at = |s: f64| {
            let mut q = uv;
            q[k] += side * s;
            q
        };
        if !self.periodic[k] && !(0.0..=1.0).contains(&at(2.0 * H)[k]) {
            return None;
        }
        let (p0, p1, p2) = (self.eval(uv), self.eval(at(H)), self.eval(at(2.0 * H)));
        Some(side * (4.0 * p1 - 3.0 * p0 - p2) / (2.0 * H))
    }

    /// Puts a parameter pair back in the domain: wraps periodic directions, clamps the others.
    /// Returns which parameters sit on a domain edge.
    pub(crate) fn normalise(&self, uv: &mut DVec2) -> [bool; 2] {
        let mut edge = [false; 2];
        for k in 0..2 {
            if self.periodic[k] {
                uv[k] = uv[k].rem_euclid(1.0);
            } else if uv[k] <= 0.0 || uv[k] >= 1.0 {
                uv[k] = uv[k].clamp(0.0, 1.0);
                edge[k] = true;
            }
        }
        edge
    }

    /// Parameters of the point of the surface nearest `p`: the nearest grid point, then Newton
    /// on `(S − p)·S_u = (S − p)·S_v = 0` (Gauss–Newton steps).
    pub fn project(&self, p: DVec3, start: Option<DVec2>) -> DVec2 {
        let mut uv = match start {
            Some(uv) if self.eval(uv).distance(p) <= WARM * self.scale => uv,
            _ => self
                .grid
                .iter()
                .min_by(|a, b| a.1.distance_squared(p).total_cmp(&b.1.distance_squared(p)))
                .map(|g| g.0)
                .unwrap_or(DVec2::splat(0.5)),
        };
        for _ in 0..30 {
            let r = self.eval(uv) - p;
            let (su, sv) = self.derivs(uv);
            let (a, b, c) = (su.dot(su), su.dot(sv), sv.dot(sv));
            let det = a * c - b * b;
            if det.abs() <= 1e-300 {
                break;
            }
            let (g0, g1) = (su.dot(r), sv.dot(r));
            let step = DVec2::new((c * g0 - b * g1) / det, (a * g1 - b * g0) / det);
            let before = uv;
            uv -= step;
            self.normalise(&mut uv);
            // Held on the domain's edge, the next step would be the same one again.
            if step.length() <= 1e-15 || uv == before {
                break;
            }
        }
        uv
    }

    /// [`Self::project`] from a warm start that checks it, and the foot: a warm start (the
    /// last point's parameters, as a tracer keeps them) may slide into another local minimum,
    /// or to a pole (an edge collapsing to a point, as a revolved profile's end on its axis,
    /// where Newton stops, clamped, far short of the nearest point: a flat ring's inner edge
    /// came back as a 4-point loop, and a circle inside the ring was traced as a contact).
    /// Where it lands farther than [`WARM_FAR`] of the surface's size from `p`, and not on an
    /// edge bounding the surface (where a point past the surface has its nearest point), the
    /// projection is taken from the search grid too and the nearer kept.
    pub(crate) fn project_warm(&self, p: DVec3, start: Option<DVec2>) -> (DVec2, DVec3) {
        let uv = self.project(p, start);
        let foot = self.eval(uv);
        let Some(from) = start else {
            return (uv, foot);
        };
        let d = foot.distance(p);
        // A start too far to be taken was the search grid's already.
        if d <= WARM_FAR * self.scale
            || self.bounds_at(uv)
            || self.eval(from).distance(p) > WARM * self.scale
        {
            return (uv, foot);
        }
        let other = self.project(p, None);
        let foot_other = self.eval(other);
        if foot_other.distance(p) < d {
            (other, foot_other)
        } else {
            (uv, foot)
        }
    }

    /// Whether `uv` lies on an edge of the domain that bounds the surface: not a seam, and
    /// not a pole (an edge collapsing to a point), where no point past the surface projects.
    pub(crate) fn bounds_at(&self, uv: DVec2) -> bool {
        (0..2).any(|k| {
            !self.periodic[k] && (uv[k] == 0.0 || uv[k] == 1.0) && !self.collapses(k, uv[k])
        })
    }

    /// Whether the domain edge where parameter `k` is `c` collapses to a point.
    fn collapses(&self, k: usize, c: f64) -> bool {
        let at = |t: f64| {
            let mut q = DVec2::splat(t);
            q[k] = c;
            self.eval(q)
        };
        let p0 = at(0.0);
        (1..=4).all(|i| at(i as f64 / 4.0).distance(p0) <= 1e-12 * self.scale)
    }
}
