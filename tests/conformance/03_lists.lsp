;; Lists.
(car '(1 2 3))
;=> 1
(cdr '(1 2 3))
;=> (2 3)
(car nil)
;=> nil
(cdr nil)
;=> nil
(cadr '(1 2 3))
;=> 2
(caddr '(1 2 3))
;=> 3
(cddr '(1 2 3))
;=> (3)
(caar '((1 2) 3))
;=> 1
(cdar '((1 2) 3))
;=> (2)
(cadddr '(1 2 3 4))
;=> 4
(cddddr '(1 2 3 4 5))
;=> (5)
(car 1)
;!! bad argument type: consp 1
(cons 1 '(2))
;=> (1 2)
(cons 1 2)
;=> (1 . 2)
(list 1 "a" 'b 2.5)
;=> (1 "a" B 2.5)
(list)
;=> nil
(append '(1 2) '(3) nil '(4 5))
;=> (1 2 3 4 5)
(append)
;=> nil
(reverse '(1 2 3))
;=> (3 2 1)
(nth 1 '(a b c))
;=> B
(nth 5 '(a b c))
;=> nil
(length '(1 2 3))
;=> 3
(length nil)
;=> 0
(last '(1 2 3))
;=> 3
(assoc 2 '((1 . "one") (2 . "two")))
;=> (2 . "two")
(assoc "b" '(("a" 1) ("b" 2)))
;=> ("b" 2)
(assoc 9 '((1 . 2)))
;=> nil
(member 'c '(a b c d))
;=> (C D)
(member 'z '(a b))
;=> nil
(subst 'x 'b '(a b c b))
;=> (A X C X)
(subst '(10 1.0 2.0) '(10 0.0 0.0) '((0 . "LINE") (10 0.0 0.0)))
;=> ((0 . "LINE") (10 1.0 2.0))
(subst 9 2 nil)
;=> nil
(subst 9 2 5)
;!! bad argument type: listp 5
(subst 9 2 '(1 2 . 5))
;!! bad list
;; Keys of different kinds are equal when their values are (integer and real).
(assoc 1.0 '((1 . a) (2 . b)))
;=> (1 . A)
(assoc 2 '((1.0 . a) (2.0 . b)))
;=> (2.0 . B)
(assoc 'b '((a . 1) (b . 2)))
;=> (B . 2)
(assoc '(1 2) '(((1 2) . x) ((1 3) . y)))
;=> ((1 2) . X)
;; subst compares with equal, not eq: equal copies are replaced, the same pair too.
(subst 'x '(1 . a) '((1 . a) (2 . b) (1 . a)))
;=> (X (2 . B) X)
(subst 'x '(1.0 . a) '((1 . a) (2 . b)))
;=> (X (2 . B))
(subst 'x '(1 . b) '((1 . a) (2 . b)))
;=> ((1 . A) (2 . B))
(progn (setq al '((1 . 10) (2 . 20) (3 . 30))) (subst '(2 . 21) (assoc 2 al) al))
;=> ((1 . 10) (2 . 21) (3 . 30))
(member '(a 1) '((a 2) (a 1) (b 1)))
;=> ((A 1) (B 1))
(member 2.0 '(1 2 3))
;=> (2 3)
(vl-remove 2 '(1 2 3 2))
;=> (1 3)
(vl-remove-if 'minusp '(1 -2 3 -4))
;=> (1 3)
(vl-remove-if-not '(lambda (x) (> x 1)) '(1 2 3))
;=> (2 3)
(vl-position 'c '(a b c))
;=> 2
(vl-position 'z '(a b c))
;=> nil
(vl-member-if 'minusp '(1 -2 3))
;=> (-2 3)
(vl-member-if-not 'numberp '(1 a 2))
;=> (A 2)
(vl-some '= '(1 2 3) '(3 2 1))
;=> T
(vl-some 'minusp '(1 2))
;=> nil
(vl-every '< '(1 2) '(2 3))
;=> T
(vl-every 'numberp '(1 a))
;=> nil
(vl-list* 1 2 3)
;=> (1 2 . 3)
(vl-list* 1)
;=> 1
(vl-consp '(1))
;=> T
(vl-consp nil)
;=> nil
(vl-list-length '(1 2 3))
;=> 3
(vl-list-length '(1 . 2))
;=> nil
(vl-sort '(3 1 2 3 1) '<)
;=> (1 2 3)
(vl-sort '(3.0 1.0 3.0) '<)
;=> (1.0 3.0 3.0)
(vl-sort '("b" "a" "c") '>)
;=> ("c" "b" "a")
(vl-sort '((2 b) (1 a)) '(lambda (p q) (< (car p) (car q))))
;=> ((1 A) (2 B))
(vl-sort-i '(30 10 20) '<)
;=> (1 2 0)
(acad_strlsort '("pear" "apple" "fig"))
;=> ("apple" "fig" "pear")
(mapcar '+ '(1 2 3) '(10 20 30))
;=> (11 22 33)
(mapcar '1+ '(1 2))
;=> (2 3)
(mapcar '(lambda (x) (* x x)) '(1 2 3))
;=> (1 4 9)
(mapcar 'list '(1 2 3) '(a b))
;=> ((1 A) (2 B))
(apply '+ '(1 2 3))
;=> 6
(apply 'max '(4 9 2))
;=> 9
(apply '(lambda (a b) (- a b)) '(10 3))
;=> 7
(apply (function (lambda (x) (* 2 x))) '(21))
;=> 42
