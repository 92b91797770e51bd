;; entget lists as AutoCAD gives them; entmod, entdel, entnext, handent.
(entnext)
;=> nil
(entlast)
;=> nil
(entmake '((0 . "LINE") (10 0 0 0) (11 10 5 0)))
(setq l1 (entlast))
(entget l1)
;=> ((-1 . <Entity name: 100>) (0 . "LINE") (330 . <Entity name: f>) (5 . "100") (100 . "AcDbEntity") (67 . 0) (410 . "Model") (8 . "0") (100 . "AcDbLine") (10 0.0 0.0 0.0) (11 10.0 5.0 0.0) (210 0.0 0.0 1.0))
(entmake '((0 . "CIRCLE") (8 . "Holes") (62 . 1) (10 5 5 0) (40 . 2.5)))
(setq c1 (entlast))
(entget c1)
;=> ((-1 . <Entity name: 101>) (0 . "CIRCLE") (330 . <Entity name: f>) (5 . "101") (100 . "AcDbEntity") (67 . 0) (410 . "Model") (8 . "Holes") (62 . 1) (100 . "AcDbCircle") (10 5.0 5.0 0.0) (40 . 2.5) (210 0.0 0.0 1.0))
(entmake '((0 . "ARC") (10 1 2 0) (40 . 3.0) (50 . 0.5) (51 . 7.0)))
(entget (entlast))
;=> ((-1 . <Entity name: 102>) (0 . "ARC") (330 . <Entity name: f>) (5 . "102") (100 . "AcDbEntity") (67 . 0) (410 . "Model") (8 . "0") (100 . "AcDbCircle") (10 1.0 2.0 0.0) (40 . 3.0) (210 0.0 0.0 1.0) (100 . "AcDbArc") (50 . 0.5) (51 . 0.716815))
(entmake '((0 . "POINT") (10 1 2 3)))
(entget (entlast))
;=> ((-1 . <Entity name: 103>) (0 . "POINT") (330 . <Entity name: f>) (5 . "103") (100 . "AcDbEntity") (67 . 0) (410 . "Model") (8 . "0") (100 . "AcDbPoint") (10 1.0 2.0 3.0) (210 0.0 0.0 1.0) (50 . 0.0))
(entmake '((0 . "TEXT") (10 1 1 0) (40 . 3.5) (1 . "M6") (50 . 0.25) (7 . "Standard")))
(entget (entlast))
;=> ((-1 . <Entity name: 104>) (0 . "TEXT") (330 . <Entity name: f>) (5 . "104") (100 . "AcDbEntity") (67 . 0) (410 . "Model") (8 . "0") (100 . "AcDbText") (10 1.0 1.0 0.0) (40 . 3.5) (1 . "M6") (50 . 0.25) (41 . 1.0) (51 . 0.0) (7 . "Standard") (71 . 0) (72 . 0) (11 0.0 0.0 0.0) (210 0.0 0.0 1.0) (100 . "AcDbText") (73 . 0))
;; A circle with extrusion (0 0 -1): group 10 is in the OCS, whose X axis is -WX.
(entmake '((0 . "CIRCLE") (10 4 0 0) (40 . 1.0) (210 0 0 -1)))
(cdr (assoc 10 (entget (entlast))))
;=> (4.0 0.0 0.0)
;; Names: eq for the same entity, printing, type, handent.
(eq l1 (entnext))
;=> T
(eq c1 (entnext l1))
;=> T
(handent "101")
;=> <Entity name: 101>
(eq (handent "101") c1)
;=> T
(handent "FFFF")
;=> nil
(handent "zz")
;=> nil
(entget "x")
;!! bad argument type: lentityp "x"
;; entdel deletes, and again restores.
(entdel c1)
;=> <Entity name: 101>
(entget c1)
;=> nil
(eq (entnext l1) c1)
;=> nil
(handent "101")
;=> <Entity name: 101>
(entdel c1)
;=> <Entity name: 101>
(cdr (assoc 40 (entget c1)))
;=> 2.5
;; entmod: change a group with subst, the entity keeps its name.
(setq ed (entget c1))
(entmod (subst '(40 . 4.0) (assoc 40 ed) ed))
(cdr (assoc 40 (entget c1)))
;=> 4.0
(entmod (list (cons -1 c1) '(8 . "Moved") '(62 . 256)))
(list (cdr (assoc 8 (entget c1))) (assoc 62 (entget c1)) (cdr (assoc 40 (entget c1))))
;=> ("Moved" nil 4.0)
(tblsearch "LAYER" "Moved")
;=> ((0 . "LAYER") (2 . "Moved") (70 . 0) (62 . 7) (6 . "Continuous"))
(entmod (list (cons -1 l1) '(11 3 4 5)))
(cdr (assoc 11 (entget l1)))
;=> (3.0 4.0 5.0)
(entmod (list (cons -1 c1) '(0 . "LINE")))
;=> nil
(entmod (list (cons -1 c1) '(40 . -2.0)))
;=> nil
(cdr (assoc 40 (entget c1)))
;=> 4.0
(entmod '((8 . "x")))
;=> nil
(entupd c1)
;=> <Entity name: 101>
;; entnext walks a POLYLINE's vertices and its SEQEND.
(entmake '((0 . "POLYLINE") (66 . 1) (70 . 0)))
(entmake '((0 . "VERTEX") (10 0 0 0)))
(entmake '((0 . "VERTEX") (10 5 0 0) (42 . 1.0)))
(entmake '((0 . "SEQEND")))
(setq pl (entlast) e (entnext pl) types nil)
(while e (setq types (cons (cdr (assoc 0 (entget e))) types) e (entnext e)))
(reverse types)
;=> ("VERTEX" "VERTEX" "SEQEND")
(setq v2 (entnext (entnext pl)))
(entget v2)
;=> ((-1 . <Entity name: 106.2>) (0 . "VERTEX") (330 . <Entity name: 106>) (100 . "AcDbEntity") (67 . 0) (410 . "Model") (8 . "0") (100 . "AcDbVertex") (100 . "AcDb2dVertex") (10 5.0 0.0 0.0) (40 . 0.0) (41 . 0.0) (42 . 1.0) (70 . 0) (50 . 0.0))
(setq ed (entget v2))
(entmod (subst '(10 6.0 1.0 0.0) (assoc 10 ed) ed))
(cdr (assoc 10 (entget v2)))
;=> (6.0 1.0 0.0)
(cdr (assoc -2 (entget (entnext v2))))
;=> <Entity name: 106>
(setq ed (entget pl))
(entmod (subst '(70 . 1) (assoc 70 ed) ed))
(cdr (assoc 70 (entget pl)))
;=> 1
