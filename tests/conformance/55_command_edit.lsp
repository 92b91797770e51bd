;; command: MOVE, COPY, ROTATE, SCALE, MIRROR, UNDO marks, prefixes (issue 12, item 7).
(command "_.LINE" '(0 0) '(10 0) "")
(setq l (entlast))
(command "_.MOVE" l "" '(0 0) '(5 5))
(cdr (assoc 10 (entget l)))
;=> (5.0 5.0 0.0)
(command "._move" l "" "1,1" "")
(cdr (assoc 11 (entget l)))
;=> (16.0 6.0 0.0)
(command "_copy" l "" '(0 0) '(0 10) '(0 20) "")
(sslength (ssget "X"))
;=> 3
(cdr (assoc 10 (entget (entlast))))
;=> (6.0 26.0 0.0)
(command "_.ROTATE" l "" '(6 6) 90)
(mapcar '(lambda (x) (/ (fix (+ (* x 1000) 0.5)) 1000.0)) (cdr (assoc 11 (entget l))))
;=> (6.0 16.0 0.0)
(command "_.CIRCLE" '(0 0) 2)
(setq c (entlast))
(command "_.SCALE" c "" '(0 0) 2.5)
(cdr (assoc 40 (entget c)))
;=> 5.0
(command "_.MIRROR" c "" '(10 0) '(10 1) "")
(cdr (assoc 10 (entget (entlast))))
;=> (20.0 0.0 0.0)
(sslength (ssget "X" '((0 . "CIRCLE"))))
;=> 2
(command "_.MIRROR" c "" '(10 0) '(10 1) "_Y")
(sslength (ssget "X" '((0 . "CIRCLE"))))
;=> 2
(command "_.UNDO" "_BEgin")
(logand (getvar "UNDOCTL") 8)
;=> 8
(command "_.UNDO" "_End")
(logand (getvar "UNDOCTL") 8)
;=> 0
(command "_.ZOOM" "_E")
;=> nil
(command "_.REGEN")
;=> nil
(command "_.MOVE" "" )
;!! MOVE: no objects selected
(command "_.FILLETX")
;!! command: unknown command "_.FILLETX" (lispcad runs LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT, MOVE, COPY, ROTATE, SCALE, MIRROR, UNDO)
(command "_.ARC" "_C" '(0 0) '(3 0) '(0 3))
(setq a (entlast))
(command "_.MIRROR" a "" '(5 0) '(5 1) "")
(mapcar '(lambda (g) (cdr (assoc g (entget (entlast))))) '(10 40 50 51 210))
;=> ((10.0 0.0 0.0) 3.0 1.5708 3.14159 (0.0 0.0 1.0))
