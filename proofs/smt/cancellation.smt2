; models: circles::impl::fallback (impl/rounding.cpp), the cancellation path: q = RN(v·kC), s = RN(p + q), taken
;   when |s|/kCancellationRatio ≤ |q| (the division by a power of two is exact, or overflows and fails); then
;   r = fma(−q, 60, v) and the answer is fma(60, s, r)/60, its one rounding.
; claim: on that path s = p + q exactly (Sterbenz's lemma; a real is a double when its RD and RU agree), for
;   every double q, so for q = RN(v·kC) too. It holds for any ratio up to 1. What 2^-8 is for, that fma(60, s, r)
;   is exact as well (|60s + r| < 2^e_q, fewer than 2^52 units of ulp(q)), is not machine-checked: with
;   q = RN(v·kC) and the two fmas z3 did not close it within 10 minutes (impl/double_bounds.hpp has the
;   argument, tests/rounding_test.cpp its rational test).
; regime: every finite double p and q, subnormals and signed zeros included (z3 decides all pairs).
; hash: impl/rounding.cpp fallback a16886b5cc979603
(set-logic QF_FP)
(define-fun kCancellationRatio () Real (/ 1.0 256.0))
(define-sort D () (_ FloatingPoint 11 53))
(define-fun d ((v Real)) D ((_ to_fp 11 53) RNE v))
(declare-const p D)
(declare-const q D)
(assert (not (or (fp.isNaN p) (fp.isInfinite p) (fp.isNaN q) (fp.isInfinite q))))
(define-fun s () D (fp.add RNE p q))
(assert (fp.leq (fp.div RNE (fp.abs s) (d kCancellationRatio)) (fp.abs q)))
; a counterexample: p + q is no double
(assert (not (fp.eq (fp.add RTN p q) (fp.add RTP p q))))
(check-sat)
