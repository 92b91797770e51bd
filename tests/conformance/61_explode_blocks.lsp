;; EXPLODE of block references (issue 12): one level. A nested block reference becomes a
;; block reference, its point, scale and rotation composed with the outer ones; an ATTDEF
;; becomes an ATTDEF showing its tag; the reference's ATTRIB values go with it. A
;; non-uniform scale maps each entity exactly: circles become ellipses, arcs (and polyline
;; arc segments) elliptical arcs. Values worked by hand below.
(defun r6 (x) (rtos x 2 6))
(defun g (e c) (cdr (assoc c (entget e))))
(entmake '((0 . "BLOCK") (2 . "INNER") (10 0 0 0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 1 0 0)))
(entmake '((0 . "ATTDEF") (10 0 1 0) (40 . 0.5) (1 . "d") (2 . "IT") (3 . "p") (70 . 0)))
(entmake '((0 . "ENDBLK")))
(entmake '((0 . "BLOCK") (2 . "OUTER") (10 1 0 0)))
(entmake '((0 . "CIRCLE") (10 1 0 0) (40 . 1.0)))
(entmake (list '(0 . "ARC") '(10 3 0 0) '(40 . 1.0) '(50 . 0.0) (cons 51 (/ pi 2))))
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 3) (70 . 0) (10 0.0 0.0) (42 . 1.0) (10 2.0 0.0) (10 2.0 2.0)))
(entmake '((0 . "ATTDEF") (10 0 2 0) (40 . 0.5) (1 . "def") (2 . "TAG") (3 . "p") (70 . 0)))
(entmake (list '(0 . "INSERT") '(2 . "INNER") '(66 . 1) '(10 5 0 0) (cons 50 (/ pi 6))))
(entmake '((0 . "ATTRIB") (10 5 1 0) (40 . 0.5) (1 . "in") (2 . "IT") (70 . 0)))
(entmake '((0 . "SEQEND")))
(entmake '((0 . "ENDBLK")))
;; Uniform: scale 2, turned 90 degrees, at (10 10); a block point p goes to
;; (10 10) + 2 * rot90(p - (1 0)).
(entmake (list '(0 . "INSERT") '(2 . "OUTER") '(66 . 1) '(10 10 10 0) '(41 . 2.0) '(42 . 2.0) '(43 . 2.0) (cons 50 (/ pi 2))))
(entmake '((0 . "ATTRIB") (10 6 10 0) (40 . 1.0) (1 . "gone") (2 . "TAG") (70 . 0)))
(entmake '((0 . "SEQEND")))
(setq ref (entlast))
(command "_.EXPLODE" ref "")
(entget ref)
;=> nil
(setq all (ssget "X"))
(setq types nil i 0)
(repeat (sslength all) (setq types (cons (g (ssname all i) 0) types) i (1+ i)))
(reverse types)
;=> ("CIRCLE" "ARC" "LWPOLYLINE" "ATTDEF" "INSERT")
;; The ATTDEF (0 2) goes to (10 10) + 2 * rot90(-1 2) = (6 8), height 1, turned 90 degrees;
;; it shows its tag and default, not the ATTRIB's value "gone".
(setq ad (ssname (ssget "X" '((0 . "ATTDEF"))) 0))
(list (g ad 2) (g ad 1) (g ad 10) (g ad 40) (r6 (g ad 50)))
;=> ("TAG" "def" (6.0 8.0 0.0) 1.0 "1.570796")
;; The nested reference: at (10 10) + 2 * rot90(4 0) = (10 18), scale 2, rotation
;; 30 + 90 = 120 degrees; its ATTRIB (5 1) goes to (10 10) + 2 * rot90(4 1) = (8 18).
(setq ni (ssname (ssget "X" '((0 . "INSERT"))) 0))
(list (g ni 2) (mapcar 'r6 (g ni 10)) (g ni 41) (g ni 42) (r6 (g ni 50)))
;=> ("INNER" ("10.000000" "18.000000" "0.000000") 2.0 2.0 "2.094395")
(setq na (entget (entnext ni)))
(list (cdr (assoc 1 na)) (mapcar 'r6 (cdr (assoc 10 na))) (cdr (assoc 40 na)))
;=> ("in" ("8.000000" "18.000000" "0.000000") 1.0)
;; Non-uniform: scale (2 1 1) at (10 10), no rotation; p goes to (10 + 2(px - 1), 10 + py).
;; The circle (1 0) r1 becomes the ellipse at (10 10) with major axis (2 0 0), ratio 1/2;
;; the arc (3 0) r1 from 0 to pi/2 the elliptical arc at (14 10), parameters 0 to pi/2; the
;; polyline's half circle from (0 0) to (2 0) (bulge 1: centre (1 0), angles pi to 2 pi)
;; the elliptical arc at (10 10) from pi to 2 pi, and its straight segment the line
;; (12 10)-(12 12). The nested reference turned 30 degrees would be skewed: an error.
(entmake '((0 . "BLOCK") (2 . "STRETCH") (10 1 0 0)))
(entmake '((0 . "CIRCLE") (10 1 0 0) (40 . 1.0)))
(entmake (list '(0 . "ARC") '(10 3 0 0) '(40 . 1.0) '(50 . 0.0) (cons 51 (/ pi 2))))
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 3) (70 . 0) (10 0.0 0.0) (42 . 1.0) (10 2.0 0.0) (10 2.0 2.0)))
(entmake '((0 . "INSERT") (2 . "INNER") (10 5 0 0)))
(entmake '((0 . "ENDBLK")))
(command "_.ERASE" (ssget "X") "")
(entmake '((0 . "INSERT") (2 . "STRETCH") (10 10 10 0) (41 . 2.0) (42 . 1.0) (43 . 1.0)))
(setq ref (entlast))
(command "_.EXPLODE" ref "")
(defun ell (e) (list (g e 10) (g e 11) (g e 40) (r6 (g e 41)) (r6 (g e 42))))
(setq el (ssget "X" '((0 . "ELLIPSE"))))
(ell (ssname el 0))
;=> ((10.0 10.0 0.0) (2.0 0.0 0.0) 0.5 "0.000000" "6.283185")
(ell (ssname el 1))
;=> ((14.0 10.0 0.0) (2.0 0.0 0.0) 0.5 "0.000000" "1.570796")
(ell (ssname el 2))
;=> ((10.0 10.0 0.0) (2.0 0.0 0.0) 0.5 "3.141593" "0.000000")
(setq ln (ssname (ssget "X" '((0 . "LINE"))) 0))
(list (g ln 10) (g ln 11))
;=> ((12.0 10.0 0.0) (12.0 12.0 0.0))
(setq ni (ssname (ssget "X" '((0 . "INSERT"))) 0))
(list (g ni 2) (g ni 10) (g ni 41) (g ni 42))
;=> ("INNER" (18.0 10.0 0.0) 2.0 1.0)
(entmake '((0 . "INSERT") (2 . "OUTER") (10 0 0 0) (41 . 2.0) (42 . 1.0) (43 . 1.0)))
(command "_.EXPLODE" (entlast) "")
;!! EXPLODE: the nested reference to block "INNER" would be skewed by the non-uniform scale
