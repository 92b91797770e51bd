;; An entity-style association list updated in a loop, as routines that walk entget lists do:
;; 200,000 rounds of assoc + subst on a 12-pair entity list, and a tally alist of 50 keys
;; updated with assoc/subst/cons.
(setq ent '((0 . "LINE") (5 . "1F") (8 . "0") (62 . 7) (6 . "CONTINUOUS") (370 . -1)
            (10 0.0 0.0 0.0) (11 1.0 1.0 0.0) (40 . 0.0) (41 . 1.0) (50 . 0.0)
            (210 0.0 0.0 1.0)))
(setq tally nil i 0)
(repeat 200000
  (setq old (assoc 40 ent)
        ent (subst (cons 40 (+ (cdr old) 0.5)) old ent)
        k (rem i 50)
        p (assoc k tally)
        tally (if p (subst (cons k (1+ (cdr p))) p tally) (cons (cons k 1) tally))
        i (1+ i)))
(princ (cdr (assoc 40 ent)))
(princ " ")
(princ (length tally))
(princ " ")
(princ (cdr (assoc 7 tally)))
(princ)
