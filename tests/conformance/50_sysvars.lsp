;; AutoCAD's system variable table: types, defaults, read-only flags, ranges (issue 12).
(defun f (a / a) a)
(f 5)
;=> 5
(defun getval (index alist / index) (nth index alist))
(getval 1 '(a b c))
;=> B
((lambda (x / x y) (list x y)) 3)
;=> (3 nil)
(setvar "ORTHOMODE" 1)
;=> 1
(getvar "orthomode")
;=> 1
(setvar "ORTHOMODE" 2)
;!! AutoCAD variable setting rejected: "ORTHOMODE" 2
(setvar "ORTHOMODE" 1.0)
;!! AutoCAD variable setting rejected: "ORTHOMODE" 1.0
(getvar "DIMSCALE")
;=> 1.0
(setvar "DIMSCALE" 50)
;=> 50
(getvar "DIMSCALE")
;=> 50.0
(setvar "DIMSCALE" -1.0)
;!! AutoCAD variable setting rejected: "DIMSCALE" -1.0
(setvar "TEXTSIZE" 0)
;!! AutoCAD variable setting rejected: "TEXTSIZE" 0
(getvar "LUNITS")
;=> 2
(setvar "LUNITS" 6)
;!! AutoCAD variable setting rejected: "LUNITS" 6
(setvar "LUNITS" 4)
;=> 4
(rtos 12.5)
;=> "1'-0 1/2\""
(setvar "LUNITS" 2)
;=> 2
(getvar "INSUNITS")
;=> 4
(getvar "CMDECHO")
;=> 1
(setvar "CMDECHO" 0)
;=> 0
(getvar "OSMODE")
;=> 0
(setvar "OSMODE" 16383)
;=> 16383
(setvar "OSMODE" 40000)
;!! AutoCAD variable setting rejected: "OSMODE" 40000
(getvar "LIMMAX")
;=> (420.0 297.0)
(setvar "LIMMAX" '(841 594))
;=> (841 594)
(getvar "LIMMAX")
;=> (841.0 594.0)
(getvar "INSBASE")
;=> (0.0 0.0 0.0)
(setvar "INSBASE" '(1 2))
;=> (1 2)
(getvar "INSBASE")
;=> (1.0 2.0 0.0)
(setvar "INSBASE" "x")
;!! AutoCAD variable setting rejected: "INSBASE" "x"
(getvar "CECOLOR")
;=> "BYLAYER"
(setvar "CECOLOR" "1")
;=> "1"
(setvar "CECOLOR" "bybloCK")
;=> "bybloCK"
(getvar "CECOLOR")
;=> "BYBLOCK"
(setvar "CECOLOR" "300")
;!! AutoCAD variable setting rejected: "CECOLOR" "300"
(setvar "CECOLOR" 1)
;!! AutoCAD variable setting rejected: "CECOLOR" 1
(setvar "DWGNAME" "x.dwg")
;!! AutoCAD variable setting rejected: "DWGNAME" "x.dwg"
(getvar "DWGNAME")
;=> "Drawing1.dwg"
(wcmatch (getvar "DWGPREFIX") "*/")
;=> T
(setvar "ACADVER" "1")
;!! AutoCAD variable setting rejected: "ACADVER" "1"
(>= (atof (getvar "ACADVER")) 15.0)
;=> T
(setvar "UNDOCTL" 0)
;!! AutoCAD variable setting rejected: "UNDOCTL" 0
(getvar "UNDOCTL")
;=> 21
(list (getvar "USERI1") (getvar "USERR5") (getvar "USERS3"))
;=> (0 0.0 "")
(setvar "USERI1" 42)
(setvar "USERR5" 2.5)
(setvar "USERS3" "Hello")
(list (getvar "USERI1") (getvar "USERR5") (getvar "USERS3"))
;=> (42 2.5 "Hello")
(setvar "USERI1" 70000)
;!! AutoCAD variable setting rejected: "USERI1" 70000
(type (getvar "DATE"))
;=> REAL
(> (getvar "DATE") 2460000.0)
;=> T
(type (getvar "MILLISECS"))
;=> INT
(> (getvar "CDATE") 20260101.0)
;=> T
(getvar "TEXTSTYLE")
;=> "Standard"
(getvar "FILLETRAD")
;=> 10.0
(getvar "DWGCODEPAGE")
;=> "ANSI_1252"
(getvar "SYSCODEPAGE")
;=> "ANSI_1252"
(setvar "SYSCODEPAGE" "ANSI_936")
;!! AutoCAD variable setting rejected: "SYSCODEPAGE" "ANSI_936"
(setvar "DIMTXSTY" "MyStyle")
;=> "MyStyle"
(getvar "DIMTXSTY")
;=> "MyStyle"
(getvar "EXTMIN")
;=> (1.0e+20 1.0e+20 1.0e+20)
(entmake '((0 . "LINE") (10 1.0 2.0 0.0) (11 5.0 -3.0 0.0)))
(getvar "EXTMIN")
;=> (1.0 -3.0 0.0)
(getvar "EXTMAX")
;=> (5.0 2.0 0.0)
(getvar "FILEDIA")
;=> 1
(setvar "FILEDIA" 0)
;=> 0
