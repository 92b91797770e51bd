;; FILLET with circles and polylines (issue 12). Values worked by hand:
;; - line y=8 and circle r=5 at the origin, radius 2, picks on the right: the fillet centre is
;;   2 below the line and 5+2 from the origin, (sqrt 13, 6); the line's tangent point is
;;   (sqrt 13, 8); the arc runs CCW from 90 degrees to the circle's tangent point, at
;;   pi + atan(6/sqrt 13) = 4.171289454 from the fillet centre. The circle stays whole.
(defun r9 (x) (rtos x 2 9))
(defun pt9 (p) (mapcar 'r9 p))
(command "_.CIRCLE" '(0 0) 5)
(setq c (entlast))
(command "_.LINE" '(-10 8) '(10 8) "")
(setq l (entlast))
(command "_.FILLET" "_R" 2.0 (list l '(6 8)) (list c '(4 3)))
(list (cdr (assoc 10 (entget c))) (cdr (assoc 40 (entget c))) (cdr (assoc 0 (entget c))))
;=> ((0.0 0.0 0.0) 5.0 "CIRCLE")
(list (pt9 (cdr (assoc 10 (entget l)))) (cdr (assoc 11 (entget l))))
;=> (("3.605551275" "8.000000000" "0.000000000") (10.0 8.0 0.0))
(setq a (entget (entlast)))
(list (pt9 (cdr (assoc 10 a))) (cdr (assoc 40 a)) (r9 (cdr (assoc 50 a))) (r9 (cdr (assoc 51 a))))
;=> (("3.605551275" "6.000000000" "0.000000000") 2.0 "1.570796327" "4.171289454")
;; Two circles r=3 at (0 0) and (10 0), radius 4: the centre is 7 from both, (5, sqrt 24);
;; the tangent points are 3/7 of the way from each circle's centre; the arc is the short one
;; between them: from atan2(-4 sqrt 24, -20) to atan2(-4 sqrt 24, 20) (mod 2 pi).
(command "_.CIRCLE" '(0 0) 3)
(setq c1 (entlast))
(command "_.CIRCLE" '(10 0) 3)
(setq c2 (entlast))
(command "_.FILLET" "_R" 4 (list c1 '(0 3)) (list c2 '(10 3)))
(setq a (entget (entlast)))
(list (pt9 (cdr (assoc 10 a))) (cdr (assoc 40 a)) (r9 (cdr (assoc 50 a))) (r9 (cdr (assoc 51 a))))
;=> (("5.000000000" "4.898979486" "0.000000000") 4.0 "3.916786027" "5.507991934")
(mapcar '(lambda (e) (cdr (assoc 0 (entget e)))) (list c1 c2))
;=> ("CIRCLE" "CIRCLE")
;; Concentric arcs or circles: no circle of one radius touches both at one place.
(command "_.ARC" "_C" '(20 0) '(23 0) '(20 3))
(setq ia (entlast))
(command "_.ARC" "_C" '(20 0) '(25 0) '(20 5))
(command "_.FILLET" "_R" 1 ia (entlast))
;!! FILLET: the objects are concentric: lispcad does not fillet concentric arcs or circles
(command "_.FILLET" ia c1)
;!! FILLET: no fillet of radius 1 joins these objects
;; The Polyline option: every vertex of a closed square of side 10 with radius 2 becomes two
;; tangent points 2 from the corner; the first carries the quarter-turn arc, bulge
;; tan(pi/8) = 0.414213562 (a left turn, positive).
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 4) (70 . 1) (10 0.0 0.0) (10 10.0 0.0) (10 10.0 10.0) (10 0.0 10.0)))
(setq p (entlast))
(command "_.FILLET" "_R" 2 "_P" p)
(defun verts (e) (vl-remove-if-not '(lambda (g) (= (car g) 10)) (entget e)))
(defun bulges (e) (mapcar '(lambda (g) (r9 (cdr g))) (vl-remove-if-not '(lambda (g) (= (car g) 42)) (entget e))))
(mapcar 'cdr (verts p))
;=> ((0.0 2.0) (2.0 0.0) (8.0 0.0) (10.0 2.0) (10.0 8.0) (8.0 10.0) (2.0 10.0) (0.0 8.0))
(bulges p)
;=> ("0.414213562" "0.000000000" "0.414213562" "0.000000000" "0.414213562" "0.000000000" "0.414213562" "0.000000000")
;; Radius 6 needs 6 of each side at each end: after the corner at (0 0), the corner at
;; (10 0) has 4 left of its first side and is left as it is; so is (0 10) after (10 10).
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 4) (70 . 1) (10 0.0 0.0) (10 10.0 0.0) (10 10.0 10.0) (10 0.0 10.0)))
(setq p (entlast))
(command "_.FILLET" "_R" 6 "_P" p)
(mapcar 'cdr (verts p))
;=> ((0.0 6.0) (6.0 0.0) (10.0 0.0) (10.0 4.0) (4.0 10.0) (0.0 10.0))
;; Two picked adjacent segments of one polyline: the vertex they share. A right turn has a
;; negative bulge.
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 3) (70 . 0) (10 0.0 0.0) (10 10.0 0.0) (10 10.0 -10.0)))
(setq p (entlast))
(command "_.FILLET" "_R" 3 (list p '(5 0)) (list p '(10 -5)))
(mapcar 'cdr (verts p))
;=> ((0.0 0.0) (7.0 0.0) (10.0 -3.0) (10.0 -10.0))
(bulges p)
;=> ("0.000000000" "-0.414213562" "0.000000000" "0.000000000")
(command "_.FILLET" (list p '(1 0)) (list p '(10 -9)))
;!! FILLET: lispcad fillets two adjacent segments of one polyline
;; A flat POLYLINE (open): (10 0) and (10 10) are filleted; (0 10), where an arc segment
;; starts, is left as it is.
(entmake '((0 . "POLYLINE") (66 . 1) (70 . 0)))
(foreach v '(((10 0 0 0)) ((10 10 0 0)) ((10 10 10 0)) ((10 0 10 0) (42 . 1.0)) ((10 0 20 0)))
  (entmake (append '((0 . "VERTEX")) v)))
(entmake '((0 . "SEQEND")))
(setq p (entlast))
(command "_.FILLET" "_R" 1 "_P" p)
(setq v (entnext p) pts nil)
(while (= "VERTEX" (cdr (assoc 0 (entget v))))
  (setq pts (cons (cdr (assoc 10 (entget v))) pts) v (entnext v)))
(reverse pts)
;=> ((0.0 0.0 0.0) (9.0 0.0 0.0) (10.0 1.0 0.0) (10.0 9.0 0.0) (9.0 10.0 0.0) (0.0 10.0 0.0) (0.0 20.0 0.0))
(command "_.FILLET" "_P" c1)
;!! FILLET: the Polyline option fillets 2D polylines, not a CIRCLE
