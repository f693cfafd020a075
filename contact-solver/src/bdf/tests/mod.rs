//! Tests of the BDF integrator against published references and closed forms.

mod andrews;
mod api;
mod inner;
mod order;
mod pendulum;
mod stiff;
