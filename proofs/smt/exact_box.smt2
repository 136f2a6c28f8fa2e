; models: circles::impl::exact::centre_bound and radius_bound (impl/exact_bounds.hpp):
;   c = RN(RN(m·kBoxRelative) + kBoxAbsolute) and ρ_e = RN(RN(ρ·kRadiusRelative) + kRadiusAbsolute).
; claim: c ≥ 2^-49·m and c ≥ 2^-1073 (twice each term of a centre's error 2^-50·m + η); ρ_e ≥ 2^-52·ρ and
;   ρ_e ≥ 2^-1074 (twice each term of a radius's error u·ρ + η), so that error_bound's RN(c + ρ_e), which
;   loses at most a factor 1 − u, covers both errors. Each right side is a product computed upward (RTP) in
;   a format with 15 exponent bits, where every product of a double by a power of two is exact.
; regime: every finite double m ≥ 0 and ρ ≥ 0 (z3 decides all pairs).
; hash: impl/exact_bounds.hpp centre_bound c4f6bf34812e200e
; hash: impl/exact_bounds.hpp radius_bound f89c0cacb2f5df52
(set-logic QF_FP)
(define-fun kBoxRelative () Real (/ 1.0 562949953421312.0))
(define-fun kBoxAbsolute () Real (/ 1.0 101201126653655309176247673359458653524778324882071059178450679013715169783997673445980191850718562247593538932158405955694904368692896738433506699970369254960758712138283180682233453871046608170619883839236372534281003741712346349309051677824579778170405028256179384776166707307615251266093163754323003131653853870546747392.0))
(define-fun kRadiusRelative () Real (/ 1.0 4503599627370496.0))
(define-fun kRadiusAbsolute () Real (/ 1.0 202402253307310618352495346718917307049556649764142118356901358027430339567995346891960383701437124495187077864316811911389808737385793476867013399940738509921517424276566361364466907742093216341239767678472745068562007483424692698618103355649159556340810056512358769552333414615230502532186327508646006263307707741093494784.0))
(define-sort D () (_ FloatingPoint 11 53))
(define-sort X () (_ FloatingPoint 15 53))
(define-fun d ((x Real)) D ((_ to_fp 11 53) RNE x))
(define-fun x ((v D)) X ((_ to_fp 15 53) RNE v))
(define-fun exact ((v Real)) X ((_ to_fp 15 53) RNE v))
(declare-const m D)
(declare-const rho D)
(assert (and (or (fp.isNormal m) (fp.isSubnormal m) (fp.isZero m)) (not (fp.isNegative m))))
(assert (and (or (fp.isNormal rho) (fp.isSubnormal rho) (fp.isZero rho)) (not (fp.isNegative rho))))
(define-fun c () D (fp.add RNE (fp.mul RNE m (d kBoxRelative)) (d kBoxAbsolute)))
(define-fun rho_e () D (fp.add RNE (fp.mul RNE rho (d kRadiusRelative)) (d kRadiusAbsolute)))
; a counterexample: one of the claims false
(assert (or (fp.lt (x c) (fp.mul RTP (x m) (exact (/ 1.0 562949953421312.0))))
            (fp.lt (x c) (exact (/ 1.0 101201126653655309176247673359458653524778324882071059178450679013715169783997673445980191850718562247593538932158405955694904368692896738433506699970369254960758712138283180682233453871046608170619883839236372534281003741712346349309051677824579778170405028256179384776166707307615251266093163754323003131653853870546747392.0)))
            (fp.lt (x rho_e) (fp.mul RTP (x rho) (exact (/ 1.0 4503599627370496.0))))
            (fp.lt (x rho_e) (exact (/ 1.0 202402253307310618352495346718917307049556649764142118356901358027430339567995346891960383701437124495187077864316811911389808737385793476867013399940738509921517424276566361364466907742093216341239767678472745068562007483424692698618103355649159556340810056512358769552333414615230502532186327508646006263307707741093494784.0)))))
(check-sat)
