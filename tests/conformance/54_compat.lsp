;; What published routines lean on besides Visual LISP (issue 12, item 6).
(boundp 'nil)
;=> nil
(setq)
;=> nil
(vl-catch-all-apply '(lambda () (vl-exit-with-value 5) 6) nil)
;=> 5
(vl-file-delete "no/such/file.txt")
;=> nil
(setq e (entmakex '((0 . "LINE") (10 0 0 0) (11 1 0 0))))
(eq e (entlast))
;=> T
(entmakex '((0 . "LINE") (10 0 0 0)))
;=> nil
(ssnamex (ssget "X"))
;=> ((0 <Entity name: 100>))
(list (snvalid "Layer 1") (snvalid "") (snvalid "a*b") (snvalid "a|b") (snvalid "a|b" 1) (snvalid "|ab" 1))
;=> (T nil nil nil T nil)
(textbox '((1 . "ABC") (40 . 3.0)))
;=> ((0.0 0.0 0.0) (6.0 3.0 0.0))
(xstrcase "abc")
;=> "ABC"
(acad_strlsort '("b" "C" "a"))
;=> ("a" "b" "C")
(load_dialog "x.dcl")
;!! dialogs are not available headless: lispcad has no DCL or dialog boxes (take the value from the script, --set or --answers)
(acad_colordlg 1)
;!! dialogs are not available headless: lispcad has no DCL or dialog boxes (take the value from the script, --set or --answers)
