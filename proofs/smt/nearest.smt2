; models: the errors of circles::impl::ExactGrid::step (impl/exact_grid_reference.cpp):
;   e = max(RN(m·kNearestRelative), kNearestFloor), m the largest of a circle's |x̃|, |ỹ| and ρ̃, each the nearest
;   double to an exact value.
; claim: e bounds each of the circle's errors: every real whose nearest double is x̃, |x̃| ≤ m, lies within
;   half a gap of x̃, and e is at least half of each of x̃'s two gaps (the gap is a power of two, exact;
;   the half is exact with 15 exponent bits). At DBL_MAX the gap above is that below.
; regime: every finite double x̃ ≥ 0 (RN is odd) and m ≥ x̃ (z3 decides all pairs).
; hash: impl/exact_grid_reference.cpp step be61c62c743a48b5
(set-logic QF_BVFP)
(define-fun kNearestRelative () Real (/ 1.0 4503599627370496.0))
(define-fun kNearestFloor () Real (/ 1.0 22471164185778948846616314884862809170224712236778832159178760144716584475687620391588559665300942002640014234983924169707348721101802077811605928829934265547220986678108185659537777450155761764931635369010625721104768835292807860184239138817603404645418813835573287279993405742309964538104419541203028017152.0))
(define-sort D () (_ FloatingPoint 11 53))
(define-sort X () (_ FloatingPoint 15 53))
(define-fun d ((v Real)) D ((_ to_fp 11 53) RNE v))
(define-fun x ((v D)) X ((_ to_fp 15 53) RNE v))
(declare-const xt D)
(declare-const m D)
(assert (and (not (fp.isNaN xt)) (not (fp.isInfinite xt)) (not (fp.isNegative xt))))
(assert (and (not (fp.isInfinite m)) (fp.geq m xt)))
(define-fun e () D (fp.max (fp.mul RNE m (d kNearestRelative)) (d kNearestFloor)))
(define-fun bits () (_ BitVec 64) ((_ fp.to_ieee_bv) xt))
(define-fun above () D ((_ to_fp 11 53) (bvadd bits #x0000000000000001)))
(define-fun below () D (ite (fp.isZero xt) (fp.neg ((_ to_fp 11 53) #x0000000000000001))
                            ((_ to_fp 11 53) (bvsub bits #x0000000000000001))))
(define-fun twice ((v D)) X (fp.mul RNE (x v) ((_ to_fp 15 53) RNE 2.0)))
; a counterexample: half a gap of x̃ beyond e
(assert (or (and (not (fp.isInfinite above)) (fp.gt (x (fp.sub RNE above xt)) (twice e)))
            (fp.gt (x (fp.sub RNE xt below)) (twice e))))
(check-sat)
