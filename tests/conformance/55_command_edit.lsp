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
;!! command: unknown command "_.FILLETX" (lispcad runs LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT, MOVE, COPY, ROTATE, SCALE, MIRROR, INSERT, OFFSET, EXPLODE, FILLET (lines, arcs, circles, polylines), CHPROP, CHANGE, UNDO)
(command "_.ARC" "_C" '(0 0) '(3 0) '(0 3))
(setq a (entlast))
(command "_.MIRROR" a "" '(5 0) '(5 1) "")
(mapcar '(lambda (g) (cdr (assoc g (entget (entlast))))) '(10 40 50 51 210))
;=> ((10.0 0.0 0.0) 3.0 1.5708 3.14159 (0.0 0.0 1.0))
;; CHPROP and CHANGE's Properties option: colour and layer; what is not modelled is an error.
(entmake '((0 . "LAYER") (2 . "Parts") (62 . 3)))
(entmake '((0 . "LINE") (10 0 0 0) (11 10 0 0)))
(setq cl (entlast))
(command "_.chprop" cl "" "_C" 1 "_LA" "Parts" "")
(list (cdr (assoc 8 (entget cl))) (cdr (assoc 62 (entget cl))))
;=> ("Parts" 1)
(command "_.change" cl "" "_P" "_C" "BYLAYER" "")
(assoc 62 (entget cl))
;=> nil
(command "_.chprop" cl "" "_LA" "NoSuchLayer")
;!! CHPROP: cannot find layer "NoSuchLayer"
(command "_.chprop" cl "" "_TR" 50)
;!! CHPROP: the TR property is not modelled by lispcad (Color, LAyer, LType, ltScale, LWeight and Thickness are)
(command "_.change" cl "" '(5 5 0))
;!! CHANGE: only the Properties option ("P") is supported by lispcad, got the point (5 5 0)
;; EXPLODE: a polyline becomes its lines and arcs, on its layer and colour.
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (8 . "Parts") (62 . 5) (90 . 3) (70 . 1) (10 0.0 0.0) (42 . 0.0) (10 4.0 0.0) (42 . 1.0) (10 4.0 4.0) (42 . 0.0)))
(setq pl (entlast))
(command "_.explode" pl)
(entget pl)
;=> nil
(setq ex (ssget "X" '((8 . "Parts") (62 . 5))))
(mapcar '(lambda (i) (cdr (assoc 0 (entget (ssname ex i))))) '(0 1 2))
;=> ("LINE" "ARC" "LINE")
;; The bulge 1 from (4 0) to (4 4) is the half circle through (6 2): centre (4 2), radius 2,
;; counter-clockwise from -90 to 90 degrees.
(setq a (entget (ssname ex 1)))
(list (cdr (assoc 10 a)) (cdr (assoc 40 a)) (rtos (cdr (assoc 50 a)) 2 9) (rtos (cdr (assoc 51 a)) 2 9))
;=> ((4.0 2.0 0.0) 2.0 "4.712388980" "1.570796327")
(cdr (assoc 11 (entget (ssname ex 2))))
;=> (0.0 0.0 0.0)
(command "_.explode" cl)
;!! EXPLODE: lispcad explodes polylines and block references, not LINE
;; OFFSET by a distance on the side of a point, and through a point.
(entmake '((0 . "CIRCLE") (10 0 0 0) (40 . 5.0)))
(setq ci (entlast))
(command "_.offset" 2 ci '(10 0 0) "")
(cdr (assoc 40 (entget (entlast))))
;=> 7.0
(command "_.offset" 2 ci '(1 0 0) "")
(cdr (assoc 40 (entget (entlast))))
;=> 3.0
(command "_.offset" "_T" cl '(3 -4 0) "")
(list (cdr (assoc 10 (entget (entlast)))) (cdr (assoc 11 (entget (entlast)))))
;=> ((0.0 -4.0 0.0) (10.0 -4.0 0.0))
(command "_.offset" 0 ci)
;!! OFFSET: expected a positive distance or T, got the number 0
(command "_.insert" "door" '(0 0 0) 1 1 0)
;!! INSERT: block "door" is not defined
(command "_.-insert" "c:/blocks/door.dwg" '(0 0 0) 1 1 0)
;!! INSERT: inserting a drawing file ("c:/blocks/door.dwg") is not supported; name a block of the opened drawing
(command "_.mline")
;!! command: unknown command "_.mline" (lispcad runs LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT, MOVE, COPY, ROTATE, SCALE, MIRROR, INSERT, OFFSET, EXPLODE, FILLET (lines, arcs, circles, polylines), CHPROP, CHANGE, UNDO)
;; FILLET two lines: radius 2 at a right-angle corner, the arc tangent to both; radius 0
;; extends the lines to their corner. Arcs and other objects are refused by name.
(command "_.fillet" "_R" 2.0)
(getvar "FILLETRAD")
;=> 2.0
(entmake '((0 . "LINE") (10 0 0 0) (11 10 0 0)))
(setq f1 (entlast))
(entmake '((0 . "LINE") (10 10 -1 0) (11 10 10 0)))
(setq f2 (entlast))
;; The pick on f2 at (10 5) keeps its upper part: the stub below the corner goes.
(command "_.fillet" (list f1 '(2 0 0)) (list f2 '(10 5 0)))
(list (cdr (assoc 10 (entget f1))) (cdr (assoc 11 (entget f1))))
;=> ((0.0 0.0 0.0) (8.0 0.0 0.0))
(list (cdr (assoc 10 (entget f2))) (cdr (assoc 11 (entget f2))))
;=> ((10.0 2.0 0.0) (10.0 10.0 0.0))
(setq fa (entget (entlast)))
(list (cdr (assoc 0 fa)) (cdr (assoc 10 fa)) (cdr (assoc 40 fa)) (rtos (cdr (assoc 50 fa)) 2 9) (rtos (cdr (assoc 51 fa)) 2 9))
;=> ("ARC" (8.0 2.0 0.0) 2.0 "4.712388980" "0.000000000")
(command "_.fillet" "_R" 0 f1 (ssadd f2))
(list (cdr (assoc 11 (entget f1))) (cdr (assoc 10 (entget f2))))
;=> ((10.0 0.0 0.0) (10.0 0.0 0.0))
(entmake '((0 . "POINT") (10 50 50 0)))
(command "_.fillet" f1 (entlast))
;!! FILLET: lispcad fillets lines, arcs and circles in the XY plane, not a POINT
(entmake '((0 . "LINE") (10 0 5 0) (11 10 5 0)))
(command "_.fillet" f1 (entlast))
;!! FILLET: the lines are parallel
;; FILLET with arcs. Expected values worked by hand: the fillet centre is at distance r
;; from both curves, so for the line y=0 and the arc (10,0) R8 with r=3 it is (14,3)
;; (4^2+3^2 = (8-3)^2); its tangent points are (14,0) and (10,0)+8*(0.8,0.6); angles are
;; atan2(0.6,0.8) = 0.643501109 and 3pi/2.
(defun fr (v) (mapcar '(lambda (x) (rtos x 2 6)) v))
(defun arcof (e) (setq e (entget e)) (list (fr (cdr (assoc 10 e))) (rtos (cdr (assoc 40 e)) 2 6) (rtos (cdr (assoc 50 e)) 2 9) (rtos (cdr (assoc 51 e)) 2 9)))
(entmake '((0 . "LINE") (10 0 0 0) (11 20 0 0)))
(setq fl (entlast))
(entmake (list '(0 . "ARC") '(10 10 0 0) '(40 . 8.0) '(50 . 0.0) (cons 51 pi)))
(setq fc (entlast))
(command "_.fillet" "_R" 3.0 (list fl '(12 0 0)) (list fc '(10 8 0)))
(list (fr (cdr (assoc 10 (entget fl)))) (fr (cdr (assoc 11 (entget fl)))))
;=> (("0.000000" "0.000000" "0.000000") ("14.000000" "0.000000" "0.000000"))
(arcof fc)
;=> (("10.000000" "0.000000" "0.000000") "8.000000" "0.643501109" "3.141592654")
(arcof (entlast))
;=> (("14.000000" "3.000000" "0.000000") "3.000000" "4.712388980" "0.643501109")
;; Radius 0: the line (0,0)-(15,0) and the arc (10,0) R8 from pi/4 to pi meet, extended, at
;; (2,0) and (18,0); (18,0) is nearer the picks, so the line grows to it and the arc's start
;; moves back to angle 0. No arc is added.
(entmake '((0 . "LINE") (10 0 0 0) (11 15 0 0)))
(setq fl (entlast))
(entmake (list '(0 . "ARC") '(10 10 0 0) '(40 . 8.0) (cons 50 (/ pi 4)) (cons 51 pi)))
(setq fc (entlast))
(command "_.fillet" "_R" 0 (list fl '(12 0 0)) (list fc '(10 8 0)))
(list (fr (cdr (assoc 11 (entget fl)))) (arcof fc) (eq (entlast) fc))
;=> (("18.000000" "0.000000" "0.000000") (("10.000000" "0.000000" "0.000000") "8.000000" "0.000000000" "3.141592654") T)
;; Two arcs, (0,0) R5 from pi/2 to pi and (8,0) R5 from 0 to pi/2, r=3.5: the centre is
;; (4,7.5) (4^2+7.5^2 = 8.5^2); the first arc's start moves back to atan2(7.5,4) =
;; 1.080839001, the second's end on to pi-1.080839001, and the fillet runs between them
;; under its centre: from atan2(-7.5,-4) = 4.222431654 to atan2(-7.5,4) = 5.202346307.
(entmake (list '(0 . "ARC") '(10 0 0 0) '(40 . 5.0) (cons 50 (/ pi 2)) (cons 51 pi)))
(setq fa1 (entlast))
(entmake (list '(0 . "ARC") '(10 8 0 0) '(40 . 5.0) '(50 . 0.0) (cons 51 (/ pi 2))))
(setq fa2 (entlast))
(command "_.fillet" "_R" 3.5 (list fa1 '(-3 4 0)) (list fa2 '(11 4 0)))
(list (arcof fa1) (arcof fa2))
;=> ((("0.000000" "0.000000" "0.000000") "5.000000" "1.080839001" "3.141592654") (("8.000000" "0.000000" "0.000000") "5.000000" "0.000000000" "2.060753653"))
(arcof (entlast))
;=> (("4.000000" "7.500000" "0.000000") "3.500000" "4.222431654" "5.202346307")
;; Concentric arcs are refused (60_fillet.lsp); a radius no fillet fits is an error.
(entmake (list '(0 . "ARC") '(10 0 0 0) '(40 . 2.0) '(50 . 0.0) (cons 51 pi)))
(command "_.fillet" "_R" 0 fa1 (entlast))
;!! FILLET: the objects are concentric: lispcad does not fillet concentric arcs or circles
(entmake (list '(0 . "ARC") '(10 40 0 0) '(40 . 2.0) '(50 . 0.0) (cons 51 pi)))
(command "_.fillet" "_R" 1.0 fa1 (entlast))
;!! FILLET: no fillet of radius 1 joins these objects
