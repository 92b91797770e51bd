;; Number and angle formatting, parsing, matching (AutoLISP reference examples).
(rtos 17.5)
;=> "17.5000"
(rtos 17.5 1 4)
;=> "1.7500E+01"
(rtos 17.5 2 2)
;=> "17.50"
(rtos 17.5 3 4)
;=> "1'-5.5000\""
(rtos 17.5 4 2)
;=> "1'-5 1/2\""
(rtos 17.5 5 2)
;=> "17 1/2"
(rtos 2.5 2 0)
;=> "3"
(rtos -2.25 2 1)
;=> "-2.3"
(setvar "LUPREC" 2)
(rtos 1.0)
;=> "1.00"
(setvar "LUPREC" 4)
(angtos 0.785398 0 4)
;=> "45.0000"
(angtos pi 3 2)
;=> "3.14r"
(angtos (/ pi 2) 2 0)
;=> "100g"
(angtos 0.785398 1 4)
;=> "45d0'0\""
(distof "17.50" 2)
;=> 17.5
(distof "1'-5 1/2\"" 4)
;=> 17.5
(distof "abc")
;=> nil
(angtof "45" 0)
;=> 0.785398
(atoi "97")
;=> 97
(atoi "3.9")
;=> 3
(atoi "abc")
;=> 0
(atof "3.5x")
;=> 3.5
(substr "abcde" 2)
;=> "bcde"
(substr "abcde" 2 1)
;=> "b"
(substr "abc" 5)
;=> ""
(strcase "Hello")
;=> "HELLO"
(strcase "Hello" t)
;=> "hello"
(wcmatch "Name" "N*")
;=> T
(wcmatch "Name" "???,~*m*")
;=> nil
(wcmatch "Name" "*a*")
;=> T
(wcmatch "A12" "@##")
;=> T
(wcmatch "ab" "[abc]b")
;=> T
(wcmatch "a*b" "a`*b")
;=> T
(vl-string-trim " " "  pad  ")
;=> "pad"
(vl-string-left-trim " \t" "  x ")
;=> "x "
(vl-string-right-trim " " " x  ")
;=> " x"
(vl-string-search "fo" "foo fo")
;=> 0
(vl-string-search "fo" "foo fo" 1)
;=> 4
(vl-string-search "zz" "foo")
;=> nil
(vl-string-position 111 "foo")
;=> 1
(vl-string-position 111 "foo" nil t)
;=> 2
(vl-string-subst "Z" "o" "foo")
;=> "fZo"
(vl-string-translate "abc" "xyz" "aabbcc")
;=> "xxyyzz"
(vl-string-mismatch "abcd" "abxd")
;=> 2
(vl-string-elt "ABC" 1)
;=> 66
