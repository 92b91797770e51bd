;; Predicates and types.
(atom 1)
;=> T
(atom nil)
;=> T
(atom '(1))
;=> nil
(listp nil)
;=> T
(listp '(1))
;=> T
(listp 1)
;=> nil
(null nil)
;=> T
(not 1)
;=> nil
(eq 'a 'a)
;=> T
(eq '(1) '(1))
;=> nil
(setq l '(1 2))
(eq l l)
;=> T
(equal '(1 (2 "x")) '(1 (2 "x")))
;=> T
(equal 1.0 1.0000001 1e-6)
;=> T
(equal 1.0 1.1 1e-6)
;=> nil
(equal '(1.0 2.0) '(1.0 2.0001) 0.001)
;=> T
(equal 1 1.0)
;=> T
(boundp 'l)
;=> T
(boundp 'never-set)
;=> nil
(vl-symbolp 'a)
;=> T
(vl-symbolp "a")
;=> nil
(type 1)
;=> INT
(type 1.0)
;=> REAL
(type "s")
;=> STR
(type 'a)
;=> SYM
(type '(1))
;=> LIST
(type nil)
;=> nil
(type t)
;=> SYM
