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
;!! command: unknown command "_.FILLETX" (lispcad runs LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT, MOVE, COPY, ROTATE, SCALE, MIRROR, INSERT, OFFSET, EXPLODE, FILLET (lines), CHPROP, CHANGE, UNDO)
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
(command "_.chprop" cl "" "_LT" "DASHED")
;!! CHPROP: per-entity line types are not modelled by lispcad (only BYLAYER; set the layer's with -LAYER LType), got "DASHED"
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
;!! EXPLODE: lispcad explodes polylines only, not LINE (block references are kept as read)
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
;!! INSERT: block "door" is not defined (lispcad inserts the blocks of a drawing opened with --open, R2000 or later)
(command "_.-insert" "c:/blocks/door.dwg" '(0 0 0) 1 1 0)
;!! INSERT: inserting a drawing file ("c:/blocks/door.dwg") is not supported; name a block of the opened drawing
(command "_.mline")
;!! command: unknown command "_.mline" (lispcad runs LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT, MOVE, COPY, ROTATE, SCALE, MIRROR, INSERT, OFFSET, EXPLODE, FILLET (lines), CHPROP, CHANGE, UNDO)
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
(command "_.fillet" f1 ci)
;!! FILLET: lispcad fillets two lines, not a CIRCLE
(entmake '((0 . "LINE") (10 0 5 0) (11 10 5 0)))
(command "_.fillet" f1 (entlast))
;!! FILLET: the lines are parallel
