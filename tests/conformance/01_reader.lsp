;; The reader: numbers, strings, symbols, quote, dotted pairs, comments.
42
;=> 42
-7
;=> -7
1.
;=> 1.0
.5
;=> 0.5
-1e-3
;=> -0.001
1e3
;=> 1000.0
3000000000
;=> 3.0e+09
'foo
;=> FOO
'FooBar
;=> FOOBAR
'1+
;=> 1+
"a\\b\"c"
;=> "a\\b\"c"
(strlen "tab\there")
;=> 8
(ascii "\101")
;=> 65
(ascii "\e")
;=> 27
'(1 . 2)
;=> (1 . 2)
'(1 2 . 3)
;=> (1 2 . 3)
''a
;=> (QUOTE A)
'()
;=> nil
'nil
;=> nil
(eq nil '())
;=> T
;| a block
   comment (with parens |;
(+ 1 ;| inline |; 2)
;=> 3
(+ 1 2) ; a line comment
;=> 3
(read "(a b . c)")
;=> (A B . C)
(read "  12  rest")
;=> 12
(read "")
;=> nil
(read "\"str\"")
;=> "str"
(type (read "1.5"))
;=> REAL
