;;; REVPL - reverse the direction of an LWPOLYLINE (vertices reversed, bulges negated and
;;; moved to the segment's new start vertex), with entmod as the published routines do.
(defun revpl (ename / ed head verts bulges n out)
  (setq ed (entget ename))
  (foreach g ed
    (cond ((= (car g) 10) (setq verts (cons (cdr g) verts)))
          ((= (car g) 42) (setq bulges (cons (- (cdr g)) bulges)))))
  ;; verts and bulges are now reversed; bulge i of the reversed polyline is the negated
  ;; bulge of the original segment that ends at its vertex i.
  (setq bulges (append (cdr bulges) (list (car bulges))))
  (setq head (vl-remove-if '(lambda (g) (member (car g) '(10 40 41 42 91))) ed))
  (setq out (reverse head) n 0)
  (foreach v verts
    (setq out (cons (cons 42 (nth n bulges)) (cons (cons 10 v) out)) n (1+ n)))
  (entmod (reverse out))
  ename)
