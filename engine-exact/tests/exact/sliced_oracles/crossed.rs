//! Crossed cylinders: slices perpendicular to both axes, each section's area and moments
//! exact across `u`; the area vector as the volume's negative gradient (see `super`'s docs).

use super::*;

/// `[A, ∫u, ∫v]` of the set `|u| ≤ wa`, `|v| ≤ ha`, `|e·p − ce| ≤ wb`, `|f·p − cf| ≤ hb`
/// (`e ⟂ f` unit): for each `u` the `v` range is an interval with piecewise-linear ends, so
/// the length is piecewise linear in `u` and Simpson's rule is exact between its breaks.
#[allow(clippy::too_many_arguments)]
fn strips_section(
    wa: f64,
    ha: f64,
    e: Vector2,
    ce: f64,
    wb: f64,
    f: Vector2,
    cf: f64,
    hb: f64,
) -> [f64; 3] {
    // Constraints g·(u, v) ≤ d.
    let lines = [
        (Vector2::new(0.0, 1.0), ha),
        (Vector2::new(0.0, -1.0), ha),
        (e, ce + wb),
        (-e, -ce + wb),
        (f, cf + hb),
        (-f, -cf + hb),
    ];
    let range = |u: f64| {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for (g, d) in lines {
            let rest = d - g.x * u;
            if g.y > 0.0 {
                hi = hi.min(rest / g.y);
            } else if g.y < 0.0 {
                lo = lo.max(rest / g.y);
            } else if rest < 0.0 {
                return (0.0, 0.0);
            }
        }
        if hi > lo { (lo, hi) } else { (0.0, 0.0) }
    };
    let mut breaks = vec![-wa, wa];
    for i in 0..lines.len() {
        for j in i + 1..lines.len() {
            let (g1, d1) = lines[i];
            let (g2, d2) = lines[j];
            let det = g1.x * g2.y - g2.x * g1.y;
            if det.abs() > 1e-300 {
                let u = (d1 * g2.y - d2 * g1.y) / det;
                if u > -wa && u < wa {
                    breaks.push(u);
                }
            }
        }
        let (g, d) = lines[i];
        if g.y == 0.0 && g.x != 0.0 {
            let u = d / g.x;
            if u > -wa && u < wa {
                breaks.push(u);
            }
        }
    }
    breaks.sort_by(f64::total_cmp);
    let mut out = [0.0; 3];
    let value = |u: f64| {
        let (lo, hi) = range(u);
        [hi - lo, u * (hi - lo), 0.5 * (hi * hi - lo * lo)]
    };
    for p in breaks.windows(2) {
        let (a, b) = (p[0], p[1]);
        if b <= a {
            continue;
        }
        // Simpson, with the ends nudged inside so a jump at a break does not leak in.
        let (fa, fm, fb) = (
            value(a + 1e-15 * (b - a)),
            value(0.5 * (a + b)),
            value(b - 1e-15 * (b - a)),
        );
        for k in 0..3 {
            out[k] += (b - a) / 6.0 * (fa[k] + 4.0 * fm[k] + fb[k]);
        }
    }
    out
}

/// Volume and centroid of two cylinders (`a`: radius `ra`, half length `ha`, centred at the
/// origin, axis +z; `b`: radius `rb`, half length `hb`, centre `cb`, unit axis `axis_b` not
/// parallel to z), by slices perpendicular to both axes.
pub fn crossed_cylinders_volume(
    ra: f64,
    ha: f64,
    rb: f64,
    hb: f64,
    cb: &Vector3,
    axis_b: &Vector3,
) -> Option<VolumeCentroid> {
    let n = Vector3::z().cross(axis_b).normalize();
    let across_a = Vector3::z().cross(&n); // u axis; v = z.
    let to_plane = |v: &Vector3| Vector2::new(v.dot(&across_a), v.z);
    let f = to_plane(axis_b).normalize();
    let e = Vector2::new(-f.y, f.x);
    let tb = n.dot(cb);
    let cb2 = to_plane(cb);
    let (lo, hi) = ((-ra).max(tb - rb), ra.min(tb + rb));
    if lo >= hi {
        return None;
    }
    let w = |r: f64, x: f64| ((r - x) * (r + x)).max(0.0).sqrt();
    let scale = ra.max(rb).max(ha).max(hb);
    // Kinks: each rim through the other cylinder's side, by sign changes on 720 samples.
    let mut breaks = vec![tb - rb, tb + rb, -ra, ra];
    let side_b = |p: &Vector3| {
        let d = p - cb;
        d.norm_squared() - d.dot(axis_b).powi(2) - rb * rb
    };
    let side_a = |p: &Vector3| p.x * p.x + p.y * p.y - ra * ra;
    let b_across = axis_b.cross(&n);
    let rims: [(Rim, bool); 4] = [
        (
            Box::new(|phi: f64| Vector3::new(ra * phi.cos(), ra * phi.sin(), ha)),
            true,
        ),
        (
            Box::new(|phi: f64| Vector3::new(ra * phi.cos(), ra * phi.sin(), -ha)),
            true,
        ),
        (
            Box::new(|phi: f64| cb + axis_b * hb + rb * (phi.cos() * n + phi.sin() * b_across)),
            false,
        ),
        (
            Box::new(|phi: f64| cb - axis_b * hb + rb * (phi.cos() * n + phi.sin() * b_across)),
            false,
        ),
    ];
    for (rim, of_a) in &rims {
        let gap = |phi: f64| {
            if *of_a {
                side_b(&rim(phi))
            } else {
                side_a(&rim(phi))
            }
        };
        let samples = 720;
        for k in 0..samples {
            let step = std::f64::consts::TAU / samples as f64;
            let (mut lo_phi, mut hi_phi) = (k as f64 * step, (k + 1) as f64 * step);
            if (gap(lo_phi) < 0.0) == (gap(hi_phi) < 0.0) {
                continue;
            }
            for _ in 0..60 {
                let mid = 0.5 * (lo_phi + hi_phi);
                if (gap(mid) < 0.0) == (gap(lo_phi) < 0.0) {
                    lo_phi = mid;
                } else {
                    hi_phi = mid;
                }
            }
            breaks.push(n.dot(&rim(lo_phi)));
        }
    }
    let s = integrate(lo, hi, &breaks, 1e-13 * scale.powi(3), &mut |t| {
        let [a, mu, mv] = strips_section(
            w(ra, t),
            ha,
            e,
            e.dot(&cb2),
            w(rb, t - tb),
            f,
            f.dot(&cb2),
            hb,
        );
        [a, t * a, mu, mv]
    });
    (s[0] > 0.0).then(|| {
        let g = (n * s[1] + across_a * s[2] + Vector3::z() * s[3]) / s[0];
        VolumeCentroid {
            volume: s[0],
            centroid: Point3::from(g),
        }
    })
}

/// A rim circle by its angle.
type Rim<'a> = Box<dyn Fn(f64) -> Vector3 + 'a>;

/// `−∂V/∂x_b` by central differences at steps `h, h/2, h/4`, extrapolated twice.
pub fn minus_gradient(volume: impl Fn(&Vector3) -> f64, h: f64) -> Vector3 {
    let mut out = Vector3::zeros();
    for k in 0..3 {
        let e = Vector3::ith(k, 1.0);
        let d = |s: f64| (volume(&(e * s)) - volume(&(-e * s))) / (2.0 * s);
        let (d1, d2, d4) = (d(h), d(0.5 * h), d(0.25 * h));
        let r1 = (4.0 * d2 - d1) / 3.0;
        let r2 = (4.0 * d4 - d2) / 3.0;
        out[k] = -(16.0 * r2 - r1) / 15.0;
    }
    out
}
