;;; temple-from-dxf.lsp -- bend a temple outline drawn in another CAD program.
;;;
;;;   lispcad run scripts/temple-from-dxf.lsp --open scripts/temple-outline.dxf -o bent.dxf
;;;   lispcad run scripts/temple-from-dxf.lsp --open my-outline.dxf --set BENDANG=35.0 -o bent.svg
;;;
;;; The drawing opened with --open holds the straight outline of a temple: a closed
;;; LWPOLYLINE or SPLINE on layer OUTLINE (set OUTLINE to use another layer), the hinge end
;;; at the base point and the temple along +X. Its vertices (a spline's fit points, else
;;; its control points) are the type-value points of the temple paper's closed quadratic
;;; spline, which bend-temple bends. The bent outline goes on layer CUT; everything else of
;;; the drawing is kept as it was, so saving as DXF writes the designer's file back with
;;; the bent outline added.

(if (not OUTLINE) (setq OUTLINE "OUTLINE"))
(if (not L2) (setq L2 35.0))           ; from the far end back to the bend's vertex
(if (not R) (setq R 15.0))             ; bend radius
(if (not BENDANG) (setq BENDANG 40.0)) ; bend angle in degrees
(if (not BASEX) (setq BASEX 0.0))      ; hinge end of the centerline
(if (not BASEY) (setq BASEY 0.0))
(setq L2 (float L2) R (float R) BENDANG (float BENDANG) BASEX (float BASEX) BASEY (float BASEY))

;; The values of every `code` group of a DXF list, in order.
(defun groups-of (code ed / out)
  (foreach g ed (if (= (car g) code) (setq out (cons (cdr g) out))))
  (reverse out))

(setq ss (ssget "X" (list '(-4 . "<OR") '(0 . "LWPOLYLINE") '(0 . "SPLINE") '(-4 . "OR>")
                          (cons 8 OUTLINE))))
(if (not ss)
  (progn (princ (strcat "no LWPOLYLINE or SPLINE on layer " OUTLINE)) (exit)))
(setq ed (entget (ssname ss 0)))
(setq pts (if (= (cdr (assoc 0 ed)) "LWPOLYLINE")
            (groups-of 10 ed)
            (or (groups-of 11 ed) (groups-of 10 ed))))
;; The temple's length: from the hinge end to the farthest vertex, unless given.
(if (not L1)
  (setq L1 (apply 'max (mapcar '(lambda (p) (- (car p) BASEX)) pts))))
(setq L1 (float L1))

(setq outline (spline (mapcar '(lambda (p) (list (car p) (cadr p))) pts) T)
      bent (bend-temple outline L1 L2 R (* pi (/ BENDANG 180.0)) (list BASEX BASEY)))

(layer "CUT" 1)
(draw bent)
(princ (strcat "bent " (itoa (length pts)) "-point outline, L1 " (rtos L1 2 1)
               ", outline length " (rtos (curve-length bent) 2 2)))
(princ)
