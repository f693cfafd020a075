//! The sine and cosine of an angle within a few turns of zero (the azimuths the quadratures
//! take, in `[−π, π]`), inline and without branches on the way: a reduction by the nearest
//! multiple of `π/2` and the fdlibm polynomial kernels on `[−π/4, π/4]` (errors below one
//! ulp there). The platform's `sin_cos` gives the same values to an ulp or two at several
//! times the cost (its range checks, and a call the compiler cannot schedule around), which
//! on an integrand that is little else than a sine, a root and a few products was a fifth of
//! the time.
#![allow(
    clippy::excessive_precision,
    reason = "fdlibm's constants as published; f64 rounds them"
)]

/// `π/2` in three parts (fdlibm's): the first two of 33 bits, so that `n·PIO2_1` and
/// `n·PIO2_2` are exact for the small `n` taken here and `x − n·PIO2_1` is too (the two are
/// within a factor of two of each other); the rest, below 1e-31, is left out. The reduced
/// angle then keeps its relative digits even next to a multiple of `π/2`.
const PIO2_1: f64 = 1.570_796_326_734_125_614_17;
/// The second 33 bits of `π/2`.
const PIO2_2: f64 = 6.077_100_506_303_965_976_60e-11;
/// `π/2 − PIO2_1 − PIO2_2`, to double precision.
const PIO2_2T: f64 = 2.022_266_248_795_950_631_54e-21;

/// `1.5·2⁵²`: added and taken away, rounds to the nearest integer.
const ROUND: f64 = 6_755_399_441_055_744.0;

/// Beyond this the platform's `sin_cos` (whose reduction is exact for every argument).
const REACH: f64 = 16.0;

/// `(sin x, cos x)`.
#[inline(always)]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() > REACH || x.is_nan() {
        return x.sin_cos();
    }
    let n = (x * std::f64::consts::FRAC_2_PI + ROUND) - ROUND;
    let r = ((x - n * PIO2_1) - n * PIO2_2) - n * PIO2_2T;
    let (s, c) = (kernel_sin(r), kernel_cos(r));
    // By the quadrant q = n mod 4: (s, c), (c, −s), (−s, −c), (−c, s), chosen by bit masks
    // (a branch per node would be mispredicted as the nodes cross quadrants).
    let q = (n as i64 as u64) & 3;
    let swap = 0u64.wrapping_sub(q & 1);
    let (s_bits, c_bits) = (s.to_bits(), c.to_bits());
    let sine = (s_bits & !swap) | (c_bits & swap);
    let cosine = (c_bits & !swap) | (s_bits & swap);
    (
        f64::from_bits(sine ^ ((q >> 1) << 63)),
        f64::from_bits(cosine ^ ((((q + 1) >> 1) & 1) << 63)),
    )
}

/// fdlibm's `__kernel_sin` on `|x| ≤ π/4`: `x + S1 x³ + … + S6 x¹³`.
#[inline(always)]
fn kernel_sin(x: f64) -> f64 {
    const S1: f64 = -1.666_666_666_666_663_243_48e-1;
    const S2: f64 = 8.333_333_333_322_489_461_24e-3;
    const S3: f64 = -1.984_126_982_985_794_931_34e-4;
    const S4: f64 = 2.755_731_370_707_006_767_89e-6;
    const S5: f64 = -2.505_076_025_340_686_341_95e-8;
    const S6: f64 = 1.589_690_995_211_550_102_21e-10;
    let z = x * x;
    let w = z * z;
    let r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    x + z * x * (S1 + z * r)
}

/// fdlibm's `__kernel_cos` on `|x| ≤ π/4`: `1 − x²/2 + C1 x⁴ + … + C6 x¹⁴`, the `1 − x²/2`
/// summed so as to keep its last bits.
#[inline(always)]
fn kernel_cos(x: f64) -> f64 {
    const C1: f64 = 4.166_666_666_666_660_190_37e-2;
    const C2: f64 = -1.388_888_888_887_410_957_49e-3;
    const C3: f64 = 2.480_158_728_947_672_941_78e-5;
    const C4: f64 = -2.755_731_435_139_066_330_35e-7;
    const C5: f64 = 2.087_572_321_298_174_827_90e-9;
    const C6: f64 = -1.135_964_755_778_819_482_65e-11;
    let z = x * x;
    let w = z * z;
    let r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let hz = 0.5 * z;
    let one_less = 1.0 - hz;
    one_less + (((1.0 - one_less) - hz) + z * r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;

    /// Within an ulp of the value (or of 1e-300 near zero) of the platform's `sin_cos`,
    /// over a million random angles in the reach, the multiples of `π/4` and their
    /// neighbours, tiny angles, and past the reach (the platform's own answer there).
    #[test]
    fn agrees_with_the_platform_to_an_ulp() {
        let check = |x: f64| {
            let (s, c) = sin_cos(x);
            let (s_ref, c_ref) = x.sin_cos();
            for (got, want) in [(s, s_ref), (c, c_ref)] {
                let ulp = f64::EPSILON * want.abs().max(1e-300);
                assert!(
                    (got - want).abs() <= 1.5 * ulp,
                    "{x:e}: {got:e} vs {want:e}"
                );
            }
        };
        let mut rng = Rng(5);
        for _ in 0..1_000_000 {
            check(rng.uniform(-REACH, REACH));
        }
        for k in -20..=20 {
            let x = k as f64 * std::f64::consts::FRAC_PI_4;
            for step in -3..=3 {
                check(x + step as f64 * f64::EPSILON * x.abs().max(1.0));
            }
        }
        for e in 0..300 {
            check(10f64.powi(-e));
            check(-(10f64.powi(-e)));
        }
        for x in [0.0, -0.0, 1e6, -3e7, 1e300] {
            check(x);
        }
        assert!(sin_cos(f64::NAN).0.is_nan() && sin_cos(f64::INFINITY).1.is_nan());
    }
}
