;; Build a 1,000,000-element list, map (+ (* x 2) 1) over it, sum it.
(setq i 0 l nil)
(repeat 1000000 (setq l (cons i l) i (1+ i)))
(setq m (mapcar '(lambda (x) (+ (* x 2) 1)) l))
(setq s 0)
(foreach x m (setq s (+ s x)))
(princ s)
(princ)
