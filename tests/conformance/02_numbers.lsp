;; Integer vs real arithmetic and AutoLISP's number quirks.
(/ 7 2)
;=> 3
(/ 7 2.0)
;=> 3.5
(/ -7 2)
;=> -3
(+ 1 2.0)
;=> 3.0
(+)
;=> 0
(*)
;=> 1
(- 5)
;=> -5
(- 10 1 2 3)
;=> 4
(* 2 3 4)
;=> 24
(+ 2147483647 1)
;=> -2147483648
(* 65536 65536)
;=> 0
(rem 7 2)
;=> 1
(rem -7 2)
;=> -1
(rem 7.5 2)
;=> 1.5
(1+ 5)
;=> 6
(1- 5.5)
;=> 4.5
(abs -3)
;=> 3
(abs -3.5)
;=> 3.5
(fix 3.7)
;=> 3
(fix -3.7)
;=> -3
(float 3)
;=> 3.0
(max 1 5 3)
;=> 5
(max 1 5.0 3)
;=> 5.0
(min 4 2 8)
;=> 2
(gcd 12 18)
;=> 6
(sqrt 16)
;=> 4.0
(expt 2 10)
;=> 1024
(expt 2.0 3)
;=> 8.0
(exp 0)
;=> 1.0
(log 1)
;=> 0.0
(sin 0)
;=> 0.0
(cos 0)
;=> 1.0
(atan 1 1)
;=> 0.785398
(atan 1)
;=> 0.785398
pi
;=> 3.14159
(~ 5)
;=> -6
(logand 12 10)
;=> 8
(logior 12 10)
;=> 14
(lsh 1 4)
;=> 16
(lsh 16 -2)
;=> 4
(boole 6 12 10)
;=> 6
(= 1 1.0)
;=> T
(= 1 2)
;=> nil
(= "a" "a")
;=> T
(/= 1 2)
;=> T
(< 1 2 3)
;=> T
(< 1 3 2)
;=> nil
(<= 1 1 2)
;=> T
(> 3 2 1)
;=> T
(>= 3 3 1)
;=> T
(< "abc" "abd")
;=> T
(zerop 0.0)
;=> T
(minusp -1)
;=> T
(numberp 1.5)
;=> T
(numberp "1")
;=> nil
(/ 1 0)
;!! divide by zero
(/ 1.0 0)
;!! divide by zero
(rem 1 0)
;!! divide by zero
(+ 1 nil)
;!! bad argument type: numberp: nil
(+ 1 "2")
;!! bad argument type: numberp: "2"
(sqrt -1)
;!! function undefined for argument: -1
(log 0)
;!! function undefined for argument: 0
(1+ 'a)
;!! bad argument type: numberp: A
(logand 1.5 1)
;!! bad argument type: fixnump: 1.5
(princ 1e6)
;>> 1.0e+06
(princ 3.14159265)
;>> 3.14159
(princ 100000.0)
;>> 100000.0
(princ 1.5e-7)
;>> 1.5e-07
(princ 123456789.0)
;>> 1.23457e+08
(= 'a 'a)
;=> T
(= 'a 'b)
;=> nil
(= nil nil)
;=> T
(= '(1) '(1))
;=> nil
(/= 'a 'b)
;=> T

;; A NaN (inf - inf) is unordered: every ordering is nil, compiled or through apply.
(progn (setq nan (- (* 1e308 10.0) (* 1e308 10.0))) (list (<= nan 1) (>= nan 1) (< nan 1) (> nan 1)))
;=> (nil nil nil nil)
(list (apply '<= (list nan 1)) (apply '>= (list nan 1)) (apply '< (list nan 1)) (apply '> (list nan 1)))
;=> (nil nil nil nil)
