//! Evaluator throughput: recursive calls (fib 20), an arithmetic loop with sin/cos, and list
//! building with cons/mapcar/foreach. Programs are compiled once per iteration batch through
//! `eval_source` of a `defun`; the timed part is the call. Runs on the evaluation thread's
//! stack like the CLI. The whole-program comparison with CPython/Lua/Guile is
//! bench/run-lang.sh.

use criterion::Criterion;
use lispcad::lang::eval::with_eval_stack;

const DEFS: &str = r#"
(defun fib (n) (if (< n 2) n (+ (fib (- n 1)) (fib (- n 2)))))
(defun circle-loop (n / i acc r step a x y)
  (setq i 0 acc 0.0 r 2.0 step (/ (* 2 pi) n))
  (while (< i n)
    (setq a (* i step) x (* r (cos a)) y (* r (sin a)) acc (+ acc (* x y)) i (1+ i)))
  acc)
(defun build-map-sum (n / i l m s)
  (setq i 0 l nil)
  (repeat n (setq l (cons i l) i (1+ i)))
  (setq m (mapcar '(lambda (x) (+ (* x 2) 1)) l))
  (setq s 0.0)
  (foreach x m (setq s (+ s x)))
  s)
"#;

fn bench_eval(c: &mut Criterion) {
    let mut it = lispcad::builtins::new_interp();
    it.out = Box::new(std::io::sink());
    it.eval_source("defs", DEFS).expect("definitions load");
    let mut g = c.benchmark_group("lang_eval");
    for (name, call) in [
        ("fib_20", "(fib 20)"),
        ("circle_loop_100k", "(circle-loop 100000)"),
        ("list_build_map_sum_100k", "(build-map-sum 100000)"),
    ] {
        // Compiled once: the benchmark times evaluation, not reading.
        let form = it.eval_source("form", &format!("(quote {call})")).unwrap();
        let code = it.compile_value(&form);
        g.bench_function(name, |b| b.iter(|| it.run_toplevel(&code).unwrap()));
    }
    g.finish();
}

fn main() {
    // Criterion's default `main` runs on the main thread; the evaluator runs on the
    // evaluation thread's stack, as in the CLI.
    with_eval_stack(|| {
        let mut c = Criterion::default().configure_from_args();
        bench_eval(&mut c);
        c.final_summary();
    });
}
