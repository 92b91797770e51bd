;; Extended data (regapp, the -3 group of entmake/entmod/entget, ssget's -3 filter),
;; tblobjname, the named-object dictionary, dictionaries and XRECORDs, as the AutoLISP
;; Reference documents them.
(regapp "LCTEST")
;=> "LCTEST"
(regapp "lctest")
;=> nil
(regapp "bad?name")
;=> nil
(tblsearch "APPID" "lctest")
;=> ((0 . "APPID") (2 . "LCTEST") (70 . 0))
(regapp 12)
;!! bad argument type: stringp 12
(setq e (entmakex '((0 . "LINE") (10 0 0 0) (11 10 0 0) (-3 ("LCTEST" (1000 . "hello") (1002 . "{") (1070 . 7) (1040 . 2.5) (1010 1 2 3) (1071 . 100000) (1002 . "}"))))))
;=> <Entity name: 100>
;; Without an application list entget leaves the extended data out.
(assoc -3 (entget e))
;=> nil
(assoc -3 (entget e '("LCTEST")))
;=> (-3 ("LCTEST" (1000 . "hello") (1002 . "{") (1070 . 7) (1040 . 2.5) (1010 1.0 2.0 3.0) (1071 . 100000) (1002 . "}")))
(assoc -3 (entget e '("lc*")))
;=> (-3 ("LCTEST" (1000 . "hello") (1002 . "{") (1070 . 7) (1040 . 2.5) (1010 1.0 2.0 3.0) (1071 . 100000) (1002 . "}")))
(assoc -3 (entget e '("OTHER")))
;=> nil
;; The -3 group comes last.
(car (last (entget e '("*"))))
;=> -3
;; An application that is not registered: entmake fails and adds nothing.
(entmake '((0 . "LINE") (10 0 0 0) (11 1 0 0) (-3 ("NOPE" (1000 . "x")))))
;=> nil
(eq (entlast) e)
;=> T
(entmake '((0 . "POINT") (10 0 0 0) (-3 ("LCTEST" (1070 . 70000)))))
;!! bad DXF group: (1070 . 70000)
;; entmod replaces the data of the applications it names, keeps the others', and an
;; application given alone loses its data.
(regapp "LC2")
;=> "LC2"
(entmod (list (cons -1 e) '(-3 ("LC2" (1000 . "second") (1041 . 4.0)))))
(cdr (assoc -3 (entget e '("LC2"))))
;=> (("LC2" (1000 . "second") (1041 . 4.0)))
(length (cdr (assoc -3 (entget e '("*")))))
;=> 2
(entmod (list (cons -1 e) '(-3 ("LCTEST"))))
(assoc -3 (entget e '("*")))
;=> (-3 ("LC2" (1000 . "second") (1041 . 4.0)))
(cdr (assoc 11 (entget e)))
;=> (10.0 0.0 0.0)
(entmake '((0 . "CIRCLE") (10 0 0 0) (40 . 1.0)))
(sslength (ssget "X" '((-3 ("LC2")))))
;=> 1
(sslength (ssget "X" '((0 . "CIRCLE,LINE"))))
;=> 2
(ssget "X" '((-3 ("LCTEST"))))
;=> nil
(sslength (ssget "X" '((-4 . "<NOT") (-3 ("LC*")) (-4 . "NOT>"))))
;=> 1
;; The named-object dictionary, a dictionary of our own, XRECORDs.
(setq nod (namedobjdict))
;=> <Entity name: a>
(cdr (assoc 0 (entget nod)))
;=> "DICTIONARY"
(cdr (assoc 0 (dictsearch nod "ACAD_GROUP")))
;=> "DICTIONARY"
(setq x (entmakex '((0 . "XRECORD") (100 . "AcDbXrecord") (1 . "alpha") (40 . 3.25) (70 . 4) (10 1 2 3) (50 . 0.5))))
;=> <Entity name: 102>
(setq d (entmakex '((0 . "DICTIONARY") (100 . "AcDbDictionary"))))
;=> <Entity name: 103>
(cdr (assoc 330 (entget x)))
;=> <Entity name: 0>
(dictadd nod "LC_DATA" d)
;=> <Entity name: 103>
(dictadd d "FIRST" x)
;=> <Entity name: 102>
(dictadd d "first" x)
;=> nil
(dictsearch d "FIRST")
;=> ((-1 . <Entity name: 102>) (0 . "XRECORD") (5 . "102") (330 . <Entity name: 103>) (100 . "AcDbXrecord") (280 . 1) (1 . "alpha") (40 . 3.25) (70 . 4) (10 1.0 2.0 3.0) (50 . 0.5))
(cdr (assoc 1 (dictsearch (cdr (assoc -1 (dictsearch nod "lc_data"))) "first")))
;=> "alpha"
(dictsearch d "MISSING")
;=> nil
(dictsearch e "FIRST")
;=> nil
(setq x2 (entmakex '((0 . "XRECORD") (100 . "AcDbXrecord") (1 . "beta"))))
(dictadd d "SECOND" x2)
(cdr (assoc 1 (dictnext d T)))
;=> "alpha"
(cdr (assoc 1 (dictnext d)))
;=> "beta"
(dictnext d)
;=> nil
(cdr (assoc 1 (dictnext d T)))
;=> "alpha"
(dictrename d "SECOND" "ZWEI")
;=> "ZWEI"
(dictrename d "ZWEI" "first")
;=> nil
(dictsearch d "SECOND")
;=> nil
(cdr (assoc 1 (dictsearch d "zwei")))
;=> "beta"
(eq (dictremove d "ZWEI") x2)
;=> T
(dictsearch d "ZWEI")
;=> nil
(dictremove d "ZWEI")
;=> nil
;; A removed object stays, without an owner.
(cdr (assoc 330 (entget x2)))
;=> <Entity name: 0>
;; entmod of an XRECORD replaces its data.
(setq xl (entget x))
(entmod (subst '(1 . "gamma") (assoc 1 xl) xl))
(cdr (assoc 1 (entget x)))
;=> "gamma"
(cdr (assoc 40 (entget x)))
;=> 3.25
(cdr (assoc 330 (entget x)))
;=> <Entity name: 103>
;; tblobjname: a table record's name, the same for every call; entget gives the record.
(setq lr (tblobjname "LAYER" "0"))
(eq lr (tblobjname "layer" "0"))
;=> T
(list (cdr (assoc 0 (entget lr))) (cdr (assoc 2 (entget lr))) (cdr (assoc 62 (entget lr))))
;=> ("LAYER" "0" 7)
(tblobjname "LAYER" "NoSuchLayer")
;=> nil
(cdr (assoc 2 (entget (tblobjname "APPID" "lc2"))))
;=> "LC2"
(cdr (assoc 2 (entget (tblobjname "STYLE" "Standard"))))
;=> "Standard"
(eq (handent (cdr (assoc 5 (entget x)))) x)
;=> T
;; A POLYLINE's extended data comes with its header and is the polyline's once SEQEND ends it.
(entmake '((0 . "POLYLINE") (66 . 1) (70 . 1) (-3 ("LC2" (1000 . "header") (1070 . 3)))))
(entmake '((0 . "VERTEX") (10 0 0 0)))
(entmake '((0 . "VERTEX") (10 4 0 0) (42 . 1.0)))
(entmake '((0 . "SEQEND")))
(list (cdr (assoc 0 (entget (entlast)))) (cdr (assoc -3 (entget (entlast) '("LC2")))) (assoc -3 (entget (entlast))))
;=> ("POLYLINE" (("LC2" (1000 . "header") (1070 . 3))) nil)
