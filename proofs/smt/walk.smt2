; models: circles::impl::exact::walked (impl/exact_bounds.hpp): the growth g = RN(RN(RN(W·kWalkMove) + RN(A·kWalkSum))
;   + kWalkAbsolute) and the walked bound nextafter(RN(E + g), +∞), the next double above RN(E + g).
; claim: walked(E, W, A) ≥ E + 2^-50·W + η + u·A, a walked slot's error bound after one step of the walk
;   (η = 2^-1075, u = 2^-53). Two facts give it, and a counterexample is one of them false:
;   - the next double above RN(E + g) is above E + g: above RD(E + g), the largest double not above it. Both it
;     and E + g are multiples of 2^-1074 (so is every double), so it is at least E + g + 2^-1074;
;   - g + 2^-1074 ≥ 2^-50·W + u·A + η: g ≥ RU(RU(2^-50·W + 2^-53·A) − η), the right side computed upward in a
;     format with 15 exponent bits, where the products by powers of two are exact (docs/proofs.md).
;   kWalkAbsolute is slack: the claim holds with it at 0 (the step to the next double gives η twice over).
; regime: every finite double E, W, A ≥ 0 whose E + g is finite (z3 decides all triples).
; hash: impl/exact_bounds.hpp walked 0a0ccab449aeb439
(set-logic QF_BVFP)
(define-fun kWalkMove () Real (/ 1.0 562949953421312.0))
(define-fun kWalkSum () Real (/ 1.0 4503599627370496.0))
(define-fun kWalkAbsolute () Real (/ 1.0 101201126653655309176247673359458653524778324882071059178450679013715169783997673445980191850718562247593538932158405955694904368692896738433506699970369254960758712138283180682233453871046608170619883839236372534281003741712346349309051677824579778170405028256179384776166707307615251266093163754323003131653853870546747392.0))
(define-sort D () (_ FloatingPoint 11 53))
(define-sort X () (_ FloatingPoint 15 53))
(define-fun d ((v Real)) D ((_ to_fp 11 53) RNE v))
(define-fun x ((v D)) X ((_ to_fp 15 53) RNE v))
(define-fun exact ((v Real)) X ((_ to_fp 15 53) RNE v))
(define-fun finite_nonnegative ((v D)) Bool (and (not (fp.isNaN v)) (not (fp.isInfinite v)) (not (fp.isNegative v))))
(declare-const e D)
(declare-const w D)
(declare-const a D)
(assert (and (finite_nonnegative e) (finite_nonnegative w) (finite_nonnegative a)))
(define-fun growth () D (fp.add RNE (fp.add RNE (fp.mul RNE w (d kWalkMove)) (fp.mul RNE a (d kWalkSum))) (d kWalkAbsolute)))
(define-fun sum () D (fp.add RNE e growth))
(assert (not (fp.isInfinite sum)))
(define-fun walked () D ((_ to_fp 11 53) (bvadd ((_ fp.to_ieee_bv) sum) #x0000000000000001)))
(define-fun need () X (fp.sub RTP (fp.add RTP (fp.mul RNE (x w) (exact (/ 1.0 1125899906842624.0))) (fp.mul RNE (x a) (exact (/ 1.0 9007199254740992.0))))
                                  (exact (/ 1.0 404804506614621236704990693437834614099113299528284236713802716054860679135990693783920767402874248990374155728633623822779617474771586953734026799881477019843034848553132722728933815484186432682479535356945490137124014966849385397236206711298319112681620113024717539104666829230461005064372655017292012526615415482186989568.0))))
; a counterexample: the next double not above E + g, or g + 2^-1074 short of the need
(assert (or (fp.leq walked (fp.add RTN e growth)) (fp.lt (x growth) need)))
(check-sat)
