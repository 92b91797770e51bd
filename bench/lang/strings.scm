;; String handling of a typical import routine (bench/lang/strings.lsp): build a 100,000-line
;; "ID,X,Y" text, take every line apart with string-index/substring/string->number, build an
;; output line per record.
(define lines
  (let loop ((n 0) (acc '()))
    (if (< n 100000)
        (loop (+ n 1)
              (cons (string-append "P" (number->string n) "," (number->string (* n 3)) ","
                                   (number->string (modulo (* n 7) 1000)))
                    acc))
        acc)))
(define total 0)
(define out '())
(for-each
 (lambda (ln)
   (let* ((c1 (string-index ln #\,))
          (c2 (string-index ln #\, (+ c1 1)))
          (id (substring ln 1 c1))
          (x (string->number (substring ln (+ c1 1) c2)))
          (y (string->number (substring ln (+ c2 1))))
          (rec (string-append id ";" (number->string (+ x y)) ";" (substring ln 0 1))))
     (set! total (+ total (string-length rec)))
     (set! out (cons rec out))))
 lines)
(display total)
(newline)
