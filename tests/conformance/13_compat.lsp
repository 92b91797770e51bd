;; Compatibility functions old routines call: screen no-ops, namespaces, cvunit, file names.
(list (graphscr) (textscr) (textpage) (redraw))
;=> (nil nil nil nil)
(list (acad-push-dbmod) (acad-pop-dbmod) (vl-acad-defun 'car) (vl-acad-undefun 'car))
;=> (nil nil nil nil)
(setfunhelp "c:box")
;=> nil
(trace 'a 'b)
;=> B
(untrace)
;=> nil
(vl-doc-set 'doc-var 3)
;=> 3
(vl-doc-ref 'doc-var)
;=> 3
doc-var
;=> 3
(vl-propagate 'doc-var)
;=> nil
;; cvunit: lengths, angles, areas, volumes; nil for unknown or mixed units
(cvunit 1 "inch" "mm")
;=> 25.4
(cvunit 1 "inch" "millimeters")
;=> 25.4
(cvunit 25.4 "MM" "Inch")
;=> 1.0
(cvunit 1 "mile" "feet")
;=> 5280.0
(cvunit 180 "degree" "radian")
;=> 3.14159
(cvunit 1 "circle" "degrees")
;=> 360.0
(cvunit 100 "grad" "degree")
;=> 90.0
(cvunit 1 "sq foot" "sq inch")
;=> 144.0
(cvunit 1 "cu m" "cu cm")
;=> 1.0e+06
(cvunit '(1 2 3) "ft" "in")
;=> (12.0 24.0 36.0)
(cvunit 1 "inch" "degree")
;=> nil
(cvunit 1 "sq inch" "inch")
;=> nil
(cvunit 1 "furlong" "m")
;=> nil
(cvunit "1" "inch" "mm")
;!! bad argument type: numberp: "1"
;; file names, split as Visual LISP does
(vl-filename-base "c:/a/b/file.name.lsp")
;=> "file.name"
(vl-filename-base "c:\\dwg\\plan.dwg")
;=> "plan"
(vl-filename-base "noext")
;=> "noext"
(vl-filename-directory "c:\\a\\b\\file.lsp")
;=> "c:\\a\\b"
(vl-filename-directory "/usr/share/x.lsp")
;=> "/usr/share"
(vl-filename-directory "file.lsp")
;=> ""
(vl-filename-extension "x.LSP")
;=> ".LSP"
(vl-filename-extension "a/b.c/file")
;=> nil
(vl-filename-extension ".hidden")
;=> nil
(vl-filename-base 5)
;!! bad argument type: stringp 5
