; models: circles::impl::fallback (impl/rounding.cpp), the tiny path: g = fma(kInverseDt, p, v), taken when
;   |g| < kTinyLimit, whose answer g/60 is then the one rounding.
; claim: when |g| < kTinyLimit, g = 60p + v exactly: the fma rounded down and rounded up give the same double
;   (a real is a double exactly when RD and RU of it agree).
; regime: every finite double p and v, subnormals and signed zeros included (z3 decides all 2^128 pairs).
; hash: impl/rounding.cpp fallback a16886b5cc979603
(set-logic QF_FP)
(define-fun kTinyLimit () Real (/ 1.0 22471164185778948846616314884862809170224712236778832159178760144716584475687620391588559665300942002640014234983924169707348721101802077811605928829934265547220986678108185659537777450155761764931635369010625721104768835292807860184239138817603404645418813835573287279993405742309964538104419541203028017152.0))
(define-sort D () (_ FloatingPoint 11 53))
(define-fun sixty () D ((_ to_fp 11 53) RNE 60.0))
(define-fun limit () D ((_ to_fp 11 53) RNE kTinyLimit))
(declare-const p D)
(declare-const v D)
(assert (not (or (fp.isNaN p) (fp.isInfinite p) (fp.isNaN v) (fp.isInfinite v))))
(assert (fp.lt (fp.abs (fp.fma RNE sixty p v)) limit))
; a counterexample: 60p + v is no double
(assert (not (fp.eq (fp.fma RTN sixty p v) (fp.fma RTP sixty p v))))
(check-sat)
