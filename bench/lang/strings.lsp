;; String handling of a typical import routine: build a 100,000-line "ID,X,Y" text with strcat
;; and itoa, then take every line apart again with vl-string-search/substr/atoi and build an
;; output line per record with strcat; report the total length of the output lines.
(setq n 0 lines nil)
(repeat 100000
  (setq lines (cons (strcat "P" (itoa n) "," (itoa (* n 3)) "," (itoa (rem (* n 7) 1000)))
                    lines)
        n (1+ n)))
(setq total 0 out nil)
(foreach ln lines
  (setq c1 (vl-string-search "," ln)
        c2 (vl-string-search "," ln (1+ c1))
        id (substr ln 2 (1- c1))
        x (atoi (substr ln (+ c1 2) (- c2 c1 1)))
        y (atoi (substr ln (+ c2 2)))
        rec (strcat id ";" (itoa (+ x y)) ";" (substr ln 1 1))
        total (+ total (strlen rec))
        out (cons rec out)))
(princ total)
(princ)
