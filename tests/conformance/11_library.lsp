;; Library functions the earlier files do not reach, and AutoLISP fidelity fixes.
;; max/min/rem with no argument return 0 (AutoCAD reference).
(max)
;=> 0
(min)
;=> 0
(rem)
;=> 0
(rem 7)
;=> 7
(apply 'max nil)
;=> 0
(max 1 2.0)
;=> 2.0
(min 3 -1 2)
;=> -1
;; vl-sort-i lists equal elements last-first, as in AutoCAD's reference.
(vl-sort-i '(3 2 1 3) '<)
;=> (2 1 3 0)
(vl-sort-i '(3 2 1 3) '>)
;=> (3 0 1 2)
(vl-sort-i '("a" "d" "f" "c") '>)
;=> (2 1 3 0)
(vl-sort-i '(1 1 1) '<)
;=> (2 1 0)
(vl-sort-i nil '<)
;=> nil
(vl-sort '(3 2 1 3) '<)
;=> (1 2 3)
(vl-sort '(3.0 2.0 1.0 3.0) '<)
;=> (1.0 2.0 3.0 3.0)
(vl-sort '("b" "a" "b") '<)
;=> ("a" "b" "b")
;; car/cdr compositions to four levels
(setq t4 '(((1 2) 3) (4 5) 6 7))
;=> (((1 2) 3) (4 5) 6 7)
(caaar t4)
;=> 1
(caadr t4)
;=> 4
(cadar t4)
;=> 3
(caddr t4)
;=> 6
(cdaar t4)
;=> (2)
(cdadr t4)
;=> (5)
(cddar t4)
;=> nil
(cdddr t4)
;=> (7)
(caaaar '((((1)))))
;=> 1
(caaadr '(0 ((1))))
;=> 1
(caadar '((0 (1))))
;=> 1
(caaddr '(0 0 (1)))
;=> 1
(cadaar '(((0 1))))
;=> 1
(cadadr '(0 (0 1)))
;=> 1
(caddar '((0 0 1)))
;=> 1
(cadddr '(0 0 0 1))
;=> 1
(cdaaar '((((0 . 1)))))
;=> 1
(cdaadr '(0 ((0 . 1))))
;=> 1
(cdadar '((0 (0 . 1))))
;=> 1
(cdaddr '(0 0 (0 . 1)))
;=> 1
(cddaar '(((0 0 . 1))))
;=> 1
(cddadr '(0 (0 0 . 1)))
;=> 1
(cdddar '((0 0 0 . 1)))
;=> 1
(cddddr '(0 0 0 0 . 1))
;=> 1
(cadddr nil)
;=> nil
(caddr '(1 2))
;=> nil
(caar '(1))
;!! bad argument type: consp 1
;; integers
(lcm 4 6)
;=> 12
(lcm 4 6 10)
;=> 60
(lcm 0 5)
;=> 0
(lcm 4 2.0)
;!! bad argument type: fixnump: 2.0
(gcd 12 18)
;=> 6
;; strings
(xstrcase "abc")
;=> "ABC"
(strcase "MiXeD" T)
;=> "mixed"
;; symbols
(vl-symbol-name 'abc)
;=> "ABC"
(vl-symbol-name "x")
;!! bad argument type: symbolp "x"
(setq sv 42)
;=> 42
(vl-symbol-value 'sv)
;=> 42
(vl-symbol-value 'no-such-symbol)
;=> nil
(vl-bb-set 'bb 7)
;=> 7
(vl-bb-ref 'bb)
;=> 7
(vl-bb-ref 'nothing-on-the-board)
;=> nil
;; setq-default: only symbols that are still nil
(setq sd1 5)
;=> 5
(setq-default 'sd1 1 'sd2 2)
;=> 2
(list sd1 sd2)
;=> (5 2)
;; compatibility no-ops and environment
(vl-load-com)
;=> nil
(gc)
;=> nil
(getenv "LISPCAD_SURELY_UNSET_VARIABLE")
;=> nil
(type (ver))
;=> STR
(wcmatch (ver) "lispcad*")
;=> T
(help 'car)
;>> (car list)\n  The first element of a list (nil for nil).\n
(help 'no-such-builtin)
;>> no help for NO-SUCH-BUILTIN: not a builtin\n
(alert "message")
;>> message\n
(prompt "p")
;>> p
(write-char 66)
;>> B
(write-char 66)
;=> 66
(terpri)
;>> \n
