;; vlax-curve-* on entities, VLA objects and CURVE values (AutoCAD's parameters per type).
(entmake '((0 . "LINE") (10 0.0 0.0 0.0) (11 3.0 4.0 0.0)))
(setq l (entlast))
(list (vlax-curve-getStartParam l) (vlax-curve-getEndParam l))
;=> (0.0 5.0)
(vlax-curve-getPointAtParam l 2.5)
;=> (1.5 2.0 0.0)
(vlax-curve-getPointAtParam l 6.0)
;=> nil
(vlax-curve-getFirstDeriv l 1.0)
;=> (0.6 0.8 0.0)
(vlax-curve-getSecondDeriv l 1.0)
;=> (0.0 0.0 0.0)
(vlax-curve-getParamAtPoint l '(3.0 4.0 0.0))
;=> 5.0
(vlax-curve-getParamAtPoint l '(3.0 4.1 0.0))
;=> nil
(vlax-curve-getClosestPointTo l '(6.0 8.0 0.0))
;=> (3.0 4.0 0.0)
(vlax-curve-getClosestPointTo l '(6.0 8.0 0.0) T)
;=> (6.0 8.0 0.0)
(vlax-curve-getClosestPointToProjection l '(6.0 8.0 5.0) '(0 0 1) T)
;=> (6.0 8.0 0.0)
(list (vlax-curve-isClosed l) (vlax-curve-isPeriodic l) (vlax-curve-isPlanar l) (vlax-curve-getArea l))
;=> (nil nil T 0.0)
(entmake '((0 . "CIRCLE") (10 1.0 1.0 0.0) (40 . 2.0)))
(setq c (entlast))
(list (vlax-curve-getEndParam c) (vlax-curve-isClosed c) (vlax-curve-isPeriodic c))
;=> (6.28319 T T)
(vlax-curve-getPointAtParam c (/ pi 2))
;=> (1.0 3.0 0.0)
(vlax-curve-getDistAtParam c pi)
;=> 6.28319
(vlax-curve-getArea c)
;=> 12.5664
(vlax-curve-getStartPoint c)
;=> (3.0 1.0 0.0)
(entmake '((0 . "ARC") (10 0.0 0.0 0.0) (40 . 1.0) (50 . 0.0) (51 . 3.14159265358979)))
(setq a (entlast))
(vlax-curve-getEndParam a)
;=> 3.14159
(vlax-curve-getParamAtDist a (/ pi 2))
;=> 1.5708
(vlax-curve-getArea a)
;=> 1.5708
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 4) (70 . 1) (10 0.0 0.0) (10 10.0 0.0) (10 10.0 5.0) (10 0.0 5.0)))
(setq p (entlast))
(list (vlax-curve-getEndParam p) (vlax-curve-getDistAtParam p 4) (vlax-curve-getArea p))
;=> (4.0 30.0 50.0)
(vlax-curve-getPointAtDist p 12.5)
;=> (10.0 2.5 0.0)
(vlax-curve-getParamAtPoint p '(5.0 5.0))
;=> 2.5
(vlax-curve-getDistAtPoint p '(0.0 2.0))
;=> 28.0
(vlax-curve-getFirstDeriv p 1.5)
;=> (0.0 5.0 0.0)
(vlax-curve-getPointAtDist p 31.0)
;=> nil
(setq s (spline '((0 0) (1 1) (2 0) (3 1))))
(vlax-curve-getEndParam s)
;=> 6.0
(vlax-curve-getEndPoint s)
;=> (3.0 1.0 0.0)
(vlax-curve-getEndParam (bspline '((0 0) (1 2) (3 3) (5 0)) 3 '(0 0 0 0 2.5 2.5 2.5 2.5)))
;=> 2.5
(entmake '((0 . "POINT") (10 0 0 0)))
(vlax-curve-getStartParam (entlast))
;!! bad argument type: curvep <Entity name: 104>
;; ELLIPSE (a CURVE value until the drawing has ELLIPSE entities): the parameter is the angle.
(setq el (ellipse '(0 0 0) '(4 0 0) 0.5))
;=> #<ELLIPSE (0 0 0) major (4 0 0) ratio 0.5>
(list (vlax-curve-getStartParam el) (vlax-curve-getEndParam el) (vlax-curve-isClosed el) (vlax-curve-isPeriodic el))
;=> (0.0 6.28319 T T)
(vlax-curve-getPointAtParam el pi)
;=> (-4.0 2.44929e-16 0.0)
(vlax-curve-getArea el)
;=> 25.1327
(vlax-curve-getFirstDeriv el 0.0)
;=> (0.0 2.0 0.0)
(vlax-curve-getParamAtPoint el '(0.0 -2.0 0.0))
;=> 4.71239
(intersect el (line '(-10 0 0) '(10 0 0)))
;=> ((4.0 0.0 0.0) (-4.0 2.44929e-16 0.0))
(ellipse '(0 0 0) '(0 0 1) 0.5)
;!! major axis: must be perpendicular to the normal
;; A changed entity is measured anew (the measures are cached per unchanged entity).
(entmake '((0 . "LINE") (10 0.0 0.0 0.0) (11 3.0 4.0 0.0)))
(setq l2 (entlast))
(vlax-curve-getDistAtParam l2 (vlax-curve-getEndParam l2))
;=> 5.0
(entmod (subst '(11 6.0 8.0 0.0) (assoc 11 (entget l2)) (entget l2)))
(list (vlax-curve-getEndParam l2) (vlax-curve-getPointAtDist l2 10.0))
;=> (10.0 (6.0 8.0 0.0))
