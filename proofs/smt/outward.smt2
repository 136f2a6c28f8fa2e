; models: circles::impl::outward_lower and outward_upper (impl/broad_phase.hpp): t = RN(x ∓ r) and
;   RN(t ∓ RN(RN(|t|·kOutwardRelative) + kOutwardAbsolute)).
; claim: outward_lower(x, r) ≤ x − r and outward_upper(x, r) ≥ x + r exactly, whenever the bound is finite. A
;   double is ≤ the real x − r exactly when it is ≤ RD(x − r), the largest double below it (fp.sub RTN), and
;   ≥ x + r exactly when it is ≥ RU(x + r): the exact claim in floating-point terms alone.
; regime: every finite double x and r ≥ 0, subnormals and signed zeros included (z3 decides all 2^128 pairs).
; hash: impl/broad_phase.hpp outward_lower b0e514f7d7af72da
; hash: impl/broad_phase.hpp outward_upper 5df5251c44602d7f
(set-logic QF_FP)
(define-fun kOutwardRelative () Real (/ 1.0 4503599627370496.0))
(define-fun kOutwardAbsolute () Real (/ 1.0 101201126653655309176247673359458653524778324882071059178450679013715169783997673445980191850718562247593538932158405955694904368692896738433506699970369254960758712138283180682233453871046608170619883839236372534281003741712346349309051677824579778170405028256179384776166707307615251266093163754323003131653853870546747392.0))
(define-sort D () (_ FloatingPoint 11 53))
(define-fun relative () D ((_ to_fp 11 53) RNE kOutwardRelative))
(define-fun absolute () D ((_ to_fp 11 53) RNE kOutwardAbsolute))
(declare-const x D)
(declare-const r D)
(assert (or (fp.isNormal x) (fp.isSubnormal x) (fp.isZero x)))
(assert (or (fp.isNormal r) (fp.isSubnormal r) (fp.isZero r)))
(assert (not (fp.isNegative r)))
(define-fun t_lo () D (fp.sub RNE x r))
(define-fun t_hi () D (fp.add RNE x r))
(define-fun lower () D (fp.sub RNE t_lo (fp.add RNE (fp.mul RNE (fp.abs t_lo) relative) absolute)))
(define-fun upper () D (fp.add RNE t_hi (fp.add RNE (fp.mul RNE (fp.abs t_hi) relative) absolute)))
; a counterexample: a finite bound on the wrong side of the exact value
(assert (or (and (not (fp.isInfinite lower)) (fp.gt lower (fp.sub RTN x r)))
            (and (not (fp.isInfinite upper)) (fp.lt upper (fp.add RTP x r)))))
(check-sat)
