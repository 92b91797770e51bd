;; Build a 1,000,000-element list, map (+ (* x 2) 1) over it, sum it as a real
;; (bench/lang/list.lsp).
(define l
  (let loop ((i 0) (l '()))
    (if (< i 1000000) (loop (+ i 1) (cons i l)) l)))
(define m (map (lambda (x) (+ (* x 2) 1)) l))
(define s 0.0)
(for-each (lambda (x) (set! s (+ s x))) m)
(display s)
(newline)
