//! Per-entity line type, line weight, thickness and line-type scale (CHPROP's LType,
//! LWeight, Thickness and LTscale), which the entity model does not carry. A drawing keeps
//! them by handle; an entity read from a file also gets them in the groups it is written
//! back from, and a new entity's groups get them when written (`with_props`). AcDbEntity
//! holds 6, 370 and 48 (after the layer); thickness (39) belongs to the entity's own
//! subclass (after its first marker past AcDbEntity), for the kinds that have one.

use std::collections::HashMap;

use super::drawing::{Drawing, EntityKind};
use super::dxf_writer::push_float;
use super::record::TagList;

/// What CHPROP set on an entity (None: as the entity had it, BYLAYER / 0 / 1 by default).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EntityProps {
    pub linetype: Option<String>,
    /// DXF 370: hundredths of a millimetre, or -1 BYLAYER, -2 BYBLOCK, -3 DEFAULT.
    pub lineweight: Option<i16>,
    pub thickness: Option<f64>,
    pub ltscale: Option<f64>,
}

/// The store (`Extras::props`).
pub type PropsMap = HashMap<u64, EntityProps>;

/// Whether an entity kind has a thickness (39) group.
pub fn has_thickness(kind: &EntityKind) -> bool {
    match kind {
        EntityKind::Line { .. }
        | EntityKind::Circle { .. }
        | EntityKind::Arc { .. }
        | EntityKind::Point { .. }
        | EntityKind::Text { .. }
        | EntityKind::LwPolyline { .. } => true,
        EntityKind::Polyline { points, .. } => super::drawing::is_flat(points),
        _ => false,
    }
}

fn real(x: f64) -> String {
    let mut s = String::new();
    push_float(&mut s, x);
    s
}

/// The groups (code, value) `p` puts after the layer, and the thickness.
fn groups(p: &EntityProps) -> (Vec<(i32, String)>, Option<String>) {
    let mut head = Vec::new();
    if let Some(lt) = &p.linetype {
        head.push((6, lt.clone()));
    }
    if let Some(s) = p.ltscale {
        head.push((48, real(s)));
    }
    if let Some(w) = p.lineweight {
        head.push((370, w.to_string()));
    }
    (head, p.thickness.map(real))
}

/// Whether a written property group holds what its absence means.
fn is_default(code: i32, v: &str) -> bool {
    match code {
        6 => v.eq_ignore_ascii_case("ByLayer"),
        48 => v.trim().parse::<f64>() == Ok(1.0),
        370 => v.trim() == "-1",
        39 => v.trim().parse::<f64>() == Ok(0.0),
        _ => false,
    }
}

/// The record's groups with `p` set in its first record (existing groups replaced).
pub fn patch_tags(t: &TagList, p: &EntityProps, thickness_ok: bool) -> TagList {
    let (head, thick) = groups(p);
    let first = t.first_record_end();
    // A property at its default is written only over a group the record had: adding
    // (370 . -1) or (48 . 1.0) would put groups an R12 file cannot hold into one that never
    // asked for them.
    let had = |code: i32| t.iter().take(first).any(|(c, _)| c == code);
    let head: Vec<(i32, String)> = head
        .into_iter()
        .filter(|(c, v)| had(*c) || !is_default(*c, v))
        .collect();
    let thick = thick
        .filter(|_| thickness_ok)
        .filter(|v| had(39) || !is_default(39, v));
    let replaced = |c: i32| head.iter().any(|(h, _)| *h == c) || (c == 39 && thick.is_some());
    let mut out = TagList::new();
    let mut markers = 0;
    let mut in_app = false;
    for (i, (c, v)) in t.iter().enumerate() {
        if i < first {
            if c == 102 {
                in_app = v.starts_with('{');
            }
            if !in_app && replaced(c) {
                continue;
            }
        }
        out.push(c, v);
        if i >= first || in_app {
            continue;
        }
        if c == 8 {
            for (hc, hv) in &head {
                out.push(*hc, hv);
            }
        }
        if c == 100 {
            markers += 1;
            if markers == 2 {
                if let Some(th) = &thick {
                    out.push(39, th);
                }
            }
        }
    }
    out
}

/// An entity's groups as written (`text`, with any followers) with `p` set; values are
/// kept as they are written (no escapes decoded).
pub fn patch_text(text: &str, p: &EntityProps, thickness_ok: bool) -> String {
    let mut t = TagList::new();
    let mut lines = text.lines();
    while let (Some(c), Some(v)) = (lines.next(), lines.next()) {
        if let Ok(c) = c.trim().parse::<i32>() {
            t.push(c, v);
        }
    }
    let mut out = String::with_capacity(text.len() + 64);
    patch_tags(&t, p, thickness_ok).write_to(&mut out);
    out
}

impl Drawing {
    /// The line type, weight, thickness and scale CHPROP set on an entity.
    pub fn props(&self, handle: u64) -> Option<&EntityProps> {
        self.extras.props.get(&handle)
    }

    /// Set an entity's properties (and in the groups it was read from, if it was).
    pub fn set_props(&mut self, handle: u64, p: EntityProps) {
        let ok = self.get(handle).is_some_and(|e| has_thickness(&e.kind));
        if let Some(s) = self.source_mut(handle) {
            s.tags = patch_tags(&s.tags, &p, ok);
        }
        self.extras.props.insert(handle, p);
    }

    /// Give entity `to` (a copy, or a piece of `from`) the properties of `from`.
    pub fn copy_props(&mut self, from: u64, to: u64) {
        if let Some(p) = self.props(from).cloned() {
            self.set_props(to, p);
        }
    }

    /// A new entity's groups as written, with the properties CHPROP set on it.
    pub fn with_props(&self, handle: u64, kind: &EntityKind, text: String) -> String {
        match self.props(handle) {
            Some(p) if self.source(handle).is_none() => patch_text(&text, p, has_thickness(kind)),
            _ => text,
        }
    }

    /// The line types entities name (besides BYLAYER, BYBLOCK, CONTINUOUS).
    pub fn entity_linetypes(&self) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for (h, p) in &self.extras.props {
            let Some(lt) = &p.linetype else { continue };
            let builtin = ["BYBLOCK", "BYLAYER", "CONTINUOUS"]
                .iter()
                .any(|b| lt.eq_ignore_ascii_case(b));
            if !builtin && self.get(*h).is_some() && !out.iter().any(|x| x.eq_ignore_ascii_case(lt))
            {
                out.push(lt.clone());
            }
        }
        out.sort();
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_go_after_the_layer_and_into_the_subclass() {
        let t = TagList::from_dxf_text(
            "  0\nLINE\n  5\n100\n330\nF\n100\nAcDbEntity\n  8\n0\n100\nAcDbLine\n 10\n0\n",
        );
        let p = EntityProps {
            linetype: Some("DASHED".into()),
            lineweight: Some(50),
            thickness: Some(2.5),
            ltscale: Some(0.5),
        };
        let u = patch_tags(&t, &p, true);
        let g: Vec<(i32, &str)> = u.iter().collect();
        assert_eq!(
            g,
            vec![
                (0, "LINE"),
                (5, "100"),
                (330, "F"),
                (100, "AcDbEntity"),
                (8, "0"),
                (6, "DASHED"),
                (48, "0.5"),
                (370, "50"),
                (100, "AcDbLine"),
                (39, "2.5"),
                (10, "0"),
            ]
        );
        // Patching again replaces rather than repeats.
        assert_eq!(patch_tags(&u, &p, true), u);
    }
}
