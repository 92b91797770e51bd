;; Surfaces and meshes (papers 001-003).
(setq cyl (cylinder-surface '(0 0 0) '(0 0 1) 2.0 10.0))
(type cyl)
;=> SURFACE
cyl
;=> #<SURFACE CYLINDER R2 H10>
(surface-area cyl)
;=> 125.664
(intersect (line '(-5 0 5) '(5 0 5)) cyl)
;=> ((-2.0 0.0 5.0) (2.0 0.0 5.0))
(intersect (line '(-5 0 5) '(5 0 5)) cyl '(1 0 5))
;=> (2.0 0.0 5.0)
(intersect (line '(-5 2 5) '(5 2 5)) cyl)
;=> ((0.0 2.0 5.0))
(intersect (line '(-5 3 5) '(5 3 5)) cyl)
;=> nil
(setq pl (plane-surface (pline '((0 0) (10 0) (10 10) (0 10)) t)))
(surface-area pl)
;=> 100.0
(intersect (line '(5 5 -1) '(5 5 1)) pl)
;=> ((5.0 5.0 0.0))
(equal (intersect (circle '(5 5 0) 3 '(1 0 0)) pl) '((5.0 8.0 0.0) (5.0 2.0 0.0)) 1e-12)
;=> T
(setq sec (surface-section cyl '(0 0 5) '(0 0 1)))
(length sec)
;=> 1
(curve-closed-p (car sec))
;=> T
(setq m (mesh-surface (sphere-surface '(0 0 0) 5.0) 0.01))
(type m)
;=> MESH
(< (abs (- (surface-area m) (* 4 pi 25))) 0.5)
;=> T
(setq m2 (mesh-surface (sphere-surface '(6 0 0) 5.0) 0.01))
(setq loops (surface-intersect m m2))
(length loops)
;=> 1
(curve-closed-p (car loops))
;=> T
(setq half (trim-surface m (mesh-surface (plane-surface (pline '((-9 -9 0) (9 -9 0) (9 9 0) (-9 9 0)) t))) '(0 0 5)))
(< (abs (- (surface-area half) (/ (surface-area m) 2))) 0.5)
;=> T
(setq sq (mesh-surface (plane-surface (pline '((0 0) (10 0) (10 10) (0 10)) t))))
(length (surface-corners sq))
;=> 4
;; four strips of 10 x 1 and four quarter-disc fans at the convex corners
(< (abs (- (surface-area (extend-surface sq 1.0)) (+ 140.0 pi))) 0.05)
;=> T
(length (surface-boundary sq))
;=> 1
(surface-section 1 '(0 0 0) '(0 0 1))
;!! bad argument type: surfacep 1
;; draw, bbox and move take parametric surfaces through their mesh at CHORDTOL
(bbox (sphere-surface '(0 0 0) 1.0))
;=> ((-1.0 -1.0 -1.0) (1.0 1.0 1.0))
(type (move cyl '(1 0 0)))
;=> MESH
(type (draw cyl))
;=> SURFACE
