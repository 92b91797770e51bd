;; Dynamic scope: a callee sees its caller's locals; locals start as nil and are restored.
(setq v 'global)
(defun show-v () v)
(defun with-local (/ v) (setq v 'local) (show-v))
(with-local)
;=> LOCAL
v
;=> GLOBAL
(defun locals-start-nil (/ v) v)
(locals-start-nil)
;=> nil
(defun param-shadow (v) (show-v))
(param-shadow 'param)
;=> PARAM
v
;=> GLOBAL
;; lambda does not capture: it sees the binding in effect when it runs.
(defun make-adder (n) (lambda (x) (+ x n)))
(setq add5 (make-adder 5))
(setq n 100)
(add5 1)
;=> 101
;; bindings are restored after an error inside the function
(defun fails (/ v) (setq v 'inside) (car 1))
(vl-catch-all-error-p (vl-catch-all-apply 'fails nil))
;=> T
v
;=> GLOBAL
;; recursion
(defun fact (n) (if (< n 2) 1 (* n (fact (1- n)))))
(fact 10)
;=> 3628800
(defun fib (n) (if (< n 2) n (+ (fib (- n 1)) (fib (- n 2)))))
(fib 15)
;=> 610
;; redefining a builtin takes effect for later calls (Lisp-1)
(defun my+ (a b) (- a b))
(setq old+ +)
(setq + my+)
(+ 5 3)
;=> 2
(setq + old+)
(+ 5 3)
;=> 8
