//! parry beside our engines, for comparison only: every parry call of the workspace is in this
//! module, so neither engine nor contact-core depends on parry, and a later move to another
//! parry (the glam-based 0.26 line) touches these files alone.
//!
//! - [`primitives`]: parry's `contact` query on the primitive pairs it has shapes for (spheres,
//!   boxes, cylinders, cones, unbounded planes; a closed mesh for the benches), and
//!   [`ParryEngine`], that query behind the [`GeometryEngine`](contact_core::GeometryEngine)
//!   trait.
//! - [`meshes`]: parry's trimesh–trimesh contact manifolds on the faceted engine's meshes
//!   ([`ParryPeer`]), which `contact query --peer parry` and the benches time.
//! - [`ParryPeerEngine`]: the trade report's peer named `parry`, primitives through
//!   [`ParryEngine`] and mesh pairs through [`ParryPeer`].
//!
//! Nothing here answers a contact for a run: the engines' answers never go through parry.

mod engine;
pub mod meshes;
pub mod primitives;

pub use engine::ParryPeerEngine;
pub use meshes::{ParryDeepest, ParryError, ParryPeer};
pub use primitives::{ParryEngine, PeerContact, PeerShape};
