;; A name repeated in a parameter list: the first occurrence wins (Autodesk's rule, as for
;; a local repeating a parameter); the call still takes one argument per name.
(defun getval (index aList index) (list index aList))
(getval 1 2 3)
;=> (1 2)
(getval 1 2)
;!! too few arguments
((lambda (a a a) a) 'first 'second 'third)
;=> FIRST
(defun f2 (x y x / x) (list x y))
(f2 10 20 30)
;=> (10 20)
;; The argument of a repeated parameter is not visible anywhere afterwards.
(setq x 'outer)
(f2 1 2 3)
;=> (1 2)
x
;=> OUTER
