"""Generate the benchmark icospheres, time lispcad's mesh API against trimesh and manifold3d.

A = icosphere (8 subdivisions, 1,310,720 triangles, radius 1); B = A rotated 0.3 rad about
(1, 2, 3) and moved by (0.5, 0.3, 0.2). Both are written as binary STL and read back by every
side, so loading is measured too.
"""

import argparse
import subprocess
import time

import numpy as np
import trimesh

PLANES = 20
NORMAL = np.array([0.1, 0.2, 1.0])


def planes():
    return [np.array([0.0, 0.0, -0.9 + 1.8 * (i + 0.5) / PLANES]) for i in range(PLANES)]


def generate(out):
    a = trimesh.creation.icosphere(subdivisions=8, radius=1.0)
    axis = np.array([1.0, 2.0, 3.0]) / np.linalg.norm([1.0, 2.0, 3.0])
    m = trimesh.transformations.rotation_matrix(0.3, axis)
    m[:3, 3] = [0.5, 0.3, 0.2]
    b = a.copy()
    b.apply_transform(m)
    a.export(f"{out}/ico_a.stl")
    b.export(f"{out}/ico_b.stl")
    return len(a.faces)


def run_lispcad(exe, out):
    res = subprocess.run([exe, f"{out}/ico_a.stl", f"{out}/ico_b.stl", str(PLANES)],
                         check=True, capture_output=True, text=True).stdout
    vals = {}
    for line in res.splitlines():
        parts = line.split()
        vals[parts[0]] = parts[1:]
    return res, vals


def run_trimesh(out):
    r = {}
    t = time.perf_counter()
    a = trimesh.load(f"{out}/ico_a.stl")
    b = trimesh.load(f"{out}/ico_b.stl")
    r["load_both_s"] = time.perf_counter() - t
    # Warm the caches trimesh builds on first use, as lispcad's numbers are "after load".
    a.section(plane_origin=[0, 0, 0.05], plane_normal=NORMAL)
    t = time.perf_counter()
    pieces = []
    for o in planes():
        s = a.section(plane_origin=o, plane_normal=NORMAL)
        pieces.append(0 if s is None else len(s.discrete))
    r["section_ms"] = (time.perf_counter() - t) / PLANES * 1e3
    s0 = a.section(plane_origin=[0, 0, 0], plane_normal=NORMAL)
    r["section_z0_pieces"] = len(s0.discrete)
    r["section_pieces_range"] = (min(pieces), max(pieces))
    sv = a.section(plane_origin=[0, 0, 0], plane_normal=[0, 0, 1])
    r["section_vertices_pieces"] = len(sv.discrete)
    t = time.perf_counter()
    for o in planes():
        trimesh.intersections.mesh_plane(a, NORMAL, o)
    r["mesh_plane_ms"] = (time.perf_counter() - t) / PLANES * 1e3
    try:
        import manifold3d as m3d

        t = time.perf_counter()
        ma = m3d.Manifold(m3d.Mesh(vert_properties=np.asarray(a.vertices, dtype=np.float32),
                                   tri_verts=np.asarray(a.faces, dtype=np.uint32)))
        mb = m3d.Manifold(m3d.Mesh(vert_properties=np.asarray(b.vertices, dtype=np.float32),
                                   tri_verts=np.asarray(b.faces, dtype=np.uint32)))
        both = ma ^ mb
        mesh = both.to_mesh()
        r["manifold_intersection_s"] = time.perf_counter() - t
        r["manifold_result_tris"] = len(mesh.tri_verts)
    except Exception as e:  # noqa: BLE001 - report, do not hide
        r["manifold_error"] = repr(e)
    return r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--lispcad", required=True)
    args = ap.parse_args()
    n = generate(args.out)
    print(f"icospheres written: {n} triangles each")
    raw, lc = run_lispcad(args.lispcad, args.out)
    print(raw)
    tm = run_trimesh(args.out)
    load_lc = float(lc["load_a_s"][0]) + float(lc["load_b_s"][0])
    rows = [
        ("load both STL (s)", f"{load_lc:.3f}", f"{tm['load_both_s']:.3f}"),
        ("plane section, per plane, no BVH (ms)", lc["section_scan_ms_per_plane"][0], f"{tm['section_ms']:.1f} (section)"),
        ("plane section, per plane, BVH cached (ms)", lc["section_bvh_ms_per_plane"][0], f"{tm['mesh_plane_ms']:.1f} (mesh_plane, segments only)"),
        ("section pieces, oblique plane at z=0", lc["section_z0"][1], str(tm["section_z0_pieces"])),
        ("section pieces, 20 oblique planes (min..max)", "1..1" if lc["section_all_single_closed_loop"][0] == "true" else "not all 1",
         f"{tm['section_pieces_range'][0]}..{tm['section_pieces_range'][1]}"),
        ("section pieces, plane z=0 through vertices", lc["section_vertices"][1], str(tm["section_vertices_pieces"])),
        ("mesh/mesh curve incl. BVH build (s)", lc["intersect_incl_bvh_s"][0],
         f"{tm.get('manifold_intersection_s', float('nan')):.3f} (manifold3d boolean ∩)"),
        ("mesh/mesh curve, BVHs cached (s)", lc["intersect_cached_bvh_s"][0], "-"),
        ("intersection pieces / closed", f"{lc['intersect'][1]} / {lc['intersect'][3]}", "-"),
        ("box pairs / plane-test pairs / true pairs",
         f"{lc['intersect'][7]} / {lc['intersect'][9]} / {lc['intersect'][11]}", "-"),
        ("independent Möller–Trumbore pair count", lc["moller_trumbore_pairs"][0], "-"),
    ]
    w = max(len(r[0]) for r in rows)
    print(f"{'measure':<{w}} | {'lispcad':>22} | trimesh / manifold3d")
    print("-" * (w + 60))
    for name, x, y in rows:
        print(f"{name:<{w}} | {x:>22} | {y}")
    if "manifold_error" in tm:
        print("manifold3d failed:", tm["manifold_error"])


if __name__ == "__main__":
    main()
