;;; intersections.lsp -- a walkthrough of lispcad's intersection forms.
;;;
;;;   lispcad run scripts/intersections.lsp -o intersections.svg
;;;
;;; Each step prints what it found and draws the curves (layer GEOM) and the hits as small
;;; circles (layer HITS), so the SVG shows every answer.

(defun show (label value)
  (princ (strcat "\n" label ": " (vl-prin1-to-string value)))
  value)

(defun mark (pts)
  (foreach p pts
    (if (= (type p) 'LIST) (draw (circle p 0.6) "HITS"))))

(layer "HITS" 1)
(layer "GEOM" 7)

;; 1. A line through a circle: two crossings, sorted along the line.
(setq c1 (draw (circle '(10 10) 6.0))
      l1 (draw (line '(0 8) '(22 12))))
(mark (show "line x circle" (intersect l1 c1)))

;; 2. Tangency is reported as such.
(setq l2 (draw (line '(0 16) '(20 16))))
(show "tangent line, info" (intersect-info l2 c1))

;; 3. Two circles 2 - 1e-9 apart meet at two points 6.3e-5 apart: both are kept.
(setq a (circle '(40 10) 1.0)
      b (circle (list (+ 42.0 -1e-9) 10.0) 1.0))
(draw a) (draw b)
(show "near-tangent circles" (length (intersect a b)))

;; 4. The papers' "nearest to the pick point".
(mark (list (show "nearest to (16 14)" (intersect l1 c1 '(16 14)))))

;; 5. A quadratic spline against an arc, and an overlap between two arcs of one circle.
(setq s1 (draw (spline '((0 30) (10 40) (20 28) (30 42) (40 30))))
      a1 (draw (arc '(20 30) 9.0 0.0 pi)))
(mark (show "spline x arc" (intersect s1 a1)))
(setq a2 (arc '(20 30) 9.0 (/ pi 2) (* 1.5 pi)))
(show "overlapping arcs" (intersect a1 a2))

;; 6. Circles in different planes still meet.
(setq v (circle '(60 10 0) 5.0 '(0 1 0))
      h (circle '(60 10 0) 5.0 '(0 0 1)))
(show "non-coplanar circles" (intersect v h))

;; 7. A curve against a surface (paper 002's closed forms).
(setq cyl (cylinder-surface '(60 35 0) '(0 0 1) 4.0 10.0))
(show "line x cylinder" (intersect (line '(50 35 5) '(70 35 5)) cyl))
(princ)
