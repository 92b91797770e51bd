;; ssget by area (AutoLISP Reference, ssget): "W" window = entirely inside, "C" crossing =
;; inside or crossing the boundary, "WP"/"CP" the same with a polygon, "F" fence = crossed
;; by the open polyline; filters apply on top. Expected sets worked out by hand.
(defun names (ss / i out)
  (setq i 0)
  (if ss (repeat (sslength ss) (setq out (cons (cdr (assoc 5 (entget (ssname ss i)))) out) i (1+ i))))
  (reverse out))
(entmake '((0 . "LINE") (10 1 1 0) (11 4 1 0)))
(entmake '((0 . "LINE") (10 4 4 0) (11 8 4 0)))
(entmake '((0 . "CIRCLE") (10 2.5 2.5 0) (40 . 1.0)))
;; Around the whole window: neither inside nor crossing it.
(entmake '((0 . "CIRCLE") (10 2.5 2.5 0) (40 . 10.0)))
;; Its extremes (0.5 0) (4.5 0) (2.5 2) are inside.
(entmake '((0 . "ARC") (10 2.5 0 0) (40 . 2.0) (50 . 0.0) (51 . 3.141592653589793)))
(entmake '((0 . "POINT") (10 9 9 0)))
;; Both ends outside, crossing the window.
(entmake '((0 . "LINE") (10 -1 2 0) (11 6 2 0)))
;; Every extreme outside; the circle cuts the window's corner (5 5) (distance 2.12 < 2.2).
(entmake '((0 . "CIRCLE") (10 6.5 6.5 0) (40 . 2.2)))
;; A bulged segment from (4.5 1) to (4.5 3) through (5.5 2): out of the window on the right.
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 2) (70 . 0) (10 4.5 1.0) (42 . 1.0) (10 4.5 3.0)))
(names (ssget "W" '(0 0) '(5 5)))
;=> ("100" "102" "104")
(names (ssget "_W" '(5 5 0) '(0 0 0)))
;=> ("100" "102" "104")
(names (ssget "C" '(0 0) '(5 5)))
;=> ("100" "101" "102" "104" "106" "107" "108")
(names (ssget "C" '(0 0) '(5 5) '((0 . "CIRCLE"))))
;=> ("102" "107")
(ssget "W" '(20 20) '(30 30))
;=> nil
;; An L-shaped polygon (concave): the arc touches its inner edge y = 2, so it is not
;; entirely inside; the circle's right half is in the notch.
(setq L '((0 0) (5 0) (5 2) (2 2) (2 5) (0 5)))
(names (ssget "WP" L))
;=> ("100")
(names (ssget "CP" L))
;=> ("100" "102" "104" "106" "108")
(names (ssget "CP" L '((0 . "LINE"))))
;=> ("100" "106")
;; A fence along y = 2.7: the small circle and the bulge (at x = 4.5 + sqrt(0.51)).
(names (ssget "F" '((-2 2.7) (10 2.7))))
;=> ("102" "108")
(names (ssget "F" '((-2 2.7) (3 2.7) (3 -5))))
;=> ("100" "102" "104" "106")
(ssget "W" '(0 0))
;!! ssget: this selection mode needs points
(ssget "WP" '((0 0) (1 1)))
;!! ssget: mode "WP" needs a list of at least 3 points
(ssget "C" '(0 0) "x")
;!! ssget: bad point: "x"
