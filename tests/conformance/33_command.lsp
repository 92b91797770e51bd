;; command / command-s / vl-cmdf on the drawing: point strings, "" as Enter, spread calls.
(defun g (c) (cdr (assoc c (entget (entlast)))))
(defun kinds (/ e out)
  (setq e (entnext))
  (while e (setq out (cons (cdr (assoc 0 (entget e))) out) e (entnext e)))
  (reverse out))
(command "LINE" '(0 0) "10,0" "")
;=> nil
(list (g 10) (g 11))
;=> ((0.0 0.0 0.0) (10.0 0.0 0.0))
(command "_.LINE" "1,1,2" "@2,3" "")
(list (g 10) (g 11))
;=> ((1.0 1.0 2.0) (3.0 4.0 2.0))
(command "line" "0,0" "@10<90" "")
(mapcar '(lambda (x) (/ (fix (+ (* x 1e6) 0.5)) 1e6)) (g 11))
;=> (0.0 10.0 0.0)
;; A line sequence over several calls, closed with "C".
(command "LINE" '(20 0))
(command '(30 0) "@0,10")
(command "C")
(list (g 10) (g 11))
;=> ((30.0 10.0 0.0) (20.0 0.0 0.0))
(length (kinds))
;=> 6
;; Undo inside LINE removes the last segment.
(command "LINE" '(0 0) '(1 0) '(2 0) "U" "")
(list (g 10) (g 11))
;=> ((0.0 0.0 0.0) (1.0 0.0 0.0))
;; CIRCLE: centre + radius, radius by point, diameter, 2P, 3P.
(command "CIRCLE" "5,5" 2.5)
(list (g 10) (g 40))
;=> ((5.0 5.0 0.0) 2.5)
(command "CIRCLE" '(0 0) '(3 4))
(g 40)
;=> 5.0
(command "CIRCLE" '(0 0) "D" 3)
(g 40)
;=> 1.5
(command "CIRCLE" "2P" '(0 0) '(4 0))
(list (g 10) (g 40))
;=> ((2.0 0.0 0.0) 2.0)
(command "CIRCLE" "3P" '(1 0) '(0 1) '(-1 0))
(list (g 10) (g 40))
;=> ((0.0 0.0 0.0) 1.0)
(command "CIRCLE" "3P" '(0 0) '(1 1) '(2 2))
;!! CIRCLE: the three points are collinear
(command "CIRCLE" '(0 0) "x")
;!! CIRCLE: expected a radius, a point or "D", got "x"
;; ARC: three points (clockwise input gives the same CCW arc), centre-start-end, start-centre-angle.
(command "ARC" '(1 0) '(0 1) '(-1 0))
(list (g 10) (g 40) (g 50) (g 51))
;=> ((0.0 0.0 0.0) 1.0 0.0 3.14159)
(command "ARC" '(-1 0) '(0 1) '(1 0))
(list (g 50) (g 51))
;=> (0.0 3.14159)
(command "ARC" "C" '(0 0) '(2 0) '(0 5))
(list (g 40) (g 50) (g 51))
;=> (2.0 0.0 1.5708)
(command "ARC" '(2 0) "C" '(0 0) "A" 90)
(list (g 50) (g 51))
;=> (0.0 1.5708)
(command "ARC" '(2 0) "E" '(0 2) "R" 2)
(list (equal (g 10) '(0.0 0.0 0.0) 1e-12) (g 40) (g 50) (g 51))
;=> (T 2.0 0.0 1.5708)
(command "ARC" '(2 0) "E" '(0 2) "R" -2)
(list (equal (g 10) '(2.0 2.0 0.0) 1e-12) (g 50) (g 51))
;=> (T 4.71239 3.14159)
;; PLINE: lines, tangent arcs (bulges), close; widths ignored.
(command "PLINE" '(0 0) '(10 0) "A" '(10 10) "L" '(0 10) "C")
(list (g 90) (g 70) (mapcar 'cdr (vl-remove-if-not '(lambda (x) (= (car x) 42)) (entget (entlast)))))
;=> (4 1 (0.0 1.0 0.0 0.0))
(command "PLINE" '(0 0) "W" 0.5 0.5 '(5 0) "A" '(10 5) '(15 0) "")
(list (g 90) (g 70) (mapcar '(lambda (b) (/ (fix (+ (* b 1e6) 0.5)) 1e6)) (mapcar 'cdr (vl-remove-if-not '(lambda (x) (= (car x) 42)) (entget (entlast))))))
;=> (4 0 (0.0 0.414214 -2.41421 0.0))
;; A PLINE spread over calls; "S" gives a three-point arc.
(command "PLINE" '(0 0))
(command '(4 0) "A" "S" '(6 2) '(4 4))
(command "")
(mapcar 'cdr (vl-remove-if-not '(lambda (x) (= (car x) 42)) (entget (entlast))))
;=> (0.0 1.0 0.0)
;; (command) cancels; a PLINE keeps what was drawn.
(command "PLINE" '(0 0) '(1 0) '(1 1))
(command)
(g 90)
;=> 3
(command "CIRCLE" '(0 0))
(command)
(g 0)
;=> "LWPOLYLINE"
;; SPLINE through fit points; Enter, then the two tangent prompts.
(command "SPLINE" '(0 0) '(5 5) '(10 0) "" "" "")
(list (g 0) (g 71) (g 74) (g 11))
;=> ("SPLINE" 2 3 (0.0 0.0 0.0))
(command "SPLINE" '(0 0) '(5 5) '(10 0) '(5 -5) "C" "")
(list (g 70) (g 74))
;=> (9 4)
;; A new command after a spline ends its tangent prompts.
(command "SPLINE" '(0 0) '(1 1) '(2 0) "" "LINE" '(0 0) '(1 1) "")
(g 0)
;=> "LINE"
;; LAYER: make, set, new, colour.
(command "-LAYER" "M" "Holes" "C" "1" "" "")
(getvar "CLAYER")
;=> "Holes"
(cdr (assoc 62 (tblsearch "LAYER" "Holes")))
;=> 1
(command "LAYER" "N" "A,B" "C" "blue" "A,B" "S" "A" "")
(list (getvar "CLAYER") (cdr (assoc 62 (tblsearch "LAYER" "B"))))
;=> ("A" 5)
(command "LINE" '(0 0) '(1 1) "")
(g 8)
;=> "A"
(command "LAYER" "S" "nope" "")
;!! LAYER: cannot find layer "nope"
(command "LAYER" "OFF" "B" "")
(cdr (assoc 62 (tblsearch "LAYER" "B")))
;=> -5
;; ERASE with an entity name, a selection set, and "L".
(setq n (length (kinds)))
(command "ERASE" (entlast) "")
(- n (length (kinds)))
;=> 1
(command "ERASE" (ssget "X" '((0 . "CIRCLE"))) "")
(ssget "X" '((0 . "CIRCLE")))
;=> nil
(command "_ERASE" "L" "")
(- n (length (kinds)))
;=> 7
;; POINT, vl-cmdf, command-s.
(command "POINT" "1,2,3")
(g 10)
;=> (1.0 2.0 3.0)
(vl-cmdf "LINE" '(0 0) '(0 9) "")
;=> T
(command-s "LINE" '(0 0) '(0 8))
(command '(5 5))
;!! command: expected a command name, got the point (5 5 0)
(command "ZOOM" "E")
;=> nil
(command "FOO")
;!! command: unknown command "FOO" (lispcad runs LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT, MOVE, COPY, ROTATE, SCALE, MIRROR, INSERT, OFFSET, EXPLODE, FILLET (lines, arcs, circles, polylines), CHPROP, CHANGE, UNDO)
(command "LINE" '(0 0) "abc")
;!! LINE: expected a point, "C" (close, after two segments), "U" or "", got "abc"
(command "LINE" '(0 0) pause)
;!! command: PAUSE waits for the user: give the answer with --answers in a headless run
;; CLAYER set by setvar is where commands draw.
(command "LAYER" "N" "Via-setvar" "")
(setvar "CLAYER" "Via-setvar")
(command "LINE" '(0 0) '(1 0) "")
(g 8)
;=> "Via-setvar"
;; TEXT: point, height, rotation (degrees), the string as typed; UCS World.
(command "TEXT" "1,2" 3.5 90 "12")
(list (g 10) (g 40) (g 50) (g 1))
;=> ((1.0 2.0 0.0) 3.5 1.5708 "12")
(command "_.TEXT" "_J" "_MC" '(0 0) "" "" "Hi")
(list (g 40) (g 50) (g 1))
;=> (2.5 0.0 "Hi")
(command "UCS" "_W")
;=> nil
(command "UCS" "OB" (entlast))
;!! UCS: only the World UCS exists in lispcad ("W"), got "OB"
(command "PLINE" '(0 0) '(10 0) "A" '(5 0))
;!! PLINE: the arc end point lies straight behind the tangent direction; no tangent arc reaches it
;; clear-drawing drops a command left waiting for input
(command "LINE" '(0 0) '(5 5))
(clear-drawing)
(command "CIRCLE" '(0 0) 3)
(cdr (assoc 0 (entget (entlast))))
;=> "CIRCLE"
