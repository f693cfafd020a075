//! The one formula behind every curved tessellation: chords of a circle.

use std::f64::consts::PI;

/// The number of equal chords `n` that keeps a circle of `radius` within `deviation` of its
/// chords: `n = max(3, ⌈π / acos(1 − deviation/radius)⌉)`; `3` when `deviation ≥ radius`.
/// Non-decreasing as `deviation` falls. Returns `u64::MAX` for a zero or non-finite ratio
/// (callers cap the count, see [`super::MAX_TRIANGLES`]).
pub fn segments_for_circle(radius: f64, deviation: f64) -> u64 {
    let ratio = deviation / radius;
    if ratio >= 1.0 {
        return 3;
    }
    if ratio.is_nan() || ratio <= 0.0 || !ratio.is_finite() {
        return u64::MAX;
    }
    let half_angle = (1.0 - ratio).acos();
    let n = (PI / half_angle).ceil();
    if n >= u64::MAX as f64 {
        u64::MAX
    } else {
        (n as u64).max(3)
    }
}

/// `n` unit directions `(cos θ_k, sin θ_k)`, `θ_k = 2πk/n`.
pub(crate) fn unit_circle(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            (t.cos(), t.sin())
        })
        .collect()
}
