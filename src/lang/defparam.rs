//! `(defparam NAME default "doc" [min max])`: a declared script parameter. NAME is not
//! evaluated; a value it already has (from `--set` or a batch table) wins over the default;
//! a numeric value outside [min, max] is an error naming the parameter and the range.
//! `lispcad params` finds these forms without running the script (cli/params.rs), and the
//! command line checks `--set` and table values against the range before anything runs.

use super::compile::{Code, Compiler, Operand};
use super::error::{err, Span};
use super::value::Value;

pub(super) fn compile(c: &mut Compiler, rest: &Value, span: Option<Span>) -> Code {
    let items: Vec<Value> = rest.iter().cloned().collect();
    let with_span = move |e: super::Exn| match span {
        Some(s) => e.with_span(s),
        None => e,
    };
    if !(3..=5).contains(&items.len()) || items.len() == 4 {
        let e = with_span(err(
            "defparam: expected (defparam NAME default \"doc\" [min max])",
        ));
        return Code::new(move |_| Err(e.clone()));
    }
    let Some(sym) = items[0].as_sym() else {
        let e = with_span(err("defparam: NAME must be a symbol"));
        return Code::new(move |_| Err(e.clone()));
    };
    let name = c.sym_name(sym).to_string();
    let default = c.operand(&items[1]);
    let range: Option<(Operand, Operand)> = if items.len() == 5 {
        Some((c.operand(&items[3]), c.operand(&items[4])))
    } else {
        None
    };
    let i = sym.idx();
    Code::new(move |it| {
        if matches!(it.values[i], Value::Nil) {
            let v = default.eval(it)?;
            std::mem::replace(&mut it.values[i], v).release();
        }
        if let Some((lo, hi)) = &range {
            let (lo, hi) = (lo.eval(it)?, hi.eval(it)?);
            let (Some(lo), Some(hi)) = (lo.as_f64(), hi.as_f64()) else {
                return Err(with_span(err(format!(
                    "defparam {name}: the range must be two numbers"
                ))));
            };
            let v = it.values[i].clone();
            match v.as_f64() {
                Some(x) if (lo..=hi).contains(&x) => {}
                _ => {
                    let shown = it.prin1_string(&v);
                    return Err(with_span(err(format!(
                        "parameter {name} = {shown} is outside its range [{lo}, {hi}]"
                    ))));
                }
            }
        }
        Ok(Value::Sym(sym))
    })
}
