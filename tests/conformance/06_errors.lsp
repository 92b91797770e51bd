;; Errors: *error*, vl-catch-all-apply, exit.
(setq r (vl-catch-all-apply '/ '(1 0)))
(vl-catch-all-error-p r)
;=> T
(vl-catch-all-error-message r)
;=> "divide by zero"
(vl-catch-all-apply '+ '(1 2))
;=> 3
(vl-catch-all-error-p 3)
;=> nil
(vl-catch-all-error-message (vl-catch-all-apply 'car '(1)))
;=> "bad argument type: consp 1"
(vl-catch-all-error-message (vl-catch-all-apply 'undefined-fn nil))
;=> "no function definition: UNDEFINED-FN"
(vl-catch-all-error-message (vl-catch-all-apply '(lambda () (exit)) nil))
;=> "quit / exit abort"
;; *error* receives the message, with the failing function's locals still bound
(defun *error* (msg) (setq caught (list msg state)))
(defun risky (/ state) (setq state 'busy) (/ 1 0))
(risky)
;!! divide by zero
caught
;=> ("divide by zero" BUSY)
(setq *error* nil)
;; a local *error* (the common idiom) is seen by callees
(defun inner () (car 'x))
(defun outer (/ *error*) (defun *error* (m) (setq seen m)) (inner))
(outer)
;!! bad argument type: consp X
seen
;=> "bad argument type: consp X"
*error*
;=> nil
;; errors inside vl-catch-all-apply do not reach *error*
(setq seen nil)
(defun *error* (m) (setq seen m))
(vl-catch-all-apply 'car '(1))
seen
;=> nil
(setq *error* nil)
(exit)
;!! quit / exit abort
(startapp "notepad")
;!! startapp is refused: lispcad has no shell escape
(vl-exit-with-error "custom")
;!! custom
