;; AutoLISP quirks users rely on (SPEC section 3), collected in one place.
(and 1 2)
;=> T
(and 1 nil 2)
;=> nil
(and)
;=> T
(or nil 5)
;=> T
(or)
;=> nil
(setq q1 1 q2 "two")
;=> "two"
(/ 7 2)
;=> 3
(/ -7 2)
;=> -3
(/ 7 2.0)
;=> 3.5
(/ 1 3.0)
;=> 0.333333
(expt 2 -1)
;=> 0
(fix 1e10)
;=> 1.0e+10
(+ 2147483647 1)
;=> -2147483648
2147483648
;=> 2.14748e+09
-2147483649
;=> -2.14748e+09
(* 1.0 123456789)
;=> 1.23457e+08
(* 1.0 100000)
;=> 100000.0
(sqrt 2)
;=> 1.41421
(+ 0.1 0.2)
;=> 0.3
(vl-sort '(3 1 2 1 3) '<)
;=> (1 2 3)
(repeat 3 (setq r 7))
;=> 7
(foreach x '(1 2 3) (* x 10))
;=> 30
(progn (setq w 0) (while (< w 3) (setq w (1+ w))))
;=> 3
(car nil)
;=> nil
(cdr nil)
;=> nil
(nth 5 '(1 2))
;=> nil
(type (defun quirk-f (x) x))
;=> SYM
(quirk-f 3)
;=> 3
;; quote is not abbreviated when printed
''a
;=> (QUOTE A)
(read "'a")
;=> (QUOTE A)
;; dynamic scope: a callee sees its caller's locals; locals are restored afterwards
(defun dyn-g () dyn-x)
;=> DYN-G
(defun dyn-f (dyn-x) (dyn-g))
;=> DYN-F
(dyn-f 42)
;=> 42
(progn (setq dyn-x 1) (dyn-f 5) dyn-x)
;=> 1
(progn (setq fx 1) (foreach fx '(5 6) fx) fx)
;=> 1
(progn (setq sym-a 'sym-b) (set sym-a 5) sym-b)
;=> 5
;; unbound symbols read as nil
undefined-symbol-xyz
;=> nil
;; read: first datum only; AutoLISP's messages for unfinished input
(read "(1 2) (3")
;=> (1 2)
(read "")
;=> nil
(read "  ; only a comment")
;=> nil
(read "(1 2")
;!! malformed list on input
(read "\"abc")
;!! malformed string on input
(read ")")
;!! extra right paren on input
;; printing
(prin1 (chr 7))
;>> "\007"
(princ '("a" b 1.5))
;>> (a B 1.5)
(print "x")
;>> \n"x" 
(princ)
;>> 
(prin1)
;>> 
;; error texts
(+ 1 nil)
;!! bad argument type: numberp: nil
(+ 1 "a")
;!! bad argument type: numberp: "a"
(itoa 3.0)
;!! bad argument type: fixnump: 3.0
(length 5)
;!! bad argument type: listp 5
(car "a")
;!! bad argument type: consp "a"
(strcat "a" nil)
;!! bad argument type: stringp nil
(/ 5.0 0)
;!! divide by zero
(rem 5 0)
;!! divide by zero
(no-such-function-xyz 1)
;!! no function definition: NO-SUCH-FUNCTION-XYZ
(quirk-f)
;!! too few arguments
(quirk-f 1 2)
;!! too many arguments
(sqrt -1)
;!! function undefined for argument: -1
(log 0)
;!! function undefined for argument: 0
(vl-catch-all-error-message (vl-catch-all-apply '/ '(1 0)))
;=> "divide by zero"
(vl-catch-all-error-message (vl-catch-all-apply 'exit nil))
;=> "quit / exit abort"
