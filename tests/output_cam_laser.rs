//! The CAM profile a laser accepts as is (issue 15 item 3), on the bundled temple: no segment
//! shorter than --cam-min-seg, still within --cam-tol of the true outline both ways (against
//! the CAD file's CUT spline flattened by ezdxf), the outline closed, counter-clockwise, started
//! where the tangent is continuous; holes cut before the outline, clockwise; text kept on its
//! own layer; a warning for what is left out.

#[path = "cli_support/mod.rs"]
mod cli;
#[path = "output_support/mod.rs"]
mod support;

use std::process::Command;

const CHECK: &str = r#"
import sys, math, ezdxf, numpy as np
from ezdxf import path as ep
cad, cam, tol, min_seg = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
# The CAD outline: a closed chain, in order, of LINEs and SPLINEs (split at the hinge corners
# and its straight end runs, which LibreCAD otherwise rounds off or leaves out).
pieces = []
for e in ezdxf.readfile(cad).modelspace():
    if e.dxf.layer != 'CUT':
        continue
    if e.dxftype() == 'LINE':
        pieces.append(np.array([(e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y)]))
    else:
        assert e.dxftype() == 'SPLINE', e.dxftype()
        pieces.append(np.array([(p.x, p.y) for p in e.flattening(0.0002)]))
assert len(pieces) > 1 and any(len(p) > 2 for p in pieces), len(pieces)
for a, b in zip(pieces, pieces[1:] + pieces[:1]):
    assert np.abs(a[-1] - b[0]).max() < 1e-9, 'CAD CUT chain not closed in order'
true_pts = np.concatenate(pieces)
doc = ezdxf.readfile(cam)
auditor = doc.audit()
assert not auditor.has_errors and not auditor.has_fixes, 'audit'
msp = doc.modelspace()
polys = [e for e in msp.query('POLYLINE') if e.dxf.layer == 'CUT']
assert len(polys) == 1, len(polys)
pl = polys[0]
assert pl.is_closed, 'CAM outline not closed'
v = [(x.dxf.location.x, x.dxf.location.y, x.dxf.bulge) for x in pl.vertices]
n = len(v)
segs = [math.dist(v[i][:2], v[(i + 1) % n][:2]) for i in range(n)]
cam_pts = np.array([(p.x, p.y) for p in ep.make_path(pl).flattening(0.0002)])
def dist_to_polyline(pts, poly):
    a, b = poly[:-1], poly[1:]
    d = b - a
    l2 = np.maximum((d * d).sum(1), 1e-300)
    best = np.full(len(pts), np.inf)
    for k in range(0, len(pts), 256):
        p = pts[k:k + 256, None, :]
        t = np.clip(((p - a) * d).sum(2) / l2, 0, 1)
        q = a + t[..., None] * d
        best[k:k + 256] = np.sqrt(((p - q) ** 2).sum(2)).min(1)
    return best
fwd = dist_to_polyline(cam_pts, true_pts).max()
back = dist_to_polyline(true_pts, cam_pts).max()
area = sum(v[i][0] * v[(i + 1) % n][1] - v[(i + 1) % n][0] * v[i][1] for i in range(n)) / 2
def tangents(i):
    (x0, y0, b), (x1, y1, _) = v[i], v[(i + 1) % n]
    c = math.atan2(y1 - y0, x1 - x0)
    h = 2 * math.atan(b)
    return c - h, c + h
turn = tangents(0)[0] - tangents(n - 1)[1]
turn = abs((turn + math.pi) % (2 * math.pi) - math.pi)
texts = [e.dxf.layer for e in msp.query('TEXT')]
print(min(segs), fwd, back, area, math.degrees(turn), len(texts), ','.join(sorted(set(texts))))
"#;

#[test]
fn the_temple_cam_file_is_laser_ready() {
    let dir = tempfile::tempdir().unwrap();
    let script = support::manifest().join("scripts/temple.lsp");
    let s = script.to_str().unwrap();
    let o = cli::lispcad_in(dir.path(), &["run", s, "-o", "cad.dxf"]);
    assert!(o.status.success());
    for (tol, min_seg) in [("0.01", "0.05"), ("0.002", "0.1")] {
        let o = cli::lispcad_in(
            dir.path(),
            &[
                "run",
                s,
                "--dxf-profile",
                "cam",
                "--cam-tol",
                tol,
                "--cam-min-seg",
                min_seg,
                "-o",
                "cam.dxf",
            ],
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let out = Command::new(support::python())
            .args(["-c", CHECK])
            .arg(dir.path().join("cad.dxf"))
            .arg(dir.path().join("cam.dxf"))
            .args([tol, min_seg])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout).unwrap();
        let f: Vec<&str> = text.split_whitespace().collect();
        let num = |i: usize| f[i].parse::<f64>().unwrap();
        let (tol, min_seg): (f64, f64) = (tol.parse().unwrap(), min_seg.parse().unwrap());
        assert!(num(0) >= min_seg, "shortest segment {} < {min_seg}", num(0));
        // Both ways within the tolerance (plus the flattening's own 0.0002 each side).
        assert!(
            num(1) <= tol + 5e-4,
            "CAM strays {} from the outline",
            num(1)
        );
        assert!(
            num(2) <= tol + 5e-4,
            "the outline strays {} from CAM",
            num(2)
        );
        assert!(num(3) > 0.0, "outer contour must run counter-clockwise");
        assert!(num(4) < 2.0, "starts at a {}° corner", num(4));
        assert_eq!(f[5], "3", "the three notes");
        assert_eq!(f[6], "NOTES", "text on its own layer");
    }
}

#[test]
fn holes_first_clockwise_and_a_warning_for_what_is_left_out() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("p.lsp"),
        "(layer \"CUT\" 1)\n\
         (draw (pline '((0 0) (50 0) (50 30) (0 30)) T))\n\
         (draw (pline '((10 10) (10 20) (20 20) (20 10)) T))\n\
         (entmake '((0 . \"POINT\") (10 5.0 5.0 0.0)))\n\
         (entmake '((0 . \"TEXT\") (8 . \"CUT\") (10 1.0 1.0 0.0) (40 . 2.0) (1 . \"A1\")))\n",
    )
    .unwrap();
    let o = cli::lispcad_in(
        dir.path(),
        &["run", "p.lsp", "--dxf-profile", "cam", "-o", "p.dxf"],
    );
    assert!(o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("1 POINT left out"), "{err}");
    let code = "import ezdxf,sys\nm=ezdxf.readfile(sys.argv[1]).modelspace()\n\
        for e in m:\n    if e.dxftype()=='POLYLINE':\n        v=[x.dxf.location for x in e.vertices]\n        \
        a=sum(v[i].x*v[(i+1)%len(v)].y-v[(i+1)%len(v)].x*v[i].y for i in range(len(v)))/2\n        \
        print('P', round(a, 6))\n    else:\n        print(e.dxftype(), e.dxf.layer)";
    let out = Command::new(support::python())
        .args(["-c", code])
        .arg(dir.path().join("p.dxf"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines, ["P -100.0", "P 1500.0", "TEXT CUT_TEXT"], "{text}");
}
