;; CHPROP and CHANGE's Properties option: line type (LT), line-type scale (S), line weight
;; (LW: millimetres, rounded to the nearest of AutoCAD's weights; DXF 370 in hundredths;
;; BYLAYER -1, BYBLOCK -2, DEFAULT -3) and thickness (T), as entget shows them.
(defun g (e c) (cdr (assoc c (entget e))))
(entmake '((0 . "LINE") (10 0 0 0) (11 10 0 0)))
(setq l (entlast))
(list (g l 6) (g l 370) (g l 48) (g l 39))
;=> (nil nil nil nil)
(command "_.CHPROP" l "" "_LT" "DASHED" "_LW" 0.3 "_T" 2.5 "_S" 0.5 "")
(list (g l 6) (g l 370) (g l 48) (g l 39))
;=> ("DASHED" 30 0.5 2.5)
;; 0.26 mm is nearest 0.25; the named line type is now in the LTYPE table.
(command "_.CHANGE" l "" "_P" "_LW" 0.26 "")
(g l 370)
;=> 25
(cdr (assoc 2 (tblsearch "LTYPE" "dashed")))
;=> "DASHED"
(command "_.CHPROP" l "" "_LW" "_ByBlock" "_LT" "_ByLayer" "")
(list (g l 6) (g l 370))
;=> (nil -2)
;; Thickness replaces an LWPOLYLINE's own 39 group; an ELLIPSE has none and keeps none.
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 2) (70 . 0) (10 0.0 0.0) (10 4.0 0.0)))
(setq p (entlast))
(command "_.CHPROP" p "" "_T" -1.5 "")
(vl-remove-if-not '(lambda (x) (= (car x) 39)) (entget p))
;=> ((39 . -1.5))
(entmake '((0 . "ELLIPSE") (10 1 2 0) (11 3 0 0) (40 . 0.5)))
(command "_.CHPROP" (entlast) "" "_T" 3 "")
(g (entlast) 39)
;=> nil
;; Several objects at once.
(command "_.CHPROP" l p "" "_S" 2 "")
(list (g l 48) (g p 48))
;=> (2.0 2.0)
(command "_.CHPROP" l "" "_LW" 3.0)
;!! CHPROP: expected a line weight in mm, BYLAYER, BYBLOCK or DEFAULT, got the number 3
(command "_.CHPROP" l "" "_S" 0)
;!! CHPROP: expected a positive line-type scale, got the number 0
(command "_.CHPROP" l "" "_LT" "A*B")
;!! CHPROP: invalid line type name "A*B"
;; entmake and entmod take the same groups; a value out of range gives nil.
(entmake '((0 . "LINE") (10 0 0 0) (11 5 0 0) (6 . "HIDDEN") (370 . 50) (48 . 2.0) (39 . 1.0)))
(setq m (entlast))
(list (g m 6) (g m 370) (g m 48) (g m 39))
;=> ("HIDDEN" 50 2.0 1.0)
(entmake '((0 . "LINE") (10 0 0 0) (11 5 0 0) (370 . 999)))
;=> nil
(entmake '((0 . "LINE") (10 0 0 0) (11 5 0 0) (48 . 0.0)))
;=> nil
(entmod (subst '(370 . 25) '(370 . 50) (entget m)))
(list (g m 6) (g m 370) (g m 48) (g m 39))
;=> ("HIDDEN" 25 2.0 1.0)
(entmod (vl-remove-if '(lambda (x) (member (car x) '(6 370 48 39))) (entget m)))
(list (g m 6) (g m 370) (g m 48) (g m 39))
;=> ("HIDDEN" 25 2.0 1.0)
(setq el (entget m))
(foreach pr '((6 . "ByLayer") (370 . -1) (48 . 1.0) (39 . 0.0))
  (setq el (subst pr (assoc (car pr) el) el)))
(entmod el)
(list (g m 6) (g m 370) (g m 48) (g m 39))
;=> (nil nil nil nil)
;; COPY (and MIRROR, OFFSET, EXPLODE of a polyline) give the new objects the same properties.
(command "_.CHPROP" m "" "_LT" "HIDDEN" "_T" 2 "")
(command "_.COPY" m "" '(0 0) '(0 5) "")
(list (g (entlast) 6) (g (entlast) 39) (g (entlast) 10))
;=> ("HIDDEN" 2.0 (0.0 5.0 0.0))
(command "_.OFFSET" 1 m '(0 -5) "")
(list (g (entlast) 6) (g (entlast) 10))
;=> ("HIDDEN" (0.0 -1.0 0.0))
