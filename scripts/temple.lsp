;;; temple.lsp -- a parametric eyeglass temple, bent as in Zhou, Li & Xue (2007),
;;; "Parametric modeling and curving algorithm of eyeglasses' temple" (paper 004).
;;;
;;;   lispcad run scripts/temple.lsp -o temple.svg -o temple.dxf
;;;   lispcad run scripts/temple.lsp --set L1=145.0 --set BENDANG=35.0 -o big.dxf
;;;   lispcad batch scripts/temple.lsp --vary bench/temple/variants.csv -o out/temple-{row}.dxf
;;;
;;; The straight temple lies along +X from the hinge end at the base point (BASEX, BASEY).
;;; Its outline is a closed quadratic spline through 13 type-value points computed from the
;;; widths below; bend-temple bends it about the centerline (bend toward -Y for a positive
;;; angle) keeping every point's distance from the centerline, and regenerates the spline
;;; within 0.05 mm of the exact bend, smooth (the achieved deviation is BENDDEV).
;;; Layers: CUT (the bent outline, for the laser/CNC), CENTER (the bent centerline:
;;; line, arc, line), NOTES (the parameter values).

;;; ---- parameters: mm and degrees; a value given with --set (or a batch table) wins over
;;; the default, and one outside its range is refused before anything runs.
;;; `lispcad params scripts/temple.lsp` lists them.
(defparam L1 140.0 "total length of the temple along its centerline" 100.0 200.0)
(defparam L2 35.0 "from the far end back to the bend's vertex" 5.0 100.0)
(defparam R 15.0 "bend radius" 1.0 100.0)
(defparam BENDANG 40.0 "bend angle in degrees (ANGLE is a builtin: not used)" 0.0 90.0)
(defparam HINGEW 5.0 "width at the hinge end" 1.0 20.0)
(defparam MINW 3.5 "slimmest width, at 0.7 L1 (the thickness profile)" 1.0 20.0)
(defparam TIPW 7.0 "width of the tip, at 0.9 L1" 1.0 20.0)
(defparam TIPR 2.0 "radius of the rounded ear tip" 0.5 10.0)
(defparam BASEX 0.0 "base point P1 (hinge end of the centerline), X")
(defparam BASEY 0.0 "base point P1, Y")

;; --set L1=140 reads an integer; the geometry wants reals.
(setq L1 (float L1) L2 (float L2) R (float R) BENDANG (float BENDANG)
      HINGEW (float HINGEW) MINW (float MINW) TIPW (float TIPW) TIPR (float TIPR)
      BASEX (float BASEX) BASEY (float BASEY))

(defun dtr (d) (* pi (/ d 180.0)))

;; A point of the straight temple: X along the centerline, Y across it.
(defun tpt (x y) (list (+ BASEX x) (+ BASEY y)))

;; The 15 type-value points of the closed outline, counter-clockwise from the hinge end's
;; lower corner: along the lower edge to the ear tip, round the tip, back along the upper
;; edge. The hinge end is a straight butt of HINGEW: its two corners (where the end meets
;; the edges at a right angle) stay corners, because the spline does not overshoot and so
;; keeps the butt and the first stretch of each edge straight. The widths taper from the
;; hinge to the slimmest point, then swell into the tip; the tip is rounded on a circle of
;; radius TIPR (five points on it: the apex, 40 and 80 degrees either side).
(defun tip-point (deg / a)
  (setq a (dtr deg))
  (tpt (+ (- L1 TIPR) (* TIPR (cos a))) (* TIPR (sin a))))

(defun temple-points (/ h0 hm ht hq)
  (setq h0 (/ HINGEW 2.0)
        hm (/ MINW 2.0)
        ht (/ TIPW 2.0)
        hq (+ hm (* 0.3 (- h0 hm))))
  (list (tpt 0.0 (- h0))
        (tpt (* 0.04 L1) (- h0))
        (tpt (* 0.35 L1) (- hq))
        (tpt (* 0.70 L1) (- hm))
        (tpt (* 0.90 L1) (- ht))
        (tip-point -80.0)
        (tip-point -40.0)
        (tip-point 0.0)
        (tip-point 40.0)
        (tip-point 80.0)
        (tpt (* 0.90 L1) ht)
        (tpt (* 0.70 L1) hm)
        (tpt (* 0.35 L1) hq)
        (tpt (* 0.04 L1) h0)
        (tpt 0.0 h0)))

;; bend-temple itself refuses a bend that would fold the outline (a point of the
;; moved part lying R or more inside the bend), R <= 0, and L or Lp < 0, naming the
;; parameter; in a batch run that row fails and the others go on.

;; A line of text on NOTES below the temple.
(defun note (row str)
  (entmake (list '(0 . "TEXT")
                 '(8 . "NOTES")
                 (list 10 BASEX (- BASEY 15.0 (* 4.0 row)) 0.0)
                 '(40 . 2.5)
                 (cons 1 str))))

;;; ---- geometry ----
(setq theta (dtr BENDANG)
      base (list BASEX BASEY)
      pts (temple-points)
      outline (spline pts T)
      ;; The smooth variant: refitted within 0.05 mm of the exact bend, which rounds off the
      ;; exact bend's slight corners (up to 3 degrees) where the outline enters and leaves the
      ;; arc; BENDDEV reports the deviation.
      bent (bend-temple outline L1 L2 R theta base 0.05))

;;; ---- drawing ----
(layer "CUT" 1)
(draw bent)

(layer "CENTER" 5)
(foreach piece (temple-centerline L1 L2 R theta base)
  (draw piece))

(layer "NOTES" 7)
(note 0 (strcat "L1 " (rtos L1 2 1) "  L2 " (rtos L2 2 1)
                "  R " (rtos R 2 1) "  BEND " (rtos BENDANG 2 1) " deg"))
(note 1 (strcat "HINGE " (rtos HINGEW 2 2) "  MIN " (rtos MINW 2 2)
                "  TIP " (rtos TIPW 2 2)))
(note 2 (strcat "outline length " (rtos (curve-length bent) 2 2)
                "  BENDDEV " (rtos (getvar "BENDDEV") 1 2)))
(princ)
