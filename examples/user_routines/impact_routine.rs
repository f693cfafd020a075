//! Example user routines for NORMAL_ROUTINE and FRICTION_ROUTINE, in Rust, with the C ABI of
//! `contact_user.h`. Build the shared library next to the datasets that name it:
//!
//! ```sh
//! rustc --edition 2021 --crate-type cdylib -C opt-level=2 \
//!     examples/user_routines/impact_routine.rs --out-dir examples/user_routines
//! ```
//!
//! `impact_force` is the IMPACT law of SPEC §5 written out, with USER(k, e, c, dmax):
//! `Fn = max(0, k·δ^e + STEP(δ, 0, 0, dmax, c)·δ̇)`. `coulomb_friction` is Adams' μ(v) with
//! USER(μs, μd, vs, vd): `F = −μ(|v|)·Fn·v/|v|` and the spin torque `−(2/3)·R·μ(|ω|R)·Fn·sign ω`,
//! `R = sqrt(A/π)`. Both return 1 when given the wrong number of constants.
#![allow(unsafe_code, clippy::missing_safety_doc)]

/// `struct contact_user_input` of contact_user.h.
#[repr(C)]
pub struct Input {
    pub abi_version: u32,
    pub index: u32,
    pub time: f64,
    pub point_i: [f64; 3],
    pub point_j: [f64; 3],
    pub normal: [f64; 3],
    pub penetration: f64,
    pub penetration_rate: f64,
    pub area: f64,
    pub slip_velocity: [f64; 3],
    pub spin: f64,
    pub normal_force: f64,
    pub parameters: *const f64,
    pub parameter_count: u32,
    pub reserved: u32,
}

fn constants(input: &Input) -> &[f64] {
    if input.parameters.is_null() {
        return &[];
    }
    // SAFETY: the caller passes `parameter_count` constants at `parameters` (contact_user.h).
    unsafe { std::slice::from_raw_parts(input.parameters, input.parameter_count as usize) }
}

/// STEP(x, x0, h0, x1, h1): the cubic step, clamped outside [x0, x1].
fn step(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> f64 {
    if x <= x0 {
        return h0;
    }
    if x >= x1 {
        return h1;
    }
    let d = (x - x0) / (x1 - x0);
    h0 + (h1 - h0) * d * d * (3.0 - 2.0 * d)
}

/// The IMPACT normal force, USER(k, e, c, dmax).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn impact_force(input: *const Input, output: *mut f64) -> i32 {
    // SAFETY: valid during the call (contact_user.h).
    let input = unsafe { &*input };
    let [k, e, c, dmax] = constants(input) else {
        return 1;
    };
    let delta = input.penetration;
    let force = if delta > 0.0 {
        (k * delta.powf(*e) + step(delta, 0.0, 0.0, *dmax, *c) * input.penetration_rate).max(0.0)
    } else {
        0.0
    };
    // SAFETY: a normal routine writes one output.
    unsafe { *output = force };
    0
}

/// Adams' friction coefficient magnitude at slip speed `v` ≥ 0.
fn mu(v: f64, mu_s: f64, mu_d: f64, vs: f64, vd: f64) -> f64 {
    if v <= vs {
        step(v, -vs, -mu_s, vs, mu_s)
    } else {
        step(v, vs, mu_s, vd, mu_d)
    }
}

/// Coulomb friction force and spin torque, USER(μs, μd, vs, vd).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn coulomb_friction(input: *const Input, output: *mut f64) -> i32 {
    // SAFETY: valid during the call (contact_user.h).
    let input = unsafe { &*input };
    let [mu_s, mu_d, vs, vd] = constants(input) else {
        return 1;
    };
    let mu = |v: f64| mu(v, *mu_s, *mu_d, *vs, *vd);
    let [x, y, z] = input.slip_velocity;
    let speed = (x * x + y * y + z * z).sqrt();
    let scale = if speed > 0.0 {
        -mu(speed) * input.normal_force / speed
    } else {
        0.0
    };
    let torque = if input.area > 0.0 {
        let radius = (input.area / std::f64::consts::PI).sqrt();
        -(2.0 / 3.0) * radius * mu(input.spin.abs() * radius) * input.normal_force
            * input.spin.signum()
    } else {
        0.0
    };
    // SAFETY: a friction routine writes four outputs.
    let out = unsafe { std::slice::from_raw_parts_mut(output, 4) };
    out.copy_from_slice(&[x * scale, y * scale, z * scale, torque]);
    0
}

/// A routine that always fails, for the error path.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn failing_force(_input: *const Input, _output: *mut f64) -> i32 {
    7
}
