;; entmake: AutoLISP's rules on the drawing model (type first, defaults, nil on missing groups).
(entmake '((0 . "LINE") (10 0 0 0) (11 10 5 0)))
;=> ((0 . "LINE") (10 0 0 0) (11 10 5 0))
(entlast)
;=> <Entity name: 100>
(type (entlast))
;=> ENAME
(entmake '((0 . "LINE") (10 0 0 0)))
;=> nil
(entmake '((10 0 0 0) (0 . "LINE") (11 1 1 0)))
;=> nil
(entmake '((0 . "line") (10 1 2) (11 3 4)))
;=> ((0 . "line") (10 1 2) (11 3 4))
(cdr (assoc 11 (entget (entlast))))
;=> (3.0 4.0 0.0)
(entmake '((0 . "CIRCLE") (10 5 5 0)))
;=> nil
(entmake '((0 . "CIRCLE") (10 5 5 0) (40 . -1.0)))
;=> nil
(entmake '((0 . "CIRCLE") (8 . "Holes") (62 . 1) (10 5 5 0) (40 . 2.5)))
;=> ((0 . "CIRCLE") (8 . "Holes") (62 . 1) (10 5 5 0) (40 . 2.5))
(tblsearch "LAYER" "HOLES")
;=> ((0 . "LAYER") (2 . "Holes") (70 . 0) (62 . 7) (6 . "Continuous"))
(entmake '((0 . "CIRCLE") (62 . 300) (10 5 5 0) (40 . 2.5)))
;=> nil
(entmake '((0 . "ARC") (10 0 0 0) (40 . 3.0) (50 . 0.0) (51 . 1.5)))
;=> ((0 . "ARC") (10 0 0 0) (40 . 3.0) (50 . 0.0) (51 . 1.5))
(list (cdr (assoc 50 (entget (entlast)))) (cdr (assoc 51 (entget (entlast)))))
;=> (0.0 1.5)
(entmake '((0 . "ARC") (10 0 0 0) (40 . 3.0) (50 . 0.0)))
;=> nil
(entmake '((0 . "POINT") (10 1 2 3)))
;=> ((0 . "POINT") (10 1 2 3))
(entmake '((0 . "3DFACE") (10 0 0 0) (11 1 0 0) (12 1 1 1)))
;=> ((0 . "3DFACE") (10 0 0 0) (11 1 0 0) (12 1 1 1))
(cdr (assoc 13 (entget (entlast))))
;=> (1.0 1.0 1.0)
(entmake '((0 . "TEXT") (10 0 0 0) (1 . "Hi")))
;=> ((0 . "TEXT") (10 0 0 0) (1 . "Hi"))
(mapcar '(lambda (c) (cdr (assoc c (entget (entlast))))) '(40 7 50))
;=> (2.5 "Standard" 0.0)
(entmake '((0 . "TEXT") (10 0 0 0) (40 . 5.0)))
;=> nil
(entmake (quote ((0 . "CIRCLE") (10 0 0 0) (40 . "x"))))
;!! bad DXF group: (40 . "x")
(entmake '((0 . "LINE") 5))
;!! bad DXF group: 5
(entmake '((0 . "INSERT") (10 0 0 0)))
;=> nil
(entmake '((0 . "MTEXT") (10 0 0 0) (1 . "x")))
;!! entmake: entity type MTEXT is not supported by lispcad (LINE, CIRCLE, ARC, POINT, LWPOLYLINE, POLYLINE, SPLINE, ELLIPSE, 3DFACE, TEXT, BLOCK...ENDBLK, INSERT, ATTDEF, ATTRIB, LAYER, APPID, XRECORD and DICTIONARY are)
(entmake '((0 . "ELLIPSE") (10 0 0 0)))
;=> nil
(cdr (assoc 40 (entmake '((0 . "ELLIPSE") (10 1 2 0) (11 3 0 0) (40 . 0.5)))))
;=> 0.5
(entmake '((0 . "NOSUCHTHING") (10 0 0 0)))
;=> nil
(entmake 5)
;!! bad argument type: listp 5
;; LWPOLYLINE: 90 count, 70 closed, vertices with bulges, elevation.
(setq pl (entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 3) (70 . 1) (38 . 2.0) (10 0 0) (42 . 0.5) (10 10 0) (10 10 10))))
(vl-remove-if-not '(lambda (g) (member (car g) '(90 70 38 10 42))) (entget (entlast)))
;=> ((90 . 3) (70 . 1) (38 . 2.0) (10 0.0 0.0) (42 . 0.5) (10 10.0 0.0) (42 . 0.0) (10 10.0 10.0) (42 . 0.0))
(entmake '((0 . "LWPOLYLINE") (90 . 4) (10 0 0) (10 1 0)))
;=> nil
(entmake '((0 . "LWPOLYLINE") (10 0 0)))
;=> nil
;; POLYLINE / VERTEX / SEQEND over several calls.
(setq before (entlast))
(entmake '((0 . "POLYLINE") (66 . 1) (70 . 1) (8 . "Outline")))
;=> ((0 . "POLYLINE") (66 . 1) (70 . 1) (8 . "Outline"))
(entmake '((0 . "VERTEX") (10 0 0 0)))
;=> ((0 . "VERTEX") (10 0 0 0))
(eq before (entlast))
;=> T
(entmake '((0 . "VERTEX") (10 5 0 0) (42 . 1.0)))
(entmake '((0 . "VERTEX") (10 5 5 0)))
(entmake '((0 . "SEQEND")))
;=> ((0 . "SEQEND"))
(cdr (assoc 0 (entget (entlast))))
;=> "POLYLINE"
(cdr (assoc 8 (entget (entlast))))
;=> "Outline"
(entmake '((0 . "VERTEX") (10 0 0 0)))
;=> nil
(entmake '((0 . "SEQEND")))
;=> nil
;; SPLINE from control points and from fit points.
(entmake '((0 . "SPLINE") (70 . 8) (71 . 3) (72 . 8) (73 . 4) (74 . 0) (40 . 0.0) (40 . 0.0) (40 . 0.0) (40 . 0.0) (40 . 1.0) (40 . 1.0) (40 . 1.0) (40 . 1.0) (10 0 0 0) (10 1 2 0) (10 3 2 0) (10 4 0 0)))
;=> ((0 . "SPLINE") (70 . 8) (71 . 3) (72 . 8) (73 . 4) (74 . 0) (40 . 0.0) (40 . 0.0) (40 . 0.0) (40 . 0.0) (40 . 1.0) (40 . 1.0) (40 . 1.0) (40 . 1.0) (10 0 0 0) (10 1 2 0) (10 3 2 0) (10 4 0 0))
(mapcar '(lambda (c) (cdr (assoc c (entget (entlast))))) '(70 71 72 73 74))
;=> (8 3 8 4 0)
(entmake '((0 . "SPLINE") (71 . 3) (40 . 0.0) (10 0 0 0) (10 1 2 0)))
;=> nil
(progn (entmake '((0 . "SPLINE") (11 0 0 0) (11 5 5 0) (11 10 0 0))) (cdr (assoc 74 (entget (entlast)))))
;=> 3
;; Layers: entmake of a LAYER record, and a duplicate.
(entmake '((0 . "LAYER") (100 . "AcDbSymbolTableRecord") (100 . "AcDbLayerTableRecord") (2 . "Centre") (70 . 0) (62 . 5) (6 . "Continuous")))
;=> ((0 . "LAYER") (100 . "AcDbSymbolTableRecord") (100 . "AcDbLayerTableRecord") (2 . "Centre") (70 . 0) (62 . 5) (6 . "Continuous"))
(tblsearch "LAYER" "centre")
;=> ((0 . "LAYER") (2 . "Centre") (70 . 0) (62 . 5) (6 . "Continuous"))
(entmake '((0 . "LAYER") (2 . "Centre") (62 . 3)))
;=> nil
(entmake '((0 . "LAYER") (62 . 3)))
;=> nil
;; The current layer (CLAYER) is the default layer.
(layer "Work" 3)
(entmake '((0 . "POINT") (10 0 0 0)))
(cdr (assoc 8 (entget (entlast))))
;=> "Work"
(entmake '((0 . "POINT") (10 0 0 0) (62 . 256)))
(assoc 62 (entget (entlast)))
;=> nil
(entmake '((0 . "POINT") (10 0 0 0) (62 . 0)))
(assoc 62 (entget (entlast)))
;=> (62 . 0)
