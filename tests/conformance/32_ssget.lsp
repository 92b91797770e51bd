;; ssget "X" with filter lists; selection-set functions; tblsearch/tblnext.
(ssget "X")
;=> nil
(layer "Outline" 1)
(entmake '((0 . "LINE") (10 0 0 0) (11 10 0 0)))
(entmake '((0 . "CIRCLE") (10 5 5 0) (40 . 2.0)))
(entmake '((0 . "CIRCLE") (8 . "Holes") (62 . 3) (10 1 1 0) (40 . 0.5)))
(entmake '((0 . "ARC") (8 . "Holes") (10 0 0 0) (40 . 1.0) (50 . 0.0) (51 . 1.0)))
(entmake '((0 . "TEXT") (8 . "Notes") (10 0 0 0) (40 . 2.0) (1 . "A")))
(setq all (ssget "X"))
;=> <Selection set: 1>
(type all)
;=> PICKSET
(sslength all)
;=> 5
(ssname all 0)
;=> <Entity name: 100>
(ssname all 4)
;=> <Entity name: 104>
(ssname all 5)
;=> nil
(ssname all -1)
;=> nil
(ssname all 1.0)
;=> <Entity name: 101>
(defun names (ss / i out)
  (setq i 0)
  (if ss (repeat (sslength ss) (setq out (cons (cdr (assoc 5 (entget (ssname ss i)))) out) i (1+ i))))
  (reverse out))
(names (ssget "X" '((0 . "CIRCLE"))))
;=> ("101" "102")
(names (ssget "_X" '((0 . "circle,ARC"))))
;=> ("101" "102" "103")
(names (ssget "X" '((8 . "H*"))))
;=> ("102" "103")
(names (ssget "X" '((0 . "CIRCLE") (8 . "Outline"))))
;=> ("101")
(names (ssget "X" '((62 . 3))))
;=> ("102")
(names (ssget "X" '((62 . 256))))
;=> ("100" "101" "103" "104")
(names (ssget "X" '((-4 . "<OR") (0 . "LINE") (8 . "Notes") (-4 . "OR>"))))
;=> ("100" "104")
(names (ssget "X" '((-4 . "<NOT") (8 . "Holes") (-4 . "NOT>"))))
;=> ("100" "101" "104")
(names (ssget "X" '((-4 . "<AND") (0 . "CIRCLE") (-4 . "<NOT") (62 . 3) (-4 . "NOT>") (-4 . "AND>"))))
;=> ("101")
(names (ssget "X" '((-4 . "<XOR") (0 . "CIRCLE") (8 . "Holes") (-4 . "XOR>"))))
;=> ("101" "103")
(names (ssget "X" '((0 . "CIRCLE") (-4 . ">") (40 . 1.0))))
;=> ("101")
(names (ssget "X" '((0 . "CIRCLE") (-4 . "<,*,*") (10 3.0 0.0 0.0))))
;=> ("102")
(names (ssget "X" '((0 . "~CIRCLE"))))
;=> ("100" "103" "104")
(ssget "X" '((0 . "SPLINE")))
;=> nil
(ssget "X" '((-4 . "<OR") (0 . "LINE")))
;!! ssget: bad filter list: <OR is not closed by OR>
(ssget)
;!! ssget: interactive selection needs a user; in a headless run use (ssget "X" [filter]), "A", "L" or "P"
(ssget ":S")
;!! ssget: selection mode ":S" needs a user; in a headless run use "X" [filter], "A", "L", "P", "W"/"C" with two points, or "WP"/"CP"/"F" with a point list
(names (ssget "L"))
;=> ("104")
(names (ssget "X" '((8 . "Outline"))))
;=> ("100" "101")
(names (ssget "P"))
;=> ("100" "101")
;; ssadd / ssdel / ssmemb change the set they are given.
(setq s (ssadd))
(sslength s)
;=> 0
(eq s (ssadd (handent "100") s))
;=> T
(ssadd (handent "102") s)
(ssadd (handent "100") s)
(names s)
;=> ("100" "102")
(ssmemb (handent "102") s)
;=> <Entity name: 102>
(ssmemb (handent "101") s)
;=> nil
(ssdel (handent "101") s)
;=> nil
(progn (ssdel (handent "100") s) (names s))
;=> ("102")
(names (ssadd (handent "103")))
;=> ("103")
(sslength 5)
;!! bad argument type: lselsetp 5
;; Deleted entities leave ssget "X".
(entdel (handent "101"))
(names (ssget "X" '((0 . "CIRCLE"))))
;=> ("102")
;; Tables.
(tblsearch "LAYER" "0")
;=> ((0 . "LAYER") (2 . "0") (70 . 0) (62 . 7) (6 . "Continuous"))
(tblsearch "LAYER" "nope")
;=> nil
(tblsearch "LTYPE" "continuous")
;=> ((0 . "LTYPE") (2 . "Continuous") (70 . 0) (3 . "Solid line") (72 . 65) (73 . 0) (40 . 0.0))
(cdr (assoc 2 (tblsearch "STYLE" "STANDARD")))
;=> "Standard"
(cdr (assoc 2 (tblnext "LAYER" T)))
;=> "0"
(cdr (assoc 2 (tblnext "LAYER")))
;=> "Outline"
(progn (setq l nil) (while (setq r (tblnext "LAYER")) (setq l (cons (cdr (assoc 2 r)) l))) (reverse l))
;=> ("Holes" "Notes")
(tblnext "LAYER")
;=> nil
(cdr (assoc 62 (tblnext "LAYER" T)))
;=> 7
(progn (tblsearch "LAYER" "Holes" T) (cdr (assoc 2 (tblnext "LAYER"))))
;=> "Notes"
