//! Properties of the pure text functions over arbitrary input: nothing panics, nothing yields
//! NaN, and the formatting functions invert their parsers.

use lispcad::builtins::text::angtos::{angtos, AngleSettings};
use lispcad::builtins::text::parse::{angtof, distof};
use lispcad::builtins::text::rtos::rtos;
use lispcad::builtins::text::vlstring::*;
use lispcad::builtins::text::wcmatch::wcmatch;
use lispcad::lang::escape::{escape_for_prin1, unescape};
use lispcad::lang::real::{format_g, format_real};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn parsers_never_panic_or_yield_nan(s in "\\PC{0,24}", mode in -1i32..7) {
        for m in [None, Some(mode)] {
            if let Some(v) = distof(&s, m) {
                prop_assert!(v.is_finite());
            }
            if let Some(v) = angtof(&s, m, &AngleSettings::default()) {
                prop_assert!((0.0..std::f64::consts::TAU).contains(&v));
            }
        }
        prop_assert!(!atof(&s).is_nan());
        let _ = atoi(&s);
    }

    #[test]
    fn unit_shaped_text_never_panics(s in "[-+ 0-9./'\"dDgGrRNSEW]{0,16}", mode in 0i32..6) {
        if let Some(v) = distof(&s, Some(mode)) {
            prop_assert!(v.is_finite());
        }
        if let Some(v) = angtof(&s, Some(mode), &AngleSettings::default()) {
            prop_assert!(v.is_finite());
        }
    }

    #[test]
    fn string_functions_never_panic(a in "\\PC{0,12}", b in "\\PC{0,12}", i in -3i64..20, j in -3i64..20) {
        let _ = wcmatch(&a, &b);
        let _ = unescape(&a);
        let _ = vl_string_search(&b, &a, i);
        let _ = vl_string_subst("x", &b, &a, i);
        let _ = vl_string_position(u32::from(b.chars().next().unwrap_or('a')), &a, i, j % 2 == 0);
        let _ = vl_string_mismatch(&a, &b, i, j, true);
        let _ = vl_string_elt(&a, i);
        let _ = substr(&a, i, Some(j));
        prop_assert_eq!(strcase(&a, false).chars().count(), a.chars().count());
        prop_assert_eq!(vl_string_translate(&b, &b, &a), a.clone());
    }

    #[test]
    fn prin1_round_trips_through_unescape(s in "\\PC{0,24}|[\\x00-\\x1f\\\\\"]{0,8}") {
        let printed = escape_for_prin1(&s);
        prop_assert_eq!(unescape(&printed[1..printed.len() - 1]).unwrap(), s);
    }

    #[test]
    fn printed_reals_read_back(x in proptest::num::f64::NORMAL | proptest::num::f64::ZERO) {
        let text = format_real(x);
        prop_assert!(text.contains('.'));
        let back: f64 = text.parse().unwrap();
        prop_assert!((back - x).abs() <= x.abs() * 5e-6);
        let full: f64 = format_g(x, 17).parse().unwrap();
        prop_assert_eq!(full, x);
    }

    #[test]
    fn distof_inverts_rtos(
        x in -1.0e6f64..1.0e6, mode in 1i32..=5, prec in 0i32..=8,
        dimzin in 0i32..16, unitmode in 0i32..2,
    ) {
        let text = rtos(x, mode, prec, dimzin, unitmode).unwrap();
        let back = distof(&text, Some(mode));
        prop_assert!(back.is_some(), "distof({:?}) failed", text);
        let step = match mode {
            4 | 5 => 1.0 / f64::from(1u32 << prec),
            1 => 10f64.powi(-prec) * x.abs().max(1.0) * 10.0,
            _ => 10f64.powi(-prec),
        };
        prop_assert!((back.unwrap() - x).abs() <= step / 2.0 + 1e-6, "{} -> {:?} -> {:?}", x, text, back);
    }

    #[test]
    fn angtof_inverts_angtos(
        a in -20.0f64..20.0, mode in 0i32..=4, prec in 0i32..=8,
        angbase in 0.0f64..6.3, angdir in 0i32..2,
    ) {
        let s = AngleSettings { angbase, angdir, dimzin: 0, unitmode: 0 };
        let text = angtos(a, mode, prec, &s).unwrap();
        let back = angtof(&text, Some(mode), &s);
        prop_assert!(back.is_some(), "angtof({:?}) failed", text);
        let diff = (back.unwrap() - a).rem_euclid(std::f64::consts::TAU);
        let diff = diff.min(std::f64::consts::TAU - diff);
        let step = match (mode, prec) {
            (1 | 4, 0) => 1f64.to_radians(),
            (1 | 4, 1 | 2) => (1.0 / 60.0f64).to_radians(),
            (1 | 4, p) => (10f64.powi(4 - p.max(4)) / 3600.0).to_radians(),
            (0, p) => 10f64.powi(-p).to_radians(),
            (2, p) => 10f64.powi(-p) * std::f64::consts::PI / 200.0,
            (_, p) => 10f64.powi(-p),
        };
        prop_assert!(diff <= step / 2.0 + 1e-9, "{} -> {:?} -> {:?}", a, text, back);
    }
}
