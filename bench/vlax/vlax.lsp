;; vlax-curve benchmark (issue 12): 100,000 vlax-curve-getDistAtParam / getPointAtDist calls,
;; half on a 40-vertex bulged LWPOLYLINE, half on a 30-point cubic SPLINE, as published
;; routines run them (the entity name is passed on every call). Prints a checksum that
;; bench/vlax/vlax_ezdxf.py prints too.
(defun make-pline (/ pts i)
  (setq i 0 pts nil)
  (repeat 40
    (setq pts (cons (cons 42 (if (= (rem i 3) 0) 0.25 0.0))
                (cons (list 10 (* i 2.0) (* 3.0 (sin (* i 0.4)))) pts))
          i (1+ i)))
  (entmake (append '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 40) (70 . 0))
                   (reverse pts)))
  (entlast))
(defun make-spline (/ i ctrl knots)
  (setq i 0 ctrl nil)
  (repeat 30
    (setq ctrl (cons (list 10 (* i 1.5) (* 4.0 (cos (* i 0.3))) (* 0.5 (sin (* i 0.7)))) ctrl)
          i (1+ i)))
  (setq knots '((40 . 0.0) (40 . 0.0) (40 . 0.0) (40 . 0.0)) i 1)
  (repeat 26 (setq knots (append knots (list (cons 40 (float i)))) i (1+ i)))
  (setq knots (append knots '((40 . 27.0) (40 . 27.0) (40 . 27.0) (40 . 27.0))))
  (entmake (append '((0 . "SPLINE") (100 . "AcDbEntity") (100 . "AcDbSpline") (70 . 8) (71 . 3) (72 . 34) (73 . 30))
                   knots (reverse ctrl)))
  (entlast))
(setq-default 'n 25000)
(setq pl (make-pline) sp (make-spline) sum 0.0)
(foreach e (list pl sp)
  (setq end (vlax-curve-getEndParam e)
        len (vlax-curve-getDistAtParam e end)
        i 0)
  (repeat n
    (setq u (* end (/ (rem (* i 7919) 25000) 25000.0))
          sum (+ sum (vlax-curve-getDistAtParam e u))
          p (vlax-curve-getPointAtDist e (* len (/ (rem (* i 7927) 25000) 25000.0)))
          sum (+ sum (car p) (cadr p))
          i (1+ i))))
(princ (strcat "checksum " (rtos sum 2 6) "\n"))
(princ)
