;; The one-argument call path: a call of a one-parameter user function binds an integer
;; argument (a variable, a constant, `(- n 1)`) straight into the parameter's cell and passes
;; the body's result back packed in two words. Each case checks a way off that path.
;;
;; Every kind of argument, and the parameter's outer value restored after each call.
(setq n 'N0 x 2.5)
(defun id1 (n) n)
(list (id1 3) (id1 x) (id1 "s") (id1 '(1 2)) (id1 nil) (id1 'sym) (eq (id1 id1) id1) n)
;=> (3 2.5 "s" (1 2) nil SYM T N0)
(setq k 41)
(list (id1 k) (id1 (+ k 1)) (id1 (- k 1)) (id1 (1+ k)) (id1 (1- k)) (id1 (+ x 1)) n)
;=> (41 42 40 42 40 3.5 N0)
;; 32-bit wrap on the way into the parameter.
(setq big 2147483647)
(list (id1 (+ big 1)) (id1 (1- -2147483648)))
;=> (-2147483648 2147483647)
;; The argument's operator redefined: the argument comes from the new definition.
(defun down (n) (if (< n 1) 'done (down (- n 1))))
(down 5)
;=> DONE
(setq real- -)
(defun - (a b) (real- a (* 2 b)))
(list (id1 (- 10 1)) (down 9))
;=> (8 DONE)
(setq - real-)
(id1 (- 10 1))
;=> 9
;; A non-number where the argument's arithmetic wants one: the builtin's own error.
(setq s "text")
(id1 (+ s 1))
;!! bad argument type: numberp: "text"
n
;=> N0
;; The head is not a one-parameter user function: a builtin, a defun-q list, other arities.
(setq id2 abs)
(id2 -4)
;=> 4
(defun-q idq (n) (list 'q n))
(idq 5)
;=> (Q 5)
(defun none () 'none)
(none 1)
;!! too many arguments
(defun two (a b) (list a b))
(two 1)
;!! too few arguments
(nope 1)
;!! no function definition: NOPE
(setq id3 7)
(id3 1)
;!! bad function: 7
;; Locals beside the parameter start nil and are restored with it.
(setq loc 'L0)
(defun withloc (n / loc) (setq loc (list n loc)) loc)
(list (withloc 1) loc n)
;=> ((1 nil) L0 N0)
;; An error in the body: *error* sees the parameter bound, then it is restored.
(setq seen nil)
(defun *error* (msg) (setq seen (list msg n)))
(defun fail1 (n) (/ n 0))
(fail1 6)
;!! divide by zero
(list seen n)
;=> (("divide by zero" 6) N0)
(setq *error* nil)
;; Caught by vl-catch-all-apply: the parameter is back and the error is a value.
(vl-catch-all-error-message (vl-catch-all-apply 'fail1 '(7)))
;=> "divide by zero"
(vl-catch-all-error-message (vl-catch-all-apply '(lambda () (fail1 (+ k 1))) nil))
;=> "divide by zero"
n
;=> N0
;; A function that redefines itself mid-recursion finishes the running body.
(defun shift (n) (if (= n 2) (defun shift (n) (list 'new n))) (if (< n 1) (list 'old n) (list n (shift (1- n)))))
(shift 3)
;=> (3 (2 (NEW 1)))
(shift 3)
;=> (NEW 3)
;; A function that clears its own name mid-recursion: the next call finds nothing.
(defun vanish (n) (if (= n 1) (setq vanish nil)) (if (< n 1) 'end (vanish (1- n))))
(vanish 3)
;!! no function definition: VANISH
;; Recursion through the path gives the same sums as a loop.
(defun fib (n) (if (< n 2) n (+ (fib (- n 1)) (fib (- n 2)))))
(list (fib 0) (fib 1) (fib 2) (fib 10) (fib 20) n)
;=> (0 1 1 55 6765 N0)
