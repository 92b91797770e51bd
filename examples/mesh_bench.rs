//! Times lispcad's mesh operations on two STL files (see bench/surface/run.sh).
//!
//! Usage: mesh_bench A.stl B.stl [planes]
//! Prints one `name seconds` line per measurement, then the result summaries.

use lispcad::geom::mesh::{intersect_meshes_with_stats, read_stl, section, Mesh};
use lispcad::geom::DVec3;
use std::time::Instant;

#[path = "../tests/mesh_support/mod.rs"]
mod mesh_support;
use mesh_support::triangles_cross;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() < 3 {
        eprintln!("usage: mesh_bench A.stl B.stl [planes]");
        std::process::exit(2);
    }
    let planes: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(20);
    let t = Instant::now();
    let cpu = cpu_seconds();
    let (a, ra) = read_stl(&args[1], 0.0).expect("read A");
    let load_a = t.elapsed().as_secs_f64();
    let load_a_cpu = cpu_seconds() - cpu;
    let t = Instant::now();
    let (b, _) = read_stl(&args[2], 0.0).expect("read B");
    let load_b = t.elapsed().as_secs_f64();
    println!("load_a_s {load_a:.4} cpu {load_a_cpu:.2}");
    println!("load_b_s {load_b:.4}");
    println!(
        "triangles {} vertices {} dropped {}",
        a.len(),
        a.vertices().len(),
        ra.dropped
    );

    // Plane sections through the centre region, first without then with a built BVH.
    let sec = |m: &Mesh| {
        let mut pieces = Vec::new();
        let t = Instant::now();
        for i in 0..planes {
            let z = -0.9 + 1.8 * (i as f64 + 0.5) / planes as f64;
            let r =
                section(m, DVec3::new(0.0, 0.0, z), DVec3::new(0.1, 0.2, 1.0)).expect("section");
            pieces.push((r.len(), r.iter().filter(|p| p.closed).count()));
        }
        (t.elapsed().as_secs_f64() / planes as f64, pieces)
    };
    let (per_plane_scan, pieces) = sec(&a);
    println!("section_scan_ms_per_plane {:.3}", per_plane_scan * 1e3);
    let r0 = section(&a, DVec3::ZERO, DVec3::new(0.1, 0.2, 1.0)).unwrap();
    println!(
        "section_z0 pieces {} closed {} points {}",
        r0.len(),
        r0.iter().filter(|p| p.closed).count(),
        r0.iter().map(|p| p.points.len()).sum::<usize>()
    );
    // A plane through mesh vertices and along edges (the icosahedron has vertices on z = 0).
    let rv = section(&a, DVec3::ZERO, DVec3::Z).unwrap();
    println!(
        "section_vertices pieces {} closed {} on_plane_vertices {}",
        rv.len(),
        rv.iter().filter(|p| p.closed).count(),
        a.vertices().iter().filter(|v| v.z == 0.0).count()
    );
    println!(
        "section_all_single_closed_loop {}",
        pieces.iter().all(|&(n, c)| n == 1 && c == 1)
    );

    let c = a.clone();
    let t = Instant::now();
    let cpu = cpu_seconds();
    c.bvh();
    println!(
        "bvh_build_one_s {:.4} cpu {:.2}",
        t.elapsed().as_secs_f64(),
        cpu_seconds() - cpu
    );
    drop(c);
    let t = Instant::now();
    c2_adj(&a);
    println!("adjacency_build_s {:.4}", t.elapsed().as_secs_f64());

    let t = Instant::now();
    let cpu = cpu_seconds();
    let (curves, stats) = intersect_meshes_with_stats(&a, &b);
    let inter = t.elapsed().as_secs_f64();
    println!(
        "intersect_incl_bvh_s {inter:.4} cpu {:.2}",
        cpu_seconds() - cpu
    );
    println!(
        "intersect pieces {} closed {} points {} box_pairs {} plane_pairs {} intersecting_pairs {} irregular {}",
        curves.len(),
        curves.iter().filter(|p| p.closed).count(),
        curves.iter().map(|p| p.points.len()).sum::<usize>(),
        stats.box_pairs,
        stats.plane_pairs,
        stats.intersecting_pairs,
        stats.irregular_pairs
    );
    // Independent check of the exact pair count: a plain-f64 Möller–Trumbore edge/triangle
    // test over every box-overlapping pair (boxes are conservative, so no true pair is missed).
    let truth = a
        .bvh()
        .overlapping_pairs(b.bvh())
        .iter()
        .filter(|&&(ta, tb)| {
            let pa = a.corners_of(ta as usize);
            let pb = b.corners_of(tb as usize);
            triangles_cross(pa, pb)
        })
        .count();
    println!("moller_trumbore_pairs {truth}");
    let (per_plane_bvh, _) = sec(&a);
    println!("section_bvh_ms_per_plane {:.3}", per_plane_bvh * 1e3);
    let t = Instant::now();
    let (curves2, _) = intersect_meshes_with_stats(&a, &b);
    println!("intersect_cached_bvh_s {:.4}", t.elapsed().as_secs_f64());
    println!("intersect_repeat_same {}", curves2 == curves);
}

fn c2_adj(m: &Mesh) {
    let c = m.clone();
    let _ = c.adjacency();
}

/// This process's user + system CPU time (Linux /proc; 0 elsewhere), to see through the load
/// of a shared machine.
fn cpu_seconds() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return 0.0;
    };
    let after = stat.rsplit(')').next().unwrap_or("");
    let f: Vec<&str> = after.split_whitespace().collect();
    let ticks = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok()).unwrap_or(0.0);
    // Fields 14 and 15 of stat (utime, stime) are at 11 and 12 after the command name.
    (ticks(11) + ticks(12)) / 100.0
}
