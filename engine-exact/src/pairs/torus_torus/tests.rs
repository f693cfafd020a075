use super::meridian::TorusTorus;
use contact_core::{Matrix3, Vector3, WorkCounters};

/// `∫ f(t) dt` over `[a, b]` by composite Simpson on 20,000 intervals (the integrands here are
/// trigonometric polynomials: the rule's error is far below round-off).
fn simpson(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let n = 20_000;
    let h = (b - a) / n as f64;
    let mut sum = f(a) + f(b);
    for k in 1..n {
        sum += f(a + h * k as f64) * if k % 2 == 1 { 4.0 } else { 2.0 };
    }
    sum * h / 3.0
}

#[test]
fn a_coaxial_meridian_is_the_lens_of_two_discs_by_greens_theorem() {
    // b coaxial with a, 0.2 above it: every meridian meets it in the same disc, centre
    // (1.2, 0.2) and radius 0.25, against a's disc, centre (1, 0) and radius 0.3.
    let pair = TorusTorus {
        big: 1.0,
        small: 0.3,
        b_big: 1.2,
        b_small: 0.25,
        origin: Vector3::new(0.0, 0.0, 0.2),
        to_b: Matrix3::identity(),
    };
    let (c1, r1, c2, r2) = ((1.0, 0.0), 0.3, (1.2, 0.2), 0.25);
    let d = f64::hypot(c2.0 - c1.0, c2.1 - c1.1);
    let toward = (c2.1 - c1.1).atan2(c2.0 - c1.0);
    let a1 = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
    let (half1, half2) = ((a1 / r1).acos(), ((d - a1) / r2).acos());
    // The lens' boundary, counter-clockwise: a's arc inside b, then b's arc inside a; each
    // Green integral ∮ g(x, z) dz along both.
    let green = |g: &dyn Fn(f64, f64) -> f64| {
        let along = |(cx, cz): (f64, f64), r: f64, mid: f64, half: f64| {
            simpson(mid - half, mid + half, |t| {
                g(cx + r * t.cos(), cz + r * t.sin()) * r * t.cos()
            })
        };
        along(c1, r1, toward, half1) + along(c2, r2, toward + std::f64::consts::PI, half2)
    };
    let volume = green(&|x, _| 0.5 * x * x);
    let radial = green(&|x, _| x * x * x / 3.0);
    let height = green(&|x, z| 0.5 * x * x * z);
    let wall = |f: &dyn Fn(f64) -> f64| {
        simpson(toward - half1, toward + half1, |t| {
            r1 * (c1.0 + r1 * t.cos()) * f(t)
        })
    };
    let expected = [
        volume,
        radial,
        height,
        wall(&|t| t.cos()),
        wall(&|t| t.sin()),
        wall(&|_| 1.0),
    ];
    for phi in [-2.0, 0.0, 0.7, 3.0] {
        let got = pair.integral(phi, &mut WorkCounters::default());
        for k in 0..6 {
            assert!(
                (got[k] - expected[k]).abs() < 1e-13,
                "φ {phi}, component {k}: {} vs {}",
                got[k],
                expected[k]
            );
        }
    }
}
