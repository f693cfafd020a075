//! Parasolid text transmit files (`.x_t`, `.xmt_txt`) as contact geometry.
//!
//! Adams writes the CAD solids of a model as one transmit file beside the dataset and names
//! each in `GRAPHICS/id, EXTERNAL, RM = marker, FILE = name.xmt_txt, ELEMENT = name`. This
//! crate reads such a file (the header, the node stream laid out by the base schema as the
//! file's embedded changes edit it, [`schema`]), finds a body by the attributes Adams puts on
//! it (`AdamsPartName`, `AdamsObjectName`; [`Part::find_body`]), reads its topology and
//! geometry ([`Body`]) and tessellates it into a closed, consistently oriented triangle mesh at
//! a faceting tolerance ([`tessellate`]).
//!
//! Only what a contact needs is read: topology, the curves and surfaces faces are bounded by
//! and lie on, and the name attributes. Everything else in the stream is read by its layout and
//! kept untyped.

pub mod brep;
pub mod error;
pub mod geom;
pub mod nurbs;
pub mod part;
pub mod primitive;
pub mod schema;
pub mod stream;
pub mod text;

pub use brep::Body;
pub use error::{Error, ErrorKind, NodeRef};
pub use part::{BodyName, Part};
pub use primitive::{Primitive, Shape};
pub mod tess;

pub use tess::{Mesh, body_mesh, tessellate};
