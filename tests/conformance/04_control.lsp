;; Special forms and their return values.
(setq a 1 b 2)
;=> 2
a
;=> 1
(setq)
;=> nil
(setq 1 2)
;!! bad argument type: symbolp 1
undefined-symbol-reads-as-nil
;=> nil
(if t 'yes 'no)
;=> YES
(if nil 'yes)
;=> nil
(if nil 'yes 'no)
;=> NO
(if)
;!! too few arguments
(if 1 2 3 4)
;!! too many arguments
(cond ((= 1 2) 'a) ((= 1 1) 'b) (t 'c))
;=> B
(cond (nil 1) (5))
;=> 5
(cond (nil 1))
;=> nil
(progn 1 2 3)
;=> 3
(progn)
;=> nil
(and 1 2 3)
;=> T
(and 1 nil 3)
;=> nil
(and)
;=> T
(or nil 5)
;=> T
(or nil nil)
;=> nil
(or)
;=> nil
(setq i 0)
(while (< i 5) (setq i (1+ i)))
;=> 5
(while nil 1)
;=> nil
(repeat 3 (setq i (+ i 10)))
;=> 35
(repeat 0 'x)
;=> nil
(repeat 2.5 'x)
;!! bad argument type: fixnump: 2.5
(setq s 0)
(foreach x '(1 2 3) (setq s (+ s x)))
;=> 6
(foreach x nil 1)
;=> nil
(setq x 'outer)
(foreach x '(1 2) x)
x
;=> OUTER
(defun sq (n) (* n n))
;=> SQ
(sq 7)
;=> 49
(sq)
;!! too few arguments
(sq 1 2)
;!! too many arguments
(type sq)
;=> USUBR
(type car)
;=> SUBR
(type if)
;=> SUBR
(nofun 1)
;!! no function definition: NOFUN
(1 2 3)
;!! bad function: 1
((lambda (x y) (+ x y)) 1 2)
;=> 3
(setq f (lambda (x) (* 3 x)))
(f 5)
;=> 15
(type f)
;=> USUBR
(setq g '(lambda (x) (* 4 x)))
(g 5)
;=> 20
(eval '(+ 1 2))
;=> 3
(eval 'a)
;=> 1
(eval (list '* 6 7))
;=> 42
(set 'zz 9)
;=> 9
zz
;=> 9
(set (read "YY") 3)
yy
;=> 3
(function car)
;=> CAR
(quote (a b))
;=> (A B)
(defun-q dq (x) (* x 10))
;=> DQ
(dq 4)
;=> 40
(defun-q-list-ref 'dq)
;=> ((X) (* X 10))
(defun-q-list-set 'dq2 '((x) (+ x 1)))
;=> DQ2
(dq2 1)
;=> 2
