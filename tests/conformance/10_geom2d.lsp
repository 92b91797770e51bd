;; Point functions: inters, polar, angle, distance, trans (AutoCAD's documented behaviour).
;; inters: onseg omitted or non-nil -> both segments must hold the point.
(inters '(0 0) '(10 10) '(0 10) '(10 0))
;=> (5.0 5.0)
(setq a '(1.0 1.0) b '(9.0 9.0) c '(4.0 1.0) d '(4.0 2.0))
;=> (4.0 2.0)
(inters a b c d)
;=> nil
(inters a b c d T)
;=> nil
(inters a b c d 1)
;=> nil
(inters a b c d nil)
;=> (4.0 4.0)
;; the point at a segment's end counts as on the segment
(inters '(0 0) '(4 0) '(4 -1) '(4 1))
;=> (4.0 0.0)
(inters '(0 0) '(4 0) '(5 -1) '(5 1))
;=> nil
(inters '(0 0) '(4 0) '(5 -1) '(5 1) nil)
;=> (5.0 0.0)
;; parallel and collinear lines never intersect
(inters '(0 0) '(1 1) '(0 1) '(1 2) nil)
;=> nil
(inters '(0 0) '(1 1) '(2 2) '(3 3) nil)
;=> nil
(inters '(0 0) '(2 2) '(1 1) '(3 3))
;=> nil
;; degenerate segment
(inters '(1 1) '(1 1) '(0 0) '(2 2) nil)
;=> nil
;; all four 3D: the lines must meet in 3D, the result is 3D
(inters '(0 0 0) '(10 10 0) '(0 10 0) '(10 0 0))
;=> (5.0 5.0 0.0)
(inters '(0 0 2) '(10 10 2) '(0 10 2) '(10 0 2))
;=> (5.0 5.0 2.0)
(inters '(0 0 0) '(10 10 0) '(0 10 1) '(10 0 1))
;=> nil
(inters '(0 0 0) '(10 10 10) '(0 10 0) '(10 0 10))
;=> (5.0 5.0 5.0)
(inters '(0 0 0) '(1 0 0) '(3 -1 0) '(3 1 0) nil)
;=> (3.0 0.0 0.0)
;; any 2D point: the lines are projected onto the XY plane, the result is 2D
(inters '(0 0 0) '(10 10 0) '(0 10 1) '(10 0 1))
;=> nil
(inters '(0 0 0) '(10 10 0) '(0 10) '(10 0 7))
;=> (5.0 5.0)
(inters '(0 0) '(10 10) '(0 10) '(10 0))
;=> (5.0 5.0)
(inters '(0 0) '(1 2) '(0 1) '(1 0) nil)
;=> (0.333333 0.666667)
(inters '(0 0) '(3 0) '(1 1) '(2 2) nil)
;=> (0.0 0.0)
(inters '(0 0) '(1 0))
;!! too few arguments
(inters '(0 0) '(1 0) '(0 1) '(1 1) nil nil)
;!! too many arguments
(inters '(0 0) '(1 0) 5 '(1 1))
;!! bad argument type: 2D/3D point: 5
;; polar keeps the dimension of its point and the Z of a 3D point
(polar '(1 1 3.5) 0.785398 1.41421)
;=> (2.0 2.0 3.5)
(polar '(1 1) (/ pi 2) 2)
;=> (1.0 3.0)
(polar '(0 0) 0 5)
;=> (5.0 0.0)
(polar '(0 0) pi 1)
;=> (-1.0 1.22465e-16)
(polar '(0 0 0) (/ pi 4) (sqrt 2))
;=> (1.0 1.0 0.0)
(polar '(2 3) 0 -1)
;=> (1.0 3.0)
(polar '(1 2 3 4) 0 1)
;!! bad argument type: 2D/3D point: (1 2 3 4)
(polar '(1 2) "a" 1)
;!! bad argument type: numberp: "a"
;; angle: radians in [0, 2pi), in the XY plane
(angle '(1.0 1.0) '(1.0 4.0))
;=> 1.5708
(angle '(5.0 1.33) '(2.4 1.33))
;=> 3.14159
(angle '(0 0) '(0 -1))
;=> 4.71239
(angle '(0 0) '(1 -1))
;=> 5.49779
(angle '(0 0) '(1 0))
;=> 0.0
(angle '(0 0) '(-1 -1e-20))
;=> 3.14159
(angle '(1 1) '(1 1))
;=> 0.0
(angle '(0 0 0) '(1 1 100))
;=> 0.785398
(angle '(0 0) '(1 1 5))
;=> 0.785398
(equal (angle '(0 0) '(-1 1)) (* 0.75 pi) 1e-12)
;=> T
(angle '(0 0) nil)
;!! bad argument type: 2D/3D point: nil
(angle '(0 0) '(1))
;!! bad argument type: 2D/3D point: (1)
(angle '(0 0) '(1 "2"))
;!! bad argument type: 2D/3D point: (1 "2")
;; distance: 3D when both points are 3D, in the XY plane otherwise
(distance '(1.0 2.5 3.0) '(7.0 2.5 3.0))
;=> 6.0
(distance '(1.0 2.0 0.5) '(3.0 4.0 0.5))
;=> 2.82843
(distance '(0 0 0) '(3 4 12))
;=> 13.0
(distance '(0 0) '(3 4 12))
;=> 5.0
(distance '(0 0 12) '(3 4))
;=> 5.0
(distance '(0 0) '(0 0))
;=> 0.0
(distance 1 2)
;!! bad argument type: 2D/3D point: 1
(distance '(0 0))
;!! too few arguments
;; trans: WCS, UCS and DCS are one frame headless; the result is always 3D
(trans '(1 2) 0 1)
;=> (1.0 2.0 0.0)
(trans '(1 2 3) 1 0)
;=> (1.0 2.0 3.0)
(trans '(1 2 3) 0 2)
;=> (1.0 2.0 3.0)
(trans '(1 2 3) 2 3)
;=> (1.0 2.0 3.0)
(trans '(1 2 3) 1 2 T)
;=> (1.0 2.0 3.0)
;; an extrusion vector is an OCS (DXF's arbitrary-axis algorithm)
(trans '(1 2 3) 0 '(0 0 1))
;=> (1.0 2.0 3.0)
(trans '(1 2 3) 0 '(0 0 -1))
;=> (-1.0 2.0 -3.0)
(trans '(1 2 3) '(0 0 -1) 0)
;=> (-1.0 2.0 -3.0)
(trans '(1 2 3) 0 '(1 0 0))
;=> (2.0 3.0 1.0)
(trans '(1 2 3) 0 '(0 0 5))
;=> (1.0 2.0 3.0)
(equal (trans (trans '(1 2 3) 0 '(1 1 1)) '(1 1 1) 0) '(1.0 2.0 3.0) 1e-12)
;=> T
(equal (distance '(0 0 0) (trans '(1 2 3) 0 '(3 -2 7))) (distance '(0 0 0) '(1 2 3)) 1e-12)
;=> T
(trans '(1 2 3) 0 '(0 1 0) T)
;=> (-1.0 3.0 2.0)
(trans '(1 2) 7 0)
;!! bad argument value: coordinate system code 7 (0 WCS, 1 UCS, 2 DCS, 3 PSDCS)
(trans '(1 2) 0 '(0 0 0))
;!! bad argument value: extrusion vector (0 0 0) is zero
(trans "p" 0 1)
;!! bad argument type: 2D/3D point: "p"
;; an entity name is its OCS (group 210, +Z when absent)
(progn (entmake '((0 . "CIRCLE") (10 1.0 2.0 3.0) (40 . 1.0) (210 0.0 0.0 -1.0))) (setq oc (entlast)) nil)
;=> nil
(trans '(1 2 3) oc 0)
;=> (-1.0 2.0 -3.0)
(trans '(-1 2 -3) 0 oc)
;=> (1.0 2.0 3.0)
(progn (entmake '((0 . "LINE") (10 0 0 0) (11 1 1 0))) (trans '(1 2 3) 0 (entlast)))
;=> (1.0 2.0 3.0)
