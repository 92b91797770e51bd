;; Routines in the style of published ones (tests/routines/*.lsp) on a drawing made with
;; entmake: expected values by hand (exact geometry).
(load "tests/routines/total_length.lsp")
(load "tests/routines/divide_curve.lsp")
(load "tests/routines/reverse_pline.lsp")
(load "tests/routines/list_intersections.lsp")
(entmake '((0 . "LINE") (10 0.0 0.0 0.0) (11 10.0 0.0 0.0)))
(entmake '((0 . "CIRCLE") (10 5.0 0.0 0.0) (40 . 2.0)))
(entmake '((0 . "ARC") (10 0.0 0.0 0.0) (40 . 4.0) (50 . 0.0) (51 . 1.5707963267948966)))
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 3) (70 . 0) (10 0.0 -3.0) (42 . 0.0) (10 6.0 -3.0) (42 . 1.0) (10 6.0 3.0) (42 . 0.0)))
(setq pl (entlast))
;; 10 + 4π + 2π + 6 + 3π = 16 + 9π
(rtos (c:tlen) 2 9)
;=> "44.274333882"
(rtos (+ 16 (* 9 pi)) 2 9)
;=> "44.274333882"
(divpts pl 4)
;=> ((3.85619 -3.0 0.0) (7.62091 -2.52441 0.0) (8.87865 0.844619 0.0))
(sslength (ssget "X" '((0 . "POINT"))))
;=> 3
(revpl pl)
(mapcar 'cdr (vl-remove-if-not '(lambda (g) (member (car g) '(10 42))) (entget pl)))
;=> ((6.0 3.0) -1.0 (6.0 -3.0) -0.0 (0.0 -3.0) -0.0)
(vlax-curve-getStartPoint pl)
;=> (6.0 3.0 0.0)
(< (distance (vlax-curve-getPointAtParam pl 0.5) '(9.0 0.0 0.0)) 1e-12)
;=> T
(rtos (vlax-curve-getDistAtParam pl 2) 2 9)
;=> "15.424777961"
;; line/circle 2, line/arc 1 (the arc's start), line/polyline 1, circle/arc 1.
(length (list-intersections))
;=> 5
(car (list-intersections))
;=> (3.0 0.0 0.0)
