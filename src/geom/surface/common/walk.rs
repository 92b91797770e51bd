//! Following a narrow region along its length, for regions the seed's one measure of width
//! does not describe: a band lying oblique to the parameter lines (narrow along u and along v,
//! its place moving across the domain) or one whose width changes along its length.
//!
//! From the seed the band is walked in half-cell stations along one parameter direction; at
//! each it is found again across the other (from where the last two stations put it) and its
//! extent measured there. A band whose extent stays the seed's gets the seed's fine lines, as
//! before; otherwise lines at a quarter of its least width are spread over all the places it
//! passes through, so every station's cross-section holds some and the band is connected on
//! the grid. The lines are global, so an oblique band crosses (its range / its width)² of
//! their nodes; only those near the band (in its corridor: the stations' extents, interpolated
//! between stations, widened by the lines' margin) are classified, so its cost grows with its
//! length. [`MOST_LINES`] bounds the lines per direction.

use super::seed::{add_line, W_MIN};
use super::{Tracer, N};
use glam::DVec2;

/// Station spacing along a band, in parameters.
const STEP: f64 = 0.5 / N as f64;
/// Most lines spread across one band in one direction (a 0.002-wide band across the whole
/// domain).
const MOST_LINES: usize = 500;
/// Bisection steps when measuring a station's extent (to 1/4096 of the bracket).
const STEPS: usize = 12;

/// The cells of the grid as first classified that lie within a cell of a node in a region:
/// where bands beside the regions the nodes saw spread their lines ([`Tracer::refine_beside`]),
/// the nodes on those lines there are classified too, and those elsewhere, off the bands'
/// corridors, left out (classifying every node cost a diagonal band beside a wide one 1.1 s).
pub(super) struct Seen {
    lines: [Vec<f64>; 2],
    cells: Vec<bool>,
}

impl Seen {
    pub(super) fn of(t: &Tracer) -> Seen {
        let [nu, nv] = t.cells();
        let mut near = vec![false; nu * nv];
        for j in 0..=nv {
            for i in 0..=nu {
                if !t.node(i, j) {
                    continue;
                }
                // The cells with this corner and those beside them.
                for b in j.saturating_sub(2)..(j + 2).min(nv) {
                    for a in i.saturating_sub(2)..(i + 2).min(nu) {
                        near[b * nu + a] = true;
                    }
                }
            }
        }
        Seen {
            lines: t.lines.clone(),
            cells: near,
        }
    }

    /// Whether `uv` (in the domain) lies in one of the cells.
    fn holds(&self, uv: DVec2) -> bool {
        let at = |k: usize| {
            let n = self.lines[k].len() - 1;
            let i = self.lines[k].partition_point(|x| *x <= uv[k]);
            i.saturating_sub(1).min(n - 1)
        };
        self.cells[at(1) * (self.lines[0].len() - 1) + at(0)]
    }
}

/// A station: its place along the walked direction and the band's extent across it.
pub(super) type Station = (f64, f64, f64);

/// Where a walked band passes: its stations across direction `k` (in order along the walk),
/// widened by `margin` either side.
pub(super) struct Corridor {
    k: usize,
    stations: Vec<Station>,
    margin: f64,
}

impl Tracer<'_, '_> {
    /// The band through `q` (on the target) measured across direction `k` at stations along
    /// the other direction, both ways until the region ends there (or at a domain edge, or
    /// half a turn each way round a seam). Stations where the band is two cells wide or more
    /// either side are passed over but not kept.
    pub(super) fn walk(&self, q: DVec2, k: usize) -> Vec<Station> {
        let m = 1 - k;
        let w_min = W_MIN * self.patch.scale();
        let mut out = Vec::new();
        for dir in [1.0, -1.0] {
            let (mut centre, mut slope) = (q[k], 0.0);
            for j in 0.. {
                if dir < 0.0 && j == 0 {
                    continue; // station 0 is walked once
                }
                let along = j as f64 * STEP;
                let mut p = q;
                p[m] = q[m] + dir * along;
                if self.periodic[m] && along > 0.5
                    || !self.periodic[m] && !(0.0..=1.0).contains(&p[m])
                {
                    break;
                }
                p[k] = centre + slope;
                if !self.on(p) {
                    let Some(g) = self.gap_at(p) else { break };
                    p = self.golden(p, k, g).0;
                    if !self.on(p) {
                        break;
                    }
                }
                let (lo, hi) = (self.extent(p, k, -1.0), self.extent(p, k, 1.0));
                let mid = match (lo, hi) {
                    (Some(lo), Some(hi)) => {
                        let (du, dv) = self.patch.derivs(p);
                        let speed = if k == 0 { du.length() } else { dv.length() };
                        if (hi - lo) * speed < w_min || self.flat_between(p, k, lo, hi).is_none() {
                            break;
                        }
                        out.push((p[m], lo, hi));
                        0.5 * (lo + hi)
                    }
                    _ => p[k],
                };
                if j > 0 {
                    slope = mid - centre;
                }
                centre = mid;
            }
        }
        out
    }

    /// Where the region ends from `p` along direction `k` (sign `s`), to a 4096th of the last
    /// doubling step; None when it goes on for two grid cells.
    fn extent(&self, p: DVec2, k: usize, s: f64) -> Option<f64> {
        let at = |d: f64| {
            let mut x = p;
            x[k] += s * d;
            x
        };
        let (mut inside, mut d) = (0.0, 1e-6 / N as f64);
        while d <= 2.0 / N as f64 {
            if !self.on(at(d)) {
                let mut outside = d;
                for _ in 0..STEPS {
                    let mid = 0.5 * (inside + outside);
                    if self.on(at(mid)) {
                        inside = mid;
                    } else {
                        outside = mid;
                    }
                }
                return Some(p[k] + s * 0.5 * (inside + outside));
            }
            inside = d;
            d *= 2.0;
        }
        None
    }

    /// Whether every station holds the extent `lo..hi` (to a sixteenth of its width): a band
    /// running along the walk at a steady width, which the seed's own lines resolve.
    pub(super) fn steady(&self, stations: &[Station], lo: f64, hi: f64) -> bool {
        let e = (hi - lo) / 16.0;
        stations
            .iter()
            .all(|&(_, l, h)| (l - lo).abs() <= e && (h - hi).abs() <= e)
    }

    /// Lines across direction `k` at a quarter of the narrowest station's width, over every
    /// station's extent and as far again beyond, as the band moves between stations, and the
    /// band's corridor; false when no station is narrow (no lines).
    pub(super) fn spread_lines(&mut self, k: usize, stations: &[Station]) -> bool {
        // In order along the walk (it goes one way from the seed, then the other), so that
        // neighbours are next to each other.
        let mut stations = stations.to_vec();
        stations.sort_by(|a, b| a.0.total_cmp(&b.0));
        let narrow: Vec<&Station> = stations
            .iter()
            .filter(|s| s.2 - s.1 < 2.0 / N as f64)
            .collect();
        let Some(e) = narrow.iter().map(|s| s.2 - s.1).min_by(f64::total_cmp) else {
            return false;
        };
        let moved = narrow
            .windows(2)
            .map(|w| (0.5 * (w[1].1 + w[1].2 - w[0].1 - w[0].2)).abs())
            .fold(0.0, f64::max);
        let margin = e + moved;
        let lo = narrow.iter().map(|s| s.1).fold(f64::MAX, f64::min) - margin;
        let hi = narrow.iter().map(|s| s.2).fold(f64::MIN, f64::max) + margin;
        let count = (((hi - lo) / (0.25 * e)).ceil() as usize).clamp(1, MOST_LINES);
        let step = (hi - lo) / count as f64;
        let lines = &mut self.lines[k];
        for i in 0..count {
            let added = add_line(lines, self.periodic[k], lo + step * (i as f64 + 0.5));
            self.spread[k].extend(added);
        }
        lines.sort_by(f64::total_cmp);
        self.spread[k].sort_by(f64::total_cmp);
        self.corridors.push(Corridor {
            k,
            stations,
            margin,
        });
        true
    }

    /// Whether grid node (i, j) is classified: on the grid the search started from, or in a
    /// band's corridor. A node on a line spread across bands ([`Self::spread_lines`]) off
    /// every corridor lies out of every band found: classifying those would cost
    /// (range / width)² nodes for an oblique band. (With lines spread, every band found is
    /// oblique: see [`Self::refine_narrow`].)
    pub(super) fn needed(&self, i: usize, j: usize) -> bool {
        let uv = self.uv_of(i, j);
        let spread = |k: usize| {
            self.spread[k]
                .binary_search_by(|x| x.total_cmp(&uv[k]))
                .is_ok()
        };
        !(spread(0) || spread(1))
            || self.corridors.iter().any(|c| self.in_corridor(c, uv))
            || self.seen.as_ref().is_some_and(|s| s.holds(uv))
    }

    /// Whether `uv` lies in the corridor: within its margin of the band's extent, interpolated
    /// between the two stations either side of it along the walk (or within a station of the
    /// walk's ends); everywhere across where stations were passed over (the band wide there).
    fn in_corridor(&self, c: &Corridor, uv: DVec2) -> bool {
        let (k, m) = (c.k, 1 - c.k);
        let st = &c.stations;
        let shifts: &[f64] = if self.periodic[m] {
            &[-1.0, 0.0, 1.0]
        } else {
            &[0.0]
        };
        let near = |lo: f64, hi: f64| {
            let mut d = uv[k] - 0.5 * (lo + hi);
            if self.periodic[k] {
                d -= d.round();
            }
            d.abs() <= 0.5 * (hi - lo) + c.margin
        };
        shifts.iter().any(|&shift| {
            let x = uv[m] + shift;
            let i = st.partition_point(|s| s.0 <= x);
            if i == 0 || i == st.len() {
                let end = st[if i == 0 { 0 } else { i - 1 }];
                return (x - end.0).abs() <= STEP && near(end.1, end.2);
            }
            let (a, b) = (st[i - 1], st[i]);
            if b.0 - a.0 > 1.5 * STEP {
                return true;
            }
            let f = (x - a.0) / (b.0 - a.0);
            near(a.1 + f * (b.1 - a.1), a.2 + f * (b.2 - a.2))
        })
    }

    /// Whether `uv` lies within a seed cell of a station's extent, half a station along.
    pub(super) fn walked(&self, k: usize, stations: &[Station], uv: DVec2) -> bool {
        let m = 1 - k;
        let off = |a: f64, b: f64, periodic: bool| {
            let d = a - b;
            if periodic {
                d - d.round()
            } else {
                d
            }
        };
        stations.iter().any(|&(at, lo, hi)| {
            off(uv[m], at, self.periodic[m]).abs() <= 0.5 * STEP
                && off(uv[k], 0.5 * (lo + hi), self.periodic[k]).abs()
                    <= 0.5 * (hi - lo) + super::seed::SEED_CELL
        })
    }
}
