;; entmake of block definitions (issue 12): BLOCK opens a definition, the entities after it
;; are held in it, ENDBLK defines the block and returns its name (AutoLISP reference,
;; entmake: "the block name" for ENDBLK); a list out of sequence gives nil.
(entmake '((0 . "ENDBLK")))
;=> nil
(entmake '((0 . "BLOCK") (2 . "PEG") (70 . 0)))
;=> nil
(entmake '((0 . "BLOCK") (2 . "PEG") (70 . 0) (10 0.0 0.0 0.0)))
;=> ((0 . "BLOCK") (2 . "PEG") (70 . 0) (10 0.0 0.0 0.0))
(entmake '((0 . "CIRCLE") (10 0 0 0) (40 . 1.0)))
;=> ((0 . "CIRCLE") (10 0 0 0) (40 . 1.0))
;; Held in the block: not a drawing entity.
(entlast)
;=> nil
(tblsearch "BLOCK" "PEG")
;=> nil
(entmake '((0 . "ATTDEF") (10 0 2 0) (40 . 0.5) (1 . "P1") (2 . "ID") (3 . "Peg id") (70 . 0)))
;=> ((0 . "ATTDEF") (10 0 2 0) (40 . 0.5) (1 . "P1") (2 . "ID") (3 . "Peg id") (70 . 0))
(entmake '((0 . "ENDBLK")))
;=> "PEG"
;; Flag 2: the block has attribute definitions.
(setq b (tblsearch "BLOCK" "peg"))
(list (cdr (assoc 2 b)) (cdr (assoc 70 b)) (cdr (assoc 10 b)))
;=> ("PEG" 2 (0.0 0.0 0.0))
(cdr (assoc 0 (entget (cdr (assoc -2 b)))))
;=> "CIRCLE"
(cdr (assoc 0 (entget (tblobjname "BLOCK" "PEG"))))
;=> "BLOCK_RECORD"
;; A second BLOCK before ENDBLK drops the open definition.
(entmake '((0 . "BLOCK") (2 . "HALF") (10 0 0 0)))
(entmake '((0 . "BLOCK") (2 . "OTHER") (10 0 0 0)))
;=> nil
(entmake '((0 . "ENDBLK")))
;=> nil
(tblsearch "BLOCK" "HALF")
;=> nil
;; (entmake) with no list drops an open definition.
(entmake '((0 . "BLOCK") (2 . "DROPPED") (10 0 0 0)))
(entmake)
(entmake '((0 . "ENDBLK")))
;=> nil
;; An anonymous block (70 bit 1) gets the next *U name.
(entmake '((0 . "BLOCK") (2 . "*U") (70 . 1) (10 0 0 0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 1 0 0)))
(entmake '((0 . "ENDBLK")))
;=> "*U1"
(entmake '((0 . "BLOCK") (2 . "*U") (70 . 1) (10 0 0 0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 1 0 0)))
(entmake '((0 . "ENDBLK")))
;=> "*U2"
;; INSERT: of a defined block only; with (66 . 1) it waits for its ATTRIBs and SEQEND.
(entmake '((0 . "INSERT") (2 . "NOSUCH") (10 0 0 0)))
;=> nil
(entmake '((0 . "INSERT") (2 . "PEG") (10 0 0 0) (41 . 0.0)))
;=> nil
(entmake '((0 . "INSERT") (2 . "PEG") (66 . 1) (10 5 5 0) (50 . 0.0)))
;=> ((0 . "INSERT") (2 . "PEG") (66 . 1) (10 5 5 0) (50 . 0.0))
(entlast)
;=> nil
(entmake '((0 . "ATTRIB") (10 5 7 0) (40 . 0.5) (1 . "P7") (2 . "ID") (70 . 0)))
;=> ((0 . "ATTRIB") (10 5 7 0) (40 . 0.5) (1 . "P7") (2 . "ID") (70 . 0))
(entmake '((0 . "SEQEND")))
;=> ((0 . "SEQEND"))
(setq ins (entlast))
(mapcar '(lambda (g) (cdr (assoc g (entget ins)))) '(0 2 66 10))
;=> ("INSERT" "PEG" 1 (5.0 5.0 0.0))
(setq at (entget (entnext ins)))
(mapcar '(lambda (g) (cdr (assoc g at))) '(0 1 2 10))
;=> ("ATTRIB" "P7" "ID" (5.0 7.0 0.0))
(cdr (assoc 0 (entget (entnext (entnext ins)))))
;=> "SEQEND"
;; Anything but ATTRIB or SEQEND abandons an INSERT waiting for its attributes.
(entmake '((0 . "INSERT") (2 . "PEG") (66 . 1) (10 9 9 0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 1 0 0)))
;=> nil
(entmake '((0 . "SEQEND")))
;=> nil
(eq ins (entlast))
;=> T
;; The INSERT command on a block entmake defined; the attribute value is prompted for.
(command "_.-INSERT" "PEG" '(20 0) 2 "" 0 "P20")
(setq at (entget (entnext (entlast))))
(list (cdr (assoc 1 at)) (cdr (assoc 10 at)) (cdr (assoc 40 at)))
;=> ("P20" (20.0 4.0 0.0) 1.0)
;; A block cannot hold a reference to itself.
(entmake '((0 . "BLOCK") (2 . "SELF") (10 0 0 0)))
(entmake '((0 . "INSERT") (2 . "SELF") (10 0 0 0)))
;=> nil
(entmake)
