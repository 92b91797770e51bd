;; The fast call path: parameters of calls with up to four arguments keep their outer values in
;; the evaluator's own frame, and `(if (< a b) ...)` is one fused step. Each case checks a way
;; out of those paths: redefinition mid-run, non-numbers, errors, repeated names.
;;
;; A parameter's outer value comes back after the call, for every fixed arity.
(setq a 'A0 b 'B0 c 'C0 d 'D0 e 'E0)
(defun p1 (a) (list a b))
(defun p2 (a b) (list a b c))
(defun p3 (a b c) (list a b c d))
(defun p4 (a b c d) (list a b c d e))
(defun p5 (a b c d e) (list a b c d e))
(list (p1 1) (p2 1 2) (p3 1 2 3) (p4 1 2 3 4) (p5 1 2 3 4 5) a b c d e)
;=> ((1 B0) (1 2 C0) (1 2 3 D0) (1 2 3 4 E0) (1 2 3 4 5) A0 B0 C0 D0 E0)
;; Parameters and locals together: locals start nil and everything is restored.
(defun pl (a b / c d) (setq c (list a b c d) d 'set) (list c d))
(pl 1 2)
;=> ((1 2 nil nil) SET)
(list a b c d)
;=> (A0 B0 C0 D0)
;; A callee sees its caller's parameters (dynamic scope), and nested calls restore in order.
(defun inner-sees () (list a b))
(defun outer-binds (a b) (list (inner-sees) (p1 'x) (inner-sees)))
(outer-binds 1 2)
;=> ((1 2) (X 2) (1 2))
(list a b)
;=> (A0 B0)
;; A parameter named like the function itself.
(defun selfname (selfname) (list selfname))
(selfname 7)
;=> (7)
(selfname 8)
;=> (8)
;; Wrong argument counts on the fixed path.
(p2 1)
;!! too few arguments
(p2 1 2 3)
;!! too many arguments
(list a b)
;=> (A0 B0)
;; A function that redefines itself while it runs finishes its own body.
(defun morph (n) (defun morph (n) (list 'new n)) (list 'old n (morph n)))
(morph 1)
;=> (OLD 1 (NEW 1))
(morph 2)
;=> (NEW 2)
;; An error inside the body: *error* sees the parameters still bound, then they are restored.
(setq seen nil)
(defun *error* (msg) (setq seen (list msg a b)))
(defun boom (a b) (/ a b))
(boom 1 0)
;!! divide by zero
seen
;=> ("divide by zero" 1 0)
(list a b)
;=> (A0 B0)
;; The innermost function's *error* runs once, with the deepest bindings in place.
(defun dive (a) (if (< a 3) (dive (1+ a)) (car a)))
(setq seen nil)
(dive 0)
;!! bad argument type: consp 3
seen
;=> ("bad argument type: consp 3" 3 B0)
a
;=> A0
(setq *error* nil)
;; vl-catch-all-apply around a failing fixed-arity call restores the parameters.
(vl-catch-all-error-p (vl-catch-all-apply 'boom '(5 0)))
;=> T
(list a b)
;=> (A0 B0)
;; `(if (< x y) ...)` on strings goes to the builtin (string order), as does a mixed pair.
(defun order (x y) (if (< x y) 'less 'not-less))
(list (order "abc" "abd") (order "b" "a") (order 1 2.5) (order 2.5 1) (order 3 3))
;=> (LESS NOT-LESS LESS NOT-LESS NOT-LESS)
(order 'x 1)
;!! bad argument type: numberp: X
;; All six comparisons fused into `if`, integer and real.
(defun cmps (x y)
  (list (if (< x y) 1 0) (if (> x y) 1 0) (if (<= x y) 1 0)
        (if (>= x y) 1 0) (if (= x y) 1 0) (if (/= x y) 1 0)))
(list (cmps 1 2) (cmps 2 2) (cmps 2.5 2) (cmps 2 2.0))
;=> ((1 0 1 0 0 1) (0 0 1 1 1 0) (0 1 0 1 0 1) (0 0 1 1 1 0))
;; `if` without an else branch.
(defun maybe (x) (if (> x 0) 'pos))
(list (maybe 1) (maybe -1))
;=> (POS nil)
;; Redefining `<` while a recursion that tests with it is running: calls made after the
;; change use the new definition.
(setq old< < flip T)
(defun countdown (n)
  (if (and flip (= n 5)) (setq flip nil < (lambda (x y) (old< y x))))
  (if (< n 1) (list 'done n) (countdown (1- n))))
(countdown 8)
;=> (DONE 5)
(setq < old<)
(countdown 8)
;=> (DONE 0)
;; `<` redefined to a non-function: the fused test reports it like any call.
(setq < 3)
(order 1 2)
;!! bad function: 3
(setq < old<)
(order 1 2)
;=> LESS
;; Arithmetic redefined mid-run inside a recursion (fib with `+` swapped for `-`).
(setq old+ +)
(defun fibr (n) (if (< n 2) n (+ (fibr (- n 1)) (fibr (- n 2)))))
(fibr 10)
;=> 55
(setq + -)
(fibr 5)
;=> -1
(setq + old+)
(fibr 10)
;=> 55
;; 32-bit wrap-around through the fused paths.
(defun wrap (n) (if (> n 0) (+ n 2147483647) (- n 1)))
(list (wrap 1) (wrap -2147483648))
;=> (-2147483648 2147483647)
;; `(- v k)`, `(+ v k)`, `(1+ v)`, `(1- v)` as arguments, branches and setq values are
;; evaluated in place; reals, non-numbers and redefinitions take the general path.
(defun down (n acc) (if (< n 1) acc (down (- n 1) (cons n acc))))
(list (down 3 nil) (down 2.5 nil))
;=> ((1 2 3) (1.5 2.5))
(defun ups (n) (list (+ n 1) (+ n -1) (- n 2) (1+ n) (1- n)))
(list (ups 0) (ups 1.5) (ups 2147483647) (ups -2147483648))
;=> ((1 -1 -2 1 -1) (2.5 0.5 -0.5 2.5 0.5) (-2147483648 2147483646 2147483645 -2147483648 2147483646) (-2147483647 2147483647 2147483646 -2147483647 2147483647))
(ups "x")
;!! bad argument type: numberp: "x"
(ups nil)
;!! bad argument type: numberp: nil
(setq i 0)
(repeat 5 (setq i (1+ i)))
i
;=> 5
;; Redefining `-` and `1+` between calls, and `1-` while a recursion runs.
(setq old- - old1+ 1+ old1- 1-)
(setq - +)
(ups 0)
;=> (1 -1 2 1 -1)
(setq - old-)
(ups 0)
;=> (1 -1 -2 1 -1)
(setq 1+ (lambda (x) (old1+ (old1+ x))))
(ups 0)
;=> (1 -1 -2 2 -1)
(setq 1+ old1+)
(setq flip T)
(defun walk (n)
  (if (numberp n)
    (progn (if (and flip (= n 3)) (setq flip nil 1- (lambda (x) 'stop))) (walk (1- n)))
    n))
(walk 5)
;=> STOP
(setq 1- old1-)
((lambda (n) (1- n)) 5)
;=> 4
