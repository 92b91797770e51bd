;; The ActiveX object model over the drawing, variants and safearrays.
(vl-load-com)
(setq acad (vlax-get-acad-object) doc (vla-get-ActiveDocument acad) ms (vla-get-ModelSpace doc))
(list acad doc ms (type ms))
;=> (#<VLA-OBJECT IAcadApplication> #<VLA-OBJECT IAcadDocument> #<VLA-OBJECT IAcadModelSpace> VLA-OBJECT)
(eq ms (vla-get-ModelSpace doc))
;=> T
(setq ln (vla-AddLine ms (vlax-3d-point 0 0 0) (vlax-3d-point 10 0 0)))
;=> #<VLA-OBJECT IAcadLine>
(vla-get-StartPoint ln)
;=> #<variant 8197 ...>
(vlax-safearray->list (vlax-variant-value (vla-get-EndPoint ln)))
;=> (10.0 0.0 0.0)
(vlax-get ln 'EndPoint)
;=> (10.0 0.0 0.0)
(list (vla-get-Length ln) (vla-get-ObjectName ln) (vla-get-Layer ln) (vla-get-Color ln))
;=> (10.0 "AcDbLine" "0" 256)
(eq (vlax-vla-object->ename ln) (entlast))
;=> T
(eq ln (vlax-ename->vla-object (entlast)))
;=> T
(vla-put-Color ln acRed)
;=> nil
(cdr (assoc 62 (entget (entlast))))
;=> 1
(vlax-put ln 'EndPoint '(20 0 0))
(vlax-get-property ln 'Length)
;=> 20.0
(vla-put-Layer ln "NOSUCH")
;!! ActiveX Server returned an error: Key not found
(setq c (vla-AddCircle ms (vlax-3d-point 5 0 0) 3.0))
(vlax-invoke ln 'IntersectWith c acExtendNone)
;=> (2.0 0.0 0.0 8.0 0.0 0.0)
(setq v (vla-IntersectWith ln c acExtendNone))
(list (vlax-variant-type v) (vlax-safearray-get-u-bound (vlax-variant-value v) 1))
;=> (8197 5)
(vla-Move ln (vlax-3d-point 0 0 0) (vlax-3d-point 0 3 0))
(vlax-invoke ln 'IntersectWith c acExtendNone)
;=> (5.0 3.0 0.0)
(setq short (vla-AddLine ms (vlax-3d-point 20 -1 0) (vlax-3d-point 21 -1 0)))
(vlax-invoke short 'IntersectWith c acExtendNone)
;=> nil
(vlax-invoke short 'IntersectWith c acExtendThisEntity)
;=> (2.17157 -1.0 0.0 7.82843 -1.0 0.0)
(vlax-safearray-get-u-bound (vlax-variant-value (vla-IntersectWith short c acExtendNone)) 1)
;=> -1
(vla-get-Radius ln)
;!! ActiveX Server returned the error: unknown name: Radius
(list (vlax-property-available-p c 'Radius) (vlax-property-available-p ln 'Radius) (vlax-property-available-p c 'Area T))
;=> (T nil nil)
(list (vlax-method-applicable-p c 'Offset) (vlax-method-applicable-p c 'AddLine))
;=> (T nil)
(vla-get-Radius (car (vlax-invoke c 'Offset 1.0)))
;=> 4.0
(setq pl (vla-AddLightWeightPolyline ms (vlax-make-variant (vlax-safearray-fill (vlax-make-safearray vlax-vbDouble '(0 . 7)) '(0 0 10 0 10 10 0 10)))))
;=> #<VLA-OBJECT IAcadLWPolyline>
(vla-put-Closed pl :vlax-true)
(list (vla-get-Closed pl) (vla-get-Area pl) (vla-get-Length pl) (vlax-get pl 'Closed))
;=> (:VLAX-TRUE 100.0 40.0 -1)
(vlax-get pl 'Coordinates)
;=> (0.0 0.0 10.0 0.0 10.0 10.0 0.0 10.0)
(vlax-curve-getDistAtParam pl 2.5)
;=> 25.0
(setq cp (vla-Copy pl))
(vla-Rotate cp (vlax-3d-point 0 0 0) (/ pi 2))
(mapcar '(lambda (x) (/ (fix (* (+ x 0.5) 1000)) 1000.0)) (vlax-get cp 'Coordinates))
;=> (0.5 0.5 0.5 10.5 -9.5 10.5 -9.5 0.5)
(vla-ScaleEntity c (vlax-3d-point 5 0 0) 2.0)
(vla-get-Radius c)
;=> 6.0
(setq n 0)
(vlax-for o ms (setq n (1+ n)))
n
;=> 6
(vla-get-Count ms)
;=> 6
(vla-Delete cp)
(list (vlax-erased-p cp) (vla-get-Count ms))
;=> (T 5)
(vla-get-Name (vla-Add (vla-get-Layers doc) "WALLS"))
;=> "WALLS"
(setq names nil)
(vlax-for l (vla-get-Layers doc) (setq names (cons (vla-get-Name l) names)))
(reverse names)
;=> ("0" "WALLS")
(vla-put-Layer ln "WALLS")
(cdr (assoc 8 (entget (vlax-vla-object->ename ln))))
;=> "WALLS"
(vla-StartUndoMark doc)
(logand (getvar "UNDOCTL") 8)
;=> 8
(vla-EndUndoMark doc)
(logand (getvar "UNDOCTL") 8)
;=> 0
(setq tx (vla-AddText ms "Hello" (vlax-3d-point 1 2 0) 2.5))
(list (vla-get-TextString tx) (vlax-get tx 'InsertionPoint) (vla-get-Height tx))
;=> ("Hello" (1.0 2.0 0.0) 2.5)
(vla-put-TextString tx "World")
(cdr (assoc 1 (entget (entlast))))
;=> "World"
(vlax-curve-getEndParam ln)
;=> 20.0
(vlax-dump-object (vla-get-Layers doc))
;>> ; IAcadLayers: AutoCAD object\n; Property values:\n;   Count (RO) = 2\n
;; Variants and safearrays.
(setq sa (vlax-make-safearray vlax-vbDouble '(0 . 2)))
(vlax-safearray->list sa)
;=> (0.0 0.0 0.0)
(vlax-safearray-put-element sa 1 5)
;=> 5
(vlax-safearray-get-element sa 1)
;=> 5.0
(vlax-safearray-get-element sa 3)
;!! ActiveX Server returned an error: Invalid index
(list (vlax-safearray-get-l-bound sa 1) (vlax-safearray-get-u-bound sa 1) (vlax-safearray-get-dim sa) (vlax-safearray-type sa))
;=> (0 2 1 5)
(setq m (vlax-make-safearray vlax-vbLong '(1 . 2) '(0 . 1)))
(vlax-safearray-fill m '((1 2) (3 4)))
(vlax-safearray->list m)
;=> ((1 2) (3 4))
(vlax-safearray-get-element m 2 1)
;=> 4
(setq v (vlax-make-variant 5))
;=> #<variant 3 5>
(list (vlax-variant-type v) (vlax-variant-value v))
;=> (3 5)
(vlax-variant-value (vlax-variant-change-type v vlax-vbDouble))
;=> 5.0
(vlax-variant-type (vlax-make-variant "x"))
;=> 8
(vlax-variant-type (vlax-make-variant sa))
;=> 8197
(vlax-make-variant 2.5 vlax-vbString)
;=> #<variant 8 2.5>
