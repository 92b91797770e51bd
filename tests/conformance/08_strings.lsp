;; Strings.
(strcat "ab" "cd" "")
;=> "abcd"
(strcat)
;=> ""
(strcat "a" 1)
;!! bad argument type: stringp 1
(strlen "hello")
;=> 5
(strlen "ab" "cde")
;=> 5
(ascii "A")
;=> 65
(chr 65)
;=> "A"
(itoa 42)
;=> "42"
(itoa -7)
;=> "-7"
(vl-princ-to-string '(1 "a"))
;=> "(1 a)"
(vl-prin1-to-string '(1 "a"))
;=> "(1 \"a\")"
(vl-string->list "AB")
;=> (65 66)
(vl-list->string '(72 105))
;=> "Hi"
(prin1 "q\"uote")
;>> "q\"uote"
(princ "q\"uote")
;>> q"uote
(print 'x)
;>> \nX 
(progn (princ "a") (terpri) (princ "b"))
;>> a\nb
(prompt "msg")
;>> msg
(princ '(1 . "two"))
;>> (1 . two)
(princ)
;>> 
