;; entget → entmake round trips: every kind comes back with the same groups (less name,
;; handle and owner), including OCS circles and arcs, elevated LWPOLYLINEs and 3D POLYLINEs.
(defun strip (l) (vl-remove-if '(lambda (g) (member (car g) '(-1 5 330 -2))) l))
(defun copy-entity (e / v)
  (entmake (strip (entget e)))
  (if (= (cdr (assoc 0 (entget e))) "POLYLINE")
    (progn
      (setq v (entnext e))
      (while (/= (cdr (assoc 0 (entget v))) "SEQEND")
        (entmake (strip (entget v)))
        (setq v (entnext v)))
      (entmake (strip (entget v)))))
  (entlast))
(defun same-after-copy (e / c)
  (setq c (copy-entity e))
  (and (not (eq c e)) (equal (strip (entget e)) (strip (entget c)) 1e-12)))
(defun vertices (e / v out)
  (setq v (entnext e))
  (while (= (cdr (assoc 0 (entget v))) "VERTEX")
    (setq out (cons (cdr (assoc 10 (entget v))) out) v (entnext v)))
  (reverse out))
(entmake '((0 . "LINE") (8 . "A") (62 . 2) (10 0 0 0) (11 1 2 3)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "CIRCLE") (10 1 2 3) (40 . 4.0) (210 0.6 0 0.8)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "ARC") (10 1 2 0) (40 . 4.0) (50 . 1.0) (51 . 4.0) (210 0 0 -1)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "POINT") (10 1 2 3)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "LWPOLYLINE") (90 . 3) (70 . 1) (38 . 5.0) (10 0 0) (42 . 0.25) (10 4 0) (10 4 4) (210 0 1 0)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "SPLINE") (71 . 2) (10 0 0 0) (10 1 2 0) (10 3 2 1) (41 . 1.0) (41 . 0.5) (41 . 1.0)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "SPLINE") (11 0 0 0) (11 1 2 0) (11 3 2 0) (11 5 0 0)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "3DFACE") (10 0 0 0) (11 1 0 0) (12 1 1 1) (13 0 1 1)))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "TEXT") (10 1 1 0) (40 . 2.0) (1 . "x") (50 . 0.5) (7 . "Standard")))
(same-after-copy (entlast))
;=> T
(entmake '((0 . "POLYLINE") (70 . 8)))
(entmake '((0 . "VERTEX") (10 0 0 0) (70 . 32)))
(entmake '((0 . "VERTEX") (10 1 0 1) (70 . 32)))
(entmake '((0 . "VERTEX") (10 1 1 2) (70 . 32)))
(entmake '((0 . "SEQEND")))
(setq p (entlast))
(same-after-copy p)
;=> T
(vertices (entlast))
;=> ((0.0 0.0 0.0) (1.0 0.0 1.0) (1.0 1.0 2.0))
(entmake '((0 . "POLYLINE") (70 . 1) (10 0 0 2.5)))
(entmake '((0 . "VERTEX") (10 0 0)))
(entmake '((0 . "VERTEX") (10 3 0) (42 . -0.5)))
(entmake '((0 . "SEQEND")))
(same-after-copy (entlast))
;=> T
(vertices (entlast))
;=> ((0.0 0.0 2.5) (3.0 0.0 2.5))
