//! The near-edge family of branch points on a curved tangent contact (issue 13) over two grids
//! of runs: the crossing through or into the contact of `surface_contact_branch`'s patch with the
//! plate z = 0, for many branch points (along the contact from the patch's edge θ = 0, on it,
//! near it, far from it), seeds and orders. Moved here from `surface_contact_branch` (which was
//! past ~800 lines) unchanged: a test "above" in these docs is one of that file's.

mod surface_support;
use lispcad::geom::mesh::Polyline3;
use surface_support::section_and_both_orders;
#[path = "surface_support/branch.rs"]
mod branch;
use branch::{check, check_sloped_within, list_if_failing, patch, plate, MEET};
use std::f64::consts::FRAC_PI_2;

/// [`check`] on each run of [`section_and_both_orders`] of `patch(d0, d1)` against [`plate`] at
/// `seed` (curves densified within 1e-6, each run twice for the same bits), the name of each
/// failing run pushed to `failed` (the check's message goes to stderr from the panic).
fn list_failing_runs(failed: &mut Vec<String>, tag: &str, (d0, d1): (f64, f64), seed: f64) {
    let s = patch(d0, d1);
    let plate = plate();
    for (name, run) in section_and_both_orders("patch", &s, &plate, seed, 1e-6) {
        let name = format!("{tag} seed {seed} {name}");
        let check = |name: &str, r: &[Polyline3]| check(name, r, (d0, d1), MEET);
        list_if_failing(failed, name, run, check);
    }
}

/// How wide the near-edge family is: the test above over a wider grid, s ∈ {2.5e-3, 5e-3,
/// 1e-2, 1.5e-2, 2e-2, 3e-2, 5e-2} along the contact from the edge θ = 0 (d running by 16 over
/// the quarter turn), the branch point on the edge (d = 0..0.3, 0.3..0, 0..16, 16..0) and the
/// inner one (−0.1..0.3), each at seeds 1e-2, 5e-3 and 1e-3 in the section and both orders:
/// 108 runs (about 20 s in a release build).
///
/// On c7e144c 22 fail. Nine were every run at s = 2e-2: a seed curve of the crossing held a
/// lens of the contact (two sides of the meshes' section closer than a cell, from the branch
/// point out to θ ≈ 0.28 and back) refined onto the contact out and back, and `regroup` kept it
/// whole, none of its first, middle and last points touching: the crossing came back 1.09
/// too long (the contact lost from the section at seed 1e-2), or with a closed 1.145-long
/// loop cut from it by `join` (seed 1e-3). `regroup` now probes such a curve where it folds
/// back (`fold_probes`), and all nine are mended; three runs at s = 2e-2 then fail on what the
/// spur had hidden (below). Three more were s = 2.5e-3 at seed 1e-3, all three runs: a seed
/// curve along the contact and on along the stub, all three probes touching (the stub parts
/// from the plane at a sine under 1e-3), kept whole beside the traced contact (three curves,
/// the contact twice); `regroup` now cuts such a curve off the contact.
///
/// On 208b8a0, 12 of 108 failed (13 before fb7e2b6, which mended the stray stub at s = 1.5e-2
/// seed 1e-2 in the section). Mended since: four section runs (s = 1.5e-2, 2e-2, 3e-2 at seed
/// 5e-3: 6.5e-6, 9.0e-6, 1.0e-5 off at |W| ≈ 3.5e-4; s = 2e-2 seed 1e-3, 2.8e-8 at W = 4.6e-3),
/// section midpoints where Newton crawled onto the crossing beside the contact's double zero
/// and stopped within 0.01·tol of the plane, now taken across the curve onto the distance's
/// root (`refine::plane_across`); s = 1.5e-2 seed 1e-3 plate ∩ patch (a 6-point copy of the
/// stub's end, a contact midpoint stepped across by stale derivatives, i13c); s = 5e-2 seed
/// 5e-3 plate ∩ patch (the crossing 12.26 long, a seam of `join_ends` run off along the
/// contact, i13d); d = 0..16 seed 1e-3 plate ∩ patch (a 15-point piece of the crossing, 0.056
/// long; mended by these merges, not traced which).
///
/// Mended on stage-s18 after that: two section runs, s = 1e-2 and 3e-2 at seed 1e-2 (a
/// crossing point 3.8e-8 off at W = −4.5e-3, 5.2e-8 at W = −5.5e-3): section midpoints whose
/// Newton stopped 4e-12 and 8e-12 off the plane, where `plane_across`'s own Newton step landed
/// on the root to rounding (1e-17) and, finding no sign change past it, was dropped (it now
/// keeps it, i13a). Two plate ∩ patch runs, s = 3e-2 seed 1e-2 and s = 2e-2 seed 1e-3: the
/// contact's end on the far edge θ = π/2 2.09e-8 and 2.81e-8 off r = 2 (allowed 2e-8). Traced
/// from the plate's parameters (`regroup`'s contact walk), the last 1.6e-4 to the patch's edge
/// were straight steps (the bisection for the end, shorter than √(tol·size)) along the last
/// settled chord's line, which leans off the circle by half its turn; they now follow the arc
/// the walk turns by (ends 8e-13 and 4e-12 off, i13d). And d = 0..16 seed 5e-3, plate ∩ patch,
/// mended in the check (i13c): no curve was taken for the crossing, because their shared end,
/// the branch point solved 1.4e-9 from (2, 0, 0), 4.7e-10 from the crossing in space, 1.2e-9
/// from the contact and 1.4e-19 off both surfaces (all in closed form), is 2.4e-9 off the
/// crossing in r, and `on_line` measured `MEET` in r across a crossing steep there (r′/r about
/// 5); it now measures the distance to the curve (`off_curve`), and the run passes whole.
///
/// All 108 runs pass on stage-s18, and the test is no longer ignored; a second grid, below,
/// holds the open runs found past this one.
///
/// The grid runs as six tests, one per seed and family (s, or the branch points' d), sharing
/// [`runs_of_the_family_pass`]: in one test it took 496 s of CI's debug build on one core.
const WIDER_S: [f64; 7] = [2.5e-3, 5e-3, 1e-2, 1.5e-2, 2e-2, 3e-2, 5e-2];

/// The branch points of the wider grid (see [`WIDER_S`]): on the edge, and the inner one.
const WIDER_D: [(f64, f64); 5] = [
    (0.0, 0.3),
    (0.3, 0.0),
    (0.0, 16.0),
    (16.0, 0.0),
    (-0.1, 0.3),
];

/// [`list_failing_runs`] at `seed` for each distance `s` along the contact from the edge θ = 0
/// (d running by 16 over the quarter turn from −16·(s/2)/(π/2)), then for each d range of `d`;
/// fails listing every failing run.
fn runs_of_the_family_pass(seed: f64, s: &[f64], d: &[(f64, f64)]) {
    let mut failed = Vec::new();
    for &s in s {
        let d0 = -16.0 * (0.5 * s) / FRAC_PI_2;
        list_failing_runs(&mut failed, &format!("s {s}"), (d0, d0 + 16.0), seed);
    }
    for &d in d {
        list_failing_runs(&mut failed, &format!("d {}..{}", d.0, d.1), d, seed);
    }
    assert!(
        failed.is_empty(),
        "failing runs ({}): {failed:?}",
        failed.len()
    );
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_2_over_s() {
    runs_of_the_family_pass(1e-2, &WIDER_S, &[]);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_2_over_d() {
    runs_of_the_family_pass(1e-2, &[], &WIDER_D);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_5e_3_over_s() {
    runs_of_the_family_pass(5e-3, &WIDER_S, &[]);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_5e_3_over_d() {
    runs_of_the_family_pass(5e-3, &[], &WIDER_D);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_3_over_s() {
    runs_of_the_family_pass(1e-3, &WIDER_S, &[]);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_3_over_d() {
    runs_of_the_family_pass(1e-3, &[], &WIDER_D);
}

/// A second grid, past the first (lead, stage-s18, once the first passed whole): s ∈ {4e-3,
/// 7.5e-3, 1.2e-2, 2.5e-2, 4e-2, 7e-2} along the contact from the edge θ = 0, the branch
/// point on the edge with d = 0..1, and inner branch points near the edge (d = −0.05..0.5,
/// θ = π/22) and far from it (d = −0.3..0.1, θ = 3π/8), at seeds 2e-2, 1e-2, 5e-3,
/// 2e-3 and 1e-3, in the section and both orders: 135 runs. All 90 runs of the s family pass,
/// and every section and patch ∩ plate run. On f9f728b 6 of 135 failed, all plate ∩ patch (the
/// gap taken from the plate's parameters), all mended on stage-s19 and now passing:
/// - d = 0..1 at seeds 2e-2, 1e-2, 5e-3, 2e-3: three curves; not the crossing in two pieces,
///   but the crossing short of the branch point and a seed curve along the contact kept whole,
///   no contact traced from it in `regroup` (i13c); see
///   [`a_crossing_from_a_branch_point_on_an_edge_at_d_0_to_1_comes_back_whole`];
/// - d = −0.05..0.5 at seeds 1e-2 and 2e-3: the contact 3.1438 (1e-2) or 3.1423 (2e-3) long
///   against π, ends in place, a spur beside the branch point on the gap's other extremum
///   (i13d); see [`a_contact_past_an_inner_branch_point_near_an_edge_has_no_spur`].
///
/// The grid runs as five tests, one per seed, sharing [`runs_of_the_family_pass`], so that
/// libtest runs them side by side.
const SECOND_S: [f64; 6] = [4e-3, 7.5e-3, 1.2e-2, 2.5e-2, 4e-2, 7e-2];

/// The branch points of the second grid (see [`SECOND_S`]): on the edge, near it, far from it.
const SECOND_D: [(f64, f64); 3] = [(0.0, 1.0), (-0.05, 0.5), (-0.3, 0.1)];

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_2e_2() {
    runs_of_the_family_pass(2e-2, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_1e_2() {
    runs_of_the_family_pass(1e-2, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_5e_3() {
    runs_of_the_family_pass(5e-3, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_2e_3() {
    runs_of_the_family_pass(2e-3, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_1e_3() {
    runs_of_the_family_pass(1e-3, &SECOND_S, &SECOND_D);
}

/// The branch points of both grids (on the edge θ = 0 or π/2, inner, near the edge, far from it)
/// at the user's CHORDTOL (`surface-section` by z = 0 and `surface-intersect` in both orders,
/// seeding meshes and chords both within CHORDTOL), checked by [`check_sloped_within`] with the
/// chord, as the patch ∩ cone test at the user's CHORDTOL (in `surface_contact_branch`) is:
/// 8 d ranges, CHORDTOL 2e-2, 1e-2, 5e-3, 2e-3 and 1e-3, three runs each, 120 runs, one test
/// per CHORDTOL. i13a (round s19, on that round's main, not committed) saw 12 of these 120 fail
/// (d = 0..1 at every CHORDTOL; d = 0..16 and 16..0 at 2e-2, 1e-2, 5e-3; −0.3..0.1 at 2e-2),
/// some perhaps only the check's `MEET` (a contact end 2.8e-9 from the branch point against
/// 2e-9 allowed; SPEC §4 promises points within GEOMTOL of both surfaces, not a meeting point).
/// Rebuilt on main 1cf74ec (i13b-s19b) all 120 pass, with `MEET` as everywhere else in these
/// tests; which merge mended which run was not traced (d = 0..1's likely by f0cd039's regroup
/// step-in, as its grid runs were).
const CHORDTOL_D: [(f64, f64); 8] = [
    (0.0, 0.3),
    (0.3, 0.0),
    (0.0, 16.0),
    (16.0, 0.0),
    (-0.1, 0.3),
    (0.0, 1.0),
    (-0.05, 0.5),
    (-0.3, 0.1),
];

/// Every run of [`section_and_both_orders`] of each [`CHORDTOL_D`] patch against [`plate`] at
/// CHORDTOL `tol` checked within the chord (each run twice for the same bits); fails listing
/// every failing run.
fn runs_at_the_users_chordtol_pass(tol: f64) {
    let plate = plate();
    let mut failed = Vec::new();
    for (d0, d1) in CHORDTOL_D {
        let s = patch(d0, d1);
        for (name, run) in section_and_both_orders("patch", &s, &plate, tol, tol) {
            let name = format!("{name} d = {d0}..{d1} CHORDTOL {tol}");
            let check = |name: &str, r: &[Polyline3]| {
                check_sloped_within(name, r, (d0, d1), 0.0, MEET, tol);
            };
            list_if_failing(&mut failed, name, run, check);
        }
    }
    let n = failed.len();
    assert!(n == 0, "failing runs ({n}): {failed:?}");
}

#[test]
fn the_branch_points_at_the_users_chordtol_come_back_whole_2e_2() {
    runs_at_the_users_chordtol_pass(2e-2);
}

#[test]
fn the_branch_points_at_the_users_chordtol_come_back_whole_1e_2() {
    runs_at_the_users_chordtol_pass(1e-2);
}

#[test]
fn the_branch_points_at_the_users_chordtol_come_back_whole_5e_3() {
    runs_at_the_users_chordtol_pass(5e-3);
}

#[test]
fn the_branch_points_at_the_users_chordtol_come_back_whole_2e_3() {
    runs_at_the_users_chordtol_pass(2e-3);
}

#[test]
fn the_branch_points_at_the_users_chordtol_come_back_whole_1e_3() {
    runs_at_the_users_chordtol_pass(1e-3);
}
