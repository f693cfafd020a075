//! The side of a point relative to a directed segment's line, exactly, with ties broken by a
//! fixed infinitesimal shift of one chain.
//!
//! `orient(a, b, c) = (b − a) × (c − a)` is evaluated in floating point with Shewchuk's
//! error bound; when the bound cannot certify the sign, it is recomputed exactly as a sum of
//! exact products (`a·b = p + e` with `e = fma(a, b, −p)`) accumulated into a nonoverlapping
//! expansion (exact while the products neither overflow nor underflow: coordinates between
//! about 1e-150 and 1e150 in the pair's plane). A zero (the point on the line) is then resolved by shifting chain `a` of a pair
//! by `ε·(1, ε)` for an infinitesimal `ε` (simulation of simplicity): the perturbed pair has no
//! vertex on a chord of the other, so every crossing is transversal and found once — at a
//! shared vertex by exactly one of the two chords, never by both or neither — and two collinear
//! overlapping chords do not cross.

use contact_core::Vector2;

/// `+1` when `c` lies left of the directed line `a → b`, `−1` right, `0` on it (exact for the
/// given floating-point coordinates).
pub(crate) fn orient_sign(a: &Vector2, b: &Vector2, c: &Vector2) -> i8 {
    let left = (a.x - c.x) * (b.y - c.y);
    let right = (a.y - c.y) * (b.x - c.x);
    let det = left - right;
    // Shewchuk's `ccwerrboundA` for this form of the determinant.
    let bound = 3.330_669_073_875_471_6e-16 * (left.abs() + right.abs());
    if det > bound {
        return 1;
    }
    if -det > bound {
        return -1;
    }
    exact_orient_sign(a, b, c)
}

/// The sign of `orient(a, b, c)` as an exact sum of the six products of its expansion
/// `a.x·b.y − a.y·b.x + b.x·c.y − b.y·c.x + c.x·a.y − c.y·a.x`.
fn exact_orient_sign(a: &Vector2, b: &Vector2, c: &Vector2) -> i8 {
    let products = [
        (a.x, b.y),
        (-a.y, b.x),
        (b.x, c.y),
        (-b.y, c.x),
        (c.x, a.y),
        (-c.y, a.x),
    ];
    let mut expansion = [0.0f64; 12];
    let mut len = 0;
    for (u, v) in products {
        let p = u * v;
        let e = u.mul_add(v, -p);
        for term in [e, p] {
            len = grow_expansion(&mut expansion, len, term);
        }
    }
    // Nonoverlapping and in increasing magnitude: the last nonzero component has the sign.
    match expansion[..len].iter().rev().find(|x| **x != 0.0) {
        Some(x) if *x > 0.0 => 1,
        Some(_) => -1,
        None => 0,
    }
}

/// Adds `b` to the nonoverlapping expansion `e[..len]` (Shewchuk's GROW-EXPANSION with zero
/// elimination); returns the new length.
fn grow_expansion(e: &mut [f64; 12], len: usize, b: f64) -> usize {
    let mut q = b;
    let mut out = 0;
    for i in 0..len {
        let (sum, err) = two_sum(q, e[i]);
        q = sum;
        if err != 0.0 {
            e[out] = err;
            out += 1;
        }
    }
    if q != 0.0 || out == 0 {
        e[out] = q;
        out += 1;
    }
    out
}

/// `a + b = s + e` exactly.
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// The side of vertex `p` of the shifted chain relative to chord `q0 → q1` of the other:
/// the exact sign, or for a point on the line the sign of the shift's effect
/// `f × ε(1, ε) = −ε·f.y + ε²·f.x` with `f = q1 − q0`.
pub(crate) fn shifted_point_side(q0: &Vector2, q1: &Vector2, p: &Vector2) -> i8 {
    match orient_sign(q0, q1, p) {
        0 => leading_sign(-(q1.y - q0.y), q1.x - q0.x),
        s => s,
    }
}

/// The side of vertex `q` of the fixed chain relative to chord `p0 → p1` of the shifted
/// chain: the exact sign, or for a point on the line the sign of the shift's effect
/// `−e × ε(1, ε) = ε·e.y − ε²·e.x` with `e = p1 − p0`.
pub(crate) fn fixed_point_side(p0: &Vector2, p1: &Vector2, q: &Vector2) -> i8 {
    match orient_sign(p0, p1, q) {
        0 => leading_sign(p1.y - p0.y, -(p1.x - p0.x)),
        s => s,
    }
}

/// The sign of `first`, or of `second` when `first` is zero (a polynomial in `ε` by its
/// leading term; the differences of floats keep their exact signs).
fn leading_sign(first: f64, second: f64) -> i8 {
    let v = if first != 0.0 { first } else { second };
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_sign_where_the_float_determinant_is_round_off() {
        // Points on the line y = x scaled far from the origin: the float determinant is noise.
        let a = Vector2::new(1e16, 1e16);
        let b = Vector2::new(1e16 + 2.0, 1e16 + 2.0);
        let on = Vector2::new(0.5, 0.5);
        assert_eq!(orient_sign(&a, &b, &on), 0);
        let left = Vector2::new(0.5, 0.5 + 2f64.powi(-40));
        assert_eq!(orient_sign(&a, &b, &left), 1);
        let right = Vector2::new(0.5, 0.5 - 2f64.powi(-40));
        assert_eq!(orient_sign(&a, &b, &right), -1);
        // Tiny coordinates (whose products still do not underflow).
        let s = 2f64.powi(-400);
        assert_eq!(
            orient_sign(
                &Vector2::new(0.0, 0.0),
                &Vector2::new(s, 0.0),
                &Vector2::new(s, s)
            ),
            1
        );
    }

    #[test]
    fn ties_follow_one_shift_of_the_first_chain() {
        // The shift is +x, then +y at second order: a point on the chord (0,0)→(1,0) goes
        // left of it (above).
        let (q0, q1) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
        assert_eq!(shifted_point_side(&q0, &q1, &Vector2::new(0.5, 0.0)), 1);
        // A vertical chord (0,0)→(0,1): the shift +x puts the point to the right.
        let q1v = Vector2::new(0.0, 1.0);
        assert_eq!(shifted_point_side(&q0, &q1v, &Vector2::new(0.0, 0.5)), -1);
        // The fixed point against the shifted chord sees the opposite shift.
        assert_eq!(fixed_point_side(&q0, &q1, &Vector2::new(0.5, 0.0)), -1);
        assert_eq!(fixed_point_side(&q0, &q1v, &Vector2::new(0.0, 0.5)), 1);
    }
}
