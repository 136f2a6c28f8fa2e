; models: the filtered comparison of circles::impl::ExactEngine::precedes (impl/exact_engine.cpp): d = RN(a_b − a_a)
;   against apart = RN(kOrderSpread·E), for approximations a_a, a_b each within E of its exact coordinate.
; claim: d > apart implies a_b − a_a > 2E exactly, so P_b > P_a: the order the approximations give is the exact
;   one. A real exceeds 2E when its downward rounding does (fp.sub RTN), and 2E is exact with 15 exponent bits.
; regime: every finite double a_a, a_b and E ≥ 0 (z3 decides all triples).
; hash: impl/exact_engine.cpp precedes afc6fb4abf3e2af0
(set-logic QF_FP)
(define-fun kOrderSpread () Real 4.0)
(define-sort D () (_ FloatingPoint 11 53))
(define-sort X () (_ FloatingPoint 15 53))
(define-fun d ((v Real)) D ((_ to_fp 11 53) RNE v))
(define-fun x ((v D)) X ((_ to_fp 15 53) RNE v))
(define-fun exact ((v Real)) X ((_ to_fp 15 53) RNE v))
(define-fun finite_nonnegative ((v D)) Bool (and (not (fp.isNaN v)) (not (fp.isInfinite v)) (not (fp.isNegative v))))
(declare-const aa D)
(declare-const ab D)
(declare-const e D)
(assert (and (not (fp.isNaN aa)) (not (fp.isInfinite aa)) (not (fp.isNaN ab)) (not (fp.isInfinite ab))))
(assert (finite_nonnegative e))
(define-fun apart () D (fp.mul RNE (d kOrderSpread) e))
; a counterexample: d > apart, yet the approximations' difference is at most 2E
(assert (fp.gt (fp.sub RNE ab aa) apart))
(assert (fp.leq (x (fp.sub RTN ab aa)) (fp.mul RNE (exact 2.0) (x e))))
(check-sat)
