;;; INTERS - every intersection between the curves of the drawing, with IntersectWith.
(vl-load-com)
(defun list-intersections (/ ss objs i j a b pts out)
  (setq ss (ssget "X" '((0 . "LINE,ARC,CIRCLE,LWPOLYLINE,SPLINE"))) i 0)
  (repeat (sslength ss)
    (setq objs (cons (vlax-ename->vla-object (ssname ss i)) objs) i (1+ i)))
  (setq objs (reverse objs))
  (while (setq a (car objs))
    (foreach b (setq objs (cdr objs))
      (setq pts (vlax-invoke a 'IntersectWith b acExtendNone))
      (while pts
        (setq out (cons (list (car pts) (cadr pts) (caddr pts)) out)
              pts (cdddr pts)))))
  (reverse out))
