;; System variables and the symbol table.
(getvar "LUPREC")
;=> 4
(getvar "luprec")
;=> 4
(setvar "LUPREC" 2)
;=> 2
(getvar "LUPREC")
;=> 2
(getvar "NOSUCHVAR")
;=> nil
(setvar "NOSUCHVAR" 1)
;!! AutoCAD variable setting rejected: "NOSUCHVAR" 1
(setvar "LUPREC" "x")
;!! AutoCAD variable setting rejected: "LUPREC" "x"
(getvar "GEOMTOL")
;=> 1.0e-09
(setvar "DXFPROFILE" "cam")
;=> "cam"
(getvar "DXFPROFILE")
;=> "CAM"
(setvar "DXFPROFILE" "xyz")
;!! AutoCAD variable setting rejected: "DXFPROFILE" "xyz"
(type (getvar "CDATE"))
;=> REAL
(setq myvar 1)
(atoms-family 1 '("MYVAR" "NOT-DEFINED-ANYWHERE"))
;=> ("MYVAR" nil)
(car (member "CAR" (atoms-family 1)))
;=> "CAR"
(numberp (vl-position "CAR" (atoms-family 1)))
;=> T
(getvar "CLAYER")
;=> "0"
(layer "PARTS" 3)
(getvar "CLAYER")
;=> "PARTS"
(setvar "CLAYER" "0")
;=> "0"
(getvar "CLAYER")
;=> "0"
(setvar "CLAYER" "NO-SUCH-LAYER")
;!! AutoCAD variable setting rejected: "CLAYER" "NO-SUCH-LAYER"
