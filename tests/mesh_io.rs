//! STL/OBJ import and export, welding, area and boundary.

use lispcad::geom::mesh::{
    icosphere, read_mesh, read_obj, read_stl, write_mesh, write_obj, write_stl_ascii,
    write_stl_binary, Mesh, MeshError,
};
use lispcad::geom::DVec3;

fn square() -> Mesh {
    Mesh::new(
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .unwrap()
}

#[test]
fn binary_stl_round_trip_welds_shared_vertices() {
    let dir = tempfile::tempdir().unwrap();
    let m = icosphere(DVec3::ZERO, 1.0, 2);
    let p = dir.path().join("s.stl");
    write_stl_binary(&m, &p).unwrap();
    let (r, info) = read_stl(&p, 0.0).unwrap();
    assert!(info.binary);
    assert_eq!(info.facets, 320);
    assert_eq!(info.dropped, 0);
    assert_eq!(r.len(), 320);
    assert_eq!(r.vertices().len(), 162);
    assert!((r.area() - m.area()).abs() < 1e-5);
    assert!(r.boundary().is_empty(), "a welded sphere is closed");
}

#[test]
fn ascii_stl_and_obj_round_trip_exactly() {
    let dir = tempfile::tempdir().unwrap();
    let m = icosphere(DVec3::new(0.1, -2.0, 3.3), 1.7, 1);
    let p = dir.path().join("s.stl");
    write_stl_ascii(&m, &p).unwrap();
    let (r, info) = read_stl(&p, 0.0).unwrap();
    assert!(!info.binary);
    assert_eq!(r.vertices().len(), m.vertices().len());
    for t in 0..m.len() {
        assert_eq!(r.corners_of(t), m.corners_of(t));
    }
    let q = dir.path().join("s.OBJ");
    write_mesh(&m, &q).unwrap();
    let o = read_mesh(&q).unwrap();
    assert_eq!(o.vertices(), m.vertices());
    assert_eq!(o.triangles(), m.triangles());
}

#[test]
fn obj_polygons_and_negative_indices() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("q.obj");
    std::fs::write(
        &p,
        "# quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1/1/1 2/2/2 -2 -1\n",
    )
    .unwrap();
    let m = read_obj(&p).unwrap();
    assert_eq!(m.triangles(), &[[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.area(), 1.0);
    write_obj(&m, &p).unwrap();
    assert_eq!(read_obj(&p).unwrap().triangles(), m.triangles());
}

#[test]
fn tolerance_weld_merges_near_vertices() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("t.stl");
    let text = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n\
                facet normal 0 0 1\nouter loop\nvertex 0 0 0.0000001\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
    std::fs::write(&p, text).unwrap();
    assert_eq!(read_stl(&p, 0.0).unwrap().0.vertices().len(), 5);
    let (m, _) = read_stl(&p, 1e-6).unwrap();
    assert_eq!(m.vertices().len(), 4);
    assert_eq!(m.boundary().len(), 1);
    assert_eq!(m.boundary()[0].points.len(), 4);
}

#[test]
fn negative_zero_welds_with_zero() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("z.stl");
    let text = "solid z\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n\
                facet normal 0 0 1\nouter loop\nvertex -0 0 -0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid z\n";
    std::fs::write(&p, text).unwrap();
    assert_eq!(read_stl(&p, 0.0).unwrap().0.vertices().len(), 4);
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("bad.stl");
    std::fs::write(&p, "solid x\nvertex 1 2\n").unwrap();
    assert!(matches!(read_stl(&p, 0.0), Err(MeshError::Parse { .. })));
    std::fs::write(&p, "garbage").unwrap();
    assert!(read_stl(&p, 0.0).is_err());
    assert!(read_stl(&p, -1.0).is_err());
    assert!(matches!(
        read_mesh(dir.path().join("x.ply")),
        Err(MeshError::UnknownFormat { .. })
    ));
    assert!(read_mesh(dir.path().join("missing.stl")).is_err());
    let q = dir.path().join("bad.obj");
    std::fs::write(&q, "v 0 0 0\nf 1 2 3\n").unwrap();
    assert!(read_obj(&q).is_err());
    assert!(Mesh::new(vec![DVec3::ZERO], vec![[0, 0, 1]]).is_err());
    assert!(Mesh::new(vec![DVec3::new(f64::NAN, 0.0, 0.0)], vec![]).is_err());
}

#[test]
fn area_and_boundary_of_a_square() {
    let m = square();
    assert_eq!(m.area(), 1.0);
    let b = m.boundary();
    assert_eq!(b.len(), 1);
    assert!(b[0].closed);
    assert_eq!(b[0].points.len(), 4);
    assert_eq!(b[0].length(), 4.0);
}

#[test]
fn adjacency_links_shared_edges() {
    let m = square();
    let a = m.adjacency();
    // Triangle 0 = (0,1,2): its edge 2 (2→0) is shared with triangle 1.
    assert_eq!(a.neighbours(0)[2], 1);
    assert_eq!(a.neighbours(1)[0], 0);
    assert_eq!(a.boundary_edges().count(), 4);
}

#[test]
fn streamed_and_in_memory_binary_reads_agree() {
    use lispcad::geom::mesh::parse_stl;
    let dir = tempfile::tempdir().unwrap();
    // 20,480 facets: more than one read chunk.
    let m = icosphere(DVec3::new(1.0, 2.0, 3.0), 2.0, 5);
    let p = dir.path().join("big.stl");
    write_stl_binary(&m, &p).unwrap();
    let (a, ia) = read_stl(&p, 0.0).unwrap();
    let (b, ib) = parse_stl(&std::fs::read(&p).unwrap(), 0.0, "big.stl").unwrap();
    assert_eq!(ia, ib);
    assert_eq!(a.vertices(), b.vertices());
    assert_eq!(a.triangles(), b.triangles());
    assert_eq!(a.vertices().len(), m.vertices().len());
    // A truncated binary file is not silently accepted.
    let bytes = std::fs::read(&p).unwrap();
    std::fs::write(&p, &bytes[..bytes.len() - 7]).unwrap();
    assert!(read_stl(&p, 0.0).is_err());
}

#[test]
fn transforms_keep_orientation_and_edges_are_unique() {
    use lispcad::geom::DMat4;
    let m = square();
    assert_eq!(m.edges(), vec![[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]);
    let mirrored = m
        .transformed(&DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0)))
        .unwrap();
    for t in 0..mirrored.len() {
        let [a, b, c] = mirrored.corners_of(t);
        assert!((b - a).cross(c - a).z > 0.0, "mirror keeps the +z facing");
    }
    let moved = m
        .transformed(&DMat4::from_translation(DVec3::new(1.0, 2.0, 3.0)))
        .unwrap();
    assert_eq!(moved.vertices()[2], DVec3::new(2.0, 3.0, 3.0));
    assert_eq!(moved.area(), 1.0);
}
