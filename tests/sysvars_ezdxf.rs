//! The system variable table against ezdxf's DXF header-variable table (names, types and
//! defaults of the drawing-stored variables). Needs `<repo>/.venv/bin/python` with ezdxf
//! (`.ci/setup` creates it).

use std::path::PathBuf;
use std::process::Command;

use lispcad::builtins::sysvars::{table, Kind};

/// Header variables that are not system variables (DXF bookkeeping) or that AutoCAD exposes
/// under another type.
const NOT_SYSVARS: &[&str] = &[
    "REQUIREDVERSIONS",
    "ACADMAINTVER",
    "HANDLING",
    "FINGERPRINTGUID",
    "VERSIONGUID",
    "INTERFEREOBJVS",
    "INTERFEREVPVS",
    "CMATERIAL",
    "MENU",
];

/// lispcad's deliberate defaults: (name, ezdxf's default).
const OWN_DEFAULTS: &[&str] = &[
    "INSUNITS",    // millimetres (4), the project's unit; ezdxf says metres
    "OSMODE",      // no running object snap headless
    "LASTSAVEDBY", // "lispcad"
    "AUPREC",      // AutoCAD's own default 0; ezdxf writes 2
    "DIMZIN",      // rtos/angtos keep AutoCAD's imperial template default 0
    "ACADVER",     // AutoCAD's getvar form "24.3s (...)", not the DXF version code
    "CECOLOR",     // a string in getvar ("BYLAYER"), an ACI number in the DXF header
    "CELTYPE",     // "BYLAYER", as getvar returns it
    "INTERFERECOLOR",
];

#[test]
fn header_variables_match_ezdxf() {
    let py = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(".venv/bin/python");
    assert!(py.exists(), "{} missing: run .ci/setup", py.display());
    let script = "import ezdxf.sections.headervars as h\n\
                  for k, v in h.HEADER_VAR_MAP.items():\n\
                  \x20   d = v.default\n\
                  \x20   d = ' '.join(repr(float(x)) for x in d) if isinstance(d, tuple) else d\n\
                  \x20   print(k[1:], v.code, d, sep='\\t')\n";
    let out = Command::new(py).arg("-c").arg(script).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut checked = 0;
    for line in text.lines() {
        let cols: Vec<&str> = line.split('\t').collect();
        let (name, code, default) = (cols[0], cols[1].parse::<i32>().unwrap(), cols[2]);
        if NOT_SYSVARS.contains(&name) {
            continue;
        }
        let def = table()
            .get(name)
            .unwrap_or_else(|| panic!("header variable {name} missing from the table"));
        assert!(def.in_header, "{name} not marked as a header variable");
        if OWN_DEFAULTS.contains(&name) {
            continue;
        }
        let want = match code {
            10 if default.split(' ').count() == 2 => Kind::Pt2,
            10 => Kind::Pt3,
            40 | 50 => Kind::Real,
            1..=9 => Kind::Str,
            _ => Kind::Int,
        };
        assert_eq!(def.kind, want, "{name}: group code {code}");
        match want {
            Kind::Real | Kind::Pt2 | Kind::Pt3 => {
                let a: Vec<f64> = def.default.split(' ').map(|x| x.parse().unwrap()).collect();
                let b: Vec<f64> = default.split(' ').map(|x| x.parse().unwrap()).collect();
                assert_eq!(a, b, "{name} default");
            }
            _ => assert_eq!(def.default, default, "{name} default"),
        }
        checked += 1;
    }
    assert!(checked > 230, "only {checked} variables compared");
    // The session variables beyond the header make the whole table several hundred names.
    assert!(table().len() > 400);
    for name in [
        "CMDECHO",
        "FILEDIA",
        "USERS1",
        "MILLISECS",
        "DWGPREFIX",
        "UNDOCTL",
    ] {
        assert!(table().contains_key(name), "{name}");
    }
}
