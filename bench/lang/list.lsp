;; Build a 1,000,000-element list, map (+ (* x 2) 1) over it, sum it.
;; The sum (10^12) is accumulated as a real: AutoLISP integers are 32-bit and would wrap,
;; while every peer has wider integers; a real sum is the same number everywhere.
(setq i 0 l nil)
(repeat 1000000 (setq l (cons i l) i (1+ i)))
(setq m (mapcar '(lambda (x) (+ (* x 2) 1)) l))
(setq s 0.0)
(foreach x m (setq s (+ s x)))
(princ s)
(princ)
