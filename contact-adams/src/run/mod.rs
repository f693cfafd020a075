//! Running a model: the dataset's [`Model`](crate::model::Model) lowered onto the solver
//! ([`lower`]), with the measures its expressions read ([`measures`]).

pub mod active;
pub mod eigenvalues;
pub mod frames;
pub mod lower;
pub mod measures;
pub mod motion_level;
pub mod output;
pub mod plan;
pub mod redundancy;
mod request_context;
pub mod request_file;
pub mod requests;
pub mod sforce;
