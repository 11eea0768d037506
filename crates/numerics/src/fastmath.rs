//! Branch-free `exp`, `ln` and `sin_cos` (and a fast `cbrt`) for the hot loops of the
//! contact and traction kernels and the roller frames.
//!
//! The platform `libm` functions are calls the compiler cannot inline or vectorise. These are
//! written with selects instead of branches, so a loop over a slice of values that calls them
//! is vectorised (SSE2 two lanes, AVX2 four), and they give the same bits in every lane and
//! on every x86-64 machine: no fused multiply–add is used, so the result does not depend on the
//! instruction set.
//!
//! Accuracy (tested against `std` over the whole working range): `exp` ≤ 1 ulp, `ln` ≤ 1 ulp.
//! Range reduction and polynomials follow fdlibm (`e_exp.c`, `e_log.c`, Sun Microsystems
//! 1993): `exp` reduces by k·ln 2 (split into a high and low part) to |r| ≤ ½ ln 2 and sums
//! the Taylor series to r¹³ (truncation < 10⁻¹⁷) in Estrin's scheme; `ln` reduces to
//! m ∈ [√½, √2) and uses fdlibm's minimax polynomial in s = (m−1)/(m+1) (error < 2⁻⁵⁸·⁴⁵).
//!
//! Special values: `exp` returns +∞ above 1023.5·ln 2 ≈ 709.44 (e^709.44 ≈ 0.7·f64::MAX; the last
//! half binade is given up so that 2^k stays a normal number), 0 below −708.39 (where the result
//! would be subnormal) and NaN for NaN. `ln` returns −∞ for 0, NaN for negative and NaN arguments,
//! +∞ for +∞ and handles subnormal arguments exactly.

// fdlibm's constants keep their published digits.
#![allow(clippy::excessive_precision)]

const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-1;
const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10;
/// 1.5·2⁵²: adding it to |x| < 2⁵¹ rounds x to an integer, held in the low mantissa bits.
const SHIFT: f64 = 6_755_399_441_055_744.0;

/// eˣ (see the module docs for accuracy and special values).
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    const MAX_ARG: f64 = 709.436_139_303_104; // 1023.5·ln 2: k ≤ 1023 keeps 2^k normal
    const MIN_ARG: f64 = -708.396_418_532_264_1; // ln(f64::MIN_POSITIVE): k ≥ −1022
    let xc = x.clamp(MIN_ARG, MAX_ARG);
    let shifted = xc * std::f64::consts::LOG2_E + SHIFT;
    let k = shifted - SHIFT;
    let r = (xc - k * LN2_HI) - k * LN2_LO;
    // Taylor series to r¹³ as 1 + (r + r²·h(r)), h in Estrin's scheme: a short dependency
    // chain for scalar callers (≈ 6 multiply–add levels instead of 13), and no loop, so that a
    // caller's loop is vectorised. The small part is summed first, 1 is added last.
    let r2 = r * r;
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let h01 = 1.0 / 2.0 + r * (1.0 / 6.0);
    let h23 = 1.0 / 24.0 + r * (1.0 / 120.0);
    let h45 = 1.0 / 720.0 + r * (1.0 / 5_040.0);
    let h67 = 1.0 / 40_320.0 + r * (1.0 / 362_880.0);
    let h89 = 1.0 / 3_628_800.0 + r * (1.0 / 39_916_800.0);
    let h1011 = 1.0 / 479_001_600.0 + r * (1.0 / 6_227_020_800.0);
    let h = (h01 + r2 * h23) + r4 * (h45 + r2 * h67) + r8 * (h89 + r2 * h1011);
    let p = 1.0 + (r + r2 * h);
    // 2^k from the integer held in the low mantissa bits of `shifted` (wrapping arithmetic:
    // only the 11 exponent bits survive the shift; no 64-bit integer conversions, which SSE2
    // and AVX2 lack)
    let k_bits = shifted.to_bits().wrapping_sub(SHIFT.to_bits());
    let scale = f64::from_bits(k_bits.wrapping_add(1023) << 52);
    let y = p * scale;
    if x > MAX_ARG {
        f64::INFINITY
    } else if x < MIN_ARG {
        0.0
    } else {
        y
    }
}

/// ln x (see the module docs for accuracy and special values).
#[inline(always)]
pub fn ln(x: f64) -> f64 {
    const LG: [f64; 7] = [
        6.666_666_666_666_735_130e-1,
        3.999_999_999_940_941_908e-1,
        2.857_142_874_366_239_149e-1,
        2.222_219_843_214_978_396e-1,
        1.818_357_216_161_805_012e-1,
        1.531_383_769_920_937_332e-1,
        1.479_819_860_511_658_591e-1,
    ];
    const TWO52: f64 = 4_503_599_627_370_496.0;
    const TWO54: f64 = 18_014_398_509_481_984.0;
    const MANTISSA: u64 = 0x000f_ffff_ffff_ffff;
    // subnormals: scale into the normal range first
    let subnormal = x < f64::MIN_POSITIVE;
    let xs = if subnormal { x * TWO54 } else { x };
    let bits = xs.to_bits();
    // biased exponent as a float: put it in the mantissa of 2⁵² (no integer conversion)
    let biased = f64::from_bits(TWO52.to_bits() | ((bits >> 52) & 0x7ff)) - TWO52;
    let m1 = f64::from_bits((bits & MANTISSA) | 0x3ff0_0000_0000_0000); // [1, 2)
    let high = m1 > std::f64::consts::SQRT_2;
    let m = if high { 0.5 * m1 } else { m1 };
    let k = biased - if subnormal { 1023.0 + 54.0 } else { 1023.0 } + if high { 1.0 } else { 0.0 };
    let f = m - 1.0;
    let s = f / (2.0 + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (LG[1] + w * (LG[3] + w * LG[5]));
    let t2 = z * (LG[0] + w * (LG[2] + w * (LG[4] + w * LG[6])));
    let r = t2 + t1;
    let hfsq = 0.5 * f * f;
    let y = k * LN2_HI - ((hfsq - (s * (hfsq + r) + k * LN2_LO)) - f);
    if x > 0.0 && x < f64::INFINITY {
        y
    } else if x == 0.0 {
        f64::NEG_INFINITY
    } else if x == f64::INFINITY {
        x
    } else {
        f64::NAN
    }
}

/// ∛x, ≤ 1 ulp (FreeBSD `s_cbrt.c`, B. Evans 2005, after fdlibm): a 5-bit estimate from the
/// exponent bits divided by 3, a polynomial step to 23 bits, rounding to 23 bits (so that the
/// square is exact), one Newton step to 53 bits. About twice as fast as the correctly rounded
/// `f64::cbrt` of Rust's `compiler_builtins`, which the per-contact EHL film calls. Handles
/// zero, subnormal, negative, infinite and NaN arguments like `f64::cbrt`.
#[inline]
pub fn cbrt(x: f64) -> f64 {
    const B1: u64 = 715_094_163; // (1023 − 1023/3 − 0.03306235651)·2²⁰
    const B2: u64 = 696_219_795; // (1023 − 1023/3 − 54/3 − 0.03306235651)·2²⁰
    // |1/∛x − p(x)| < 2^−23.5
    const P0: f64 = 1.875_951_824_271_770_096_43;
    const P1: f64 = -1.884_979_795_433_771_698_75;
    const P2: f64 = 1.621_429_720_105_354_466_140;
    const P3: f64 = -0.758_397_934_778_766_047_437;
    const P4: f64 = 0.145_996_192_886_612_446_982;
    let bits = x.to_bits();
    let sign = bits & 0x8000_0000_0000_0000;
    let high = (bits >> 32) as u32 & 0x7fff_ffff;
    if high >= 0x7ff0_0000 {
        return x + x; // NaN, ±∞
    }
    let t = if high < 0x0010_0000 {
        if bits << 1 == 0 {
            return x; // ±0
        }
        let scaled = x * f64::from_bits(0x4350_0000_0000_0000); // 2⁵⁴
        let h = (scaled.to_bits() >> 32) as u32 & 0x7fff_ffff;
        f64::from_bits(sign | ((h as u64 / 3 + B2) << 32))
    } else {
        f64::from_bits(sign | ((high as u64 / 3 + B1) << 32))
    };
    let r = (t * t) * (t / x);
    let t = t * ((P0 + r * (P1 + r * P2)) + ((r * r) * r) * (P3 + r * P4));
    let t = f64::from_bits((t.to_bits().wrapping_add(0x8000_0000)) & 0xffff_ffff_c000_0000);
    let s = t * t;
    let r = x / s;
    let w = t + t;
    let r = (r - t) / (w + r);
    t + t * r
}

/// Largest |x| for which [`sin_cos`] reduces its argument accurately (2²⁰ · π/2 ≈ 1.6·10⁶; the
/// multiples k·π/2 of the three-part reduction stay exact up to there).
pub const SIN_COS_MAX_ARG: f64 = 1_647_099.3;

/// (sin x, cos x), ≤ 2 ulp in tests, for |x| ≤ [`SIN_COS_MAX_ARG`] (beyond it: NaN — callers
/// fall back to `f64::sin_cos`). Branch-free, so that a loop over angles is vectorised: x is
/// reduced by k·π/2 (k = round(2x/π), π/2 in three parts, fdlibm `__rem_pio2`'s medium case)
/// to |r| ≤ π/4, and sin r, cos r are fdlibm's `__kernel_sin`/`__kernel_cos` polynomials
/// (Sun Microsystems 1993, |error| < 2⁻⁵⁸), exchanged and signed by the quadrant k mod 4.
#[inline(always)]
pub fn sin_cos(x: f64) -> (f64, f64) {
    const PIO2_1: f64 = 1.570_796_326_734_125_614_17; // first 33 bits of π/2
    const PIO2_2: f64 = 6.077_100_506_303_965_976_60e-11; // next 33 bits
    const PIO2_2T: f64 = 2.022_266_248_795_950_631_54e-21; // π/2 − PIO2_1 − PIO2_2
    const S: [f64; 6] = [
        -1.666_666_666_666_663_243_48e-1,
        8.333_333_333_322_489_461_24e-3,
        -1.984_126_982_985_794_931_34e-4,
        2.755_731_370_707_006_767_89e-6,
        -2.505_076_025_340_686_341_95e-8,
        1.589_690_995_211_550_102_21e-10,
    ];
    const C: [f64; 6] = [
        4.166_666_666_666_660_190_37e-2,
        -1.388_888_888_887_410_957_49e-3,
        2.480_158_728_947_672_941_78e-5,
        -2.755_731_435_139_066_330_35e-7,
        2.087_572_321_298_174_827_90e-9,
        -1.135_964_755_778_819_482_65e-11,
    ];
    let inside = x.abs() <= SIN_COS_MAX_ARG;
    let xc = if inside { x } else { 0.0 };
    let shifted = xc * std::f64::consts::FRAC_2_PI + SHIFT;
    let k = shifted - SHIFT;
    let r = ((xc - k * PIO2_1) - k * PIO2_2) - k * PIO2_2T;
    let z = r * r;
    let sin_r = r + r * z * (S[0] + z * (S[1] + z * (S[2] + z * (S[3] + z * (S[4] + z * S[5])))));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    let cos_r = w
        + (((1.0 - w) - hz)
            + z * z * (C[0] + z * (C[1] + z * (C[2] + z * (C[3] + z * (C[4] + z * C[5]))))));
    // quadrant k mod 4 from the low bits of the shifted integer (two's complement for k < 0)
    let quadrant = shifted.to_bits().wrapping_sub(SHIFT.to_bits()) & 3;
    let odd = quadrant & 1 == 1;
    let (s, c) = if odd { (cos_r, sin_r) } else { (sin_r, cos_r) };
    let s = if quadrant >= 2 { -s } else { s };
    let c = if quadrant == 1 || quadrant == 2 {
        -c
    } else {
        c
    };
    if inside { (s, c) } else { (f64::NAN, f64::NAN) }
}

crate::avx512_twin! {
    /// [`sin_cos`] of every element of `x` into `sin` and `cos` (at least as long as `x`), in a
    /// vectorised loop; arguments beyond [`SIN_COS_MAX_ARG`] (and non-finite ones) by
    /// `f64::sin_cos`.
    pub fn sin_cos_many(x: &[f64], sin: &mut [f64], cos: &mut [f64]) =
        sin_cos_many_portable / sin_cos_many_avx512 {
        let n = x.len();
        let (sin, cos) = (&mut sin[..n], &mut cos[..n]);
        for i in 0..n {
            (sin[i], cos[i]) = sin_cos(x[i]);
        }
        for i in 0..n {
            if x[i].is_nan() || x[i].abs() > SIN_COS_MAX_ARG {
                (sin[i], cos[i]) = x[i].sin_cos();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distance in units in the last place.
    fn ulps(a: f64, b: f64) -> u64 {
        if a == b {
            return 0;
        }
        let (ia, ib) = (a.to_bits() as i64, b.to_bits() as i64);
        (ia - ib).unsigned_abs()
    }

    /// Deterministic pseudo-random numbers in [0, 1) (xorshift64*).
    fn uniform(n: usize) -> Vec<f64> {
        let mut s = 0x9e37_79b9_7f4a_7c15_u64;
        (0..n)
            .map(|_| {
                s ^= s >> 12;
                s ^= s << 25;
                s ^= s >> 27;
                (s.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
            })
            .collect()
    }

    #[test]
    fn exp_within_one_ulp() {
        let mut worst = 0;
        for u in uniform(400_000) {
            let x = -708.0 + u * (709.4 + 708.0);
            worst = worst.max(ulps(exp(x), x.exp()));
        }
        for u in uniform(200_000) {
            let x = -1.0 + 2.0 * u;
            worst = worst.max(ulps(exp(x), x.exp()));
        }
        assert!(worst <= 1, "worst {worst} ulp");
        assert_eq!(exp(0.0), 1.0);
        assert!(ulps(exp(1.0), std::f64::consts::E) <= 1);
        assert_eq!(exp(710.0), f64::INFINITY);
        assert_eq!(exp(-800.0), 0.0);
        assert!(exp(f64::NAN).is_nan());
        assert_eq!(exp(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
    }

    #[test]
    fn ln_within_one_ulp() {
        let mut worst = 0;
        for u in uniform(400_000) {
            // log-uniform over the normal range
            let x = (-700.0 + 1400.0 * u).exp();
            worst = worst.max(ulps(ln(x), x.ln()));
        }
        for u in uniform(200_000) {
            let x = 0.5 + 1.5 * u;
            worst = worst.max(ulps(ln(x), x.ln()));
        }
        for x in [1e-310, 5e-324, 2.2e-308, f64::MAX, 1.0, 2.0, 0.5] {
            worst = worst.max(ulps(ln(x), x.ln()));
        }
        assert!(worst <= 1, "worst {worst} ulp");
        assert_eq!(ln(1.0), 0.0);
        assert_eq!(ln(0.0), f64::NEG_INFINITY);
        assert_eq!(ln(f64::INFINITY), f64::INFINITY);
        assert!(ln(-1.0).is_nan());
        assert!(ln(f64::NAN).is_nan());
    }

    #[test]
    fn sin_cos_within_two_ulp() {
        let mut worst = 0;
        let mut check = |x: f64| {
            let (s, c) = sin_cos(x);
            let (es, ec) = x.sin_cos();
            // ulps near a zero of sin or cos are meaningless: compare absolutely there
            for (got, want) in [(s, es), (c, ec)] {
                if want.abs() > 1e-3 {
                    worst = worst.max(ulps(got, want));
                } else {
                    assert!((got - want).abs() < 2e-16 * x.abs().max(1.0), "{x}");
                }
            }
        };
        for u in uniform(300_000) {
            check(-10.0 + 20.0 * u);
            check(-SIN_COS_MAX_ARG + 2.0 * SIN_COS_MAX_ARG * u);
        }
        for x in [0.0, -0.0, 1e-300, 1e-8, 0.785, 1.57, 3.1, 1e4, 1e6] {
            check(x);
        }
        assert!(worst <= 2, "worst {worst} ulp");
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        assert!(sin_cos(2e6).0.is_nan() && sin_cos(f64::NAN).1.is_nan());
        assert!(sin_cos(f64::INFINITY).0.is_nan());
        // the many-argument version: same bits, std beyond the range
        let x = [0.3, -7.0, 3e6, 1e3, f64::NAN, 2.0, 4.0, 5.0, 6.0, 7.0, 8.0];
        let (mut s, mut c) = ([0.0; 11], [0.0; 11]);
        sin_cos_many(&x, &mut s, &mut c);
        for i in 0..x.len() {
            let want = if x[i].abs() <= SIN_COS_MAX_ARG {
                sin_cos(x[i])
            } else {
                x[i].sin_cos()
            };
            assert_eq!(s[i].to_bits(), want.0.to_bits());
            assert_eq!(c[i].to_bits(), want.1.to_bits());
        }
    }

    #[test]
    fn cbrt_within_one_ulp() {
        let mut worst = 0;
        for u in uniform(400_000) {
            let x = (-700.0 + 1400.0 * u).exp();
            worst = worst.max(ulps(cbrt(x), x.cbrt()));
            worst = worst.max(ulps(cbrt(-x), (-x).cbrt()));
        }
        for x in [1e-310, 5e-324, 2.2e-308, f64::MAX, 1.0, 8.0, 27.0, 0.125] {
            worst = worst.max(ulps(cbrt(x), x.cbrt()));
        }
        assert!(worst <= 1, "worst {worst} ulp");
        assert_eq!(cbrt(27.0), 3.0);
        assert_eq!(cbrt(0.0).to_bits(), 0.0_f64.to_bits());
        assert_eq!(cbrt(-0.0).to_bits(), (-0.0_f64).to_bits());
        assert_eq!(cbrt(f64::INFINITY), f64::INFINITY);
        assert_eq!(cbrt(f64::NEG_INFINITY), f64::NEG_INFINITY);
        assert!(cbrt(f64::NAN).is_nan());
    }
}
