//! R12 records made fit for an R2000+ document: the subclass markers (100 groups) that
//! AutoCAD and ezdxf expect, placed as ezdxf writes them. R12 has only the entity types
//! listed here; a record of any other type, or one that already has markers, is kept.

use super::record::TagList;

/// The groups of AcDbEntity (those an R12 record can have, and a few more).
const ENTITY: [i32; 13] = [8, 6, 62, 67, 48, 60, 370, 420, 430, 440, 284, 347, 390];
const TEXT_BODY: [i32; 12] = [39, 10, 40, 1, 50, 41, 51, 7, 71, 72, 11, 210];
const DIM_BODY: [i32; 19] = [
    280, 2, 3, 10, 11, 12, 70, 71, 72, 41, 42, 73, 74, 75, 1, 52, 53, 51, 210,
];

/// A subclass marker and the group codes it holds.
type Subclass = (&'static str, &'static [i32]);

/// The subclasses after AcDbEntity of an R12 record: (marker, the codes it holds); a code no
/// subclass names goes to the one at the returned index.
fn subclasses(t: &TagList) -> Option<(Vec<Subclass>, usize)> {
    let flags = || {
        t.get(70)
            .and_then(|v| v.trim().parse::<i64>().ok())
            .unwrap_or(0)
    };
    let one = |m: &'static str| Some((vec![(m, &[][..])], 0));
    match t.type_name() {
        "LINE" => one("AcDbLine"),
        "POINT" => one("AcDbPoint"),
        "CIRCLE" => one("AcDbCircle"),
        "ARC" => Some((vec![("AcDbCircle", &[][..]), ("AcDbArc", &[50, 51][..])], 0)),
        "TRACE" | "SOLID" => one("AcDbTrace"),
        "3DFACE" => one("AcDbFace"),
        "SHAPE" => one("AcDbShape"),
        "INSERT" => one("AcDbBlockReference"),
        "VIEWPORT" => one("AcDbViewport"),
        "BLOCK" => one("AcDbBlockBegin"),
        "ENDBLK" => one("AcDbBlockEnd"),
        "SEQEND" => Some((Vec::new(), 0)),
        "TEXT" => Some((vec![("AcDbText", &[][..]), ("AcDbText", &[73][..])], 0)),
        "ATTRIB" => Some((
            vec![("AcDbText", &TEXT_BODY[..]), ("AcDbAttribute", &[][..])],
            1,
        )),
        "ATTDEF" => Some((
            vec![
                ("AcDbText", &TEXT_BODY[..]),
                ("AcDbAttributeDefinition", &[][..]),
            ],
            1,
        )),
        "POLYLINE" => one(match flags() {
            f if f & 8 != 0 => "AcDb3dPolyline",
            f if f & 16 != 0 => "AcDbPolygonMesh",
            f if f & 64 != 0 => "AcDbPolyFaceMesh",
            _ => "AcDb2dPolyline",
        }),
        "VERTEX" => {
            let f = flags();
            if f & 128 != 0 && f & 64 == 0 {
                return one("AcDbFaceRecord");
            }
            let kind = match f {
                f if f & 32 != 0 => "AcDb3dPolylineVertex",
                f if f & 128 != 0 => "AcDbPolyFaceMeshVertex",
                f if f & 64 != 0 => "AcDbPolygonMeshVertex",
                _ => "AcDb2dVertex",
            };
            Some((vec![("AcDbVertex", &[][..]), (kind, &[][..])], 1))
        }
        "DIMENSION" => {
            let sub: &[Subclass] = match flags() & 0x0F {
                0 => &[
                    ("AcDbAlignedDimension", &[]),
                    ("AcDbRotatedDimension", &[-1]),
                ],
                1 => &[("AcDbAlignedDimension", &[])],
                2 => &[("AcDb2LineAngularDimension", &[])],
                3 => &[("AcDbDiametricDimension", &[])],
                4 => &[("AcDbRadialDimension", &[])],
                5 => &[("AcDb3PointAngularDimension", &[])],
                _ => &[("AcDbOrdinateDimension", &[])],
            };
            let mut v = vec![("AcDbDimension", &DIM_BODY[..])];
            v.extend_from_slice(sub);
            Some((v, 1))
        }
        _ => None,
    }
}

/// Each record of `t` (an entity and its followers, or a BLOCK/ENDBLK) with the subclass
/// markers of R2000: AcDbEntity after the handle, owner and application data, then its
/// type's subclasses; extended data stays last.
pub fn with_subclass_markers(t: &TagList) -> TagList {
    let mut out = TagList::new();
    for r in super::dxfin::factory::record_ranges(t) {
        let mut rec = TagList::new();
        for i in r {
            let (c, v) = t.at(i);
            rec.push(c, v);
        }
        match subclasses(&rec).filter(|_| rec.get(100).is_none()) {
            Some((subs, default)) => upgrade_record(&mut out, &rec, &subs, default),
            None => {
                for (c, v) in rec.iter() {
                    out.push(c, v);
                }
            }
        }
    }
    out
}

fn upgrade_record(out: &mut TagList, rec: &TagList, subs: &[Subclass], default: usize) {
    let mut head = 1;
    let mut in_app = false;
    // The type, handle, application data and owner stay in front.
    for (i, (c, _)) in rec.iter().enumerate().skip(1) {
        if c == 102 {
            in_app = !in_app;
        } else if !(in_app || c == 5 || c == 330) {
            break;
        }
        head = i + 1;
    }
    let xdata = (0..rec.len())
        .find(|&i| rec.at(i).0 >= 1000)
        .unwrap_or(rec.len());
    for i in 0..head {
        let (c, v) = rec.at(i);
        out.push(c, v);
    }
    let body: Vec<(i32, &str)> = (head..xdata).map(|i| rec.at(i)).collect();
    out.push(100, "AcDbEntity");
    for (c, v) in body.iter().filter(|(c, _)| ENTITY.contains(c)) {
        out.push(*c, v);
    }
    let home = |c: i32| {
        // A point's y and z go where its x goes.
        let c = match c {
            20..=28 => c - 10,
            30..=37 => c - 20,
            220 | 230 => 210,
            _ => c,
        };
        subs.iter()
            .position(|(_, codes)| codes.contains(&c))
            .unwrap_or(default)
    };
    for (k, (marker, _)) in subs.iter().enumerate() {
        out.push(100, marker);
        for (c, v) in body.iter().filter(|(c, _)| !ENTITY.contains(c)) {
            if home(*c) == k {
                out.push(*c, v);
            }
        }
    }
    for i in xdata..rec.len() {
        let (c, v) = rec.at(i);
        out.push(c, v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tags(groups: &[(i32, &str)]) -> TagList {
        TagList::of(groups)
    }

    #[test]
    fn attrib_and_seqend_get_their_markers() {
        let t = tags(&[
            (0, "INSERT"),
            (5, "20"),
            (8, "A"),
            (66, "1"),
            (2, "B"),
            (10, "0"),
            (0, "ATTRIB"),
            (5, "21"),
            (8, "A"),
            (10, "1"),
            (40, "2"),
            (1, "x"),
            (2, "TAG"),
            (70, "0"),
            (0, "SEQEND"),
            (5, "22"),
            (8, "A"),
        ]);
        let want = tags(&[
            (0, "INSERT"),
            (5, "20"),
            (100, "AcDbEntity"),
            (8, "A"),
            (100, "AcDbBlockReference"),
            (66, "1"),
            (2, "B"),
            (10, "0"),
            (0, "ATTRIB"),
            (5, "21"),
            (100, "AcDbEntity"),
            (8, "A"),
            (100, "AcDbText"),
            (10, "1"),
            (40, "2"),
            (1, "x"),
            (100, "AcDbAttribute"),
            (2, "TAG"),
            (70, "0"),
            (0, "SEQEND"),
            (5, "22"),
            (100, "AcDbEntity"),
            (8, "A"),
        ]);
        assert_eq!(with_subclass_markers(&t), want);
    }
}
