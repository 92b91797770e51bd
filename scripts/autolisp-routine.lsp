;;; autolisp-routine.lsp -- an AutoLISP routine as it would run inside AutoCAD, run headless.
;;;
;;;   lispcad run scripts/autolisp-routine.lsp -o flange.dxf
;;;
;;; C:FLANGE draws a square flange plate with rounded corners, a centre bore and a ring of
;;; bolt holes. It uses the classic AutoLISP interface only: tblsearch/entmake for layers and
;;; the outline, command for circles, lines and layer switching, ssget to check the result,
;;; and an *error* handler that restores the system variables it changed.

(defun flange:make-layers (/ spec)
  ;; (name colour) for every layer the routine draws on; entmake only the missing ones.
  (foreach spec '(("FLANGE-OUTLINE" 7) ("FLANGE-HOLES" 1) ("FLANGE-CENTER" 4) ("FLANGE-NOTES" 3))
    (if (not (tblsearch "LAYER" (car spec)))
      (entmake
        (list '(0 . "LAYER")
              '(100 . "AcDbSymbolTableRecord")
              '(100 . "AcDbLayerTableRecord")
              (cons 2 (car spec))
              '(70 . 0)
              (cons 62 (cadr spec))
              '(6 . "Continuous"))))))

(defun flange:rounded-square (size r / h b)
  ;; A closed LWPOLYLINE centred on the origin; each corner is a quarter arc, whose bulge is
  ;; tan(90 deg / 4).
  (setq h (/ size 2.0)
        b (/ (sin (/ pi 8.0)) (cos (/ pi 8.0))))
  (entmake
    (list '(0 . "LWPOLYLINE")
          '(100 . "AcDbEntity")
          '(8 . "FLANGE-OUTLINE")
          '(100 . "AcDbPolyline")
          '(90 . 8)
          '(70 . 1)
          (list 10 (- r h) (- h))      '(42 . 0.0)
          (list 10 (- h r) (- h))      (cons 42 b)
          (list 10 h (- r h))          '(42 . 0.0)
          (list 10 h (- h r))          (cons 42 b)
          (list 10 (- h r) h)          '(42 . 0.0)
          (list 10 (- r h) h)          (cons 42 b)
          (list 10 (- h) (- h r))      '(42 . 0.0)
          (list 10 (- h) (- r h))      (cons 42 b))))

(defun c:flange (/ *error* old-echo old-layer size corner bore pcd nbolt hole i a p ss ext)
  (defun *error* (msg)
    (if old-echo (setvar "CMDECHO" old-echo))
    (if (and old-layer (tblsearch "LAYER" old-layer)) (command "_.-LAYER" "_S" old-layer ""))
    (princ (strcat "\nC:FLANGE failed: " msg))
    (princ))
  (setq old-echo  (getvar "CMDECHO")
        old-layer (getvar "CLAYER"))
  (setvar "CMDECHO" 0)
  ;; Plate 120 x 120, corner radius 10, bore 50, six M10 clearance holes on a 90 pitch circle.
  (setq size 120.0 corner 10.0 bore 25.0 pcd 90.0 nbolt 6 hole 5.5
        ext (+ (/ size 2.0) 5.0))
  (flange:make-layers)
  (flange:rounded-square size corner)
  (command "_.-LAYER" "_S" "FLANGE-OUTLINE" "")
  (command "_.CIRCLE" '(0.0 0.0) bore)
  (command "_.-LAYER" "_S" "FLANGE-HOLES" "")
  (setq i 0)
  (repeat nbolt
    (setq a (* i (/ (* 2.0 pi) nbolt))
          p (list (* (/ pcd 2.0) (cos a)) (* (/ pcd 2.0) (sin a))))
    (command "_.CIRCLE" p hole)
    (setq i (1+ i)))
  ;; Centre lines and the pitch circle.
  (command "_.-LAYER" "_S" "FLANGE-CENTER" "")
  (command "_.LINE" (list (- ext) 0.0) (strcat "@" (rtos (* 2.0 ext) 2 4) ",0") "")
  (command "_.LINE" (list 0.0 (- ext)) (strcat "@" (rtos (* 2.0 ext) 2 4) "<90") "")
  (entmake (list '(0 . "CIRCLE") '(8 . "FLANGE-CENTER") '(10 0.0 0.0 0.0) (cons 40 (/ pcd 2.0))))
  (entmake
    (list '(0 . "TEXT") '(8 . "FLANGE-NOTES")
          (list 10 (- (/ size 2.0)) (- (+ (/ size 2.0) 12.0)) 0.0)
          '(40 . 3.5)
          (cons 1 (strcat "FLANGE " (rtos size 2 0) " x " (rtos size 2 0)
                          "  " (itoa nbolt) " HOLES D" (rtos (* 2.0 hole) 2 0)
                          " ON PCD " (rtos pcd 2 0)))))
  ;; Check the result the AutoLISP way.
  (setq ss (ssget "X" '((0 . "CIRCLE") (8 . "FLANGE-HOLES"))))
  (if (/= (sslength ss) nbolt)
    (*error* (strcat "expected " (itoa nbolt) " bolt holes")))
  (command "_.-LAYER" "_S" old-layer "")
  (setvar "CMDECHO" old-echo)
  (princ (strcat "\nFlange drawn: " (itoa (sslength ss)) " bolt holes."))
  (princ))

(c:flange)
